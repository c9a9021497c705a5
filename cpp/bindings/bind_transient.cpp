// Nonlinear transient (CVODE): options, inputs and results; the GIL is released while
// integrating (the solver object must not be shared between threads).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/transient.hpp"

namespace rotordyn::py_bind {

void bind_transient(py::module_& m) {
  py::class_<CvodeOptions>(m, "CvodeOptions", "CVODE settings (BDF, dense Newton).")
      .def(py::init<>())
      .def_readwrite("rtol", &CvodeOptions::rtol)
      .def_readwrite("atol_position", &CvodeOptions::atol_position)
      .def_readwrite("atol_velocity", &CvodeOptions::atol_velocity)
      .def_readwrite("max_steps", &CvodeOptions::max_steps)
      .def_readwrite("max_step", &CvodeOptions::max_step)
      .def_readwrite("analytic_jacobian", &CvodeOptions::analytic_jacobian);
  py::class_<TransientInput>(m, "TransientInput")
      .def(py::init<>())
      .def_readwrite("omega", &TransientInput::omega)
      .def_readwrite("chamber_pressure", &TransientInput::chamber_pressure)
      .def_readwrite("a", &TransientInput::a)
      .def_readwrite("unbalance_cos", &TransientInput::unbalance_cos)
      .def_readwrite("unbalance_sin", &TransientInput::unbalance_sin)
      .def_readwrite("r0", &TransientInput::r0)
      .def_readwrite("v0", &TransientInput::v0)
      .def_readwrite("t_out", &TransientInput::t_out);
  py::class_<TransientResult>(m, "TransientResult")
      .def_readonly("t", &TransientResult::t)
      .def_readonly("r", &TransientResult::r)
      .def_readonly("v", &TransientResult::v)
      .def_readonly("h_min", &TransientResult::h_min)
      .def_readonly("status", &TransientResult::status)
      .def_readonly("message", &TransientResult::message)
      .def_readonly("steps", &TransientResult::steps)
      .def_readonly("rhs_evals", &TransientResult::rhs_evals)
      .def_readonly("jac_evals", &TransientResult::jac_evals)
      .def_readonly("newton_fails", &TransientResult::newton_fails)
      .def_readonly("error_test_fails", &TransientResult::error_test_fails);
  m.def("integrate", &integrate, py::arg("solver"), py::arg("input"), py::arg("options"),
        py::call_guard<py::gil_scoped_release>(),
        "Integrate eq. 12 with CVODE from t = 0 to input.t_out[-1].");
  m.def("cvode_flag_name", &cvode_flag_name, py::arg("flag"));
}

}  // namespace rotordyn::py_bind
