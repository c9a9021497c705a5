// CVODE integration of the nonlinear system (paper eq. 12). One SUNContext, CVODE memory and
// dense linear solver per call: nothing global, so threads and processes can run it at once.
#include "rotordyn/transient.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <sstream>
#include <utility>
#include <algorithm>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <utility>

#include "rotordyn/errors.hpp"
#include "cvode_detail.hpp"

namespace rotordyn {

std::string cvode_flag_name(int flag) {
  switch (flag) {
    case CV_SUCCESS: return "CV_SUCCESS";
    case CV_TSTOP_RETURN: return "CV_TSTOP_RETURN";
    case CV_ROOT_RETURN: return "CV_ROOT_RETURN";
    case CV_WARNING: return "CV_WARNING";
    case CV_TOO_MUCH_WORK: return "CV_TOO_MUCH_WORK (max_steps reached)";
    case CV_TOO_MUCH_ACC: return "CV_TOO_MUCH_ACC (tolerances too tight)";
    case CV_ERR_FAILURE: return "CV_ERR_FAILURE (repeated error-test failures)";
    case CV_CONV_FAILURE: return "CV_CONV_FAILURE (repeated Newton convergence failures)";
    case CV_LINIT_FAIL: return "CV_LINIT_FAIL";
    case CV_LSETUP_FAIL: return "CV_LSETUP_FAIL (Jacobian setup failed)";
    case CV_LSOLVE_FAIL: return "CV_LSOLVE_FAIL";
    case CV_RHSFUNC_FAIL: return "CV_RHSFUNC_FAIL (right-hand side failed)";
    case CV_FIRST_RHSFUNC_ERR: return "CV_FIRST_RHSFUNC_ERR";
    case CV_REPTD_RHSFUNC_ERR: return "CV_REPTD_RHSFUNC_ERR (film contact on repeated tries)";
    case CV_UNREC_RHSFUNC_ERR: return "CV_UNREC_RHSFUNC_ERR";
    case CV_MEM_FAIL: return "CV_MEM_FAIL";
    case CV_MEM_NULL: return "CV_MEM_NULL";
    case CV_ILL_INPUT: return "CV_ILL_INPUT";
    case CV_NO_MALLOC: return "CV_NO_MALLOC";
    case CV_BAD_K: return "CV_BAD_K";
    case CV_BAD_T: return "CV_BAD_T";
    case CV_BAD_DKY: return "CV_BAD_DKY";
    case CV_TOO_CLOSE: return "CV_TOO_CLOSE";
    default: return "CVODE flag " + std::to_string(flag);
  }
}

namespace {

struct Ctx {
  SystemSolver* solver;
  const TransientInput* in;
  Eigen::Index n, na = 0, nk = 0, N = 0;
  bool kcont = false;     // continuous controller (states in y)
  bool kdisc = false;     // discrete controller (states here)
  Eigen::VectorXd xk;     // discrete controller states
  double u_hold = 0.0;    // discrete controller output (ZOH)
  double u_next = 0.0;    // computed, waiting for its application (a computation delay)
  bool pending = false;   // u_next not applied yet
  Eigen::MatrixXd noise;  // (n_samples, n_y) noise table, empty: none
  double noise_dt = 0.0;
  Eigen::LLT<Eigen::MatrixXd> Mllt;
  Eigen::VectorXd F0;     // Q − K a
  Eigen::VectorXd KcA;    // Kc a (rotating damping with housing offsets; else empty)
  Eigen::VectorXd g;      // M⁻¹ c_s
  bool table_mass = false;  // bearing tables with mass coefficients: M = M(Ω)
  double mass_omega = std::numeric_limits<double>::quiet_NaN();  // Ω of Mllt (table_mass)
  std::string last_error;
  bool contact = false;
  std::string cvode_message;
  std::string rub;  // why the run stopped at a thin film (empty: it did not)
  // Rate limit as a switched system (exact while active): 0 free (ṗ = the valve's own rate,
  // still clipped as a fallback), ±1 limited (ṗ = ±rate_limit exactly, p linear in t). CVODE
  // root-finding on the switching surfaces (unlimited rate ∓ rate_limit) stops the
  // integration at each switch, the mode flips and CVODE restarts, so the right-hand side is
  // smooth inside every step.
  bool rate_switched = false;
  int rate_mode = 0;
  bool aw = false;  // back-calculation anti-windup on the continuous controller's states
  bool awd = false;  // the same on the discrete controller's states, at each application
  bool ad = false;         // adaptive 1× command: states [P_r, P_i] at index iad
  Eigen::Index iad = 0;
  Eigen::Index nw = 0;     // washout states z (n_y) at iad + 2, or none
  // Gain schedule: the law's matrices at law_omega (interpolated once per new speed).
  mutable Eigen::MatrixXd Ak, Bk, Ck, Dk;
  mutable double law_omega = std::numeric_limits<double>::quiet_NaN();
};

// The controller's matrices at the speed Ω: the fixed law's own, or the schedule's
// interpolation y_i + (y_{i+1} − y_i) s (as interp_table; constant outside the grid).
struct Law {
  const Eigen::MatrixXd &A, &B, &C, &D;
};

Law law_at(const Ctx& c, double omega) {
  const Controller& k = c.in->controller;
  if (!k.scheduled()) return {k.A, k.B, k.C, k.D};
  if (omega != c.law_omega) {
    const Eigen::VectorXd& x = k.schedule_omega;
    const Eigen::Index ng = x.size();
    Eigen::VectorXd row;
    if (omega <= x(0)) row = k.schedule_law.row(0).transpose();
    else if (omega >= x(ng - 1)) row = k.schedule_law.row(ng - 1).transpose();
    else {
      const Eigen::Index i =
          static_cast<Eigen::Index>(std::upper_bound(x.data(), x.data() + ng, omega) - x.data()) - 1;
      const double s = (omega - x(i)) / (x(i + 1) - x(i));
      row = (k.schedule_law.row(i) + (k.schedule_law.row(i + 1) - k.schedule_law.row(i)) * s)
                .transpose();
    }
    const Eigen::Index nk = k.A.rows(), ny = k.D.cols();
    Eigen::Index o = 0;
    c.Ak = Eigen::Map<const Eigen::MatrixXd>(row.data() + o, nk, nk); o += nk * nk;
    c.Bk = Eigen::Map<const Eigen::MatrixXd>(row.data() + o, nk, ny); o += nk * ny;
    c.Ck = Eigen::Map<const Eigen::MatrixXd>(row.data() + o, 1, nk); o += nk;
    c.Dk = Eigen::Map<const Eigen::MatrixXd>(row.data() + o, 1, ny);
    c.law_omega = omega;
  }
  return {c.Ak, c.Bk, c.Ck, c.Dk};
}

// Everything the right-hand side and the Jacobian share at (t, y).
struct Point {
  double omega, omega_dot, theta;
  Eigen::VectorXd ym;     // measurements (n_y), empty without controller
  double u = 0.0;         // controller output
  double cmd = 0.0;       // command before saturation
  double csat = 0.0;      // saturated command
  double pc = 0.0;        // actual chamber pressure
  double ck = 1.0, sk = 0.0;  // cos kθ, sin kθ of the adaptive command
};

Eigen::VectorXd noise_at(const Ctx& c, double t) {
  const Eigen::Index ns = c.noise.rows();
  double s = t / c.noise_dt;
  Eigen::Index i = static_cast<Eigen::Index>(std::floor(s));
  if (i < 0) i = 0;
  if (i >= ns - 1) return c.noise.row(ns - 1).transpose();
  if (c.kdisc) return c.noise.row(i).transpose();  // sampled at the instants only
  const double w = s - static_cast<double>(i);
  return ((1 - w) * c.noise.row(i) + w * c.noise.row(i + 1)).transpose();
}

Eigen::VectorXd measure(const Ctx& c, const double* y, double t) {
  const Controller& k = c.in->controller;
  Eigen::Map<const Eigen::VectorXd> rv(y, 2 * c.n);
  Eigen::VectorXd ym = k.measurement * rv - k.offset;
  if (c.noise.size()) ym += noise_at(c, t);
  return ym;
}

double clip(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }

double base_command(const Ctx& c, double t, double omega, double theta) {
  const PressureCommand& p = c.in->pressure;
  double cmd = c.in->chamber_pressure;
  if (p.source == PressureSource::time_table) cmd = interp_table(p.table_x, p.table_p, t);
  else if (p.source == PressureSource::speed_table) cmd = interp_table(p.table_x, p.table_p, omega);
  double amp = p.harmonic_amplitude, phase = p.harmonic_phase;
  if (p.harmonic_scheduled()) {
    amp = interp_table(p.harmonic_table_omega, p.harmonic_table_amplitude, omega);
    phase = interp_table(p.harmonic_table_omega, p.harmonic_table_phase, omega);
  }
  if (amp != 0.0) {
    const double arg = p.harmonic_order > 0 ? p.harmonic_order * theta + phase
                                            : p.harmonic_frequency * t + phase;
    cmd += amp * std::sin(arg);
  }
  return cmd;
}

Point evaluate(const Ctx& c, double t, const double* y) {
  const TransientInput& in = *c.in;
  Point P;
  P.omega = profile_speed(in.speed, in.omega, t);
  P.omega_dot = profile_speed_rate(in.speed, t);
  P.theta = profile_angle(in.speed, in.omega, t);
  if (c.kcont) {
    P.ym = measure(c, y, t);
    Eigen::Map<const Eigen::VectorXd> xk(y + 2 * c.n + c.na, c.nk);
    const Law L = law_at(c, P.omega);
    P.u = (L.C * xk + L.D * P.ym)(0);
  } else if (c.kdisc) {
    P.u = c.u_hold;
  }
  const Actuator& a = in.actuator;
  const double base = base_command(c, t, P.omega, P.theta);
  // Conditioning: the open-loop part realised first (clip(base) == base inside the limits)
  P.cmd = (in.controller.realise_schedule ? clip(base, a.p_min, a.p_max) : base) + P.u;
  if (c.ad) {
    const double arg = in.adaptive.order * P.theta;
    P.ck = std::cos(arg);
    P.sk = std::sin(arg);
    P.cmd += y[c.iad] * P.ck - y[c.iad + 1] * P.sk;
  }
  P.csat = clip(P.cmd, a.p_min, a.p_max);
  P.pc = a.order == 0 ? P.csat : clip(y[2 * c.n], a.p_min, a.p_max);
  return P;
}

// The valve's own pressure rate before the rate limit (order 1: (clip(cmd) − p)/τ, order 2:
// its rate state).
double unlimited_rate(const Ctx& c, const Point& P, const double* y) {
  const Actuator& a = c.in->actuator;
  const Eigen::Index ia = 2 * c.n;
  return a.order == 1 ? (P.csat - y[ia]) / a.time_constant : y[ia + 1];
}

// The limited pressure rate in the current mode.
double limited_rate(const Ctx& c, double unlimited) {
  const double R = c.in->actuator.rate_limit;
  return c.rate_mode != 0 ? c.rate_mode * R : clip(unlimited, -R, R);
}

// The mode for a state, from the value of the unlimited rate (at the start and after a
// discrete controller's sample, where the held command jumps).
int rate_mode_of(double unlimited, double R) {
  return unlimited >= R ? 1 : (unlimited <= -R ? -1 : 0);
}

// Back-calculation anti-windup: û − u, the command the valve follows minus the requested one.
// Magnitude: clip(cmd) − cmd, exactly 0 inside [p_min, p_max]. While the rate is limited
// (ṗ = ṗ_lim ≠ ṗ_u) the valve follows the command whose unlimited lag moves p at ṗ_lim:
// order 1 p + τ ṗ_lim, order 2 (a steady ramp) p + 2ζ/ω_n ṗ_lim; at the switch (ṗ_u = ±R) the
// first-order value equals clip(cmd), so the correction is continuous there.
double windup_excess(const Ctx& c, const Point& P, const double* y, double rate_u,
                     double rate_lim) {
  const Actuator& a = c.in->actuator;
  if (a.order == 0 || rate_lim == rate_u) return P.csat - P.cmd;
  const double lag = a.order == 1 ? a.time_constant : 2 * a.damping / a.natural_frequency;
  return y[2 * c.n] + lag * rate_lim - P.cmd;
}

// Switching surfaces: g0 = ṗ_u − R, g1 = ṗ_u + R (ṗ_u the unlimited rate).
int rate_roots(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  const Ctx& c = *static_cast<const Ctx*>(user);
  try {
    const double* yp = N_VGetArrayPointer(y);
    const double ru = unlimited_rate(c, evaluate(c, t, yp), yp);
    const double R = c.in->actuator.rate_limit;
    g[0] = ru - R;
    g[1] = ru + R;
    return 0;
  } catch (...) {
    return -1;
  }
}

// The mode after a root: the direction in which each surface was crossed (CVODE returns the
// state just past the crossing).
int rate_mode_after(int mode, const int found[2]) {
  if (found[1] < 0) return -1;  // ṗ_u fell through −R
  if (found[0] > 0) return 1;   // ṗ_u rose through +R
  if (found[0] < 0 || found[1] > 0) return 0;
  return mode;
}

// With table mass coefficients the mass matrix is M(Ω) at the current speed: refactor it (and
// g = M⁻¹ c_s) whenever Ω changes — a function of Ω only, whatever the call order.
void mass_at_speed(Ctx& c, double omega) {
  if (!c.table_mass || omega == c.mass_omega) return;
  const SystemModel& m = c.solver->model();
  c.Mllt.compute(m.mass_at(omega));
  if (c.Mllt.info() != Eigen::Success)
    throw InputError("M: the mass matrix with the bearing tables' mass coefficients at " +
                     std::to_string(omega / (2 * M_PI)) + " Hz is not positive definite");
  c.g = c.Mllt.solve(m.chamber);
  c.mass_omega = omega;
}

// The adaptive law's update row G(Ω) (interpolated as interp_table) and the measured
// signals y; returns z = Σ_j G_j y_j e^{−ikθ} as (re, im) and, for the Jacobian, the rows
// dre/dy and dim/dy over the measurements.
struct AdaptiveTerms {
  double re = 0.0, im = 0.0;
  Eigen::RowVectorXd wre, wim;  // (n_y) so that re = wre · y, im = wim · y
};

AdaptiveTerms adaptive_terms(const Ctx& c, const Point& P, const double* y, bool want_y) {
  const AdaptiveHarmonic& h = c.in->adaptive;
  const Eigen::Index ny = h.measurement.rows();
  AdaptiveTerms T;
  T.wre.resize(ny);
  T.wim.resize(ny);
  // With the washout H(s) = s/(s + ω_w) the 1× of y − z is H(ikΩ) Y, and the update row
  // is G/H(ikΩ) = G (1 − i a), a = ω_w/(kΩ): the same revolution-averaged law.
  const double kw = h.order * P.omega;
  const double a = (c.nw && kw > 0.0) ? h.washout / kw : 0.0;
  for (Eigen::Index j = 0; j < ny; ++j) {
    double gr = interp_table(h.table_omega, h.table_re.col(j), P.omega);
    double gi = interp_table(h.table_omega, h.table_im.col(j), P.omega);
    if (c.nw) {
      const double r0 = gr;
      gr = gr + gi * a;
      gi = gi - r0 * a;
    }
    // (gr + i gi)(cos − i sin)
    T.wre(j) = gr * P.ck + gi * P.sk;
    T.wim(j) = gi * P.ck - gr * P.sk;
  }
  if (want_y) {
    Eigen::Map<const Eigen::VectorXd> rv(y, 2 * c.n);
    Eigen::VectorXd ym = h.measurement * rv - h.offset;
    if (c.nw) ym -= Eigen::Map<const Eigen::VectorXd>(y + c.iad + 2, c.nw);
    T.re = T.wre.dot(ym);
    T.im = T.wim.dot(ym);
  }
  return T;
}

// The adaptation gain at this point: the constant γ or γ(Ω) of the schedule (interpolated as
// interp_table); 0 while the command is saturated and the law freezes there (the leak stays).
double adaptive_gain(const Ctx& c, const Point& P) {
  const AdaptiveHarmonic& h = c.in->adaptive;
  if (h.freeze_saturated) {
    const Actuator& a = c.in->actuator;
    if (!(P.cmd > a.p_min && P.cmd < a.p_max)) return 0.0;
  }
  return h.scheduled_gain() ? interp_table(h.gain_omega, h.gain_table, P.omega) : h.gain;
}

int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  Ctx& c = *static_cast<Ctx*>(user);
  const Eigen::Index n = c.n;
  const double* yp = N_VGetArrayPointer(y);
  Eigen::Map<const Eigen::VectorXd> Y(yp, c.N);
  Eigen::Map<Eigen::VectorXd> Yd(N_VGetArrayPointer(ydot), c.N);
  return cvode_detail::guarded(c, [&] {
    const TransientInput& in = *c.in;
    const SystemModel& m = c.solver->model();
    const Point P = evaluate(c, t, yp);
    mass_at_speed(c, P.omega);
    const Eigen::VectorXd r = Y.head(n), v = Y.segment(n, n);
    const Eigen::VectorXd H = c.solver->film_forces(r, v, P.omega);
    Eigen::VectorXd f = c.F0 + P.pc * m.chamber;
    if (c.KcA.size()) f.noalias() -= P.omega * c.KcA;
    if (in.unbalance_cos.size()) {
      const double cs = std::cos(P.theta), sn = std::sin(P.theta);
      f += P.omega * P.omega * (cs * in.unbalance_cos + sn * in.unbalance_sin);
      if (P.omega_dot != 0.0)
        f -= P.omega_dot * (-sn * in.unbalance_cos + cs * in.unbalance_sin);
    }
    const Eigen::VectorXd rhs_f = H + f - m.K * r - (m.C + P.omega * m.G) * v;
    Yd.head(n) = v;
    Yd.segment(n, n) = c.Mllt.solve(rhs_f);
    const Actuator& a = in.actuator;
    const Eigen::Index ia = 2 * n;
    double rate_u = 0.0, rate_lim = 0.0;
    if (a.order >= 1) {
      rate_u = unlimited_rate(c, P, yp);
      rate_lim = limited_rate(c, rate_u);
      Yd(ia) = rate_lim;
    }
    if (a.order == 2) {
      const double w = a.natural_frequency;
      Yd(ia + 1) = w * w * (P.csat - Y(ia)) - 2 * a.damping * w * Y(ia + 1);
    }
    if (c.kcont) {
      const Controller& k = in.controller;
      const Law L = law_at(c, P.omega);
      Yd.segment(2 * n + c.na, c.nk) = L.A * Y.segment(2 * n + c.na, c.nk) + L.B * P.ym;
      if (c.aw) {
        const double d = windup_excess(c, P, yp, rate_u, rate_lim);
        if (d != 0.0) Yd.segment(2 * n + c.na, c.nk) += k.tracking * d;  // inside: untouched
      }
    }
    if (c.ad) {
      const AdaptiveHarmonic& h = in.adaptive;
      const double g2 = 2.0 * adaptive_gain(c, P);
      const AdaptiveTerms T = adaptive_terms(c, P, yp, true);
      Yd(c.iad) = -g2 * T.re;
      Yd(c.iad + 1) = -g2 * T.im;
      if (h.leak != 0.0) {
        Yd(c.iad) -= h.leak * Y(c.iad);
        Yd(c.iad + 1) -= h.leak * Y(c.iad + 1);
      }
      if (c.nw) {  // ż = ω_w (C_m r − offset − z)
        Yd.segment(c.iad + 2, c.nw) =
            h.washout * (h.measurement * Y.head(2 * n) - h.offset - Y.segment(c.iad + 2, c.nw));
      }
    }
  });
}

int jac(sunrealtype t, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector,
        N_Vector) {
  Ctx& c = *static_cast<Ctx*>(user);
  const Eigen::Index n = c.n, N = c.N;
  const double* yp = N_VGetArrayPointer(y);
  Eigen::Map<const Eigen::VectorXd> Y(yp, N);
  return cvode_detail::guarded(c, [&] {
    const TransientInput& in = *c.in;
    const SystemModel& m = c.solver->model();
    const Point P = evaluate(c, t, yp);
    mass_at_speed(c, P.omega);
    const Linearization lin = c.solver->linearize(Y.head(n), Y.segment(n, n), P.omega);
    // SUNDenseMatrix is column-major.
    Eigen::Map<Eigen::MatrixXd> Jm(SUNDenseMatrix_Data(J), N, N);
    Jm.setZero();
    Jm.block(0, n, n, n).setIdentity();
    Jm.block(n, 0, n, n) = -c.Mllt.solve(m.K + lin.KH);
    Jm.block(n, n, n, n) = -c.Mllt.solve(m.C + P.omega * m.G + lin.DH);
    if (c.na == 0 && !c.kcont && !c.ad) return;
    const Actuator& a = in.actuator;
    // d(command)/dy: only a continuous controller makes it depend on the state.
    Eigen::RowVectorXd dcmd = Eigen::RowVectorXd::Zero(N);
    if (c.kcont) {
      const Controller& k = in.controller;
      const Law L = law_at(c, P.omega);
      dcmd.head(2 * n) = L.D * k.measurement;
      dcmd.segment(2 * n + c.na, c.nk) = L.C;
    }
    if (c.ad) {
      dcmd(c.iad) = P.ck;
      dcmd(c.iad + 1) = -P.sk;
    }
    const double s_c = (P.cmd > a.p_min && P.cmd < a.p_max) ? 1.0 : 0.0;
    const Eigen::Index ia = 2 * n;
    if (a.order == 0) {
      Jm.block(n, 0, n, N) += c.g * (s_c * dcmd);
    } else {
      const double s_p = (Y(ia) > a.p_min && Y(ia) < a.p_max) ? 1.0 : 0.0;
      Jm.block(n, ia, n, 1) += s_p * c.g;
      if (a.order == 1) {
        const double rate = (P.csat - Y(ia)) / a.time_constant;
        if (c.rate_mode == 0 && std::abs(rate) < a.rate_limit) {
          Jm.row(ia) = s_c * dcmd / a.time_constant;
          Jm(ia, ia) -= 1.0 / a.time_constant;
        }
      } else {
        const double w = a.natural_frequency;
        if (c.rate_mode == 0 && std::abs(Y(ia + 1)) < a.rate_limit) Jm(ia, ia + 1) = 1.0;
        Jm.row(ia + 1) = w * w * s_c * dcmd;
        Jm(ia + 1, ia) -= w * w;
        Jm(ia + 1, ia + 1) -= 2 * a.damping * w;
      }
    }
    if (c.kcont) {
      const Controller& k = in.controller;
      const Eigen::Index ik = 2 * n + c.na;
      const Law L = law_at(c, P.omega);
      Jm.block(ik, 0, c.nk, 2 * n) = L.B * k.measurement;
      Jm.block(ik, ik, c.nk, c.nk) = L.A;
      if (c.aw) {
        // d(û − u)/dy: −dcmd while saturated or rate limited (+ e_p in the rate-limited form)
        bool limited = false;
        if (a.order >= 1) {
          const double ru = unlimited_rate(c, P, yp);
          limited = limited_rate(c, ru) != ru;
        }
        if (limited || s_c == 0.0) {
          Eigen::RowVectorXd dd = -dcmd;
          if (limited) dd(ia) += 1.0;
          Jm.block(ik, 0, c.nk, N) += k.tracking * dd;
        }
      }
    }
    if (c.ad) {
      const AdaptiveHarmonic& h = in.adaptive;
      const AdaptiveTerms T = adaptive_terms(c, P, yp, false);
      const double g2 = 2.0 * adaptive_gain(c, P);
      const Eigen::MatrixXd& Cm = h.measurement;
      Jm.block(c.iad, 0, 1, 2 * n) = -g2 * T.wre * Cm;
      Jm.block(c.iad + 1, 0, 1, 2 * n) = -g2 * T.wim * Cm;
      Jm(c.iad, c.iad) -= h.leak;
      Jm(c.iad + 1, c.iad + 1) -= h.leak;
      if (c.nw) {
        const Eigen::Index iz = c.iad + 2;
        Jm.block(c.iad, iz, 1, c.nw) = g2 * T.wre;
        Jm.block(c.iad + 1, iz, 1, c.nw) = g2 * T.wim;
        Jm.block(iz, 0, c.nw, 2 * n) = h.washout * Cm;
        for (Eigen::Index j = 0; j < c.nw; ++j) Jm(iz + j, iz + j) = -h.washout;
      }
    }
  });
}

}  // namespace

// The film force at the coordinates in.record_film_force at every output state reached
// (after the run, so the integration's solves and its counters are those of a run without
// it): one film solve per output, each from its own inputs (film continuation off, so a
// recorded value does not depend on the solve before it). A film that fails there (closed:
// ContactError; its cavitation iteration: ConvergenceError) leaves NaN in that row, and the
// message counts such rows: a finished run is never lost to its recording.
static void record_film_force(SystemSolver& solver, const TransientInput& in,
                              TransientResult& out) {
  const auto k = static_cast<Eigen::Index>(in.record_film_force.size());
  const Eigen::Index nt = out.t.size();
  out.film_force = Eigen::MatrixXd::Constant(nt, k, NAN);
  if (k == 0) return;
  solver.set_film_continuation(false);
  int failed = 0;
  std::string first;
  for (Eigen::Index i = 0; i < nt; ++i) {
    if (!std::isfinite(out.t(i)) || !out.r.row(i).allFinite() || !out.v.row(i).allFinite())
      continue;
    try {
      Eigen::VectorXd H =
          solver.film_forces(out.r.row(i).transpose(), out.v.row(i).transpose(), out.speed(i));
      if (solver.model().Kc.size())  // the bearings' own: less the circulatory −Ω Kc r
        H += out.speed(i) * (solver.model().Kc * out.r.row(i).transpose());
      for (Eigen::Index q = 0; q < k; ++q)
        out.film_force(i, q) = H(in.record_film_force[static_cast<std::size_t>(q)]);
    } catch (const std::runtime_error& e) {  // ContactError, ConvergenceError
      if (failed++ == 0) first = e.what();
    }
  }
  if (failed > 0)
    out.message += std::string(out.message.empty() ? "" : "; ") + "film forces not recorded at " +
                   std::to_string(failed) + " output(s) (NaN there): " + first;
}

TransientResult integrate(SystemSolver& solver, const TransientInput& in,
                          const CvodeOptions& opt) {
  const SystemModel& m = solver.model();
  const Eigen::Index n = m.n();
  auto vec_ok = [&](const Eigen::VectorXd& v, const char* name, bool allow_empty) {
    cvode_detail::check_state_vector(v, name, n, allow_empty);
  };
  vec_ok(in.a, "a", false);
  vec_ok(in.r0, "r0", false);
  vec_ok(in.v0, "v0", false);
  vec_ok(in.unbalance_cos, "unbalance_cos", true);
  vec_ok(in.unbalance_sin, "unbalance_sin", in.unbalance_cos.size() == 0);
  require(in.t_out.size() > 0 && in.t_out.allFinite() && in.t_out(0) >= 0,
          "t_out: expected a non-empty array of times >= 0");
  for (Eigen::Index i = 1; i < in.t_out.size(); ++i)
    if (!(in.t_out(i) > in.t_out(i - 1)))
      throw InputError("t_out: expected strictly increasing times");
  require(opt.rtol > 0 && opt.rtol < 1 && opt.atol_position > 0 && opt.atol_velocity > 0 &&
              opt.atol_pressure > 0 && opt.atol_controller > 0,
          "cvode options: tolerances must be positive");
  require(opt.max_steps > 0, "cvode options: max_steps must be positive");
  require(opt.rub_fraction >= 0 && opt.rub_fraction < 1,
          "rub_fraction: expected a value in [0, 1), got " + std::to_string(opt.rub_fraction));
  require(opt.max_order >= 1 && opt.max_order <= 5,
          "max_order: expected an integer in [1, 5], got " + std::to_string(opt.max_order));
  const Eigen::Index nt = in.t_out.size();
  const double t_end = in.t_out(nt - 1);
  validate_operation(in.speed, in.pressure, in.actuator, in.controller, n, t_end);
  for (int j : in.record_film_force)
    require(j >= 0 && j < n, "record_film_force: expected coordinate indices in [0, " +
                                 std::to_string(n) + "), got " + std::to_string(j));

  // The films continue their cavitation sets from one right-hand side to the next for this
  // run only (started afresh here, so the run is a function of its inputs; off again on exit,
  // also by an exception).
  struct Continuation {
    SystemSolver& s;
    explicit Continuation(SystemSolver& solver) : s(solver) { s.set_film_continuation(true); }
    ~Continuation() { s.set_film_continuation(false); }
  } continuation(solver);
  const long solves0 = solver.reynolds_solves(), iters0 = solver.reynolds_iterations();

  Ctx c;
  c.solver = &solver;
  c.in = &in;
  c.n = n;
  c.na = in.actuator.n_states();
  const Controller& K = in.controller;
  c.kcont = K.enabled && K.sample_time == 0.0;
  c.kdisc = K.enabled && K.sample_time > 0.0;
  c.nk = c.kcont ? K.n_states() : 0;
  c.aw = c.kcont && c.nk > 0 && K.tracking.size() == c.nk;
  c.awd = c.kdisc && K.n_states() > 0 && K.tracking.size() == K.n_states();
  validate_adaptive(in.adaptive, n);
  c.ad = in.adaptive.enabled;
  c.iad = 2 * n + c.na + c.nk;
  c.nw = (c.ad && in.adaptive.washout > 0.0) ? in.adaptive.measurement.rows() : 0;
  c.N = 2 * n + c.na + c.nk + (c.ad ? 2 + c.nw : 0);
  c.Mllt.compute(m.M);
  require(c.Mllt.info() == Eigen::Success, "M: the mass matrix must be positive definite");
  c.F0 = m.Q - m.K * in.a;
  if (m.Kc.size()) c.KcA = m.Kc * in.a;  // −Ω(t) Kc a: the offsets' circulatory load
  c.g = c.Mllt.solve(m.chamber);
  c.table_mass = m.has_table_mass();
  if (K.enabled && K.noise_std.size() && (K.noise_std.array() > 0).any()) {
    c.noise_dt = c.kdisc ? K.sample_time : K.noise_dt;
    const Eigen::Index ns = static_cast<Eigen::Index>(std::ceil(t_end / c.noise_dt)) + 2;
    c.noise.resize(ns, K.noise_std.size());
    std::mt19937_64 gen(K.seed);
    std::normal_distribution<double> nd(0.0, 1.0);
    for (Eigen::Index i = 0; i < ns; ++i)
      for (Eigen::Index j = 0; j < K.noise_std.size(); ++j) c.noise(i, j) = K.noise_std(j) * nd(gen);
  }

  TransientResult out;
  out.t = Eigen::VectorXd::Constant(nt, NAN);
  out.r = Eigen::MatrixXd::Constant(nt, n, NAN);
  out.v = Eigen::MatrixXd::Constant(nt, n, NAN);
  out.h_min = Eigen::MatrixXd::Constant(nt, static_cast<Eigen::Index>(m.films.size()), NAN);
  out.speed = out.angle = out.pc_command = out.pc = out.controller_output =
      Eigen::VectorXd::Constant(nt, NAN);
  out.actuator_states = Eigen::MatrixXd::Constant(nt, c.na, NAN);
  const Eigen::Index nks = K.enabled ? K.n_states() : 0;
  out.controller_states = Eigen::MatrixXd::Constant(nt, nks, NAN);
  out.adaptive_states = Eigen::MatrixXd::Constant(nt, c.ad ? 2 : 0, NAN);

  std::unique_ptr<SUNContext, cvode_detail::SunContextDeleter> sunctx(new SUNContext(nullptr));
  if (SUNContext_Create(nullptr, sunctx.get()) != 0)
    throw SundialsError(-1, "SUNContext_Create", "could not create a SUNDIALS context");
  SUNContext ctx = *sunctx;
  const sunindextype N = static_cast<sunindextype>(c.N);
  N_Vector y = N_VNew_Serial(N, ctx);
  N_Vector yo = N_VNew_Serial(N, ctx);  // the state at the output time (interpolated)
  N_Vector abstol = N_VNew_Serial(N, ctx);
  SUNMatrix A = SUNDenseMatrix(N, N, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  void* mem = CVodeCreate(CV_BDF, ctx);
  auto cleanup = [&]() {
    CVodeFree(&mem);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(abstol);
    N_VDestroy(yo);
    N_VDestroy(y);
  };
  auto check = [&](int flag, const char* where) {
    if (flag < 0) {
      const std::string msg = cvode_flag_name(flag) + (c.cvode_message.empty() ? "" : ": " + c.cvode_message);
      cleanup();
      throw SundialsError(flag, where, msg);
    }
  };
  Eigen::Map<Eigen::VectorXd> Y(N_VGetArrayPointer(y), N);
  Y.head(n) = in.r0;
  Y.segment(n, n) = in.v0;
  Eigen::Map<Eigen::VectorXd> AT(N_VGetArrayPointer(abstol), N);
  AT.head(n).setConstant(opt.atol_position);
  AT.segment(n, n).setConstant(opt.atol_velocity);
  if (c.kcont) {
    Y.segment(2 * n + c.na, c.nk) = K.x0.size() ? K.x0 : Eigen::VectorXd::Zero(c.nk);
    AT.segment(2 * n + c.na, c.nk).setConstant(opt.atol_controller);
  }
  if (c.ad) {
    Y(c.iad) = in.adaptive.p0_re;
    Y(c.iad + 1) = in.adaptive.p0_im;
    AT(c.iad) = AT(c.iad + 1) = opt.atol_pressure;
    if (c.nw) {  // the washout starts at rest on the initial measurement (y − z = 0)
      const AdaptiveHarmonic& h = in.adaptive;
      Y.segment(c.iad + 2, c.nw) = h.measurement * Y.head(2 * n) - h.offset;
      AT.segment(c.iad + 2, c.nw).setConstant(opt.atol_position);
    }
  }
  if (c.kdisc) {
    c.xk = K.x0.size() ? K.x0 : Eigen::VectorXd::Zero(K.n_states());
  }
  // Discrete controller: the first sample at t = 0 (before the actuator starts at rest).
  // With a computation delay the command waits (u_next) until t_k + delay.
  const bool delayed = c.kdisc && K.delay > 0.0;
  auto sample = [&](double ts) {
    const Eigen::VectorXd ym = measure(c, Y.data(), ts);
    const Law L = law_at(c, profile_speed(in.speed, in.omega, ts));
    const double u = (L.C * c.xk + L.D * ym)(0);
    c.xk = L.A * c.xk + L.B * ym;
    if (delayed) {
      c.u_next = u;
      c.pending = true;
    } else {
      c.u_hold = u;
    }
  };
  // Discrete anti-windup: once u_k is applied at ta (the actuator state Y there), the part of
  // the command the valve does not follow, û_k − u_k (windup_excess with the rate mode the
  // new command gives), corrects the next state: x_{k+1} += L (û_k − u_k), untouched at 0.
  auto condition_sample = [&](double ta) {
    if (!c.awd) return;
    const Point P = evaluate(c, ta, Y.data());
    double ru = 0.0, rl = 0.0;
    if (c.na) {
      ru = unlimited_rate(c, P, Y.data());
      rl = std::isfinite(in.actuator.rate_limit)
               ? clip(ru, -in.actuator.rate_limit, in.actuator.rate_limit) : ru;
    }
    const double d = windup_excess(c, P, Y.data(), ru, rl);
    if (d != 0.0) c.xk += K.tracking * d;
  };
  if (c.kdisc) sample(0.0);
  if (c.na) {
    // Actuator at rest at the saturated initial command.
    Y(2 * n) = 0.0;
    const Point P0 = evaluate(c, 0.0, Y.data());
    Y(2 * n) = P0.csat;
    AT(2 * n) = opt.atol_pressure;
    if (c.na == 2) {
      Y(2 * n + 1) = 0.0;
      AT(2 * n + 1) = opt.atol_pressure * in.actuator.natural_frequency;
    }
    c.rate_switched = std::isfinite(in.actuator.rate_limit);
    if (c.rate_switched)
      c.rate_mode = rate_mode_of(unlimited_rate(c, evaluate(c, 0.0, Y.data()), Y.data()),
                                 in.actuator.rate_limit);
  }
  if (c.kdisc && !delayed) condition_sample(0.0);  // u_0 applied at t = 0

  check(CVodeSetErrHandlerFn(mem, cvode_detail::store_error<Ctx>, &c), "CVodeSetErrHandlerFn");
  check(CVodeInit(mem, rhs, 0.0, y), "CVodeInit");
  check(CVodeSetUserData(mem, &c), "CVodeSetUserData");
  check(CVodeSVtolerances(mem, opt.rtol, abstol), "CVodeSVtolerances");
  check(CVodeSetLinearSolver(mem, LS, A), "CVodeSetLinearSolver");
  if (opt.analytic_jacobian) check(CVodeSetJacFn(mem, jac), "CVodeSetJacFn");
  check(CVodeSetMaxNumSteps(mem, opt.max_steps), "CVodeSetMaxNumSteps");
  if (opt.max_step > 0) check(CVodeSetMaxStep(mem, opt.max_step), "CVodeSetMaxStep");
  if (opt.stability_limit_detection)
    check(CVodeSetStabLimDet(mem, SUNTRUE), "CVodeSetStabLimDet");
  if (opt.max_order < 5) check(CVodeSetMaxOrd(mem, opt.max_order), "CVodeSetMaxOrd");
  check(CVodeSetStopTime(mem, t_end), "CVodeSetStopTime");
  if (c.rate_switched) {
    check(CVodeRootInit(mem, 2, rate_roots), "CVodeRootInit");
    check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");
  }

  // Discrete controller: sample k at k·T; CVODE stops there and restarts (the held output
  // jumps). Samples and output times are merged in time order.
  // CVodeReInit resets CVODE's counters: they are harvested before each restart.
  auto harvest = [&]() {
    using Getter = int (*)(void*, long*);
    const std::pair<Getter, long TransientResult::*> counters[] = {
        {CVodeGetNumSteps, &TransientResult::steps},
        {CVodeGetNumRhsEvals, &TransientResult::rhs_evals},
        {CVodeGetNumJacEvals, &TransientResult::jac_evals},
        {CVodeGetNumNonlinSolvConvFails, &TransientResult::newton_fails},
        {CVodeGetNumErrTestFails, &TransientResult::error_test_fails},
        {CVodeGetNumLinSolvSetups, &TransientResult::linear_setups},
        {CVodeGetNumNonlinSolvIters, &TransientResult::newton_iters},
        {CVodeGetNumStabLimOrderReds, &TransientResult::stab_lim_order_reductions}};
    for (const auto& [get, member] : counters) {
      long v = 0;
      get(mem, &v);
      out.*member += v;
    }
  };
  // After a root (a rate-limit switch): the new mode, then a restart from the state at the
  // switch (the Jacobian and the step history belong to one mode).
  auto switch_mode = [&](double at, double tstop) {
    int found[2] = {0, 0};
    check(CVodeGetRootInfo(mem, found), "CVodeGetRootInfo");
    c.rate_mode = rate_mode_after(c.rate_mode, found);
    harvest();
    check(CVodeReInit(mem, at, y), "CVodeReInit");
    check(CVodeSetStopTime(mem, tstop), "CVodeSetStopTime");
  };
  // Rub check after every step: a film below rub_fraction of its clearance stops the run.
  const auto& films = solver.model().films;
  auto rubbed = [&](double at) {
    if (!(opt.rub_fraction > 0.0)) return false;
    const std::vector<double> hm = solver.film_h_min(Y.head(n));
    for (std::size_t k = 0; k < hm.size(); ++k) {
      const double cl = films[k].geometry.clearance_m;
      if (hm[k] < opt.rub_fraction * cl) {
        std::ostringstream os;
        os << "film '" << films[k].name << "': minimum film thickness " << hm[k] << " m = "
           << hm[k] / cl << " of the clearance, below rub_fraction = " << opt.rub_fraction
           << ", at t = " << at << " s";
        c.rub = os.str();
        return true;
      }
    }
    return false;
  };
  // Discrete controller: CVODE steps one at a time to the stop time tstop (where it lands
  // exactly, as CV_NORMAL would), with the rub check after every step and at most max_steps.
  // A successful step clears the contact flag: a closed film that CVODE stepped around is no
  // rub; only one met by the failing call is.
  auto step_to = [&](double tstop, double& tt) {
    check(CVodeSetStopTime(mem, tstop), "CVodeSetStopTime");
    long s = 0;  // steps taken (counted here: a restart resets CVODE's counters)
    int f = CV_SUCCESS;
    while (tt < tstop) {
      if (s++ >= opt.max_steps) {
        c.cvode_message = "max_steps = " + std::to_string(opt.max_steps) +
                          " steps taken before reaching t = " + std::to_string(tstop) + " s";
        return static_cast<int>(CV_TOO_MUCH_WORK);
      }
      f = CVode(mem, tstop, y, &tt, CV_ONE_STEP);
      if (f < 0) return f;
      c.contact = false;
      if (rubbed(tt)) return static_cast<int>(CV_RHSFUNC_FAIL);
      if (f == CV_ROOT_RETURN && tt < tstop) switch_mode(tt, tstop);
    }
    return f;
  };
  long k_next = 1;
  auto t_sample = [&](long k) { return static_cast<double>(k) * K.sample_time; };
  double t = 0.0;   // time of the state in Yo (the last output)
  double tn = 0.0;  // time CVODE has reached (continuous runs, one step at a time)
  bool pending_switch = false;  // a rate-limit switch at tn, restart before the next step
  Eigen::Map<Eigen::VectorXd> Yo(N_VGetArrayPointer(yo), N);
  Yo = Y;
  for (Eigen::Index i = 0; i < nt; ++i) {
    int flag = CV_SUCCESS;
    const double target = in.t_out(i);
    // Events in time order: samples k·T and, with a computation delay, the application of
    // the last sample's command at (k−1)·T + delay (one restart each; an application within
    // round-off of the next sample is done at that sample, before it).
    auto t_apply = [&]() {
      const double ta = t_sample(k_next - 1) + K.delay;
      const double tn = t_sample(k_next);
      return tn - ta <= 1e-9 * K.sample_time ? tn : ta;
    };
    while (flag >= 0 && c.kdisc &&
           (c.pending ? t_apply() : t_sample(k_next)) <= target) {
      const bool apply = c.pending;
      const double ts = apply ? t_apply() : t_sample(k_next);
      if (ts > t) {
        flag = step_to(ts, t);
        if (flag < 0) break;
        t = ts;
      }
      if (apply) {
        c.u_hold = c.u_next;
        c.pending = false;
        condition_sample(ts);  // before the next sample reads x_{k+1}
        if (ts == t_sample(k_next)) {  // the next sample at the same instant
          sample(ts);
          ++k_next;
        }
      } else {
        sample(ts);
        if (!delayed) condition_sample(ts);  // delayed: at its application
        ++k_next;
      }
      if (c.rate_switched)  // the held command jumped
        c.rate_mode = rate_mode_of(unlimited_rate(c, evaluate(c, t, Y.data()), Y.data()),
                                   in.actuator.rate_limit);
      harvest();
      check(CVodeReInit(mem, t, y), "CVodeReInit");
    }
    if (flag >= 0 && target > t && c.kdisc) {
      flag = step_to(target, t);
      if (flag >= 0) t = target;
    } else if (flag >= 0 && target > t) {
      // Continuous run: CVODE steps toward t_end (its first step is sized from t_end, so the
      // path does not depend on the output times) and each output is interpolated from the
      // step that passed it (what CV_NORMAL does too).
      // max_steps bounds the steps between two outputs, as CVODE's mxstep does in CV_NORMAL.
      long steps = 0;  // counted here: a restart resets CVODE's counters
      while (flag >= 0 && tn < target) {
        if (pending_switch) {
          switch_mode(tn, t_end);
          pending_switch = false;
        }
        if (steps++ >= opt.max_steps) {
          flag = CV_TOO_MUCH_WORK;
          c.cvode_message = "max_steps = " + std::to_string(opt.max_steps) +
                            " steps taken before reaching the output time " +
                            std::to_string(target) + " s";
          break;
        }
        flag = CVode(mem, t_end, y, &tn, CV_ONE_STEP);
        if (flag >= 0) c.contact = false;  // as in step_to
        if (flag >= 0 && rubbed(tn)) flag = CV_RHSFUNC_FAIL;
        // A switch: outputs up to the root are interpolated from the step that found it
        // (before the restart, which therefore waits for the next step).
        if (flag == CV_ROOT_RETURN && tn < t_end) pending_switch = true;
      }
      if (flag >= 0) {
        check(CVodeGetDky(mem, target, 0, yo), "CVodeGetDky");
        t = target;
      }
    }
    if (c.kdisc) Yo = Y;  // discrete controller: CVODE stopped exactly at the output time
    if (flag < 0) {
      // "rub": the journal reached the bush (a film below rub_fraction of its clearance, or
      // closed so that CVODE could not step on). Not "contact", which names a converged
      // equilibrium with a thin film (a run that started from one and finished is "contact").
      if (!c.rub.empty()) {
        out.status = "rub";
        out.message = "the journal reached the bush: " + c.rub;
        break;
      }
      // a closed film met by the failing call (contact is cleared by every successful step)
      out.status = c.contact ? "rub" : "not_converged";
      const double t_fail = c.kdisc ? t : tn;
      out.message = cvode_flag_name(flag) + " at t = " + std::to_string(t_fail) + " s" +
                    (c.last_error.empty() ? "" : ": " + c.last_error) +
                    (c.cvode_message.empty() ? "" : " [" + c.cvode_message + "]");
      break;
    }
    out.t(i) = target;
    out.r.row(i) = Yo.head(n).transpose();
    out.v.row(i) = Yo.segment(n, n).transpose();
    const Point P = evaluate(c, target, Yo.data());
    out.speed(i) = P.omega;
    out.angle(i) = P.theta;
    out.pc_command(i) = P.cmd;
    out.pc(i) = P.pc;
    out.controller_output(i) = P.u;
    if (c.na) out.actuator_states.row(i) = Yo.segment(2 * n, c.na).transpose();
    if (c.kcont) out.controller_states.row(i) = Yo.segment(2 * n + c.na, c.nk).transpose();
    if (c.ad) out.adaptive_states.row(i) = Yo.segment(c.iad, 2).transpose();
    if (c.kdisc) out.controller_states.row(i) = c.xk.transpose();
    // The film thickness needs no pressure: from the geometry, not a Reynolds solve.
    const std::vector<double> hm = solver.film_h_min(Yo.head(n));
    for (std::size_t k = 0; k < hm.size(); ++k) out.h_min(i, static_cast<Eigen::Index>(k)) = hm[k];
  }
  harvest();
  out.reynolds_solves = solver.reynolds_solves() - solves0;
  out.reynolds_iterations = solver.reynolds_iterations() - iters0;
  cleanup();
  record_film_force(solver, in, out);
  return out;
}

}  // namespace rotordyn
