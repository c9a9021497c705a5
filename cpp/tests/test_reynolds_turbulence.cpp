// Turbulent film (Ng–Pan–Elrod, Taylor & Dowson 1974 fits) and the effective-temperature model:
// the coefficients' closed forms, the laminar limit, derivative consistency of the turbulent
// conductances (smooth, stepped, short films), the thermal iteration's heat balance and input
// errors. Python tests (tests/test_film_turbulence.py, tests/test_film_thermal.py) hold the
// closed-form and published-table checks.
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/reynolds.hpp"
#include "rotordyn/thermal.hpp"
#include "reynolds_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
JournalBearingGeometry turbulent(double L) {
  JournalBearingGeometry g;
  g.diameter_m = 0.1;
  g.length_m = L;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.003;
  g.turbulence = Turbulence::ng_pan;
  g.density_kg_m3 = 860.0;
  return g;
}
}  // namespace

TEST_CASE("turbulence: Ng-Pan-Elrod coefficients are the closed forms; Re = 0 is laminar") {
  for (const double re : {0.0, 10.0, 1e3, 1e4}) {
    const TurbulenceFactors t = turbulence_factors(Turbulence::ng_pan, re);
    CHECK_CLOSE(t.kx, 12.0 + 0.0136 * std::pow(re, 0.90), 1e-15, 0.0);
    CHECK_CLOSE(t.kz, 12.0 + 0.0043 * std::pow(re, 0.96), 1e-15, 0.0);
    CHECK_CLOSE(t.cf, 1.0 + 0.0012 * std::pow(re, 0.94), 1e-15, 0.0);
  }
  const TurbulenceFactors z = turbulence_factors(Turbulence::ng_pan, 0.0);
  CHECK(z.kx == 12.0 && z.kz == 12.0 && z.cf == 1.0);
}

TEST_CASE("turbulence: perturbation K, C match finite differences (smooth, stepped, short)") {
  // omega = 2 pi 300: Re_h at the clearance ~ 2.7e3
  const double w = 2.0 * 3.14159265358979323846 * 300.0;
  for (Cavitation cv : {Cavitation::gumbel, Cavitation::reynolds}) {
    ReynoldsSolver s(turbulent(0.05), FilmGrid{36, 8}, cv);
    rdtest::check_coefficients_match_fd(s, 2e-5, -5e-5, w);
  }
  JournalBearingGeometry gp = turbulent(0.05);
  gp.grooves.push_back(Groove{90.0, 0.0, 0.0});
  gp.pockets.push_back(Pocket{100.0, 131.3, -0.0142, 0.0142, 2e-4});
  for (Cavitation cv : {Cavitation::reynolds, Cavitation::jfo}) {
    ReynoldsSolver s(gp, FilmGrid{48, 12}, cv);
    rdtest::check_coefficients_match_fd(s, 3e-5, -4e-5, w);
  }
  JournalBearingGeometry gs = turbulent(0.02);
  gs.short_bearing = true;
  ReynoldsSolver s(gs, FilmGrid{72, 8}, Cavitation::none);
  rdtest::check_coefficients_match_fd(s, 2e-5, -5e-5, w);
}

TEST_CASE("turbulence: a turbulent film without a density is an InputError") {
  JournalBearingGeometry g = turbulent(0.05);
  g.density_kg_m3 = 0.0;
  CHECK_THROWS(g.validate(), InputError);
  CHECK_THROWS(parse_turbulence("k-epsilon"), InputError);
}

TEST_CASE("thermal: the equilibrium satisfies its heat balance; bad oils are InputErrors") {
  JournalBearingGeometry g;
  g.diameter_m = 0.1;
  g.length_m = 0.05;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.02;
  ReynoldsSolver s(g, FilmGrid{36, 8}, Cavitation::reynolds);
  OilModel oil;  // Walther, ISO VG 32 (32 / 5.4 mm^2/s at 40 / 100 degC)
  ThermalOptions opt;
  opt.supply_temperature_c = 45.0;
  const double w = 2.0 * 3.14159265358979323846 * 100.0;
  const ThermalEquilibrium r = thermal_equilibrium(s, oil, opt, 0.0, -5000.0, w);
  const double rc = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k;
  CHECK_CLOSE(r.power_loss_w, rc * r.temperature_rise_k * (r.film_flow_m3_s - 0.5 * r.side_flow_m3_s),
              1e-12, 0.0);
  CHECK_CLOSE(r.effective_temperature_c, 45.0 + 0.5 * r.temperature_rise_k, 0.0, 1e-5);
  CHECK_CLOSE(r.viscosity_pa_s, oil.viscosity_pa_s(r.effective_temperature_c), 1e-12, 0.0);
  CHECK_CLOSE(r.equilibrium.force_n.y(), 5000.0, 1e-8, 0.0);
  OilModel bad = oil;
  bad.nu2_mm2_s = 40.0;  // rises with temperature
  CHECK_THROWS(bad.validate(), InputError);
  bad = oil;
  bad.specific_heat_j_per_kg_k = -1.0;
  CHECK_THROWS(bad.validate(), InputError);
  ThermalOptions cold = opt;
  cold.supply_temperature_c = -50.0;  // below the law's range
  CHECK_THROWS(thermal_equilibrium(s, oil, cold, 0.0, -5000.0, w), InputError);
}

TEST_CASE("thermal: set_viscosity equals a solver built with that viscosity, bit for bit") {
  JournalBearingGeometry g;
  g.diameter_m = 0.1;
  g.length_m = 0.05;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.02;
  ReynoldsSolver a(g, FilmGrid{72, 16}, Cavitation::reynolds);
  a.rigid(1e-5, -6e-5, 0.0, 0.0, 300.0);  // its coarse-grid solver exists now
  a.set_viscosity(0.013);
  g.viscosity_pa_s = 0.013;
  ReynoldsSolver b(g, FilmGrid{72, 16}, Cavitation::reynolds);
  const Eigen::Vector2d fa = a.rigid(2e-5, -5e-5, 0.0, 0.0, 300.0).force_n;
  const Eigen::Vector2d fb = b.rigid(2e-5, -5e-5, 0.0, 0.0, 300.0).force_n;
  CHECK(fa == fb);
  const DynamicCoefficients ca = a.coefficients(2e-5, -5e-5, 300.0);
  const DynamicCoefficients cb = b.coefficients(2e-5, -5e-5, 300.0);
  CHECK(ca.K == cb.K && ca.C == cb.C);
  CHECK_THROWS(a.set_viscosity(-1.0), InputError);
}
