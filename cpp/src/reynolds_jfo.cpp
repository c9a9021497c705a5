// Mass-conserving cavitation (Jakobsson–Floberg–Olsson / Elrod–Adams, p–θ complementarity).
//
// Each film cell balances Poiseuille outflow, the Couette flux (ωR/2)·h_f·θ_upwind and the
// storage θ ∂h/∂t (quasi-static in θ). Unknowns: p ≥ 0 and r = 1 − θ ≥ 0 with p·r = 0. With the
// partition into pressurised (r = 0) and cavitated (p = 0) cells the balance is a linear
// system M u = b whose column i is A's column (u_i = p_i) or the Couette column of r_i; the
// partition is updated as in a semismooth Newton step on the piecewise-linear equation
// F(u) = A max(u,0) − B max(−u,0) − b = 0 (Giacopini et al. 2010; Almqvist et al. 2014 give the
// LCP form). Started from the Swift–Stieber solution, or from the previous partition.
#include <algorithm>
#include <cmath>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

void ReynoldsSolver::Impl::fill_jfo() {
  double* val = A.valuePtr();
  const bool fwd = omega >= 0.0;
  for (int i = 0; i < n_unk; ++i) {
    const int n = node_of[i];
    const ColPos& q = pos[i];
    const int w = west(n);
    if (!active[i]) {  // pressure column
      val[q.diag] = cE[n] + cE[w] + cN[n] + cN[n - 1];
      if (q.e >= 0) val[q.e] = -cE[n];
      if (q.w >= 0) val[q.w] = -cE[w];
      if (q.n >= 0) val[q.n] = -cN[n];
      if (q.s >= 0) val[q.s] = -cN[n - 1];
      continue;
    }
    // r = 1 − θ column: −(Couette out of this cell) here, + into the downstream cell.
    if (q.n >= 0) val[q.n] = 0.0;
    if (q.s >= 0) val[q.s] = 0.0;
    if (fwd) {
      val[q.diag] = -(qE[n] + src[n]);
      if (q.e >= 0) val[q.e] = qE[n];
      if (q.w >= 0) val[q.w] = 0.0;
    } else {
      val[q.diag] = qE[w] - src[n];
      if (q.w >= 0) val[q.w] = -qE[w];
      if (q.e >= 0) val[q.e] = 0.0;
    }
  }
}

void ReynoldsSolver::Impl::solve_jfo() {
  if (omega == 0.0)
    throw InputError("speed_hz: cavitation='jfo' needs a nonzero speed (got 0)");
  std::fill(theta.begin(), theta.end(), 1.0);
  int it0 = 0;
  if (!have_active) {  // start from the Swift–Stieber solution
    solve_reynolds();
    it0 = out.iterations;
  }
  base_rhs(rhs);
  std::vector<char> next(n_unk);
  const int max_iter = 100 + n_unk / 4;
  for (int it = 1; it <= max_iter; ++it) {
    fill_jfo();
    if (!lu_analysed) {
      lu.analyzePattern(A);
      lu_analysed = true;
    }
    lu.factorize(A);
    if (lu.info() != Eigen::Success)
      throw ConvergenceError("jfo cavitation: sparse LU factorisation failed");
    factor = Factor::lu;
    sol = lu.solve(rhs);
    double pscale = 0.0;
    for (int i = 0; i < n_unk; ++i) {
      const int n = node_of[i];
      if (active[i]) {
        p[n] = 0.0;
        theta[n] = 1.0 - sol[i];
      } else {
        p[n] = sol[i];
        theta[n] = 1.0;
        pscale = std::max(pscale, std::abs(sol[i]));
      }
    }
    for (int n = 0; n < n_nodes; ++n)
      if (unk[n] < 0) pscale = std::max(pscale, std::abs(p[n]));
    const double tol_p = 1e-13 * pscale;
    bool changed = false;
    for (int i = 0; i < n_unk; ++i) {
      next[i] = active[i] ? (sol[i] >= -1e-13 ? 1 : 0) : (sol[i] < -tol_p ? 1 : 0);
      if (next[i] != active[i]) changed = true;
    }
    if (!changed) {
      for (int n = 0; n < n_nodes; ++n) pfull[n] = p[n];
      have_active = true;
      out.iterations = it0 + it;
      return;
    }
    active.swap(next);
  }
  have_active = false;
  throw ConvergenceError("jfo cavitation: p-theta partition did not converge in " +
                         std::to_string(max_iter) + " iterations");
}

}  // namespace rotordyn
