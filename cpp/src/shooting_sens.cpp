// The staggered sensitivity corrector of the shooting flows (shooting_detail.hpp,
// blocked_sensitivity_solver): all 2n monodromy columns in one dense solve per iteration.
//
// CVODES's own corrector (SUNNonlinSol_Newton over the sensitivity wrapper) solves the
// sensitivity columns one at a time with the state's dense LU of I − γJ, a Jacobian CVODES
// keeps for up to 20 steps at an older γ: on the overhung pump (72 columns) that was 52 % of
// a shooting solve in SUNDIALS's column-by-column back-substitution (docs/nonlinear.md). The
// sensitivity equations are linear, Ṡ = A(x(t)) S (+ ∂f/∂p for a parameter column), with the
// A the right-hand side has just formed at the corrected state: with the exact matrix
// I − γA one Newton step solves them to round-off. This corrector factors I − γA (LU with
// partial pivoting) once per (state, γ) and solves every column in one blocked
// back-substitution; CVODES's convergence test and error test are used unchanged.
#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <Eigen/LU>
#include <cmath>
#include <exception>
#include <limits>

#include "rotordyn/errors.hpp"
#include "shooting_detail.hpp"

namespace rotordyn::shooting_detail {

namespace {

// CVODES wraps the Ns sensitivity vectors in a "sensitivity wrapper" N_Vector whose header is
// not installed with SUNDIALS; its content's layout (SUNDIALS 6, src/sundials/
// sundials_nvector_senswrapper.h) is redeclared here.
struct SensWrapperContent {
  N_Vector* vecs;
  int nvecs;
  sunbooleantype own_vecs;
};
N_Vector* wrapped(N_Vector v) { return static_cast<SensWrapperContent*>(v->content)->vecs; }
int n_wrapped(N_Vector v) { return static_cast<SensWrapperContent*>(v->content)->nvecs; }

struct Content {
  Flow* F = nullptr;
  void* cvode_mem = nullptr;
  SUNNonlinSolSysFn sys = nullptr;
  SUNNonlinSolConvTestFn ctest = nullptr;
  void* ctest_data = nullptr;
  int maxiters = 3, curiter = 0;
  long niters = 0, nconvfails = 0, factorizations = 0;
  N_Vector delta = nullptr;  // a clone of the corrections' wrapper: residual, then step
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd y_lu;
  double gamma_lu = std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixXd R;
};

Content& content(SUNNonlinearSolver nls) { return *static_cast<Content*>(nls->content); }

SUNNonlinearSolver_Type get_type(SUNNonlinearSolver) { return SUNNONLINEARSOLVER_ROOTFIND; }
int initialize(SUNNonlinearSolver nls) {
  content(nls).niters = content(nls).nconvfails = 0;
  return SUN_NLS_SUCCESS;
}
int setup(SUNNonlinearSolver, N_Vector, void*) { return SUN_NLS_SUCCESS; }
int set_sys(SUNNonlinearSolver nls, SUNNonlinSolSysFn f) {
  content(nls).sys = f;
  return SUN_NLS_SUCCESS;
}
// CVODES's linear-solver wrappers are not used: the matrix is this corrector's own.
int set_lsetup(SUNNonlinearSolver, SUNNonlinSolLSetupFn) { return SUN_NLS_SUCCESS; }
int set_lsolve(SUNNonlinearSolver, SUNNonlinSolLSolveFn) { return SUN_NLS_SUCCESS; }
int set_ctest(SUNNonlinearSolver nls, SUNNonlinSolConvTestFn f, void* data) {
  content(nls).ctest = f;
  content(nls).ctest_data = data;
  return SUN_NLS_SUCCESS;
}
int set_maxiters(SUNNonlinearSolver nls, int m) {
  if (m < 1) return SUN_NLS_ILL_INPUT;
  content(nls).maxiters = m;
  return SUN_NLS_SUCCESS;
}
int get_num_iters(SUNNonlinearSolver nls, long* n) {
  *n = content(nls).niters;
  return SUN_NLS_SUCCESS;
}
int get_cur_iter(SUNNonlinearSolver nls, int* m) {
  *m = content(nls).curiter;
  return SUN_NLS_SUCCESS;
}
int get_num_conv_fails(SUNNonlinearSolver nls, long* n) {
  *n = content(nls).nconvfails;
  return SUN_NLS_SUCCESS;
}

// Newton on the (linear) sensitivity system with the exact matrix I − γA: res = rl1 zS[1] +
// ycor − γ A (zS[0] + ycor) (CVODES's residual), δ = −(I − γA)⁻¹ res, ycor += δ, and CVODES's
// convergence test (which also sets the error-test norm of the corrections).
int solve(SUNNonlinearSolver nls, N_Vector, N_Vector ycor, N_Vector w, sunrealtype tol,
          sunbooleantype, void* mem) {
  Content& c = content(nls);
  try {
    Flow& F = *c.F;
    const Eigen::Index N = F.N;
    const int Ns = n_wrapped(ycor);
    if (!c.delta) c.delta = N_VClone(ycor);
    if (!c.delta) return SUN_NLS_MEM_FAIL;
    c.niters = c.nconvfails = 0;  // per solve: CVODES adds them to its totals
    N_Vector* yc = wrapped(ycor);
    N_Vector* dl = wrapped(c.delta);
    c.R.resize(N, Ns);
    for (c.curiter = 0; c.curiter < c.maxiters; ++c.curiter) {
      const int r = c.sys(ycor, c.delta, mem);  // the sensitivity right-hand side forms A
      if (r != 0) return r;
      ++c.niters;
      double gamma = 0.0;
      if (CVodeGetCurrentGamma(c.cvode_mem, &gamma) != CV_SUCCESS || !F.have_A)
        return SUN_NLS_EXT_FAIL;
      if (!(gamma == c.gamma_lu) || c.y_lu.size() != N || c.y_lu != F.y_A) {
        c.lu.compute(Eigen::MatrixXd::Identity(N, N) - gamma * F.A);
        c.gamma_lu = gamma;
        c.y_lu = F.y_A;
        ++c.factorizations;
      }
      for (int j = 0; j < Ns; ++j)
        c.R.col(j) = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(dl[j]), N);
      c.R = c.lu.solve(c.R);
      if (!c.R.allFinite()) return SUN_NLS_CONV_RECVR;  // CVODES retries with a smaller step
      for (int j = 0; j < Ns; ++j) {
        Eigen::Map<Eigen::VectorXd> d(N_VGetArrayPointer(dl[j]), N);
        d = -c.R.col(j);
        Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(yc[j]), N) += d;
      }
      const int t = c.ctest(nls, ycor, c.delta, tol, w, c.ctest_data);
      if (t == SUN_NLS_SUCCESS) return SUN_NLS_SUCCESS;
      if (t != SUN_NLS_CONTINUE) {
        ++c.nconvfails;
        return t;
      }
    }
    ++c.nconvfails;
    return SUN_NLS_CONV_RECVR;
  } catch (const std::exception& e) {
    c.F->last_error = e.what();
    return SUN_NLS_EXT_FAIL;
  }
}

int free_solver(SUNNonlinearSolver nls) {
  if (!nls) return SUN_NLS_SUCCESS;
  if (nls->content) {
    Content* c = static_cast<Content*>(nls->content);
    if (c->delta) N_VDestroy(c->delta);
    delete c;
    nls->content = nullptr;
  }
  SUNNonlinSolFreeEmpty(nls);
  return SUN_NLS_SUCCESS;
}

}  // namespace

SUNNonlinearSolver blocked_sensitivity_solver(Flow& F, void* cvode_mem, SUNContext ctx) {
#if SUNDIALS_VERSION_MAJOR != 6
  // the wrapper layout redeclared above is SUNDIALS 6's: another version is refused rather
  // than read through a layout that may have changed
  throw InputError(std::string("sensitivity_solve: 'blocked' needs SUNDIALS 6 (this build has ") +
                   SUNDIALS_VERSION + "); use 'columns'");
#endif
  SUNNonlinearSolver nls = SUNNonlinSolNewEmpty(ctx);
  if (!nls) return nullptr;
  auto* c = new Content;
  c->F = &F;
  c->cvode_mem = cvode_mem;
  nls->content = c;
  nls->ops->gettype = get_type;
  nls->ops->initialize = initialize;
  nls->ops->setup = setup;
  nls->ops->solve = solve;
  nls->ops->free = free_solver;
  nls->ops->setsysfn = set_sys;
  nls->ops->setlsetupfn = set_lsetup;
  nls->ops->setlsolvefn = set_lsolve;
  nls->ops->setctestfn = set_ctest;
  nls->ops->setmaxiters = set_maxiters;
  nls->ops->getnumiters = get_num_iters;
  nls->ops->getcuriter = get_cur_iter;
  nls->ops->getnumconvfails = get_num_conv_fails;
  return nls;
}

long blocked_sensitivity_factorizations(SUNNonlinearSolver nls) {
  return nls && nls->content ? content(nls).factorizations : 0;
}

}  // namespace rotordyn::shooting_detail
