// Private state of ReynoldsSolver (shared by the reynolds_*.cpp translation units).
#pragma once
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <vector>

#include "rotordyn/reynolds.hpp"

namespace rotordyn {

/// Eigen's up-looking LDLT, refactorised on a sub-pattern of the analysed one. The numeric
/// phase derives each row's pattern from the entries it is given (walking the elimination tree
/// of the analysed pattern), so dropping zero couplings is valid and skips their work; the
/// column slots it leaves unwritten would keep stale values from an earlier factorisation, so
/// they are cleared (row index = column, value 0: ignored by the triangular solves).
class SubPatternLDLT
    : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double, Eigen::ColMajor, int>, Eigen::Lower,
                                   Eigen::AMDOrdering<int>> {
 public:
  void factorize_subpattern(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& a) {
    factorize(a);
    const int n = static_cast<int>(m_matrix.cols());
    const int* Lp = m_matrix.outerIndexPtr();
    int* Li = m_matrix.innerIndexPtr();
    double* Lx = m_matrix.valuePtr();
    for (int i = 0; i < n; ++i)
      for (int q = Lp[i] + m_nonZerosPerCol[i]; q < Lp[i + 1]; ++q) {
        Li[q] = i;
        Lx[q] = 0.0;
      }
  }
};

struct ReynoldsSolver::Impl {
  using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  JournalBearingGeometry geo;
  FilmGrid grid;
  Cavitation cav;

  int N = 0;        // nodes around
  int K1 = 0;       // node rows along (n_axial + 1)
  int n_nodes = 0;  // N * K1, node n = j * K1 + k
  int n_unk = 0;
  double R = 0, L = 0, c = 0, mu = 0, dphi = 0, dz = 0;
  std::vector<double> cosphi, sinphi;
  std::vector<int> unk;          // node -> unknown index, -1 for a prescribed-pressure node
  std::vector<int> node_of;      // unknown -> node
  std::vector<double> p_fixed;   // node -> prescribed pressure (0 if unknown)
  std::vector<char> groove;      // node -> 1 on a groove (interior rows)

  // Sparse pattern: full symmetric 5-point stencil over the unknowns (explicit zeros kept).
  SpMat A;
  SpMat Ap;  // A without the zero couplings of decoupled unknowns (sub-pattern, cheaper LDLT)
  struct ColPos {
    int diag, e, w, n, s;  // value positions of (i,i), (E,i), (W,i), (N,i), (S,i); -1: none
  };
  std::vector<ColPos> pos;
  SubPatternLDLT ldlt;
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;
  bool lu_analysed = false;

  // Film of the current solve (node arrays).
  double omega = 0.0;
  std::vector<double> h, hdot;
  std::vector<double> cE, cN;  // conductances of faces (j+1/2, k) and (j, k+1/2)
  std::vector<double> qE;      // Couette coefficient (ωRΔz/2)·h of face (j+1/2, k)
  std::vector<double> src;     // RΔφΔz ∂h/∂t

  // Solution state.
  std::vector<double> p;       // node pressures (the model's answer)
  std::vector<double> pfull;   // unclipped linear solution (none/gumbel)
  std::vector<double> theta;   // node fill fraction
  std::vector<char> active;    // unknown: 1 = p held at 0 (reynolds) / cavitated (jfo)
  bool have_active = false;
  bool solved = false;
  enum class Factor { none, ldlt, lu } factor = Factor::none;
  Eigen::VectorXd rhs, sol;
  FilmSolution out;

  Impl(const JournalBearingGeometry& g, const FilmGrid& gr, Cavitation cv);

  int east(int n) const { return n + K1 >= n_nodes ? n + K1 - n_nodes : n + K1; }
  int west(int n) const { return n - K1 < 0 ? n - K1 + n_nodes : n - K1; }

  void set_film(const double* h_in, const double* hdot_in, double omega_in);
  // Right-hand side b of A p = b (Couette, squeeze, prescribed neighbours), unknown ordering.
  void base_rhs(Eigen::VectorXd& b) const;
  // A's values; mask (unknown-indexed, may be null) decouples masked unknowns (identity rows).
  void fill_spd(const std::vector<char>* mask);
  void factor_spd(bool prune = false);
  // Residual (outflow + storage) of node n's cell for node pressures pp and fill theta.
  double cell_residual(int n, const std::vector<double>& pp) const;

  void solve_linear();    // none / gumbel
  void solve_reynolds();  // Swift–Stieber LCP by primal–dual active set
  void solve_jfo();       // Elrod–Adams p–θ
  void fill_jfo();
  void postprocess();

  // d(residual)/d(h, hdot) at the frozen state, unknown ordering.
  void residual_derivative(const double* dh, const double* dhdot, Eigen::VectorXd& out) const;
};

}  // namespace rotordyn
