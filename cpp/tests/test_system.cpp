// System core: a mass on one film must reach the single-bearing solver's equilibrium; the
// perturbation K_H must match central differences; Newton and successive substitution agree.
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/system.hpp"
#include "system_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
SystemModel one_film(double k_struct) {
  JournalBearingGeometry g;
  g.diameter_m = 0.05;
  g.length_m = 0.04;
  g.clearance_m = 3e-4;
  g.viscosity_pa_s = 0.04;
  FilmGrid grid{48, 12};
  SystemModel m;
  m.M = Eigen::Matrix2d::Identity() * 10.0;
  m.K = Eigen::Matrix2d::Identity() * k_struct;
  m.C = Eigen::Matrix2d::Zero();
  m.G = Eigen::Matrix2d::Zero();
  m.Q = Eigen::Vector2d(0.0, -500.0);
  m.chamber = Eigen::Vector2d::Zero();
  m.films = {rdtest::journal_film(g, grid, Cavitation::reynolds)};
  return m;
}
}  // namespace

TEST_CASE("system: one film carrying a weight equals the bearing's own equilibrium") {
  SystemModel m = one_film(0.0);
  SystemSolver s(m);
  const double w = 2 * M_PI * 50;
  const EquilibriumResult e =
      s.equilibrium(w, 0.0, Eigen::Vector2d::Zero(), Eigen::VectorXd(), EquilibriumOptions{});
  CHECK(e.status == "ok");
  ReynoldsSolver rs(m.films[0].geometry, m.films[0].grid, Cavitation::reynolds);
  const EquilibriumSolution ref = rs.equilibrium(0.0, -500.0, w);
  CHECK_CLOSE(e.r(0), ref.x_m, 0, 1e-12);
  CHECK_CLOSE(e.r(1), ref.y_m, 0, 1e-12);
  CHECK(e.residual < 1e-10);
}

TEST_CASE("system: perturbation K_H, D_H equal central finite differences") {
  SystemSolver s(one_film(0.0));
  const Eigen::Vector2d r(1e-4, -1.2e-4);
  const double w = 2 * M_PI * 50;
  const Linearization a = s.linearize(r, Eigen::Vector2d::Zero(), w);
  const Linearization b = s.linearize_fd(r, w, 1e-5);
  CHECK((a.KH - b.KH).norm() < 1e-5 * a.KH.norm());
  CHECK((a.DH - b.DH).norm() < 1e-5 * a.DH.norm());
}

TEST_CASE("system: Newton and successive substitution (automatic P_m) agree") {
  SystemSolver s(one_film(2e6));
  const double w = 2 * M_PI * 50;
  const Eigen::Vector2d a(0.0, -2e-4);
  EquilibriumOptions on;
  EquilibriumOptions os;
  os.method = EquilibriumMethod::Successive;
  const EquilibriumResult en = s.equilibrium(w, 0.0, a, Eigen::VectorXd(), on);
  const EquilibriumResult es = s.equilibrium(w, 0.0, a, Eigen::VectorXd(), os);
  CHECK(en.status == "ok" && es.status == "ok");
  CHECK((en.r - es.r).cwiseAbs().maxCoeff() < 1e-9 * 3e-4);
  CHECK(es.pm > 0);
}

TEST_CASE("system: failed and contact equilibria are told apart, bad shapes raise InputError") {
  SystemSolver s(one_film(1e7));
  EquilibriumOptions o;
  // A housing 50 mm off: no equilibrium with an open film. The failed solve is
  // "no_equilibrium", never the converged status "contact" (issue 13).
  const EquilibriumResult e =
      s.equilibrium(2 * M_PI * 5, 0.0, Eigen::Vector2d(0, 0.05), Eigen::VectorXd(), o);
  if (e.status != "no_equilibrium") throw rdtest::Failure("status " + e.status + ": " + e.message);
  CHECK(!(e.residual < o.tol));
  // A converged equilibrium whose film is below contact_fraction c is "contact".
  EquilibriumOptions oc;
  oc.contact_fraction = 0.999;
  const EquilibriumResult ec =
      s.equilibrium(2 * M_PI * 50, 0.0, Eigen::Vector2d(0, 0), Eigen::VectorXd(), oc);
  if (ec.status != "contact") throw rdtest::Failure("status " + ec.status + ": " + ec.message);
  CHECK(ec.residual < oc.tol);
  CHECK_THROWS(s.film_forces(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1.0), InputError);
  CHECK_THROWS(s.film_forces(Eigen::Vector2d(0, -4e-4), Eigen::Vector2d::Zero(), 1.0),
               ContactError);
}

namespace {
/// one_film with the journal's rotations as coordinates 2, 3 (rdtest::tilting_journal_film).
SystemModel tilting_film() {
  SystemModel m = one_film(0.0);
  m.films[0] = rdtest::tilting_journal_film(m.films[0].geometry, m.films[0].grid,
                                            Cavitation::reynolds);
  m.M = Eigen::Matrix4d::Identity();
  m.K = m.C = m.G = Eigen::Matrix4d::Zero();
  m.Q = m.chamber = Eigen::Vector4d::Zero();
  return m;
}
}  // namespace

TEST_CASE("system: a tilting film at zero tilt is the untilted film bit for bit") {
  SystemSolver a(one_film(0.0)), b(tilting_film());
  const double w = 2 * M_PI * 50;
  const Eigen::Vector2d r(1e-4, -1.2e-4), v(1e-3, 2e-3);
  const Eigen::Vector4d r4(1e-4, -1.2e-4, 0, 0), v4(1e-3, 2e-3, 0, 0);
  const Linearization la = a.linearize(r, v, w);
  const Linearization lb = b.linearize(r4, v4, w);
  CHECK(la.film_force == lb.film_force.head<2>());
  CHECK(la.KH == lb.KH.topLeftCorner<2, 2>());
  CHECK(la.DH == lb.DH.topLeftCorner<2, 2>());
  CHECK(a.last_pressure(0) == b.last_pressure(0));
}

TEST_CASE("system: opposite tilts mirror each other; tilt K_H equals differences") {
  SystemSolver s(tilting_film());
  const double w = 2 * M_PI * 50, c = 3e-4, L = 0.04;
  const Eigen::Vector4d rp(1e-4, -1.2e-4, 0.1 * c / L, -0.2 * c / L);
  Eigen::Vector4d rm = rp;
  rm.tail<2>() *= -1.0;
  const Eigen::Vector4d z = Eigen::Vector4d::Zero();
  const Eigen::VectorXd hp = s.film_forces(rp, z, w);
  const double zp = s.last_h_min_z_m()[0];
  const Eigen::VectorXd hm = s.film_forces(rm, z, w);
  const double zm = s.last_h_min_z_m()[0];
  const double fs = hp.head<2>().norm(), ms = hp.tail<2>().norm();
  CHECK(ms > 0);
  CHECK((hp.head<2>() - hm.head<2>()).norm() < 1e-11 * fs);
  CHECK((hp.tail<2>() + hm.tail<2>()).norm() < 1e-11 * ms);
  CHECK(std::abs(zp) == 0.5 * L && zm == -zp);  // the edge film at opposite edges
  const Linearization a = s.linearize(rp, z, w);
  const Linearization b = s.linearize_fd(rp, w, 1e-6);
  CHECK((a.KH - b.KH).bottomRightCorner<2, 2>().norm() <
        1e-4 * b.KH.bottomRightCorner<2, 2>().norm());
  CHECK((a.DH - b.DH).bottomRightCorner<2, 2>().norm() <
        1e-4 * b.DH.bottomRightCorner<2, 2>().norm());
}

TEST_CASE("system: rotating damping's Kc enters H as −Ω Kc r and K_H as Ω Kc") {
  // a film plus a shaft spring k with a circulatory Kc = c_i [[0, 1], [−1, 0]] (per rad/s)
  const double ci = 300.0, w = 2 * M_PI * 50;
  SystemModel m0 = one_film(2e6), m1 = m0;
  m1.Kc = (Eigen::Matrix2d() << 0.0, ci, -ci, 0.0).finished();
  SystemSolver s0(m0), s1(m1);
  const Eigen::Vector2d r(1e-4, -1.2e-4), z = Eigen::Vector2d::Zero();
  const Eigen::VectorXd d = s1.film_forces(r, z, w) - s0.film_forces(r, z, w);
  CHECK((d + w * m1.Kc * r).cwiseAbs().maxCoeff() < 1e-12 * (w * m1.Kc * r).norm());
  const Linearization a0 = s0.linearize(r, z, w), a1 = s1.linearize(r, z, w);
  CHECK((a1.KH - a0.KH - w * m1.Kc).cwiseAbs().maxCoeff() < 1e-9 * a0.KH.norm());
  CHECK((a1.DH - a0.DH).cwiseAbs().maxCoeff() == 0.0);
  // the equilibrium: K r + Ω Kc r = H_films + Q, its film_force the film's own
  const EquilibriumResult e =
      s1.equilibrium(w, 0.0, Eigen::Vector2d::Zero(), Eigen::VectorXd(), EquilibriumOptions{});
  CHECK(e.status == "ok");
  const Eigen::VectorXd own = s0.film_forces(e.r, z, w);
  CHECK((e.film_force - own).cwiseAbs().maxCoeff() < 1e-12 * 500.0);
  CHECK((m1.K * e.r + w * m1.Kc * e.r - own - m1.Q).cwiseAbs().maxCoeff() < 1e-8 * 500.0);
  SystemModel bad = m0;
  bad.Kc = Eigen::Matrix3d::Zero();
  CHECK_THROWS((void)SystemSolver(bad), InputError);
}
