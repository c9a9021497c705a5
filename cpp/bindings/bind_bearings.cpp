// Bearing elements beyond the plain film: speed-dependent coefficient tables (TableCoupling)
// and batches of operating points over speed (coefficient tables of any film bearing).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/bearing_table.hpp"

namespace rotordyn::py_bind {

void bind_bearings(py::module_& m) {
  py::class_<TableCoupling>(m, "TableCoupling",
                            "Linear bearing with coefficients interpolated in speed.")
      .def(py::init<>())
      .def_readwrite("name", &TableCoupling::name)
      .def_readwrite("coords", &TableCoupling::coords)
      .def_readwrite("omegas", &TableCoupling::omegas)
      .def_readwrite("K", &TableCoupling::K)
      .def_readwrite("C", &TableCoupling::C)
      .def_readwrite("M", &TableCoupling::M, "(n_s, 4) mxx mxy myx myy, kg; empty: none")
      .def_readwrite("extrapolate", &TableCoupling::extrapolate)
      .def(
          "at",
          [](const TableCoupling& t, double omega) {
            Eigen::Matrix2d K, C;
            t.at(omega, K, C);
            return py::make_tuple(K, C);
          },
          py::arg("omega"), "(K, C) at the speed omega (rad/s).")
      .def(
          "mass_at",
          [](const TableCoupling& t, double omega) {
            Eigen::Matrix2d K, C, M;
            t.at(omega, K, C, &M);
            return M;
          },
          py::arg("omega"), "M (2x2, kg) at the speed omega (rad/s); zero without mass terms.");

  py::class_<OperatingPointTable>(m, "OperatingPointTable")
      .def_readonly("r", &OperatingPointTable::r)
      .def_readonly("KH", &OperatingPointTable::KH)
      .def_readonly("DH", &OperatingPointTable::DH)
      .def_readonly("force", &OperatingPointTable::force)
      .def_readonly("status", &OperatingPointTable::status)
      .def_readonly("message", &OperatingPointTable::message)
      .def_readonly("iterations", &OperatingPointTable::iterations)
      .def_readonly("reynolds_solves", &OperatingPointTable::reynolds_solves)
      .def_readonly("path", &OperatingPointTable::path);

  m.def("operating_points", &operating_points, py::arg("model"), py::arg("omegas"),
        py::arg("a"), py::arg("r0"), py::arg("options"), py::arg("n_threads") = 1,
        py::arg("pad_penalty") = Eigen::MatrixXd(), py::call_guard<py::gil_scoped_release>(),
        "Equilibrium and linearisation at each speed (rad/s), parallel over speeds.");
  m.def("homotopy_start", &homotopy_start, py::arg("model"), py::arg("omega"),
        py::arg("chamber_pressure"), py::arg("a"), py::arg("r0"), py::arg("options"),
        py::arg("pad_penalty"), py::call_guard<py::gil_scoped_release>(),
        "Equilibrium start for systems with tilting pads (pad-tilt penalty released in stages).");
  m.def("pad_system_equilibrium", &pad_system_equilibrium, py::arg("solver"), py::arg("model"),
        py::arg("omega"), py::arg("chamber_pressure"), py::arg("a"), py::arg("r0"),
        py::arg("homotopy_r0"), py::arg("options"), py::arg("pad_penalty"),
        py::call_guard<py::gil_scoped_release>(),
        "Equilibrium of a system with tilting pads: pad assembly, tilt homotopy as fallback.");
}

}  // namespace rotordyn::py_bind
