// Mass-conserving cavitation (Jakobsson–Floberg–Olsson / Elrod–Adams, p–θ complementarity).
//
// Each film cell balances Poiseuille outflow, the Couette flux (ωR/2)·h_f·θ_upwind and the
// storage θ ∂h/∂t (quasi-static in θ). Unknowns: p ≥ 0 and r = 1 − θ ≥ 0 with p·r = 0. With the
// partition into pressurised (r = 0) and cavitated (p = 0) cells the balance is a linear
// system M u = b whose column i is A's column (u_i = p_i) or the Couette column of r_i; the
// partition is updated as in a semismooth Newton step on the piecewise-linear equation
// F(u) = A max(u,0) − B max(−u,0) − b = 0 (Giacopini et al. 2010; Almqvist et al. 2014 give the
// LCP form). Started from this call's Swift–Stieber solution (no warm start).
#include <algorithm>
#include <cmath>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

void ReynoldsSolver::Impl::fill_jfo(LinearSystem& S) {
  double* val = S.A.valuePtr();
  const bool fwd = omega >= 0.0;
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    const LinearSystem::ColPos& q = S.pos[i];
    const int w = west(n);
    const double wp = S.wphi[i];
    if (!S.active[i]) {  // pressure column
      val[q.diag] = wp * (cE[n] + cE[w]) + (S.has_n[i] ? cN[n] : 0.0) + cN[n - 1];
      if (q.e >= 0) val[q.e] = -wp * cE[n];
      if (q.w >= 0) val[q.w] = -wp * cE[w];
      if (q.n >= 0) val[q.n] = -cN[n];
      if (q.s >= 0) val[q.s] = -cN[n - 1];
      continue;
    }
    // r = 1 − θ column: −(Couette out of this cell) here, + into the downstream cell.
    if (q.n >= 0) val[q.n] = 0.0;
    if (q.s >= 0) val[q.s] = 0.0;
    if (fwd) {
      val[q.diag] = -wp * (qE[n] + src[n]);
      if (q.e >= 0) val[q.e] = wp * qE[n];
      if (q.w >= 0) val[q.w] = 0.0;
    } else {
      val[q.diag] = wp * (qE[w] - src[n]);
      if (q.w >= 0) val[q.w] = -wp * qE[w];
      if (q.e >= 0) val[q.e] = 0.0;
    }
  }
}

void ReynoldsSolver::Impl::factor_solve_jfo(LinearSystem& S, const Eigen::VectorXd& b,
                                            Eigen::VectorXd& x) {
  x.resize(S.n_unk);
  if (S.ldlt.factorize_lu(S.A.valuePtr())) {
    S.factor = LinearSystem::Factor::static_lu;
    S.ldlt.solve_lu(b.data(), x.data());
    const double res = (S.A * x - b).norm();
    if (std::isfinite(res) && res <= 1e-10 * std::max(b.norm(), 1e-300)) return;
  }
  if (!S.lu_analysed) {
    S.lu.analyzePattern(S.A);
    S.lu_analysed = true;
  }
  S.lu.factorize(S.A);
  if (S.lu.info() != Eigen::Success)
    throw ConvergenceError("jfo cavitation: sparse LU factorisation failed");
  S.factor = LinearSystem::Factor::lu;
  x = S.lu.solve(b);
}

void ReynoldsSolver::Impl::solve_factored(const LinearSystem& S, const Eigen::VectorXd& b,
                                          Eigen::VectorXd& x) const {
  x.resize(S.n_unk);
  switch (S.factor) {
    case LinearSystem::Factor::ldlt:
    case LinearSystem::Factor::band:
      S.solve_spd(b.data(), x.data());
      break;
    case LinearSystem::Factor::static_lu:
      S.ldlt.solve_lu(b.data(), x.data());
      break;
    case LinearSystem::Factor::lu:
      x = S.lu.solve(b);
      break;
    case LinearSystem::Factor::none:
      throw ConvergenceError("Reynolds solver: no factorisation available");
  }
}

void ReynoldsSolver::Impl::solve_jfo(LinearSystem& S) {
  if (omega == 0.0)
    throw InputError("speed_hz: cavitation='jfo' needs a nonzero speed (got 0)");
  std::fill(theta.begin(), theta.end(), 1.0);
  // Always start from this call's Swift–Stieber solution (itself started from a prediction
  // of the inputs only): no state of an earlier call enters the answer or its convergence.
  solve_reynolds(S);
  const int it0 = out.iterations;
  base_rhs(S, S.rhs);
  if (groove_theta != 1.0) {
    // A starved groove (reynolds_starved.cpp): its nodes hold p = 0 and the fill θ_in, so the
    // Couette flux a groove node sends into its downstream cell is (ωRΔz/2)·h_f·θ_in instead
    // of the full film's: b_i − (1 − θ_in)·(that flux) (the cell balance of cell_residual).
    const double d = 1.0 - groove_theta;
    for (const int g : groove_nodes) theta[g] = groove_theta;
    const bool fwd = omega >= 0.0;
    for (int i = 0; i < S.n_unk; ++i) {
      const int n = S.node_of[i];
      if (fwd && groove[west(n)]) S.rhs[i] -= S.wphi[i] * d * qE[west(n)];
      if (!fwd && groove[east(n)]) S.rhs[i] += S.wphi[i] * d * qE[n];
    }
  }
  std::vector<char> next(S.n_unk);
  const int max_iter = 100 + S.n_unk / 4;
  for (int it = 1; it <= max_iter; ++it) {
    fill_jfo(S);
    factor_solve_jfo(S, S.rhs, S.sol);
    double pscale = 0.0;
    for (int i = 0; i < S.n_unk; ++i) {
      const int n = S.node_of[i];
      if (S.active[i]) {
        p[n] = 0.0;
        theta[n] = 1.0 - S.sol[i];
      } else {
        p[n] = S.sol[i];
        theta[n] = 1.0;
        pscale = std::max(pscale, std::abs(S.sol[i]));
      }
    }
    for (int n = 0; n < n_nodes; ++n)
      if (fixed[n]) pscale = std::max(pscale, std::abs(p[n]));
    const double tol_p = 1e-13 * pscale;
    bool changed = false;
    for (int i = 0; i < S.n_unk; ++i) {
      next[i] = S.active[i] ? (S.sol[i] >= -1e-13 ? 1 : 0) : (S.sol[i] < -tol_p ? 1 : 0);
      if (next[i] != S.active[i]) changed = true;
    }
    if (!changed) {
      if (S.half) mirror_fields();
      for (int n = 0; n < n_nodes; ++n) pfull[n] = p[n];
      out.iterations = it0 + it;
      return;
    }
    S.active.swap(next);
  }
  throw ConvergenceError("jfo cavitation: p-theta partition did not converge in " +
                         std::to_string(max_iter) + " iterations");
}

}  // namespace rotordyn
