// The threshold of instability along one sweep line (scan + Brent in one call, GIL released).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/threshold.hpp"

namespace rotordyn::py_bind {

void bind_threshold(py::module_& m) {
  py::enum_<ThresholdAxis>(m, "ThresholdAxis")
      .value("speed", ThresholdAxis::Speed)
      .value("chamber_pressure", ThresholdAxis::ChamberPressure)
      .value("config", ThresholdAxis::Config);
  py::class_<ThresholdLineInput>(m, "ThresholdLineInput")
      .def(py::init<>())
      .def_readwrite("x", &ThresholdLineInput::x)
      .def_readwrite("omega", &ThresholdLineInput::omega)
      .def_readwrite("pressure", &ThresholdLineInput::pressure)
      .def_readwrite("a", &ThresholdLineInput::a)
      .def_readwrite("axis", &ThresholdLineInput::axis)
      .def_readwrite("config_index", &ThresholdLineInput::config_index)
      .def_readwrite("options", &ThresholdLineInput::options)
      .def_readwrite("exclude_sleeve", &ThresholdLineInput::exclude_sleeve)
      .def_readwrite("xtol", &ThresholdLineInput::xtol)
      .def_readwrite("xtol_given", &ThresholdLineInput::xtol_given)
      .def_readwrite("max_iter", &ThresholdLineInput::max_iter)
      .def_readwrite("xy_pairs", &ThresholdLineInput::xy_pairs)
      .def_readwrite("rot_pairs", &ThresholdLineInput::rot_pairs)
      .def_readwrite("sleeve", &ThresholdLineInput::sleeve)
      .def_readwrite("pads", &ThresholdLineInput::pads)
      .def_readwrite("valid", &ThresholdLineInput::valid);
  py::class_<ThresholdLineResult>(m, "ThresholdLineResult")
      .def_readonly("y", &ThresholdLineResult::y)
      .def_readonly("freq", &ThresholdLineResult::freq)
      .def_readonly("stable", &ThresholdLineResult::stable)
      .def_readonly("bracket", &ThresholdLineResult::bracket)
      .def_readonly("root", &ThresholdLineResult::root)
      .def_readonly("root_freq", &ThresholdLineResult::root_freq)
      .def_readonly("status", &ThresholdLineResult::status)
      .def_readonly("message", &ThresholdLineResult::message)
      .def_readonly("evaluations", &ThresholdLineResult::evaluations);
  m.def("threshold_line", &threshold_line, py::arg("solver"), py::arg("input"),
        py::call_guard<py::gil_scoped_release>(),
        "max Re lambda along a sweep line (equilibria continued) and every sign change "
        "refined by Brent's method (SciPy's brentq steps).");
  py::class_<MaxRealBatchInput>(m, "MaxRealBatchInput")
      .def(py::init<>())
      .def_readwrite("omega", &MaxRealBatchInput::omega)
      .def_readwrite("pressure", &MaxRealBatchInput::pressure)
      .def_readwrite("a", &MaxRealBatchInput::a)
      .def_readwrite("restart", &MaxRealBatchInput::restart)
      .def_readwrite("valid", &MaxRealBatchInput::valid)
      .def_readwrite("r0", &MaxRealBatchInput::r0)
      .def_readwrite("starts", &MaxRealBatchInput::starts)
      .def_readwrite("options", &MaxRealBatchInput::options)
      .def_readwrite("exclude_sleeve", &MaxRealBatchInput::exclude_sleeve)
      .def_readwrite("xy_pairs", &MaxRealBatchInput::xy_pairs)
      .def_readwrite("rot_pairs", &MaxRealBatchInput::rot_pairs)
      .def_readwrite("sleeve", &MaxRealBatchInput::sleeve)
      .def_readwrite("pads", &MaxRealBatchInput::pads);
  py::class_<MaxRealBatchResult>(m, "MaxRealBatchResult")
      .def_readonly("y", &MaxRealBatchResult::y)
      .def_readonly("freq", &MaxRealBatchResult::freq)
      .def_readonly("status", &MaxRealBatchResult::status)
      .def_readonly("message", &MaxRealBatchResult::message)
      .def_readonly("r_last", &MaxRealBatchResult::r_last)
      .def_readonly("r", &MaxRealBatchResult::r)
      .def_readonly("n_eig", &MaxRealBatchResult::n_eig)
      .def_readonly("eigenvalues", &MaxRealBatchResult::eigenvalues)
      .def_readonly("whirl", &MaxRealBatchResult::whirl)
      .def_readonly("sleeve_share", &MaxRealBatchResult::sleeve_share)
      .def_readonly("pad_share", &MaxRealBatchResult::pad_share);
  m.def("max_real_batch", &max_real_batch, py::arg("solver"), py::arg("input"),
        py::call_guard<py::gil_scoped_release>(),
        "max Re lambda (and its frequency, and every eigenvalue) at each listed point of a boundary-refinement "
        "chunk, equilibria continued along lines, in one call.");
}

}  // namespace rotordyn::py_bind
