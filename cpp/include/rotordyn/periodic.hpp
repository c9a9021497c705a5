// Periodic orbits of the nonlinear system (paper eq. 12, every film by the Reynolds equation,
// sleeve and pad coordinates included) by single shooting, and their Floquet multipliers.
//
// State x = (r, ṙ) (2n). The flow φ_T(x0) is eq. 12 integrated by CVODES (BDF, dense Newton
// with the analytic perturbation-method Jacobian, as the transient) from t0 to t0 + T; the
// monodromy matrix Φ = ∂φ_T/∂x0 comes from CVODES forward sensitivities in the same run
// (staggered corrector, sensitivity right-hand side Ṡ = A(x(t)) S with the same analytic
// Jacobian A, sensitivities inside the local error test).
//
//   forced (unbalance, period T = k·2π/Ω fixed):   R(x0) = φ_T(x0) − x0 = 0,
//                                                  Newton matrix Φ − I;
//   autonomous (no unbalance, T unknown):          R(x0, T) = φ_T(x0) − x0 = 0 and the phase
//                                                  condition f(x̂)ᵀ D⁻² (x0 − x̂) = 0 (x̂ the
//                                                  previous iterate: the new start lies on the
//                                                  hyperplane through x̂ normal to the flow),
//                                                  Newton matrix [Φ − I, f(φ_T); f(x̂)ᵀ D⁻², 0].
//
// The Newton iteration works in scaled coordinates (positions / L, velocities / (L ω), L the
// smallest film clearance, ω the larger of Ω and 2π/T), with the step capped at 0.25 L. Its
// matrix: Φ from one flow with sensitivities, then Broyden updates from flows without them
// (ShootingOptions::broyden); the converged orbit is integrated once more with the
// sensitivities in the error test for the reported monodromy.
#pragma once
#include <Eigen/Core>

#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "rotordyn/system.hpp"
#include "rotordyn/transient.hpp"

namespace rotordyn {

enum class OrbitKind { autonomous, forced };

struct PeriodicInput {
  OrbitKind kind = OrbitKind::autonomous;
  double omega = 0.0;             ///< rad/s, constant
  double chamber_pressure = 0.0;  ///< Pa, constant
  Eigen::VectorXd a;              ///< (n,) configuration
  Eigen::VectorXd unbalance_cos;  ///< (n,) u_c (forced orbits), may be empty (autonomous)
  Eigen::VectorXd unbalance_sin;  ///< (n,) u_s
  Eigen::VectorXd r0, v0;         ///< (n,) start: positions and velocities at t0
  double t0 = 0.0;                ///< s; the rotor angle is θ = Ω t (forced orbits)
  double period = 0.0;            ///< s; forced: the period; autonomous: the first guess
  int n_out = 201;                ///< samples of the converged orbit over [t0, t0 + T]
};

/// Where shooting's reported monodromy comes from (ShootingOptions::floquet).
enum class ShootingFloquet { flow, samples, none };

struct ShootingOptions {
  CvodeOptions cvode;          ///< rtol, atol_position, atol_velocity, max_steps, max_step
  double tol = 1e-7;           ///< converged when ‖D⁻¹(φ_T(x0) − x0)‖∞ < tol
  double length_scale = 0.0;   ///< L, m; 0: the smallest film clearance (1e-3 m if no film)
  int max_iter = 30;           ///< Newton iterations (each one period with sensitivities)
  /// Sensitivities in CVODES's local error test (CVodeSetSensErrCon) during the Newton
  /// iterations. Off: the steps are chosen for the orbit alone and the sensitivities follow
  /// them (staggered corrector) — a cheaper, less accurate Newton matrix. The converged
  /// orbit is always integrated once more with the sensitivities in the error test: the
  /// monodromy reported is error-controlled either way.
  bool sensitivity_error_control = false;
  /// Relative tolerance of the sensitivities in the error test (their absolute tolerances:
  /// this × atol_i / atol_j for ∂x_i/∂x0_j); 0: cvode.rtol.
  double sensitivity_rtol = 0.0;
  /// Newton matrix of the iterations before the final pass. true: the monodromy of one flow
  /// with sensitivities (outside the error test), then Broyden rank-one secant updates from
  /// flows without sensitivities (each as cheap as one transient period); refreshed by a flow
  /// with sensitivities when a step does not halve the residual. false: sensitivities in
  /// every iteration (Newton). The final pass is the same either way.
  bool broyden = false;
  /// The staggered sensitivity corrector of the flows with sensitivities. true (opt-in): all
  /// 2n monodromy columns in one blocked solve per iteration with the exact matrix I − γA
  /// (one LU per step attempt); false (default): CVODES's own corrector, one dense
  /// back-substitution per column with the state's lagged Newton matrix. Same error tests.
  bool blocked_sensitivities = false;
  /// Continuation only (continuation_step): ∂R/∂p from one more CVODES sensitivity column in
  /// the flows with sensitivities (ṡ_p = A s_p + ∂f/∂p, exact for p_c and a_y, where f is
  /// affine in p) instead of two flows at p ± h. The speed keeps the central difference.
  bool parameter_sensitivity = false;
  /// Continuation only: > 0 gives the final pass (sensitivities in the error test) first at
  /// this looser sensitivity tolerance; it is repeated at sensitivity_rtol only where the
  /// stability verdict is not safe at the screening tolerance: | |μ_c| − 1 | < screen_margin
  /// or |μ_trivial − 1| > screen_margin (a poor monodromy). 0: off. screen_margin 0: never
  /// repeated (every point keeps the screening tolerance; for measurements). A corrector
  /// starting from the previous point's matrix runs its first flow as the screened pass.
  double screen_rtol = 0.0;
  double screen_margin = 0.005;
  /// flow: the converged orbit
  /// integrated once more with the sensitivities in the error test (the monodromy to
  /// sensitivity_rtol). samples: no such pass; the monodromy by 4th-order Magnus on the
  /// converged orbit's film linearisations (its n_out − 1 samples, then refined on the
  /// orbit's trigonometric interpolant until |μ_c| moves by ≤ floquet_tol·max(1, |μ_c|), as
  /// harmonic balance's samples route): the exponentials take a flexible rotor's stiff
  /// bending modes exactly, where the error-controlled pass resolves them with nanosecond
  /// steps. none: no monodromy, no multipliers (the orbit only).
  /// The continuation (continuation.hpp) takes flow or samples; its samples route is
  /// harmonic balance's: the single product from the n_out − 1 samples, screened by
  /// floquet_margin, then refined (floquet_tol > 0; 0 allowed there: no refinement) or
  /// recomputed by the flow where the verdict is close.
  ShootingFloquet floquet = ShootingFloquet::flow;
  double floquet_tol = 1e-3;
  int floquet_max_steps = 0;  ///< samples: the most Magnus steps per period; 0: 128 (n_out − 1)
  /// Continuation with floquet = samples only: the screen's band about the unit circle
  /// (hb_detail::screen_close; 0: never rechecked)
  double floquet_margin = 0.01;
};

/// Floquet multipliers of a monodromy matrix and the type of the critical one.
struct Floquet {
  Eigen::VectorXcd multipliers;  ///< (2n,) sorted by modulus, largest first
  int trivial = -1;              ///< index of the trivial multiplier (autonomous), else −1
  double critical_modulus = 0.0; ///< largest modulus of the non-trivial multipliers
  int critical = -1;             ///< its index
  bool stable = false;           ///< critical_modulus < 1
  /// Type of the critical multiplier: "fold" (real > 0, crosses +1), "period_doubling"
  /// (real < 0, crosses −1), "neimark_sacker" (complex pair).
  std::string critical_type;
};

/// Eigenvalues of Φ and their classification; `autonomous`: the multiplier nearest 1 is the
/// trivial one (the flow direction) and is left out of the stability test.
Floquet floquet(const Eigen::MatrixXd& monodromy, bool autonomous);
/// The same classification of given multipliers (e.g. Hill's method: hill.hpp).
Floquet floquet_from_multipliers(const Eigen::VectorXcd& multipliers, bool autonomous);

struct PeriodicOrbitResult {
  Eigen::VectorXd r0, v0;          ///< (n,) converged start at t0
  double period = 0.0;             ///< s
  double t0 = 0.0;                 ///< s
  Eigen::VectorXd t;               ///< (n_out,) s, t0 … t0 + T
  Eigen::MatrixXd r, v;            ///< (n_out, n) the orbit
  Eigen::MatrixXd monodromy;       ///< (2n, 2n) ∂x(t0 + T)/∂x(t0) at the converged orbit
  Floquet floquet;
  double residual = 0.0;           ///< final ‖D⁻¹(φ_T(x0) − x0)‖∞
  /// ‖Δz_x‖∞ of the Newton step the final (error-controlled) monodromy gives at the converged
  /// start, scaled units (positions / L): the estimated distance to the exact orbit (the
  /// residual test allows up to tol / |1 − μ|); an autonomous orbit is refused when it
  /// exceeds a tenth of the orbit's extent. NaN when not computed.
  double newton_correction = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> residuals;   ///< per Newton iteration
  int iterations = 0;              ///< flows integrated (Newton iterations + 1)
  double length_scale = 0.0;       ///< L used in D, m
  std::string status = "ok";       ///< ok | not_converged | rub | error
  std::string message;
  long steps = 0, rhs_evals = 0, sens_rhs_evals = 0, jac_evals = 0, reynolds_solves = 0;
  long sensitivity_flows = 0;      ///< flows with sensitivities among the `iterations`
  /// BDF stability-limit order reductions over all flows (CVODES; 0 with the detection off):
  /// many of them mean lightly damped stiff modes hold BDF orders 3-5 at their stability
  /// limit (cvode.max_order = 2 steps over them).
  long order_reductions = 0;
  /// Dense back-substitutions of the sensitivity corrector over all flows: its iterations
  /// × the 2n columns (the monodromy's cost beyond the orbit's own steps).
  long sens_linear_solves = 0;
  /// LU factorisations of I − γA by the blocked sensitivity corrector (0 with
  /// ShootingOptions::blocked_sensitivities off: then sens_linear_solves are CVODES's).
  long sens_factorizations = 0;
  /// The sensitivity tolerance of the pass that gave the reported monodromy (the error test's
  /// relative tolerance: sensitivity_rtol, or screen_rtol for a screened continuation point).
  double monodromy_rtol = 0.0;
  /// ShootingFloquet::samples: | |μ_c| − |μ_c| of the previous level | (inf: one level only;
  /// autonomous: at least |μ_trivial − 1|), whether it met floquet_tol, the Magnus steps per
  /// period and the film linearisations of the product. NaN / false / 0 otherwise.
  double floquet_error = std::numeric_limits<double>::quiet_NaN();
  bool floquet_converged = false;
  int floquet_steps = 0;
  long floquet_linearizations = 0;
  /// The factor on cvode.rtol, atol_position and atol_velocity of the last flow: 1, or 0.1 /
  /// 0.01 once a full (uncapped) Newton step with fresh sensitivities lowered the residual by
  /// less than half, with ShootingFloquet samples or none (the residual's floor is then the
  /// flow's own error: the state's tolerances are tightened before the sensitivities go into
  /// the error test;
  /// docs/nonlinear.md, "The residual's floor"). The monodromy's sensitivity tolerance is
  /// not scaled.
  double flow_tol_factor = 1.0;
};

/// Shooting Newton from (r0, v0, period). A failure (no convergence, the journal reaching the
/// bush, CVODES giving up) is a status with a message; monodromy and multipliers are then
/// empty. InputError for shapes, non-finite values, period ≤ 0, unbalance in an autonomous
/// orbit, no unbalance in a forced one.
PeriodicOrbitResult periodic_orbit(SystemSolver& solver, const PeriodicInput& in,
                                   const ShootingOptions& opt);

/// One flow map with its monodromy: x(t0 + T) (2n) and Φ (2n × 2n) from x0 = (r0, v0); a
/// CVODES failure throws SundialsError. For tests and for the continuation built on top.
void flow_map(SystemSolver& solver, const PeriodicInput& in, const CvodeOptions& opt,
              Eigen::VectorXd& xT, Eigen::MatrixXd& monodromy);

}  // namespace rotordyn
