// Eigen-analysis of M q̈ + D q̇ + K q = 0 (D = C + Ω G): damped natural frequencies, damping,
// whirl direction and mode shapes (paper §5, eq. 19 without excitation).
#pragma once
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

namespace rotordyn {

/// Whirl direction of a mode, from the orbits of its (x, y) pairs.
enum class Whirl : int { Backward = -1, Planar = 0, Forward = 1 };

struct ModalResult {
  /// (n_modes,) eigenvalues λ = σ + iω_d with ω_d >= 0, ascending in ω_d (then |λ|), 1/s.
  Eigen::VectorXcd eigenvalues;
  /// (n_dof, n_modes) displacement part of the eigenvectors, scaled so that the largest
  /// component is 1 (real).
  Eigen::MatrixXcd modes;
  /// (n_modes,) whirl direction of each mode.
  std::vector<Whirl> whirl;
};

/// All eigenvalues of the real general matrix A (LAPACK dgeev). With vectors=true, V holds
/// the right eigenvectors as columns.
void eig_general(const Eigen::MatrixXd& A, Eigen::VectorXcd& w, Eigen::MatrixXcd* V);

/// Round-off band of Re λ: |Re λ| < kRoundOffRel·max(|λ|, 1) counts as 0 (the rule of
/// rotordyn.results.modes.ROUND_OFF_REL, for the verdicts computed in C++).
inline constexpr double kRoundOffRel = 1e-9;

/// Re λ with the round-off band set to exactly 0 (rotordyn.results.modes.settled_real).
inline double settled_real(const std::complex<double>& l) {
  return std::abs(l.real()) < kRoundOffRel * std::max(std::abs(l), 1.0) ? 0.0 : l.real();
}

/// Modal analysis of the second-order system (dense, n_dof ≤ a few thousand).
/// xy_pairs: (ix, iy) index pairs used to classify whirl. n_modes <= 0: all (with
/// with_modes = false: eigenvalues only, for a verdict over every root; their whirl is then
/// not classified: planar). A growing real root (a divergence) is always kept.
/// rot_pairs: (iθx, iθy) pairs, used for the whirl of modes without translation (a tilting
/// disk).
ModalResult modal(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D, const Eigen::MatrixXd& K,
                  const std::vector<std::pair<int, int>>& xy_pairs, int n_modes,
                  bool with_modes = true,
                  const std::vector<std::pair<int, int>>& rot_pairs = {});

/// Campbell data: the n_modes least-frequency eigenvalues at each spin speed (rad/s), using
/// D = C + Ω G at each speed. eigenvalues (n_speeds, n_modes); whirl (n_speeds, n_modes).
struct CampbellResult {
  Eigen::MatrixXcd eigenvalues;
  Eigen::MatrixXi whirl;
};
CampbellResult campbell(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                        const Eigen::MatrixXd& G, const Eigen::MatrixXd& K,
                        const std::vector<std::pair<int, int>>& xy_pairs,
                        const Eigen::VectorXd& speeds_rad_s, int n_modes,
                        const std::vector<std::pair<int, int>>& rot_pairs = {});

/// Classify the whirl of one displacement vector from its (x, y) pairs; when the translations
/// are negligible (a pure tilt mode), from its (θx, θy) pairs (forward when the disk axis
/// precesses with the spin).
Whirl whirl_direction(const Eigen::VectorXcd& shape, const std::vector<std::pair<int, int>>& xy,
                      const std::vector<std::pair<int, int>>& rot = {});

}  // namespace rotordyn
