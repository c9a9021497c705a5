// Mode tracking: the assignment is optimal (against every permutation of small matrices), and
// ids follow the shapes through a crossing of two uncoupled modes.
#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

#include "rotordyn/errors.hpp"
#include "rotordyn/tracking.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
/// Least total cost over every injective map of the smaller side into the larger (brute force).
double brute_force(const Eigen::MatrixXd& c) {
  const bool tr = c.rows() > c.cols();
  const Eigen::MatrixXd a = tr ? Eigen::MatrixXd(c.transpose()) : c;
  std::vector<int> cols(static_cast<std::size_t>(a.cols()));
  std::iota(cols.begin(), cols.end(), 0);
  double best = 1e300;
  do {  // the first a.rows() entries of each permutation (repeats are harmless)
    double s = 0;
    for (Eigen::Index r = 0; r < a.rows(); ++r) s += a(r, cols[static_cast<std::size_t>(r)]);
    best = std::min(best, s);
  } while (std::next_permutation(cols.begin(), cols.end()));
  return best;
}
}  // namespace

TEST_CASE("linear_assignment: optimal against brute force, square and rectangular") {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int nr = 1 + trial % 5, nc = 1 + (trial / 5) % 5;
    Eigen::MatrixXd c(nr, nc);
    for (int i = 0; i < nr; ++i)
      for (int j = 0; j < nc; ++j) c(i, j) = u(gen);
    const std::vector<int> col = linear_assignment(c);
    CHECK(static_cast<int>(col.size()) == nr);
    std::vector<int> used;
    double total = 0;
    for (int i = 0; i < nr; ++i) {
      if (col[static_cast<std::size_t>(i)] < 0) continue;
      used.push_back(col[static_cast<std::size_t>(i)]);
      total += c(i, col[static_cast<std::size_t>(i)]);
    }
    CHECK(static_cast<int>(used.size()) == std::min(nr, nc));
    std::sort(used.begin(), used.end());
    CHECK(std::adjacent_find(used.begin(), used.end()) == used.end());
    CHECK_CLOSE(total, brute_force(c), 1e-12, 1e-12);
  }
  Eigen::MatrixXd bad = Eigen::MatrixXd::Zero(2, 2);
  bad(1, 0) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS(linear_assignment(bad), InputError);
}

TEST_CASE("track_modes: ids follow the shapes through a crossing; lines restart at 0") {
  // two uncoupled modes, x at 10 rad/s, y sweeping 5 -> 15 rad/s; slots sorted by frequency
  const int n_pts = 11;
  Eigen::MatrixXcd lam(2 * n_pts, 2);
  std::vector<Eigen::MatrixXcd> shapes;
  std::vector<int> start(2 * n_pts, 0);
  for (int line = 0; line < 2; ++line) {
    start[static_cast<std::size_t>(line * n_pts)] = 1;
    for (int i = 0; i < n_pts; ++i) {
      const double wy = 5.0 + i + 0.01;  // never exactly equal to 10
      Eigen::MatrixXcd s = Eigen::MatrixXcd::Zero(2, 2);
      const bool y_first = wy < 10.0;
      lam(line * n_pts + i, 0) = {0.0, y_first ? wy : 10.0};
      lam(line * n_pts + i, 1) = {0.0, y_first ? 10.0 : wy};
      s(y_first ? 1 : 0, 0) = 1.0;
      s(y_first ? 0 : 1, 1) = 1.0;
      shapes.push_back(s);
    }
  }
  const Eigen::MatrixXi ids = track_modes(lam, shapes, Eigen::MatrixXd(), start);
  for (int line = 0; line < 2; ++line)
    for (int i = 0; i < n_pts; ++i) {
      const bool y_first = 5.0 + i + 0.01 < 10.0;
      // id 0 is the y mode (slot 0 at the first point) on every line
      CHECK(ids(line * n_pts + i, 0) == (y_first ? 0 : 1));
      CHECK(ids(line * n_pts + i, 1) == (y_first ? 1 : 0));
    }
  // an empty slot has id -1; bad shapes are named
  Eigen::MatrixXcd one = lam.topRows(1);
  one(0, 1) = {std::numeric_limits<double>::quiet_NaN(), 0.0};
  const Eigen::MatrixXi e = track_modes(one, {}, Eigen::MatrixXd(), {});
  CHECK(e(0, 0) == 0 && e(0, 1) == -1);
  CHECK_THROWS(track_modes(lam, {shapes[0]}, Eigen::MatrixXd(), {}), InputError);
  CHECK_THROWS(track_modes(lam, shapes, Eigen::MatrixXd::Identity(3, 3), {}), InputError);
}
