// Periodic orbits by shooting and Floquet multipliers; the GIL is released while shooting
// (the solver object must not be shared between threads).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/periodic.hpp"

namespace rotordyn::py_bind {

void bind_periodic(py::module_& m) {
  py::enum_<OrbitKind>(m, "OrbitKind")
      .value("autonomous", OrbitKind::autonomous)
      .value("forced", OrbitKind::forced);
  py::class_<PeriodicInput>(m, "PeriodicInput")
      .def(py::init<>())
      .def_readwrite("kind", &PeriodicInput::kind)
      .def_readwrite("omega", &PeriodicInput::omega)
      .def_readwrite("chamber_pressure", &PeriodicInput::chamber_pressure)
      .def_readwrite("a", &PeriodicInput::a)
      .def_readwrite("unbalance_cos", &PeriodicInput::unbalance_cos)
      .def_readwrite("unbalance_sin", &PeriodicInput::unbalance_sin)
      .def_readwrite("r0", &PeriodicInput::r0)
      .def_readwrite("v0", &PeriodicInput::v0)
      .def_readwrite("t0", &PeriodicInput::t0)
      .def_readwrite("period", &PeriodicInput::period)
      .def_readwrite("n_out", &PeriodicInput::n_out);
  py::enum_<ShootingFloquet>(m, "ShootingFloquet")
      .value("flow", ShootingFloquet::flow)
      .value("samples", ShootingFloquet::samples)
      .value("none", ShootingFloquet::none);
  py::class_<ShootingOptions>(m, "ShootingOptions")
      .def(py::init<>())
      .def_readwrite("cvode", &ShootingOptions::cvode)
      .def_readwrite("tol", &ShootingOptions::tol)
      .def_readwrite("length_scale", &ShootingOptions::length_scale)
      .def_readwrite("max_iter", &ShootingOptions::max_iter)
      .def_readwrite("sensitivity_error_control", &ShootingOptions::sensitivity_error_control)
      .def_readwrite("sensitivity_rtol", &ShootingOptions::sensitivity_rtol)
      .def_readwrite("broyden", &ShootingOptions::broyden)
      .def_readwrite("blocked_sensitivities", &ShootingOptions::blocked_sensitivities)
      .def_readwrite("parameter_sensitivity", &ShootingOptions::parameter_sensitivity)
      .def_readwrite("screen_rtol", &ShootingOptions::screen_rtol)
      .def_readwrite("screen_margin", &ShootingOptions::screen_margin)
      .def_readwrite("floquet", &ShootingOptions::floquet)
      .def_readwrite("floquet_tol", &ShootingOptions::floquet_tol)
      .def_readwrite("floquet_max_steps", &ShootingOptions::floquet_max_steps)
      .def_readwrite("floquet_margin", &ShootingOptions::floquet_margin);
  py::class_<Floquet>(m, "Floquet")
      .def_readonly("multipliers", &Floquet::multipliers)
      .def_readonly("trivial", &Floquet::trivial)
      .def_readonly("critical", &Floquet::critical)
      .def_readonly("critical_modulus", &Floquet::critical_modulus)
      .def_readonly("stable", &Floquet::stable)
      .def_readonly("critical_type", &Floquet::critical_type);
  py::class_<PeriodicOrbitResult>(m, "PeriodicOrbitResult")
      .def_readonly("r0", &PeriodicOrbitResult::r0)
      .def_readonly("v0", &PeriodicOrbitResult::v0)
      .def_readonly("period", &PeriodicOrbitResult::period)
      .def_readonly("t0", &PeriodicOrbitResult::t0)
      .def_readonly("t", &PeriodicOrbitResult::t)
      .def_readonly("r", &PeriodicOrbitResult::r)
      .def_readonly("v", &PeriodicOrbitResult::v)
      .def_readonly("monodromy", &PeriodicOrbitResult::monodromy)
      .def_readonly("floquet", &PeriodicOrbitResult::floquet)
      .def_readonly("residual", &PeriodicOrbitResult::residual)
      .def_readonly("residuals", &PeriodicOrbitResult::residuals)
      .def_readonly("newton_correction", &PeriodicOrbitResult::newton_correction)
      .def_readonly("iterations", &PeriodicOrbitResult::iterations)
      .def_readonly("length_scale", &PeriodicOrbitResult::length_scale)
      .def_readonly("status", &PeriodicOrbitResult::status)
      .def_readonly("message", &PeriodicOrbitResult::message)
      .def_readonly("steps", &PeriodicOrbitResult::steps)
      .def_readonly("rhs_evals", &PeriodicOrbitResult::rhs_evals)
      .def_readonly("sens_rhs_evals", &PeriodicOrbitResult::sens_rhs_evals)
      .def_readonly("jac_evals", &PeriodicOrbitResult::jac_evals)
      .def_readonly("reynolds_solves", &PeriodicOrbitResult::reynolds_solves)
      .def_readonly("sensitivity_flows", &PeriodicOrbitResult::sensitivity_flows)
      .def_readonly("order_reductions", &PeriodicOrbitResult::order_reductions)
      .def_readonly("sens_linear_solves", &PeriodicOrbitResult::sens_linear_solves)
      .def_readonly("sens_factorizations", &PeriodicOrbitResult::sens_factorizations)
      .def_readonly("monodromy_rtol", &PeriodicOrbitResult::monodromy_rtol)
      .def_readonly("floquet_error", &PeriodicOrbitResult::floquet_error)
      .def_readonly("floquet_converged", &PeriodicOrbitResult::floquet_converged)
      .def_readonly("floquet_steps", &PeriodicOrbitResult::floquet_steps)
      .def_readonly("floquet_linearizations", &PeriodicOrbitResult::floquet_linearizations)
      .def_readonly("flow_tol_factor", &PeriodicOrbitResult::flow_tol_factor);
  m.def("periodic_orbit", &periodic_orbit, py::arg("solver"), py::arg("input"),
        py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "Periodic orbit of eq. 12 by single shooting (CVODES forward sensitivities for the "
        "monodromy); status and message on failure.");
  m.def(
      "flow_map",
      [](SystemSolver& solver, const PeriodicInput& in, const CvodeOptions& opt) {
        Eigen::VectorXd xT;
        Eigen::MatrixXd Phi;
        {
          py::gil_scoped_release release;  // the solver belongs to this call's thread
          flow_map(solver, in, opt, xT, Phi);
        }
        return py::make_tuple(xT, Phi);
      },
      py::arg("solver"), py::arg("input"), py::arg("options"),
      "(x(t0 + T) (2n,), monodromy (2n, 2n)) from x0 = (r0, v0).");
  m.def("floquet", &floquet, py::arg("monodromy"), py::arg("autonomous"),
        py::call_guard<py::gil_scoped_release>(),
        "Floquet multipliers of a monodromy matrix and the type of the critical one.");
}

}  // namespace rotordyn::py_bind
