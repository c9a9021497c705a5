// Tilting-pad equilibrium by pad assembly (J. W. Lund, ASLE Trans. 7 (1964) 342-352; P. E.
// Allaire & J. C. Nicholas's pad-assembly method): for given journal (and rotor, sleeve)
// coordinates o, each pad's own coordinates p_k (tilt, and with a flexible pivot the radial
// pivot displacement) are solved pad by pad — each pad's film depends only on its own
// coordinates and the journal — then a Newton on o with the reduced Jacobian
// J_oo − J_op J_pp⁻¹ J_po (implicit function theorem; J = K + K_H by the perturbation method)
// and a backtracking line search. The caller (SystemSolver::equilibrium) finishes with full
// Newton steps and the round-off polish on every coordinate.
//
// The pad's tilt: an unloaded pad has a continuum of pressure-free equilibria (fully divergent
// film, zero moment at any tilt). The physical one carries pressure. Along the pad's tilt
// coordinate the film closes at both ends of its range; near the end that pinches the trailing
// edge the film is pressured and its moment clearly nonzero (sign s_L), towards the other end
// the film becomes divergent and pressure-free. A pressure-free point whose residual vanishes
// counts as sign −s_L, so the bracket [loaded end, other end] holds exactly one sign change:
// the pressured root when one exists, else the boundary of the pressure-free set (the
// smallest tilt, from the loaded side, at which the film carries no pressure), which is then
// the pad's defined position: found by bisection to round-off, a function of the journal
// position alone. Safeguarded Newton inside the bracket (bisection when a step leaves it).
//
// A flexible pivot u: for each u the tilt is solved as above, and f(u) = R_u(u, δ*(u)) is
// increasing in u (K(u, u) > 0, the film force falls as the pad moves away); a film closed at
// every tilt counts as f = −∞. Newton on f with the Schur derivative, bracket expansion and
// bisection.
//
// A spherical pivot's pitch γ: solved around the tilt (and pivot) solve (pitch_solve below),
// or, by default, first by one joint Newton on the pad's coordinates (pad_joint.cpp) that
// hands back to these nested solves where it does not reach a pressured, restoring root.
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "pad_detail.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/system.hpp"

namespace rotordyn {

namespace {
using pad_detail::kPinch;
double sgn(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }
double inf_norm(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }
}  // namespace

namespace {

/// The tilt on the pad's loaded branch for the current other coordinates (ps.rc). Returns 1
/// (pressured root), 0 (no pressured root: the pad sits at the boundary of its pressure-free
/// set) or −1 (no sign change: nothing balances the pad); ContactError if the film closes at
/// every tilt. ps is left evaluated at the returned tilt.
template <class PadSolve, class FilmCoupling>
int tilt_solve(PadSolve& ps, const FilmCoupling& fc) {
  const int it = ps.g.local[0];
  const double C = fc.geometry.clearance_m, pinch = kPinch * C;
  double lo = -INFINITY, hi = INFINITY;
  // node thickness h0 + sj·tilt: the tilt range keeps every node above the pinch
  auto bound = [&](double h0, double sj) {
    if (sj > 0)
      lo = std::max(lo, (pinch - h0) / sj);
    else if (sj < 0)
      hi = std::min(hi, (h0 - pinch) / -sj);
    else if (!(h0 > pinch))
      throw ContactError("film '" + fc.name + "': the pad's film closes at every tilt");
  };
  if (fc.axial_weight.size() == 0) {  // h − tilt term constant along z up to base_h: by rows
    for (Eigen::Index j = 0; j < fc.shape.rows(); ++j) {
      double h0 = fc.base_h.size() ? fc.base_h.row(j).minCoeff() : C;
      for (Eigen::Index k = 0; k < fc.shape.cols(); ++k)
        if (k != it) h0 += fc.shape(j, k) * ps.rc(k);
      bound(h0, fc.shape(j, it));
    }
  } else {  // journal tilt (or pad pitch): the thickness varies along z, node by node
    Eigen::VectorXd r0 = ps.rc;
    r0(it) = 0.0;
    const RowMatrixXd h0 = fc.thickness(r0), d = fc.thickness_derivative(it);
    for (Eigen::Index j = 0; j < h0.rows(); ++j)
      for (Eigen::Index k = 0; k < h0.cols(); ++k) bound(h0(j, k), d(j, k));
  }
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw ContactError("film '" + fc.name + "': the pad's film closes at every tilt");
  const double step_tol = 1e-14 * std::max(C, std::max(std::abs(lo), std::abs(hi)));
  const double x0 = ps.rc(it);

  // Newton from the guess: accepted only on a pressured root inside the range.
  if (x0 > lo && x0 < hi) {
    double x = x0, prev = INFINITY;
    for (int k = 0; k < 12; ++k) {
      ps.rc(it) = x;
      ps.eval();
      if (ps.pressure_free) break;
      const double r = ps.R(0);
      // a pressured root is restoring (∂R/∂δ > 0: the film moment grows against the tilt);
      // a negative slope means the iterate slides towards the pressure-free set, where the
      // moment fades to zero without a root (small |R| there is no root): bracket instead
      const double d = ps.jac(1)(0, 0);
      if (!(d > 0)) break;
      if (std::abs(r) <= ps.tol) return 1;
      if (k >= 3 && std::abs(r) > 0.25 * prev) break;  // not converging: bracket instead
      prev = std::abs(r);
      const double xn = x - r / d;
      if (!std::isfinite(xn) || !(xn > lo && xn < hi)) break;
      if (std::abs(xn - x) <= step_tol) return 1;
      x = xn;
    }
  }

  // Bracket: the loaded end (larger peak pressure) against the other.
  ps.rc(it) = lo;
  ps.eval();
  const double R_lo = ps.R(0), p_lo = ps.pmax;
  const bool pf_lo = ps.pressure_free;
  ps.rc(it) = hi;
  ps.eval();
  const double R_hi = ps.R(0), p_hi = ps.pmax;
  const bool pf_hi = ps.pressure_free;
  const bool lo_loaded = p_lo >= p_hi;
  const double sL = sgn(lo_loaded ? R_lo : R_hi);
  auto eff = [&](double r, bool pf) { return pf && std::abs(r) <= ps.tol ? -sL : sgn(r); };
  double a = lo_loaded ? lo : hi, b = lo_loaded ? hi : lo;
  bool pf_b = lo_loaded ? pf_hi : pf_lo;
  if (sL == 0.0 || eff(lo_loaded ? R_hi : R_lo, pf_b) == sL) return -1;
  double x = (x0 > std::min(a, b) && x0 < std::max(a, b)) ? x0 : 0.5 * (a + b);
  double dx_old = std::abs(b - a);
  for (int k = 0; k < 300; ++k) {
    ps.rc(it) = x;
    ps.eval();
    const double r = ps.R(0);
    const double d = ps.pressure_free ? 0.0 : ps.jac(1)(0, 0);
    if (!ps.pressure_free && std::abs(r) <= ps.tol && d > 0) return 1;
    if (eff(r, ps.pressure_free) == sL) {
      a = x;
    } else {
      b = x;
      pf_b = ps.pressure_free;
    }
    if (std::abs(b - a) <= step_tol) break;
    double xn = NAN;
    if (!ps.pressure_free) xn = x - r / d;
    const bool inside = std::isfinite(xn) && xn > std::min(a, b) && xn < std::max(a, b);
    if (inside && std::abs(xn - x) <= step_tol && d > 0) return 1;
    // Newton while it stays inside the bracket and its steps at least halve (rtsafe);
    // bisection otherwise
    if (inside && std::abs(xn - x) <= 0.5 * dx_old) {
      dx_old = std::abs(xn - x);
      x = xn;
    } else {
      x = 0.5 * (a + b);
      dx_old = 0.5 * std::abs(b - a);
    }
  }
  if (pf_b) {  // no pressured root: the boundary of the pressure-free set
    ps.rc(it) = b;
    ps.eval();
    return 0;
  }
  ps.rc(it) = a;
  ps.eval();
  return std::abs(ps.R(0)) <= 1e3 * ps.tol ? 1 : -1;
}

/// A spherical pivot's pitch γ (the group's last coordinate): f(γ) = R_γ(γ, inner*(γ)) with
/// the tilt (and pivot) re-solved by `inner` at each γ. The film's pitch moment restores (f
/// non-decreasing in γ); past the admissible range the film closes at the edge the pad swings
/// towards, so f = +∞ above it and −∞ below. Start: the current γ, and wherever the pad is
/// pressure-free (or cannot be balanced) there, the defined γ_def — the pitch that makes the
/// pad's film closest to parallel to the journal (least squares of h over the pad's nodes,
/// tilt and pivot held) — from which the search is a function of the other coordinates
/// alone. A pad pressure-free at γ_def keeps γ_def (its pitch, like its tilt, then has no
/// film stiffness). Safeguarded Newton (Schur derivative over the inner coordinates) with
/// bracket expansion and bisection. Returns inner's state (1, 0) or −1. first ≥ −2: inner has
/// already run at the current γ and returned it (−2: ContactError), ps evaluated where it left.
template <class PadSolve, class FilmCoupling, class Inner>
int pitch_solve(PadSolve& ps, const FilmCoupling& fc, Inner&& inner, int first = -3) {
  const int m = ps.m(), pg = m - 1;
  const int ig = ps.g.local[static_cast<std::size_t>(pg)];
  double gdef = 0.0;
  {
    Eigen::VectorXd r0 = ps.rc;
    r0(ig) = 0.0;
    const RowMatrixXd h0 = fc.thickness(r0), d = fc.thickness_derivative(ig);
    const double dd = d.squaredNorm();
    if (dd > 0) gdef = -h0.cwiseProduct(d).sum() / dd;
  }
  const double kgg = ps.Kgg(pg, pg);
  const double half = 0.5 * fc.geometry.length_m;
  const double gscale = fc.geometry.clearance_m / half;  // the pitch that moves an edge by C
  double gam = ps.rc(ig), a = 0, b = 0, good = 0, step = 0.1 * gscale;
  bool has_a = false, has_b = false, has_good = false, from_def = false;
  auto restart = [&]() {
    from_def = true;
    has_a = has_b = has_good = false;
    step = 0.1 * gscale;
    gam = gdef;
  };
  for (int k = 0; k < 200; ++k) {
    ps.rc(ig) = gam;
    int st = -1;
    bool ok = true;
    if (k == 0 && first >= -2) {
      st = std::max(first, -1);
      ok = st >= 0;
    } else {
      try {
        st = inner();
        ok = st >= 0;
      } catch (const ContactError&) {
        ok = false;
      }
    }
    if (!from_def && (!ok || ps.pressure_free)) {
      restart();
      continue;
    }
    if (ok && ps.pressure_free && kgg == 0.0) return st;  // unloaded at γ_def (or a plateau)
    double f;
    if (ok) {
      f = ps.R(pg);
      if (std::abs(f) <= ps.tol) return st;
      good = gam;
      has_good = true;
    } else {
      if (!has_good) return -1;  // nothing balances the pad near γ_def
      f = gam > good ? INFINITY : -INFINITY;
    }
    if (f < 0) {
      a = gam;
      has_a = true;
    } else {
      b = gam;
      has_b = true;
    }
    double gn = NAN;
    if (ok) {
      const Eigen::Matrix3d J = ps.jac();
      // Schur complement over the inner coordinates taking part (the tilt if pressured, the
      // pivot)
      std::vector<int> in;
      if (st == 1) in.push_back(0);
      if (pg == 2) in.push_back(1);
      double d = J(pg, pg);
      if (!in.empty()) {
        const auto ni = static_cast<Eigen::Index>(in.size());
        Eigen::MatrixXd Jii(ni, ni);
        Eigen::VectorXd Jig(ni), Jgi(ni);
        for (Eigen::Index i = 0; i < ni; ++i) {
          Jig(i) = J(in[static_cast<std::size_t>(i)], pg);
          Jgi(i) = J(pg, in[static_cast<std::size_t>(i)]);
          for (Eigen::Index j = 0; j < ni; ++j)
            Jii(i, j) = J(in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(j)]);
        }
        const Eigen::VectorXd x = Jii.partialPivLu().solve(Jig);
        if (x.allFinite()) d -= Jgi.dot(x);
      }
      if (d > 0) gn = gam - f / d;
    }
    const double gtol = 1e-14 * std::max(gscale, std::abs(gam));
    if (has_a && has_b) {
      if (b - a <= gtol) return ok ? st : -1;
      if (!(std::isfinite(gn) && gn > a && gn < b)) gn = 0.5 * (a + b);
    } else if (!has_b) {
      if (!(std::isfinite(gn) && gn > gam)) gn = gam + step;
      step *= 2;
    } else {
      if (!(std::isfinite(gn) && gn < gam)) gn = gam - step;
      step *= 2;
    }
    if (ok && std::abs(gn - gam) <= gtol) return st;
    gam = gn;
  }
  return -1;
}

/// X = J_pp⁻¹ J_po and y = J_pp⁻¹ R_p for the reduced Newton (the pads' sensitivities to the
/// outer coordinates, implicit function theorem). J_pp is block diagonal, one block per pad
/// (a pad's film depends on its own coordinates and the journal's only); `start` gives each
/// pad's first row in J_pp (blocks run to the next pad's start), `scale` each row's coordinate
/// scale. Where every block has full rank: LU of J_pp. A pad at the boundary of its
/// pressure-free set can carry pressure on a single node (the compressor on misaligned
/// spherical pads at 5 and 20 Hz: the top pads, 1.4e-9 and 7.5e-8 Pa on 1 of 165 nodes):
/// its tilt and pitch moments are then two multiples of that node's pressure and its block has
/// rank 1 (smallest singular value 1e-20 of the largest, scaled) — the LU divided by zero and
/// the NaN step ended the pad assembly. There each block is inverted on its range (scaled
/// pseudo-inverse, singular values below kRankTol of the block's largest dropped): the pad's
/// moment balance fixes only the one film combination its pressure sees, the flat direction
/// is left to the pads' own solve (which re-solves every pad at each trial point).
void pad_block_solve(const Eigen::MatrixXd& Jpp, const Eigen::MatrixXd& Jpo,
                     const Eigen::VectorXd& Rp, const std::vector<int>& start,
                     const std::vector<double>& scale, Eigen::MatrixXd& X, Eigen::VectorXd& y) {
  // film stiffness entries carry round-off ~1e-13 of a block's largest; the rank-1 pads seen
  // had 1e-20
  // (a trade-off: a well-posed but lightly loaded block whose smallest scaled singular value
  // falls below it loses that direction to the pads' own solve and converges linearly there)
  constexpr double kRankTol = 1e-10;
  const auto np = Jpp.rows();
  if (!Jpp.allFinite() || !Jpo.allFinite() || !Rp.allFinite()) {
    // no SVD of a non-finite block (Eigen leaves its factors unset): the LU's NaN step, which
    // the caller's finiteness check turns into the pad assembly's failure
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Jpp);
    X = lu.solve(Jpo);
    y = lu.solve(Rp);
    return;
  }
  std::vector<Eigen::Index> b0, b1;  // the non-empty blocks [b0, b1)
  for (std::size_t k = 0; k < start.size(); ++k) {
    const Eigen::Index e = k + 1 < start.size() ? start[k + 1] : np;
    if (e > start[k]) {
      b0.push_back(start[k]);
      b1.push_back(e);
    }
  }
  bool block_diagonal = true, full_rank = true;
  std::vector<Eigen::JacobiSVD<Eigen::MatrixXd>> svd;
  for (std::size_t k = 0; k < b0.size(); ++k) {
    const Eigen::Index a = b0[k], m = b1[k] - a;
    for (Eigen::Index i = a; i < a + m; ++i)
      for (Eigen::Index j = 0; j < np; ++j)
        if ((j < a || j >= a + m) && Jpp(i, j) != 0.0) block_diagonal = false;
    Eigen::MatrixXd B = Jpp.block(a, a, m, m);
    for (Eigen::Index i = 0; i < m; ++i) {
      B.row(i) *= scale[static_cast<std::size_t>(a + i)];
      B.col(i) *= scale[static_cast<std::size_t>(a + i)];
    }
    svd.emplace_back(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::VectorXd sv = svd.back().singularValues();
    if (!(sv(m - 1) > kRankTol * sv(0))) full_rank = false;
  }
  if (full_rank || !block_diagonal) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Jpp);
    X = lu.solve(Jpo);
    y = lu.solve(Rp);
    return;
  }
  X = Eigen::MatrixXd::Zero(np, Jpo.cols());
  y = Eigen::VectorXd::Zero(np);
  for (std::size_t k = 0; k < b0.size(); ++k) {
    const Eigen::Index a = b0[k], m = b1[k] - a;
    const Eigen::VectorXd s =
        Eigen::Map<const Eigen::VectorXd>(scale.data() + a, m);  // x = S B_s⁺ S b
    const Eigen::JacobiSVD<Eigen::MatrixXd>& d = svd[k];
    const Eigen::VectorXd sv = d.singularValues();
    Eigen::VectorXd inv = Eigen::VectorXd::Zero(m);
    for (Eigen::Index i = 0; i < m; ++i)
      if (sv(i) > kRankTol * sv(0)) inv(i) = 1.0 / sv(i);
    const Eigen::MatrixXd P =
        s.asDiagonal() * (d.matrixV() * inv.asDiagonal() * d.matrixU().transpose()) *
        s.asDiagonal();
    X.middleRows(a, m) = P * Jpo.middleRows(a, m);
    y.segment(a, m) = P * Rp.segment(a, m);
  }
}

}  // namespace

bool SystemSolver::pad_assembly(double omega, const Eigen::VectorXd& F, double load_scale,
                                double tol, int max_iter, bool joint, Eigen::VectorXd& r,
                                int& iterations, int& unloaded, std::string& why) {
  const Eigen::Index n = model_.n();
  std::vector<char> in_pad(static_cast<std::size_t>(n), 0);
  for (const auto& g : pads_)
    for (int c : g.coords) in_pad[static_cast<std::size_t>(c)] = 1;
  std::vector<int> outer;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!in_pad[static_cast<std::size_t>(i)]) outer.push_back(static_cast<int>(i));
  // Pad residual tolerance: loose while the journal is far from its equilibrium (the Newton
  // step below solves for the pads' residual too), 1e-14 of the load scale at the end.
  const double tol_floor = 1e-14 * load_scale;
  double tol_in = tol_floor;
  std::vector<int> state(pads_.size(), 1);  // 1 pressured, 0 unloaded (pressure-free)
  // a spherical pad's coordinates in r come from its pressured root at the last evaluation
  std::vector<char> warm(pads_.size(), 0);

  // Every pad on its loaded branch for the other coordinates of r (pad coordinates in r are
  // the guesses). false (why) if a pad cannot be balanced; ContactError propagates.
  auto solve_pads = [&](Eigen::VectorXd& rr) -> bool {
    const Eigen::VectorXd Kr = model_.K * rr - F;
    for (std::size_t k = 0; k < pads_.size(); ++k) {
      const PadGroup& g = pads_[k];
      const FilmCoupling& fc = model_.films[g.film];
      PadSolve ps(*this, g);
      ps.omega = omega;
      // a flexible pivot's nested solve needs its tilt converged (a stiff pivot amplifies the
      // tilt's error in f(u)): the tight tolerance there
      ps.tol = g.coords.size() >= 2 ? tol_floor : tol_in;
      ps.rc.resize(static_cast<Eigen::Index>(fc.coords.size()));
      for (std::size_t j = 0; j < fc.coords.size(); ++j)
        ps.rc(static_cast<Eigen::Index>(j)) = rr(fc.coords[j]);
      const int m = static_cast<int>(g.coords.size());
      for (int a = 0; a < m; ++a) {
        ps.A(a) = Kr(g.coords[static_cast<std::size_t>(a)]);
        for (int b = 0; b < m; ++b) {
          ps.Kgg(a, b) = model_.K(g.coords[static_cast<std::size_t>(a)],
                                  g.coords[static_cast<std::size_t>(b)]);
          ps.A(a) -= ps.Kgg(a, b) * rr(g.coords[static_cast<std::size_t>(b)]);
        }
      }
      // tilt, and with a flexible pivot the pivot displacement, for the current pitch
      auto inner = [&]() -> int {
        if (!g.pivot()) return tilt_solve(ps, fc);
        // flexible pivot: f(u) = R_u(u, tilt*(u)), increasing in u
        int st = -1;
        const int iu = g.local[1];
        const double C = fc.geometry.clearance_m;
        double u = ps.rc(iu), a = 0, b = 0, step = 0.1 * C;
        bool has_a = false, has_b = false;
        for (int k2 = 0; k2 < 200; ++k2) {
          ps.rc(iu) = u;
          bool ok = true;
          try {
            st = tilt_solve(ps, fc);
            ok = st >= 0;
          } catch (const ContactError&) {
            ok = false;
          }
          const double fu = ok ? ps.R(1) : -INFINITY;
          if (ok && std::abs(fu) <= ps.tol) break;
          if (fu < 0) {
            a = u;
            has_a = true;
          } else {
            b = u;
            has_b = true;
          }
          double un = NAN;
          if (ok) {
            const Eigen::Matrix3d J = ps.jac(2);
            const double d = (st == 1 && J(0, 0) != 0.0) ? J(1, 1) - J(1, 0) * J(0, 1) / J(0, 0)
                                                         : J(1, 1);
            if (d > 0) un = u - fu / d;
          }
          const double utol = 1e-14 * std::max(C, std::abs(u));
          if (has_a && has_b) {
            if (b - a <= utol) {
              st = ok ? st : -1;
              break;
            }
            if (!(std::isfinite(un) && un > a && un < b)) un = 0.5 * (a + b);
          } else if (!has_b) {
            if (!(std::isfinite(un) && un > u)) un = u + step;
            step *= 2;
          } else {
            if (!(std::isfinite(un) && un < u)) un = u - step;
            step *= 2;
          }
          if (ok && std::abs(un - u) <= utol) break;
          u = un;
          st = -1;
        }
        return st;
      };
      int st = -1;
      if (!g.pitch) {
        st = inner();
      } else if (!joint) {
        st = pitch_solve(ps, fc, inner);
      } else {
        // a spherical pad: the joint Newton (pad_joint.cpp; no nesting, so the loose tolerance
        // as for a rocker pad's tilt) from a warm start — the pad's coordinates predicted from
        // its pressured root at the assembly's last evaluation. Otherwise, or where it fails,
        // the nested solves' own first step, the tilt (and pivot) for the current pitch, and
        // from there the joint Newton if the pad carries pressure; else the nested solves go
        // on from that step (a pad pressure-free there restarts from γ_def): the joint Newton
        // only replaces the pitch iteration the nested solves would run from the same point.
        const double tol_nested = ps.tol;
        // (tight at once where the pads are the only coordinates: a held pose)
        auto try_joint = [&]() {
          ps.tol = outer.empty() ? tol_floor : tol_in;
          const int j = ps.joint(fc);
          ps.tol = tol_nested;
          return j;
        };
        const int j0 = warm[k] ? try_joint() : -1;
        if (j0 == 1) {
          st = 1;
        } else if (j0 == 0) {
          st = pitch_solve(ps, fc, inner);
        } else {
          int st0 = -2;
          try {
            st0 = inner();
          } catch (const ContactError&) {
          }
          if (st0 == 1 && !ps.pressure_free && try_joint() == 1) {
            st = 1;
          } else {
            if (st0 == 1 && !ps.pressure_free) ps.eval();  // at inner's point (rc restored)
            st = pitch_solve(ps, fc, inner, st0);
          }
        }
        warm[k] = st == 1;
      }
      if (st < 0) {
        why = "pad '" + fc.name + "': no tilt balances the pad";
        return false;
      }
      state[k] = st;
      for (int a = 0; a < m; ++a)
        rr(g.coords[static_cast<std::size_t>(a)]) = ps.own(a);
    }
    return true;
  };

  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd H, R;
  double res = NAN;
  auto evaluate = [&](Eigen::VectorXd& rr, Eigen::VectorXd& Hr, Eigen::VectorXd& Rr,
                      double& resr) -> bool {
    try {
      if (!solve_pads(rr)) return false;
      Hr = film_forces(rr, zero, omega);  // the pads' films are reused (same coordinates)
    } catch (const ContactError& e) {
      why = e.what();
      return false;
    }
    Rr = model_.K * rr - Hr - F;
    resr = inf_norm(Rr) / load_scale;
    return std::isfinite(resr);
  };
  tol_in = std::max(tol_floor, 1e-3 * load_scale);
  if (!evaluate(r, H, R, res)) {
    why = "pad assembly, starting point: " + why;
    return false;
  }
  const auto no = static_cast<Eigen::Index>(outer.size());
  Eigen::MatrixXd KH;
  double step_prev = INFINITY;
  bool tight = false;
  double res_prev = INFINITY;
  // Work budget: a hopeless case (a load the pads cannot carry, under the homotopy's stiff
  // pad penalty) made 100 iterations of line-search steps t ~ 1e-6 … 1e-12 that each lowered
  // the residual by ~1e-6 of itself, each line search ~20 trials of ~1000 Reynolds solves (the
  // nested pad solves): 2.7·10^6 solves, ~9 s. Converged runs seen (tests and fuzz cases)
  // took at most 4.7·10^4; the pad assembly stops after kPadSolvesPerIter·max_iter (10^5 at
  // the default max_iter) and the caller goes on with plain Newton.
  constexpr long kPadSolvesPerIter = 1000;
  const long budget = kPadSolvesPerIter * max_iter;
  const int solves_start = solves_;
  for (iterations = 0; iterations < max_iter; ++iterations) {
    // converged: on to the round-off floor while each step at least halves the residual
    // (the reduced Newton is well conditioned where the full Jacobian, with a very soft pivot
    // or an almost unloaded pad, is not, so the full polish may decline)
    if (res < tol && (res == 0.0 || res > 0.5 * res_prev || step_prev <= 1e-15)) break;
    res_prev = res;
    linearize_last_solve(false, KH, nullptr);  // every film's last solve is at r
    const Eigen::MatrixXd J = model_.K + KH;
    // pad coordinates that take part (an unloaded pad's tilt, and its pitch without a pitch
    // spring, have a zero row and column)
    std::vector<int> pc, pc_start(pads_.size());
    std::vector<double> pc_scale;  // C for tilt and pivot, C/(L/2) for a pitch (pad_joint.cpp)
    for (std::size_t k = 0; k < pads_.size(); ++k) {
      pc_start[k] = static_cast<int>(pc.size());
      const JournalBearingGeometry& geo = model_.films[pads_[k].film].geometry;
      for (std::size_t a = 0; a < pads_[k].coords.size(); ++a) {
        const int c = pads_[k].coords[a];
        const bool is_pitch = pads_[k].pitch && a + 1 == pads_[k].coords.size();
        const bool free_pitch = is_pitch && model_.K(c, c) == 0.0;
        if (state[k] == 1 || (a > 0 && !free_pitch)) {
          pc.push_back(c);
          pc_scale.push_back(is_pitch ? geo.clearance_m / (0.5 * geo.length_m)
                                      : geo.clearance_m);
        }
      }
    }
    const auto np = static_cast<Eigen::Index>(pc.size());
    Eigen::MatrixXd Joo(no, no), Jop(no, np), Jpo(np, no), Jpp(np, np);
    Eigen::VectorXd Ro(no), Rp(np);
    for (Eigen::Index i = 0; i < no; ++i) {
      Ro(i) = R(outer[static_cast<std::size_t>(i)]);
      for (Eigen::Index j = 0; j < no; ++j)
        Joo(i, j) = J(outer[static_cast<std::size_t>(i)], outer[static_cast<std::size_t>(j)]);
      for (Eigen::Index j = 0; j < np; ++j) {
        Jop(i, j) = J(outer[static_cast<std::size_t>(i)], pc[static_cast<std::size_t>(j)]);
        Jpo(j, i) = J(pc[static_cast<std::size_t>(j)], outer[static_cast<std::size_t>(i)]);
      }
    }
    for (Eigen::Index i = 0; i < np; ++i) {
      Rp(i) = R(pc[static_cast<std::size_t>(i)]);
      for (Eigen::Index j = 0; j < np; ++j)
        Jpp(i, j) = J(pc[static_cast<std::size_t>(i)], pc[static_cast<std::size_t>(j)]);
    }
    Eigen::VectorXd dro, drp;
    if (np) {
      Eigen::MatrixXd X;
      Eigen::VectorXd y;
      pad_block_solve(Jpp, Jpo, Rp, pc_start, pc_scale, X, y);
      if (!X.allFinite() || !y.allFinite()) {
        why = "pad assembly: non-finite pad sensitivities";
        return false;
      }
      const Eigen::MatrixXd S = Joo - Jop * X;  // reduced Jacobian
      dro = S.partialPivLu().solve(-(Ro - Jop * y));
      // singular reduced Jacobian: e.g. a journal on one loaded pad with the others
      // pressure-free has no stiffness across that pad's pivot line; minimum-norm step
      if (!dro.allFinite()) dro = S.completeOrthogonalDecomposition().solve(-(Ro - Jop * y));
      drp = -(y + X * dro);
    } else {
      dro = Joo.partialPivLu().solve(-Ro);
    }
    if (!dro.allFinite()) {
      why = "pad assembly: singular reduced Jacobian";
      return false;
    }
    const bool drp_finite = drp.allFinite();
    double t = 1.0;
    bool accepted = false;
    tol_in = tight ? tol_floor : std::max(tol_floor, 1e-3 * res * load_scale);
    for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
      Eigen::VectorXd rt = r;
      for (Eigen::Index i = 0; i < no; ++i) rt(outer[static_cast<std::size_t>(i)]) += t * dro(i);
      if (drp_finite)
        for (Eigen::Index i = 0; i < np; ++i) rt(pc[static_cast<std::size_t>(i)]) += t * drp(i);
      Eigen::VectorXd Ht, Rt;
      double rest = NAN;
      if (!evaluate(rt, Ht, Rt, rest)) continue;
      if (rest <= (1.0 - 1e-4 * t) * res || rest < 1e-2 * tol) {
        step_prev = 0.0;
        for (Eigen::Index i = 0; i < no; ++i) {
          const int c = outer[static_cast<std::size_t>(i)];
          step_prev = std::max(step_prev, std::abs(rt(c) - r(c)) /
                                              std::max(std::abs(r(c)), 1e-300));
        }
        r = rt;
        H = Ht;
        R = Rt;
        res = rest;
        accepted = true;
        break;
      }
    }
    if (accepted && !(res < tol) && solves_ - solves_start > budget) {
      ++iterations;
      std::ostringstream os;
      os << "pad assembly: stopped after " << solves_ - solves_start
         << " Reynolds solves (budget " << budget << ") in " << iterations
         << " iterations, residual " << res;
      why = os.str();
      return false;
    }
    if (!accepted) {
      // leave the films at r (pads re-solved to the tight tolerance)
      const bool was_tight = tight;
      tight = true;
      tol_in = tol_floor;
      if (!evaluate(r, H, R, res)) return false;
      if (res < tol) break;
      if (!was_tight) continue;  // inexact pads stalled the line search: again, exact
      std::ostringstream os;
      os << "pad assembly: line search failed (residual " << res << ")";
      why = os.str();
      return false;
    }
  }
  unloaded = static_cast<int>(std::count(state.begin(), state.end(), 0));
  if (!(res < tol)) {
    std::ostringstream os;
    os << "pad assembly: no convergence in " << max_iter << " iterations (residual " << res
       << ")";
    why = os.str();
    return false;
  }
  why.clear();  // trial points in contact on the way are no failure
  return true;
}

}  // namespace rotordyn
