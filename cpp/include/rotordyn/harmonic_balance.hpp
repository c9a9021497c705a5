// Periodic orbits of the nonlinear system (paper eq. 12, every film by the Reynolds equation,
// sleeve and pad coordinates included) by harmonic balance with alternating frequency–time
// (AFT): the same system right-hand side as the transient and the shooting.
//
// Unknowns: the Fourier coefficients of the positions, r(τ) = c0 + Σ_{k=1..H} a_k cos kτ +
// b_k sin kτ (τ = ω (t − t0), ω = 2π/T), and for an autonomous cycle the frequency ω with the
// phase condition b_1 = 0 in one coordinate (the one with the largest first harmonic of the
// start). Residual: eq. 12 in second-order form,
//   R(τ_j) = ω² M r''(τ_j) + ω (C + ΩG) r'(τ_j) + K r(τ_j) − H(r, ω r', Ω) − F0 − f_u(t_j),
// at M ≥ 2H + 1 equally spaced samples τ_j (the film forces by Reynolds at each sample),
// projected back on the 2H + 1 harmonics (a DFT: Galerkin with the trapezoidal rule, exact
// for the linear terms). Newton matrix: the same projection of the time-domain linearisation
// K + K_H(τ_j), ω (C + ΩG + D_H(τ_j)), ω² M (the perturbation-method K_H, D_H of the films,
// the transient's Jacobian), the ω column exactly; damped (the step capped at 0.25 L per
// coefficient and 10 % in ω, halved while the residual's 2-norm does not fall).
#pragma once
#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

#include "rotordyn/hill.hpp"
#include "rotordyn/periodic.hpp"

namespace rotordyn {

/// How the Floquet multipliers of a harmonic-balance orbit are computed.
enum class HbFloquet {
  none,     ///< not computed (monodromy and multipliers empty)
  samples,  ///< Φ from the M linearisations of the converged orbit: A(τ) trigonometrically
            ///< interpolated, 4th-order Magnus (Gauss points) with exponentials, no film solve
  flow,     ///< one CVODES flow with forward sensitivities from the HB orbit's start (as the
            ///< shooting's final pass: error-controlled at sensitivity_rtol)
  hill      ///< Hill's method (hill.hpp) on the converged orbit's HB Jacobian: the eigenvalues
            ///< of the Hill matrix, one exponent per family; no film solve; the monodromy
            ///< reported is the one its exponents and eigenvectors give
};

struct HarmonicBalanceOptions {
  int harmonics = 8;           ///< H ≥ 1
  int time_points = 0;         ///< M ≥ 2H + 1; 0: 4H (at least 2H + 1)
  double tol = 1e-8;           ///< converged when ‖R̃‖∞ < tol (scaled residual, units of L)
  int max_iter = 40;           ///< Newton iterations
  double length_scale = 0.0;   ///< L, m; 0: the smallest film clearance (1e-3 m if no film)
  /// Autonomous: deflate the equilibria (m(z) R, m = ‖z_h‖⁻² + 1) so that Newton does not
  /// fall onto them from a start off the cycle.
  bool deflation = true;
  /// The films' cavitation-set continuation between consecutive samples (as in a transient).
  bool film_continuation = true;
  HbFloquet floquet = HbFloquet::samples;
  /// floquet = samples: > 0 refines the monodromy on the orbit itself (the films linearised
  /// between the samples, Simpson-node 4th-order Magnus, the steps doubled from M/2) until
  /// |μ_c| moves by ≤ floquet_tol·max(1, |μ_c|) between two levels (result: floquet_error,
  /// floquet_converged); 0: one product from the M samples, A(τ) trigonometrically
  /// interpolated (magnus_substeps per sample interval), no error estimate.
  double floquet_tol = 1e-3;
  /// floquet = samples, floquet_tol > 0: the most Magnus steps per period (each level doubles
  /// them and linearises the films at the new midpoints); 0: 128 M.
  int floquet_max_steps = 0;
  int magnus_substeps = 4;     ///< floquet = samples, floquet_tol = 0: steps per sample interval
  HillSelection hill_selection = HillSelection::centroid;  ///< floquet = hill: the rule
  /// floquet = hill: samples of the Jacobian of the Hill matrix; 0: max(M, 8H) — the Newton's
  /// own Jacobian when M ≥ 8H, else one more evaluation at the converged orbit on 8H samples
  /// (8H film linearisations; the AFT aliasing of the 4H default was the largest error of
  /// Hill's multipliers on the compressor's whip cycles: docs/nonlinear.md).
  int hill_time_points = 0;
  CvodeOptions cvode;          ///< the start flow (state start) and floquet = flow
  double sensitivity_rtol = 0; ///< floquet = flow; 0: cvode.rtol
};

struct HarmonicBalanceResult {
  /// The orbit as shooting reports it (samples over one period, start, period, monodromy,
  /// multipliers, status); `iterations` are Newton iterations, `residuals` the scaled
  /// ‖R̃‖∞ per iteration, `reynolds_solves` the film solves of the whole call.
  PeriodicOrbitResult orbit;
  /// (2H + 1, n): rows c0, a_1, b_1, a_2, b_2, …, m; r(t) = c0 + Σ a_k cos kω(t − t0) + …
  Eigen::MatrixXd coefficients;
  /// (H + 1,) max over the coordinates of |(a_k, b_k)| / L (k = 0: |c0| / L): the spectrum's
  /// decay, the truncation check.
  Eigen::VectorXd harmonic_amplitudes;
  int harmonics = 0, time_points = 0;
  double frequency = 0.0;      ///< ω = 2π/T, rad/s
  long linearizations = 0;     ///< film linearisations (one per sample per evaluation)
  long evaluations = 0;        ///< residual evaluations (M samples each)
  /// floquet = samples refined (floquet_tol > 0): | |μ_c| − |μ_c|_previous level | of the
  /// reported multipliers, for an autonomous cycle at least |μ_trivial − 1| (NaN otherwise),
  /// whether the move met floquet_tol within the budget (a stability verdict with | |μ_c| − 1 | ≤ floquet_error, or not converged, is unresolved),
  /// the Magnus steps per period, the levels, the film linearisations the refinement added
  /// (also counted in `linearizations`), the trivial multiplier's |μ − 1| and |μ_c| per level.
  double floquet_error = std::numeric_limits<double>::quiet_NaN();
  bool floquet_converged = false;
  int floquet_steps = 0, floquet_levels = 0;
  long floquet_linearizations = 0;
  double floquet_trivial_error = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> floquet_moduli;
};

/// Harmonic balance from a start given as position samples `start_samples` (M0, n) at
/// τ_j = 2πj/M0 (j = 0 … M0 − 1, over one period from in.t0; M0 ≥ 2H + 1), or — if empty —
/// from one flow of eq. 12 over in.period from (in.r0, in.v0) (no sensitivities). Forced:
/// T = in.period fixed; autonomous: in.period is the first guess. Failures (no convergence,
/// a film closing, the iteration falling onto an equilibrium) are a status with a message;
/// bad input (H < 1, M < 2H + 1, period ≤ 0, shapes, forcing inconsistent with the kind) an
/// InputError naming the field.
HarmonicBalanceResult harmonic_balance(SystemSolver& solver, const PeriodicInput& in,
                                       const Eigen::MatrixXd& start_samples,
                                       const HarmonicBalanceOptions& opt);

}  // namespace rotordyn
