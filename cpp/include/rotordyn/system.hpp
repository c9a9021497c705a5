// The multi-bearing system of the paper (eq. 12-13): rotor (condensed) and flexible-sleeve
// coordinates r, coupled through any number of fluid films.
//
//   M r̈ + (C + Ω G) ṙ + K r = H(Ω, r, ṙ) + Q + p_c·c_s + F − K a_r                (eq. 12)
//
// Each film couples a few coordinates of r: the journal's (x, y) and, for an active bearing,
// the sleeve's master coordinates. The film thickness is affine in them,
//   h(φ, z) = c + Σ_k S(φ, k) r_coords[k]     (S = −cos φ, −sin φ for the journal; −ψ_j(φ)
//                                             for the sleeve's inward modes, eq. 3-5),
// so the generalised film force on coordinate k is, by virtual work, H_k = ∫∫ p S(φ, k) dA.
#pragma once
#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

#include "rotordyn/reynolds.hpp"

namespace rotordyn {

/// One fluid-film bearing in the system.
struct FilmCoupling {
  std::string name;
  JournalBearingGeometry geometry;
  FilmGrid grid;
  Cavitation cavitation = Cavitation::reynolds;
  std::vector<int> coords;  ///< indices into r: journal x, journal y, then sleeve coordinates
  RowMatrixXd shape;        ///< (n_circ, n_coords): ∂h/∂r_k at the grid angles, m/m
  /// Film thickness at r = 0 (lobes, preload, pad geometry, dam step), m: (n_circ, 1), or
  /// (n_circ, n_axial + 1) when it varies along z; empty: the clearance everywhere (plain
  /// bush). h = base_h + S r.
  RowMatrixXd base_h;
  /// The film's surface speed is spin_factor·Ω: 1 for a journal bearing, 0 for a
  /// squeeze-film damper (the damper journal does not spin).
  double spin_factor = 1.0;
  /// Axial weight of each coordinate, (n_coords, n_axial + 1): ∂h/∂r_k(φ_j, z_m) =
  /// shape(j, k)·axial_weight(k, m). Journal tilt: the rotations θx, θy of the bearing
  /// station move the journal centre to (x + θy z, y − θx z) (rotor.hpp: dx/dz = θy,
  /// dy/dz = −θx), so their columns are shape = (sin φ, −cos φ) with weight z_m, and the
  /// virtual work H_k = ∫∫ p ∂h/∂r_k dA is the film moment about x (resp. y) at the bearing
  /// centre. Empty (default): 1 everywhere (h varies along z only through base_h), the
  /// untilted film bit for bit.
  RowMatrixXd axial_weight;
  /// Film thickness h = base_h + Σ_k shape(·, k)·axial_weight(k, ·)·rc_k on the grid,
  /// (n_circ, n_axial + 1), for the film's coordinates rc (n_coords,).
  RowMatrixXd thickness(const Eigen::VectorXd& rc) const;
  /// ∂h/∂r_k on the grid, (n_circ, n_axial + 1).
  RowMatrixXd thickness_derivative(Eigen::Index k) const;
  /// Viscosity per node (n_circ, n_axial + 1), Pa·s (a thermo-hydrodynamic film's frozen
  /// temperature field, thd.hpp); empty: geometry.viscosity_pa_s everywhere.
  RowMatrixXd viscosity_field;
};

/// Linear bearing with speed-dependent coefficients (bearing tables): force on the two
/// coordinates (x, y) = −K(Ω) q − C(Ω) q̇ − M(Ω) q̈, K, C (and M) interpolated linearly in Ω
/// between table rows; the mass coefficients enter the system's mass matrix
/// (SystemModel::mass_at). Outside [omegas.front(), omegas.back()] an InputError names the speed unless
/// `extrapolate` (then the end intervals are extended linearly).
struct TableCoupling {
  std::string name;
  std::vector<int> coords;  ///< (2,): x, y indices into r
  Eigen::VectorXd omegas;   ///< (n_s,) rad/s, strictly increasing
  RowMatrixXd K;            ///< (n_s, 4): kxx kxy kyx kyy, N/m
  RowMatrixXd C;            ///< (n_s, 4): cxx cxy cyx cyy, N·s/m
  RowMatrixXd M;            ///< (n_s, 4): mxx mxy myx myy, kg; empty (0 × 0): no mass terms
  bool extrapolate = false;
  /// K(Ω), C(Ω) (2×2 each) and, when Mout is given, M(Ω) (zero without mass terms).
  /// InputError outside the table unless extrapolate.
  void at(double omega, Eigen::Matrix2d& Kout, Eigen::Matrix2d& Cout,
          Eigen::Matrix2d* Mout = nullptr) const;
  void validate(const std::string& where, Eigen::Index n) const;
};

/// Linear matrices, loads and films of the system (SI). n = total coordinates.
struct SystemModel {
  Eigen::MatrixXd M, K, C, G;  ///< (n, n); G per unit spin speed (rad/s)
  /// Circulatory stiffness of the shaft's rotating (internal) damping per unit spin speed
  /// (rad/s), N·s/m: (n, n) or empty (none). It acts like the tables, inside H: the solver's
  /// H(Ω, r, ṙ) includes −Ω Kc r and its K_H includes Ω Kc, so every analysis built on H
  /// (equilibrium, linearisation, transient and its Jacobian, orbits, thresholds, sweeps over
  /// Ω by differences) carries it. The damping itself (β K) is in C. The housing offsets a of
  /// eq. 14 bend the shaft too (r is relative to the housings, the shaft's displacement r + a):
  /// their part −Ω Kc a is a load, in offset_load().
  Eigen::MatrixXd Kc;
  Eigen::VectorXd Q;           ///< (n,) static load (gravity), N
  Eigen::VectorXd chamber;     ///< (n,) chamber force per unit chamber pressure, N/Pa
  std::vector<FilmCoupling> films;
  std::vector<TableCoupling> tables;
  /// (n,) The shaft's force from the housing offsets a at spin speed ω (rad/s): K a + ω Kc a
  /// (elastic and, with rotating damping, circulatory), moved to the right side of eq. 14 as
  /// −offset_load(ω, a).
  Eigen::VectorXd offset_load(double omega, const Eigen::VectorXd& a) const {
    Eigen::VectorXd f = K * a;
    if (Kc.size()) f.noalias() += omega * (Kc * a);
    return f;
  }
  /// Tilting pads (or any element whose own coordinates enter one film only): per pad, its
  /// coordinates in r, the tilt-like one first (film moment; any structural stiffness, often
  /// none), then optionally a radial pivot displacement (K(u, u) > 0, film force decreasing
  /// as u grows), then optionally the pad's pitch (rotation about the tangent at the pivot, a
  /// spherical pivot's axial tilt: flagged by pad_pitch). Each group's coordinates must
  /// belong to exactly one film and no other film or table, and K must not couple two
  /// groups. The pad's film may carry axial weights (journal tilt). Non-empty: the Newton
  /// equilibrium starts from the pad-assembly solve (pad_equilibrium.cpp).
  std::vector<std::vector<int>> pad_coords;
  /// Per pad group, 1 if its last coordinate is the pad's pitch (film moment about the
  /// pivot's tangent; its film column has an axial weight, z), else 0; empty: no pitch.
  std::vector<int> pad_pitch;
  Eigen::Index n() const { return M.rows(); }
  void validate() const;  ///< shapes and indices; InputError naming the field
  /// True when a table carries mass coefficients (the mass matrix then depends on Ω).
  bool has_table_mass() const;
  /// The mass matrix at spin speed Ω: M plus the tables' interpolated mass coefficients.
  Eigen::MatrixXd mass_at(double omega) const;
};

enum class EquilibriumMethod { Newton, Successive };
EquilibriumMethod parse_equilibrium_method(const std::string& name);

struct EquilibriumOptions {
  EquilibriumMethod method = EquilibriumMethod::Newton;
  double tol = 1e-10;          ///< residual tolerance relative to the load scale
  int max_iter = 100;          ///< Newton iterations (successive: 500× this)
  double pm = -1.0;            ///< P_m of eq. 16 (successive substitution); < 0: automatic
  double contact_fraction = 0.02;  ///< h_min below this fraction of c → status "contact"
  /// After converging to tol, full Newton steps down to the round-off floor where the root is
  /// well conditioned, so that the answer does not depend on the starting point (warm start)
  /// beyond round-off. rotordyn.equilibrium sets it; bearing-element tables leave it off.
  bool polish = false;
  /// Newton Jacobian (issue 22). false: K + K_H formed exactly (linearised Reynolds solves) at
  /// every iterate that takes a step. true: modified Newton — the Jacobian is kept from step to
  /// step and Broyden-updated (rank one, from the step and the residual change), so a step
  /// costs a Reynolds solve and no linearisation; it is formed exactly again after a step that
  /// reduced the residual by less than reuse_contraction, and a reused Jacobian whose full
  /// step does not reduce the residual is replaced by the exact one at the same iterate
  /// (which then takes the damped step). Converged to the same tolerance: the answer changes
  /// within it, not beyond. The polish and the load continuation always use the exact one.
  bool reuse_jacobian = false;
  double reuse_contraction = 0.1;  ///< in (0, 1): a step reducing ‖R‖ less than this refreshes J
  /// Tilting pads on spherical pivots: each pad's (tilt[, pivot], pitch) by one joint Newton
  /// in the pad assembly, the nested solves (pitch ⊃ pivot ⊃ tilt) where it fails (true), or
  /// always the nested solves (false: the reference the joint solve is tested against).
  bool joint_pad_solve = true;
};

struct EquilibriumResult {
  Eigen::VectorXd r;           ///< (n,) equilibrium coordinates (relative to the housings)
  /// (n,) H at the equilibrium: the bearings' own (films, tables), without the shaft's
  /// circulatory −Ω Kc r that the solver's H carries
  Eigen::VectorXd film_force;
  std::vector<double> h_min;   ///< per film, m
  std::vector<double> h_min_angle_deg;
  /// Axial position z of each film's minimum (m, z = 0 mid-plane; 0 where the film is
  /// uniform along z at that angle): a tilted or misaligned journal's edge film.
  std::vector<double> h_min_z_m;
  int iterations = 0;
  int reynolds_solves = 0;
  double residual = 0.0;       ///< ‖K(r + a) − H − Q − p_c c_s‖∞ / load scale
  double load_scale = 0.0;     ///< N
  double pm = 0.0;             ///< P_m used (successive substitution)
  std::string status = "ok";   ///< ok | not_converged | contact
  std::string message;
  /// How the Newton start was reached: "newton" (from r0), "pad_assembly" (pads solved pad
  /// by pad inside a reduced journal Newton, then full Newton), "load_continuation"
  /// (fallback), "successive"; callers may set "homotopy" (bearing_table.cpp).
  std::string path;
  int unloaded_pads = 0;       ///< pads with no pressured tilt equilibrium (pad_assembly)
};

struct Linearization {
  Eigen::MatrixXd KH, DH;      ///< (n, n) film stiffness and damping, eq. 18: ΔH = −K_H Δr − D_H Δṙ
  Eigen::VectorXd film_force;  ///< (n,) H at the operating point
};

/// Owns one Reynolds solver per film (factorisations and warm-start active sets). Not
/// thread-safe: use one per thread.
class SystemSolver {
 public:
  explicit SystemSolver(SystemModel model);
  ~SystemSolver();
  SystemSolver(SystemSolver&&) noexcept;
  SystemSolver& operator=(SystemSolver&&) noexcept;

  const SystemModel& model() const { return model_; }

  /// H(Ω, r, ṙ) (n,). ContactError if a film thickness is ≤ 0.
  Eigen::VectorXd film_forces(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot,
                              double omega);
  /// Film forces and their linearisation about (r, ṙ) by the perturbation method: each film
  /// is solved once and its linearised Reynolds equation reuses the factorisation.
  Linearization linearize(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot, double omega);
  /// The same by central finite differences of H (paper eq. 20, central form); steps
  /// rel_step·c on positions and rel_step·c·|ω| on velocities.
  Linearization linearize_fd(const Eigen::VectorXd& r, double omega, double rel_step = 1e-6);

  /// Static equilibrium (eq. 14): K (r + a) = H(Ω, r, 0) + Q + p_c c_s.
  /// a: (n,) configuration (housing offsets at the journal coordinates). r0: start (n,) or
  /// empty for the concentric, undeformed state.
  /// kh_guess (with opt.reuse_jacobian): an approximation of K_H at r0 ((n, n); a sweep line's
  /// previous point's K_H), taken as the first Newton Jacobian K + kh_guess; null or empty:
  /// the exact one at the first iterate that needs a step.
  EquilibriumResult equilibrium(double omega, double chamber_pressure, const Eigen::VectorXd& a,
                                const Eigen::VectorXd& r0, const EquilibriumOptions& opt,
                                const Eigen::MatrixXd* kh_guess = nullptr);

  /// Set film `film`'s viscosity (Pa·s, finite > 0) in place — the model's geometry and the
  /// film's Reynolds solver — and forget the last solve (the thermal iteration,
  /// thermal_system_equilibrium). InputError naming the film index or viscosity_pa_s.
  void set_film_viscosity(int film, double viscosity_pa_s);
  /// Set film `film`'s viscosity per node ((n_circ, n_axial + 1), Pa·s; the THD iteration) in
  /// place, as set_film_viscosity; the film's reference viscosity stays.
  void set_film_viscosity_field(int film, const RowMatrixXd& viscosity_pa_s);

  int reynolds_solves() const { return solves_; }
  /// Active-set (or linear) iterations summed over those solves: sparse factorisations.
  long reynolds_iterations() const { return iterations_; }
  /// Linearisations about a solve (K_H, or K_H and D_H, by linearised Reynolds solves on its
  /// factorisation): the Newton Jacobians, the polish and linearize().
  long linearizations() const { return linearizations_; }
  /// Cavitation-set continuation in every film (ReynoldsSolver::set_continuation): on for the
  /// duration of one transient run (consecutive right-hand sides at nearby states), off
  /// otherwise. Each switch forgets the stored sets.
  void set_film_continuation(bool on);
  /// Cavitation-set carry for a sequence of equilibria (the points of one sweep line): each
  /// film's Swift–Stieber solve starts from its last converged set instead of the coarse-grid
  /// prediction, from this call on, across equilibrium() calls, until switched off; every
  /// switch (on or off) forgets the stored sets, so a line that switches it on at its start is
  /// a function of its own inputs. Unlike set_film_continuation the last solve stays valid
  /// (its pressures do not depend on the start set). Off: each equilibrium() carries the sets
  /// between its own solves only, from the prediction at its start.
  void set_film_carry(bool on);
  bool film_carry() const { return carry_; }
  /// Testing switch: every film's ReynoldsSolver::set_refine_prediction (on by default; the
  /// same pressures bit for bit, fewer active-set iterations on full grids). Invalidates the
  /// last solve, so the next call solves again.
  void set_refine_prediction(bool on);
  /// Forget every state an earlier call left: the films' last solve (pressures,
  /// factorisations) and their carried cavitation sets, continuation and carry switched off.
  /// The next call's answer is then a function of its own inputs only (a public analysis
  /// starts here: python/rotordyn/_common/calls.py).
  void forget_state();
  /// Minimum film thickness of each film at positions r (n,), m, from the geometry alone
  /// (h = c + S r over the grid angles, eq. 3): no Reynolds solve, no change to the solvers'
  /// state. Equals last_h_min() after a solve at the same r; ≤ 0 means contact.
  std::vector<double> film_h_min(const Eigen::VectorXd& r) const;
  /// Minimum film thickness of each film at the last film_forces/linearize call.
  const std::vector<double>& last_h_min() const { return h_min_; }
  const std::vector<double>& last_h_min_angle_deg() const { return h_min_angle_; }
  /// Axial position of each film's minimum at the last call, m (see EquilibriumResult).
  const std::vector<double>& last_h_min_z_m() const { return h_min_z_; }
  /// Pressure field of film i at the last call, (n_circ, n_axial + 1).
  const RowMatrixXd& last_pressure(int film) const;
  /// The thinnest film at the last call: the first index of the smallest last_h_min (the
  /// first NaN if any) and its minimum (m), angle (deg) and z (m).
  struct ThinnestFilm {
    int film = -1;
    double h_min_m = 0.0, h_min_angle_deg = 0.0, h_min_z_m = 0.0;
  };
  ThinnestFilm thinnest_film() const;

 private:
  struct Film;
  SystemModel model_;
  std::vector<std::unique_ptr<Film>> films_;
  std::vector<double> h_min_, h_min_angle_, h_min_z_;
  int solves_ = 0;
  long iterations_ = 0;
  long linearizations_ = 0;
  // The state of the films' last solve: a call at the same (r, ṙ, Ω) — an equilibrium's
  // final point then its linearisation, a CVODE right-hand side then its Jacobian — reuses
  // the pressures and factorisations instead of solving again.
  bool solved_ = false;
  bool carry_ = false;  ///< the films carry their cavitation sets (set_film_carry / continuation)
  void carry_sets(bool on);  ///< each film's continuation on/off (sets forgotten), cache kept
  Eigen::VectorXd last_r_, last_rdot_;
  double last_omega_ = 0.0;
  void solve_films(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot, double omega);
  /// K_H (and D_H if `damping`) about the films' last solve, by the perturbation method
  /// (linearised solves reusing each film's factorisation; no new Reynolds solve).
  void linearize_last_solve(bool damping, Eigen::MatrixXd& KH, Eigen::MatrixXd* DH);
  /// The table bearings' −K(Ω) q − C(Ω) q̇ and the shaft's circulatory −Ω Kc r added to
  /// H, and their K, C (and Ω Kc) added to K_H, D_H.
  void add_table_forces(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot, double omega,
                        Eigen::VectorXd& H) const;
  void add_table_coefficients(double omega, Eigen::MatrixXd& KH, Eigen::MatrixXd* DH) const;
  /// Solve film i alone at its local coordinates rc (zero velocity): its generalised forces
  /// (n_coords,). Reuses the film's last solve when rc and Ω are unchanged.
  Eigen::VectorXd solve_film(std::size_t i, const Eigen::VectorXd& rc, double omega);
  void solve_one(std::size_t i, const Eigen::VectorXd& rc, const Eigen::VectorXd& vc,
                 double omega);
  /// −∂H/∂rc of film i about its last solve (n_coords × n_coords), perturbation method; only
  /// the columns `cols` (positions in the film's coordinates; the others are zero).
  Eigen::MatrixXd film_stiffness(std::size_t i, const std::vector<int>& cols);
  /// One pad (SystemModel::pad_coords) resolved: its film and the coordinates' positions in
  /// the film's coordinate list.
  struct PadGroup {
    std::size_t film = 0;
    std::vector<int> coords;  ///< indices into r: tilt[, pivot]
    std::vector<int> local;   ///< their positions in films[film].coords
    bool pitch = false;       ///< the last coordinate is the pad's pitch
    /// with a radial pivot coordinate (it is then the second)
    bool pivot() const { return coords.size() == (pitch ? 3u : 2u); }
  };
  std::vector<PadGroup> pads_;
  struct PadSolve;
  /// Pad-assembly start (pad_equilibrium.cpp): every pad solved on its loaded branch for the
  /// current journal/rotor coordinates, inside a Newton on those with the reduced Jacobian.
  /// true with r at a point whose residual is below tol·load_scale (pads at round-off).
  /// joint: spherical pads by the joint Newton first (EquilibriumOptions::joint_pad_solve).
  bool pad_assembly(double omega, const Eigen::VectorXd& F, double load_scale, double tol,
                    int max_iter, bool joint, Eigen::VectorXd& r, int& iterations,
                    int& unloaded, std::string& why);
};

}  // namespace rotordyn
