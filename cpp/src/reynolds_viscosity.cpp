// A viscosity per node (the thermo-hydrodynamic film, thd.hpp) and the film's finite-volume
// flows and viscous dissipation, the transport terms of the energy equation. A turbulent film
// takes every face's and node's Re_h at its own viscosity (reynolds_turbulence.cpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

using reynolds_detail::num;

void ReynoldsSolver::set_viscosity_field(const RowMatrixXd& v) {
  Impl& s = *impl_;
  if (v.rows() != s.N || v.cols() != s.K1)
    throw InputError("viscosity_pa_s: expected a (" + std::to_string(s.N) + ", " +
                     std::to_string(s.K1) + ") node field, got (" + std::to_string(v.rows()) +
                     ", " + std::to_string(v.cols()) + ")");
  if (s.geo.short_bearing)
    throw InputError("short_bearing: a viscosity field needs the finite film (the short-bearing "
                     "model has no circumferential flow), got short_bearing = true");
  if (s.sealed)
    throw InputError("end_seal: a viscosity field needs open ends (the seal's flow carries no "
                     "temperature model), got sealed ends");
  for (int n = 0; n < s.n_nodes; ++n) {
    const double m = v.data()[n];
    if (!(std::isfinite(m) && m > 0.0))
      throw InputError("viscosity_pa_s: expected finite values > 0 at every node, got " + num(m) +
                       " at node (" + std::to_string(n / s.K1) + ", " + std::to_string(n % s.K1) +
                       ")");
  }
  s.mu_node.assign(v.data(), v.data() + s.n_nodes);
  s.vmE.assign(s.n_nodes, 1.0);
  s.vmN.assign(s.n_nodes, 1.0);
  for (int n = 0; n < s.n_nodes; ++n) {
    s.vmE[n] = s.mu / (0.5 * (s.mu_node[n] + s.mu_node[s.east(n)]));
    if (n % s.K1 + 1 < s.K1) s.vmN[n] = s.mu / (0.5 * (s.mu_node[n] + s.mu_node[n + 1]));
  }
  s.visc_field = true;
  s.visc_symmetric = s.symmetric(s.mu_node.data());
  s.solved = false;
}

FilmFlows ReynoldsSolver::film_flows() const {
  const Impl& s = *impl_;
  if (!s.solved || s.pressure_only || s.sys == nullptr)
    throw ConvergenceError("film_flows: no solve with full output to take the flows from");
  FilmFlows f;
  s.film_flows(f);
  return f;
}

void ReynoldsSolver::Impl::film_flows(FilmFlows& f) const {
  const int Kl = K1 - 1;
  const bool fwd = omega >= 0.0;
  const bool clipped = cav == Cavitation::gumbel;
  auto cavitated = [&](int n) {  // a Swift–Stieber (strictly active) or clipped node
    if (fixed[n]) return false;
    if (clipped) return pfull[n] < 0.0;
    if (cav != Cavitation::reynolds) return false;
    const LinearSystem& S = *sys;
    const int m = (S.half && n % K1 > Kh) ? mirror(n) : n;
    const int u = S.unk[m];
    return u >= 0 && S.active[u] && !biactive[n];
  };
  // A cavitated node's distance from the full film, in the units of a pressure: its
  // complementarity variable, continuous in the film's inputs and 0 where the node changes
  // between cavitated and full. Swift–Stieber: the multiplier (A p − b)_n ≥ 0 over the
  // conductance of the face to the full neighbour; clipped: −p_full, the unclipped pressure.
  // front(n, m, g): where the zero of that variable lies between the cavitated node n and its
  // neighbour m, 1 at n and 0 at m (linear between p_m ≥ 0 and −ζ_n); 0 if m is not full.
  auto front = [&](int n, double rn, int m, double g) {
    const double pm = p[m];
    if (!(pm > 0.0)) return 0.0;
    const double zn = clipped ? -pfull[n] : (g > 0.0 ? rn / g : 0.0);
    return zn > 0.0 ? pm / (pm + zn) : 1.0;
  };
  // A Swift–Stieber node whose multiplier is within kNearFull of the degenerate band (p = 0
  // and A p − b = 0 together, reynolds_solve.cpp) is on the edge of the full film whatever
  // its neighbours' pressures: its fill goes linearly from 1 at the band's edge (where a
  // degenerate node is full, fill 1) to its streamer's at kNearFull × the band. front()
  // cannot give that where no neighbour carries pressure: on an unloaded tilting pad (p = 0
  // everywhere, the pad at the edge of its pressure-free branch) the cell before the trailing
  // edge sat at a multiplier of round-off size, and round-off chose fill 1 or θ_s = 0.965:
  // the pad's dissipation jumped by 0.35 %, its effective temperature by 1.5e-3 K, and the
  // generator's thermal equilibrium cycled without a fixed point (docs/film-physics.md, "When
  // the pad temperatures do not settle").
  constexpr double kNearFull = 1e6;
  auto near_full = [&](double rn) {
    const double d = deg_mu_last;
    if (clipped || !(d > 0.0)) return 0.0;
    if (rn <= d) return 1.0;
    return std::max(0.0, (kNearFull * d - rn) / ((kNearFull - 1.0) * d));
  };
  std::vector<double> th(theta);
  if (cav == Cavitation::reynolds || clipped) {
    // Couette streamers: from each rupture, the flow through the upstream face fills the
    // fraction θ_s = F/(U h_f Δz/2) of the cell's downstream face (p = 0 in the zone).
    // A cavitated node next to the full film takes θ_s + (1 − θ_s) s, s = the largest
    // front() over its four neighbours: the full film's fill 1 where the node is about to
    // turn full (ζ_n → 0), its streamer's where the neighbour is about to cavitate (p_m → 0).
    // Without it the fill of a node jumped θ_s <-> 1 as it changed between cavitated and full
    // (a Swift–Stieber film creates the streamers' missing mass at reformation), so the THD map
    // jumped there and could have two fixed points (docs/film-physics.md, "Thermal films with
    // a tilted journal").
    const int dir = fwd ? 1 : N - 1;
    for (int k = 1; k < Kl; ++k) {
      int j0 = -1;
      for (int j = 0; j < N && j0 < 0; ++j)
        if (!cavitated(j * K1 + k)) j0 = j;
      if (j0 < 0) continue;  // a wholly cavitated row (degenerate): θ stays 1
      for (int step = 1; step < N; ++step) {
        const int j = (j0 + step * dir) % N, n = j * K1 + k;
        if (!cavitated(n)) continue;
        const int up = fwd ? west(n) : east(n);
        double F, cap;
        if (fwd) {
          F = cE[up] * (p[up] - p[n]) + qE[up] * th[up];
          cap = qE[n];
        } else {
          F = -(cE[n] * (p[n] - p[up]) + qE[n] * th[up]);
          cap = -qE[west(n)];
        }
        const double ts = cap > 0.0 ? std::clamp(F / cap, 0.0, 1.0) : 1.0;
        const double rn = clipped ? 0.0 : cell_residual(n, p);
        const int e = east(n), w = west(n);
        const double sf = std::max({front(n, rn, e, cE[n]), front(n, rn, w, cE[w]),
                                    front(n, rn, n + 1, cN[n]), front(n, rn, n - 1, cN[n - 1]),
                                    near_full(rn)});
        th[n] = ts + (1.0 - ts) * sf;
      }
    }
  }
  if (!sealed && K1 > 2)
    for (int j = 0; j < N; ++j) {  // open ends: the fill of their inner rows (as flows())
      th[j * K1] = th[j * K1 + 1];
      th[j * K1 + Kl] = th[j * K1 + Kl - 1];
    }
  f.q_phi_m3_s.resize(N, K1);
  f.q_z_m3_s.resize(N, K1);
  f.fill.resize(N, K1);
  f.dissipation_w.setZero(N, K1);
  f.area_m2.resize(N, K1);
  f.viscosity_pa_s.resize(N, K1);
  f.makeup_m3_s.setZero(N, K1);
  double* qp = f.q_phi_m3_s.data();
  double* qz = f.q_z_m3_s.data();
  double* ds = f.dissipation_w.data();
  const double U = omega * R, a0 = R * dphi * dz;
  for (int n = 0; n < n_nodes; ++n) {
    const int k = n % K1, e = east(n);
    const double half = (k == 0 || k == Kl) ? 0.5 : 1.0;
    const double ce = half * cE[n], dpe = p[n] - p[e];
    qp[n] = ce * dpe + half * qE[n] * (fwd ? th[n] : th[e]);
    const double pe = 0.5 * ce * dpe * dpe;  // Poiseuille dissipation c Δp², half per side
    ds[n] += pe;
    ds[e] += pe;
    if (k < Kl) {
      const double dpn = p[n] - p[n + 1];
      qz[n] = cN[n] * dpn;
      const double pn = 0.5 * cN[n] * dpn * dpn;
      ds[n] += pn;
      ds[n + 1] += pn;
    } else {
      qz[n] = 0.0;
    }
    const double area = half * a0;
    f.area_m2.data()[n] = area;
    f.fill.data()[n] = th[n];
    f.viscosity_pa_s.data()[n] = node_mu(n);
    // Couette μU²θ/h (turbulent: the wall-shear factor C_f at the node's Re_h, as the torque)
    const double cf = node_cf(n, h[n]);
    ds[n] += cf * node_mu(n) * U * U * th[n] / h[n] * area;
  }
  for (const int n : pk_cells) {  // a cell a pocket edge crosses: its mean of 1/h
    const int k = n % K1;
    const double area = ((k == 0 || k == Kl) ? 0.5 : 1.0) * a0;
    const double cf = node_cf(n, h[n]);
    ds[n] += cf * node_mu(n) * U * U * th[n] * (pocket_inv_h(n) - 1.0 / h[n]) * area;
  }
}

}  // namespace rotordyn
