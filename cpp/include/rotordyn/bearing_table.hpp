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
  Eigen::VectorXi iterations;
};

/// Equilibrium (with r0 as the start at every speed: results do not depend on the order or the
/// split over threads) and perturbation linearisation at each Ω in `omegas` (rad/s).
/// n_threads: 1 serial, 0 all hardware threads; each thread builds its own SystemSolver.
OperatingPointTable operating_points(const SystemModel& model, const Eigen::VectorXd& omegas,
                                     const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                                     const EquilibriumOptions& options, int n_threads = 1);

}  // namespace rotordyn
