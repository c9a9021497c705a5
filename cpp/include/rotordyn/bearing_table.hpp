// Bearing coefficient tables: batches of operating points over speed (equilibrium, then the
// linearised film coefficients at each speed), parallel over speeds, one SystemSolver per
// thread. Used by every standalone bearing (plain, fixed geometry, tilting pad, squeeze-film
// damper) to tabulate its coefficients, and by the speed-dependent table bearing's
// interpolation (TableCoupling, system.hpp).
#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

#include "rotordyn/system.hpp"

namespace rotordyn {

/// One row per speed. r (n_s, n): equilibrium coordinates; KH, DH (n_s, n·n) row-major
/// n×n film stiffness/damping (eq. 18) at the equilibrium; force (n_s, n): H there.
/// status: "ok" | "not_converged" | "contact" | "error"; rows not ok hold NaN coefficients.
struct OperatingPointTable {
  RowMatrixXd r, KH, DH, force;
  std::vector<std::string> status, message;
  std::vector<std::string> path;  ///< EquilibriumResult::path per speed ("homotopy": fallback)
  Eigen::VectorXi iterations;
  Eigen::VectorXi reynolds_solves;  ///< equilibrium's Reynolds solves per speed (with the
                                    ///< fallback: the whole pad_system_equilibrium's)
};

/// Equilibrium (with r0 as the start at every speed: results do not depend on the order or the
/// split over threads) and perturbation linearisation at each Ω in `omegas` (rad/s).
/// n_threads: 1 serial, 0 all hardware threads; each thread builds its own SystemSolver.
/// `pad_penalty` (n×n, or empty): see homotopy_start; the fallback at a speed whose
/// equilibrium did not converge through the pad assembly (model.pad_coords).
OperatingPointTable operating_points(const SystemModel& model, const Eigen::VectorXd& omegas,
                                     const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                                     const EquilibriumOptions& options, int n_threads = 1,
                                     const Eigen::MatrixXd& pad_penalty = Eigen::MatrixXd());

/// Starting point for the equilibrium of a system with tilting pads: equilibria of the model
/// with K + κ_i P for κ = κ_0·10^{−t}, t = 0 … 10 in adaptive steps (each from the previous one), P the pads'
/// penalty (e.g. identity on the pad coordinates), κ_0 = 100 × the largest diagonal entry of K_H at the
/// start. The stiff penalty first holds the pads near their aligned position (every pad with
/// a convergent, pressurised film), then releases them gradually, so Newton does not jump onto
/// the pressure-free branch of an unloaded pad (fully divergent film: zero moment at any tilt).
/// Returns the last converged stage's r (r0 / zero if none converged). The stages stop once
/// the failed ones' Reynolds solves exceed kHomotopyMaxSolves (bounded cost where no start
/// exists).
inline constexpr long kHomotopyMaxSolves = 30000;

Eigen::VectorXd homotopy_start(const SystemModel& model, double omega, double chamber_pressure,
                               const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                               const EquilibriumOptions& options,
                               const Eigen::MatrixXd& pad_penalty);

/// The equilibrium of a system with tilting pads (`pad_penalty` P, n×n; empty: no pads, a
/// plain solver.equilibrium): the pad assembly from r0 first; where it did not converge
/// through the pad assembly, the tilt homotopy from `homotopy_r0` then the true model's
/// Newton (path "homotopy"). A converged first answer is kept when the fallback fails.
/// reynolds_solves: the whole call's (the first attempt, the homotopy's stages and the
/// returned equilibrium's Newton; it was the returned equilibrium's own, which hid the
/// fallback's cost: 34 solves reported for ~4000 made).
EquilibriumResult pad_system_equilibrium(SystemSolver& solver, const SystemModel& model,
                                         double omega, double chamber_pressure,
                                         const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                                         const Eigen::VectorXd& homotopy_r0,
                                         const EquilibriumOptions& options,
                                         const Eigen::MatrixXd& pad_penalty);

}  // namespace rotordyn
