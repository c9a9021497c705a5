// Batch entries of sweep chunks (GIL released around the whole chunk).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/batch.hpp"

namespace rotordyn::py_bind {

void bind_batch(py::module_& m) {
  py::class_<StabilityBatchResult>(m, "StabilityBatchResult")
      .def_readonly("status", &StabilityBatchResult::status)
      .def_readonly("message", &StabilityBatchResult::message)
      .def_readonly("iterations", &StabilityBatchResult::iterations)
      .def_readonly("r", &StabilityBatchResult::r)
      .def_readonly("h_min", &StabilityBatchResult::h_min)
      .def_readonly("h_min_z_m", &StabilityBatchResult::h_min_z_m)
      .def_readonly("film_force", &StabilityBatchResult::film_force)
      .def_readonly("n_eig", &StabilityBatchResult::n_eig)
      .def_readonly("eigenvalues", &StabilityBatchResult::eigenvalues)
      .def_readonly("whirl", &StabilityBatchResult::whirl)
      .def_readonly("sleeve_share", &StabilityBatchResult::sleeve_share)
      .def_readonly("modes", &StabilityBatchResult::modes)
      .def_readonly("least_stable", &StabilityBatchResult::least_stable)
      .def_readonly("max_real", &StabilityBatchResult::max_real);
  m.def(
      "stability_batch",
      [](SystemSolver& solver, const Eigen::VectorXd& omega, const Eigen::VectorXd& pressure,
         const RowMatrixXd& a, const std::vector<int>& restart, const EquilibriumOptions& opt,
         int n_modes, bool finite_difference, double fd_step,
         const std::vector<std::pair<int, int>>& xy_pairs,
         const std::vector<std::pair<int, int>>& rot_pairs, const std::vector<int>& sleeve,
         bool carry_cavitation, const std::string& jacobian) {
        StabilityBatchInput in;
        in.omega = omega;
        in.pressure = pressure;
        in.a = a;
        in.restart = restart;
        in.options = opt;
        in.n_modes = n_modes;
        in.finite_difference = finite_difference;
        in.fd_step = fd_step;
        in.xy_pairs = xy_pairs;
        in.rot_pairs = rot_pairs;
        in.sleeve = sleeve;
        in.carry_cavitation = carry_cavitation;
        in.jacobian = jacobian;
        py::gil_scoped_release release;
        return stability_batch(solver, in);
      },
      py::arg("solver"), py::arg("omega"), py::arg("pressure"), py::arg("a"),
      py::arg("restart"), py::arg("options"), py::arg("n_modes"),
      py::arg("finite_difference"), py::arg("fd_step"), py::arg("xy_pairs"),
      py::arg("rot_pairs"), py::arg("sleeve"), py::arg("carry_cavitation") = true,
      py::arg("jacobian") = "reuse",
      "Equilibrium (continued), K_H/D_H and eigen-analysis of each point of a sweep chunk.");

  py::class_<EquilibriumBatchResult>(m, "EquilibriumBatchResult")
      .def_readonly("status", &EquilibriumBatchResult::status)
      .def_readonly("message", &EquilibriumBatchResult::message)
      .def_readonly("iterations", &EquilibriumBatchResult::iterations)
      .def_readonly("residual", &EquilibriumBatchResult::residual)
      .def_readonly("r", &EquilibriumBatchResult::r)
      .def_readonly("h_min", &EquilibriumBatchResult::h_min)
      .def_readonly("h_min_z_m", &EquilibriumBatchResult::h_min_z_m)
      .def_readonly("film_force", &EquilibriumBatchResult::film_force);
  m.def(
      "equilibrium_batch",
      [](SystemSolver& solver, const Eigen::VectorXd& omega, const Eigen::VectorXd& pressure,
         const RowMatrixXd& a, const std::vector<int>& restart, const EquilibriumOptions& opt) {
        StabilityBatchInput in;
        in.omega = omega;
        in.pressure = pressure;
        in.a = a;
        in.restart = restart;
        in.options = opt;
        py::gil_scoped_release release;
        return equilibrium_batch(solver, in);
      },
      py::arg("solver"), py::arg("omega"), py::arg("pressure"), py::arg("a"),
      py::arg("restart"), py::arg("options"),
      "Equilibrium of each point of a sweep chunk (continued along lines from ok points).");
}

}  // namespace rotordyn::py_bind
