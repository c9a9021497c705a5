// Unbalance response over speeds with bearing elements (one call, GIL released).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/unbalance.hpp"

namespace rotordyn::py_bind {

void bind_unbalance(py::module_& m) {
  py::class_<UnbalanceSweepResult>(m, "UnbalanceSweepResult")
      .def_readonly("Y", &UnbalanceSweepResult::Y)
      .def_readonly("status", &UnbalanceSweepResult::status)
      .def_readonly("message", &UnbalanceSweepResult::message)
      .def_readonly("r", &UnbalanceSweepResult::r)
      .def_readonly("max_real", &UnbalanceSweepResult::max_real)
      .def_readonly("solve_error", &UnbalanceSweepResult::solve_error);
  m.def(
      "unbalance_sweep",
      [](const SystemModel& model, const Eigen::VectorXd& omegas, const Eigen::VectorXd& pressure,
         const RowMatrixXd& a, const Eigen::VectorXd& r0, const EquilibriumOptions& opt,
         const Eigen::MatrixXd& pad_penalty, const Eigen::VectorXcd& F, const Eigen::MatrixXd& O,
         bool finite_difference, double fd_step, bool bearing_elements, bool check_stability,
         const std::vector<std::pair<int, int>>& xy_pairs,
         const std::vector<std::pair<int, int>>& rot_pairs, int n_threads,
         bool cold_after_failure) {
        UnbalanceSweepInput in;
        in.omegas = omegas;
        in.pressure = pressure;
        in.a = a;
        in.r0 = r0;
        in.options = opt;
        in.pad_penalty = pad_penalty;
        in.F = F;
        in.O = O;
        in.finite_difference = finite_difference;
        in.fd_step = fd_step;
        in.bearing_elements = bearing_elements;
        in.check_stability = check_stability;
        in.xy_pairs = xy_pairs;
        in.rot_pairs = rot_pairs;
        in.n_threads = n_threads;
        in.cold_after_failure = cold_after_failure;
        py::gil_scoped_release release;
        return unbalance_sweep(model, in);
      },
      py::arg("model"), py::arg("omegas"), py::arg("pressure"), py::arg("a"),
      py::arg("r0"), py::arg("options"), py::arg("pad_penalty"), py::arg("F"), py::arg("O"),
      py::arg("finite_difference"), py::arg("fd_step"), py::arg("bearing_elements"),
      py::arg("check_stability"), py::arg("xy_pairs"), py::arg("rot_pairs"),
      py::arg("n_threads") = 1, py::arg("cold_after_failure") = false,
      "Equilibrium (continued), K_H/D_H, the harmonic solve O q and optionally the largest "
      "eigenvalue real part at each speed (rad/s) of an unbalance response.");
}

}  // namespace rotordyn::py_bind
