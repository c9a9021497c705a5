"""Result of the thermal equilibrium of a system (effective temperature or THD film,
:func:`rotordyn.system_thermal_equilibrium`): one row per thermal film."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotordyn.results._display import Display

WALL_COLUMNS = ("journal_temperature_c", "max_wall_temperature_c", "heat_to_journal_w",
                "heat_to_bush_w")
"""The THD films' wall outputs of :meth:`SystemThermalResult.to_frame` (NaN for others)."""


PAD_FRAME_THERMAL = ("effective_temperature_c", "max_temperature_c", "inlet_temperature_c",
                     "temperature_rise_k", "viscosity_pa_s", "power_loss_w", "supply_flow_m3_s",
                     "max_wall_temperature_c")
"""The thermal columns of :meth:`SystemThermalResult.pads_frame` (its pads' ``pad_*``)."""


@dataclass(frozen=True)
class SystemThermalResult(Display):
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
    # "thd": per film, the heat it gives the journal and the bush or pad (W), the journal's
    # temperature (°C; fixed, or one per bearing from its heat balance), the hottest bush or
    # pad surface (°C) and the surface fields (rotordyn.bearings.thd_walls); NaN otherwise
    heat_to_journal_w: np.ndarray | None = None
    heat_to_bush_w: np.ndarray | None = None
    journal_temperature_c: np.ndarray | None = None
    max_wall_temperature_c: np.ndarray | None = None
    wall_temperature_c: tuple = ()
    # per film: the minimum film thickness at the thermal equilibrium (m; the hot film, not the
    # isothermal one) and its axial position (m, z = 0 mid-plane: a tilted journal's edge
    # film); NaN where the equilibrium failed
    h_min_m: np.ndarray | None = None
    h_min_z_m: np.ndarray | None = None
    # a model with tilting films (tilt = true), per film: its bearing's journal rotations
    # (rad, the system's coordinates as the equilibrium's columns of the same names) and the
    # bearing's film moments on the journal (N·m; a tilting-pad bearing's whole moment on each
    # pad's row); NaN for an untilted film and where the equilibrium failed; None (no columns)
    # when no film tilts
    tilt: dict | None = None
    # per thermal tilting-pad bearing (index into the model's bearings): every pad's state at
    # the thermal equilibrium, tuples in pad order — the isothermal equilibrium's pad_pivot_deg,
    # pad_tilt_rad, pad_p_max_pa, pad_h_min_m, pad_unloaded (EquilibriumResult.pads) and the
    # pad's pad_effective_temperature_c (THD: its mean), pad_max_temperature_c,
    # pad_inlet_temperature_c, pad_temperature_rise_k, pad_viscosity_pa_s, pad_power_loss_w,
    # pad_supply_flow_m3_s, pad_max_wall_temperature_c (THD); {} where it failed
    pads: dict = field(default_factory=dict)
    # per film: λ_eff, the carried-over fraction of the hot flow reaching its inlet (the given
    # carry_over, or (Q − Q_f)/Q_r where a metered supply falls short of the demand); NaN
    # where the equilibrium failed
    carry_over_effective: np.ndarray | None = None

    def wall(self, name: str) -> np.ndarray:
        """One of the THD wall outputs (or the minimum film's) per film (NaN where there is
        none)."""
        x = getattr(self, name)
        return np.full(len(self.bearing_names), np.nan) if x is None else np.asarray(x)

    def __repr__(self) -> str:
        t = ", ".join(f"{n}: {x:.2f} degC" for n, x in zip(self.bearing_names,
                                                           self.effective_temperature_c))
        return f"SystemThermalResult(speed_hz={self.speed_hz:g}, T_eff=[{t}], status={self.status!r})"

    def pads_frame(self):
        """One row per pad of every thermal tilting-pad bearing: ``bearing``, ``pad`` (0-based,
        pivot order), ``pivot_deg``, ``tilt_rad``, ``p_max_pa``, ``h_min_m``, ``unloaded``
        (as :meth:`EquilibriumResult.pads_frame`) and the pad's ``effective_temperature_c``
        (THD: mean), ``max_temperature_c``, ``inlet_temperature_c``, ``temperature_rise_k``,
        ``viscosity_pa_s``, ``power_loss_w``, ``supply_flow_m3_s``,
        ``max_wall_temperature_c`` (THD; NaN otherwise). Empty without tilting pads or
        without a converged thermal equilibrium."""
        import pandas as pd

        cols = ["bearing", "pad", "pivot_deg", "tilt_rad", "p_max_pa", "h_min_m", "unloaded",
                *PAD_FRAME_THERMAL]
        names = self.system.bearings
        rows = []
        for bi, d in self.pads.items():
            for k in range(len(d["pad_tilt_rad"])):
                rows.append([names[bi].name, k, d["pad_pivot_deg"][k], d["pad_tilt_rad"][k],
                             d["pad_p_max_pa"][k], d["pad_h_min_m"][k], d["pad_unloaded"][k],
                             *(d["pad_" + c][k] for c in PAD_FRAME_THERMAL)])
        return pd.DataFrame(rows, columns=cols)

    def to_frame(self):
        """One row per thermal bearing: inputs, temperatures, viscosity, power, flows,
        journal position, status. A thermal equilibrium that did not converge has no state:
        those columns are NaN, as in the sweep rows (the attributes keep the last iterate)."""
        import pandas as pd
        from rotordyn._common.status import CONVERGED

        n = len(self.bearing_names)
        df = pd.DataFrame({
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
            "carry_over_effective": self.wall("carry_over_effective"),
            "journal_x_m": self.journal_x_m,
            "journal_y_m": self.journal_y_m,
            "h_min_m": self.wall("h_min_m"),
            "h_min_z_m": self.wall("h_min_z_m"),
            **{c: self.wall(c) for c in WALL_COLUMNS},
            **(self.tilt or {}),
            "status": [self.status] * n,
            "message": [self.message] * n,
        })
        if self.status not in CONVERGED:
            inputs = ["speed_hz", "supply_temperature_c", "bearing", "thermal_model", "status",
                      "message"]
            for col in df.columns.difference(inputs):
                df[col] = np.nan
        return df


# The thermal outputs a point at its own thermal equilibrium carries (``thermal=`` of
# stability, Campbell, unbalance: their frames; ``options.thermal`` of those sweeps: their
# rows): per film (lists in the order of ``film``) and summarised over the films.
THERMAL_POINT_COLUMNS = ("film", "film_effective_temperature_c", "film_max_temperature_c",
                         "film_power_loss_w", "max_temperature_c", "power_loss_w",
                         "thermal_iterations")


def thermal_point_values(t: SystemThermalResult) -> dict:
    """The :data:`THERMAL_POINT_COLUMNS` of one point's thermal equilibrium (°C, W; NaN where
    it failed): lists per film, the hottest film's maximum, the total power loss."""
    from rotordyn._common.status import CONVERGED

    ok = t.status in CONVERGED
    nan = [float("nan")] * len(t.bearing_names)
    te = [float(x) for x in t.effective_temperature_c] if ok else nan
    tm = [float(x) for x in t.max_temperature_c] if ok else nan
    pw = [float(x) for x in t.power_loss_w] if ok else nan
    return {"film": list(t.bearing_names), "film_effective_temperature_c": te,
            "film_max_temperature_c": tm, "film_power_loss_w": pw,
            "max_temperature_c": max(tm) if ok else float("nan"),
            "power_loss_w": float(sum(pw)) if ok else float("nan"),
            "thermal_iterations": int(t.iterations)}


def thermal_frame_columns(results, repeat: int) -> dict:
    """Frame columns (:data:`THERMAL_POINT_COLUMNS`) of per-point thermal equilibria
    ``results`` (SystemThermalResult, or None where it raised: nulls), each point's values
    repeated ``repeat`` times (its modes or stations), points in order."""
    import pandas as pd

    vals = [thermal_point_values(t) if t is not None else None for t in results]
    out = {}
    for c in THERMAL_POINT_COLUMNS:
        col = []
        for v in vals:
            x = None if v is None else v[c]
            col += [x] * repeat
        if c == "thermal_iterations":
            out[c] = pd.array(col, dtype="Int64")
        elif c in ("max_temperature_c", "power_loss_w"):
            out[c] = np.array([np.nan if x is None else x for x in col], dtype=np.float64)
        else:
            out[c] = col
    return out
