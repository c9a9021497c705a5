// Banded LDLᵀ for the Reynolds operator when the cavitation set cuts the film (private).
//
// The unknowns are numbered ring by ring around the bearing, so the 5-point operator is
// banded (bandwidth = the unknowns of about one ring) except for the couplings that close the
// circle. When every unknown of some ring is held at p = 0 (decoupled: a cavitated ring, or a
// ring with no unknowns), the circle is open there: numbering from that ring gives a banded
// matrix, factorised densely in its band — about n·b²/2 multiply-adds, contiguous, and the
// decoupled columns skipped — where the periodic pattern's sparse factor carries the fill of
// the closed circle. Used by ReynoldsSolver when such a ring exists, StaticLDLT otherwise.
#pragma once
#include <Eigen/SparseCore>

#include <algorithm>
#include <utility>
#include <vector>

namespace rotordyn {

class BandLDLT {
 public:
  using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  /// Pattern of A (structurally symmetric, both triangles) with its unknowns numbered ring
  /// by ring: ring_first[j] is the first unknown of ring j (size n_rings + 1, last = n).
  /// Returns false (band path unavailable, nothing allocated) when fewer than 3 rings, no
  /// narrow band exists, or a band factorisation (n·b(b+1)/2 multiply-adds) would cost more
  /// than max_flops — the sparse factor's, so long thin grids keep the sparse path.
  bool analyze(const SpMat& A, const std::vector<int>& ring_first, double max_flops = 1e300);
  bool usable() const { return usable_; }
  int bandwidth() const { return b_; }
  /// Numeric factorisation with the circle opened before ring `cut` (every coupling of that
  /// ring's unknowns must be zero in `values`). False if a pivot is zero or not finite or a
  /// nonzero value falls outside the band (the caller then uses the sparse factor).
  bool factorize(const double* values, int cut);
  /// x = A⁻¹ b (x may alias b).
  void solve(const double* b, double* x) const;
  /// x_v = A⁻¹ x_v in place for four vectors at once: the same values as four solve() calls
  /// (the four interleaved, two lanes per instruction).
  void solve4(double* const x[4]) const;
  /// Direct assembly, the same factor as factorize() without a sparse value array: begin()
  /// clears the band for the circle opened before ring `cut`; set(i, j, v) stores
  /// A(i, j) = A(j, i) = v (i == j: the diagonal), false when the pair lies outside the band
  /// or across the opening; factorize_assembled() then factorises (false as factorize()).
  void begin(int cut);
  bool set(int i, int j, double v) {
    if (v == 0.0) return true;
    int ci = i - shift_, cj = j - shift_;
    if (ci < 0) ci += n_;
    if (cj < 0) cj += n_;
    if (ci > cj) std::swap(ci, cj);
    if (cj - ci > b_) return false;
    a_[static_cast<std::size_t>(ci) * (b_ + 1) + (cj - ci)] = v;
    return true;
  }
  bool factorize_assembled();
  /// Column-wise assembly (what begin()/set() do, without clearing the whole band):
  /// begin_columns(cut) opens the circle and clears the padding only; the caller then writes
  /// every column column(opened(i)) in full — b + 1 values, the diagonal and A(i + d, i) for
  /// the unknown i + d, d places later in the opened order.
  void begin_columns(int cut) {
    shift_ = ring_first_[cut];
    std::fill(a_.begin() + static_cast<std::size_t>(n_) * (b_ + 1), a_.end(), 0.0);
  }
  int opened(int i) const { return i - shift_ < 0 ? i - shift_ + n_ : i - shift_; }
  double* column(int c) { return a_.data() + static_cast<std::size_t>(c) * (b_ + 1); }

 private:
  bool usable_ = false;
  int n_ = 0, b_ = 0, shift_ = 0;
  std::vector<int> ring_first_;
  std::vector<int> col_of_;   // value slot -> column (unknown)
  std::vector<int> dist_;     // value slot -> forward distance row − column (mod n), -1: upper
  std::vector<double> a_;     // band, column c at a_[c*(b+1) + d] = L(c + d, c) (d = 0: D)
  std::vector<char> coupled_; // column c has a nonzero below the diagonal
  mutable std::vector<double> ys_;
  mutable std::vector<double> y4s_;  // solve4's interleaved workspace, (n + b) x 4
};

}  // namespace rotordyn
