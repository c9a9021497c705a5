// Stability batch of a sweep chunk (see batch.hpp).
#include "rotordyn/batch.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include "rotordyn/errors.hpp"
#include "rotordyn/modal.hpp"

namespace rotordyn {

namespace {

/// The ratio s of the step of the inputs (omega, pressure, a) from point i1 to i2 to their
/// step from i0 to i1 when the three points lie on one straight line through the inputs (every
/// moving input steps by the same ratio, the others stay): true and s, else false.
bool step_ratio(const StabilityBatchInput& in, Eigen::Index i0, Eigen::Index i1,
                Eigen::Index i2, double& s) {
  bool have = false, line = true;
  auto step = [&](double x0, double x1, double x2) {
    const double d0 = x1 - x0, d1 = x2 - x1;
    const double scale = std::max({std::abs(x0), std::abs(x1), std::abs(x2), 1e-300});
    if (std::abs(d0) <= 1e-12 * scale) {
      if (std::abs(d1) > 1e-12 * scale) line = false;  // a kink: this input starts moving
      return;
    }
    const double si = d1 / d0;
    if (!have) {
      s = si;
      have = true;
    } else if (std::abs(si - s) > 1e-9 * std::max(std::abs(s), 1.0)) {
      line = false;
    }
  };
  step(in.omega[i0], in.omega[i1], in.omega[i2]);
  step(in.pressure[i0], in.pressure[i1], in.pressure[i2]);
  for (Eigen::Index j = 0; j < in.a.cols() && line; ++j)
    step(in.a(i0, j), in.a(i1, j), in.a(i2, j));
  return line && have && s > 0.0 && s <= 2.0;
}

/// The start of point i continued along a line from the equilibria of its predecessors on
/// it, hist = {r(i-1), r(i-2), r(i-3)} (as many as converged in a row, 1 to 3): the
/// polynomial through them in the line's parameter (quadratic from three, linear from two),
/// evaluated at point i, when the points lie on one straight line through the inputs with
/// steps of ratio in (0, 2] (a grid axis, uniform or not); else r(i-1) itself. The Newton
/// iteration is polished to the discrete root where the Jacobian is well conditioned, so the
/// start changes the cost, and otherwise the answer within the equilibrium tolerance only.
Eigen::VectorXd line_start(const StabilityBatchInput& in, Eigen::Index i,
                           const std::vector<Eigen::VectorXd>& hist) {
  double s = 0.0, q = 0.0;
  if (hist.size() < 2 || !step_ratio(in, i - 2, i - 1, i, s)) return hist[0];
  if (hist.size() < 3 || !step_ratio(in, i - 3, i - 2, i - 1, q))
    return hist[0] + s * (hist[0] - hist[1]);
  // Lagrange through t = -1/q (i-3), 0 (i-2), 1 (i-1), evaluated at T = 1 + s (i).
  const double t0 = -1.0 / q, T = 1.0 + s;
  const double l3 = T * (T - 1.0) / (t0 * (t0 - 1.0));
  const double l2 = (T - t0) * (T - 1.0) / t0;
  const double l1 = (T - t0) * T / (1.0 - t0);
  return l1 * hist[0] + l2 * hist[1] + l3 * hist[2];
}

bool converged(const std::string& status) { return status == "ok" || status == "contact"; }

/// The one rule for a failed point of either batch (its equilibrium not "ok"/"contact", or
/// any stage raised: "error"): every numeric output of the point NaN — the equilibrium, the
/// minimum films and their z, H; the residual of the equilibrium batch; the eigenvalues and
/// sleeve shares of the stability batch, with n_eig 0, whirl 0 and no modes — and a message
/// (the status itself when the solver gave none). The iteration count (the work done) stays.
template <class Result>
void fail_common(Result& out, Eigen::Index i) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.r.row(i).setConstant(nan);
  out.h_min.row(i).setConstant(nan);
  out.h_min_z_m.row(i).setConstant(nan);
  out.film_force.row(i).setConstant(nan);
  if (out.message[static_cast<std::size_t>(i)].empty())
    out.message[static_cast<std::size_t>(i)] = "no equilibrium (" +
                                               out.status[static_cast<std::size_t>(i)] + ")";
}

void fail_point(StabilityBatchResult& out, Eigen::Index i) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  fail_common(out, i);
  out.n_eig[i] = 0;
  out.eigenvalues.row(i).setConstant(std::complex<double>(nan, nan));
  out.whirl.row(i).setZero();
  out.sleeve_share.row(i).setConstant(nan);
  out.modes[static_cast<std::size_t>(i)] = Eigen::MatrixXcd();
  out.least_stable[i] = std::complex<double>(nan, nan);
  out.max_real[i] = nan;
}

/// The root with the largest real part, Re λ within the round-off band kRoundOffRel counted
/// as 0 (rotordyn.results.modes.settled_real); NaN when there is none.
std::complex<double> least_stable_root(const Eigen::VectorXcd& roots) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::complex<double> best(nan, nan);
  double key_best = -std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < roots.size(); ++j) {
    const double key = settled_real(roots[j]);
    if (key > key_best || std::isnan(best.real())) {
      key_best = key;
      best = roots[j];
    }
  }
  return best;
}

void fail_point(EquilibriumBatchResult& out, Eigen::Index i) {
  fail_common(out, i);
  out.residual[i] = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

StabilityBatchResult stability_batch(SystemSolver& solver, const StabilityBatchInput& in) {
  const Eigen::Index np = in.omega.size();
  const SystemModel& m = solver.model();
  const Eigen::Index n = m.n();
  if (in.pressure.size() != np || in.a.rows() != np || in.a.cols() != n ||
      static_cast<Eigen::Index>(in.restart.size()) != np) {
    throw InputError("stability_batch: expected omega, pressure, restart of length n_pts and "
                     "a of shape (n_pts, n)");
  }
  if (in.jacobian != "exact" && in.jacobian != "reuse" && in.jacobian != "line")
    throw InputError("jacobian: expected 'exact', 'reuse' or 'line', got '" + in.jacobian + "'");
  EquilibriumOptions opt = in.options;
  if (in.jacobian != "exact") opt.reuse_jacobian = true;
  const bool line_jacobian = in.jacobian == "line";
  const Eigen::Index k = in.n_modes > 0 ? std::min<Eigen::Index>(in.n_modes, n) : n;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  StabilityBatchResult out;
  out.status.assign(np, "error");
  out.message.assign(np, "");
  out.iterations = Eigen::VectorXi::Zero(np);
  out.r = RowMatrixXd::Constant(np, n, nan);
  out.h_min = RowMatrixXd::Constant(np, static_cast<Eigen::Index>(m.films.size()), nan);
  out.h_min_z_m = out.h_min;
  out.film_force = RowMatrixXd::Constant(np, n, nan);
  out.n_eig = Eigen::VectorXi::Zero(np);
  out.eigenvalues = Eigen::MatrixXcd::Constant(np, k, std::complex<double>(nan, nan));
  out.whirl = Eigen::MatrixXi::Zero(np, k);
  out.sleeve_share = RowMatrixXd::Constant(np, k, nan);
  out.modes.resize(np);
  out.least_stable = Eigen::VectorXcd::Constant(np, std::complex<double>(nan, nan));
  out.max_real = Eigen::VectorXd::Constant(np, nan);
  // Continuation along a line: hist holds the equilibria of the points before i on its line
  // that converged ("ok") in a row, newest first (at most 3), for an extrapolated start
  // (line_start); an extrapolated start that fails is retried from hist[0] itself, so
  // extrapolation never loses an equilibrium the plain continuation finds.
  std::vector<Eigen::VectorXd> hist;
  // K_H of hist[0] (the previous point's, from its stability analysis): the first Newton
  // Jacobian of the next point with jacobian "line"; empty when hist is.
  Eigen::MatrixXd kh_prev;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  // The films' cavitation sets carried along a line (in.carry_cavitation), forgotten at each
  // line's start and when the call returns (also by an exception), so a line's results
  // depend on its own points only.
  struct Carry {
    SystemSolver& s;
    bool on;
    ~Carry() {
      if (on) s.set_film_carry(false);
    }
  } carry{solver, in.carry_cavitation && !solver.film_carry()};
  for (Eigen::Index i = 0; i < np; ++i) {
    const double w = in.omega[i];
    try {
      const Eigen::VectorXd a = in.a.row(i).transpose();
      if (in.restart[i] != 0 || i == 0) {
        hist.clear();
        if (carry.on) solver.set_film_carry(true);  // forgets the previous line's sets
      }
      const Eigen::VectorXd r0 = hist.empty() ? Eigen::VectorXd() : line_start(in, i, hist);
      const bool extrapolated = hist.size() >= 2 && (r0.array() != hist[0].array()).any();
      if (hist.empty()) kh_prev.resize(0, 0);
      EquilibriumResult e = solver.equilibrium(w, in.pressure[i], a, r0, opt,
                                               line_jacobian ? &kh_prev : nullptr);
      int extra = 0;
      if (extrapolated && e.status != "ok" && e.status != "contact") {
        extra = e.iterations;
        e = solver.equilibrium(w, in.pressure[i], a, hist[0], in.options);
      }
      out.status[i] = e.status;
      out.message[i] = e.message;
      out.iterations[i] = e.iterations + extra;
      if (e.status == "ok") {
        hist.insert(hist.begin(), e.r);
        if (hist.size() > 3) hist.pop_back();
        kh_prev.resize(0, 0);  // this point's K_H, once it is formed and finite
      } else {
        hist.clear();
        kh_prev.resize(0, 0);
      }
      if (!converged(e.status)) {
        fail_point(out, i);
        continue;
      }
      for (std::size_t f = 0; f < e.h_min.size() && f < m.films.size(); ++f)
        out.h_min(i, static_cast<Eigen::Index>(f)) = e.h_min[f];
      out.r.row(i) = e.r.transpose();
      if (e.film_force.size() == n) out.film_force.row(i) = e.film_force.transpose();
      for (std::size_t f = 0; f < e.h_min_z_m.size() && f < m.films.size(); ++f)
        out.h_min_z_m(i, static_cast<Eigen::Index>(f)) = e.h_min_z_m[f];
      Linearization lin = in.finite_difference ? solver.linearize_fd(e.r, w, in.fd_step)
                                               : solver.linearize(e.r, zero, w);
      const Eigen::MatrixXd D = m.C + w * m.G + lin.DH;
      const Eigen::MatrixXd K = m.K + lin.KH;
      if (!D.allFinite() || !K.allFinite()) {
        out.status[i] = "error";
        out.message[i] = "non-finite bearing coefficients";
        fail_point(out, i);
        continue;
      }
      if (e.status == "ok" && line_jacobian) kh_prev = lin.KH;
      const Eigen::MatrixXd Mw = m.has_table_mass() ? m.mass_at(w) : m.M;  // table masses
      ModalResult mr = modal(Mw, D, K, in.xy_pairs, static_cast<int>(k), true, in.rot_pairs);
      const Eigen::Index ke = mr.eigenvalues.size();
      out.n_eig[i] = static_cast<int>(ke);
      for (Eigen::Index j = 0; j < ke; ++j) {
        out.eigenvalues(i, j) = mr.eigenvalues[j];
        out.whirl(i, j) = static_cast<int>(mr.whirl[static_cast<std::size_t>(j)]);
        const Eigen::VectorXcd phi = mr.modes.col(j);
        const double kin = (phi.adjoint() * Mw * phi).real()(0, 0);
        double ks = 0.0;
        for (int p : in.sleeve)
          for (int q : in.sleeve) ks += (std::conj(phi[p]) * Mw(p, q) * phi[q]).real();
        out.sleeve_share(i, j) = kin > 0 ? ks / kin : 0.0;
      }
      out.modes[static_cast<std::size_t>(i)] = std::move(mr.modes);
      // the verdict over every root: the kept ones when they are all, else all of them
      // (eigenvalues only) — a mode above the n_modes cut can be the unstable one
      const Eigen::VectorXcd all =
          k < n ? modal(Mw, D, K, in.xy_pairs, 0, false, in.rot_pairs).eigenvalues
                : Eigen::VectorXcd(mr.eigenvalues);
      out.least_stable[i] = least_stable_root(all);
      if (all.size()) out.max_real[i] = all.real().maxCoeff();
    } catch (const std::exception& ex) {
      out.status[i] = "error";
      out.message[i] = ex.what();
      fail_point(out, i);
      hist.clear();
      kh_prev.resize(0, 0);
    }
  }
  return out;
}

EquilibriumBatchResult equilibrium_batch(SystemSolver& solver, const StabilityBatchInput& in) {
  const Eigen::Index np = in.omega.size();
  const Eigen::Index n = solver.model().n();
  if (in.pressure.size() != np || in.a.rows() != np || in.a.cols() != n ||
      static_cast<Eigen::Index>(in.restart.size()) != np) {
    throw InputError("equilibrium_batch: expected omega, pressure, restart of length n_pts "
                     "and a of shape (n_pts, n)");
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto nf = static_cast<Eigen::Index>(solver.model().films.size());
  EquilibriumBatchResult out;
  out.status.assign(np, "error");
  out.message.assign(np, "");
  out.iterations = Eigen::VectorXi::Zero(np);
  out.residual = Eigen::VectorXd::Constant(np, nan);
  out.r = RowMatrixXd::Constant(np, n, nan);
  out.h_min = RowMatrixXd::Constant(np, nf, nan);
  out.h_min_z_m = RowMatrixXd::Constant(np, nf, nan);
  out.film_force = RowMatrixXd::Constant(np, n, nan);
  Eigen::VectorXd prev;
  bool have_prev = false;
  for (Eigen::Index i = 0; i < np; ++i) {
    try {
      const Eigen::VectorXd a = in.a.row(i).transpose();
      const Eigen::VectorXd r0 = (in.restart[i] == 0 && have_prev) ? prev : Eigen::VectorXd();
      EquilibriumResult e = solver.equilibrium(in.omega[i], in.pressure[i], a, r0, in.options);
      out.status[i] = e.status;
      out.message[i] = e.message;
      out.iterations[i] = e.iterations;
      have_prev = e.status == "ok";
      if (have_prev) prev = e.r;
      if (!converged(e.status)) {
        fail_point(out, i);
        continue;
      }
      out.residual[i] = e.residual;
      out.r.row(i) = e.r.transpose();
      if (e.film_force.size() == n) out.film_force.row(i) = e.film_force.transpose();
      for (std::size_t f = 0; f < e.h_min.size() && static_cast<Eigen::Index>(f) < nf; ++f)
        out.h_min(i, static_cast<Eigen::Index>(f)) = e.h_min[f];
      for (std::size_t f = 0; f < e.h_min_z_m.size() && static_cast<Eigen::Index>(f) < nf; ++f)
        out.h_min_z_m(i, static_cast<Eigen::Index>(f)) = e.h_min_z_m[f];
    } catch (const std::exception& ex) {
      out.status[i] = "error";
      out.message[i] = ex.what();
      fail_point(out, i);
      have_prev = false;
    }
  }
  return out;
}

}  // namespace rotordyn
