// Nonlinear time integration of the system (paper eq. 12) with SUNDIALS CVODE (BDF, dense
// Newton with the analytic Jacobian from the perturbation method):
//   M r̈ + (C + Ω G) ṙ + K (r + a) = H(Ω, r, ṙ) + Q + p_c(t) c_s
//                                   + Ω² (u_c cos θ + u_s sin θ) − Ω̇ (−u_c sin θ + u_s cos θ)
// with Ω(t), θ(t) = ∫Ω dt (operation.hpp), p_c from the actuator driven by the pressure
// command (schedule + harmonic + controller output); actuator and continuous-controller
// states are integrated in the same CVODE run, a discrete controller is updated at its
// sample instants (CVODE stopped and re-initialised there).
// Each film's Reynolds equation is solved at every right-hand side.
#pragma once
#include <Eigen/Core>

#include <string>

#include "rotordyn/operation.hpp"
#include "rotordyn/system.hpp"

namespace rotordyn {

struct CvodeOptions {
  double rtol = 1e-6;
  double atol_position = 1e-9;  ///< m (sleeve and rotor coordinates)
  double atol_velocity = 1e-6;  ///< m/s
  long max_steps = 200000;      ///< CVODE steps in all
  double max_step = 0.0;        ///< s; 0: no limit
  bool analytic_jacobian = true;
  /// BDF stability-limit detection (CVodeSetStabLimDet): orders 3-5 are unstable for lightly
  /// damped oscillatory modes at large h|λ|; CVODE then lowers the order instead of taking
  /// repeated error-test failures and small steps. Limit cycle of the rig: -21 % right-hand
  /// sides at equal tolerance (docs/performance.md).
  bool stability_limit_detection = true;
  /// Highest BDF order (CVodeSetMaxOrd, 1..5).
  int max_order = 5;
  double atol_pressure = 1.0;     ///< Pa (actuator pressure state; its rate state: × ω_n)
  double atol_controller = 1e-9;  ///< controller states (units of the controller)
  /// The run stops with status "rub" once a film's minimum thickness falls below
  /// rub_fraction × its clearance (checked after every step): the journal has reached the
  /// bush for any real surface finish, and the film force (∝ 1/h³) would otherwise hold
  /// CVODE in ever smaller steps. 0: only a closed film (h ≤ 0 that CVODE cannot step past).
  double rub_fraction = 1e-3;
};

struct TransientInput {
  double omega = 0.0;              ///< rad/s (constant speed when speed.t is empty)
  double chamber_pressure = 0.0;   ///< Pa
  Eigen::VectorXd a;               ///< (n,) configuration
  Eigen::VectorXd unbalance_cos;   ///< (n,) u_c (kg·m mapped to coordinates), may be empty
  Eigen::VectorXd unbalance_sin;   ///< (n,) u_s, may be empty
  Eigen::VectorXd r0, v0;          ///< (n,) initial positions and velocities
  Eigen::VectorXd t_out;           ///< (n_t,) output times, increasing, ≥ 0 (t0 = 0)
  SpeedProfile speed;              ///< Ω(t); empty: constant omega
  PressureCommand pressure;        ///< p_cmd(t) (base = chamber_pressure when constant)
  Actuator actuator;               ///< command -> p_c
  Controller controller;           ///< optional LTI feedback added to the command
  AdaptiveHarmonic adaptive;       ///< optional adaptive 1× command added to the command
  /// Coordinates whose film force H_k is recorded at every output time (a tilted film's
  /// rotations: its moments, N·m), after the run, by one film solve per output state reached
  /// (r, ṙ, Ω there); empty: none recorded, no extra solve.
  std::vector<int> record_film_force;
};

struct TransientResult {
  Eigen::VectorXd t;               ///< (n_t,) times reached
  Eigen::MatrixXd r, v;            ///< (n_t, n) positions and velocities
  Eigen::MatrixXd h_min;           ///< (n_t, n_films) minimum film thickness, m
  Eigen::VectorXd speed;           ///< (n_t,) Ω, rad/s
  Eigen::VectorXd angle;           ///< (n_t,) θ, rad
  Eigen::VectorXd pc_command;      ///< (n_t,) pressure command before saturation, Pa
  Eigen::VectorXd pc;              ///< (n_t,) actual chamber pressure p_c, Pa
  Eigen::VectorXd controller_output;  ///< (n_t,) u, Pa (0 without a controller)
  Eigen::MatrixXd actuator_states;    ///< (n_t, order)
  Eigen::MatrixXd controller_states;  ///< (n_t, n_k)
  Eigen::MatrixXd adaptive_states;    ///< (n_t, 2) [P_r, P_i] Pa, or (n_t, 0)
  /// (n_t, len(record_film_force)) H at those coordinates at each output (NaN: not reached,
  /// or the film closed there); not counted in reynolds_solves.
  Eigen::MatrixXd film_force;
  std::string status = "ok";       ///< ok | contact | not_converged | error
  std::string message;
  long steps = 0, rhs_evals = 0, jac_evals = 0, newton_fails = 0, error_test_fails = 0;
  /// CVODE's linear-solver setups (dense LU of I − γJ), Newton iterations and order
  /// reductions by the stability-limit detection; the Reynolds solves of the run (right-hand
  /// sides at a new state and the Jacobians' base states) and their active-set iterations
  /// (one sparse factorisation each).
  long linear_setups = 0, newton_iters = 0, stab_lim_order_reductions = 0;
  long reynolds_solves = 0, reynolds_iterations = 0;
};

/// Integrate from t = 0 to t_out.back(); a failure stops the run with a status (the rows
/// reached are returned) — never an abort.
TransientResult integrate(SystemSolver& solver, const TransientInput& in, const CvodeOptions& opt);

/// Readable name of a CVODE return flag ("CV_TOO_MUCH_WORK", ...).
std::string cvode_flag_name(int flag);

}  // namespace rotordyn
