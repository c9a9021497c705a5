// Pseudo-arclength corrector by harmonic balance; the GIL is released while correcting (the
// solver object must not be shared between threads). Over a model field the corrector calls
// back into Python for the system at each value (the callable's wrapper takes the GIL for
// the call).
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/hb_continuation.hpp"

namespace rotordyn::py_bind {

void bind_hb_continuation(py::module_& m) {
  py::class_<HbContinuationInput>(m, "HbContinuationInput")
      .def(py::init<>())
      .def_readwrite("base", &HbContinuationInput::base)
      .def_readwrite("parameter", &HbContinuationInput::parameter)
      .def_readwrite("config_direction", &HbContinuationInput::config_direction)
      .def_readwrite("subharmonic", &HbContinuationInput::subharmonic)
      .def_readwrite("coefficients", &HbContinuationInput::coefficients)
      .def_readwrite("frequency", &HbContinuationInput::frequency)
      .def_readwrite("p", &HbContinuationInput::p)
      .def_readwrite("scale", &HbContinuationInput::scale)
      .def_readwrite("y_prev", &HbContinuationInput::y_prev)
      .def_readwrite("tangent", &HbContinuationInput::tangent)
      .def_readwrite("ds", &HbContinuationInput::ds)
      .def_readwrite("direction", &HbContinuationInput::direction)
      .def_readwrite("fd_step", &HbContinuationInput::fd_step);
  py::class_<HbContinuationOptions>(m, "HbContinuationOptions")
      .def(py::init<>())
      .def_readwrite("hb", &HbContinuationOptions::hb)
      .def_readwrite("floquet_margin", &HbContinuationOptions::floquet_margin);
  py::class_<HbContinuationStep>(m, "HbContinuationStep")
      .def_readonly("hb", &HbContinuationStep::hb)
      .def_readonly("p", &HbContinuationStep::p)
      .def_readonly("tangent", &HbContinuationStep::tangent)
      .def_readonly("floquet_route", &HbContinuationStep::floquet_route)
      .def_readonly("screen_critical_modulus", &HbContinuationStep::screen_critical_modulus)
      .def_readonly("screen_trivial_error", &HbContinuationStep::screen_trivial_error)
      .def_readonly("fd_evaluations", &HbContinuationStep::fd_evaluations)
      .def_readonly("floquet_error", &HbContinuationStep::floquet_error)
      .def_readonly("floquet_steps", &HbContinuationStep::floquet_steps);
  py::class_<HbSystemAt>(m, "HbSystemAt")
      .def(py::init<>())
      .def_readwrite("solver", &HbSystemAt::solver)
      .def_readwrite("input", &HbSystemAt::input)
      .def_readwrite("refused", &HbSystemAt::refused);
  using Step = HbContinuationStep (*)(SystemSolver&, const HbContinuationInput&,
                                      const HbContinuationOptions&);
  using FieldStep = HbContinuationStep (*)(const HbSystemProvider&, const HbContinuationInput&,
                                           const HbContinuationOptions&);
  m.def("hb_continuation_step", static_cast<Step>(&hb_continuation_step), py::arg("solver"),
        py::arg("input"), py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "One pseudo-arclength corrector step of a periodic-orbit branch by harmonic balance "
        "(Newton on the Fourier coefficients, frequency and parameter, bordered by dR/dp and "
        "the arclength condition); the new unit tangent and the Floquet route.");
  m.def("hb_continuation_step", static_cast<FieldStep>(&hb_continuation_step),
        py::arg("system_at"), py::arg("input"), py::arg("options"),
        py::call_guard<py::gil_scoped_release>(),
        "The same step over a parameter the caller varies: system_at(p) returns the "
        "HbSystemAt there (solver and orbit input, or refused with the model's reason); "
        "dR/dp by a central difference on the systems at p +- h.");
}

}  // namespace rotordyn::py_bind
