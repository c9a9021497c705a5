// Internal helpers of the modal solvers (not part of the public headers).
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <functional>
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

/// The factorisation of K alone (σ = 0) when it succeeds with a finite log-determinant (the
/// first thing modal_shift_invert tries), else false.
bool factor_at_zero(const SpMat& K, SpLU& lu);

/// The modal analysis behind rotordyn::modal: M, K dense; D dense made on demand (only the
/// dense path needs it); pre: the sparse pencil to use in place of one made from the dense
/// matrices (same numbers, so the same answer).
ModalResult modal_impl(const Eigen::MatrixXd& M,
                       const std::function<const Eigen::MatrixXd&()>& dense_D,
                       const Eigen::MatrixXd& K, const std::vector<std::pair<int, int>>& xy_pairs,
                       int n_modes, bool with_modes,
                       const std::vector<std::pair<int, int>>& rot_pairs, Eigen::VectorXd* start,
                       const SparsePencil* pre);

}  // namespace rotordyn::detail
