// Speed profile, rotor angle, pressure tables, and the checks of the time-varying operation.
#include "rotordyn/operation.hpp"

#include <algorithm>
#include <cmath>

#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {

// Index i with x(i) <= xi < x(i+1), for x(0) <= xi < x(last).
Eigen::Index segment(const Eigen::VectorXd& x, double xi) {
  const double* b = x.data();
  const double* e = b + x.size();
  return static_cast<Eigen::Index>(std::upper_bound(b, e, xi) - b) - 1;
}

bool increasing(const Eigen::VectorXd& x) {
  for (Eigen::Index i = 1; i < x.size(); ++i)
    if (!(x(i) > x(i - 1))) return false;
  return true;
}

}  // namespace

double interp_table(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double xi) {
  const Eigen::Index n = x.size();
  if (xi <= x(0)) return y(0);
  if (xi >= x(n - 1)) return y(n - 1);
  const Eigen::Index i = segment(x, xi);
  const double s = (xi - x(i)) / (x(i + 1) - x(i));
  return y(i) + (y(i + 1) - y(i)) * s;
}

double profile_speed(const SpeedProfile& s, double omega_const, double t) {
  if (s.t.size() == 0) return omega_const;
  return interp_table(s.t, s.omega, t);
}

double profile_speed_rate(const SpeedProfile& s, double t) {
  const Eigen::Index n = s.t.size();
  if (n < 2 || t < s.t(0) || t >= s.t(n - 1)) return 0.0;
  const Eigen::Index i = segment(s.t, t);
  return (s.omega(i + 1) - s.omega(i)) / (s.t(i + 1) - s.t(i));
}

double profile_angle(const SpeedProfile& s, double omega_const, double t) {
  const Eigen::Index n = s.t.size();
  if (n == 0) return omega_const * t;
  // Before the first point the speed is omega(0); the angle is 0 at t = 0.
  auto integral_to = [&](double tau) {  // ∫ from min(0, t_0) ... handled by differences below
    double th = 0.0;
    if (tau <= s.t(0)) return s.omega(0) * (tau - s.t(0));
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
      const double a = s.t(i), b = std::min(s.t(i + 1), tau);
      if (b <= a) break;
      const double wb = s.omega(i) + (s.omega(i + 1) - s.omega(i)) * (b - a) / (s.t(i + 1) - a);
      th += 0.5 * (s.omega(i) + wb) * (b - a);
    }
    if (tau > s.t(n - 1)) th += s.omega(n - 1) * (tau - s.t(n - 1));
    return th;
  };
  return integral_to(t) - integral_to(0.0);
}

void validate_adaptive(const AdaptiveHarmonic& h, Eigen::Index n) {
  if (!h.enabled) return;
  const Eigen::Index ny = h.measurement.rows(), ng = h.table_omega.size();
  require(std::isfinite(h.gain) && h.gain >= 0,
          "adaptive.gain: expected a finite adaptation gain >= 0 1/s");
  require(std::isfinite(h.order) && h.order > 0, "adaptive.order: expected > 0");
  require(ny >= 1 && h.measurement.cols() == 2 * n,
          shape_msg("adaptive.measurement", ny, 2 * n, h.measurement.rows(),
                    h.measurement.cols()));
  require(h.offset.size() == ny, shape_msg("adaptive.offset", ny, 1, h.offset.size(), 1));
  require(ng >= 1 && h.table_re.rows() == ng && h.table_re.cols() == ny &&
              h.table_im.rows() == ng && h.table_im.cols() == ny,
          shape_msg("adaptive.table_re/table_im", ng, ny, h.table_re.rows(), h.table_re.cols()));
  require(h.table_omega.allFinite() && increasing(h.table_omega) && h.table_re.allFinite() &&
              h.table_im.allFinite() && h.measurement.allFinite() && h.offset.allFinite() &&
              std::isfinite(h.p0_re) && std::isfinite(h.p0_im),
          "adaptive: expected strictly increasing finite speeds and finite tables");
  require(std::isfinite(h.leak) && h.leak >= 0,
          "adaptive.leak: expected a finite leak rate >= 0 1/s");
  require(std::isfinite(h.washout) && h.washout >= 0,
          "adaptive.washout: expected a finite washout corner >= 0 rad/s");
  require(h.gain_table.size() == h.gain_omega.size(),
          shape_msg("adaptive.gain_table", h.gain_omega.size(), 1, h.gain_table.size(), 1));
  if (h.scheduled_gain())
    require(h.gain_omega.allFinite() && increasing(h.gain_omega) && h.gain_table.allFinite() &&
                (h.gain_table.array() >= 0).all(),
            "adaptive.gain_table: expected strictly increasing finite speeds and finite "
            "gains >= 0 1/s");
}

void validate_operation(const SpeedProfile& s, const PressureCommand& p, const Actuator& a,
                        const Controller& c, Eigen::Index n, double t_end) {
  require(s.t.size() == s.omega.size(), "speed_profile: t and omega must have the same length");
  if (s.t.size()) {
    require(s.t.allFinite() && s.omega.allFinite() && increasing(s.t),
            "speed_profile.t: expected strictly increasing finite times");
  }
  if (p.source != PressureSource::constant) {
    require(p.table_x.size() >= 1 && p.table_x.size() == p.table_p.size(),
            "chamber_pressure table: expected x and p of the same non-zero length");
    require(p.table_x.allFinite() && p.table_p.allFinite() && increasing(p.table_x),
            "chamber_pressure table: expected strictly increasing finite x and finite p");
  }
  require(std::isfinite(p.harmonic_amplitude) && std::isfinite(p.harmonic_frequency) &&
              std::isfinite(p.harmonic_phase) && p.harmonic_order >= 0,
          "chamber_pressure harmonic: expected finite amplitude, frequency, phase and order >= 0");
  const Eigen::Index nh = p.harmonic_table_omega.size();
  require(p.harmonic_table_amplitude.size() == nh && p.harmonic_table_phase.size() == nh,
          "chamber_pressure harmonic tables: expected speed, amplitude and phase of the same "
          "length");
  if (nh)
    require(p.harmonic_table_omega.allFinite() && p.harmonic_table_amplitude.allFinite() &&
                p.harmonic_table_phase.allFinite() && increasing(p.harmonic_table_omega),
            "chamber_pressure harmonic tables: expected strictly increasing finite speeds and "
            "finite amplitudes and phases");
  require(a.order >= 0 && a.order <= 2, "actuator.order: expected 0, 1 or 2");
  if (a.order == 1)
    require(std::isfinite(a.time_constant) && a.time_constant > 0,
            "actuator.time_constant: expected > 0 s");
  if (a.order == 2) {
    require(std::isfinite(a.natural_frequency) && a.natural_frequency > 0,
            "actuator.natural_frequency: expected > 0 rad/s");
    require(std::isfinite(a.damping) && a.damping > 0, "actuator.damping: expected > 0");
  }
  require(!std::isnan(a.p_min) && !std::isnan(a.p_max) && a.p_min < a.p_max,
          "actuator.p_min/p_max: expected p_min < p_max");
  require(a.rate_limit > 0, "actuator.rate_limit: expected > 0 Pa/s");
  require(a.order >= 1 || std::isinf(a.rate_limit),
          "actuator.rate_limit: a rate limit needs actuator dynamics (order 1 or 2)");
  if (!c.enabled) return;
  const Eigen::Index nk = c.A.rows(), ny = c.measurement.rows();
  require(c.A.cols() == nk, shape_msg("controller.A", nk, nk, c.A.rows(), c.A.cols()));
  require(c.B.rows() == nk && c.B.cols() == ny,
          shape_msg("controller.B", nk, ny, c.B.rows(), c.B.cols()));
  require(c.C.rows() == 1 && c.C.cols() == nk,
          shape_msg("controller.C", 1, nk, c.C.rows(), c.C.cols()));
  require(c.D.rows() == 1 && c.D.cols() == ny,
          shape_msg("controller.D", 1, ny, c.D.rows(), c.D.cols()));
  require(ny >= 1 && c.measurement.cols() == 2 * n,
          shape_msg("controller.measurement", ny, 2 * n, c.measurement.rows(),
                    c.measurement.cols()));
  require(c.offset.size() == ny, shape_msg("controller.offset", ny, 1, c.offset.size(), 1));
  require(c.x0.size() == 0 || c.x0.size() == nk,
          shape_msg("controller.x0", nk, 1, c.x0.size(), 1));
  require(c.A.allFinite() && c.B.allFinite() && c.C.allFinite() && c.D.allFinite() &&
              c.measurement.allFinite() && c.offset.allFinite() && c.x0.allFinite(),
          "controller: matrices must be finite");
  require(c.tracking.size() == 0 || c.tracking.size() == nk,
          shape_msg("controller.tracking", nk, 1, c.tracking.size(), 1));
  require(c.tracking.allFinite(), "controller.tracking: expected a finite anti-windup gain");
  if (c.scheduled()) {
    const Eigen::Index ng = c.schedule_omega.size(), w = nk * nk + nk * ny + nk + ny;
    require(c.schedule_law.rows() == ng && c.schedule_law.cols() == w,
            shape_msg("controller.schedule_law", ng, w, c.schedule_law.rows(),
                      c.schedule_law.cols()));
    require(c.schedule_omega.allFinite() && increasing(c.schedule_omega) &&
                c.schedule_law.allFinite(),
            "controller.schedule_omega: expected strictly increasing finite speeds and a "
            "finite law at each");
  }
  require(std::isfinite(c.sample_time) && c.sample_time >= 0,
          "controller.sample_time: expected >= 0 s (0: continuous)");
  require(std::isfinite(c.delay) && c.delay >= 0 && c.delay <= c.sample_time,
          "controller.delay: expected a computation delay in [0, sample_time] s (a continuous "
          "controller: 0)");
  if (c.noise_std.size()) {
    require(c.noise_std.size() == ny && c.noise_std.allFinite() && (c.noise_std.array() >= 0).all(),
            "controller.noise_std: expected one standard deviation >= 0 per measurement");
    if (c.sample_time == 0)
      require(std::isfinite(c.noise_dt) && c.noise_dt > 0,
              "controller.noise_dt: expected > 0 s for a continuous controller with noise");
    const double dt = c.sample_time > 0 ? c.sample_time : c.noise_dt;
    require(t_end / dt < 5e7, "controller.noise_dt: more than 5e7 noise samples in the run");
  }
  if (c.sample_time > 0)
    require(t_end / c.sample_time < 5e7, "controller.sample_time: more than 5e7 samples in the run");
}

}  // namespace rotordyn
