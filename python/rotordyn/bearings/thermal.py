"""Effective-temperature thermal model of a plain journal film (issue 20; docs/film-physics.md).

The oil (:class:`Oil`): a viscosity–temperature law — Walther/ASTM D341 through two points
(e.g. an ISO VG grade's kinematic viscosities at 40 °C and 100 °C), or an exponential law
μ = μ_ref exp(−β (T − T_ref)) — with density and specific heat. The heat balance (global,
adiabatic: all friction power into the oil; Raimondi–Boyd/Shigley assumptions with hot-oil
carry-over) and its iteration with the Reynolds equilibrium run in C++ as one unit of work
(``_core.thermal_equilibrium``); :meth:`rotordyn.JournalBearing.thermal_equilibrium` is the
entry point and returns a :class:`ThermalEquilibriumResult`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings.thd_walls import WALL_OPTIONS, check_walls
from rotordyn.bearings.tilt_names import RenamedTiltOutputs
from rotordyn.errors import InputError

VISCOSITY_LAWS = ("walther", "exponential", "power")
_OIL_NUMBERS = ("t1_c", "nu1_mm2_s", "t2_c", "nu2_mm2_s", "mu_ref_pa_s", "t_ref_c",
                "beta_1_per_k", "mu1_pa_s", "mu2_pa_s", "density_kg_m3",
                "specific_heat_j_per_kg_k", "conductivity_w_per_m_k", "t_min_c", "t_max_c")


@dataclass(frozen=True, slots=True)
class Oil:
    """Lubricant: viscosity law and properties (SI; temperatures in °C).

    Parameters
    ----------
    viscosity_law : "walther" (ASTM D341 through (t1_c, nu1_mm2_s), (t2_c, nu2_mm2_s), μ = ρν)
        or "exponential" (μ = mu_ref_pa_s · exp(−beta_1_per_k (T − t_ref_c)))
        or "power" (μ = a T^b with T in °C, the law of ROSS's thermal bearings, through
        (t1_c, mu1_pa_s), (t2_c, mu2_pa_s); needs t_min_c > 0 °C).
    density_kg_m3, specific_heat_j_per_kg_k : ρ, c_p (constant).
    conductivity_w_per_m_k : k, W/(m K) (constant; 0.13, a mineral oil): the THD film's
        conduction across its thickness to its walls (``wall_htc = "film"``,
        :mod:`rotordyn.bearings.thd_walls`); no other model uses it.
    t_min_c, t_max_c : range of the law; supply and film temperatures must lie in it.
    """

    viscosity_law: str = "walther"
    t1_c: float = 40.0
    nu1_mm2_s: float = 32.0
    t2_c: float = 100.0
    nu2_mm2_s: float = 5.4
    mu_ref_pa_s: float = 0.03
    t_ref_c: float = 40.0
    beta_1_per_k: float = 0.03
    mu1_pa_s: float = 0.0278
    mu2_pa_s: float = 0.0047
    density_kg_m3: float = 870.0
    specific_heat_j_per_kg_k: float = 2000.0
    conductivity_w_per_m_k: float = 0.13
    t_min_c: float = -20.0
    t_max_c: float = 200.0

    def __post_init__(self) -> None:
        v.choice("oil.viscosity_law", self.viscosity_law, VISCOSITY_LAWS)
        for f in _OIL_NUMBERS:
            object.__setattr__(self, f, v.finite(f"oil.{f}", getattr(self, f)))
        self.to_core().validate()  # InputError naming the field (and its range)

    def to_core(self) -> _core.OilModel:
        o = _core.OilModel()
        o.law = self.viscosity_law
        for f in _OIL_NUMBERS:
            setattr(o, f, float(getattr(self, f)))
        return o

    def viscosity_pa_s(self, t_c) -> np.ndarray | float:
        """μ(T), Pa·s, at temperatures ``t_c`` (°C, scalar or array)."""
        o = self.to_core()
        f = np.vectorize(lambda t: o.viscosity_pa_s(float(t)))
        out = f(np.asarray(t_c, dtype=float))
        return float(out) if np.ndim(out) == 0 else out


@dataclass(frozen=True, slots=True, kw_only=True)
class TiltedJournalOutputs(RenamedTiltOutputs):
    """A tilted journal's outputs of a thermal equilibrium (rotordyn.bearings.tilt_thermal):
    its tilt relative to the bearing (rad), the film's force (N, Fx, Fy: it carries the load)
    and moments (N·m, about x, y) on it at the frozen temperature, the edge film (m, its angle
    deg and z m) and K, C 4×4 over (x, y, θx, θy) at the frozen temperature; None untilted.
    Keyword-only, after the result's own fields; the names of the system's outputs
    (:mod:`rotordyn.bearings.tilt_names`)."""
    journal_theta_x_rad: float = 0.0
    journal_theta_y_rad: float = 0.0
    force_n: np.ndarray | None = field(default=None, repr=False)
    film_moment_n_m: np.ndarray | None = field(default=None, repr=False)
    h_min_m: float = math.nan
    h_min_angle_deg: float = math.nan
    h_min_z_m: float = math.nan
    K4: np.ndarray | None = field(default=None, repr=False)
    C4: np.ndarray | None = field(default=None, repr=False)


@dataclass(frozen=True, slots=True)
class ThermalEquilibriumResult(TiltedJournalOutputs):
    """Effective-temperature equilibrium of a plain film and its K, C (temperature frozen).

    Temperatures °C; ``temperature_rise_k`` ΔT (K); flows m³/s (``film_flow_m3_s`` Q across
    the line of maximum film, ``side_flow_m3_s`` Q_s, ``supply_flow_m3_s`` the fresh oil);
    ``power_loss_w`` the friction power; K (N/m), C (N·s/m) 2×2 with dF = −K dq − C dq̇.
    A tilted journal (``thermal_equilibrium(..., theta_x_rad, theta_y_rad)``, inputs): the
    tilt ``journal_theta_x_rad``, ``journal_theta_y_rad``, the film's force ``force_n`` (N)
    and moments ``film_moment_n_m`` (N·m), the edge film ``h_min_m`` at ``h_min_angle_deg``,
    ``h_min_z_m`` and ``K4``, ``C4`` (4×4 over x, y, θx, θy) at the frozen temperature.
    """

    speed_hz: float
    load_n: tuple[float, float]
    supply_temperature_c: float
    effective_temperature_c: float
    max_temperature_c: float
    inlet_temperature_c: float
    temperature_rise_k: float
    viscosity_pa_s: float
    power_loss_w: float
    film_flow_m3_s: float
    side_flow_m3_s: float
    supply_flow_m3_s: float
    x_m: float
    y_m: float
    eccentricity_ratio: float
    K: np.ndarray
    C: np.ndarray
    iterations: int
    status: str = "ok"
    message: str = ""
    # λ_eff: the carried-over fraction of the recirculating flow the inlet mixes (the given
    # carry_over, or (Q − Q_f)/(Q − Q_s) where a metered supply falls short of the demand)
    carry_over_effective: float = math.nan

    def __repr__(self) -> str:
        return (f"ThermalEquilibriumResult(T_eff={self.effective_temperature_c:.2f} degC, "
                f"T_max={self.max_temperature_c:.2f} degC, mu={self.viscosity_pa_s:.4g} Pa s, "
                f"P={self.power_loss_w:.4g} W, eps={self.eccentricity_ratio:.4f}, "
                f"status={self.status!r})")

    def to_frame(self):
        """One row: inputs, temperatures, viscosity, power, flows, journal position, K, C."""
        import pandas as pd

        row = {
            "speed_hz": self.speed_hz, "load_x_n": self.load_n[0], "load_y_n": self.load_n[1],
            "supply_temperature_c": self.supply_temperature_c,
            "effective_temperature_c": self.effective_temperature_c,
            "max_temperature_c": self.max_temperature_c,
            "inlet_temperature_c": self.inlet_temperature_c,
            "temperature_rise_k": self.temperature_rise_k,
            "viscosity_pa_s": self.viscosity_pa_s, "power_loss_w": self.power_loss_w,
            "film_flow_m3_s": self.film_flow_m3_s, "side_flow_m3_s": self.side_flow_m3_s,
            "supply_flow_m3_s": self.supply_flow_m3_s,
            "carry_over_effective": self.carry_over_effective,
            "journal_x_m": self.x_m, "journal_y_m": self.y_m,
            "eccentricity_ratio": self.eccentricity_ratio,
        }
        for name, A, unit in (("k", self.K, "n_per_m"), ("c", self.C, "n_s_per_m")):
            for i, a in enumerate("xy"):
                for j, b in enumerate("xy"):
                    row[f"{name}{a}{b}_{unit}"] = float(A[i, j])
        row.update(tilt_columns(self))
        row.update(iterations=self.iterations, status=self.status, message=self.message)
        return pd.DataFrame([row])


def untilted_h_min(x_m: float, y_m: float, clearance_m: float) -> dict:
    """The minimum film of an untilted journal at (x, y) (m) and its angle (deg, from +x
    towards +y), c − e as the core's rigid film gives it; its z is the whole length (NaN)."""
    e = math.hypot(x_m, y_m)
    ang = math.degrees(math.atan2(y_m, x_m)) % 360.0 if e > 0.0 else 0.0
    return {"h_min_m": clearance_m - e, "h_min_angle_deg": ang}


def tilt_columns(res) -> dict:
    """A tilted plain film's columns (none untilted): its tilt, moments and edge film."""
    if res.K4 is None:
        return {}
    return {"journal_theta_x_rad": res.journal_theta_x_rad,
            "journal_theta_y_rad": res.journal_theta_y_rad,
            "film_moment_x_n_m": float(res.film_moment_n_m[0]),
            "film_moment_y_n_m": float(res.film_moment_n_m[1]),
            "h_min_m": res.h_min_m, "h_min_angle_deg": res.h_min_angle_deg,
            "h_min_z_m": res.h_min_z_m}


def thermal_options(*, supply_temperature_c, supply_flow_m3_s=0.0, carry_over=0.0,
                    effective_factor=0.5, tol_k=1e-6) -> _core.ThermalOptions:
    """The core's options (numbers checked here; ranges by the core, naming the field)."""
    o = _core.ThermalOptions()
    o.supply_temperature_c = v.finite("supply_temperature_c", supply_temperature_c)
    o.supply_flow_m3_s = v.finite("supply_flow_m3_s", supply_flow_m3_s)
    o.carry_over = v.finite("carry_over", carry_over)
    o.effective_factor = v.finite("effective_factor", effective_factor)
    o.tol_k = v.finite("tol_k", tol_k)
    return o


def run_thermal_equilibrium(solver, oil: Oil, opts, load_n, speed_hz: float,
                            clearance_m: float) -> ThermalEquilibriumResult:
    """One C++ call (GIL released) on ``solver`` (its viscosity is changed)."""
    if not isinstance(oil, Oil):
        from rotordyn.errors import InputError

        raise InputError(f"oil: expected a rotordyn.bearings.Oil, got {oil!r}")
    r = _core.thermal_equilibrium(solver, oil.to_core(), opts, float(load_n[0]),
                                  float(load_n[1]), 2.0 * math.pi * float(speed_hz))
    e, dc = r.equilibrium, r.coefficients
    return ThermalEquilibriumResult(
        speed_hz=float(speed_hz), load_n=(float(load_n[0]), float(load_n[1])),
        supply_temperature_c=float(opts.supply_temperature_c),
        effective_temperature_c=r.effective_temperature_c, max_temperature_c=r.max_temperature_c,
        inlet_temperature_c=r.inlet_temperature_c, temperature_rise_k=r.temperature_rise_k,
        viscosity_pa_s=r.viscosity_pa_s, power_loss_w=r.power_loss_w,
        film_flow_m3_s=r.film_flow_m3_s, side_flow_m3_s=r.side_flow_m3_s,
        supply_flow_m3_s=r.supply_flow_m3_s, carry_over_effective=r.carry_over_effective,
        x_m=float(e.x_m), y_m=float(e.y_m),
        eccentricity_ratio=math.hypot(e.x_m, e.y_m) / clearance_m,
        **untilted_h_min(float(e.x_m), float(e.y_m), clearance_m),
        K=np.array(dc.K), C=np.array(dc.C), iterations=int(r.iterations))


def _check_settings(obj) -> None:
    """The heat-balance settings' ranges (those of the core's check, named by field)."""
    for f in ("carry_over", "effective_factor", "supply_flow_m3_s"):
        object.__setattr__(obj, f, v.finite(f, getattr(obj, f)))
    if not 0.0 <= obj.carry_over <= 1.0:
        raise InputError(f"carry_over: expected 0 <= carry_over <= 1, got {obj.carry_over}")
    if not 0.5 <= obj.effective_factor <= 1.0:
        raise InputError(f"effective_factor: expected 0.5 <= effective_factor <= 1, got "
                         f"{obj.effective_factor}")
    if obj.supply_flow_m3_s < 0.0:
        raise InputError(f"supply_flow_m3_s: expected >= 0 (0: the film's own demand), got "
                         f"{obj.supply_flow_m3_s}")


@dataclass(frozen=True, slots=True)
class ThermalFilm:
    """One bearing's own heat-balance settings in a :class:`ThermalModel` (``[[thermal.film]]``).

    ``bearing`` is the bearing's name in the model; ``carry_over`` λ (0..1, hot oil carried
    over the supply groove), ``effective_factor`` k (0..1, T_eff = T_in + k ΔT) and
    ``supply_flow_m3_s`` (m³/s, 0: the film's own demand) as in
    :meth:`rotordyn.JournalBearing.thermal_equilibrium`.
    """

    bearing: str
    carry_over: float = 0.0
    effective_factor: float = 0.5
    supply_flow_m3_s: float = 0.0

    def __post_init__(self) -> None:
        v.text("bearing", self.bearing)
        if not self.bearing:
            raise InputError("bearing: the name of a bearing of the model, got ''")
        _check_settings(self)

    @property
    def name(self) -> str:  # sweep paths address films by bearing name (thermal.films.DE...)
        return self.bearing


@dataclass(frozen=True, slots=True)
class ThermalModel:
    """The model file's ``[thermal]`` table: one oil system feeding every plain journal bearing.

    ``oil`` the lubricant (:class:`Oil`), ``supply_temperature_c`` its supply temperature (°C);
    ``carry_over``, ``effective_factor``, ``supply_flow_m3_s`` the heat-balance settings of
    every bearing that has no entry of its own in ``films`` (:class:`ThermalFilm`, by bearing
    name). Used by :func:`rotordyn.analysis.system_thermal_equilibrium` and ``rotordyn
    thermal`` when they are given no oil of their own. ``model``: "effective" (the
    effective-temperature heat balance) or "thd" (the thermo-hydrodynamic film, with the
    heat-transfer coefficients ``journal_htc_w_m2k``, ``bush_htc_w_m2k`` W/(m² K), 0:
    adiabatic, to walls at ``journal_temperature_c``, ``bush_temperature_c`` °C, None: the
    supply temperature; and the walls' own heat paths ``wall_htc``, ``journal_wall``,
    ``bush_wall``, ``bush_thickness_m``, ``bush_conductivity_w_per_m_k``, ``back_htc_w_m2k``,
    ``back_temperature_c`` of :mod:`rotordyn.bearings.thd_walls`, for every bearing; on pad
    bearings the "bush" is each pad).
    """

    supply_temperature_c: float
    oil: Oil = Oil()
    carry_over: float = 0.0
    effective_factor: float = 0.5
    supply_flow_m3_s: float = 0.0
    films: tuple[ThermalFilm, ...] = ()
    model: str = "effective"
    journal_htc_w_m2k: float = 0.0
    bush_htc_w_m2k: float = 0.0
    journal_temperature_c: float | None = None
    bush_temperature_c: float | None = None
    wall_htc: str = "given"
    journal_wall: str = "fixed"
    bush_wall: str = "fixed"
    bush_thickness_m: float = 0.0
    bush_conductivity_w_per_m_k: float = 0.0
    back_htc_w_m2k: float = 0.0
    back_temperature_c: float | None = None

    def __post_init__(self) -> None:
        v.choice("thermal.model", self.model, ("effective", "thd"))
        walls = check_walls({f: getattr(self, f) for f in WALL_OPTIONS}, "thermal.")
        for f in WALL_OPTIONS:
            object.__setattr__(self, f, walls[f])
        if self.journal_wall == "balance" and self.journal_temperature_c is not None:
            raise InputError("thermal.journal_temperature_c: not used with journal_wall = "
                             "'balance' (the journal's temperature follows from its heat "
                             f"balance), got {self.journal_temperature_c}")
        if self.bush_wall == "conduction" and self.bush_temperature_c is not None:
            raise InputError("thermal.bush_temperature_c: not used with bush_wall = "
                             "'conduction' (the back face's oil is back_temperature_c), got "
                             f"{self.bush_temperature_c}")
        for f in ("journal_temperature_c", "bush_temperature_c"):
            if getattr(self, f) is not None:
                object.__setattr__(self, f, v.finite(f, getattr(self, f)))
        for f in ("journal_htc_w_m2k", "bush_htc_w_m2k"):
            val = v.finite(f, getattr(self, f))
            if val < 0.0:
                raise InputError(f"{f}: expected >= 0 W/(m^2 K) (0: adiabatic), got {val}")
            object.__setattr__(self, f, val)
        if not isinstance(self.oil, Oil):
            raise InputError(f"oil: expected a rotordyn.bearings.Oil, got {self.oil!r}")
        object.__setattr__(self, "films", tuple(self.films))
        for i, f in enumerate(self.films):
            if not isinstance(f, ThermalFilm):
                raise InputError(f"films[{i}]: expected a ThermalFilm, got {type(f).__name__}")
        names = [f.bearing for f in self.films]
        if len(set(names)) != len(names):
            raise InputError(f"films: one entry per bearing, got {names}")
        object.__setattr__(self, "supply_temperature_c",
                           v.finite("supply_temperature_c", self.supply_temperature_c))
        _check_settings(self)
        if not self.oil.t_min_c <= self.supply_temperature_c < self.oil.t_max_c:
            raise InputError(f"supply_temperature_c: expected a temperature in the oil's range "
                             f"[{self.oil.t_min_c}, {self.oil.t_max_c}) degC, got "
                             f"{self.supply_temperature_c}")

    def film(self, bearing_name: str) -> ThermalFilm:
        """The settings of the bearing named ``bearing_name`` (its entry or the defaults)."""
        for f in self.films:
            if f.bearing == bearing_name:
                return f
        return ThermalFilm(bearing=bearing_name or "-", carry_over=self.carry_over,
                           effective_factor=self.effective_factor,
                           supply_flow_m3_s=self.supply_flow_m3_s)

    def options(self, bearing_name: str | None = None, tol_k: float = 1e-6):
        """The core's options for the bearing named ``bearing_name`` (None: the defaults)."""
        f = self.film(bearing_name) if bearing_name is not None else self
        return thermal_options(supply_temperature_c=self.supply_temperature_c,
                               supply_flow_m3_s=f.supply_flow_m3_s, carry_over=f.carry_over,
                               effective_factor=f.effective_factor, tol_k=tol_k)


__all__ = ["Oil", "ThermalEquilibriumResult", "ThermalFilm", "ThermalModel", "TiltedJournalOutputs",
           "VISCOSITY_LAWS", "untilted_h_min"]
