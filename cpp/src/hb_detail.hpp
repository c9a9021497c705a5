// Internal to the harmonic-balance code (harmonic_balance.cpp: one orbit; hb_continuation.cpp:
// the corrector of a branch): the Fourier basis, the AFT residual of eq. 12 with its Jacobian,
// the orbit's samples and its monodromy (from the samples' linearisations or from one CVODES
// sensitivity flow). Not installed, not part of the public headers.
#pragma once
#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

#include "rotordyn/harmonic_balance.hpp"
#include "rotordyn/hill.hpp"
#include "rotordyn/periodic.hpp"
#include "shooting_detail.hpp"

namespace rotordyn::hb_detail {

/// The truncated Fourier basis at M equally spaced samples τ_j = 2πj/M; coefficient rows
/// c0, a_1, b_1, …, a_H, b_H.
struct Basis {
  int H = 0, M = 0, nb = 0;   // nb = 2H + 1
  Eigen::MatrixXd E, E1, E2;  // (M, nb): basis, d/dτ, d²/dτ² at τ_j
  Eigen::MatrixXd P;          // (nb, M): the projection (DFT) R̂ = P R
};

Basis make_basis(int H, int M);

/// One residual evaluation at (Z, ω): R̂ (nb·n, block p = harmonic row p), with `jac` the
/// Jacobian in z (nb·n × nb·n), its ω column and the films' K_H, D_H at the samples (for the
/// Floquet multipliers).
struct Eval {
  Eigen::VectorXd R, dRdw;
  Eigen::MatrixXd J;
  std::vector<Eigen::MatrixXd> KH, DH;
  bool ok = false;
  std::string why;
  bool contact = false;
};

/// The AFT residual of eq. 12 at the operating point of `in` (F: its M(Ω) factor, F0, C + ΩG;
/// both must outlive the problem).
struct Problem {
  SystemSolver* solver = nullptr;
  const PeriodicInput* in = nullptr;
  shooting_detail::Flow* F = nullptr;
  Basis B;
  Eigen::Index n = 0;
  long linearizations = 0, evaluations = 0;

  /// Z: (nb, n) coefficients; ω the fundamental (rad/s).
  Eval eval(const Eigen::MatrixXd& Z, double w, bool jac);
};

/// Coefficients (nb, n) of position samples X (M0, n) at τ_j = 2πj/M0, truncated to H.
Eigen::MatrixXd project_samples(const Eigen::MatrixXd& X, int H);
/// Shift the time origin by φ (τ → τ + φ).
void shift_phase(Eigen::MatrixXd& Z, int H, double phi);
/// The smallest film clearance, m (`length_scale` if > 0; 1e-3 m for a system without films).
double length_scale(const SystemModel& m, double length_scale);
/// Each coordinate's residual scale |K_ii + K_H,ii| + ω_s²|M_ii| + ω_s|C_ii + ΩG_ii| (ω_s =
/// max(|Ω|, ω)) from an evaluation with the Jacobian: the residual in units of a displacement.
Eigen::VectorXd row_scale(const Eval& e, const SystemModel& m, const shooting_detail::Flow& F,
                          double omega, double w);
/// R̃ = R / (rowscale · L), block by block (nb blocks of n).
Eigen::VectorXd scaled(const Eigen::VectorXd& R, const Eigen::VectorXd& rowscale, int nb, double L);
/// (H + 1,) max over the coordinates of |(a_k, b_k)| / L (k = 0: |c0| / L).
Eigen::VectorXd harmonic_amplitudes(const Eigen::MatrixXd& Z, double L);
/// The orbit over one period into o: n_out samples including the end point (t, r, v), the
/// start (r0, v0) at τ = 0 and the period 2π/ω. false if a sample is not finite.
bool fill_orbit(PeriodicOrbitResult& o, const Eigen::MatrixXd& Z, double w, double t0, int n_out);
/// The monodromy from the linearisations of `e` at its M samples (A(τ) trigonometrically
/// interpolated, 4th-order Magnus with exponentials): no film solve.
Eigen::MatrixXd sample_monodromy(const shooting_detail::Flow& F, const SystemModel& m,
                                 const Eval& e, double T, int substeps);
/// exp(A) with A's rows and columns balanced first (Osborne, powers of 2): hb_detail.cpp.
Eigen::MatrixXd balanced_exp(const Eigen::MatrixXd& A);

/// The samples route refined (hb_floquet.cpp): the monodromy of the orbit's linearisation
/// by 4th-order Magnus with Simpson nodes (each step's ends and midpoint) at which the films
/// are linearised on the HB orbit itself (no interpolation of A(τ)); the first level's nodes
/// are the Newton's M samples (M even; M/2 steps), each further level doubles the steps and
/// linearises the films at the new midpoints only. Stops when the critical multiplier's
/// modulus changed by ≤ tol·max(1, |μ_c|) between two levels and its type did not change
/// (converged), or when the next level would exceed max_steps steps per period.
struct RefinedMonodromy {
  Eigen::MatrixXd Phi;      ///< the finest level's monodromy (empty on failure)
  /// | |μ_c| − |μ_c|_previous level | (inf with one level only: no estimate); autonomous:
  /// at least trivial_error
  double error = std::numeric_limits<double>::quiet_NaN();
  double trivial_error = std::numeric_limits<double>::quiet_NaN();  ///< |μ_triv − 1|
  int steps = 0;            ///< Magnus steps per period of Phi
  int levels = 0;
  bool converged = false;
  long linearizations = 0;  ///< film linearisations added (beyond the Newton's samples)
  std::vector<double> moduli;  ///< |μ_c| per level
  bool ok = false, contact = false;
  std::string why;
};
/// trivial_tol > 0 (an autonomous orbit known to the integrator's accuracy, not a truncated
/// series): converged also needs |μ_trivial − 1| ≤ trivial_tol — the one multiplier whose
/// exact value is known, which a pre-asymptotic level can leave far off while |μ_c| no
/// longer moves (the paper rig's whirl by shooting: 0.07 at 3,200 steps, 2e-5 at 25,600).
RefinedMonodromy refined_monodromy(Problem& P, const Eval& e, const Eigen::MatrixXd& Z, double w,
                                   bool autonomous, double tol, int max_steps,
                                   double trivial_tol = 0.0);
/// The same refined product on a shooting orbit (hb_floquet.cpp): the films linearised at its
/// samples X (n_out rows over [t0, t0 + T], the last equal to the first; positions then
/// velocities), refined on the positions' trigonometric interpolant (H = (n_out − 2) / 2).
RefinedMonodromy refined_monodromy_of_samples(SystemSolver& solver, const PeriodicInput& in,
                                              shooting_detail::Flow& F, const Eigen::MatrixXd& X,
                                              double T, bool autonomous, double tol,
                                              int max_steps);
/// The films linearised at a shooting orbit's samples X (n_out rows over [t0, t0 + T], the
/// last equal to the first) into e.KH, e.DH (n_out − 1 each); false with out.why /
/// out.contact (a film closed) on a failure; out.linearizations counts them.
bool linearize_samples(SystemSolver& solver, const PeriodicInput& in, const Eigen::MatrixXd& X,
                       Eval& e, RefinedMonodromy& out);
/// refined_monodromy_of_samples from linearisations e already made (linearize_samples); the
/// result's linearizations count only those it adds.
RefinedMonodromy refine_samples(SystemSolver& solver, const PeriodicInput& in,
                                shooting_detail::Flow& F, const Eigen::MatrixXd& X,
                                const Eval& e, double T, bool autonomous, double tol,
                                int max_steps);
/// The budget of refined_monodromy: `requested` if > 0, else 128 M steps per period.
int refined_max_steps(int M, int requested);

/// out.block(p, q) += P(p, j) (E(j, q) X0 + s1 E'(j, q) X1 + s2 E''(j, q) X2) for every harmonic
/// row p and column q (n × n blocks): sample j's share of a projected linear operator (the AFT
/// Jacobian: X0 = K + K_H, s1 X1 = ω D, s2 X2 = ω² M). hill.cpp.
void add_sample_block(Eigen::MatrixXd& out, const Basis& B, int j, const Eigen::MatrixXd& X0,
                      double s1, const Eigen::MatrixXd& X1, double s2, const Eigen::MatrixXd& X2);
/// Floquet exponents and multipliers by Hill's method (hill.hpp) at an evaluation with the
/// Jacobian: its J, and Δ1 from its D_H and Cd = C + ΩG; Mm = M(Ω). hill.cpp.
HillResult hill_at(const Basis& B, const Eval& e, const Eigen::MatrixXd& Cd,
                   const Eigen::MatrixXd& Mm, double w, HillSelection selection);
/// o.floquet (and o.monodromy, the one Hill's exponents and eigenvectors give) by Hill's
/// method at the converged orbit (Z, w) of P, whose last evaluation with the Jacobian is e:
/// with that Jacobian when time_points ≤ its M, else with one more evaluation on time_points
/// samples (counted in P). false with o.status ("error", or "rub" if a film closes at a new
/// sample) and a message when that evaluation or the eigenvalue solver fails, or fewer than 2n
/// finite exponents come out. hill.cpp.
bool hill_floquet_into(PeriodicOrbitResult& o, Problem& P, const Eval& e, const Eigen::MatrixXd& Z,
                       double w, bool autonomous, HillSelection selection, int time_points);
/// Hill's time points for H harmonics and the Newton's M: `requested` if > 0, else max(M, 8H)
/// (the AFT Jacobian's aliasing: docs/nonlinear.md).
int hill_time_points(int H, int M, int requested);
/// The checks of the harmonic-balance options every entry point shares (harmonics in
/// [1, 1000], M = time_points or max(4H, 2H + 1) in [2H + 1, 1e5], tol > 0, max_iter >= 1,
/// magnus_substeps >= 1, hill_time_points 0 or in [2H + 1, 1e5]; InputError naming the
/// field); returns M.
int checked_time_points(const HarmonicBalanceOptions& ho);
/// The monodromy of one CVODES flow with forward sensitivities in the error test (at
/// `srtol`) from (o.r0, o.v0) over [t0, t0 + T] into o.monodromy (o.monodromy_rtol, the
/// flow's counters). false with o.status / o.message set when the flow fails.
bool flow_monodromy(shooting_detail::Flow& F, PeriodicOrbitResult& o, double t0, double T,
                    const CvodeOptions& cvode, double srtol);

/// Where a converged point's multipliers came from: "samples", "hill", "flow" or "none", the
/// screening route's |μ_c| and |μ_trivial − 1| (NaN when not computed; 0 when there is none),
/// and the film linearisations and evaluations Hill's method added (one more evaluation on
/// its own time points).
struct PointFloquet {
  std::string route;
  double screen_critical_modulus = 0.0, screen_trivial_error = 0.0;
  /// route "refined": the refined product's | |μ_c| − |μ_c|_previous level | (else NaN) and
  /// its Magnus steps per period (0: not refined)
  double refined_error = std::numeric_limits<double>::quiet_NaN();
  int refined_steps = 0;
  long linearizations = 0, evaluations = 0;
};

/// The screen of a point's multipliers from a cheap route (pf.screen_critical_modulus and
/// pf.screen_trivial_error set from fq): whether the verdict needs the flow (or first the
/// refinement). Samples: no critical multiplier, | |μ_c| − 1 | < margin, or |μ_trivial − 1| >
/// margin / 2 (a poor monodromy); `hill`: | |μ_c| − 1 | < margin + 3 |μ_trivial − 1|. margin
/// 0: never. Shared by the harmonic-balance and the shooting continuation's correctors.
bool screen_close(const Floquet& fq, double margin, bool hill, PointFloquet& pf);
/// A refined product (refined_monodromy) taken where it resolves the verdict: converged,
/// finite, with a critical multiplier and | |μ_c| − 1 | above its error estimate; then
/// o.monodromy is its Φ (monodromy_rtol 0) and pf.route "refined" with refined_error. Always
/// records pf.refined_steps. false: the flow decides.
bool take_refined(RefinedMonodromy& rm, bool autonomous, PeriodicOrbitResult& o,
                  PointFloquet& pf);

/// The end of a converged corrector at (Z, ω) (a branch point: hb_continuation.cpp): an
/// autonomous orbit whose harmonics are all below max(100 tol, 1e-4) L is refused (the branch
/// reached an equilibrium), the orbit's samples into o (fill_orbit), and its Floquet
/// multipliers — from the screening route (floquet = samples: the samples' linearisations of
/// `e`, an evaluation of P with the Jacobian at Z, ω; floquet = hill: Hill's method on e's
/// Jacobian, with one more evaluation of P on Hill's time points), recomputed by one CVODES
/// sensitivity flow at sensitivity_rtol where the screen is not safe (samples: | |μ_c| − 1 | <
/// margin or |μ_trivial − 1| > margin / 2; Hill: | |μ_c| − 1 | < margin + 3 |μ_trivial − 1|;
/// margin 0: never), or by the flow for floquet = flow. With floquet = samples and
/// ho.floquet_tol > 0 a point the screen calls close is first refined (refined_monodromy;
/// route "refined") and goes to the flow only when that leaves the verdict unresolved. false with o.status / o.message set
/// on a failure.
bool finish_point(PeriodicOrbitResult& o, const Eigen::MatrixXd& Z, double w, double L,
                  const PeriodicInput& in, shooting_detail::Flow& F, Problem& P, const Eval& e,
                  const HarmonicBalanceOptions& ho, double margin, PointFloquet& pf);

}  // namespace rotordyn::hb_detail
