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

/// The response of a speed-independent model M, C, G, K (D = C + ω G: a rotor on linear
/// supports, the unbalance turning with it) at every angular frequency omegas (n_freq,) rad/s
/// to the forcing ω² F (F: (n,) complex, per ω²), seen through the outputs O (r, n):
/// Y (n_freq, r) = O X(ω). One symbolic analysis of the pencil's pattern (the union of
/// M, C, G, K), then one numeric LU and solve per frequency: each frequency's numbers are those
/// harmonic_response(M, C + ω G, K, ω, ω² F) factorises. Errors as harmonic_response.
Eigen::MatrixXcd harmonic_sweep(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                const Eigen::MatrixXd& G, const Eigen::MatrixXd& K,
                                const Eigen::VectorXd& omegas, const Eigen::VectorXcd& F,
                                const Eigen::MatrixXd& O);

}  // namespace rotordyn
