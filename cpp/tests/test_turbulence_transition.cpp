// The turbulent film's optional laminar-to-turbulent transition (turbulence_weight): the
// intermittency weight's closed form, the blended coefficients and their Re-slopes, the
// laminar film below the onset and today's turbulent film above the full value bit for bit,
// K and C against finite differences on a film whose Re_h spans the ramp, the wall factors and
// input errors. Python tests: tests/test_turbulence_transition.py.
#include <cmath>
#include <limits>

#include "rotordyn/errors.hpp"
#include "rotordyn/reynolds.hpp"
#include "rotordyn/thd_wall_turbulence.hpp"
#include "reynolds_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
// Re_h at the clearance 860 · 2π·300 · 0.05 · 1e-4 / 0.003 = 2.70e3
JournalBearingGeometry film(double onset, double full) {
  JournalBearingGeometry g;
  g.diameter_m = 0.1;
  g.length_m = 0.05;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.003;
  g.turbulence = Turbulence::ng_pan;
  g.density_kg_m3 = 860.0;
  g.turbulence_onset_re = onset;
  g.turbulence_full_re = full;
  return g;
}
}  // namespace

TEST_CASE("transition: the weight is the cubic smoothstep; the blended k, C_f its closed forms") {
  const double on = 1000.0, full = 3000.0, w = full - on;
  double rg = -1.0;
  CHECK(turbulence_weight(on, on, full, &rg) == 0.0 && rg == 0.0);
  CHECK(turbulence_weight(full, on, full, &rg) == 1.0 && rg == 0.0);
  CHECK(turbulence_weight(5.0, std::nan(""), std::nan(""), &rg) == 1.0 && rg == 0.0);
  for (const double t : {0.1, 0.25, 0.5, 0.9}) {
    const double re = on + t * w;
    const double g = turbulence_weight(re, on, full, &rg);
    CHECK_CLOSE(g, t * t * (3.0 - 2.0 * t), 1e-15, 0.0);
    CHECK_CLOSE(rg, re * 6.0 * t * (1.0 - t) / w, 1e-14, 0.0);
    const TurbulenceFactors f = turbulence_factors(Turbulence::ng_pan, re, on, full);
    const double ax = 0.0136 * std::pow(re, 0.90), az = 0.0043 * std::pow(re, 0.96);
    CHECK_CLOSE(f.kx, 12.0 + g * ax, 1e-15, 0.0);
    CHECK_CLOSE(f.kz, 12.0 + g * az, 1e-15, 0.0);
    CHECK_CLOSE(f.cf, 1.0 + g * 0.0012 * std::pow(re, 0.94), 1e-15, 0.0);
    // Re dk/dRe against central differences of k (step 1e-4 Re: truncation ~1e-8 relative)
    const double d = 1e-4 * re;
    const TurbulenceFactors fp = turbulence_factors(Turbulence::ng_pan, re + d, on, full);
    const TurbulenceFactors fm = turbulence_factors(Turbulence::ng_pan, re - d, on, full);
    CHECK_CLOSE(f.re_dkx, re * (fp.kx - fm.kx) / (2.0 * d), 1e-7, 0.0);
    CHECK_CLOSE(f.re_dkz, re * (fp.kz - fm.kz) / (2.0 * d), 1e-7, 0.0);
  }
  // below the onset exactly laminar, above the full value exactly today's factors
  const TurbulenceFactors lo = turbulence_factors(Turbulence::ng_pan, 999.0, on, full);
  CHECK(lo.kx == 12.0 && lo.kz == 12.0 && lo.cf == 1.0 && lo.re_dkx == 0.0 && lo.re_dkz == 0.0);
  const TurbulenceFactors hi = turbulence_factors(Turbulence::ng_pan, 3001.0, on, full);
  const TurbulenceFactors ref = turbulence_factors(Turbulence::ng_pan, 3001.0);
  CHECK(hi.kx == ref.kx && hi.kz == ref.kz && hi.cf == ref.cf && hi.re_dkx == ref.re_dkx &&
        hi.re_dkz == ref.re_dkz);
}

TEST_CASE("transition: below the onset the laminar film, above the full value today's, bit for bit") {
  const double w = kTwoPi * 300.0, x = 2e-5, y = -5e-5;  // Re_h 1.24e3 ... 4.16e3
  JournalBearingGeometry lam = film(std::nan(""), std::nan(""));
  lam.turbulence = Turbulence::laminar;
  ReynoldsSolver a(film(1e5, 2e5), FilmGrid{36, 8}, Cavitation::reynolds);
  ReynoldsSolver b(lam, FilmGrid{36, 8}, Cavitation::reynolds);
  const FilmSolution sa = a.rigid(x, y, 0.0, 0.0, w), sb = b.rigid(x, y, 0.0, 0.0, w);
  CHECK(sa.force_n == sb.force_n && sa.friction_torque_nm == sb.friction_torque_nm);
  const DynamicCoefficients ca = a.coefficients(x, y, w), cb = b.coefficients(x, y, w);
  CHECK(ca.K == cb.K && ca.C == cb.C);
  ReynoldsSolver c(film(0.0, 1000.0), FilmGrid{36, 8}, Cavitation::reynolds);
  ReynoldsSolver d(film(std::nan(""), std::nan("")), FilmGrid{36, 8}, Cavitation::reynolds);
  const FilmSolution sc = c.rigid(x, y, 0.0, 0.0, w), sd = d.rigid(x, y, 0.0, 0.0, w);
  CHECK(sc.force_n == sd.force_n && sc.friction_torque_nm == sd.friction_torque_nm);
  const DynamicCoefficients cc = c.coefficients(x, y, w), cd = d.coefficients(x, y, w);
  CHECK(cc.K == cd.K && cc.C == cd.C);
}

TEST_CASE("transition: K, C match finite differences on a film spanning the ramp") {
  const double w = kTwoPi * 300.0;
  for (Cavitation cv : {Cavitation::gumbel, Cavitation::reynolds}) {
    ReynoldsSolver s(film(1500.0, 4000.0), FilmGrid{36, 8}, cv);
    rdtest::check_coefficients_match_fd(s, 2e-5, -5e-5, w);
  }
  JournalBearingGeometry gs = film(1500.0, 4000.0);
  gs.length_m = 0.02;
  gs.short_bearing = true;
  ReynoldsSolver s(gs, FilmGrid{72, 8}, Cavitation::none);
  rdtest::check_coefficients_match_fd(s, 2e-5, -5e-5, w);
}

TEST_CASE("transition: the wall factors' excess takes the weight") {
  const double on = 1000.0, full = 3000.0, pr = 400.0;
  const TurbulentWallFactors lo = turbulent_wall_factors(Turbulence::ng_pan, 999.0, pr, on, full);
  CHECK(lo.symmetric == 1.0 && lo.across == 1.0);
  const TurbulentWallFactors hi = turbulent_wall_factors(Turbulence::ng_pan, 3500.0, pr, on, full);
  const TurbulentWallFactors ref = turbulent_wall_factors(Turbulence::ng_pan, 3500.0, pr);
  CHECK(hi.symmetric == ref.symmetric && hi.across == ref.across);
  const double re = 2000.0;  // t = 1/2: γ = 1/2
  const TurbulentWallFactors mid = turbulent_wall_factors(Turbulence::ng_pan, re, pr, on, full);
  const TurbulentWallFactors full_g = turbulent_wall_factors(Turbulence::ng_pan, re, pr);
  CHECK_CLOSE(mid.symmetric, 1.0 + 0.5 * (full_g.symmetric - 1.0), 1e-15, 0.0);
  CHECK_CLOSE(mid.across, 1.0 + 0.5 * (full_g.across - 1.0), 1e-15, 0.0);
}

TEST_CASE("transition: bad ramps are InputErrors naming the field") {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS(film(1000.0, nan).validate(), InputError);   // both or neither
  CHECK_THROWS(film(nan, 1000.0).validate(), InputError);
  CHECK_THROWS(film(-1.0, 1000.0).validate(), InputError);  // onset >= 0
  CHECK_THROWS(film(1000.0, 1000.0).validate(), InputError);  // onset < full
  CHECK_THROWS(film(1000.0, inf).validate(), InputError);
  JournalBearingGeometry lam = film(500.0, 1000.0);
  lam.turbulence = Turbulence::laminar;  // nothing to switch on
  CHECK_THROWS(lam.validate(), InputError);
  try {
    film(2000.0, 1000.0).validate();
    CHECK(false);
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("turbulence_full_re") != std::string::npos);
  }
  film(0.0, 1000.0).validate();  // an onset at 0 is allowed
}
