// BandLDLT: the Reynolds operator with its circle opened at a decoupled ring (see
// reynolds_band.hpp).
#include "reynolds_band.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rotordyn {

bool BandLDLT::analyze(const SpMat& A, const std::vector<int>& ring_first, double max_flops) {
  usable_ = false;
  n_ = static_cast<int>(A.cols());
  const int n_rings = static_cast<int>(ring_first.size()) - 1;
  if (n_rings < 3 || n_ <= 0) return false;
  ring_first_ = ring_first;
  const int* Ap = A.outerIndexPtr();
  const int* Ai = A.innerIndexPtr();
  const int nnz = Ap[n_];
  col_of_.resize(nnz);
  dist_.resize(nnz);
  // Forward distance (row − column) mod n of each coupling. Opened at any ring, a coupling
  // that does not cross the opening keeps it as its distance below the diagonal (or n minus
  // it above); the band is the largest forward distance that is the shorter of the two.
  int b = 0;
  for (int c = 0; c < n_; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q) {
      const int d = ((Ai[q] - c) % n_ + n_) % n_;
      col_of_[q] = c;
      if (d == 0 || 2 * d <= n_) {  // d = n/2: lower, and rejected below as no band
        dist_[q] = d;
        b = std::max(b, d);
      } else {
        dist_[q] = -1;
      }
    }
  // A band of about half the matrix is no band (tiny grids), and a band wider than the sparse
  // factor's work (many nodes along z) is no gain: keep the sparse factor.
  if (4 * b >= n_) return false;
  if (static_cast<double>(n_) * b * (b + 1) / 2.0 > max_flops) return false;
  b_ = b;
  // b_ zero columns of padding: every column updates exactly b_ columns and rows.
  a_.assign(static_cast<std::size_t>(n_ + b_) * (b_ + 1), 0.0);
  coupled_.assign(n_, 0);
  ys_.assign(n_ + b_, 0.0);
  y4s_.assign(static_cast<std::size_t>(n_ + b_) * 4, 0.0);
  ckpt_.clear();  // allocated on the first factorisation that saves checkpoints
  ckpt_ok_ = false;
  usable_ = true;
  return true;
}

namespace {
#if defined(__GNUC__) && !defined(__clang__)
#define ROTORDYN_UNROLL _Pragma("GCC unroll 40")
#else
#define ROTORDYN_UNROLL
#endif

// Checkpoint of a right-looking factorisation before column c (c a multiple of the stride
// ks): columns c .. c+b-1 are the only ones that columns < c have updated, so with them the
// factorisation can be resumed at c (BandLDLT::refactorize_from). Saved at every ks-th
// column only (ks = kCheckpointRings·b): a copy of the whole band per factorisation cost
// about as much as a resumed iteration saved.
struct Checkpoints {
  double* ckpt;  // null: none saved
  int ks;        // stride (columns)
  int next;      // the next column to save before
  void at(const double* col, int c, int b) {
    if (ckpt && c == next) {
      const std::size_t w = static_cast<std::size_t>(b) + 1;
      std::memcpy(ckpt + static_cast<std::size_t>(c / ks) * b * w, col, sizeof(double) * b * w);
      next += ks;
    }
  }
};

// Right-looking LDLᵀ in the band of width b: B = b as a compile-time constant (the update
// loops unroll), or B = 0 for any b given at run time. Columns with no coupling below the
// diagonal (decoupled unknowns) are skipped. a has n + b columns of b + 1 values, the last b
// zero padding, so every column updates exactly b columns. False on a zero or non-finite pivot.
// From column c_start (the earlier columns and the state of c_start .. c_start+b-1 those of
// an earlier run); the checkpoints saved on the way (Checkpoints).
template <int B>
bool factor_band(double* a, int n, int b_run, char* coupled, int c_start, Checkpoints ck) {
  const int b = B > 0 ? B : b_run;
  const int w = b + 1;
  for (int c = c_start; c < n; ++c) {
    double* col = a + static_cast<std::size_t>(c) * w;
    ck.at(col, c, b);
    const double d = col[0];
    if (!(d != 0.0 && std::isfinite(d))) return false;
    bool nz = false;
    for (int t = 1; t <= b; ++t) nz |= col[t] != 0.0;
    coupled[c] = nz ? 1 : 0;
    if (!nz) continue;
    const double inv = 1.0 / d;
    // A(c+t2, c+t1) −= A(c+t2, c) A(c+t1, c) / d, then L(c+t, c) = A(c+t, c) / d.
ROTORDYN_UNROLL
    for (int t1 = 1; t1 <= b; ++t1) {
      const double g = col[t1] * inv;  // no branch on a zero multiplier (unrolled)
      double* tgt = a + static_cast<std::size_t>(c + t1) * w - t1;
ROTORDYN_UNROLL
      for (int t2 = t1; t2 <= b; ++t2) tgt[t2] -= g * col[t2];
    }
    for (int t = 1; t <= b; ++t) col[t] *= inv;
  }
  return true;
}

#if defined(__SSE2__)
// factor_band<B> with the updates two lanes at a time (SSE2, baseline x86-64): every entry
// gets the same multiply and subtract, in the same order, as in the scalar loop, so the factor
// is the same bit for bit. The pivot column is read once into registers in the pairs its
// column was last written in (offsets 0-1, 2-3, ...; store forwarding), the shifted pairs an
// odd t1 needs are shuffles of them; every target column is written in those same pairs.
template <int B>
bool factor_band_sse2(double* a, int n, char* coupled, int c_start, Checkpoints ck) {
  constexpr int w = B + 1;
  constexpr int P = B / 2 + 1;  // pairs covering offsets 0..B (the last a single when B even)
  const __m128d zero = _mm_setzero_pd();
  for (int c = c_start; c < n; ++c) {
    double* col = a + static_cast<std::size_t>(c) * w;
    ck.at(col, c, B);
    __m128d cp[P];
ROTORDYN_UNROLL
    for (int m = 0; m < P; ++m)
      cp[m] = (2 * m + 1 <= B) ? _mm_loadu_pd(col + 2 * m) : _mm_load_sd(col + 2 * m);
    const double d = _mm_cvtsd_f64(cp[0]);
    if (!(d != 0.0 && std::isfinite(d))) return false;
    // any nonzero below the diagonal (lane 0 of pair 0 is the diagonal)
    int nzmask = _mm_movemask_pd(_mm_cmpneq_pd(cp[0], zero)) & 2;
ROTORDYN_UNROLL
    for (int m = 1; m < P; ++m) nzmask |= _mm_movemask_pd(_mm_cmpneq_pd(cp[m], zero));
    coupled[c] = nzmask ? 1 : 0;
    if (!nzmask) continue;
    const double inv = 1.0 / d;
    auto at = [&](int t) {  // col[t] from the registers
      return (t % 2 == 0) ? _mm_cvtsd_f64(cp[t / 2])
                          : _mm_cvtsd_f64(_mm_unpackhi_pd(cp[t / 2], cp[t / 2]));
    };
    auto pair = [&](int t) {  // (col[t], col[t + 1]), t + 1 <= B
      return (t % 2 == 0) ? cp[t / 2] : _mm_shuffle_pd(cp[t / 2], cp[t / 2 + 1], 1);
    };
ROTORDYN_UNROLL
    for (int t1 = 1; t1 <= B; ++t1) {
      const double g = at(t1) * inv;
      const __m128d gv = _mm_set1_pd(g);
      double* tgt = a + static_cast<std::size_t>(c + t1) * w;  // offsets 0..B-t1
      int o = 0;
ROTORDYN_UNROLL
      for (; o + 1 <= B - t1; o += 2)
        _mm_storeu_pd(tgt + o, _mm_sub_pd(_mm_loadu_pd(tgt + o), _mm_mul_pd(gv, pair(t1 + o))));
      if (o == B - t1) tgt[o] -= g * at(t1 + o);
    }
    // L(c + t, c) = A(c + t, c) / d; the diagonal stays (1·d = d)
    cp[0] = _mm_mul_pd(cp[0], _mm_set_pd(inv, 1.0));
ROTORDYN_UNROLL
    for (int m = 1; m < P; ++m) cp[m] = _mm_mul_pd(cp[m], _mm_set1_pd(inv));
ROTORDYN_UNROLL
    for (int m = 0; m < P; ++m) {
      if (2 * m + 1 <= B)
        _mm_storeu_pd(col + 2 * m, cp[m]);
      else
        _mm_store_sd(col + 2 * m, cp[m]);
    }
  }
  return true;
}
#endif

// y = A⁻¹ y with the factor of factor_band<B> (same B / b_run convention).
template <int B>
void solve_band(const double* a, int n, int b_run, const char* coupled, double* y) {
  const int b = B > 0 ? B : b_run;
  const int w = b + 1;
  for (int c = 0; c < n; ++c) {
    const double yc = y[c];
    if (!coupled[c] || yc == 0.0) continue;
    const double* col = a + static_cast<std::size_t>(c) * w;
    for (int t = 1; t <= b; ++t) y[c + t] -= col[t] * yc;
  }
  for (int c = 0; c < n; ++c) y[c] /= a[static_cast<std::size_t>(c) * w];
  // Back substitution: the far terms first, the one that needs the unknown just found last,
  // so that a column waits for its predecessor by one multiply-subtract, not b of them.
  for (int c = n - 1; c >= 0; --c) {
    if (!coupled[c]) continue;
    const double* col = a + static_cast<std::size_t>(c) * w;
    double far = 0.0;
    for (int t = b; t >= 2; --t) far += col[t] * y[c + t];
    y[c] = (y[c] - far) - col[1] * y[c + 1];
  }
}

#if defined(__SSE2__)
// solve_band<B> with the forward updates two lanes at a time, in pairs of y at even indices
// (every step writes y in the same pairs: store forwarding), and the diagonal scaling of y[c]
// done as soon as it is final; every value gets the same operations in the same order as in
// solve_band<B> (the back substitution is that loop), so the solution is the same bit for bit.
template <int B, int kOdd>
inline void forward_step_sse2(const double* col, double* yp, double yc) {
  // yp = y + c + 1, odd absolute index when kOdd: y[c + t] -= col[t] yc, t = 1..B
  const __m128d yv = _mm_set1_pd(yc);
  int t = 1;
  if (kOdd) {
    yp[0] -= col[1] * yc;
    t = 2;
  }
ROTORDYN_UNROLL
  for (; t + 1 <= B; t += 2)
    _mm_storeu_pd(yp + t - 1, _mm_sub_pd(_mm_loadu_pd(yp + t - 1),
                                         _mm_mul_pd(_mm_loadu_pd(col + t), yv)));
  if (t == B) yp[t - 1] -= col[t] * yc;
}

template <int B>
void solve_band_sse2(const double* a, int n, const char* coupled, double* y) {
  constexpr int w = B + 1;
  for (int c = 0; c < n; ++c) {
    const double* col = a + static_cast<std::size_t>(c) * w;
    const double yc = y[c];
    if (coupled[c] && yc != 0.0) {
      if ((c + 1) & 1)
        forward_step_sse2<B, 1>(col, y + c + 1, yc);
      else
        forward_step_sse2<B, 0>(col, y + c + 1, yc);
    }
    y[c] = yc / col[0];
  }
  for (int c = n - 1; c >= 0; --c) {
    if (!coupled[c]) continue;
    const double* col = a + static_cast<std::size_t>(c) * w;
    double far = 0.0;
ROTORDYN_UNROLL
    for (int t = B; t >= 2; --t) far += col[t] * y[c + t];
    y[c] = (y[c] - far) - col[1] * y[c + 1];
  }
}

// Four right-hand sides at once, y4[c·4 + v] (v = 0..3): for each of them the operations of
// solve_band<B> in its order (a zero y[c] updates by ±0 instead of skipping: the same values),
// two lanes per instruction.
template <int B>
void solve_band4_sse2(const double* a, int n, const char* coupled, double* y4) {
  constexpr int w = B + 1;
  for (int c = 0; c < n; ++c) {
    const double* col = a + static_cast<std::size_t>(c) * w;
    double* yc = y4 + static_cast<std::size_t>(c) * 4;
    const __m128d y01 = _mm_loadu_pd(yc), y23 = _mm_loadu_pd(yc + 2);
    if (coupled[c]) {
ROTORDYN_UNROLL
      for (int t = 1; t <= B; ++t) {
        const __m128d l = _mm_set1_pd(col[t]);
        double* yt = yc + 4 * t;
        _mm_storeu_pd(yt, _mm_sub_pd(_mm_loadu_pd(yt), _mm_mul_pd(l, y01)));
        _mm_storeu_pd(yt + 2, _mm_sub_pd(_mm_loadu_pd(yt + 2), _mm_mul_pd(l, y23)));
      }
    }
    const __m128d d = _mm_set1_pd(col[0]);
    _mm_storeu_pd(yc, _mm_div_pd(y01, d));
    _mm_storeu_pd(yc + 2, _mm_div_pd(y23, d));
  }
  for (int c = n - 1; c >= 0; --c) {
    if (!coupled[c]) continue;
    const double* col = a + static_cast<std::size_t>(c) * w;
    double* yc = y4 + static_cast<std::size_t>(c) * 4;
    __m128d f01 = _mm_setzero_pd(), f23 = _mm_setzero_pd();
ROTORDYN_UNROLL
    for (int t = B; t >= 2; --t) {
      const __m128d l = _mm_set1_pd(col[t]);
      f01 = _mm_add_pd(f01, _mm_mul_pd(l, _mm_loadu_pd(yc + 4 * t)));
      f23 = _mm_add_pd(f23, _mm_mul_pd(l, _mm_loadu_pd(yc + 4 * t + 2)));
    }
    const __m128d l1 = _mm_set1_pd(col[1]);
    _mm_storeu_pd(yc, _mm_sub_pd(_mm_sub_pd(_mm_loadu_pd(yc), f01),
                                 _mm_mul_pd(l1, _mm_loadu_pd(yc + 4))));
    _mm_storeu_pd(yc + 2, _mm_sub_pd(_mm_sub_pd(_mm_loadu_pd(yc + 2), f23),
                                     _mm_mul_pd(l1, _mm_loadu_pd(yc + 6))));
  }
}
#endif

// The bandwidths of the grids met in practice (unknowns per ring of a half or full film)
// get unrolled kernels; others the generic loop.
#define ROTORDYN_BAND_CASES(X) \
  X(2) X(3) X(4) X(5) X(6) X(7) X(8) X(9) X(10) X(11) X(12) X(13) X(14) X(15) X(16) X(17) \
  X(18) X(19) X(20) X(21) X(22) X(23) X(24) X(25) X(31) X(32) X(33)
}  // namespace

bool BandLDLT::factorize(const double* values, int cut, bool reverse) {
  if (!usable_) return false;
  const int w = b_ + 1;
  begin(cut, reverse);
  const int nnz = static_cast<int>(dist_.size());
  for (int q = 0; q < nnz; ++q) {
    const double v = values[q];
    if (v == 0.0) continue;
    const int d = dist_[q];
    if (d < 0) continue;  // upper triangle (mirror of a stored lower entry)
    // the pair (column unknown, the one d after it): forward, the column unknown comes
    // first; reverse, the other one
    const int cf = opened(col_of_[q]);
    const int c = rev_ ? cf - d : cf;
    // A nonzero coupling across the opening.
    if (c < 0 || c + d >= n_) return false;
    a_[static_cast<std::size_t>(c) * w + d] = v;
  }
  return factorize_assembled();
}

void BandLDLT::begin(int cut, bool reverse) {
  ckpt_ok_ = false;
  rev_ = reverse;
  shift_ = reverse ? ring_first_[cut + 1] : ring_first_[cut];
  std::fill(a_.begin(), a_.end(), 0.0);
}

bool BandLDLT::factorize_assembled(bool checkpoints) { return factor_from(0, checkpoints); }

bool BandLDLT::refactorize_from(int c0, bool checkpoints) {
  const int ks = checkpoint_stride();
  // no saved state for c0: the band's columns before c0 hold the last factor, not A, so no
  // factorisation can start from it (the caller assembles the band again)
  if (!ckpt_ok_ || c0 < 0 || c0 % ks != 0 || c0 >= n_) return false;
  std::memcpy(a_.data() + static_cast<std::size_t>(c0) * (b_ + 1),
              ckpt_.data() + static_cast<std::size_t>(c0 / ks) * b_ * (b_ + 1),
              sizeof(double) * static_cast<std::size_t>(b_) * (b_ + 1));
  return factor_from(c0, checkpoints);
}

bool BandLDLT::factor_from(int c0, bool checkpoints) {
  ckpt_ok_ = false;
  if (!usable_) return false;
  const int ks = checkpoint_stride();
  Checkpoints ck{nullptr, ks, (c0 + ks - 1) / ks * ks};
  if (checkpoints) {
    ckpt_.resize(static_cast<std::size_t>((n_ + ks - 1) / ks) * b_ * (b_ + 1));
    ck.ckpt = ckpt_.data();
  }
  bool ok;
  switch (b_) {
#if defined(__SSE2__)
#define ROTORDYN_BAND_FACTOR(B) \
  case B:                      \
    ok = factor_band_sse2<B>(a_.data(), n_, coupled_.data(), c0, ck); \
    break;
#else
#define ROTORDYN_BAND_FACTOR(B) \
  case B:                      \
    ok = factor_band<B>(a_.data(), n_, B, coupled_.data(), c0, ck); \
    break;
#endif
    ROTORDYN_BAND_CASES(ROTORDYN_BAND_FACTOR)
#undef ROTORDYN_BAND_FACTOR
    default:
      ok = factor_band<0>(a_.data(), n_, b_, coupled_.data(), c0, ck);
  }
  ckpt_ok_ = ok && checkpoints;
  return ok;
}

void BandLDLT::solve(const double* bvec, double* x) const {
  double* y = ys_.data();
  // the padding receives 0·y updates: cleared, so a non-finite right-hand side cannot linger
  std::fill(ys_.begin() + n_, ys_.end(), 0.0);
  // y[opened(i)] = b[i]: two contiguous pieces (reversed in the reverse order)
  if (rev_) {
    std::reverse_copy(bvec, bvec + shift_, y);
    std::reverse_copy(bvec + shift_, bvec + n_, y + shift_);
  } else {
    std::copy(bvec + shift_, bvec + n_, y);
    std::copy(bvec, bvec + shift_, y + (n_ - shift_));
  }
  switch (b_) {
#if defined(__SSE2__)
#define ROTORDYN_BAND_SOLVE(B) \
  case B:                     \
    solve_band_sse2<B>(a_.data(), n_, coupled_.data(), y); \
    break;
#else
#define ROTORDYN_BAND_SOLVE(B) \
  case B:                     \
    solve_band<B>(a_.data(), n_, B, coupled_.data(), y); \
    break;
#endif
    ROTORDYN_BAND_CASES(ROTORDYN_BAND_SOLVE)
#undef ROTORDYN_BAND_SOLVE
    default:
      solve_band<0>(a_.data(), n_, b_, coupled_.data(), y);
  }
  if (rev_) {
    std::reverse_copy(y, y + shift_, x);
    std::reverse_copy(y + shift_, y + n_, x + shift_);
  } else {
    std::copy(y, y + (n_ - shift_), x + shift_);
    std::copy(y + (n_ - shift_), y + n_, x);
  }
}

void BandLDLT::solve4(double* const x[4]) const {
#if defined(__SSE2__)
  switch (b_) {
#define ROTORDYN_BAND_SOLVE4(B) case B:
    ROTORDYN_BAND_CASES(ROTORDYN_BAND_SOLVE4)
#undef ROTORDYN_BAND_SOLVE4
    {
      double* y4 = y4s_.data();
      std::fill(y4s_.begin() + static_cast<std::size_t>(n_) * 4, y4s_.end(), 0.0);
      for (int i = 0; i < n_; ++i) {  // y4[opened(i)·4 + v] = x_v[i]
        double* yc = y4 + static_cast<std::size_t>(opened(i)) * 4;
        for (int v = 0; v < 4; ++v) yc[v] = x[v][i];
      }
      switch (b_) {
#define ROTORDYN_BAND_SOLVE4(B) \
  case B:                      \
    solve_band4_sse2<B>(a_.data(), n_, coupled_.data(), y4); \
    break;
        ROTORDYN_BAND_CASES(ROTORDYN_BAND_SOLVE4)
#undef ROTORDYN_BAND_SOLVE4
      }
      for (int i = 0; i < n_; ++i) {
        const double* yc = y4 + static_cast<std::size_t>(opened(i)) * 4;
        for (int v = 0; v < 4; ++v) x[v][i] = yc[v];
      }
      return;
    }
    default:
      break;
  }
#endif
  for (int v = 0; v < 4; ++v) solve(x[v], x[v]);
}

}  // namespace rotordyn
