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
