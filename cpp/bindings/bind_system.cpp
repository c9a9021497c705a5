// Multi-bearing system: model struct, solver (film forces, linearisation, equilibrium).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "rotordyn/system.hpp"

namespace rotordyn::py_bind {

void bind_system(py::module_& m) {
  py::class_<FilmCoupling>(m, "FilmCoupling", "One fluid film coupling system coordinates.")
      .def(py::init<>())
      .def_readwrite("name", &FilmCoupling::name)
      .def_readwrite("geometry", &FilmCoupling::geometry)
      .def_readwrite("grid", &FilmCoupling::grid)
      .def_property(
          "cavitation", [](const FilmCoupling& f) { return std::string(cavitation_name(f.cavitation)); },
          [](FilmCoupling& f, const std::string& s) { f.cavitation = parse_cavitation(s); })
      .def_readwrite("coords", &FilmCoupling::coords)
      .def_readwrite("shape", &FilmCoupling::shape)
      .def_readwrite("base_h", &FilmCoupling::base_h)
      .def_readwrite("spin_factor", &FilmCoupling::spin_factor)
      .def_readwrite("axial_weight", &FilmCoupling::axial_weight,
                     "(n_coords, n_axial + 1): dh/dr_k(phi, z) = shape(phi, k) * "
                     "axial_weight(k, z); empty: 1 (journal tilt: z on the rotations).")
      .def("thickness", &FilmCoupling::thickness, py::arg("rc"),
           "Film thickness (n_circ, n_axial + 1), m, at the film's coordinates rc (n_coords,).")
      .def_readwrite("viscosity_field", &FilmCoupling::viscosity_field);

  py::class_<SystemModel>(m, "SystemModel", "M, K, C, G, loads and films of eq. 12 (SI).")
      .def(py::init<>())
      .def("has_table_mass", &SystemModel::has_table_mass)
      .def("mass_at", &SystemModel::mass_at, py::arg("omega"),
           "M plus the tables' mass coefficients at the spin speed omega (rad/s), (n, n).")
      .def_readwrite("M", &SystemModel::M)
      .def_readwrite("K", &SystemModel::K)
      .def_readwrite("C", &SystemModel::C)
      .def_readwrite("G", &SystemModel::G)
      .def_readwrite("Kc", &SystemModel::Kc)
      .def("offset_load", &SystemModel::offset_load, py::arg("omega"), py::arg("a"),
           "(n,) the shaft's force from the housing offsets a at spin speed omega (rad/s): "
           "K a + omega Kc a, N.")
      .def_readwrite("Q", &SystemModel::Q)
      .def_readwrite("chamber", &SystemModel::chamber)
      .def_readwrite("films", &SystemModel::films)
      .def_readwrite("tables", &SystemModel::tables)
      .def_readwrite("pad_coords", &SystemModel::pad_coords)
      .def_readwrite("pad_pitch", &SystemModel::pad_pitch)
      .def("validate", &SystemModel::validate);

  py::class_<EquilibriumOptions>(m, "EquilibriumOptions")
      .def(py::init<>())
      .def_property(
          "method",
          [](const EquilibriumOptions& o) {
            return std::string(o.method == EquilibriumMethod::Newton ? "newton" : "successive");
          },
          [](EquilibriumOptions& o, const std::string& s) { o.method = parse_equilibrium_method(s); })
      .def_readwrite("tol", &EquilibriumOptions::tol)
      .def_readwrite("max_iter", &EquilibriumOptions::max_iter)
      .def_readwrite("pm", &EquilibriumOptions::pm)
      .def_readwrite("contact_fraction", &EquilibriumOptions::contact_fraction)
      .def_readwrite("polish", &EquilibriumOptions::polish)
      .def_readwrite("reuse_jacobian", &EquilibriumOptions::reuse_jacobian)
      .def_readwrite("reuse_contraction", &EquilibriumOptions::reuse_contraction)
      .def_readwrite("joint_pad_solve", &EquilibriumOptions::joint_pad_solve,
                     "Spherical-pivot pads: joint Newton on each pad's coordinates with the "
                     "nested solves as fallback (True), or always nested (False; tests).");

  py::class_<EquilibriumResult>(m, "EquilibriumResult")
      .def_readonly("r", &EquilibriumResult::r)
      .def_readonly("film_force", &EquilibriumResult::film_force)
      .def_readonly("h_min", &EquilibriumResult::h_min)
      .def_readonly("h_min_angle_deg", &EquilibriumResult::h_min_angle_deg)
      .def_readonly("h_min_z_m", &EquilibriumResult::h_min_z_m)
      .def_readonly("iterations", &EquilibriumResult::iterations)
      .def_readonly("reynolds_solves", &EquilibriumResult::reynolds_solves)
      .def_readonly("residual", &EquilibriumResult::residual)
      .def_readonly("load_scale", &EquilibriumResult::load_scale)
      .def_readonly("pm", &EquilibriumResult::pm)
      .def_readonly("status", &EquilibriumResult::status)
      .def_readonly("message", &EquilibriumResult::message)
      .def_readonly("path", &EquilibriumResult::path)
      .def_readonly("unloaded_pads", &EquilibriumResult::unloaded_pads);

  py::class_<Linearization>(m, "Linearization")
      .def_readonly("KH", &Linearization::KH)
      .def_readonly("DH", &Linearization::DH)
      .def_readonly("film_force", &Linearization::film_force);

  using gil = py::call_guard<py::gil_scoped_release>;
  // shared holder: a corrector over a model field keeps the systems it is given alive
  py::class_<SystemSolver, std::shared_ptr<SystemSolver>>(m, "SystemSolver",
                           "Film forces, linearisation and equilibrium of a SystemModel. "
                           "One per thread.")
      .def(py::init<SystemModel>(), py::arg("model"))
      .def_property_readonly("model", &SystemSolver::model)
      .def("film_forces", &SystemSolver::film_forces, py::arg("r"), py::arg("rdot"),
           py::arg("omega"), gil())
      .def(
          "film_point",
          [](SystemSolver& s, const std::vector<double>& r, const std::vector<double>& rdot,
             double omega) {
            Eigen::VectorXd H;
            SystemSolver::ThinnestFilm t;
            {  // released after the conversions: the solve touches only C++ state (the
               // solver is one per thread) and the results are built after reacquiring
              py::gil_scoped_release release;
              const auto n = static_cast<Eigen::Index>(r.size());
              const auto nd = static_cast<Eigen::Index>(rdot.size());
              H = s.film_forces(Eigen::Map<const Eigen::VectorXd>(r.data(), n),
                                Eigen::Map<const Eigen::VectorXd>(rdot.data(), nd), omega);
              t = s.thinnest_film();
            }
            return py::make_tuple(py::cast(std::move(H)), t.film, t.h_min_m, t.h_min_angle_deg,
                                  t.h_min_z_m);
          },
          py::arg("r"), py::arg("rdot"), py::arg("omega"),
          "film_forces(r, rdot, omega) and the thinnest film at that call in one call (r, "
          "rdot: sequences of floats): (H, film index, h_min m, its angle deg, its z m).")
      .def("linearize", &SystemSolver::linearize, py::arg("r"), py::arg("rdot"), py::arg("omega"),
           gil())
      .def("linearize_fd", &SystemSolver::linearize_fd, py::arg("r"), py::arg("omega"),
           py::arg("rel_step") = 1e-6, gil())
      .def(
          "equilibrium",
          [](SystemSolver& s, double omega, double pc, const Eigen::VectorXd& a,
             const Eigen::VectorXd& r0, const EquilibriumOptions& opt,
             const std::optional<Eigen::MatrixXd>& kh_guess) {
            return s.equilibrium(omega, pc, a, r0, opt, kh_guess ? &*kh_guess : nullptr);
          },
          py::arg("omega"), py::arg("chamber_pressure"), py::arg("a"), py::arg("r0"),
          py::arg("options"), py::arg("kh_guess") = py::none(), gil(),
          "Static equilibrium (eq. 14); kh_guess (n, n): the first Newton Jacobian's K_H "
          "when options.reuse_jacobian.")
      .def_property_readonly("reynolds_solves", &SystemSolver::reynolds_solves)
      .def_property_readonly("reynolds_iterations", &SystemSolver::reynolds_iterations,
                             "Active-set (or linear) iterations summed over the solves.")
      .def_property_readonly("linearizations", &SystemSolver::linearizations,
                             "Linearisations (K_H, or K_H and D_H) about a solve.")
      .def("set_refine_prediction", &SystemSolver::set_refine_prediction, py::arg("on"),
           "Testing switch: every film's refined cavitation-set prediction (default on; the "
           "same pressures bit for bit). Invalidates the last solve.")
      .def("forget_state", &SystemSolver::forget_state,
           "Forget the films' last solve and carried cavitation sets (a new public call).")
      .def_property_readonly("last_h_min", &SystemSolver::last_h_min)
      .def("film_h_min", &SystemSolver::film_h_min, py::arg("r"),
           "Minimum film thickness of each film at positions r (n,), m, from the geometry "
           "alone (no Reynolds solve).")
      .def("last_pressure", &SystemSolver::last_pressure, py::arg("film"))
      .def_property_readonly("last_h_min_angle_deg", &SystemSolver::last_h_min_angle_deg)
      .def_property_readonly("last_h_min_z_m", &SystemSolver::last_h_min_z_m,
                             "Axial position of each film's minimum at the last call, m "
                             "(0 where the film is uniform along z there).");
}

}  // namespace rotordyn::py_bind
