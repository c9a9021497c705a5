// ReynoldsSolver: pockets (recesses, steps in the film thickness) on the finite-volume grid.
//
// A node-centred scheme takes the film at a face from its two nodes. Across a step that mean
// smears the step over a cell and the film converges at first order only (a pressure dam at
// 72 x 16 was 12-14 % off in K, C). Here every face is given the exact value of the piecewise
// film over the strip between its nodes: along the face's normal the pieces are in series
// (the flux through them is one: 1/G3 = Σ t_i / h_i³, the Couette flux the flux-continuous
// Gc = G3 Σ t_i / h_i², both exact for a 1-D step wherever it falls between the nodes);
// across the face, strips of different thickness are in parallel (G = Σ w_s G_s, exact along
// an edge that runs through the nodes). h_i = hf + d_i with hf the mean of the caller's
// (smooth) film at the two nodes. A node's film is the caller's plus the depth averaged
// over its cell (friction: the cell average of 1/h).
#include <algorithm>
#include <cmath>

#include "reynolds_impl.hpp"

namespace rotordyn {

namespace {
using reynolds_detail::kPi;

struct Rect {
  double a, b;    // φ from a to b (rad, a in [0, 2π)); ring: the whole circle
  bool ring;
  double z0, z1;  // z range
  double d;       // depth
};
}  // namespace

void ReynoldsSolver::Impl::setup_pockets() {
  has_pockets = !geo.pockets.empty();
  if (!has_pockets) return;
  std::vector<Rect> rs;
  for (const Pocket& pk : geo.pockets) {
    double s = std::fmod(pk.start_deg, 360.0);
    if (s < 0.0) s += 360.0;
    Rect r;
    r.a = s * kPi / 180.0;
    r.b = r.a + pk.arc_deg * kPi / 180.0;
    r.ring = pk.arc_deg >= 360.0;
    r.z0 = pk.z_min_m;
    r.z1 = pk.z_max_m;
    r.d = pk.depth_m;
    rs.push_back(r);
  }
  // Mirror symmetry about z = 0 (the half system): every pocket has its mirror image.
  pockets_symmetric = true;
  for (const Pocket& p : geo.pockets) {
    bool found = false;
    for (const Pocket& q : geo.pockets)
      found = found || (q.start_deg == p.start_deg && q.arc_deg == p.arc_deg &&
                        q.depth_m == p.depth_m && q.z_min_m == -p.z_max_m &&
                        q.z_max_m == -p.z_min_m);
    pockets_symmetric = pockets_symmetric && found;
  }
  // Edges of the pockets that overlap the box [x0, x1] x [y0, y1], strictly inside it, with
  // its sides (sorted); an edge closer than tol to a side is on it (no round-off slivers).
  const double tol_phi = 1e-9 * dphi, tol_z = 1e-9 * dz;
  auto overlaps = [&](const Rect& r, double x0, double x1, double y0, double y1) {
    if (!(r.z0 < y1 - tol_z && r.z1 > y0 + tol_z)) return false;
    if (r.ring) return true;
    for (int m = -1; m <= 1; ++m)
      if (r.a + 2.0 * kPi * m < x1 - tol_phi && r.b + 2.0 * kPi * m > x0 + tol_phi) return true;
    return false;
  };
  auto cuts_phi = [&](double x0, double x1, double y0, double y1) {
    std::vector<double> c{x0};
    for (const Rect& r : rs) {
      if (r.ring || !overlaps(r, x0, x1, y0, y1)) continue;
      for (const double e : {r.a, r.b})
        for (int m = -1; m <= 1; ++m) {
          const double x = e + 2.0 * kPi * m;
          if (x > x0 + tol_phi && x < x1 - tol_phi) c.push_back(x);
        }
    }
    c.push_back(x1);
    std::sort(c.begin(), c.end());
    return c;
  };
  auto cuts_z = [&](double x0, double x1, double y0, double y1) {
    std::vector<double> c{y0};
    for (const Rect& r : rs) {
      if (!overlaps(r, x0, x1, y0, y1)) continue;
      for (const double e : {r.z0, r.z1})
        if (e > y0 + tol_z && e < y1 - tol_z) c.push_back(e);
    }
    c.push_back(y1);
    std::sort(c.begin(), c.end());
    return c;
  };
  auto depth_at = [&](double x, double y) {
    double d = 0.0;
    for (const Rect& r : rs) {
      double rel = std::fmod(x - r.a, 2.0 * kPi);
      if (rel < 0.0) rel += 2.0 * kPi;
      if ((r.ring || rel < r.b - r.a) && y > r.z0 && y < r.z1) d += r.d;
    }
    return d;
  };
  // a box with an edge inside: its film is not uniform
  auto cut = [&](double x0, double x1, double y0, double y1) {
    return cuts_phi(x0, x1, y0, y1).size() > 2 || cuts_z(x0, x1, y0, y1).size() > 2;
  };
  const double zend = 0.5 * L;
  auto zlo = [&](int k) { return std::max(-zend, -zend + (k - 0.5) * dz); };
  auto zhi = [&](int k) { return std::min(zend, -zend + (k + 0.5) * dz); };
  auto zk = [&](int k) { return -zend + k * dz; };

  // Nodes: the depth averaged over the cell; non-uniform cells keep their pieces.
  dnode.assign(n_nodes, 0.0);
  h_smooth.assign(n_nodes, c);
  pk_cell.assign(n_nodes, -1);
  pk_cell_end.assign(n_nodes, -1);
  for (int n = 0; n < n_nodes; ++n) {
    const int j = n / K1, k = n % K1;
    const double x0 = (j - 0.5) * dphi, x1 = (j + 0.5) * dphi;
    const std::vector<double> cx = cuts_phi(x0, x1, zlo(k), zhi(k));
    const std::vector<double> cy = cuts_z(x0, x1, zlo(k), zhi(k));
    if (cx.size() == 2 && cy.size() == 2) {
      dnode[n] = depth_at(j * dphi, 0.5 * (cy[0] + cy[1]));
      continue;
    }
    const double area = (cx.back() - cx.front()) * (cy.back() - cy.front());
    pk_cell[n] = static_cast<int>(pk_pieces.size());
    for (std::size_t a = 0; a + 1 < cx.size(); ++a)
      for (std::size_t b = 0; b + 1 < cy.size(); ++b) {
        const double t = (cx[a + 1] - cx[a]) * (cy[b + 1] - cy[b]) / area;
        const double d = depth_at(0.5 * (cx[a] + cx[a + 1]), 0.5 * (cy[b] + cy[b + 1]));
        pk_pieces.push_back({t, d});
        dnode[n] += t * d;
      }
    pk_cell_end[n] = static_cast<int>(pk_pieces.size());
    pk_cells.push_back(n);
  }

  // Faces: strips across (parallel) of pieces along the normal (series), merged by depth.
  pk_east.assign(n_nodes, -1);
  pk_north.assign(n_nodes, -1);
  auto add_face = [&](int n, bool north, const std::vector<double>& along,
                      const std::vector<double>& across, bool along_phi) {
    PocketFace f{n, north, static_cast<int>(pk_strips.size()), 0};
    const double len = along.back() - along.front(), wid = across.back() - across.front();
    for (std::size_t b = 0; b + 1 < across.size(); ++b) {
      PocketStrip st{(across[b + 1] - across[b]) / wid, static_cast<int>(pk_pieces.size()), 0};
      const double ym = 0.5 * (across[b] + across[b + 1]);
      for (std::size_t a = 0; a + 1 < along.size(); ++a) {
        const double xm = 0.5 * (along[a] + along[a + 1]);
        const double d = along_phi ? depth_at(xm, ym) : depth_at(ym, xm);
        const double t = (along[a + 1] - along[a]) / len;
        if (static_cast<int>(pk_pieces.size()) > st.p0 && pk_pieces.back().d == d)
          pk_pieces.back().t += t;
        else
          pk_pieces.push_back({t, d});
      }
      st.p1 = static_cast<int>(pk_pieces.size());
      pk_strips.push_back(st);
    }
    f.s1 = static_cast<int>(pk_strips.size());
    (north ? pk_north : pk_east)[n] = static_cast<int>(pk_faces.size());
    pk_faces.push_back(f);
  };
  for (int n = 0; n < n_nodes; ++n) {
    const int j = n / K1, k = n % K1;
    const double xw = (j - 0.5) * dphi, xc = j * dphi, xe = (j + 0.5) * dphi;
    // φ-face (j+1/2, k): special when an edge crosses the box of both nodes' cells
    if (cut(xw, xe + dphi, zlo(k), zhi(k)))
      add_face(n, false, cuts_phi(xc, xc + dphi, zlo(k), zhi(k)),
               cuts_z(xc, xc + dphi, zlo(k), zhi(k)), true);
    // z-face (j, k+1/2)
    if (k + 1 < K1 && cut(xw, xe, zlo(k), zhi(k + 1)))
      add_face(n, true, cuts_z(xw, xe, zk(k), zk(k + 1)), cuts_phi(xw, xe, zk(k), zk(k + 1)),
               false);
  }
}

void ReynoldsSolver::Impl::pocket_face(int f, double hf, double& G3, double& Gc, double* dG3,
                                       double* dGc) const {
  G3 = Gc = 0.0;
  double d3 = 0.0, dc = 0.0;
  const PocketFace& pf = pk_faces[f];
  for (int s = pf.s0; s < pf.s1; ++s) {
    const PocketStrip& st = pk_strips[s];
    if (st.p1 - st.p0 == 1) {  // uniform along the normal: h³ and h
      const double h1 = hf + pk_pieces[st.p0].d;
      G3 += st.w * h1 * h1 * h1;
      Gc += st.w * h1;
      d3 += st.w * 3.0 * h1 * h1;
      dc += st.w;
      continue;
    }
    double S2 = 0.0, S3 = 0.0, S4 = 0.0;
    for (int i = st.p0; i < st.p1; ++i) {
      const double ih = 1.0 / (hf + pk_pieces[i].d), t = pk_pieces[i].t;
      const double ih2 = ih * ih, ih3 = ih2 * ih;
      S2 += t * ih2;
      S3 += t * ih3;
      S4 += t * ih3 * ih;
    }
    const double H = 1.0 / S3;  // the strip's effective h³ (pieces in series)
    G3 += st.w * H;
    Gc += st.w * S2 * H;
    d3 += st.w * 3.0 * S4 * H * H;
    dc += st.w * (3.0 * S2 * S4 - 2.0 * S3 * S3) * H * H;
  }
  if (dG3) *dG3 = d3;
  if (dGc) *dGc = dc;
}

double ReynoldsSolver::Impl::pocket_inv_h(int n) const {
  double v = 0.0;
  for (int i = pk_cell[n]; i < pk_cell_end[n]; ++i)
    v += pk_pieces[i].t / (h_smooth[n] + pk_pieces[i].d);
  return v;
}

}  // namespace rotordyn
