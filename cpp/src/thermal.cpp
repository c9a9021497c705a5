// Effective-temperature thermal model (thermal.hpp): viscosity laws, the heat balance and its
// iteration with the Reynolds equilibrium.
#include "rotordyn/thermal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "rotordyn/errors.hpp"
#include "thermal_detail.hpp"

namespace rotordyn {

namespace {
constexpr double kKelvin = 273.15;

void positive(double v, const char* field) {
  if (!(std::isfinite(v) && v > 0.0))
    throw InputError(std::string(field) + ": expected a finite value > 0, got " + num(v));
}

double walther_w(double nu) { return std::log10(std::log10(nu + 0.7)); }
}  // namespace

ViscosityLaw parse_viscosity_law(const std::string& name) {
  if (name == "walther") return ViscosityLaw::walther;
  if (name == "exponential") return ViscosityLaw::exponential;
  if (name == "power") return ViscosityLaw::power;
  throw InputError("viscosity_law: expected 'walther', 'exponential' or 'power', got '" + name +
                   "'");
}

const char* viscosity_law_name(ViscosityLaw law) {
  switch (law) {
    case ViscosityLaw::walther: return "walther";
    case ViscosityLaw::exponential: return "exponential";
    case ViscosityLaw::power: return "power";
  }
  return "walther";
}

void OilModel::validate() const {
  positive(density_kg_m3, "density_kg_m3");
  positive(specific_heat_j_per_kg_k, "specific_heat_j_per_kg_k");
  if (!(std::isfinite(conductivity_w_per_m_k) && conductivity_w_per_m_k >= 0.0))
    throw InputError("conductivity_w_per_m_k: expected a finite value >= 0 W/(m K), got " +
                     num(conductivity_w_per_m_k));
  if (!(std::isfinite(t_min_c) && std::isfinite(t_max_c) && t_min_c > -kKelvin &&
        t_min_c < t_max_c))
    throw InputError("t_min_c, t_max_c: expected -273.15 < t_min_c < t_max_c (the viscosity "
                     "law's range, degC), got " + num(t_min_c) + ", " + num(t_max_c));
  if (law == ViscosityLaw::walther) {
    if (!std::isfinite(t1_c) || t1_c <= -kKelvin)
      throw InputError("t1_c: expected a finite temperature > -273.15 degC, got " + num(t1_c));
    if (!(std::isfinite(t2_c) && t2_c > t1_c))
      throw InputError("t2_c: expected a temperature > t1_c = " + num(t1_c) + " degC, got " +
                       num(t2_c));
    // Walther's double logarithm needs ν + 0.7 > 1
    if (!(std::isfinite(nu1_mm2_s) && nu1_mm2_s > 0.3))
      throw InputError("nu1_mm2_s: expected a kinematic viscosity > 0.3 mm^2/s, got " +
                       num(nu1_mm2_s));
    if (!(std::isfinite(nu2_mm2_s) && nu2_mm2_s > 0.3))
      throw InputError("nu2_mm2_s: expected a kinematic viscosity > 0.3 mm^2/s, got " +
                       num(nu2_mm2_s));
    if (!(nu2_mm2_s < nu1_mm2_s))
      throw InputError("nu2_mm2_s: expected a viscosity below nu1_mm2_s = " + num(nu1_mm2_s) +
                       " mm^2/s (the viscosity must fall with temperature: t2_c > t1_c), got " +
                       num(nu2_mm2_s));
  } else if (law == ViscosityLaw::power) {
    // μ = a T^b with T in degC: both points and the whole range above 0 degC
    if (!(std::isfinite(t1_c) && t1_c > 0.0))
      throw InputError("t1_c: expected a temperature > 0 degC (the power law mu = a T^b takes T "
                       "in degC), got " + num(t1_c));
    if (!(std::isfinite(t2_c) && t2_c > t1_c))
      throw InputError("t2_c: expected a temperature > t1_c = " + num(t1_c) + " degC, got " +
                       num(t2_c));
    positive(mu1_pa_s, "mu1_pa_s");
    positive(mu2_pa_s, "mu2_pa_s");
    if (!(mu2_pa_s < mu1_pa_s))
      throw InputError("mu2_pa_s: expected a viscosity below mu1_pa_s = " + num(mu1_pa_s) +
                       " Pa s (the viscosity must fall with temperature: t2_c > t1_c), got " +
                       num(mu2_pa_s));
    if (!(t_min_c > 0.0))
      throw InputError("t_min_c: expected > 0 degC for the power law (mu = a T^b, T in degC), "
                       "got " + num(t_min_c));
  } else {
    positive(mu_ref_pa_s, "mu_ref_pa_s");
    if (!std::isfinite(t_ref_c))
      throw InputError("t_ref_c: expected a finite temperature, got " + num(t_ref_c));
    if (!(std::isfinite(beta_1_per_k) && beta_1_per_k > 0.0 && beta_1_per_k < 1.0))
      throw InputError("beta_1_per_k: expected 0 < beta_1_per_k < 1 1/K (the viscosity must "
                       "fall with temperature), got " + num(beta_1_per_k));
  }
}

double OilModel::viscosity_pa_s(double t_c) const {
  if (law == ViscosityLaw::exponential) return mu_ref_pa_s * std::exp(-beta_1_per_k * (t_c - t_ref_c));
  if (law == ViscosityLaw::power) {
    const double b = std::log(mu2_pa_s / mu1_pa_s) / std::log(t2_c / t1_c);
    return mu1_pa_s * std::pow(t_c / t1_c, b);
  }
  const double l1 = std::log10(t1_c + kKelvin), l2 = std::log10(t2_c + kKelvin);
  const double B = (walther_w(nu1_mm2_s) - walther_w(nu2_mm2_s)) / (l2 - l1);
  const double A = walther_w(nu1_mm2_s) + B * l1;
  const double w = A - B * std::log10(t_c + kKelvin);
  const double nu = std::pow(10.0, std::pow(10.0, w)) - 0.7;  // mm²/s
  return density_kg_m3 * nu * 1e-6;
}

void validate_supply(const OilModel& oil, double supply_temperature_c, double supply_flow_m3_s,
                     double carry_over) {
  if (!(std::isfinite(supply_temperature_c) && supply_temperature_c >= oil.t_min_c &&
        supply_temperature_c < oil.t_max_c))
    throw InputError("supply_temperature_c: expected a temperature in the viscosity law's "
                     "range [t_min_c, t_max_c) = [" + num(oil.t_min_c) + ", " +
                     num(oil.t_max_c) + ") degC, got " + num(supply_temperature_c));
  if (!(std::isfinite(supply_flow_m3_s) && supply_flow_m3_s >= 0.0))
    throw InputError("supply_flow_m3_s: expected >= 0 (0: the film's own demand), got " +
                     num(supply_flow_m3_s));
  if (!(carry_over >= 0.0 && carry_over <= 1.0))
    throw InputError("carry_over: expected 0 <= carry_over <= 1, got " + num(carry_over));
}

void check_film_density(const JournalBearingGeometry& g, const OilModel& oil,
                        const std::string& where) {
  if (g.turbulence == Turbulence::laminar) return;
  if (!(std::abs(g.density_kg_m3 - oil.density_kg_m3) <= 1e-9 * oil.density_kg_m3))
    throw InputError(where + "density_kg_m3: a turbulent film's density (its Reynolds number "
                     "rho |omega| R h / mu) must be the thermal oil's, oil.density_kg_m3 = " +
                     num(oil.density_kg_m3) + " kg/m^3 (one oil: give both the same value), "
                     "got " + num(g.density_kg_m3));
}

void ThermalOptions::validate(const OilModel& oil) const {
  validate_supply(oil, supply_temperature_c, supply_flow_m3_s, carry_over);
  if (!(effective_factor >= 0.5 && effective_factor <= 1.0))
    throw InputError("effective_factor: expected 0.5 <= effective_factor <= 1, got " +
                     num(effective_factor));
  if (!(tol_k >= 1e-12 && tol_k <= 1.0))
    throw InputError("tol_k: expected 1e-12 <= tol_k <= 1 K, got " + num(tol_k));
  if (!(max_iter >= 1 && max_iter <= 1000))
    throw InputError("max_iter: expected 1 <= max_iter <= 1000, got " + std::to_string(max_iter));
}

double max_film_flow(const ReynoldsSolver& solver, const FilmSolution& sol, double omega) {
  const JournalBearingGeometry& g = solver.geometry();
  const int N = static_cast<int>(sol.h_m.rows()), K1 = static_cast<int>(sol.h_m.cols());
  if (N == 0) throw InputError("max_film_flow: the solution has no film fields");
  const int kmid = (K1 - 1) / 2;
  int jmax = 0;
  for (int j = 1; j < N; ++j)
    if (sol.h_m(j, kmid) > sol.h_m(jmax, kmid)) jmax = j;
  const double R = 0.5 * g.diameter_m, dphi = 2.0 * 3.14159265358979323846 / N;
  const double dz = g.length_m / (K1 - 1), mu = g.viscosity_pa_s;
  const double re_per_h = g.turbulence == Turbulence::laminar
                              ? 0.0 : g.density_kg_m3 * std::abs(omega) * R / mu;
  // The film's conservative flux through the face from node j to its downstream neighbour
  // (mean-of-nodes h, the upwind fill, the face's conductance), > 0 downstream.
  const int sd = omega >= 0.0 ? 1 : N - 1;  // downstream index step (mod N)
  auto face_flux = [&](int j) {
    const int jd = (j + sd) % N;
    double q = 0.0;
    for (int k = 0; k < K1; ++k) {
      const double wk = (k == 0 || k == K1 - 1) ? 0.5 : 1.0;
      const double hf = 0.5 * (sol.h_m(j, k) + sol.h_m(jd, k));
      double flux = 0.5 * std::abs(omega) * R * hf * sol.theta(j, k);
      if (!g.short_bearing) {  // the short-bearing model has no circumferential pressure flow
        const double kx = turbulence_factors(g.turbulence, re_per_h * hf,
                                             g.turbulence_onset_re, g.turbulence_full_re).kx;
        flux -= hf * hf * hf / (kx * mu * R * dphi) * (sol.p_pa(jd, k) - sol.p_pa(j, k));
      }
      q += wk * flux;
    }
    return q * dz;
  };
  // The maximum film's position between nodes (parabola through the three mid-row nodes,
  // offset d in [-1/2, 1/2] node spacings downstream) and the flux half a spacing downstream
  // of it, interpolated linearly between the faces: a continuous function of the journal
  // position (the node of the maximum jumps; a flux taken at that node's face jumps with it
  // and made the thermal iteration cycle between two states on coarse grids).
  const int jm = (jmax + N - 1) % N, jp = (jmax + 1) % N;
  const double hm = sol.h_m(jm, kmid), h0 = sol.h_m(jmax, kmid), hp = sol.h_m(jp, kmid);
  const double curv = hm - 2.0 * h0 + hp;
  double d = curv < 0.0 ? 0.5 * (hm - hp) / curv : 0.0;  // + index direction
  d = std::clamp(omega >= 0.0 ? d : -d, -0.5, 0.5);       // downstream
  const int ju = (jmax + N - sd) % N;                     // upstream neighbour
  return d < 0.0 ? face_flux(ju) + (d + 1.0) * (face_flux(jmax) - face_flux(ju))
                 : face_flux(jmax) + d * (face_flux((jmax + sd) % N) - face_flux(jmax));
}

// The film's temperature at a fixed position (P ∝ μ, flows independent of μ): the root of
// T − Ts − m a μ(T), a = P/(μ ρ c (Q − Q_s/2)), m = λ Q_r/Q_f + k (bracketed secant/bisection).
ThermalFilmState heat_balance(const OilModel& oil, const ThermalOptions& opt, double mu,
                              double P, double Q, double Qs, const std::string& name) {
  const double rc = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k;
  const double denom = Q - 0.5 * Qs;
  if (!(P > 0.0 && Q > 0.0 && Qs >= 0.0 && denom > 0.0)) {
    std::ostringstream os;
    os << "thermal equilibrium" << (name.empty() ? "" : ", film '" + name + "'")
       << ": power loss " << P << " W, flow " << Q
       << " m^3/s and side flow " << Qs << " m^3/s give no heat balance";
    throw ConvergenceError(os.str());
  }
  const double Ts = opt.supply_temperature_c;
  const double Qr = std::max(Q - Qs, 0.0);
  const std::string where =
      "thermal equilibrium" + (name.empty() ? std::string() : ", film '" + name + "'");
  const SupplyMixing mix =
      checked_supply_mixing(where, Q, Qr, opt.carry_over, opt.supply_flow_m3_s);
  const double Qf = mix.qf;
  const double m = mix.carried / Qf + opt.effective_factor;
  const double a = P / (mu * rc * denom);
  auto g = [&](double t) { return t - Ts - m * a * oil.viscosity_pa_s(t); };
  double lo = Ts, hi = std::min(Ts + m * a * oil.viscosity_pa_s(Ts), oil.t_max_c);
  double glo = g(lo), ghi = g(hi);
  if (ghi < 0.0 && hi < oil.t_max_c) {  // a rise near round-off (huge c_p): widen by ulps
    hi = std::min(Ts + 2.0 * (hi - Ts) + 8.0 * std::numeric_limits<double>::epsilon() *
                                             std::max(1.0, std::abs(Ts)), oil.t_max_c);
    ghi = g(hi);
  }
  if (ghi < 0.0) {
    if (mix.starved) throw StarvedError(starved_message(where, Qf, Q, Qr));
    throw ConvergenceError(where + ": the film temperature exceeds the viscosity law's range "
                           "(t_max_c = " + num(oil.t_max_c) + " degC)");
  }
  for (int k = 0; k < 200 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++k) {
    double t = hi - ghi * (hi - lo) / (ghi - glo);
    if (!(t > lo && t < hi) || k % 3 == 2) t = 0.5 * (lo + hi);
    const double gt = g(t);
    if (gt == 0.0) {
      lo = hi = t;
      break;
    }
    if (gt < 0.0) {
      lo = t;
      glo = gt;
    } else {
      hi = t;
      ghi = gt;
    }
  }
  ThermalFilmState st;
  st.effective_temperature_c = 0.5 * (lo + hi);  // the new temperature
  st.temperature_rise_k = P / (rc * denom);       // ΔT at μ
  st.inlet_temperature_c = Ts + mix.carried * st.temperature_rise_k / Qf;
  st.max_temperature_c = st.inlet_temperature_c + st.temperature_rise_k;
  st.viscosity_pa_s = mu;
  st.power_loss_w = P;
  st.film_flow_m3_s = Q;
  st.side_flow_m3_s = Qs;
  st.supply_flow_m3_s = Qf;
  st.carry_over_effective = mix.lam_eff;
  st.starved = mix.starved;
  return st;
}

std::string starved_message(const std::string& where, double Qf, double Q, double Qr) {
  return where + ": starved: the metered supply Q_f = " + num(Qf) + " m^3/s and all the hot "
         "oil reaching the inlet Q_r = " + num(Qr) + " m^3/s fall short of the flow the film "
         "draws, Q = " + num(Q) + " m^3/s; the shortfall at this state, Q - Q_r = " +
         num(Q - Qr) + " m^3/s, estimates the supply it needs (not a bound: the flows move "
         "with the temperature and the journal); a starved film's reduced wetted arc is not "
         "modelled";
}

ThermalEquilibrium thermal_equilibrium(ReynoldsSolver& solver, const OilModel& oil,
                                       const ThermalOptions& opt, double lx, double ly,
                                       double omega) {
  oil.validate();
  opt.validate(oil);
  check_film_density(solver.geometry(), oil, "");
  if (!(std::isfinite(omega) && omega != 0.0))
    throw InputError("speed_hz: the thermal equilibrium needs a nonzero speed");
  const double Ts = opt.supply_temperature_c;
  ThermalEquilibrium out;
  std::string starved;  // the last iterate's, when starved (its failure is the starvation)
  double T = Ts, x = 0.0, y = 0.0;
  double T_prev = Ts, f_prev = std::numeric_limits<double>::quiet_NaN();
  for (int it = 1; it <= opt.max_iter; ++it) {
    const double mu = oil.viscosity_pa_s(T);
    solver.set_viscosity(mu);
    const EquilibriumSolution eq = solver.equilibrium(lx, ly, omega, x, y);
    out.equilibrium_iterations += eq.iterations;
    x = eq.x_m;
    y = eq.y_m;
    const FilmSolution& sol = solver.rigid(x, y, 0.0, 0.0, omega);
    const double P = sol.friction_torque_nm * omega;  // > 0 for either sense
    // Q: with supply grooves, the flow they deliver into the film (Raimondi & Boyd's Q when
    // the supply line sits at the maximum film); without, the flux just downstream of the
    // maximum film (above Raimondi & Boyd's Q: +0.2 % at L/D = 1/4, +5.5 % at L/D = 1, ε = 0.6)
    const double qg = sol.inlet_flow_m3_s;
    const double Q = solver.geometry().grooves.empty() || !(qg > 0.0)
                         ? max_film_flow(solver, sol, omega) : qg;
    const double Qs = sol.side_flow_m3_s;
    const ThermalFilmState st = heat_balance(oil, opt, mu, P, Q, Qs, "");
    const double Tn = st.effective_temperature_c;  // the heat balance's temperature at this position
    out.iterations = it;
    starved = st.starved ? starved_message("thermal equilibrium", st.supply_flow_m3_s, Q,
                                           std::max(Q - Qs, 0.0)) : std::string();
    if (std::abs(Tn - T) <= opt.tol_k) {
      if (st.starved) throw StarvedError(starved);  // no equilibrium of the full film
      out.equilibrium = eq;
      out.coefficients = solver.coefficients(x, y, omega);
      out.viscosity_pa_s = mu;
      out.effective_temperature_c = T;
      out.temperature_rise_k = st.temperature_rise_k;
      out.inlet_temperature_c = st.inlet_temperature_c;
      out.max_temperature_c = st.max_temperature_c;
      out.power_loss_w = P;
      out.film_flow_m3_s = Q;
      out.side_flow_m3_s = Qs;
      out.supply_flow_m3_s = st.supply_flow_m3_s;
      out.carry_over_effective = st.carry_over_effective;
      if (!(out.max_temperature_c <= oil.t_max_c))
        throw ConvergenceError("thermal equilibrium: the maximum film temperature " +
                               num(out.max_temperature_c) + " degC exceeds the viscosity "
                               "law's range (t_max_c = " + num(oil.t_max_c) + " degC)");
      return out;
    }
    // Next temperature: the fixed-point map T -> G(T) = Tn, accelerated by the secant step on
    // f(T) = G(T) - T once two iterates exist (safeguarded: inside the law's range and
    // between the supply temperature and twice the last step; else the plain map).
    const double f = Tn - T;
    double Tnext = Tn;
    if (it > 1 && std::isfinite(f_prev) && f != f_prev) {
      const double ts = T - f * (T - T_prev) / (f - f_prev);
      if (std::isfinite(ts) && ts > Ts && ts < oil.t_max_c && std::abs(ts - T) <= 4.0 * std::abs(f))
        Tnext = ts;
    }
    T_prev = T;
    f_prev = f;
    T = Tnext;
  }
  if (!starved.empty()) throw StarvedError(starved);
  throw ConvergenceError("thermal equilibrium: the effective temperature did not settle to " +
                         num(opt.tol_k) + " K in " + std::to_string(opt.max_iter) +
                         " iterations");
}

}  // namespace rotordyn
