"""Thermo-hydrodynamic (THD) films of pad bearings: tilting pads and the lobes of
fixed-geometry bearings (issue 20; docs/film-physics.md §"THD pad bearings").

Each pad (lobe) has the plain film's energy equation on its own grid (upwind convection by the
Reynolds flows, viscous dissipation, adiabatic or heat transfer to journal and pad), the
viscosity μ(T) per node; the gap between the pads is the inlet. The inlet temperature of pad k
mixes fresh oil at the supply temperature with the hot oil the upstream pad k − 1 (in the
direction of rotation) passes on at its trailing edge — Ettles' hot-oil carry-over
(C. M. McC. Ettles, "Hot oil carry-over in thrust bearings", Proc. IMechE 184 (3L), 1969–70,
75–81; the same mixing balance as in Ettles' tilting-pad journal analyses):

    T_in,k = (Q_f,k T_s + λ Q_out,k−1 T_out,k−1) / (Q_f,k + λ Q_out,k−1),
    Q_f,k = Q_in,k − λ Q_out,k−1   (the pad's own demand; or the given supply flow / n_pads),

(a metered share below the pad's demand draws more hot oil, λ_eff = (Q_in,k − Q_f,k)/Q_out,k−1,
mass-conserving; Q_f,k + Q_out,k−1 < Q_in,k starves the bearing: status "starved",
docs/film-physics.md "A metered supply below the film's demand"),
λ the carry-over (mixing) coefficient in [0, 1] (``carry_over``), Q_out = Q_in − Q_s the pad's
own mass balance (inflow at the leading edge minus side leakage) and T_out the mixing-cup
temperature of the flow its trailing-edge cells receive. Each field is affine in its
inlet temperature, so the ring of inlet temperatures is solved exactly (a small linear system)
at every outer step. The energy equations, the pad equilibrium (tilts and journal, the
pad-assembly Newton of ``pad_equilibrium.cpp``) and μ(T) are iterated in one C++ call
(``_core.thermal_system_equilibrium``). K and C are the perturbation coefficients at the
thermal equilibrium with the **temperature (viscosity) field frozen**, reduced over the pads'
coordinates at the whirl frequency as for the isothermal bearing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings.tilt_names import RenamedTiltOutputs
from rotordyn.errors import ConvergenceError, InputError, status_error


def failed_equilibrium(what: str, eq) -> ConvergenceError:
    """The ConvergenceError of a thermal equilibrium ``eq`` (the core's EquilibriumResult)
    that did not converge, carrying its ``status`` and ``detail`` (the core's message) for a
    caller that reports the failed point as a status record (``rotordyn bearing``)."""
    exc = status_error(eq.status, f"{what}: {eq.status}: {eq.message}")
    exc.status, exc.detail = str(eq.status), str(eq.message)
    return exc


def pad_fields(fields, films, where: str):
    """Check a frozen per-pad viscosity field ((n_pads,) arrays (N_pad, n_axial + 1), Pa·s)
    against the pad films and put it on their couplings. InputError naming ``where``."""
    if fields is None:
        return
    if len(fields) != len(films):
        raise InputError(f"{where}: expected {len(films)} pad fields, got {len(fields)}")
    for k, (f, pf) in enumerate(zip(fields, films)):
        a = np.asarray(f, dtype=float)
        shape = (pf.coupling.grid.n_circ, pf.coupling.grid.n_axial + 1)
        if a.shape != shape or not np.all(np.isfinite(a)) or not np.all(a > 0.0):
            raise InputError(f"{where}[{k}]: expected finite values > 0 of shape {shape}, got "
                             f"shape {a.shape}")
        pf.coupling.viscosity_field = a


def freeze_fields(fields) -> tuple:
    """A per-pad field as nested tuples (hashable, for the frozen bearing dataclasses)."""
    return tuple(tuple(map(tuple, np.asarray(f, dtype=float).tolist())) for f in fields)


def pad_thermal_films(first_film: int, n_pads: int, first: int, oil, opts, omega: float):
    """The core's thermal films of one pad bearing's ``n_pads`` films (model indices
    ``first_film``…), placed at ``first``… in the thermal list, each pad's upstream the pad
    before it in the direction of rotation (sign of ``omega``). ``opts``: ``_core.ThdOptions``
    (the THD film) or ``_core.ThermalOptions`` (the effective-temperature model per pad)."""
    thd = isinstance(opts, _core.ThdOptions)
    out = []
    for k in range(n_pads):
        tf = _core.ThermalFilm()
        tf.film = first_film + k
        tf.oil = oil
        tf.thd = thd
        if thd:
            tf.thd_options = opts
        else:
            tf.options = opts
        tf.upstream = first + ((k - 1) % n_pads if omega > 0 else (k + 1) % n_pads)
        out.append(tf)
    return out


def pad_options(opts, n_pads: int):
    """Per-pad options (THD or effective): a given total supply flow is shared equally by the
    pads."""
    if opts.supply_flow_m3_s > 0.0:
        thd = isinstance(opts, _core.ThdOptions)
        o = _core.ThdOptions() if thd else _core.ThermalOptions()
        for f in ("supply_temperature_c", "carry_over", "tol_k", "max_iter") + (
                ("journal_htc_w_m2k", "bush_htc_w_m2k", "journal_temperature_c",
                 "bush_temperature_c", "film_htc", "wall_eddy_conductivity",
                 "journal_balance", "bush_conduction", "bush_thickness_m",
                 "bush_conductivity_w_per_m_k", "back_htc_w_m2k", "back_temperature_c")
                if thd else ("effective_factor",)):
            setattr(o, f, getattr(opts, f))
        o.supply_flow_m3_s = opts.supply_flow_m3_s / n_pads
        return o
    return opts


def check_carry_over(value, field: str = "carry_over") -> float:
    """The carry-over (mixing) coefficient λ in [0, 1] (InputError naming ``field``)."""
    x = v.finite(field, value)
    if not 0.0 <= x <= 1.0:
        raise InputError(f"{field}: expected 0 <= {field.rsplit('.', 1)[-1]} <= 1 (the hot-oil "
                         f"carry-over, mixing coefficient), got {x}")
    return x


def pad_model_options(model: str, *, supply_temperature_c, supply_flow_m3_s, carry_over,
                      effective_factor, tol_k, **walls):
    """The checked options of a standalone pad bearing's thermal equilibrium: ``model``
    "thd" (``_core.ThdOptions`` with the wall options ``walls``) or "effective"
    (``_core.ThermalOptions``; ``effective_factor`` k; a wall option other than its default
    is an InputError naming it, as for the plain film)."""
    from rotordyn.bearings.thd import film_thermal_options

    given = {k: x for k, x in walls.items() if x is not None and not (
        k in ("journal_htc_w_m2k", "bush_htc_w_m2k") and x == 0.0)} \
        if model == "effective" else walls
    return film_thermal_options(model, given, supply_temperature_c=supply_temperature_c,
                                supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                                effective_factor=effective_factor, tol_k=tol_k)


@dataclass(frozen=True, slots=True)
class PadThdResult(RenamedTiltOutputs):
    """THD equilibrium of a pad bearing (tilting pads or fixed-geometry lobes) and its K, C
    with the temperature field frozen.

    Per pad (arrays (n_pads,)): temperatures °C ``max_temperature_c``, ``mean_temperature_c``
    (area mean over the pad), ``inlet_temperature_c`` (after mixing), ``outlet_temperature_c``
    (mixing-cup of the hot oil leaving the trailing edge); ``power_loss_w`` (dissipation of the
    pad's cells); flows m³/s ``film_flow_m3_s`` (into the pad at its leading edge),
    ``outlet_flow_m3_s`` (out at its trailing edge: Q_in − Q_s), ``side_flow_m3_s``, ``supply_flow_m3_s``
    (fresh oil). Totals: the properties ``max_temperature_c_total`` … and
    :meth:`to_frame`'s ``total`` row. Journal position (m), pad tilts (rad; tilting pads),
    K (N/m), C (N·s/m) 2×2 reduced over the pad coordinates at the whirl frequency (dF =
    −K dq − C dq̇), ``K_full``, ``C_full``, ``M_full`` unreduced over [x, y, pad coordinates].
    Fields per pad (N_pad, n_axial + 1): ``temperature_c``, ``viscosity_pa_s`` (the frozen
    field), ``inlet_mask``, ``flows`` (face flows, cell dissipation and area).

    A tilted journal (:meth:`rotordyn.bearings.FixedGeometryBearing.thermal_equilibrium` or
    :meth:`rotordyn.bearings.TiltingPadBearing.thermal_equilibrium` with the inputs
    ``theta_x_rad``, ``theta_y_rad`` or ``tilt = True``): the tilt ``journal_theta_x_rad``,
    ``journal_theta_y_rad``, the film's force ``force_n`` (Fx, Fy) N and moments
    ``film_moment_n_m`` (Mx, My) N·m on the journal, the edge film ``h_min_m`` at
    ``h_min_angle_deg``, ``h_min_z_m``, and ``K4``, ``C4`` (4×4 over x, y, θx, θy,
    ΔH = −K Δr − C Δṙ) at the frozen field (the names of
    :mod:`rotordyn.bearings.tilt_names`).

    ``thermal_model = "effective"`` (the effective-temperature model per pad): each pad is
    isoviscous at μ(T_eff); ``mean_temperature_c`` (also :attr:`effective_temperature_c`) is
    T_eff = T_in + k ΔT, ``max_temperature_c`` = ``outlet_temperature_c`` = T_in + ΔT,
    ``viscosity_pa_s`` the pads' uniform fields μ(T_eff) (frozen for K, C); no
    ``temperature_c``, ``inlet_mask`` or ``flows`` fields."""

    speed_hz: float
    load_n: tuple
    supply_temperature_c: float
    max_temperature_c: np.ndarray
    mean_temperature_c: np.ndarray
    inlet_temperature_c: np.ndarray
    outlet_temperature_c: np.ndarray
    power_loss_w: np.ndarray
    film_flow_m3_s: np.ndarray
    outlet_flow_m3_s: np.ndarray
    side_flow_m3_s: np.ndarray
    supply_flow_m3_s: np.ndarray
    x_m: float
    y_m: float
    eccentricity_ratio: float
    pad_tilts_rad: np.ndarray
    K: np.ndarray
    C: np.ndarray
    K_full: np.ndarray = field(repr=False)
    C_full: np.ndarray = field(repr=False)
    M_full: np.ndarray = field(repr=False)
    r: np.ndarray = field(repr=False)
    iterations: int = 0
    temperature_c: tuple = field(default=(), repr=False)
    viscosity_pa_s: tuple = field(default=(), repr=False)
    inlet_mask: tuple = field(default=(), repr=False)
    flows: tuple = field(default=(), repr=False)
    status: str = "ok"
    message: str = ""
    thermal_model: str = "thd"
    # a tilted journal (fixed-geometry, tilting pads; rotordyn.bearings.tilt_thermal): its tilt
    # relative to the bearing (rad), the film's force (N) and moments (N·m, about x, y) on it,
    # the edge film (m, its angle deg and z) and K, C 4×4 over (x, y, θx, θy) at the frozen
    # field; None untilted (the names of rotordyn.bearings.tilt_names)
    journal_theta_x_rad: float = 0.0
    journal_theta_y_rad: float = 0.0
    film_moment_n_m: np.ndarray | None = field(default=None, repr=False)
    h_min_m: float = math.nan
    h_min_z_m: float = math.nan
    force_n: np.ndarray | None = field(default=None, repr=False)
    h_min_angle_deg: float = math.nan
    K4: np.ndarray | None = field(default=None, repr=False)
    C4: np.ndarray | None = field(default=None, repr=False)
    # the THD pads' walls (rotordyn.bearings.thd_walls), per pad: heat to the journal and to
    # the pad (W), the journal's temperature (°C; one per bearing, repeated), the hottest pad
    # surface (°C) and the pad surface fields; None for the effective model
    heat_to_journal_w: np.ndarray | None = field(default=None, repr=False)
    heat_to_bush_w: np.ndarray | None = field(default=None, repr=False)
    journal_temperature_c: np.ndarray | None = field(default=None, repr=False)
    max_wall_temperature_c: np.ndarray | None = field(default=None, repr=False)
    wall_temperature_c: tuple = field(default=(), repr=False)
    # per pad: λ_eff, the carried-over fraction of the upstream pad's outflow its inlet mixes
    # (the given carry_over, or (Q − Q_f)/Q_out,u where its metered supply share falls short)
    carry_over_effective: np.ndarray | None = field(default=None, repr=False)

    @property
    def effective_temperature_c(self) -> np.ndarray:
        """Per pad: T_eff (effective model), the area mean (THD), °C."""
        return self.mean_temperature_c

    @property
    def max_temperature_c_total(self) -> float:
        return float(np.max(self.max_temperature_c))

    @property
    def mean_temperature_c_total(self) -> float:
        """Mean over all pads' areas (pads of equal area: the mean of the pad means)."""
        return float(np.mean(self.mean_temperature_c))

    @property
    def max_wall_temperature_c_total(self) -> float:
        """The hottest pad surface (THD; °C): the quantity a thermocouple in the pad reads."""
        return float(np.max(self.max_wall_temperature_c))

    @property
    def power_loss_w_total(self) -> float:
        return float(np.sum(self.power_loss_w))

    @property
    def makeup_flow_m3_s(self) -> np.ndarray:
        """Per pad (THD): the inlet-gap oil its trailing-edge cells draw where the pad hardly
        feeds them (m³/s; cpp/src/thd.cpp, kTeMakeup; it enters at the pad's inlet
        temperature and leaves with the cell's oil); zeros for the effective model."""
        if not self.flows:
            return np.zeros(len(self.max_temperature_c))
        return np.array([float(np.sum(np.asarray(f["makeup_m3_s"])[np.asarray(m) == 0]))
                         for f, m in zip(self.flows, self.inlet_mask)])

    @property
    def supply_flow_m3_s_total(self) -> float:
        return float(np.sum(self.supply_flow_m3_s))

    @property
    def side_flow_m3_s_total(self) -> float:
        return float(np.sum(self.side_flow_m3_s))

    def __repr__(self) -> str:
        return (f"PadThdResult(T_max={self.max_temperature_c_total:.2f} degC, "
                f"P={self.power_loss_w_total:.4g} W, eps={self.eccentricity_ratio:.4f}, "
                f"status={self.status!r})")

    def to_frame(self):
        """One row per pad and a ``total`` row (max of T_max, mean of T_mean, sums of power
        and flows, the inlet and outlet temperatures as flow-weighted means), with the journal
        position and the reduced K, C on every row; the effective model adds
        ``effective_temperature_c`` (= ``mean_temperature_c``)."""
        import pandas as pd

        n = len(self.max_temperature_c)
        cols = {"pad": [str(k) for k in range(n)] + ["total"]}

        def wmean(x, w):
            return float(np.sum(x * w) / np.sum(w)) if np.sum(w) > 0 else float(np.mean(x))
        cols["max_temperature_c"] = [*self.max_temperature_c, self.max_temperature_c_total]
        cols["mean_temperature_c"] = [*self.mean_temperature_c, self.mean_temperature_c_total]
        if self.thermal_model == "effective":  # the same numbers under the model's own name
            cols["effective_temperature_c"] = cols["mean_temperature_c"]
        cols["inlet_temperature_c"] = [*self.inlet_temperature_c,
                                       wmean(self.inlet_temperature_c, self.film_flow_m3_s)]
        cols["outlet_temperature_c"] = [*self.outlet_temperature_c,
                                        wmean(self.outlet_temperature_c, self.outlet_flow_m3_s)]
        for f in ("power_loss_w", "film_flow_m3_s", "outlet_flow_m3_s", "side_flow_m3_s",
                  "supply_flow_m3_s") + (("makeup_flow_m3_s",) if self.flows else ()):
            a = getattr(self, f)
            cols[f] = [*a, float(np.sum(a))]
        if self.carry_over_effective is not None:
            cols["carry_over_effective"] = [*self.carry_over_effective, np.nan]
        cols["pad_tilt_rad"] = [*self.pad_tilts_rad, np.nan] if len(self.pad_tilts_rad) \
            else [np.nan] * (n + 1)
        if self.max_wall_temperature_c is not None:  # THD: the walls
            cols["max_wall_temperature_c"] = [*self.max_wall_temperature_c,
                                              self.max_wall_temperature_c_total]
            cols["journal_temperature_c"] = [*self.journal_temperature_c,
                                             float(np.mean(self.journal_temperature_c))]
            for f in ("heat_to_journal_w", "heat_to_bush_w"):
                a = getattr(self, f)
                cols[f] = [*a, float(np.sum(a))]
        df = pd.DataFrame(cols)
        df.insert(0, "speed_hz", self.speed_hz)
        df.insert(1, "supply_temperature_c", self.supply_temperature_c)
        df["journal_x_m"] = self.x_m
        df["journal_y_m"] = self.y_m
        df["eccentricity_ratio"] = self.eccentricity_ratio
        for name, A, unit in (("k", self.K, "n_per_m"), ("c", self.C, "n_s_per_m")):
            for i, a in enumerate("xy"):
                for j, b in enumerate("xy"):
                    df[f"{name}{a}{b}_{unit}"] = float(A[i, j])
        if self.K4 is not None:  # a tilted journal
            df["journal_theta_x_rad"] = self.journal_theta_x_rad
            df["journal_theta_y_rad"] = self.journal_theta_y_rad
            df["film_moment_x_n_m"] = float(self.film_moment_n_m[0])
            df["film_moment_y_n_m"] = float(self.film_moment_n_m[1])
            df["h_min_m"] = self.h_min_m
            df["h_min_angle_deg"] = self.h_min_angle_deg
            df["h_min_z_m"] = self.h_min_z_m
        df["status"] = self.status
        df["message"] = self.message
        return df


def pad_thd_equilibrium(parts, *, oil, opts, load_n, speed_hz: float, clearance_m: float,
                        whirl_ratio: float | None, tilts=None, model=None) -> PadThdResult:
    """THD equilibrium of a standalone pad bearing from its ``parts``
    (:class:`rotordyn.bearings._film.SystemParts`, journal x, y = coordinates 0, 1): one C++
    call for the equilibrium (journal, pads) with the pads' energy equations and inlet mixing,
    then K, C at it with the field frozen. ``tilts(r)`` (optional) gives the pad tilts.
    ``model``: the core model over [x, y, pad coordinates] loaded by ``load_n`` instead of
    the one built from ``parts`` (a tilted journal held in the pads' base films,
    :mod:`rotordyn.bearings.tilt_thermal`)."""
    from rotordyn.bearings._film import reduce_coefficients, standalone_model
    from rotordyn.bearings.thermal import Oil

    if not isinstance(oil, Oil):
        raise InputError(f"oil: expected a rotordyn.bearings.Oil, got {oil!r}")
    load = np.asarray(load_n, dtype=float)
    if load.shape != (2,) or not np.all(np.isfinite(load)):
        raise InputError(f"load_n: expected two finite numbers (Fx, Fy) N, got {load_n!r}")
    v.speed("speed_hz", speed_hz)
    if float(speed_hz) == 0.0:
        raise InputError("speed_hz: the thermal equilibrium needs a nonzero speed, got 0")
    check_carry_over(opts.carry_over)
    n = 2 + parts.n_extra
    model = standalone_model(parts, load) if model is None else model
    M, K, C = (np.array(a, dtype=float) for a in (model.M, model.K, model.C))  # structural
    films = model.films
    omega = 2.0 * math.pi * float(speed_hz)
    npad = len(films)
    tf = pad_thermal_films(0, npad, 0, oil.to_core(), pad_options(opts, npad), omega)
    eopt = _core.EquilibriumOptions()
    eopt.polish = True
    res = _core.thermal_system_equilibrium(model, tf, omega, 0.0, np.zeros(n), eopt)
    eq = res.equilibrium
    thd = isinstance(opts, _core.ThdOptions)
    if eq.status not in ("ok", "contact"):
        raise failed_equilibrium("pad THD equilibrium" if thd else
                                 "pad effective-temperature equilibrium", eq)
    st = list(res.films)
    r = np.asarray(eq.r)
    for f, s in zip(films, st):  # freeze the field (THD) or the pad's μ(T_eff) (effective)
        if thd:
            f.viscosity_field = np.array(s.viscosity_field)
        else:
            g = f.geometry
            g.viscosity_pa_s = s.viscosity_pa_s
            f.geometry = g
    model.films = films
    lin = _core.SystemSolver(model).linearize(r, np.zeros(n), omega)
    Kf = np.asarray(lin.KH) + K
    Cf = np.asarray(lin.DH) + C
    nu = 0.0 if whirl_ratio is None else float(whirl_ratio) * omega
    Kr, Cr = reduce_coefficients(Kf, Cf, M, nu)

    def col(name):
        return np.array([getattr(s, name) for s in st])
    return PadThdResult(
        speed_hz=float(speed_hz), load_n=(float(load[0]), float(load[1])),
        supply_temperature_c=float(opts.supply_temperature_c),
        max_temperature_c=col("max_temperature_c"), mean_temperature_c=col("mean_temperature_c"),
        inlet_temperature_c=col("inlet_temperature_c"),
        outlet_temperature_c=col("recirculation_temperature_c"),
        power_loss_w=col("power_loss_w"), film_flow_m3_s=col("film_flow_m3_s"),
        outlet_flow_m3_s=col("recirculation_flow_m3_s"), side_flow_m3_s=col("side_flow_m3_s"),
        supply_flow_m3_s=col("supply_flow_m3_s"),
        carry_over_effective=col("carry_over_effective"), x_m=float(r[0]), y_m=float(r[1]),
        eccentricity_ratio=math.hypot(r[0], r[1]) / clearance_m,
        pad_tilts_rad=np.asarray(tilts(r)) if tilts is not None else np.zeros(0),
        K=Kr, C=Cr, K_full=Kf, C_full=Cf, M_full=M, r=r, iterations=int(res.iterations),
        temperature_c=tuple(np.array(s.temperature_c) for s in st) if thd else (),
        viscosity_pa_s=tuple(np.array(s.viscosity_field) for s in st) if thd else
        uniform_fields(films, st),
        inlet_mask=tuple(np.array(s.inlet_mask) for s in st) if thd else (),
        flows=tuple({k: np.array(getattr(s.flows, k)) for k in
                     ("q_phi_m3_s", "q_z_m3_s", "fill", "dissipation_w", "area_m2",
                      "makeup_m3_s")}
                    for s in st) if thd else (),
        status=eq.status, message=eq.message, thermal_model="thd" if thd else "effective",
        **(dict(heat_to_journal_w=col("heat_to_journal_w"), heat_to_bush_w=col("heat_to_bush_w"),
                journal_temperature_c=col("journal_temperature_c"),
                max_wall_temperature_c=col("max_wall_temperature_c"),
                wall_temperature_c=tuple(np.array(s.wall_temperature_c) for s in st))
           if thd else {}))


def uniform_fields(films, states) -> tuple:
    """Each effective-temperature pad's frozen μ(T_eff) as a uniform field on its grid
    ((N_pad, n_axial + 1) Pa·s per pad film)."""
    return tuple(np.full((f.grid.n_circ, f.grid.n_axial + 1), float(s.viscosity_pa_s))
                 for f, s in zip(films, states))


__all__ = ["PadThdResult", "check_carry_over", "freeze_fields", "pad_fields",
           "pad_model_options", "pad_options", "pad_thd_equilibrium", "pad_thermal_films", "uniform_fields"]
