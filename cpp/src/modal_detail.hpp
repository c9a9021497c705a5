// Internal helpers of the modal solvers (not part of the public headers).
#pragma once
#include <Eigen/Core>

namespace rotordyn::detail {
/// Lowest |λ| eigenpairs of M q̈ + D q̇ + K q = 0 by shift-invert Arnoldi (sparse LU).
/// Returns false if it did not converge (callers fall back to the dense solver).
/// start (optional, (2n,)): the Krylov start vector on input if non-empty; on output the sum
/// of the converged wanted Ritz vectors, the start for a nearby problem (the next speed).
bool modal_shift_invert(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                        const Eigen::MatrixXd& K, int n_modes, Eigen::VectorXcd& lambda,
                        Eigen::MatrixXcd& shapes, Eigen::VectorXd* start = nullptr);

}  // namespace rotordyn::detail
