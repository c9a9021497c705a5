// ReynoldsSolver, rigid-journal path: forces, K/C (perturbation and finite differences),
// static equilibrium (Newton), batches.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {
constexpr double kPi = 3.14159265358979323846;

std::string num(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}
}  // namespace

const FilmSolution& ReynoldsSolver::rigid(double x, double y, double vx, double vy,
                                          double omega) {
  Impl& s = *impl_;
  if (!(std::isfinite(x) && std::isfinite(y)))
    throw InputError("x_m, y_m: expected finite journal position, got (" + num(x) + ", " +
                     num(y) + ")");
  if (!(std::isfinite(vx) && std::isfinite(vy)))
    throw InputError("vx_m_s, vy_m_s: expected finite journal velocity, got (" + num(vx) +
                     ", " + num(vy) + ")");
  const double e = std::hypot(x, y);
  if (!(e < s.c))
    throw InputError("eccentricity ratio: expected sqrt(x_m^2 + y_m^2)/clearance_m < 1, got " +
                     num(e / s.c));
  RowMatrixXd h(s.N, s.K1), hd(s.N, s.K1);
  for (int j = 0; j < s.N; ++j) {
    const double hv = s.c - x * s.cosphi[j] - y * s.sinphi[j];
    const double hdv = -vx * s.cosphi[j] - vy * s.sinphi[j];
    h.row(j).setConstant(hv);
    hd.row(j).setConstant(hdv);
  }
  solve(h, hd, omega);
  s.out.h_min_m = s.c - e;
  double ang = e > 0.0 ? std::atan2(y, x) * 180.0 / kPi : 0.0;
  if (ang < 0.0) ang += 360.0;
  s.out.h_min_angle_deg = ang;
  return s.out;
}

DynamicCoefficients ReynoldsSolver::coefficients(double x, double y, double omega) {
  Impl& s = *impl_;
  DynamicCoefficients dc;
  dc.force_n = rigid(x, y, 0.0, 0.0, omega).force_n;
  RowMatrixXd zero = RowMatrixXd::Zero(s.N, s.K1);
  RowMatrixXd mc(s.N, s.K1), ms(s.N, s.K1);
  for (int j = 0; j < s.N; ++j) {
    mc.row(j).setConstant(-s.cosphi[j]);
    ms.row(j).setConstant(-s.sinphi[j]);
  }
  dc.K.col(0) = -integrate_force(linearize(mc, zero));
  dc.K.col(1) = -integrate_force(linearize(ms, zero));
  dc.C.col(0) = -integrate_force(linearize(zero, mc));
  dc.C.col(1) = -integrate_force(linearize(zero, ms));
  return dc;
}

DynamicCoefficients ReynoldsSolver::coefficients_fd(double x, double y, double omega,
                                                    double rel_step) {
  Impl& s = *impl_;
  if (!(rel_step > 0.0 && rel_step < 0.1))
    throw InputError("rel_step: expected 0 < rel_step < 0.1, got " + num(rel_step));
  DynamicCoefficients dc;
  dc.force_n = rigid(x, y, 0.0, 0.0, omega).force_n;
  const double dq = rel_step * s.c;
  const double dv = rel_step * s.c * std::max(std::abs(omega), 1.0);
  for (int m = 0; m < 2; ++m) {
    const double ex = m == 0 ? 1.0 : 0.0, ey = m == 0 ? 0.0 : 1.0;
    const Eigen::Vector2d fp = rigid(x + ex * dq, y + ey * dq, 0, 0, omega).force_n;
    const Eigen::Vector2d fm = rigid(x - ex * dq, y - ey * dq, 0, 0, omega).force_n;
    dc.K.col(m) = -(fp - fm) / (2.0 * dq);
    const Eigen::Vector2d gp = rigid(x, y, ex * dv, ey * dv, omega).force_n;
    const Eigen::Vector2d gm = rigid(x, y, -ex * dv, -ey * dv, omega).force_n;
    dc.C.col(m) = -(gp - gm) / (2.0 * dv);
  }
  rigid(x, y, 0.0, 0.0, omega);  // leave the solver at the operating point
  return dc;
}

EquilibriumSolution ReynoldsSolver::equilibrium(double lx, double ly, double omega, double x0,
                                                double y0, double rtol, int max_iter) {
  Impl& s = *impl_;
  const double W = std::hypot(lx, ly);
  if (!(std::isfinite(W) && W > 0.0))
    throw InputError("load_n: expected a finite nonzero load, got (" + num(lx) + ", " + num(ly) +
                     ")");
  if (!(std::isfinite(omega) && omega != 0.0))
    throw InputError("speed_hz: static equilibrium needs a finite nonzero speed, got " +
                     num(omega / (2.0 * kPi)));
  if (!(rtol > 0.0)) throw InputError("rtol: expected > 0, got " + num(rtol));
  const double emax = 0.9999 * s.c;
  Eigen::Vector2d q(x0, y0);
  if (q.norm() >= emax)
    throw InputError("x0_m, y0_m: expected a starting point inside the clearance circle");
  if (q.norm() == 0.0) {
    // Journal moves along the load, turned by ~45° in the direction of rotation.
    const double a = (omega > 0 ? 1.0 : -1.0) * kPi / 4.0;
    const Eigen::Vector2d d(lx / W, ly / W);
    q = 0.5 * s.c * Eigen::Vector2d(std::cos(a) * d.x() - std::sin(a) * d.y(),
                                    std::sin(a) * d.x() + std::cos(a) * d.y());
  }
  const Eigen::Vector2d load(lx, ly);
  DynamicCoefficients dc = coefficients(q.x(), q.y(), omega);
  Eigen::Vector2d res = dc.force_n + load;
  for (int it = 0; it <= max_iter; ++it) {
    if (res.norm() <= rtol * W) {
      EquilibriumSolution e;
      e.x_m = q.x();
      e.y_m = q.y();
      e.force_n = dc.force_n;
      e.residual_rel = res.norm() / W;
      e.iterations = it;
      return e;
    }
    Eigen::Vector2d step = dc.K.inverse() * res;  // F(q+δ) ≈ F − K δ = −load
    if (!step.allFinite()) step = res.normalized() * 0.05 * s.c;
    double alpha = 1.0;
    Eigen::Vector2d qn;
    DynamicCoefficients dn;
    Eigen::Vector2d rn;
    for (int ls = 0; ls < 30; ++ls) {
      qn = q + alpha * step;
      if (qn.norm() >= emax) {
        alpha *= 0.5;
        continue;
      }
      dn = coefficients(qn.x(), qn.y(), omega);
      rn = dn.force_n + load;
      if (rn.norm() < (1.0 - 1e-4 * alpha) * res.norm() || ls == 29) break;
      alpha *= 0.5;
    }
    if (qn.norm() >= emax)
      throw ConvergenceError("static equilibrium: no film position inside the clearance "
                             "carries the load (eccentricity ratio -> 1)");
    q = qn;
    dc = dn;
    res = rn;
  }
  throw ConvergenceError("static equilibrium: Newton did not converge in " +
                         std::to_string(max_iter) + " iterations (relative residual " +
                         num(res.norm() / W) + ")");
}

RowMatrixXd ReynoldsSolver::batch_forces(const RowMatrixXd& states,
                                         const Eigen::VectorXd& omegas) {
  if (states.cols() != 4)
    throw InputError(shape_msg("states", states.rows(), 4, states.rows(), states.cols()));
  if (omegas.size() != states.rows())
    throw InputError(shape_msg("omegas", states.rows(), 1, omegas.size(), 1));
  RowMatrixXd out(states.rows(), 2);
  for (Eigen::Index r = 0; r < states.rows(); ++r)
    out.row(r) = rigid(states(r, 0), states(r, 1), states(r, 2), states(r, 3), omegas[r])
                     .force_n.transpose();
  return out;
}

RowMatrixXd ReynoldsSolver::batch_coefficients(const RowMatrixXd& positions,
                                               const Eigen::VectorXd& omegas) {
  if (positions.cols() != 2)
    throw InputError(shape_msg("positions", positions.rows(), 2, positions.rows(),
                               positions.cols()));
  if (omegas.size() != positions.rows())
    throw InputError(shape_msg("omegas", positions.rows(), 1, omegas.size(), 1));
  RowMatrixXd out(positions.rows(), 10);
  for (Eigen::Index r = 0; r < positions.rows(); ++r) {
    const DynamicCoefficients dc = coefficients(positions(r, 0), positions(r, 1), omegas[r]);
    out.row(r) << dc.force_n.x(), dc.force_n.y(), dc.K(0, 0), dc.K(0, 1), dc.K(1, 0), dc.K(1, 1),
        dc.C(0, 0), dc.C(0, 1), dc.C(1, 0), dc.C(1, 1);
  }
  return out;
}

}  // namespace rotordyn
