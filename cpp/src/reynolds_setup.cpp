// ReynoldsSolver: input validation, grid and groove layout, sparse pattern, film coefficients.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {
using reynolds_detail::kPi;
using reynolds_detail::num;
using reynolds_detail::kMaxFactorBytes;
using reynolds_detail::kMaxFactorFlops;
using reynolds_detail::kMaxFilmNodes;
using reynolds_detail::kMaxOmega;

void require_positive(double v, const char* field) {
  if (!(std::isfinite(v) && v > 0.0))
    throw InputError(std::string(field) + ": expected a finite value > 0, got " + num(v));
}
}  // namespace

Cavitation parse_cavitation(const std::string& name) {
  if (name == "none") return Cavitation::none;
  if (name == "gumbel") return Cavitation::gumbel;
  if (name == "reynolds") return Cavitation::reynolds;
  if (name == "jfo") return Cavitation::jfo;
  throw InputError("cavitation: expected one of 'none', 'gumbel', 'reynolds', 'jfo', got '" +
                   name + "'");
}

const char* cavitation_name(Cavitation c) {
  switch (c) {
    case Cavitation::none:
      return "none";
    case Cavitation::gumbel:
      return "gumbel";
    case Cavitation::reynolds:
      return "reynolds";
    case Cavitation::jfo:
      return "jfo";
  }
  return "?";
}

void JournalBearingGeometry::validate() const {
  require_positive(diameter_m, "diameter_m");
  require_positive(length_m, "length_m");
  require_positive(clearance_m, "clearance_m");
  require_positive(viscosity_pa_s, "viscosity_pa_s");
  if (!(clearance_m < 0.5 * diameter_m))
    throw InputError("clearance_m: expected 0 < clearance_m < diameter_m/2 = " +
                     num(0.5 * diameter_m) + ", got " + num(clearance_m));
  if (!(end_seal_conductance > 0.0))  // NaN fails too; +inf: open ends
    throw InputError("end_seal_conductance: expected a seal conductance > 0 m^2/(Pa s) "
                     "(inf: open ends; a fully sealed film without a supply has no pressure "
                     "level: use a small positive value), got " + num(end_seal_conductance));
  // Below 1e-8 of the film's own axial conductance c³/(12μL) the seal is the fully sealed
  // limit to ~1e-8, and the film's pressure level (set by the seal alone) is lost in the
  // round-off of a nearly singular operator (a π film then clips a wrong level).
  const double g_min = 1e-8 * clearance_m * clearance_m * clearance_m /
                       (12.0 * viscosity_pa_s * length_m);
  if (std::isfinite(end_seal_conductance) && !(end_seal_conductance >= g_min))
    throw InputError("end_seal_conductance: expected >= 1e-8 clearance_m^3/(12 viscosity_pa_s "
                     "length_m) = " + num(g_min) + " m^2/(Pa s) (tighter is the fully sealed "
                     "limit, whose pressure level round-off would lose), got " +
                     num(end_seal_conductance));
  if (short_bearing && (end_sealed() || !grooves.empty()))
    throw InputError("short_bearing: the short-bearing approximation has open ends and no "
                     "grooves (end_seal_conductance must be inf, grooves empty)");
  if (short_bearing && !pockets.empty())
    throw InputError("short_bearing: the short-bearing approximation takes no pockets (its "
                     "film thickness is smooth along the circumference)");
  if (turbulence != Turbulence::laminar &&
      !(std::isfinite(density_kg_m3) && density_kg_m3 > 0.0 && density_kg_m3 <= 1e5))
    throw InputError("density_kg_m3: expected 0 < density_kg_m3 <= 1e5 with turbulence = '" +
                     std::string(turbulence_name(turbulence)) + "' (the film Reynolds number "
                     "rho |omega| R h / mu needs it), got " + num(density_kg_m3));
  if (turbulence != Turbulence::laminar && turbulence != Turbulence::ng_pan)
    throw InputError("turbulence: expected 'laminar' or 'ng_pan'");
  // the optional transition: both NaN (none) or 0 <= onset < full, finite, with a turbulent
  // model (a laminar film has nothing to switch on)
  const bool no_on = std::isnan(turbulence_onset_re), no_full = std::isnan(turbulence_full_re);
  if (no_on != no_full)
    throw InputError(std::string(no_on ? "turbulence_onset_re" : "turbulence_full_re") +
                     ": the transition needs both turbulence_onset_re and turbulence_full_re "
                     "(or neither)");
  if (!no_on) {
    if (turbulence == Turbulence::laminar)
      throw InputError("turbulence_onset_re: a laminar-to-turbulent transition needs "
                       "turbulence = 'ng_pan', got 'laminar'");
    if (!(std::isfinite(turbulence_onset_re) && turbulence_onset_re >= 0.0))
      throw InputError("turbulence_onset_re: expected a finite Re_h >= 0, got " +
                       num(turbulence_onset_re));
    if (!(std::isfinite(turbulence_full_re) && turbulence_full_re > turbulence_onset_re))
      throw InputError("turbulence_full_re: expected a finite Re_h > turbulence_onset_re = " +
                       num(turbulence_onset_re) + ", got " + num(turbulence_full_re));
  }
  if (!(std::isfinite(supply_flow_m3_s) && supply_flow_m3_s >= 0.0 && supply_flow_m3_s <= 1e3))
    throw InputError("supply_flow_m3_s: expected a metered supply in [0, 1e3] m^3/s (0: flooded "
                     "grooves), got " + num(supply_flow_m3_s));
  for (std::size_t i = 0; i < pockets.size(); ++i) {
    const Pocket& pk = pockets[i];
    const std::string f = "pockets[" + std::to_string(i) + "].";
    if (!std::isfinite(pk.start_deg))
      throw InputError(f + "start_deg: expected a finite angle, got " + num(pk.start_deg));
    if (!(pk.arc_deg > 0.0 && pk.arc_deg <= 360.0))
      throw InputError(f + "arc_deg: expected 0 < arc_deg <= 360, got " + num(pk.arc_deg));
    if (!(pk.z_min_m >= -0.5 * length_m && pk.z_min_m < pk.z_max_m &&
          pk.z_max_m <= 0.5 * length_m))
      throw InputError(f + "z_min_m, z_max_m: expected -length_m/2 <= z_min_m < z_max_m <= "
                       "length_m/2 = " + num(0.5 * length_m) + ", got " + num(pk.z_min_m) +
                       ", " + num(pk.z_max_m));
    if (!(std::isfinite(pk.depth_m) && pk.depth_m > 0.0 && pk.depth_m <= 1e3 * clearance_m))
      throw InputError(f + "depth_m: expected 0 < depth_m <= 1000 clearance_m, got " +
                       num(pk.depth_m));
  }
  for (std::size_t i = 0; i < grooves.size(); ++i) {
    const Groove& g = grooves[i];
    const std::string f = "grooves[" + std::to_string(i) + "].";
    if (!std::isfinite(g.center_deg))
      throw InputError(f + "center_deg: expected a finite angle, got " + num(g.center_deg));
    if (!(std::isfinite(g.width_deg) && g.width_deg >= 0.0 && g.width_deg < 360.0))
      throw InputError(f + "width_deg: expected 0 <= width_deg < 360, got " + num(g.width_deg));
    if (!(std::isfinite(g.pressure_pa) && g.pressure_pa >= 0.0 && g.pressure_pa <= 1e9))
      throw InputError(f + "pressure_pa: expected a gauge pressure in [0, 1e9] Pa, got " +
                       num(g.pressure_pa));
  }
}

void FilmGrid::validate() const {
  if (n_circ < 12 || n_circ > 1 << 20)
    throw InputError("n_circ: expected 12 <= n_circ <= 1048576 (grid too coarse below 12), got " +
                     std::to_string(n_circ));
  if (n_axial < 2 || n_axial > 1 << 20)
    throw InputError("n_axial: expected 2 <= n_axial <= 1048576 (grid too coarse below 2), got " +
                     std::to_string(n_axial));
  const long long nodes = static_cast<long long>(n_circ) * (n_axial + 1);
  if (nodes > kMaxFilmNodes)
    throw InputError("n_circ, n_axial: expected at most " + std::to_string(kMaxFilmNodes) +
                     " film nodes n_circ*(n_axial+1), got " + std::to_string(nodes) +
                     " (about " + num(nodes * 400.0 / 1e9) +
                     " GB before the factorisation's fill)");
  // A priori work of one factorisation (fill of AMD on a periodic 5-point grid: ~31 n^1.5
  // multiply-adds for a square-ish grid, ~4 n (n_axial+1)^2 for a long thin ring; measured
  // within ~30 %). Grids clearly beyond the cap are refused here, before any analysis; the
  // exact count follows the ordering (build_system).
  const double nd = static_cast<double>(nodes);
  const double est = nd * std::min(31.0 * std::sqrt(nd), 4.0 * (n_axial + 1.0) * (n_axial + 1.0));
  if (est > 4.0 * kMaxFactorFlops)
    throw InputError("n_circ, n_axial: the " + std::to_string(n_circ) + " x " +
                     std::to_string(n_axial) + " film grid needs about " + num(est) +
                     " multiply-adds per sparse factorisation (limit " + num(kMaxFactorFlops) +
                     ", about 10 s): use a coarser grid");
}

ReynoldsSolver::Impl::Impl(const JournalBearingGeometry& g, const FilmGrid& gr, Cavitation cv)
    : geo(g), grid(gr), cav(cv) {
  geo.validate();
  grid.validate();
  N = grid.n_circ;
  K1 = grid.n_axial + 1;
  mid_node = grid.n_axial % 2 == 0;
  Kh = grid.n_axial / 2;  // even: the mid-plane row; odd: the row below the mid-plane face
  n_nodes = N * K1;
  R = 0.5 * geo.diameter_m;
  L = geo.length_m;
  c = geo.clearance_m;
  mu = geo.viscosity_pa_s;
  turb = geo.turbulence != Turbulence::laminar;
  dphi = 2.0 * kPi / N;
  dz = L / grid.n_axial;
  cosphi.resize(N);
  sinphi.resize(N);
  for (int j = 0; j < N; ++j) {
    cosphi[j] = std::cos(j * dphi);
    sinphi[j] = std::sin(j * dphi);
  }

  // Prescribed-pressure nodes: both ends (p = 0) unless they are seals, grooves (interior rows).
  sealed = geo.end_sealed();
  gseal = sealed ? geo.end_seal_conductance * R * dphi : 0.0;
  if (sealed && cav == Cavitation::jfo)
    throw InputError("end_seal_conductance: end seals are not available with cavitation='jfo' "
                     "(use 'none', 'gumbel' or 'reynolds', or open ends: inf)");
  groove.assign(n_nodes, 0);
  p_fixed.assign(n_nodes, 0.0);
  fixed.assign(n_nodes, 0);
  for (int j = 0; j < N && !sealed; ++j) {
    fixed[j * K1] = 1;
    fixed[j * K1 + K1 - 1] = 1;
  }
  for (const Groove& gv : geo.grooves) {
    std::vector<int> cols;
    const double half = 0.5 * gv.width_deg * kPi / 180.0;
    // wrap in degrees first (exact for any finite angle), then convert: a centre of
    // 90 + 360e6 deg is the same groove as 90 deg, and 1e300 deg cannot overflow lround
    double cdeg = std::fmod(gv.center_deg, 360.0);
    if (cdeg < 0.0) cdeg += 360.0;
    const double centre = cdeg * kPi / 180.0;
    if (gv.width_deg > 0.0) {
      for (int j = 0; j < N; ++j) {
        const double d = std::remainder(j * dphi - centre, 2.0 * kPi);
        if (std::abs(d) <= half * (1.0 + 1e-12) + 1e-12) cols.push_back(j);
      }
    }
    if (cols.empty()) {
      long jj = std::lround(centre / dphi) % N;  // centre in [0, 2π]: no overflow
      if (jj < 0) jj += N;
      cols.push_back(static_cast<int>(jj));
    }
    for (int j : cols)
      for (int k = 1; k < K1 - 1; ++k) {
        const int n = j * K1 + k;
        fixed[n] = 1;
        groove[n] = 1;
        p_fixed[n] = gv.pressure_pa;  // a later groove overrides an overlapping earlier one
      }
  }
  for (int n = 0; n < n_nodes; ++n)
    if (groove[n]) groove_nodes.push_back(n);
  groove_p0 = p_fixed;  // the flooded grooves' pressures (set_groove_state scales them)
  if (geo.short_bearing && cav == Cavitation::jfo)
    throw InputError("short_bearing: not with cavitation='jfo' (use 'none', 'gumbel' or "
                     "'reynolds')");
  if (geo.supply_flow_m3_s > 0.0 && cav != Cavitation::jfo)
    throw InputError(std::string("supply_flow_m3_s: a metered supply (starved film) needs "
                                 "cavitation='jfo' (the mass-conserving film), got '") +
                     cavitation_name(cav) + "'");
  if (geo.supply_flow_m3_s > 0.0 && !geo.pockets.empty())
    throw InputError("supply_flow_m3_s: a metered supply (starved film) is not available with "
                     "pockets (the held-supply linearisation assumes a smooth film)");
  if (cav == Cavitation::jfo && geo.grooves.empty())
    throw InputError("grooves: cavitation='jfo' needs at least one supply groove (without a "
                     "supply the steady mass-conserving film content is undetermined)");
  setup_pockets();
  build_system(full, false);
  if (full.n_unk == 0)
    throw InputError("grooves: the grooves cover the whole bearing (no film left)");
  sys = &full;

  h.assign(n_nodes, c);
  hdot.assign(n_nodes, 0.0);
  cE.assign(n_nodes, 0.0);
  cN.assign(n_nodes, 0.0);
  qE.assign(n_nodes, 0.0);
  src.assign(n_nodes, 0.0);
  p.assign(n_nodes, 0.0);
  pfull.assign(n_nodes, 0.0);
  theta.assign(n_nodes, 1.0);
  biactive.assign(n_nodes, 0);
  for (int n = 0; n < n_nodes; ++n) p[n] = pfull[n] = p_fixed[n];
  // Coarse grid for the cavitation-set prediction: a direction is halved (rounded up) if it
  // keeps >= 24 nodes around / >= 4 intervals along and its spacing is not more than twice
  // the other's. Coarsening the coarser direction of an elongated cell would move the
  // predicted cavitation boundary by many of the fine direction's nodes (slow to correct).
  const double sphi = R * dphi;
  coarse_n_circ = N >= 48 && sphi <= 2.0 * dz ? (N + 1) / 2 : N;
  coarse_n_axial = grid.n_axial >= 8 && dz <= 2.0 * sphi ? (grid.n_axial + 1) / 2 : grid.n_axial;
  coarse_usable = (cav == Cavitation::reynolds || cav == Cavitation::jfo) &&
                  (coarse_n_circ < N || coarse_n_axial < grid.n_axial);
}

void ReynoldsSolver::Impl::build_system(LinearSystem& S, bool half) {
  S.half = half;
  S.unk.assign(n_nodes, -1);
  S.node_of.clear();
  S.wphi.clear();
  S.has_n.clear();
  S.has_s.clear();
  for (int n = 0; n < n_nodes; ++n) {
    const int k = n % K1;
    if (fixed[n] || (half && k > Kh)) continue;
    S.unk[n] = static_cast<int>(S.node_of.size());
    S.node_of.push_back(n);
    S.wphi.push_back((half && k == Kh && mid_node) || end_row(n) ? 0.5 : 1.0);
    S.has_n.push_back((half && k == Kh) || k == K1 - 1 ? 0 : 1);  // k = K1-1: a sealed end
    S.has_s.push_back(k > 0 ? 1 : 0);                              // k = 0: a sealed end
  }
  S.n_unk = static_cast<int>(S.node_of.size());
  if (S.n_unk == 0) return;
  std::vector<Eigen::Triplet<double, int>> trip;
  trip.reserve(5 * S.n_unk);
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    trip.emplace_back(i, i, 1.0);
    for (int nb : {east(n), west(n)})
      if (S.unk[nb] >= 0) trip.emplace_back(S.unk[nb], i, 1.0);
    if (S.has_s[i] && S.unk[n - 1] >= 0) trip.emplace_back(S.unk[n - 1], i, 1.0);
    if (S.has_n[i] && S.unk[n + 1] >= 0) trip.emplace_back(S.unk[n + 1], i, 1.0);
  }
  S.A.resize(S.n_unk, S.n_unk);
  S.A.setFromTriplets(trip.begin(), trip.end());
  S.A.makeCompressed();
  auto find = [&](int row, int col) -> int {
    if (row < 0) return -1;
    for (int q = S.A.outerIndexPtr()[col]; q < S.A.outerIndexPtr()[col + 1]; ++q)
      if (S.A.innerIndexPtr()[q] == row) return q;
    return -1;
  };
  S.pos.resize(S.n_unk);
  S.nbr.resize(S.n_unk);
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    S.nbr[i] = LinearSystem::Nbr{S.unk[east(n)], S.unk[west(n)],
                                 S.has_n[i] ? S.unk[n + 1] : -1, S.has_s[i] ? S.unk[n - 1] : -1};
    S.pos[i] = LinearSystem::ColPos{find(i, i), find(S.unk[east(n)], i), find(S.unk[west(n)], i),
                                    S.has_n[i] ? find(S.unk[n + 1], i) : -1,
                                    S.has_s[i] ? find(S.unk[n - 1], i) : -1};
  }
  if (!S.ldlt.analyze(S.A, kMaxFactorBytes))
    throw InputError("n_circ, n_axial: the " + std::to_string(N) + " x " +
                     std::to_string(grid.n_axial) + " film grid needs an estimated " +
                     num(S.ldlt.bytes_needed() / 1e9) +
                     " GB for its sparse factorisation (limit " + num(kMaxFactorBytes / 1e9) +
                     " GB): use a coarser grid");
  if (S.ldlt.flops() > kMaxFactorFlops)
    throw InputError("n_circ, n_axial: the " + std::to_string(N) + " x " +
                     std::to_string(grid.n_axial) + " film grid needs an estimated " +
                     num(S.ldlt.flops()) + " multiply-adds per factorisation (limit " +
                     num(kMaxFactorFlops) + ", about 10 s): use a coarser grid");
  // Unknowns are numbered in node order, node n = j * K1 + k: ring j's are contiguous.
  S.ring_first.assign(N + 1, 0);
  for (int n = 0; n < n_nodes; ++n)
    if (S.unk[n] >= 0) ++S.ring_first[n / K1 + 1];
  for (int j = 0; j < N; ++j) S.ring_first[j + 1] += S.ring_first[j];
  S.use_band = S.band.analyze(S.A, S.ring_first, S.ldlt.flops());
  S.active.assign(S.n_unk, 0);
  S.rhs.resize(S.n_unk);
  S.sol.resize(S.n_unk);
}

bool ReynoldsSolver::Impl::symmetric(const double* f) const {
  for (int j = 0; j < N; ++j) {
    const double* row = f + j * K1;
    for (int k = 0; k < K1 / 2; ++k)
      if (row[k] != row[K1 - 1 - k]) return false;
  }
  return true;
}

void ReynoldsSolver::Impl::mirror_fields() {
  const int kend = mirror_end();
  for (int j = 0; j < N; ++j)
    for (int k = Kh + 1; k < kend; ++k) {
      const int n = j * K1 + k, m = j * K1 + K1 - 1 - k;  // mirror(n)
      p[n] = p[m];
      pfull[n] = pfull[m];
      theta[n] = theta[m];
    }
}

void ReynoldsSolver::Impl::set_film(const double* h_in, const double* hdot_in, double omega_in) {
  if (!(std::isfinite(omega_in) && std::abs(omega_in) <= kMaxOmega))
    throw InputError("speed_hz: expected |speed_hz| <= 1e5 Hz, got " +
                     num(omega_in / (2.0 * kPi)));
  // One pass per right-hand side of a transient: the minimum and the finiteness check run in
  // four independent lanes (0·x is NaN exactly when x is not finite); the node of the minimum
  // is searched only when it is needed for the contact message.
  double m4[4] = {h_in[0], h_in[0], h_in[0], h_in[0]}, c4[4] = {0.0, 0.0, 0.0, 0.0};
  int n = 0;
  for (; n + 4 <= n_nodes; n += 4)
    for (int l = 0; l < 4; ++l) {
      m4[l] = std::min(m4[l], h_in[n + l]);
      c4[l] += 0.0 * h_in[n + l] + 0.0 * hdot_in[n + l];
    }
  for (; n < n_nodes; ++n) {
    m4[0] = std::min(m4[0], h_in[n]);
    c4[0] += 0.0 * h_in[n] + 0.0 * hdot_in[n];
  }
  if (!(c4[0] + c4[1] + c4[2] + c4[3] == 0.0))
    throw InputError("h/dhdt: expected finite film thickness and rate at every node");
  const double hmin = std::min(std::min(m4[0], m4[1]), std::min(m4[2], m4[3]));
  if (!(hmin > 0.0)) {
    int nmin = 0;
    for (int q = 1; q < n_nodes; ++q)
      if (h_in[q] < h_in[nmin]) nmin = q;
    throw ContactError("film thickness " + num(hmin) + " m <= 0 at phi = " +
                       num((nmin / K1) * dphi * 180.0 / kPi) + " deg: journal touches the bush");
  }
  omega = omega_in;
  if (has_pockets) {
    std::copy(h_in, h_in + n_nodes, h_smooth.begin());
    for (int q = 0; q < n_nodes; ++q) h[q] = h_in[q] + dnode[q];
  } else {
    std::copy(h_in, h_in + n_nodes, h.begin());
  }
  std::copy(hdot_in, hdot_in + n_nodes, hdot.begin());
  const double fE = dz / (12.0 * mu * R * dphi);
  const double fN = R * dphi / (12.0 * mu * dz);
  const double fq = 0.5 * omega * R * dz;
  const double fs = R * dphi * dz;
  re_per_h = turb ? geo.density_kg_m3 * std::abs(omega) * R / mu : 0.0;
  for (int j = 0; j < N; ++j) {
    const int row = j * K1, erow = (j + 1 == N) ? 0 : row + K1;
    for (int k = 0; k < K1; ++k) {
      const int q = row + k;
      const double he = 0.5 * (h[q] + h[erow + k]);
      cE[q] = fE * he * he * he;
      qE[q] = fq * he;
      src[q] = fs * hdot[q];
    }
    for (int k = 0; k + 1 < K1; ++k) {
      const int q = row + k;
      const double hn = 0.5 * (h[q] + h[q + 1]);
      cN[q] = fN * hn * hn * hn;
    }
    cN[row + K1 - 1] = 0.0;
    if (turb) {  // Poiseuille conductances h³/(k μ) at the face's Re_h (the laminar path above
                 // is untouched: laminar films are the same bit for bit)
      double m, dm;
      for (int k = 0; k < K1; ++k) {
        const int q = row + k;
        turb_face(0.5 * (h[q] + h[erow + k]), false, q, m, dm);
        cE[q] *= m;
      }
      for (int k = 0; k + 1 < K1; ++k) {
        const int q = row + k;
        turb_face(0.5 * (h[q] + h[q + 1]), true, q, m, dm);
        cN[q] *= m;
      }
    }
  }
  // Faces a pocket edge crosses: the exact value of the stepped film (reynolds_pockets.cpp).
  for (std::size_t f = 0; f < pk_faces.size(); ++f) {
    const PocketFace& pf = pk_faces[f];
    const int q = pf.n, o = pf.north ? q + 1 : east(q);
    double G3, Gc;
    pocket_face(static_cast<int>(f), 0.5 * (h_smooth[q] + h_smooth[o]), G3, Gc);
    if (turb) {  // the stepped face's Re_h at its effective film cbrt(G3)
      double m, dm;
      turb_face(std::cbrt(G3), pf.north, q, m, dm);
      G3 *= m;
    }
    if (pf.north) {
      cN[q] = fN * G3;
    } else {
      cE[q] = fE * G3;
      qE[q] = fq * Gc;
    }
  }
  if (visc_field)  // h³/(12 μ_face): the uniform film's conductance times μ/μ_face
    for (int q = 0; q < n_nodes; ++q) {
      cE[q] *= vmE[q];
      cN[q] *= vmN[q];
    }
}

void ReynoldsSolver::Impl::base_rhs(const LinearSystem& S, Eigen::VectorXd& b) const {
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    const int e = east(n), w = west(n);
    const double wp = S.wphi[i];
    double v = -(qE[n] - qE[w]) - src[n];
    if (fixed[e]) v += cE[n] * p_fixed[e];
    if (fixed[w]) v += cE[w] * p_fixed[w];
    v *= wp;
    if (S.has_n[i] && fixed[n + 1]) v += cN[n] * p_fixed[n + 1];
    if (S.has_s[i] && fixed[n - 1]) v += cN[n - 1] * p_fixed[n - 1];
    b[i] = v;  // a seal's outer pressure is the ambient 0: no term
  }
}

void ReynoldsSolver::Impl::fill_spd(LinearSystem& S, const std::vector<char>* mask) {
  double* val = S.A.valuePtr();
  const char* mk = mask ? mask->data() : nullptr;
  for (int i = 0; i < S.n_unk; ++i) {
    const int n = S.node_of[i];
    const LinearSystem::ColPos& q = S.pos[i];
    if (mk && mk[i]) {
      val[q.diag] = 1.0;
      if (q.e >= 0) val[q.e] = 0.0;
      if (q.w >= 0) val[q.w] = 0.0;
      if (q.n >= 0) val[q.n] = 0.0;
      if (q.s >= 0) val[q.s] = 0.0;
      continue;
    }
    const int w = west(n);
    const double wp = S.wphi[i];
    if (S.has_s[i])
      val[q.diag] = wp * (cE[n] + cE[w]) + (S.has_n[i] ? cN[n] : 0.0) + cN[n - 1];
    else
      val[q.diag] = wp * (cE[n] + cE[w]) + cN[n];
    if (end_row(n)) val[q.diag] += gseal;
    // a slot exists only for an unknown neighbour (pos = -1 otherwise)
    const LinearSystem::Nbr& u = S.nbr[i];
    if (q.e >= 0) val[q.e] = (mk && mk[u.e]) ? 0.0 : -(wp * cE[n]);
    if (q.w >= 0) val[q.w] = (mk && mk[u.w]) ? 0.0 : -(wp * cE[w]);
    if (q.n >= 0) val[q.n] = (mk && mk[u.n]) ? 0.0 : -cN[n];
    if (q.s >= 0) val[q.s] = (mk && mk[u.s]) ? 0.0 : -cN[n - 1];
  }
}

// ---- public plumbing -------------------------------------------------------------------

ReynoldsSolver::ReynoldsSolver(const JournalBearingGeometry& geometry, const FilmGrid& grid,
                               Cavitation cavitation)
    : impl_(std::make_unique<Impl>(geometry, grid, cavitation)) {}
ReynoldsSolver::~ReynoldsSolver() = default;
ReynoldsSolver::ReynoldsSolver(ReynoldsSolver&&) noexcept = default;
ReynoldsSolver& ReynoldsSolver::operator=(ReynoldsSolver&&) noexcept = default;

const JournalBearingGeometry& ReynoldsSolver::geometry() const { return impl_->geo; }
const FilmGrid& ReynoldsSolver::grid() const { return impl_->grid; }
Cavitation ReynoldsSolver::cavitation() const { return impl_->cav; }
int ReynoldsSolver::n_unknowns() const { return impl_->full.n_unk; }
bool ReynoldsSolver::use_axial_symmetry() const { return impl_->use_symmetry; }
void ReynoldsSolver::set_use_axial_symmetry(bool on) { impl_->use_symmetry = on; }
bool ReynoldsSolver::predict_cavitation() const { return impl_->predict; }
void ReynoldsSolver::set_predict_cavitation(bool on) { impl_->predict = on; }
bool ReynoldsSolver::pressure_only() const { return impl_->pressure_only; }
void ReynoldsSolver::set_pressure_only(bool on) { impl_->pressure_only = on; }
bool ReynoldsSolver::band_factor() const { return impl_->band_factor; }
void ReynoldsSolver::set_band_factor(bool on) { impl_->band_factor = on; }
bool ReynoldsSolver::band_resume() const { return impl_->band_resume; }
void ReynoldsSolver::set_band_resume(bool on) { impl_->band_resume = on; }
int ReynoldsSolver::band_resumed() const { return impl_->band_resumed; }
bool ReynoldsSolver::refine_prediction() const { return impl_->refine; }
void ReynoldsSolver::set_refine_prediction(bool on) { impl_->refine = on; }
bool ReynoldsSolver::band_factor_used() const {
  return impl_->sys && impl_->sys->factor == LinearSystem::Factor::band;
}
bool ReynoldsSolver::continuation() const { return impl_->continuation; }
void ReynoldsSolver::set_continuation(bool on) {
  impl_->continuation = on;
  for (auto* S : {&impl_->full, &impl_->halfsys}) S->last_set.clear();
}

Eigen::VectorXd ReynoldsSolver::phi_rad() const {
  Eigen::VectorXd v(impl_->N);
  for (int j = 0; j < impl_->N; ++j) v[j] = j * impl_->dphi;
  return v;
}

Eigen::VectorXd ReynoldsSolver::z_m() const {
  Eigen::VectorXd v(impl_->K1);
  for (int k = 0; k < impl_->K1; ++k) v[k] = -0.5 * impl_->L + k * impl_->dz;
  return v;
}

RowMatrixXd ReynoldsSolver::dirichlet_mask() const {
  RowMatrixXd m(impl_->N, impl_->K1);
  for (int n = 0; n < impl_->n_nodes; ++n) m.data()[n] = impl_->fixed[n] ? 1.0 : 0.0;
  return m;
}

void ReynoldsSolver::set_viscosity(double viscosity_pa_s) {
  require_positive(viscosity_pa_s, "viscosity_pa_s");
  impl_->geo.viscosity_pa_s = viscosity_pa_s;
  impl_->mu = viscosity_pa_s;
  impl_->visc_field = false;  // uniform again
  impl_->visc_symmetric = true;
  if (impl_->coarse) impl_->coarse->set_viscosity(viscosity_pa_s);
  impl_->solved = false;
}

void ReynoldsSolver::reset() {
  // Solves do not depend on earlier calls (each starts from its own prediction); this only
  // drops the last solution, so linearize() needs a new solve first.
  impl_->solved = false;
}

}  // namespace rotordyn
