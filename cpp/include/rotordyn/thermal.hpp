// Effective-temperature thermal model of a plain journal film (issue 20; docs/film-physics.md):
// a global (adiabatic) heat balance iterated with the Reynolds equilibrium, one unit of work.
//
// Viscosity–temperature laws (OilModel):
//   walther     ASTM D341 (Walther): log10 log10(ν + 0.7) = A − B log10(T + 273.15), ν in
//               mm²/s, A and B from two points (t1_c, nu1), (t2_c, nu2) (e.g. an ISO VG grade's
//               40 °C and 100 °C viscosities); μ = ρ ν.
//   exponential μ = mu_ref exp(−beta (T − t_ref_c)).
//   power       μ = a T^b with T in °C (the law of ROSS's thermal bearings), a and b through
//               two points (t1_c, mu1_pa_s), (t2_c, mu2_pa_s); needs T > 0 °C (t_min_c > 0).
// Heat balance (the Raimondi–Boyd/Shigley assumptions, with hot-oil carry-over): the film draws
// Q (with supply grooves: the flow they deliver into the film; without: the flow into the film
// just downstream of its line of maximum thickness, max_film_flow) and leaks Q_s at its ends; the leakage leaves at the mean rise ΔT/2, the rest Q − Q_s at ΔT, all the friction
// power P = torque·|ω| goes into the oil:  P = ρ c_p ΔT (Q − Q_s/2).
// At the supply, the fraction λ (carry_over) of the recirculating hot flow Q_r = Q − Q_s mixes
// with the supply flow Q_f at T_s (supply_flow_m3_s; 0: the film's own demand Q − λ Q_r;
// a metered Q_f below that demand draws more hot oil, λ_eff = (Q − Q_f)/Q_r, and a film with
// Q_f + Q_r < Q is starved: StarvedError, thermal_detail.hpp supply_mixing):
//   T_in = T_s + λ_eff Q_r ΔT / Q_f,  T_max = T_in + ΔT,  T_eff = T_in + k ΔT
// (k = effective_factor, 0.5: Shigley's average film temperature). The film is isoviscous at
// μ(T_eff).
#pragma once
#include <limits>

#include "rotordyn/reynolds.hpp"
#include "rotordyn/system.hpp"

namespace rotordyn {

enum class ViscosityLaw { walther = 0, exponential = 1, power = 2 };
ViscosityLaw parse_viscosity_law(const std::string& name);  // "walther" | "exponential" | "power"
const char* viscosity_law_name(ViscosityLaw law);

struct OilModel {
  ViscosityLaw law = ViscosityLaw::walther;
  double t1_c = 40.0, nu1_mm2_s = 32.0;    ///< walther: first point (ISO VG 32 at 40 °C)
  double t2_c = 100.0, nu2_mm2_s = 5.4;    ///< walther: second point (t2_c > t1_c)
  double mu_ref_pa_s = 0.03, t_ref_c = 40.0, beta_1_per_k = 0.03;  ///< exponential
  double mu1_pa_s = 0.0278, mu2_pa_s = 0.0047;  ///< power: μ at t1_c, t2_c (VG 32: ρν)
  double density_kg_m3 = 870.0;
  double specific_heat_j_per_kg_k = 2000.0;
  /// thermal conductivity k, W/(m K) (a mineral oil: 0.13); used by the THD film's
  /// cross-film conduction to its walls (ThdOptions::film_htc)
  double conductivity_w_per_m_k = 0.13;
  double t_min_c = -20.0, t_max_c = 200.0;  ///< range of the law (supply and film temperatures)
  /// InputError naming the field: positive properties, a law that falls with temperature,
  /// a valid range.
  void validate() const;
  double viscosity_pa_s(double t_c) const;  ///< μ(T), Pa·s
};

struct ThermalOptions {
  double supply_temperature_c = 40.0;
  double supply_flow_m3_s = 0.0;   ///< 0: the film's own demand
  double carry_over = 0.0;         ///< λ in [0, 1]
  double effective_factor = 0.5;   ///< k in [0.5, 1]
  double tol_k = 1e-6;             ///< on the effective temperature, K
  int max_iter = 60;
  void validate(const OilModel& oil) const;
};

struct ThermalEquilibrium {
  EquilibriumSolution equilibrium;   ///< at μ(T_eff)
  DynamicCoefficients coefficients;  ///< K, C at it, temperature frozen
  double effective_temperature_c = 0.0, max_temperature_c = 0.0, inlet_temperature_c = 0.0;
  double temperature_rise_k = 0.0;   ///< ΔT
  double viscosity_pa_s = 0.0;       ///< μ(T_eff)
  double power_loss_w = 0.0;
  double film_flow_m3_s = 0.0;       ///< Q (groove inflow, or downstream of the maximum film)
  double side_flow_m3_s = 0.0;       ///< Q_s
  double supply_flow_m3_s = 0.0;     ///< Q_f (fresh oil)
  /// λ_eff: the carried-over fraction of Q_r the inlet mixes — the given λ, or (Q − Q_f)/Q_r
  /// where a metered supply falls short of the demand Q − λ Q_r
  double carry_over_effective = 0.0;
  int iterations = 0;                ///< outer (equilibrium) iterations
  int equilibrium_iterations = 0;    ///< Newton iterations summed
};

/// Thermal equilibrium of a rigid journal under the load (N, on the journal) at ω (rad/s):
/// the film's viscosity is set to μ(T_eff) and the equilibrium, the heat balance and T_eff are
/// iterated to |ΔT_eff| <= tol_k (each step solves the heat balance exactly for the
/// temperature at the current journal position, where P ∝ μ and the flows do not depend on μ
/// for a laminar film). K, C are the perturbation coefficients at the thermal equilibrium with
/// the temperature (viscosity) frozen. The solver's viscosity is left at μ(T_eff).
/// ConvergenceError when the iteration does not settle or T leaves the law's range.
ThermalEquilibrium thermal_equilibrium(ReynoldsSolver& solver, const OilModel& oil,
                                       const ThermalOptions& opt, double load_x_n,
                                       double load_y_n, double omega);

/// Flow into the film just downstream of its line of maximum thickness (mid-plane row), m³/s
/// (> 0 for either sense of rotation): the film's conservative flux through the face after
/// the maximum-film node, Σ_k [(|ω|R/2) h_f θ − h_f³/(k_x μ R Δφ) Δp] Δz (trapezoidal along
/// z; without the pressure term for the short-bearing model, which neglects the
/// circumferential pressure flow). With the supply line at the maximum film this is Raimondi &
/// Boyd's Q.
double max_film_flow(const ReynoldsSolver& solver, const FilmSolution& sol, double omega);

/// Options of the thermo-hydrodynamic film (thd.hpp): supply, carry-over, heat transfer.
struct ThdOptions {
  double supply_temperature_c = 40.0;
  double supply_flow_m3_s = 0.0;   ///< 0: the film's own demand
  double carry_over = 0.0;         ///< λ in [0, 1]
  double journal_htc_w_m2k = 0.0;  ///< h_J >= 0 (0: adiabatic journal)
  double bush_htc_w_m2k = 0.0;     ///< h_B >= 0 (0: adiabatic bush)
  /// T_J, T_B, degC; NaN: the supply temperature.
  double journal_temperature_c = std::numeric_limits<double>::quiet_NaN();
  double bush_temperature_c = std::numeric_limits<double>::quiet_NaN();
  // The walls' own heat paths (thd_walls.hpp; docs/film-physics.md "Heat paths to the
  // journal and through the bush or pad"):
  /// the film-side coefficient of each wall from the film's own conduction across its
  /// thickness, q = θ k/h (6 T − 4 T_wall − 2 T_other wall) per cell (the parabolic cross-film
  /// profile of a uniform viscous heat source; k the oil's conductivity), instead of the
  /// given journal_htc_w_m2k, bush_htc_w_m2k (which must then be 0); a turbulent film's
  /// eddy conductivity raises them (thd_wall_turbulence.hpp)
  bool film_htc = false;
  /// with film_htc on a turbulent film: the eddy conductivity raises the film-side
  /// coefficients (thd_wall_turbulence.hpp); false: the laminar film's conduction alone (the
  /// lower bound of the wall heat the turbulent film had before; for comparisons)
  bool wall_eddy_conductivity = true;
  /// the journal's temperature from its own heat balance: zero net heat flux into the
  /// journal over the whole bearing (all its films), instead of journal_temperature_c
  bool journal_balance = false;
  /// the bush (pad) surface temperature from 1-D conduction through the bush (pad) to its
  /// back face, which loses heat to the surrounding oil: q_B = U (T_w − T_o),
  /// 1/U = t/k + 1/h_o, instead of a fixed bush_temperature_c
  bool bush_conduction = false;
  double bush_thickness_m = 0.0;              ///< t >= 0
  double bush_conductivity_w_per_m_k = 0.0;   ///< k >= 0 (0: an insulating bush)
  double back_htc_w_m2k = 0.0;                ///< h_o >= 0 (0: an insulated back face)
  double back_temperature_c = std::numeric_limits<double>::quiet_NaN();  ///< T_o; NaN: T_s
  double tol_k = 1e-6;             ///< on max |ΔT| over the nodes between iterations, K
  int max_iter = 200;
  void validate(const OilModel& oil) const;  ///< InputError naming the field
};


/// A film of a system (SystemModel::films[film]) under the effective-temperature model
/// (thd = false; options) or the thermo-hydrodynamic film (thd = true; thd_options, thd.hpp).
struct ThermalFilm {
  int film = 0;
  OilModel oil;
  ThermalOptions options;
  bool thd = false;
  ThdOptions thd_options;  ///< used when thd
  /// THD pad films (tilting pads, lobes): the index into the thermal list of the film whose
  /// trailing-edge hot oil reaches this film's inlet (the upstream pad in the direction of
  /// rotation), with the film marked as a pad (thd_field). The inlet temperature mixes the
  /// fresh flow Q_f at T_s with the carried-over part λ (thd_options.carry_over) of the
  /// upstream pad's outflow Q_r,u at its mixing-cup temperature T_r,u (Ettles' hot-oil
  /// carry-over): T_in = (Q_f T_s + λ Q_r,u T_r,u)/(Q_f + λ Q_r,u), Q_f the pad's demand
  /// Q − λ Q_r,u (or thd_options.supply_flow_m3_s when > 0); when λ Q_r,u exceeds the demand
  /// the pad draws Q of the carried-over oil alone; a metered Q_f below the demand draws
  /// Q − Q_f of it (λ_eff), starved when that exceeds Q_r,u (thermal_detail.hpp
  /// supply_mixing). The ring's inlet temperatures are solved together (a small linear
  /// system: each field is affine in its T_in). −1: a plain film mixing its own
  /// recirculation.
  /// Effective-temperature pad films (thd = false, upstream >= 0 an effective pad film): per
  /// pad the plain heat balance P = ρ c ΔT (Q − Q_s/2) with the pad's dissipation P, the flow
  /// Q into its leading edge and its side leakage Q_s (the THD pad film's flows and cells),
  /// T_out = T_in + ΔT, T_eff = T_in + k ΔT, the pad isoviscous at μ(T_eff); the inlet mixes
  /// λ (options.carry_over) of the upstream pad's outflow Q_out,u = Q_u − Q_s,u (its own mass
  /// balance, as the plain model's Q_r) at T_out,u with fresh oil by the same rule (Q_f from options.supply_flow_m3_s). The ring is solved exactly at each
  /// position (the heat balance of every pad, Gauss–Seidel around the ring).
  int upstream = -1;
};

/// The thermal state of one film at the system's thermal equilibrium (as ThermalEquilibrium).
struct ThermalFilmState {
  double effective_temperature_c = 0.0, max_temperature_c = 0.0, inlet_temperature_c = 0.0;
  double temperature_rise_k = 0.0, viscosity_pa_s = 0.0, power_loss_w = 0.0;
  double film_flow_m3_s = 0.0, side_flow_m3_s = 0.0, supply_flow_m3_s = 0.0;
  /// λ_eff, the carried-over fraction of the hot flow reaching the inlet (the given λ, or
  /// (Q − Q_f)/Q_r where a metered supply falls short of the demand); `starved`: Q_f + Q_r < Q
  /// (no equilibrium of the full film is reported from such a state)
  double carry_over_effective = 0.0;
  bool starved = false;
  /// THD films: the area-weighted mean temperature (also in effective_temperature_c), the
  /// temperature and viscosity fields (n_circ, n_axial + 1); temperature_rise_k = T_max − T_in,
  /// viscosity_pa_s = μ(mean). Empty fields for effective-temperature films.
  double mean_temperature_c = 0.0;
  RowMatrixXd temperature_c, viscosity_field;
  /// THD films: the flow into the inlet nodes (plain: back to the groove; pad: the hot oil
  /// passed on to the next pad) and its mixing-cup temperature; the inlet nodes; the film's
  /// face flows and cell dissipation (the energy balance's terms).
  double recirculation_flow_m3_s = 0.0, recirculation_temperature_c = 0.0;
  RowMatrixXd inlet_mask;
  FilmFlows flows;
  /// THD films: the heat the film gives its walls (W), the journal's temperature (fixed, or
  /// from the journal's heat balance), the bush (pad) surface temperature field and its
  /// maximum over the film's cells (ThdFilmState)
  double heat_to_journal_w = 0.0, heat_to_bush_w = 0.0;
  double journal_temperature_c = 0.0, max_wall_temperature_c = 0.0;
  RowMatrixXd wall_temperature_c;
  /// THD films: the mixing-cup temperature of the side leakage (degC) and the Reynolds
  /// solution's friction power torque·|ω| (W) (ThdFilmState); 0 for effective films.
  double side_temperature_c = 0.0, friction_power_w = 0.0;
};

struct ThermalSystemResult {
  EquilibriumResult equilibrium;        ///< of the model at the films' μ(T_eff)
  std::vector<ThermalFilmState> films;  ///< one per ThermalFilm, same order
  std::vector<double> viscosities;      ///< per model film, Pa·s (the thermal ones changed)
  int iterations = 0;                   ///< outer iterations (one system equilibrium each)
};

/// Thermal equilibrium of a system: the system equilibrium (SystemSolver::equilibrium, eq. 14)
/// iterated with each thermal film's heat balance (each film's viscosity set to μ(T_eff); the
/// heat balance of a film solved exactly for its temperature at the current position, as in
/// thermal_equilibrium) until every |ΔT_eff| <= its tol_k. A system equilibrium that does not
/// converge ends the iteration with its status (never a thermal answer from it). The
/// dynamics at the thermal equilibrium are the model's with `viscosities` (temperature frozen).
ThermalSystemResult thermal_system_equilibrium(const SystemModel& model,
                                               const std::vector<ThermalFilm>& thermal,
                                               double omega, double chamber_pressure,
                                               const Eigen::VectorXd& a,
                                               const EquilibriumOptions& options);

}  // namespace rotordyn
