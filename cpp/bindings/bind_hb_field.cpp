// The harmonic-balance system on one assembled model (the evaluation and a converged point's
// Floquet multipliers) for correctors that re-assemble the model at each parameter value; the
// GIL is released in both calls (the solver object must not be shared between threads).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/hb_field.hpp"

namespace rotordyn::py_bind {

void bind_hb_field(py::module_& m) {
  py::class_<HbEvaluation>(m, "HbEvaluation")
      .def_readonly("coefficients", &HbEvaluation::coefficients)
      .def_readonly("frequency", &HbEvaluation::frequency)
      .def_readonly("residual", &HbEvaluation::residual)
      .def_readonly("jacobian", &HbEvaluation::jacobian)
      .def_readonly("d_frequency", &HbEvaluation::d_frequency)
      .def_readonly("row_scale", &HbEvaluation::row_scale)
      .def_readonly("film_stiffness", &HbEvaluation::film_stiffness)
      .def_readonly("film_damping", &HbEvaluation::film_damping)
      .def_readonly("ok", &HbEvaluation::ok)
      .def_readonly("contact", &HbEvaluation::contact)
      .def_readonly("message", &HbEvaluation::message)
      .def_readonly("linearizations", &HbEvaluation::linearizations)
      .def_readonly("reynolds_solves", &HbEvaluation::reynolds_solves);
  m.def("hb_evaluate", &hb_evaluate, py::arg("solver"), py::arg("input"),
        py::arg("coefficients"), py::arg("frequency"), py::arg("options"), py::arg("jacobian"),
        py::call_guard<py::gil_scoped_release>(),
        "One AFT evaluation of eq. 12 by harmonic balance at the coefficients (2H + 1, n) and "
        "the frequency (rad/s) on this solver's model and the input's operating point: the "
        "projected residual, with the Jacobian its derivatives, row scales and the films' "
        "K_H, D_H at the samples; ok = False with the message when a film fails.");
  m.def("hb_orbit_point", &hb_orbit_point, py::arg("solver"), py::arg("input"), py::arg("at"),
        py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "A converged branch point from its evaluation with the Jacobian: the samples, the "
        "equilibrium check and the Floquet multipliers (from the samples, or one CVODES "
        "sensitivity flow by the floquet_margin rule) of a harmonic-balance corrector.");
}

}  // namespace rotordyn::py_bind
