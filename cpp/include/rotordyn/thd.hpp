// Thermo-hydrodynamic (THD) film of a plain journal bearing (issue 20; docs/film-physics.md
// §"Thermo-hydrodynamic film"): an energy equation for the film temperature T(φ, z) (averaged
// across the film thickness) on the Reynolds grid, the viscosity μ(T) at every node, iterated
// with the Reynolds equilibrium in one call.
//
// Energy equation (steady, per node cell P of area A_P, finite volumes on the Reynolds cells):
//   ρ c_p Σ_{faces f into P} |F_f| (T_P − T_f,up) + (h_J + h_B) A_P T_P
//       = Φ_P + A_P (h_J T_J + h_B T_B),
// F_f the Reynolds solution's volume flows through the cell faces (circumferential Couette +
// Poiseuille, axial Poiseuille; in a cavitated zone only the Couette streamers, FilmFlows),
// T_f,up the upwind node's temperature, Φ_P = ∫ (μU²θ/h + h³|∇p|²/(12μ)) dA the viscous
// dissipation, h_J, h_B heat-transfer coefficients to journal and bush (0: adiabatic) at
// temperatures T_J, T_B. Conduction within the film plane is neglected (convection-dominated,
// Péclet ≫ 1). An end cell whose internal faces give a net inflow (side inflow) draws ambient
// oil at the supply temperature.
// Inlet: the supply-groove nodes (with a groove) or the column of maximum film (without one)
// hold the mixing temperature T_in = (Q_f T_s + λ Q_r T_r)/(Q_f + λ Q_r): the fresh flow Q_f
// (supply_flow_m3_s; 0: the film's demand Q − λ Q_r; a metered Q_f below it draws more hot oil,
// λ_eff = (Q − Q_f)/Q_r, starved when Q_f + Q_r < Q) at T_s mixed with the carried-over part λ
// (carry_over) of the flow Q_r reaching the inlet from the film at its mixing-cup temperature
// T_r (solved exactly: T is affine in T_in). The same mixing as the effective model.
#pragma once
#include <limits>
#include <vector>

#include "rotordyn/thermal.hpp"
#include "rotordyn/thd_walls.hpp"

namespace rotordyn {

// ThdOptions (supply, carry-over, heat-transfer coefficients): thermal.hpp.


/// The film's thermal state at one Reynolds solution.
struct ThdFilmState {
  RowMatrixXd temperature_c;    ///< (n_circ, n_axial + 1), degC
  RowMatrixXd inlet_mask;       ///< 1 on the nodes held at the inlet temperature
  FilmFlows flows;              ///< the flows and dissipation of the energy equation
  double max_temperature_c = 0.0, mean_temperature_c = 0.0;  ///< mean: area-weighted
  double inlet_temperature_c = 0.0;
  double recirculation_temperature_c = 0.0;  ///< T_r, mixing-cup of the flow reaching the inlet
  double side_temperature_c = 0.0;           ///< mixing-cup of the side leakage
  double power_loss_w = 0.0;       ///< Σ Φ (the energy equation's dissipation)
  double friction_power_w = 0.0;   ///< torque·|ω| (the Reynolds solution's friction)
  double film_flow_m3_s = 0.0;     ///< Q, from the inlet nodes into the film
  double recirculation_flow_m3_s = 0.0;  ///< Q_r, from the film into the inlet nodes (a pad film: Q_in − Q_s, the pad's mass balance)
  double side_flow_m3_s = 0.0;     ///< through the ends from the film's end cells
  double supply_flow_m3_s = 0.0;   ///< Q_f (fresh oil)
  /// λ_eff, the carried-over fraction of Q_r the inlet mixes (the given λ, or (Q − Q_f)/Q_r
  /// where a metered supply falls short of the demand); `starved`: Q_f + Q_r < Q
  double carry_over_effective = 0.0;
  bool starved = false;
  double heat_to_journal_w = 0.0, heat_to_bush_w = 0.0;
  /// the journal's temperature (journal_temperature_c, or from its heat balance), degC
  double journal_temperature_c = 0.0;
  /// the bush (pad) surface temperature, degC (n_circ, n_axial + 1): the given bush
  /// temperature, the conducting bush's surface, or the film's own where no heat crosses
  /// (adiabatic); inlet nodes: the film's. Its maximum over the film's cells.
  RowMatrixXd wall_temperature_c;
  double max_wall_temperature_c = 0.0;
};

/// The energy equation at the solver's last (full-output) solution `sol` at ω (rad/s).
ThdFilmState thd_energy(const ReynoldsSolver& solver, const FilmSolution& sol,
                        const OilModel& oil, const ThdOptions& opt, double omega);

/// The energy equation's solution before the inlet temperature is known: the field is affine
/// in it, T = X0 + T_in X1, and so is the mixing-cup temperature of the flow Q_r that leaves
/// the film into the inlet nodes, Q_r T_r = ta + T_in tb. `pad`: a pad film (tilting pad,
/// lobe of a fixed-geometry bearing; the pressure-prescribed gap between its trailing and
/// leading edges is the inlet): the trailing-edge column is the pad's last cell, not inlet,
/// and Q_r is the hot oil the pad passes on to the next pad's inlet.
struct ThdFieldParts {
  FilmFlows flows;
  std::vector<char> inlet;       ///< (n_nodes,) 1 on the inlet nodes
  std::vector<double> side_out;  ///< (n_nodes,) flow leaving through the ends, m³/s
  std::vector<double> makeup;    ///< (n_nodes,) inlet-gap oil a trailing-edge cell draws, m³/s
  Eigen::VectorXd X0, X1;        ///< (n_nodes,) degC, degC/degC
  /// a journal from its heat balance (ThdOptions::journal_balance): T = X0 + T_in X1 + T_J X2,
  /// Q_r T_r = ta + T_in tb + T_J tc, and the net heat into the journal from the film's cells
  /// (W) ja + T_in jb + T_J jc; otherwise X2 empty and tc = ja = jb = jc = 0
  Eigen::VectorXd X2;
  double Q = 0.0;                ///< from the inlet into the film, m³/s
  double Qr = 0.0;               ///< from the film into the inlet (pad: Q − Σ side_out), m³/s
  double ta = 0.0, tb = 0.0;     ///< Q_r T_r = ta + T_in tb (+ T_J tc); a pad: with the heat
                                 ///< its trailing-edge make-up picks up, Σ m (T − T_in)
  double tc = 0.0, ja = 0.0, jb = 0.0, jc = 0.0;
  /// an ungrooved plain film: the heat its inlet cells (the inlet column at the film's peak,
  /// their inlet_mask share) add to the oil passing them, their dissipation minus their wall
  /// exchange at T_in, si0 + T_in si1 + T_J si2 (W; si2 with journal_balance), a source in
  /// the inlet mixing (thd_energy); and the heat the side flows carry out, Σ side_out T =
  /// so0 + T_in so1 + T_J so2 (W/(ρc)), blended per solve (exact for a handed-over inlet)
  double si0 = 0.0, si1 = 0.0, si2 = 0.0, so0 = 0.0, so1 = 0.0, so2 = 0.0;
  std::vector<CellWall> walls;   ///< (n_nodes,) each cell's heat paths (thd_walls.hpp)
  bool pad = false;
  /// a plain film with supply grooves: the groove nodes (`inlet`) are not film — a supply
  /// groove is deep, its shear small; the grid has no groove depth, so the film's thickness
  /// would over-state it — so, as a pad's gap, their dissipation is in neither the power
  /// loss nor the heat balance, and their walls exchange nothing
  bool grooved = false;
  /// an ungrooved film's inlet handed over to a neighbour column (thd_field): that column
  /// (-1: none) and its weight w in (0, 1/2]; the parts are the blend (1 − w) · inlet at
  /// the `inlet` column + w · inlet at this one
  int blend_column = -1;
  double blend_weight = 0.0;
};
ThdFieldParts thd_field(const ReynoldsSolver& solver, const FilmSolution& sol,
                        const OilModel& oil, const ThdOptions& opt, double omega, bool pad);
/// The film's state at the inlet temperature T_in (degC) with the fresh flow Q_f (m³/s).
/// A pad film's mean, maximum and power loss cover the pad's cells only (not the gap).
/// `t_journal_c`: the journal's temperature from its heat balance (journal_balance; NaN
/// otherwise: the fixed journal temperature).
ThdFilmState thd_state(ThdFieldParts&& parts, const FilmSolution& sol, const ThdOptions& opt,
                       double omega, double t_in_c, double supply_flow_m3_s,
                       double t_journal_c = std::numeric_limits<double>::quiet_NaN());

struct ThdEquilibrium {
  EquilibriumSolution equilibrium;   ///< under the load with the viscosity field μ(T)
  DynamicCoefficients coefficients;  ///< K, C at it, the temperature (viscosity) field frozen
  ThdFilmState film;
  int iterations = 0;                ///< outer iterations (one warm-started equilibrium each)
  int equilibrium_iterations = 0;
};

/// THD equilibrium of a rigid journal under the load (N) at ω: the viscosity field μ(T) and
/// the equilibrium iterated (Anderson-accelerated fixed point on the node temperatures) to
/// max |ΔT| <= tol_k. The solver keeps the final viscosity field. ConvergenceError when the
/// iteration does not settle or a temperature leaves the law's range.
ThdEquilibrium thd_equilibrium(ReynoldsSolver& solver, const OilModel& oil,
                               const ThdOptions& opt, double load_x_n, double load_y_n,
                               double omega);

/// The residual of a THD fixed-point step, max |min(G, t_max_c) − T| (K): the iterates T are
/// held in the law's range, so a film whose energy equation asks for more than t_max_c at a
/// node held there has settled at that clamped point (the caller's range check then names
/// t_max_c) instead of never settling.
double thd_residual_k(const Eigen::Ref<const Eigen::VectorXd>& G,
                      const Eigen::Ref<const Eigen::VectorXd>& T, double t_max_c);

}  // namespace rotordyn
