// Rigid-body roots of a pencil λ²M + λD + K whose stiffness is singular (a rotor without
// supports, `modes --without-bearings`): one rule for the dense and the sparse modal paths.
//
// With d rigid-body motions (K Φ = 0), the pencil has zero roots that are defective at rest
// (λ² M φ = 0: Jordan pairs), and the dense eigensolver spreads them to |λ| ~ √ε ω_max; left
// in, two of them showed as a 0.00015 Hz "mode" of damping ratio −0.75 on an overhung pump.
// How many zero roots there are follows from the rigid-body subspace alone: on it the pencil is
// λ (λ M_r + D_r), M_r = ΦᵀMΦ, D_r = ΦᵀDΦ, so it has d roots at zero from the factor λ and
// d − rank D_r more from λ M_r + D_r; its other roots, the eigenvalues of −M_r⁻¹ D_r, are
// regular (a spinning free rotor's nutation Ω I_p/I_t, a damper's decay) and are kept however
// small, down to the solver's resolution. At rest without damping all 2d roots are zero; once
// the gyroscopic coupling splits a conical pair, two fewer.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "modal_detail.hpp"

namespace rotordyn::detail {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
// Pivot of the Jacobi-scaled stiffness, relative to the largest, below which a column is a
// rigid-body motion (see rigid_body; the same number in modal_sparse.cpp's check).
constexpr double kRigidPivot = 1e-13;
// A regular root of the rigid-body subspace must exceed kResolution √ε ω_max, and a computed
// root lie within kMatch (relative) of it, to be kept (see rigid_roots).
constexpr double kResolution = 2.0;
constexpr double kMatch = 0.1;

// ‖S‖₂ of a symmetric positive semi-definite S by power iteration (to a few per cent: a scale).
double norm2_estimate(const Eigen::MatrixXd& S) {
  const Eigen::Index n = S.rows();
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x(i) = 1.0 + 0.1 * std::sin(1.0 + 2.3 * i);  // generic
  double est = 0.0;
  for (int it = 0; it < 60; ++it) {
    const double nx = x.norm();
    if (!(nx > 0)) break;
    x /= nx;
    Eigen::VectorXd y = S * x;
    const double e = y.norm();
    x.swap(y);
    if (std::abs(e - est) <= 1e-3 * e) {
      est = e;
      break;
    }
    est = e;
  }
  return est;
}
}  // namespace

double frequency_reference(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  double r = 0.0;
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    if (M(i, i) > 0) r = std::max(r, std::abs(K(i, i)) / M(i, i));
  return std::sqrt(r);
}

double rigid_root_bound(double omega_high) { return 10.0 * std::sqrt(kEps) * omega_high; }

RigidBody rigid_body(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  RigidBody rb;
  rb.phi.resize(n, 0);
  if (n == 0) return rb;
  // K's null space from the rank of its Jacobi-scaled form J⁻¹ K J⁻¹ (J = diag √|K_ii|): the
  // same matrix whatever the units of each coordinate (mm or m, rad or mrad) and however long
  // the rotor, and independent of M (a mass-scaled test called the physical modes of a disk on
  // a nearly massless cantilever rigid: ω²/ω_max² = 3e-17 there, ω_max set by the shaft's
  // 1e-8 mass). Pivoted QR of its transpose, so that the trailing columns of Q span the right
  // null space. A pivot below kRigidPivot (1e-13) of the largest is a rigid-body motion:
  // rounding leaves them at ≤ 4.5e-16 (the overhung pump, free 1 m and 1.5 m shafts of 20 and
  // 100 elements); supports of 200 N/m under the pump give 8.7e-9, of 0.02 N/m (roots at
  // 0.014 rad/s) 8.7e-13 — in m or mm alike (the pivots of K itself, the old test: 8.5e-10 for
  // 200 N/m in m and N/m, 2.2e-12 with the translations in mm, against 1e-11).
  Eigen::VectorXd jinv(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double k = std::abs(K(i, i));
    jinv(i) = k > 0 ? 1.0 / std::sqrt(k) : 1.0;
  }
  const Eigen::MatrixXd Kj = jinv.asDiagonal() * K * jinv.asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Kj.transpose());
  qr.setThreshold(kRigidPivot);
  const Eigen::Index d = n - qr.rank();
  if (d == 0) return rb;
  const Eigen::MatrixXd Q = qr.householderQ();
  rb.phi = jinv.asDiagonal() * Q.rightCols(d);
  // The model's highest undamped frequency, the scale of the dense solver's rounding: from the
  // mass-scaled stiffness L⁻¹ K L⁻ᵀ (L Lᵀ = M; without a Cholesky factor, diag √M_ii).
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  Eigen::LLT<Eigen::MatrixXd> llt(M);
  if (llt.info() == Eigen::Success) {
    L = llt.matrixL();
  } else {
    for (Eigen::Index i = 0; i < n; ++i) L(i, i) = M(i, i) > 0 ? std::sqrt(M(i, i)) : 1.0;
  }
  const auto Lt = L.triangularView<Eigen::Lower>();
  Eigen::MatrixXd Ks = Lt.solve(K);                  // L⁻¹ K
  Ks = Lt.solve(Ks.transpose()).transpose().eval();  // L⁻¹ K L⁻ᵀ
  rb.omega_max = std::sqrt(norm2_estimate(0.5 * (Ks + Ks.transpose())));
  return rb;
}

std::vector<char> rigid_roots(const RigidBody& rb, const Eigen::MatrixXd& M,
                              const Eigen::MatrixXd& D, Eigen::VectorXcd& w) {
  std::vector<char> rigid(static_cast<std::size_t>(w.size()), 0);
  const Eigen::Index d = rb.phi.cols();
  if (d == 0 || w.size() == 0) return rigid;
  const double bound = rigid_root_bound(std::max(rb.omega_max, w.cwiseAbs().maxCoeff()));
  // The regular roots of the rigid-body subspace, μ = eigenvalues of −M_r⁻¹ D_r (1/s, unit-
  // consistent): a nutation Ω I_p/I_t, a damper's decay. Only those above the resolution
  // kResolution √ε ω_max are roots the dense solver tells apart from the spread zeros (the
  // spread measured up to 0.6 √ε ω_max); a slower one counts as zero.
  const Eigen::MatrixXd Mr = rb.phi.transpose() * M * rb.phi;
  const Eigen::MatrixXd Dr = rb.phi.transpose() * D * rb.phi;
  const double resolution = kResolution * std::sqrt(kEps) * rb.omega_max;
  std::vector<std::complex<double>> mu;
  Eigen::LLT<Eigen::MatrixXd> llt(Mr);
  if (llt.info() == Eigen::Success) {
    const Eigen::MatrixXd A = -llt.solve(Dr);
    Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
    if (es.info() == Eigen::Success)
      for (Eigen::Index i = 0; i < d; ++i)
        if (std::abs(es.eigenvalues()(i)) > resolution) mu.push_back(es.eigenvalues()(i));
  }
  // 2d − |μ| roots are zero. Every root below the bound is one of them unless it is the
  // nearest root to a regular μ and within kMatch of it (each μ claims one root): so neither a
  // slow nutation is dropped nor a spread zero kept, whatever their order in |λ|.
  std::vector<char> claimed(static_cast<std::size_t>(w.size()), 0);
  std::vector<std::complex<double>> value(static_cast<std::size_t>(w.size()));
  for (const auto& m : mu) {
    Eigen::Index best = -1;
    double dist = 0.0;
    for (Eigen::Index i = 0; i < w.size(); ++i) {
      const double e = std::abs(w(i) - m);
      if (!claimed[static_cast<std::size_t>(i)] && (best < 0 || e < dist)) {
        best = i;
        dist = e;
      }
    }
    if (best >= 0 && dist <= kMatch * std::abs(m)) {
      claimed[static_cast<std::size_t>(best)] = 1;
      value[static_cast<std::size_t>(best)] = m;
    }
  }
  // Below the bound a computed root carries the solver's rounding relative to ω_max (the dense
  // one: 1e-3 in frequency and ±1e-3 of damping ratio for a nutation at 5-15 √ε ω_max), while
  // μ, the rigid-body subspace's Galerkin root, is off by O(|μ|²/ω₁²) only (a free rotor's
  // flexibility moves its nutation by 3.4e-7 per Hz² of speed, 1e-8 at the bound): μ replaces
  // it, on both paths.
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    if (!(std::abs(w(i)) < bound)) continue;
    if (claimed[static_cast<std::size_t>(i)])
      w(i) = value[static_cast<std::size_t>(i)];
    else
      rigid[static_cast<std::size_t>(i)] = 1;
  }
  return rigid;
}

bool conservative_gyroscopic(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                             const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < j; ++i)
      if (M(i, j) != M(j, i) || K(i, j) != K(j, i) || D(i, j) != -D(j, i)) return false;
  for (Eigen::Index i = 0; i < n; ++i)
    if (D(i, i) != 0.0) return false;
  return true;
}

std::complex<double> conservative_root(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                       const Eigen::MatrixXd& K, const Eigen::VectorXcd& x,
                                       std::complex<double> lam) {
  const Eigen::VectorXd xr = x.real(), xi = x.imag();
  const double m = xr.dot(M * xr) + xi.dot(M * xi);
  const double k = xr.dot(K * xr) + xi.dot(K * xi);
  const double g = xr.dot(D * xi) - xi.dot(D * xr);  // x^H D x = i g (D skew)
  if (!(m > 0) || !std::isfinite(k) || !std::isfinite(g)) return lam;
  // λ = i ν: m ν² + g ν − k = 0
  const double disc = g * g + 4.0 * m * k;
  std::complex<double> c1, c2;
  if (disc >= 0) {
    const double q = -0.5 * (g + std::copysign(std::sqrt(disc), g));
    const double nu1 = q / m, nu2 = q != 0.0 ? -k / q : 0.0;
    c1 = {0.0, nu1};
    c2 = {0.0, nu2};
  } else {  // K < 0 along x: a real pair about −g / 2m
    const double re = std::sqrt(-disc) / (2.0 * m), im = -g / (2.0 * m);
    c1 = {re, im};
    c2 = {-re, im};
  }
  const std::complex<double> c = std::abs(c1 - lam) <= std::abs(c2 - lam) ? c1 : c2;
  return std::abs(c - lam) <= 1e-3 * std::abs(lam) ? c : lam;
}

}  // namespace rotordyn::detail
