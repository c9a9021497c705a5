#include "rotordyn/reduction.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "rotordyn/errors.hpp"

namespace rotordyn {
namespace {

struct Partition {
  std::vector<int> m, s;  // master and slave indices
};

Partition partition(Eigen::Index n, const std::vector<int>& masters) {
  require(!masters.empty(), "masters: expected at least one master DOF, got none");
  std::vector<char> is_m(static_cast<std::size_t>(n), 0);
  for (std::size_t i = 0; i < masters.size(); ++i) {
    const int d = masters[i];
    require(d >= 0 && d < n, "masters[" + std::to_string(i) + "]: expected a DOF in [0, " +
                                 std::to_string(n - 1) + "], got " + std::to_string(d));
    require(!is_m[d], "masters[" + std::to_string(i) + "]: DOF " + std::to_string(d) +
                          " is listed twice");
    is_m[d] = 1;
  }
  Partition p;
  p.m = masters;
  for (int i = 0; i < n; ++i)
    if (!is_m[i]) p.s.push_back(i);
  return p;
}

Eigen::MatrixXd sub(const Eigen::MatrixXd& X, const std::vector<int>& r,
                    const std::vector<int>& c) {
  Eigen::MatrixXd out(r.size(), c.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t j = 0; j < c.size(); ++j) out(i, j) = X(r[i], c[j]);
  return out;
}

void check_square(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  const Eigen::Index n = K.rows();
  require(K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  require(M.rows() == n && M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
}

// Kss⁻¹ via Cholesky, with a clear error if Kss is singular.
Eigen::LDLT<Eigen::MatrixXd> slave_factor(const Eigen::MatrixXd& Kss) {
  Eigen::LDLT<Eigen::MatrixXd> f(Kss);
  const auto d = f.vectorD().cwiseAbs();
  const double dmax = d.size() ? d.maxCoeff() : 1.0;
  require(f.info() == Eigen::Success && d.size() && d.minCoeff() > 1e-12 * dmax,
          "masters: the slave stiffness is singular; the masters (with the supports) must "
          "restrain every rigid-body motion of the rotor");
  return f;
}

}  // namespace

ReductionKind parse_reduction(const std::string& name, const std::string& field) {
  if (name == "guyan") return ReductionKind::Guyan;
  if (name == "irs") return ReductionKind::IRS;
  if (name == "craig-bampton" || name == "craig_bampton") return ReductionKind::CraigBampton;
  throw InputError(field + ": expected one of 'guyan', 'irs', 'craig-bampton', got '" + name +
                   "'");
}

Eigen::MatrixXd Reduction::reduce(const Eigen::MatrixXd& X) const {
  require(X.rows() == T.rows() && X.cols() == T.rows(),
          shape_msg("X", T.rows(), T.rows(), X.rows(), X.cols()));
  return T.transpose() * X * T;
}
Eigen::MatrixXd Reduction::expand(const Eigen::MatrixXd& qr) const {
  require(qr.rows() == T.cols(), shape_msg("q_r", T.cols(), qr.cols(), qr.rows(), qr.cols()));
  return T * qr;
}

Reduction guyan(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                const std::vector<int>& masters) {
  check_square(M, K);
  const Partition p = partition(K.rows(), masters);
  const Eigen::Index n = K.rows(), nm = static_cast<Eigen::Index>(p.m.size());
  Reduction r;
  r.kind = ReductionKind::Guyan;
  r.masters = masters;
  r.T = Eigen::MatrixXd::Zero(n, nm);
  for (Eigen::Index j = 0; j < nm; ++j) r.T(p.m[j], j) = 1.0;
  if (!p.s.empty()) {
    const auto f = slave_factor(sub(K, p.s, p.s));
    const Eigen::MatrixXd Tsm = -f.solve(sub(K, p.s, p.m));
    for (std::size_t i = 0; i < p.s.size(); ++i) r.T.row(p.s[i]) = Tsm.row(i);
  }
  r.M = r.T.transpose() * M * r.T;
  r.K = r.T.transpose() * K * r.T;
  return r;
}

Reduction irs(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
              const std::vector<int>& masters) {
  Reduction g = guyan(M, K, masters);
  const Partition p = partition(K.rows(), masters);
  if (p.s.empty()) return g;
  // S = [[0, 0], [0, Kss⁻¹]] in full ordering; T_IRS = T_G + S M T_G M_G⁻¹ K_G.
  const auto f = slave_factor(sub(K, p.s, p.s));
  const Eigen::MatrixXd MT = M * g.T;                       // (n, nm)
  const Eigen::MatrixXd X = g.M.ldlt().solve(g.K);          // M_G⁻¹ K_G (nm, nm)
  Eigen::MatrixXd MTs(p.s.size(), MT.cols());
  for (std::size_t i = 0; i < p.s.size(); ++i) MTs.row(i) = MT.row(p.s[i]);
  const Eigen::MatrixXd corr = f.solve(MTs) * X;
  Reduction r = g;
  r.kind = ReductionKind::IRS;
  for (std::size_t i = 0; i < p.s.size(); ++i) r.T.row(p.s[i]) += corr.row(i);
  r.M = r.T.transpose() * M * r.T;
  r.K = r.T.transpose() * K * r.T;
  return r;
}

Reduction craig_bampton(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                        const std::vector<int>& masters, int n_modes) {
  Reduction g = guyan(M, K, masters);
  const Partition p = partition(K.rows(), masters);
  const int ns = static_cast<int>(p.s.size());
  require(n_modes >= 0 && n_modes <= ns, "n_modes: expected 0 <= n_modes <= " +
                                             std::to_string(ns) + " (slave DOFs), got " +
                                             std::to_string(n_modes));
  Reduction r = g;
  r.kind = ReductionKind::CraigBampton;
  if (n_modes > 0) {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(sub(K, p.s, p.s),
                                                                  sub(M, p.s, p.s));
    require(es.info() == Eigen::Success, "craig-bampton: slave eigenproblem failed");
    const Eigen::Index nm = static_cast<Eigen::Index>(p.m.size());
    r.T.conservativeResize(Eigen::NoChange, nm + n_modes);
    r.T.rightCols(n_modes).setZero();
    for (int i = 0; i < ns; ++i)
      r.T.row(p.s[i]).tail(n_modes) = es.eigenvectors().row(i).head(n_modes);
  }
  r.M = r.T.transpose() * M * r.T;
  r.K = r.T.transpose() * K * r.T;
  return r;
}

Reduction reduce_model(ReductionKind kind, const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                       const std::vector<int>& masters, int n_modes) {
  switch (kind) {
    case ReductionKind::Guyan:
      return guyan(M, K, masters);
    case ReductionKind::IRS:
      return irs(M, K, masters);
    case ReductionKind::CraigBampton:
      return craig_bampton(M, K, masters, n_modes);
  }
  throw InputError("reduction: unknown kind");
}

}  // namespace rotordyn
