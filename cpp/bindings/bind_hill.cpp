// Hill's method for the Floquet exponents of a linear time-periodic system (hill.hpp); the GIL
// is released while solving.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/hill.hpp"

namespace rotordyn::py_bind {

void bind_hill(py::module_& m) {
  py::enum_<HillSelection>(m, "HillSelection")
      .value("centroid", HillSelection::centroid)
      .value("imaginary", HillSelection::imaginary);
  py::class_<HillResult>(m, "HillResult")
      .def_readonly("exponents", &HillResult::exponents)
      .def_readonly("multipliers", &HillResult::multipliers)
      .def_readonly("centroids", &HillResult::centroids)
      .def_readonly("eigenvalues", &HillResult::eigenvalues)
      .def_readonly("all_centroids", &HillResult::all_centroids)
      .def_readonly("monodromy", &HillResult::monodromy)
      .def_readonly("harmonics", &HillResult::harmonics);
  m.def("hill_floquet", &hill_floquet, py::arg("mass"), py::arg("stiffness"), py::arg("damping"),
        py::arg("omega"), py::arg("harmonics"), py::arg("selection") = HillSelection::centroid,
        py::call_guard<py::gil_scoped_release>(),
        "Floquet exponents and multipliers of M x'' + D(τ) x' + G(τ) x = 0 (τ = ω t, samples "
        "G_j, D_j at τ_j = 2πj/M_s, M_s ≥ 2H + 1) by Hill's method with H harmonics: the Hill "
        "matrix's eigenvalues, one kept per family λ + ikω (selection: centroid of the "
        "eigenvector's harmonics, or smallest |Im λ|).");
}

}  // namespace rotordyn::py_bind
