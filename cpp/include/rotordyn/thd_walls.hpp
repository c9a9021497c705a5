// Heat paths of a THD film's cells to its walls (thd.hpp; docs/film-physics.md "Heat paths to
// the journal and through the bush or pad"). Per film cell and unit area, with T the film's
// (cross-film mean) temperature, T_J the journal's and T_w the bush (pad) surface temperature:
//
// film side, either given coefficients (the film before the walls had only these)
//   q_J = h_J (T − T_J),  q_B = h_B (T − T_w),
// or the film's own conduction across its thickness h (ThdOptions::film_htc): the cross-film
// profile of a uniform viscous heat source between two walls (the Couette film; Bird, Stewart
// & Lightfoot, Transport Phenomena, 2nd ed., §10.4) is the parabola
//   T(y) = T_J + (T_w − T_J) y/h + S y (h − y)/(2k),  mean T = (T_J + T_w)/2 + S h²/(12k),
// whose wall fluxes in terms of its mean are, per unit area and with the fill θ of the cell,
//   q_J = θ k/h (6 T − 4 T_J − 2 T_w),  q_B = θ k/h (6 T − 2 T_J − 4 T_w)
// (with T_J = T_w: 6 θ k/h (T − T_wall) to each wall, a Nusselt number of 6 on h); a
// turbulent film (turbulence "ng_pan") adds an eddy conductivity: the same relations with the
// symmetric part 6 θ k/h and the across-film part θ k/h raised by the factors G_s, G_c >= 1 at
// the cell's Re_h and Prandtl number (thd_wall_turbulence.hpp; exactly 1 at Re_h = 0);
//
// bush (pad): a fixed surface temperature T_w = T_B, or 1-D conduction through its thickness t
// (conductivity k_b) to its back face, which convects to the surrounding oil at T_o with h_o
// (the plane wall in series with a convective surface: Incropera & DeWitt, Fundamentals of
// Heat and Mass Transfer, §3.1, the overall coefficient U = 1/(t/k_b + 1/h_o)):
//   q_B = U (T_w − T_o)  — eliminates T_w cell by cell (circumferential and axial conduction in
// the bush, its curvature and its deformation are neglected);
//
// journal: a fixed T_J, or one T_J from the journal's heat balance over the whole bearing
// (zero net heat into the journal, which rotates through every part of the film).
//
// Each cell's relations are affine in (T, T_J): CellWall.
#pragma once

#include "rotordyn/reynolds.hpp"

namespace rotordyn {

struct ThdOptions;
struct OilModel;
struct ThdFieldParts;

/// One film cell's heat paths per unit area: W/(m² K) on temperatures in degC, W/m² alone.
///   q_J = kJ T − lJ T_J − nJ    (film → journal)
///   q_B = kB T − lB T_J − nB    (film → bush or pad)
///   T_w = pT T + pJ T_J + p0    (the bush or pad surface temperature)
struct CellWall {
  double kJ = 0.0, lJ = 0.0, nJ = 0.0;
  double kB = 0.0, lB = 0.0, nB = 0.0;
  double pT = 1.0, pJ = 0.0, p0 = 0.0;
};

/// The options' wall model: `legacy` the film with given coefficients to fixed wall
/// temperatures (the energy equation keeps its original arithmetic, bit for bit).
struct WallModel {
  bool legacy = true, film_htc = false, balance = false, conduction = false;
  double hJ = 0.0, hB = 0.0;    ///< given film-side coefficients, W/(m² K)
  double k_oil = 0.0;           ///< W/(m K), film_htc
  double TJ = 0.0, TB = 0.0;    ///< fixed journal and bush temperatures, degC
  double U = 0.0, To = 0.0;     ///< bush conduction: U = 1/(t/k_b + 1/h_o), back oil degC
  /// a turbulent film (film_htc; set_film): the eddy conductivity at each cell's
  /// Re_h = rho_u h/μ and Pr = μ c_p/k (thd_wall_turbulence.hpp)
  Turbulence turbulence = Turbulence::laminar;
  double rho_u = 0.0;           ///< ρ|ω|R of the film's Reynolds number, kg/(m² s)
  /// the film's transition (NaN: none; thd_wall_turbulence.hpp)
  double onset_re = std::numeric_limits<double>::quiet_NaN();
  double full_re = std::numeric_limits<double>::quiet_NaN();
  double cp = 0.0;              ///< the oil's specific heat, J/(kg K)
  /// the film's turbulence (its geometry's model and density, at ω, rad/s): the film-side
  /// coefficients of a turbulent film take the eddy conductivity
  void set_film(const JournalBearingGeometry& geo, double omega, double specific_heat);
  /// the heat paths of a cell with the film thickness h (m), fill θ and viscosity μ (Pa s;
  /// used by a turbulent film only)
  CellWall cell(double h_m, double fill, double mu_pa_s) const;
};

/// The wall model of the options (checked: ThdOptions::validate).
WallModel wall_model(const ThdOptions& opt, const OilModel& oil);

/// A journal from its heat balance: the net heat into the journal from the film's cells of
/// `parts` (an inlet handed over: the film's share of its columns), affine in the inlet's and
/// the journal's temperatures, ja + T_in jb + T_J jc (W), into parts.ja, jb, jc.
void journal_sums(ThdFieldParts& parts, int n_circ, int n_axial_nodes);

/// The wall options' checks (InputError naming the field): called by ThdOptions::validate.
void validate_walls(const ThdOptions& opt, const OilModel& oil);

}  // namespace rotordyn
