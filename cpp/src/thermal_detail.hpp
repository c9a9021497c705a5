// Internal to the thermal model (thermal.cpp, thermal_system.cpp, thd.cpp, thd_walls.cpp): the
// heat balance of one film (the number format of its messages: format_detail.hpp).
#pragma once

#include <Eigen/Dense>

#include <sstream>
#include <string>
#include <vector>

#include "format_detail.hpp"
#include "rotordyn/reynolds.hpp"
#include "rotordyn/thermal.hpp"

namespace rotordyn {

using format_detail::num;  // a number in the thermal films' error messages

/// The supply's checks shared by the effective-temperature and THD options: the supply
/// temperature inside the viscosity law's range, a fresh flow >= 0, 0 <= carry_over <= 1.
/// InputError naming the field.
void validate_supply(const OilModel& oil, double supply_temperature_c, double supply_flow_m3_s,
                     double carry_over);

/// The oil a film's inlet mixes (docs/film-physics.md "A metered supply below the film's
/// demand"): the film draws Q; the hot flow Q_r reaches its inlet (a plain film's own
/// recirculation, a pad's: the upstream pad's outflow); λ the given carry-over.
/// * no metered supply (metered <= 0): Q_f = Q − λ Q_r, the film's own demand; when λ Q_r
///   exceeds Q the film draws Q of hot oil alone (Q_f = 0, carried = Q);
/// * metered Q_f with Q_f + λ Q_r >= Q: carried = λ Q_r; the surplus Q_f + λ Q_r − Q mixes
///   at the inlet (it cools T_in) and leaves there, not through the film;
/// * metered Q_f with Q_f + λ Q_r < Q: the shortfall is made up by more hot oil, carried =
///   Q − Q_f (λ_eff = carried / Q_r): Q T_in = Q_f T_s + carried T_r, mass-conserving;
/// * starved when carried > Q_r (Q_f + Q_r < Q; also Q_r = 0): more hot oil than reaches the
///   inlet — the mixing is still carried = Q − Q_f (a continuation, so that an iterate can
///   pass through), but no equilibrium of the full film may be reported from it.
struct SupplyMixing {
  double qf = 0.0;        ///< fresh flow mixed at T_s, m³/s
  double carried = 0.0;   ///< hot flow mixed at T_r, m³/s
  double lam_eff = 0.0;   ///< carried / Q_r (exactly the given λ where that is carried)
  bool made_up = false;   ///< a metered supply's shortfall made up by hot oil
  bool starved = false;
};
/// `Qr_avail` (default Q_r): the hot oil that may make up a shortfall — a THD plain film's
/// flux into its inlet may exceed what the film keeps, Q − Q_s (the oil a Swift–Stieber film
/// adds where it reforms is no supply), so it passes min(Q_r, Q − Q_s): starved when
/// carried > Q_r_avail.
inline SupplyMixing supply_mixing(double Q, double Qr, double lam, double metered,
                                  double Qr_avail = -1.0) {
  if (Qr_avail < 0.0) Qr_avail = Qr;
  SupplyMixing s;
  s.carried = Qr > 0.0 ? lam * Qr : 0.0;
  s.qf = metered > 0.0 ? metered : Q - s.carried;
  s.lam_eff = lam;
  if (!(metered > 0.0) && s.qf < 0.0) {  // more hot oil than the film draws
    s.carried = Q;
    s.qf = 0.0;
    s.lam_eff = Q / Qr;
  }
  if (metered > 0.0 && s.qf + s.carried < Q) {  // the shortfall: more hot oil
    s.carried = Q - s.qf;
    s.starved = !(s.carried <= Qr_avail);
    s.made_up = true;
    if (Qr > 0.0) s.lam_eff = s.carried / Qr;
  }
  return s;
}

/// The message of a starved film (StarvedError): its metered supply Q_f, the flow it draws Q,
/// the hot flow reaching its inlet Q_r and the shortfall at this state, Q − Q_r (an estimate
/// of the supply it needs, not a bound: the equilibrium at another supply has other flows).
std::string starved_message(const std::string& where, double Qf, double Q, double Qr);

/// supply_mixing, with the one starvation that has no continuation: no hot oil at all reaches
/// the inlet (Q_r <= 0), so λ_eff is undefined — StarvedError (starved_message at `where`,
/// with Qr_avail), at once; a starved film with Q_r > 0 is returned flagged (the iteration
/// passes through it and reports "starved" if it ends there).
inline SupplyMixing checked_supply_mixing(const std::string& where, double Q, double Qr,
                                          double lam, double metered, double Qr_avail = -1.0) {
  const SupplyMixing s = supply_mixing(Q, Qr, lam, metered, Qr_avail);
  if (s.starved && !(Qr > 0.0))
    throw StarvedError(starved_message(where, s.qf, Q, Qr_avail < 0.0 ? Qr : Qr_avail));
  return s;
}

/// A turbulent film's density (its Reynolds number ρ|ω|R h/μ) and the thermal oil's (the heat
/// balance, the Walther law's μ = ρν) are one oil's: InputError naming `where` +
/// "density_kg_m3" when they differ by more than 1e-9 relative. A laminar film's density is
/// not used and not checked.
void check_film_density(const JournalBearingGeometry& g, const OilModel& oil,
                        const std::string& where);

/// The film's effective temperature at a fixed journal position (P ∝ μ, flows independent of
/// μ): the root of T − Ts − m a μ(T), a = P/(μ ρ c (Q − Q_s/2)), m = λ Q_r/Q_f + k, with the
/// temperature rise, inlet and maximum temperatures and the fresh supply flow. ``mu`` (Pa·s)
/// the viscosity P (W) was computed with; Q, Q_s (m³/s) the film and side flows; ``name`` the
/// film's name in messages ("" for a standalone bearing). Throws ConvergenceError when the
/// flows give no heat balance or the temperature leaves the viscosity law's range.
ThermalFilmState heat_balance(const OilModel& oil, const ThermalOptions& opt, double mu,
                              double P, double Q, double Qs, const std::string& name);

/// Anderson acceleration (depth 3) of a fixed point x = G(x) (the THD node temperatures):
/// next(x, G(x)) returns the next iterate; the history restarts when the residual grows.
class AndersonMixer {
 public:
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
    const Eigen::VectorXd f = g - x;
    const double res = f.cwiseAbs().maxCoeff();
    if (res > 2.0 * res_prev_) {
      dF_.clear();
      dG_.clear();
    } else if (f_prev_.size() == f.size()) {
      dF_.push_back(f - f_prev_);
      dG_.push_back(g - g_prev_);
      if (dF_.size() > 3) {
        dF_.erase(dF_.begin());
        dG_.erase(dG_.begin());
      }
    }
    f_prev_ = f;
    g_prev_ = g;
    res_prev_ = res;
    if (dF_.empty()) return g;
    const int m = static_cast<int>(dF_.size());
    Eigen::MatrixXd Fm(f.size(), m), Gm(f.size(), m);
    for (int i = 0; i < m; ++i) {
      Fm.col(i) = dF_[static_cast<std::size_t>(i)];
      Gm.col(i) = dG_[static_cast<std::size_t>(i)];
    }
    const Eigen::VectorXd gam = Fm.colPivHouseholderQr().solve(f);
    return gam.allFinite() ? Eigen::VectorXd(g - Gm * gam) : g;
  }

 private:
  std::vector<Eigen::VectorXd> dF_, dG_;
  Eigen::VectorXd f_prev_, g_prev_;
  double res_prev_ = 1e300;
};

}  // namespace rotordyn
