// Rotor FEM: plain structs with named fields, assembly, constraints.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/rotor.hpp"

namespace rotordyn::py_bind {

namespace {
py::tuple csc(const SparseMatrixD& A_in) {
  SparseMatrixD A = A_in;
  A.makeCompressed();
  const auto nnz = A.nonZeros();
  py::array_t<double> data(nnz);
  py::array_t<int> indices(nnz), indptr(A.cols() + 1);
  std::copy(A.valuePtr(), A.valuePtr() + nnz, data.mutable_data());
  std::copy(A.innerIndexPtr(), A.innerIndexPtr() + nnz, indices.mutable_data());
  std::copy(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1, indptr.mutable_data());
  return py::make_tuple(data, indices, indptr, py::make_tuple(A.rows(), A.cols()));
}
}  // namespace

void bind_rotor(py::module_& m) {
  py::class_<ShaftElement>(m, "ShaftElement", "One Timoshenko beam element (SI units).")
      .def(py::init<>())
      .def_readwrite("length", &ShaftElement::length)
      .def_readwrite("outer_diameter", &ShaftElement::outer_diameter)
      .def_readwrite("inner_diameter", &ShaftElement::inner_diameter)
      .def_readwrite("density", &ShaftElement::density)
      .def_readwrite("young", &ShaftElement::young)
      .def_readwrite("shear_modulus", &ShaftElement::shear_modulus)
      .def_readwrite("shear_coefficient", &ShaftElement::shear_coefficient)
      .def_readwrite("shear", &ShaftElement::shear)
      .def_readwrite("rotary_inertia", &ShaftElement::rotary_inertia)
      .def_readwrite("damping_alpha", &ShaftElement::damping_alpha,
                     "proportional damping α (1/s): the element adds α M_e to C")
      .def_readwrite("damping_beta", &ShaftElement::damping_beta,
                     "proportional damping β (s): the element adds β K_e to C")
      .def("area", &ShaftElement::area)
      .def("second_moment", &ShaftElement::second_moment)
      .def("kappa", &ShaftElement::kappa)
      .def("phi", &ShaftElement::phi);

  py::class_<Disk>(m, "Disk", "Rigid disk at a node.")
      .def(py::init<>())
      .def_readwrite("node", &Disk::node)
      .def_readwrite("mass", &Disk::mass)
      .def_readwrite("ip", &Disk::ip)
      .def_readwrite("id", &Disk::id);

  py::class_<LinearSupport>(m, "LinearSupport", "Linear spring/damper support at a node.")
      .def(py::init<>())
      .def_readwrite("node", &LinearSupport::node)
      .def_readwrite("k", &LinearSupport::k)
      .def_readwrite("c", &LinearSupport::c);

  py::class_<RotorModel>(m, "RotorModel", "Chain of shaft elements with disks and supports.")
      .def(py::init<>())
      .def_readwrite("elements", &RotorModel::elements)
      .def_readwrite("disks", &RotorModel::disks)
      .def_readwrite("supports", &RotorModel::supports)
      .def_readwrite("rigid_nodes", &RotorModel::rigid_nodes)
      .def("n_nodes", &RotorModel::n_nodes)
      .def("n_dof", &RotorModel::n_dof)
      .def("validate", &RotorModel::validate);

  py::class_<ConstrainedRotor>(m, "ConstrainedRotor",
                               "Dense M, K, C, G after rigid supports; dofs maps back.")
      .def_readonly("M", &ConstrainedRotor::M)
      .def_readonly("K", &ConstrainedRotor::K)
      .def_readonly("C", &ConstrainedRotor::C)
      .def_readonly("G", &ConstrainedRotor::G)
      .def_readonly("dofs", &ConstrainedRotor::dofs)
      .def_readonly("xy", &ConstrainedRotor::xy)
      .def_readonly("rot", &ConstrainedRotor::rot)
      .def("local", &ConstrainedRotor::local, py::arg("full_dof"));

  m.def(
      "element_matrices",
      [](const ShaftElement& e) {
        const ElementMatrices em = element_matrices(e);
        return py::make_tuple(Eigen::MatrixXd(em.M), Eigen::MatrixXd(em.K),
                              Eigen::MatrixXd(em.G));
      },
      py::arg("element"), "(M, K, G) 8×8 in DOF order (x1, y1, θx1, θy1, x2, y2, θx2, θy2).");
  m.def(
      "assemble",
      [](const RotorModel& model) {
        RotorMatrices r;
        {
          py::gil_scoped_release release;  // pure C++ on owned data
          r = assemble(model);
        }
        py::dict d;
        d["M"] = csc(r.M);
        d["K"] = csc(r.K);
        d["C"] = csc(r.C);
        d["G"] = csc(r.G);
        return d;
      },
      py::arg("model"), "Free-free sparse M, K, C, G as CSC tuples (data, indices, indptr, shape).");
  m.def("constrain", &constrain, py::arg("model"), py::call_guard<py::gil_scoped_release>());
  m.def("total_mass", &total_mass, py::arg("model"));
}

}  // namespace rotordyn::py_bind
