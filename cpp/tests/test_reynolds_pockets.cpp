// Pockets (steps in the film thickness): the Rayleigh step closed form, derivative consistency,
// equivalences (a full ring is a deeper clearance; half = full system), mass conservation and
// input errors. Python tests (tests/test_film_steps.py) hold the grid-convergence orders of the
// pressure dam.
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/reynolds.hpp"
#include "reynolds_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
constexpr double kPi = 3.14159265358979323846;

JournalBearingGeometry geom(double D, double L) {
  JournalBearingGeometry g;
  g.diameter_m = D;
  g.length_m = L;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.02;
  return g;
}

RowMatrixXd constant(const ReynoldsSolver& s, double v) {
  return RowMatrixXd::Constant(s.grid().n_circ, s.grid().n_axial + 1, v);
}
}  // namespace

TEST_CASE("pockets: the Rayleigh step is exact on the mid-plane wherever the step falls") {
  // A 360° slider: supply line (p = 0) at φ = 0, a pocket of depth d from 0 to α over the
  // whole length, a centred journal. Far from the ends of a long bearing (L = 80 R) the film is
  // the 1-D Rayleigh step (Rayleigh, Phil. Mag. 35 (1918) 1-12): p rises linearly to
  //   p_s = 6 μ U (h1 − h2) / (h1³/B1 + h2³/B2),  U = ω R, B1 = R α, B2 = R (2π − α),
  // and falls linearly back. The scheme reproduces piecewise-linear pressures exactly when its
  // faces carry the exact film (series across the step); the mean of the nodes did not.
  const double D = 0.05, R = 0.025, L = 2.0, d = 1e-4, omega = 2 * kPi * 50.0;
  for (const double alpha_deg : {120.0, 122.5, 121.7}) {  // on a node, a face, in between
    JournalBearingGeometry g = geom(D, L);
    g.grooves.push_back(Groove{0.0, 0.0, 0.0});
    g.pockets.push_back(Pocket{0.0, alpha_deg, -0.5 * L, 0.5 * L, d});
    for (Cavitation cv : {Cavitation::none, Cavitation::reynolds}) {
      ReynoldsSolver s(g, FilmGrid{72, 16}, cv);
      const FilmSolution& sol = s.solve(constant(s, 1e-4), constant(s, 0.0), omega);
      const double a = alpha_deg * kPi / 180.0, U = omega * R, h1 = 1e-4 + d, h2 = 1e-4;
      const double ps = 6.0 * g.viscosity_pa_s * U * (h1 - h2) /
                        (h1 * h1 * h1 / (R * a) + h2 * h2 * h2 / (R * (2 * kPi - a)));
      for (int j = 0; j < 72; ++j) {
        const double phi = 2 * kPi * j / 72;
        const double exact = phi <= a ? ps * phi / a : ps * (2 * kPi - phi) / (2 * kPi - a);
        CHECK_CLOSE(sol.p_pa(j, 8), exact, 0.0, 1e-6 * ps);
      }
    }
  }
}

TEST_CASE("pockets: perturbation K, C match central finite differences") {
  JournalBearingGeometry g = geom(0.05, 0.025);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  // a dam-like pocket whose edges fall between nodes and faces, and a second one on nodes
  g.pockets.push_back(Pocket{100.0, 131.3, -0.0071, 0.0071, 2e-4});
  g.pockets.push_back(Pocket{300.0, 25.0, -0.0125, 0.003125, 5e-5});
  for (Cavitation cv : {Cavitation::none, Cavitation::gumbel, Cavitation::reynolds,
                        Cavitation::jfo}) {
    ReynoldsSolver s(g, FilmGrid{48, 12}, cv);
    for (const double y : {-5e-5, 3e-5}) rdtest::check_coefficients_match_fd(s, 3e-5, y, 150.0);
  }
}

TEST_CASE("pockets: a misaligned film's linearisation matches finite differences") {
  JournalBearingGeometry g = geom(0.05, 0.03);
  g.grooves.push_back(Groove{90.0, 10.0, 2e4});
  g.pockets.push_back(Pocket{120.0, 100.0, -0.01, 0.01, 1e-4});  // symmetric: half system
  ReynoldsSolver s(g, FilmGrid{48, 12}, Cavitation::reynolds);
  const Eigen::VectorXd phi = s.phi_rad(), z = s.z_m();
  RowMatrixXd h(48, 13), hd(48, 13), dh(48, 13);
  for (int j = 0; j < 48; ++j)
    for (int k = 0; k < 13; ++k) {
      h(j, k) = 1e-4 - 4e-5 * std::cos(phi[j]) * (1 + 10 * z[k]) - 2e-5 * std::sin(phi[j]);
      hd(j, k) = 1e-3 * std::sin(phi[j]);
      dh(j, k) = std::cos(phi[j] - 0.3) * (1 + 20 * z[k]);
    }
  s.solve(h, hd, 300.0);
  const Eigen::Vector2d lin = s.integrate_force(s.linearize(dh, RowMatrixXd::Zero(48, 13)));
  const double dq = 1e-11;
  const Eigen::Vector2d fp = s.solve(h + dq * dh, hd, 300.0).force_n;
  const Eigen::Vector2d fm = s.solve(h - dq * dh, hd, 300.0).force_n;
  const Eigen::Vector2d fd = (fp - fm) / (2 * dq);
  CHECK_CLOSE(lin.x(), fd.x(), 0.0, 1e-5 * lin.norm());
  CHECK_CLOSE(lin.y(), fd.y(), 0.0, 1e-5 * lin.norm());
}

TEST_CASE("pockets: a full ring over the length is a deeper clearance, bit for bit") {
  JournalBearingGeometry g = geom(0.05, 0.03);
  g.grooves.push_back(Groove{90.0, 0.0, 1e4});
  JournalBearingGeometry gp = g;
  gp.pockets.push_back(Pocket{17.0, 360.0, -0.015, 0.015, 3e-5});
  ReynoldsSolver a(g, FilmGrid{36, 8}, Cavitation::reynolds);
  ReynoldsSolver b(gp, FilmGrid{36, 8}, Cavitation::reynolds);
  const Eigen::VectorXd phi = a.phi_rad();
  RowMatrixXd h(36, 9), hd = RowMatrixXd::Zero(36, 9);
  for (int j = 0; j < 36; ++j) h.row(j).setConstant(1e-4 - 6e-5 * std::sin(phi[j]));
  const FilmSolution sa = a.solve(h.array() + 3e-5, hd, 200.0);
  const FilmSolution sb = b.solve(h, hd, 200.0);
  CHECK((sa.p_pa.array() == sb.p_pa.array()).all());
  CHECK(sa.force_n == sb.force_n);
  CHECK(sa.friction_torque_nm == sb.friction_torque_nm);
  CHECK(sa.side_flow_m3_s == sb.side_flow_m3_s && sa.inlet_flow_m3_s == sb.inlet_flow_m3_s);
}

TEST_CASE("pockets: the half system equals the full one; asymmetric pockets use the full") {
  JournalBearingGeometry g = geom(0.05, 0.025);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  g.pockets.push_back(Pocket{100.0, 131.3, -0.0071, 0.0071, 2e-4});
  for (int na : {12, 11}) {
    ReynoldsSolver half(g, FilmGrid{48, na}, Cavitation::reynolds);
    ReynoldsSolver full(g, FilmGrid{48, na}, Cavitation::reynolds);
    full.set_use_axial_symmetry(false);
    const DynamicCoefficients a = half.coefficients(2e-5, -5e-5, 300.0);
    const DynamicCoefficients b = full.coefficients(2e-5, -5e-5, 300.0);
    CHECK_CLOSE((a.force_n - b.force_n).norm(), 0.0, 0.0, 1e-12 * b.force_n.norm());
    CHECK_CLOSE((a.K - b.K).norm(), 0.0, 0.0, 1e-10 * b.K.norm());
    CHECK_CLOSE((a.C - b.C).norm(), 0.0, 0.0, 1e-10 * b.C.norm());
  }
  // an asymmetric pocket: the film is not symmetric, K and C still match finite differences
  JournalBearingGeometry ga = g;
  ga.pockets[0].z_max_m = 0.0125;
  ReynoldsSolver s(ga, FilmGrid{48, 12}, Cavitation::reynolds);
  const DynamicCoefficients a = s.coefficients(2e-5, -5e-5, 300.0);
  const DynamicCoefficients b = s.coefficients_fd(2e-5, -5e-5, 300.0, 1e-6);
  CHECK_CLOSE((a.K - b.K).norm(), 0.0, 0.0, 1e-3 * a.K.norm());
  const FilmSolution& sol = s.rigid(2e-5, -5e-5, 0, 0, 300.0);
  CHECK(std::abs(sol.p_pa(20, 2) - sol.p_pa(20, 10)) > 0.0);
}

TEST_CASE("pockets: jfo conserves mass across a pocket") {
  JournalBearingGeometry g = geom(0.05, 0.04);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  g.pockets.push_back(Pocket{95.0, 133.0, -0.0113, 0.0087, 1.5e-4});
  ReynoldsSolver j(g, FilmGrid{72, 16}, Cavitation::jfo);
  const FilmSolution& f = j.rigid(1e-5, -0.6e-4, 0, 0, 300.0);
  CHECK(f.inlet_flow_m3_s > 0.0);
  CHECK_CLOSE(f.inlet_flow_m3_s, f.side_flow_m3_s, 1e-9, 0.0);
}

TEST_CASE("pockets: bad pockets are InputErrors naming the field") {
  const auto bad = [](Pocket p, bool short_bearing = false) {
    JournalBearingGeometry g = geom(0.05, 0.04);
    g.pockets.push_back(p);
    g.short_bearing = short_bearing;
    CHECK_THROWS(ReynoldsSolver(g, FilmGrid{24, 4}, Cavitation::reynolds), InputError);
  };
  bad(Pocket{0.0, 0.0, -0.01, 0.01, 1e-4});          // arc 0
  bad(Pocket{0.0, 361.0, -0.01, 0.01, 1e-4});        // arc > 360
  bad(Pocket{std::nan(""), 90.0, -0.01, 0.01, 1e-4});
  bad(Pocket{0.0, 90.0, -0.03, 0.01, 1e-4});         // beyond the end
  bad(Pocket{0.0, 90.0, 0.01, 0.01, 1e-4});          // empty z range
  bad(Pocket{0.0, 90.0, -0.01, 0.01, 0.0});          // no depth
  bad(Pocket{0.0, 90.0, -0.01, 0.01, 1e-4}, true);   // short bearing
  try {
    JournalBearingGeometry g = geom(0.05, 0.04);
    g.pockets.push_back(Pocket{0.0, 90.0, -0.01, 0.01, -1.0});
    g.validate();
    CHECK(false);
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("pockets[0].depth_m") != std::string::npos);
  }
}
