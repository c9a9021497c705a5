// The threshold of instability along one line of a sweep in one call (issue 22): the scan of
// max Re λ over the line's points (equilibrium continued along the line, K_H/D_H, the
// eigen-analysis of eq. 19), then every sign change refined by Brent's method (the algorithm
// of SciPy's brentq, step for step, so that the roots are those the Python loop found).
#pragma once
#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

#include "rotordyn/system.hpp"

namespace rotordyn {

/// The quantity varied along the line.
enum class ThresholdAxis { Speed = 0, ChamberPressure = 1, Config = 2 };

struct ThresholdLineInput {
  Eigen::VectorXd x;            ///< (n_pts,) values of the varied axis (Hz, Pa or m)
  Eigen::VectorXd omega;        ///< (n_pts,) spin speed of each point, rad/s
  Eigen::VectorXd pressure;     ///< (n_pts,) chamber pressure, Pa
  RowMatrixXd a;                ///< (n_pts, n) configuration vector
  ThresholdAxis axis = ThresholdAxis::Speed;
  int config_index = -1;        ///< Config: the entry of a set to x
  EquilibriumOptions options;
  bool exclude_sleeve = false;  ///< max Re λ over the rotor modes only
  /// Brent's absolute tolerance; <= 0 with xtol_given false: 1e-8 × the bracket's width.
  double xtol = 0.0;
  bool xtol_given = false;
  int max_iter = 100;
  std::vector<std::pair<int, int>> xy_pairs, rot_pairs;
  std::vector<int> sleeve;      ///< sleeve coordinates (mode kind by kinetic-energy share)
  std::vector<int> pads;        ///< tilting pads' tilt/pivot coordinates ("pad" kind, likewise)
  std::vector<int> valid;       ///< (n_pts,) 0: the point's operating values were refused (a failed point)
};

struct ThresholdLineResult {
  Eigen::VectorXd y, freq;      ///< (n_pts,) max Re λ (1/s) and its frequency (Hz); NaN: failed
  /// (n_pts,) the verdict (the round-off band of modal.hpp over the counted roots):
  /// 1 stable, 0 unstable, -1 failed
  std::vector<int> stable;
  std::vector<int> bracket;     ///< per crossing: i of the bracket [x_i, x_{i+1}]
  std::vector<double> root, root_freq;  ///< per crossing (NaN on error)
  std::vector<std::string> status, message;  ///< per crossing: "ok" | "error", "<Error>: what"
  std::vector<int> evaluations; ///< per crossing: evaluations of max Re λ so far on the line
};

/// Scan then refine, on `solver` (its state carried through, as the per-point loop did).
/// Scan: each point starts from the previous point's equilibrium when that one converged
/// (ok or contact) and was analysed, else cold. Brent: every evaluation in [x_i, x_{i+1}]
/// starts from point i's equilibrium; no equilibrium there is an error of that crossing.
ThresholdLineResult threshold_line(SystemSolver& solver, const ThresholdLineInput& in);

/// The listed points of one boundary-refinement chunk (issue 22): max Re λ of eq. 19 at each,
/// by the threshold scan's rule (every mode, the sleeve's own left out with exclude_sleeve).
struct MaxRealBatchInput {
  Eigen::VectorXd omega;        ///< (n_pts,) spin speed, rad/s
  Eigen::VectorXd pressure;     ///< (n_pts,) chamber pressure, Pa
  RowMatrixXd a;                ///< (n_pts, n) configuration vector
  std::vector<int> restart;     ///< (n_pts,) 1: start cold, 0: continue along the line
  std::vector<int> valid;       ///< (n_pts,) 0: operating values refused (no evaluation)
  Eigen::VectorXd r0;           ///< start of a first point with restart 0 (empty: cold)
  /// (n_pts, n) or empty: a point's own start (e.g. a solved neighbour's equilibrium) where
  /// its row is finite, overriding restart and the continuation; NaN rows follow restart
  RowMatrixXd starts;
  EquilibriumOptions options;
  bool exclude_sleeve = false;
  std::vector<std::pair<int, int>> xy_pairs, rot_pairs;
  std::vector<int> sleeve;      ///< sleeve coordinates (mode kind by kinetic-energy share)
  std::vector<int> pads;        ///< tilting pads' tilt/pivot coordinates ("pad" kind, likewise)
};

struct MaxRealBatchResult {
  Eigen::VectorXd y, freq;      ///< (n_pts,) max Re λ (1/s), its frequency (Hz); NaN: failed
  /// (n_pts,) the equilibrium's status ("ok", "contact", a failure), "error" when a stage
  /// raised (message "<Error>: what"), "invalid" for valid = 0
  std::vector<std::string> status, message;
  Eigen::VectorXd r_last;       ///< the last point's equilibrium if it was analysed, else empty
  RowMatrixXd r;                ///< (n_pts, n) each point's equilibrium if analysed, else NaN
  /// the eigen-analysis of each analysed point (stability_batch's layout): n_eig (0 for a
  /// failed point), eigenvalues (n_pts, k) NaN past n_eig, whirl (n_pts, k) -1, 0, 1, and
  /// sleeve_share (n_pts, k) the sleeve's kinetic-energy share of each mode (0 without one),
  /// pad_share (n_pts, k) the tilting pads' (0 without pads)
  Eigen::VectorXi n_eig;
  Eigen::MatrixXcd eigenvalues;
  Eigen::MatrixXi whirl;
  RowMatrixXd sleeve_share;
  RowMatrixXd pad_share;
};

/// Points in order on `solver`, as the per-point loop: a point with restart 0 starts from the
/// previous point's equilibrium when that one converged (ok or contact) and was analysed,
/// else cold; a failed or invalid point makes the next one start cold. A finite row of
/// `starts` is that point's start instead (the equilibrium is polished to round-off, so the
/// start changes the cost, not the answer beyond round-off).
MaxRealBatchResult max_real_batch(SystemSolver& solver, const MaxRealBatchInput& in);

}  // namespace rotordyn
