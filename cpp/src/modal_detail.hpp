// Internal helpers of the modal solvers (not part of the public headers).
#pragma once
#include <Eigen/Core>

namespace rotordyn::detail {
/// Lowest |λ| eigenpairs of M q̈ + D q̇ + K q = 0 by shift-invert Arnoldi (sparse LU).
/// Returns false if it did not converge (callers fall back to the dense solver).
bool modal_shift_invert(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                        const Eigen::MatrixXd& K, int n_modes, Eigen::VectorXcd& lambda,
                        Eigen::MatrixXcd& shapes);
}  // namespace rotordyn::detail
