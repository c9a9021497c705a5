// The turbulent film's Couette shear factor, one expression (reynolds_turbulence.cpp) for
// every user: turbulence_factors' cf, the film's friction torque and dissipation
// (reynolds_solve.cpp, reynolds_viscosity.cpp) and the turbulent THD walls' shear
// (thd_wall_turbulence.cpp).
#pragma once

#include "rotordyn/reynolds.hpp"

namespace rotordyn {

/// C_f = 1 + 0.0012 Re_h^0.94 (Taylor & Dowson's fit of Ng & Pan; reynolds.hpp, Turbulence);
/// 1 for a laminar film and at Re_h <= 0: turbulence_factors(model, Re).cf.
double couette_shear_factor(Turbulence model, double reynolds_number);

}  // namespace rotordyn
