#include "rotordyn/tracking.hpp"

#include <algorithm>
#include <complex>
#include <cmath>
#include <limits>
#include <string>

#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {

/// Shortest augmenting paths with potentials (Kuhn–Munkres in O(n² m)), n_rows <= n_cols:
/// every row gets a column. Returns the column of each row.
std::vector<int> assign_rows(const Eigen::MatrixXd& a) {
  const int n = static_cast<int>(a.rows());
  const int m = static_cast<int>(a.cols());
  const double inf = std::numeric_limits<double>::infinity();
  // 1-based potentials u (rows), v (columns); p[j]: the row matched to column j (0: none)
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0), minv(m + 1);
  std::vector<int> p(m + 1, 0), way(m + 1, 0);
  std::vector<char> used(m + 1);
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const int i0 = p[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = a(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const int j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> col(static_cast<std::size_t>(n), -1);
  for (int j = 1; j <= m; ++j)
    if (p[j] != 0) col[static_cast<std::size_t>(p[j] - 1)] = j - 1;
  return col;
}

}  // namespace

std::vector<int> linear_assignment(const Eigen::MatrixXd& cost) {
  if (!cost.allFinite())
    throw InputError("linear_assignment: the cost matrix has a non-finite entry");
  const Eigen::Index nr = cost.rows(), nc = cost.cols();
  std::vector<int> out(static_cast<std::size_t>(nr), -1);
  if (nr == 0 || nc == 0) return out;
  if (nr <= nc) return assign_rows(cost);
  const std::vector<int> row_of_col = assign_rows(cost.transpose());
  for (Eigen::Index j = 0; j < nc; ++j)
    out[static_cast<std::size_t>(row_of_col[static_cast<std::size_t>(j)])] = static_cast<int>(j);
  return out;
}

Eigen::MatrixXi track_modes(const Eigen::MatrixXcd& eigenvalues,
                            const std::vector<Eigen::MatrixXcd>& shapes,
                            const Eigen::MatrixXd& weight, const std::vector<int>& line_start,
                            const TrackOptions& options) {
  const Eigen::Index n_pts = eigenvalues.rows(), k = eigenvalues.cols();
  const bool with_shapes = !shapes.empty();
  if (with_shapes && static_cast<Eigen::Index>(shapes.size()) != n_pts)
    throw InputError("track_modes: expected " + std::to_string(n_pts) +
                     " shape matrices (one per point), got " + std::to_string(shapes.size()));
  if (!line_start.empty() && static_cast<Eigen::Index>(line_start.size()) != n_pts)
    throw InputError("track_modes: expected line_start of length " + std::to_string(n_pts) +
                     ", got " + std::to_string(line_start.size()));
  for (const auto& [name, x] : {std::pair<const char*, double>{"eig_weight", options.eig_weight},
                                {"min_mac", options.min_mac}})
    if (!std::isfinite(x) || x < 0)
      throw InputError(std::string(name) + ": expected a finite value >= 0, got " +
                       std::to_string(x));
  Eigen::Index n = -1;  // coordinates of the shapes
  if (with_shapes) {
    for (Eigen::Index i = 0; i < n_pts; ++i) {
      const auto& s = shapes[static_cast<std::size_t>(i)];
      if (s.cols() > k)
        throw InputError("track_modes: point " + std::to_string(i) + ": expected at most " +
                         std::to_string(k) + " mode shapes, got " + std::to_string(s.cols()));
      if (s.cols() == 0) continue;
      if (n < 0) n = s.rows();
      if (s.rows() != n)
        throw InputError("track_modes: point " + std::to_string(i) + ": expected shapes of " +
                         std::to_string(n) + " coordinates, got " + std::to_string(s.rows()));
    }
    if (weight.size() != 0 && n >= 0 && (weight.rows() != n || weight.cols() != n))
      throw InputError("track_modes: expected a weight of shape (" + std::to_string(n) + ", " +
                       std::to_string(n) + "), got (" + std::to_string(weight.rows()) + ", " +
                       std::to_string(weight.cols()) + ")");
  }

  // Per point: which slots hold a mode, the weighted shapes W φ and the norms φ^H W φ.
  std::vector<std::vector<int>> present(static_cast<std::size_t>(n_pts));
  std::vector<Eigen::MatrixXcd> wphi(with_shapes ? static_cast<std::size_t>(n_pts) : 0);
  std::vector<Eigen::VectorXd> nrm(with_shapes ? static_cast<std::size_t>(n_pts) : 0);
  for (Eigen::Index i = 0; i < n_pts; ++i) {
    const std::size_t iu = static_cast<std::size_t>(i);
    for (Eigen::Index s = 0; s < k; ++s) {
      const std::complex<double> lam = eigenvalues(i, s);
      if (!std::isfinite(lam.real()) || !std::isfinite(lam.imag())) continue;
      if (with_shapes && (s >= shapes[iu].cols() || !shapes[iu].col(s).allFinite())) continue;
      present[iu].push_back(static_cast<int>(s));
    }
    if (with_shapes && shapes[iu].cols() > 0) {
      wphi[iu] = weight.size() ? Eigen::MatrixXcd(weight.cast<std::complex<double>>() * shapes[iu])
                               : shapes[iu];
      nrm[iu] = (shapes[iu].conjugate().cwiseProduct(wphi[iu])).colwise().sum().real().transpose();
    }
  }

  Eigen::MatrixXi ids = Eigen::MatrixXi::Constant(n_pts, k, -1);
  std::vector<Eigen::Index> last_pt, last_slot;  // where each id of the line was last seen
  for (Eigen::Index i = 0; i < n_pts; ++i) {
    const std::size_t iu = static_cast<std::size_t>(i);
    if (i == 0 || (!line_start.empty() && line_start[iu])) {
      last_pt.clear();
      last_slot.clear();
    }
    const std::vector<int>& slots = present[iu];
    if (slots.empty()) continue;
    const Eigen::Index ns = static_cast<Eigen::Index>(slots.size());
    const Eigen::Index nk = static_cast<Eigen::Index>(last_pt.size());
    std::vector<int> assigned(static_cast<std::size_t>(k), -1);
    if (nk > 0) {
      double scale = 1e-300;
      for (Eigen::Index c = 0; c < nk; ++c)
        scale = std::max(scale, std::abs(eigenvalues(last_pt[c], last_slot[c])));
      for (int s : slots) scale = std::max(scale, std::abs(eigenvalues(i, s)));
      Eigen::MatrixXd dist(ns, nk), mac = Eigen::MatrixXd::Ones(ns, nk);
      for (Eigen::Index r = 0; r < ns; ++r) {
        const int s = slots[static_cast<std::size_t>(r)];
        for (Eigen::Index c = 0; c < nk; ++c) {
          dist(r, c) = std::abs(eigenvalues(i, s) - eigenvalues(last_pt[c], last_slot[c])) / scale;
          if (!with_shapes) continue;
          const std::size_t pu = static_cast<std::size_t>(last_pt[c]);
          const double cross =
              std::norm(shapes[iu].col(s).dot(wphi[pu].col(last_slot[c])));  // conj(a)·Wb
          const double den = nrm[iu](s) * nrm[pu](last_slot[c]);
          mac(r, c) = den > 0 ? std::clamp(cross / den, 0.0, 1.0) : 0.0;
        }
      }
      const Eigen::MatrixXd cost =
          (1.0 - mac.array()).matrix() + options.eig_weight * dist;
      const std::vector<int> col = linear_assignment(cost);
      for (Eigen::Index r = 0; r < ns; ++r) {
        const int c = col[static_cast<std::size_t>(r)];
        if (c < 0) continue;
        if (with_shapes ? mac(r, c) < options.min_mac : dist(r, c) > 0.1) continue;
        assigned[static_cast<std::size_t>(slots[static_cast<std::size_t>(r)])] = c;
      }
    }
    for (int s : slots) {
      int& j = assigned[static_cast<std::size_t>(s)];
      if (j < 0) {
        j = static_cast<int>(last_pt.size());
        last_pt.push_back(i);
        last_slot.push_back(s);
      }
      ids(i, s) = j;
      last_pt[static_cast<std::size_t>(j)] = i;
      last_slot[static_cast<std::size_t>(j)] = s;
    }
  }
  return ids;
}

}  // namespace rotordyn
