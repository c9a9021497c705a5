// Fluid-film journal bearing: finite-length Reynolds equation (paper eq. 2-5) on a (φ, z) grid,
// with cavitation, forces, flows, friction and the linearised (perturbation) solve that gives
// the stiffness and damping coefficients (paper eq. 18-20).
//
// Conventions (DESIGN.md §3): x horizontal, y up; φ measured from +x, positive with the
// rotation; film thickness h = c − x cos φ − y sin φ (− w for a deformable sleeve);
//   (1/R²) ∂φ(h³/(12μ) ∂φ p) + ∂z(h³/(12μ) ∂z p) = (ω/2) ∂h/∂φ + ∂h/∂t,
// p = 0 (gauge) at z = ±L/2, periodic in φ, grooves are Dirichlet lines/bands p = p_groove.
// End seals (optional, JournalBearingGeometry::end_seal_conductance G_s finite): the ends are
// flow restrictions instead, a Robin condition −(h³/12μ) ∂p/∂z = ±G_s p at z = ±L/2 (the
// axial flow per unit circumference leaving the film equals G_s times the pressure above the
// ambient 0); the end node rows are then unknowns on half cells. G_s = ∞ (default) is the
// open-ends path above, unchanged.
//
// Discretisation: node-centred finite volumes. Nodes φ_j = j·2π/n_circ (j = 0..n_circ-1) and
// z_k = −L/2 + k·L/n_axial (k = 0..n_axial; k = 0 and n_axial are the bearing ends). Face
// values of h are the averages of the two nodes, the Poiseuille conductance is h_f³/(12μ),
// the Couette flux through a φ-face is (ωR/2)·h_f·θ_upwind; faces that a pocket's edge (a
// step in h) crosses take the exact values of the stepped film instead (Pocket). The scheme
// is conservative and second-order accurate; forces are integrated with the trapezoidal
// rule.
//
// A ReynoldsSolver is built once per (geometry, grid, cavitation model): it analyses the
// sparse pattern once and refactors numerically per call; it keeps the last solution and
// factorisation for linearised solves. A solve never depends on earlier calls (its cavitation
// set starts from a prediction of its own film: a coarse-grid solve). It is not thread-safe:
// use one solver per thread (they share nothing).
#pragma once
#include <Eigen/Core>

#include <cmath>
#include <limits>

#include <memory>
#include <string>
#include <vector>

namespace rotordyn {

using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Cavitation model. none: full Sommerfeld (negative pressures kept); gumbel: half-Sommerfeld
/// (solve, then clip p < 0); reynolds: Swift–Stieber, p ≥ 0 as a linear complementarity
/// problem (primal–dual active set); jfo: mass-conserving Elrod–Adams p–θ complementarity
/// (steady film; the squeeze term is taken as θ ∂h/∂t, i.e. quasi-static in θ).
enum class Cavitation { none = 0, gumbel = 1, reynolds = 2, jfo = 3 };

/// "none" | "gumbel" | "reynolds" | "jfo"; InputError naming `cavitation` otherwise.
Cavitation parse_cavitation(const std::string& name);
const char* cavitation_name(Cavitation c);

/// Turbulent lubrication model of the film (docs/film-physics.md). laminar: the Poiseuille
/// conductance h³/(12μ) (today's film, bit for bit). ng_pan: the linearised turbulent theory
/// of Ng & Pan (1965) with Elrod & Ng (1967), in the curve fits of Taylor & Dowson (1974):
///   k_x = 12 + 0.0136 Re_h^0.90 (circumferential), k_z = 12 + 0.0043 Re_h^0.96 (axial),
///   Couette shear factor C_f = 1 + 0.0012 Re_h^0.94,
/// with the local film Reynolds number Re_h = ρ |ω| R h / μ (U = |ω| R, the journal surface
/// speed; h the local film). The Poiseuille conductances become h³/(k_x μ), h³/(k_z μ); the
/// Couette flux stays U h/2 (the linearised theory's mean Couette flow: the turbulent
/// Couette profile is antisymmetric about mid-film), the wall shear of the Couette flow
/// becomes C_f μ U/h (friction torque). Every coefficient → 12 (C_f → 1) as Re_h → 0.
enum class Turbulence { laminar = 0, ng_pan = 1 };
/// "laminar" | "ng_pan"; InputError naming `turbulence` otherwise.
Turbulence parse_turbulence(const std::string& name);
const char* turbulence_name(Turbulence t);
/// The model's coefficients at a film Reynolds number Re_h >= 0: k_x, k_z (12 laminar), the
/// Couette shear factor C_f (1 laminar), and Re dk/dRe for k_x and k_z (0 laminar).
struct TurbulenceFactors {
  double kx = 12.0, kz = 12.0, cf = 1.0;
  double re_dkx = 0.0, re_dkz = 0.0;
};
TurbulenceFactors turbulence_factors(Turbulence model, double reynolds_number);
/// Optional laminar-to-turbulent transition over onset_re < Re_h < full_re (both NaN: none,
/// the model acts at every Re_h > 0): the intermittency weight γ(Re_h), 0 at and below the
/// onset, 1 at and above full_re, between them the cubic smoothstep γ = t²(3 − 2t),
/// t = (Re − onset)/(full − onset) (C1: γ' = 0 at both ends). With `re_dweight`, also
/// Re dγ/dRe. The turbulent increments take γ: k = 12 + γ a Re^b, C_f = 1 + γ 0.0012 Re^0.94,
/// Re dk/dRe = γ a b Re^b + (Re γ') a Re^b; below the onset exactly laminar (12, 12, 1, 0,
/// 0), above full_re exactly turbulence_factors(model, Re).
double turbulence_weight(double reynolds_number, double onset_re, double full_re,
                         double* re_dweight = nullptr);
TurbulenceFactors turbulence_factors(Turbulence model, double reynolds_number, double onset_re,
                                     double full_re);

/// Axial supply groove fixed in the bearing frame: nodes with φ in
/// [center − width/2, center + width/2] (the nearest node for a zero width) are held at
/// pressure_pa (gauge) over the whole interior length.
struct Groove {
  double center_deg = 0.0;
  double width_deg = 0.0;
  double pressure_pa = 0.0;
};

/// Recess in the bush (a pressure dam's relief pocket, a step bearing's deep inlet region):
/// the film is deeper by depth_m over φ ∈ [start_deg, start_deg + arc_deg] (periodic, the
/// grid's angle φ) and z ∈ [z_min_m, z_max_m] (z = 0 the mid-plane). The film thickness
/// passed to solve() is the one without recesses; the solver adds them. The thickness steps
/// at the recess edges wherever they fall on the grid: every face whose strip between its
/// two nodes an edge crosses takes the exact value of the piecewise film (h³ in series
/// across an edge, in parallel along it; the Couette flux the flux-continuous one), so a
/// stepped film converges at second order. Recesses that overlap add their depths.
struct Pocket {
  double start_deg = 0.0;
  double arc_deg = 0.0;    ///< (0, 360]
  double z_min_m = 0.0;    ///< −L/2 <= z_min_m < z_max_m <= L/2
  double z_max_m = 0.0;
  double depth_m = 0.0;    ///< > 0
};

/// 360° bush (rigid, or with a sleeve deformation supplied through the film thickness).
struct JournalBearingGeometry {
  double diameter_m = 0.05;
  double length_m = 0.04;
  double clearance_m = 3e-4;
  double viscosity_pa_s = 0.04;
  std::vector<Groove> grooves;
  std::vector<Pocket> pockets;  ///< recesses (steps in the film thickness); not short_bearing
  /// End-seal conductance G_s, m²/(Pa·s) (= m³/s of axial leakage per Pa and per metre of
  /// circumference), the same at both ends: q_z = G_s (p − 0) leaves the film through each
  /// end. +∞ (default): open ends, p = 0 at z = ±L/2. Must be ≥ 1e-8 c³/(12μL) (a fully
  /// sealed film without a supply has no pressure level; below this bound the sealed limit
  /// is reached and the level would be lost in round-off); not with cavitation "jfo".
  double end_seal_conductance = std::numeric_limits<double>::infinity();
  /// True when the ends are seals (finite end_seal_conductance).
  bool end_sealed() const { return std::isfinite(end_seal_conductance); }
  /// Short-bearing (Ocvirk) approximation: the circumferential pressure flow is neglected, so
  /// on every node line p = 6μ s (z² − L²/4)/h³ with s = (ω/2) ∂h/∂φ + ∂h/∂t (∂h/∂φ by
  /// central differences), clipped at 0 for "gumbel" and "reynolds" (the short film's
  /// Swift–Stieber solution is the clipped one, line by line). Open ends, no grooves, not
  /// "jfo". Forces integrate it with the same trapezoidal rule (along z: relative error
  /// 1/n_axial² on the parabola).
  bool short_bearing = false;
  /// Turbulent lubrication (see Turbulence): laminar (default) or ng_pan, which needs the
  /// oil density (kg/m³, in (0, 1e5]) for the film Reynolds number ρ|ω|R h/μ. On a mapped
  /// pad grid (diameter s·D at speed ω/s) the surface speed |ω|R is the pad's own.
  Turbulence turbulence = Turbulence::laminar;
  double density_kg_m3 = 0.0;
  /// Optional transition (turbulence_weight): the Re_h at which the turbulent corrections
  /// start and reach their full value, 0 <= onset < full, finite; both NaN (default): none.
  double turbulence_onset_re = std::numeric_limits<double>::quiet_NaN();
  double turbulence_full_re = std::numeric_limits<double>::quiet_NaN();
  /// Metered oil supply to the groove(s), m³/s (cavitation "jfo" only; reynolds_starved.cpp).
  /// 0 (default): flooded grooves, each held at its pressure_pa with a full film. > 0: when
  /// the flooded film draws more than this through its grooves, the film is starved: every
  /// groove holds the same state s, found by a 1-D root so that the grooves' net inflow
  /// equals the supply; s in [1, 2): a full film at (s − 1)·pressure_pa; s in [0, 1): p = 0
  /// and a partial film of fill θ_in = s entering the film (Elrod–Adams: the oil column
  /// θ_in·h travels as striations until the gap closes to it). At or above the flooded
  /// demand the film is the flooded one, bit for bit. Finite, >= 0, <= 1e3 m³/s.
  double supply_flow_m3_s = 0.0;
  /// InputError naming the field and its allowed range.
  void validate() const;
};

/// n_circ nodes around (periodic), n_axial intervals along the length (n_axial + 1 node rows,
/// the first and last on the bearing ends).
struct FilmGrid {
  int n_circ = 72;
  int n_axial = 16;
  void validate() const;
};

/// Everything one Reynolds solve produces. Fields are (n_circ, n_axial + 1), row j = φ_j.
struct FilmSolution {
  RowMatrixXd p_pa;          ///< gauge pressure, Pa
  RowMatrixXd theta;         ///< fill fraction (1 in the full film; < 1 cavitated, jfo only)
  RowMatrixXd h_m;           ///< film thickness, m
  Eigen::Vector2d force_n;   ///< film force on the journal (Fx, Fy), N
  double friction_torque_nm = 0.0;  ///< viscous torque resisting the rotation, N·m (> 0 for ω > 0)
  /// Flow the grooves deliver into the film, m³/s: the net flux out of the groove nodes, a
  /// Swift–Stieber (or clipped) cavitated cell returning nothing; with a supply line at the
  /// maximum film this is the flow just downstream of it (Raimondi & Boyd's Q). Mass-
  /// conserving films (jfo, full films): supply = side flow + storage.
  double inlet_flow_m3_s = 0.0;
  /// Flow leaving through both ends, m³/s (open ends: the end half cells included; seals: the
  /// seal flux), second-order accurate.
  double side_flow_m3_s = 0.0;
  double h_min_m = 0.0;             ///< minimum film thickness over the nodes, m
  double h_min_angle_deg = 0.0;     ///< its angle φ, deg, in [0, 360)
  int iterations = 0;               ///< active-set iterations (1 for none/gumbel)
  /// jfo films (reynolds_starved.cpp): the grooves' inlet fill θ_in (1: a full film at the
  /// groove; < 1: a starved film entering as striations) and the fraction of pressure_pa the
  /// grooves hold (1 flooded; < 1 a metered supply below the flooded demand); starved: true
  /// when a metered supply (JournalBearingGeometry::supply_flow_m3_s) set the groove state.
  double inlet_fill = 1.0;
  double groove_pressure_factor = 1.0;
  bool starved = false;
  /// jfo films: the angle φ (deg, [0, 360)) of the first pressurised node (p > 0) on the
  /// mid-plane row downstream of the first groove column, in the direction of rotation (the
  /// start of the full film, to the grid's Δφ); NaN if there is none (or not jfo).
  double full_film_start_deg = std::numeric_limits<double>::quiet_NaN();
  /// Root iterations of the metered-supply groove state (0: flooded or no supply).
  int supply_iterations = 0;
};

/// The finite-volume flows and the viscous dissipation of the last solve (the transport terms
/// of the thermo-hydrodynamic energy equation, thd.hpp). Arrays (n_circ, n_axial + 1), node
/// n = (j, k). End rows (open ends) are half cells (their φ-faces carry half a face).
struct FilmFlows {
  RowMatrixXd q_phi_m3_s;     ///< flow through face (j+1/2, k), + in the +φ direction, m³/s
  RowMatrixXd q_z_m3_s;       ///< flow through face (j, k+1/2), + towards +z (last column 0)
  RowMatrixXd fill;           ///< fill θ of the flows: 1 in the full film; in a Swift–Stieber
                              ///< (or clipped) cavitated zone the Couette streamers' θ carried
                              ///< from the rupture (θ h conserved along φ); jfo: the solver's θ
  RowMatrixXd dissipation_w;  ///< viscous dissipation in the node's cell, W: μU²θ/h·A (Couette)
                              ///< + half of c Δp² of each of its faces (Poiseuille)
  RowMatrixXd area_m2;        ///< the node's cell area (half on the end rows), m²
  RowMatrixXd viscosity_pa_s; ///< the node viscosities the solve used
  RowMatrixXd makeup_m3_s;    ///< THD pad films: the inlet-gap oil a trailing-edge cell draws
                              ///< (its make-up, thd.cpp kTeMakeup), entering at the pad's
                              ///< inlet temperature; 0 elsewhere and outside the THD field
};

/// Linear coefficients at an operating point: film force change = −K dq − C dq̇ (DESIGN frame).
struct DynamicCoefficients {
  Eigen::Matrix2d K;        ///< N/m
  Eigen::Matrix2d C;        ///< N·s/m
  Eigen::Vector2d force_n;  ///< film force at the operating point
};

struct EquilibriumSolution {
  double x_m = 0.0;
  double y_m = 0.0;
  Eigen::Vector2d force_n;   ///< film force at the equilibrium (≈ −load)
  double residual_rel = 0.0; ///< |F + load| / |load|
  int iterations = 0;        ///< Newton iterations
};

/// Result of a batch call: one row per point; status 0 ok, 1 bad input, 2 contact,
/// 3 not converged, 4 other error; message empty where ok.
struct BatchResult {
  RowMatrixXd values;
  Eigen::VectorXi status;
  std::vector<std::string> message;
};

class ReynoldsSolver {
 public:
  ReynoldsSolver(const JournalBearingGeometry& geometry, const FilmGrid& grid,
                 Cavitation cavitation);
  ~ReynoldsSolver();
  ReynoldsSolver(ReynoldsSolver&&) noexcept;
  ReynoldsSolver& operator=(ReynoldsSolver&&) noexcept;
  ReynoldsSolver(const ReynoldsSolver&) = delete;
  ReynoldsSolver& operator=(const ReynoldsSolver&) = delete;

  const JournalBearingGeometry& geometry() const;
  const FilmGrid& grid() const;
  Cavitation cavitation() const;
  Eigen::VectorXd phi_rad() const;  ///< (n_circ,)
  Eigen::VectorXd z_m() const;      ///< (n_axial + 1,)
  /// (n_circ, n_axial + 1): 1 where the node holds a prescribed pressure (end or groove).
  RowMatrixXd dirichlet_mask() const;
  int n_unknowns() const;

  /// General film: h and ∂h/∂t on the nodes, (n_circ, n_axial + 1); ω in rad/s.
  /// ContactError if h ≤ 0 anywhere.
  /// z_constant: the caller's promise that h and dhdt are constant along z (the mirror-
  /// symmetry check is then skipped; the same solution).
  const FilmSolution& solve(const RowMatrixXd& h, const RowMatrixXd& dhdt, double omega,
                            bool z_constant = false);

  /// Linearised solve about the last solve(): the pressure change (n_circ, n_axial + 1) for a
  /// film-thickness change dh and a change d_dhdt of ∂h/∂t, with the cavitation set frozen
  /// (exact derivative of the discrete map away from set switches). Reuses the factorisation.
  RowMatrixXd linearize(const RowMatrixXd& dh, const RowMatrixXd& d_dhdt);
  /// linearize() for m perturbations at once: dp[v] for (*dh[v], *d_dhdt[v]), v < m, each
  /// field (n_circ, n_axial + 1); the same values as m linearize() calls in that order (bit
  /// for bit, up to the sign of a zero), the residual derivatives formed first and the
  /// triangular solves done four at a time. Falls back to the m calls where linearize()
  /// takes another branch (short bearing, jfo, a degenerate set, a non-symmetric perturbation
  /// of a half-grid solve). z_constant: the caller's promise that every field is constant
  /// along z (the symmetry checks are skipped).
  void linearize_many(const std::vector<const RowMatrixXd*>& dh,
                      const std::vector<const RowMatrixXd*>& d_dhdt,
                      std::vector<RowMatrixXd>& dp, bool z_constant = false);
  /// Force change for a pressure change from linearize().
  Eigen::Vector2d integrate_force(const RowMatrixXd& p) const;
  /// ∫∫ p·g R dφ dz over the bush (trapezoidal rule on the nodes), e.g. the generalised
  /// force of the film on a sleeve mode whose inward radial displacement is g(φ, z) (virtual
  /// work: Q = ∫∫ p·w dA with w the mode's inward displacement per unit coordinate).
  double integrate(const RowMatrixXd& p, const RowMatrixXd& g) const;

  /// Rigid journal at (x, y) with velocity (vx, vy). InputError if the eccentricity ratio ≥ 1.
  const FilmSolution& rigid(double x_m, double y_m, double vx_m_s, double vy_m_s, double omega);
  /// K, C by the perturbation (linearised) solve: one factorisation, four right-hand sides.
  DynamicCoefficients coefficients(double x_m, double y_m, double omega);
  /// K, C by central finite differences of rigid() (steps rel_step·c and rel_step·c·|ω|).
  DynamicCoefficients coefficients_fd(double x_m, double y_m, double omega,
                                      double rel_step = 1e-6);
  /// Newton iteration for F(x, y) + load = 0 with the perturbation Jacobian −K.
  /// x0, y0: starting point (a default guess is used when both are 0).
  EquilibriumSolution equilibrium(double load_x_n, double load_y_n, double omega,
                                  double x0_m = 0.0, double y0_m = 0.0, double rtol = 1e-10,
                                  int max_iter = 60);

  /// Batch of rigid-journal states: rows (x, y, vx, vy), omegas (n,). values (n, 2): forces.
  /// A failing point gets a NaN row and a status (never aborts the batch). n_threads > 1 splits
  /// the rows into contiguous chunks, each solved by its own solver (0: all hardware threads).
  BatchResult batch_forces(const RowMatrixXd& states, const Eigen::VectorXd& omegas,
                           int n_threads = 1);
  /// Batch of positions: rows (x, y), omegas (n,). values (n, 10): Fx, Fy, Kxx, Kxy, Kyx, Kyy,
  /// Cxx, Cxy, Cyx, Cyy (perturbation method).
  BatchResult batch_coefficients(const RowMatrixXd& positions, const Eigen::VectorXd& omegas,
                                 int n_threads = 1);

  /// Change the film's viscosity (Pa·s, finite > 0) without rebuilding the solver (the
  /// effective-temperature model's iteration): every later solve uses it.
  void set_viscosity(double viscosity_pa_s);
  /// A viscosity per node, (n_circ, n_axial + 1), Pa·s, finite > 0 (the thermo-hydrodynamic
  /// film): each face's conductance is h³/(12 μ_f) with μ_f the mean of its two nodes', the
  /// Couette shear μ_n U/h at the nodes (friction torque, dissipation). A uniform field equal
  /// to the solver's viscosity gives the isoviscous film bit for bit; set_viscosity() returns
  /// to a uniform film. Not with the short-bearing model, turbulence or end seals (InputError).
  void set_viscosity_field(const RowMatrixXd& viscosity_pa_s);
  /// Flows and dissipation of the last solve (full postprocess; ConvergenceError if none).
  FilmFlows film_flows() const;

  /// Drop the last solution (linearize() then needs a new solve). Solves never depend on
  /// earlier calls: each starts its cavitation set from a prediction of its own inputs.
  void reset();
  /// Start the cavitation set from the coarse-grid prediction (default) or, when off, from
  /// the empty set (the full-Sommerfeld solution: the pre-prediction algorithm, kept as the
  /// in-run baseline of benchmarks/bench_reynolds.py). Same answer either way (the
  /// complementarity solution is unique), different iteration counts.
  bool predict_cavitation() const;
  void set_predict_cavitation(bool on);
  /// Continuation (off by default): a Swift–Stieber solve starts from the last converged
  /// cavitation set instead of the prediction. For a sequence of nearby states (the right-hand
  /// sides of one transient run) it saves most of the active-set iterations; the answer is the
  /// same unique complementarity solution (equal to round-off at degenerate nodes, where
  /// p = 0 and A p − b = 0 together). Switching it on or off forgets the stored sets, so a run
  /// that switches it on at its start is a function of its own inputs.
  bool continuation() const;
  void set_continuation(bool on);
  /// Pressure only (off by default): solve() fills p_pa, h_min_m, h_min_angle_deg and
  /// iterations only; force_n, the torque and the flows are NaN and theta, h_m empty. For a
  /// caller that integrates the pressure itself (SystemSolver: one solve per transient
  /// right-hand side, where the friction torque and the flows were ~15 % of the solve). The
  /// pressures are the same bit for bit; a non-finite pressure still raises ConvergenceError.
  bool pressure_only() const;
  void set_pressure_only(bool on);
  /// Banded factorisation (on by default): when the cavitation set (or a full-width groove)
  /// empties a whole ring of unknowns, the circle is opened there and the operator is
  /// factorised in its band (1.24-1.45x faster per solve than the periodic pattern's sparse
  /// LDLᵀ on groove-less films, 1.0-1.1x with a supply line); otherwise the sparse LDLᵀ. Off: always the sparse LDLᵀ (the pressures agree to
  /// round-off; for tests and benchmarks).
  bool band_factor() const;
  void set_band_factor(bool on);
  /// Whether the last solve's (final) factorisation was the banded one.
  bool band_factor_used() const;
  /// Testing switch (on by default): in the Swift–Stieber active-set loop on the full grid
  /// the banded factor (ordered against the rotation) resumes after the first column an
  /// iteration's set change touches (the factor is the full refactorisation's bit for bit).
  /// Off: every iteration refactorises in full.
  /// band_resumed(): how many of the last Swift–Stieber solve's factorisations resumed.
  bool band_resume() const;
  void set_band_resume(bool on);
  int band_resumed() const;
  /// Testing switch (on by default): on the full grid the coarse prediction of the
  /// cavitation set is refined by a few projected relaxation sweeps of the fine operator near
  /// the predicted film boundaries (reynolds_refine.cpp), so that the active-set loop starts
  /// closer to its solution (72 × 16 tilted films: 1.5 iterations instead of 2.9). The loop's
  /// answer is the factorisation of the set it ends at, the same bit for bit (round-off where
  /// the set is degenerate). Off: the coarse prediction alone.
  bool refine_prediction() const;
  void set_refine_prediction(bool on);
  /// When h and ∂h/∂t are mirror-symmetric about z = 0 (rigid aligned journal), solve on the
  /// half grid, for either parity of n_axial (exactly the same discrete solution, ~2-4x
  /// cheaper); on by default. Non-symmetric films and perturbations use the full grid.
  bool use_axial_symmetry() const;
  void set_use_axial_symmetry(bool on);

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rotordyn
