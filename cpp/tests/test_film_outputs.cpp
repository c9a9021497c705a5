// Film outputs beside the state (issue 20): the transient's recorded film forces and moments
// (TransientInput::record_film_force) and stability_batch's film force and h_min z at each
// equilibrium, on a rigid journal whose film tilts with it (rdtest::tilting_journal_film),
// its housing misaligned: each output equals the film evaluated directly, on a fresh
// solver, at the state the run reports (1e-12 relative: the same film solve, its cavitation
// set reached from another start), and a failed point's outputs are NaN.
#include <cmath>

#include "rotordyn/batch.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/transient.hpp"
#include "system_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
constexpr double kC = 3e-4, kL = 0.04;

/// A 10 kg rigid journal (rotary inertia 0.01 kg m²) on one tilting film (D 50 mm, L 40 mm,
/// c 0.3 mm, 0.04 Pa s, 48 × 12), its rotations held by a 2000 N m/rad spring, 500 N down.
SystemModel journal_on_tilting_film() {
  JournalBearingGeometry g;
  g.diameter_m = 0.05;
  g.length_m = kL;
  g.clearance_m = kC;
  g.viscosity_pa_s = 0.04;
  SystemModel m;
  m.M = Eigen::Vector4d(10.0, 10.0, 0.01, 0.01).asDiagonal();
  m.K = Eigen::Vector4d(0.0, 0.0, 2e3, 2e3).asDiagonal();
  m.C = m.G = Eigen::Matrix4d::Zero();
  m.Q = Eigen::Vector4d(0.0, -500.0, 0.0, 0.0);
  m.chamber = Eigen::Vector4d::Zero();
  m.films = {rdtest::tilting_journal_film(g, FilmGrid{48, 12}, Cavitation::reynolds)};
  return m;
}

/// The housing misaligned by (0.2, −0.3) c/L about x, y: the configuration at the rotations.
Eigen::Vector4d misalignment() { return Eigen::Vector4d(0.0, 0.0, 0.2 * kC / kL, -0.3 * kC / kL); }

/// |got − want| per block (forces 0, 1; moments 2, 3) within rtol of the block's size.
void check_blocks(const Eigen::VectorXd& got, const Eigen::VectorXd& want, double rtol) {
  const double fs = want.head<2>().norm(), ms = want.tail<2>().norm();
  CHECK(fs > 0 && ms > 0);
  CHECK_CLOSE((got.head<2>() - want.head<2>()).norm(), 0.0, 0.0, rtol * fs);
  CHECK_CLOSE((got.tail<2>() - want.tail<2>()).norm(), 0.0, 0.0, rtol * ms);
}
}  // namespace

TEST_CASE("transient: recorded film forces and moments equal the film at each output state") {
  const SystemModel m = journal_on_tilting_film();
  const double w = 2 * M_PI * 50;
  TransientInput in;
  in.omega = w;
  in.a = misalignment();
  in.r0 = Eigen::Vector4d(0.2 * kC, -0.5 * kC, -0.1 * kC / kL, 0.15 * kC / kL);
  in.v0 = Eigen::Vector4d(0.01, -0.02, 0.3, -0.2);
  in.t_out = Eigen::Vector3d(0.0, 5e-4, 1e-3);
  in.record_film_force = {3, 0, 2, 1};  // a permutation: column q is coordinate [q]
  CvodeOptions o;
  SystemSolver s(m);
  const TransientResult r = integrate(s, in, o);
  CHECK(r.status == "ok");
  CHECK(r.film_force.rows() == 3 && r.film_force.cols() == 4);
  SystemSolver direct(m);
  for (Eigen::Index i = 0; i < r.t.size(); ++i) {
    const Eigen::VectorXd H =
        direct.film_forces(r.r.row(i).transpose(), r.v.row(i).transpose(), r.speed(i));
    Eigen::Vector4d rec;
    for (int q = 0; q < 4; ++q) rec(in.record_film_force[static_cast<std::size_t>(q)]) =
        r.film_force(i, q);
    check_blocks(rec, H, 1e-12);
  }
  // the first output is the initial state: the film at (r0, v0) as given
  CHECK((r.r.row(0).transpose() - in.r0).norm() == 0.0);
  const Eigen::VectorXd H0 = direct.film_forces(in.r0, in.v0, w);
  CHECK_CLOSE(r.film_force(0, 1), H0(0), 1e-12, 0.0);
  CHECK_CLOSE(r.film_force(0, 0), H0(3), 1e-12, 0.0);
  // recording costs no solve of the run and changes nothing in it
  TransientInput bare = in;
  bare.record_film_force.clear();
  SystemSolver s2(m);
  const TransientResult b = integrate(s2, bare, o);
  CHECK(b.reynolds_solves == r.reynolds_solves && b.steps == r.steps);
  CHECK((b.r - r.r).norm() == 0.0);
  CHECK(b.film_force.rows() == 3 && b.film_force.cols() == 0);
  // a coordinate outside [0, n) is an InputError
  TransientInput bad = in;
  bad.record_film_force = {4};
  SystemSolver s3(m);
  CHECK_THROWS(integrate(s3, bad, o), InputError);
}

TEST_CASE("stability_batch: film force and h_min z at each equilibrium, NaN where it failed") {
  const SystemModel m = journal_on_tilting_film();
  StabilityBatchInput in;
  // two points on one line (the second continued from the first), then the journal at rest
  // under its load (no film to carry it: no equilibrium)
  in.omega = Eigen::Vector3d(2 * M_PI * 50, 2 * M_PI * 60, 0.0);
  in.pressure = Eigen::Vector3d::Zero();
  in.a = RowMatrixXd(3, 4);
  in.a.row(0) = in.a.row(1) = misalignment().transpose();
  in.a.row(2) = misalignment().transpose();
  in.restart = {1, 0, 1};
  in.xy_pairs = {{0, 1}};
  in.rot_pairs = {{2, 3}};
  in.jacobian = "exact";
  SystemSolver s(m);
  const StabilityBatchResult out = stability_batch(s, in);
  CHECK(out.status[0] == "ok" && out.status[1] == "ok");
  if (out.status[2] == "ok" || out.status[2] == "contact")
    throw rdtest::Failure("point 2: status " + out.status[2] + ": " + out.message[2]);
  CHECK(out.film_force.rows() == 3 && out.film_force.cols() == 4);
  for (Eigen::Index i = 0; i < 2; ++i) {
    const Eigen::VectorXd r = out.r.row(i).transpose(), a = in.a.row(i).transpose();
    const Eigen::VectorXd H = out.film_force.row(i).transpose();
    // the film at the reported equilibrium, on a fresh solver
    SystemSolver direct(m);
    const Eigen::VectorXd Hd = direct.film_forces(r, Eigen::Vector4d::Zero(), in.omega[i]);
    check_blocks(H, Hd, 1e-12);
    CHECK(out.h_min_z_m(i, 0) == direct.last_h_min_z_m()[0]);
    CHECK(std::abs(out.h_min_z_m(i, 0)) == 0.5 * kL);  // misaligned: the edge film
    // it balances the structure: K (r + a) = H + Q, the moments the rotation spring's
    const Eigen::VectorXd R = m.K * (r + a) - H - m.Q;
    CHECK(R.head<2>().norm() < 1e-8 * 500.0);
    CHECK(R.tail<2>().norm() < 1e-8 * H.tail<2>().norm());
    // and equals a separate equilibrium's film force (the first point: the same cold start)
    if (i == 0) {
      EquilibriumOptions eo = in.options;
      const EquilibriumResult e = direct.equilibrium(in.omega[0], 0.0, a, Eigen::VectorXd(), eo);
      CHECK(e.status == "ok");
      check_blocks(H, e.film_force, 1e-12);
      CHECK(out.h_min_z_m(0, 0) == e.h_min_z_m[0]);
    }
  }
  CHECK(!out.film_force.row(2).array().isFinite().any());
  CHECK(std::isnan(out.h_min_z_m(2, 0)));
  // one rule for a failed point in both batches: every numeric output NaN, a message set
  // (before, stability_batch kept the failed iterate's h_min and equilibrium_batch its r, H,
  // h_min, h_min z and residual)
  CHECK(!out.r.row(2).array().isFinite().any() && !out.h_min.row(2).array().isFinite().any());
  CHECK(out.n_eig[2] == 0 && !out.eigenvalues.row(2).array().isFinite().any());
  CHECK(!out.message[2].empty());
  SystemSolver s2(m);
  const EquilibriumBatchResult eq = equilibrium_batch(s2, in);
  CHECK(eq.status == out.status && eq.status[0] == "ok");
  CHECK((eq.r.row(0) - out.r.row(0)).norm() == 0.0);  // the same cold start, exact Jacobian
  CHECK(!eq.r.row(2).array().isFinite().any() && !eq.film_force.row(2).array().isFinite().any());
  CHECK(!eq.h_min.row(2).array().isFinite().any() && std::isnan(eq.h_min_z_m(2, 0)));
  CHECK(std::isnan(eq.residual[2]) && std::isfinite(eq.residual[0]) && !eq.message[2].empty());
}
