"""Thresholds of instability found exactly (bracketing + Brent's method on the largest real
part of the eigenvalues of eq. 19), and boundary tracing by continuation (paper §6.2)."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import math

import numpy as np

from rotordyn.errors import InputError, RotordynError
from rotordyn._common import validate as v
from rotordyn.analysis.assembly import OPERATING, chamber_pressure, check_operating_parameter
from rotordyn.analysis.thermal_dynamics import thermal_keywords, thermal_point
from rotordyn.model.paths import set_field
from rotordyn.model.system import System
from rotordyn.results.modes import verdict_real
from rotordyn.results.threshold import BoundaryResult, ThresholdResult


def _point(system, params, exclude_sleeve_modes, thermal=None):
    from rotordyn.analysis.linear import stability

    if thermal is not None:  # the thermal equilibrium at this point, its field frozen
        # (a refused keyword raises InputError "thermal.<key>: ...", as stability(thermal=))
        t = thermal_point(system, params["speed_hz"], params["chamber_pressure_pa"],
                          params["config_ay_m"], thermal)
        if t.status not in ("ok", "contact"):
            return math.nan, math.nan, f"thermal {t.status}", math.nan
        system = t.system
    st = stability(system, params["speed_hz"], params["chamber_pressure_pa"],
                   params["config_ay_m"])
    if st.status not in ("ok", "contact") or len(st.eigenvalues) == 0:
        return math.nan, math.nan, st.status, math.nan
    lam = st.eigenvalues
    if exclude_sleeve_modes:  # the rotor's and the tilting pads' roots (the sweep's rule)
        lam = lam[st.kind != "sleeve"]
    i = int(np.argmax(lam.real))
    # the function whose zero is the threshold: its sign is the point's verdict
    # (point_stable's round-off band), never 0; away from the band it is max Re λ itself
    return verdict_real(lam), float(lam[i].imag / (2 * np.pi)), st.status, float(lam[i].real)


@limited_blas
def threshold(system: System, vary: str = "chamber_pressure_pa", *, bounds,
              speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
              config_ay_m: float | None = None, n_scan: int = 25, xtol: float | None = None,
              exclude_sleeve_modes: bool = False, thermal: dict | bool | None = None
              ) -> ThresholdResult:
    """The value of ``vary`` (``"chamber_pressure_pa"``, ``"config_ay_m"``, ``"speed_hz"``, or
    a numeric model field path such as ``"bearings.*.clearance_m"``: the system re-assembled
    with the field at every scanned value, the operating point fixed) in ``bounds`` where the
    point's stability verdict flips: where the least-damped eigenvalue's real part crosses
    zero, a real part within the round-off band of 0 (an undamped rotor's, 1e-9 max(|λ|, 1):
    :func:`rotordyn.results.modes.point_stable`) counting as stable — the verdict of
    :func:`rotordyn.stability` and of the sweeps, not the raw sign. The function bracketed
    and refined is :func:`rotordyn.results.modes.verdict_real` (max Re λ away from the band;
    the scan's ``verdict_real_1_per_s`` beside the raw ``max_real_1_per_s`` and ``stable``).

    The bounds are scanned at ``n_scan`` points (equilibria continued from point to point),
    then refined where a parabola through three neighbouring scan values dips through zero
    between them (a narrow band the scan stepped over); every sign change is refined with
    Brent's method to ``xtol`` (default 1e-6 of the bounds' span) and listed in
    ``crossings``; ``value`` is the first. No sign change gives status ``"no_crossing"`` and
    ``value`` NaN — never an invented number. A band narrower than the scan spacing that
    leaves no trace in the scanned values can still be missed: raise ``n_scan``.

    ``thermal``: None (the isothermal films), True (the model's ``[thermal]`` as it is) or
    the keywords of
    :func:`rotordyn.system_thermal_equilibrium` (``oil``, ``supply_temperature_c``,
    ``model="thd"``, ``carry_over``...; not the operating point, which the threshold sets):
    every evaluation then first solves the thermal equilibrium at its point (a cold start;
    speed, p_c and a_y of the point) and takes the stability of the returned system, the
    temperature (viscosity) field frozen there — the threshold of the thermal film, each
    point at its own temperature.
    """
    from scipy.optimize import brentq
    import pandas as pd
    from rotordyn.analysis.field_axis import field_parameter

    vary = field_parameter(system, vary)
    field = vary not in OPERATING
    lo, hi = v.bounds("bounds", bounds)
    if vary == "chamber_pressure_pa" and lo < 0:
        raise InputError(f"bounds: {vary} must be >= 0, got {bounds!r}")
    v.integer("n_scan", n_scan, lo=2, hi=10000)
    xtol = (hi - lo) * 1e-6 if xtol is None else v.positive("xtol", xtol)
    # The fixed parameters obey the ranges of stability() (issue 13: a negative fixed
    # chamber pressure used to scan and report "no_crossing").
    fixed = {"speed_hz": v.speed("speed_hz", speed_hz),
             "chamber_pressure_pa": chamber_pressure(system, chamber_pressure_pa),
             "config_ay_m": None if config_ay_m is None else v.finite("config_ay_m",
                                                                       config_ay_m)}
    if not field:
        fixed.pop(vary)
    else:  # a bound the model refuses (a clearance <= 0) is bad input, not a failed point
        for b in (lo, hi):
            try:
                set_field(system, vary, b, where="vary")
            except InputError as exc:
                raise InputError(f"bounds: the model refuses {vary} = {b:g} ({exc})") from None
    thermal = thermal_keywords(thermal)
    calls = [0]

    def g(x):
        calls[0] += 1
        p = dict(fixed)
        if not field:
            p[vary] = float(x)
        try:  # a model field: the system re-assembled with the field at x
            # Each system's first equilibrium of this call starts cold, the others continue
            # from it (rotordyn._common.calls): the same inputs give the same threshold bit
            # for bit whatever ran before (a warm start from an earlier call moved it by
            # ~2e-13 relative)
            sx = set_field(system, vary, float(x), where="bounds") if field else system
            return _point(sx, p, exclude_sleeve_modes, thermal)
        except InputError as exc:
            if str(exc).startswith("thermal."):  # the keywords' fault: every point refuses
                raise
            return math.nan, math.nan, f"error: {exc}", math.nan
        except RotordynError as exc:  # a failed point is a NaN, the scan goes on
            return math.nan, math.nan, f"error: {exc}", math.nan

    xs = np.linspace(lo, hi, n_scan)
    rows = []
    for x in xs:
        y, f, stt, re = g(x)
        rows.append({vary: x, "max_real_1_per_s": re, "verdict_real_1_per_s": y,
                     "stable": bool(y < 0) if np.isfinite(y) else None, "freq_hz": f,
                     "status": stt})
    # Refinement: where three neighbours share a sign but the parabola through them crosses
    # zero between them, evaluate at its extremum (two rounds).
    for _ in range(2):
        pts = sorted((r[vary], r["verdict_real_1_per_s"]) for r in rows
                     if np.isfinite(r["verdict_real_1_per_s"]))
        extra = []
        for (x0, y0), (x1, y1), (x2, y2) in zip(pts, pts[1:], pts[2:]):
            if not (np.sign(y0) == np.sign(y1) == np.sign(y2)):
                continue
            den = (x0 - x1) * (x0 - x2) * (x1 - x2)
            A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den
            B = (x2**2 * (y0 - y1) + x1**2 * (y2 - y0) + x0**2 * (y1 - y2)) / den
            if A == 0:
                continue
            xe = -B / (2 * A)
            ye = y1 + A * (xe - x1) ** 2 + (2 * A * x1 + B) * (xe - x1)
            if x0 < xe < x2 and np.sign(ye) != np.sign(y1):
                extra.append(float(xe))
        if not extra:
            break
        for x in extra:
            y, f, stt, re = g(x)
            rows.append({vary: x, "max_real_1_per_s": re, "verdict_real_1_per_s": y,
                         "stable": bool(y < 0) if np.isfinite(y) else None, "freq_hz": f,
                         "status": stt})
    scan = pd.DataFrame(rows).sort_values(vary, ignore_index=True)
    scan["stable"] = scan["stable"].astype("boolean")  # NA at a failed point
    ok = scan[np.isfinite(scan["verdict_real_1_per_s"])].reset_index(drop=True)
    base = dict(vary=vary, fixed=fixed, bounds=(lo, hi), xtol=xtol, scan=scan)
    re = ok["verdict_real_1_per_s"].to_numpy()
    idx = np.where(np.sign(re[:-1]) * np.sign(re[1:]) < 0)[0]
    n_failed = len(scan) - len(ok)
    if len(idx) == 0:
        # A failed point (no converged equilibrium) is neither stable nor unstable: it is
        # excluded from the scan and counted as failed (issue 13).
        if len(re) == 0:
            what = f"none of the {len(scan)} scanned points has a converged equilibrium"
        else:
            state = "unstable" if np.all(re > 0) else "stable"
            what = f"{state} at all {len(re)} scanned points with an equilibrium"
            if n_failed:
                what += f" ({n_failed} failed: " + ", ".join(
                    sorted(set(scan.loc[~np.isfinite(scan["verdict_real_1_per_s"]),
                                        "status"].str.split(":").str[0]))) + ")"
        return ThresholdResult(value=math.nan, whirl_frequency_hz=math.nan,
                               whirl_ratio=math.nan, stable_side="", evaluations=calls[0],
                               status="no_crossing" if len(re) else "no_equilibrium",
                               message=f"the stability verdict does not change in {vary} ∈ "
                                       f"[{lo:g}, {hi:g}]: {what} (a band narrower than the "
                                       "scan spacing can hide between them)",
                               **base)
    roots = []
    for i in idx:
        a, b = float(ok[vary][i]), float(ok[vary][i + 1])
        # The bracket's ends are the scan's own values (their signs found the crossing): a
        # re-evaluation at a scan point that sits on the root can differ in the last bits
        # (the equilibrium's tolerance) and flip the sign Brent's method checks.
        ends = {a: float(re[i]), b: float(re[i + 1])}
        try:
            roots.append((brentq(lambda x, e=ends: e[x] if x in e else g(x)[0], a, b,
                                 xtol=xtol, rtol=4 * np.finfo(float).eps, maxiter=200),
                          int(i)))
        except ValueError as exc:  # NaN inside the bracket
            return ThresholdResult(value=math.nan, whirl_frequency_hz=math.nan,
                                   whirl_ratio=math.nan, stable_side="", evaluations=calls[0],
                                   status="error",
                                   message=f"root finding failed in [{a:g}, {b:g}]: {exc}",
                                   **base)
    root, i = roots[0]
    _, f, _, _ = g(root)
    speed = root if vary == "speed_hz" else fixed["speed_hz"]
    side = "above" if re[i + 1] < 0 else "below"
    msg = ""
    if len(roots) > 1:
        msg = (f"{len(roots)} crossings in the bounds: "
               + ", ".join(f"{r:.6g}" for r, _ in roots) + "; value is the first")
    return ThresholdResult(value=float(root), whirl_frequency_hz=f,
                           whirl_ratio=f / speed if speed else math.nan, stable_side=side,
                           evaluations=calls[0], crossings=tuple(float(r) for r, _ in roots),
                           message=msg, **base)


@limited_blas
def stability_boundary(system: System, vary: str = "chamber_pressure_pa",
                       along: str = "config_ay_m", *, values, bounds, n_scan: int = 25,
                       **fixed) -> BoundaryResult:
    """Trace the threshold of ``vary`` across ``values`` of ``along`` (paper Fig. 9: p_c
    against a_y at 50 Hz; Fig. 10: p_c against speed at a_y = 0). Each point first searches a
    narrow bracket around the previous threshold (continuation), then the full ``bounds``."""
    import pandas as pd
    v.choice("vary", vary, OPERATING)
    v.choice("along", along, OPERATING)
    if along == vary:
        raise InputError("along: expected a parameter other than vary")
    check_operating_parameter(system, vary)
    check_operating_parameter(system, along, "along")
    vals = v.vector("values", values)
    if vals.size == 0:
        raise InputError("values: expected a non-empty 1-D array of finite values")
    lo, hi = v.bounds("bounds", bounds)
    rows, prev = [], None
    for x in vals:
        kw = dict(fixed)
        kw[along] = float(x)
        res = None
        if prev is not None and math.isfinite(prev):
            w = 0.15 * (hi - lo)
            nb = (max(lo, prev - w), min(hi, prev + w))
            res = threshold(system, vary, bounds=nb, n_scan=3, **kw)
            if res.status != "ok":
                res = None
        if res is None:
            res = threshold(system, vary, bounds=(lo, hi), n_scan=n_scan, **kw)
        prev = res.value
        rows.append({along: float(x), vary: res.value,
                     "whirl_frequency_hz": res.whirl_frequency_hz,
                     "whirl_ratio": res.whirl_ratio, "stable_side": res.stable_side,
                     "crossings": list(res.crossings),
                     "evaluations": res.evaluations, "status": res.status,
                     "message": res.message})
    return BoundaryResult(vary=vary, along=along, table=pd.DataFrame(rows))
