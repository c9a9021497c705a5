// Nonlinear time integration of the system (paper eq. 12) with SUNDIALS CVODE (BDF, dense
// Newton with the analytic Jacobian from the perturbation method):
//   M r̈ + (C + Ω G) ṙ + K (r + a) = H(Ω, r, ṙ) + Q + p_c c_s + Ω² (u_c cos Ωt + u_s sin Ωt)
// Each film's Reynolds equation is solved at every right-hand side.
#pragma once
#include <Eigen/Core>

#include <string>

#include "rotordyn/system.hpp"

namespace rotordyn {

struct CvodeOptions {
  double rtol = 1e-6;
  double atol_position = 1e-9;  ///< m (sleeve and rotor coordinates)
  double atol_velocity = 1e-6;  ///< m/s
  long max_steps = 200000;      ///< CVODE steps in all
  double max_step = 0.0;        ///< s; 0: no limit
  bool analytic_jacobian = true;
};

struct TransientInput {
  double omega = 0.0;              ///< rad/s
  double chamber_pressure = 0.0;   ///< Pa
  Eigen::VectorXd a;               ///< (n,) configuration
  Eigen::VectorXd unbalance_cos;   ///< (n,) u_c (kg·m mapped to coordinates), may be empty
  Eigen::VectorXd unbalance_sin;   ///< (n,) u_s, may be empty
  Eigen::VectorXd r0, v0;          ///< (n,) initial positions and velocities
  Eigen::VectorXd t_out;           ///< (n_t,) output times, increasing, ≥ 0 (t0 = 0)
};

struct TransientResult {
  Eigen::VectorXd t;               ///< (n_t,) times reached
  Eigen::MatrixXd r, v;            ///< (n_t, n) positions and velocities
  Eigen::MatrixXd h_min;           ///< (n_t, n_films) minimum film thickness, m
  std::string status = "ok";       ///< ok | contact | not_converged | error
  std::string message;
  long steps = 0, rhs_evals = 0, jac_evals = 0, newton_fails = 0, error_test_fails = 0;
};

/// Integrate from t = 0 to t_out.back(); a failure stops the run with a status (the rows
/// reached are returned) — never an abort.
TransientResult integrate(SystemSolver& solver, const TransientInput& in, const CvodeOptions& opt);

/// Readable name of a CVODE return flag ("CV_TOO_MUCH_WORK", ...).
std::string cvode_flag_name(int flag);

}  // namespace rotordyn
