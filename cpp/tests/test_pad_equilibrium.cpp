// Pad-assembly equilibrium (pad_equilibrium.cpp) on a single tilting pad built here as the
// Python element does (_film.py: the pad's arc on m intervals of a core grid of m + 2 nodes
// whose other nodes are a groove at supply pressure): the pad is solved on its loaded
// branch, its moment and the journal's force balance vanish to round-off, the tilt is
// restoring, and a start on the pressure-free side (fully divergent film) reaches the same
// equilibrium.
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/system.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
// One pad of arc β with its pivot at ψ = 270° (under a downward load), preload 0.3, centre
// pivot. Coordinates: journal x, y, then the pad's η (tangential offset of the journal
// relative to the tilted pad, m); a spring on x holds the journal sideways (a single pad
// has no x stiffness of its own once its moment vanishes).
SystemModel one_pad(double load_n) {
  const double D = 0.05, Cb = 1e-4, preload = 0.3, beta = 100.0 * M_PI / 180.0;
  const double psi = 1.5 * M_PI, start = psi - 0.5 * beta;
  const int n_circ = 144;
  const int m = static_cast<int>(std::lround(n_circ * beta / (2 * M_PI)));
  const int N = m + 2;
  const double s = beta * N / (2 * M_PI * m);
  const double Cp = Cb / (1 - preload);
  FilmCoupling f;
  f.name = "pad";
  f.geometry.diameter_m = D * s;
  f.geometry.length_m = 0.025;
  f.geometry.clearance_m = Cb;
  f.geometry.viscosity_pa_s = 0.02;
  const double dc = 360.0 / N;
  f.geometry.grooves = {Groove{0.5 * (m + N) * dc, (N - m) * dc, 0.0}};
  f.grid = FilmGrid{N, 8};
  f.cavitation = Cavitation::reynolds;
  f.coords = {0, 1, 2};
  f.shape = RowMatrixXd::Zero(N, 3);
  f.base_h = RowMatrixXd::Constant(N, 1, 4.0 * Cp);
  for (int j = 0; j <= m; ++j) {
    const double th = start + s * 2 * M_PI * j / N - psi;
    f.base_h(j, 0) = Cp - (Cp - Cb) * std::cos(th);
    f.shape(j, 0) = -std::cos(th) * std::cos(psi);
    f.shape(j, 1) = -std::cos(th) * std::sin(psi);
    f.shape(j, 2) = -std::sin(th);
  }
  f.spin_factor = 1.0 / s;
  SystemModel mod;
  mod.M = Eigen::Matrix3d::Identity();
  mod.K = Eigen::Matrix3d::Zero();
  mod.K(0, 0) = 1e7;
  mod.C = Eigen::Matrix3d::Zero();
  mod.G = Eigen::Matrix3d::Zero();
  mod.Q = Eigen::Vector3d(0.0, -load_n, 0.0);
  mod.chamber = Eigen::Vector3d::Zero();
  mod.films = {f};
  mod.pad_coords = {{2}};
  return mod;
}
}  // namespace

TEST_CASE("pad assembly: one pad balanced on its loaded branch, from any start") {
  const SystemModel mod = one_pad(300.0);
  SystemSolver s(mod);
  const double w = 2 * M_PI * 40;
  EquilibriumOptions opt;
  opt.polish = true;
  const EquilibriumResult e = s.equilibrium(w, 0.0, Eigen::Vector3d::Zero(), Eigen::VectorXd(), opt);
  CHECK(e.status == "ok");
  CHECK(e.path == "pad_assembly");
  CHECK(e.unloaded_pads == 0);
  const Eigen::VectorXd H = s.film_forces(e.r, Eigen::Vector3d::Zero(), w);
  const Eigen::VectorXd R = mod.K * e.r - H - mod.Q;
  CHECK(std::abs(R(1)) < 1e-11 * 300.0);  // journal force balance
  CHECK(std::abs(R(2)) < 1e-11 * 300.0);  // pad moment (over the lever)
  CHECK(s.last_pressure(0).maxCoeff() > 0.0);
  const Linearization lin = s.linearize(e.r, Eigen::Vector3d::Zero(), w);
  CHECK(lin.KH(2, 2) > 0.0);  // restoring tilt stiffness
  CHECK(lin.KH(1, 1) > 0.0);
  // a start with the pad tilted onto its pressure-free side (the film diverging everywhere)
  // and the journal elsewhere: the same root
  for (const double eta : {-0.9e-4, 0.9e-4}) {
    SystemSolver s2(mod);
    const EquilibriumResult e2 =
        s2.equilibrium(w, 0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 2e-5, eta), opt);
    CHECK(e2.status == "ok");
    CHECK(e2.path == "pad_assembly");
    for (int k = 0; k < 3; ++k) CHECK_CLOSE(e2.r(k), e.r(k), 0, 1e-12 * 1e-4);
  }
}

TEST_CASE("pad assembly: pad coordinates are validated") {
  SystemModel mod = one_pad(300.0);
  mod.pad_coords = {{2, 2}};
  CHECK_THROWS(SystemSolver{mod}, InputError);
  mod.pad_coords = {{2, 1}};  // a "pivot" without stiffness
  CHECK_THROWS(SystemSolver{mod}, InputError);
  mod.pad_coords = {{5}};
  CHECK_THROWS(SystemSolver{mod}, InputError);
  mod.pad_coords = {{2}};
  mod.pad_pitch = {1};  // a pitch needs the pad's tilt before it
  CHECK_THROWS(SystemSolver{mod}, InputError);
  mod.pad_pitch = {0, 0};  // one flag per pad group
  CHECK_THROWS(SystemSolver{mod}, InputError);
  mod.pad_pitch = {0};
  SystemSolver ok{mod};  // no pitch flagged: valid
}
