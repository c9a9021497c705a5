"""Stability, Campbell and unbalance response of thermal films (issue 20; docs/film-physics.md,
"Dynamics at each point's own thermal equilibrium").

At every operating point (speed, p_c, a) the system's thermal equilibrium is solved first
(:func:`rotordyn.system_thermal_equilibrium`, a cold start: the answer does not depend on the
points before it), then the system with the viscosity (THD: the viscosity field) of that
equilibrium **frozen** is solved again (equilibrium, K_H, D_H of eq. 18, eq. 19): the dynamic
coefficients are those of the isoviscous (THD: fixed-field) film at the thermal state, i.e. the
temperature does not follow the vibration (the film's thermal time constant is taken as long
against a whirl period). A point whose thermal equilibrium fails is never linearised: it keeps
the thermal status (stability raises ConvergenceError; Campbell and unbalance: a NaN row with
``point_status`` = the thermal status). Bad input (a thermal model that does not apply to the
bearings, a zero speed) is an InputError, not a row per speed.
"""

from __future__ import annotations

import inspect

import numpy as np

from rotordyn.errors import InputError, status_error
from rotordyn._common.status import point_messages
from rotordyn.results.equilibrium import CONVERGED

WHIRL_CODE = {"forward": 1, "backward": -1, "planar": 0}
OWN = ("speed_hz", "chamber_pressure_pa", "config_ay_m", "config_ax_m")


def thermal_keywords(thermal, where: str = "thermal") -> dict | None:
    """``thermal`` checked: None (isothermal), True (the model's ``[thermal]`` as it is) or a
    dict of :func:`rotordyn.system_thermal_equilibrium`'s keywords other than the operating
    point's (InputError naming ``<where>.<key>``)."""
    if thermal is None or thermal is False:
        return None
    if thermal is True:
        return {}
    from rotordyn.analysis.thermal import system_thermal_equilibrium

    if not isinstance(thermal, dict):
        raise InputError(f"{where}: expected None, True or a dict of "
                         f"system_thermal_equilibrium keywords, got {type(thermal).__name__}")
    from rotordyn.bearings.thd_walls import WALL_OPTIONS

    # its named keywords and the THD walls' options it takes as **walls (before, the
    # signature's "walls" itself was listed and wall_htc, bush_wall, ... refused)
    params = inspect.signature(system_thermal_equilibrium).parameters
    allowed = [k for k, p in params.items() if k not in OWN and k != "system"
               and p.kind is not inspect.Parameter.VAR_KEYWORD] + list(WALL_OPTIONS)
    for k in thermal:
        if k in OWN:
            raise InputError(f"{where}.{k}: set by the operating point, not by the thermal "
                             "keywords")
        if k not in allowed:
            raise InputError(f"{where}.{k}: not a keyword of system_thermal_equilibrium; "
                             f"expected one of {allowed}")
    return dict(thermal)


def _no_zero(sp) -> None:
    """A thermal equilibrium needs a turning journal: InputError naming ``speeds_hz``."""
    if np.any(np.asarray(sp) == 0.0):
        raise InputError("speeds_hz: the thermal equilibrium needs a nonzero speed at every "
                         "speed (thermal=), got 0 Hz among them")


def thermal_point(system, speed_hz, chamber_pressure_pa=0.0, config_ay_m=None, kw=None):
    """The thermal equilibrium at one point (a :class:`SystemThermalResult`; its ``system``
    carries the frozen viscosities and the offsets used)."""
    from rotordyn.analysis.thermal import system_thermal_equilibrium

    try:
        return system_thermal_equilibrium(system, speed_hz=float(speed_hz),
                                          chamber_pressure_pa=float(chamber_pressure_pa),
                                          config_ay_m=config_ay_m, **(kw or {}))
    except InputError as exc:  # a value of the thermal keywords: named as the caller gave it
        if any(str(exc).startswith(f"{k}:") for k in (kw or {})):
            raise InputError(f"thermal.{exc}") from None
        raise


def _converged_points(system, sp, chamber_pressure_pa, config_ay_m, thermal, status, therm,
                      message):
    """(i, speed, thermal equilibrium) of every speed whose thermal equilibrium converged;
    fills ``status`` (the thermal status, "error" where it raised), ``therm`` (the
    equilibria, None where it raised) and ``message`` (why a speed failed, as the sweep rows
    say it; "" otherwise) for every speed. A failed point is never yielded (never
    linearised); an InputError (the model's or the keywords' fault: every speed would refuse)
    propagates."""
    from rotordyn.errors import RotordynError

    _no_zero(sp)
    for i, s in enumerate(sp):
        try:
            t = thermal_point(system, s, chamber_pressure_pa, config_ay_m, thermal)
        except InputError:
            raise
        except RotordynError as exc:
            therm.append(None)
            status[i] = "error"
            message[i] = f"{type(exc).__name__}: {exc}"
            continue
        therm.append(t)
        status[i] = t.status
        if t.status in CONVERGED:
            yield i, s, t
        else:
            message[i] = f"thermal equilibrium: {t.message}"


def thermal_stability(stability, system, speed_hz, chamber_pressure_pa, config_ay_m, *,
                      n_modes, method, thermal, **equilibrium_kw):
    """``stability`` (:func:`rotordyn.stability`, passed in: this module sits below the API)
    at the point's own thermal equilibrium (its field frozen); the result's ``thermal`` is
    that equilibrium."""
    import dataclasses

    t = thermal_point(system, speed_hz, chamber_pressure_pa, config_ay_m, thermal)
    if t.status not in CONVERGED:  # a starved film: StarvedFilmError (status "starved")
        raise status_error(t.status, f"thermal equilibrium at {float(speed_hz):g} Hz: "
                                     f"{t.status} ({t.message}); not linearised")
    st = stability(t.system, speed_hz, chamber_pressure_pa, config_ay_m, n_modes=n_modes,
                   method=method, warm_start=False, **equilibrium_kw)
    return dataclasses.replace(st, thermal=t)


def thermal_campbell(linearize, stability_from, system, sp, chamber_pressure_pa, config_ay_m,
                     *, n_modes, method, thermal):
    """:func:`rotordyn.campbell` with every speed at its own thermal equilibrium (cold, field
    frozen); a failed thermal equilibrium is a NaN row with its status. ``linearize``,
    ``stability_from``: those of :mod:`rotordyn.analysis.linear` (passed in)."""
    from rotordyn.analysis.assembly import assembled
    from rotordyn.analysis.tracking import track_modes
    from rotordyn.errors import RotordynError
    from rotordyn.results.campbell import CampbellResult

    asm = assembled(system)
    k = asm.n if n_modes is None else min(n_modes, asm.n)
    n_pad = sum(len(getattr(bc, "extra", ())) for bc in asm.bearings)
    width = k if n_modes is None else min(k + n_pad, asm.n)
    lam = np.full((sp.size, width), np.nan + 1j * np.nan)
    whirl = np.zeros((sp.size, width), dtype=np.int64)
    kind = np.full((sp.size, width), "rotor", dtype=object)
    status = np.empty(sp.size, dtype=object)
    shapes = np.full((sp.size, asm.n, width), np.nan + 0j)
    therm: list = []
    message = np.full(sp.size, "", dtype=object)
    for i, s, t in _converged_points(system, sp, chamber_pressure_pa, config_ay_m, thermal,
                                     status, therm, message):
        try:
            lm = linearize(t.system, float(s), chamber_pressure_pa, config_ay_m, method=method,
                           warm_start=False)
            status[i] = lm.status
            if lm.status not in CONVERGED:
                message[i] = lm.equilibrium.message
                continue
            st = stability_from(assembled(t.system), lm, None if n_modes is None else k)
        except RotordynError as exc:
            status[i] = "error"
            message[i] = f"{type(exc).__name__}: {exc}"
            continue
        m = min(width, len(st.eigenvalues))
        lam[i, :m] = st.eigenvalues[:m]
        whirl[i, :m] = [WHIRL_CODE[w] for w in st.whirl[:m]]
        kind[i, :m] = st.kind[:m]
        if st.modes is not None:
            shapes[i, :, :m] = st.modes[:, :m]
    mode_id = track_modes(lam, shapes, weight=np.asarray(asm.model.M))
    return CampbellResult(sp, lam, whirl, model=system.reduction.method, kind=kind,
                          point_status=status.astype(str), mode_id=mode_id,
                          thermal=tuple(therm), point_message=point_messages(status, message))


def thermal_unbalance(unbalance_response, system, ub, sp, kw: dict, thermal):
    """The unbalance response with every speed at its own thermal equilibrium (cold, field
    frozen): per speed the isothermal response of the frozen system (``kw``: the keywords of
    ``unbalance_response`` (:func:`rotordyn.unbalance_response`, passed in) without
    ``refine``); NaN and the thermal status where the thermal equilibrium fails."""
    from rotordyn.results.unbalance import UnbalanceResult

    pc, ay = kw.get("chamber_pressure_pa", 0.0), kw.get("config_ay_m")
    outs = tuple(kw["stations"]) if kw.get("stations") is not None else \
        tuple(dict.fromkeys(int(s) for s, _, _ in ub))
    X = np.full((sp.size, len(outs)), np.nan + 0j)
    Y = np.full((sp.size, len(outs)), np.nan + 0j)
    status = np.empty(sp.size, dtype=object)
    check = kw.get("check_stability")
    check = bool(system.bearings) if check is None else bool(check)
    mr = np.full(sp.size, np.nan) if check else None
    therm: list = []
    message = np.full(sp.size, "", dtype=object)
    for i, s, t in _converged_points(system, sp, pc, ay, thermal, status, therm, message):
        u = unbalance_response(t.system, ub, [float(s)], **{**kw, "stations": outs},
                               refine=False)
        X[i], Y[i], status[i] = u.x[0], u.y[0], u.point_status[0]
        if check:
            mr[i] = u.max_real_1_per_s[0]
    return UnbalanceResult(sp, outs, X, Y, status.astype(str), tuple(ub),
                           kw.get("operating_speed_hz"), mr, thermal=tuple(therm),
                           point_message=point_messages(status, message))
