// Steady harmonic response of M q̈ + D q̇ + K q = Re(F e^{iωt}) (paper §5, forced response to
// unbalance): (K − ω² M + iω D) X = F, with a sparse LU when the matrices are sparse (finite
// element rotors are banded; bearings and sleeves add a few off-band entries).
#pragma once
#include <Eigen/Core>

namespace rotordyn {

/// X (n, m) for the right-hand sides F (n, m) at the angular frequency omega (rad/s).
/// M, D, K: (n, n) real. Sparse LU (UMFPACK) when the pencil has few non-zeros, else dense
/// partial-pivot LU. InputError on shape mismatch, ConvergenceError if the dynamic stiffness
/// is singular (an undamped resonance hit exactly).
Eigen::MatrixXcd harmonic_response(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                   const Eigen::MatrixXd& K, double omega,
                                   const Eigen::MatrixXcd& F);

}  // namespace rotordyn
