// Pseudo-arclength continuation of periodic orbits (paper eq. 12) by harmonic balance: one
// corrector step per call on the harmonic-balance unknowns, bordered by the parameter and the
// arclength condition. The branch loop (predictor, step control, bifurcations) drives it
// (python/rotordyn/analysis/hb_continuation.py); the shooting corrector is continuation.hpp.
//
// Unknowns in scaled coordinates u = (z / L, ω / D_ω, p / D_p): z the Fourier coefficients of
// the positions (harmonic_balance.hpp: rows c0, a_1, b_1, …, a_H, b_H of every coordinate,
// flattened row by row), ω = 2π/T (an unknown for autonomous cycles only; a forced orbit has
// ω = |Ω|/k and follows a speed parameter), p the parameter. With a unit tangent t at the
// previous point u_prev and the arclength step ds the corrector solves
//
//   R̃(z, ω, p) = 0                              the AFT residual of eq. 12, scaled (units of L)
//   φᵀ z = 0                                    (autonomous) the integral phase condition
//                                               ∫ r(τ)·r'_prev(τ) dτ = 0 against the previous
//                                               point: Σ_k k (a_k·b_k,prev − b_k·a_k,prev)
//   tᵀ (u − u_prev) − ds = 0                    pseudo-arclength (first point: p held)
//
// by damped Newton with the matrix [[∂R̃/∂z, ∂R̃/∂ω, ∂R̃/∂p]; [φᵀ, 0, 0]; tᵀ]: ∂R̃/∂z and ∂R̃/∂ω
// the harmonic-balance Jacobian (the films' perturbation-method K_H, D_H at the samples, the
// code of harmonic_balance.cpp), ∂R̃/∂p exact where eq. 12 is affine in p (p_c: −c_s, a_y:
// K·∂a/∂a_y, both in the constant harmonic only) and a central difference of two residual
// evaluations at p ± h for the speed (M, G, the films and a forced period depend on Ω) and for
// a parameter the caller varies (the systems at p ± h from its provider: a model field). The
// new tangent is the null vector of the first rows, oriented along the previous tangent.
// Floquet multipliers from the samples' linearisations or by Hill's method on the converged
// Jacobian (no film solve), recomputed by one CVODES sensitivity flow where the verdict is not
// safe from them.
#pragma once
#include <Eigen/Core>

#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "rotordyn/continuation.hpp"
#include "rotordyn/harmonic_balance.hpp"

namespace rotordyn {

struct HbContinuationInput {
  /// The orbit's fixed data (kind, a, unbalance, t0, n_out); omega / chamber_pressure / a are
  /// overridden by the parameter; r0, v0 and period are not used.
  PeriodicInput base;
  ContinuationParameter parameter = ContinuationParameter::chamber_pressure;
  /// config: a(p) = base.a + p · config_direction (n,); base.a is the configuration at p = 0.
  Eigen::VectorXd config_direction;
  int subharmonic = 1;             ///< forced orbits: T = subharmonic · 2π / |Ω|
  Eigen::MatrixXd coefficients;    ///< (2H + 1, n) predicted coefficients, m
  double frequency = 0.0;          ///< predicted ω, rad/s (autonomous; forced: from p)
  double p = 0.0;                  ///< predicted parameter: Pa, rad/s or m
  Eigen::VectorXd scale;           ///< (3): L (coefficients, m), D_ω (rad/s), D_p
  /// ((2H + 1) n + 2) the previous point (coefficients row by row, ω, p), unscaled
  Eigen::VectorXd y_prev;
  /// ((2H + 1) n + 2) unit tangent at y_prev in scaled coordinates; empty: no arclength
  /// condition, the parameter is held at p (the first point of a branch)
  Eigen::VectorXd tangent;
  double ds = 0.0;                 ///< scaled arclength from y_prev
  int direction = 1;               ///< first point: orient the new tangent to increase p (+1)
  double fd_step = 1e-4;           ///< h / D_p of the central difference ∂R/∂p (speed)
};

struct HbContinuationOptions {
  /// harmonics, time_points, tol (scaled residual), max_iter, film_continuation, floquet,
  /// magnus_substeps, cvode and sensitivity_rtol (the flows of the Floquet recheck); the length
  /// scale is scale(0) and there is no deflation (the arclength row keeps the corrector off
  /// the equilibria).
  HarmonicBalanceOptions hb;
  /// floquet = samples or hill: the multipliers are recomputed by one CVODES sensitivity flow
  /// (at sensitivity_rtol) where | |μ_c| − 1 | < floquet_margin or |μ_trivial − 1| >
  /// floquet_margin / 2 (a poor screen: the samples' |μ_c| error was measured up to about
  /// 1.5 × their trivial multiplier's); 0: never.
  double floquet_margin = 0.01;
};

struct HbContinuationStep {
  /// The corrected orbit (orbit: samples, multipliers, status; coefficients, frequency,
  /// counters of the call).
  HarmonicBalanceResult hb;
  double p = 0.0;                  ///< its parameter
  /// ((2H + 1) n + 2) unit tangent there (scaled), empty on failure
  Eigen::VectorXd tangent;
  /// Where the reported multipliers come from: "samples", "refined" (the samples' product
  /// refined to hb.floquet_tol), "hill", "flow" (the recheck, or floquet = flow) or "none";
  /// empty on failure.
  std::string floquet_route;
  /// From the screening route (the samples' monodromy, or Hill's method with floquet = hill;
  /// also where the flow replaced it, and with floquet = flow the samples'): |μ_c| and
  /// |μ_trivial − 1| (autonomous; else 0); NaN when not computed.
  double screen_critical_modulus = 0.0, screen_trivial_error = 0.0;
  long fd_evaluations = 0;         ///< residual evaluations for the central difference ∂R/∂p
  /// hb.floquet_tol > 0 and a close screen: the refined product's | |μ_c| − |μ_c|_previous
  /// level | where it decided (route "refined"; else NaN) and its Magnus steps per period
  /// (0: not refined; > 0 with another route: it was refined, then left to the flow)
  double floquet_error = std::numeric_limits<double>::quiet_NaN();
  int floquet_steps = 0;
};

/// One pseudo-arclength corrector step by harmonic balance over p_c, Ω or a_y (the
/// parameter varies the operating point of `solver`'s model). Failures are statuses of
/// hb.orbit (not_converged, rub, error, with a message); InputError for shapes, a
/// non-positive scale, fd_step outside (0, 1), harmonics / time points out of range.
HbContinuationStep hb_continuation_step(SystemSolver& solver, const HbContinuationInput& in,
                                        const HbContinuationOptions& opt);

/// The system of a branch at one value of a parameter the caller varies (a model field: a
/// clearance, a viscosity, a support stiffness, for which the caller re-assembles the model):
/// its solver and orbit input there (kind, Ω, p_c, a, unbalance, t0, n_out; a forced orbit's
/// period; r0 and v0 are not used), or the model's refusal of the value.
struct HbSystemAt {
  std::shared_ptr<SystemSolver> solver;  ///< null: the value is refused
  PeriodicInput input;
  std::string refused;                   ///< why the model refuses the value (solver null)
};
/// p ↦ the system at p. Called at every value the corrector visits (the iterates, the line
/// search's trials, p ± h of the central difference ∂R/∂p); a refused value is an evaluation
/// that failed there, with the refusal as its message.
using HbSystemProvider = std::function<HbSystemAt(double p)>;

/// The same corrector step over a parameter the caller varies: the systems come from
/// `system_at`, ∂R/∂p is the central difference of two residual evaluations on the systems at
/// p ± h (h = fd_step · D_p), and in.base, parameter, config_direction and subharmonic are not
/// used. InputError as above, and for a system whose coordinates differ from the
/// coefficients' columns.
HbContinuationStep hb_continuation_step(const HbSystemProvider& system_at,
                                        const HbContinuationInput& in,
                                        const HbContinuationOptions& opt);

}  // namespace rotordyn
