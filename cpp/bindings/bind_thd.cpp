// Thermo-hydrodynamic film (thd.hpp): options, the film's thermal state, the THD equilibrium of
// a plain film (GIL released: one Reynolds equilibrium and one energy solve per iteration).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/thd.hpp"
#include "rotordyn/thd_wall_turbulence.hpp"

namespace rotordyn::py_bind {

void bind_thd(py::module_& m) {
  py::class_<ThdOptions>(m, "ThdOptions")
      .def(py::init<>())
      .def_readwrite("supply_temperature_c", &ThdOptions::supply_temperature_c)
      .def_readwrite("supply_flow_m3_s", &ThdOptions::supply_flow_m3_s)
      .def_readwrite("carry_over", &ThdOptions::carry_over)
      .def_readwrite("journal_htc_w_m2k", &ThdOptions::journal_htc_w_m2k)
      .def_readwrite("bush_htc_w_m2k", &ThdOptions::bush_htc_w_m2k)
      .def_readwrite("journal_temperature_c", &ThdOptions::journal_temperature_c)
      .def_readwrite("bush_temperature_c", &ThdOptions::bush_temperature_c)
      .def_readwrite("film_htc", &ThdOptions::film_htc)
      .def_readwrite("wall_eddy_conductivity", &ThdOptions::wall_eddy_conductivity)
      .def_readwrite("journal_balance", &ThdOptions::journal_balance)
      .def_readwrite("bush_conduction", &ThdOptions::bush_conduction)
      .def_readwrite("bush_thickness_m", &ThdOptions::bush_thickness_m)
      .def_readwrite("bush_conductivity_w_per_m_k", &ThdOptions::bush_conductivity_w_per_m_k)
      .def_readwrite("back_htc_w_m2k", &ThdOptions::back_htc_w_m2k)
      .def_readwrite("back_temperature_c", &ThdOptions::back_temperature_c)
      .def_readwrite("tol_k", &ThdOptions::tol_k)
      .def_readwrite("max_iter", &ThdOptions::max_iter)
      .def("validate", &ThdOptions::validate, py::arg("oil"));
  py::class_<ThdFilmState>(m, "ThdFilmState")
      .def_readonly("temperature_c", &ThdFilmState::temperature_c)
      .def_readonly("inlet_mask", &ThdFilmState::inlet_mask)
      .def_readonly("flows", &ThdFilmState::flows)
      .def_readonly("max_temperature_c", &ThdFilmState::max_temperature_c)
      .def_readonly("mean_temperature_c", &ThdFilmState::mean_temperature_c)
      .def_readonly("inlet_temperature_c", &ThdFilmState::inlet_temperature_c)
      .def_readonly("recirculation_temperature_c", &ThdFilmState::recirculation_temperature_c)
      .def_readonly("side_temperature_c", &ThdFilmState::side_temperature_c)
      .def_readonly("power_loss_w", &ThdFilmState::power_loss_w)
      .def_readonly("friction_power_w", &ThdFilmState::friction_power_w)
      .def_readonly("film_flow_m3_s", &ThdFilmState::film_flow_m3_s)
      .def_readonly("recirculation_flow_m3_s", &ThdFilmState::recirculation_flow_m3_s)
      .def_readonly("side_flow_m3_s", &ThdFilmState::side_flow_m3_s)
      .def_readonly("supply_flow_m3_s", &ThdFilmState::supply_flow_m3_s)
      .def_readonly("carry_over_effective", &ThdFilmState::carry_over_effective)
      .def_readonly("heat_to_journal_w", &ThdFilmState::heat_to_journal_w)
      .def_readonly("heat_to_bush_w", &ThdFilmState::heat_to_bush_w)
      .def_readonly("journal_temperature_c", &ThdFilmState::journal_temperature_c)
      .def_readonly("wall_temperature_c", &ThdFilmState::wall_temperature_c)
      .def_readonly("max_wall_temperature_c", &ThdFilmState::max_wall_temperature_c);
  py::class_<ThdEquilibrium>(m, "ThdEquilibrium")
      .def_readonly("equilibrium", &ThdEquilibrium::equilibrium)
      .def_readonly("coefficients", &ThdEquilibrium::coefficients)
      .def_readonly("film", &ThdEquilibrium::film)
      .def_readonly("iterations", &ThdEquilibrium::iterations)
      .def_readonly("equilibrium_iterations", &ThdEquilibrium::equilibrium_iterations);
  m.def("thd_equilibrium", &thd_equilibrium, py::arg("solver"), py::arg("oil"),
        py::arg("options"), py::arg("load_x_n"), py::arg("load_y_n"), py::arg("omega"),
        py::call_guard<py::gil_scoped_release>(),
        "Thermo-hydrodynamic equilibrium of a plain film (thd.hpp); the solver keeps the "
        "final viscosity field.");
  m.def("thd_energy", &thd_energy, py::arg("solver"), py::arg("solution"), py::arg("oil"),
        py::arg("options"), py::arg("omega"), py::call_guard<py::gil_scoped_release>(),
        "The THD energy equation at the solver's last full solve.");
  m.def(
      "turbulent_wall_factors",
      [](const std::string& model, double re, double pr, double onset, double full) {
        if (!(std::isnan(onset) && std::isnan(full))) {  // the transition's checks
          JournalBearingGeometry geo;
          geo.turbulence = parse_turbulence(model);
          geo.density_kg_m3 = 1.0;
          geo.turbulence_onset_re = onset;
          geo.turbulence_full_re = full;
          geo.validate();
        }
        const TurbulentWallFactors g =
            turbulent_wall_factors(parse_turbulence(model), re, pr, onset, full);
        return py::make_tuple(g.symmetric, g.across);
      },
      py::arg("model"), py::arg("reynolds_number"), py::arg("prandtl_number"),
      py::arg("onset_re") = std::numeric_limits<double>::quiet_NaN(),
      py::arg("full_re") = std::numeric_limits<double>::quiet_NaN(),
      "(G_s, G_c): the eddy conductivity's factors on a THD film's wall coefficients "
      "(thd_wall_turbulence.hpp) at Re_h and the molecular Prandtl number.");
  m.def(
      "eddy_wall_factors",
      [](double a, double p) {
        const TurbulentWallFactors g = eddy_wall_factors(a, p);
        return py::make_tuple(g.symmetric, g.across);
      },
      py::arg("half_film_plus"), py::arg("prandtl_ratio"),
      "(G_s, G_c) at the half film in wall units h+/2 and Pr/Pr_t.");
  m.def("eddy_couette_shear_factor", &eddy_couette_shear_factor, py::arg("reynolds_number"),
        "The Reichardt eddy model's own Couette shear factor at Re_h.");
  m.attr("TURBULENT_PRANDTL") = kTurbulentPrandtl;
}

}  // namespace rotordyn::py_bind
