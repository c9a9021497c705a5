// Harmonic response (K − ω² M + iω D) X = F. A 100-element rotor has ~400 DOFs but only ~12
// non-zeros per row: the sparse LU costs O(n · bandwidth²) against the dense LU's O(n³).
#include "rotordyn/harmonic.hpp"

#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <Eigen/UmfPackSupport>
#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {
using cplx = std::complex<double>;
// Below this size, or above this fill, the dense LU is as fast and simpler.
constexpr Eigen::Index kSparseMinRows = 40;
constexpr double kSparseMaxFill = 0.25;
}  // namespace

Eigen::MatrixXcd harmonic_response(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                   const Eigen::MatrixXd& K, double omega,
                                   const Eigen::MatrixXcd& F) {
  const Eigen::Index n = M.rows();
  require(n > 0 && M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
  require(D.rows() == n && D.cols() == n, shape_msg("D", n, n, D.rows(), D.cols()));
  require(K.rows() == n && K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  require(F.rows() == n, shape_msg("F", n, F.cols(), F.rows(), F.cols()));
  require(std::isfinite(omega), "omega: expected a finite angular frequency");
  const double w2 = omega * omega;

  // Pattern: the union of the non-zeros of M, D and K, column by column.
  std::vector<Eigen::Triplet<cplx>> trip;
  trip.reserve(static_cast<std::size_t>(16 * n));
  Eigen::Index nnz = 0;
  bool sparse = n >= kSparseMinRows;
  for (Eigen::Index j = 0; j < n && sparse; ++j) {
    for (Eigen::Index i = 0; i < n; ++i) {
      const double k = K(i, j), m = M(i, j), d = D(i, j);
      if (k == 0.0 && m == 0.0 && d == 0.0) continue;
      trip.emplace_back(i, j, cplx(k - w2 * m, omega * d));
      ++nnz;
    }
    if (static_cast<double>(nnz) > kSparseMaxFill * static_cast<double>(n) * static_cast<double>(n))
      sparse = false;
  }
  Eigen::MatrixXcd X;
  if (sparse) {
    Eigen::SparseMatrix<cplx> Z(n, n);
    Z.setFromTriplets(trip.begin(), trip.end());
    Z.makeCompressed();
    Eigen::UmfPackLU<Eigen::SparseMatrix<cplx>> lu;
    lu.compute(Z);
    if (lu.info() != Eigen::Success)
      throw ConvergenceError("harmonic response: the dynamic stiffness K - w^2 M + i w D is "
                             "singular at omega = " + std::to_string(omega) + " rad/s");
    X = lu.solve(F);
  } else {
    Eigen::MatrixXcd Z = K.cast<cplx>();
    Z.real() -= w2 * M;
    Z.imag() = omega * D;
    Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Z);
    X = lu.solve(F);
  }
  if (!X.allFinite())
    throw ConvergenceError("harmonic response: non-finite solution at omega = " +
                           std::to_string(omega) + " rad/s (singular dynamic stiffness)");
  return X;
}

Eigen::MatrixXcd harmonic_sweep(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                const Eigen::MatrixXd& G, const Eigen::MatrixXd& K,
                                const Eigen::VectorXd& omegas, const Eigen::VectorXcd& F,
                                const Eigen::MatrixXd& O) {
  const Eigen::Index n = M.rows();
  require(n > 0 && M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
  require(C.rows() == n && C.cols() == n, shape_msg("C", n, n, C.rows(), C.cols()));
  require(G.rows() == n && G.cols() == n, shape_msg("G", n, n, G.rows(), G.cols()));
  require(K.rows() == n && K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  require(F.size() == n, shape_msg("F", n, 1, F.size(), 1));
  require(O.cols() == n, shape_msg("O", O.rows(), n, O.rows(), O.cols()));
  for (Eigen::Index k = 0; k < omegas.size(); ++k)
    require(std::isfinite(omegas(k)), "omegas: expected finite angular frequencies");
  Eigen::MatrixXcd Y(omegas.size(), O.rows());
  // The pattern: where any of M, C, G, K is non-zero (what harmonic_response keeps at every
  // frequency but an exact cancellation), as compressed columns.
  std::vector<Eigen::Triplet<cplx>> trip;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> where;
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (K(i, j) != 0.0 || M(i, j) != 0.0 || C(i, j) != 0.0 || G(i, j) != 0.0)
        where.emplace_back(i, j);
  const bool sparse = n >= kSparseMinRows &&
                      static_cast<double>(where.size()) <=
                          kSparseMaxFill * static_cast<double>(n) * static_cast<double>(n);
  const Eigen::MatrixXcd Oc = O.cast<cplx>();
  auto check = [](const Eigen::VectorXcd& x, double omega) {
    if (!x.allFinite())
      throw ConvergenceError("harmonic response: non-finite solution at omega = " +
                             std::to_string(omega) + " rad/s (singular dynamic stiffness)");
  };
  if (sparse) {
    Eigen::SparseMatrix<cplx> Z(n, n);
    trip.reserve(where.size());
    for (const auto& [i, j] : where) trip.emplace_back(i, j, cplx(1.0, 0.0));
    Z.setFromTriplets(trip.begin(), trip.end());
    Z.makeCompressed();
    Eigen::UmfPackLU<Eigen::SparseMatrix<cplx>> lu;
    lu.analyzePattern(Z);
    for (Eigen::Index k = 0; k < omegas.size(); ++k) {
      const double omega = omegas(k), w2 = omega * omega;
      cplx* v = Z.valuePtr();
      std::size_t e = 0;
      for (const auto& [i, j] : where) {
        const double d = C(i, j) + omega * G(i, j);
        v[e++] = cplx(K(i, j) - w2 * M(i, j), omega * d);
      }
      lu.factorize(Z);
      if (lu.info() != Eigen::Success)
        throw ConvergenceError("harmonic response: the dynamic stiffness K - w^2 M + i w D is "
                               "singular at omega = " + std::to_string(omega) + " rad/s");
      const Eigen::VectorXcd x = lu.solve(Eigen::VectorXcd(F * w2));
      check(x, omega);
      Y.row(k) = (Oc * x).transpose();
    }
  } else {
    for (Eigen::Index k = 0; k < omegas.size(); ++k) {
      const double omega = omegas(k), w2 = omega * omega;
      Eigen::MatrixXcd Z = K.cast<cplx>();
      Z.real() -= w2 * M;
      Z.imag() = omega * (C + omega * G);
      Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Z);
      const Eigen::VectorXcd x = lu.solve(Eigen::VectorXcd(F * w2));
      check(x, omega);
      Y.row(k) = (Oc * x).transpose();
    }
  }
  return Y;
}

}  // namespace rotordyn
