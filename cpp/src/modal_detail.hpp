// Internal helpers of the modal solvers (not part of the public headers).
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <complex>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

#include "rotordyn/modal.hpp"

namespace rotordyn::detail {

using SpMat = Eigen::SparseMatrix<double>;
using SpLU = Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>>;

/// The sparse quadratic pencil of one problem M q̈ + D q̇ + K q = 0. lu0: a factorisation of
/// K (the shift σ = 0) that succeeded with a finite log-determinant, to reuse, or null (the
/// solver then factorises P(σ) itself, exactly as it would have without one).
struct SparsePencil {
  const SpMat* M = nullptr;
  const SpMat* D = nullptr;
  const SpMat* K = nullptr;
  double scale = 1.0;  ///< √(max |K_ii| / max |M_ii|): the model's frequency scale (1/s)
  const SpLU* lu0 = nullptr;
};

/// Lowest |λ| eigenpairs of M q̈ + D q̇ + K q = 0 by shift-invert Arnoldi (sparse LU).
/// Returns false if it did not converge (callers fall back to the dense solver).
/// start (optional, (2n,)): the Krylov start vector on input if non-empty; on output the sum
/// of the converged wanted Ritz vectors, the start for a nearby problem (the next speed).
bool modal_shift_invert(const SparsePencil& p, int n_modes, Eigen::VectorXcd& lambda,
                        Eigen::MatrixXcd& shapes, Eigen::VectorXd* start = nullptr);
bool modal_shift_invert(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                        const Eigen::MatrixXd& K, int n_modes, Eigen::VectorXcd& lambda,
                        Eigen::MatrixXcd& shapes, Eigen::VectorXd* start = nullptr);

/// The factorisation of K alone (σ = 0) when it succeeds with a finite log-determinant and K
/// has no rigid-body motion (the first thing modal_shift_invert tries), else false.
bool factor_at_zero(const SpMat& K, const SpMat& M, SpLU& lu);

/// The rigid-body motions of M q̈ + D q̇ + K q = 0: the null space of K found from the rank of
/// the Jacobi-scaled stiffness J⁻¹ K J⁻¹ (J = diag √|K_ii|), so the verdict does not depend on
/// the units of the coordinates. phi: (n, d), d = 0 when K is regular. omega_max (when d > 0):
/// √‖L⁻¹ K L⁻ᵀ‖₂ (L Lᵀ = M), the
/// model's highest undamped frequency (1/s), the scale of the eigensolver's rounding.
struct RigidBody {
  Eigen::MatrixXd phi;
  double omega_max = 0.0;
};
RigidBody rigid_body(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K);

/// √max_i (K_ii / M_ii) (1/s): a Rayleigh quotient of the undamped pencil, so at most its
/// highest frequency, in any units; O(n), to decide whether rigid_body is worth its O(n³).
double frequency_reference(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K);

/// 10 √ε ω: the largest |λ| to which rounding spreads a defective zero root of a model whose
/// highest frequency is ω (dense solver; the shift-invert path spreads them far less).
double rigid_root_bound(double omega);

/// The one rule of both modal paths: marks (1) the roots of w that are the pencil's zero
/// roots, spread by rounding. The rigid-body subspace has 2d roots: the regular ones μ (the
/// eigenvalues of −M_r⁻¹D_r above 2 √ε ω_max, M_r = ΦᵀMΦ, D_r = ΦᵀDΦ), the rest zero. Every
/// root of w below rigid_root_bound(max(ω_max, max |w|)) is marked but the nearest to each μ,
/// if within 10 % of it, which takes the value μ (more accurate there than the solver's). None
/// when d = 0 (w untouched).
std::vector<char> rigid_roots(const RigidBody& rb, const Eigen::MatrixXd& M,
                              const Eigen::MatrixXd& D, Eigen::VectorXcd& w);

/// Whether the pencil is conservative gyroscopic: M and K symmetric and D skew-symmetric,
/// exactly (no damping, no cross-coupled stiffness: a free rotor or one on linear springs).
bool conservative_gyroscopic(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                             const Eigen::MatrixXd& K);

/// The root near `lam` of the conservative pencil's structured Rayleigh quotient
/// m λ² + i g λ + k = 0 of the displacement vector x (m = x^H M x, k = x^H K x real,
/// x^H D x = i g, each formed from the real and imaginary parts so that the structure is
/// exact): purely imaginary when g² + 4 m k ≥ 0 (K ≥ 0 along x), and stationary in x (P(iν)
/// is Hermitian), so second-order accurate. `lam` itself when the quotient's root is more
/// than 1e-3 |lam| away (x not that root's vector) or x is degenerate.
std::complex<double> conservative_root(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                       const Eigen::MatrixXd& K, const Eigen::VectorXcd& x,
                                       std::complex<double> lam);

/// rigid_body(M, K) made once on first use and then shared (by the speeds of a Campbell
/// diagram, the threads that run them, the calls on one ModalOperator).
class RigidBodyCache {
 public:
  const RigidBody& get(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) const {
    std::call_once(once_, [&] { value_ = rigid_body(M, K); });
    return value_;
  }

 private:
  mutable std::once_flag once_;
  mutable RigidBody value_;
};

/// The modal analysis behind rotordyn::modal: M, K dense; D dense made on demand (only the
/// dense path needs it); pre: the sparse pencil to use in place of one made from the dense
/// matrices (same numbers, so the same answer); rigid: K's rigid-body motions kept between
/// calls, or null (found here if needed).
ModalResult modal_impl(const Eigen::MatrixXd& M,
                       const std::function<const Eigen::MatrixXd&()>& dense_D,
                       const Eigen::MatrixXd& K, const std::vector<std::pair<int, int>>& xy_pairs,
                       int n_modes, bool with_modes,
                       const std::vector<std::pair<int, int>>& rot_pairs, Eigen::VectorXd* start,
                       const SparsePencil* pre, const RigidBodyCache* rigid = nullptr);

}  // namespace rotordyn::detail
