// Pseudo-arclength continuation of periodic orbits (paper eq. 12): one corrector step per
// call, the shooting Newton of periodic.hpp bordered by the parameter and the arclength
// condition. The branch loop (predictor, step-size control, bifurcation detection) drives it
// (python/rotordyn/analysis/continuation.py).
//
// Unknowns in scaled coordinates y = (x / D_x, T / D_T, p / D_p) (the period only for
// autonomous cycles; a forced orbit has T = k·2π/Ω). With a unit tangent t at the previous
// point y_prev and the arclength step ds the corrector solves
//
//   R(x, T, p) = φ_T(x; p) − x = 0                       (N)
//   f(x̂)ᵀ D_x⁻² (x − x̂) = 0                               (autonomous: phase condition)
//   tᵀ (y − y_prev) − ds = 0                              (pseudo-arclength)
//
// by Newton with the matrix [[Φ − I, D_T f(φ_T), ∂R/∂p]; [f(x̂)ᵀ, 0, 0]; tᵀ] (scaled):
// Φ from CVODES forward sensitivities, ∂R/∂p by a central finite difference of two flows
// without sensitivities at p ± h (h = fd_step · D_p); with ShootingOptions::broyden the
// iterations start from the previous point's matrix and update it by Broyden from flows
// without sensitivities, and only the converged point gets Φ (error-controlled) and ∂R/∂p.
// With ShootingOptions::floquet = samples the converged point's Φ (the tangent's) comes from
// the last flow with sensitivities outside the error test, and its multipliers from the films'
// linearisations at the orbit's samples, recomputed by the error-controlled flow only where
// the verdict is close (hb_detail::screen_close, the harmonic-balance corrector's screen).
// The new tangent is the null vector of the first N (+1) rows, oriented along the previous
// tangent.
#pragma once
#include <Eigen/Core>
#include <limits>
#include <string>

#include "rotordyn/periodic.hpp"

namespace rotordyn {

enum class ContinuationParameter { chamber_pressure, speed, config };

struct ContinuationInput {
  /// The orbit's fixed data (kind, a, unbalance, t0, n_out) and the predicted start
  /// (r0, v0, period); omega / chamber_pressure / a are overridden by the parameter.
  PeriodicInput base;
  ContinuationParameter parameter = ContinuationParameter::chamber_pressure;
  /// config: a(p) = base.a + p · config_direction (n,); base.a is the configuration at p = 0.
  Eigen::VectorXd config_direction;
  double p = 0.0;                  ///< predicted parameter: Pa, rad/s or m
  int subharmonic = 1;             ///< forced orbits: T = subharmonic · 2π / |Ω|
  Eigen::VectorXd scale;           ///< (2n + 2): D_x, D_T, D_p
  Eigen::VectorXd y_prev;          ///< (2n + 2) previous point (x, T, p), unscaled
  /// (2n + 2) unit tangent at y_prev in scaled coordinates; empty: no arclength condition,
  /// the parameter is held at p (the first point of a branch).
  Eigen::VectorXd tangent;
  double ds = 0.0;                 ///< scaled arclength from y_prev
  int direction = 1;               ///< first point: orient the new tangent to increase p (+1)
  double fd_step = 1e-4;           ///< h / D_p of the central difference ∂R/∂p
  /// (2n, U) the scaled rows R of the bordered matrix at the previous point
  /// (ContinuationStep::jacobian; U = 2n + 2 autonomous, 2n + 1 forced): with
  /// ShootingOptions::broyden the corrector starts from it without sensitivities and updates
  /// it by Broyden; empty: the first iteration integrates the sensitivities.
  Eigen::MatrixXd jacobian;
};

struct ContinuationStep {
  PeriodicOrbitResult orbit;       ///< the corrected orbit (status ok or a failure)
  double p = 0.0;                  ///< its parameter
  Eigen::VectorXd tangent;         ///< (2n + 2) unit tangent there (scaled), empty on failure
  long fd_flows = 0;               ///< flows without sensitivities for ∂R/∂p
  /// (2n, U) the scaled rows R of the bordered matrix at the corrected point (error-controlled
  /// Φ − I, D_T f(φ_T), ∂R/∂p): the next corrector's starting matrix. Empty on failure.
  Eigen::MatrixXd jacobian;
  /// Where the reported multipliers come from: "flow" (the final pass of ShootingOptions::
  /// floquet = flow, or the samples route's recheck), "samples" (the monodromy from the films'
  /// linearisations at the n_out − 1 samples of the converged flow) or "refined" (that product
  /// refined to floquet_tol); empty on failure.
  std::string floquet_route;
  /// floquet = samples: the samples' |μ_c| and |μ_trivial − 1| (autonomous; else 0), also where
  /// the flow replaced them; NaN otherwise.
  double screen_critical_modulus = std::numeric_limits<double>::quiet_NaN();
  double screen_trivial_error = std::numeric_limits<double>::quiet_NaN();
  /// Route "refined": the refined product's last change of |μ_c| (else NaN); its Magnus steps
  /// per period (0: not refined; > 0 with route "flow": refined, then left to the flow).
  double floquet_error = std::numeric_limits<double>::quiet_NaN();
  int floquet_steps = 0;
};

/// One pseudo-arclength corrector step. Failures are statuses of `orbit`; InputError for
/// shapes, a non-positive scale, fd_step ≤ 0.
ContinuationStep continuation_step(SystemSolver& solver, const ContinuationInput& in,
                                   const ShootingOptions& opt);

}  // namespace rotordyn
