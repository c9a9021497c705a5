// Starved mass-conserving film: a metered supply to the grooves (JournalBearingGeometry::
// supply_flow_m3_s, cavitation "jfo").
//
// A flooded groove is a Dirichlet line p = pressure_pa with a full film (θ = 1). A metered
// supply Q_s below what that film draws cannot keep it: the groove's pressure falls and, once
// it is at the ambient 0, the oil leaves the groove as a partial film — in the Elrod–Adams
// variables a groove node with p = 0 and fill θ_in < 1, i.e. a boundary condition on the film
// content. The partial film travels as striations carrying the column θ_in·h_groove and
// builds pressure only where the gap has closed to it (the reduced wetted arc).
//
// One groove state s for all grooves of the bearing (they share one supply):
//   s in [1, 2]:  θ_in = 1, p_groove = (s − 1)·pressure_pa   (s = 2: the flooded film)
//   s in [0, 1):  θ_in = s, p_groove = 0                     (the starved inlet)
// The grooves' net inflow Q(s) (FilmSolution::inlet_flow_m3_s, the flow the finite volumes
// carry out of the groove nodes) is continuous, piecewise linear between changes of the p–θ
// partition (the complementarity solution is piecewise linear in its right-hand side, which
// is linear in s) and non-decreasing; Q(0) = 0 (an empty groove delivers nothing). Brent's
// method on Q(s) = Q_s over [0, 2] then converges in a few solves (it is exact within one
// linear piece). At or above the flooded demand Q(2) the flooded film is returned unchanged.
#include <algorithm>
#include <cmath>
#include <limits>

#include "brent_detail.hpp"
#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

void ReynoldsSolver::Impl::set_groove_state(double s) {
  groove_theta = std::min(s, 1.0);
  const double fp = std::max(s - 1.0, 0.0);  // s = 2: 1.0 * p0 == p0 exactly
  for (const int g : groove_nodes) {
    p_fixed[g] = fp * groove_p0[g];
    p[g] = pfull[g] = p_fixed[g];
    theta[g] = groove_theta;
  }
}

void ReynoldsSolver::Impl::solve_supplied(LinearSystem& S) {
  out.inlet_fill = 1.0;
  out.groove_pressure_factor = 1.0;
  out.starved = false;
  out.supply_iterations = 0;
  supply_s = 2.0;
  const double qs = geo.supply_flow_m3_s;
  if (!(qs > 0.0)) {  // flooded grooves (no supply given): today's film
    solve_jfo(S);
    return;
  }
  set_groove_state(2.0);
  solve_jfo(S);
  flows();
  const double qf = out.inlet_flow_m3_s;
  if (!(qf > qs)) return;  // the supply meets the flooded demand: the flooded film
  int total_it = out.iterations, n_eval = 0;
  double s_last = 2.0;
  auto eval = [&](double s) {
    set_groove_state(s);
    solve_jfo(S);
    flows();
    total_it += out.iterations;
    ++n_eval;
    s_last = s;
    return out.inlet_flow_m3_s - qs;
  };
  // Brent (brent_detail.hpp) on f(s) = Q(s) − Q_s, f(0) = −Q_s < 0 < f(2) (both known: s = 0
  // passes no oil, s = 2 is the flooded film just solved); the supply to 1e-12, or to the
  // inflow's own round-off (64 ε of the flooded inflow) at a supply so small that 1e-12 of it
  // is below what the fluxes resolve
  const double eps = std::numeric_limits<double>::epsilon();
  const double ftol = std::max(1e-12 * qs, 64.0 * eps * qf);
  auto f = [&](double s) { return s == 0.0 ? -qs : s == 2.0 ? qf - qs : eval(s); };
  double b = 0.0;
  try {
    b = brent_detail::brent(f, 0.0, 2.0, 1e-15, 4.0 * eps, 200, ftol);
  } catch (const ConvergenceError&) {  // a film solve's own failure: as it is
    throw;
  } catch (const ContactError&) {
    throw;
  } catch (const std::runtime_error&) {  // the root's iterations exhausted
    throw ConvergenceError("supply_flow_m3_s: the starved groove state did not converge in "
                           "200 iterations");
  }
  if (s_last != b) eval(b);  // leave the solver at the root
  if (!std::isfinite(out.inlet_flow_m3_s))
    throw ConvergenceError("supply_flow_m3_s: non-finite inflow of the starved film");
  out.iterations = total_it;
  supply_s = b;
  out.inlet_fill = groove_theta;
  out.groove_pressure_factor = std::max(b - 1.0, 0.0);
  out.starved = true;
  out.supply_iterations = n_eval;
}

// flows()' inlet flow, differentiated: the faces from groove nodes into film cells and the
// end half cells' φ-faces next to a groove column (jfo: open ends, every face counts).
double ReynoldsSolver::Impl::inflow_derivative(const std::vector<double>& dp,
                                               const std::vector<double>& dth,
                                               const double* dh) const {
  const int Kl = K1 - 1;
  const bool fwd = omega >= 0.0;
  const double fE3 = 3.0 * dz / (12.0 * mu * R * dphi), fq = 0.5 * omega * R * dz;
  // the change of face (a, east(a)): conductance (as residual_derivative_t), Couette, and
  // the flux's own p and θ changes; the fill the upwind node's (row kin for an end face)
  auto dflux = [&](int a, int b, int up) {
    const double he = 0.5 * (h[a] + h[b]), dhe = 0.5 * (dh[a] + dh[b]);
    double g = fE3 * he * he;
    if (turb) {
      double m, dm;
      turb_face(he, false, a, m, dm);
      g *= dm;
    }
    if (visc_field) g *= vmE[a];
    return g * dhe * (p[a] - p[b]) + cE[a] * (dp[a] - dp[b]) + fq * dhe * theta[up] +
           qE[a] * dth[up];
  };
  double dq = 0.0;
  for (const int g : groove_nodes) {
    const int e = east(g), w = west(g);
    if (!fixed[e]) dq += dflux(g, e, fwd ? g : e);
    if (!fixed[w]) dq -= dflux(w, g, fwd ? w : g);
  }
  for (const int k : {0, Kl}) {
    const int kin = k == 0 ? 1 : Kl - 1;
    for (int j = 0; j < N; ++j) {
      const int n = j * K1 + k, e = east(n), w = west(n);
      if (groove[n - k + kin]) continue;
      if (groove[w - k + kin]) dq += 0.5 * dflux(w, n, (fwd ? w : n) - k + kin);
      if (groove[e - k + kin]) dq -= 0.5 * dflux(n, e, (fwd ? n : e) - k + kin);
    }
  }
  return dq;
}

double ReynoldsSolver::Impl::hold_supply(const LinearSystem& S, const double* dh,
                                         Eigen::VectorXd& x) {
  // x_s = M⁻¹ ∂b/∂s at the frozen partition (M's factor is the one x was solved with)
  const bool th_seg = supply_s < 1.0, fwd = omega >= 0.0;
  Eigen::VectorXd bs = Eigen::VectorXd::Zero(S.n_unk), xs;
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i], e = east(n), w = west(n);
    double v = 0.0;
    if (th_seg) {  // b_i − (1 − θ_in)·(the groove's Couette flux into cell i)
      if (fwd && groove[w]) v = qE[w];
      if (!fwd && groove[e]) v = -qE[n];
    } else {  // b_i + c·p_groove with p_groove = (s − 1)·pressure_pa
      if (groove[e]) v += cE[n] * groove_p0[e];
      if (groove[w]) v += cE[w] * groove_p0[w];
    }
    bs[i] = S.wphi[i] * v;
  }
  solve_factored(S, bs, xs);
  std::vector<double> dp(n_nodes), dth(n_nodes);
  auto to_nodes = [&](const Eigen::VectorXd& u) {
    std::fill(dp.begin(), dp.end(), 0.0);
    std::fill(dth.begin(), dth.end(), 0.0);
    for (int i = 0; i < S.n_unk; ++i) {
      const int n = S.node_of[i];
      (S.active[i] ? dth[n] : dp[n]) = S.active[i] ? -u[i] : u[i];
    }
    if (S.half)
      for (int j = 0; j < N; ++j)
        for (int k = Kh + 1; k < mirror_end(); ++k) {
          dp[j * K1 + k] = dp[j * K1 + K1 - 1 - k];
          dth[j * K1 + k] = dth[j * K1 + K1 - 1 - k];
        }
  };
  to_nodes(x);
  const double dq_x = inflow_derivative(dp, dth, dh);
  to_nodes(xs);
  for (const int g : groove_nodes) (th_seg ? dth[g] : dp[g]) = th_seg ? 1.0 : groove_p0[g];
  const std::vector<double> zero(n_nodes, 0.0);
  const double dq_s = inflow_derivative(dp, dth, zero.data());
  if (!(dq_s > 0.0 && std::isfinite(dq_x)))
    throw ConvergenceError("supply_flow_m3_s: the starved film's inflow does not change with "
                           "its groove state here (no held-supply linearisation)");
  const double ds = -dq_x / dq_s;
  x += ds * xs;
  return ds;
}

void ReynoldsSolver::Impl::full_film_start() {
  // the first pressurised node (p > 0) on the mid-plane row downstream of the first groove
  // column, in the direction of rotation (resolution Δφ)
  out.full_film_start_deg = std::numeric_limits<double>::quiet_NaN();
  if (groove_nodes.empty()) return;
  const int km = K1 / 2;  // the mid-plane row (n_axial even) or the row above it
  const int step = omega >= 0.0 ? 1 : N - 1;
  auto gcol = [&](int j) { return groove[j * K1 + km] != 0; };
  int j = groove_nodes[0] / K1;
  int guard = 0;
  while (gcol(j) && guard < N) {
    j = (j + step) % N;
    ++guard;
  }
  if (guard >= N) return;
  for (int t = 0; t < N; ++t, j = (j + step) % N) {
    if (gcol(j)) return;  // the next groove before any full film
    if (p[j * K1 + km] > 0.0) {
      out.full_film_start_deg = j * dphi * 180.0 / reynolds_detail::kPi;
      return;
    }
  }
}

}  // namespace rotordyn
