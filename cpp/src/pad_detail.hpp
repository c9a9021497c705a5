// Internal to the tilting-pad equilibrium (pad_equilibrium.cpp: the pad assembly and each
// pad's nested tilt / pivot / pitch solves; pad_joint.cpp: a spherical pad's joint Newton):
// one pad's residual as a function of its own coordinates. Not installed, not part of the
// public headers.
#pragma once
#include <Eigen/Core>

#include <algorithm>
#include <vector>

#include "rotordyn/system.hpp"

namespace rotordyn {

namespace pad_detail {
constexpr double kPinch = 1e-3;  // the ends of a pad's tilt range: film pinched to kPinch·C
}  // namespace pad_detail

/// One pad's residual as a function of its own coordinates, everything else fixed.
struct SystemSolver::PadSolve {
  SystemSolver& s;
  const PadGroup& g;
  double omega = 0.0;
  // the film's local coordinates: journal x, y[, θx, θy], tilt[, pivot][, pitch]
  Eigen::VectorXd rc;
  Eigen::Vector3d A = Eigen::Vector3d::Zero();  // (K r − F) on the pad less K_gg p_g
  Eigen::Matrix3d Kgg = Eigen::Matrix3d::Zero();
  double tol = 0.0;           // absolute residual tolerance, N
  bool pressure_free = false;
  double pmax = 0.0;
  Eigen::Vector3d R = Eigen::Vector3d::Zero();

  PadSolve(SystemSolver& solver, const PadGroup& group) : s(solver), g(group) {}
  int m() const { return static_cast<int>(g.local.size()); }
  double own(int k) const { return rc(g.local[static_cast<std::size_t>(k)]); }
  void eval() {
    const Eigen::VectorXd Hl = s.solve_film(g.film, rc, omega);
    const RowMatrixXd& p = s.last_pressure(static_cast<int>(g.film));
    pmax = p.maxCoeff();
    pressure_free = p.cwiseAbs().maxCoeff() == 0.0;
    for (int k = 0; k < m(); ++k) {
      R(k) = A(k) - Hl(g.local[static_cast<std::size_t>(k)]);
      for (int j = 0; j < m(); ++j) R(k) += Kgg(k, j) * own(j);
    }
  }
  /// ∂R/∂p_g (m × m, in the top-left corner) about the last eval; with cols ≥ 0 only the
  /// first cols columns (the tilt's, the pivot's: the nested solves' derivatives), each a
  /// linearised Reynolds solve; the others are left as the identity's.
  Eigen::Matrix3d jac(int cols = -1) {
    Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
    jac_columns(J, 0, cols < 0 ? m() : std::min(cols, m()));
    return J;
  }
  /// Columns [from, to) of jac() into J.
  void jac_columns(Eigen::Matrix3d& J, int from, int to) {
    if (to <= from) return;
    const std::vector<int> cols(g.local.begin() + from, g.local.begin() + to);
    const Eigen::MatrixXd Kf = s.film_stiffness(g.film, cols);  // the pad's own columns
    for (int k = 0; k < m(); ++k)
      for (int j = from; j < to; ++j)
        J(k, j) = Kgg(k, j) + Kf(g.local[static_cast<std::size_t>(k)],
                                 g.local[static_cast<std::size_t>(j)]);
  }
  /// A spherical pad's (tilt[, pivot], pitch) solved together from rc (pad_joint.cpp): 1 with
  /// the pad evaluated at a pressured root (every residual within tol, the Jacobian
  /// restoring); otherwise rc restored to its start and 0 (the start itself carries no
  /// pressure or pinches the film) or −1 (the joint Newton did not get to a root): the caller
  /// then runs the nested solves.
  int joint(const FilmCoupling& fc);
};

}  // namespace rotordyn
