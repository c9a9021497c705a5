"""Result of the thermal equilibrium of a system (effective temperature or THD film,
:func:`rotordyn.system_thermal_equilibrium`): one row per thermal film."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SystemThermalResult:
    """Thermal equilibrium of a system (docs/film-physics.md).

    Per thermal bearing (arrays in the order of ``bearing_names``): temperatures °C, the rise
    ΔT (K), the viscosity μ(T_eff) (Pa·s), the friction power (W), the flows (m³/s), the
    journal position (m). ``r`` (n,) the system's equilibrium coordinates; ``system`` the
    model with each thermal bearing's ``viscosity_pa_s`` set to μ(T_eff): its linearisation,
    stability and Campbell diagram are the dynamics at the thermal equilibrium with the
    temperature frozen. ``status``: the system equilibrium's (``ok``/``contact`` converged).
    """

    speed_hz: float
    supply_temperature_c: float
    bearing_names: tuple
    effective_temperature_c: np.ndarray
    max_temperature_c: np.ndarray
    inlet_temperature_c: np.ndarray
    temperature_rise_k: np.ndarray
    viscosity_pa_s: np.ndarray
    power_loss_w: np.ndarray
    film_flow_m3_s: np.ndarray
    side_flow_m3_s: np.ndarray
    supply_flow_m3_s: np.ndarray
    journal_x_m: np.ndarray
    journal_y_m: np.ndarray
    r: np.ndarray
    iterations: int
    system: object
    status: str = "ok"
    message: str = ""
    thermal_model: str = "effective"  # "thd": effective_temperature_c is the film's mean
    temperature_c: tuple = ()         # "thd": each bearing's field (n_circ, n_axial + 1), degC
    # "thd": per film, the nodes held at the inlet temperature (1) and the energy equation's
    # terms, a dict of (n_circ, n_axial + 1) arrays: face flows q_phi_m3_s (through j+1/2,
    # + with φ) and q_z_m3_s (through k+1/2, + towards +z), fill, cell dissipation_w,
    # area_m2, the node viscosity_pa_s
    inlet_mask: tuple = ()
    flows: tuple = ()

    def __repr__(self) -> str:
        t = ", ".join(f"{n}: {x:.2f} degC" for n, x in zip(self.bearing_names,
                                                           self.effective_temperature_c))
        return f"SystemThermalResult(speed_hz={self.speed_hz:g}, T_eff=[{t}], status={self.status!r})"

    def to_frame(self):
        """One row per thermal bearing: inputs, temperatures, viscosity, power, flows,
        journal position, status."""
        import pandas as pd

        n = len(self.bearing_names)
        return pd.DataFrame({
            "speed_hz": np.full(n, self.speed_hz),
            "supply_temperature_c": np.full(n, self.supply_temperature_c),
            "bearing": list(self.bearing_names),
            "thermal_model": [self.thermal_model] * n,
            "effective_temperature_c": self.effective_temperature_c,
            "max_temperature_c": self.max_temperature_c,
            "inlet_temperature_c": self.inlet_temperature_c,
            "temperature_rise_k": self.temperature_rise_k,
            "viscosity_pa_s": self.viscosity_pa_s,
            "power_loss_w": self.power_loss_w,
            "film_flow_m3_s": self.film_flow_m3_s,
            "side_flow_m3_s": self.side_flow_m3_s,
            "supply_flow_m3_s": self.supply_flow_m3_s,
            "journal_x_m": self.journal_x_m,
            "journal_y_m": self.journal_y_m,
            "status": [self.status] * n,
            "message": [self.message] * n,
        })
