// The harmonic-balance pieces shared by one orbit and a branch's corrector (hb_detail.hpp).
#include "hb_detail.hpp"

#include <Eigen/Cholesky>
#include <unsupported/Eigen/MatrixFunctions>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rotordyn/errors.hpp"

namespace rotordyn::hb_detail {

Basis make_basis(int H, int M) {
  Basis b;
  b.H = H;
  b.M = M;
  b.nb = 2 * H + 1;
  b.E.setZero(M, b.nb);
  b.E1.setZero(M, b.nb);
  b.E2.setZero(M, b.nb);
  b.P.setZero(b.nb, M);
  for (int j = 0; j < M; ++j) {
    const double tau = 2 * M_PI * j / M;
    b.E(j, 0) = 1.0;
    b.P(0, j) = 1.0 / M;
    for (int k = 1; k <= H; ++k) {
      const double c = std::cos(k * tau), s = std::sin(k * tau);
      b.E(j, 2 * k - 1) = c;
      b.E(j, 2 * k) = s;
      b.E1(j, 2 * k - 1) = -k * s;
      b.E1(j, 2 * k) = k * c;
      b.E2(j, 2 * k - 1) = -k * k * c;
      b.E2(j, 2 * k) = -k * k * s;
      b.P(2 * k - 1, j) = 2.0 * c / M;
      b.P(2 * k, j) = 2.0 * s / M;
    }
  }
  return b;
}

Eval Problem::eval(const Eigen::MatrixXd& Z, double w, bool jac) {
  const SystemModel& m = solver->model();
  const PeriodicInput& I = *in;
  const int M = B.M, nb = B.nb;
  const Eigen::Index nn = n * nb;
  Eval e;
  e.R.setZero(nn);
  if (jac) {
    e.J.setZero(nn, nn);
    e.dRdw.setZero(nn);
    e.KH.resize(static_cast<std::size_t>(M));
    e.DH.resize(static_cast<std::size_t>(M));
  }
  const Eigen::MatrixXd Rt = B.E * Z, R1 = B.E1 * Z, R2 = B.E2 * Z;  // (M, n)
  const Eigen::MatrixXd& Mm = m.mass_at(I.omega);
  const bool forced = I.unbalance_cos.size() > 0;
  ++evaluations;
  for (int j = 0; j < M; ++j) {
    const Eigen::VectorXd r = Rt.row(j).transpose(), r1 = R1.row(j).transpose(),
                          r2 = R2.row(j).transpose();
    const Eigen::VectorXd v = w * r1;
    Linearization lin;
    try {
      if (jac) {
        lin = solver->linearize(r, v, I.omega);
        ++linearizations;
      } else {
        lin.film_force = solver->film_forces(r, v, I.omega);
      }
    } catch (const ContactError& ex) {
      e.contact = true;
      e.why = std::string("a film closed at sample ") + std::to_string(j) + ": " + ex.what();
      return e;
    } catch (const ConvergenceError& ex) {
      e.why = std::string("film solve at sample ") + std::to_string(j) + ": " + ex.what();
      return e;
    }
    if (!lin.film_force.allFinite()) {
      e.why = "non-finite film force at sample " + std::to_string(j);
      return e;
    }
    Eigen::VectorXd Rj = w * w * (Mm * r2) + w * (F->Cd * r1) + m.K * r - lin.film_force - F->F0;
    if (forced) {
      const double th = I.omega * (I.t0 + (2 * M_PI * j / M) / w);
      Rj -= I.omega * I.omega * (std::cos(th) * I.unbalance_cos + std::sin(th) * I.unbalance_sin);
    }
    for (int p = 0; p < nb; ++p) e.R.segment(p * n, n) += B.P(p, j) * Rj;
    if (!jac) continue;
    const Eigen::MatrixXd G = m.K + lin.KH;
    const Eigen::MatrixXd Dv = F->Cd + lin.DH;
    const Eigen::VectorXd dw = 2 * w * (Mm * r2) + Dv * r1;
    for (int p = 0; p < nb; ++p) e.dRdw.segment(p * n, n) += B.P(p, j) * dw;
    add_sample_block(e.J, B, j, G, w, Dv, w * w, Mm);
    e.KH[static_cast<std::size_t>(j)] = lin.KH;
    e.DH[static_cast<std::size_t>(j)] = lin.DH;
  }
  if (!e.R.allFinite() || (jac && !e.J.allFinite())) {
    e.why = "non-finite residual or Jacobian";
    return e;
  }
  e.ok = true;
  return e;
}

Eigen::MatrixXd project_samples(const Eigen::MatrixXd& X, int H) {
  const Eigen::Index M0 = X.rows();
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(2 * H + 1, X.cols());
  for (Eigen::Index j = 0; j < M0; ++j) {
    const double tau = 2 * M_PI * static_cast<double>(j) / static_cast<double>(M0);
    Z.row(0) += X.row(j) / static_cast<double>(M0);
    for (int k = 1; k <= H; ++k) {
      Z.row(2 * k - 1) += 2.0 * std::cos(k * tau) * X.row(j) / static_cast<double>(M0);
      Z.row(2 * k) += 2.0 * std::sin(k * tau) * X.row(j) / static_cast<double>(M0);
    }
  }
  return Z;
}

void shift_phase(Eigen::MatrixXd& Z, int H, double phi) {
  for (int k = 1; k <= H; ++k) {
    const double c = std::cos(k * phi), s = std::sin(k * phi);
    const Eigen::RowVectorXd a = Z.row(2 * k - 1), b = Z.row(2 * k);
    Z.row(2 * k - 1) = a * c + b * s;
    Z.row(2 * k) = b * c - a * s;
  }
}

double length_scale(const SystemModel& m, double length_scale) {
  if (length_scale > 0) return length_scale;
  double L = std::numeric_limits<double>::infinity();
  for (const FilmCoupling& fc : m.films) L = std::min(L, fc.geometry.clearance_m);
  return std::isfinite(L) ? L : 1e-3;
}

Eigen::VectorXd row_scale(const Eval& e, const SystemModel& m, const shooting_detail::Flow& F,
                          double omega, double w) {
  const Eigen::Index n = F.n;
  const Eigen::MatrixXd& Mm = m.mass_at(omega);
  Eigen::VectorXd s(n);
  const double ws = std::max(std::abs(omega), w);
  // The ω-independent part of the Jacobian's c0 block is mean(K + K_H).
  const Eigen::MatrixXd G0 = e.J.block(0, 0, n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    s(i) = std::abs(G0(i, i)) + ws * ws * std::abs(Mm(i, i)) + ws * std::abs(F.Cd(i, i)) + 1e-300;
  return s;
}

Eigen::VectorXd scaled(const Eigen::VectorXd& R, const Eigen::VectorXd& rowscale, int nb, double L) {
  const Eigen::Index n = rowscale.size();
  Eigen::VectorXd s(R.size());
  for (int p = 0; p < nb; ++p) s.segment(p * n, n) = R.segment(p * n, n).cwiseQuotient(rowscale);
  return s / L;
}

Eigen::VectorXd harmonic_amplitudes(const Eigen::MatrixXd& Z, double L) {
  const int H = static_cast<int>((Z.rows() - 1) / 2);
  Eigen::VectorXd a(H + 1);
  a(0) = Z.row(0).cwiseAbs().maxCoeff() / L;
  for (int k = 1; k <= H; ++k)
    a(k) = (Z.row(2 * k - 1).array().square() + Z.row(2 * k).array().square()).sqrt().maxCoeff() / L;
  return a;
}

bool fill_orbit(PeriodicOrbitResult& o, const Eigen::MatrixXd& Z, double w, double t0, int n_out) {
  const int H = static_cast<int>((Z.rows() - 1) / 2), nb = 2 * H + 1;
  const Eigen::Index n = Z.cols();
  const double T = 2 * M_PI / w;
  o.period = T;
  const int ns = std::max(n_out, 2);
  o.t.resize(ns);
  o.r.resize(ns, n);
  o.v.resize(ns, n);
  for (int i = 0; i < ns; ++i) {
    const double tau = 2 * M_PI * i / (ns - 1);
    o.t(i) = t0 + T * i / (ns - 1);
    Eigen::RowVectorXd E(nb), E1(nb);
    E(0) = 1.0;
    E1(0) = 0.0;
    for (int k = 1; k <= H; ++k) {
      E(2 * k - 1) = std::cos(k * tau);
      E(2 * k) = std::sin(k * tau);
      E1(2 * k - 1) = -k * std::sin(k * tau);
      E1(2 * k) = k * std::cos(k * tau);
    }
    o.r.row(i) = E * Z;
    o.v.row(i) = w * (E1 * Z);
  }
  o.r0 = o.r.row(0).transpose();
  o.v0 = o.v.row(0).transpose();
  return o.r.allFinite() && o.v.allFinite();
}

// exp(A) = D exp(D⁻¹ A D) D⁻¹ with D diagonal, powers of 2 (exact), balancing the rows and
// columns of A (Osborne's iteration, as LAPACK's gebal). The first-order matrix of a
// flexible rotor mixes metres, radians and their rates: on the overhung pump (36
// coordinates, tilted films) ‖A h‖₁ ≈ 2e8 where its eigenvalues are ≤ 41, and the scaling
// and squaring of the exponential, sized by the norm, took 12 s CPU for the 128 steps of one
// monodromy (balanced: under a second; docs/nonlinear.md).
Eigen::MatrixXd balanced_exp(const Eigen::MatrixXd& A) {
  const Eigen::Index N = A.rows();
  // A non-finite entry: no balancing (an inf row or column sum never settles in the loops
  // below); the exponential is non-finite and the caller falls back to the flow.
  if (!A.allFinite())
    return Eigen::MatrixXd::Constant(N, N, std::numeric_limits<double>::quiet_NaN());
  Eigen::MatrixXd B = A;
  Eigen::VectorXd d = Eigen::VectorXd::Ones(N);
  bool changed = true;
  for (int sweep = 0; changed && sweep < 64; ++sweep) {
    changed = false;
    for (Eigen::Index i = 0; i < N; ++i) {
      double c = B.col(i).cwiseAbs().sum() - std::abs(B(i, i));
      double r = B.row(i).cwiseAbs().sum() - std::abs(B(i, i));
      if (!(c > 0.0) || !(r > 0.0)) continue;
      const double total = c + r;
      double f = 1.0;
      while (c < 0.5 * r) {
        c *= 2.0;
        r *= 0.5;
        f *= 2.0;
      }
      while (c >= 2.0 * r) {
        c *= 0.5;
        r *= 2.0;
        f *= 0.5;
      }
      if (c + r < 0.95 * total) {
        changed = true;
        d(i) *= f;
        B.col(i) *= f;
        B.row(i) /= f;
      }
    }
  }
  return d.asDiagonal() * B.exp() * d.cwiseInverse().asDiagonal();
}

namespace {

// Monodromy of ẋ = A(t) x over one period from the samples A_j = A(t_j) (first-order form),
// A(τ) trigonometrically interpolated, 4th-order Magnus (two Gauss points per step) with
// the exact exponential of each step (stable for the stiff sleeve and film modes).
Eigen::MatrixXd monodromy_from_samples(const std::vector<Eigen::MatrixXd>& A, double T,
                                       int substeps) {
  const int M = static_cast<int>(A.size());
  const Eigen::Index N = A[0].rows();
  const int K = (M - 1) / 2;
  const bool nyq = M % 2 == 0;
  std::vector<Eigen::MatrixXd> Ac(static_cast<std::size_t>(K + 1), Eigen::MatrixXd::Zero(N, N)),
      As(static_cast<std::size_t>(K + 1), Eigen::MatrixXd::Zero(N, N));
  Eigen::MatrixXd An = Eigen::MatrixXd::Zero(N, N);
  for (int j = 0; j < M; ++j) {
    const double tau = 2 * M_PI * j / M;
    Ac[0] += A[static_cast<std::size_t>(j)] / M;
    for (int k = 1; k <= K; ++k) {
      Ac[static_cast<std::size_t>(k)] += (2.0 * std::cos(k * tau) / M) * A[static_cast<std::size_t>(j)];
      As[static_cast<std::size_t>(k)] += (2.0 * std::sin(k * tau) / M) * A[static_cast<std::size_t>(j)];
    }
    if (nyq) An += (std::cos(0.5 * M * tau) / M) * A[static_cast<std::size_t>(j)];
  }
  auto at = [&](double tau) {
    Eigen::MatrixXd out = Ac[0];
    for (int k = 1; k <= K; ++k)
      out += std::cos(k * tau) * Ac[static_cast<std::size_t>(k)] +
             std::sin(k * tau) * As[static_cast<std::size_t>(k)];
    if (nyq) out += std::cos(0.5 * M * tau) * An;
    return out;
  };
  const int ns = M * std::max(substeps, 1);
  const double h = T / ns, dtau = 2 * M_PI / ns;
  const double g = std::sqrt(3.0) / 6.0;
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Identity(N, N);
  for (int i = 0; i < ns; ++i) {
    const Eigen::MatrixXd A1 = at((i + 0.5 - g) * dtau), A2 = at((i + 0.5 + g) * dtau);
    const Eigen::MatrixXd Om =
        (0.5 * h) * (A1 + A2) + (std::sqrt(3.0) / 12.0 * h * h) * (A2 * A1 - A1 * A2);
    Phi = balanced_exp(Om) * Phi;
  }
  return Phi;
}

}  // namespace

Eigen::MatrixXd sample_monodromy(const shooting_detail::Flow& F, const SystemModel& m,
                                 const Eval& e, double T, int substeps) {
  const Eigen::Index n = F.n, N = F.N;
  const int M = static_cast<int>(e.KH.size());
  std::vector<Eigen::MatrixXd> A(static_cast<std::size_t>(M));
  for (int j = 0; j < M; ++j) {
    Eigen::MatrixXd Aj = Eigen::MatrixXd::Zero(N, N);
    Aj.block(0, n, n, n).setIdentity();
    Aj.block(n, 0, n, n) = -F.Mllt.solve(m.K + e.KH[static_cast<std::size_t>(j)]);
    Aj.block(n, n, n, n) = -F.Mllt.solve(F.Cd + e.DH[static_cast<std::size_t>(j)]);
    A[static_cast<std::size_t>(j)] = Aj;
  }
  return monodromy_from_samples(A, T, substeps);
}

bool flow_monodromy(shooting_detail::Flow& F, PeriodicOrbitResult& o, double t0, double T,
                    const CvodeOptions& cvode, double srtol) {
  Eigen::VectorXd x0(F.N);
  x0 << o.r0, o.v0;
  const long sens0 = F.sens_evals;
  shooting_detail::FlowRun run = shooting_detail::run_flow(F, x0, t0, T, true, 2, cvode, true, srtol);
  o.steps += run.steps;
  o.rhs_evals += run.rhs_evals;
  o.jac_evals += run.jac_evals;
  o.sensitivity_flows += 1;
  o.sens_rhs_evals += F.sens_evals - sens0;
  if (run.flag < 0) {
    o.status = F.contact ? "rub" : "error";
    o.message = "the monodromy flow failed: " + run.why;
    return false;
  }
  o.monodromy = run.Phi;
  o.monodromy_rtol = srtol;
  return true;
}

bool screen_close(const Floquet& fq, double margin, bool hill, PointFloquet& pf) {
  pf.screen_critical_modulus = fq.critical >= 0 ? fq.critical_modulus : 0.0;
  pf.screen_trivial_error = fq.trivial >= 0 ? std::abs(fq.multipliers(fq.trivial) - 1.0) : 0.0;
  const double et = pf.screen_trivial_error;
  // samples: near the unit circle, or a poor monodromy (trivial error above margin / 2);
  // Hill: near the unit circle by the margin widened by 3 × the trivial error. Hill's
  // |μ_c| error against the flow was ≤ 3.6e-4 on the rig's 50-point branch and ≤ 7.7e-3 on
  // the compressor's 30-point whip branch (trivial errors ≤ 9.5e-4 and ≤ 1.6e-2): inside
  // the margin, but not proportional to the trivial error (up to 27 × it), so the trivial
  // error only widens the band (docs/nonlinear.md, "Floquet multipliers by Hill's method").
  const bool near = hill ? std::abs(fq.critical_modulus - 1.0) < margin + 3.0 * et
                         : (std::abs(fq.critical_modulus - 1.0) < margin || et > 0.5 * margin);
  return margin > 0 && (fq.critical < 0 || near);
}

bool take_refined(RefinedMonodromy& rm, bool autonomous, PeriodicOrbitResult& o,
                  PointFloquet& pf) {
  pf.refined_steps = rm.steps;
  if (!(rm.ok && rm.converged && rm.Phi.allFinite())) return false;
  const Floquet fr = floquet(rm.Phi, autonomous);
  if (!(fr.critical >= 0 && std::abs(fr.critical_modulus - 1.0) > rm.error)) return false;
  o.monodromy = std::move(rm.Phi);
  o.monodromy_rtol = 0.0;
  pf.route = "refined";
  pf.refined_error = rm.error;
  return true;
}

bool finish_point(PeriodicOrbitResult& o, const Eigen::MatrixXd& Z, double w, double L,
                  const PeriodicInput& in, shooting_detail::Flow& F, Problem& P, const Eval& e,
                  const HarmonicBalanceOptions& ho, double margin, PointFloquet& pf) {
  const int H = static_cast<int>((Z.rows() - 1) / 2);
  const bool autonomous = in.kind == OrbitKind::autonomous;
  const SystemModel& m = P.solver->model();
  const double hmax = harmonic_amplitudes(Z, L).tail(H).maxCoeff();
  if (autonomous && hmax < std::max(100 * ho.tol, 1e-4)) {
    std::ostringstream os;
    os << "the branch reached an equilibrium (the orbit's harmonics are " << hmax
       << " of the length scale): the cycle has shrunk to a Hopf point";
    o.status = "not_converged";
    o.message = os.str();
    return false;
  }
  if (!fill_orbit(o, Z, w, in.t0, in.n_out)) {
    o.status = "error";
    o.message = "non-finite harmonic-balance orbit";
    return false;
  }
  // Floquet multipliers: from the screening route (the samples' linearisations, or Hill's
  // method on the converged Jacobian), recomputed by one sensitivity flow where the verdict is
  // not safe at the screen's accuracy: |μ_c| within the margin of 1, or the trivial multiplier
  // off 1 by more than half the margin (measured on the rig and the compressor's whip cycles:
  // the samples' |μ_c| within 1.5 × their trivial error of the flow's at all but one point,
  // and within 1.4e-3 there; Hill's: below).
  const double T = o.period;
  const double srtol = ho.sensitivity_rtol > 0 ? ho.sensitivity_rtol : ho.cvode.rtol;
  pf.screen_critical_modulus = pf.screen_trivial_error = std::numeric_limits<double>::quiet_NaN();
  // (floquet = flow: the samples' multipliers are computed as well, for the record: a few
  // milliseconds of dense algebra.)
  bool flow = ho.floquet == HbFloquet::flow;
  bool screened = false;
  if (ho.floquet == HbFloquet::samples || flow) {
    o.monodromy = sample_monodromy(F, m, e, T, ho.magnus_substeps);
    o.monodromy_rtol = 0.0;
    pf.route = "samples";
    if (o.monodromy.allFinite()) {
      o.floquet = floquet(o.monodromy, autonomous);
      screened = true;
    } else {
      flow = true;  // the samples gave nothing usable: the flow decides
    }
  } else if (ho.floquet == HbFloquet::hill) {
    pf.route = "hill";
    const long l0 = P.linearizations, e0 = P.evaluations;
    screened = hill_floquet_into(o, P, e, Z, w, autonomous, ho.hill_selection,
                                 hill_time_points(H, P.B.M, ho.hill_time_points));
    pf.linearizations += P.linearizations - l0;
    pf.evaluations += P.evaluations - e0;
    if (!screened) {  // the eigenvalue solver failed: the flow decides
      o.status = "ok";
      o.message.clear();
      flow = true;
    }
  }
  if (screened) {
    bool recheck = screen_close(o.floquet, margin, pf.route == "hill", pf);
    // floquet_tol > 0 (samples): a close verdict is first refined by the Magnus product at
    // doubling step counts (hb_floquet.cpp, the periodic orbit's floquet_tol); the flow
    // decides only where the refinement leaves it unresolved (not converged within its
    // budget, or | |μ_c| − 1 | within its own error estimate).
    if (recheck && !flow && ho.floquet == HbFloquet::samples && ho.floquet_tol > 0) {
      RefinedMonodromy rm = refined_monodromy(P, e, Z, w, autonomous, ho.floquet_tol,
                                              refined_max_steps(P.B.M, ho.floquet_max_steps));
      recheck = !take_refined(rm, autonomous, o, pf);
    }
    flow = flow || recheck;
  }
  if (flow) {
    if (!flow_monodromy(F, o, in.t0, T, ho.cvode, srtol)) {
      o.monodromy.resize(0, 0);
      o.floquet = Floquet();
      return false;
    }
    pf.route = "flow";
  }
  if (ho.floquet == HbFloquet::none) {
    pf.route = "none";
  } else if (pf.route != "hill") {
    if (!o.monodromy.allFinite()) {
      o.status = "error";
      o.message = "non-finite monodromy matrix";
      o.monodromy.resize(0, 0);
      o.floquet = Floquet();
      return false;
    }
    o.floquet = floquet(o.monodromy, autonomous);
  }
  return true;
}

int checked_time_points(const HarmonicBalanceOptions& ho) {
  require(ho.harmonics >= 1 && ho.harmonics <= 1000,
          "harmonics: expected an integer in [1, 1000], got " + std::to_string(ho.harmonics));
  const int H = ho.harmonics;
  const int M = ho.time_points == 0 ? std::max(4 * H, 2 * H + 1) : ho.time_points;
  require(M >= 2 * H + 1 && M <= 100000,
          "time_points: expected M >= 2H + 1 = " + std::to_string(2 * H + 1) +
              " (and <= 1e5), got " + std::to_string(M));
  require(ho.tol > 0 && std::isfinite(ho.tol), "tol: expected a value > 0");
  require(ho.max_iter >= 1, "max_iter: expected at least 1");
  require(ho.magnus_substeps >= 1, "magnus_substeps: expected at least 1");
  require(ho.floquet_tol >= 0 && ho.floquet_tol < 1,
          "floquet_tol: expected a value in [0, 1) (0: no refinement)");
  require(ho.floquet_max_steps >= 0 && ho.floquet_max_steps <= 1000000,
          "floquet_max_steps: expected 0 (8 M) or an integer in [1, 1e6], got " +
              std::to_string(ho.floquet_max_steps));
  require(ho.hill_time_points == 0 ||
              (ho.hill_time_points >= 2 * H + 1 && ho.hill_time_points <= 100000),
          "hill_time_points: expected 0 (max(M, 8H)) or an integer in [2H + 1, 1e5], got " +
              std::to_string(ho.hill_time_points));
  return M;
}

}  // namespace rotordyn::hb_detail
