// The harmonic-balance residual's Jacobian (hb_detail::Problem::eval: the AFT residual of
// eq. 12 and its z and ω derivatives from the films' perturbation-method K_H, D_H at the
// samples) against central differences of the residual, on a mass carried by one full
// (Sommerfeld, smooth) film under unbalance: every Newton step of harmonic_balance and of the
// branch correctors relies on it, and a wrong entry would only slow their convergence.
// Tolerance 1e-9 (z), 1e-10 (ω) of the difference's largest entry; measured 1e-11 .. 4e-11
// (z), 1.5e-12 (ω).
#include <cmath>
#include <random>

#include "../src/hb_detail.hpp"  // private: the AFT problem, tested directly
#include "../src/shooting_detail.hpp"
#include "rotordyn/system.hpp"
#include "system_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {

constexpr double kC = 1e-4;  // radial clearance, m

SystemModel mass_on_film() {
  JournalBearingGeometry g;
  g.diameter_m = 0.05;
  g.length_m = 0.03;
  g.clearance_m = kC;
  g.viscosity_pa_s = 0.02;
  FilmGrid grid{36, 8};
  SystemModel m;
  m.M = Eigen::Matrix2d::Identity() * 5.0;
  m.K = Eigen::Matrix2d::Identity() * 1e5;
  m.C = Eigen::Matrix2d::Identity() * 50.0;
  m.G = Eigen::Matrix2d::Zero();
  m.Q = Eigen::Vector2d(0.0, -200.0);
  m.chamber = Eigen::Vector2d::Zero();
  m.films = {rdtest::journal_film(g, grid, Cavitation::none)};
  return m;
}

}  // namespace

TEST_CASE("hb residual: its z and frequency derivatives equal central differences (film)") {
  SystemSolver solver(mass_on_film());
  const double omega = 2 * M_PI * 40.0;
  PeriodicInput in;
  in.kind = OrbitKind::forced;
  in.omega = omega;
  in.a = Eigen::VectorXd::Zero(2);
  in.unbalance_cos = Eigen::Vector2d(2e-6, 0.0);
  in.unbalance_sin = Eigen::Vector2d(0.0, 2e-6);
  in.period = 2 * M_PI / omega;
  in.n_out = 9;
  shooting_detail::Flow F;
  shooting_detail::setup_flow(F, solver, in);
  hb_detail::Problem P;
  P.solver = &solver;
  P.in = &in;
  P.F = &F;
  const int H = 3;
  P.B = hb_detail::make_basis(H, 16);
  P.n = F.n;
  const int nb = 2 * H + 1;
  // an orbit about an off-centre point (ε ≈ 0.3) with a 1x circle of 0.15 c and small 2x, 3x
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(nb, 2);
  Z(0, 0) = 0.1 * kC;
  Z(0, 1) = -0.28 * kC;
  Z(1, 0) = 0.15 * kC;
  Z(2, 1) = 0.15 * kC;
  Z(3, 0) = 0.02 * kC;
  Z(6, 1) = -0.01 * kC;
  const hb_detail::Eval e = P.eval(Z, omega, true);
  CHECK(e.ok);
  CHECK(e.J.rows() == nb * 2 && e.J.cols() == nb * 2);
  // along three random directions of size 1e-3 c per coefficient, step h = 1e-3 of it
  std::mt19937 gen(7);
  std::normal_distribution<double> nd;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::MatrixXd D(nb, 2);
    for (int r = 0; r < nb; ++r)
      for (int c = 0; c < 2; ++c) D(r, c) = nd(gen) * 1e-3 * kC;
    Eigen::VectorXd d(nb * 2);  // the Jacobian's column order: harmonic row p, block of n
    for (int p = 0; p < nb; ++p) d.segment(2 * p, 2) = D.row(p).transpose();
    const double h = 1e-3;
    const hb_detail::Eval ep = P.eval(Z + h * D, omega, false);
    const hb_detail::Eval em = P.eval(Z - h * D, omega, false);
    CHECK(ep.ok);
    CHECK(em.ok);
    const Eigen::VectorXd fd = (ep.R - em.R) / (2 * h);
    const Eigen::VectorXd jd = e.J * d;
    CHECK(fd.cwiseAbs().maxCoeff() > 0.0);
    CHECK((jd - fd).cwiseAbs().maxCoeff() <= 1e-9 * fd.cwiseAbs().maxCoeff());
  }
  // the ω column, used by autonomous orbits (a forced orbit's ω is 2π/period, its forcing's
  // phase at the samples moves with ω, and dR/dω is not used): the same orbit, no unbalance
  PeriodicInput ain = in;
  ain.kind = OrbitKind::autonomous;
  ain.unbalance_cos.resize(0);
  ain.unbalance_sin.resize(0);
  shooting_detail::Flow Fa;
  shooting_detail::setup_flow(Fa, solver, ain);
  hb_detail::Problem A = P;
  A.in = &ain;
  A.F = &Fa;
  const hb_detail::Eval ea = A.eval(Z, omega, true);
  CHECK(ea.ok);
  const double hw = 1e-4 * omega;
  const hb_detail::Eval wp = A.eval(Z, omega + hw, false);
  const hb_detail::Eval wm = A.eval(Z, omega - hw, false);
  CHECK(wp.ok);
  CHECK(wm.ok);
  const Eigen::VectorXd fdw = (wp.R - wm.R) / (2 * hw);
  CHECK(fdw.cwiseAbs().maxCoeff() > 0.0);
  CHECK((ea.dRdw - fdw).cwiseAbs().maxCoeff() <= 1e-10 * fdw.cwiseAbs().maxCoeff());
}
