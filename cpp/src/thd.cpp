// Thermo-hydrodynamic film (thd.hpp): the energy equation on the Reynolds grid and its
// iteration with the equilibrium.
#include "rotordyn/thd.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "rotordyn/errors.hpp"
#include "thermal_detail.hpp"

namespace rotordyn {

namespace {
// The width (cells of the grid, either side of the midpoint between two columns) over which
// an ungrooved film's inlet passes from one column of maximum film to the next (thd_field).
// Outside it the inlet is the one column, as before the hand-over existed.
constexpr double kInletBand = 0.5;
// a pad's trailing-edge cell whose inflow from the pad is below kTeMakeup of its outflow into
// the gap draws the shortfall from the gap (at the inlet temperature), linearly from none at
// in = kTeMakeup·out to all of it at in = 0 (where the no-inflow rule gives it too): its
// temperature T_up + Φ/(ρ c in) otherwise grows without bound as in -> 0 and jumps back to
// T_s + Φ/(ρ c out) when the flow from the pad reverses (a lightly loaded lobe's trailing-edge
// end cells: the turbine of tests/data/models at 5.387 Hz cycled 200 outer steps, that node
// 45 <-> 63 degC). It never acts on the compressor's pads and lobes of the THD tests (their
// results bit for bit, docs/film-physics.md "A trailing-edge cell the pad hardly feeds").
constexpr double kTeMakeup = 0.1;

void nonneg(double v, const char* field) {
  if (!(std::isfinite(v) && v >= 0.0))
    throw InputError(std::string(field) + ": expected a finite value >= 0 W/(m^2 K) (0: "
                     "adiabatic), got " + num(v));
}

// a field symmetric about z = 0 when the film is (bitwise: the half-grid solve needs it)
bool mirror_symmetric(const RowMatrixXd& f) {
  const int K1 = static_cast<int>(f.cols());
  for (int j = 0; j < f.rows(); ++j)
    for (int k = 0; k < K1 / 2; ++k)
      if (f(j, k) != f(j, K1 - 1 - k)) return false;
  return true;
}

void symmetrize(double* t, int N, int K1) {
  for (int j = 0; j < N; ++j)
    for (int k = 0; k < K1 / 2; ++k) {
      double& a = t[j * K1 + k];
      double& b = t[j * K1 + K1 - 1 - k];
      a = b = 0.5 * (a + b);
    }
}
}  // namespace

void ThdOptions::validate(const OilModel& oil) const {
  validate_supply(oil, supply_temperature_c, supply_flow_m3_s, carry_over);
  nonneg(journal_htc_w_m2k, "journal_htc_w_m2k");
  nonneg(bush_htc_w_m2k, "bush_htc_w_m2k");
  for (auto [v, f] : {std::pair{journal_temperature_c, "journal_temperature_c"},
                      std::pair{bush_temperature_c, "bush_temperature_c"}})
    if (!std::isnan(v) && !(std::isfinite(v) && v > -273.15))
      throw InputError(std::string(f) + ": expected a temperature > -273.15 degC (NaN: the "
                       "supply temperature), got " + num(v));
  if (!(tol_k >= 1e-12 && tol_k <= 1.0))
    throw InputError("tol_k: expected 1e-12 <= tol_k <= 1 K, got " + num(tol_k));
  if (!(max_iter >= 1 && max_iter <= 1000))
    throw InputError("max_iter: expected 1 <= max_iter <= 1000, got " + std::to_string(max_iter));
  validate_walls(*this, oil);
}

ThdFieldParts thd_field(const ReynoldsSolver& solver, const FilmSolution& sol,
                        const OilModel& oil, const ThdOptions& opt, double omega, bool pad) {
  ThdFieldParts parts;
  parts.pad = pad;
  parts.flows = solver.film_flows();
  const FilmFlows& fl = parts.flows;
  const int N = static_cast<int>(sol.h_m.rows()), K1 = static_cast<int>(sol.h_m.cols());
  const int nn = N * K1, Kl = K1 - 1;
  const double Ts = opt.supply_temperature_c;
  const double TJ = std::isnan(opt.journal_temperature_c) ? Ts : opt.journal_temperature_c;
  const double TB = std::isnan(opt.bush_temperature_c) ? Ts : opt.bush_temperature_c;
  const double hJ = opt.journal_htc_w_m2k, hB = opt.bush_htc_w_m2k;
  // one oil: a turbulent film's Re_h (the walls' eddy factors, the film's own) takes the
  // film's density, the heat balance the oil's (every THD path passes here: standalone,
  // system, pads, thd_energy)
  check_film_density(solver.geometry(), oil, "");
  const double rc = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k;
  // the cells' heat paths to the walls (thd_walls.hpp); `legacy`: given coefficients to fixed
  // wall temperatures, in the energy equation's original arithmetic
  // (a turbulent film: at each cell's Re_h and Prandtl number, its own viscosity)
  WallModel wm = wall_model(opt, oil);
  if (wm.film_htc && opt.wall_eddy_conductivity)
    wm.set_film(solver.geometry(), omega, oil.specific_heat_j_per_kg_k);
  parts.walls.resize(static_cast<std::size_t>(nn));
  for (int n = 0; n < nn; ++n)
    parts.walls[static_cast<std::size_t>(n)] =
        wm.cell(sol.h_m.data()[n], fl.fill.data()[n], fl.viscosity_pa_s.data()[n]);
  // inlet nodes: the groove nodes and the end half cells of groove columns (their flows are
  // the supply's, as FilmSolution::inlet_flow_m3_s), or the column of maximum film
  std::vector<char> D(nn, 0);
  const RowMatrixXd dm = solver.dirichlet_mask();
  bool any = false;
  for (int n = 0; n < nn; ++n) {
    const int k = n % K1;
    if (k > 0 && k < Kl && dm.data()[n] != 0.0) D[n] = any = true;
  }
  for (int n = 0; n < nn && any; ++n) {
    const int k = n % K1;
    if ((k == 0 && D[n + 1]) || (k == Kl && D[n - 1])) D[n] = 1;
  }
  // a pad's trailing-edge column (below): prescribed pressure, but the pad's last cells
  std::vector<char> te(N, 0);
  if (pad && any) {
    // a pad film (tilting pad, lobe): the prescribed-pressure gap between the pad's trailing
    // and leading edges is the inlet, but not the trailing-edge column, whose circumferential
    // upstream neighbour is on the pad: that cell is the pad's last, and what leaves it into
    // the gap is the hot oil the pad passes on (to the next pad's inlet, ThermalFilm::upstream)
    const std::vector<char> D0 = D;
    auto col_in = [&](int j) {
      for (int k = 1; k < Kl; ++k)
        if (D0[j * K1 + k]) return true;
      return false;
    };
    for (int j = 0; j < N; ++j) {
      const int up = omega > 0.0 ? (j + N - 1) % N : (j + 1) % N;
      if (col_in(j) && !col_in(up)) {
        te[j] = 1;
        for (int k = 0; k < K1; ++k) D[j * K1 + k] = 0;
      }
    }
  }
  // without grooves the inlet is the column of maximum film; where the peak of the film
  // (parabola through the column of maximum film and its neighbours) lies within
  // kInletBand of a cell of the midpoint between two columns, the inlet is handed over
  // smoothly to the neighbour column: the field is the blend (1 − w) of the field with the
  // inlet at the one column and w of the field with it at the other, w = 1/2 at the midpoint
  // — so the map position -> temperature is continuous and the THD fixed point exists where
  // a snapped inlet gives none (the compressor at 120 Hz: the inlet at column j moves the
  // journal so that column j + 1 has the maximum film, and back)
  int jb = -1;
  double wb = 0.0;
  if (!any) {
    const int kmid = Kl / 2;
    int jmax = 0;
    for (int j = 1; j < N; ++j)
      if (sol.h_m(j, kmid) > sol.h_m(jmax, kmid)) jmax = j;
    for (int k = 0; k < K1; ++k) D[jmax * K1 + k] = 1;
    const double hm = sol.h_m((jmax + N - 1) % N, kmid), h0 = sol.h_m(jmax, kmid),
                 hp = sol.h_m((jmax + 1) % N, kmid);
    const double den = hm - 2.0 * h0 + hp;
    const double sp = den < 0.0 ? std::clamp(0.5 * (hm - hp) / den, -0.5, 0.5) : 0.0;
    const double d = 0.5 - std::abs(sp);  // cells from the midpoint between two columns
    if (sp != 0.0 && d < kInletBand) {
      jb = sp > 0.0 ? (jmax + 1) % N : (jmax + N - 1) % N;
      wb = 0.5 * (1.0 - d / kInletBand);  // linear: the peak's position between the columns
    }
  }
  auto solve = [&](std::vector<char> D, ThdFieldParts& parts) {
    const double* qp = fl.q_phi_m3_s.data();
    const double* qz = fl.q_z_m3_s.data();
    std::vector<double> diag(nn, 0.0), in(nn, 0.0), out(nn, 0.0);
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(4 * nn);
    auto link = [&](int a, int b, double F) {  // flow F from a to b
      if (F < 0.0) {
        std::swap(a, b);
        F = -F;
      }
      if (!(F > 0.0)) return;
      in[b] += F;
      out[a] += F;
      if (!D[b]) {
        diag[b] += rc * F;
        trip.emplace_back(b, a, -rc * F);
      }
    };
    for (int n = 0; n < nn; ++n) {
      const int e = n + K1 >= nn ? n + K1 - nn : n + K1;
      link(n, e, qp[n]);
      if (n % K1 < Kl) link(n, n + 1, qz[n]);
    }
    Eigen::VectorXd b0 = Eigen::VectorXd::Zero(nn), b1 = Eigen::VectorXd::Zero(nn);
    Eigen::VectorXd b2 = Eigen::VectorXd::Zero(wm.balance ? nn : 0);  // the journal's T_J
    std::vector<double> side_out(nn, 0.0), makeup(nn, 0.0);
    const double* A = fl.area_m2.data();
    const double* phi = fl.dissipation_w.data();
    for (int n = 0; n < nn; ++n) {
      if (D[n]) {
        trip.emplace_back(n, n, 1.0);
        b1[n] = 1.0;
        continue;
      }
      const int k = n % K1;
      // open end: what the internal faces bring leaves through it. Not at a pad's trailing-
      // edge column: its nodes hold the prescribed pressure, and the flux of their face into
      // the gap (whose thickness averages in the gap's 4 C_p) exceeds what the pad brings, as
      // in its inner cells; that imbalance is the prescribed pressure's, not ambient oil
      // drawn in at the two end cells (which took 0.12-0.30 Q_in at T_s there and cooled the
      // pad's outlet), so every trailing-edge cell passes on just what the pad brings it
      if ((k == 0 || k == Kl) && !te[static_cast<std::size_t>(n / K1)]) {
        const double B = in[n] - out[n];
        if (B >= 0.0) {
          side_out[n] = B;
        } else {  // side inflow of ambient oil at the supply temperature
          diag[n] -= rc * B;
          b0[n] -= rc * B * Ts;
        }
      }
      if (te[static_cast<std::size_t>(n / K1)]) {  // the trailing edge's make-up (kTeMakeup)
        const double mk = out[n] - in[n] / kTeMakeup;
        if (mk > 0.0) {
          diag[n] += rc * mk;
          b1[n] += rc * mk;
          makeup[n] = mk;
        }
      }
      if (wm.legacy) {
        diag[n] += (hJ + hB) * A[n];
        b0[n] += phi[n] + A[n] * (hJ * TJ + hB * TB);
      } else {  // loss to the walls (kJ + kB) T − (lJ + lB) T_J − (nJ + nB), per area
        const CellWall& w = parts.walls[static_cast<std::size_t>(n)];
        diag[n] += (w.kJ + w.kB) * A[n];
        b0[n] += phi[n] + A[n] * (w.nJ + w.nB + (wm.balance ? 0.0 : (w.lJ + w.lB) * wm.TJ));
        if (wm.balance) b2[n] = A[n] * (w.lJ + w.lB);
      }
      if (!(diag[n] > 0.0)) {  // no inflow at all: the cell's outflow enters at T_s
        diag[n] = out[n] > 0.0 ? rc * out[n] : 1.0;
        b0[n] = out[n] > 0.0 ? b0[n] + rc * out[n] * Ts : Ts;
        if (wm.balance && !(out[n] > 0.0)) b2[n] = 0.0;
      }
      trip.emplace_back(n, n, diag[n]);
    }
    // Solve M X = [b0 b1]. Upwind convection makes M lower triangular in the flow's order when
    // the flow graph (the inlet cutting the circle) has no cycle: one sweep in topological order
    // (Kahn); a recirculation cycle (e.g. a backflow eddy) falls back to the sparse LU.
    Eigen::VectorXd X0(nn), X1(nn), X2(b2.size());
    const bool j2 = wm.balance;
    {
      std::vector<int> indeg(nn, 0), dstart(nn + 1, 0), dnode;
      for (const auto& t : trip)
        if (t.row() != t.col()) {
          ++indeg[t.row()];
          ++dstart[t.col() + 1];
        }
      for (int n = 0; n < nn; ++n) dstart[n + 1] += dstart[n];
      dnode.resize(dstart[nn]);
      std::vector<int> fill(dstart.begin(), dstart.end() - 1);
      // upstream lists in CSR (row = downstream node)
      std::vector<int> ustart(nn + 1, 0), unode;
      std::vector<double> uw;
      for (const auto& t : trip)
        if (t.row() != t.col()) ++ustart[t.row() + 1];
      for (int n = 0; n < nn; ++n) ustart[n + 1] += ustart[n];
      unode.resize(ustart[nn]);
      uw.resize(ustart[nn]);
      std::vector<int> ufill(ustart.begin(), ustart.end() - 1);
      for (const auto& t : trip)
        if (t.row() != t.col()) {
          dnode[fill[t.col()]++] = t.row();
          unode[ufill[t.row()]] = t.col();
          uw[ufill[t.row()]++] = -t.value();
        }
      std::vector<int> order;
      order.reserve(nn);
      for (int n = 0; n < nn; ++n)
        if (indeg[n] == 0) order.push_back(n);
      for (std::size_t q = 0; q < order.size(); ++q) {
        const int n = order[q];
        if (D[n]) {
          X0[n] = 0.0;
          X1[n] = 1.0;
          if (j2) X2[n] = 0.0;
        } else {
          double s0 = b0[n], s1 = b1[n];
          for (int i = ustart[n]; i < ustart[n + 1]; ++i) {
            s0 += uw[i] * X0[unode[i]];
            s1 += uw[i] * X1[unode[i]];
          }
          X0[n] = s0 / diag[n];
          X1[n] = s1 / diag[n];
          if (j2) {
            double s2 = b2[n];
            for (int i = ustart[n]; i < ustart[n + 1]; ++i) s2 += uw[i] * X2[unode[i]];
            X2[n] = s2 / diag[n];
          }
        }
        for (int i = dstart[n]; i < dstart[n + 1]; ++i)
          if (--indeg[dnode[i]] == 0) order.push_back(dnode[i]);
      }
      if (static_cast<int>(order.size()) < nn) {  // a cycle: the sparse LU
        Eigen::SparseMatrix<double> M(nn, nn);
        M.setFromTriplets(trip.begin(), trip.end());
        M.makeCompressed();
        Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
        lu.compute(M);
        if (lu.info() != Eigen::Success)
          throw ConvergenceError("THD energy equation: the convection operator is singular");
        X0 = lu.solve(b0);
        X1 = lu.solve(b1);
        if (j2) X2 = lu.solve(b2);
      }
    }
    // the flows into and out of the inlet: Q (inlet -> film), Q_r and its mixing-cup T (affine
    // in T_in: T_r = a + b T_in)
    double Q = 0.0, Qr = 0.0, ta = 0.0, tb = 0.0, tc = 0.0;
    auto inlet = [&](int a, int b, double F) {
      if (F < 0.0) {
        std::swap(a, b);
        F = -F;
      }
      if (D[a] && !D[b]) Q += F;
      if (!D[a] && D[b]) {
        Qr += F;
        ta += F * X0[a];
        tb += F * X1[a];
        if (j2) tc += F * X2[a];
      }
    };
    for (int n = 0; n < nn; ++n) {
      const int e = n + K1 >= nn ? n + K1 - nn : n + K1;
      inlet(n, e, qp[n]);
      if (n % K1 < Kl) inlet(n, n + 1, qz[n]);
    }
    if (pad && any) {
      // the hot oil a pad passes on (to the next pad's inlet): the pad's own mass balance,
      // Q_out = Q_in − Q_s (inflow at the leading edge minus the side leakage over the pad's
      // cells), not the flux from the trailing-edge cells into the gap, whose face thickness
      // averages in the gap's clearance (2.4–4.3 × Q_in). Its mixing-cup temperature is that of
      // the flow the trailing-edge cells receive from the pad (their energy equations' inflow,
      // in_n: Σ in_n = Q_in − Q_s to round-off where the film conserves mass; a cavitated pad's
      // excess is scaled out, so the temperature is the trailing edge's profile).
      double qte = 0.0, sa = 0.0, sb = 0.0, sc = 0.0, qs = 0.0;
      for (int n = 0; n < nn; ++n) {
        qs += side_out[n];
        if (D[n] || !(in[n] > 0.0)) continue;
        const int k = n % K1, j = n / K1;
        const int down = omega > 0.0 ? (j + 1) % N : (j + N - 1) % N;
        if (!D[down * K1 + k]) continue;  // not a trailing-edge cell
        qte += in[n];
        sa += in[n] * X0[n];
        sb += in[n] * X1[n];
        if (j2) sc += in[n] * X2[n];
      }
      Qr = qte > 0.0 ? std::max(Q - qs, 0.0) : 0.0;
      ta = qte > 0.0 ? Qr * sa / qte : 0.0;
      tb = qte > 0.0 ? Qr * sb / qte : 0.0;
      tc = qte > 0.0 ? Qr * sc / qte : 0.0;
      // the make-up (kTeMakeup) enters at T_in and leaves with the cell's oil at T: it returns
      // to the gap the heat m (T − T_in) it picked up, which the hot oil passed on carries
      // (the pad's heat balance and the next inlet's mixing close with it); Q_out stays the
      // pad's own mass balance (the make-up goes back where it came from)
      if (Qr > 0.0)
        for (int n = 0; n < nn; ++n)
          if (makeup[n] > 0.0) {
            ta += makeup[n] * X0[n];
            tb += makeup[n] * (X1[n] - 1.0);
            if (j2) tc += makeup[n] * X2[n];
          }
    }
    double so0 = 0.0, so1 = 0.0, so2 = 0.0;  // Σ side_out T, affine (ThdFieldParts::so0)
    for (int n = 0; n < nn; ++n) {
      so0 += side_out[n] * X0[n];
      so1 += side_out[n] * X1[n];
      if (j2) so2 += side_out[n] * X2[n];
    }
    parts.so0 = so0;
    parts.so1 = so1;
    parts.so2 = so2;
    parts.inlet = std::move(D);
    parts.side_out = std::move(side_out);
    parts.makeup = std::move(makeup);
    parts.X0 = std::move(X0);
    parts.X1 = std::move(X1);
    parts.X2 = std::move(X2);
    parts.Q = Q;
    parts.Qr = Qr;
    parts.ta = ta;
    parts.tb = tb;
    parts.tc = tc;
  };
  solve(D, parts);
  if (jb >= 0 && wb > 0.0) {
    ThdFieldParts other;
    other.walls = parts.walls;
    std::vector<char> Db(nn, 0);
    for (int k = 0; k < K1; ++k) Db[jb * K1 + k] = 1;
    solve(std::move(Db), other);
    const double wa = 1.0 - wb;  // every part is linear in the field: blend them all
    parts.X0 = wa * parts.X0 + wb * other.X0;
    parts.X1 = wa * parts.X1 + wb * other.X1;
    if (wm.balance) parts.X2 = wa * parts.X2 + wb * other.X2;
    for (int n = 0; n < nn; ++n)
      parts.side_out[static_cast<std::size_t>(n)] =
          wa * parts.side_out[static_cast<std::size_t>(n)] +
          wb * other.side_out[static_cast<std::size_t>(n)];
    for (int n = 0; n < nn; ++n)
      parts.makeup[static_cast<std::size_t>(n)] =
          wa * parts.makeup[static_cast<std::size_t>(n)] +
          wb * other.makeup[static_cast<std::size_t>(n)];
    parts.Q = wa * parts.Q + wb * other.Q;
    parts.Qr = wa * parts.Qr + wb * other.Qr;
    parts.ta = wa * parts.ta + wb * other.ta;
    parts.tb = wa * parts.tb + wb * other.tb;
    parts.tc = wa * parts.tc + wb * other.tc;
    parts.so0 = wa * parts.so0 + wb * other.so0;
    parts.so1 = wa * parts.so1 + wb * other.so1;
    parts.so2 = wa * parts.so2 + wb * other.so2;
    parts.blend_column = jb;
    parts.blend_weight = wb;
  }
  parts.grooved = any && !pad;
  if (!pad && !any) {
    // an ungrooved film's inlet column (at its peak) is film: its dissipation and its wall
    // exchange at T_in heat the oil passing it, a source in the inlet mixing (thd_energy),
    // so that every watt of the power loss (Σ Φ over all cells) goes into the oil or the
    // walls. A groove's nodes are not film (ThdFieldParts::grooved): no source
    const double* A = fl.area_m2.data();
    const double* phi = fl.dissipation_w.data();
    for (int n = 0; n < nn; ++n) {
      const int j = n / K1;
      const double m = j == jb ? wb : (parts.inlet[static_cast<std::size_t>(n)] ? 1.0 - wb : 0.0);
      if (!(m > 0.0)) continue;
      if (wm.legacy) {
        parts.si0 += m * (phi[n] + A[n] * (hJ * TJ + hB * TB));
        parts.si1 -= m * A[n] * (hJ + hB);
      } else {
        const CellWall& w = parts.walls[static_cast<std::size_t>(n)];
        parts.si0 +=
            m * (phi[n] + A[n] * (w.nJ + w.nB + (wm.balance ? 0.0 : (w.lJ + w.lB) * wm.TJ)));
        parts.si1 -= m * A[n] * (w.kJ + w.kB);
        if (wm.balance) parts.si2 += m * A[n] * (w.lJ + w.lB);
      }
    }
  }
  if (wm.balance) journal_sums(parts, N, K1);
  parts.flows.makeup_m3_s = Eigen::Map<const RowMatrixXd>(parts.makeup.data(), N, K1);
  return parts;
}

ThdFilmState thd_energy(const ReynoldsSolver& solver, const FilmSolution& sol,
                        const OilModel& oil, const ThdOptions& opt, double omega) {
  ThdFieldParts parts = thd_field(solver, sol, oil, opt, omega, false);
  const double Q = parts.Q, Qr = parts.Qr, Ts = opt.supply_temperature_c;
  // the mixing (thermal_detail.hpp supply_mixing): λ, or λ_eff = (Q − Q_f)/Q_r where a
  // metered supply falls short of the demand Q − λ Q_r (starved: Q_f + Q_r < Q)
  double qs = 0.0;  // the film's side leakage: it keeps Q − Q_s (supply_mixing's Qr_avail)
  for (double q : parts.side_out) qs += q;
  const double Qr_avail = std::min(Qr, std::max(Q - qs, 0.0));
  const SupplyMixing mix = checked_supply_mixing("THD energy equation", Q, Qr, opt.carry_over,
                                                 opt.supply_flow_m3_s, Qr_avail);
  const double Qf = mix.qf;
  const double lam = mix.made_up ? mix.lam_eff : opt.carry_over;
  if (!(Q > 0.0 && Qf > 0.0))
    throw ConvergenceError("THD energy equation: the film draws no fresh oil (flow from the "
                           "inlet " + num(Q) + " m^3/s, carried over " + num(lam * Qr) +
                           " m^3/s)");
  // the inlet cells' heat (si0 + T_in si1 + T_J si2 W, thd_field) joins the mixing
  const double rc = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k;
  const double s0 = parts.si0 / rc, s1 = parts.si1 / rc, s2 = parts.si2 / rc;
  if (opt.journal_balance) {
    // the inlet mixing and the journal's heat balance together (both affine in T_in, T_J):
    //   (Q_f + λ Q_r − λ tb − s1) T_in − (λ tc + s2) T_J = Q_f T_s + λ ta + s0,
    //   jb T_in + jc T_J = −ja
    Eigen::Matrix2d M;
    M << Qf + lam * Qr - lam * parts.tb - s1, -lam * parts.tc - s2, parts.jb, parts.jc;
    const Eigen::Vector2d x =
        M.fullPivLu().solve(Eigen::Vector2d(Qf * Ts + lam * parts.ta + s0, -parts.ja));
    if (!x.allFinite())
      throw ConvergenceError("THD energy equation: the journal's heat balance is singular");
    ThdFilmState st = thd_state(std::move(parts), sol, opt, omega, x[0], Qf, x[1]);
    st.carry_over_effective = lam;
    st.starved = mix.starved;
    return st;
  }
  const double Tin = (Qf * Ts + lam * parts.ta + s0) / (Qf + lam * Qr - lam * parts.tb - s1);
  if (!std::isfinite(Tin))
    throw ConvergenceError("THD energy equation: non-finite inlet temperature");
  ThdFilmState st = thd_state(std::move(parts), sol, opt, omega, Tin, Qf);
  st.carry_over_effective = lam;
  st.starved = mix.starved;
  return st;
}

ThdFilmState thd_state(ThdFieldParts&& parts, const FilmSolution& sol, const ThdOptions& opt,
                       double omega, double Tin, double Qf, double TJb) {
  ThdFilmState st;
  st.flows = std::move(parts.flows);
  const FilmFlows& fl = st.flows;
  const int N = static_cast<int>(sol.h_m.rows()), K1 = static_cast<int>(sol.h_m.cols());
  const int nn = N * K1;
  const double Ts = opt.supply_temperature_c;
  const double TJ = std::isnan(opt.journal_temperature_c) ? Ts : opt.journal_temperature_c;
  const double TB = std::isnan(opt.bush_temperature_c) ? Ts : opt.bush_temperature_c;
  const double hJ = opt.journal_htc_w_m2k, hB = opt.bush_htc_w_m2k;
  const std::vector<char>& D = parts.inlet;
  const std::vector<double>& side_out = parts.side_out;
  const double* A = fl.area_m2.data();
  const double* phi = fl.dissipation_w.data();
  const double Q = parts.Q, Qr = parts.Qr, ta = parts.ta, tb = parts.tb;
  const bool balance = opt.journal_balance;
  const bool legacy = !(opt.film_htc || balance || opt.bush_conduction);
  const double tj = balance ? TJb : TJ;  // the journal's temperature
  if (balance && !(std::isfinite(TJb) && parts.X2.size() == nn))
    throw ConvergenceError("THD energy equation: no journal temperature from its balance");
  Eigen::VectorXd T = balance ? Eigen::VectorXd(parts.X0 + Tin * parts.X1 + TJb * parts.X2)
                              : Eigen::VectorXd(parts.X0 + Tin * parts.X1);
  if (mirror_symmetric(sol.h_m)) symmetrize(T.data(), N, K1);
  if (!T.allFinite())
    throw ConvergenceError("THD energy equation: non-finite film temperature");
  st.temperature_c = Eigen::Map<const RowMatrixXd>(T.data(), N, K1);
  st.wall_temperature_c = st.temperature_c;
  st.inlet_mask.resize(N, K1);
  double area = 0.0, tmean = 0.0, qs = 0.0, ts = 0.0, P = 0.0, qj = 0.0, qb = 0.0;
  double twmax = -std::numeric_limits<double>::infinity();
  // a pad film: the mean, the maximum and the power over the pad's cells only (the gap nodes
  // are not film: they hold the inlet temperature and their shear is not the pad's)
  double tmax = -std::numeric_limits<double>::infinity();
  for (int n = 0; n < nn; ++n) st.inlet_mask.data()[n] = D[n] ? 1.0 - parts.blend_weight : 0.0;
  if (parts.blend_column >= 0)  // an inlet handed over between two columns (thd_field)
    for (int k = 0; k < K1; ++k) st.inlet_mask(parts.blend_column, k) = parts.blend_weight;
  for (int n = 0; n < nn; ++n) {
    qs += side_out[n];
    ts += side_out[n] * T[n];
    if (parts.pad && D[n]) continue;
    area += A[n];
    tmean += A[n] * T[n];
    if (!(parts.grooved && D[n])) P += phi[n];  // a groove's shear is not the film's
    tmax = std::max(tmax, T[n]);
    // the walls of the film's cells; not a pad: every node's (an inlet cell's exchange at
    // T_in, the inlet source's share, is in its blended T: exact, the walls being affine)
    const double wf = (parts.pad || parts.grooved) ? 1.0 - st.inlet_mask.data()[n] : 1.0;
    const CellWall& w = parts.walls[static_cast<std::size_t>(n)];
    if (legacy) {
      qj += wf * hJ * A[n] * (T[n] - TJ);
      qb += wf * hB * A[n] * (T[n] - TB);
    } else {
      qj += wf * A[n] * (w.kJ * T[n] - w.lJ * tj - w.nJ);
      qb += wf * A[n] * (w.kB * T[n] - w.lB * tj - w.nB);
    }
    if (wf > 0.0) {  // the wall surface of every cell the walls' heat counts
      const double tw = w.pT * T[n] + w.pJ * tj + w.p0;
      st.wall_temperature_c.data()[n] = tw;
      twmax = std::max(twmax, tw);
    }
  }
  st.max_temperature_c = parts.pad ? std::max(tmax, Tin) : T.maxCoeff();
  st.mean_temperature_c = tmean / area;
  st.inlet_temperature_c = Tin;
  st.recirculation_temperature_c =
      Qr > 0.0 ? (ta + Tin * tb + (balance ? TJb * parts.tc : 0.0)) / Qr : Tin;
  if (!parts.pad)  // the blend's own side heat (ThdFieldParts::so0), not blended T · side_out
    ts = parts.so0 + Tin * parts.so1 + (balance ? TJb * parts.so2 : 0.0);
  st.side_temperature_c = qs > 0.0 ? ts / qs : Tin;
  st.power_loss_w = P;
  st.friction_power_w = sol.friction_torque_nm * omega;
  st.film_flow_m3_s = Q;
  st.recirculation_flow_m3_s = Qr;
  st.side_flow_m3_s = qs;
  st.supply_flow_m3_s = Qf;
  st.heat_to_journal_w = qj;
  st.heat_to_bush_w = qb;
  st.journal_temperature_c = tj;
  st.max_wall_temperature_c = twmax;
  return st;
}

double thd_residual_k(const Eigen::Ref<const Eigen::VectorXd>& G,
                      const Eigen::Ref<const Eigen::VectorXd>& T, double t_max_c) {
  double r = 0.0;
  for (Eigen::Index n = 0; n < G.size(); ++n) {
    const double d = std::abs(std::min(G[n], t_max_c) - T[n]);
    if (std::isnan(d)) return d;  // a NaN node is no settled field, wherever it sits
    r = std::max(r, d);
  }
  return r;
}

namespace {
/// The hot oil that may reach a plain film's inlet, min(Q_r, Q − Q_s) (thd_energy)
double hot_oil(const ThdFilmState& st) {
  return std::min(st.recirculation_flow_m3_s,
                  std::max(st.film_flow_m3_s - st.side_flow_m3_s, 0.0));
}
}  // namespace

ThdEquilibrium thd_equilibrium(ReynoldsSolver& solver, const OilModel& oil,
                               const ThdOptions& opt, double lx, double ly, double omega) {
  oil.validate();
  opt.validate(oil);
  if (!(std::isfinite(omega) && omega != 0.0))
    throw InputError("speed_hz: the thermal equilibrium needs a nonzero speed");
  const int N = solver.grid().n_circ, K1 = solver.grid().n_axial + 1, nn = N * K1;
  const double Ts = opt.supply_temperature_c;
  solver.set_viscosity(oil.viscosity_pa_s(Ts));  // the reference of the field's faces
  ThdEquilibrium out;
  Eigen::VectorXd T = Eigen::VectorXd::Constant(nn, Ts);
  RowMatrixXd mu(N, K1);
  double x = 0.0, y = 0.0;
  AndersonMixer mixer;  // T -> G(T) accelerated
  std::string starved;  // the last iterate's message, when it was starved
  for (int it = 1; it <= opt.max_iter; ++it) {
    for (int n = 0; n < nn; ++n) {
      if (!(T[n] <= oil.t_max_c))
        throw ConvergenceError("THD equilibrium: the film temperature " + num(T[n]) +
                               " degC exceeds the viscosity law's range (t_max_c = " +
                               num(oil.t_max_c) + " degC)");
      mu.data()[n] = oil.viscosity_pa_s(std::max(T[n], oil.t_min_c));
    }
    solver.set_viscosity_field(mu);
    // the position: the full equilibrium on the first iteration (cold start), then one Newton
    // step per iteration (F + W = 0, dF/dq = −K: q += K⁻¹(F + W)) — the position converges
    // with the temperature; the final equilibrium is polished to 1e-10 below
    EquilibriumSolution eq;
    eq.force_n.setZero();
    double rtol = 1e-10;
    bool stepped = false;
    if (it > 1) {
      const DynamicCoefficients dc = solver.coefficients(x, y, omega);
      const Eigen::Vector2d r = dc.force_n + Eigen::Vector2d(lx, ly);
      const Eigen::Vector2d dq = dc.K.fullPivLu().solve(r);
      const double c = solver.geometry().clearance_m;
      if (dq.allFinite() && std::hypot(x + dq[0], y + dq[1]) < 0.98 * c) {
        x += dq[0];
        y += dq[1];
        stepped = true;
        rtol = 1.0;  // not an equilibrium yet: polish at the end
      }
    }
    if (!stepped) {
      eq = solver.equilibrium(lx, ly, omega, x, y, 1e-6);
      out.equilibrium_iterations += eq.iterations;
      x = eq.x_m;
      y = eq.y_m;
      rtol = 1e-6;
    }
    const FilmSolution* sol = &solver.rigid(x, y, 0.0, 0.0, omega);
    ThdFilmState st = thd_energy(solver, *sol, oil, opt, omega);
    starved = st.starved ? starved_message("THD equilibrium", st.supply_flow_m3_s,
                                           st.film_flow_m3_s, hot_oil(st)) : std::string();
    const Eigen::VectorXd G = Eigen::Map<const Eigen::VectorXd>(st.temperature_c.data(), nn);
    const double res = thd_residual_k(G, T, oil.t_max_c);
    out.iterations = it;
    if (res <= opt.tol_k) {
      if (rtol > 1e-10) {  // polish the equilibrium with the field frozen, and its state
        eq = solver.equilibrium(lx, ly, omega, x, y, 1e-10);
        out.equilibrium_iterations += eq.iterations;
        x = eq.x_m;
        y = eq.y_m;
        sol = &solver.rigid(x, y, 0.0, 0.0, omega);
        st = thd_energy(solver, *sol, oil, opt, omega);
        const Eigen::VectorXd G2 =
            Eigen::Map<const Eigen::VectorXd>(st.temperature_c.data(), nn);
        if (thd_residual_k(G2, T, oil.t_max_c) > opt.tol_k) {  // the position had not settled
          T = G2;
          continue;
        }
      }
      if (st.starved)  // no equilibrium of the full film (thermal_detail.hpp supply_mixing)
        throw StarvedError(starved_message("THD equilibrium", st.supply_flow_m3_s,
                                           st.film_flow_m3_s, hot_oil(st)));
      out.equilibrium = eq;
      out.coefficients = solver.coefficients(x, y, omega);
      out.film = std::move(st);
      if (!(out.film.max_temperature_c <= oil.t_max_c))
        throw ConvergenceError("THD equilibrium: the maximum film temperature " +
                               num(out.film.max_temperature_c) + " degC exceeds the viscosity "
                               "law's range (t_max_c = " + num(oil.t_max_c) + " degC)");
      return out;
    }
    Eigen::VectorXd Tn = mixer.next(T, G.cwiseMin(oil.t_max_c));  // the clamped map
    for (int n = 0; n < nn; ++n) Tn[n] = std::clamp(Tn[n], oil.t_min_c, oil.t_max_c);
    if (mirror_symmetric(sol->h_m)) symmetrize(Tn.data(), N, K1);
    T = Tn;
  }
  if (!starved.empty()) throw StarvedError(starved);  // the last iterate was starved
  throw ConvergenceError("THD equilibrium: the film temperature did not settle to " +
                         num(opt.tol_k) + " K in " + std::to_string(opt.max_iter) +
                         " iterations");
}

}  // namespace rotordyn
