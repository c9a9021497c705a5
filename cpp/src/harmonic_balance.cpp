// Periodic orbits by harmonic balance with alternating frequency–time (harmonic_balance.hpp).
// Nothing global: the films' cavitation-set continuation is switched on for the call (the
// samples of one evaluation are consecutive nearby states, as a transient's right-hand sides)
// and off at its end, so the result is a function of the call's inputs.
#include "rotordyn/harmonic_balance.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rotordyn/errors.hpp"
#include "hb_detail.hpp"
#include "shooting_detail.hpp"

namespace rotordyn {

using shooting_detail::Flow;
using namespace hb_detail;

HarmonicBalanceResult harmonic_balance(SystemSolver& solver, const PeriodicInput& in,
                                       const Eigen::MatrixXd& start_samples,
                                       const HarmonicBalanceOptions& opt) {
  const int M = checked_time_points(opt);
  const int H = opt.harmonics;
  ShootingOptions so;
  so.cvode = opt.cvode;
  so.tol = opt.tol;
  so.length_scale = opt.length_scale;
  so.sensitivity_rtol = opt.sensitivity_rtol;
  shooting_detail::validate(solver, in, so);
  const SystemModel& m = solver.model();
  const Eigen::Index n = m.n(), N = 2 * n;
  if (start_samples.size()) {
    require(start_samples.cols() == n,
            "start_samples: expected " + std::to_string(n) + " columns (positions), got " +
                std::to_string(start_samples.cols()));
    require(start_samples.rows() >= 2 * H + 1,
            "start_samples: expected at least 2H + 1 = " + std::to_string(2 * H + 1) +
                " samples over the period, got " + std::to_string(start_samples.rows()));
    require(start_samples.allFinite(), "start_samples: expected finite values");
  }
  HarmonicBalanceResult out;
  out.harmonics = H;
  out.time_points = M;
  PeriodicOrbitResult& o = out.orbit;
  o.t0 = in.t0;
  const long solves0 = solver.reynolds_solves();
  const bool autonomous = in.kind == OrbitKind::autonomous;

  Flow F;
  shooting_detail::setup_flow(F, solver, in);
  const double L = hb_detail::length_scale(m, opt.length_scale);
  o.length_scale = L;

  // The start's coefficients.
  Eigen::MatrixXd Z;
  if (start_samples.size()) {
    Z = project_samples(start_samples, H);
  } else {
    Eigen::VectorXd x0(N);
    x0 << in.r0, in.v0;
    const int ms = std::max(M, 4 * H);
    shooting_detail::FlowRun run = shooting_detail::run_flow(F, x0, in.t0, in.period, false, ms + 1,
                                                             opt.cvode, false, opt.cvode.rtol);
    o.steps += run.steps;
    o.rhs_evals += run.rhs_evals;
    o.jac_evals += run.jac_evals;
    if (run.flag < 0) {
      o.status = F.contact ? "rub" : "not_converged";
      o.message = "harmonic balance: the start flow failed: " + run.why;
      o.reynolds_solves = solver.reynolds_solves() - solves0;
      return out;
    }
    Z = project_samples(run.X.topRows(ms).leftCols(n), H);
  }
  double w = 2 * M_PI / in.period;
  int ip = -1;  // the phase coordinate (autonomous)
  if (autonomous) {
    double best = -1.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double a1 = std::hypot(Z(1, i), Z(2, i));
      if (a1 > best) {
        best = a1;
        ip = static_cast<int>(i);
      }
    }
    if (!(best > 0)) {
      o.status = "not_converged";
      o.message = "harmonic balance: the start has no first harmonic (an equilibrium): start on "
                  "or near a cycle";
      return out;
    }
    shift_phase(Z, H, std::atan2(Z(2, ip), Z(1, ip)));
    Z(2, ip) = 0.0;
  }

  Problem P;
  P.solver = &solver;
  P.in = &in;
  P.F = &F;
  P.B = make_basis(H, M);
  P.n = n;
  const int nb = P.B.nb;
  const Eigen::Index nn = n * nb;
  const Eigen::Index K = autonomous ? nn + 1 : nn;

  if (opt.film_continuation) solver.set_film_continuation(true);
  struct Off {
    SystemSolver& s;
    ~Off() { s.set_film_continuation(false); }
  } off{solver};

  // Row scales: each coordinate's |K_ii + K_H,ii| + ω²|M_ii| + ω|C_ii + D_H,ii| at the start
  // (the residual in units of a displacement), so ‖R̃‖ is measured in L.
  Eigen::VectorXd rowscale;
  auto scaled = [&](const Eigen::VectorXd& R) { return hb_detail::scaled(R, rowscale, nb, L); };
  Eval e = P.eval(Z, w, true);
  if (e.ok) rowscale = row_scale(e, m, F, in.omega, w);
  bool converged = false;
  double res = std::numeric_limits<double>::infinity();
  for (int it = 0; e.ok; ++it) {
    const Eigen::VectorXd Rs = scaled(e.R);
    res = Rs.cwiseAbs().maxCoeff();
    o.residuals.push_back(res);
    o.iterations = it;
    if (res < opt.tol) {
      converged = true;
      break;
    }
    if (it >= opt.max_iter) break;
    // Newton in scaled unknowns z̃ = z / L, ω̃ = ω / ω_now; rows scaled as Rs.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(K, K);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(K);
    for (int p = 0; p < nb; ++p)
      J.block(p * n, 0, n, nn) = rowscale.cwiseInverse().asDiagonal() * e.J.middleRows(p * n, n);
    b.head(nn) = -Rs;
    if (autonomous) {
      Eigen::VectorXd col(nn);
      for (int p = 0; p < nb; ++p) col.segment(p * n, n) = e.dRdw.segment(p * n, n).cwiseQuotient(rowscale);
      J.block(0, nn, nn, 1) = col * (w / L);
      J(nn, 2 * n + ip) = 1.0;  // b_1 of the phase coordinate (row 2 of Z)
      b(nn) = -Z(2, ip) / L;
    }
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
    Eigen::VectorXd d = lu.solve(b);
    if (!d.allFinite() || (J * d - b).norm() > 1e-6 * std::max(b.norm(), 1e-300) + 1e-12) {
      o.status = "not_converged";
      o.message = "harmonic balance iteration " + std::to_string(it) +
                  ": singular Newton matrix (a Floquet multiplier at 1, or the start is an "
                  "equilibrium)";
      break;
    }
    // Deflation of the equilibria (autonomous; Farrell, Birkisson & Funke, SIAM J. Sci.
    // Comput. 37 (2015) A2026): every constant r is an HB solution of any ω, and plain
    // Newton from a start off the cycle tends to fall onto it. Newton on m(z) R with
    // m = ‖z_h‖⁻ᵖ + σ (z_h the harmonics k ≥ 1, scaled; p = 2, σ = 1) has the same roots
    // away from the equilibria; its step is the Newton step times 1 / (1 − m⁻¹ ∇mᵀ d),
    // which turns a step that shrinks the harmonics into one that does not.
    auto harm2 = [&](const Eigen::MatrixXd& Zc) {
      double h2 = 0.0;
      for (int p = 1; p < nb; ++p)
        for (Eigen::Index i = 0; i < n; ++i) h2 += Zc(p, i) * Zc(p, i);
      return h2 / (L * L);
    };
    if (autonomous && opt.deflation) {
      const double h2 = harm2(Z), mz = 1.0 / std::max(h2, 1e-300) + 1.0;
      double zd = 0.0;  // z_hᵀ d_h in scaled units
      for (int p = 1; p < nb; ++p) zd += Z.row(p).dot(d.segment(p * n, n)) / L;
      const double g = -2.0 * zd / (h2 * h2) / mz;  // m⁻¹ ∇mᵀ d
      const double tau = 1.0 / (1.0 - g);
      if (std::isfinite(tau)) d *= tau;
    }
    // The cap: a limit cycle's every coefficient at 0.25 L (the rig's published runs); a
    // forced orbit's step at 0.25 of a clearance in film thickness at any sample (rotations
    // and coordinates far from the films are not capped as lengths: film_step_fraction).
    double big = d.head(nn).cwiseAbs().maxCoeff() / 0.25;
    if (!autonomous) {
      Eigen::MatrixXd Dz(nb, n);
      for (int p = 0; p < nb; ++p) Dz.row(p) = L * d.segment(p * n, n).transpose();
      big = shooting_detail::film_step_fraction(m, P.B.E * Dz) / 0.25;
    }
    const double cap = std::max({1.0, big, autonomous ? std::abs(d(nn)) / 0.1 : 0.0});
    d /= cap;
    auto dmerit = [&](const Eigen::MatrixXd& Zc, const Eigen::VectorXd& Rsc) {
      return (autonomous && opt.deflation) ? (1.0 / std::max(harm2(Zc), 1e-300) + 1.0) * Rsc.norm()
                                           : Rsc.norm();
    };
    const double merit = dmerit(Z, Rs);
    double lam = 1.0;
    Eval trial;
    Eigen::MatrixXd Zt;
    double wt = w;
    for (int ls = 0; ls < 8; ++ls, lam *= 0.5) {
      Zt = Z;
      for (int p = 0; p < nb; ++p) Zt.row(p) += lam * L * d.segment(p * n, n).transpose();
      wt = autonomous ? w * (1.0 + lam * d(nn)) : w;
      trial = P.eval(Zt, wt, true);
      if (trial.ok && dmerit(Zt, scaled(trial.R)) < (1.0 - 1e-4 * lam) * merit) break;
      if (trial.ok && ls == 7) break;  // the smallest step: accepted (a kink of the film)
    }
    if (!trial.ok) {
      o.status = trial.contact ? "rub" : "not_converged";
      o.message = "harmonic balance iteration " + std::to_string(it) + ": " + trial.why;
      e = trial;
      break;
    }
    Z = Zt;
    w = wt;
    e = std::move(trial);
  }
  if (!e.ok && o.status == "ok") {
    o.status = e.contact ? "rub" : "not_converged";
    o.message = "harmonic balance at the start: " + e.why;
  }
  out.coefficients = Z;
  out.frequency = w;
  out.linearizations = P.linearizations;
  out.evaluations = P.evaluations;
  out.harmonic_amplitudes = harmonic_amplitudes(Z, L);
  const double T = 2 * M_PI / w;
  o.period = T;
  o.residual = res;
  auto finish = [&]() { o.reynolds_solves = solver.reynolds_solves() - solves0; };
  // The start at τ = 0.
  o.r0 = (P.B.E.row(0) * Z).transpose();
  o.v0 = w * (P.B.E1.row(0) * Z).transpose();
  if (!converged) {
    if (o.status == "ok") {
      o.status = "not_converged";
      std::ostringstream os;
      os << "harmonic balance did not converge in " << opt.max_iter << " Newton iterations: "
         << "residual " << res << " (tol " << opt.tol << "); the start may not be near a "
         << "periodic orbit";
      o.message = os.str();
    }
    finish();
    return out;
  }
  if (autonomous && out.harmonic_amplitudes.tail(H).maxCoeff() < std::max(100 * opt.tol, 1e-4)) {
    std::ostringstream os;
    os << "harmonic balance converged to an equilibrium (first harmonics "
       << out.harmonic_amplitudes.tail(H).maxCoeff() << " of the length scale), not a limit "
       << "cycle: start on or near a cycle";
    o.status = "not_converged";
    o.message = os.str();
    finish();
    return out;
  }
  // The orbit over one period, n_out samples including the end point.
  if (!fill_orbit(o, Z, w, in.t0, in.n_out)) {
    o.status = "error";
    o.message = "non-finite harmonic-balance orbit";
    finish();
    return out;
  }
  if (opt.floquet == HbFloquet::samples && opt.floquet_tol > 0) {
    RefinedMonodromy rm = refined_monodromy(P, e, Z, w, autonomous, opt.floquet_tol,
                                            refined_max_steps(M, opt.floquet_max_steps));
    out.linearizations = P.linearizations;
    out.floquet_linearizations = rm.linearizations;
    out.floquet_steps = rm.steps;
    out.floquet_levels = rm.levels;
    out.floquet_moduli = rm.moduli;
    if (!rm.ok) {
      o.status = rm.contact ? "rub" : "error";
      o.message = "harmonic balance: the Floquet multipliers from the samples: " + rm.why;
      finish();
      return out;
    }
    out.floquet_error = rm.error;
    out.floquet_converged = rm.converged;
    out.floquet_trivial_error = autonomous ? rm.trivial_error
                                           : std::numeric_limits<double>::quiet_NaN();
    o.monodromy = std::move(rm.Phi);
    o.monodromy_rtol = 0.0;
  } else if (opt.floquet == HbFloquet::samples) {
    o.monodromy = sample_monodromy(F, m, e, T, opt.magnus_substeps);
    o.monodromy_rtol = 0.0;
  } else if (opt.floquet == HbFloquet::hill) {
    const bool ok = hill_floquet_into(o, P, e, Z, w, autonomous, opt.hill_selection,
                                      hill_time_points(H, M, opt.hill_time_points));
    out.linearizations = P.linearizations;
    out.evaluations = P.evaluations;
    if (!ok) {
      finish();
      return out;
    }
  } else if (opt.floquet == HbFloquet::flow) {
    const double srtol = opt.sensitivity_rtol > 0 ? opt.sensitivity_rtol : opt.cvode.rtol;
    if (!flow_monodromy(F, o, in.t0, T, opt.cvode, srtol)) {
      finish();
      return out;
    }
  }
  if (opt.floquet != HbFloquet::none && opt.floquet != HbFloquet::hill) {
    if (!o.monodromy.allFinite()) {
      o.status = "error";
      o.message = "non-finite monodromy matrix";
      o.monodromy.resize(0, 0);
      finish();
      return out;
    }
    o.floquet = floquet(o.monodromy, autonomous);
  }
  finish();
  return out;
}

}  // namespace rotordyn
