"""Thermal equilibrium of a system (issue 20; docs/film-physics.md): the system equilibrium
(eq. 14) iterated with the heat balance (effective temperature) or the energy equation (THD)
of each thermal bearing's film — plain and active journal bearings (the active bearing's
sleeve deformation w(φ) in its film thickness, eq. 3, and its sleeve coordinates in the
equilibrium), tilting-pad and fixed-geometry bearings (per pad or lobe, with hot-oil
carry-over between pads; either model) — in one C++ call
(``_core.thermal_system_equilibrium``)."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn._common.status import CONVERGED
from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis.assembly import assembled, chamber_pressure
from rotordyn.bearings import (ActiveJournalBearing, FixedGeometryBearing, FluidFilmBearing,
                               Oil, TiltingPadBearing)
from rotordyn.bearings.pad_thd import (check_carry_over, pad_options, pad_thermal_films,
                                       uniform_fields)
from rotordyn.bearings.thd import THERMAL_MODELS, thd_options
from rotordyn.bearings.thd_walls import WALL_DEFAULTS, WALL_OPTIONS
from rotordyn.bearings.thermal import thermal_options
from rotordyn.errors import InputError
from rotordyn.results.thermal import WALL_COLUMNS, SystemThermalResult
from rotordyn.units import hz_to_rad_s

# the energy equation's terms of a THD film (FilmFlows), per node (n_circ, n_axial + 1)
FLOW_FIELDS = ("q_phi_m3_s", "q_z_m3_s", "fill", "dissipation_w", "area_m2", "viscosity_pa_s",
               "makeup_m3_s")


THD_ONLY_OPTIONS = ("journal_htc_w_m2k", "bush_htc_w_m2k", "journal_temperature_c",
                    "bush_temperature_c", *WALL_OPTIONS)


def refuse_other_model_options(model: str, given: dict, prefix: str = "",
                               flags: bool = False) -> None:
    """InputError naming the first of ``given`` (keyword → value, None: not given) that the
    thermal ``model`` does not use: the THD walls with "effective" (adiabatic),
    ``effective_factor`` with "thd" (no effective temperature); ``prefix`` goes before the
    name (e.g. "options.thermal."). ``flags``: named as the command line's options
    (``--bush-htc-w-m2k: an option of --model thd only``). The one rule of the API, the
    sweep spec and the CLI."""
    named = sorted(k for k, x in given.items() if x is not None)

    def name(k):
        return f"--{k.replace('_', '-')}" if flags else f"{prefix}{k}"

    def of(m):
        return f"--model {m}" if flags else f"model='{m}'"

    if model == "effective":
        bad = [k for k in named if k in THD_ONLY_OPTIONS]
        if bad:
            raise InputError(f"{name(bad[0])}: an option of {of('thd')} only (the "
                             "effective-temperature model is adiabatic)")
    if model == "thd" and "effective_factor" in named:
        raise InputError(f"{name('effective_factor')}: an option of {of('effective')} only "
                         "(the THD film has no effective temperature: the energy equation "
                         "gives the field)")


@limited_blas
def system_thermal_equilibrium(system, *, speed_hz: float, oil: Oil | None = None,
                               supply_temperature_c: float | None = None, bearings=None,
                               carry_over: float | None = None,
                               effective_factor: float | None = None,
                               supply_flow_m3_s: float | None = None,
                               chamber_pressure_pa: float = 0.0,
                               config_ay_m: float | None = None,
                               config_ax_m: float | None = None,
                               tol_k: float = 1e-6, model: str | None = None,
                               journal_htc_w_m2k: float | None = None,
                               bush_htc_w_m2k: float | None = None,
                               journal_temperature_c: float | None = None,
                               bush_temperature_c: float | None = None,
                               **walls) -> SystemThermalResult:
    """Thermal equilibrium of ``system`` at ``speed_hz``: each plain or active journal bearing
    (``type = "journal"``, :class:`rotordyn.FluidFilmBearing`; ``type = "active_journal"``,
    :class:`rotordyn.ActiveJournalBearing`, whose film thickness includes the sleeve's
    deformation at the equilibrium, eq. 3) in ``bearings`` (indices into
    ``system.bearings``; None: all of them) runs at μ(T_eff) of ``oil`` with its own heat
    balance (supply at ``supply_temperature_c`` °C, ``carry_over`` λ, ``effective_factor`` k,
    ``supply_flow_m3_s``; :meth:`rotordyn.JournalBearing.thermal_equilibrium` for the model),
    iterated with the system equilibrium to |ΔT_eff| <= ``tol_k`` for every bearing. The
    result's ``system`` carries the viscosities μ(T_eff): pass it to ``linearize``,
    ``stability`` or ``campbell`` for the dynamics with the temperature frozen. Tilting-pad
    and fixed-geometry bearings run either model per pad (lobe), each pad's inlet mixing the
    upstream pad's hot oil (:mod:`rotordyn.bearings.pad_thd`); with the effective model the
    returned bearing carries each pad's μ(T_eff) as a uniform frozen field.

    ``chamber_pressure_pa`` (Pa) is every active bearing's p_c; ``config_ay_m``,
    ``config_ax_m`` (m) override the active bearing's housing offsets as in
    :func:`rotordyn.equilibrium` (None: the model's). The returned ``system`` carries the
    offsets used, so ``equilibrium(result.system, speed_hz, chamber_pressure_pa)`` is the
    thermal equilibrium; its frozen temperature field belongs to this (speed, p_c, a) only.

    Every thermal argument left None comes from the model's oil system (``system.thermal``,
    the model file's ``[thermal]`` table, per bearing from its ``[[thermal.film]]`` entry);
    one given applies to every bearing. Without ``system.thermal``, ``oil`` and
    ``supply_temperature_c`` are required (λ = 0, k = 0.5, the film's own demand).

    ``model``: ``"effective"`` (the effective-temperature heat balance above) or ``"thd"``
    (the thermo-hydrodynamic film of every thermal bearing: the energy equation over its grid,
    μ(T) per node, :mod:`rotordyn.bearings.thd`; ``effective_factor`` refused; heat-transfer
    coefficients ``journal_htc_w_m2k``, ``bush_htc_w_m2k`` W/(m² K), 0 adiabatic, walls at
    ``journal_temperature_c``, ``bush_temperature_c`` °C, None: the model's, else the supply
    temperature); None: the model's ``[thermal] model`` (default "effective"). With
    "thd" the result's ``system`` carries each bearing's frozen viscosity field
    (``viscosity_field_pa_s``) and ``temperature_c`` the fields. ``walls``: the THD film's
    heat paths (:mod:`rotordyn.bearings.thd_walls`: ``wall_htc``, ``journal_wall``,
    ``bush_wall``, ``bush_thickness_m``, ``bush_conductivity_w_per_m_k``,
    ``back_htc_w_m2k``, ``back_temperature_c``), each one left out: the model's ``[thermal]``
    value, else its default; a journal from its heat balance is one per bearing (all its
    pads)."""
    v.speed("speed_hz", speed_hz)
    if float(speed_hz) == 0.0:
        raise InputError("speed_hz: the thermal equilibrium needs a nonzero speed, got 0")
    chamber_pressure(system, chamber_pressure_pa)
    for name, val in (("config_ay_m", config_ay_m), ("config_ax_m", config_ax_m)):
        if val is not None:
            v.finite(name, val)
    thermal_model = model_ = system.thermal
    if oil is None:
        if model_ is None:
            raise InputError("oil: the model has no [thermal] table; give oil= and "
                             "supply_temperature_c= (or add [thermal] to the model file)")
        oil = model_.oil
    if not isinstance(oil, Oil):
        raise InputError(f"oil: expected a rotordyn.bearings.Oil, got {oil!r}")
    if supply_temperature_c is None:
        if model_ is None:
            raise InputError("supply_temperature_c: required (the oil's supply temperature, "
                             "degC) when the model has no [thermal] table")
        supply_temperature_c = model_.supply_temperature_c
    if model is None:
        model = getattr(thermal_model, "model", "effective") if thermal_model is not None \
            else "effective"
    v.choice("model", model, THERMAL_MODELS)
    unknown = set(walls) - set(WALL_OPTIONS)
    if unknown:
        raise InputError(f"{sorted(unknown)[0]}: not an option of the thermal equilibrium")
    # an option the chosen model does not use is refused, as the standalone film refuses it
    # (before, the system call ignored it silently: the same answer with or without it)
    refuse_other_model_options(model, {
        "journal_htc_w_m2k": journal_htc_w_m2k, "bush_htc_w_m2k": bush_htc_w_m2k,
        "journal_temperature_c": journal_temperature_c,
        "bush_temperature_c": bush_temperature_c, "effective_factor": effective_factor,
        **walls})
    plain = [i for i, b in enumerate(system.bearings)
             if isinstance(b, (FluidFilmBearing, ActiveJournalBearing))]
    pads = [i for i, b in enumerate(system.bearings)
            if isinstance(b, (TiltingPadBearing, FixedGeometryBearing))]
    if bearings is None:
        idx = plain + pads
    else:
        idx = [v.integer("bearings[]", i, lo=0, hi=len(system.bearings) - 1) for i in bearings]
        for i in idx:
            if i not in plain and i not in pads:
                raise InputError(f"bearings: bearing {i} is a "
                                 f"{type(system.bearings[i]).__name__}; the thermal model is "
                                 "available for plain and active journal bearings (type = "
                                 "'journal', 'active_journal'), tilting-pad and fixed-geometry "
                                 "bearings")
    if not idx:
        raise InputError("bearings: the system has no plain, active, tilting-pad or "
                         "fixed-geometry journal bearing for the thermal model")
    for i in idx:  # the starved film (a metered jfo film) is isothermal only, so far
        if getattr(system.bearings[i], "supply_flow_m3_s", None):
            raise InputError(f"bearings[{i}].supply_flow_m3_s: the starved (metered-supply) "
                             "film is not coupled to the thermal models yet; meter the "
                             "supply in the thermal options instead (docs/film-physics.md, "
                             "\"A starved film\")")
    def options(i):
        own = model_.film(system.bearings[i].name) if model_ is not None else None

        def pick(given, field, default):
            if given is not None:
                return given
            return getattr(own, field) if own is not None else default
        return thermal_options(supply_temperature_c=supply_temperature_c,
                               supply_flow_m3_s=pick(supply_flow_m3_s, "supply_flow_m3_s", 0.0),
                               carry_over=pick(carry_over, "carry_over", 0.0),
                               effective_factor=pick(effective_factor, "effective_factor", 0.5),
                               tol_k=tol_k)
    thd = model == "thd"

    def wall(given, field):
        if given is not None:
            return given
        return getattr(thermal_model, field) if thermal_model is not None else 0.0
    hj, hb = wall(journal_htc_w_m2k, "journal_htc_w_m2k"), wall(bush_htc_w_m2k, "bush_htc_w_m2k")
    def wall_opt(f):
        return walls[f] if walls.get(f) is not None else \
            getattr(thermal_model, f) if thermal_model is not None else WALL_DEFAULTS[f]
    wall_kw = {f: wall_opt(f) for f in ("wall_htc", "journal_wall", "bush_wall")}
    # the bush's conduction data: the model's only where its bush conducts here too
    own = thermal_model is not None and thermal_model.bush_wall == wall_kw["bush_wall"]
    wall_kw.update({f: walls[f] if walls.get(f) is not None else
                    getattr(thermal_model, f) if own else WALL_DEFAULTS[f]
                    for f in WALL_OPTIONS[3:]})
    # a wall temperature the model gives does not apply where the call chooses the wall's
    # own heat balance or conduction instead
    tj = journal_temperature_c if journal_temperature_c is not None else \
        getattr(thermal_model, "journal_temperature_c", None) \
        if wall_kw["journal_wall"] != "balance" else None
    tb = bush_temperature_c if bush_temperature_c is not None else \
        getattr(thermal_model, "bush_temperature_c", None) \
        if wall_kw["bush_wall"] != "conduction" else None
    opts = {i: options(i) for i in idx}
    thd_opts = {i: thd_options(supply_temperature_c=supply_temperature_c,
                               supply_flow_m3_s=opts[i].supply_flow_m3_s,
                               carry_over=opts[i].carry_over, journal_htc_w_m2k=hj,
                               bush_htc_w_m2k=hb, journal_temperature_c=tj,
                               bush_temperature_c=tb, tol_k=tol_k, **wall_kw)
                for i in idx} if thd else {}
    asm = assembled(system)
    omega = hz_to_rad_s(float(speed_hz))
    films = []
    rows = []  # per thermal film: (bearing index, film index)
    for i in idx:
        if i in pads:  # every pad (lobe) film, its inlet fed by the upstream pad
            own = [j for j, o in enumerate(asm.film_owner) if o == i]
            check_carry_over(opts[i].carry_over, f"thermal.films.{system.bearings[i].name or i}"
                             ".carry_over")
            films += pad_thermal_films(own[0], len(own), len(films), oil.to_core(),
                                       pad_options(thd_opts[i] if thd else opts[i], len(own)),
                                       omega)
            rows += [(i, j) for j in own]
            continue
        rows.append((i, asm.film_owner.index(i)))
        tf = _core.ThermalFilm()
        tf.film = rows[-1][1]
        tf.oil = oil.to_core()
        tf.options = opts[i]
        if thd:
            tf.thd = True
            tf.thd_options = thd_opts[i]
        films.append(tf)
    opt = _core.EquilibriumOptions()
    opt.polish = True
    a = asm.config_vector(config_ay_m, config_ax_m)
    res = _core.thermal_system_equilibrium(asm.model, films, omega,
                                           float(chamber_pressure_pa), a, opt)
    eq = res.equilibrium
    message = eq.message
    if eq.status == "not_converged" and "did not settle" in message:
        message += f" to tol_k = {tol_k:g} K"
    r = np.asarray(eq.r)
    st = list(res.films)
    mus, fields = {}, {}
    mfilms = asm.model.films
    for i in idx:
        own = [s for (b, _), s in zip(rows, st) if b == i]
        if i in pads:  # μ(mean over the pads) as the reference; the frozen field per pad
            mus[i] = oil.viscosity_pa_s(float(np.mean([s.mean_temperature_c for s in own])))
            fields[i] = tuple(np.array(s.viscosity_field) for s in own) if thd else \
                uniform_fields([mfilms[j] for (b, j) in rows if b == i], own)
        else:
            mus[i] = own[0].viscosity_pa_s
            if thd:
                fields[i] = np.array(own[0].viscosity_field)
    bcs = {bc.index: bc for bc in asm.bearings}
    # the housing offsets this equilibrium used (config_ay_m/config_ax_m overrides included)
    cfg = {i: dict(config_ax_m=float(a[bc.jx]), config_ay_m=float(a[bc.jy]))
           for i, bc in bcs.items() if hasattr(system.bearings[i], "config_ay_m")
           and (float(a[bc.jx]), float(a[bc.jy])) != (system.bearings[i].config_ax_m,
                                                      system.bearings[i].config_ay_m)}
    # a failed system equilibrium (its status) leaves no film state to freeze: the films that
    # never got one carry no viscosity (0), so the returned system is the model as given
    # (never linearised: rotordyn.analysis.thermal_dynamics checks the status first)
    hot = dataclasses.replace(system, bearings=tuple(
        dataclasses.replace(b, viscosity_pa_s=float(mus[i]), viscosity_field_pa_s=fields.get(i),
                            **cfg.get(i, {}))
        if i in mus else dataclasses.replace(b, **cfg[i]) if i in cfg else b
        for i, b in enumerate(system.bearings))) if eq.status in CONVERGED else system
    names = tuple(asm.model.films[j].name if i in pads else bcs[i].name for i, j in rows)

    def col(name):  # a failed equilibrium's film states are no thermal state: NaN
        x = np.array([getattr(s, name) for s in st], dtype=np.float64)
        return x if eq.status in CONVERGED else np.full_like(x, np.nan)

    pads = _pad_outputs(hot, r, omega, eq, rows, st, thd) if eq.status in CONVERGED else {}
    return SystemThermalResult(
        pads=pads, speed_hz=float(speed_hz), supply_temperature_c=float(supply_temperature_c),
        bearing_names=names, effective_temperature_c=col("effective_temperature_c"),
        max_temperature_c=col("max_temperature_c"), inlet_temperature_c=col("inlet_temperature_c"),
        temperature_rise_k=col("temperature_rise_k"), viscosity_pa_s=col("viscosity_pa_s"),
        power_loss_w=col("power_loss_w"), film_flow_m3_s=col("film_flow_m3_s"),
        side_flow_m3_s=col("side_flow_m3_s"), supply_flow_m3_s=col("supply_flow_m3_s"),
        carry_over_effective=col("carry_over_effective"),
        journal_x_m=np.array([r[bcs[i].jx] for i, _ in rows]),
        journal_y_m=np.array([r[bcs[i].jy] for i, _ in rows]),
        r=r, iterations=int(res.iterations), system=hot, status=eq.status, message=message,
        thermal_model=model,
        temperature_c=tuple(np.array(s.temperature_c) for s in st) if thd else (),
        inlet_mask=tuple(np.array(s.inlet_mask) for s in st) if thd else (),
        flows=tuple({k: np.array(getattr(s.flows, k)) for k in FLOW_FIELDS} for s in st)
        if thd else (),
        **{f: col(f) if thd else np.full(len(rows), np.nan) for f in WALL_COLUMNS},
        **{f: np.array([getattr(eq, g)[j] for _, j in rows], dtype=np.float64)
           if eq.status in CONVERGED else np.full(len(rows), np.nan)
           for f, g in (("h_min_m", "h_min"), ("h_min_z_m", "h_min_z_m"))},
        wall_temperature_c=tuple(np.array(s.wall_temperature_c) for s in st) if thd else (),
        tilt=_tilt_columns(asm, eq, r, a, [bcs[i] for i, _ in rows]))


def _tilt_columns(asm, eq, r: np.ndarray, a: np.ndarray, film_bcs: list) -> dict | None:
    """Per film (its bearing ``film_bcs[k]``): the journal rotations at the bearing and the
    bearing's film moments at the thermal equilibrium ``eq`` (system coordinates ``r``, the
    configuration ``a``), as the isothermal equilibrium's ``tilt`` entries
    (:func:`rotordyn.analysis.equilibrium.tilt_outputs`); NaN for an untilted film and where
    the equilibrium failed; None when no film tilts."""
    if not any(bc.rot for bc in film_bcs):
        return None
    from rotordyn.analysis.equilibrium import tilt_outputs

    t = (tilt_outputs(asm, r, a, np.asarray(eq.h_min_z_m), np.asarray(eq.h_min),
                      np.asarray(eq.film_force)) if eq.status in CONVERGED else {})
    return {k: np.array([t.get(bc.index, {}).get(k, np.nan) for bc in film_bcs], dtype=float)
            for k in ("journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
                      "film_moment_y_n_m")}

# per pad of a thermal tilting-pad bearing: SystemThermalResult.pads key -> film state field
PAD_THERMAL = (("pad_effective_temperature_c", "effective_temperature_c"),
               ("pad_max_temperature_c", "max_temperature_c"),
               ("pad_inlet_temperature_c", "inlet_temperature_c"),
               ("pad_temperature_rise_k", "temperature_rise_k"),
               ("pad_viscosity_pa_s", "viscosity_pa_s"),
               ("pad_power_loss_w", "power_loss_w"),
               ("pad_supply_flow_m3_s", "supply_flow_m3_s"),
               ("pad_max_wall_temperature_c", "max_wall_temperature_c"))
EFFECTIVE_PAD = {f for _, f in PAD_THERMAL} - {"max_wall_temperature_c"}  # not THD-only


def _pad_outputs(hot, r: np.ndarray, omega: float, eq, rows: list, st: list,
                 thd: bool) -> dict:
    """Per thermal tilting-pad bearing, every pad's state at the converged thermal
    equilibrium ``r`` as the isothermal equilibrium's ``pads``
    (:func:`rotordyn.analysis.equilibrium.pad_outputs`: pivot, tilt, peak pressure, minimum
    film, unloaded; the pressures from the returned system ``hot``, whose films carry the
    frozen viscosities of this equilibrium) and each pad's film state (``PAD_THERMAL``; THD:
    ``pad_effective_temperature_c`` is the pad's mean, ``pad_max_wall_temperature_c`` its
    hottest surface, NaN for the effective model). Bearings left isothermal are left out."""
    from rotordyn.analysis.equilibrium import pad_outputs

    out = pad_outputs(assembled(hot), r, omega, np.asarray(eq.h_min))
    for bi, d in out.items():
        own = [s for (b, _), s in zip(rows, st) if b == bi]
        if len(own) == len(d["pad_tilt_rad"]):
            for key, field in PAD_THERMAL:
                d[key] = tuple(float(getattr(s, field)) if thd or field in EFFECTIVE_PAD
                               else float("nan") for s in own)
    return {bi: d for bi, d in out.items() if "pad_power_loss_w" in d}
