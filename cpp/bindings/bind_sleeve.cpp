// Flexible sleeve: curved-beam element, arc/ring meshes, three-step Guyan condensation.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/sleeve.hpp"

namespace rotordyn::py_bind {

void bind_sleeve(py::module_& m) {
  py::class_<CurvedBeamOptions>(m, "CurvedBeamOptions",
                                "Effects included by the curved-beam element.")
      .def(py::init<>())
      .def_readwrite("extension", &CurvedBeamOptions::extension)
      .def_readwrite("shear", &CurvedBeamOptions::shear)
      .def_readwrite("rotary_inertia", &CurvedBeamOptions::rotary_inertia)
      .def_readwrite("plane_strain", &CurvedBeamOptions::plane_strain)
      .def_readwrite("shear_coefficient", &CurvedBeamOptions::shear_coefficient);
  py::class_<CurvedBeamSection>(m, "CurvedBeamSection",
                                "Rectangular sleeve section and material (SI units).")
      .def(py::init<>())
      .def_readwrite("thickness", &CurvedBeamSection::thickness)
      .def_readwrite("width", &CurvedBeamSection::width)
      .def_readwrite("young", &CurvedBeamSection::young)
      .def_readwrite("density", &CurvedBeamSection::density)
      .def_readwrite("poisson", &CurvedBeamSection::poisson)
      .def_readwrite("options", &CurvedBeamSection::options);
  py::class_<CurvedBeamProperties>(m, "CurvedBeamProperties")
      .def_readonly("compliance_bending", &CurvedBeamProperties::compliance_bending)
      .def_readonly("compliance_axial", &CurvedBeamProperties::compliance_axial)
      .def_readonly("compliance_shear", &CurvedBeamProperties::compliance_shear)
      .def_readonly("mass", &CurvedBeamProperties::mass)
      .def_readonly("rotary", &CurvedBeamProperties::rotary);
  m.def("curved_beam_properties", &curved_beam_properties, py::arg("section"));

  py::class_<CurvedBeamElement>(m, "CurvedBeamElement",
                                "Exact-flexibility circular-arc element; DOFs (x, y, v) per node.")
      .def(py::init<double, double, double, const CurvedBeamProperties&>(), py::arg("radius"),
           py::arg("theta_a"), py::arg("theta_b"), py::arg("properties"))
      .def("K", [](const CurvedBeamElement& e) { return Eigen::MatrixXd(e.K()); })
      .def("M", [](const CurvedBeamElement& e) { return Eigen::MatrixXd(e.M()); })
      .def("K_local", [](const CurvedBeamElement& e) { return Eigen::MatrixXd(e.K_local()); })
      .def("M_local", [](const CurvedBeamElement& e) { return Eigen::MatrixXd(e.M_local()); })
      .def("to_local", [](const CurvedBeamElement& e) { return Eigen::MatrixXd(e.to_local()); })
      .def("shape", [](const CurvedBeamElement& e, double t) { return Eigen::MatrixXd(e.shape(t)); },
           py::arg("theta"), "(3, 6) shape functions: (u_x, u_y, v) at theta.")
      .def("flexibility",
           [](const CurvedBeamElement& e) { return Eigen::MatrixXd(e.flexibility()); });

  py::class_<CurvedBeamMesh>(m, "CurvedBeamMesh")
      .def_readonly("radius", &CurvedBeamMesh::radius)
      .def_readonly("node_angles", &CurvedBeamMesh::node_angles)
      .def_readonly("element_nodes", &CurvedBeamMesh::element_nodes)
      .def_readonly("M", &CurvedBeamMesh::M)
      .def_readonly("K", &CurvedBeamMesh::K);
  m.def("curved_arc", &curved_arc, py::arg("radius"), py::arg("theta_start"), py::arg("arc"),
        py::arg("n_elements"), py::arg("section"), py::call_guard<py::gil_scoped_release>(),
        "Open arc (unconstrained), 3 DOF (x, y, v) per node.");
  m.def("closed_ring", &closed_ring, py::arg("radius"), py::arg("n_elements"),
        py::arg("section"), py::call_guard<py::gil_scoped_release>(),
        "Complete free ring closing on node 0, 3 DOF (x, y, v) per node.");
  m.def("natural_frequencies_hz", &natural_frequencies_hz, py::arg("M"), py::arg("K"),
        py::call_guard<py::gil_scoped_release>());

  py::class_<SleeveGeometry>(m, "SleeveGeometry", "Sleeve arc in the bearing frame (SI, rad).")
      .def(py::init<>())
      .def_readwrite("radius", &SleeveGeometry::radius)
      .def_readwrite("arc", &SleeveGeometry::arc)
      .def_readwrite("clamp_angle", &SleeveGeometry::clamp_angle);
  py::class_<SleeveModel>(m, "SleeveModel")
      .def(py::init<>())
      .def_readwrite("geometry", &SleeveModel::geometry)
      .def_readwrite("section", &SleeveModel::section)
      .def_readwrite("n_elements", &SleeveModel::n_elements)
      .def_readwrite("master_nodes", &SleeveModel::master_nodes);
  py::class_<SleeveCondensation>(m, "SleeveCondensation")
      .def_readonly("mesh", &SleeveCondensation::mesh)
      .def_readonly("M_full", &SleeveCondensation::M_full)
      .def_readonly("K_full", &SleeveCondensation::K_full)
      .def_readonly("M_xy", &SleeveCondensation::M_xy)
      .def_readonly("K_xy", &SleeveCondensation::K_xy)
      .def_readonly("M_rt", &SleeveCondensation::M_rt)
      .def_readonly("K_rt", &SleeveCondensation::K_rt)
      .def_readonly("Ms", &SleeveCondensation::Ms)
      .def_readonly("Ks", &SleeveCondensation::Ks)
      .def_readonly("T", &SleeveCondensation::T)
      .def_readonly("freq_full_hz", &SleeveCondensation::freq_full_hz)
      .def_readonly("freq_xy_hz", &SleeveCondensation::freq_xy_hz)
      .def_readonly("freq_condensed_hz", &SleeveCondensation::freq_condensed_hz)
      .def_readonly("master_angles", &SleeveCondensation::master_angles)
      .def("expand", &SleeveCondensation::expand, py::arg("r_s"))
      .def("interpolation", &SleeveCondensation::interpolation, py::arg("phi"),
           py::call_guard<py::gil_scoped_release>(),
           "(n_phi, n_m) inward radial displacement w(phi) per master coordinate.")
      .def("interpolation_full", &SleeveCondensation::interpolation_full, py::arg("phi"),
           py::call_guard<py::gil_scoped_release>(),
           "(n_phi, 3n) inward radial displacement w(phi) per full DOF.")
      .def("chamber_load_full", &SleeveCondensation::chamber_load_full, py::arg("phi_start"),
           py::arg("phi_end"), py::call_guard<py::gil_scoped_release>(),
           "(3n,) consistent full-DOF load per unit chamber pressure, m^2.")
      .def("chamber_load", &SleeveCondensation::chamber_load, py::arg("phi_start"),
           py::arg("phi_end"), py::call_guard<py::gil_scoped_release>(),
           "(n_m,) generalized master force per unit chamber pressure, m^2.");
  m.def("condense_sleeve", &condense_sleeve, py::arg("model"),
        py::call_guard<py::gil_scoped_release>(),
        "Build the clamped sleeve and apply the three-step Guyan condensation.");
}

}  // namespace rotordyn::py_bind
