// CVODE integration of the nonlinear system (paper eq. 12). One SUNContext, CVODE memory and
// dense linear solver per call: nothing global, so threads and processes can run it at once.
#include "rotordyn/transient.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <sstream>

#include "rotordyn/errors.hpp"

namespace rotordyn {

std::string cvode_flag_name(int flag) {
  switch (flag) {
    case CV_SUCCESS: return "CV_SUCCESS";
    case CV_TSTOP_RETURN: return "CV_TSTOP_RETURN";
    case CV_ROOT_RETURN: return "CV_ROOT_RETURN";
    case CV_WARNING: return "CV_WARNING";
    case CV_TOO_MUCH_WORK: return "CV_TOO_MUCH_WORK (max_steps reached)";
    case CV_TOO_MUCH_ACC: return "CV_TOO_MUCH_ACC (tolerances too tight)";
    case CV_ERR_FAILURE: return "CV_ERR_FAILURE (repeated error-test failures)";
    case CV_CONV_FAILURE: return "CV_CONV_FAILURE (repeated Newton convergence failures)";
    case CV_LINIT_FAIL: return "CV_LINIT_FAIL";
    case CV_LSETUP_FAIL: return "CV_LSETUP_FAIL (Jacobian setup failed)";
    case CV_LSOLVE_FAIL: return "CV_LSOLVE_FAIL";
    case CV_RHSFUNC_FAIL: return "CV_RHSFUNC_FAIL (right-hand side failed)";
    case CV_FIRST_RHSFUNC_ERR: return "CV_FIRST_RHSFUNC_ERR";
    case CV_REPTD_RHSFUNC_ERR: return "CV_REPTD_RHSFUNC_ERR (film contact on repeated tries)";
    case CV_UNREC_RHSFUNC_ERR: return "CV_UNREC_RHSFUNC_ERR";
    case CV_MEM_FAIL: return "CV_MEM_FAIL";
    case CV_MEM_NULL: return "CV_MEM_NULL";
    case CV_ILL_INPUT: return "CV_ILL_INPUT";
    case CV_NO_MALLOC: return "CV_NO_MALLOC";
    case CV_BAD_K: return "CV_BAD_K";
    case CV_BAD_T: return "CV_BAD_T";
    case CV_BAD_DKY: return "CV_BAD_DKY";
    case CV_TOO_CLOSE: return "CV_TOO_CLOSE";
    default: return "CVODE flag " + std::to_string(flag);
  }
}

namespace {

struct Ctx {
  SystemSolver* solver;
  const TransientInput* in;
  Eigen::Index n;
  Eigen::LLT<Eigen::MatrixXd> Mllt;
  Eigen::MatrixXd D0;  // C + Ω G
  Eigen::VectorXd Fconst;  // Q + p_c c_s − K a
  std::string last_error;
  bool contact = false;
  std::string cvode_message;
};

Eigen::VectorXd forcing(const Ctx& c, double t) {
  Eigen::VectorXd f = c.Fconst;
  const double w = c.in->omega;
  if (c.in->unbalance_cos.size())
    f += w * w * (std::cos(w * t) * c.in->unbalance_cos + std::sin(w * t) * c.in->unbalance_sin);
  return f;
}

int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  Ctx& c = *static_cast<Ctx*>(user);
  const Eigen::Index n = c.n;
  Eigen::Map<const Eigen::VectorXd> Y(N_VGetArrayPointer(y), 2 * n);
  Eigen::Map<Eigen::VectorXd> Yd(N_VGetArrayPointer(ydot), 2 * n);
  try {
    const Eigen::VectorXd r = Y.head(n), v = Y.tail(n);
    const Eigen::VectorXd H = c.solver->film_forces(r, v, c.in->omega);
    const Eigen::VectorXd rhs_f =
        H + forcing(c, t) - c.solver->model().K * r - c.D0 * v;
    Yd.head(n) = v;
    Yd.tail(n) = c.Mllt.solve(rhs_f);
    return 0;
  } catch (const ContactError& e) {
    c.contact = true;
    c.last_error = e.what();
    return 1;  // recoverable: CVODE retries with a smaller step
  } catch (const std::exception& e) {
    c.last_error = e.what();
    return -1;
  }
}

int jac(sunrealtype, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector,
        N_Vector) {
  Ctx& c = *static_cast<Ctx*>(user);
  const Eigen::Index n = c.n;
  Eigen::Map<const Eigen::VectorXd> Y(N_VGetArrayPointer(y), 2 * n);
  try {
    const Linearization lin = c.solver->linearize(Y.head(n), Y.tail(n), c.in->omega);
    const Eigen::MatrixXd A21 = -c.Mllt.solve(c.solver->model().K + lin.KH);
    const Eigen::MatrixXd A22 = -c.Mllt.solve(c.D0 + lin.DH);
    // SUNDenseMatrix is column-major.
    sunrealtype* data = SUNDenseMatrix_Data(J);
    const Eigen::Index N = 2 * n;
    Eigen::Map<Eigen::MatrixXd> Jm(data, N, N);
    Jm.setZero();
    Jm.topRightCorner(n, n).setIdentity();
    Jm.bottomLeftCorner(n, n) = A21;
    Jm.bottomRightCorner(n, n) = A22;
    return 0;
  } catch (const ContactError& e) {
    c.contact = true;
    c.last_error = e.what();
    return 1;
  } catch (const std::exception& e) {
    c.last_error = e.what();
    return -1;
  }
}

void err_handler(int error_code, const char* module, const char* function, char* msg,
                 void* user) {
  Ctx& c = *static_cast<Ctx*>(user);
  std::ostringstream os;
  os << module << "." << function << " (" << cvode_flag_name(error_code) << "): " << msg;
  c.cvode_message = os.str();  // stored, never printed or aborted
}

struct SunDeleter {
  void operator()(SUNContext* p) const {
    if (p && *p) SUNContext_Free(p);
    delete p;
  }
};

}  // namespace

TransientResult integrate(SystemSolver& solver, const TransientInput& in,
                          const CvodeOptions& opt) {
  const SystemModel& m = solver.model();
  const Eigen::Index n = m.n();
  auto vec_ok = [&](const Eigen::VectorXd& v, const char* name, bool allow_empty) {
    require((allow_empty && v.size() == 0) || v.size() == n, shape_msg(name, n, 1, v.size(), 1));
    require(v.allFinite(), std::string(name) + ": expected finite values");
  };
  vec_ok(in.a, "a", false);
  vec_ok(in.r0, "r0", false);
  vec_ok(in.v0, "v0", false);
  vec_ok(in.unbalance_cos, "unbalance_cos", true);
  vec_ok(in.unbalance_sin, "unbalance_sin", in.unbalance_cos.size() == 0);
  require(in.t_out.size() > 0 && in.t_out.allFinite() && in.t_out(0) >= 0,
          "t_out: expected a non-empty array of times >= 0");
  for (Eigen::Index i = 1; i < in.t_out.size(); ++i)
    require(in.t_out(i) > in.t_out(i - 1), "t_out: expected strictly increasing times");
  require(opt.rtol > 0 && opt.rtol < 1 && opt.atol_position > 0 && opt.atol_velocity > 0,
          "cvode options: tolerances must be positive");
  require(opt.max_steps > 0, "cvode options: max_steps must be positive");

  Ctx c;
  c.solver = &solver;
  c.in = &in;
  c.n = n;
  c.Mllt.compute(m.M);
  require(c.Mllt.info() == Eigen::Success, "M: the mass matrix must be positive definite");
  c.D0 = m.C + in.omega * m.G;
  c.Fconst = m.Q + in.chamber_pressure * m.chamber - m.K * in.a;

  TransientResult out;
  const Eigen::Index nt = in.t_out.size();
  out.t = Eigen::VectorXd::Constant(nt, NAN);
  out.r = Eigen::MatrixXd::Constant(nt, n, NAN);
  out.v = Eigen::MatrixXd::Constant(nt, n, NAN);
  out.h_min = Eigen::MatrixXd::Constant(nt, static_cast<Eigen::Index>(m.films.size()), NAN);

  std::unique_ptr<SUNContext, SunDeleter> sunctx(new SUNContext(nullptr));
  if (SUNContext_Create(nullptr, sunctx.get()) != 0)
    throw SundialsError(-1, "SUNContext_Create", "could not create a SUNDIALS context");
  SUNContext ctx = *sunctx;
  const sunindextype N = static_cast<sunindextype>(2 * n);
  N_Vector y = N_VNew_Serial(N, ctx);
  N_Vector abstol = N_VNew_Serial(N, ctx);
  SUNMatrix A = SUNDenseMatrix(N, N, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  void* mem = CVodeCreate(CV_BDF, ctx);
  auto cleanup = [&]() {
    CVodeFree(&mem);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(abstol);
    N_VDestroy(y);
  };
  auto check = [&](int flag, const char* where) {
    if (flag < 0) {
      const std::string msg = cvode_flag_name(flag) + (c.cvode_message.empty() ? "" : ": " + c.cvode_message);
      cleanup();
      throw SundialsError(flag, where, msg);
    }
  };
  Eigen::Map<Eigen::VectorXd> Y(N_VGetArrayPointer(y), N);
  Y.head(n) = in.r0;
  Y.tail(n) = in.v0;
  Eigen::Map<Eigen::VectorXd> AT(N_VGetArrayPointer(abstol), N);
  AT.head(n).setConstant(opt.atol_position);
  AT.tail(n).setConstant(opt.atol_velocity);

  check(CVodeSetErrHandlerFn(mem, err_handler, &c), "CVodeSetErrHandlerFn");
  check(CVodeInit(mem, rhs, 0.0, y), "CVodeInit");
  check(CVodeSetUserData(mem, &c), "CVodeSetUserData");
  check(CVodeSVtolerances(mem, opt.rtol, abstol), "CVodeSVtolerances");
  check(CVodeSetLinearSolver(mem, LS, A), "CVodeSetLinearSolver");
  if (opt.analytic_jacobian) check(CVodeSetJacFn(mem, jac), "CVodeSetJacFn");
  check(CVodeSetMaxNumSteps(mem, opt.max_steps), "CVodeSetMaxNumSteps");
  if (opt.max_step > 0) check(CVodeSetMaxStep(mem, opt.max_step), "CVodeSetMaxStep");
  check(CVodeSetStopTime(mem, in.t_out(nt - 1)), "CVodeSetStopTime");

  double t = 0.0;
  for (Eigen::Index i = 0; i < nt; ++i) {
    int flag = CV_SUCCESS;
    if (in.t_out(i) > t) flag = CVode(mem, in.t_out(i), y, &t, CV_NORMAL);
    if (flag < 0) {
      out.status = c.contact ? "contact" : "not_converged";
      out.message = cvode_flag_name(flag) + " at t = " + std::to_string(t) + " s" +
                    (c.last_error.empty() ? "" : ": " + c.last_error) +
                    (c.cvode_message.empty() ? "" : " [" + c.cvode_message + "]");
      break;
    }
    out.t(i) = in.t_out(i);
    out.r.row(i) = Y.head(n).transpose();
    out.v.row(i) = Y.tail(n).transpose();
    // The film thickness needs no pressure: from the geometry, not a Reynolds solve.
    const std::vector<double> hm = solver.film_h_min(Y.head(n));
    for (std::size_t k = 0; k < hm.size(); ++k) out.h_min(i, static_cast<Eigen::Index>(k)) = hm[k];
  }
  long v = 0;
  CVodeGetNumSteps(mem, &v);
  out.steps = v;
  CVodeGetNumRhsEvals(mem, &v);
  out.rhs_evals = v;
  CVodeGetNumJacEvals(mem, &v);
  out.jac_evals = v;
  CVodeGetNumNonlinSolvConvFails(mem, &v);
  out.newton_fails = v;
  CVodeGetNumErrTestFails(mem, &v);
  out.error_test_fails = v;
  cleanup();
  return out;
}

}  // namespace rotordyn
