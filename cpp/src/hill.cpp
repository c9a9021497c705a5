// Floquet exponents by Hill's method (hill.hpp): the Hill matrix of the linearised periodic
// system, its eigenvalues and the choice of one per family λ + i k ω.
#include "rotordyn/hill.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

#include "hb_detail.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/modal.hpp"

namespace rotordyn {

namespace {

using cd = std::complex<double>;

// κ = Σ k |c_k|² / Σ |c_k|² of the positions z (nb·n, harmonic rows of n) of an eigenvector,
// c_{±k} = (a_k ∓ i b_k) / 2 the complex-exponential coefficients of a_k cos kτ + b_k sin kτ.
double centroid(const Eigen::Ref<const Eigen::VectorXcd>& z, int H, Eigen::Index n) {
  double num = 0.0, den = z.head(n).squaredNorm();
  for (int k = 1; k <= H; ++k) {
    const Eigen::VectorXcd a = z.segment((2 * k - 1) * n, n), b = z.segment(2 * k * n, n);
    const double wp = (a - cd(0, 1) * b).squaredNorm() / 4, wm = (a + cd(0, 1) * b).squaredNorm() / 4;
    num += k * (wp - wm);
    den += wp + wm;
  }
  return den > 0 ? num / den : 0.0;
}

// InputError unless X is a non-empty square matrix of finite values (named `name`).
void require_square(const std::string& name, const Eigen::MatrixXd& X) {
  require(X.rows() >= 1 && X.cols() == X.rows(),
          name + ": expected a non-empty square matrix, got shape (" + std::to_string(X.rows()) +
              ", " + std::to_string(X.cols()) + ")");
  require(X.allFinite(), name + ": expected finite values");
}

// InputError unless X has shape (n, n) and finite values.
void require_block(const std::string& name, const Eigen::MatrixXd& X, Eigen::Index n) {
  require(X.rows() == n && X.cols() == n, shape_msg(name, n, n, X.rows(), X.cols()));
  require(X.allFinite(), name + ": expected finite values");
}

}  // namespace

HillResult hill_from_matrices(const Eigen::MatrixXd& J, const Eigen::MatrixXd& delta1,
                              const Eigen::MatrixXd& mass, double omega, int harmonics,
                              HillSelection selection) {
  require(harmonics >= 1 && harmonics <= 200,
          "harmonics: expected an integer in [1, 200], got " + std::to_string(harmonics));
  require(std::isfinite(omega) && omega > 0, "omega: expected a finite value > 0 rad/s");
  const Eigen::Index n = mass.rows(), H = harmonics, nb = 2 * H + 1, nn = nb * n, N2 = 2 * nn;
  require_square("mass", mass);
  require(N2 <= 6000, "harmonics: the Hill matrix would have " + std::to_string(N2) +
                          " rows (2n(2H + 1)); at most 6000: lower harmonics");
  require_block("J", J, nn);
  require_block("delta1", delta1, nn);
  Eigen::PartialPivLU<Eigen::MatrixXd> mlu(mass);
  require(mlu.rcond() > 1e-14, "mass: expected an invertible matrix");

  // Companion form in (z, λ z / ω): eigenvalue λ / ω (the blocks of order one for ω-scaled
  // problems; LAPACK balances the rest).
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(N2, N2);
  A.topRightCorner(nn, nn).setIdentity();
  for (Eigen::Index p = 0; p < nb; ++p) {
    A.block(nn + p * n, 0, n, nn) = -mlu.solve(J.middleRows(p * n, n)) / (omega * omega);
    A.block(nn + p * n, nn, n, nn) = -mlu.solve(delta1.middleRows(p * n, n)) / omega;
  }
  Eigen::VectorXcd ev;
  Eigen::MatrixXcd V;
  eig_general(A, ev, &V);
  HillResult out;
  out.harmonics = harmonics;
  out.eigenvalues = ev * omega;
  out.all_centroids.resize(N2);
  for (Eigen::Index i = 0; i < N2; ++i) out.all_centroids(i) = centroid(V.col(i).head(nn), harmonics, n);

  std::vector<Eigen::Index> order(static_cast<std::size_t>(N2));
  std::iota(order.begin(), order.end(), 0);
  const Eigen::VectorXcd& lam = out.eigenvalues;
  // The key: |κ| (centroid) or |Im λ| / ω (imaginary). The central set (key ≤ 0.75: each
  // family has a copy there) is taken first, largest real part first — a stiff, overdamped
  // family (|λ| ≫ H ω, its eigenfunction far from smooth) is not resolved and smears into many
  // real eigenvalues with κ = 0, which must not crowd out the families that decide stability;
  // then the rest by the key.
  auto key = [&](Eigen::Index i) {
    return selection == HillSelection::centroid ? std::abs(out.all_centroids(i))
                                                : std::abs(lam(i).imag()) / omega;
  };
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    const double ka = key(a), kb = key(b);
    const bool ca = ka <= 0.75, cb = kb <= 0.75;
    if (ca != cb) return ca;
    if (ca && lam(a).real() != lam(b).real()) return lam(a).real() > lam(b).real();
    if (ka != kb) return ka < kb;
    return std::abs(lam(a).imag()) < std::abs(lam(b).imag());
  });
  const double tol = 0.01 * omega;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i : order) {
    if (static_cast<Eigen::Index>(kept.size()) == 2 * n) break;
    bool copy = false;
    for (std::size_t a = 0; a < kept.size() && !copy; ++a) {
      const cd d = lam(i) - lam(kept[a]);
      const double m = std::round(d.imag() / omega);
      // a copy λ_a + i m ω has λ_a's eigenvector shifted by m harmonics: κ_a − m
      if (m != 0.0 && std::abs(d - cd(0, m * omega)) <= tol &&
          std::abs(out.all_centroids(i) - out.all_centroids(kept[a]) + m) <= 0.25)
        copy = true;
    }
    if (!copy) kept.push_back(i);
  }
  const Eigen::Index nk = static_cast<Eigen::Index>(kept.size());
  const double T = 2 * M_PI / omega;
  out.exponents.resize(nk);
  out.multipliers.resize(nk);
  out.centroids.resize(nk);
  for (Eigen::Index a = 0; a < nk; ++a) {
    const Eigen::Index i = kept[static_cast<std::size_t>(a)];
    out.exponents(a) = lam(i);
    out.multipliers(a) = std::exp(lam(i) * T);
    out.centroids(a) = out.all_centroids(i);
  }
  // A self-conjugate family — its conjugate conj(λ) = λ − 2i Im λ is its own copy m = −2 Im λ / ω
  // (odd: a real negative multiplier) with the conjugate eigenvector (κ → −κ = κ − m) — is
  // real unless another kept multiplier is its conjugate (a genuine pair near −1).
  for (Eigen::Index a = 0; a < nk; ++a) {
    const cd l = out.exponents(a);
    const double m = std::round(-2 * l.imag() / omega);
    if (m == 0.0 || std::abs(2 * l.imag() + m * omega) > tol ||
        std::abs(2 * out.centroids(a) - m) > 0.25)
      continue;
    const cd mu = out.multipliers(a);
    bool paired = false;
    for (Eigen::Index b = 0; b < nk && !paired; ++b)
      paired = b != a && std::abs(out.multipliers(b) - std::conj(mu)) <= 1e-9 * std::abs(mu);
    if (!paired) out.multipliers(a) = cd(mu.real() < 0 ? -std::abs(mu) : std::abs(mu), 0.0);
  }
  // The monodromy from the kept Floquet solutions: x(τ = 0) = p(0), x'(0) = λ p(0) + ω p'(0).
  if (nk == 2 * n) {
    Eigen::MatrixXcd X0(2 * n, nk);
    for (Eigen::Index a = 0; a < nk; ++a) {
      const Eigen::Index i = kept[static_cast<std::size_t>(a)];
      const Eigen::VectorXcd z = V.col(i).head(nn);
      Eigen::VectorXcd p0 = z.head(n), dp0 = Eigen::VectorXcd::Zero(n);
      for (Eigen::Index k = 1; k <= H; ++k) {
        p0 += z.segment((2 * k - 1) * n, n);
        dp0 += static_cast<double>(k) * z.segment(2 * k * n, n);
      }
      X0.col(a) << p0, out.exponents(a) * p0 + omega * dp0;
      const double nrm = X0.col(a).norm();  // unit columns: the rcond test below is scale-free
      if (nrm > 0) X0.col(a) /= nrm;
    }
    // Φ = X0 diag(μ) X0⁻¹ as the solution of X0ᵀ Φᵀ = (X0 diag(μ))ᵀ (full pivoting: X0 is
    // near singular where two families' Floquet solutions nearly coincide, e.g. a pair about
    // to collide on the real axis); left empty when X0 is numerically singular (rcond below
    // 1e-13) or Φ comes out non-finite: the multipliers do not depend on it.
    const Eigen::FullPivLU<Eigen::MatrixXcd> xlu(X0.transpose());
    if (xlu.rcond() > 1e-13) {
      const Eigen::MatrixXcd XL = X0 * out.multipliers.asDiagonal();
      out.monodromy = xlu.solve(XL.transpose()).transpose().real();
      if (!out.monodromy.allFinite()) out.monodromy.resize(0, 0);
    }
  }
  return out;
}

HillResult hill_floquet(const Eigen::MatrixXd& mass, const std::vector<Eigen::MatrixXd>& stiffness,
                        const std::vector<Eigen::MatrixXd>& damping, double omega, int harmonics,
                        HillSelection selection) {
  require(harmonics >= 1 && harmonics <= 200,
          "harmonics: expected an integer in [1, 200], got " + std::to_string(harmonics));
  const Eigen::Index n = mass.rows();
  const int Ms = static_cast<int>(stiffness.size());
  require(Ms >= 2 * harmonics + 1 && damping.size() == stiffness.size(),
          "stiffness, damping: expected the same number of samples, at least 2H + 1 = " +
              std::to_string(2 * harmonics + 1) + ", got " + std::to_string(stiffness.size()) +
              " and " + std::to_string(damping.size()));
  require_square("mass", mass);
  for (int j = 0; j < Ms; ++j) {
    require_block("stiffness[" + std::to_string(j) + "]", stiffness[static_cast<std::size_t>(j)], n);
    require_block("damping[" + std::to_string(j) + "]", damping[static_cast<std::size_t>(j)], n);
  }
  require(std::isfinite(omega) && omega > 0, "omega: expected a finite value > 0 rad/s");
  require(2 * n * (2 * harmonics + 1) <= 6000,
          "harmonics: the Hill matrix would have " + std::to_string(2 * n * (2 * harmonics + 1)) +
              " rows (2n(2H + 1)); at most 6000: lower harmonics");
  const hb_detail::Basis B = hb_detail::make_basis(harmonics, Ms);
  const Eigen::Index nn = B.nb * n;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nn, nn), D1 = Eigen::MatrixXd::Zero(nn, nn);
  for (int j = 0; j < Ms; ++j) {
    hb_detail::add_sample_block(J, B, j, stiffness[static_cast<std::size_t>(j)], omega,
                                damping[static_cast<std::size_t>(j)], omega * omega, mass);
    hb_detail::add_sample_block(D1, B, j, damping[static_cast<std::size_t>(j)], 2 * omega, mass,
                                0.0, mass);
  }
  return hill_from_matrices(J, D1, mass, omega, harmonics, selection);
}

namespace hb_detail {

void add_sample_block(Eigen::MatrixXd& out, const Basis& B, int j, const Eigen::MatrixXd& X0,
                      double s1, const Eigen::MatrixXd& X1, double s2, const Eigen::MatrixXd& X2) {
  const Eigen::Index n = X0.rows();
  for (int q = 0; q < B.nb; ++q) {
    const double e0 = B.E(j, q), e1 = B.E1(j, q), e2 = B.E2(j, q);
    if (e0 == 0.0 && e1 == 0.0 && e2 == 0.0) continue;
    const Eigen::MatrixXd T = e0 * X0 + (s1 * e1) * X1 + (s2 * e2) * X2;
    for (int p = 0; p < B.nb; ++p) {
      const double pw = B.P(p, j);
      if (pw != 0.0) out.block(p * n, q * n, n, n) += pw * T;
    }
  }
}

HillResult hill_at(const Basis& B, const Eval& e, const Eigen::MatrixXd& Cd,
                   const Eigen::MatrixXd& Mm, double w, HillSelection selection) {
  const Eigen::Index n = Mm.rows(), nn = B.nb * n;
  Eigen::MatrixXd D1 = Eigen::MatrixXd::Zero(nn, nn);
  for (int j = 0; j < B.M; ++j)
    add_sample_block(D1, B, j, Cd + e.DH[static_cast<std::size_t>(j)], 2 * w, Mm, 0.0, Mm);
  return hill_from_matrices(e.J, D1, Mm, w, B.H, selection);
}

bool hill_floquet_into(PeriodicOrbitResult& o, Problem& P, const Eval& e, const Eigen::MatrixXd& Z,
                       double w, bool autonomous, HillSelection selection, int time_points) {
  const shooting_detail::Flow& F = *P.F;
  const SystemModel& m = P.solver->model();
  // The Jacobian at time_points samples: the Newton's own, or one more evaluation at the
  // converged orbit on the denser grid (its film linearisations counted in P).
  Eval dense;
  Problem Pd = P;
  const Eval* use = &e;
  if (time_points > P.B.M) {
    Pd.B = make_basis(P.B.H, time_points);
    Pd.linearizations = Pd.evaluations = 0;
    dense = Pd.eval(Z, w, true);
    P.linearizations += Pd.linearizations;
    P.evaluations += Pd.evaluations;
    if (!dense.ok) {
      o.status = dense.contact ? "rub" : "error";
      o.message = "Hill's method: the Jacobian at " + std::to_string(time_points) +
                  " samples: " + dense.why;
      return false;
    }
    use = &dense;
  }
  HillResult h;
  try {
    h = hill_at(use == &e ? P.B : Pd.B, *use, F.Cd, m.mass_at(F.in->omega), w, selection);
  } catch (const ConvergenceError& ex) {
    o.status = "error";
    o.message = std::string("Hill's method: ") + ex.what();
    return false;
  }
  if (h.multipliers.size() != F.N || !h.multipliers.allFinite()) {
    o.status = "error";
    o.message = "Hill's method: " + std::to_string(h.multipliers.size()) + " finite exponents of " +
                std::to_string(F.N) + " (a non-finite Hill matrix or eigenvector)";
    o.monodromy.resize(0, 0);
    return false;
  }
  o.monodromy = h.monodromy;
  o.monodromy_rtol = 0.0;
  o.floquet = floquet_from_multipliers(h.multipliers, autonomous);
  return true;
}

int hill_time_points(int H, int M, int requested) {
  return requested > 0 ? requested : std::max(M, 8 * H);
}

}  // namespace hb_detail

}  // namespace rotordyn
