// The turbulent film's Couette shear factor, one expression (reynolds_turbulence.cpp) for
// every user: turbulence_factors' cf, the film's friction torque and dissipation
// (reynolds_solve.cpp, reynolds_viscosity.cpp) and the turbulent THD walls' shear
// (thd_wall_turbulence.cpp).
#pragma once

#include <limits>

#include "rotordyn/reynolds.hpp"

namespace rotordyn {

/// C_f = 1 + γ 0.0012 Re_h^0.94 (Taylor & Dowson's fit of Ng & Pan; reynolds.hpp, Turbulence),
/// γ the transition's weight between `onset` and `full` (turbulence_weight; NaN: none, γ = 1);
/// 1 for a laminar film, at Re_h <= 0 and below the onset: turbulence_factors(...).cf.
double couette_shear_factor(Turbulence model, double reynolds_number,
                            double onset = std::numeric_limits<double>::quiet_NaN(),
                            double full = std::numeric_limits<double>::quiet_NaN());

}  // namespace rotordyn
