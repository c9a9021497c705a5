// Thermal equilibrium of a system (thermal.hpp): the system equilibrium iterated with the
// heat balance of each thermal film.
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "rotordyn/errors.hpp"
#include "rotordyn/thd.hpp"
#include "rotordyn/thermal.hpp"
#include "thermal_detail.hpp"

namespace rotordyn {

namespace {
// A THD film's solution as the film's state and its slice [o, o + nn) of the fixed-point map
// GX; true when the slice moved by at most the film's tol_k from the iterate X.
bool take_thd_state(const ThdFilmState& ts, const ThermalFilm& tf, const Eigen::VectorXd& X,
                    int o, int nn, Eigen::VectorXd& GX, ThermalFilmState& st) {
  // the clamped map (the iterates stay in the law's range): a film hotter than t_max_c
  // settles at nodes held there, and the range check names it (thd_residual_k)
  const Eigen::Map<const Eigen::VectorXd> G(ts.temperature_c.data(), nn);
  const double res = thd_residual_k(G, X.segment(o, nn), tf.oil.t_max_c);
  GX.segment(o, nn) = G.cwiseMin(tf.oil.t_max_c);
  st.mean_temperature_c = st.effective_temperature_c = ts.mean_temperature_c;
  st.max_temperature_c = ts.max_temperature_c;
  st.inlet_temperature_c = ts.inlet_temperature_c;
  st.temperature_rise_k = ts.max_temperature_c - ts.inlet_temperature_c;
  st.viscosity_pa_s = tf.oil.viscosity_pa_s(ts.mean_temperature_c);
  st.power_loss_w = ts.power_loss_w;
  st.film_flow_m3_s = ts.film_flow_m3_s;
  st.side_flow_m3_s = ts.side_flow_m3_s;
  st.supply_flow_m3_s = ts.supply_flow_m3_s;
  st.carry_over_effective = ts.carry_over_effective;
  st.starved = ts.starved;
  st.recirculation_flow_m3_s = ts.recirculation_flow_m3_s;
  st.recirculation_temperature_c = ts.recirculation_temperature_c;
  st.temperature_c = ts.temperature_c;
  st.viscosity_field = ts.flows.viscosity_pa_s;  // the field of this equilibrium
  st.inlet_mask = ts.inlet_mask;
  st.flows = ts.flows;
  st.heat_to_journal_w = ts.heat_to_journal_w;
  st.heat_to_bush_w = ts.heat_to_bush_w;
  st.journal_temperature_c = ts.journal_temperature_c;
  st.max_wall_temperature_c = ts.max_wall_temperature_c;
  st.wall_temperature_c = ts.wall_temperature_c;
  st.side_temperature_c = ts.side_temperature_c;
  st.friction_power_w = ts.friction_power_w;
  return !(res > tf.thd_options.tol_k);
}

/// A pad's inlet mixing (both pad models): its supply share with the upstream pad's outflow
/// Q_out,u (checked_supply_mixing: a share below the demand draws more of it; starved when
/// Q_f + Q_out,u < Q) at the pad's carry-over λ and metered share. `where`: "THD energy
/// equation" or "thermal equilibrium". ConvergenceError when the pad draws no oil.
SupplyMixing pad_mixing(const std::string& where, double lam, double metered, double Q,
                        double Qout_u, const std::string& name) {
  const std::string at = where + ", film '" + name + "'";
  const SupplyMixing mix = checked_supply_mixing(at, Q, Qout_u, lam, metered);
  if (!(Q > 0.0 && mix.qf + mix.carried > 0.0))
    throw ConvergenceError(at + ": the pad draws no oil (flow into its leading edge " + num(Q) +
                           " m^3/s)");
  return mix;
}

/// The THD pad films' inlet temperatures (Ettles' hot-oil carry-over from the upstream pad,
/// ThermalFilm::upstream), solved together — each pad's field is affine in its inlet
/// temperature, so the ring is one small linear system — then their states and next fields.
/// A journal from its heat balance (journal_balance) is one more unknown per bearing (the
/// pads linked by `upstream`): the net heat into it from all the bearing's pads is zero.
void pad_states(const std::vector<ThermalFilm>& thermal, std::vector<ThdFieldParts>& parts,
                const std::vector<const FilmSolution*>& sols, const std::vector<double>& wfs,
                const std::vector<int>& off, const Eigen::VectorXd& X, Eigen::VectorXd& GX,
                std::vector<ThermalFilmState>& films, bool& done, const SystemModel& m) {
  std::vector<int> ring, pos(thermal.size(), -1);
  for (std::size_t i = 0; i < thermal.size(); ++i)
    if (sols[i] != nullptr) {
      pos[i] = static_cast<int>(ring.size());
      ring.push_back(static_cast<int>(i));
    }
  if (ring.empty()) return;
  const int nr = static_cast<int>(ring.size());
  // the bearings: pads linked by `upstream` share a journal (union–find over the ring)
  std::vector<int> grp(nr);
  for (int r = 0; r < nr; ++r) grp[r] = r;
  std::function<int(int)> root = [&](int r) { return grp[r] == r ? r : grp[r] = root(grp[r]); };
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    const int u = pos[static_cast<std::size_t>(thermal[i].upstream)];
    if (u >= 0) grp[root(r)] = root(u);
  }
  std::vector<int> jrow(nr, -1);  // the row of each pad's journal unknown (-1: fixed journal)
  int n = nr;
  for (int r = 0; r < nr; ++r) {
    const ThdOptions& o = thermal[static_cast<std::size_t>(ring[r])].thd_options;
    const int g = root(r);
    if (o.journal_balance != thermal[static_cast<std::size_t>(ring[g])].thd_options.journal_balance)
      throw InputError("journal_wall: the pads of one bearing need one journal model");
    if (o.journal_balance && jrow[g] < 0) jrow[g] = n++;
    jrow[r] = o.journal_balance ? jrow[g] : -1;
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  std::vector<SupplyMixing> mixes(thermal.size());
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    const std::size_t u = static_cast<std::size_t>(thermal[i].upstream);
    const ThdOptions& o = thermal[i].thd_options;
    const ThdFieldParts& pi = parts[i];
    const std::string& name = m.films[thermal[i].film].name;
    if (pos[u] < 0)
      throw InputError("thermal[" + std::to_string(i) + "].upstream: film '" +
                       m.films[thermal[u].film].name + "' is not a pad film");
    const ThdFieldParts& pu = parts[u];
    // the pad's inlet mixes its supply share with the upstream pad's outflow Q_r,u
    mixes[i] = pad_mixing("THD energy equation", o.carry_over, o.supply_flow_m3_s, pi.Q, pu.Qr,
                          name);
    const double carried = mixes[i].carried, qf = mixes[i].qf;
    // (Q_f + c) T_in,i − c (tb_u/Q_r,u) T_in,u [− c (tc_u/Q_r,u) T_J] = Q_f T_s + c ta_u/Q_r,u
    A(r, r) += qf + carried;
    if (carried > 0.0) {
      A(r, pos[u]) -= carried * pu.tb / pu.Qr;
      if (jrow[r] >= 0) A(r, jrow[r]) -= carried * pu.tc / pu.Qr;
      b[r] += carried * pu.ta / pu.Qr;
    }
    b[r] += qf * o.supply_temperature_c;
    if (jrow[r] >= 0) {  // the journal's balance: Σ_pads (ja + jb T_in + jc T_J) = 0
      A(jrow[r], r) += pi.jb;
      A(jrow[r], jrow[r]) += pi.jc;
      b[jrow[r]] -= pi.ja;
    }
  }
  const Eigen::VectorXd tin = A.fullPivLu().solve(b);
  if (!tin.allFinite())
    throw ConvergenceError("THD energy equation: the pads' inlet temperatures are singular "
                           "(no fresh oil reaches the ring)");
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    ThdFilmState ts = thd_state(std::move(parts[i]), *sols[i], thermal[i].thd_options, wfs[i],
                                tin[r], mixes[i].qf,
                                jrow[r] >= 0 ? tin[jrow[r]]
                                             : std::numeric_limits<double>::quiet_NaN());
    ts.carry_over_effective = mixes[i].lam_eff;
    ts.starved = mixes[i].starved;
    if (!take_thd_state(ts, thermal[i], X, off[i], off[i + 1] - off[i], GX, films[i]))
      done = false;
  }
}

/// An effective-temperature pad film's heat-balance terms at one solution: the dissipation
/// P of the pad's cells (not the gap), the flow Q into the pad at its leading edge and the
/// side leakage Q_s (the same flows and cells as the THD pad film, thd_field), at the film's
/// viscosity mu; the hot flow the pad passes on, Q_out = Q − Q_s (the plain model's
/// recirculating flow Q_r; the THD pad film's too, thd_field).
struct PadBalance {
  double P = 0.0, Q = 0.0, Qout = 0.0, Qs = 0.0, mu = 0.0;
};

PadBalance pad_balance(const ReynoldsSolver& rs, const FilmSolution& sol, const OilModel& oil,
                       double wf, double mu) {
  const ThdOptions flows_only;  // only the flows and the dissipation are used
  const ThdFieldParts parts = thd_field(rs, sol, oil, flows_only, wf, true);
  PadBalance b;
  const double* phi = parts.flows.dissipation_w.data();
  for (std::size_t n = 0; n < parts.inlet.size(); ++n) {
    b.Qs += parts.side_out[n];
    if (!parts.inlet[n]) b.P += phi[n];
  }
  b.Q = parts.Q;
  b.Qout = std::max(parts.Q - b.Qs, 0.0);
  b.mu = mu;
  return b;
}

/// The effective-temperature pad films (ThermalFilm::upstream >= 0, thd = false): per pad the
/// plain film's heat balance P = ρ c ΔT (Q − Q_s/2) (side leakage at the mean rise), T_out =
/// T_in + ΔT, T_eff = T_in + k ΔT, and each inlet the THD pads' ring rule
/// T_in = (Q_f T_s + λ Q_out,u T_out,u)/(Q_f + λ Q_out,u).
/// The state of this step (at the pads' current μ, `T` their temperatures): ΔT from P at μ,
/// the ring of inlet temperatures one linear system (as pad_states). The next temperatures:
/// the ring solved exactly at this position (P ∝ μ, flows independent of μ: each pad's
/// T_eff the root of the scalar heat balance at its inlet temperature, Gauss–Seidel around
/// the ring in the direction of the flow), then one Anderson step (`mixer`) on the pads'
/// temperatures.
void effective_pad_states(const std::vector<ThermalFilm>& thermal,
                          const std::vector<PadBalance>& bal, const std::vector<char>& is_pad,
                          std::vector<double>& T, std::vector<ThermalFilmState>& films,
                          bool& done, const SystemModel& m, AndersonMixer& mixer) {
  std::vector<int> ring, pos(thermal.size(), -1);
  for (std::size_t i = 0; i < thermal.size(); ++i)
    if (is_pad[i]) {
      pos[i] = static_cast<int>(ring.size());
      ring.push_back(static_cast<int>(i));
    }
  if (ring.empty()) return;
  const int nr = static_cast<int>(ring.size());
  auto up = [&](int r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    const int u = thermal[i].upstream;
    if (pos[static_cast<std::size_t>(u)] < 0)
      throw InputError("thermal[" + std::to_string(i) + "].upstream: film '" +
                       m.films[thermal[static_cast<std::size_t>(u)].film].name +
                       "' is not an effective-temperature pad film");
    return pos[static_cast<std::size_t>(u)];
  };
  std::vector<double> dT(nr), den(nr);
  std::vector<SupplyMixing> mix(nr);
  const auto name = [&](int r) {
    return m.films[thermal[static_cast<std::size_t>(ring[static_cast<std::size_t>(r)])].film].name;
  };
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nr, nr);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(nr);
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    up(r);  // checks the upstream film (InputError)
    const PadBalance& pb = bal[i];
    const OilModel& oil = thermal[i].oil;
    den[r] = pb.Q - 0.5 * pb.Qs;
    if (!(pb.P > 0.0 && pb.Q > 0.0 && pb.Qs >= 0.0 && den[r] > 0.0))
      throw ConvergenceError("thermal equilibrium, film '" + name(r) + "': power loss " +
                             num(pb.P) + " W, flow " + num(pb.Q) + " m^3/s and side flow " +
                             num(pb.Qs) + " m^3/s give no heat balance");
    dT[r] = pb.P / (oil.density_kg_m3 * oil.specific_heat_j_per_kg_k * den[r]);
  }
  for (int r = 0; r < nr; ++r) {  // (the upstream pad's ΔT is known now)
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    const int u = up(r);
    const PadBalance& pb = bal[i];
    const ThermalOptions& o = thermal[i].options;
    mix[r] = pad_mixing("thermal equilibrium", o.carry_over, o.supply_flow_m3_s, pb.Q,
                        bal[static_cast<std::size_t>(ring[u])].Qout, name(r));
    // (Q_f + c) T_in,r − c T_in,u = Q_f T_s + c ΔT_u
    A(r, r) += mix[r].qf + mix[r].carried;
    A(r, u) -= mix[r].carried;
    b[r] += mix[r].qf * thermal[i].options.supply_temperature_c + mix[r].carried * dT[u];
  }
  const Eigen::VectorXd tin = A.fullPivLu().solve(b);
  if (!tin.allFinite() || !((A * tin - b).cwiseAbs().maxCoeff() <=
                            1e-9 * std::max(1.0, b.cwiseAbs().maxCoeff())))
    throw ConvergenceError("thermal equilibrium: the pads' inlet temperatures are singular "
                           "(no fresh oil reaches the ring)");
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    const PadBalance& pb = bal[i];
    ThermalFilmState st;
    st.effective_temperature_c = st.mean_temperature_c = T[i];  // μ = μ(T[i]) in this solve
    st.inlet_temperature_c = tin[r];
    st.temperature_rise_k = dT[r];
    st.max_temperature_c = st.recirculation_temperature_c = tin[r] + dT[r];
    st.viscosity_pa_s = pb.mu;
    st.power_loss_w = pb.P;
    st.film_flow_m3_s = pb.Q;
    st.side_flow_m3_s = pb.Qs;
    st.supply_flow_m3_s = mix[r].qf;
    st.carry_over_effective = mix[r].lam_eff;
    st.starved = mix[r].starved;
    st.recirculation_flow_m3_s = pb.Qout;
    films[i] = st;
  }
  // the ring at this position: order the pads in the direction of the flow (each after its
  // upstream pad), then Gauss–Seidel sweeps; each sweep contracts the inlet temperatures by
  // the product of the carried fractions c/(Q_f + c) around the ring (< 1 with fresh oil)
  std::vector<int> order;
  {
    std::vector<int> down(nr, -1);
    for (int r = 0; r < nr; ++r) down[up(r)] = r;
    std::vector<char> seen(nr, 0);
    for (int s = 0; s < nr; ++s)
      for (int r = s; r >= 0 && !seen[r]; r = down[r]) {
        seen[r] = 1;
        order.push_back(r);
      }
  }
  std::vector<double> Tin(tin.data(), tin.data() + nr), Teff(nr), Tout(nr);
  for (int r = 0; r < nr; ++r) Tout[r] = Tin[r] + dT[r];
  bool settled = false;
  for (int sweep = 0; sweep < 2000 && !settled; ++sweep) {
    double change = 0.0;
    for (int r : order) {
      const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
      const double ts = thermal[i].options.supply_temperature_c;
      const double t_in = (mix[r].qf * ts + mix[r].carried * Tout[up(r)]) /
                          (mix[r].qf + mix[r].carried);
      ThermalOptions o = thermal[i].options;  // the pad's own balance from its inlet
      o.supply_temperature_c = std::min(t_in, thermal[i].oil.t_max_c);
      o.carry_over = 0.0;
      o.supply_flow_m3_s = 0.0;
      const PadBalance& pb = bal[i];
      const ThermalFilmState hb = heat_balance(thermal[i].oil, o, pb.mu, pb.P, pb.Q, pb.Qs,
                                               name(r));
      Teff[r] = hb.effective_temperature_c;
      const double tout = t_in + (Teff[r] - t_in) / o.effective_factor;  // ΔT at μ(T_eff)
      change = std::max({change, std::abs(t_in - Tin[r]), std::abs(tout - Tout[r])});
      Tin[r] = t_in;
      Tout[r] = tout;
    }
    // (the scalar heat balance brackets its root to 1e-12 relative: a floor far below this)
    settled = change <= 1e-10 * std::max(1.0, *std::max_element(Tout.begin(), Tout.end()));
  }
  if (!settled)
    throw ConvergenceError("thermal equilibrium: the pads' inlet temperatures did not settle "
                           "(little fresh oil reaches the ring)");
  // the next temperatures: the pads couple through the position (journal and tilts), so one
  // Anderson step over all effective pads (a per-film secant took 23 steps where this takes
  // 6 on a 5-pad bearing, 4 kN, 100 Hz, λ = 0.5), kept inside [T_s, t_max]
  Eigen::VectorXd x(nr), g(nr);
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    if (std::abs(Teff[r] - T[i]) > thermal[i].options.tol_k) done = false;
    x[r] = T[i];
    g[r] = Teff[r];
  }
  const Eigen::VectorXd xn = mixer.next(x, g);
  for (int r = 0; r < nr; ++r) {
    const std::size_t i = static_cast<std::size_t>(ring[static_cast<std::size_t>(r)]);
    T[i] = std::isfinite(xn[r]) ? std::clamp(xn[r], thermal[i].options.supply_temperature_c,
                                             thermal[i].oil.t_max_c) : g[r];
  }
}

/// The starved message of pad film `i`: the bearing's metered supply is shared equally by its
/// pads (the ring of `upstream` links), so the message gives the bearing's supply and the
/// least supply that feeds every pad under equal shares, n × max_k (Q_k − Q_r,k), Q_r,k the
/// outflow of pad k's upstream pad; and this pad's share, hot oil and draw.
std::string pad_starved_message(const std::string& where, std::size_t i,
                                const ThermalSystemResult& out,
                                const std::vector<ThermalFilm>& thermal) {
  const ThermalFilmState& f = out.films[i];
  const double Qr = out.films[static_cast<std::size_t>(thermal[i].upstream)]
                        .recirculation_flow_m3_s;
  std::size_t k = i, n = 0;
  double need = 0.0;  // the largest per-pad shortfall of hot oil, m^3/s
  do {
    const std::size_t u = static_cast<std::size_t>(thermal[k].upstream);
    need = std::max(need, out.films[k].film_flow_m3_s - out.films[u].recirculation_flow_m3_s);
    k = u;
    ++n;
  } while (k != i && n <= thermal.size());
  const double N = static_cast<double>(n);
  return where + ": starved: the bearing's metered supply " + num(N * f.supply_flow_m3_s) +
         " m^3/s is shared equally by its " + std::to_string(n) + " pads; this pad's share "
         "Q_f = " + num(f.supply_flow_m3_s) + " m^3/s and the upstream pad's outflow Q_r = " +
         num(Qr) + " m^3/s fall short of the flow it draws, Q = " + num(f.film_flow_m3_s) +
         " m^3/s; with equal shares the shortfall at this state estimates a bearing supply of " +
         num(N * need) + " m^3/s (" + std::to_string(n) + " x the largest pad shortfall Q - "
         "Q_r; not a bound: the flows move with the temperatures and the journal; an unloaded "
         "pad's surplus share does not feed a loaded one); a starved film's reduced wetted arc "
         "is not modelled";
}

/// Status "starved" on `out` when one of its films' current states is starved (the first, by
/// the thermal list's order; its message names the film and gives Q_f, Q, Q_r and the least
/// supply Q − Q_r); false when none is.
bool starved_status(ThermalSystemResult& out, const std::vector<ThermalFilm>& thermal,
                    const SystemModel& m) {
  for (std::size_t i = 0; i < out.films.size(); ++i) {
    const ThermalFilmState& f = out.films[i];
    if (!f.starved) continue;
    const double Q = f.film_flow_m3_s, Qf = f.supply_flow_m3_s;
    const std::string where =
        "thermal equilibrium, film '" + m.films[static_cast<std::size_t>(thermal[i].film)].name +
        "'";
    out.equilibrium.status = "starved";
    if (thermal[i].upstream >= 0) {
      out.equilibrium.message = pad_starved_message(where, i, out, thermal);
      return true;
    }
    // the hot oil available (supply_mixing): a plain effective film's Q − Q_s, a THD plain
    // film's min(Q_r, Q − Q_s)
    double Qr = std::max(Q - f.side_flow_m3_s, 0.0);
    if (thermal[i].thd) Qr = std::min(Qr, f.recirculation_flow_m3_s);
    out.equilibrium.message = starved_message(where, Qf, Q, Qr);
    return true;
  }
  return false;
}
}  // namespace


ThermalSystemResult thermal_system_equilibrium(const SystemModel& model,
                                               const std::vector<ThermalFilm>& thermal,
                                               double omega, double chamber_pressure,
                                               const Eigen::VectorXd& a,
                                               const EquilibriumOptions& options) {
  model.validate();
  if (!(std::isfinite(omega) && omega != 0.0))
    throw InputError("speed_hz: the thermal equilibrium needs a nonzero speed");
  const int nf = static_cast<int>(model.films.size());
  int max_iter = 1;
  for (std::size_t i = 0; i < thermal.size(); ++i) {
    const ThermalFilm& t = thermal[i];
    if (t.film < 0 || t.film >= nf)
      throw InputError("thermal[" + std::to_string(i) + "].film: expected a film index in [0, " +
                       std::to_string(nf - 1) + "], got " + std::to_string(t.film));
    for (std::size_t j = 0; j < i; ++j)
      if (thermal[j].film == t.film)
        throw InputError("thermal[" + std::to_string(i) + "].film: film " +
                         std::to_string(t.film) + " is given twice");
    t.oil.validate();
    {
      const FilmCoupling& fc = model.films[static_cast<std::size_t>(t.film)];
      check_film_density(fc.geometry, t.oil,
                         "films." + (fc.name.empty() ? std::to_string(t.film) : fc.name) + ".");
    }
    if (t.upstream >= 0 && !(t.upstream < static_cast<int>(thermal.size()) &&
                             thermal[static_cast<std::size_t>(t.upstream)].thd == t.thd))
      throw InputError("thermal[" + std::to_string(i) + "].upstream: expected the index of a "
                       "film of the same thermal model (THD or effective) in [0, " +
                       std::to_string(thermal.size() - 1) + "] (or -1), got " +
                       std::to_string(t.upstream));
    if (t.thd) {
      t.thd_options.validate(t.oil);
      max_iter = std::max(max_iter, t.thd_options.max_iter);
    } else {
      t.options.validate(t.oil);
      max_iter = std::max(max_iter, t.options.max_iter);
    }
  }
  auto supply_t = [&](std::size_t i) {
    return thermal[i].thd ? thermal[i].thd_options.supply_temperature_c
                          : thermal[i].options.supply_temperature_c;
  };
  SystemModel m = model;
  for (std::size_t i = 0; i < thermal.size(); ++i) {  // start at the supply temperatures
    m.films[thermal[i].film].geometry.viscosity_pa_s = thermal[i].oil.viscosity_pa_s(supply_t(i));
    m.films[thermal[i].film].viscosity_field.resize(0, 0);  // the THD field's reference
  }
  // THD films: their node temperatures, one vector (offsets), Anderson-accelerated together
  std::vector<int> off(thermal.size() + 1, 0);
  for (std::size_t i = 0; i < thermal.size(); ++i) {
    const FilmGrid& g = m.films[thermal[i].film].grid;
    off[i + 1] = off[i] + (thermal[i].thd ? g.n_circ * (g.n_axial + 1) : 0);
  }
  Eigen::VectorXd X(off.back()), GX(off.back());
  for (std::size_t i = 0; i < thermal.size(); ++i)
    X.segment(off[i], off[i + 1] - off[i]).setConstant(supply_t(i));
  AndersonMixer mixer, pad_mixer;  // THD node temperatures; effective pad temperatures
  SystemSolver solver(m);  // one solver; the films' viscosities change in place
  // each thermal film's own full-output solver (the system's films solve pressures only)
  std::vector<std::unique_ptr<ReynoldsSolver>> fsol;
  for (const ThermalFilm& t : thermal)
    fsol.push_back(std::make_unique<ReynoldsSolver>(m.films[t.film].geometry,
                                                    m.films[t.film].grid,
                                                    m.films[t.film].cavitation));
  std::vector<double> T_prev(thermal.size()), f_prev(thermal.size(),
                                                     std::numeric_limits<double>::quiet_NaN());
  ThermalSystemResult out;
  std::vector<double> T(thermal.size());
  for (std::size_t i = 0; i < thermal.size(); ++i) T[i] = supply_t(i);
  Eigen::VectorXd r0;  // empty: the solver's default start
  out.films.resize(thermal.size());
  for (int it = 1; it <= max_iter; ++it) {
    for (std::size_t i = 0; i < thermal.size(); ++i) {
      if (thermal[i].thd) {  // μ(T) per node
        const FilmGrid& g = m.films[thermal[i].film].grid;
        const OilModel& oil = thermal[i].oil;
        RowMatrixXd mu(g.n_circ, g.n_axial + 1);
        for (Eigen::Index n = 0; n < mu.size(); ++n)
          mu.data()[n] = oil.viscosity_pa_s(std::clamp(X[off[i] + n], oil.t_min_c, oil.t_max_c));
        solver.set_film_viscosity_field(thermal[i].film, mu);
        fsol[i]->set_viscosity_field(mu);
        m.films[thermal[i].film].viscosity_field = mu;
        continue;
      }
      const double mu = thermal[i].oil.viscosity_pa_s(T[i]);
      m.films[thermal[i].film].geometry.viscosity_pa_s = mu;
      solver.set_film_viscosity(thermal[i].film, mu);
      fsol[i]->set_viscosity(mu);
    }
    out.equilibrium = solver.equilibrium(omega, chamber_pressure, a, r0, options);
    out.iterations = it;
    out.viscosities.resize(nf);
    for (int f = 0; f < nf; ++f) out.viscosities[f] = m.films[f].geometry.viscosity_pa_s;
    if (out.equilibrium.status != "ok" && out.equilibrium.status != "contact") return out;
    const Eigen::VectorXd& r = out.equilibrium.r;
    r0 = r;
    bool done = true;
    for (ThermalFilmState& f : out.films) f.starved = false;  // this iteration's flags
    try {  // a starved film ends the iteration with status "starved" (starved_status)
      std::vector<ThdFieldParts> parts(thermal.size());
      std::vector<const FilmSolution*> sols(thermal.size(), nullptr);
      std::vector<double> wfs(thermal.size(), 0.0);
      std::vector<PadBalance> bal(thermal.size());
      std::vector<char> eff_pad(thermal.size(), 0);
      // the next temperature of an effective-temperature film: the map T -> Tn with a per-film
      // secant step once two iterates exist (safeguarded as in thermal_equilibrium; the films
      // couple only weakly, through the positions)
      auto next = [&](std::size_t i, double Tn) {
        const double f = Tn - T[i];
        double Tnext = Tn;
        if (it > 1 && std::isfinite(f_prev[i]) && f != f_prev[i]) {
          const double ts = T[i] - f * (T[i] - T_prev[i]) / (f - f_prev[i]);
          if (std::isfinite(ts) && ts > thermal[i].options.supply_temperature_c &&
              ts < thermal[i].oil.t_max_c && std::abs(ts - T[i]) <= 4.0 * std::abs(f))
            Tnext = ts;
        }
        T_prev[i] = T[i];
        f_prev[i] = f;
        T[i] = Tnext;
      };
      for (std::size_t i = 0; i < thermal.size(); ++i) {
        const FilmCoupling& fc = m.films[thermal[i].film];
        Eigen::VectorXd rc(fc.coords.size());
        for (std::size_t k = 0; k < fc.coords.size(); ++k) rc[k] = r[fc.coords[k]];
        const RowMatrixXd h = fc.thickness(rc);
        ReynoldsSolver& rs = *fsol[i];
        const double wf = omega * fc.spin_factor;
        const FilmSolution& sol = rs.solve(h, RowMatrixXd::Zero(h.rows(), h.cols()), wf);
        if (thermal[i].thd && thermal[i].upstream >= 0) {  // a pad: after the loop (its ring)
          parts[i] = thd_field(rs, sol, thermal[i].oil, thermal[i].thd_options, wf, true);
          sols[i] = &sol;
          wfs[i] = wf;
          continue;
        }
        if (thermal[i].upstream >= 0) {  // an effective-temperature pad: after the loop
          bal[i] = pad_balance(rs, sol, thermal[i].oil, wf, fc.geometry.viscosity_pa_s);
          eff_pad[i] = 1;
          continue;
        }
        if (thermal[i].thd) {
          const ThdFilmState ts =
              thd_energy(rs, sol, thermal[i].oil, thermal[i].thd_options, wf);
          if (!take_thd_state(ts, thermal[i], X, off[i], off[i + 1] - off[i], GX, out.films[i]))
            done = false;
          continue;
        }
        const double P = sol.friction_torque_nm * wf;
        const double qg = sol.inlet_flow_m3_s;
        const double Q = fc.geometry.grooves.empty() || !(qg > 0.0) ? max_film_flow(rs, sol, wf)
                                                                     : qg;
        const double mu = fc.geometry.viscosity_pa_s;
        ThermalFilmState st = heat_balance(thermal[i].oil, thermal[i].options, mu, P, Q,
                                           sol.side_flow_m3_s, fc.name);
        const double Tn = st.effective_temperature_c;
        st.effective_temperature_c = T[i];  // the state of this solve (μ = μ(T[i]))
        out.films[i] = st;
        if (std::abs(Tn - T[i]) > thermal[i].options.tol_k) done = false;
        next(i, Tn);
      }
      pad_states(thermal, parts, sols, wfs, off, X, GX, out.films, done, m);
      effective_pad_states(thermal, bal, eff_pad, T, out.films, done, m, pad_mixer);
    } catch (const StarvedError& e) {
      out.equilibrium.status = "starved";
      out.equilibrium.message = e.what();
      return out;
    } catch (const ConvergenceError& e) {  // a starved film's state has no heat balance
      if (starved_status(out, thermal, m)) {  // the failure kept beside the starvation
        out.equilibrium.message += "; and then: " + std::string(e.what());
        return out;
      }
      throw;
    }
    if (off.back() > 0 && !done) {  // the THD films' next temperatures
      X = mixer.next(X, GX);
      for (std::size_t i = 0; i < thermal.size(); ++i)
        for (int n = off[i]; n < off[i + 1]; ++n)
          X[n] = std::clamp(X[n], thermal[i].oil.t_min_c, thermal[i].oil.t_max_c);
    }
    if (done) {
      if (starved_status(out, thermal, m)) return out;  // never a thermal answer from it
      for (std::size_t i = 0; i < thermal.size(); ++i)
        if (!(out.films[i].max_temperature_c <= thermal[i].oil.t_max_c))
          throw ConvergenceError("thermal equilibrium, film '" + m.films[thermal[i].film].name +
                                 "': the maximum film temperature " +
                                 num(out.films[i].max_temperature_c) + " degC exceeds the "
                                 "viscosity law's range (t_max_c = " +
                                 num(thermal[i].oil.t_max_c) + " degC)");
      return out;
    }
  }
  if (starved_status(out, thermal, m)) return out;  // the last iterate was starved
  out.equilibrium.status = "not_converged";
  out.equilibrium.message = "thermal equilibrium: the film temperatures did not settle in " +
                            std::to_string(max_iter) + " iterations";
  return out;
}

}  // namespace rotordyn
