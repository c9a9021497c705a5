// The turbulent THD film's heat transfer to its walls (issue 20; docs/film-physics.md
// "Turbulent films with a temperature field"): the factors by which an eddy conductivity
// raises the film-side coefficients of the laminar film (thd_walls.hpp, wall_htc = "film").
//
// Model: the film's fully developed Couette profile across its thickness h (the laminar film's
// own first-order statement, thd_walls.hpp), with
//   * the eddy viscosity of Reichardt's wall law, with the distance y to the nearer wall,
//       ε_m/ν = κ [y⁺ − δ_l⁺ tanh(y⁺/δ_l⁺)],  κ = 0.4, δ_l⁺ = 10.7
//     (H. Reichardt, ZAMM 31 (1951) 208–219; the law of Ng & Pan's and Elrod & Ng's turbulent
//     lubrication theory, whose Couette shear the film's C_f fits, and of the turbulent THD
//     analyses of Suganami & Szeri, J. Lubr. Technol. 101 (1979) 21–27, and Taniguchi,
//     Makino, Takeshita & Ichimura, J. Tribol. 112 (1990) 542–550);
//   * the eddy diffusivity of heat ε_h = ε_m / Pr_t, Pr_t = 0.9 (kTurbulentPrandtl), so the
//     conductivity across the film is k (1 + (Pr/Pr_t) ε_m/ν), Pr = μ c_p / k;
//   * the wall units of the film's own Couette wall shear τ = C_f μU/h (C_f the film's
//     Ng–Pan factor): u* = √(τ/ρ), h⁺ = h u*/ν = √(C_f Re_h), Re_h = ρUh/μ, a = h⁺/2;
//   * the heat source of the turbulent THD energy equation, μ(1 + ε_m/ν)(du/dy)² = τ du/dy
//     (Suganami & Szeri's), distributed across the film as the Couette velocity gradient,
//     du⁺/dy⁺ = 1/(1 + ε_m/ν): its integral is the film's Couette dissipation.
// With the cross-film mean temperature T (the film's temperature) and the wall temperatures
// T_J, T_w the wall fluxes are then exactly, per unit area and cell fill θ,
//   q_J = H_s (T − (T_J + T_w)/2) + K_c (T_w − T_J),  q_B = H_s (T − (T_J + T_w)/2) − K_c (T_w − T_J)
// with H_s = 6 θ k/h · G_s (each wall's share of the heat generated) and K_c = θ k/h · G_c
// (conduction straight across), in wall units (F(y) = ∫₀^y dy'/(1 + ε_m/ν), t(y) = 1 +
// (Pr/Pr_t) ε_m/ν, integrals over the half film 0 … a):
//   G_c = a / ∫₀^a dy/t,   G_s = a² F(a) / (3 ∫₀^a (a − y)(F(a) − F(y))/t dy).
// Laminar (ε_m = 0: F(y) = y, t = 1): G_s = G_c = 1, the parabola's q_J = θ k/h (6T − 4T_J −
// 2T_w). Fully turbulent: G_s → G_c/3, each wall's coefficient the half film's eddy-conduction
// resistance from the mid-film.
#pragma once

#include "rotordyn/reynolds.hpp"

namespace rotordyn {

/// Reichardt's wall-law constants (κ, δ_l⁺) and the turbulent Prandtl number.
inline constexpr double kReichardtKappa = 0.4;
inline constexpr double kReichardtSublayer = 10.7;
inline constexpr double kTurbulentPrandtl = 0.9;

/// The factors on the laminar film's coefficients: G_s on the symmetric (6 θ k/h), G_c on the
/// across-film (θ k/h) one; exactly 1 for the laminar model or Re_h = 0.
struct TurbulentWallFactors {
  double symmetric = 1.0;
  double across = 1.0;
};

/// The factors at the film Reynolds number Re_h = ρUh/μ (>= 0) and the oil's molecular
/// Prandtl number Pr = μ c_p / k (> 0), the wall shear the film's C_f (turbulence_factors).
/// InputError naming reynolds_number or prandtl_number. With a transition (onset_re <
/// full_re; NaN: none) the factors' excess takes the film's intermittency weight γ(Re_h)
/// (turbulence_weight): G = 1 + γ (G_turbulent − 1), exactly 1 at and below the onset and
/// exactly the turbulent factors at and above full_re.
TurbulentWallFactors turbulent_wall_factors(
    Turbulence model, double reynolds_number, double prandtl_number,
    double onset_re = std::numeric_limits<double>::quiet_NaN(),
    double full_re = std::numeric_limits<double>::quiet_NaN());

/// The same factors at the half film in wall units a = h⁺/2 (>= 0) and Pr/Pr_t (> 0).
TurbulentWallFactors eddy_wall_factors(double half_film_plus, double prandtl_ratio);

/// The eddy model's own Couette shear factor τ h/(μU) at Re_h (its wall shear from the
/// momentum integral Re_h = 4 a F(a), C_f = a/F(a)): the model's calibration against the film's
/// Ng–Pan C_f (docs/film-physics.md). InputError naming reynolds_number.
double eddy_couette_shear_factor(double reynolds_number);

}  // namespace rotordyn
