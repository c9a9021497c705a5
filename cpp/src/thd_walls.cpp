// Heat paths of a THD film's cells to the journal and the bush or pad (thd_walls.hpp).
#include "rotordyn/thd_walls.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "rotordyn/errors.hpp"
#include "rotordyn/thd.hpp"
#include "rotordyn/thd_wall_turbulence.hpp"
#include "rotordyn/thermal.hpp"
#include "thermal_detail.hpp"

namespace rotordyn {

namespace {
void nonneg(double v, const std::string& field, const char* unit) {
  if (!(std::isfinite(v) && v >= 0.0))
    throw InputError(field + ": expected a finite value >= 0 " + unit + ", got " + num(v));
}
}  // namespace

void validate_walls(const ThdOptions& o, const OilModel& oil) {
  nonneg(o.bush_thickness_m, "bush_thickness_m", "m");
  nonneg(o.bush_conductivity_w_per_m_k, "bush_conductivity_w_per_m_k", "W/(m K)");
  nonneg(o.back_htc_w_m2k, "back_htc_w_m2k", "W/(m^2 K) (0: an insulated back face)");
  if (!std::isnan(o.back_temperature_c) &&
      !(std::isfinite(o.back_temperature_c) && o.back_temperature_c > -273.15))
    throw InputError("back_temperature_c: expected a temperature > -273.15 degC (NaN: the "
                     "supply temperature), got " + num(o.back_temperature_c));
  if (o.film_htc) {
    for (auto [v, f] : {std::pair{o.journal_htc_w_m2k, "journal_htc_w_m2k"},
                        std::pair{o.bush_htc_w_m2k, "bush_htc_w_m2k"}})
      if (v != 0.0)
        throw InputError(std::string(f) + ": expected 0 with wall_htc = 'film' (the film's "
                         "own conduction sets the film-side coefficients), got " + num(v));
    if (!(oil.conductivity_w_per_m_k > 0.0))
      throw InputError("oil.conductivity_w_per_m_k: expected > 0 W/(m K) with wall_htc = "
                       "'film', got " + num(oil.conductivity_w_per_m_k));
  }
  if (o.journal_balance) {
    if (!std::isnan(o.journal_temperature_c))
      throw InputError("journal_temperature_c: not used with journal_wall = 'balance' (the "
                       "journal's temperature follows from its heat balance), got " +
                       num(o.journal_temperature_c));
    if (!o.film_htc && !(o.journal_htc_w_m2k > 0.0))
      throw InputError("journal_htc_w_m2k: expected > 0 with journal_wall = 'balance' (or "
                       "wall_htc = 'film'): a journal without heat transfer has no heat "
                       "balance, got " + num(o.journal_htc_w_m2k));
  }
  if (o.bush_conduction) {
    if (!std::isnan(o.bush_temperature_c))
      throw InputError("bush_temperature_c: not used with bush_wall = 'conduction' (the "
                       "surface temperature follows from the conduction; the back face's oil "
                       "is back_temperature_c), got " + num(o.bush_temperature_c));
  } else {
    for (auto [v, f] : {std::pair{o.bush_thickness_m, "bush_thickness_m"},
                        std::pair{o.bush_conductivity_w_per_m_k, "bush_conductivity_w_per_m_k"},
                        std::pair{o.back_htc_w_m2k, "back_htc_w_m2k"}})
      if (v != 0.0)
        throw InputError(std::string(f) + ": used only with bush_wall = 'conduction', got " +
                         num(v));
    if (!std::isnan(o.back_temperature_c))
      throw InputError("back_temperature_c: used only with bush_wall = 'conduction', got " +
                       num(o.back_temperature_c));
  }
}

namespace {
// the share of node n whose journal heat the balance counts: a pad film's cells (not the
// gap), a grooved film's (not the groove); every node of an ungrooved plain film (its inlet
// cells' exchange at T_in, which the blended X gives them, is the inlet source's share,
// thd_field)
double film_share(const ThdFieldParts& p, int n, int K1) {
  if (!p.pad && !p.grooved) return 1.0;
  if (p.blend_column >= 0 && n / K1 == p.blend_column) return 1.0 - p.blend_weight;
  return p.inlet[static_cast<std::size_t>(n)] ? p.blend_weight : 1.0;
}

}  // namespace

// the net heat into the journal from the film's cells, affine in (T_in, T_J): ja + T_in jb +
// T_J jc (W), with T = X0 + T_in X1 + T_J X2 and q_J = kJ T − lJ T_J − nJ per area
void journal_sums(ThdFieldParts& p, int N, int K1) {
  const double* A = p.flows.area_m2.data();
  p.ja = p.jb = p.jc = 0.0;
  for (int n = 0; n < N * K1; ++n) {
    const double wf = film_share(p, n, K1);
    if (!(wf > 0.0)) continue;
    const CellWall& w = p.walls[static_cast<std::size_t>(n)];
    p.ja += wf * A[n] * (w.kJ * p.X0[n] - w.nJ);
    p.jb += wf * A[n] * w.kJ * p.X1[n];
    p.jc += wf * A[n] * (w.kJ * p.X2[n] - w.lJ);
  }
}

WallModel wall_model(const ThdOptions& o, const OilModel& oil) {
  WallModel w;
  const double Ts = o.supply_temperature_c;
  w.film_htc = o.film_htc;
  w.balance = o.journal_balance;
  w.conduction = o.bush_conduction;
  w.legacy = !(w.film_htc || w.balance || w.conduction);
  w.hJ = o.journal_htc_w_m2k;
  w.hB = o.bush_htc_w_m2k;
  w.k_oil = oil.conductivity_w_per_m_k;
  w.TJ = std::isnan(o.journal_temperature_c) ? Ts : o.journal_temperature_c;
  w.TB = std::isnan(o.bush_temperature_c) ? Ts : o.bush_temperature_c;
  w.To = std::isnan(o.back_temperature_c) ? Ts : o.back_temperature_c;
  if (w.conduction) {
    // 1/U = t/k + 1/h_o: no path through an insulating bush (k = 0, t > 0) or an insulated
    // back face (h_o = 0); a wall of no thickness passes what its back face takes
    const double t = o.bush_thickness_m, k = o.bush_conductivity_w_per_m_k,
                 ho = o.back_htc_w_m2k;
    if (ho > 0.0 && (k > 0.0 || t == 0.0))
      w.U = 1.0 / ((t > 0.0 ? t / k : 0.0) + 1.0 / ho);
  }
  return w;
}

void WallModel::set_film(const JournalBearingGeometry& geo, double omega,
                         double specific_heat) {
  turbulence = geo.turbulence;
  onset_re = geo.turbulence_onset_re;
  full_re = geo.turbulence_full_re;
  rho_u = geo.turbulence == Turbulence::laminar
              ? 0.0 : geo.density_kg_m3 * std::abs(omega) * 0.5 * geo.diameter_m;
  cp = specific_heat;
}

CellWall WallModel::cell(double h_m, double fill, double mu) const {
  // film side: q_J = aJ T − bJJ T_J − bJB T_w, q_B = aB T − bBJ T_J − bBB T_w
  double aJ = hJ, bJJ = hJ, bJB = 0.0, aB = hB, bBJ = 0.0, bBB = hB;
  if (film_htc) {
    const double c = h_m > 0.0 ? fill * k_oil / h_m : 0.0;
    // a turbulent film: the eddy conductivity's factors at the cell's Re_h and Pr
    TurbulentWallFactors g;
    if (turbulence != Turbulence::laminar && rho_u > 0.0 && c > 0.0)
      g = turbulent_wall_factors(turbulence, rho_u * h_m / mu, mu * cp / k_oil, onset_re,
                                 full_re);
    if (g.symmetric == 1.0 && g.across == 1.0) {  // the laminar film's arithmetic
      aJ = aB = 6.0 * c;
      bJJ = bBB = 4.0 * c;
      bJB = bBJ = 2.0 * c;
    } else {  // q_J = H_s (T − (T_J + T_w)/2) + K_c (T_w − T_J), q_B likewise with − K_c
      const double Hs = 6.0 * c * g.symmetric, Kc = c * g.across;
      aJ = aB = Hs;
      bJJ = bBB = 0.5 * Hs + Kc;
      bJB = bBJ = 0.5 * Hs - Kc;
    }
  }
  CellWall w;
  // the surface temperature T_w = pT T + pJ T_J + p0
  if (conduction) {  // aB T − bBJ T_J − bBB T_w = U (T_w − T_o)
    const double den = bBB + U;
    if (den > 0.0) {
      w.pT = aB / den;
      w.pJ = -bBJ / den;
      w.p0 = U * To / den;
    }  // else no heat crosses: the surface at the film's temperature (pT = 1)
  } else if (aB != 0.0 || bBB != 0.0 || bBJ != 0.0) {
    w.pT = 0.0;
    w.p0 = TB;
  }
  w.kB = aB - bBB * w.pT;
  w.lB = bBJ + bBB * w.pJ;
  w.nB = bBB * w.p0;
  w.kJ = aJ - bJB * w.pT;
  w.lJ = bJJ + bJB * w.pJ;
  w.nJ = bJB * w.p0;
  return w;
}

}  // namespace rotordyn
