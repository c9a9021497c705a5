// Mode tracking of a batch of points (GIL released around the assignment loop).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/tracking.hpp"

namespace rotordyn::py_bind {

void bind_tracking(py::module_& m) {
  m.def(
      "track_modes",
      [](const Eigen::MatrixXcd& eigenvalues, const std::vector<Eigen::MatrixXcd>& shapes,
         const Eigen::MatrixXd& weight, const std::vector<int>& line_start, double eig_weight,
         double min_mac) {
        py::gil_scoped_release release;
        return track_modes(eigenvalues, shapes, weight, line_start,
                           TrackOptions{eig_weight, min_mac});
      },
      py::arg("eigenvalues"), py::arg("shapes"), py::arg("weight"), py::arg("line_start"),
      py::arg("eig_weight") = 0.2, py::arg("min_mac") = 0.3,
      "Tracked mode ids (n_pts, k) of points on lines: eigenvalues (n_pts, k) complex (NaN: "
      "no mode), shapes one (n, k_i) matrix per point or [] (eigenvalues alone), weight (n, n) "
      "or an empty matrix (identity), line_start (n_pts,) nonzero where a line starts.");
  m.def(
      "linear_assignment",
      [](const Eigen::MatrixXd& cost) { return linear_assignment(cost); }, py::arg("cost"),
      "Optimal assignment of a (n_rows, n_cols) cost matrix: the column of each row (-1: "
      "none), min(n_rows, n_cols) pairs of least total cost.");
}

}  // namespace rotordyn::py_bind
