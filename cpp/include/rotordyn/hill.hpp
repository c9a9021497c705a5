// Floquet exponents and multipliers of a linear time-periodic system by Hill's method: the
// eigenvalues of the Hill matrix (the linearised periodic system in Fourier coefficients) are
// the Floquet exponents λ plus i k ω; the rule below keeps one of each family.
//
// System: M x'' + D(τ) x' + G(τ) x = 0, τ = ω (t − t0), D and G 2π-periodic in τ (n × n), M
// constant and invertible. With x = e^{λ (t − t0)} p(τ), p(τ) = c0 + Σ_{k≤H} a_k cos kτ +
// b_k sin kτ (the harmonic-balance basis, coefficient rows c0, a_1, b_1, …):
//
//   λ² Δ2 z + λ Δ1 z + J z = 0,   J = P[G E + ω D E' + ω² M E''],   Δ1 = P[D E + 2 ω M E'],
//                                 Δ2 = I ⊗ M,
//
// P the projection on the 2H + 1 harmonics (DFT of M_s ≥ 2H + 1 samples, the AFT of the
// harmonic-balance code), E, E', E'' the basis and its τ-derivatives at the samples. J is the
// harmonic-balance Jacobian of eq. 12 at a converged orbit (D = C + ΩG + D_H(τ), G = K +
// K_H(τ)). The quadratic problem is solved as the companion matrix [[0, I]; [−Δ2⁻¹J, −Δ2⁻¹Δ1]]
// of size 2n(2H + 1) (LAPACK dgeev, eigenvectors included).
//
// Selection of the 2n exponents (one per family λ + i k ω):
//  * centroid (default; the "symmetry" criterion of Peletan et al., Nonlinear Dyn. 2013, and
//    the weighted mean of Guillot et al., J. Comput. Phys. 2020): the eigenvector of the copy
//    λ + i m ω is the one of λ shifted by m harmonics, and the truncation is most accurate for
//    the copy whose eigenvector sits on the central harmonics. κ = Σ k |c_k|² / Σ |c_k|² (c_k,
//    k = −H … H, the complex-exponential coefficients of the eigenvector's positions); the
//    eigenvalues are taken in the order of |κ|;
//  * imaginary (Lazarus & Thomas, C. R. Mécanique 2010): in the order of |Im λ| (the copies in
//    the fundamental strip |Im λ| ≤ ω/2). Cheaper to state, but a family whose frequency lies
//    beyond H ω has no accurate copy in the strip.
// Walking that order, an eigenvalue is skipped when it is a copy of one already kept: |λ −
// λ_a − i m ω| ≤ 0.01 ω for an integer m ≠ 0 and its centroid κ_a − m within 0.25 (the shifted
// eigenvector). So the two central copies of a real negative multiplier (λ = a ± i ω/2,
// conjugates of each other, κ = ±1/2) count once, and that multiplier is reported real, while
// two distinct families whose multipliers nearly coincide are both kept. The multipliers are
// e^{λ T}, T = 2π/ω.
#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

namespace rotordyn {

enum class HillSelection { centroid, imaginary };

struct HillResult {
  Eigen::VectorXcd exponents;     ///< (2n,) the kept eigenvalues λ, 1/s, in the walk's order
  Eigen::VectorXcd multipliers;   ///< (2n,) e^{λ T} (a self-conjugate family's made real)
  Eigen::VectorXd centroids;      ///< (2n,) κ of the kept eigenvalues' eigenvectors
  Eigen::VectorXcd eigenvalues;   ///< (2n(2H + 1),) every eigenvalue of the Hill matrix
  Eigen::VectorXd all_centroids;  ///< their κ
  /// (2n, 2n) Re(X0 e^{ΛT} X0⁻¹), X0 the kept Floquet solutions' states (x, x') at τ = 0: the
  /// monodromy matrix these exponents and eigenvectors give (ill-conditioned where two
  /// multipliers nearly coincide; (0, 0) where X0 is numerically singular, rcond ≤ 1e-13;
  /// the multipliers above do not depend on it).
  Eigen::MatrixXd monodromy;
  int harmonics = 0;
};

/// Hill's method for M x'' + D(τ) x' + G(τ) x = 0 given by samples G_j = G(τ_j), D_j = D(τ_j)
/// at τ_j = 2πj/M_s (M_s ≥ 2H + 1), fundamental ω (rad/s). InputError for shapes, non-finite
/// values, a singular mass, ω ≤ 0, H outside [1, 200] or a Hill matrix above 6000 rows.
HillResult hill_floquet(const Eigen::MatrixXd& mass, const std::vector<Eigen::MatrixXd>& stiffness,
                        const std::vector<Eigen::MatrixXd>& damping, double omega, int harmonics,
                        HillSelection selection = HillSelection::centroid);

/// The same from the harmonic-balance matrices: J and Δ1 ((2H + 1)n square, harmonic rows of n
/// coordinates each), M (n × n).
HillResult hill_from_matrices(const Eigen::MatrixXd& J, const Eigen::MatrixXd& delta1,
                              const Eigen::MatrixXd& mass, double omega, int harmonics,
                              HillSelection selection);

}  // namespace rotordyn
