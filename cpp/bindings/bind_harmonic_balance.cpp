// Periodic orbits by harmonic balance (AFT); the GIL is released while solving (the solver
// object must not be shared between threads).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/harmonic_balance.hpp"

namespace rotordyn::py_bind {

void bind_harmonic_balance(py::module_& m) {
  py::enum_<HbFloquet>(m, "HbFloquet")
      .value("none", HbFloquet::none)
      .value("samples", HbFloquet::samples)
      .value("flow", HbFloquet::flow)
      .value("hill", HbFloquet::hill);
  py::class_<HarmonicBalanceOptions>(m, "HarmonicBalanceOptions")
      .def(py::init<>())
      .def_readwrite("harmonics", &HarmonicBalanceOptions::harmonics)
      .def_readwrite("time_points", &HarmonicBalanceOptions::time_points)
      .def_readwrite("tol", &HarmonicBalanceOptions::tol)
      .def_readwrite("max_iter", &HarmonicBalanceOptions::max_iter)
      .def_readwrite("length_scale", &HarmonicBalanceOptions::length_scale)
      .def_readwrite("deflation", &HarmonicBalanceOptions::deflation)
      .def_readwrite("film_continuation", &HarmonicBalanceOptions::film_continuation)
      .def_readwrite("floquet", &HarmonicBalanceOptions::floquet)
      .def_readwrite("magnus_substeps", &HarmonicBalanceOptions::magnus_substeps)
      .def_readwrite("floquet_tol", &HarmonicBalanceOptions::floquet_tol)
      .def_readwrite("floquet_max_steps", &HarmonicBalanceOptions::floquet_max_steps)
      .def_readwrite("hill_selection", &HarmonicBalanceOptions::hill_selection)
      .def_readwrite("hill_time_points", &HarmonicBalanceOptions::hill_time_points)
      .def_readwrite("cvode", &HarmonicBalanceOptions::cvode)
      .def_readwrite("sensitivity_rtol", &HarmonicBalanceOptions::sensitivity_rtol);
  py::class_<HarmonicBalanceResult>(m, "HarmonicBalanceResult")
      .def_readonly("orbit", &HarmonicBalanceResult::orbit)
      .def_readonly("coefficients", &HarmonicBalanceResult::coefficients)
      .def_readonly("harmonic_amplitudes", &HarmonicBalanceResult::harmonic_amplitudes)
      .def_readonly("harmonics", &HarmonicBalanceResult::harmonics)
      .def_readonly("time_points", &HarmonicBalanceResult::time_points)
      .def_readonly("frequency", &HarmonicBalanceResult::frequency)
      .def_readonly("linearizations", &HarmonicBalanceResult::linearizations)
      .def_readonly("evaluations", &HarmonicBalanceResult::evaluations)
      .def_readonly("floquet_error", &HarmonicBalanceResult::floquet_error)
      .def_readonly("floquet_converged", &HarmonicBalanceResult::floquet_converged)
      .def_readonly("floquet_steps", &HarmonicBalanceResult::floquet_steps)
      .def_readonly("floquet_levels", &HarmonicBalanceResult::floquet_levels)
      .def_readonly("floquet_linearizations", &HarmonicBalanceResult::floquet_linearizations)
      .def_readonly("floquet_trivial_error", &HarmonicBalanceResult::floquet_trivial_error)
      .def_readonly("floquet_moduli", &HarmonicBalanceResult::floquet_moduli);
  m.def("harmonic_balance", &harmonic_balance, py::arg("solver"), py::arg("input"),
        py::arg("start_samples"), py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "Periodic orbit of eq. 12 by harmonic balance (AFT, Newton on the Fourier coefficients "
        "with the films' linearisation at the time samples); status and message on failure. "
        "start_samples: (M0, n) positions over one period, or empty for one flow from "
        "(input.r0, input.v0).");
}

}  // namespace rotordyn::py_bind
