// Eigen-analysis, Campbell batches and model reductions.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/modal.hpp"
#include "rotordyn/modal_operator.hpp"
#include "rotordyn/reduction.hpp"

namespace rotordyn::py_bind {

void bind_modal(py::module_& m) {
  // The round-off band of Re λ of every verdict, C++ and Python (rotordyn.results.modes).
  m.attr("ROUND_OFF_REL") = kRoundOffRel;
  py::class_<ModalResult>(m, "ModalResult")
      .def_readonly("eigenvalues", &ModalResult::eigenvalues)
      .def_readonly("modes", &ModalResult::modes)
      .def_property_readonly("whirl", [](const ModalResult& r) {
        std::vector<int> w;
        for (auto x : r.whirl) w.push_back(static_cast<int>(x));
        return w;
      });
  py::class_<CampbellResult>(m, "CampbellResult")
      .def_readonly("eigenvalues", &CampbellResult::eigenvalues)
      .def_readonly("whirl", &CampbellResult::whirl);

  m.def("modal", &modal, py::arg("M"), py::arg("D"), py::arg("K"), py::arg("xy_pairs"),
        py::arg("n_modes"), py::arg("with_modes") = true,
        py::arg("rot_pairs") = std::vector<std::pair<int, int>>{},
        py::call_guard<py::gil_scoped_release>(),
        "Eigen-analysis of M q'' + D q' + K q = 0; n_modes <= 0 keeps all.");
  m.def("campbell", &campbell, py::arg("M"), py::arg("C"), py::arg("G"), py::arg("K"),
        py::arg("xy_pairs"), py::arg("speeds_rad_s"), py::arg("n_modes"),
        py::arg("rot_pairs") = std::vector<std::pair<int, int>>{},
        py::call_guard<py::gil_scoped_release>(),
        "Eigenvalues (n_speeds, n_modes) with D = C + Ω G at each speed.");

  py::class_<ModalOperator>(m, "ModalOperator",
                            "The sparse pencil and K's factorisation of one model, kept between "
                            "modal calls (same answers as modal(M, C + omega G, K, ...)).")
      .def(py::init<const Eigen::MatrixXd&, const Eigen::MatrixXd&, const Eigen::MatrixXd&,
                    const Eigen::MatrixXd&>(),
           py::arg("M"), py::arg("C"), py::arg("G"), py::arg("K"),
           py::call_guard<py::gil_scoped_release>())
      .def("modal", &ModalOperator::modal, py::arg("omega"), py::arg("xy_pairs"),
           py::arg("n_modes"), py::arg("with_modes") = true,
           py::arg("rot_pairs") = std::vector<std::pair<int, int>>{},
           py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("size", &ModalOperator::size)
      .def_property_readonly("factored", &ModalOperator::factored);

  py::class_<Reduction>(m, "Reduction")
      .def_readonly("masters", &Reduction::masters)
      .def_readonly("T", &Reduction::T)
      .def_readonly("M", &Reduction::M)
      .def_readonly("K", &Reduction::K)
      .def("reduce", &Reduction::reduce, py::arg("X"))
      .def("expand", &Reduction::expand, py::arg("q_r"));
  m.def(
      "reduce_model",
      [](const std::string& kind, const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
         const std::vector<int>& masters, int n_modes) {
        const ReductionKind k = parse_reduction(kind);
        py::gil_scoped_release release;
        return reduce_model(k, M, K, masters, n_modes);
      },
      py::arg("kind"), py::arg("M"), py::arg("K"), py::arg("masters"), py::arg("n_modes") = 0);
}

}  // namespace rotordyn::py_bind
