// Mode tracking along lines of operating points (speed, chamber pressure, configuration):
// the modal assurance criterion between a point's modes and the modes last seen, completed by
// the eigenvalue distance, and a one-to-one assignment (shortest augmenting paths, optimal).
// Python: rotordyn.analysis.tracking.track_modes and the sweep's stability chunks.
#pragma once
#include <Eigen/Core>

#include <vector>

namespace rotordyn {

/// Optimal assignment of a (n_rows, n_cols) cost matrix: min(n_rows, n_cols) pairs, each row
/// and column used at most once, with the least total cost. Returns, per row, its column or
/// -1. Costs must be finite (InputError otherwise).
std::vector<int> linear_assignment(const Eigen::MatrixXd& cost);

struct TrackOptions {
  double eig_weight = 0.2;  ///< weight of |Δλ|/scale beside 1 − MAC
  double min_mac = 0.3;     ///< a pair with a lower MAC is not matched (with shapes)
};

/// Tracked mode ids of a batch of points.
///
/// eigenvalues: (n_pts, k), 1/s, NaN for an empty slot. shapes: per point an (n, k_i) matrix
/// (k_i <= k; columns past k_i are empty slots), or an empty vector to track by eigenvalue
/// proximity alone. weight: (n, n) weighting of the MAC (e.g. the mass matrix), or empty for
/// the identity. line_start: (n_pts,) nonzero where a new line starts (ids start again at 0;
/// the first point always starts one). Returns (n_pts, k) ids, −1 for an empty slot.
///
/// On each line every point is matched with the last point where each id was seen, by the
/// assignment that minimises Σ (1 − MAC) + eig_weight·|Δλ|/scale, scale = max |λ| over the
/// two sets; a pair with MAC < min_mac (with shapes) or |Δλ|/scale > 0.1 (without) is not
/// matched and the slot starts a new id (in slot order).
Eigen::MatrixXi track_modes(const Eigen::MatrixXcd& eigenvalues,
                            const std::vector<Eigen::MatrixXcd>& shapes,
                            const Eigen::MatrixXd& weight, const std::vector<int>& line_start,
                            const TrackOptions& options = {});

}  // namespace rotordyn
