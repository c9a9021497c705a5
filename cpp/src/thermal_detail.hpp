// Internal to the thermal model (thermal.cpp, thermal_system.cpp): the heat balance of one film.
#pragma once

#include <string>

#include "rotordyn/thermal.hpp"

namespace rotordyn {

/// The film's effective temperature at a fixed journal position (P ∝ μ, flows independent of
/// μ): the root of T − Ts − m a μ(T), a = P/(μ ρ c (Q − Q_s/2)), m = λ Q_r/Q_f + k, with the
/// temperature rise, inlet and maximum temperatures and the fresh supply flow. ``mu`` (Pa·s)
/// the viscosity P (W) was computed with; Q, Q_s (m³/s) the film and side flows; ``name`` the
/// film's name in messages ("" for a standalone bearing). Throws ConvergenceError when the
/// flows give no heat balance or the temperature leaves the viscosity law's range.
ThermalFilmState heat_balance(const OilModel& oil, const ThermalOptions& opt, double mu,
                              double P, double Q, double Qs, const std::string& name);

}  // namespace rotordyn
