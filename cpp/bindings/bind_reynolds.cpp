// Fluid-film journal bearing (Reynolds solver): geometry/grid structs, the reusable solver
// object and its results. Every solve releases the GIL; one solver object must not be used by
// two threads at once (the Python layer keeps one per thread).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/reynolds.hpp"

#include <cmath>

namespace rotordyn::py_bind {

void bind_reynolds(py::module_& m) {
  py::class_<Groove>(m, "Groove", "Axial groove fixed in the bearing frame (deg, deg, Pa).")
      .def(py::init<>())
      .def(py::init([](double c, double w, double p) { return Groove{c, w, p}; }),
           py::arg("center_deg"), py::arg("width_deg"), py::arg("pressure_pa"))
      .def_readwrite("center_deg", &Groove::center_deg)
      .def_readwrite("width_deg", &Groove::width_deg)
      .def_readwrite("pressure_pa", &Groove::pressure_pa);

  py::class_<Pocket>(m, "Pocket",
                     "Recess of depth_m over phi in [start_deg, start_deg + arc_deg] (the grid's "
                     "angle, periodic) and z in [z_min_m, z_max_m] (0 the mid-plane): a step in "
                     "the film thickness at its edges.")
      .def(py::init<>())
      .def(py::init([](double s, double a, double z0, double z1, double d) {
             return Pocket{s, a, z0, z1, d};
           }),
           py::arg("start_deg"), py::arg("arc_deg"), py::arg("z_min_m"), py::arg("z_max_m"),
           py::arg("depth_m"))
      .def_readwrite("start_deg", &Pocket::start_deg)
      .def_readwrite("arc_deg", &Pocket::arc_deg)
      .def_readwrite("z_min_m", &Pocket::z_min_m)
      .def_readwrite("z_max_m", &Pocket::z_max_m)
      .def_readwrite("depth_m", &Pocket::depth_m);

  py::class_<JournalBearingGeometry>(m, "JournalBearingGeometry", "360° bush, SI units.")
      .def(py::init<>())
      .def_readwrite("diameter_m", &JournalBearingGeometry::diameter_m)
      .def_readwrite("length_m", &JournalBearingGeometry::length_m)
      .def_readwrite("clearance_m", &JournalBearingGeometry::clearance_m)
      .def_readwrite("viscosity_pa_s", &JournalBearingGeometry::viscosity_pa_s)
      .def_readwrite("grooves", &JournalBearingGeometry::grooves)
      .def_readwrite("pockets", &JournalBearingGeometry::pockets,
                     "Recesses (Pocket): the film passed to solve() is without them.")
      .def_readwrite("short_bearing", &JournalBearingGeometry::short_bearing,
                     "Short-bearing (Ocvirk) approximation: no circumferential pressure flow.")
      .def_readwrite("end_seal_conductance", &JournalBearingGeometry::end_seal_conductance,
                     "End-seal conductance G_s, m^2/(Pa s): axial leakage q_z = G_s p per metre "
                     "of circumference at each end (Robin condition); inf (default): open ends.")
      .def_property(
          "turbulence",
          [](const JournalBearingGeometry& g) { return std::string(turbulence_name(g.turbulence)); },
          [](JournalBearingGeometry& g, const std::string& s) { g.turbulence = parse_turbulence(s); },
          "Turbulent lubrication model: 'laminar' (default) or 'ng_pan' (Ng-Pan-Elrod, Taylor & "
          "Dowson 1974 fits), switched on by the local Re_h = rho |omega| R h / mu.")
      .def_readwrite("density_kg_m3", &JournalBearingGeometry::density_kg_m3,
                     "Oil density, kg/m^3 (the film Reynolds number of a turbulent film).")
      .def_readwrite("turbulence_onset_re", &JournalBearingGeometry::turbulence_onset_re,
                     "Re_h at which the turbulent corrections start (transition; NaN: none).")
      .def_readwrite("turbulence_full_re", &JournalBearingGeometry::turbulence_full_re,
                     "Re_h at which the turbulent corrections are full (transition; NaN: none).")
      .def_readwrite("supply_flow_m3_s", &JournalBearingGeometry::supply_flow_m3_s,
                     "Metered supply to the grooves, m^3/s (jfo only; 0: flooded grooves). "
                     "Below the flooded demand the film is starved (reynolds_starved.cpp).")
      .def("validate", &JournalBearingGeometry::validate);

  m.def(
      "turbulence_factors",
      [](const std::string& model, double re, double onset, double full) {
        if (!(std::isfinite(re) && re >= 0.0))
          throw InputError("reynolds_number: expected a finite value >= 0");
        JournalBearingGeometry g;  // the transition's checks
        g.turbulence = parse_turbulence(model);
        g.density_kg_m3 = 1.0;
        g.turbulence_onset_re = onset;
        g.turbulence_full_re = full;
        g.validate();
        const TurbulenceFactors t = turbulence_factors(g.turbulence, re, onset, full);
        return py::make_tuple(t.kx, t.kz, t.cf);
      },
      py::arg("model"), py::arg("reynolds_number"),
      py::arg("onset_re") = std::numeric_limits<double>::quiet_NaN(),
      py::arg("full_re") = std::numeric_limits<double>::quiet_NaN(),
      "(k_x, k_z, C_f) of the turbulent lubrication model at the film Reynolds number Re_h: "
      "Poiseuille coefficients (12 laminar) and the Couette shear factor (1 laminar); with a "
      "transition onset_re < full_re (NaN: none) the turbulent increments take its weight.");
  m.def(
      "turbulence_weight",
      [](double re, double onset, double full) {
        JournalBearingGeometry geo;  // the transition's checks (InputError naming the field)
        geo.turbulence = Turbulence::ng_pan;
        geo.density_kg_m3 = 1.0;
        geo.turbulence_onset_re = onset;
        geo.turbulence_full_re = full;
        geo.validate();
        if (!(std::isfinite(re) && re >= 0.0))
          throw InputError("reynolds_number: expected a finite value >= 0");
        double rg = 0.0;
        const double g = turbulence_weight(re, onset, full, &rg);
        return py::make_tuple(g, rg);
      },
      py::arg("reynolds_number"), py::arg("onset_re"), py::arg("full_re"),
      "(gamma, Re dgamma/dRe): the transition's intermittency weight (cubic smoothstep).");

  py::class_<FilmGrid>(m, "FilmGrid", "n_circ nodes around, n_axial intervals along.")
      .def(py::init<>())
      .def(py::init([](int nc, int na) { return FilmGrid{nc, na}; }), py::arg("n_circ"),
           py::arg("n_axial"))
      .def_readwrite("n_circ", &FilmGrid::n_circ)
      .def_readwrite("n_axial", &FilmGrid::n_axial)
      .def("validate", &FilmGrid::validate);

  py::class_<FilmSolution>(m, "FilmSolution")
      .def_readonly("p_pa", &FilmSolution::p_pa)
      .def_readonly("theta", &FilmSolution::theta)
      .def_readonly("h_m", &FilmSolution::h_m)
      .def_readonly("force_n", &FilmSolution::force_n)
      .def_readonly("friction_torque_nm", &FilmSolution::friction_torque_nm)
      .def_readonly("inlet_flow_m3_s", &FilmSolution::inlet_flow_m3_s)
      .def_readonly("side_flow_m3_s", &FilmSolution::side_flow_m3_s)
      .def_readonly("h_min_m", &FilmSolution::h_min_m)
      .def_readonly("h_min_angle_deg", &FilmSolution::h_min_angle_deg)
      .def_readonly("iterations", &FilmSolution::iterations)
      .def_readonly("inlet_fill", &FilmSolution::inlet_fill,
                    "jfo: the grooves' inlet fill theta_in (1: a full film at the groove)")
      .def_readonly("groove_pressure_factor", &FilmSolution::groove_pressure_factor,
                    "jfo: the fraction of pressure_pa the grooves hold (1 flooded)")
      .def_readonly("starved", &FilmSolution::starved,
                    "jfo: a metered supply below the flooded demand set the groove state")
      .def_readonly("full_film_start_deg", &FilmSolution::full_film_start_deg,
                    "jfo: angle (deg) where the full film starts downstream of the first "
                    "groove, mid-plane row; NaN if none")
      .def_readonly("supply_iterations", &FilmSolution::supply_iterations,
                    "film solves of the metered-supply root (0: flooded)");

  py::class_<DynamicCoefficients>(m, "DynamicCoefficients")
      .def_readonly("K", &DynamicCoefficients::K)
      .def_readonly("C", &DynamicCoefficients::C)
      .def_readonly("force_n", &DynamicCoefficients::force_n);

  py::class_<EquilibriumSolution>(m, "EquilibriumSolution")
      .def_readonly("x_m", &EquilibriumSolution::x_m)
      .def_readonly("y_m", &EquilibriumSolution::y_m)
      .def_readonly("force_n", &EquilibriumSolution::force_n)
      .def_readonly("residual_rel", &EquilibriumSolution::residual_rel)
      .def_readonly("iterations", &EquilibriumSolution::iterations);

  py::class_<BatchResult>(m, "BatchResult",
                          "values (n, m) with NaN rows where status != 0; status 0 ok, 1 bad "
                          "input, 2 contact, 3 not converged, 4 other; message per row.")
      .def_readonly("values", &BatchResult::values)
      .def_readonly("status", &BatchResult::status)
      .def_readonly("message", &BatchResult::message);

  using RS = ReynoldsSolver;
  using gil = py::call_guard<py::gil_scoped_release>;
  py::class_<RS>(m, "ReynoldsSolver",
                 "Finite-length Reynolds solver for one geometry, grid and cavitation model.")
      .def(py::init([](const JournalBearingGeometry& g, const FilmGrid& gr,
                       const std::string& cav) { return new RS(g, gr, parse_cavitation(cav)); }),
           py::arg("geometry"), py::arg("grid"), py::arg("cavitation"))
      .def_property_readonly("cavitation",
                             [](const RS& s) { return std::string(cavitation_name(s.cavitation())); })
      .def_property_readonly("phi_rad", &RS::phi_rad)
      .def_property_readonly("z_m", &RS::z_m)
      .def_property_readonly("n_unknowns", &RS::n_unknowns)
      .def("dirichlet_mask", &RS::dirichlet_mask)
      .def(
          "solve",
          [](RS& s, const RowMatrixXd& h, const RowMatrixXd& dhdt, double omega) {
            py::gil_scoped_release release;
            return s.solve(h, dhdt, omega);  // copy: the solver's buffer is reused
          },
          py::arg("h"), py::arg("dhdt"), py::arg("omega_rad_s"),
          "General film: h, dh/dt (n_circ, n_axial+1), m and m/s. Returns FilmSolution.")
      .def("linearize", &RS::linearize, py::arg("dh"), py::arg("d_dhdt"), gil(),
           "Pressure change (n_circ, n_axial+1) about the last solve for dh, d(dh/dt).")
      .def("integrate_force", &RS::integrate_force, py::arg("p"), gil())
      .def("integrate", &RS::integrate, py::arg("p"), py::arg("g"), gil(),
           "Trapezoidal integral of p*g over the bush surface (R dphi dz), e.g. a sleeve mode's "
           "generalised film force.")
      .def(
          "rigid",
          [](RS& s, double x, double y, double vx, double vy, double omega) {
            py::gil_scoped_release release;
            return s.rigid(x, y, vx, vy, omega);
          },
          py::arg("x_m"), py::arg("y_m"), py::arg("vx_m_s"), py::arg("vy_m_s"),
          py::arg("omega_rad_s"))
      .def(
          "force",
          [](RS& s, double x, double y, double vx, double vy, double omega) {
            py::gil_scoped_release release;
            return Eigen::Vector2d(s.rigid(x, y, vx, vy, omega).force_n);
          },
          py::arg("x_m"), py::arg("y_m"), py::arg("vx_m_s"), py::arg("vy_m_s"),
          py::arg("omega_rad_s"), "Film force (Fx, Fy) on a rigid journal, N.")
      .def("coefficients", &RS::coefficients, py::arg("x_m"), py::arg("y_m"),
           py::arg("omega_rad_s"), gil())
      .def("coefficients_fd", &RS::coefficients_fd, py::arg("x_m"), py::arg("y_m"),
           py::arg("omega_rad_s"), py::arg("rel_step") = 1e-6, gil())
      .def("equilibrium", &RS::equilibrium, py::arg("load_x_n"), py::arg("load_y_n"),
           py::arg("omega_rad_s"), py::arg("x0_m") = 0.0, py::arg("y0_m") = 0.0,
           py::arg("rtol") = 1e-10, py::arg("max_iter") = 60, gil())
      .def("batch_forces", &RS::batch_forces, py::arg("states"), py::arg("omegas_rad_s"),
           py::arg("n_threads") = 1, gil(),
           "states (n, 4) rows x, y, vx, vy; BatchResult.values (n, 2) forces.")
      .def("batch_coefficients", &RS::batch_coefficients, py::arg("positions"),
           py::arg("omegas_rad_s"), py::arg("n_threads") = 1, gil(),
           "positions (n, 2); BatchResult.values (n, 10): Fx Fy Kxx Kxy Kyx Kyy Cxx Cxy Cyx Cyy.")
      .def_property("use_axial_symmetry", &RS::use_axial_symmetry, &RS::set_use_axial_symmetry,
                    "Solve symmetric films on the half grid (exact; default True).")
      .def_property("predict_cavitation", &RS::predict_cavitation, &RS::set_predict_cavitation,
                    "Start the cavitation set from a coarse-grid prediction (default True); "
                    "False: from the empty set (benchmark baseline). Same answer either way.")
      .def_property("pressure_only", &RS::pressure_only, &RS::set_pressure_only,
                    "solve() fills p_pa and h_min only (force, torque, flows NaN; theta, "
                    "h_m empty); the pressures are the same bit for bit (default False).")
      .def_property("band_factor", &RS::band_factor, &RS::set_band_factor,
                    "Factorise in the band when a wholly cavitated ring (or a full-width "
                    "groove) opens the circle (default True); False: always the sparse LDLT. "
                    "The pressures agree to round-off.")
      .def_property("refine_prediction", &RS::refine_prediction, &RS::set_refine_prediction,
                    "Full grid: refine the coarse cavitation-set prediction by projected "
                    "relaxation near the film boundaries (default True); the same pressures "
                    "bit for bit, fewer active-set iterations (testing switch).")
      .def_property_readonly("band_factor_used", &RS::band_factor_used,
                             "Whether the last solve's final factorisation was banded.")
      .def("reset", &RS::reset, "Drop the last solution (solves never depend on earlier calls).")
      .def("set_viscosity", &RS::set_viscosity, py::arg("viscosity_pa_s"),
           "Uniform viscosity, Pa s (drops a viscosity field).")
      .def("set_viscosity_field", &RS::set_viscosity_field, py::arg("viscosity_pa_s"),
           "Viscosity per node (n_circ, n_axial + 1), Pa s: faces take the mean of their "
           "nodes' (the thermo-hydrodynamic film).")
      .def("film_flows", &RS::film_flows,
           "Face flows, fill, dissipation and cell areas of the last solve (FilmFlows).");
  py::class_<FilmFlows>(m, "FilmFlows",
                        "Finite-volume flows (m^3/s) through faces (j+1/2, k) and (j, k+1/2), "
                        "fill, dissipation per cell (W), cell areas (m^2), node viscosities.")
      .def_readonly("q_phi_m3_s", &FilmFlows::q_phi_m3_s)
      .def_readonly("q_z_m3_s", &FilmFlows::q_z_m3_s)
      .def_readonly("fill", &FilmFlows::fill)
      .def_readonly("dissipation_w", &FilmFlows::dissipation_w)
      .def_readonly("area_m2", &FilmFlows::area_m2)
      .def_readonly("viscosity_pa_s", &FilmFlows::viscosity_pa_s)
      .def_readonly("makeup_m3_s", &FilmFlows::makeup_m3_s);
}

}  // namespace rotordyn::py_bind
