// Starved (metered-supply) jfo film (reynolds_starved.cpp): the flooded limit bit for bit, the
// supply met to the root's tolerance and conserved, the held-supply linearisation against
// central differences of the supplied film (each perturbed state re-solves its groove state).
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/reynolds.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
JournalBearingGeometry starved_geom(double supply, double p_groove) {
  JournalBearingGeometry g;
  g.diameter_m = 0.05;
  g.length_m = 0.025;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.02;
  g.grooves.push_back(Groove{90.0, 0.0, p_groove});  // at the top; the load is downwards
  g.supply_flow_m3_s = supply;
  return g;
}
}  // namespace

TEST_CASE("starved: a supply at or above the flooded demand is the flooded film bit for bit") {
  ReynoldsSolver f(starved_geom(0.0, 2e4), FilmGrid{48, 12}, Cavitation::jfo);
  const FilmSolution a = f.rigid(2e-5, -5e-5, 0, 0, 300.0);
  const DynamicCoefficients da = f.coefficients(2e-5, -5e-5, 300.0);
  ReynoldsSolver s(starved_geom(1.0001 * a.inlet_flow_m3_s, 2e4), FilmGrid{48, 12},
                   Cavitation::jfo);
  const FilmSolution b = s.rigid(2e-5, -5e-5, 0, 0, 300.0);
  const DynamicCoefficients db = s.coefficients(2e-5, -5e-5, 300.0);
  CHECK(a.p_pa == b.p_pa);
  CHECK(a.theta == b.theta);
  CHECK(a.force_n == b.force_n);
  CHECK(da.K == db.K);
  CHECK(da.C == db.C);
  CHECK(!b.starved && b.inlet_fill == 1.0 && b.groove_pressure_factor == 1.0);
}

TEST_CASE("starved: the inflow meets the supply and leaves through the ends") {
  ReynoldsSolver f(starved_geom(0.0, 2e4), FilmGrid{48, 12}, Cavitation::jfo);
  const double q0 = f.rigid(2e-5, -5e-5, 0, 0, 300.0).inlet_flow_m3_s;
  for (double frac : {0.9, 0.5, 0.2}) {  // 0.9: the groove pressure falls; below: θ_in < 1
    ReynoldsSolver s(starved_geom(frac * q0, 2e4), FilmGrid{48, 12}, Cavitation::jfo);
    const FilmSolution& r = s.rigid(2e-5, -5e-5, 0, 0, 300.0);
    CHECK(r.starved);
    CHECK_CLOSE(r.inlet_flow_m3_s, frac * q0, 1e-11, 0.0);
    CHECK_CLOSE(r.side_flow_m3_s, r.inlet_flow_m3_s, 1e-10, 0.0);
    CHECK(r.inlet_fill <= 1.0 && r.inlet_fill > 0.0);
    CHECK(r.groove_pressure_factor < 1.0);
  }
}

TEST_CASE("starved: held-supply K, C match central differences of the supplied film") {
  ReynoldsSolver f(starved_geom(0.0, 0.0), FilmGrid{48, 12}, Cavitation::jfo);
  const double q0 = f.rigid(2e-5, -5e-5, 0, 0, 300.0).inlet_flow_m3_s;
  ReynoldsSolver s(starved_geom(0.5 * q0, 0.0), FilmGrid{48, 12}, Cavitation::jfo);
  const DynamicCoefficients p = s.coefficients(2e-5, -5e-5, 300.0);
  const DynamicCoefficients d = s.coefficients_fd(2e-5, -5e-5, 300.0, 1e-6);
  const double ks = p.K.norm(), cs = p.C.norm();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      CHECK_CLOSE(p.K(i, j), d.K(i, j), 0.0, 1e-4 * ks);
      CHECK_CLOSE(p.C(i, j), d.C(i, j), 0.0, 1e-4 * cs);
    }
}

TEST_CASE("starved: a supply needs jfo, is finite and >= 0, takes no pockets") {
  CHECK_THROWS(ReynoldsSolver(starved_geom(1e-6, 0.0), FilmGrid{48, 12}, Cavitation::reynolds),
               InputError);
  CHECK_THROWS(ReynoldsSolver(starved_geom(-1e-6, 0.0), FilmGrid{48, 12}, Cavitation::jfo),
               InputError);
  CHECK_THROWS(ReynoldsSolver(starved_geom(std::nan(""), 0.0), FilmGrid{48, 12},
                              Cavitation::jfo), InputError);
  JournalBearingGeometry g = starved_geom(1e-6, 0.0);
  g.pockets.push_back(Pocket{10.0, 20.0, -0.005, 0.005, 1e-5});
  CHECK_THROWS(ReynoldsSolver(g, FilmGrid{48, 12}, Cavitation::jfo), InputError);
}
