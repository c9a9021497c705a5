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
  /// Numeric factorisation with the circle opened at ring `cut` (every coupling of that
  /// ring's unknowns must be zero in `values`): its unknowns first, then the rings after it
  /// (+j), or before it (−j) when `reverse`. False if a pivot is zero or not finite or a
  /// nonzero value falls outside the band (the caller then uses the sparse factor).
  bool factorize(const double* values, int cut, bool reverse = false);
  /// x = A⁻¹ b (x may alias b).
  void solve(const double* b, double* x) const;
  /// x_v = A⁻¹ x_v in place for four vectors at once: the same values as four solve() calls
  /// (the four interleaved, two lanes per instruction).
  void solve4(double* const x[4]) const;
  /// Direct assembly, the same factor as factorize() without a sparse value array: begin()
  /// clears the band for the circle opened at ring `cut`; set(i, j, v) stores
  /// A(i, j) = A(j, i) = v (i == j: the diagonal), false when the pair lies outside the band
  /// or across the opening; factorize_assembled() then factorises (false as factorize()).
  void begin(int cut, bool reverse = false);
  bool set(int i, int j, double v) {
    if (v == 0.0) return true;
    int ci = opened(i), cj = opened(j);
    if (ci > cj) std::swap(ci, cj);
    if (cj - ci > b_) return false;
    a_[static_cast<std::size_t>(ci) * (b_ + 1) + (cj - ci)] = v;
    return true;
  }
  /// checkpoints: also save, every checkpoint_stride() columns, the state of the next b
  /// columns (what a later refactorize_from needs).
  bool factorize_assembled(bool checkpoints = false);
  int checkpoint_stride() const { return kCheckpointRings * b_; }
  /// Resumes the last factorisation at column c0 (a multiple of checkpoint_stride(), opened
  /// order):
  /// valid when the assembled band equals the last one's in columns 0 .. c0 + b − 1 (the
  /// same opening, checkpoints saved) and the caller has rewritten columns c0 + b .. n − 1
  /// (begin_from, then the columns; a write into c0 .. c0 + b − 1 is overwritten here). The
  /// factor is the one factorize_assembled() gives, bit for bit (the same operations from the
  /// state saved before column c0). False when no state is saved for c0 (the caller then
  /// assembles and factorises the whole band).
  bool refactorize_from(int c0, bool checkpoints = true);
  /// The last factorisation saved its checkpoints and succeeded, opened at `cut` that way.
  bool resumable(int cut, bool reverse) const {
    return ckpt_ok_ && reverse == rev_ && shift_ == (reverse ? ring_first_[cut + 1]
                                                             : ring_first_[cut]);
  }
  /// Clears columns c .. n + b − 1 only (a resumed factorisation: the same opening).
  void begin_from(int c) {
    std::fill(a_.begin() + static_cast<std::size_t>(c) * (b_ + 1), a_.end(), 0.0);
  }
  /// Column of unknown i in the opened order. Forward (opened at ring j0, shift_ its first
  /// unknown): i − shift_ mod n. Reverse (shift_ one past ring j0's last unknown): the
  /// unknowns shift_ − 1, shift_ − 2, ..., 0, n − 1, ..., shift_.
  int opened(int i) const {
    if (rev_) return i < shift_ ? shift_ - 1 - i : n_ + shift_ - 1 - i;
    return i - shift_ < 0 ? i - shift_ + n_ : i - shift_;
  }
  bool reversed() const { return rev_; }
  double* column(int c) { return a_.data() + static_cast<std::size_t>(c) * (b_ + 1); }

 private:
  bool usable_ = false;
  int n_ = 0, b_ = 0, shift_ = 0;
  bool rev_ = false;  // opened order runs in −j (see opened())
  static constexpr int kCheckpointRings = 4;
  std::vector<int> ring_first_;
  std::vector<int> col_of_;   // value slot -> column (unknown)
  std::vector<int> dist_;     // value slot -> forward distance row − column (mod n), -1: upper
  std::vector<double> a_;     // band, column c at a_[c*(b+1) + d] = L(c + d, c) (d = 0: D)
  std::vector<char> coupled_; // column c has a nonzero below the diagonal
  mutable std::vector<double> ys_;
  std::vector<double> ckpt_;  // state of columns k·s .. k·s + b − 1 before column k·s (s the stride)
  bool ckpt_ok_ = false;      // ckpt_ holds the last (successful) factorisation's states
  bool factor_from(int c0, bool checkpoints);
  mutable std::vector<double> y4s_;  // solve4's interleaved workspace, (n + b) x 4
};

}  // namespace rotordyn
