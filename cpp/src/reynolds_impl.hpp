// Private state of ReynoldsSolver (shared by the reynolds_*.cpp translation units).
#pragma once
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <array>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "format_detail.hpp"
#include "reynolds_band.hpp"
#include "reynolds_ldlt.hpp"
#include "rotordyn/reynolds.hpp"
#include "turbulence_detail.hpp"

namespace rotordyn {

namespace reynolds_detail {
constexpr double kPi = 3.14159265358979323846;
/// Operating ranges accepted at the boundary (beyond them the film has no physical meaning
/// and its pressures overflow): |speed| <= 1e5 Hz, journal velocity |v| <= 1e3 m/s.
constexpr double kMaxOmega = 2.0 * kPi * 1e5;
constexpr double kMaxVelocity = 1e3;
/// Resource caps of one film grid, checked before the factor is allocated: nodes, bytes of
/// the sparse factor, multiply-adds of one numeric factorisation.
constexpr long long kMaxFilmNodes = 1LL << 22;
constexpr double kMaxFactorBytes = 4e9;
constexpr double kMaxFactorFlops = 2e10;

using format_detail::num;  // a number in error messages (6 significant digits)
}  // namespace reynolds_detail

/// One sparse system over a set of unknown nodes: the full grid, or — when the film and its
/// rate are mirror-symmetric about z = 0 — the half grid k <= Kh. For an even n_axial the
/// mid-plane is the node row Kh = n_axial/2, a half cell (its φ-terms and right-hand side
/// halved, no flux across the mid-plane); for an odd n_axial the mid-plane is the face between
/// rows Kh = (n_axial-1)/2 and its mirror Kh+1, which carries no flux (equal pressures). The
/// half system is the full system restricted by symmetry, not an approximation.
struct LinearSystem {
  using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  struct ColPos {
    int diag, e, w, n, s;  // value positions of (i,i), (E,i), (W,i), (N,i), (S,i); -1: none
  };
  bool half = false;
  int n_unk = 0;
  std::vector<int> unk;        // node -> unknown index, -1 if prescribed (or mirrored, half)
  std::vector<int> node_of;    // unknown -> node
  std::vector<double> wphi;    // unknown -> weight of φ-fluxes and sources (0.5 on a half cell)
  std::vector<char> has_n;     // unknown -> couples to its k+1 neighbour
  std::vector<char> has_s;     // unknown -> couples to its k-1 neighbour (0 on a sealed z = -L/2 row)
  SpMat A;                     // 5-point pattern, both triangles, explicit zeros kept
  std::vector<ColPos> pos;
  struct Nbr {
    int e, w, n, s;  // neighbour unknowns of (i) where pos has a slot (else unused)
  };
  std::vector<Nbr> nbr;
  StaticLDLT ldlt;             // symbolic once per system, numeric per call
  BandLDLT band;               // when a decoupled ring opens the circle (reynolds_band.hpp)
  std::vector<int> ring_first; // ring j's unknowns are ring_first[j] .. ring_first[j+1]-1
  bool use_band = true;
  int band_cut = -1;           // the ring the last band factor opened the circle at (-1: none)
  // fill_band's per-unknown table (built on its first use): node, west node, flags, weight,
  // north/east neighbour unknowns where a slot exists (-1 none) and their distances mod n.
  struct FillEntry {
    int n, wn, un, ue, dn, de;
    bool has_s, has_n, seal;
    double wp;
  };
  std::vector<FillEntry> fill_tab;
  bool fill_tab_ok = false;
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;
  bool lu_analysed = false;
  std::vector<char> active;    // unknown: 1 = p held at 0 (reynolds) / cavitated (jfo)
  std::vector<char> last_set;  // the last converged Swift–Stieber set (continuation only)
  enum class Factor { none, ldlt, band, lu, static_lu } factor = Factor::none;
  /// x = A⁻¹ b with the symmetric factor of the last factor_spd (ldlt or band).
  // predict_active: the four coarse nodes (flat p_pa indices) around each unknown
  std::vector<std::array<int, 4>> coarse_around;
  // refine_prediction (full grid): bilinear weights of coarse_around, the operator's neighbour
  // unknowns (n_unk: none), per solve its rows over their diagonals (b, e, w, n, s), the
  // relaxed pressures (one zero slot past the end), a ring's updates, the rings relaxed
  std::vector<std::array<double, 4>> coarse_w;
  std::vector<std::array<int, 4>> relax_idx;
  std::vector<std::array<double, 5>> relax_c;
  std::vector<double> relax_x, relax_t;
  std::vector<char> relax_ring;
  void solve_spd(const double* b, double* x) const {
    if (factor == Factor::band)
      band.solve(b, x);
    else
      ldlt.solve(b, x);
  }
  /// x_v = A⁻¹ x_v in place for four vectors (the same values as four solve_spd calls).
  void solve_spd4(double* const x[4]) const {
    if (factor == Factor::band)
      band.solve4(x);
    else
      for (int v = 0; v < 4; ++v) ldlt.solve(x[v], x[v]);
  }
  Eigen::VectorXd rhs, sol;
};

struct ReynoldsSolver::Impl {
  using SpMat = LinearSystem::SpMat;

  JournalBearingGeometry geo;
  FilmGrid grid;
  Cavitation cav;

  int N = 0;        // nodes around
  int K1 = 0;       // node rows along (n_axial + 1)
  int Kh = -1;      // last row of the half grid: n_axial/2 (even; the mid-plane row) or
                    // (n_axial-1)/2 (odd; the mid-plane is the face above it)
  bool mid_node = true;  // n_axial even: the mid-plane is a node row
  int n_nodes = 0;  // N * K1, node n = j * K1 + k
  double R = 0, L = 0, c = 0, mu = 0, dphi = 0, dz = 0;
  // Turbulence (geo.turbulence != laminar, reynolds_turbulence.cpp): Re_h = re_per_h · h with
  // re_per_h = ρ|ω|R/μ (set per solve). turb_face: the multipliers of a face's conductance
  // (12/k) and of its h-derivative; the face is the east (axial = false) or north face of
  // node q, whose viscosity (a viscosity field: the mean of its nodes') sets its Re_h.
  // node_re: Re_h at node n with film h (its own viscosity).
  bool turb = false;
  double re_per_h = 0.0;
  void turb_face(double hf, bool axial, int q, double& m, double& dm) const;
  double node_re(int n, double hn) const {
    return visc_field ? re_per_h * hn * (mu / mu_node[n]) : re_per_h * hn;
  }
  // node_cf: the Couette wall-shear factor C_f at node n with film h (1 laminar): the
  // friction torque's and the dissipation's, one expression (couette_shear_factor), with
  // the geometry's transition (if any)
  double node_cf(int n, double hn) const {
    return turb ? couette_shear_factor(geo.turbulence, node_re(n, hn), geo.turbulence_onset_re,
                                       geo.turbulence_full_re)
                : 1.0;
  }
  // the model's factors at Re_h with the geometry's transition (if any)
  TurbulenceFactors tfac(double re) const {
    return turbulence_factors(geo.turbulence, re, geo.turbulence_onset_re,
                              geo.turbulence_full_re);
  }
  // Viscosity field (set_viscosity_field, the thermo-hydrodynamic film; reynolds_viscosity.cpp):
  // node viscosities and the multipliers mu/mu_face of the faces' conductances (the face
  // viscosity the mean of its two nodes'), applied after the uniform film's conductances, so
  // an unset field leaves the isoviscous path untouched.
  bool visc_field = false;
  bool visc_symmetric = true;      // the field is mirror-symmetric about z = 0 (bitwise)
  std::vector<double> mu_node, vmE, vmN;
  double node_mu(int n) const { return visc_field ? mu_node[n] : mu; }
  void film_flows(FilmFlows& f) const;
  std::vector<double> cosphi, sinphi;
  std::vector<char> fixed;       // node -> prescribed pressure (ends, grooves)
  std::vector<double> p_fixed;   // node -> prescribed pressure (0 if unknown)
  std::vector<char> groove;      // node -> 1 on a groove (interior rows)
  std::vector<int> groove_nodes; // the groove nodes
  // End seals (geo.end_sealed()): the end rows k = 0 and K1-1 are unknowns on half cells
  // (φ-fluxes and sources weighted 1/2) whose outer face is the seal, a conductance
  // gseal = G_s R Δφ to the ambient pressure 0. Off: the end rows are Dirichlet p = 0.
  bool sealed = false;
  double gseal = 0.0;
  bool end_row(int n) const { return sealed && (n % K1 == 0 || n % K1 == K1 - 1); }

  // Pockets (geo.pockets, reynolds_pockets.cpp). The solver's node film h is the caller's
  // h_smooth plus the pocket depth averaged over the node's cell (dnode). A face whose strip
  // between its nodes (or whose nodes' cells) a pocket edge crosses is a PocketFace: its
  // values come from the piecewise film over the strip, hf + d on each piece (hf the mean of
  // h_smooth at its nodes): strips across the face (widths w, in parallel) of pieces along it
  // (lengths t, in series). Every other face is uniform: the mean of its nodes' h is exact.
  struct PocketPiece {
    double t, d;  // fraction of the strip (or of the cell), depth
  };
  struct PocketStrip {
    double w;  // fraction of the face
    int p0, p1;
  };
  struct PocketFace {
    int n;       // the face (j+1/2, k) of node n = (j, k), or (j, k+1/2) when north
    bool north;
    int s0, s1;  // its strips
  };
  bool has_pockets = false;
  bool pockets_symmetric = true;  // mirror-symmetric about z = 0 (half system allowed)
  std::vector<double> dnode, h_smooth;
  std::vector<PocketPiece> pk_pieces;
  std::vector<PocketStrip> pk_strips;
  std::vector<PocketFace> pk_faces;
  std::vector<int> pk_east, pk_north;  // node -> PocketFace of face (j+1/2, k) / (j, k+1/2), -1
  std::vector<int> pk_cell;            // node -> first piece of its cell (non-uniform), -1
  std::vector<int> pk_cell_end;
  std::vector<int> pk_cells;           // the nodes whose cell is not uniform
  void setup_pockets();
  // Face value for the smooth film hf: G3 = effective h³ (conductance / (h³ factor)),
  // Gc = effective h of the Couette flux, and their derivatives with respect to hf.
  void pocket_face(int f, double hf, double& G3, double& Gc, double* dG3 = nullptr,
                   double* dGc = nullptr) const;
  double pocket_inv_h(int n) const;  // the cell average of 1/h (friction)

  LinearSystem full, halfsys;
  bool halfsys_built = false;
  bool use_symmetry = true;
  LinearSystem* sys = nullptr;   // the system of the last solve

  // Film of the current solve (node arrays).
  double omega = 0.0;
  std::vector<double> h, hdot;
  std::vector<double> cE, cN;  // conductances of faces (j+1/2, k) and (j, k+1/2)
  std::vector<double> qE;      // Couette coefficient (ωRΔz/2)·h of face (j+1/2, k)
  std::vector<double> src;     // RΔφΔz ∂h/∂t

  // Solution state (node arrays).
  std::vector<double> p;       // node pressures (the model's answer)
  std::vector<double> pfull;   // unclipped linear solution (none/gumbel)
  std::vector<double> theta;   // node fill fraction
  // Reynolds: nodes where p = 0 and the multiplier A p − b = 0 (to round-off) — the
  // cavitation set is degenerate there (e.g. the whole film of a centred journal) and the
  // pressure is only directionally differentiable; linearize() then takes the limit of
  // central differences (see solve_derivative_lcp).
  std::vector<char> biactive;  // node -> 1 if degenerate
  int n_biactive = 0;
  double deg_mu_last = 0.0;    // the last active-set solve's degenerate band of the multiplier
  bool solved = false;
  FilmSolution out;

  Impl(const JournalBearingGeometry& g, const FilmGrid& gr, Cavitation cv);

  int east(int n) const { return n + K1 >= n_nodes ? n + K1 - n_nodes : n + K1; }
  int west(int n) const { return n - K1 < 0 ? n - K1 + n_nodes : n - K1; }
  int mirror(int n) const { return n - 2 * (n % K1) + K1 - 1; }

  void build_system(LinearSystem& S, bool half);
  bool symmetric(const double* f) const;  // f(φ, z) == f(φ, −z) bitwise
  void mirror_fields();                   // fill k > Kh from their mirrors after a half solve
  int mirror_end() const { return sealed ? K1 : K1 - 1; }  // rows Kh+1 .. mirror_end()-1 mirrored

  void set_film(const double* h_in, const double* hdot_in, double omega_in);
  // Right-hand side b of A p = b (Couette, squeeze, prescribed neighbours), unknown ordering.
  void base_rhs(const LinearSystem& S, Eigen::VectorXd& b) const;
  // A's values; mask (unknown-indexed, may be null) decouples masked unknowns (identity rows).
  void fill_spd(LinearSystem& S, const std::vector<char>* mask);
  // Assemble and factorise A with the masked unknowns decoupled: banded when a ring is wholly
  // masked (or has no unknowns), which opens the circle there — the band filled directly from
  // the conductances, one pass, no sparse values; otherwise fill_spd and the static sparse
  // LDLᵀ. Both factor the same values as fill_spd(S, mask).
  // reuse (the active-set loop, reynolds_band_fill.cpp): keep_cut >= 0 opens the circle at
  // that ring while it stays decoupled; checkpoints saves what a resumed band factor needs;
  // prev, the mask of the last factor_spd of S with the film unchanged since, resumes the
  // band factor after the first columns the mask change touches (bit for bit the full one).
  struct BandReuse {
    bool checkpoints = false;
    const std::vector<char>* prev = nullptr;
    int keep_cut = -1;
  };
  void factor_spd(LinearSystem& S, const std::vector<char>* mask,
                  const BandReuse* reuse = nullptr);
  bool fill_band(LinearSystem& S, const char* mask, int cut, bool rev, int c_from = 0);
  bool band_factor = true;  // the banded path on (off: always the sparse factor; tests)
  bool band_resume = true;  // BandReuse::prev honoured (off: a full refactor; tests)
  int band_resumed = 0;     // resumed band factorisations in the last solve_reynolds
  // Residual (outflow + storage) of node n's full cell for node pressures pp and fill theta.
  double cell_residual(int n, const std::vector<double>& pp) const;

  void solve_linear(LinearSystem& S);    // none / gumbel
  // Short-bearing approximation (geo.short_bearing): p node by node, no linear system.
  void solve_short();
  double short_source(const double* hh, const double* hd, int n) const;  // (ω/2)∂h/∂φ + ∂h/∂t
  double short_factor(int n) const;  // 6μ (z² − L²/4) at node n's row
  // Start of the active set, a function of this call's inputs only: the cavitated region of
  // the same film on the grid with every other node in each direction (solved recursively
  // the same way), interpolated; on grids too coarse or not halvable, the nodes whose source
  // term b_i < 0 (divergent film: the Couette and squeeze terms draw fluid out of the cell).
  // The primal–dual iteration then needs ~1–3 steps, nearly independent of the grid.
  void predict_active(LinearSystem& S);
  // Full grid: the coarse prediction (coarse pressures pc, flat) refined by projected
  // relaxation of the fine operator near the predicted film boundaries (reynolds_refine.cpp).
  void refine_prediction(LinearSystem& S, const double* pc);
  bool refine = true;  // refine_prediction on (off: the coarse prediction alone; tests)
  std::unique_ptr<ReynoldsSolver> coarse;  // Swift–Stieber solver on the halved grid
  bool coarse_usable = false;
  bool predict = true;  // coarse-grid prediction on; off: start from the empty set
  bool continuation = false;  // start from the last converged set of this system (in a run)
  int coarse_n_circ = 0, coarse_n_axial = 0;
  RowMatrixXd hc, hdc;                     // film sampled on the coarse nodes
  struct CoarseLerp {
    int n00, n01, n10, n11;  // fine nodes (j0,k0), (j0,k1), (j1,k0), (j1,k1)
    double fj, fk;
  };
  std::vector<CoarseLerp> coarse_lerp;     // per coarse node (row-major), built once
  void solve_reynolds(LinearSystem& S);  // Swift–Stieber LCP by primal–dual active set
  // Directional derivative dp of the Swift–Stieber solution for a residual change dr at a
  // degenerate set: the LCP on the biactive unknowns, dp = 0 on the strongly active ones.
  void solve_derivative_lcp(LinearSystem& S, const Eigen::VectorXd& dr, Eigen::VectorXd& x);
  // (A_unmasked x)_i for the system's unknown ordering (x indexed by unknowns).
  double apply_row(const LinearSystem& S, int i, const Eigen::VectorXd& x) const;
  void solve_jfo(LinearSystem& S);       // Elrod–Adams p–θ
  // Metered supply (reynolds_starved.cpp): the grooves' state s (see JournalBearingGeometry::
  // supply_flow_m3_s): inlet fill θ_in = min(s, 1), pressure max(s − 1, 0)·pressure_pa.
  double groove_theta = 1.0;
  std::vector<double> groove_p0;  // node -> the groove's nominal pressure_pa
  void set_groove_state(double s);
  void solve_supplied(LinearSystem& S);  // jfo with the supply: flooded, or the root in s
  void full_film_start();                // out.full_film_start_deg
  double supply_s = 2.0;                 // the last solve's groove state (2: flooded)
  // linearize() of a starved film at the held supply: adds ds·x_s to the frozen-state
  // unknowns x (x_s = ∂u/∂s at the frozen partition, ds so that the inflow does not change);
  // returns ds. inflow_derivative: the change of flows()' inlet flow for node changes dp, dth
  // of pressure and fill and dh of the film (the groove state's own change in dp, dth).
  double hold_supply(const LinearSystem& S, const double* dh, Eigen::VectorXd& x);
  double inflow_derivative(const std::vector<double>& dp, const std::vector<double>& dth,
                           const double* dh) const;
  void fill_jfo(LinearSystem& S);
  // Factorise the p–θ system in S.A: static-pattern LU without pivoting (columns are
  // diagonally dominant) checked by its residual on b, else Eigen's pivoting SparseLU.
  void factor_solve_jfo(LinearSystem& S, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  void solve_factored(const LinearSystem& S, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  void postprocess();
  std::vector<double> tau_ring;  // postprocess: the shear of one ring's nodes
  void flows();  // out.inlet_flow_m3_s, out.side_flow_m3_s (postprocess)
  bool pressure_only = false;  // solve() fills p_pa and h_min only (postprocess_pressure)
  void postprocess_pressure();

  // The four frozen-set linearised solves of coefficients() at once (dh = -cos φ, -sin φ with
  // d_dhdt = 0, then the same as d_dhdt with dh = 0; all mirror-symmetric): dp_v as
  // ReynoldsSolver::linearize gives them, bit for bit, with one four-vector triangular solve.
  // False (nothing done) where linearize takes another branch (short bearing, jfo or a
  // pivoting LU, a degenerate Swift–Stieber set).
  bool linearize_trig4(RowMatrixXd (&dp)[4]);
  // set by rigid() for the one solve() it calls (h, ∂h/∂t depend on φ only); solve() clears it
  bool film_z_constant = false;
  RowMatrixXd rigid_h, rigid_hd;  // ReynoldsSolver::rigid's film (written fully every call)
  RowMatrixXd trig_c, trig_s, trig_zero;  // -cos φ_j, -sin φ_j, 0 on the nodes (lazily)
  void make_trig_fields();
  std::array<Eigen::VectorXd, 4> lin_r;  // linearize_trig4's right-hand sides / solutions

  // d(residual)/d(h, hdot) at the frozen state, S's unknown ordering and row weights.
  void residual_derivative(const LinearSystem& S, const double* dh, const double* dhdot,
                           Eigen::VectorXd& out) const;
  // residual_derivative for several dh (d_dhdt[v] each) of a film without pockets or seals:
  // the face conductances and pressure differences formed once, each column then the same
  // operations in the same order as residual_derivative_t<false> (the same values, bit for
  // bit).
  void residual_derivative_many(const LinearSystem& S, const std::vector<const double*>& dh,
                                const std::vector<const double*>& dhdot,
                                const std::vector<Eigen::VectorXd*>& out) const;
  template <bool kPockets>  // with pocket faces, or the plain film's code unchanged
  void residual_derivative_t(const LinearSystem& S, const double* dh, const double* dhdot,
                             Eigen::VectorXd& out) const;
};

// (inline: the active-set loop calls it once per held node and iteration)
inline double ReynoldsSolver::Impl::cell_residual(int n, const std::vector<double>& pp) const {
  const int e = east(n), w = west(n);
  const double pn = pp[n];
  if (end_row(n)) {  // a sealed end's half cell: half the φ-balance, its inner face, the seal
    double r = cE[n] * (pn - pp[e]) + cE[w] * (pn - pp[w]);
    if (omega >= 0.0)
      r += qE[n] * theta[n] - qE[w] * theta[w];
    else
      r += qE[n] * theta[e] - qE[w] * theta[n];
    r += src[n] * theta[n];
    const int k = n % K1;
    return 0.5 * r + (k == 0 ? cN[n] * (pn - pp[n + 1]) : cN[n - 1] * (pn - pp[n - 1])) +
           gseal * pn;
  }
  double r = cE[n] * (pn - pp[e]) + cE[w] * (pn - pp[w]) + cN[n] * (pn - pp[n + 1]) +
             cN[n - 1] * (pn - pp[n - 1]);
  if (omega >= 0.0)
    r += qE[n] * theta[n] - qE[w] * theta[w];
  else
    r += qE[n] * theta[e] - qE[w] * theta[n];
  r += src[n] * theta[n];
  return r;
}

}  // namespace rotordyn
