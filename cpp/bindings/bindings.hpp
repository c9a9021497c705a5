// Declarations of the per-concept binding functions (one file per concept).
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace rotordyn::py_bind {
namespace py = pybind11;
/// float64, C-ordered array argument (forcecast converts other dtypes).
using array_d = py::array_t<double, py::array::c_style | py::array::forcecast>;

void bind_errors(py::module_& m);
void bind_info(py::module_& m);
void bind_threads(py::module_& m);
void bind_rotor(py::module_& m);
void bind_modal(py::module_& m);
void bind_harmonic(py::module_& m);
void bind_system(py::module_& m);
void bind_transient(py::module_& m);
void bind_reynolds(py::module_& m);
void bind_sleeve(py::module_& m);
void bind_bearings(py::module_& m);
void bind_batch(py::module_& m);
void bind_periodic(py::module_& m);
void bind_harmonic_balance(py::module_& m);
void bind_hill(py::module_& m);
void bind_thermal(py::module_& m);
void bind_continuation(py::module_& m);
void bind_hb_continuation(py::module_& m);
void bind_unbalance(py::module_& m);
void bind_threshold(py::module_& m);
void bind_thd(py::module_& m);
void bind_tracking(py::module_& m);
}  // namespace rotordyn::py_bind
