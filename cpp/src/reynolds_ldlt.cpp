// StaticLDLT: symbolic analysis once, lean numeric refactorisations (see reynolds_ldlt.hpp).
#include "reynolds_ldlt.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace rotordyn {

bool StaticLDLT::analyze(const SpMat& A, double max_bytes) {
  n_ = static_cast<int>(A.cols());
  {
    Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int>> amd;
    amd.analyzePattern(A);
    const auto& idx = amd.permutationP().indices();
    perm_.assign(idx.data(), idx.data() + idx.size());
    if (perm_.empty()) {
      perm_.resize(n_);
      for (int i = 0; i < n_; ++i) perm_[i] = i;
    }
  }
  // Permuted upper triangle: entry (r, c) of A goes to (perm r, perm c); keep row <= column.
  Up_.assign(n_ + 1, 0);
  const int* Ap = A.outerIndexPtr();
  const int* Ai = A.innerIndexPtr();
  for (int c = 0; c < n_; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q) {
      const int r2 = perm_[Ai[q]], c2 = perm_[c];
      if (r2 <= c2) ++Up_[c2 + 1];
    }
  for (int k = 0; k < n_; ++k) Up_[k + 1] += Up_[k];
  Ui_.resize(Up_[n_]);
  Usrc_.resize(Up_[n_]);
  {
    std::vector<int> next(Up_.begin(), Up_.end() - 1);
    for (int c = 0; c < n_; ++c)
      for (int q = Ap[c]; q < Ap[c + 1]; ++q) {
        const int r2 = perm_[Ai[q]], c2 = perm_[c];
        if (r2 > c2) continue;
        Ui_[next[c2]] = r2;
        Usrc_[next[c2]++] = q;
      }
  }
  // Permuted strict lower triangle by row: entry (r, c) with perm r > perm c goes to row perm r.
  Wp_.assign(n_ + 1, 0);
  for (int c = 0; c < n_; ++c)
    for (int q = Ap[c]; q < Ap[c + 1]; ++q)
      if (perm_[Ai[q]] > perm_[c]) ++Wp_[perm_[Ai[q]] + 1];
  for (int k = 0; k < n_; ++k) Wp_[k + 1] += Wp_[k];
  Wi_.resize(Wp_[n_]);
  Wsrc_.resize(Wp_[n_]);
  {
    std::vector<int> next(Wp_.begin(), Wp_.end() - 1);
    for (int c = 0; c < n_; ++c)
      for (int q = Ap[c]; q < Ap[c + 1]; ++q) {
        const int r2 = perm_[Ai[q]], c2 = perm_[c];
        if (r2 <= c2) continue;
        Wi_[next[r2]] = c2;
        Wsrc_[next[r2]++] = q;
      }
  }
  // Elimination tree and row patterns of L (row k: the etree paths from the entries of U(:,k)).
  std::vector<int> parent(n_, -1), flag(n_, -1), colcount(n_, 0);
  {
    // Counting pass (no storage): the size of L before anything of that size is allocated.
    std::vector<int> par(n_, -1), flg(n_, -1);
    double nnz = 0.0;
    for (int k = 0; k < n_; ++k) {
      flg[k] = k;
      for (int t = Up_[k]; t < Up_[k + 1]; ++t)
        for (int i = Ui_[t]; i < k && flg[i] != k; i = par[i]) {
          if (par[i] == -1) par[i] = k;
          flg[i] = k;
          ++colcount[i];
          nnz += 1.0;
        }
    }
    flops_ = 0.0;
    for (int i = 0; i < n_; ++i) flops_ += static_cast<double>(colcount[i]) * colcount[i];
    // Li, Rcol, Rslot (int) and Lx, Ux (double) per entry of L; D, y, w, ys, perm per row.
    bytes_needed_ = nnz * (3 * sizeof(int) + 2 * sizeof(double)) +
                    n_ * (4 * sizeof(double) + 2 * sizeof(int));
    if (bytes_needed_ > max_bytes) return false;
    std::fill(colcount.begin(), colcount.end(), 0);
  }
  Rp_.assign(n_ + 1, 0);
  Rcol_.clear();
  for (int k = 0; k < n_; ++k) {
    flag[k] = k;
    const std::size_t start = Rcol_.size();
    for (int t = Up_[k]; t < Up_[k + 1]; ++t) {
      for (int i = Ui_[t]; i < k && flag[i] != k; i = parent[i]) {
        if (parent[i] == -1) parent[i] = k;
        flag[i] = k;
        Rcol_.push_back(i);
        ++colcount[i];
      }
    }
    // Ascending column order is a topological order (etree children precede parents).
    std::sort(Rcol_.begin() + static_cast<long>(start), Rcol_.end());
    Rp_[k + 1] = static_cast<int>(Rcol_.size());
  }
  Lp_.assign(n_ + 1, 0);
  for (int i = 0; i < n_; ++i) Lp_[i + 1] = Lp_[i] + colcount[i];
  Li_.resize(Lp_[n_]);
  Rslot_.resize(Rcol_.size());
  std::vector<int> fill(n_, 0);
  for (int k = 0; k < n_; ++k)
    for (int t = Rp_[k]; t < Rp_[k + 1]; ++t) {
      const int i = Rcol_[t];
      const int slot = Lp_[i] + fill[i]++;
      Li_[slot] = k;
      Rslot_[t] = slot;
    }
  Lx_.assign(Lp_[n_], 0.0);
  D_.assign(n_, 0.0);
  y_.assign(n_, 0.0);
  ys_.assign(n_, 0.0);
  Ux_.assign(Lp_[n_], 0.0);
  w_.assign(n_, 0.0);
  return true;
}

// Up-looking LU: at step k, column k of U solves L y = A(0:k, k) and row k of L solves
// w U = A(k, 0:k), both over the elimination-tree row pattern of k (structural symmetry).
bool StaticLDLT::factorize_lu(const double* values) {
  double* y = y_.data();
  double* w = w_.data();
  for (int k = 0; k < n_; ++k) {
    for (int t = Up_[k]; t < Up_[k + 1]; ++t) y[Ui_[t]] += values[Usrc_[t]];
    for (int t = Wp_[k]; t < Wp_[k + 1]; ++t) w[Wi_[t]] += values[Wsrc_[t]];
    double d = y[k];
    y[k] = 0.0;
    for (int t = Rp_[k]; t < Rp_[k + 1]; ++t) {
      const int i = Rcol_[t];
      const int slot = Rslot_[t];
      const double u = y[i];  // U(i, k)
      const double l = w[i] / D_[i];  // L(k, i)
      y[i] = 0.0;
      w[i] = 0.0;
      if (u != 0.0)
        for (int p = Lp_[i]; p < slot; ++p) y[Li_[p]] -= Lx_[p] * u;
      if (l != 0.0)
        for (int p = Lp_[i]; p < slot; ++p) w[Li_[p]] -= Ux_[p] * l;
      Lx_[slot] = l;
      Ux_[slot] = u;
      d -= l * u;
    }
    if (!(d != 0.0 && std::isfinite(d))) {
      std::fill(y_.begin(), y_.end(), 0.0);
      std::fill(w_.begin(), w_.end(), 0.0);
      return false;
    }
    D_[k] = d;  // U(k, k)
  }
  return true;
}

double* StaticLDLT::forward(const double* b) const {
  double* y = ys_.data();
  for (int i = 0; i < n_; ++i) y[perm_[i]] = b[i];
  for (int j = 0; j < n_; ++j) {
    const double yj = y[j];
    if (yj != 0.0)
      for (int p = Lp_[j]; p < Lp_[j + 1]; ++p) y[Li_[p]] -= Lx_[p] * yj;
  }
  return y;
}

void StaticLDLT::solve_lu(const double* b, double* x) const {
  double* y = forward(b);
  for (int j = n_ - 1; j >= 0; --j) {
    double s = y[j];
    for (int p = Lp_[j]; p < Lp_[j + 1]; ++p) s -= Ux_[p] * y[Li_[p]];
    y[j] = s / D_[j];
  }
  for (int i = 0; i < n_; ++i) x[i] = y[perm_[i]];
}

bool StaticLDLT::factorize(const double* values) {
  double* y = y_.data();
  for (int k = 0; k < n_; ++k) {
    for (int t = Up_[k]; t < Up_[k + 1]; ++t) y[Ui_[t]] += values[Usrc_[t]];
    double d = y[k];
    y[k] = 0.0;
    for (int t = Rp_[k]; t < Rp_[k + 1]; ++t) {
      const int i = Rcol_[t];
      const int slot = Rslot_[t];
      const double yi = y[i];
      y[i] = 0.0;
      if (yi == 0.0) {
        Lx_[slot] = 0.0;
        continue;
      }
      for (int p = Lp_[i]; p < slot; ++p) y[Li_[p]] -= Lx_[p] * yi;
      const double l = yi / D_[i];
      Lx_[slot] = l;
      d -= l * yi;
    }
    if (!(d != 0.0 && std::isfinite(d))) {
      std::fill(y_.begin(), y_.end(), 0.0);
      return false;
    }
    D_[k] = d;
  }
  return true;
}

void StaticLDLT::solve(const double* b, double* x) const {
  double* y = forward(b);
  for (int j = 0; j < n_; ++j) y[j] /= D_[j];
  for (int j = n_ - 1; j >= 0; --j) {
    double s = y[j];
    for (int p = Lp_[j]; p < Lp_[j + 1]; ++p) s -= Lx_[p] * y[Li_[p]];
    y[j] = s;
  }
  for (int i = 0; i < n_; ++i) x[i] = y[perm_[i]];
}

}  // namespace rotordyn
