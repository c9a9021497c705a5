// Pseudo-arclength corrector by harmonic balance (hb_continuation.hpp). The residual, its
// Jacobian, the orbit's samples and the monodromy are harmonic_balance.cpp's (hb_detail.hpp);
// the operating point at a parameter value is the shooting corrector's (shooting_detail.hpp)
// over p_c, Ω and a_y, and the caller's provider over a model field: one corrector for both.
#include "rotordyn/hb_continuation.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include "hb_detail.hpp"
#include "rotordyn/errors.hpp"
#include "shooting_detail.hpp"

namespace rotordyn {

namespace {

using shooting_detail::Flow;

// The films' cavitation-set continuation, switched on in a solver while a system of the step
// uses it and off after its last: over p_c, Ω or a_y one solver for the whole step, over a
// model field each system the provider gives (the answer is the same unique film solution to
// round-off; the carried sets save active-set iterations).
struct FilmSwitch {
  bool on = false;
  std::vector<std::pair<SystemSolver*, int>> users;
  void take(SystemSolver* s) {
    if (!on) return;
    for (auto& u : users)
      if (u.first == s) {
        ++u.second;
        return;
      }
    s->set_film_continuation(true);
    users.emplace_back(s, 1);
  }
  void drop(SystemSolver* s) {
    if (!on) return;
    for (auto it = users.begin(); it != users.end(); ++it)
      if (it->first == s && --it->second == 0) {
        s->set_film_continuation(false);
        users.erase(it);
        return;
      }
  }
};

// Everything an evaluation at one parameter value needs: the system there (a refused value:
// none, every evaluation fails with the refusal), its flow data (M(Ω), F0, C + ΩG) and the AFT
// problem pointing at both (so not copyable), with the film solves of its evaluations.
struct At {
  std::shared_ptr<SystemSolver> solver;
  std::string refused;
  PeriodicInput in;
  Flow F;
  hb_detail::Problem P;
  FilmSwitch& films;
  long solves = 0;
  At(HbSystemAt sys, const hb_detail::Basis& B, Eigen::Index n, OrbitKind kind,
     const ShootingOptions& so, FilmSwitch& fs)
      : solver(std::move(sys.solver)), refused(std::move(sys.refused)), in(std::move(sys.input)),
        films(fs) {
    if (!solver) {
      if (refused.empty()) refused = "the system at this parameter value is not available";
      return;
    }
    require(solver->model().n() == n,
            "system_at: the system has " + std::to_string(solver->model().n()) +
                " coordinates, the coefficients " + std::to_string(n));
    require(in.kind == kind, "system_at: the orbit kind differs from the branch's");
    PeriodicInput chk = in;  // the operating point's checks, with a finite start
    chk.r0 = Eigen::VectorXd::Zero(n);
    chk.v0 = Eigen::VectorXd::Zero(n);
    if (kind == OrbitKind::autonomous) chk.period = 1.0;
    shooting_detail::validate(*solver, chk, so);
    shooting_detail::setup_flow(F, *solver, in);
    P.solver = solver.get();
    P.in = &in;
    P.F = &F;
    P.B = B;
    P.n = F.n;
    films.take(solver.get());
  }
  ~At() {
    if (solver) films.drop(solver.get());
  }
  At(const At&) = delete;
  At& operator=(const At&) = delete;
  /// ω of a forced orbit at this parameter (its period follows Ω); `w` for a refused value.
  double forced_w(double w) const { return solver ? 2 * M_PI / in.period : w; }
  hb_detail::Eval eval(const Eigen::MatrixXd& Z, double w, bool jac) {
    hb_detail::Eval e;
    if (!solver) {
      e.why = refused;
      return e;
    }
    const long s0 = solver->reynolds_solves();
    e = P.eval(Z, w, jac);
    solves += solver->reynolds_solves() - s0;
    return e;
  }
};

// The corrector of both entry points: `exact_c0` (n) the constant harmonic of ∂R/∂p where
// eq. 12 is affine in p (p_c, a_y), empty for the central difference on the systems at p ± h.
HbContinuationStep correct(const HbSystemProvider& system_at, const Eigen::VectorXd& exact_c0,
                           const HbContinuationInput& c, const HbContinuationOptions& opt) {
  const HarmonicBalanceOptions& ho = opt.hb;
  const int M = hb_detail::checked_time_points(ho);
  const int H = ho.harmonics, nb = 2 * H + 1;
  require(opt.floquet_margin >= 0 && opt.floquet_margin < 1,
          "floquet_margin: expected a value in [0, 1)");
  const Eigen::Index n = c.coefficients.cols(), nn = nb * n, Y = nn + 2;
  const bool autonomous = c.base.kind == OrbitKind::autonomous;
  require(c.coefficients.rows() == nb && n > 0 && c.coefficients.allFinite(),
          shape_msg("coefficients", nb, n, c.coefficients.rows(), c.coefficients.cols()) +
              " (2H + 1 rows) with finite values");
  require(c.scale.size() == 3 && c.scale.allFinite() && (c.scale.array() > 0).all(),
          shape_msg("scale", 3, 1, c.scale.size(), 1) + " with finite values > 0");
  require(c.y_prev.size() == Y && c.y_prev.allFinite(),
          shape_msg("y_prev", Y, 1, c.y_prev.size(), 1) + " with finite values");
  require(c.tangent.size() == 0 || (c.tangent.size() == Y && c.tangent.allFinite()),
          shape_msg("tangent", Y, 1, c.tangent.size(), 1) + " (or empty)");
  require(std::isfinite(c.p) && std::isfinite(c.ds), "p, ds: expected finite values");
  require(c.fd_step > 0 && c.fd_step < 1, "fd_step: expected a value in (0, 1)");
  require(!autonomous || (std::isfinite(c.frequency) && c.frequency > 0),
          "frequency: expected a finite ω > 0 rad/s for an autonomous orbit");
  ShootingOptions so;
  so.cvode = ho.cvode;
  so.tol = ho.tol;
  so.max_iter = ho.max_iter;
  so.sensitivity_rtol = ho.sensitivity_rtol;

  HbContinuationStep out;
  HarmonicBalanceResult& hb = out.hb;
  hb.harmonics = H;
  hb.time_points = M;
  PeriodicOrbitResult& o = hb.orbit;
  o.t0 = c.base.t0;
  const double L = c.scale(0), Dw = c.scale(1), Dp = c.scale(2);
  o.length_scale = L;
  const bool first = c.tangent.size() == 0;
  const hb_detail::Basis B = hb_detail::make_basis(H, M);
  FilmSwitch films;  // (before every At: they switch their solvers off as they go)
  films.on = ho.film_continuation;

  // The unknowns' columns: z, [ω], p; the full layout (y, tangent) always has the ω entry.
  const Eigen::Index U = autonomous ? nn + 2 : nn + 1, iw = nn, ip = U - 1;
  Eigen::VectorXd sfull(Y);
  sfull.head(nn).setConstant(L);
  sfull(nn) = Dw;
  sfull(nn + 1) = Dp;
  const Eigen::VectorXd yprev_s = c.y_prev.cwiseQuotient(sfull);
  auto to_unknowns = [&](const Eigen::VectorXd& full) {  // (Y) → (U)
    Eigen::VectorXd u(U);
    u.head(nn) = full.head(nn);
    if (autonomous) u(iw) = full(nn);
    u(ip) = full(nn + 1);
    return u;
  };
  const Eigen::VectorXd uprev = to_unknowns(yprev_s);
  const Eigen::VectorXd t_prev = first ? Eigen::VectorXd() : to_unknowns(c.tangent);
  auto flat = [&](const Eigen::MatrixXd& Z) {  // (nb, n) → (nn), row by row
    Eigen::VectorXd z(nn);
    for (int p = 0; p < nb; ++p) z.segment(p * n, n) = Z.row(p).transpose();
    return z;
  };
  auto unflat = [&](const Eigen::VectorXd& z) {
    Eigen::MatrixXd Z(nb, n);
    for (int p = 0; p < nb; ++p) Z.row(p) = z.segment(p * n, n).transpose();
    return Z;
  };
  // The integral phase condition against the previous point's coefficients (autonomous),
  // normalised; φᵀ z_prev = 0 identically.
  Eigen::VectorXd phi;
  if (autonomous) {
    const Eigen::MatrixXd Zp = unflat(c.y_prev.head(nn));
    phi = Eigen::VectorXd::Zero(nn);
    for (int k = 1; k <= H; ++k)
      for (Eigen::Index i = 0; i < n; ++i) {
        phi((2 * k - 1) * n + i) = k * Zp(2 * k, i);
        phi(2 * k * n + i) = -k * Zp(2 * k - 1, i);
      }
    const double pn = phi.norm();
    if (!(pn > 0)) {
      o.status = "not_converged";
      o.message = "the previous point has no harmonics (an equilibrium): no phase condition";
      return out;
    }
    phi /= pn;
  }

  Eigen::MatrixXd Z = c.coefficients;
  double p = c.p;
  long linearizations = 0, evaluations = 0, solves = 0;
  auto count = [&](const At& a) {
    linearizations += a.P.linearizations;
    evaluations += a.P.evaluations;
    solves += a.solves;
  };
  // Each system is counted once, when it is released: the iterates', the trials' and p ± h's.
  auto release = [&](std::unique_ptr<At>& a) {
    if (a) count(*a);
    a.reset();
  };
  auto make_at = [&](double pp) {
    return std::make_unique<At>(system_at(pp), B, n, c.base.kind, so, films);
  };
  std::unique_ptr<At> cur = make_at(p);
  double w = autonomous ? c.frequency : cur->forced_w(c.frequency);
  auto unknowns = [&](const Eigen::MatrixXd& Zc, double wc, double pc) {
    Eigen::VectorXd u(U);
    u.head(nn) = flat(Zc) / L;
    if (autonomous) u(iw) = wc / Dw;
    u(ip) = pc / Dp;
    return u;
  };
  // The condition rows' residuals: phase (autonomous) and arclength (the parameter held for
  // the first point: its row is e_p with a zero residual).
  auto conditions = [&](const Eigen::VectorXd& u) {
    Eigen::VectorXd g(autonomous ? 2 : 1);
    if (autonomous) g(0) = phi.dot(u.head(nn));
    g(g.size() - 1) = first ? 0.0 : t_prev.dot(u - uprev) - c.ds;
    return g;
  };
  Eigen::VectorXd rowscale;
  hb_detail::Eval e = cur->eval(Z, w, true);
  if (e.ok) rowscale = hb_detail::row_scale(e, cur->solver->model(), cur->F, cur->in.omega, w);

  // ∂R/∂p at (Z, w, p) (unscaled, nn): exact where given (the constant harmonic), else a
  // central difference of two residual evaluations on the systems at p ± h (ω follows Ω for
  // a forced orbit). Empty when an evaluation at p ± h fails.
  auto dRdp = [&]() -> Eigen::VectorXd {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(nn);
    if (exact_c0.size() == n) {
      d.head(n) = exact_c0;
      return d;
    }
    const double h = c.fd_step * Dp;
    std::unique_ptr<At> ap = make_at(p + h), am = make_at(p - h);
    const hb_detail::Eval ep = ap->eval(Z, autonomous ? w : ap->forced_w(w), false);
    const hb_detail::Eval em = am->eval(Z, autonomous ? w : am->forced_w(w), false);
    release(ap);
    release(am);
    out.fd_evaluations += 2;
    if (!ep.ok || !em.ok) return Eigen::VectorXd();
    d = (ep.R - em.R) / (2 * h);
    return d;
  };
  // The bordered rows without the arclength row (scaled): R̃ and the phase row.
  auto rows = [&](const hb_detail::Eval& ev, const Eigen::VectorXd& drdp) {
    const Eigen::Index Rr = autonomous ? nn + 1 : nn;
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(Rr, U);
    for (int q = 0; q < nb; ++q)
      J.block(q * n, 0, n, nn) = rowscale.cwiseInverse().asDiagonal() * ev.J.middleRows(q * n, n);
    const Eigen::VectorXd sp = hb_detail::scaled(drdp, rowscale, nb, L);
    J.block(0, ip, nn, 1) = sp * Dp;
    if (autonomous) {
      J.block(0, iw, nn, 1) = hb_detail::scaled(ev.dRdw, rowscale, nb, L) * Dw;
      J.block(nn, 0, 1, nn) = phi.transpose();
    }
    return J;
  };
  auto merit = [&](const Eigen::VectorXd& Rs, const Eigen::VectorXd& g) {
    return std::sqrt(Rs.squaredNorm() + g.squaredNorm());
  };

  bool converged = false;
  double res = std::numeric_limits<double>::infinity();
  Eigen::VectorXd drdp_conv;
  for (int it = 0; e.ok; ++it) {
    const Eigen::VectorXd Rs = hb_detail::scaled(e.R, rowscale, nb, L);
    const Eigen::VectorXd u = unknowns(Z, w, p);
    const Eigen::VectorXd g = conditions(u);
    res = std::max(Rs.cwiseAbs().maxCoeff(), g.cwiseAbs().maxCoeff());
    o.residuals.push_back(res);
    o.iterations = it;
    if (!std::isfinite(res)) {
      o.status = "error";
      o.message = "non-finite harmonic-balance residual";
      break;
    }
    const Eigen::VectorXd drdp = dRdp();
    if (drdp.size() == 0) {
      o.status = "not_converged";
      o.message = "corrector iteration " + std::to_string(it) +
                  ": a residual at p ± h for the parameter derivative failed";
      break;
    }
    if (res < ho.tol) {
      converged = true;
      drdp_conv = drdp;
      break;
    }
    if (it >= ho.max_iter) break;
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(U, U);
    const Eigen::MatrixXd Jr = rows(e, drdp);
    J.topRows(Jr.rows()) = Jr;
    Eigen::VectorXd b(U);
    b.head(nn) = -Rs;
    if (autonomous) b(nn) = -g(0);
    if (first) {
      J(U - 1, ip) = 1.0;
      b(U - 1) = 0.0;
    } else {
      J.row(U - 1) = t_prev.transpose();
      b(U - 1) = -g(g.size() - 1);
    }
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
    Eigen::VectorXd d = lu.solve(b);
    if (!d.allFinite() || (J * d - b).norm() > 1e-6 * std::max(b.norm(), 1e-300) + 1e-12) {
      o.status = "not_converged";
      o.message = "corrector iteration " + std::to_string(it) +
                  ": singular bordered Newton matrix (a branch point, or a step too long)";
      break;
    }
    const double cap = std::max({1.0, d.head(nn).cwiseAbs().maxCoeff() / 0.25,
                                 autonomous ? std::abs(d(iw)) * Dw / (0.1 * w) : 0.0,
                                 std::abs(d(ip)) / 0.25});
    d /= cap;
    const double m0 = merit(Rs, g);
    double lam = 1.0;
    hb_detail::Eval trial;
    std::unique_ptr<At> at_t;
    Eigen::MatrixXd Zt;
    double wt = w, pt = p;
    for (int ls = 0; ls < 8; ++ls, lam *= 0.5) {
      Zt = Z + lam * L * unflat(d.head(nn));
      pt = p + lam * d(ip) * Dp;
      release(at_t);
      at_t = make_at(pt);
      wt = autonomous ? w + lam * d(iw) * Dw : at_t->forced_w(w);
      trial = at_t->eval(Zt, wt, true);
      if (trial.ok &&
          merit(hb_detail::scaled(trial.R, rowscale, nb, L), conditions(unknowns(Zt, wt, pt))) <
              (1.0 - 1e-4 * lam) * m0)
        break;
      if (trial.ok && ls == 7) break;  // the smallest step: accepted (a kink of the film)
    }
    if (!trial.ok) {
      o.status = trial.contact ? "rub" : "not_converged";
      o.message = "corrector iteration " + std::to_string(it) + ": " + trial.why;
      e = trial;
      release(at_t);
      break;
    }
    if (autonomous && !(wt > 0)) {
      o.status = "not_converged";
      o.message = "corrector iteration " + std::to_string(it) + ": the frequency fell to ≤ 0";
      release(at_t);
      break;
    }
    Z = Zt;
    w = wt;
    p = pt;
    release(cur);
    cur = std::move(at_t);
    e = std::move(trial);
  }
  if (!e.ok && o.status == "ok") {
    o.status = e.contact ? "rub" : "not_converged";
    o.message = "harmonic balance at the predicted point: " + e.why;
  }
  hb.coefficients = Z;
  hb.frequency = w;
  hb.harmonic_amplitudes = hb_detail::harmonic_amplitudes(Z, L);
  out.p = p;
  o.residual = res;
  o.period = 2 * M_PI / w;
  o.r0 = (B.E.row(0) * Z).transpose();
  o.v0 = w * (B.E1.row(0) * Z).transpose();
  auto finish = [&]() {
    release(cur);
    o.reynolds_solves = solves;
    hb.linearizations = linearizations;
    hb.evaluations = evaluations;
  };
  if (!converged) {
    if (o.status == "ok") {
      std::ostringstream os;
      os << "corrector did not converge in " << ho.max_iter << " Newton iterations: residual "
         << res << " (tol " << ho.tol << "); shorten the step";
      o.status = "not_converged";
      o.message = os.str();
    }
    finish();
    return out;
  }
  // The converged point's checks and multipliers on its own system (Hill's method may
  // evaluate once more there: counted with it; a flow's film solves as well).
  hb_detail::PointFloquet pf;
  const long s0 = cur->solver->reynolds_solves();
  const bool done = hb_detail::finish_point(o, Z, w, L, cur->in, cur->F, cur->P, e, ho,
                                            opt.floquet_margin, pf);
  cur->solves += cur->solver->reynolds_solves() - s0;
  out.floquet_route = pf.route;
  out.screen_critical_modulus = pf.screen_critical_modulus;
  out.screen_trivial_error = pf.screen_trivial_error;
  out.floquet_error = pf.refined_error;
  out.floquet_steps = pf.refined_steps;
  if (!done) {
    finish();
    return out;
  }
  // Tangent: the null vector of the rows (R̃, phase) in the unknowns, bordered by the previous
  // tangent (first point: by e_p), oriented along it (first point: p growing with direction).
  Eigen::MatrixXd Bm = Eigen::MatrixXd::Zero(U, U);
  const Eigen::MatrixXd Jr = rows(e, drdp_conv);
  Bm.topRows(Jr.rows()) = Jr;
  if (first)
    Bm(U - 1, ip) = 1.0;
  else
    Bm.row(U - 1) = t_prev.transpose();
  Eigen::VectorXd eU = Eigen::VectorXd::Zero(U);
  eU(U - 1) = 1.0;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Bm);
  Eigen::VectorXd tz = lu.solve(eU);
  if (lu.rank() < U || !tz.allFinite() || tz.norm() == 0) {
    o.status = "not_converged";
    o.message = "no tangent at the corrected point (singular bordered matrix: a branch point)";
    finish();
    return out;
  }
  tz /= tz.norm();
  if (first && tz(ip) * c.direction < 0) tz = -tz;
  out.tangent = Eigen::VectorXd::Zero(Y);
  out.tangent.head(nn) = tz.head(nn);
  if (autonomous) out.tangent(nn) = tz(iw);
  out.tangent(nn + 1) = tz(ip);
  finish();
  return out;
}

}  // namespace

HbContinuationStep hb_continuation_step(SystemSolver& solver, const HbContinuationInput& c,
                                        const HbContinuationOptions& opt) {
  const SystemModel& m = solver.model();
  const Eigen::Index n = m.n();
  require(c.coefficients.cols() == n,
          shape_msg("coefficients", 2 * opt.hb.harmonics + 1, n, c.coefficients.rows(),
                    c.coefficients.cols()) + " (2H + 1 rows) with finite values");
  require(c.subharmonic >= 1, "subharmonic: expected at least 1");
  require(c.parameter != ContinuationParameter::config || c.config_direction.size() == n,
          shape_msg("config_direction", n, 1, c.config_direction.size(), 1));
  require(c.parameter != ContinuationParameter::speed || c.p != 0.0,
          "speed: the continuation parameter Ω must not be 0");
  // The one system (not owned: the caller's), at each value the operating point of `c.base`
  // moved by the parameter; ∂R/∂p exact for p_c and a_y.
  const std::shared_ptr<SystemSolver> s(&solver, [](SystemSolver*) {});
  const HbSystemProvider at = [&](double p) {
    HbSystemAt a;
    a.solver = s;
    a.input =
        shooting_detail::at_parameter(c.base, c.parameter, c.config_direction, c.subharmonic, p);
    return a;
  };
  Eigen::VectorXd exact;
  if (c.parameter == ContinuationParameter::chamber_pressure) exact = -m.chamber;
  if (c.parameter == ContinuationParameter::config)
    exact = m.offset_load(c.base.omega, c.config_direction);  // (K + Ω Kc) da
  return correct(at, exact, c, opt);
}

HbContinuationStep hb_continuation_step(const HbSystemProvider& system_at,
                                        const HbContinuationInput& c,
                                        const HbContinuationOptions& opt) {
  require(static_cast<bool>(system_at), "system_at: expected a provider of the systems");
  return correct(system_at, Eigen::VectorXd(), c, opt);
}

}  // namespace rotordyn
