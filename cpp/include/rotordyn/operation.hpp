// Time-varying operation of the nonlinear transient: the speed Ω(t) and rotor angle θ(t), the
// chamber-pressure command, the actuator (servo valve + chamber) from command to p_c, and an
// LTI controller in the loop. Plain structs (bound to Python field by field) plus the small
// evaluators the CVODE right-hand side calls.
#pragma once
#include <Eigen/Core>

#include <cstdint>
#include <limits>

namespace rotordyn {

/// Ω(t): piecewise linear through (t_i, Ω_i), constant before the first and after the last
/// point. Empty: the constant TransientInput::omega. θ(t) = ∫₀ᵗ Ω dτ exactly (the integral of
/// a piecewise-linear function), so the rotor angle carries no integration error.
struct SpeedProfile {
  Eigen::VectorXd t;      ///< (n_s,) s, strictly increasing
  Eigen::VectorXd omega;  ///< (n_s,) rad/s
};

enum class PressureSource { constant, time_table, speed_table };

/// Chamber-pressure command p_cmd(t) = base + harmonic + controller output, in Pa:
/// base = constant (TransientInput::chamber_pressure), a table p(t) or a table p(Ω)
/// (piecewise linear, constant outside); harmonic = amplitude · sin(frequency·t + phase), or
/// with order > 0 locked to the rotor: amplitude · sin(order·θ(t) + phase). With the harmonic
/// tables set, the amplitude and phase are scheduled over the speed: amplitude(Ω(t)) and
/// phase(Ω(t)) interpolated piecewise linearly (constant outside) replace the constants.
struct PressureCommand {
  PressureSource source = PressureSource::constant;
  Eigen::VectorXd table_x;  ///< (n_p,) s (time_table) or rad/s (speed_table), increasing
  Eigen::VectorXd table_p;  ///< (n_p,) Pa
  double harmonic_amplitude = 0.0;  ///< Pa
  double harmonic_frequency = 0.0;  ///< rad/s (order == 0)
  double harmonic_phase = 0.0;      ///< rad
  double harmonic_order = 0.0;      ///< > 0: argument order·θ(t) (1: once per revolution)
  Eigen::VectorXd harmonic_table_omega;      ///< (n_h,) rad/s, increasing; empty: constants
  Eigen::VectorXd harmonic_table_amplitude;  ///< (n_h,) Pa
  Eigen::VectorXd harmonic_table_phase;      ///< (n_h,) rad (unwrapped: interpolated as is)
  bool harmonic_scheduled() const { return harmonic_table_omega.size() > 0; }
};

/// Servo valve + chamber from the command to the chamber pressure p_c.
/// order 0: p_c = clip(p_cmd); order 1: τ ṗ = clip(p_cmd) − p; order 2:
/// p̈ + 2ζω_n ṗ + ω_n² p = ω_n² clip(p_cmd); in both the rate ṗ is limited to ±rate_limit and
/// p_c = clip(p) with clip to [p_min, p_max]. The states start at rest at clip(p_cmd(0)).
struct Actuator {
  int order = 0;
  double time_constant = 0.0;      ///< s (order 1)
  double natural_frequency = 0.0;  ///< rad/s (order 2)
  double damping = 0.7;            ///< ζ (order 2)
  double p_min = -std::numeric_limits<double>::infinity();  ///< Pa
  double p_max = std::numeric_limits<double>::infinity();   ///< Pa
  double rate_limit = std::numeric_limits<double>::infinity();  ///< Pa/s (order ≥ 1)
  int n_states() const { return order; }
};

/// LTI controller u = output added to the pressure command (Pa), from the measurements
/// y_m = C_m [r; ṙ] − offset + noise. Continuous (sample_time 0): ẋ = A x + B y_m,
/// u = C x + D y_m, states integrated by CVODE with the rotor. Discrete (sample_time > 0):
/// at t_k = k·T: u_k = C x_k + D y_m(t_k), x_{k+1} = A x_k + B y_m(t_k), u held (ZOH).
/// Noise: Gaussian with noise_std per measurement, drawn from a seeded generator on a grid of
/// noise_dt (the sample time for a discrete controller), linearly interpolated in between
/// for a continuous one, so the right-hand side is a deterministic function of t.
struct Controller {
  bool enabled = false;
  Eigen::MatrixXd A, B, C, D;    ///< (n_k, n_k), (n_k, n_y), (1, n_k), (1, n_y)
  Eigen::MatrixXd measurement;   ///< C_m (n_y, 2n)
  Eigen::VectorXd offset;        ///< (n_y,) subtracted from C_m [r; ṙ]
  Eigen::VectorXd x0;            ///< (n_k,) initial controller states (empty: zeros)
  double sample_time = 0.0;      ///< s; 0: continuous
  /// s, in [0, sample_time] (discrete only): the command computed at t_k is applied at
  /// t_k + delay (the controller's computation time); 0 is applied at t_k. Before the first
  /// application the command increment is 0.
  double delay = 0.0;
  /// (n_k,) back-calculation anti-windup gain L (empty: none): continuous
  /// ẋ = A x + B y_m + L (û − u), discrete x_{k+1} = A x_k + B y_k + L (û_k − u_k) with
  /// û_k − u_k taken when u_k is applied (at t_k + delay); û − u the part of the command
  /// the valve does not follow (the saturated minus the requested command; while rate
  /// limited, the command the valve follows at ±rate_limit minus the requested one).
  /// Exactly 0 inside the limits.
  Eigen::VectorXd tracking;
  /// Conditioning (the realisable reference, Hanus): the open-loop part of the command (the
  /// base p_c, its table and harmonic) is clipped to [p_min, p_max] before the controller
  /// output is added, cmd = clip(base) + u (+ adaptive), so the saturation û − u fed back
  /// through `tracking` is the controller's own share only. Inside the limits clip(base) =
  /// base exactly: the command is unchanged bit for bit.
  bool realise_schedule = false;
  /// Gain schedule over the speed (empty: the fixed law A, B, C, D): at Ω(t) the law's
  /// matrices are interpolated piecewise linearly, element by element, between grid points
  /// (constant outside; the caller refuses a run leaving the grid). Row g of schedule_law
  /// holds [vec A, vec B, vec C, vec D] (each column-major) of the design at schedule_omega(g).
  Eigen::VectorXd schedule_omega;  ///< (n_g,) rad/s, strictly increasing
  Eigen::MatrixXd schedule_law;    ///< (n_g, n_k² + n_k n_y + n_k + n_y)
  bool scheduled() const { return schedule_omega.size() > 0; }
  Eigen::VectorXd noise_std;     ///< (n_y,) or empty: no noise
  double noise_dt = 0.0;         ///< s (continuous controller with noise)
  std::uint64_t seed = 0;
  Eigen::Index n_states() const { return A.rows(); }
};

/// Adaptive harmonic (1×) command for unbalance rejection: p_ad = Re(P e^{i k θ}) =
/// P_r cos kθ − P_i sin kθ (k = order, θ the rotor angle) added to the command, the complex
/// coefficient P = P_r + i P_i two CVODE states adapted by the normalised LMS /
/// influence-coefficient law
///   Ṗ = −γ Σ_j G_j(Ω) · 2 y_j e^{−i kθ},   y = C_m [r; ṙ] − offset (n_y),
/// G(Ω) (1 × n_y complex) the pseudo-inverse of the influence coefficients T(Ω) (the measured
/// k× response to P = 1), interpolated piecewise linearly over Ω (constant outside). With
/// T exact and the speed constant, the average of Ṗ is −γ (P − P*), P* = −T⁺ Y_u the
/// least-squares optimum of the 1× response Y_u + T P.
/// Extensions (each off by default, the law above bit for bit): a leak −σ P (σ = leak, 1/s;
/// fixed point −(T̂⁺T + σ/γ)⁻¹ T̂⁺ Y_u); a gain scheduled over the speed, γ(Ω) interpolated
/// piecewise linearly on its own grid (constant outside) in place of the constant gain; and
/// freezing: while the command is outside the valve's [p_min, p_max] the gradient term is
/// switched off (the leak stays), so P does not wind up against a saturated valve.
struct AdaptiveHarmonic {
  bool enabled = false;
  double order = 1.0;
  double gain = 0.0;            ///< γ, 1/s (≥ 0); used when gain_omega is empty
  double leak = 0.0;            ///< σ, 1/s (≥ 0)
  Eigen::VectorXd gain_omega;   ///< (n_γ,) rad/s, strictly increasing; empty: constant gain
  Eigen::VectorXd gain_table;   ///< (n_γ,) γ(Ω) 1/s (≥ 0)
  bool freeze_saturated = false;  ///< gradient off while the command is saturated
  /// ω_w, rad/s (≥ 0): first-order washout s/(s + ω_w) on each measurement before the
  /// demodulation (n_y extra states z, ż = ω_w (y − z)), the update row compensated by
  /// 1/H(ikΩ) = 1 − i ω_w/(kΩ); 0: none (the law without washout, bit for bit)
  double washout = 0.0;
  bool scheduled_gain() const { return gain_omega.size() > 0; }
  Eigen::MatrixXd measurement;  ///< C_m (n_y, 2n)
  Eigen::VectorXd offset;       ///< (n_y,)
  Eigen::VectorXd table_omega;  ///< (n_g,) rad/s, strictly increasing
  Eigen::MatrixXd table_re;     ///< (n_g, n_y) Re G
  Eigen::MatrixXd table_im;     ///< (n_g, n_y) Im G
  double p0_re = 0.0, p0_im = 0.0;  ///< Pa, P at t = 0
};

/// Evaluators of the profiles (validated once by `validate_operation`).
double profile_speed(const SpeedProfile& s, double omega_const, double t);
double profile_speed_rate(const SpeedProfile& s, double t);
double profile_angle(const SpeedProfile& s, double omega_const, double t);
/// Piecewise-linear interpolation, constant outside [x_0, x_last].
double interp_table(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double xi);

/// Shape and range checks of the adaptive command; throws InputError naming the field.
void validate_adaptive(const AdaptiveHarmonic& h, Eigen::Index n_coords);

/// Shape and range checks; throws InputError naming the field.
void validate_operation(const SpeedProfile& s, const PressureCommand& p, const Actuator& a,
                        const Controller& c, Eigen::Index n_coords, double t_end);

}  // namespace rotordyn
