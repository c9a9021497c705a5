"""Pseudo-arclength continuation of periodic orbits of eq. 12 (docs/nonlinear.md): a branch of
limit cycles or unbalance-forced orbits over the chamber pressure, the speed or the
configuration a_y, with Floquet stability, folds continued past, and the bifurcations where a
multiplier crosses the unit circle.

The loop (predictor along the tangent, step-size control, bounds, detection) runs here; each
corrector is one C++ call (``_core.continuation_step``: the shooting Newton over CVODES,
bordered by ∂R/∂p and the arclength condition; its matrix starts from the previous point's
and is updated by Broyden from flows without sensitivities; Φ from forward sensitivities and
∂R/∂p — a central finite difference of two flows — are recomputed at the converged point)."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis.assembly import assembled, check_operating_parameter
from rotordyn.analysis.periodic import NEWTON, orbit_result
from rotordyn.errors import InputError
from rotordyn.model.system import System
from rotordyn.results.continuation import BranchResult
from rotordyn.results.periodic import PeriodicOrbitResult
from rotordyn.units import hz_to_rad_s

VARIABLES = ("chamber_pressure_pa", "speed_hz", "config_ay_m")
#: the correctors' names: "exact" is "sensitivities" (Newton with Φ and ∂R/∂p at every
#: iteration) by the name the CLI and sweep specs use beside "fast"
NEWTON_MODES = ("exact", "fast") + NEWTON
#: the choices of ``rotordyn continuation --newton``
CLI_NEWTON = ("exact", "fast")
#: the correctors when none is asked for (docs/nonlinear.md, "fast on a second model")
DEFAULT_NEWTON = "exact"
_PARAM = {"chamber_pressure_pa": "chamber_pressure", "speed_hz": "speed",
          "config_ay_m": "config"}


def _amplitude(o: PeriodicOrbitResult) -> np.ndarray:
    """(n_bearings,) the journals' amplitudes; a system without bearings: (1,) the largest
    distance of any coordinate from its mean over the orbit."""
    if o.journal_x_m.shape[1] == 0:
        return np.array([float(np.max(np.abs(o.r - o.r.mean(axis=0))))])
    return np.array([o.amplitude(b) for b in range(o.journal_x_m.shape[1])])


def _names(bcs) -> tuple:
    return tuple(bc.name for bc in bcs) if bcs else ("largest coordinate",)


def _clearances(bcs) -> np.ndarray:
    return np.array([bc.clearance_m for bc in bcs]) if bcs else np.array([np.nan])


def continuation(system: System, vary: str, bounds, start="equilibrium", **options):
    """Pseudo-arclength continuation of a branch over ``vary`` within ``bounds``.

    ``start`` a converged :class:`~rotordyn.results.PeriodicOrbitResult`: the branch of
    periodic orbits (:func:`orbit_continuation`, ``vary`` p_c, speed or a_y) →
    :class:`~rotordyn.results.BranchResult`. ``start="equilibrium"`` (the default) or a
    converged :class:`~rotordyn.results.EquilibriumResult`: the branch of static equilibria
    with their linear stability, Hopf points and folds
    (:func:`rotordyn.analysis.equilibrium_branch.equilibrium_continuation`; ``vary`` also any
    numeric model field path, e.g. ``"bearings.0.clearance_m"``; the operating point by
    ``speed_hz``, ``chamber_pressure_pa``, ``config_ay_m``) →
    :class:`~rotordyn.results.EquilibriumBranchResult`. ``options``: the keywords of the
    function called (InputError naming an unknown one)."""
    import inspect

    from rotordyn.analysis.equilibrium_branch import equilibrium_continuation
    from rotordyn.results.equilibrium import EquilibriumResult

    if isinstance(start, PeriodicOrbitResult):
        fn = orbit_continuation
    elif isinstance(start, EquilibriumResult) or (isinstance(start, str)
                                                  and start == "equilibrium"):
        fn = equilibrium_continuation
    else:
        raise InputError("start: expected a PeriodicOrbitResult (a converged orbit from "
                         "rotordyn.periodic_orbit), an EquilibriumResult or \"equilibrium\", "
                         f"got {type(start).__name__ if not isinstance(start, str) else start!r}")
    allowed = [k for k, prm in inspect.signature(fn).parameters.items()
               if prm.kind == prm.KEYWORD_ONLY]
    unknown = sorted(set(options) - set(allowed))
    if unknown:
        what = "an orbit" if fn is orbit_continuation else "an equilibrium"
        raise InputError(f"{unknown[0]}: not an option of {what} branch (allowed: "
                         f"{', '.join(allowed)})")
    return fn(system, vary, bounds, start, **options)


@limited_blas
def orbit_continuation(system: System, vary: str, bounds, start, *, unbalances=(),
                 ds: float = 0.05, ds_min: float = 1e-3, ds_max: float = 0.2,
                 max_points: int = 50, direction: int = 1, param_scale: float | None = None,
                 rtol: float = 1e-8, atol_m: float = 1e-12, tol: float = 1e-6,
                 max_iter: int = 8, max_steps: int = 200000, fd_step: float = 1e-4,
                 n_out: int = 101, sensitivity_rtol: float | None = None,
                 newton: str = DEFAULT_NEWTON, screen_rtol: float = 1e-4,
                 screen_margin: float = 0.005, progress=None) -> BranchResult:
    """Continue the periodic orbit ``start`` over ``vary`` within ``bounds``.

    Parameters
    ----------
    vary
        ``"chamber_pressure_pa"`` (Pa), ``"speed_hz"`` (Hz) or ``"config_ay_m"`` (m, the
        active bearing's vertical configuration); the other operating values are the start's.
    bounds
        (low, high) in the unit of ``vary``; must contain the start's value. The branch stops
        at the first point outside.
    start
        A converged :class:`~rotordyn.results.PeriodicOrbitResult` (autonomous: a limit cycle;
        forced: pass its ``unbalances`` again — the result does not keep them).
    ds, ds_min, ds_max
        Pseudo-arclength step in scaled units: positions / L (L the smallest film clearance),
        velocities / (L ω), the period / T_start, the parameter / ``param_scale``. The step
        grows ×1.5 after a corrector converging in ≤ 3 flows (≤ 4 with Broyden), halves after
        a failure or a turn of the tangent by more than 30°; the branch stops below
        ``ds_min``.
    max_points
        Points on the branch, the start included.
    direction
        +1: leave the start towards growing parameter, −1: decreasing.
    param_scale
        The parameter's scale in the arclength (unit of ``vary``); default high − low.
    rtol, atol_m, tol, max_iter, max_steps, n_out
        As for :func:`rotordyn.periodic_orbit` (tol also bounds the arclength residual).
    fd_step
        h / param_scale of the central difference ∂R/∂p.
    sensitivity_rtol
        Relative tolerance of the monodromy in the final (error-controlled) pass at each
        point (default ``rtol``): the accuracy of the multipliers and the tangent; looser is
        cheaper (as for :func:`rotordyn.periodic_orbit`).
    newton
        ``"exact"`` (default; ``"sensitivities"`` is the same): Φ and ∂R/∂p at every
        iteration. ``"broyden"``: each
        corrector starts from the previous point's bordered matrix and updates it by Broyden
        from flows without sensitivities; Φ and ∂R/∂p are recomputed at the converged point
        (and when a step does not halve the residual). Both converge within tol.
        ``"fast"`` (opt-in, issue 19's 50-point branch): Broyden as above, ∂R/∂p from one
        more CVODES sensitivity column (p_c, a_y; the speed keeps the central difference),
        and the final pass screened at ``screen_rtol`` (docs/nonlinear.md).
    screen_rtol, screen_margin
        ``newton="fast"`` only: each point's final pass (sensitivities in the error test)
        runs first at the sensitivity tolerance ``screen_rtol``, and again at
        ``sensitivity_rtol`` where the verdict is not safe at the looser one:
        ||μ_c| − 1| < ``screen_margin`` or |μ_trivial − 1| > ``screen_margin``. Each
        point's ``stats["monodromy_rtol"]`` says which tolerance its multipliers have
        (``screen_margin`` 0: never repeated, for measurements).
    progress
        None, or a callable(point_index, BranchResult-so-far message) for progress lines.

    Returns
    -------
    BranchResult
        status ``"ok"`` with at least the start point; ``"not_converged"`` when the start
        itself does not converge under these options.
    """
    vary = v.choice("vary", vary, VARIABLES)
    check_operating_parameter(system, vary)
    lo, hi = v.bounds("bounds", bounds)
    if not isinstance(start, PeriodicOrbitResult):
        raise InputError("start: expected a PeriodicOrbitResult (a converged orbit from "
                         f"rotordyn.periodic_orbit), got {type(start).__name__}")
    if not start.ok:
        raise InputError(f"start: the orbit did not converge (status {start.status!r}: "
                         f"{start.message})")
    ds, ds_min, ds_max, max_points, direction = v.arclength_steps(ds, ds_min, ds_max,
                                                                  max_points, direction)
    if param_scale is None:
        param_scale = hi - lo
    param_scale = v.positive("param_scale", param_scale)
    v.in_range("rtol", rtol, 1e-14, 1e-3)
    v.positive("atol_m", atol_m)
    v.positive("tol", tol)
    v.integer("max_iter", max_iter, lo=1, hi=1000)
    v.integer("max_steps", max_steps, lo=1)
    v.in_range("fd_step", fd_step, 1e-10, 0.1)
    v.integer("n_out", n_out, lo=2, hi=1_000_000)

    asm = assembled(system)
    n = asm.n
    if start.r.shape[1] != n:
        raise InputError(f"start: the orbit has {start.r.shape[1]} coordinates, the system {n}")
    kind = start.kind
    ub_list = v.unbalances("unbalances", unbalances, system.rotor.n_stations)
    if kind == "forced" and not ub_list:
        raise InputError("unbalances: a forced start needs its unbalances "
                         "[(station, mass_kg_m, phase_deg)] again")
    if kind == "autonomous" and ub_list:
        raise InputError("unbalances: an autonomous branch has no unbalance forcing")
    subharmonic = 1
    if kind == "forced":
        subharmonic = max(1, int(round(start.period_s * abs(start.speed_hz))))

    bcs = asm.bearings
    a0 = asm.config_vector(None)
    if bcs and abs(a0[bcs[0].jy] - start.config_ay_m) > 1e-15:
        a0 = asm.config_vector(start.config_ay_m)
    p_start = {"chamber_pressure_pa": start.chamber_pressure_pa, "speed_hz": start.speed_hz,
               "config_ay_m": start.config_ay_m}[vary]
    if not lo <= p_start <= hi:
        raise InputError(f"bounds: ({lo:g}, {hi:g}) must contain the start's {vary} = "
                         f"{p_start:g}")
    if vary == "speed_hz" and (lo <= 0 <= hi):
        raise InputError(f"bounds: a speed branch must not contain 0 Hz, got ({lo:g}, {hi:g})")

    inp = _core.ContinuationInput()
    base = _core.PeriodicInput()
    base.kind = _core.OrbitKind.autonomous if kind == "autonomous" else _core.OrbitKind.forced
    omega = hz_to_rad_s(float(start.speed_hz))
    base.omega = omega
    base.chamber_pressure = float(start.chamber_pressure_pa)
    uc, us = np.zeros(n), np.zeros(n)
    for st, me, ph in ub_list:
        L = asm.station_load_matrix(st)
        q = np.radians(ph)
        uc += me * (L[:, 0] * np.cos(q) + L[:, 1] * np.sin(q))
        us += me * (-L[:, 0] * np.sin(q) + L[:, 1] * np.cos(q))
    base.unbalance_cos, base.unbalance_sin = (uc, us) if ub_list else (np.zeros(0), np.zeros(0))
    base.t0 = float(start.t[0])
    base.n_out = int(n_out)
    # p in the core's units: Pa, rad/s, m; a(p) = a_base + p · direction for config
    to_core = hz_to_rad_s(1.0) if vary == "speed_hz" else 1.0
    if vary == "config_ay_m":
        a_base = asm.config_vector(0.0)
        inp.config_direction = asm.config_vector(1.0) - a_base
        base.a = a_base
    else:
        base.a = a0
    inp.parameter = getattr(_core.ContinuationParameter, _PARAM[vary])
    inp.subharmonic = subharmonic
    inp.fd_step = float(fd_step)
    inp.direction = int(direction)

    L = start.length_scale_m
    w = max(abs(omega), 2 * np.pi / start.period_s)
    scale = np.concatenate([np.full(n, L), np.full(n, L * w),
                            [start.period_s, param_scale * to_core]])
    inp.scale = scale
    opt = _core.ShootingOptions()
    c = _core.CvodeOptions()
    c.rtol, c.atol_position = float(rtol), float(atol_m)
    c.atol_velocity = float(atol_m) * max(w, 1.0)
    c.max_steps = int(max_steps)
    opt.cvode, opt.tol, opt.max_iter = c, float(tol), int(max_iter)
    if sensitivity_rtol is not None:
        opt.sensitivity_rtol = v.in_range("sensitivity_rtol", sensitivity_rtol, 1e-14, 0.1)
    newton = v.choice("newton", newton, NEWTON_MODES)
    if newton == "exact":
        newton = "sensitivities"
    opt.broyden = newton in ("broyden", "fast")
    if newton == "fast":
        opt.parameter_sensitivity = True
        opt.screen_rtol = v.in_range("screen_rtol", screen_rtol, 1e-14, 0.1)
        opt.screen_margin = v.in_range("screen_margin", screen_margin, 0.0, 0.5)

    def point_result(step, p_core):
        p = p_core / to_core
        spd = p if vary == "speed_hz" else start.speed_hz
        pc = p if vary == "chamber_pressure_pa" else start.chamber_pressure_pa
        if vary != "config_ay_m":
            return orbit_result(asm, step.orbit, kind, float(spd), float(pc), a0)
        a = base.a + p * np.asarray(inp.config_direction)
        o = orbit_result(asm, step.orbit, kind, float(spd), float(pc), np.asarray(a))
        # the result's config_ay_m is the first bearing's; the parameter is the active one's
        return dataclasses.replace(o, config_ay_m=float(p))

    def correct(x, T, p_core, y_prev, tangent, step_ds, jacobian=np.zeros((0, 0))):
        base.r0, base.v0, base.period = x[:n], x[n:], float(T)
        inp.jacobian = jacobian
        inp.base = base
        inp.p = float(p_core)
        inp.y_prev = y_prev
        inp.tangent = tangent
        inp.ds = float(step_ds)
        return _core.continuation_step(asm.solver, inp, opt)

    x0 = np.concatenate([start.r[0], start.v[0]])
    y_start = np.concatenate([x0, [start.period_s, p_start * to_core]])
    first = correct(x0, start.period_s, p_start * to_core, y_start, np.zeros(0), 0.0)
    orbits, ys, tangents, arcl, jacobians = [], [], [], [], []
    stats = {"correctors": 1, "failed_correctors": 0, "flows": first.orbit.iterations,
             "sensitivity_flows": first.orbit.sensitivity_flows, "fd_flows": first.fd_flows}
    if first.orbit.status != "ok":
        return BranchResult(
            vary=vary, kind=kind, parameter=np.zeros(0),
            amplitude_m=np.zeros((0, len(_names(bcs)))),
            period_s=np.zeros(0), max_multiplier=np.zeros(0), stable=np.zeros(0, bool),
            critical_type=(), arclength=np.zeros(0), tangent_p=np.zeros(0),
            bearing_names=_names(bcs), clearance_m=_clearances(bcs), bifurcations=(),
            bounds=(lo, hi), stop="start", message=first.orbit.message, stats=stats,
            status="not_converged")

    def accept(step):
        o = point_result(step, step.p)
        orbits.append(o)
        ys.append(np.concatenate([o.r[0], o.v[0], [o.period_s, step.p]]))
        tangents.append(np.asarray(step.tangent, dtype=float))
        jacobians.append(np.asarray(step.jacobian, dtype=float))
        if progress is not None:
            progress(len(orbits) - 1, repr(o))

    accept(first)
    arcl.append(0.0)
    stop, message = "max_points", ""
    hopf = None
    h = ds
    while len(orbits) < max_points:
        y, t = ys[-1], tangents[-1]
        yp = y + h * t * scale
        step = correct(yp[:2 * n], yp[2 * n], yp[2 * n + 1], y, t, h, jacobians[-1])
        stats["correctors"] += 1
        stats["flows"] += step.orbit.iterations
        stats["sensitivity_flows"] += step.orbit.sensitivity_flows
        stats["fd_flows"] += step.fd_flows
        o = step.orbit
        bad = o.status != "ok"
        if not bad and float(np.dot(step.tangent, t)) < np.cos(np.radians(30)):
            bad, o_msg = True, "the tangent turned by more than 30°"
        else:
            o_msg = o.message
        if bad:
            stats["failed_correctors"] += 1
            message = o_msg
            if o.status == "not_converged" and "equilibrium" in o.message:
                stop = "equilibrium"
                if h / 2 < ds_min:
                    break
            h /= 2
            if h < ds_min:
                stop = "rub" if o.status == "rub" else ("equilibrium" if stop == "equilibrium"
                                                        else "step_min")
                break
            continue
        p_new = step.p / to_core
        if not lo <= p_new <= hi:
            stop = "bound"
            break
        # Through a Hopf point the cycles shrink to the equilibrium and the branch of starts
        # x0 passes through it: the offsets of x0 from the orbits' mean points turn round
        # (a fold of cycles keeps them pointing the same way). The point beyond is the same
        # family half a period on: the branch ends there.
        o_new = point_result(step, step.p)
        if kind == "autonomous" and _offset_dot(orbits[-1], o_new, scale[:2 * n]) < 0:
            hopf = _hopf_estimate(orbits, o_new, vary)
            stop = "hopf"
            break
        accept(step)
        arcl.append(arcl[-1] + h)
        # a quick corrector (Broyden: its flows are cheaper and converge superlinearly, one
        # more is allowed) lets the step grow
        if o.iterations <= (3 if newton == "sensitivities" else 4):
            h = min(h * 1.5, ds_max)

    br = _branch(vary, kind, orbits, tangents, arcl, to_core, bcs, (lo, hi), stop, message,
                 stats)
    if hopf is not None:
        br = dataclasses.replace(br, bifurcations=br.bifurcations + (hopf,))
    return br


def _offset(o: PeriodicOrbitResult, dx: np.ndarray) -> np.ndarray:
    x = np.concatenate([o.r, o.v], axis=1)
    return (x[0] - x[:-1].mean(axis=0)) / dx


def _offset_dot(a: PeriodicOrbitResult, b: PeriodicOrbitResult, dx: np.ndarray) -> float:
    return float(np.dot(_offset(a, dx), _offset(b, dx)))


def _hopf_estimate(orbits, beyond: PeriodicOrbitResult, vary: str) -> dict:
    """The Hopf point where the branch meets the equilibrium: p against the signed amplitude
    (positive on the branch, negative beyond) through the last two points and the one
    beyond, a parabola p = p_H + b·A + c·A² evaluated at A = 0 (near a Hopf point
    A² ∝ |p − p_H|). ``curvature`` c (unit of ``vary`` per m²): with the cycles on the
    unstable side of the equilibrium and stable, the Hopf point is supercritical."""
    pts = list(orbits[-2:]) + [beyond]
    key = {"chamber_pressure_pa": "chamber_pressure_pa", "speed_hz": "speed_hz",
           "config_ay_m": "config_ay_m"}[vary]
    p = np.array([getattr(o, key) for o in pts])
    A = np.array([_amplitude(o)[0] for o in pts])
    A[-1] = -A[-1]
    if len(pts) == 3:
        coef = np.polyfit(A, p, 2)
        p_h, curv = float(coef[2]), float(coef[0])
    else:
        w = A[0] / (A[0] - A[1])
        p_h, curv = float(p[0] + w * (p[1] - p[0])), float("nan")
    nb = max(beyond.journal_x_m.shape[1], 1)
    return {"kind": "hopf", "index": len(orbits) - 1, "parameter": p_h,
            "amplitude_m": np.zeros(nb), "multiplier": complex(1.0), "curvature": curv,
            "period_s": float(beyond.period_s), "beyond_parameter": float(p[-1]),
            "beyond_amplitude_m": float(-A[-1])}


def _branch(vary, kind, orbits, tangents, arcl, to_core, bcs, bounds, stop, message, stats):
    n_pts = len(orbits)
    p = np.array([{"chamber_pressure_pa": o.chamber_pressure_pa, "speed_hz": o.speed_hz,
                   "config_ay_m": o.config_ay_m}[vary] for o in orbits])
    amp = np.array([_amplitude(o) for o in orbits]).reshape(n_pts, len(_names(bcs)))
    mm = np.array([abs(o.critical_multiplier) if o.critical_multiplier is not None else 0.0
                   for o in orbits])
    stable = np.array([o.stable for o in orbits], dtype=bool)
    ctype = tuple(o.critical_type for o in orbits)
    tp = np.array([t[-1] for t in tangents])
    bif = []
    for i in range(1, n_pts):
        turned = tp[i - 1] * tp[i] < 0
        crossed = (mm[i - 1] - 1.0) * (mm[i] - 1.0) < 0
        if not (turned or crossed):
            continue
        if turned:
            # where dp/ds = 0, linear in the arclength between the two points
            w = tp[i - 1] / (tp[i - 1] - tp[i])
            k = "fold"
        else:
            w = (1.0 - mm[i - 1]) / (mm[i] - mm[i - 1])
            unstable_side = i if mm[i] > 1 else i - 1
            ct = ctype[unstable_side]
            k = {"fold": "stability_change"}.get(ct, ct)
        mu = orbits[i].critical_multiplier
        bif.append({"kind": k, "index": i, "parameter": float(p[i - 1] + w * (p[i] - p[i - 1])),
                    "amplitude_m": amp[i - 1] + w * (amp[i] - amp[i - 1]),
                    "multiplier": complex(mu) if mu is not None else complex(np.nan)})
    return BranchResult(
        vary=vary, kind=kind, parameter=p, amplitude_m=amp,
        period_s=np.array([o.period_s for o in orbits]), max_multiplier=mm, stable=stable,
        critical_type=ctype, arclength=np.array(arcl, dtype=float), tangent_p=tp,
        bearing_names=_names(bcs), clearance_m=_clearances(bcs), bifurcations=tuple(bif),
        orbits=tuple(orbits), bounds=bounds, stop=stop, message=message, stats=stats,
        status="ok")
