// Sparse LDLᵀ with a static symbolic structure, for the Reynolds operator (private).
//
// analyze() runs AMD (Eigen) once, and precomputes the permuted upper pattern with the source
// position of every value, the elimination-tree row patterns of L and the storage slot of each
// L(k, i). factorize() is then the up-looking numeric LDLᵀ without any pattern work or matrix
// copy, and it skips zero multipliers, so unknowns decoupled by zeroing their couplings
// (cavitated nodes) cost almost nothing. About 1.5–2× Eigen's SimplicialLDLT::factorize on
// the 5-point grids used here.
#pragma once
#include <Eigen/SparseCore>

#include <vector>

namespace rotordyn {

class StaticLDLT {
 public:
  using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  /// A: structurally symmetric pattern (both triangles stored, compressed). Counts the fill
  /// of L first (O(n) memory); returns false without allocating the factor when it would
  /// need more than max_bytes (bytes_needed() then tells how much).
  bool analyze(const SpMat& A, double max_bytes = 1e300);
  /// Bytes of the factor's storage (values, indices, row patterns) as counted by analyze().
  double bytes_needed() const { return bytes_needed_; }
  /// Multiply-adds of one numeric factorisation (sum of squared column counts).
  double flops() const { return flops_; }
  /// Numeric factorisation from A's value array (same pattern as analysed). False if a pivot
  /// is zero or not finite.
  bool factorize(const double* values);
  /// x = A⁻¹ b (x may alias b).
  void solve(const double* b, double* x) const;
  /// LU without pivoting on the same (structurally symmetric) pattern, for a non-symmetric
  /// matrix whose columns are diagonally dominant (the jfo p–θ system): P A Pᵀ = L U with unit
  /// L. False if a pivot is zero or not finite (the caller then falls back to pivoting LU).
  bool factorize_lu(const double* values);
  /// x = A⁻¹ b with the factors of factorize_lu (x may alias b).
  void solve_lu(const double* b, double* x) const;
  int rows() const { return n_; }
  long nnz_l() const { return static_cast<long>(Li_.size()); }

 private:
  /// ys_ = P b, then the unit-lower forward substitution L y = P b in place (both solves).
  double* forward(const double* b) const;
  int n_ = 0;
  double bytes_needed_ = 0.0, flops_ = 0.0;
  std::vector<int> perm_;               // old index -> new index
  std::vector<int> Up_, Ui_, Usrc_;     // permuted upper triangle (with diagonal), by column
  std::vector<int> Wp_, Wi_, Wsrc_;     // permuted strict lower triangle, by row
  std::vector<int> Lp_, Li_;            // strictly lower L, column-compressed, static rows
  std::vector<int> Rp_, Rcol_, Rslot_;  // row k of L: columns (ascending) and value slots
  std::vector<double> Lx_, D_;
  std::vector<double> Ux_;              // LU: U(i, k) stored in the slot of L(k, i)
  std::vector<double> w_;               // LU: row workspace
  std::vector<double> y_;           // factorisation workspace, all zero between calls
  mutable std::vector<double> ys_;  // solve workspace
};

}  // namespace rotordyn
