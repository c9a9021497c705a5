// ReynoldsSolver, rigid-journal path: forces, K/C (perturbation and finite differences),
// static equilibrium (Newton), batches.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>
#include <vector>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {
using reynolds_detail::kPi;
using reynolds_detail::num;

void check_finite(const DynamicCoefficients& dc) {
  if (!(dc.K.allFinite() && dc.C.allFinite() && dc.force_n.allFinite()))
    throw ConvergenceError("bearing coefficients: non-finite K or C");
}
}  // namespace

const FilmSolution& ReynoldsSolver::rigid(double x, double y, double vx, double vy,
                                          double omega) {
  Impl& s = *impl_;
  if (!(std::isfinite(x) && std::isfinite(y)))
    throw InputError("x_m, y_m: expected finite journal position, got (" + num(x) + ", " +
                     num(y) + ")");
  if (!(std::isfinite(vx) && std::isfinite(vy) && std::abs(vx) <= reynolds_detail::kMaxVelocity &&
        std::abs(vy) <= reynolds_detail::kMaxVelocity))
    throw InputError("vx_m_s, vy_m_s: expected a journal velocity with |vx_m_s|, |vy_m_s| <= "
                     "1e3 m/s, got (" + num(vx) + ", " + num(vy) + ")");
  const double e = std::hypot(x, y);
  if (!(e < s.c))
    throw InputError("eccentricity ratio: expected sqrt(x_m^2 + y_m^2)/clearance_m < 1, got " +
                     num(e / s.c));
  RowMatrixXd& h = s.rigid_h;  // kept between calls: no allocation per solve
  RowMatrixXd& hd = s.rigid_hd;
  h.resize(s.N, s.K1);
  hd.resize(s.N, s.K1);
  for (int j = 0; j < s.N; ++j) {
    const double hv = s.c - x * s.cosphi[j] - y * s.sinphi[j];
    const double hdv = -vx * s.cosphi[j] - vy * s.sinphi[j];
    h.row(j).setConstant(hv);
    hd.row(j).setConstant(hdv);
  }
  s.film_z_constant = true;  // solve() then skips its symmetry scan (and clears the flag)
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
  s.make_trig_fields();
  const RowMatrixXd &mc = s.trig_c, &ms = s.trig_s, &zero = s.trig_zero;
  RowMatrixXd dp[4];
  if (s.linearize_trig4(dp)) {  // the four solves below at once, the same values
    // integrate_force of each, in one pass (each sum in its own order: the same bits)
    double fx[4] = {0.0, 0.0, 0.0, 0.0}, fy[4] = {0.0, 0.0, 0.0, 0.0};
    const double* d[4] = {dp[0].data(), dp[1].data(), dp[2].data(), dp[3].data()};
    for (int j = 0, n = 0; j < s.N; ++j)
      for (int k = 0; k < s.K1; ++k, ++n) {
        const double wk = (k == 0 || k == s.K1 - 1) ? 0.5 : 1.0;
        for (int v = 0; v < 4; ++v) {
          fx[v] -= wk * d[v][n] * s.cosphi[j];
          fy[v] -= wk * d[v][n] * s.sinphi[j];
        }
      }
    const double area = s.R * s.dphi * s.dz;
    for (int v = 0; v < 4; ++v) {
      const Eigen::Vector2d f(fx[v] * area, fy[v] * area);
      (v < 2 ? dc.K : dc.C).col(v % 2) = -f;
    }
  } else {
    dc.K.col(0) = -integrate_force(linearize(mc, zero));
    dc.K.col(1) = -integrate_force(linearize(ms, zero));
    dc.C.col(0) = -integrate_force(linearize(zero, mc));
    dc.C.col(1) = -integrate_force(linearize(zero, ms));
  }
  check_finite(dc);
  return dc;
}

DynamicCoefficients ReynoldsSolver::coefficients_fd(double x, double y, double omega,
                                                    double rel_step) {
  Impl& s = *impl_;
  if (!(rel_step >= 1e-10 && rel_step < 0.1))
    throw InputError("rel_step: expected 1e-10 <= rel_step < 0.1 (a smaller step is lost in "
                     "round-off of the position), got " + num(rel_step));
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
  check_finite(dc);
  return dc;
}

namespace {
// Damped Newton on F(q) + load = 0 with the perturbation Jacobian dF/dq = −K and a backtracking
// line search on |F + load| that keeps q inside the clearance circle. Returns false (q at the
// last iterate) when it stalls or runs out of iterations.
bool newton_equilibrium(ReynoldsSolver& rs, const Eigen::Vector2d& load, double omega,
                        double emax, double tol_abs, int max_iter, Eigen::Vector2d& q,
                        DynamicCoefficients& dc, int& iters) {
  dc = rs.coefficients(q.x(), q.y(), omega);
  Eigen::Vector2d res = dc.force_n + load;
  for (int it = 0; it <= max_iter; ++it) {
    iters = it;
    if (res.stableNorm() <= tol_abs) return true;
    // Newton step first; if the line search fails along it (a kink of the cavitated film or a
    // poorly conditioned K), the steepest-descent direction of |F + load|²/2, i.e. Kᵀ(F + load).
    const Eigen::Vector2d newton = dc.K.inverse() * res;  // F(q+δ) ≈ F − K δ = −load
    Eigen::Vector2d grad = dc.K.transpose() * res;
    if (grad.norm() > 0.0) grad *= 0.05 * emax / grad.norm();
    bool accepted = false;
    for (int dir = 0; dir < 2 && !accepted; ++dir) {
      const Eigen::Vector2d step = dir == 0 ? newton : grad;
      if (!step.allFinite() || step.norm() == 0.0) continue;
      double alpha = 1.0;
      for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
        const Eigen::Vector2d qn = q + alpha * step;
        if (qn.norm() >= emax) continue;
        DynamicCoefficients dn = rs.coefficients(qn.x(), qn.y(), omega);
        const Eigen::Vector2d rn = dn.force_n + load;
        if (rn.stableNorm() < (1.0 - 1e-4 * alpha) * res.stableNorm()) {
          q = qn;
          dc = dn;
          res = rn;
          accepted = true;
          break;
        }
      }
    }
    if (!accepted) return false;
  }
  return false;
}
}  // namespace

EquilibriumSolution ReynoldsSolver::equilibrium(double lx, double ly, double omega, double x0,
                                                double y0, double rtol, int max_iter) {
  Impl& s = *impl_;
  if (!(std::isfinite(lx) && std::isfinite(ly)))
    throw InputError("load_n: expected a finite load, got (" + num(lx) + ", " + num(ly) + ")");
  const double W = std::hypot(lx, ly);  // no underflow for tiny loads (unlike sqrt(x²+y²))
  if (!std::isfinite(W))
    throw InputError("load_n: expected a finite load, got (" + num(lx) + ", " + num(ly) + ")");
  if (!(std::isfinite(omega) && omega != 0.0 && std::abs(omega) <= reynolds_detail::kMaxOmega))
    throw InputError("speed_hz: static equilibrium needs 0 < |speed_hz| <= 1e5 Hz, got " +
                     num(omega / (2.0 * kPi)));
  if (!(rtol >= 1e-14 && rtol <= 1e-2))
    throw InputError("rtol: expected 1e-14 <= rtol <= 1e-2, got " + num(rtol));
  if (!(max_iter >= 1 && max_iter <= 10000))
    throw InputError("max_iter: expected 1 <= max_iter <= 10000, got " +
                     std::to_string(max_iter));
  // The solves of this call (Newton steps, line searches, the load continuation) start from
  // the last converged cavitation set of this call — the same unique Swift–Stieber solution in
  // fewer active-set steps. The set is cleared on entry and on exit, so the call's result
  // never depends on what the solver ran before it (or runs after).
  struct WithinCall {
    ReynoldsSolver& rs;
    bool was;
    ~WithinCall() { rs.set_continuation(was); }
  } within_call{*this, continuation()};
  set_continuation(true);
  const double emax = 0.9999 * s.c;
  const Eigen::Vector2d load(lx, ly);
  Eigen::Vector2d q(x0, y0);
  if (!(q.allFinite() && std::hypot(x0, y0) < emax))
    throw InputError("x0_m, y0_m: expected a starting point inside the clearance circle");
  // Lightly loaded journal. The film's force scale is F_s = μ|ω|RL(R/c)²; a plain film
  // carries nothing at the centre (F(0) = 0) and is positively homogeneous of degree one
  // there: F(t·q) = t·F(q) + O(t²). Below W_lin = 1e-6·F_s (eccentricity ratio ~1e-6, where
  // the film thickness changes by fewer digits than the force needs), the equilibrium is the
  // one for the load W_lin in the same direction scaled by W/W_lin (relative error ~1e-6 of
  // the eccentricity, far below the discretisation error); a zero load is the centre.
  const double Fs = s.mu * std::abs(omega) * s.R * s.L * (s.R / s.c) * (s.R / s.c);
  const double Wlin = 1e-6 * Fs;
  if (W < Wlin && x0 == 0.0 && y0 == 0.0) {
    const Eigen::Vector2d F0 = rigid(0.0, 0.0, 0.0, 0.0, omega).force_n;
    if (F0.norm() <= 1e-12 * Fs) {
      EquilibriumSolution e;
      if (W == 0.0) {
        e.force_n = F0;
        e.residual_rel = F0.norm() / Fs;
        return e;
      }
      e = equilibrium(lx / W * Wlin, ly / W * Wlin, omega, 0.0, 0.0, rtol, max_iter);
      const double t = W / Wlin;
      e.x_m *= t;
      e.y_m *= t;
      e.force_n *= t;
      return e;
    }
  }
  if (W == 0.0)
    throw InputError("load_n: a zero load is accepted for a film that carries nothing at the "
                     "centre; this one (pressurised grooves) needs a nonzero load");
  const Eigen::Vector2d d = load / W;
  auto guess = [&](double eps) {
    // along the load, turned by ~45° in the direction of rotation
    const double a = (omega > 0 ? 1.0 : -1.0) * kPi / 4.0;
    return Eigen::Vector2d(eps * s.c * (std::cos(a) * d.x() - std::sin(a) * d.y()),
                           eps * s.c * (std::sin(a) * d.x() + std::cos(a) * d.y()));
  };
  if (q.norm() == 0.0) {
    q = guess(0.5);
    if (W < 0.05 * Fs) {
      // light load: the centred film's linearisation F ≈ −K q gives q ≈ K⁻¹ load
      const DynamicCoefficients d0 = coefficients(0.0, 0.0, omega);
      const Eigen::Vector2d ql = d0.K.inverse() * load;
      if (ql.allFinite() && ql.norm() < 0.5 * s.c && ql.norm() > 0.0) q = ql;
    }
  }
  DynamicCoefficients dc;
  int iters = 0, total = 0;
  auto done = [&](const Eigen::Vector2d& qq) {
    EquilibriumSolution e;
    e.x_m = qq.x();
    e.y_m = qq.y();
    e.force_n = dc.force_n;
    const Eigen::Vector2d res = dc.force_n + load;
    e.residual_rel = std::hypot(res.x(), res.y()) / W;
    e.iterations = total;
    return e;
  };
  // 1) Newton from the starting point.
  Eigen::Vector2d qn = q;
  const bool ok = newton_equilibrium(*this, load, omega, emax, rtol * W, max_iter, qn, dc, iters);
  total += iters;
  if (ok) return done(qn);
  // 2) Continuation in the load from a lightly loaded journal (the equilibrium locus is
  //    followed from near the centre, each Newton started from the previous equilibrium).
  Eigen::Vector2d qc = guess(0.02);
  {
    // equilibrium for a load small enough that the film is nearly linear: F ≈ −K q
    const DynamicCoefficients d0 = coefficients(0.0, 0.0, omega);
    const Eigen::Vector2d q0 = d0.K.inverse() * (-(-load) * 1e-3);
    if (q0.allFinite() && q0.norm() < 0.2 * s.c) qc = q0;
  }
  double frac = 1e-3, dfrac = 1e-3;
  int n_fail = 0;
  while (true) {
    const double target = std::min(1.0, frac + dfrac);
    Eigen::Vector2d qt = qc;
    const bool okc = newton_equilibrium(*this, load * target, omega, emax,
                                        target < 1.0 ? 1e-6 * W * target : rtol * W, 30, qt,
                                        dc, iters);
    total += iters;
    if (okc) {
      qc = qt;
      frac = target;
      if (frac >= 1.0) return done(qc);
      dfrac = std::min(2.0 * dfrac, 1.0);
      n_fail = 0;
    } else {
      dfrac *= 0.25;
      if (++n_fail > 12 || dfrac < 1e-6)
        throw ConvergenceError(
            "static equilibrium: the film carries at most about " + num(frac * W) +
            " N of the " + num(W) + " N load along this direction (eccentricity ratio " +
            num(qc.norm() / s.c) + "); no equilibrium inside the clearance was found");
    }
    if (total > 40 * max_iter)
      throw ConvergenceError("static equilibrium: Newton/continuation did not converge in " +
                             std::to_string(total) + " iterations");
  }
}

namespace {
// Runs row_fn(solver, r) for every row, in contiguous chunks over n_threads threads (the first
// chunk on `self`, the others on fresh solvers of the same bearing); per-row exceptions become
// status codes, so a failing point never aborts the batch or crosses a thread boundary.
template <class RowFn>
void run_batch(ReynoldsSolver& self, Eigen::Index n, int n_threads, int n_cols, BatchResult& out,
               RowFn row_fn) {
  out.values.setConstant(n, n_cols, std::numeric_limits<double>::quiet_NaN());
  out.status.setZero(n);
  out.message.assign(static_cast<std::size_t>(n), std::string());
  if (n_threads <= 0) n_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  n_threads = static_cast<int>(std::min<Eigen::Index>(n_threads, std::max<Eigen::Index>(n, 1)));
  auto chunk = [&](ReynoldsSolver& rs, Eigen::Index r0, Eigen::Index r1) {
    for (Eigen::Index r = r0; r < r1; ++r) {
      int code = 0;
      try {
        row_fn(rs, r);
      } catch (const InputError& e) {
        code = 1;
        out.message[r] = e.what();
      } catch (const ContactError& e) {
        code = 2;
        out.message[r] = e.what();
      } catch (const ConvergenceError& e) {
        code = 3;
        out.message[r] = e.what();
      } catch (const std::exception& e) {
        code = 4;
        out.message[r] = e.what();
      }
      if (code != 0) {
        out.status[r] = code;
        out.values.row(r).setConstant(std::numeric_limits<double>::quiet_NaN());
      }
    }
  };
  if (n_threads == 1) {
    chunk(self, 0, n);
    return;
  }
  std::vector<std::thread> pool;
  const Eigen::Index per = (n + n_threads - 1) / n_threads;
  for (int t = 1; t < n_threads; ++t) {
    const Eigen::Index r0 = t * per, r1 = std::min(n, r0 + per);
    if (r0 >= r1) break;
    pool.emplace_back([&, r0, r1] {
      try {
        ReynoldsSolver rs(self.geometry(), self.grid(), self.cavitation());
        rs.set_use_axial_symmetry(self.use_axial_symmetry());
        chunk(rs, r0, r1);
      } catch (const std::exception& e) {  // solver construction (memory): mark the chunk
        for (Eigen::Index r = r0; r < r1; ++r) {
          out.status[r] = 4;
          out.message[r] = e.what();
        }
      }
    });
  }
  chunk(self, 0, std::min(n, per));
  for (auto& th : pool) th.join();
}
}  // namespace

BatchResult ReynoldsSolver::batch_forces(const RowMatrixXd& states, const Eigen::VectorXd& omegas,
                                         int n_threads) {
  if (states.cols() != 4)
    throw InputError(shape_msg("states", states.rows(), 4, states.rows(), states.cols()));
  if (omegas.size() != states.rows())
    throw InputError(shape_msg("omegas", states.rows(), 1, omegas.size(), 1));
  BatchResult out;
  run_batch(*this, states.rows(), n_threads, 2, out, [&](ReynoldsSolver& rs, Eigen::Index r) {
    out.values.row(r) =
        rs.rigid(states(r, 0), states(r, 1), states(r, 2), states(r, 3), omegas[r])
            .force_n.transpose();
  });
  return out;
}

BatchResult ReynoldsSolver::batch_coefficients(const RowMatrixXd& positions,
                                               const Eigen::VectorXd& omegas, int n_threads) {
  if (positions.cols() != 2)
    throw InputError(shape_msg("positions", positions.rows(), 2, positions.rows(),
                               positions.cols()));
  if (omegas.size() != positions.rows())
    throw InputError(shape_msg("omegas", positions.rows(), 1, omegas.size(), 1));
  BatchResult out;
  run_batch(*this, positions.rows(), n_threads, 10, out, [&](ReynoldsSolver& rs, Eigen::Index r) {
    const DynamicCoefficients dc = rs.coefficients(positions(r, 0), positions(r, 1), omegas[r]);
    out.values.row(r) << dc.force_n.x(), dc.force_n.y(), dc.K(0, 0), dc.K(0, 1), dc.K(1, 0),
        dc.K(1, 1), dc.C(0, 0), dc.C(0, 1), dc.C(1, 0), dc.C(1, 1);
  });
  return out;
}

}  // namespace rotordyn
