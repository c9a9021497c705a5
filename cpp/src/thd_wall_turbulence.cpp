// The turbulent THD film's wall heat-transfer factors (thd_wall_turbulence.hpp).
#include "rotordyn/thd_wall_turbulence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "format_detail.hpp"
#include "rotordyn/errors.hpp"
#include "turbulence_detail.hpp"

namespace rotordyn {

using format_detail::num;

namespace {
constexpr double kK = kReichardtKappa, kD = kReichardtSublayer;

// ε_m/ν at y⁺ (Reichardt): κ δ (x − tanh x), x = y⁺/δ; the series below x = 0.01, where the
// difference would lose half its digits (next term 62 x⁹/2835: relative 1e-13 there)
double eddy(double y) {
  const double x = y / kD;
  if (x < 0.01) {
    const double x2 = x * x;
    return kK * kD * x * x2 * (1.0 / 3.0 - x2 * (2.0 / 15.0 - x2 * (17.0 / 315.0)));
  }
  return kK * kD * (x - std::tanh(x));
}

// 8-point Gauss–Legendre on [-1, 1]
constexpr std::array<double, 4> kGx = {0.1834346424956498, 0.5255324099163290,
                                       0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGw = {0.3626837833783620, 0.3137066458778873,
                                       0.2223810344533745, 0.1012285362903763};

// F(y) = ∫₀^y dy'/(1 + ε_m/ν): a table on [0, kYT] (step 1/16, each step by 8-point
// Gauss–Legendre) with cubic Hermite interpolation on the exact derivative 1/(1 + ε_m/ν)
// (error ~ Δ⁴ F''''/384 < 1e-9); beyond kYT, tanh(y/δ) = 1 in double (kYT/δ > 19.1) and
// F = F(kYT) + ln(1 + κ(y − kYT)/(1 + κ(kYT − δ)))/κ exactly.
constexpr double kYT = 256.0, kDY = 1.0 / 16.0;
constexpr int kNT = 4096;  // kYT / kDY
// panel growth: 1.4e-9 worst relative error against scipy over Re_h 30–1e5, Pr 0.7–1e4 (2:
// 6e-11, 4: 2e-7); the cost per cell ~0.6 µs
constexpr double kGrow = 3.0;

struct FTable {
  std::vector<double> f, d;  // F and F' at y_i = i kDY
  FTable() : f(kNT + 1), d(kNT + 1) {
    f[0] = 0.0;
    for (int i = 0; i <= kNT; ++i) d[i] = 1.0 / (1.0 + eddy(i * kDY));
    for (int i = 0; i < kNT; ++i) {
      const double m = (i + 0.5) * kDY, r = 0.5 * kDY;
      double s = 0.0;
      for (int g = 0; g < 4; ++g)
        s += kGw[g] * (1.0 / (1.0 + eddy(m - r * kGx[g])) + 1.0 / (1.0 + eddy(m + r * kGx[g])));
      f[i + 1] = f[i] + r * s;
    }
  }
  double operator()(double y) const {
    if (y < kDY) {  // the first step by quadrature: F ≈ y there, and its curvature ~ y⁴ is
      double s = 0.0;  // below the cubic's relative resolution
      for (int g = 0; g < 4; ++g)
        s += kGw[g] * (1.0 / (1.0 + eddy(0.5 * y * (1.0 - kGx[g]))) +
                       1.0 / (1.0 + eddy(0.5 * y * (1.0 + kGx[g]))));
      return 0.5 * y * s;
    }
    if (y >= kYT) return f[kNT] + std::log1p(kK * (y - kYT) / (1.0 + kK * (kYT - kD))) / kK;
    const int i = std::min(static_cast<int>(y / kDY), kNT - 1);
    const double s = y / kDY - i, s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * f[i] + (s3 - 2 * s2 + s) * kDY * d[i] +
           (-2 * s3 + 3 * s2) * f[i + 1] + (s3 - s2) * kDY * d[i + 1];
  }
};

const FTable& momentum_integral() {
  static const FTable table;  // built once (thread-safe), ~4k steps
  return table;
}

void check_reynolds(double re) {
  if (!(std::isfinite(re) && re >= 0.0))
    throw InputError("reynolds_number: expected a finite value >= 0, got " + num(re));
}
}  // namespace

TurbulentWallFactors eddy_wall_factors(double a, double P) {
  if (!(std::isfinite(a) && a >= 0.0))
    throw InputError("half_film_plus: expected a finite value >= 0, got " + num(a));
  if (!(std::isfinite(P) && P > 0.0))
    throw InputError("prandtl_ratio: expected a finite value > 0, got " + num(P));
  TurbulentWallFactors g;
  if (a == 0.0) return g;
  const FTable& F = momentum_integral();
  const double Fa = F(a);
  // panels: [0, b0], then doubling to a; b0 a quarter of the smaller of the thermal sublayer
  // (P ε_m/ν = 1 at y⁺ ≈ (3δ²/(κP))^(1/3)) and δ_l⁺, so every panel spans at most a factor
  // of two of the distance from the wall over which 1/(1 + P ε_m/ν) changes smoothly
  const double b0 = 0.25 * std::min(std::cbrt(3.0 * kD * kD / (kK * P)), kD);
  double R = 0.0, J = 0.0, lo = 0.0, hi = std::min(b0, a);
  while (lo < a) {
    const double m = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
    for (int q = 0; q < 8; ++q) {
      const double y = q < 4 ? m - r * kGx[q] : m + r * kGx[q - 4];
      const double w = r * kGw[q % 4] / (1.0 + P * eddy(y));
      R += w;
      J += w * (a - y) * (Fa - F(y));
    }
    lo = hi;
    hi = std::min(kGrow * hi, a);
  }
  g.across = a / R;
  g.symmetric = a * a * Fa / (3.0 * J);
  return g;
}

TurbulentWallFactors turbulent_wall_factors(Turbulence model, double re, double pr,
                                            double onset, double full) {
  check_reynolds(re);
  if (!(std::isfinite(pr) && pr > 0.0))
    throw InputError("prandtl_number: expected a finite value > 0, got " + num(pr));
  if (model == Turbulence::laminar || re == 0.0) return {};
  const double g = turbulence_weight(re, onset, full);
  if (g == 0.0) return {};  // below the transition's onset: the laminar film's conduction
  // the film's own Couette wall shear τ = C_f μU/h: h⁺ = √(C_f Re_h) (the fully turbulent
  // factors, whose excess the weight then scales)
  const double cf = couette_shear_factor(model, re);
  TurbulentWallFactors f = eddy_wall_factors(0.5 * std::sqrt(cf * re), pr / kTurbulentPrandtl);
  if (g < 1.0) {
    f.symmetric = 1.0 + g * (f.symmetric - 1.0);
    f.across = 1.0 + g * (f.across - 1.0);
  }
  return f;
}

double eddy_couette_shear_factor(double re) {
  check_reynolds(re);
  if (re == 0.0) return 1.0;
  const FTable& F = momentum_integral();
  // Re_h = U⁺ h⁺ = 4 a F(a), increasing in a; F(a) <= a, so a >= √Re/2
  auto g = [&](double a) { return 4.0 * a * F(a) - re; };
  double lo = 0.5 * std::sqrt(re), hi = lo;
  while (g(hi) < 0.0) hi *= 2.0;
  double a = hi;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double ga = g(a);
    if (ga == 0.0) break;
    (ga < 0.0 ? lo : hi) = a;
    const double step = ga / (4.0 * F(a) + 4.0 * a / (1.0 + eddy(a)));
    a = (a - step > lo && a - step < hi) ? a - step : 0.5 * (lo + hi);
  }
  return a / F(a);
}

}  // namespace rotordyn
