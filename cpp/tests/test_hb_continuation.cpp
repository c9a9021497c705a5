// The harmonic-balance corrector over a parameter the caller varies (hb_continuation_step with
// a provider of the systems): a forced oscillator (no film) over its stiffness against the
// closed form of its response and of the response's derivative, and a value the provider
// refuses as a status with the refusal.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "rotordyn/errors.hpp"
#include "rotordyn/hb_continuation.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {

constexpr double kMass = 2.0, kDamp = 4.0, kOmega = 30.0, kU = 1e-3;

SystemModel oscillator(double k) {
  SystemModel s;
  s.M = Eigen::MatrixXd::Constant(1, 1, kMass);
  s.K = Eigen::MatrixXd::Constant(1, 1, k);
  s.C = Eigen::MatrixXd::Constant(1, 1, kDamp);
  s.G = Eigen::MatrixXd::Zero(1, 1);
  s.Q = Eigen::VectorXd::Zero(1);
  s.chamber = Eigen::VectorXd::Zero(1);
  return s;
}

PeriodicInput forced_input() {
  PeriodicInput in;
  in.kind = OrbitKind::forced;
  in.omega = kOmega;
  in.a = Eigen::VectorXd::Zero(1);
  in.unbalance_cos = Eigen::VectorXd::Constant(1, kU);
  in.unbalance_sin = Eigen::VectorXd::Zero(1);
  in.period = 2 * M_PI / kOmega;
  in.n_out = 9;
  return in;
}

// m ẍ + c ẋ + k x = Ω² u cos Ωt: x = a cos Ωt + b sin Ωt with (a, b) = Ω² u (k − mΩ², cΩ) / D,
// D = (k − mΩ²)² + (cΩ)², and d(a, b)/dk.
struct Response {
  double a, b, da, db;
};
Response closed_form(double k) {
  const double r = k - kMass * kOmega * kOmega, s = kDamp * kOmega, D = r * r + s * s;
  const double f = kOmega * kOmega * kU;
  return {f * r / D, f * s / D, f * (D - 2 * r * r) / (D * D), -2 * f * s * r / (D * D)};
}

// The systems at k: a solver per call (as a caller re-assembling a model), k ≥ k_max refused.
struct Provider {
  double k_max;
  std::vector<double> visited;  // every k asked for, in order
  HbSystemAt operator()(double k) {
    visited.push_back(k);
    HbSystemAt at;
    if (k >= k_max) {
      at.refused = "the model refuses k = " + std::to_string(k);
      return at;
    }
    at.solver = std::make_shared<SystemSolver>(oscillator(k));
    at.input = forced_input();
    return at;
  }
};

HbContinuationInput first_point(double k) {
  HbContinuationInput c;
  c.base = forced_input();
  const Response r = closed_form(k);  // 10 % off: a predictor's error
  c.coefficients = Eigen::MatrixXd::Zero(3, 1);
  c.coefficients(1, 0) = 0.9 * r.a;
  c.coefficients(2, 0) = 1.1 * r.b;
  c.frequency = kOmega;
  c.p = k;
  c.scale = Eigen::Vector3d(1e-3, kOmega, 1e3);
  c.y_prev = Eigen::VectorXd::Zero(5);
  c.y_prev(3) = kOmega;
  c.y_prev(4) = k;
  c.fd_step = 1e-4;
  return c;
}

HbContinuationOptions options() {
  HbContinuationOptions o;
  o.hb.harmonics = 1;
  o.hb.time_points = 8;
  o.hb.tol = 1e-12;
  o.hb.floquet = HbFloquet::samples;
  o.floquet_margin = 0.0;
  return o;
}

}  // namespace

TEST_CASE("hb corrector over a caller's parameter: forced oscillator over k is the closed form") {
  // k from 2500 N/m (above the resonance mΩ² = 1800 N/m) along the branch:
  // the first point (k held) and one arclength step, each against the closed form to 1e-10
  // of the amplitude, and the tangent's direction against d(a, b)/dk to 1e-6 (the central
  // difference ∂R/∂p: O(h²) = 1e-8 relative here, plus round-off).
  Provider prov{1e9, {}};
  const HbSystemProvider at = std::ref(prov);
  const HbContinuationOptions opt = options();
  HbContinuationInput c = first_point(2500.0);
  const HbContinuationStep s0 = hb_continuation_step(at, c, opt);
  CHECK(s0.hb.orbit.status == "ok");
  CHECK(s0.p == 2500.0);
  Response ref = closed_form(2500.0);
  const double amp = std::hypot(ref.a, ref.b);
  CHECK_CLOSE(s0.hb.coefficients(1, 0), ref.a, 0, 1e-10 * amp);
  CHECK_CLOSE(s0.hb.coefficients(2, 0), ref.b, 0, 1e-10 * amp);
  CHECK_CLOSE(s0.hb.coefficients(0, 0), 0.0, 0, 1e-10 * amp);
  CHECK(s0.hb.orbit.iterations >= 1);  // the Newton path, not the start, is checked
  CHECK(s0.hb.orbit.reynolds_solves == 0);
  CHECK(s0.fd_evaluations == 2 * (s0.hb.orbit.iterations + 1));
  CHECK(s0.hb.evaluations == s0.fd_evaluations + s0.hb.orbit.iterations + 1);
  CHECK(s0.floquet_route == "samples");
  // the tangent (scaled by L, D_ω, D_p): (da/dk, db/dk) · D_p / L per unit of p
  const Eigen::VectorXd& t = s0.tangent;
  CHECK(t.size() == 5 && t(4) > 0);
  CHECK_CLOSE(t(1) / t(4), ref.da * c.scale(2) / c.scale(0), 1e-6, 0);
  CHECK_CLOSE(t(2) / t(4), ref.db * c.scale(2) / c.scale(0), 1e-6, 0);
  // one arclength step from the first point's tangent
  HbContinuationInput c1 = first_point(2500.0);
  c1.y_prev << s0.hb.coefficients(0, 0), s0.hb.coefficients(1, 0), s0.hb.coefficients(2, 0),
      kOmega, s0.p;
  c1.tangent = t;
  c1.ds = 0.5;
  Eigen::VectorXd sfull(5);
  sfull << 1e-3, 1e-3, 1e-3, kOmega, 1e3;
  const Eigen::VectorXd yp = c1.y_prev + c1.ds * t.cwiseProduct(sfull);
  c1.coefficients = yp.head(3);
  c1.p = yp(4);
  const HbContinuationStep s1 = hb_continuation_step(at, c1, opt);
  CHECK(s1.hb.orbit.status == "ok");
  CHECK(s1.p > s0.p + 150.0);
  ref = closed_form(s1.p);
  CHECK_CLOSE(s1.hb.coefficients(1, 0), ref.a, 0, 1e-10 * amp);
  CHECK_CLOSE(s1.hb.coefficients(2, 0), ref.b, 0, 1e-10 * amp);
  // The systems the provider was asked for: per step the start value, then per corrector
  // iteration (it = 0..iterations) the central difference's pair p ± h (h = fd_step · D_p =
  // 0.1 N/m) at that iterate's p and, before the next iteration, one line-search trial (the
  // residual is affine in (z, k): every full Newton step is accepted, so one trial per step).
  const double h = c.fd_step * c.scale(2);
  auto expected = [&](double p_start, const HbContinuationStep& s, const std::vector<double>& got,
                      std::size_t at) {
    const int it = s.hb.orbit.iterations;
    const std::size_t n = 1 + 2 * (it + 1) + it;  // start, pairs, trials
    CHECK(got.size() >= at + n);
    if (got.size() < at + n) return at + n;
    CHECK(got[at] == p_start);
    double p = p_start;
    std::size_t q = at + 1;
    for (int i = 0; i <= it; ++i) {
      CHECK_CLOSE(got[q], p + h, 1e-15, 0);
      CHECK_CLOSE(got[q + 1], p - h, 1e-15, 0);
      q += 2;
      if (i < it) p = got[q++];  // the trial: the next iterate
    }
    CHECK(p == s.p);  // the last iterate is the step's answer
    return q;
  };
  CHECK(s0.fd_evaluations == 2 * (s0.hb.orbit.iterations + 1));
  CHECK(s1.fd_evaluations == 2 * (s1.hb.orbit.iterations + 1));
  const std::size_t n0 = expected(2500.0, s0, prov.visited, 0);
  CHECK(std::all_of(prov.visited.begin() + 1, prov.visited.begin() + n0,
                    [&](double k) { return std::abs(k - 2500.0) <= h * (1 + 1e-12); }));
  const std::size_t n1 = expected(c1.p, s1, prov.visited, n0);
  CHECK(prov.visited.size() == n1);  // nothing else asked for
}

TEST_CASE("hb corrector over a caller's parameter: a refused value is a status with its reason") {
  const HbContinuationOptions opt = options();
  Provider prov{2000.0, {}};
  const HbSystemProvider at = std::ref(prov);
  // the predicted point refused
  HbContinuationStep s = hb_continuation_step(at, first_point(2500.0), opt);
  CHECK(s.hb.orbit.status == "not_converged");
  CHECK(s.hb.orbit.message ==
        "harmonic balance at the predicted point: the model refuses k = 2500.000000");
  CHECK(s.tangent.size() == 0);
  // p + h refused (h = fd_step · D_p = 0.1 N/m): no parameter derivative
  s = hb_continuation_step(at, first_point(1999.95), opt);
  CHECK(s.hb.orbit.status == "not_converged");
  CHECK(s.hb.orbit.message.find("a residual at p ± h for the parameter derivative failed") !=
        std::string::npos);
  // a system whose coordinates differ from the coefficients': InputError
  HbContinuationInput c = first_point(1000.0);
  c.coefficients = Eigen::MatrixXd::Zero(3, 2);
  c.y_prev = Eigen::VectorXd::Zero(8);
  CHECK_THROWS(hb_continuation_step(at, c, opt), InputError);
  CHECK_THROWS(hb_continuation_step(HbSystemProvider(), first_point(1000.0), opt), InputError);
}

TEST_CASE("hb corrector on one system: its orbit input is validated (once, at the first value)") {
  // The one-system entry (p_c here; the oscillator has no chamber, so the response is the
  // closed form at any p_c): the system and the orbit input differ between parameter values
  // only by p_c, Ω or a_y, so they are checked at the first value only; a bad input is still
  // an InputError before any solve.
  const HbContinuationOptions opt = options();
  SystemSolver one(oscillator(2500.0));
  HbContinuationInput c = first_point(2500.0);
  c.parameter = ContinuationParameter::chamber_pressure;
  c.p = 1e5;
  c.y_prev(4) = c.p;
  const HbContinuationStep s = hb_continuation_step(one, c, opt);
  CHECK(s.hb.orbit.status == "ok" && s.p == 1e5);
  const Response ref = closed_form(2500.0);
  const double amp = std::hypot(ref.a, ref.b);
  CHECK_CLOSE(s.hb.coefficients(1, 0), ref.a, 0, 1e-10 * amp);
  CHECK_CLOSE(s.hb.coefficients(2, 0), ref.b, 0, 1e-10 * amp);
  HbContinuationInput bad = c;
  bad.base.unbalance_cos.setZero();  // a forced orbit without forcing
  CHECK_THROWS(hb_continuation_step(one, bad, opt), InputError);
  bad = c;
  bad.base.n_out = 1;
  CHECK_THROWS(hb_continuation_step(one, bad, opt), InputError);
}
