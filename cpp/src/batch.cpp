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

/// The start of point i continued along a line from its two predecessors' equilibria
/// r1 (point i-1) and r2 (point i-2): linear extrapolation r1 + s (r1 - r2) when the point's
/// inputs (omega, pressure, a) step from i-1 to i by s times their step from i-2 to i-1 (one
/// straight line through the inputs, 0 < s <= 2: a line of a grid axis, uniform or not),
/// else r1 itself. The Newton iteration is polished to the discrete root (round-off), so
/// the start changes the cost, not the answer.
Eigen::VectorXd line_start(const StabilityBatchInput& in, Eigen::Index i,
                           const Eigen::VectorXd& r1, const Eigen::VectorXd* r2) {
  if (r2 == nullptr || i < 2) return r1;
  const Eigen::Index n = in.a.cols();
  double s = 0.0;
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
  step(in.omega[i - 2], in.omega[i - 1], in.omega[i]);
  step(in.pressure[i - 2], in.pressure[i - 1], in.pressure[i]);
  for (Eigen::Index j = 0; j < n && line; ++j) step(in.a(i - 2, j), in.a(i - 1, j), in.a(i, j));
  if (!line || !have || !(s > 0.0 && s <= 2.0)) return r1;
  return r1 + s * (r1 - *r2);
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
  const Eigen::Index k = in.n_modes > 0 ? std::min<Eigen::Index>(in.n_modes, n) : n;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  StabilityBatchResult out;
  out.status.assign(np, "error");
  out.message.assign(np, "");
  out.iterations = Eigen::VectorXi::Zero(np);
  out.r = RowMatrixXd::Constant(np, n, nan);
  out.h_min = RowMatrixXd::Constant(np, static_cast<Eigen::Index>(m.films.size()), nan);
  out.n_eig = Eigen::VectorXi::Zero(np);
  out.eigenvalues = Eigen::MatrixXcd::Constant(np, k, std::complex<double>(nan, nan));
  out.whirl = Eigen::MatrixXi::Zero(np, k);
  out.sleeve_share = RowMatrixXd::Constant(np, k, nan);
  out.modes.resize(np);
  // Continuation along a line: prev (point i-1) and, when i-2 is on the same line and
  // converged too, prev2 for a linearly extrapolated start (line_start); a start that fails
  // is retried from prev itself, so extrapolation never loses an equilibrium the plain
  // continuation finds.
  Eigen::VectorXd prev, prev2;
  bool have_prev = false, have_prev2 = false;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < np; ++i) {
    const double w = in.omega[i];
    try {
      const Eigen::VectorXd a = in.a.row(i).transpose();
      const bool cont = in.restart[i] == 0 && have_prev;
      const bool two = cont && have_prev2;
      const Eigen::VectorXd r0 =
          cont ? line_start(in, i, prev, two ? &prev2 : nullptr) : Eigen::VectorXd();
      EquilibriumResult e = solver.equilibrium(w, in.pressure[i], a, r0, in.options);
      int extra = 0;
      if (two && e.status != "ok" && e.status != "contact") {
        extra = e.iterations;
        e = solver.equilibrium(w, in.pressure[i], a, prev, in.options);
      }
      out.status[i] = e.status;
      out.message[i] = e.message;
      out.iterations[i] = e.iterations + extra;
      have_prev2 = cont && e.status == "ok";
      if (have_prev2) prev2 = prev;
      have_prev = e.status == "ok";
      if (have_prev) prev = e.r;
      for (std::size_t f = 0; f < e.h_min.size() && f < m.films.size(); ++f)
        out.h_min(i, static_cast<Eigen::Index>(f)) = e.h_min[f];
      if (e.status != "ok" && e.status != "contact") continue;
      out.r.row(i) = e.r.transpose();
      Linearization lin = in.finite_difference ? solver.linearize_fd(e.r, w, in.fd_step)
                                               : solver.linearize(e.r, zero, w);
      const Eigen::MatrixXd D = m.C + w * m.G + lin.DH;
      const Eigen::MatrixXd K = m.K + lin.KH;
      if (!D.allFinite() || !K.allFinite()) {
        out.status[i] = "error";
        out.message[i] = "non-finite bearing coefficients";
        continue;
      }
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
    } catch (const std::exception& ex) {
      out.status[i] = "error";
      out.message[i] = ex.what();
      have_prev = have_prev2 = false;
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
      out.residual[i] = e.residual;
      out.r.row(i) = e.r.transpose();
      for (std::size_t f = 0; f < e.h_min.size() && static_cast<Eigen::Index>(f) < nf; ++f)
        out.h_min(i, static_cast<Eigen::Index>(f)) = e.h_min[f];
      for (std::size_t f = 0; f < e.h_min_z_m.size() && static_cast<Eigen::Index>(f) < nf; ++f)
        out.h_min_z_m(i, static_cast<Eigen::Index>(f)) = e.h_min_z_m[f];
      have_prev = e.status == "ok";
      if (have_prev) prev = e.r;
    } catch (const std::exception& ex) {
      out.status[i] = "error";
      out.message[i] = ex.what();
      have_prev = false;
    }
  }
  return out;
}

}  // namespace rotordyn
