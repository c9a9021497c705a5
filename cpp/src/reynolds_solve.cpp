// ReynoldsSolver: the film solves (full/half Sommerfeld, Swift–Stieber LCP), outputs, and the
// linearised solve that shares the last factorisation.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {
constexpr double kPi = 3.14159265358979323846;

// max_i |x_i| (0 for n = 0), in four independent lanes: max is exact, so the result is the
// same as a sequential scan, without its loop-carried dependency.
double max_abs(const double* x, int n) {
  double m[4] = {0.0, 0.0, 0.0, 0.0};
  int i = 0;
  for (; i + 4 <= n; i += 4)
    for (int l = 0; l < 4; ++l) m[l] = std::max(m[l], std::abs(x[i + l]));
  for (; i < n; ++i) m[0] = std::max(m[0], std::abs(x[i]));
  return std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
}
}  // namespace

double ReynoldsSolver::Impl::short_source(const double* hh, const double* hd, int n) const {
  return 0.5 * omega * (hh[east(n)] - hh[west(n)]) / (2.0 * dphi) + hd[n];
}

double ReynoldsSolver::Impl::short_factor(int n) const {
  const double z = -0.5 * L + (n % K1) * dz;
  if (turb)  // p = (k_z/2) μ s (z² − L²/4)/h³: the axial conductance h³/(k_z μ) at the node
    return 0.5 * tfac(re_per_h * h[n]).kz * mu *
           (z * z - 0.25 * L * L);
  return 6.0 * mu * (z * z - 0.25 * L * L);
}

void ReynoldsSolver::Impl::solve_short() {
  for (int n = 0; n < n_nodes; ++n) {
    const double hv = h[n];
    const double pv = short_factor(n) * short_source(h.data(), hdot.data(), n) / (hv * hv * hv);
    pfull[n] = pv;
    p[n] = (cav != Cavitation::none && pv < 0.0) ? 0.0 : pv;
  }
  out.iterations = 1;
}

void ReynoldsSolver::Impl::solve_linear(LinearSystem& S) {
  factor_spd(S, nullptr);
  base_rhs(S, S.rhs);
  S.solve_spd(S.rhs.data(), S.sol.data());
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    pfull[n] = S.sol[i];
    p[n] = (cav == Cavitation::gumbel && S.sol[i] < 0.0) ? 0.0 : S.sol[i];
  }
  if (S.half) mirror_fields();
  out.iterations = 1;
}

// Swift–Stieber: find p >= 0 with μ = A p − b >= 0 and p·μ = 0 (A is a Stieltjes matrix, so
// the LCP has one solution). Primal–dual active set (Hintermüller, Ito & Kunisch 2003): on the
// active set p = 0, elsewhere A_II p_I = b_I; update active = {μ > 0 on the old set} ∪ {p < 0};
// stop when the set repeats. The set starts from predict_active(), a function of this call's
// inputs only, so the answer never depends on what the solver solved before (bit for bit).
// Active unknowns are decoupled in place (identity row/column): the analysed pattern never
// changes.
void ReynoldsSolver::Impl::predict_active(LinearSystem& S) {
  if (!predict) {
    std::fill(S.active.begin(), S.active.end(), 0);
    return;
  }
  if (coarse_usable) {
    // Coarse grid Nc × nac (about half in each direction); coarse node jc sits at fine
    // position jc·N/Nc (exactly every other node when N is even), likewise along z. The film
    // is interpolated linearly from the fine nodes (exact sampling when the ratio is 1 or 2).
    const int Nc = coarse_n_circ, nac = coarse_n_axial, K1c = nac + 1, na = grid.n_axial;
    try {
      if (!coarse) {
        JournalBearingGeometry gc = geo;  // a Swift–Stieber predictor: no metered supply
        gc.supply_flow_m3_s = 0.0;
        coarse = std::make_unique<ReynoldsSolver>(gc, FilmGrid{Nc, nac}, Cavitation::reynolds);
        coarse->set_pressure_only(true);  // only its p_pa is read below
        hc.resize(Nc, K1c);
        hdc.resize(Nc, K1c);
      }
      coarse->set_use_axial_symmetry(use_symmetry);
      if (coarse_lerp.empty()) {  // sampling positions of the coarse nodes, once per solver
        coarse_lerp.resize(static_cast<std::size_t>(Nc) * K1c);
        for (int jc = 0; jc < Nc; ++jc) {
          const long sj = static_cast<long>(jc) * N;
          const int j0 = static_cast<int>(sj / Nc), j1 = (j0 + 1) % N;
          const double fj = static_cast<double>(sj % Nc) / Nc;
          for (int kc = 0; kc < K1c; ++kc) {
            const long sk = static_cast<long>(kc) * na;
            const int k0 = static_cast<int>(sk / nac), k1 = std::min(k0 + 1, na);
            const double fk = static_cast<double>(sk % nac) / nac;
            coarse_lerp[static_cast<std::size_t>(jc) * K1c + kc] =
                CoarseLerp{j0 * K1 + k0, j0 * K1 + k1, j1 * K1 + k0, j1 * K1 + k1, fj, fk};
          }
        }
      }
      const std::vector<double>& hs = has_pockets ? h_smooth : h;  // the coarse film adds its own
      double* hcd = hc.data();
      double* hdcd = hdc.data();
      for (std::size_t q = 0; q < coarse_lerp.size(); ++q) {
        const CoarseLerp& t = coarse_lerp[q];
        auto lerp = [&](const std::vector<double>& f) {
          const double a0 = f[t.n00] + t.fk * (f[t.n01] - f[t.n00]);
          const double a1 = f[t.n10] + t.fk * (f[t.n11] - f[t.n10]);
          return a0 + t.fj * (a1 - a0);
        };
        hcd[q] = lerp(hs);
        hdcd[q] = lerp(hdot);
      }
      const RowMatrixXd& pc = coarse->solve(hc, hdc, omega).p_pa;
      // A fine node is predicted cavitated when every coarse node around it is (p == 0).
      if (S.coarse_around.size() != static_cast<std::size_t>(S.n_unk)) {
        S.coarse_around.resize(S.n_unk);
        for (int i = 0; i < S.n_unk; ++i) {
          const int n = S.node_of[i];
          const long sj = static_cast<long>(n / K1) * Nc, sk = static_cast<long>(n % K1) * nac;
          const int j0 = static_cast<int>(sj / N), j1 = (sj % N) ? (j0 + 1) % Nc : j0;
          const int k0 = static_cast<int>(sk / na), k1 = (sk % na) ? k0 + 1 : k0;
          S.coarse_around[i] = {j0 * K1c + k0, j1 * K1c + k0, j0 * K1c + k1, j1 * K1c + k1};
        }
      }
      const double* pcd = pc.data();
      for (int i = 0; i < S.n_unk; ++i) {
        const std::array<int, 4>& a = S.coarse_around[i];
        S.active[i] = (pcd[a[0]] <= 0.0 && pcd[a[1]] <= 0.0 && pcd[a[2]] <= 0.0 &&
                       pcd[a[3]] <= 0.0)
                          ? 1
                          : 0;
        // Between two coarse columns of which the downstream one is cavitated (a rupture
        // boundary; Swift–Stieber: p and ∂p/∂φ vanish there, so √p is linear in φ near it):
        // cavitated when the zero of √p extrapolated from the two upstream coarse nodes lies
        // before the fine node. Only the start changes (the LCP has one solution).
        if (S.active[i] || a[0] == a[1]) continue;
        const int n = S.node_of[i];
        const long sj = static_cast<long>(n / K1) * Nc;
        const int j0 = static_cast<int>(sj / N), j1 = (j0 + 1) % Nc;
        const double t = static_cast<double>(sj % N) / N;
        auto row_cav = [&](int o0, int o1) {  // o0, o1: flat indices of (j0, k), (j1, k)
          const double p0 = pcd[o0], p1 = pcd[o1];
          if (p0 <= 0.0 && p1 <= 0.0) return true;
          const int kk = o0 - j0 * K1c;
          // up: the coarse node upstream of the fine one is the film one (a rupture
          // boundary); otherwise the downstream one is (a reformation boundary)
          const bool fwd = omega >= 0.0;
          const bool up = fwd ? p1 <= 0.0 : p0 <= 0.0;
          double pP, pPP, u;
          if (up == fwd) {  // film at j0: extrapolate from j0 and the node before it
            pP = p0;
            pPP = pcd[((j0 - 1 + Nc) % Nc) * K1c + kk];
            u = t;
          } else {  // film at j1: from j1 and the node after it
            pP = p1;
            pPP = pcd[((j1 + 1) % Nc) * K1c + kk];
            u = 1.0 - t;
          }
          if (up) {
            const double r = std::sqrt(pP), rr = std::sqrt(std::max(pPP, 0.0));
            return rr > r && u * (rr - r) >= r;
          }
          // Reformation: p rises from 0 with a nonzero slope, so p itself is linear there.
          return pPP > pP && u * (pPP - pP) >= pP;
        };
        if (row_cav(a[0], a[1]) && row_cav(a[2], a[3])) S.active[i] = 1;
      }
      if (refine && !S.half) refine_prediction(S, pcd);
      return;
    } catch (const ConvergenceError&) {
      // fall through to the local prediction (still a function of the inputs only)
    }
  }
  for (int i = 0; i < S.n_unk; ++i) S.active[i] = S.rhs[i] < 0.0 ? 1 : 0;
}

void ReynoldsSolver::Impl::solve_reynolds(LinearSystem& S) {
  base_rhs(S, S.rhs);
  band_resumed = 0;
  deg_mu_last = 0.0;  // this solve's band, set on convergence (none from an earlier solve)
  // In a continuation (a transient run: consecutive right-hand sides at nearby states) the
  // last converged set is the better start; it leads to the same unique solution.
  if (continuation && S.last_set.size() == static_cast<std::size_t>(S.n_unk))
    S.active = S.last_set;
  else
    predict_active(S);
  const double bscale = max_abs(S.rhs.data(), S.n_unk);
  std::vector<char> next(S.n_unk), degenerate(S.n_unk);
  Eigen::VectorXd b(S.n_unk);
  const int max_iter = 100 + S.n_unk / 4;
  double pscale_fixed = 0.0;  // the prescribed nodes' pressures, the same every iteration
  for (int n = 0; n < n_nodes; ++n)
    if (fixed[n]) pscale_fixed = std::max(pscale_fixed, std::abs(p[n]));
  for (int it = 1; it <= max_iter; ++it) {
    // from the 2nd iteration on, `next` holds the last set (swapped below): the band factor
    // keeps its opening and resumes after the first column the change touches
    const BandReuse reuse{true, it > 1 ? &next : nullptr, it > 1 ? S.band_cut : -1};
    factor_spd(S, &S.active, &reuse);
    for (int i = 0; i < S.n_unk; ++i) b[i] = S.active[i] ? 0.0 : S.rhs[i];
    S.solve_spd(b.data(), S.sol.data());
    for (int i = 0; i < S.n_unk; ++i) {
      if (S.active[i]) S.sol[i] = 0.0;
      p[S.node_of[i]] = S.sol[i];
    }
    const double pscale = std::max(pscale_fixed, max_abs(S.sol.data(), S.n_unk));
    // The half system's mirrored rows: only p is read below (the fill stays 1 with this
    // model, pfull is set from p on convergence).
    if (S.half) {  // p[n] = p[mirror(n)], row by row (no division per node)
      const int kend = mirror_end();
      for (int j = 0; j < N; ++j) {
        double* row = p.data() + static_cast<std::size_t>(j) * K1;
        for (int k = Kh + 1; k < kend; ++k) row[k] = row[K1 - 1 - k];
      }
    }
    const double tol_p = 1e-13 * pscale;
    const double tol_mu = 1e-13 * bscale;
    // Degenerate (p = 0 and A p − b = 0 together): zero to within 1e-12 of the film's own
    // scales — the characteristic pressure μ|ω|(R/c)² and the Couette flux (|ω|R/2)·c·Δz of a
    // cell — or of this solution's, whichever is larger. Not by exact zeros: an unloaded
    // tilting pad sits at the edge of its pressure-free branch, where round-off of the state
    // (a warm-started equilibrium that differs from a cold one in the last bits) leaves either
    // ~1e-8 Pa on a few nodes or p = 0 with a multiplier of round-off size; both are the
    // same degenerate state, and the linearisation (the directional-derivative limit below)
    // must not jump between them (it moved the compressor's modes by 1.5e-3).
    const double deg_p = 1e-12 * std::max(pscale, mu * std::abs(omega) * (R / c) * (R / c));
    const double deg_mu = 1e-12 * std::max(bscale, 0.5 * std::abs(omega) * R * c * dz);
    bool changed = false;
    for (int i = 0; i < S.n_unk; ++i) {
      const int n = S.node_of[i];
      if (S.active[i]) {
        const double mu_i = cell_residual(n, p);  // multiplier ∝ (A p − b)_i
        next[i] = mu_i >= -tol_mu ? 1 : 0;
        degenerate[i] = std::abs(mu_i) <= deg_mu ? 1 : 0;
      } else {
        next[i] = p[n] < -tol_p ? 1 : 0;
        degenerate[i] = std::abs(p[n]) <= deg_p ? 1 : 0;
      }
      if (next[i] != S.active[i]) changed = true;
    }
    if (!changed) {
      deg_mu_last = deg_mu;
      for (int n = 0; n < n_nodes; ++n) pfull[n] = p[n];
      std::fill(biactive.begin(), biactive.end(), 0);
      n_biactive = 0;
      for (int i = 0; i < S.n_unk; ++i)
        if (degenerate[i]) {
          const int n = S.node_of[i];
          biactive[n] = 1;
          if (S.half) biactive[mirror(n)] = 1;
          ++n_biactive;
        }
      out.iterations = it;
      if (continuation) S.last_set = S.active;
      return;
    }
    S.active.swap(next);
  }
  S.last_set.clear();
  throw ConvergenceError("reynolds cavitation: active-set iteration did not converge in " +
                         std::to_string(max_iter) + " iterations");
}

double ReynoldsSolver::Impl::apply_row(const LinearSystem& S, int i,
                                       const Eigen::VectorXd& x) const {
  const int n = S.node_of[i];
  const int e = east(n), w = west(n);
  auto val = [&](int nb) { return S.unk[nb] >= 0 ? x[S.unk[nb]] : 0.0; };
  const double xn = x[i];
  double r = S.wphi[i] * (cE[n] * (xn - val(e)) + cE[w] * (xn - val(w)));
  if (S.has_n[i]) r += cN[n] * (xn - val(n + 1));
  if (S.has_s[i]) r += cN[n - 1] * (xn - val(n - 1));
  if (end_row(n)) r += gseal * xn;
  return r;
}

// At a degenerate Swift–Stieber state the solution map r ↦ p is piecewise linear and only
// directionally differentiable (e.g. a centred journal: the film for +dx and for −dx cavitate
// on opposite halves). The directional derivative dp for a residual change dr solves the LCP
//   dp = 0 on strongly active unknowns (μ > 0),  (A dp + dr)_i = 0 on inactive ones (p > 0),
//   dp_i >= 0, (A dp + dr)_i >= 0, dp_i (A dp + dr)_i = 0 on the degenerate ones,
// solved by the same primal–dual active set (started from the prediction dr_i > 0). The
// factorisation of the base state is restored afterwards.
void ReynoldsSolver::Impl::solve_derivative_lcp(LinearSystem& S, const Eigen::VectorXd& dr,
                                                Eigen::VectorXd& x) {
  std::vector<char> mask(S.n_unk), next(S.n_unk);
  std::vector<char> deg(S.n_unk);
  double rscale = 0.0;
  for (int i = 0; i < S.n_unk; ++i) {
    deg[i] = biactive[S.node_of[i]];
    mask[i] = S.active[i] && !deg[i] ? 1 : (deg[i] && dr[i] > 0.0 ? 1 : 0);
    rscale = std::max(rscale, std::abs(dr[i]));
  }
  Eigen::VectorXd b(S.n_unk);
  x.setZero(S.n_unk);
  const int max_iter = 100 + S.n_unk / 4;
  bool converged = false;
  const BandReuse restore{false, nullptr, S.band_cut};  // the base factor again: its opening
  for (int it = 1; it <= max_iter && !converged; ++it) {
    factor_spd(S, &mask);
    for (int i = 0; i < S.n_unk; ++i) b[i] = mask[i] ? 0.0 : -dr[i];
    S.solve_spd(b.data(), x.data());
    for (int i = 0; i < S.n_unk; ++i)
      if (mask[i]) x[i] = 0.0;
    double xscale = 0.0;
    for (int i = 0; i < S.n_unk; ++i) xscale = std::max(xscale, std::abs(x[i]));
    const double tol_x = 1e-13 * xscale, tol_mu = 1e-13 * rscale;
    converged = true;
    for (int i = 0; i < S.n_unk; ++i) {
      next[i] = mask[i];
      if (!deg[i]) continue;
      next[i] = mask[i] ? (apply_row(S, i, x) + dr[i] >= -tol_mu ? 1 : 0)
                        : (x[i] < -tol_x ? 1 : 0);
      if (next[i] != mask[i]) converged = false;
    }
    mask.swap(next);
  }
  factor_spd(S, &S.active, &restore);
  if (!converged)
    throw ConvergenceError("reynolds cavitation: the directional derivative at a degenerate "
                           "cavitation set did not converge");
}

void ReynoldsSolver::Impl::postprocess() {
  const int Kl = K1 - 1;
  const double area = R * dphi * dz;
  double fx = 0.0, fy = 0.0, torque = 0.0;
  double hmin = h[0];
  int nmin = 0;
  // Ring by ring: the shear of each node first (no reduction: its divisions run two lanes
  // at a time), then the sums in node order — the same operations and order as one loop.
  tau_ring.resize(K1);
  double* tr = tau_ring.data();
  const double mur = mu * omega * R;
  for (int j = 0; j < N; ++j) {
    const int row = j * K1;
    const double* pr = p.data() + row;
    const double* pe = p.data() + (j + 1 == N ? 0 : row + K1);
    const double* pw = p.data() + (j == 0 ? (N - 1) * K1 : row - K1);
    const double* hr = h.data() + row;
    const double* thr = theta.data() + row;
    if (!turb && !visc_field) {
      for (int k = 0; k < K1; ++k)
        tr[k] = mur * thr[k] / hr[k] + hr[k] / (2.0 * R) * ((pe[k] - pw[k]) / (2.0 * dphi));
    } else {
      for (int k = 0; k < K1; ++k) {
        const int n = row + k;
        const double dpdphi = (pe[k] - pw[k]) / (2.0 * dphi);
        double tau = node_mu(n) * omega * R * thr[k] / hr[k];
        if (turb) tau *= node_cf(n, hr[k]);  // Couette
        tr[k] = tau + hr[k] / (2.0 * R) * dpdphi;
      }
    }
    const double cj = cosphi[j], sj = sinphi[j];
    for (int k = 0; k < K1; ++k) {
      const double wk = (k == 0 || k == Kl) ? 0.5 : 1.0;
      fx -= wk * pr[k] * cj;
      fy -= wk * pr[k] * sj;
      torque += wk * tr[k];
      if (hr[k] < hmin) {
        hmin = hr[k];
        nmin = row + k;
      }
    }
  }
  for (const int n : pk_cells) {  // a cell a pocket edge crosses: its mean of 1/h
    const int k = n % K1;
    const double wk = (k == 0 || k == Kl) ? 0.5 : 1.0;
    const double cf = node_cf(n, h[n]);
    torque += wk * cf * node_mu(n) * omega * R * theta[n] * (pocket_inv_h(n) - 1.0 / h[n]);
  }
  out.force_n = Eigen::Vector2d(fx * area, fy * area);
  out.friction_torque_nm = torque * area * R;
  if (!(out.force_n.allFinite() && std::isfinite(out.friction_torque_nm)))
    throw ConvergenceError(
        "Reynolds solve: non-finite pressure or force (the film's pressure scale "
        "viscosity_pa_s*omega*(R/clearance_m)^2 = " +
        reynolds_detail::num(mu * std::abs(omega) * (R / c) * (R / c)) +
        " Pa is beyond what double precision represents)");
  out.h_min_m = hmin;
  out.h_min_angle_deg = (nmin / K1) * dphi * 180.0 / kPi;

  flows();

  out.p_pa.resize(N, K1);
  out.theta.resize(N, K1);
  out.h_m.resize(N, K1);
  std::copy(p.begin(), p.end(), out.p_pa.data());
  std::copy(theta.begin(), theta.end(), out.theta.data());
  std::copy(h.begin(), h.end(), out.h_m.data());
}

// Supply and side flows from the finite-volume fluxes of the solution (the cell balances of
// the solve itself, so a mass-conserving film balances them to round-off).
//
// Supply: the flux through every face from a groove node into a film cell. A cell of a
// Swift–Stieber cavitated zone (strictly active: the multiplier is the mass the model creates
// there; gumbel: the clipped nodes) carries no defined flow, so its faces to a groove count
// nothing. With a supply line at the maximum film this is the flow into the film just
// downstream of the line (Raimondi & Boyd's Q); before, the full Couette flux of the
// cavitated cell upstream was subtracted (about -0.04 R c N L instead of +4.99 at L/D = 1/4,
// ε = 0.6). jfo and full films count every face (a partly filled film entering a groove from
// upstream is the flow that recirculates).
//
// Side flow with open ends: the flux through the faces half a cell inside the ends plus the
// balance of the end half cells between those faces and the ends (their Couette inflow minus
// outflow and storage; their Poiseuille flux around is 0 with p = 0 on the end rows, to
// second order the true one). Without the half cells the side flow was the flow at
// z = ±(L/2 − Δz/2), first-order (−6.8 % at 72 x 16 against Raimondi & Boyd). End half cells
// of groove columns belong to the supply (their fluxes into film half cells are supply); the
// half cell of a film column whose inner node is cavitated (as above) carries nothing; its
// fill θ is the inner node's. Every face is counted once on each side of a balance, so
// supply − side = storage for jfo and full films (exactly, to round-off).
void ReynoldsSolver::Impl::flows() {
  const int Kl = K1 - 1;
  const bool fwd = omega >= 0.0;
  const bool clipped = cav == Cavitation::gumbel ||
                       (geo.short_bearing && cav == Cavitation::reynolds);
  auto no_flow = [&](int n) {  // n: a film node; cavitated in a Swift–Stieber / clipped film
    if (clipped) return pfull[n] < 0.0;
    if (cav != Cavitation::reynolds) return false;
    const LinearSystem& S = *sys;
    const int m = (S.half && n % K1 > Kh) ? mirror(n) : n;
    const int u = S.unk[m];
    return u >= 0 && S.active[u] && !biactive[n];
  };
  double qin = 0.0, qside = 0.0;
  // faces from groove nodes (interior rows) into film cells; a sealed end's half cell takes
  // half a φ-face
  for (const int g : groove_nodes) {
    const int e = east(g), w = west(g), k = g % K1;
    if (!fixed[e] && !no_flow(e))
      qin += (end_row(e) ? 0.5 : 1.0) *
             (cE[g] * (p[g] - p[e]) + qE[g] * (fwd ? theta[g] : theta[e]));
    if (!fixed[w] && !no_flow(w))
      qin += (end_row(w) ? 0.5 : 1.0) *
             (cE[w] * (p[g] - p[w]) - qE[w] * (fwd ? theta[w] : theta[g]));
    if (k == 1 && !fixed[g - 1] && !no_flow(g - 1)) qin += cN[g - 1] * (p[g] - p[g - 1]);
    if (k == Kl - 1 && !fixed[g + 1] && !no_flow(g + 1)) qin += cN[g] * (p[g] - p[g + 1]);
  }
  for (int j = 0; j < N; ++j) {
    const int n0 = j * K1, nl = n0 + Kl;
    if (sealed) {  // through the seals to the ambient 0
      qside += gseal * p[n0];
      qside += gseal * p[nl];
    } else {  // through the faces half a cell inside the ends
      if (!fixed[n0 + 1]) qside += cN[n0] * (p[n0 + 1] - p[n0]);
      if (!fixed[nl - 1]) qside += cN[nl - 1] * (p[nl - 1] - p[nl]);
    }
  }
  if (!sealed) {
    for (const int k : {0, Kl}) {
      const int kin = k == 0 ? 1 : Kl - 1;  // the inner row
      // φ-flux from end node a to its east neighbour b (fills from the inner rows)
      auto flux = [&](int a, int b) {
        return cE[a] * (p[a] - p[b]) +
               qE[a] * (fwd ? theta[a - k + kin] : theta[b - k + kin]);
      };
      for (int j = 0; j < N; ++j) {
        const int n = j * K1 + k, e = east(n), w = west(n);
        if (groove[n - k + kin]) continue;         // a groove column: supply
        if (no_flow(n - k + kin)) continue;        // a cavitated column: no flow
        const double in = flux(w, n), outf = flux(n, e);
        qside += 0.5 * (in - outf - src[n] * theta[n - k + kin]);
        if (groove[w - k + kin]) qin += 0.5 * in;
        if (groove[e - k + kin]) qin -= 0.5 * outf;
      }
    }
  }
  out.inlet_flow_m3_s = qin;
  out.side_flow_m3_s = qside;
}

// The part of postprocess() a caller integrating p itself needs: p and h_min (the same
// values bit for bit), no force, torque, flows or fill copies.
void ReynoldsSolver::Impl::postprocess_pressure() {
  // Four independent lanes (0·p is NaN exactly when p is not finite); the node of the
  // minimum film is the first one that attains it, as in postprocess().
  double m4[4] = {h[0], h[0], h[0], h[0]}, c4[4] = {0.0, 0.0, 0.0, 0.0};
  int q = 0;
  for (; q + 4 <= n_nodes; q += 4)
    for (int l = 0; l < 4; ++l) {
      m4[l] = std::min(m4[l], h[q + l]);
      c4[l] += 0.0 * p[q + l];
    }
  for (; q < n_nodes; ++q) {
    m4[0] = std::min(m4[0], h[q]);
    c4[0] += 0.0 * p[q];
  }
  const double hmin = std::min(std::min(m4[0], m4[1]), std::min(m4[2], m4[3]));
  int nmin = 0;
  while (h[nmin] != hmin) ++nmin;
  if (!(c4[0] + c4[1] + c4[2] + c4[3] == 0.0))
    throw ConvergenceError(
        "Reynolds solve: non-finite pressure (the film's pressure scale "
        "viscosity_pa_s*omega*(R/clearance_m)^2 = " +
        reynolds_detail::num(mu * std::abs(omega) * (R / c) * (R / c)) +
        " Pa is beyond what double precision represents)");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.force_n = Eigen::Vector2d(nan, nan);
  out.friction_torque_nm = out.inlet_flow_m3_s = out.side_flow_m3_s = nan;
  out.h_min_m = hmin;
  out.h_min_angle_deg = (nmin / K1) * dphi * 180.0 / kPi;
  out.p_pa.resize(N, K1);
  out.theta.resize(0, 0);
  out.h_m.resize(0, 0);
  std::copy(p.begin(), p.end(), out.p_pa.data());
}

void ReynoldsSolver::Impl::residual_derivative(const LinearSystem& S, const double* dh,
                                               const double* dhdot, Eigen::VectorXd& outv) const {
  if (has_pockets)
    residual_derivative_t<true>(S, dh, dhdot, outv);
  else
    residual_derivative_t<false>(S, dh, dhdot, outv);
}

template <bool kPockets>
void ReynoldsSolver::Impl::residual_derivative_t(const LinearSystem& S, const double* dh,
                                                 const double* dhdot,
                                                 Eigen::VectorXd& outv) const {
  // Pressure at which the operator is linearised: the unclipped solution for none/gumbel.
  const std::vector<double>& P =
      (cav == Cavitation::none || cav == Cavitation::gumbel) ? pfull : p;
  const double fE = 3.0 * dz / (12.0 * mu * R * dphi);
  const double fN = 3.0 * R * dphi / (12.0 * mu * dz);
  const double fq = 0.5 * omega * R * dz;
  const double fs = R * dphi * dz;
  const bool fwd = omega >= 0.0;
  outv.resize(S.n_unk);
  // A face a pocket edge crosses: d(conductance)/dh and d(Couette h)/dh of the stepped film,
  // in place of fE h_f² (the factor 3 is in fE, fN) and 1 (reynolds_pockets.cpp).
  [[maybe_unused]] auto pocket = [&](int face, int a, int b, double f3, double& g,
                                     double& bq) {
    if (face < 0) return;
    double G3, Gc, dG3, dGc;
    pocket_face(face, 0.5 * (h_smooth[a] + h_smooth[b]), G3, Gc, &dG3, &dGc);
    g = f3 / 3.0 * dG3;
    if (turb) {  // d(G3·12/k(cbrt G3))/dhf = dG3 · dm (reynolds_turbulence.cpp)
      double m, dm;
      turb_face(std::cbrt(G3), pk_faces[face].north, pk_faces[face].n, m, dm);
      g *= dm;
    }
    bq = dGc;
  };
  // turbulent films: each conductance derivative takes its face's multiplier dm
  auto tmul = [&](double hf, bool axial, int q) {
    double m, dm;
    turb_face(hf, axial, q, m, dm);
    return dm;
  };
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    const int e = east(n), w = west(n);
    if (end_row(n)) {  // a sealed end's half cell; the seal's conductance does not depend on h
      const int k = n % K1, in = k == 0 ? n + 1 : n - 1;
      const double he = 0.5 * (h[n] + h[e]), hw = 0.5 * (h[w] + h[n]);
      const double hi = 0.5 * (h[n] + h[in]);
      const double dhe = 0.5 * (dh[n] + dh[e]), dhw = 0.5 * (dh[w] + dh[n]);
      const double dhi = 0.5 * (dh[n] + dh[in]);
      double ge = fE * he * he, gw = fE * hw * hw, gi = fN * hi * hi;
      if (turb) {
        ge *= tmul(he, false, n);
        gw *= tmul(hw, false, w);
        gi *= tmul(hi, true, k == 0 ? n : in);
      }
      double qe = dhe, qw = dhw;  // Couette-thickness changes of the two φ-faces
      if constexpr (kPockets) {
        double be = 1.0, bw = 1.0, unused = 1.0;
        pocket(pk_east[n], n, e, fE, ge, be);
        pocket(pk_east[w], w, n, fE, gw, bw);
        pocket(pk_north[k == 0 ? n : in], k == 0 ? n : in, k == 0 ? in : n, fN, gi, unused);
        qe = be * dhe;
        qw = bw * dhw;
      }
      if (visc_field) {  // the faces' μ/μ_face (set_film)
        ge *= vmE[n];
        gw *= vmE[w];
        gi *= vmN[k == 0 ? n : in];
      }
      double r = ge * dhe * (P[n] - P[e]) + gw * dhw * (P[n] - P[w]);
      if (fwd)
        r += fq * (qe * theta[n] - qw * theta[w]);
      else
        r += fq * (qe * theta[e] - qw * theta[n]);
      r += fs * dhdot[n] * theta[n];
      outv[i] = 0.5 * r + gi * dhi * (P[n] - P[in]);
      continue;
    }
    const double he = 0.5 * (h[n] + h[e]), hw = 0.5 * (h[w] + h[n]);
    const double hn = 0.5 * (h[n] + h[n + 1]), hs = 0.5 * (h[n - 1] + h[n]);
    const double dhe = 0.5 * (dh[n] + dh[e]), dhw = 0.5 * (dh[w] + dh[n]);
    const double dhn = 0.5 * (dh[n] + dh[n + 1]), dhs = 0.5 * (dh[n - 1] + dh[n]);
    double ge = fE * he * he, gw = fE * hw * hw, gn = fN * hn * hn, gs = fN * hs * hs;
    if (turb) {
      ge *= tmul(he, false, n);
      gw *= tmul(hw, false, w);
      gn *= tmul(hn, true, n);
      gs *= tmul(hs, true, n - 1);
    }
    double qe = dhe, qw = dhw;
    if constexpr (kPockets) {
      double be = 1.0, bw = 1.0, unused = 1.0;
      pocket(pk_east[n], n, e, fE, ge, be);
      pocket(pk_east[w], w, n, fE, gw, bw);
      pocket(pk_north[n], n, n + 1, fN, gn, unused);
      pocket(pk_north[n - 1], n - 1, n, fN, gs, unused);
      qe = be * dhe;
      qw = bw * dhw;
    }
    if (visc_field) {
      ge *= vmE[n];
      gw *= vmE[w];
      gn *= vmN[n];
      gs *= vmN[n - 1];
    }
    double r = ge * dhe * (P[n] - P[e]) + gw * dhw * (P[n] - P[w]) +
               gn * dhn * (P[n] - P[n + 1]) + gs * dhs * (P[n] - P[n - 1]);
    if (fwd)
      r += fq * (qe * theta[n] - qw * theta[w]);
    else
      r += fq * (qe * theta[e] - qw * theta[n]);
    r += fs * dhdot[n] * theta[n];
    outv[i] = S.wphi[i] * r;  // a half cell carries half of the full cell's balance
  }
}

// ---- public ------------------------------------------------------------------------------

const FilmSolution& ReynoldsSolver::solve(const RowMatrixXd& h, const RowMatrixXd& dhdt,
                                          double omega, bool z_constant_in) {
  Impl& s = *impl_;
  // rigid()'s promise holds for this call only: taken (and cleared) before anything can throw
  const bool z_constant = s.film_z_constant || z_constant_in;
  s.film_z_constant = false;
  if (h.rows() != s.N || h.cols() != s.K1)
    throw InputError(shape_msg("h", s.N, s.K1, h.rows(), h.cols()));
  if (dhdt.rows() != s.N || dhdt.cols() != s.K1)
    throw InputError(shape_msg("dhdt", s.N, s.K1, dhdt.rows(), dhdt.cols()));
  s.solved = false;
  s.set_film(h.data(), dhdt.data(), omega);
  if (s.geo.short_bearing) {
    s.solve_short();
    s.pressure_only ? s.postprocess_pressure() : s.postprocess();
    s.solved = true;
    return s.out;
  }
  // rigid() passes films constant along z (mirror-symmetric by construction)
  const bool half = s.use_symmetry && s.pockets_symmetric && s.visc_symmetric &&
                    (z_constant || (s.symmetric(h.data()) && s.symmetric(dhdt.data())));
  if (half && !s.halfsys_built) {
    s.build_system(s.halfsys, true);
    s.halfsys_built = true;
  }
  LinearSystem& S = half ? s.halfsys : s.full;
  s.sys = &S;
  switch (s.cav) {
    case Cavitation::none:
    case Cavitation::gumbel:
      s.solve_linear(S);
      break;
    case Cavitation::reynolds:
      s.solve_reynolds(S);
      break;
    case Cavitation::jfo:
      s.solve_supplied(S);
      break;
  }
  s.pressure_only ? s.postprocess_pressure() : s.postprocess();
  if (s.cav == Cavitation::jfo && !s.pressure_only) s.full_film_start();
  s.solved = true;
  return s.out;
}

RowMatrixXd ReynoldsSolver::linearize(const RowMatrixXd& dh, const RowMatrixXd& d_dhdt) {
  Impl& s = *impl_;
  if (!s.solved) throw InputError("linearize: call solve() or rigid() first");
  if (dh.rows() != s.N || dh.cols() != s.K1)
    throw InputError(shape_msg("dh", s.N, s.K1, dh.rows(), dh.cols()));
  if (d_dhdt.rows() != s.N || d_dhdt.cols() != s.K1)
    throw InputError(shape_msg("d_dhdt", s.N, s.K1, d_dhdt.rows(), d_dhdt.cols()));
  if (s.geo.short_bearing) {
    // dp = 6μ(z² − L²/4) (ds/h³ − 3 s dh/h⁴); the clipped films take the one-sided mean
    // where the unclipped pressure vanishes to round-off (as the gumbel branch below).
    RowMatrixXd dp(s.N, s.K1);
    double pmax = 0.0;
    for (int n = 0; n < s.n_nodes; ++n) pmax = std::max(pmax, std::abs(s.pfull[n]));
    const double ptol = 1e-10 * pmax;
    for (int n = 0; n < s.n_nodes; ++n) {
      const double hv = s.h[n], src = s.short_source(s.h.data(), s.hdot.data(), n);
      const double dsrc = s.short_source(dh.data(), d_dhdt.data(), n);
      // turbulent: the factor k_z(h)/2 also varies, d ln k_z/d ln h = Re dk_z/dRe / k_z
      double q3 = 3.0;
      if (s.turb) {
        const TurbulenceFactors t = s.tfac(s.re_per_h * hv);
        q3 -= t.re_dkz / t.kz;
      }
      const double v = s.short_factor(n) * (dsrc - q3 * src * dh.data()[n] / hv) /
                       (hv * hv * hv);
      double wgt = 1.0;
      if (s.cav != Cavitation::none)
        wgt = s.pfull[n] > ptol ? 1.0 : (s.pfull[n] < -ptol ? 0.0 : 0.5);
      dp.data()[n] = wgt * v;
    }
    return dp;
  }
  LinearSystem* S = s.sys;
  if (S->half && !(s.symmetric(dh.data()) && s.symmetric(d_dhdt.data()))) {
    // A non-symmetric perturbation of a symmetric film: factorise the full system with the
    // mirrored cavitation set (same base state, so the same frozen-set derivative).
    LinearSystem& F = s.full;
    const LinearSystem& Hs = *S;
    for (int i = 0; i < F.n_unk; ++i) {
      const int n = F.node_of[i];
      const int m = (n % s.K1) > s.Kh ? s.mirror(n) : n;
      F.active[i] = Hs.active[Hs.unk[m]];
    }
    if (s.cav == Cavitation::jfo) {
      s.fill_jfo(F);
      Eigen::VectorXd b0 = Eigen::VectorXd::Zero(F.n_unk), x0;
      b0.setOnes();
      s.factor_solve_jfo(F, b0, x0);
    } else {
      const bool masked = s.cav == Cavitation::reynolds;
      s.factor_spd(F, masked ? &F.active : nullptr);
    }
    s.sys = S = &F;
  }
  Eigen::VectorXd r;
  s.residual_derivative(*S, dh.data(), d_dhdt.data(), r);
  RowMatrixXd dp = RowMatrixXd::Zero(s.N, s.K1);
  double* dpd = dp.data();
  if (S->factor == LinearSystem::Factor::ldlt || S->factor == LinearSystem::Factor::band) {
    Eigen::VectorXd x(S->n_unk);
    if (s.cav == Cavitation::reynolds && s.n_biactive > 0) {
      // Degenerate set: the limit of central differences, (D(+d) − D(−d))/2, of the
      // directional derivatives D — what coefficients_fd converges to as its step → 0.
      Eigen::VectorXd xp, xm;
      s.solve_derivative_lcp(*S, r, xp);
      const Eigen::VectorXd mr = -r;
      s.solve_derivative_lcp(*S, mr, xm);
      x = 0.5 * (xp - xm);
      for (int i = 0; i < S->n_unk; ++i) dpd[S->node_of[i]] = x[i];
      if (S->half)
        for (int j = 0; j < s.N; ++j)
          for (int k = s.Kh + 1; k < s.mirror_end(); ++k) {
            dpd[j * s.K1 + k] = dpd[j * s.K1 + s.K1 - 1 - k];  // the mirror node
          }
      return dp;
    }
    if (s.cav == Cavitation::reynolds)
      for (int i = 0; i < S->n_unk; ++i)
        if (S->active[i]) r[i] = 0.0;
    r = -r;
    S->solve_spd(r.data(), x.data());
    // gumbel: p = max(p_full, 0); where p_full vanishes to round-off (e.g. on a symmetry line)
    // the one-sided derivatives differ and we take their mean, as a central difference does.
    double pmax = 0.0;
    for (int n = 0; n < s.n_nodes; ++n) pmax = std::max(pmax, std::abs(s.pfull[n]));
    const double ptol = 1e-10 * pmax;
    for (int i = 0; i < S->n_unk; ++i) {
      const int n = S->node_of[i];
      double wgt = 1.0;
      if (s.cav == Cavitation::gumbel)
        wgt = s.pfull[n] > ptol ? 1.0 : (s.pfull[n] < -ptol ? 0.0 : 0.5);
      if (s.cav == Cavitation::reynolds && S->active[i]) wgt = 0.0;
      dpd[n] = wgt * x[i];
    }
  } else {
    const Eigen::VectorXd mr = -r;
    Eigen::VectorXd x;
    s.solve_factored(*S, mr, x);
    if (s.cav == Cavitation::jfo && s.supply_s < 2.0) {
      // a starved film: the metered supply is held (reynolds_starved.cpp)
      const double ds = s.hold_supply(*S, dh.data(), x);
      if (s.supply_s >= 1.0)
        for (const int g : s.groove_nodes) dpd[g] = ds * s.groove_p0[g];
    }
    for (int i = 0; i < S->n_unk; ++i)
      if (!S->active[i]) dpd[S->node_of[i]] = x[i];
  }
  if (S->half)
    for (int j = 0; j < s.N; ++j)
      for (int k = s.Kh + 1; k < s.mirror_end(); ++k) {
        dpd[j * s.K1 + k] = dpd[j * s.K1 + s.K1 - 1 - k];  // the mirror node
      }
  return dp;
}

void ReynoldsSolver::Impl::make_trig_fields() {
  if (trig_c.rows() == N) return;
  trig_c.resize(N, K1);
  trig_s.resize(N, K1);
  trig_zero = RowMatrixXd::Zero(N, K1);
  for (int j = 0; j < N; ++j) {
    trig_c.row(j).setConstant(-cosphi[j]);
    trig_s.row(j).setConstant(-sinphi[j]);
  }
}

bool ReynoldsSolver::Impl::linearize_trig4(RowMatrixXd (&dpo)[4]) {
  if (!solved || geo.short_bearing || cav == Cavitation::jfo) return false;
  LinearSystem& S = *sys;
  if (S.factor != LinearSystem::Factor::ldlt && S.factor != LinearSystem::Factor::band)
    return false;
  if (cav == Cavitation::reynolds && n_biactive > 0) return false;
  // the fields are constant along z: mirror-symmetric, so a half system stays the system
  const double* dh[4] = {trig_c.data(), trig_s.data(), trig_zero.data(), trig_zero.data()};
  const double* dhd[4] = {trig_zero.data(), trig_zero.data(), trig_c.data(), trig_s.data()};
  double* x[4];
  const double fs = R * dphi * dz;  // as residual_derivative_t
  for (int v = 0; v < 4; ++v) {
    Eigen::VectorXd& r = lin_r[v];
    if (v < 2) {
      residual_derivative(S, dh[v], dhd[v], r);
    } else {
      // dh = 0: every term of residual_derivative but the squeeze one is a product with a
      // face's dh (±0), so its value is the squeeze term alone (the same bits, up to the sign
      // of a zero)
      r.resize(S.n_unk);
      for (int i = 0; i < S.n_unk; ++i) {
        const int n = S.node_of[i];
        r[i] = S.wphi[i] * (fs * dhd[v][n] * theta[n]);
      }
    }
    if (cav == Cavitation::reynolds)
      for (int i = 0; i < S.n_unk; ++i)
        if (S.active[i]) r[i] = 0.0;
    r = -r;
    x[v] = r.data();
  }
  S.solve_spd4(x);
  // as linearize(): gumbel's one-sided mean where p_full vanishes to round-off
  double pmax = 0.0;
  for (int n = 0; n < n_nodes; ++n) pmax = std::max(pmax, std::abs(pfull[n]));
  const double ptol = 1e-10 * pmax;
  for (int v = 0; v < 4; ++v) {
    dpo[v] = RowMatrixXd::Zero(N, K1);
    double* dpd = dpo[v].data();
    for (int i = 0; i < S.n_unk; ++i) {
      const int n = S.node_of[i];
      double wgt = 1.0;
      if (cav == Cavitation::gumbel)
        wgt = pfull[n] > ptol ? 1.0 : (pfull[n] < -ptol ? 0.0 : 0.5);
      if (cav == Cavitation::reynolds && S.active[i]) wgt = 0.0;
      dpd[n] = wgt * x[v][i];
    }
    if (S.half)
      for (int j = 0; j < N; ++j)
        for (int k = Kh + 1; k < mirror_end(); ++k) dpd[j * K1 + k] = dpd[j * K1 + K1 - 1 - k];
  }
  return true;
}

double ReynoldsSolver::integrate(const RowMatrixXd& pr, const RowMatrixXd& g) const {
  const Impl& s = *impl_;
  if (pr.rows() != s.N || pr.cols() != s.K1)
    throw InputError(shape_msg("p", s.N, s.K1, pr.rows(), pr.cols()));
  if (g.rows() != s.N || g.cols() != s.K1)
    throw InputError(shape_msg("g", s.N, s.K1, g.rows(), g.cols()));
  double acc = 0.0;
  for (int j = 0, n = 0; j < s.N; ++j)  // node n = j·K1 + k, in node order (no division)
    for (int k = 0; k < s.K1; ++k, ++n) {
      const double wk = (k == 0 || k == s.K1 - 1) ? 0.5 : 1.0;
      acc += wk * pr.data()[n] * g.data()[n];
    }
  return acc * s.R * s.dphi * s.dz;
}

Eigen::Vector2d ReynoldsSolver::integrate_force(const RowMatrixXd& pr) const {
  const Impl& s = *impl_;
  if (pr.rows() != s.N || pr.cols() != s.K1)
    throw InputError(shape_msg("p", s.N, s.K1, pr.rows(), pr.cols()));
  double fx = 0.0, fy = 0.0;
  for (int j = 0, n = 0; j < s.N; ++j)  // node order, as before (no division per node)
    for (int k = 0; k < s.K1; ++k, ++n) {
      const double wk = (k == 0 || k == s.K1 - 1) ? 0.5 : 1.0;
      fx -= wk * pr.data()[n] * s.cosphi[j];
      fy -= wk * pr.data()[n] * s.sinphi[j];
    }
  const double area = s.R * s.dphi * s.dz;
  return Eigen::Vector2d(fx * area, fy * area);
}

}  // namespace rotordyn
