// CVODE transient: a damped oscillator (no film) against its closed-form free response, and
// CVODE failures turned into statuses.
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/transient.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
SystemModel oscillator(double m, double k, double c) {
  SystemModel s;
  s.M = Eigen::MatrixXd::Constant(1, 1, m);
  s.K = Eigen::MatrixXd::Constant(1, 1, k);
  s.C = Eigen::MatrixXd::Constant(1, 1, c);
  s.G = Eigen::MatrixXd::Zero(1, 1);
  s.Q = Eigen::VectorXd::Zero(1);
  s.chamber = Eigen::VectorXd::Zero(1);
  return s;
}
}  // namespace

TEST_CASE("transient: damped oscillator free response equals the closed form") {
  const double m = 2.0, k = 800.0, c = 4.0;
  SystemSolver s(oscillator(m, k, c));
  TransientInput in;
  in.a = Eigen::VectorXd::Zero(1);
  in.r0 = Eigen::VectorXd::Constant(1, 1e-3);
  in.v0 = Eigen::VectorXd::Zero(1);
  in.t_out = Eigen::VectorXd::LinSpaced(21, 0.0, 1.0);
  CvodeOptions o;
  o.rtol = 1e-10;
  o.atol_position = 1e-14;
  o.atol_velocity = 1e-12;
  const TransientResult r = integrate(s, in, o);
  CHECK(r.status == "ok");
  const double wn = std::sqrt(k / m), z = c / (2 * std::sqrt(k * m)),
               wd = wn * std::sqrt(1 - z * z);
  for (Eigen::Index i = 0; i < in.t_out.size(); ++i) {
    const double t = in.t_out(i);
    const double x = 1e-3 * std::exp(-z * wn * t) * (std::cos(wd * t) + z * wn / wd * std::sin(wd * t));
    CHECK_CLOSE(r.r(i, 0), x, 0, 1e-9);
  }
}

TEST_CASE("transient: too few steps is a status with the CVODE flag name") {
  SystemSolver s(oscillator(1.0, 1e4, 0.0));
  TransientInput in;
  in.a = Eigen::VectorXd::Zero(1);
  in.r0 = Eigen::VectorXd::Constant(1, 1e-3);
  in.v0 = Eigen::VectorXd::Zero(1);
  in.t_out = Eigen::VectorXd::LinSpaced(3, 0.0, 10.0);
  CvodeOptions o;
  o.max_steps = 5;
  const TransientResult r = integrate(s, in, o);
  CHECK(r.status == "not_converged");
  CHECK(r.message.find("CV_TOO_MUCH_WORK") != std::string::npos);
  in.t_out = Eigen::VectorXd::LinSpaced(3, 1.0, 0.0);
  CHECK_THROWS(integrate(s, in, o), InputError);
}

TEST_CASE("transient: first-order valve follows a sine command as the closed form") {
  // τ ṗ + p = A sin ωt, p(0) = 0: p = A/(1+(ωτ)²) (sin ωt − ωτ cos ωt + ωτ e^{−t/τ}).
  SystemSolver s(oscillator(1.0, 1e4, 10.0));
  TransientInput in;
  in.a = Eigen::VectorXd::Zero(1);
  in.r0 = Eigen::VectorXd::Zero(1);
  in.v0 = Eigen::VectorXd::Zero(1);
  in.t_out = Eigen::VectorXd::LinSpaced(41, 0.0, 0.2);
  const double A = 1e5, w = 2 * M_PI * 20.0, tau = 5e-3;
  in.pressure.harmonic_amplitude = A;
  in.pressure.harmonic_frequency = w;
  in.actuator.order = 1;
  in.actuator.time_constant = tau;
  CvodeOptions o;
  o.rtol = 1e-10;
  o.atol_pressure = 1e-6;
  const TransientResult r = integrate(s, in, o);
  CHECK(r.status == "ok");
  const double wt = w * tau;
  for (Eigen::Index i = 0; i < in.t_out.size(); ++i) {
    const double t = in.t_out(i);
    const double p = A / (1 + wt * wt) * (std::sin(w * t) - wt * std::cos(w * t) + wt * std::exp(-t / tau));
    CHECK_CLOSE(r.pc(i), p, 0, 1e-3);
    CHECK_CLOSE(r.pc_command(i), A * std::sin(w * t), 0, 1e-6);
  }
}

TEST_CASE("transient: a rate-limited valve ramps at the limit, then lags exponentially") {
  // Step command p1 from rest at 0 (table), τ = 2 ms, R = 1e7 Pa/s: ṗ = min((p1 − p)/τ, R):
  // a ramp R t until p1 − p = R τ (t1 = (p1 − Rτ)/R), then p1 − Rτ e^{−(t−t1)/τ}.
  SystemSolver s(oscillator(1.0, 1e4, 10.0));
  TransientInput in;
  in.a = Eigen::VectorXd::Zero(1);
  in.r0 = Eigen::VectorXd::Zero(1);
  in.v0 = Eigen::VectorXd::Zero(1);
  in.t_out = Eigen::VectorXd::LinSpaced(61, 0.0, 0.06);
  in.pressure.source = PressureSource::time_table;
  in.pressure.table_x = Eigen::Vector2d(0.0, 1e-9);
  in.pressure.table_p = Eigen::Vector2d(0.0, 2e5);
  const double tau = 2e-3, R = 1e7, p1 = 2e5;
  in.actuator.order = 1;
  in.actuator.time_constant = tau;
  in.actuator.rate_limit = R;
  in.actuator.p_min = 0.0;
  in.actuator.p_max = 1.5e5;  // saturation below the command: the target is 1.5e5
  CvodeOptions o;
  o.rtol = 1e-10;
  o.atol_pressure = 1e-6;
  o.max_step = 1e-4;
  const TransientResult r = integrate(s, in, o);
  CHECK(r.status == "ok");
  const double target = 1.5e5, t1 = (target - R * tau) / R;
  for (Eigen::Index i = 1; i < in.t_out.size(); ++i) {
    const double t = in.t_out(i);
    const double p = t <= t1 ? R * t : target - R * tau * std::exp(-(t - t1) / tau);
    CHECK_CLOSE(r.pc(i), p, 0, 1.0);
    CHECK(r.pc(i) <= 1.5e5);
    CHECK_CLOSE(r.pc_command(i), p1, 0, 0);
  }
  (void)p1;
}

TEST_CASE("transient: bad operation inputs are InputErrors") {
  SystemSolver s(oscillator(1.0, 1e4, 10.0));
  TransientInput in;
  in.a = Eigen::VectorXd::Zero(1);
  in.r0 = Eigen::VectorXd::Zero(1);
  in.v0 = Eigen::VectorXd::Zero(1);
  in.t_out = Eigen::VectorXd::LinSpaced(3, 0.0, 0.1);
  in.actuator.order = 1;
  in.actuator.time_constant = -1.0;
  CHECK_THROWS(integrate(s, in, CvodeOptions()), InputError);
  in.actuator.time_constant = 1e-3;
  in.controller.enabled = true;
  in.controller.A = Eigen::MatrixXd::Zero(1, 1);
  in.controller.B = Eigen::MatrixXd::Zero(1, 1);
  in.controller.C = Eigen::MatrixXd::Zero(1, 1);
  in.controller.D = Eigen::MatrixXd::Zero(1, 1);
  in.controller.measurement = Eigen::MatrixXd::Zero(1, 2);
  in.controller.offset = Eigen::VectorXd::Zero(1);
  in.controller.sample_time = -1e-3;
  CHECK_THROWS(integrate(s, in, CvodeOptions()), InputError);
  in.controller.sample_time = 0.0;
  in.controller.C = Eigen::MatrixXd::Zero(2, 1);  // two outputs
  CHECK_THROWS(integrate(s, in, CvodeOptions()), InputError);
}
