// One sweep chunk of stability points in one call: the equilibrium continued from point to
// point along a line, K_H/D_H (eq. 18) and the eigen-analysis of eq. 19 at each point, the
// results written into flat arrays (no per-point objects crossing into Python).
#pragma once
#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

#include "rotordyn/system.hpp"

namespace rotordyn {

struct StabilityBatchInput {
  Eigen::VectorXd omega;     ///< (n_pts,) spin speed, rad/s
  Eigen::VectorXd pressure;  ///< (n_pts,) chamber pressure, Pa
  RowMatrixXd a;             ///< (n_pts, n) configuration vector of each point
  std::vector<int> restart;  ///< (n_pts,) 1: start cold (a new line), 0: continue
  EquilibriumOptions options;
  int n_modes = 0;           ///< <= 0: all
  bool finite_difference = false;
  double fd_step = 1e-6;
  std::vector<std::pair<int, int>> xy_pairs, rot_pairs;
  std::vector<int> sleeve;   ///< sleeve coordinates (mode kind by kinetic-energy share)
  /// The films carry their cavitation sets from point to point along a line (forgotten at
  /// every restart and at the end; SystemSolver::set_film_carry): fewer active-set steps, the
  /// same answers (the Swift–Stieber solution is unique). Off: each equilibrium starts from
  /// the coarse-grid prediction (the former cost; for tests and benchmarks).
  bool carry_cavitation = true;
  /// The equilibrium's Newton Jacobian (EquilibriumOptions::reuse_jacobian): "exact" (formed
  /// by linearisation at every iterate that steps), "reuse" (modified Newton: formed at the
  /// first such iterate, then Broyden-updated, formed anew when a step does not contract),
  /// "line" (as "reuse", the first one being K plus the previous point's K_H on the line, which
  /// the stability analysis formed anyway). Not "exact": the answers change within the
  /// equilibrium tolerance.
  std::string jacobian = "reuse";
};

struct StabilityBatchResult {
  std::vector<std::string> status, message;  ///< (n_pts,)
  Eigen::VectorXi iterations;                ///< (n_pts,)
  RowMatrixXd r;                             ///< (n_pts, n) equilibrium
  RowMatrixXd h_min;                         ///< (n_pts, n_films)
  /// (n_pts, n_films) axial position of h_min, m, and (n_pts, n) H at the equilibrium (a
  /// tilted film's moments at its rotations): NaN where the equilibrium did not converge
  RowMatrixXd h_min_z_m, film_force;
  Eigen::VectorXi n_eig;                     ///< (n_pts,) eigenvalues found (0: none)
  Eigen::MatrixXcd eigenvalues;              ///< (n_pts, k), NaN past n_eig
  Eigen::MatrixXi whirl;                     ///< (n_pts, k) -1, 0, 1
  RowMatrixXd sleeve_share;                  ///< (n_pts, k) kinetic-energy share of the sleeve
  std::vector<Eigen::MatrixXcd> modes;       ///< per point (n, n_eig)
  /// (n_pts,) the root with the largest real part among ALL the point's roots (Re λ within
  /// the round-off band 1e-9·max(|λ|, 1) counted as 0), whatever n_modes kept: the point's
  /// verdict and max Re λ. NaN where the point failed.
  Eigen::VectorXcd least_stable;
  /// (n_pts,) max Re λ over ALL the point's roots, 1/s (NaN where the point failed)
  Eigen::VectorXd max_real;
};

/// Points in order on one solver; a point failing at any stage gets status "error" (or the
/// equilibrium's status) and the batch goes on. A failed point (not "ok"/"contact"): every
/// numeric output NaN (r, h_min, h_min_z_m, film_force, eigenvalues, sleeve_share; n_eig 0,
/// no modes) and a message — the rule of equilibrium_batch too; iterations kept.
/// Continuation: a point with restart = 0 starts from the previous point's equilibrium when
/// that one converged ("ok"), extrapolated along
/// the line (quadratic through up to three converged predecessors whose inputs lie on one
/// straight line; retried from the previous equilibrium itself if that start fails).
StabilityBatchResult stability_batch(SystemSolver& solver, const StabilityBatchInput& in);

/// The equilibria of a sweep chunk's points (omega, pressure, a, restart, options as in
/// StabilityBatchInput; n_modes and the linearisation fields unused).
struct EquilibriumBatchResult {
  std::vector<std::string> status, message;  ///< (n_pts,) "error": the solve raised
  Eigen::VectorXi iterations;                ///< (n_pts,)
  Eigen::VectorXd residual;                  ///< (n_pts,)
  RowMatrixXd r;                             ///< (n_pts, n) equilibrium
  RowMatrixXd h_min;                         ///< (n_pts, n_films)
  RowMatrixXd h_min_z_m;                     ///< (n_pts, n_films) axial position of h_min, m
  RowMatrixXd film_force;                    ///< (n_pts, n) H at the equilibrium
  // a failed point (not "ok"/"contact", or "error": the solve raised): residual, r, h_min,
  // h_min_z_m and film_force NaN, a message set (stability_batch's rule); iterations kept
};

/// Points in order on one solver, exactly as a Python loop of solver.equilibrium calls
/// would (but a failed point's outputs NaN, above): a point with restart = 0 starts from the
/// previous point's equilibrium when that one's status was "ok", else (and after a point
/// that raised) from the concentric state.
EquilibriumBatchResult equilibrium_batch(SystemSolver& solver, const StabilityBatchInput& in);

}  // namespace rotordyn
