// Internal to the shooting code (periodic.cpp, continuation.cpp): the flow of eq. 12 at a
// constant operating point, integrated by CVODES with or without forward sensitivities.
// Not installed, not part of the public headers.
#pragma once
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <sundials/sundials_nonlinearsolver.h>

#include <string>

#include "rotordyn/continuation.hpp"
#include "rotordyn/periodic.hpp"

namespace rotordyn::shooting_detail {

// Everything the right-hand sides share: eq. 12 at constant Ω and p_c, first-order form.
struct Flow {
  SystemSolver* solver = nullptr;
  const PeriodicInput* in = nullptr;
  Eigen::Index n = 0, N = 0;
  Eigen::LLT<Eigen::MatrixXd> Mllt;
  Eigen::VectorXd F0;     // Q − K a + p_c c_s
  Eigen::MatrixXd Cd;     // C + Ω G
  // The system Jacobian A(x) (N × N) at the state y_A: the sensitivity right-hand side and
  // CVODES's Newton matrix at the same state share one linearisation.
  Eigen::VectorXd y_A;
  Eigen::MatrixXd A;
  bool have_A = false;
  std::string last_error, cvode_message;
  bool contact = false;
  long sens_evals = 0;
  // Optional parameter column: with dfdp (N) set, the flows with sensitivities integrate one
  // more column s_p, ṡ_p = A s_p + dfdp, s_p(t0) = 0 (∂x/∂p for an f affine in p); its
  // absolute tolerances are sens_rtol · atol_i / p_unit (p_unit: the change of p that counts
  // as much as one absolute tolerance of the positions).
  Eigen::VectorXd dfdp;
  double p_unit = 1.0;
  // The staggered sensitivity corrector: true, all columns in one blocked solve with the
  // exact matrix I − γA (blocked_sensitivity_solver); false (default), CVODES's own Newton
  // (one dense back-substitution per column with the state's lagged matrix).
  bool blocked_sensitivities = false;
};

struct FlowRun {
  Eigen::VectorXd xT;
  Eigen::MatrixXd Phi;       // empty without sensitivities
  Eigen::VectorXd dxdp;      // ∂x(t0 + T)/∂p with F.dfdp and sensitivities, else empty
  Eigen::VectorXd t;         // samples
  Eigen::MatrixXd X;         // (n_out, N)
  int flag = 0;              // < 0: CVODES failure
  std::string why;
  long steps = 0, rhs_evals = 0, jac_evals = 0;
  long order_reductions = 0;   // BDF stability-limit order reductions (CVODES)
  long sens_newton_iters = 0;  // sensitivity corrector iterations (each: Ns linear solves)
  long sens_factorizations = 0;  // LU factorisations of I − γA by the blocked corrector
};

/// ẋ = f(t, x) of eq. 12 (first-order form) at the flow's operating point.
Eigen::VectorXd vector_field(Flow& F, double t, const Eigen::Ref<const Eigen::VectorXd>& y);
/// The staggered sensitivity corrector for CVODES (CVodeSetNonlinearSolverSensStg) that
/// solves all sensitivity columns at once with its own LU of I − γA, A the Jacobian the
/// sensitivity right-hand side formed (F.A at F.y_A); shooting_sens.cpp. The caller frees it
/// (SUNNonlinSolFree) after CVodeFree.
SUNNonlinearSolver blocked_sensitivity_solver(Flow& F, void* cvode_mem, SUNContext ctx);
/// Factorisations made by a blocked_sensitivity_solver so far.
long blocked_sensitivity_factorizations(SUNNonlinearSolver nls);
/// Binds F to solver and `in` (which must outlive F): M(Ω), the constant forces, C + ΩG.
void setup_flow(Flow& F, SystemSolver& solver, const PeriodicInput& in);
/// Integrate x0 over [t0, t0 + T] (with the monodromy when `sens`), sampling n_out points.
FlowRun run_flow(Flow& F, const Eigen::VectorXd& x0, double t0, double T, bool sens, int n_out,
                 const CvodeOptions& opt, bool sens_errcon, double sens_rtol);
/// The orbit input at the parameter value p of a continuation (continuation.cpp): p_c, Ω or
/// a = base.a + p · config_direction; a forced orbit's period follows Ω (subharmonic · 2π/|Ω|).
PeriodicInput at_parameter(const PeriodicInput& base, ContinuationParameter parameter,
                           const Eigen::VectorXd& config_direction, int subharmonic, double p);
/// The largest change of any film's thickness a displacement makes, in units of that film's
/// clearance: max over the rows of dR (k, n), the films and their grid nodes of
/// |Σ_j ∂h/∂r_j dR(i, j)| / c. Coordinates that enter no film count for nothing (the films
/// are the only forces nonlinear in r). The step cap of a forced orbit's Newton (shooting and
/// harmonic balance): a rotation or a coordinate far from the films is not a length and
/// capping it at a fraction of the clearance crawled (the overhung pump's tilted films:
/// 9 harmonic-balance iterations at 5e-3 kg·m, docs/nonlinear.md).
double film_step_fraction(const SystemModel& m, const Eigen::Ref<const Eigen::MatrixXd>& dR);
/// InputError for shapes, non-finite values, period ≤ 0, forcing inconsistent with the kind.
void validate(const SystemSolver& solver, const PeriodicInput& in, const ShootingOptions& opt,
              bool continuation = false);

}  // namespace rotordyn::shooting_detail
