// Steady unbalance response of a system with bearing elements over a list of speeds in one
// call (paper §5): at each speed the equilibrium (continued from the previous converged one),
// K_H and D_H (eq. 18), the harmonic solve (K + K_H − Ω² M + iΩ (C + Ω G + D_H)) q = Ω² F₁
// and optionally the largest real part of the linear system's eigenvalues (eq. 19).
#pragma once
#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

#include "rotordyn/system.hpp"

namespace rotordyn {

struct UnbalanceSweepInput {
  Eigen::VectorXd omegas;          ///< (n_s,) spin speeds, rad/s, in the order continued
  Eigen::VectorXd pressure;        ///< (n_s,) p_c at each speed, Pa
  RowMatrixXd a;                   ///< (n_s, n) configuration (housing offsets) at each speed
  Eigen::VectorXd r0;              ///< (n,) start of the first speed, or empty (concentric)
  EquilibriumOptions options;
  Eigen::MatrixXd pad_penalty;     ///< (n, n) or empty: see pad_system_equilibrium
  Eigen::VectorXcd F;              ///< (n,) unbalance forcing per Ω², N/(rad/s)²
  Eigen::MatrixXd O;               ///< (n_out, n) outputs (x, y of each station)
  bool finite_difference = false;  ///< K_H, D_H by eq. 20 instead of the perturbation method
  double fd_step = 1e-6;
  /// The system has bearing elements: identically zero K_H and D_H are a degenerate
  /// linearisation (status "error").
  bool bearing_elements = true;
  bool check_stability = false;    ///< max_real: the largest real part of eq. 19's eigenvalues
  std::vector<std::pair<int, int>> xy_pairs, rot_pairs;  ///< whirl pairs (modal)
  /// After a speed that did not converge, raised, or whose harmonic solve failed, the next
  /// speed starts cold (the concentric state; a sweep line's rule) instead of from the last
  /// converged equilibrium; a failed harmonic solve is then that speed's status "error".
  bool cold_after_failure = false;
  /// 1: one continuation over all speeds (the order given). k > 1: k contiguous blocks of
  /// speeds on k threads, each block continued from r0 at its first speed.
  int n_threads = 1;
};

struct UnbalanceSweepResult {
  Eigen::MatrixXcd Y;                        ///< (n_s, n_out) O q; NaN where not converged
  /// (n_s,) equilibrium status, or "error" with "<ErrorClass>: <what>" as the message
  std::vector<std::string> status, message;
  RowMatrixXd r;                             ///< (n_s, n) equilibrium (NaN on "error")
  /// (n_s,) 1/s, the largest Re λ with the round-off band (kRoundOffRel) set to 0; NaN
  /// unless check_stability
  Eigen::VectorXd max_real;
  /// (n_s,) non-empty where the harmonic or the eigen solve failed after a converged,
  /// linearised equilibrium (a singular dynamic stiffness): the caller raises it.
  std::vector<std::string> solve_error;
};

/// Every speed of `in` (see UnbalanceSweepInput); per speed, one SystemSolver per thread:
/// the equilibrium by pad_system_equilibrium from the last speed whose status was ok or
/// contact and whose linearisation succeeded (else from the previous start), the
/// linearisation (finite K_H, D_H required), then harmonic_response and modal on exactly the
/// matrices the per-speed analysis builds (M(Ω) with table masses). An exception at a speed
/// gives it status "error" with the message; the sweep goes on.
UnbalanceSweepResult unbalance_sweep(const SystemModel& model, const UnbalanceSweepInput& in);

}  // namespace rotordyn
