// The harmonic-balance system on one assembled model (hb_field.hpp): the AFT evaluation and
// the converged point's Floquet multipliers of harmonic_balance.cpp / hb_continuation.cpp
// (hb_detail.hpp), callable on their own for a corrector that re-assembles the model.
#include "rotordyn/hb_field.hpp"

#include <algorithm>
#include <cmath>

#include "hb_detail.hpp"
#include "rotordyn/errors.hpp"
#include "shooting_detail.hpp"

namespace rotordyn {

namespace {

// The checks of an orbit input at (Z, ω): shapes, a positive frequency (a forced one the
// input's), the operating point (shooting_detail::validate on a copy with a finite start).
void check(const SystemSolver& solver, const PeriodicInput& in, const Eigen::MatrixXd& Z, double w,
           const HarmonicBalanceOptions& ho) {
  const Eigen::Index n = solver.model().n();
  const int nb = 2 * ho.harmonics + 1;
  require(Z.rows() == nb && Z.cols() == n && Z.allFinite(),
          shape_msg("coefficients", nb, n, Z.rows(), Z.cols()) +
              " (2H + 1 rows) with finite values");
  require(std::isfinite(w) && w > 0, "frequency: expected a finite ω > 0 rad/s");
  PeriodicInput chk = in;
  chk.r0 = Z.colwise().sum().transpose();  // any finite (n,) state
  chk.v0 = Eigen::VectorXd::Zero(n);
  if (in.kind == OrbitKind::autonomous) {
    chk.period = 2 * M_PI / w;
  } else {
    require(std::isfinite(in.period) && in.period > 0 &&
                std::abs(w * in.period - 2 * M_PI) <= 1e-12 * 2 * M_PI,
            "frequency: a forced orbit's ω must be 2π / period = " +
                std::to_string(2 * M_PI / in.period) + " rad/s, got " + std::to_string(w));
  }
  ShootingOptions so;
  so.cvode = ho.cvode;
  so.tol = ho.tol;
  so.max_iter = ho.max_iter;
  so.length_scale = ho.length_scale;
  so.sensitivity_rtol = ho.sensitivity_rtol;
  shooting_detail::validate(solver, chk, so);
}

}  // namespace

HbEvaluation hb_evaluate(SystemSolver& solver, const PeriodicInput& in,
                         const Eigen::MatrixXd& coefficients, double frequency,
                         const HarmonicBalanceOptions& opt, bool jacobian) {
  const int M = hb_detail::checked_time_points(opt);
  check(solver, in, coefficients, frequency, opt);
  shooting_detail::Flow F;
  shooting_detail::setup_flow(F, solver, in);
  hb_detail::Problem P;
  P.solver = &solver;
  P.in = &in;
  P.F = &F;
  P.B = hb_detail::make_basis(opt.harmonics, M);
  P.n = F.n;
  const long solves0 = solver.reynolds_solves();
  // The cavitation-set continuation between the samples, for this call only (each switch
  // forgets the stored sets): the evaluation is a function of its arguments.
  if (opt.film_continuation) solver.set_film_continuation(true);
  struct Off {
    SystemSolver& s;
    ~Off() { s.set_film_continuation(false); }
  } off{solver};
  hb_detail::Eval e = P.eval(coefficients, frequency, jacobian);
  HbEvaluation out;
  out.coefficients = coefficients;
  out.frequency = frequency;
  out.ok = e.ok;
  out.contact = e.contact;
  out.message = e.why;
  out.linearizations = P.linearizations;
  out.reynolds_solves = solver.reynolds_solves() - solves0;
  if (!e.ok) return out;
  out.residual = std::move(e.R);
  if (jacobian) {
    out.row_scale = hb_detail::row_scale(e, solver.model(), F, in.omega, frequency);
    out.jacobian = std::move(e.J);
    out.d_frequency = std::move(e.dRdw);
    out.film_stiffness = std::move(e.KH);
    out.film_damping = std::move(e.DH);
  }
  return out;
}

HbContinuationStep hb_orbit_point(SystemSolver& solver, const PeriodicInput& in,
                                  const HbEvaluation& at, const HbContinuationOptions& opt) {
  const HarmonicBalanceOptions& ho = opt.hb;
  const int M = hb_detail::checked_time_points(ho);
  require(opt.floquet_margin >= 0 && opt.floquet_margin < 1,
          "floquet_margin: expected a value in [0, 1)");
  require(at.ok, "at: expected a successful evaluation, got one that failed: " + at.message);
  check(solver, in, at.coefficients, at.frequency, ho);
  const Eigen::Index n = solver.model().n();
  require(static_cast<int>(at.film_stiffness.size()) == M &&
              static_cast<int>(at.film_damping.size()) == M,
          "at: expected an evaluation with the Jacobian at " + std::to_string(M) +
              " samples (the options' time points)");
  for (int j = 0; j < M; ++j)
    require(at.film_stiffness[static_cast<std::size_t>(j)].rows() == n &&
                at.film_stiffness[static_cast<std::size_t>(j)].cols() == n &&
                at.film_damping[static_cast<std::size_t>(j)].rows() == n &&
                at.film_damping[static_cast<std::size_t>(j)].cols() == n,
            "at: the films' K_H, D_H do not fit this system's " + std::to_string(n) +
                " coordinates");
  HbContinuationStep out;
  HarmonicBalanceResult& hb = out.hb;
  const int H = ho.harmonics;
  hb.harmonics = H;
  hb.time_points = M;
  hb.coefficients = at.coefficients;
  hb.frequency = at.frequency;
  const SystemModel& m = solver.model();
  const double L = hb_detail::length_scale(m, ho.length_scale);
  hb.harmonic_amplitudes = hb_detail::harmonic_amplitudes(at.coefficients, L);
  PeriodicOrbitResult& o = hb.orbit;
  o.t0 = in.t0;
  o.length_scale = L;
  o.period = 2 * M_PI / at.frequency;
  const hb_detail::Basis B = hb_detail::make_basis(H, M);
  o.r0 = (B.E.row(0) * at.coefficients).transpose();
  o.v0 = at.frequency * (B.E1.row(0) * at.coefficients).transpose();
  const long solves0 = solver.reynolds_solves();
  shooting_detail::Flow F;
  shooting_detail::setup_flow(F, solver, in);
  hb_detail::Problem P;  // Hill's method evaluates once more on its own time points
  P.solver = &solver;
  P.in = &in;
  P.F = &F;
  P.B = B;
  P.n = F.n;
  if (ho.film_continuation) solver.set_film_continuation(true);  // as hb_evaluate: this call only
  struct Off {
    SystemSolver& s;
    ~Off() { s.set_film_continuation(false); }
  } off{solver};
  hb_detail::Eval e;
  e.ok = true;
  e.R = at.residual;
  e.J = at.jacobian;
  e.dRdw = at.d_frequency;
  e.KH = at.film_stiffness;
  e.DH = at.film_damping;
  hb_detail::PointFloquet pf;
  hb_detail::finish_point(o, at.coefficients, at.frequency, L, in, F, P, e, ho,
                          opt.floquet_margin, pf);
  out.floquet_route = pf.route;
  out.screen_critical_modulus = pf.screen_critical_modulus;
  out.screen_trivial_error = pf.screen_trivial_error;
  hb.linearizations = pf.linearizations;
  hb.evaluations = pf.evaluations;
  o.reynolds_solves = solver.reynolds_solves() - solves0;
  return out;
}

}  // namespace rotordyn
