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
}

}  // namespace rotordyn::py_bind
