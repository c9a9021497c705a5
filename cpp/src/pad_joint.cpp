// A spherical pad's coordinates (tilt[, pivot], pitch) solved together: a safeguarded Newton on
// the pad's 2–3 residuals with its own Jacobian (film stiffness over its columns plus the
// structural K_gg), started from the current guess (inside one pad assembly, the reduced
// Newton's prediction). It replaces the nested solves of pad_equilibrium.cpp (pitch ⊃ pivot ⊃
// tilt: every pitch trial re-solves the tilt, and the pivot's) where they would end at the same
// point: a pressured pad whose Jacobian is restoring — every leading principal minor > 0, i.e.
// the tilt's ∂R/∂δ > 0 (the tilt solve's loaded-branch root), the pivot's and the pitch's Schur
// derivatives > 0 (the increasing f(u) and f(γ) the nested solves bracket) — so that the root
// is the nested solves' root to the tolerance. Anything else hands back to the nested solves
// from the same start (rc restored): a pad pressure-free or only lightly loaded at a trial
// point (peak pressure below 1e-3 of μ|Ω s|(R/C)²: near its pressure-free set the nested
// solves' defined choice — the boundary of that set, or γ_def — decides), a trial that pinches the
// film below kPinch·C or closes it, a Jacobian that is not restoring, a step with no decrease
// of the scaled residual after five halvings, or no convergence in 8 steps. The start is the
// nested solves' own start, so the answer stays a function of the same inputs.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "pad_detail.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

int SystemSolver::PadSolve::joint(const FilmCoupling& fc) {
  constexpr int kMaxSteps = 8, kHalvings = 5;
  const int n = m();
  const Eigen::VectorXd start = rc;
  const double C = fc.geometry.clearance_m, pinch = pad_detail::kPinch * C;
  // coordinate scales: C for the tilt (η) and the pivot, and the pitch that moves an edge by C;
  // the merit max_k |R_k|·scale_k compares the rows' work (N·m) instead of N against N·m
  Eigen::Vector3d scale = Eigen::Vector3d::Constant(C);
  scale(n - 1) = C / (0.5 * fc.geometry.length_m);
  // a clearly loaded pad only: peak pressure ≥ 1e-3 of the film's pressure scale μ|Ω s|(R/C)²
  // (the load scale's 1e-3 of the Sommerfeld load). A lighter pad sits near its pressure-free
  // set, where it may have more than one equilibrium and the nested solves' defined choice
  // (their restart from γ_def) decides; the joint Newton, started elsewhere, could end on
  // another one or on the set's boundary with a vanishing stiffness.
  const double Rj = 0.5 * fc.geometry.diameter_m;
  const double p_light = 1e-3 * fc.geometry.viscosity_pa_s * std::abs(omega * fc.spin_factor) *
                         (Rj / C) * (Rj / C);
  auto fail = [&](int why) {
    rc = start;
    return why;
  };
  // evaluate at own coordinates p: false where the film pinches, closes or carries no pressure
  auto at = [&](const Eigen::Vector3d& p) {
    for (int k = 0; k < n; ++k) rc(g.local[static_cast<std::size_t>(k)]) = p(k);
    if (!(fc.thickness(rc).minCoeff() > pinch)) return false;
    try {
      eval();
    } catch (const ContactError&) {
      return false;
    }
    return !pressure_free && pmax >= p_light;
  };
  auto merit = [&]() {
    double f = 0.0;
    for (int k = 0; k < n; ++k) f = std::max(f, std::abs(R(k)) * scale(k));
    return f;
  };
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) p(k) = own(k);
  if (!at(p)) return fail(0);
  double f = merit();
  for (int it = 0; it < kMaxSteps; ++it) {
    // accepted where the nested solves accept at their first evaluation: a tilt root with
    // ∂R_δ/∂δ > 0 (the tilt solve's test), the pivot's and the pitch's residuals within tol
    Eigen::Matrix3d J = jac(1);
    if (!(J(0, 0) > 0.0)) return fail(-1);
    if (R.head(n).cwiseAbs().maxCoeff() <= tol) return 1;
    // a step only from a restoring Jacobian (the branch the nested solves follow)
    jac_columns(J, 1, n);  // identity outside the pad's n × n block
    if (!(J.topLeftCorner<2, 2>().determinant() > 0.0 && J.determinant() > 0.0))
      return fail(-1);
    const Eigen::VectorXd dp = J.topLeftCorner(n, n).partialPivLu().solve(-R.head(n));
    if (!dp.allFinite()) return fail(-1);
    bool tiny = true;  // a step at round-off: the root (as the nested solves' step tests)
    for (int k = 0; k < n; ++k)
      tiny = tiny && std::abs(dp(k)) <= 1e-14 * std::max(scale(k), std::abs(p(k)));
    if (tiny) return 1;
    bool accepted = false;
    double t = 1.0;
    for (int ls = 0; ls < kHalvings && !accepted; ++ls, t *= 0.5) {
      Eigen::Vector3d pt = p;
      pt.head(n) += t * dp;
      if (!at(pt)) continue;
      const double ft = merit();
      if (ft <= (1.0 - 1e-4 * t) * f) {
        p = pt;
        f = ft;
        accepted = true;
      }
    }
    if (!accepted) return fail(-1);
  }
  return fail(-1);
}

}  // namespace rotordyn
