"""Thermo-hydrodynamic (THD) film of a plain journal bearing (issue 20; docs/film-physics.md
§"Thermo-hydrodynamic film").

The film temperature T(φ, z), averaged across the film thickness, from a finite-volume energy
equation on the Reynolds grid (convection by the Reynolds flows, viscous dissipation, heat flux
to journal and bush through heat-transfer coefficients — adiabatic by default — and the inlet
mixing with hot-oil carry-over of the effective-temperature model), the viscosity μ(T) at every
node, iterated with the Reynolds equilibrium in one C++ call (``_core.thd_equilibrium``).
:meth:`rotordyn.JournalBearing.thermal_equilibrium` with ``model="thd"`` is the entry point and
returns a :class:`ThdEquilibriumResult`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings.thd_walls import WALL_OPTIONS, check_walls, set_walls
from rotordyn.bearings.thermal import (TiltedJournalOutputs, thermal_options, tilt_columns,
                                       untilted_h_min)
from rotordyn.errors import InputError

THERMAL_MODELS = ("effective", "thd")
"""The thermal film models: the effective-temperature model and the THD energy equation."""


def thd_options(*, supply_temperature_c, supply_flow_m3_s=0.0, carry_over=0.0,
                journal_htc_w_m2k=0.0, bush_htc_w_m2k=0.0, journal_temperature_c=None,
                bush_temperature_c=None, tol_k=1e-6, **walls) -> _core.ThdOptions:
    """The core's THD options (numbers checked here; ranges by the core, naming the field).
    ``journal_temperature_c``/``bush_temperature_c`` None: the supply temperature; ``walls``
    the heat paths of :mod:`rotordyn.bearings.thd_walls` (``wall_htc``, ``journal_wall``,
    ``bush_wall``, ``bush_thickness_m``, ...)."""
    o = _core.ThdOptions()
    o.supply_temperature_c = v.finite("supply_temperature_c", supply_temperature_c)
    o.supply_flow_m3_s = v.finite("supply_flow_m3_s", supply_flow_m3_s)
    o.carry_over = v.finite("carry_over", carry_over)
    o.journal_htc_w_m2k = v.finite("journal_htc_w_m2k", journal_htc_w_m2k)
    o.bush_htc_w_m2k = v.finite("bush_htc_w_m2k", bush_htc_w_m2k)
    if journal_temperature_c is not None:
        o.journal_temperature_c = v.finite("journal_temperature_c", journal_temperature_c)
    if bush_temperature_c is not None:
        o.bush_temperature_c = v.finite("bush_temperature_c", bush_temperature_c)
    o.tol_k = v.finite("tol_k", tol_k)
    w = check_walls(walls)
    if w["journal_wall"] == "balance" and journal_temperature_c is not None:
        raise InputError(f"journal_temperature_c: not used with journal_wall = 'balance' (the "
                         f"journal's temperature follows from its heat balance), got "
                         f"{journal_temperature_c}")
    if w["bush_wall"] == "conduction" and bush_temperature_c is not None:
        raise InputError(f"bush_temperature_c: not used with bush_wall = 'conduction' (the "
                         f"back face's oil is back_temperature_c), got {bush_temperature_c}")
    set_walls(o, w)
    return o


@dataclass(frozen=True, slots=True)
class ThdEquilibriumResult(TiltedJournalOutputs):
    """THD equilibrium of a plain film and its K, C (temperature field frozen).

    Temperatures °C: ``max_temperature_c``, ``mean_temperature_c`` (area-weighted over the
    film), ``inlet_temperature_c`` (after mixing), ``recirculation_temperature_c`` (mixing-cup
    of the flow reaching the inlet), ``side_temperature_c`` (of the side leakage). Flows m³/s:
    ``film_flow_m3_s`` Q from the inlet into the film, ``recirculation_flow_m3_s`` Q_r back to
    it, ``side_flow_m3_s``, ``supply_flow_m3_s`` Q_f. ``power_loss_w`` the dissipation of the
    energy equation, ``friction_power_w`` torque·|ω|; heat to journal/bush (W, 0 adiabatic);
    ``journal_temperature_c`` the journal's (fixed, or from its heat balance) and
    ``max_wall_temperature_c`` the hottest bush surface over the film (the film's own where no
    heat crosses; :mod:`rotordyn.bearings.thd_walls`).
    Fields (n_circ, n_axial + 1): ``temperature_c``, ``viscosity_pa_s`` (the field K, C and the
    equilibrium used), ``inlet_mask``, ``wall_temperature_c`` (the bush surface). K (N/m),
    C (N·s/m) 2×2 with dF = −K dq − C dq̇. A tilted journal: the tilt fields of
    :class:`rotordyn.bearings.ThermalEquilibriumResult` (moments, edge film, K4, C4).
    """

    speed_hz: float
    load_n: tuple[float, float]
    supply_temperature_c: float
    max_temperature_c: float
    mean_temperature_c: float
    inlet_temperature_c: float
    recirculation_temperature_c: float
    side_temperature_c: float
    power_loss_w: float
    friction_power_w: float
    film_flow_m3_s: float
    recirculation_flow_m3_s: float
    side_flow_m3_s: float
    supply_flow_m3_s: float
    heat_to_journal_w: float
    heat_to_bush_w: float
    journal_temperature_c: float
    max_wall_temperature_c: float
    x_m: float
    y_m: float
    eccentricity_ratio: float
    K: np.ndarray
    C: np.ndarray
    iterations: int
    temperature_c: np.ndarray = field(repr=False)
    viscosity_pa_s: np.ndarray = field(repr=False)
    inlet_mask: np.ndarray = field(repr=False)
    flows: dict = field(repr=False)
    wall_temperature_c: np.ndarray = field(repr=False, default=None)
    status: str = "ok"
    message: str = ""
    # λ_eff: the carried-over fraction of Q_r the inlet mixes (the given carry_over, or
    # (Q − Q_f)/Q_r where a metered supply falls short of the demand)
    carry_over_effective: float = math.nan

    def __repr__(self) -> str:
        return (f"ThdEquilibriumResult(T_max={self.max_temperature_c:.2f} degC, "
                f"T_mean={self.mean_temperature_c:.2f} degC, P={self.power_loss_w:.4g} W, "
                f"eps={self.eccentricity_ratio:.4f}, status={self.status!r})")

    def to_frame(self):
        """One row: inputs, temperatures, power, flows, journal position, K, C."""
        import pandas as pd

        row = {"speed_hz": self.speed_hz, "load_x_n": self.load_n[0],
               "load_y_n": self.load_n[1], "thermal_model": "thd"}
        for f in ("supply_temperature_c", "max_temperature_c", "mean_temperature_c",
                  "inlet_temperature_c", "recirculation_temperature_c", "side_temperature_c",
                  "power_loss_w", "friction_power_w", "film_flow_m3_s",
                  "recirculation_flow_m3_s", "side_flow_m3_s", "supply_flow_m3_s",
                  "carry_over_effective", "heat_to_journal_w", "heat_to_bush_w",
                  "journal_temperature_c",
                  "max_wall_temperature_c"):
            row[f] = getattr(self, f)
        row.update(journal_x_m=self.x_m, journal_y_m=self.y_m,
                   eccentricity_ratio=self.eccentricity_ratio)
        for name, A, unit in (("k", self.K, "n_per_m"), ("c", self.C, "n_s_per_m")):
            for i, a in enumerate("xy"):
                for j, b in enumerate("xy"):
                    row[f"{name}{a}{b}_{unit}"] = float(A[i, j])
        row.update(tilt_columns(self))
        row.update(iterations=self.iterations, status=self.status, message=self.message)
        return pd.DataFrame([row])

    def temperature_frame(self):
        """The field, one row per node: ``phi_deg``, ``z_index``, ``temperature_c``,
        ``viscosity_pa_s``."""
        import pandas as pd

        n, k1 = self.temperature_c.shape
        j, k = np.meshgrid(np.arange(n), np.arange(k1), indexing="ij")
        return pd.DataFrame({"phi_deg": (360.0 * j / n).ravel(), "z_index": k.ravel(),
                             "temperature_c": self.temperature_c.ravel(),
                             "viscosity_pa_s": self.viscosity_pa_s.ravel()})

    def plot(self, ax=None):
        """The temperature field over (φ, z index) as an image (matplotlib Axes)."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        im = ax.imshow(self.temperature_c.T, origin="lower", aspect="auto",
                       extent=(0.0, 360.0, 0, self.temperature_c.shape[1] - 1))
        ax.set_xlabel("phi, deg")
        ax.set_ylabel("axial node")
        ax.figure.colorbar(im, ax=ax, label="film temperature, degC")
        return ax


def run_thd_equilibrium(solver, oil, opts, load_n, speed_hz: float,
                        clearance_m: float) -> ThdEquilibriumResult:
    """One C++ call (GIL released) on ``solver`` (it keeps the final viscosity field)."""
    from rotordyn.bearings.thermal import Oil

    if not isinstance(oil, Oil):
        raise InputError(f"oil: expected a rotordyn.bearings.Oil, got {oil!r}")
    r = _core.thd_equilibrium(solver, oil.to_core(), opts, float(load_n[0]), float(load_n[1]),
                              2.0 * math.pi * float(speed_hz))
    e, dc, st = r.equilibrium, r.coefficients, r.film
    fl = st.flows
    flows = {name: np.array(getattr(fl, name)) for name in
             ("q_phi_m3_s", "q_z_m3_s", "fill", "dissipation_w", "area_m2", "makeup_m3_s")}
    return ThdEquilibriumResult(
        speed_hz=float(speed_hz), load_n=(float(load_n[0]), float(load_n[1])),
        supply_temperature_c=float(opts.supply_temperature_c),
        max_temperature_c=st.max_temperature_c, mean_temperature_c=st.mean_temperature_c,
        inlet_temperature_c=st.inlet_temperature_c,
        recirculation_temperature_c=st.recirculation_temperature_c,
        side_temperature_c=st.side_temperature_c, power_loss_w=st.power_loss_w,
        friction_power_w=st.friction_power_w, film_flow_m3_s=st.film_flow_m3_s,
        recirculation_flow_m3_s=st.recirculation_flow_m3_s, side_flow_m3_s=st.side_flow_m3_s,
        supply_flow_m3_s=st.supply_flow_m3_s, carry_over_effective=st.carry_over_effective,
        heat_to_journal_w=st.heat_to_journal_w,
        heat_to_bush_w=st.heat_to_bush_w, journal_temperature_c=st.journal_temperature_c,
        max_wall_temperature_c=st.max_wall_temperature_c, x_m=float(e.x_m), y_m=float(e.y_m),
        eccentricity_ratio=math.hypot(e.x_m, e.y_m) / clearance_m,
        **untilted_h_min(float(e.x_m), float(e.y_m), clearance_m),
        K=np.array(dc.K), C=np.array(dc.C), iterations=int(r.iterations),
        temperature_c=np.array(st.temperature_c), viscosity_pa_s=np.array(fl.viscosity_pa_s),
        inlet_mask=np.array(st.inlet_mask), flows=flows,
        wall_temperature_c=np.array(st.wall_temperature_c))


def film_thermal_options(model: str, thd: dict, *, supply_temperature_c: float,
                         supply_flow_m3_s: float, carry_over: float, effective_factor: float,
                         tol_k: float):
    """The checked options of a standalone film's thermal equilibrium: ``model`` "effective"
    (:func:`rotordyn.bearings.thermal.thermal_options`) or "thd" (:func:`thd_options`, with
    the keyword options ``thd``: heat-transfer coefficients W/(m² K), wall temperatures °C,
    the wall options of :mod:`rotordyn.bearings.thd_walls`).
    InputError naming the model or the option."""
    v.choice("model", model, THERMAL_MODELS)
    # an unknown keyword first, whatever the model (before: with model="effective" any
    # keyword, e.g. a tilt, was called "an option of model='thd' only", which it was not)
    unknown = set(thd) - {"journal_htc_w_m2k", "bush_htc_w_m2k",
                          "journal_temperature_c", "bush_temperature_c", *WALL_OPTIONS}
    if unknown:
        raise InputError(f"{sorted(unknown)[0]}: not an option of the thermal equilibrium")
    if model == "effective":
        if thd:
            raise InputError(f"{sorted(thd)[0]}: an option of model='thd' only")
        return thermal_options(supply_temperature_c=supply_temperature_c,
                               supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                               effective_factor=effective_factor, tol_k=tol_k)
    return thd_options(supply_temperature_c=supply_temperature_c,
                       supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                       tol_k=tol_k, **thd)


__all__ = ["THERMAL_MODELS", "ThdEquilibriumResult", "film_thermal_options", "thd_options"]

