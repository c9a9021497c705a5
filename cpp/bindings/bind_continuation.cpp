// Pseudo-arclength corrector for periodic orbits; the GIL is released while correcting (the
// solver object must not be shared between threads).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/continuation.hpp"

namespace rotordyn::py_bind {

void bind_continuation(py::module_& m) {
  py::enum_<ContinuationParameter>(m, "ContinuationParameter")
      .value("chamber_pressure", ContinuationParameter::chamber_pressure)
      .value("speed", ContinuationParameter::speed)
      .value("config", ContinuationParameter::config);
  py::class_<ContinuationInput>(m, "ContinuationInput")
      .def(py::init<>())
      .def_readwrite("base", &ContinuationInput::base)
      .def_readwrite("parameter", &ContinuationInput::parameter)
      .def_readwrite("config_direction", &ContinuationInput::config_direction)
      .def_readwrite("p", &ContinuationInput::p)
      .def_readwrite("subharmonic", &ContinuationInput::subharmonic)
      .def_readwrite("scale", &ContinuationInput::scale)
      .def_readwrite("y_prev", &ContinuationInput::y_prev)
      .def_readwrite("tangent", &ContinuationInput::tangent)
      .def_readwrite("ds", &ContinuationInput::ds)
      .def_readwrite("direction", &ContinuationInput::direction)
      .def_readwrite("fd_step", &ContinuationInput::fd_step)
      .def_readwrite("jacobian", &ContinuationInput::jacobian);
  py::class_<ContinuationStep>(m, "ContinuationStep")
      .def_readonly("orbit", &ContinuationStep::orbit)
      .def_readonly("p", &ContinuationStep::p)
      .def_readonly("tangent", &ContinuationStep::tangent)
      .def_readonly("fd_flows", &ContinuationStep::fd_flows)
      .def_readonly("jacobian", &ContinuationStep::jacobian)
      .def_readonly("floquet_route", &ContinuationStep::floquet_route)
      .def_readonly("screen_critical_modulus", &ContinuationStep::screen_critical_modulus)
      .def_readonly("screen_trivial_error", &ContinuationStep::screen_trivial_error)
      .def_readonly("floquet_error", &ContinuationStep::floquet_error)
      .def_readonly("floquet_steps", &ContinuationStep::floquet_steps);
  m.def("continuation_step", &continuation_step, py::arg("solver"), py::arg("input"),
        py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "One pseudo-arclength corrector step of a periodic-orbit branch (shooting Newton "
        "bordered by ∂R/∂p and the arclength condition); the new unit tangent.");
}

}  // namespace rotordyn::py_bind
