// Harmonic (unbalance) response solves.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>

#include "bindings.hpp"
#include "rotordyn/harmonic.hpp"

namespace rotordyn::py_bind {

void bind_harmonic(py::module_& m) {
  m.def("harmonic_response", &harmonic_response, py::arg("M"), py::arg("D"), py::arg("K"),
        py::arg("omega"), py::arg("F"), py::call_guard<py::gil_scoped_release>(),
        "X (n, m) solving (K - omega^2 M + i omega D) X = F (n, m); sparse LU when the "
        "matrices are sparse.");
  m.def("harmonic_sweep", &harmonic_sweep, py::arg("M"), py::arg("C"), py::arg("G"),
        py::arg("K"), py::arg("omegas"), py::arg("F"), py::arg("O"),
        py::call_guard<py::gil_scoped_release>(),
        "Y (n_freq, r) = O X(omega) with (K - w^2 M + i w (C + w G)) X = w^2 F at each omega: "
        "one symbolic analysis of the pattern, one numeric LU per frequency.");
}

}  // namespace rotordyn::py_bind
