// Effective-temperature thermal model (thermal.hpp): oil model, options, the thermal
// equilibrium of a plain film (GIL released: one Reynolds equilibrium per outer iteration).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/thermal.hpp"

namespace rotordyn::py_bind {

void bind_thermal(py::module_& m) {
  py::class_<OilModel>(m, "OilModel",
                       "Oil: viscosity-temperature law (walther: two points (t1_c, nu1_mm2_s), "
                       "(t2_c, nu2_mm2_s); exponential: mu_ref_pa_s, t_ref_c, beta_1_per_k; power: "
                       "mu = a T^b (T in degC) through (t1_c, mu1_pa_s), (t2_c, mu2_pa_s)), "
                       "density, specific heat, the law's range [t_min_c, t_max_c].")
      .def(py::init<>())
      .def_property(
          "law", [](const OilModel& o) { return std::string(viscosity_law_name(o.law)); },
          [](OilModel& o, const std::string& s) { o.law = parse_viscosity_law(s); })
      .def_readwrite("t1_c", &OilModel::t1_c)
      .def_readwrite("nu1_mm2_s", &OilModel::nu1_mm2_s)
      .def_readwrite("t2_c", &OilModel::t2_c)
      .def_readwrite("nu2_mm2_s", &OilModel::nu2_mm2_s)
      .def_readwrite("mu_ref_pa_s", &OilModel::mu_ref_pa_s)
      .def_readwrite("t_ref_c", &OilModel::t_ref_c)
      .def_readwrite("beta_1_per_k", &OilModel::beta_1_per_k)
      .def_readwrite("mu1_pa_s", &OilModel::mu1_pa_s)
      .def_readwrite("mu2_pa_s", &OilModel::mu2_pa_s)
      .def_readwrite("density_kg_m3", &OilModel::density_kg_m3)
      .def_readwrite("specific_heat_j_per_kg_k", &OilModel::specific_heat_j_per_kg_k)
      .def_readwrite("conductivity_w_per_m_k", &OilModel::conductivity_w_per_m_k)
      .def_readwrite("t_min_c", &OilModel::t_min_c)
      .def_readwrite("t_max_c", &OilModel::t_max_c)
      .def("validate", &OilModel::validate)
      .def("viscosity_pa_s", &OilModel::viscosity_pa_s, py::arg("t_c"));

  py::class_<ThermalOptions>(m, "ThermalOptions")
      .def(py::init<>())
      .def_readwrite("supply_temperature_c", &ThermalOptions::supply_temperature_c)
      .def_readwrite("supply_flow_m3_s", &ThermalOptions::supply_flow_m3_s)
      .def_readwrite("carry_over", &ThermalOptions::carry_over)
      .def_readwrite("effective_factor", &ThermalOptions::effective_factor)
      .def_readwrite("tol_k", &ThermalOptions::tol_k)
      .def_readwrite("max_iter", &ThermalOptions::max_iter);

  py::class_<ThermalEquilibrium>(m, "ThermalEquilibrium")
      .def_readonly("equilibrium", &ThermalEquilibrium::equilibrium)
      .def_readonly("coefficients", &ThermalEquilibrium::coefficients)
      .def_readonly("effective_temperature_c", &ThermalEquilibrium::effective_temperature_c)
      .def_readonly("max_temperature_c", &ThermalEquilibrium::max_temperature_c)
      .def_readonly("inlet_temperature_c", &ThermalEquilibrium::inlet_temperature_c)
      .def_readonly("temperature_rise_k", &ThermalEquilibrium::temperature_rise_k)
      .def_readonly("viscosity_pa_s", &ThermalEquilibrium::viscosity_pa_s)
      .def_readonly("power_loss_w", &ThermalEquilibrium::power_loss_w)
      .def_readonly("film_flow_m3_s", &ThermalEquilibrium::film_flow_m3_s)
      .def_readonly("side_flow_m3_s", &ThermalEquilibrium::side_flow_m3_s)
      .def_readonly("supply_flow_m3_s", &ThermalEquilibrium::supply_flow_m3_s)
      .def_readonly("carry_over_effective", &ThermalEquilibrium::carry_over_effective)
      .def_readonly("iterations", &ThermalEquilibrium::iterations)
      .def_readonly("equilibrium_iterations", &ThermalEquilibrium::equilibrium_iterations);

  m.def("thermal_equilibrium", &thermal_equilibrium, py::arg("solver"), py::arg("oil"),
        py::arg("options"), py::arg("load_x_n"), py::arg("load_y_n"), py::arg("omega"),
        py::call_guard<py::gil_scoped_release>(),
        "Effective-temperature equilibrium of a plain film (thermal.hpp); the solver's "
        "viscosity is left at mu(T_eff).");
  py::class_<ThermalFilm>(m, "ThermalFilm")
      .def(py::init<>())
      .def_readwrite("film", &ThermalFilm::film)
      .def_readwrite("oil", &ThermalFilm::oil)
      .def_readwrite("options", &ThermalFilm::options)
      .def_readwrite("thd", &ThermalFilm::thd)
      .def_readwrite("thd_options", &ThermalFilm::thd_options)
      .def_readwrite("upstream", &ThermalFilm::upstream);
  py::class_<ThermalFilmState>(m, "ThermalFilmState")
      .def_readonly("effective_temperature_c", &ThermalFilmState::effective_temperature_c)
      .def_readonly("max_temperature_c", &ThermalFilmState::max_temperature_c)
      .def_readonly("inlet_temperature_c", &ThermalFilmState::inlet_temperature_c)
      .def_readonly("temperature_rise_k", &ThermalFilmState::temperature_rise_k)
      .def_readonly("viscosity_pa_s", &ThermalFilmState::viscosity_pa_s)
      .def_readonly("power_loss_w", &ThermalFilmState::power_loss_w)
      .def_readonly("film_flow_m3_s", &ThermalFilmState::film_flow_m3_s)
      .def_readonly("side_flow_m3_s", &ThermalFilmState::side_flow_m3_s)
      .def_readonly("supply_flow_m3_s", &ThermalFilmState::supply_flow_m3_s)
      .def_readonly("carry_over_effective", &ThermalFilmState::carry_over_effective)
      .def_readonly("starved", &ThermalFilmState::starved)
      .def_readonly("mean_temperature_c", &ThermalFilmState::mean_temperature_c)
      .def_readonly("temperature_c", &ThermalFilmState::temperature_c)
      .def_readonly("viscosity_field", &ThermalFilmState::viscosity_field)
      .def_readonly("recirculation_flow_m3_s", &ThermalFilmState::recirculation_flow_m3_s)
      .def_readonly("recirculation_temperature_c",
                    &ThermalFilmState::recirculation_temperature_c)
      .def_readonly("inlet_mask", &ThermalFilmState::inlet_mask)
      .def_readonly("flows", &ThermalFilmState::flows)
      .def_readonly("heat_to_journal_w", &ThermalFilmState::heat_to_journal_w)
      .def_readonly("heat_to_bush_w", &ThermalFilmState::heat_to_bush_w)
      .def_readonly("journal_temperature_c", &ThermalFilmState::journal_temperature_c)
      .def_readonly("max_wall_temperature_c", &ThermalFilmState::max_wall_temperature_c)
      .def_readonly("wall_temperature_c", &ThermalFilmState::wall_temperature_c)
      .def_readonly("side_temperature_c", &ThermalFilmState::side_temperature_c)
      .def_readonly("friction_power_w", &ThermalFilmState::friction_power_w);
  py::class_<ThermalSystemResult>(m, "ThermalSystemResult")
      .def_readonly("equilibrium", &ThermalSystemResult::equilibrium)
      .def_readonly("films", &ThermalSystemResult::films)
      .def_readonly("viscosities", &ThermalSystemResult::viscosities)
      .def_readonly("iterations", &ThermalSystemResult::iterations);
  m.def("thermal_system_equilibrium", &thermal_system_equilibrium, py::arg("model"),
        py::arg("thermal"), py::arg("omega"), py::arg("chamber_pressure"), py::arg("a"),
        py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "System equilibrium iterated with the heat balance of the thermal films (thermal.hpp).");
  m.def("max_film_flow", &max_film_flow, py::arg("solver"), py::arg("solution"),
        py::arg("omega"), "Flow across the film's line of maximum thickness, m^3/s.");
}

}  // namespace rotordyn::py_bind
