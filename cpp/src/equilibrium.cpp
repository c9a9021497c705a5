// Static equilibrium of the multi-bearing system (paper eq. 14-16): Newton with line search
// (Jacobian K + K_H by the perturbation method) and the paper's successive substitution with
// the relaxation coefficient P_m.
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "rotordyn/errors.hpp"
#include "rotordyn/system.hpp"

namespace rotordyn {

EquilibriumMethod parse_equilibrium_method(const std::string& name) {
  if (name == "newton") return EquilibriumMethod::Newton;
  if (name == "successive") return EquilibriumMethod::Successive;
  throw InputError("method: expected 'newton' or 'successive', got '" + name + "'");
}

namespace {
double inf_norm(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

/// Coordinates whose row and column in J are both zero (an unloaded tilting pad's tilt: a
/// pressure-free film and no tilt stiffness). Empty when none are.
std::vector<Eigen::Index> inactive_coordinates(const Eigen::MatrixXd& J) {
  std::vector<Eigen::Index> out;
  for (Eigen::Index i = 0; i < J.rows(); ++i)
    if (J.row(i).cwiseAbs().maxCoeff() == 0.0 && J.col(i).cwiseAbs().maxCoeff() == 0.0)
      out.push_back(i);
  return out;
}

/// J restricted to the active coordinates (all but `off`).
Eigen::MatrixXd active_block(const Eigen::MatrixXd& J, const std::vector<Eigen::Index>& off,
                             std::vector<Eigen::Index>& on) {
  on.clear();
  for (Eigen::Index i = 0, k = 0; i < J.rows(); ++i) {
    if (k < static_cast<Eigen::Index>(off.size()) && off[static_cast<std::size_t>(k)] == i) {
      ++k;
      continue;
    }
    on.push_back(i);
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(on.size()), static_cast<Eigen::Index>(on.size()));
  for (std::size_t a = 0; a < on.size(); ++a)
    for (std::size_t b = 0; b < on.size(); ++b)
      A(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = J(on[a], on[b]);
  return A;
}

/// Newton step −J⁻¹R; coordinates with a zero row and column in J (and R) stay put.
Eigen::VectorXd newton_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& R) {
  const std::vector<Eigen::Index> off = inactive_coordinates(J);
  if (off.empty()) return J.partialPivLu().solve(-R);
  std::vector<Eigen::Index> on;
  const Eigen::MatrixXd A = active_block(J, off, on);
  if (on.empty()) return Eigen::VectorXd::Constant(J.rows(), NAN);  // J = 0: singular
  Eigen::VectorXd Ra(static_cast<Eigen::Index>(on.size()));
  for (std::size_t a = 0; a < on.size(); ++a) Ra(static_cast<Eigen::Index>(a)) = R(on[a]);
  const Eigen::VectorXd da = A.partialPivLu().solve(-Ra);
  Eigen::VectorXd dr = Eigen::VectorXd::Zero(J.rows());
  for (std::size_t a = 0; a < on.size(); ++a) dr(on[a]) = da(static_cast<Eigen::Index>(a));
  return dr;
}
}  // namespace

EquilibriumResult SystemSolver::equilibrium(double omega, double pc, const Eigen::VectorXd& a,
                                            const Eigen::VectorXd& r0,
                                            const EquilibriumOptions& opt,
                                            const Eigen::MatrixXd* kh_guess) {
  const Eigen::Index n = model_.n();
  require(std::isfinite(omega), "speed: expected a finite value");
  require(std::isfinite(pc) && pc >= 0, "chamber_pressure_pa: expected a finite value >= 0");
  require(a.size() == n, shape_msg("a", n, 1, a.size(), 1));
  require(r0.size() == 0 || r0.size() == n, shape_msg("r0", n, 1, r0.size(), 1));
  require(r0.allFinite(), "r0: expected finite values");
  require(a.allFinite(), "a: expected finite values");
  require(opt.tol > 0 && opt.max_iter > 0, "options: tol and max_iter must be positive");
  require(std::isfinite(opt.pm), "pm: expected P_m >= 0, or < 0 for automatic");
  require(!opt.reuse_jacobian || (opt.reuse_contraction > 0 && opt.reuse_contraction < 1),
          "reuse_contraction: expected a value in (0, 1)");
  const bool have_guess = opt.reuse_jacobian && kh_guess && kh_guess->size() > 0;
  require(!have_guess || (kh_guess->rows() == n && kh_guess->cols() == n),
          shape_msg("kh_guess", n, n, have_guess ? kh_guess->rows() : 0,
                    have_guess ? kh_guess->cols() : 0));
  require(!have_guess || kh_guess->allFinite(), "kh_guess: expected finite values");

  const int solves0 = solves_;
  // The solves of this call (Newton steps, line searches, the polish, the load continuation)
  // start from the last converged cavitation set of this call, from the prediction at its
  // start: the same unique Swift–Stieber solution in fewer active-set steps (and no coarse
  // solve). Cleared on entry and on exit, so the result never depends on what the solver ran
  // before; a caller that carries the sets over a sequence (set_film_carry: one sweep line)
  // keeps its own.
  struct WithinCall {
    SystemSolver& s;
    bool own;
    ~WithinCall() {
      if (own) s.carry_sets(false);
    }
  } within_call{*this, !carry_};
  if (within_call.own) carry_sets(true);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd Ka = model_.offset_load(omega, a);
  const Eigen::VectorXd F = model_.Q + pc * model_.chamber - Ka;  // eq. 14 right side less H
  EquilibriumResult out;
  out.load_scale = std::max({inf_norm(model_.Q), inf_norm(Ka), inf_norm(pc * model_.chamber),
                             1e-12});
  Eigen::VectorXd r = r0.size() ? r0 : zero;
  {
    // The residual scale is at least 1e-3 of the largest film's Sommerfeld load
    // μ|Ω s| R L (R/C)², so an unloaded system has a reachable tolerance: preloaded tilting
    // pads carry force without a load, and a rotor without gravity (a vertical machine) has
    // only the films' round-off at its centred journals (a two-axial-groove bearing with
    // supply pressure: 2e-13 N against a scale of 1e-12 N failed its line search). A loaded
    // system's scale (its weight) is far above this floor and unchanged.
    double fs = 0.0;
    for (const FilmCoupling& f : model_.films) {
      const double R = 0.5 * f.geometry.diameter_m, C = f.geometry.clearance_m;
      fs = std::max(fs, f.geometry.viscosity_pa_s * std::abs(omega * f.spin_factor) * R *
                            f.geometry.length_m * (R / C) * (R / C));
    }
    out.load_scale = std::max(out.load_scale, 1e-3 * fs);
  }

  auto residual = [&](const Eigen::VectorXd& rr, const Eigen::VectorXd& H) {
    return Eigen::VectorXd(model_.K * rr - H - F);
  };
  auto finish = [&](Eigen::VectorXd rr, const Eigen::VectorXd& H, double res) {
    // the bearings' own force: H less the shaft's circulatory −Ω Kc r (rotating damping)
    out.film_force = model_.Kc.size() ? Eigen::VectorXd(H + omega * (model_.Kc * rr)) : H;
    out.r = std::move(rr);
    out.residual = res;
    out.h_min = h_min_;
    out.h_min_angle_deg = h_min_angle_;
    out.h_min_z_m = h_min_z_;
    out.reynolds_solves = solves_ - solves0;
    // Statuses (issue 13): "ok" and "contact" are converged equilibria (contact: a film is
    // thinner than contact_fraction c there); "not_converged" and "no_equilibrium" (the
    // iteration failed with a film closing) are failures, never to be linearised. A failed
    // solve is never renamed to a converged status.
    const bool converged = out.status == "ok";
    if (converged && !(out.r.allFinite() && out.film_force.allFinite() &&
                       std::isfinite(res))) {
      out.status = "not_converged";
      out.message = "non-finite equilibrium (residual " + std::to_string(res) + ")";
    }
    for (std::size_t i = 0; i < films_.size(); ++i) {
      const double c = model_.films[i].geometry.clearance_m;
      if (!(h_min_[i] < opt.contact_fraction * c)) continue;
      std::ostringstream os;
      os << "film '" << model_.films[i].name << "': minimum film thickness " << h_min_[i]
         << " m is below " << opt.contact_fraction << " c";
      if (out.status == "ok" || out.status == "contact") {
        out.status = "contact";
        out.message = os.str();
      } else {
        out.status = "no_equilibrium";
        out.message = "no equilibrium: " + out.message + "; " + os.str();
        break;
      }
    }
    return out;
  };

  if (opt.method == EquilibriumMethod::Newton) {
    // Damped Newton on K r − H(r) − Fs = 0 from rs; Jacobian K + K_H (perturbation method),
    // backtracking line search on ‖R‖∞ that also steps back from contact. Each trial point
    // costs one Reynolds solve per film; K_H (linearised solves on that solve's factorisation,
    // no D_H) is formed only at an accepted point that still needs a step, so the converged
    // point and rejected trials cost no linearisation. With opt.reuse_jacobian (`reuse`: the
    // first Newton from the start only) the Jacobian J is kept and Broyden-updated between
    // steps (EquilibriumOptions::reuse_jacobian).
    Eigen::VectorXd H = zero;
    Eigen::MatrixXd KH;
    auto newton = [&](const Eigen::VectorXd& Fs, Eigen::VectorXd& rs, int iters, double& res,
                      std::string& why, bool polish, bool reuse) -> bool {
      auto resid = [&](const Eigen::VectorXd& rr, const Eigen::VectorXd& Hr) {
        return Eigen::VectorXd(model_.K * rr - Hr - Fs);
      };
      Eigen::VectorXd R;
      // Converged to the tolerance: full Newton steps on to the round-off floor, so the
      // answer is the discrete root itself and not the first iterate inside the tolerance,
      // which depends on the starting point (a warm start may change the cost, never the
      // answer beyond round-off).
      auto polish_root = [&]() {
        if (!polish || !opt.polish) return;
        for (int k = 0; k < 3; ++k) {
          linearize_last_solve(false, KH, nullptr);
          const Eigen::MatrixXd J = model_.K + KH;
          if (k == 0) {
            // Only where the root is well conditioned (cond(J) < 1e6): with a nearly singular
            // Jacobian (e.g.
            // a very stiff pivot beside a soft film) the step is round-off amplified, not
            // removed, and the tolerance-converged point is kept.
            if (J.rows() > 200) return;
            std::vector<Eigen::Index> on;
            const Eigen::MatrixXd Ja = active_block(J, inactive_coordinates(J), on);
            if (on.empty()) return;  // J = 0: nothing to polish
            const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(Ja).singularValues();
            if (!(sv.size() > 0 && sv(sv.size() - 1) > 1e-6 * sv(0))) return;
          }
          const Eigen::VectorXd dr = newton_step(J, R);
          // Only a small correction (a well-conditioned Jacobian; in a nearly flat direction
          // the step would amplify round-off instead of removing it), and only while the
          // residual falls by half or more.
          const double scale = std::max(inf_norm(rs), 1e-300);
          if (!dr.allFinite() || inf_norm(dr) <= 1e-15 * scale || inf_norm(dr) > 1e-6 * scale)
            return;
          const Eigen::VectorXd r_try = rs + dr;
          Eigen::VectorXd H_try;
          try {
            H_try = film_forces(r_try, zero, omega);
          } catch (const ContactError&) {
            film_forces(rs, zero, omega);
            return;
          }
          const Eigen::VectorXd R_try = resid(r_try, H_try);
          const double res_try = inf_norm(R_try) / out.load_scale;
          if (!(res_try <= 0.5 * res)) {
            film_forces(rs, zero, omega);  // leave the films at the returned point
            return;
          }
          ++out.iterations;
          rs = r_try;
          H = H_try;
          R = R_try;
          res = res_try;
        }
      };
      try {
        H = film_forces(rs, zero, omega);
      } catch (const ContactError& e) {
        why = std::string("starting point: ") + e.what();
        return false;
      }
      R = resid(rs, H);
      res = inf_norm(R) / out.load_scale;
      // J: the Jacobian of this iterate when have_J (exact_J: formed at rs by linearisation;
      // else kept from earlier iterates with Broyden updates, or the caller's guess).
      Eigen::MatrixXd J;
      bool have_J = false, exact_J = false;
      if (reuse && have_guess) {
        J = model_.K + *kh_guess;
        have_J = true;
      }
      // Broyden's rank-one update J += (y − J s) sᵀ / sᵀs from a step s and R's change y; a
      // step that reduced ‖R‖ by less than reuse_contraction has J formed anew next time.
      auto update_J = [&](const Eigen::VectorXd& s, const Eigen::VectorXd& y, double ratio) {
        const double ss = s.squaredNorm();
        have_J = reuse && ss > 0.0 && ratio <= opt.reuse_contraction;
        if (!have_J) return;
        J.noalias() += ((y - J * s) / ss) * s.transpose();
        exact_J = false;
      };
      for (int it = 0; it < iters; ++it, ++out.iterations) {
        if (res < opt.tol) {
          polish_root();
          return true;
        }
        if (have_J && !exact_J) {
          // A reused Jacobian: its full step, kept when it reduces the residual; else the
          // films go back to rs and the exact Jacobian takes the (damped) step from there.
          const Eigen::VectorXd dr = newton_step(J, R);
          bool ok = dr.allFinite();
          Eigen::VectorXd r_try, H_try, R_try;
          double res_try = NAN;
          if (ok) {
            r_try = rs + dr;
            try {
              H_try = film_forces(r_try, zero, omega);
              R_try = resid(r_try, H_try);
              res_try = inf_norm(R_try) / out.load_scale;
              ok = res_try <= (1.0 - 1e-4) * res || res_try < opt.tol;
            } catch (const ContactError&) {
              ok = false;
            }
          }
          if (ok) {
            update_J(dr, R_try - R, res_try / res);
            rs = r_try;
            H = H_try;
            R = R_try;
            res = res_try;
            continue;
          }
          H = film_forces(rs, zero, omega);
          have_J = false;
        }
        if (!have_J) {
          linearize_last_solve(false, KH, nullptr);  // the films' last solve is at rs
          J = model_.K + KH;
          have_J = exact_J = true;
        }
        const Eigen::VectorXd dr = newton_step(J, R);
        if (!dr.allFinite()) {
          why = "Newton: singular Jacobian K + K_H";
          return false;
        }
        double t = 1.0;
        bool accepted = false;
        Eigen::VectorXd r_try;
        for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
          r_try = rs + t * dr;
          Eigen::VectorXd H_try;
          try {
            H_try = film_forces(r_try, zero, omega);
          } catch (const ContactError&) {
            continue;
          }
          const Eigen::VectorXd R_try = resid(r_try, H_try);
          const double res_try = inf_norm(R_try) / out.load_scale;
          if (res_try <= (1.0 - 1e-4 * t) * res || res_try < opt.tol) {
            update_J(t * dr, R_try - R, res_try / res);
            H = H_try;
            R = R_try;
            res = res_try;
            accepted = true;
            break;
          }
        }
        if (!accepted) {
          H = film_forces(rs, zero, omega);
          why = "Newton: line search failed (residual " + std::to_string(res) + ")";
          return false;
        }
        rs = r_try;
      }
      if (res < opt.tol) {
        polish_root();
        return true;
      }
      why = "Newton: no convergence in " + std::to_string(iters) + " iterations";
      return false;
    };

    double res = NAN;
    std::string why;
    Eigen::VectorXd rn = r;
    out.path = "newton";
    std::string why_pads;
    if (!pads_.empty()) {
      // Tilting pads: pad assembly first (each pad on its loaded branch, reduced Newton on
      // the rest; pad_equilibrium.cpp), then the full Newton below finishes and polishes.
      Eigen::VectorXd rp = r;
      int it = 0, unloaded = 0;
      if (pad_assembly(omega, F, out.load_scale, opt.tol, opt.max_iter, opt.joint_pad_solve, rp,
                       it, unloaded, why_pads)) {
        rn = rp;
        out.path = "pad_assembly";
        out.unloaded_pads = unloaded;
      }
      out.iterations += it;
    }
    if (newton(F, rn, opt.max_iter, res, why, true, opt.reuse_jacobian)) {
      if (!why_pads.empty() && out.path != "pad_assembly")
        out.message = why_pads + "; plain Newton from the start converged";
      return finish(rn, H, res);
    }
    if (!why_pads.empty()) why = why_pads + "; " + why;
    out.path = "load_continuation";
    // Fallback: continuation in the load and configuration, F(λ) = λ F from the concentric,
    // undeformed state (the solution at λ = 0), with adaptive steps.
    Eigen::VectorXd rc = zero;
    double lam = 0.0, dlam = 0.25, res_c = NAN;
    std::string why_c;
    while (lam < 1.0 && dlam > 1e-4 && out.iterations < 20 * opt.max_iter) {
      const double next = std::min(1.0, lam + dlam);
      Eigen::VectorXd rt = rc;
      if (newton(next * F, rt, 40, res_c, why_c, next >= 1.0, false)) {
        rc = rt;
        lam = next;
        dlam *= 1.5;
      } else {
        dlam *= 0.5;
      }
    }
    if (lam >= 1.0) {
      H = film_forces(rc, zero, omega);
      return finish(rc, H, inf_norm(model_.K * rc - H - F) / out.load_scale);
    }
    // No equilibrium reached: report where the continuation stopped.
    try {
      H = film_forces(lam > 0 ? rc : rn, zero, omega);
    } catch (const ContactError&) {
    }
    const Eigen::VectorXd rf = lam > 0 ? rc : rn;
    out.status = "not_converged";
    out.message = why + "; load continuation reached " + std::to_string(lam) +
                  " of the load (" + why_c + ")";
    return finish(rf, H, inf_norm(model_.K * rf - H - F) / out.load_scale);
  }

  // Successive substitution, eq. 16: (1 + P_m) K r_{i+1} = P_m K r_i + H(r_i) + F.
  out.path = "successive";
  Eigen::PartialPivLU<Eigen::MatrixXd> Klu(model_.K);
  const double rc = 1.0 / (model_.K.cwiseAbs().rowwise().sum().maxCoeff() *
                           Klu.inverse().cwiseAbs().rowwise().sum().maxCoeff());
  require(std::isfinite(rc) && rc > 1e-14,
          "method: successive substitution needs a non-singular structural stiffness K "
          "(rigid or linear supports); use method='newton'");
  Eigen::VectorXd H;
  double pm = opt.pm;
  try {
    if (pm < 0) {
      // Automatic P_m: the iteration map's Jacobian is (P_m I − K⁻¹K_H)/(1 + P_m); choose
      // P_m to minimise its spectral radius max|P_m − μ_i|/(1 + P_m) over the eigenvalues μ_i
      // of K⁻¹K_H at the starting point (golden-section search on log P_m).
      H = film_forces(r, zero, omega);
      Eigen::MatrixXd KH;
      linearize_last_solve(false, KH, nullptr);
      const Eigen::VectorXcd mu = Eigen::EigenSolver<Eigen::MatrixXd>(Klu.solve(KH),
                                                                      false).eigenvalues();
      auto rho = [&](double lp) {
        const double p = std::exp(lp);
        double m = 0;
        for (Eigen::Index i = 0; i < mu.size(); ++i) m = std::max(m, std::abs(p - mu(i)) / (1 + p));
        return m;
      };
      double a = std::log(1e-3), b = std::log(1e9);
      const double g = 0.5 * (std::sqrt(5.0) - 1);
      for (int it = 0; it < 100; ++it) {
        const double c1 = b - g * (b - a), c2 = a + g * (b - a);
        if (rho(c1) < rho(c2)) b = c2; else a = c1;
      }
      pm = std::exp(0.5 * (a + b));
    } else {
      H = film_forces(r, zero, omega);
    }
  } catch (const ContactError& e) {
    out.status = "no_equilibrium";
    out.message = std::string("starting point: ") + e.what();
    return finish(r, zero, NAN);
  }
  out.pm = pm;
  double res = inf_norm(residual(r, H)) / out.load_scale;
  const int max_it = 500 * opt.max_iter;  // the relaxation converges linearly, slowly
  const int window = 200;
  double res_window = res;
  bool stalled = false;
  for (out.iterations = 0; out.iterations < max_it; ++out.iterations) {
    if (res < opt.tol) return finish(r, H, res);
    const Eigen::VectorXd target = Klu.solve(H + F);
    Eigen::VectorXd step = (target - r) / (1.0 + pm);
    bool ok = false;
    for (int ls = 0; ls < 40; ++ls, step *= 0.5) {
      try {
        H = film_forces(r + step, zero, omega);
        ok = true;
        break;
      } catch (const ContactError&) {
      }
    }
    if (!ok) {
      out.status = "no_equilibrium";
      out.message = "successive substitution: every step ends in contact";
      H = film_forces(r, zero, omega);
      return finish(r, H, res);
    }
    r += step;
    res = inf_norm(residual(r, H)) / out.load_scale;
    if (!std::isfinite(res)) break;
    // Stall check every `window` iterations (issue 13: a slow relaxation ran 50 000 Reynolds
    // solves, over a minute): from the observed linear rate, the iterations still needed to
    // reach tol; stop when that is more than twice the remaining budget (or no progress).
    if ((out.iterations + 1) % window == 0) {
      const double rate = std::pow(res / res_window, 1.0 / window);
      const double needed = rate < 1.0 ? std::log(opt.tol / res) / std::log(rate) : INFINITY;
      if (res >= opt.tol && needed > 2.0 * (max_it - out.iterations)) {
        stalled = true;
        out.message = "successive substitution: too slow (residual " + std::to_string(res) +
                      " after " + std::to_string(out.iterations + 1) +
                      " iterations, rate " + std::to_string(rate) +
                      " per iteration); try a larger P_m or method='newton'";
        ++out.iterations;
        break;
      }
      res_window = res;
    }
  }
  out.status = res < opt.tol ? "ok" : "not_converged";
  if (out.status != "ok" && !stalled)
    out.message = "successive substitution: no convergence in " + std::to_string(max_it) +
                  " iterations (try a larger P_m)";
  return finish(r, H, res);
}

}  // namespace rotordyn
