// Pseudo-arclength corrector for periodic orbits (continuation.hpp).
#include "rotordyn/continuation.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "rotordyn/errors.hpp"
#include "hb_detail.hpp"
#include "shooting_detail.hpp"

namespace rotordyn {

using namespace shooting_detail;

namespace {

PeriodicInput at_parameter(const ContinuationInput& c, double p) {
  return shooting_detail::at_parameter(c.base, c.parameter, c.config_direction, c.subharmonic, p);
}

// ∂f/∂p of eq. 12's right-hand side where f is affine in p (first-order form, (N)): p_c
// enters the constant force p_c c_s, a_y the spring force −K a(p); empty for the speed (M, G,
// the films and the period depend on Ω: the central difference of two flows stays).
Eigen::VectorXd parameter_rhs(const Flow& F, const SystemModel& m, const ContinuationInput& c) {
  Eigen::VectorXd d;
  if (c.parameter == ContinuationParameter::speed) return d;
  d = Eigen::VectorXd::Zero(F.N);
  if (c.parameter == ContinuationParameter::chamber_pressure)
    d.tail(F.n) = F.Mllt.solve(m.chamber);
  else
    d.tail(F.n) = -F.Mllt.solve(m.offset_load(c.base.omega, c.config_direction));
  return d;
}

// One flow without sensitivities: φ_T(x; p) − x, or an empty vector when CVODES fails.
Eigen::VectorXd residual(SystemSolver& solver, const ContinuationInput& c, const Eigen::VectorXd& x,
                         double T, double p, const CvodeOptions& opt) {
  const PeriodicInput in = at_parameter(c, p);
  Flow F;
  setup_flow(F, solver, in);
  const double TT = in.kind == OrbitKind::forced ? in.period : T;
  FlowRun run = run_flow(F, x, in.t0, TT, false, 2, opt, false, opt.rtol);
  if (run.flag < 0) return Eigen::VectorXd();
  return run.xT - x;
}

// floquet = samples: the converged orbit's multipliers from its films' linearisations at the
// n_out − 1 samples X (the single Magnus product of harmonic balance's samples route), screened
// by hb_detail::screen_close (the harmonic-balance corrector's rule), refined where close
// (opt.floquet_tol > 0) and recomputed by one error-controlled flow at srtol where the verdict
// is still close. false with o.status / o.message on a failure ("rub": a film closed at a
// sample, as periodic_orbit's samples route).
bool samples_floquet(SystemSolver& solver, const PeriodicInput& in, const Eigen::MatrixXd& X,
                     bool autonomous, const ShootingOptions& opt, double srtol,
                     PeriodicOrbitResult& o, ContinuationStep& out) {
  Flow F;
  setup_flow(F, solver, in);
  F.blocked_sensitivities = opt.blocked_sensitivities;
  const double T = o.period;
  hb_detail::Eval e;
  hb_detail::RefinedMonodromy lin;
  hb_detail::PointFloquet pf;
  if (!hb_detail::linearize_samples(solver, in, X, e, lin)) {
    o.status = lin.contact ? "rub" : "error";
    o.message = "the orbit converged but its monodromy from the samples failed: " + lin.why +
                " (floquet='flow' integrates it instead)";
    return false;
  }
  o.floquet_linearizations = lin.linearizations;
  pf.route = "samples";
  o.monodromy = hb_detail::sample_monodromy(F, solver.model(), e, T,
                                            HarmonicBalanceOptions().magnus_substeps);
  o.monodromy_rtol = 0.0;
  bool flow = !o.monodromy.allFinite();  // nothing usable from the samples: the flow decides
  if (!flow) {
    o.floquet = floquet(o.monodromy, autonomous);
    flow = hb_detail::screen_close(o.floquet, opt.floquet_margin, false, pf);
    if (flow && opt.floquet_tol > 0) {
      const int M = static_cast<int>(X.rows()) - 1;
      hb_detail::RefinedMonodromy rm = hb_detail::refine_samples(
          solver, in, F, X, e, T, autonomous, opt.floquet_tol,
          hb_detail::refined_max_steps(M, opt.floquet_max_steps));
      o.floquet_linearizations += rm.linearizations;
      const double err = rm.error;
      const bool conv = rm.converged;
      flow = !hb_detail::take_refined(rm, autonomous, o, pf);
      if (!flow) {
        o.floquet_error = err;
        o.floquet_converged = conv;
        o.floquet_steps = pf.refined_steps;
      }
    }
  }
  if (flow) {
    if (!hb_detail::flow_monodromy(F, o, in.t0, T, opt.cvode, srtol)) return false;
    pf.route = "flow";
  }
  if (!o.monodromy.allFinite()) {
    o.status = "error";
    o.message = "non-finite monodromy matrix";
    return false;
  }
  o.floquet = floquet(o.monodromy, autonomous);
  out.floquet_route = pf.route;
  out.screen_critical_modulus = pf.screen_critical_modulus;
  out.screen_trivial_error = pf.screen_trivial_error;
  out.floquet_error = pf.refined_error;
  out.floquet_steps = pf.refined_steps;
  return true;
}

}  // namespace

PeriodicInput shooting_detail::at_parameter(const PeriodicInput& base, ContinuationParameter parameter,
                                            const Eigen::VectorXd& config_direction, int subharmonic,
                                            double p) {
  PeriodicInput in = base;
  switch (parameter) {
    case ContinuationParameter::chamber_pressure:
      in.chamber_pressure = p;
      break;
    case ContinuationParameter::speed:
      in.omega = p;
      break;
    case ContinuationParameter::config:
      in.a = base.a + p * config_direction;
      break;
  }
  if (in.kind == OrbitKind::forced) in.period = subharmonic * 2 * M_PI / std::abs(in.omega);
  return in;
}

ContinuationStep continuation_step(SystemSolver& solver, const ContinuationInput& c,
                                   const ShootingOptions& opt) {
  const Eigen::Index n = solver.model().n(), N = 2 * n;
  const bool autonomous = c.base.kind == OrbitKind::autonomous;
  require(c.scale.size() == N + 2 && c.scale.allFinite() && (c.scale.array() > 0).all(),
          shape_msg("scale", N + 2, 1, c.scale.size(), 1) + " with finite values > 0");
  require(c.y_prev.size() == N + 2 && c.y_prev.allFinite(),
          shape_msg("y_prev", N + 2, 1, c.y_prev.size(), 1) + " with finite values");
  require(c.tangent.size() == 0 || (c.tangent.size() == N + 2 && c.tangent.allFinite()),
          shape_msg("tangent", N + 2, 1, c.tangent.size(), 1) + " (or empty)");
  require(std::isfinite(c.p) && std::isfinite(c.ds), "p, ds: expected finite values");
  require(c.fd_step > 0 && c.fd_step < 1, "fd_step: expected a value in (0, 1)");
  require(c.subharmonic >= 1, "subharmonic: expected at least 1");
  require(c.parameter != ContinuationParameter::config || c.config_direction.size() == n,
          shape_msg("config_direction", n, 1, c.config_direction.size(), 1));
  require(c.parameter != ContinuationParameter::speed || c.p != 0.0,
          "speed: the continuation parameter Ω must not be 0");
  validate(solver, at_parameter(c, c.p), opt, true);

  ContinuationStep out;
  PeriodicOrbitResult& o = out.orbit;
  o.t0 = c.base.t0;
  const long solves0 = solver.reynolds_solves();
  const Eigen::VectorXd Dx = c.scale.head(N);
  const double DT = c.scale(N), Dp = c.scale(N + 1);
  o.length_scale = Dx(0);
  const bool first = c.tangent.size() == 0;
  const Eigen::Index K = N + 2;  // (x, T, p); for forced orbits T is not an unknown
  Eigen::VectorXd x(N);
  x << c.base.r0, c.base.v0;
  double T = c.base.period, p = c.p;
  // The scaled point; its T entry is held at y_prev's for forced orbits (not an unknown).
  auto scaled = [&](const Eigen::VectorXd& xx, double TT, double pp) {
    Eigen::VectorXd y(K);
    y.head(N) = xx.cwiseQuotient(Dx);
    y(N) = (autonomous ? TT : c.y_prev(N)) / DT;
    y(N + 1) = pp / Dp;
    return y;
  };
  const Eigen::VectorXd yprev_s = c.y_prev.cwiseQuotient(c.scale);
  Eigen::VectorXd t_prev = c.tangent;
  if (!autonomous && !first) t_prev(N) = 0.0;

  // The bordered matrix (rows: R, [phase], condition row) in scaled unknowns; the columns of
  // the unknowns only (forced: x, p; autonomous: x, T, p).
  const double h = c.fd_step * Dp;
  const double max_step = 0.25;
  FlowRun run;
  PeriodicInput in_p;
  bool converged = false, errcon = opt.sensitivity_error_control;
  const double srtol = opt.sensitivity_rtol > 0 ? opt.sensitivity_rtol : opt.cvode.rtol;
  Eigen::MatrixXd Jrp;  // the rows without the condition row, at the last iterate
  std::vector<Eigen::Index> cols;
  for (Eigen::Index j = 0; j < N; ++j) cols.push_back(j);
  if (autonomous) cols.push_back(N);
  cols.push_back(N + 1);
  const Eigen::Index U = static_cast<Eigen::Index>(cols.size());  // unknowns
  const Eigen::Index Rrows = U - 1;
  // The rows R of the bordered matrix (N × U, scaled): Φ − I, the period column, ∂R/∂p.
  // With opt.broyden the corrector starts from the previous point's (c.jacobian) and flows
  // without sensitivities, updating the x and p columns by Broyden; the period column is
  // recomputed from f(φ_T) at every iterate. Φ (with the sensitivities) and ∂R/∂p (two flows)
  // are computed afresh only when the matrix needs it: no usable previous matrix, a step
  // that did not halve the residual, and the final pass at the converged point (error test).
  Eigen::MatrixXd JR;
  bool fresh = !(opt.broyden && c.jacobian.rows() == N && c.jacobian.cols() == U &&
                 c.jacobian.allFinite());
  if (!fresh) JR = c.jacobian;
  bool refreshed = false;
  Eigen::VectorXd R_prev, tcol_prev, dz_prev;
  // floquet = flow: the converged point is integrated once more with the sensitivities in the
  // error test (the reported monodromy and the tangent's). samples: no such pass; the last
  // flow with sensitivities (outside the error test) gives the tangent's Φ and ∂R/∂p, the
  // multipliers come from the samples (samples_floquet).
  const bool final_pass = opt.floquet == ShootingFloquet::flow;
  // The final pass's sensitivity tolerance: screen_rtol first when screening (repeated at
  // srtol where the verdict is not safe), else srtol.
  const bool screen = final_pass && opt.screen_rtol > 0 && opt.screen_rtol > srtol;
  double pass_rtol = screen ? opt.screen_rtol : srtol;
  bool dxdp_ok = false;  // the last sensitivity flow gave ∂R/∂p
  // Screening from the previous point's matrix: the first flow is already the screened final
  // pass (on a short step the predictor is usually within tol: the flow without
  // sensitivities that would only confirm it is saved). If it is not within tol, its
  // error-controlled Φ and ∂R/∂p are the Newton matrix and the iterations go on without.
  bool speculative = screen && !fresh && !errcon;
  if (speculative) errcon = true;
  for (int it = 0; it <= opt.max_iter + 2; ++it) {
    in_p = at_parameter(c, p);
    Flow F;
    setup_flow(F, solver, in_p);
    F.blocked_sensitivities = opt.blocked_sensitivities;
    if (opt.parameter_sensitivity) {
      F.dfdp = parameter_rhs(F, solver.model(), c);
      F.p_unit = Dp * opt.cvode.atol_position / Dx(0);
    }
    const double TT = autonomous ? T : in_p.period;
    const bool sens = errcon || fresh || !opt.broyden;
    run = run_flow(F, x, in_p.t0, TT, sens, in_p.n_out, opt.cvode, errcon,
                   errcon ? pass_rtol : srtol);
    dxdp_ok = sens && run.dxdp.size() == N;
    o.iterations = it + 1;
    if (sens) ++o.sensitivity_flows;
    o.steps += run.steps;
    o.rhs_evals += run.rhs_evals;
    o.jac_evals += run.jac_evals;
    o.order_reductions += run.order_reductions;
    o.sens_factorizations += run.sens_factorizations;
    o.sens_linear_solves += run.sens_newton_iters * (N + (run.dxdp.size() == N ? 1 : 0));
    o.sens_rhs_evals += F.sens_evals;
    if (run.flag < 0) {
      o.status = F.contact ? "rub" : "not_converged";
      o.message = "corrector iteration " + std::to_string(it) + ": " + run.why;
      break;
    }
    const Eigen::VectorXd Rz = (run.xT - x).cwiseQuotient(Dx);
    const Eigen::VectorXd ys = scaled(x, T, p);
    const double g = first ? 0.0 : t_prev.dot(ys - yprev_s) - c.ds;
    const double res = std::max(Rz.cwiseAbs().maxCoeff(), std::abs(g));
    o.residuals.push_back(res);
    o.residual = res;
    if (!std::isfinite(res)) {
      o.status = "error";
      o.message = "non-finite state after one period";
      break;
    }
    const bool done = res < opt.tol;
    if (speculative && !done) errcon = opt.sensitivity_error_control;
    speculative = false;
    if (done && !final_pass && !sens) {  // samples: a Broyden flow under tol is repeated
      fresh = true;                        // once with the sensitivities (the tangent's Φ and
      refreshed = true;                    // ∂R/∂p), outside the error test
      continue;
    }
    if (done && final_pass && !errcon) {  // converged without the sensitivities' error test:
      errcon = true;  // one more pass at the same point with it (no ∂R/∂p needed for this one)
      continue;
    }
    if (done && screen && pass_rtol != srtol && run.Phi.allFinite()) {
      // The screened final pass: keep it only where its stability verdict is safe.
      const Floquet fq = floquet(run.Phi, autonomous);
      const double mu_t = fq.trivial >= 0 ? std::abs(fq.multipliers(fq.trivial) - 1.0) : 0.0;
      if (opt.screen_margin > 0 &&
          (fq.critical < 0 || std::abs(fq.critical_modulus - 1.0) < opt.screen_margin ||
           mu_t > opt.screen_margin)) {
        pass_rtol = srtol;  // the same point again at the full tolerance
        continue;
      }
    }
    const bool stalled = !done && !refreshed && o.residuals.size() > 1 &&
                         res > 0.5 * o.residuals[o.residuals.size() - 2];
    refreshed = false;
    if (stalled && !sens) {  // the secant matrix no longer halves the residual: refresh it
      fresh = true;          // at the same point
      refreshed = true;
      continue;
    }
    Eigen::VectorXd tcol;
    if (autonomous) tcol = DT * vector_field(F, in_p.t0 + T, run.xT).cwiseQuotient(Dx);
    if (sens) {
      JR = Eigen::MatrixXd::Zero(N, U);
      JR.leftCols(N) = Dx.cwiseInverse().asDiagonal() * run.Phi * Dx.asDiagonal() -
                       Eigen::MatrixXd::Identity(N, N);
      if (dxdp_ok) {  // ∂R/∂p = ∂x(t0 + T)/∂p from the parameter column (scaled)
        JR.col(U - 1) = Dp * run.dxdp.cwiseQuotient(Dx);
      } else {
        // ∂R/∂p by a central difference (also needed for the tangent at the converged point).
        const Eigen::VectorXd Rp1 = residual(solver, c, x, T, p + h, opt.cvode);
        const Eigen::VectorXd Rm1 = residual(solver, c, x, T, p - h, opt.cvode);
        out.fd_flows += 2;
        if (Rp1.size() == 0 || Rm1.size() == 0) {
          o.status = "not_converged";
          o.message = "corrector iteration " + std::to_string(it) +
                      ": a flow at p ± h for the parameter derivative failed";
          break;
        }
        JR.col(U - 1) = ((Rp1 - Rm1) / (2 * c.fd_step)).cwiseQuotient(Dx);
      }
      fresh = false;
    } else if (dz_prev.size() == U) {
      // Broyden on the x and p columns: JR += (y − JR s) sᵀ / sᵀs, s the last step without
      // its period component, y the change of R less the period column's share.
      Eigen::VectorXd s_xp = dz_prev;
      Eigen::VectorXd y = Rz - R_prev;
      if (autonomous) {
        y -= tcol_prev * dz_prev(N);
        s_xp(N) = 0.0;
      }
      const double ss = s_xp.squaredNorm();
      if (ss > 0) JR += (y - JR * s_xp) * (s_xp.transpose() / ss);
    }
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(U, U);
    J.topRows(N) = JR;
    if (autonomous) {
      J.block(0, N, N, 1) = tcol;
      JR.col(N) = tcol;
      const Eigen::VectorXd f0 = vector_field(F, in_p.t0, x).cwiseQuotient(Dx);
      J.block(N, 0, 1, N) = f0.transpose() / std::max(f0.norm(), 1e-300);
    }
    Jrp = J.topRows(Rrows);
    if (done) {
      converged = true;
      break;
    }
    if (stalled && !errcon) errcon = true;
    if (it >= opt.max_iter) break;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(U);
    b.head(N) = -Rz;
    if (first) {
      J(U - 1, U - 1) = 1.0;  // the parameter held
    } else {
      for (Eigen::Index k = 0; k < U; ++k) J(U - 1, k) = t_prev(cols[static_cast<std::size_t>(k)]);
      b(U - 1) = -g;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
    if (lu.rank() < U) {
      if (!sens) {  // a degenerate secant matrix: refresh it at the same point
        fresh = true;
        refreshed = true;
        continue;
      }
      o.status = "not_converged";
      o.message = "corrector iteration " + std::to_string(it) +
                  ": singular bordered Newton matrix (a branch point, or a step too long)";
      break;
    }
    Eigen::VectorXd dz = lu.solve(b);
    const double big = dz.head(N).cwiseAbs().maxCoeff() / max_step;
    const double big_t = autonomous ? std::abs(dz(N)) * DT / (0.2 * T) : 0.0;
    const double cap = std::max({1.0, big, big_t});
    dz /= cap;
    x += dz.head(N).cwiseProduct(Dx);
    if (autonomous) T += dz(N) * DT;
    p += dz(U - 1) * Dp;
    if (autonomous && !(T > 0)) {
      o.status = "not_converged";
      o.message = "corrector iteration " + std::to_string(it) + ": the period fell to ≤ 0";
      break;
    }
    R_prev = Rz;
    tcol_prev = tcol;
    dz_prev = dz;
  }
  o.reynolds_solves = solver.reynolds_solves() - solves0;
  o.period = autonomous ? T : at_parameter(c, p).period;
  o.r0 = x.head(n);
  o.v0 = x.tail(n);
  out.p = p;
  if (!converged) {
    if (o.status == "ok") {
      std::ostringstream os;
      os << "corrector did not converge in " << opt.max_iter << " Newton iterations: residual "
         << o.residual << " (tol " << opt.tol << "); shorten the step";
      o.status = "not_converged";
      o.message = os.str();
    }
    return out;
  }
  if (autonomous) {
    double extent = 0.0;
    for (Eigen::Index i = 0; i < run.X.rows(); ++i)
      extent = std::max(extent, (run.X.row(i).transpose() - x).cwiseQuotient(Dx).cwiseAbs().maxCoeff());
    if (extent < 100 * opt.tol) {
      std::ostringstream os;
      os << "the branch reached an equilibrium (the orbit's extent is " << extent
         << " of the length scale): the cycle has shrunk to a Hopf point";
      o.status = "not_converged";
      o.message = os.str();
      return out;
    }
  }
  if (!run.Phi.allFinite()) {
    o.status = "error";
    o.message = "non-finite monodromy matrix";
    return out;
  }
  o.t = run.t;
  o.r = run.X.leftCols(n);
  o.v = run.X.rightCols(n);
  if (final_pass) {
    o.monodromy = run.Phi;
    o.floquet = floquet(o.monodromy, autonomous);
    o.monodromy_rtol = pass_rtol;
    out.floquet_route = "flow";
  } else {
    const bool ok = samples_floquet(solver, in_p, run.X, autonomous, opt, srtol, o, out);
    o.reynolds_solves = solver.reynolds_solves() - solves0;
    if (!ok) return out;
  }
  // Tangent: null vector of the rows R (and phase) in the unknowns, bordered by the previous
  // tangent (first point: by e_p), oriented along it (first point: p growing with direction).
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(U, U);
  B.topRows(Rrows) = Jrp;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(U);
  e(U - 1) = 1.0;
  if (first) {
    B(U - 1, U - 1) = 1.0;
  } else {
    for (Eigen::Index k = 0; k < U; ++k) B(U - 1, k) = t_prev(cols[static_cast<std::size_t>(k)]);
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(B);
  Eigen::VectorXd tz = lu.solve(e);
  if (lu.rank() < U || !tz.allFinite() || tz.norm() == 0) {
    o.status = "not_converged";
    o.message = "no tangent at the corrected point (singular bordered matrix: a branch point)";
    return out;
  }
  tz /= tz.norm();
  if (first && tz(U - 1) * c.direction < 0) tz = -tz;
  out.tangent = Eigen::VectorXd::Zero(K);
  for (Eigen::Index k = 0; k < U; ++k) out.tangent(cols[static_cast<std::size_t>(k)]) = tz(k);
  out.jacobian = JR;
  return out;
}

}  // namespace rotordyn
