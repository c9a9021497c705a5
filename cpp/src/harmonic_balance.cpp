// Periodic orbits by harmonic balance with alternating frequency–time (harmonic_balance.hpp).
// Nothing global: the films' cavitation-set continuation is switched on for the call (the
// samples of one evaluation are consecutive nearby states, as a transient's right-hand sides)
// and off at its end, so the result is a function of the call's inputs.
#include "rotordyn/harmonic_balance.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rotordyn/errors.hpp"
#include "shooting_detail.hpp"

namespace rotordyn {

namespace {

using shooting_detail::Flow;

struct Basis {
  int H = 0, M = 0, nb = 0;   // nb = 2H + 1
  Eigen::MatrixXd E, E1, E2;  // (M, nb): basis, d/dτ, d²/dτ² at τ_j
  Eigen::MatrixXd P;          // (nb, M): the projection (DFT) R̂ = P R
};

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

// One residual evaluation at (Z, ω): R̂ (nb·n), the Jacobian in z (nb·n × nb·n) and its ω
// column, and the linearisations at the samples (for the Floquet multipliers).
struct Eval {
  Eigen::VectorXd R, dRdw;
  Eigen::MatrixXd J;
  std::vector<Eigen::MatrixXd> KH, DH;
  bool ok = false;
  std::string why;
  bool contact = false;
};

struct Problem {
  SystemSolver* solver = nullptr;
  const PeriodicInput* in = nullptr;
  Flow* F = nullptr;  // M(Ω) factor, F0, C + ΩG
  Basis B;
  Eigen::Index n = 0;
  bool autonomous = true;
  long linearizations = 0, evaluations = 0;

  // Z: (nb, n) coefficients; ω the fundamental (rad/s).
  Eval eval(const Eigen::MatrixXd& Z, double w, bool jac) {
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
      for (int q = 0; q < nb; ++q) {
        const double e0 = B.E(j, q), e1 = B.E1(j, q), e2 = B.E2(j, q);
        if (e0 == 0.0 && e1 == 0.0 && e2 == 0.0) continue;
        const Eigen::MatrixXd T = e0 * G + (w * e1) * Dv + (w * w * e2) * Mm;
        for (int p = 0; p < nb; ++p) {
          const double pw = B.P(p, j);
          if (pw != 0.0) e.J.block(p * n, q * n, n, n) += pw * T;
        }
      }
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
};

// Coefficients (nb, n) of position samples X (M0, n) at τ_j = 2πj/M0, truncated to H.
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

// Shift the time origin by φ (τ → τ + φ): a_k' + i b_k' from a_k, b_k.
void shift_phase(Eigen::MatrixXd& Z, int H, double phi) {
  for (int k = 1; k <= H; ++k) {
    const double c = std::cos(k * phi), s = std::sin(k * phi);
    const Eigen::RowVectorXd a = Z.row(2 * k - 1), b = Z.row(2 * k);
    Z.row(2 * k - 1) = a * c + b * s;
    Z.row(2 * k) = b * c - a * s;
  }
}

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
    Phi = Om.exp() * Phi;
  }
  return Phi;
}

}  // namespace

HarmonicBalanceResult harmonic_balance(SystemSolver& solver, const PeriodicInput& in,
                                       const Eigen::MatrixXd& start_samples,
                                       const HarmonicBalanceOptions& opt) {
  require(opt.harmonics >= 1 && opt.harmonics <= 1000,
          "harmonics: expected an integer in [1, 1000], got " + std::to_string(opt.harmonics));
  const int H = opt.harmonics;
  const int M = opt.time_points == 0 ? std::max(4 * H, 2 * H + 1) : opt.time_points;
  require(M >= 2 * H + 1 && M <= 100000,
          "time_points: expected M >= 2H + 1 = " + std::to_string(2 * H + 1) + " (and <= 1e5), got " +
              std::to_string(M));
  require(opt.tol > 0 && std::isfinite(opt.tol), "tol: expected a value > 0");
  require(opt.max_iter >= 1, "max_iter: expected at least 1");
  require(opt.magnus_substeps >= 1, "magnus_substeps: expected at least 1");
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
  double L = opt.length_scale;
  if (!(L > 0)) {
    L = std::numeric_limits<double>::infinity();
    for (const FilmCoupling& fc : m.films) L = std::min(L, fc.geometry.clearance_m);
    if (!std::isfinite(L)) L = 1e-3;
  }
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
  P.autonomous = autonomous;
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
  auto scaled = [&](const Eigen::VectorXd& R) -> Eigen::VectorXd {
    Eigen::VectorXd s(R.size());
    for (int p = 0; p < nb; ++p) s.segment(p * n, n) = R.segment(p * n, n).cwiseQuotient(rowscale);
    return s / L;
  };
  Eval e = P.eval(Z, w, true);
  if (e.ok) {
    const Eigen::MatrixXd& Mm = m.mass_at(in.omega);
    rowscale.resize(n);
    const double ws = std::max(std::abs(in.omega), w);
    // The ω-independent part of the Jacobian's c0 block is mean(K + K_H).
    const Eigen::MatrixXd G0 = e.J.block(0, 0, n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      rowscale(i) = std::abs(G0(i, i)) + ws * ws * std::abs(Mm(i, i)) + ws * std::abs(F.Cd(i, i)) + 1e-300;
  }
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
    const double cap = std::max({1.0, d.head(nn).cwiseAbs().maxCoeff() / 0.25,
                                 autonomous ? std::abs(d(nn)) / 0.1 : 0.0});
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
  out.harmonic_amplitudes.resize(H + 1);
  out.harmonic_amplitudes(0) = Z.row(0).cwiseAbs().maxCoeff() / L;
  for (int k = 1; k <= H; ++k)
    out.harmonic_amplitudes(k) =
        (Z.row(2 * k - 1).array().square() + Z.row(2 * k).array().square()).sqrt().maxCoeff() / L;
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
  const int ns = std::max(in.n_out, 2);
  o.t.resize(ns);
  o.r.resize(ns, n);
  o.v.resize(ns, n);
  for (int i = 0; i < ns; ++i) {
    const double tau = 2 * M_PI * i / (ns - 1);
    o.t(i) = in.t0 + T * i / (ns - 1);
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
  if (!o.r.allFinite() || !o.v.allFinite()) {
    o.status = "error";
    o.message = "non-finite harmonic-balance orbit";
    finish();
    return out;
  }
  if (opt.floquet == HbFloquet::samples) {
    std::vector<Eigen::MatrixXd> A(static_cast<std::size_t>(M));
    for (int j = 0; j < M; ++j) {
      Eigen::MatrixXd Aj = Eigen::MatrixXd::Zero(N, N);
      Aj.block(0, n, n, n).setIdentity();
      Aj.block(n, 0, n, n) = -F.Mllt.solve(m.K + e.KH[static_cast<std::size_t>(j)]);
      Aj.block(n, n, n, n) = -F.Mllt.solve(F.Cd + e.DH[static_cast<std::size_t>(j)]);
      A[static_cast<std::size_t>(j)] = Aj;
    }
    o.monodromy = monodromy_from_samples(A, T, opt.magnus_substeps);
    o.monodromy_rtol = 0.0;
  } else if (opt.floquet == HbFloquet::flow) {
    Eigen::VectorXd x0(N);
    x0 << o.r0, o.v0;
    const double srtol = opt.sensitivity_rtol > 0 ? opt.sensitivity_rtol : opt.cvode.rtol;
    shooting_detail::FlowRun run =
        shooting_detail::run_flow(F, x0, in.t0, T, true, 2, opt.cvode, true, srtol);
    o.steps += run.steps;
    o.rhs_evals += run.rhs_evals;
    o.jac_evals += run.jac_evals;
    o.sensitivity_flows = 1;
    o.sens_rhs_evals = F.sens_evals;
    if (run.flag < 0) {
      o.status = F.contact ? "rub" : "error";
      o.message = "harmonic balance: the monodromy flow failed: " + run.why;
      finish();
      return out;
    }
    o.monodromy = run.Phi;
    o.monodromy_rtol = srtol;
  }
  if (opt.floquet != HbFloquet::none) {
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
