"""Threshold of instability of the linear closed loop (a fixed controller on the plant
re-linearised at each point) beside the passive one (:func:`rotordyn.threshold`): how far
feedback moves the onset of oil whirl in speed or in chamber pressure."""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control import _checks as chk
from rotordyn.errors import InputError, RotordynError


def closed_loop_max_real(system, controller, *, speed_hz, chamber_pressure_pa, config_ay_m,
                         actuator=None, exclude_above_hz: float | None = None) -> float:
    """Largest real part of the closed-loop eigenvalues at one operating point (NaN if the
    point has no equilibrium)."""
    speed_hz, chamber_pressure_pa, config_ay_m = chk.operating_point(
        system, speed_hz, chamber_pressure_pa, config_ay_m)
    chk.controller(controller, continuous=True)
    chk.measured_by(system, controller)
    actuator = chk.actuator(actuator)
    if exclude_above_hz is not None:
        v.positive("exclude_above_hz", exclude_above_hz)
    return _max_real(system, controller, speed_hz, chamber_pressure_pa, config_ay_m, actuator,
                     exclude_above_hz)


def _max_real(system, controller, speed_hz, chamber_pressure_pa, config_ay_m, actuator,
              exclude_above_hz):
    """:func:`closed_loop_max_real` on checked arguments: only a numerical failure of the
    point (no equilibrium, a failed linearisation) is NaN; bad input was refused before."""
    from rotordyn.control.closedloop import closed_loop_matrix
    from rotordyn.control.plant import plant

    try:
        p = plant(system, speed_hz, chamber_pressure_pa, config_ay_m,
                  measurements=controller.measurements, actuator=actuator)
    except InputError:
        raise
    except RotordynError:
        return math.nan
    lam = np.linalg.eigvals(closed_loop_matrix(p, controller))
    if exclude_above_hz is not None:
        lam = lam[np.abs(lam) < 2 * np.pi * exclude_above_hz]
    return float(lam.real.max()) if lam.size else math.nan


def closed_loop_threshold(system, controller, vary: str = "chamber_pressure_pa", *, bounds,
                          speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
                          config_ay_m: float | None = None, actuator=None, n_scan: int = 25,
                          xtol: float | None = None):
    """Scan ``vary`` (``"chamber_pressure_pa"`` or ``"speed_hz"``) over ``bounds`` at
    ``n_scan`` points and refine every sign change of the closed loop's max Re λ with
    Brent's method. Returns (crossings (list), scan DataFrame)."""
    from scipy.optimize import brentq
    import pandas as pd
    v.choice("vary", vary, ("chamber_pressure_pa", "speed_hz"))
    lo, hi = v.bounds("bounds", bounds)
    if vary == "chamber_pressure_pa" and lo < 0:
        raise InputError(f"bounds: chamber_pressure_pa must be >= 0 Pa, got {bounds!r}")
    if vary == "speed_hz":
        v.speed("bounds[0]", lo)
        v.speed("bounds[1]", hi)
    v.integer("n_scan", n_scan, lo=2, hi=10000)
    xtol = (hi - lo) * 1e-6 if xtol is None else v.positive("xtol", xtol)
    speed_hz, chamber_pressure_pa, config_ay_m = chk.operating_point(
        system, speed_hz, chamber_pressure_pa, config_ay_m)
    chk.controller(controller, continuous=True)
    chk.measured_by(system, controller)
    actuator = chk.actuator(actuator)
    fixed = dict(speed_hz=speed_hz, chamber_pressure_pa=chamber_pressure_pa,
                 config_ay_m=config_ay_m)

    def g(x):
        kw = dict(fixed)
        kw[vary] = float(x)
        return _max_real(system, controller, kw["speed_hz"], kw["chamber_pressure_pa"],
                         kw["config_ay_m"], actuator, None)

    xs = np.linspace(lo, hi, n_scan)
    ys = np.array([g(x) for x in xs])
    roots = []
    ok = np.isfinite(ys)
    xo, yo = xs[ok], ys[ok]
    for i in range(len(xo) - 1):
        if np.sign(yo[i]) * np.sign(yo[i + 1]) < 0:
            try:
                roots.append(brentq(g, xo[i], xo[i + 1], xtol=xtol))
            except ValueError:
                pass
    return roots, pd.DataFrame({vary: xs, "max_real_1_per_s": ys})
