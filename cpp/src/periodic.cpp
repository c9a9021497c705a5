// Periodic orbits by single shooting over CVODES with forward sensitivities (periodic.hpp).
// One SUNContext and CVODES memory per flow: nothing global, one SystemSolver per thread.
#include "rotordyn/periodic.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "rotordyn/errors.hpp"
#include "cvode_detail.hpp"
#include "hb_detail.hpp"
#include "shooting_detail.hpp"

namespace rotordyn {

namespace shooting_detail {

Eigen::VectorXd vector_field(Flow& F, double t, const Eigen::Ref<const Eigen::VectorXd>& y) {
  const SystemModel& m = F.solver->model();
  const PeriodicInput& in = *F.in;
  const Eigen::Index n = F.n;
  const Eigen::VectorXd r = y.head(n), v = y.segment(n, n);
  const Eigen::VectorXd H = F.solver->film_forces(r, v, in.omega);
  Eigen::VectorXd f = F.F0;
  if (in.unbalance_cos.size()) {
    const double th = in.omega * t;
    f += in.omega * in.omega * (std::cos(th) * in.unbalance_cos + std::sin(th) * in.unbalance_sin);
  }
  Eigen::VectorXd out(F.N);
  out.head(n) = v;
  out.tail(n) = F.Mllt.solve(H + f - m.K * r - F.Cd * v);
  return out;
}

// A(x) = [[0, I], [−M⁻¹(K + K_H), −M⁻¹(C + ΩG + D_H)]] (perturbation method, as the
// transient's Jacobian); independent of t (the unbalance force does not depend on x).
const Eigen::MatrixXd& jacobian_at(Flow& F, const Eigen::Ref<const Eigen::VectorXd>& y) {
  if (F.have_A && F.y_A == y) return F.A;
  const SystemModel& m = F.solver->model();
  const Eigen::Index n = F.n;
  const Linearization lin = F.solver->linearize(y.head(n), y.segment(n, n), F.in->omega);
  F.A.setZero(F.N, F.N);
  F.A.block(0, n, n, n).setIdentity();
  F.A.block(n, 0, n, n) = -F.Mllt.solve(m.K + lin.KH);
  F.A.block(n, n, n, n) = -F.Mllt.solve(F.Cd + lin.DH);
  F.y_A = y;
  F.have_A = true;
  return F.A;
}

int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  Flow& F = *static_cast<Flow*>(user);
  return cvode_detail::guarded(F, [&] {
    Eigen::Map<const Eigen::VectorXd> Y(N_VGetArrayPointer(y), F.N);
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(ydot), F.N) = vector_field(F, t, Y);
  });
}

int jac(sunrealtype, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector,
        N_Vector) {
  Flow& F = *static_cast<Flow*>(user);
  return cvode_detail::guarded(F, [&] {
    Eigen::Map<const Eigen::VectorXd> Y(N_VGetArrayPointer(y), F.N);
    Eigen::Map<Eigen::MatrixXd>(SUNDenseMatrix_Data(J), F.N, F.N) = jacobian_at(F, Y);
  });
}

// Ṡ_j = A(x(t)) S_j for every column j of the monodromy (all at once, one linearisation).
int sens_rhs(int Ns, sunrealtype, N_Vector y, N_Vector, N_Vector* yS, N_Vector* ySdot,
             void* user, N_Vector, N_Vector) {
  Flow& F = *static_cast<Flow*>(user);
  return cvode_detail::guarded(F, [&] {
    Eigen::Map<const Eigen::VectorXd> Y(N_VGetArrayPointer(y), F.N);
    const Eigen::MatrixXd& A = jacobian_at(F, Y);
    for (int j = 0; j < Ns; ++j) {
      Eigen::Map<const Eigen::VectorXd> s(N_VGetArrayPointer(yS[j]), F.N);
      Eigen::Map<Eigen::VectorXd> sd(N_VGetArrayPointer(ySdot[j]), F.N);
      sd.noalias() = A * s;
      if (j == F.N) sd += F.dfdp;  // the parameter column
    }
    ++F.sens_evals;
  });
}

void setup_flow(Flow& F, SystemSolver& solver, const PeriodicInput& in) {
  const SystemModel& m = solver.model();
  F.solver = &solver;
  F.in = &in;
  F.n = m.n();
  F.N = 2 * F.n;
  F.Mllt.compute(m.mass_at(in.omega));
  require(F.Mllt.info() == Eigen::Success, "M: the mass matrix must be positive definite");
  F.F0 = m.Q - m.offset_load(in.omega, in.a) + in.chamber_pressure * m.chamber;
  F.Cd = m.C + in.omega * m.G;
}


FlowRun run_flow(Flow& F, const Eigen::VectorXd& x0, double t0, double T, bool sens, int n_out,
                 const CvodeOptions& opt, bool sens_errcon, double sens_rtol) {
  FlowRun out;
  const Eigen::Index N = F.N, n = F.n;
  // Each flow starts the films' cavitation sets afresh (a function of its inputs only).
  F.solver->set_film_continuation(true);
  F.have_A = false;
  F.contact = false;
  F.last_error.clear();
  F.cvode_message.clear();
  std::unique_ptr<SUNContext, cvode_detail::SunContextDeleter> sunctx(new SUNContext(nullptr));
  if (SUNContext_Create(nullptr, sunctx.get()) != 0)
    throw SundialsError(-1, "SUNContext_Create", "could not create a SUNDIALS context");
  SUNContext ctx = *sunctx;
  const sunindextype NN = static_cast<sunindextype>(N);
  N_Vector y = N_VNew_Serial(NN, ctx);
  N_Vector abstol = N_VNew_Serial(NN, ctx);
  SUNMatrix Jm = SUNDenseMatrix(NN, NN, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, Jm, ctx);
  void* mem = CVodeCreate(CV_BDF, ctx);
  const int Ns = static_cast<int>(N) + (F.dfdp.size() == N ? 1 : 0);
  N_Vector* yS = sens ? N_VCloneVectorArray(Ns, y) : nullptr;
  SUNNonlinearSolver sens_nls = nullptr;
  auto cleanup = [&]() {
    if (yS) N_VDestroyVectorArray(yS, Ns);
    CVodeFree(&mem);
    if (sens_nls) SUNNonlinSolFree(sens_nls);
    SUNLinSolFree(LS);
    SUNMatDestroy(Jm);
    N_VDestroy(abstol);
    N_VDestroy(y);
    F.solver->set_film_continuation(false);
  };
  auto check = [&](int flag, const char* where) {
    if (flag < 0) {
      const std::string msg =
          cvode_flag_name(flag) + (F.cvode_message.empty() ? "" : ": " + F.cvode_message);
      cleanup();
      throw SundialsError(flag, where, msg);
    }
  };
  Eigen::Map<Eigen::VectorXd> Y(N_VGetArrayPointer(y), N);
  Y = x0;
  Eigen::Map<Eigen::VectorXd> AT(N_VGetArrayPointer(abstol), N);
  AT.head(n).setConstant(opt.atol_position);
  AT.tail(n).setConstant(opt.atol_velocity);
  check(CVodeSetErrHandlerFn(mem, cvode_detail::store_error<Flow>, &F), "CVodeSetErrHandlerFn");
  check(CVodeInit(mem, rhs, t0, y), "CVodeInit");
  check(CVodeSetUserData(mem, &F), "CVodeSetUserData");
  check(CVodeSVtolerances(mem, opt.rtol, abstol), "CVodeSVtolerances");
  check(CVodeSetLinearSolver(mem, LS, Jm), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(mem, jac), "CVodeSetJacFn");
  check(CVodeSetMaxNumSteps(mem, opt.max_steps), "CVodeSetMaxNumSteps");
  if (opt.max_step > 0) check(CVodeSetMaxStep(mem, opt.max_step), "CVodeSetMaxStep");
  if (opt.stability_limit_detection) check(CVodeSetStabLimDet(mem, SUNTRUE), "CVodeSetStabLimDet");
  if (opt.max_order < 5) check(CVodeSetMaxOrd(mem, opt.max_order), "CVodeSetMaxOrd");
  const double t_end = t0 + T;
  check(CVodeSetStopTime(mem, t_end), "CVodeSetStopTime");
  if (sens) {
    // S(t0) = I. Column j is ∂x/∂x0_j: its absolute tolerance is rtol·atol_i/atol_j, i.e.
    // rtol in the units where each coordinate is measured by its own absolute tolerance.
    for (int j = 0; j < Ns; ++j) {
      Eigen::Map<Eigen::VectorXd> s(N_VGetArrayPointer(yS[j]), N);
      s.setZero();
      if (j < N) s(j) = 1.0;
    }
    check(CVodeSensInit(mem, Ns, CV_STAGGERED, sens_rhs, yS), "CVodeSensInit");
    N_Vector* atolS = N_VCloneVectorArray(Ns, y);
    for (int j = 0; j < Ns; ++j) {
      Eigen::Map<Eigen::VectorXd> s(N_VGetArrayPointer(atolS[j]), N);
      s = sens_rtol * AT / (j < N ? AT(j) : F.p_unit);
    }
    const int f = CVodeSensSVtolerances(mem, sens_rtol, atolS);
    N_VDestroyVectorArray(atolS, Ns);
    check(f, "CVodeSensSVtolerances");
    check(CVodeSetSensErrCon(mem, sens_errcon ? SUNTRUE : SUNFALSE), "CVodeSetSensErrCon");
    if (F.blocked_sensitivities) {
      sens_nls = blocked_sensitivity_solver(F, mem, ctx);
      if (!sens_nls) check(CV_MEM_FAIL, "blocked_sensitivity_solver");
      check(CVodeSetNonlinearSolverSensStg(mem, sens_nls), "CVodeSetNonlinearSolverSensStg");
    }
  }
  const int ns = std::max(n_out, 2);
  out.t.resize(ns);
  out.X.resize(ns, N);
  out.t(0) = t0;
  out.X.row(0) = x0.transpose();
  double tret = t0;
  int flag = CV_SUCCESS;
  for (int i = 1; i < ns; ++i) {
    const double target = i == ns - 1 ? t_end : t0 + T * static_cast<double>(i) / (ns - 1);
    flag = CVode(mem, target, y, &tret, CV_NORMAL);
    if (flag < 0) break;
    out.t(i) = target;
    out.X.row(i) = Y.transpose();
  }
  long v = 0;
  CVodeGetNumSteps(mem, &v);
  out.steps = v;
  CVodeGetNumRhsEvals(mem, &v);
  out.rhs_evals = v;
  CVodeGetNumJacEvals(mem, &v);
  out.jac_evals = v;
  if (opt.stability_limit_detection) {
    CVodeGetNumStabLimOrderReds(mem, &v);
    out.order_reductions = v;
  }
  if (sens) {
    CVodeGetSensNumNonlinSolvIters(mem, &v);
    out.sens_newton_iters = v;
    out.sens_factorizations = blocked_sensitivity_factorizations(sens_nls);
  }
  out.flag = flag;
  if (flag < 0) {
    out.why = cvode_flag_name(flag) + " at t = " + std::to_string(tret) + " s" +
              (F.last_error.empty() ? "" : ": " + F.last_error) +
              (F.cvode_message.empty() ? "" : " [" + F.cvode_message + "]");
    cleanup();
    return out;
  }
  out.xT = Y;
  if (sens) {
    check(CVodeGetSens(mem, &tret, yS), "CVodeGetSens");
    out.Phi.resize(N, N);
    for (Eigen::Index j = 0; j < N; ++j)
      out.Phi.col(j) = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(yS[j]), N);
    if (Ns > N) out.dxdp = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(yS[N]), N);
  }
  cleanup();
  return out;
}

double film_step_fraction(const SystemModel& m, const Eigen::Ref<const Eigen::MatrixXd>& dR) {
  double out = 0.0;
  for (const FilmCoupling& fc : m.films) {
    const Eigen::Index nc = static_cast<Eigen::Index>(fc.coords.size());
    Eigen::MatrixXd dRf(dR.rows(), nc);  // the film's coordinates of each row
    for (Eigen::Index k = 0; k < nc; ++k)
      dRf.col(k) = dR.col(fc.coords[static_cast<std::size_t>(k)]);
    if (dRf.cwiseAbs().maxCoeff() == 0.0) continue;
    RowMatrixXd dh = RowMatrixXd::Zero(dR.rows(), fc.shape.rows() * (fc.grid.n_axial + 1));
    for (Eigen::Index k = 0; k < nc; ++k) {
      const RowMatrixXd dk = fc.thickness_derivative(k);  // (n_circ, n_axial + 1)
      dh += dRf.col(k) * Eigen::Map<const Eigen::RowVectorXd>(dk.data(), dk.size());
    }
    out = std::max(out, dh.cwiseAbs().maxCoeff() / fc.geometry.clearance_m);
  }
  return out;
}

void validate(const SystemSolver& solver, const PeriodicInput& in, const ShootingOptions& opt,
              bool continuation) {
#if SUNDIALS_VERSION_MAJOR != 6
  // refused before any CVODES memory exists (shooting_sens.cpp redeclares SUNDIALS 6's layout)
  if (opt.blocked_sensitivities)
    throw InputError(std::string("sensitivity_solve: 'blocked' needs SUNDIALS 6 (this build "
                                 "has ") + SUNDIALS_VERSION + "); use 'columns'");
#endif
  const Eigen::Index n = solver.model().n();
  auto vec_ok = [&](const Eigen::VectorXd& v, const char* name, bool allow_empty) {
    cvode_detail::check_state_vector(v, name, n, allow_empty);
  };
  vec_ok(in.a, "a", false);
  vec_ok(in.r0, "r0", false);
  vec_ok(in.v0, "v0", false);
  vec_ok(in.unbalance_cos, "unbalance_cos", true);
  require(in.unbalance_sin.size() == in.unbalance_cos.size(),
          "unbalance_sin: expected the size of unbalance_cos");
  vec_ok(in.unbalance_sin, "unbalance_sin", true);
  require(std::isfinite(in.period) && in.period > 0,
          "period: expected a finite period > 0 s, got " + std::to_string(in.period));
  require(std::isfinite(in.t0), "t0: expected a finite time");
  require(std::isfinite(in.omega) && std::isfinite(in.chamber_pressure),
          "omega, chamber_pressure: expected finite values");
  require(in.n_out >= 2, "n_out: expected at least 2 samples");
  const bool forcing = in.unbalance_cos.size() > 0 &&
                       ((in.unbalance_cos.array() != 0).any() || (in.unbalance_sin.array() != 0).any());
  if (in.kind == OrbitKind::autonomous)
    require(!forcing, "unbalance: an autonomous orbit has no unbalance forcing (use the forced "
                      "kind)");
  else
    require(forcing && in.omega != 0.0,
            "unbalance: a forced orbit needs an unbalance and a speed != 0");
  const CvodeOptions& c = opt.cvode;
  require(c.rtol > 0 && c.rtol < 1 && c.atol_position > 0 && c.atol_velocity > 0,
          "cvode options: tolerances must be positive");
  require(c.max_steps > 0, "cvode options: max_steps must be positive");
  require(c.max_order >= 1 && c.max_order <= 5,
          "bdf_max_order: expected an integer in [1, 5], got " + std::to_string(c.max_order));
  require(opt.tol > 0 && std::isfinite(opt.tol), "tol: expected a value > 0");
  require(opt.max_iter >= 1, "max_iter: expected at least 1");
  require(opt.floquet_tol >= 0 && std::isfinite(opt.floquet_tol),
          "floquet_tol: expected a finite value >= 0");
  require(opt.floquet_max_steps >= 0, "floquet_max_steps: expected a value >= 0");
  if (continuation) {  // the branch's samples route: 0 is the unrefined product (screened)
    require(opt.floquet != ShootingFloquet::none,
            "floquet: expected flow or samples for a continuation (none leaves no verdict)");
    require(opt.floquet_tol <= 0.5, "floquet_tol: expected a value in [0, 0.5]");
    require(opt.floquet_margin >= 0 && opt.floquet_margin <= 0.5,
            "floquet_margin: expected a value in [0, 0.5]");
  } else {
    require(opt.floquet != ShootingFloquet::samples || opt.floquet_tol > 0,
            "floquet_tol: expected a value > 0 with floquet = samples");
  }
  require(opt.sensitivity_rtol >= 0 && opt.sensitivity_rtol < 1,
          "sensitivity_rtol: expected a value in [0, 1)");
  require(opt.length_scale >= 0 && std::isfinite(opt.length_scale),
          "length_scale: expected a value >= 0 m");
}

}  // namespace shooting_detail

using namespace shooting_detail;

Floquet floquet(const Eigen::MatrixXd& monodromy, bool autonomous) {
  require(monodromy.rows() == monodromy.cols() && monodromy.size() > 0,
          "monodromy: expected a non-empty square matrix");
  require(monodromy.allFinite(), "monodromy: expected finite values");
  Eigen::EigenSolver<Eigen::MatrixXd> es(monodromy, false);
  if (es.info() != Eigen::Success) throw ConvergenceError("monodromy: eigenvalues did not converge");
  return floquet_from_multipliers(es.eigenvalues(), autonomous);
}

Floquet floquet_from_multipliers(const Eigen::VectorXcd& mu, bool autonomous) {
  require(mu.size() > 0 && mu.allFinite(), "multipliers: expected finite values");
  Floquet out;
  std::vector<Eigen::Index> idx(static_cast<std::size_t>(mu.size()));
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::abs(mu(a)) > std::abs(mu(b));
  });
  out.multipliers.resize(mu.size());
  for (Eigen::Index i = 0; i < mu.size(); ++i) out.multipliers(i) = mu(idx[static_cast<std::size_t>(i)]);
  if (autonomous) {
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < mu.size(); ++i) {
      const double d = std::abs(out.multipliers(i) - 1.0);
      if (d < best) {
        best = d;
        out.trivial = static_cast<int>(i);
      }
    }
  }
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    if (static_cast<int>(i) == out.trivial) continue;
    out.critical = static_cast<int>(i);
    out.critical_modulus = std::abs(out.multipliers(i));
    break;
  }
  if (out.critical < 0) {  // a one-dimensional autonomous system: nothing but the trivial one
    out.stable = true;
    return out;
  }
  const std::complex<double> c = out.multipliers(out.critical);
  out.stable = out.critical_modulus < 1.0;
  // Eigen returns exactly real eigenvalues of a real matrix with zero imaginary parts; a
  // complex pair has |Im| well above round-off.
  const bool real = std::abs(c.imag()) <= 1e-9 * std::max(std::abs(c), 1e-300);
  out.critical_type = !real ? "neimark_sacker" : (c.real() > 0 ? "fold" : "period_doubling");
  return out;
}

void flow_map(SystemSolver& solver, const PeriodicInput& in, const CvodeOptions& opt,
              Eigen::VectorXd& xT, Eigen::MatrixXd& monodromy) {
  validate(solver, in, ShootingOptions{opt});
  Flow F;
  setup_flow(F, solver, in);
  Eigen::VectorXd x0(F.N);
  x0 << in.r0, in.v0;
  FlowRun run = run_flow(F, x0, in.t0, in.period, true, 2, opt, true, opt.rtol);
  if (run.flag < 0) throw SundialsError(run.flag, "CVode", run.why);
  xT = run.xT;
  monodromy = run.Phi;
}

PeriodicOrbitResult periodic_orbit(SystemSolver& solver, const PeriodicInput& in,
                                   const ShootingOptions& opt) {
  validate(solver, in, opt);
  const SystemModel& m = solver.model();
  Flow F;
  setup_flow(F, solver, in);
  F.blocked_sensitivities = opt.blocked_sensitivities;
  const Eigen::Index n = F.n, N = F.N;
  const bool autonomous = in.kind == OrbitKind::autonomous;
  PeriodicOrbitResult out;
  out.t0 = in.t0;
  const long solves0 = solver.reynolds_solves();

  double L = opt.length_scale;
  if (!(L > 0)) {
    L = std::numeric_limits<double>::infinity();
    for (const FilmCoupling& fc : m.films) L = std::min(L, fc.geometry.clearance_m);
    if (!std::isfinite(L)) L = 1e-3;
  }
  out.length_scale = L;
  Eigen::VectorXd x(N);
  x << in.r0, in.v0;
  double T = in.period;
  auto scale = [&](double period) {
    const double w = std::max(std::abs(in.omega), 2 * M_PI / period);
    Eigen::VectorXd d(N);
    d.head(n).setConstant(L);
    d.tail(n).setConstant(L * w);
    return d;
  };
  const double max_step = 0.25;  // scaled units: a quarter of the length scale
  FlowRun run;
  bool converged = false;
  // The Newton iterations run with the sensitivities outside the error test (cheap: the steps
  // are the orbit's), and with opt.broyden only when the matrix needs refreshing: in between,
  // flows without sensitivities and Broyden's rank-one secant update of Φ − I. With
  // ShootingFloquet::flow the converged orbit is integrated once more with the sensitivities
  // in the error test, so the monodromy and the multipliers reported have CVODES's error
  // control; with samples or none the converged flow is the last (one with sensitivities,
  // whose Φ gives the Newton correction below) and the monodromy comes from elsewhere.
  bool errcon = opt.sensitivity_error_control;
  bool fresh = true;        // the next flow integrates the sensitivities (a new matrix)
  bool refreshed = false;   // that flow repeats the last point (no stall test against it)
  const Eigen::Index K = autonomous ? N + 1 : N;
  Eigen::MatrixXd Jx;       // scaled Φ − I (N × N), exact or Broyden-updated
  Eigen::VectorXd R_prev, tcol_prev, dz_prev;
  // The state's tolerances of the flows: opt.cvode's, tightened tenfold at a stall (below).
  CvodeOptions flow_opt = opt.cvode;
  int tightenings = 0;
  bool stalled_once = false;  // a stall met the rule below (the message says what was tried)
  double last_cap = 1.0;    // the cap of the step that led to this flow (1: uncapped)
  for (int it = 0; it <= opt.max_iter + 1; ++it) {
    const bool sens = errcon || fresh || !opt.broyden;
    run = run_flow(F, x, in.t0, T, sens, in.n_out, flow_opt, errcon,
                   opt.sensitivity_rtol > 0 ? opt.sensitivity_rtol : opt.cvode.rtol);
    out.iterations = it + 1;
    if (sens) ++out.sensitivity_flows;
    out.steps += run.steps;
    out.rhs_evals += run.rhs_evals;
    out.jac_evals += run.jac_evals;
    out.order_reductions += run.order_reductions;
    out.sens_factorizations += run.sens_factorizations;
    out.sens_linear_solves += run.sens_newton_iters * N;  // Ns = N columns per iteration
    if (run.flag < 0) {
      out.status = F.contact ? "rub" : "not_converged";
      out.message = "shooting iteration " + std::to_string(it) + ": " + run.why;
      break;
    }
    const Eigen::VectorXd D = scale(T);
    const Eigen::VectorXd R = (run.xT - x).cwiseQuotient(D);
    const double res = R.cwiseAbs().maxCoeff();
    out.residuals.push_back(res);
    out.residual = res;
    if (!std::isfinite(res)) {
      out.status = "error";
      out.message = "non-finite state after one period";
      break;
    }
    // Without the flow's final pass (floquet samples or none) a flow under tol with
    // sensitivities is the end (their Φ, outside the error test, gives the Newton correction);
    // one without (Broyden's secant, stale by a step and, for a cycle, by a period) is
    // repeated once with them at the same start.
    const bool final_pass = opt.floquet == ShootingFloquet::flow;
    if (res < opt.tol && !final_pass && !sens && !errcon) {
      fresh = true;
      refreshed = true;
      continue;
    }
    if (res < opt.tol && (errcon || !final_pass)) {
      converged = true;
      // The Newton correction the monodromy gives at the converged point (uncapped, scaled
      // units; error-controlled on the flow route): an estimate of the distance to the true
      // orbit. The residual test alone allows up to tol / |1 − μ| there, which near a Hopf
      // point (the radial multiplier → 1) can exceed the orbit itself.
      Eigen::MatrixXd J = Eigen::MatrixXd::Zero(K, K);
      Eigen::VectorXd b = Eigen::VectorXd::Zero(K);
      J.topLeftCorner(N, N) = D.cwiseInverse().asDiagonal() * run.Phi * D.asDiagonal() -
                              Eigen::MatrixXd::Identity(N, N);
      b.head(N) = -R;
      if (autonomous) {
        const Eigen::VectorXd f0 = vector_field(F, in.t0, x).cwiseQuotient(D);
        J.block(0, N, N, 1) = T * vector_field(F, in.t0 + T, run.xT).cwiseQuotient(D);
        J.block(N, 0, 1, N) = f0.transpose() / std::max(f0.norm(), 1e-300);
      }
      Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
      out.newton_correction = (J.allFinite() && lu.rank() == K)
                                  ? lu.solve(b).head(N).cwiseAbs().maxCoeff()
                                  : std::numeric_limits<double>::infinity();
      break;
    }
    if (res < opt.tol) {
      errcon = true;  // the final pass at the same start
      continue;
    }
    const bool stalled = !refreshed && out.residuals.size() > 1 &&
                         res > 0.5 * out.residuals[out.residuals.size() - 2];
    refreshed = false;
    if (stalled && !sens) {
      // A secant matrix that no longer halves the residual: the same start once more, with
      // the sensitivities (the flow is the same; the matrix is new).
      fresh = true;
      refreshed = true;
      continue;
    }
    // A Newton step with fresh sensitivities that stops halving the residual. Where the
    // residual still fell and the step was not capped, the step was Newton's full linear one
    // and the residual has reached the floor set by the flow's own error. The flow map
    // CVODES computes is x ↦ φ_T(x) + e(x), e its global error, which jumps with the step
    // sequence: measured on the overhung pump (rtol 1e-8, atol 1e-12 m, tol 1e-6) the same
    // start gave scaled residuals 1.38e-6 (column corrector), 1.63e-6 (blocked: other steps)
    // and 2.65e-6 (rtol 1e-10): the flow's error is at tol's level, beyond any Newton matrix. The
    // state's tolerances are tightened tenfold (at most twice, rtol ≥ 1e-13): that lowers the floor
    // and keeps the steps the orbit's. Only then the sensitivities go into the error test (before:
    // at once, which on a flexible rotor resolves the stiff modes the unit-vector columns excite —
    // 73,000 steps for the pump's period against 8,000).
    // A residual that grew, or a capped step, is Newton away from the orbit (the nonlinear
    // phase): the sensitivities go into the error test at once, as before.
    const bool at_floor = stalled && res <= out.residuals[out.residuals.size() - 2] &&
                          last_cap == 1.0;
    // With the flow's final pass (ShootingFloquet::flow) the error-controlled flow is needed
    // anyway: the stall goes straight to it at the given tolerances, as before (on the pump
    // that pass with the state tightened as well had not ended after 6 min CPU, against
    // 3 min 23 s for the whole solve without the tightening).
    if (stalled && !errcon) {
      stalled_once = true;
      if (at_floor && opt.floquet != ShootingFloquet::flow && tightenings < 2 &&
          flow_opt.rtol * 0.1 >= 1e-13) {
        flow_opt.rtol *= 0.1;
        flow_opt.atol_position *= 0.1;
        flow_opt.atol_velocity *= 0.1;
        ++tightenings;
      } else {
        errcon = true;
      }
    }
    if (it >= opt.max_iter) break;
    Eigen::VectorXd tcol;
    if (autonomous) tcol = T * vector_field(F, in.t0 + T, run.xT).cwiseQuotient(D);
    if (sens) {
      Jx = D.cwiseInverse().asDiagonal() * run.Phi * D.asDiagonal() -
           Eigen::MatrixXd::Identity(N, N);
      fresh = false;
    } else {
      // Broyden: Jx += (y − Jx s) sᵀ / sᵀs with s the last step in x and y the change of R
      // less the period column's share.
      const Eigen::VectorXd s_x = dz_prev.head(N);
      Eigen::VectorXd y = R - R_prev;
      if (autonomous) y -= tcol_prev * dz_prev(N);
      const double ss = s_x.squaredNorm();
      if (ss > 0) Jx += (y - Jx * s_x) * (s_x.transpose() / ss);
    }
    // Newton step in scaled coordinates z = D⁻¹ x, τ = ΔT / T.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(K, K);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(K);
    J.topLeftCorner(N, N) = Jx;
    b.head(N) = -R;
    if (autonomous) {
      const Eigen::VectorXd f0 = vector_field(F, in.t0, x).cwiseQuotient(D);
      J.block(0, N, N, 1) = tcol;
      J.block(N, 0, 1, N) = f0.transpose() / std::max(f0.norm(), 1e-300);
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
    if (lu.rank() < K) {
      if (!sens) {  // a degenerate secant matrix: start again from sensitivities
        fresh = true;
        refreshed = true;
        continue;
      }
      out.status = "not_converged";
      out.message = "shooting iteration " + std::to_string(it) +
                    ": singular Newton matrix (a Floquet multiplier at 1, or the start is an "
                    "equilibrium)";
      break;
    }
    Eigen::VectorXd dz = lu.solve(b);
    // The cap: a limit cycle's every coordinate at max_step of L (the rig's published runs);
    // a forced orbit's step by the change of film thickness it makes, positions and
    // velocities / ω (film_step_fraction: only the films are nonlinear in x).
    double big = dz.head(N).cwiseAbs().maxCoeff() / max_step;
    if (!autonomous) {
      Eigen::MatrixXd rows(2, n);
      rows.row(0) = L * dz.head(n).transpose();
      rows.row(1) = L * dz.segment(n, n).transpose();
      big = film_step_fraction(m, rows) / max_step;
    }
    const double big_t = autonomous ? std::abs(dz(N)) / 0.2 : 0.0;
    const double cap = std::max({1.0, big, big_t});
    last_cap = cap;
    dz /= cap;
    x += dz.head(N).cwiseProduct(D);
    if (autonomous) T *= 1.0 + dz(N);
    R_prev = R;
    tcol_prev = tcol;
    dz_prev = dz;
  }
  out.reynolds_solves = solver.reynolds_solves() - solves0;
  out.sens_rhs_evals = F.sens_evals;
  out.flow_tol_factor = std::pow(0.1, tightenings);  // exactly 1, 0.1 or 0.01 (not a ratio)
  out.period = T;
  out.r0 = x.head(n);
  out.v0 = x.tail(n);
  if (!converged) {
    if (out.status == "ok") {
      out.status = "not_converged";
      std::ostringstream os;
      os << "shooting did not converge in " << opt.max_iter << " Newton iterations: residual "
         << out.residual << " (tol " << opt.tol << ")";
      if (stalled_once)
        os << "; the residual stalled with the flows' tolerances tightened "
           << (tightenings ? std::to_string(tightenings) + " time(s) tenfold" : "not at all")
           << (errcon ? " and the sensitivities in the error test" : "")
           << ": its floor may be the integration's error (tighten rtol/atol_m or loosen tol)";
      else
        os << "; the start may not be near a periodic orbit";
      out.message = os.str();
    }
    return out;
  }
  if (autonomous) {
    // An equilibrium is a "periodic orbit" of any period: the Newton iteration can fall onto
    // one from a start off any cycle. Refused: the orbit must move by more than 100 tol.
    const Eigen::VectorXd D = scale(T);
    double extent = 0.0;
    for (Eigen::Index i = 0; i < run.X.rows(); ++i)
      extent = std::max(extent, (run.X.row(i).transpose() - x).cwiseQuotient(D).cwiseAbs().maxCoeff());
    if (extent < 100 * opt.tol) {
      std::ostringstream os;
      os << "shooting converged to an equilibrium (the orbit's extent is " << extent
         << " of the length scale), not a limit cycle: start on or near a cycle";
      out.status = "not_converged";
      out.message = os.str();
      return out;
    }
    // Near a weakly damped equilibrium (a Hopf point: its multipliers ≈ 1) a small orbit about
    // it has a residual below tol without being a cycle — measured on the paper rig 5e-5 Hz
    // from its Hopf speed: "cycles" of 0.04–1.4 nm at the journal where the cycle has 0.24 µm;
    // on a linear rotor with a mode damped to |μ| = 1 − 2e-8, any small orbit along the mode.
    // The Newton correction at the converged point tells: for those it is half the orbit's
    // extent (≤ 1e-3 of it for the cycles found). Refused above 10 %: the orbit is not known
    // to better than that.
    if (!(out.newton_correction <= 0.1 * extent)) {
      std::ostringstream os;
      os << "the orbit is not resolved at tol " << opt.tol << ": the Newton correction at the "
         << "converged point (" << out.newton_correction << " of the length scale) is "
         << out.newton_correction / extent << " of the orbit's extent (" << extent
         << ", > 0.1: not a cycle, or one not resolved); near a Hopf point (a Floquet "
         << "multiplier near 1) tighten tol or use harmonic balance";
      out.status = "not_converged";
      out.message = os.str();
      return out;
    }
  }
  out.t = run.t;
  out.r = run.X.leftCols(n);
  out.v = run.X.rightCols(n);
  if (opt.floquet == ShootingFloquet::none) return out;
  if (opt.floquet == ShootingFloquet::samples) {
    // The orbit's samples from t0: the converged start's flow (run) ends at x(t0 + T).
    Eigen::MatrixXd X = run.X;
    const int max_steps = opt.floquet_max_steps > 0
                              ? opt.floquet_max_steps
                              : 128 * static_cast<int>(std::max<Eigen::Index>(X.rows() - 1, 1));
    const hb_detail::RefinedMonodromy rm = hb_detail::refined_monodromy_of_samples(
        solver, in, F, X, T, autonomous, opt.floquet_tol, max_steps);
    out.reynolds_solves = solver.reynolds_solves() - solves0;
    out.floquet_linearizations = rm.linearizations;
    if (!rm.ok) {
      out.status = rm.contact ? "rub" : "error";  // as harmonic balance's refined product
      out.message = "the orbit converged but its monodromy from the samples failed: " + rm.why +
                    " (floquet='flow' integrates it instead)";
      return out;
    }
    out.monodromy = rm.Phi;
    out.floquet_error = rm.error;
    out.floquet_converged = rm.converged;
    out.floquet_steps = rm.steps;
  } else {
    out.monodromy = run.Phi;
  }
  if (!out.monodromy.allFinite()) {
    out.status = "error";
    out.message = "non-finite monodromy matrix";
    out.monodromy.resize(0, 0);
    return out;
  }
  out.floquet = floquet(out.monodromy, autonomous);
  if (opt.floquet == ShootingFloquet::flow)
    out.monodromy_rtol = opt.sensitivity_rtol > 0 ? opt.sensitivity_rtol : opt.cvode.rtol;
  return out;
}

}  // namespace rotordyn
