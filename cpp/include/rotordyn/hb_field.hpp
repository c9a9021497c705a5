// The harmonic-balance system of eq. 12 on one assembled model at a fixed operating point, for
// the correctors of a branch whose parameter the core cannot vary: a model field (a clearance,
// a viscosity, a support stiffness, a disk mass), which the caller re-assembles at every value
// (python/rotordyn/analysis/hb_field.py runs the bordered Newton and the branch around these
// calls; the corrector over p_c, Ω or a_y, which the core varies itself, is
// hb_continuation.hpp). Each call is one whole unit of work: one AFT evaluation of the residual
// (M film solves), with its Jacobian (M film linearisations), or the samples and Floquet
// multipliers of a converged orbit.
#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

#include "rotordyn/harmonic_balance.hpp"
#include "rotordyn/hb_continuation.hpp"

namespace rotordyn {

struct HbEvaluation {
  Eigen::MatrixXd coefficients;  ///< (2H + 1, n) where evaluated (rows c0, a_1, b_1, …), m
  double frequency = 0.0;        ///< ω where evaluated, rad/s
  /// ((2H + 1) n) R̂: eq. 12's residual at the M samples projected on the harmonics, block
  /// by block (block p = harmonic row p, n entries), N
  Eigen::VectorXd residual;
  /// With the Jacobian (else empty): ∂R̂/∂z ((2H + 1) n square, N/m; z the coefficients
  /// flattened block by block), ∂R̂/∂ω ((2H + 1) n, N·s/rad), and each coordinate's
  /// residual scale (n, N/m: |mean(K + K_H)_ii| + ω_s²|M_ii| + ω_s|(C + ΩG)_ii|, ω_s =
  /// max(|Ω|, ω)), as the harmonic balance scales its rows.
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd d_frequency, row_scale;
  /// With the Jacobian: the films' K_H and D_H at the M samples (n × n each).
  std::vector<Eigen::MatrixXd> film_stiffness, film_damping;
  bool ok = false;
  bool contact = false;          ///< a film closed at a sample
  std::string message;           ///< why not ok
  long linearizations = 0;       ///< film linearisations of this call (M with the Jacobian)
  long reynolds_solves = 0;      ///< film solves of this call
};

/// One AFT evaluation of eq. 12 at the operating point and model of `in` / `solver` (in.kind,
/// in.omega, in.chamber_pressure, in.a, the unbalance; in.period, in.r0, in.v0 are not used)
/// at the coefficients (2H + 1, n) and the frequency ω (a forced orbit: ω = 2π/in.period,
/// checked to 1e-12). opt: harmonics, time_points, film_continuation (switched on for this
/// call only: the call is a function of its arguments). A film closing or failing at a sample
/// is ok = false with the message; InputError for shapes, H, M, ω ≤ 0.
HbEvaluation hb_evaluate(SystemSolver& solver, const PeriodicInput& in,
                         const Eigen::MatrixXd& coefficients, double frequency,
                         const HarmonicBalanceOptions& opt, bool jacobian);

/// A converged branch point at `at` (an evaluation with the Jacobian, ok, at the orbit's
/// coefficients and frequency on this solver and input): the checks and Floquet multipliers
/// of hb_continuation_step's converged point — an autonomous orbit with all harmonics below
/// max(100 tol, 1e-4) L refused as an equilibrium, the samples (in.n_out over one period from
/// in.t0), the multipliers from the samples' linearisations (floquet = samples) or by Hill's
/// method on the evaluation's Jacobian (floquet = hill: one more evaluation on Hill's time
/// points), recomputed by one CVODES sensitivity flow by opt.floquet_margin's rule or for
/// floquet = flow. Returns the step with hb (orbit, coefficients, frequency, harmonic
/// amplitudes; its counters those of this call), floquet_route and the screening route's
/// |μ_c| and trivial error; p, tangent and fd_evaluations are the caller's. L: opt.hb.length_scale (0: the smallest film clearance). InputError when
/// `at` has no Jacobian or does not fit the solver.
HbContinuationStep hb_orbit_point(SystemSolver& solver, const PeriodicInput& in,
                                  const HbEvaluation& at, const HbContinuationOptions& opt);

}  // namespace rotordyn
