"""Pseudo-arclength continuation of periodic orbits of eq. 12 (docs/nonlinear.md): a branch of
limit cycles or unbalance-forced orbits over the chamber pressure, the speed or the
configuration a_y, with Floquet stability, folds continued past, and the bifurcations where a
multiplier crosses the unit circle.

The loop (predictor along the tangent, step-size control, bounds, detection) runs here; each
corrector is one C++ call (``_core.continuation_step``: the shooting Newton over CVODES,
bordered by ∂R/∂p and the arclength condition; its matrix starts from the previous point's
and is updated by Broyden from flows without sensitivities; Φ from forward sensitivities and
∂R/∂p — a central finite difference of two flows — are recomputed at the converged point;
with ``floquet="samples"`` the multipliers come from the samples' linearisations, the
error-controlled flow only where the verdict is close).
``method="harmonic_balance"`` hands the branch to :mod:`rotordyn.analysis.hb_continuation`
(the correctors on the orbit's Fourier coefficients); what both share (the set-up from the
start orbit, the Hopf end, the assembly of the result) is :mod:`rotordyn.analysis.orbit_branch`."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis import hb_continuation as hbc
from rotordyn.analysis.orbit_branch import (PARAM, assemble, floquet_options, halved,
                                            hopf_estimate, prepare, rejected)
from rotordyn.analysis.periodic import NEWTON
from rotordyn.errors import InputError
from rotordyn.model.system import System
from rotordyn.results.continuation import BranchResult
from rotordyn.results.periodic import PeriodicOrbitResult

#: the correctors' names: "exact" is "sensitivities" (Newton with Φ and ∂R/∂p at every
#: iteration) by the name the CLI and sweep specs use beside "fast"
NEWTON_MODES = ("exact", "fast") + NEWTON
#: the choices of ``rotordyn continuation --newton``
CLI_NEWTON = ("exact", "fast")
#: the correctors when none is asked for (docs/nonlinear.md, "fast on a second model")
DEFAULT_NEWTON = "exact"
#: the correctors' methods: shooting (the default) or harmonic balance (``hb_continuation``)
METHODS = ("shooting", "harmonic_balance")
#: the options of the harmonic-balance correctors only (None: not given)
HB_OPTIONS = ("harmonics", "time_points")
#: the Floquet routes of a shooting branch point (the default first: today's final pass)
SHOOTING_FLOQUET = ("flow", "samples")


def field_method_error(vary: str) -> InputError:
    """The refusal of a corrector other than harmonic balance on a branch over a field."""
    return InputError(f"method: a branch over the model field {vary} has harmonic-balance "
                      "correctors only (method='harmonic_balance'; the shooting corrector "
                      "varies p_c, the speed or a_y inside the core)")


@limited_blas
def continuation(system: System, vary: str, bounds, start="equilibrium", **options):
    """Pseudo-arclength continuation of a branch over ``vary`` within ``bounds``.

    ``start`` a converged :class:`~rotordyn.results.PeriodicOrbitResult`: the branch of
    periodic orbits (:func:`orbit_continuation`, ``vary`` p_c, speed or a_y, or with
    ``method="harmonic_balance"`` a numeric model field path) →
    :class:`~rotordyn.results.BranchResult`. ``start="equilibrium"`` (the default) or a
    converged :class:`~rotordyn.results.EquilibriumResult`: the branch of static equilibria
    with their linear stability, Hopf points and folds
    (:func:`rotordyn.analysis.equilibrium_branch.equilibrium_continuation`; ``vary`` also any
    numeric model field path, e.g. ``"bearings.0.clearance_m"``; the operating point by
    ``speed_hz``, ``chamber_pressure_pa``, ``config_ay_m``) →
    :class:`~rotordyn.results.EquilibriumBranchResult`. ``options``: the keywords of the
    function called (InputError naming an unknown one). An orbit branch's multipliers:
    ``floquet`` applies to both methods — shooting ``"flow"`` (default: the error-controlled
    sensitivity flow at every point) or ``"samples"`` (the films' linearisations at the
    orbit's samples, the flow only where the verdict is within ``floquet_margin`` of the
    unit circle; ``floquet_tol`` refines first), harmonic balance ``"samples"`` (default),
    ``"hill"`` or ``"flow"``; each point's ``stats["floquet"]`` names its route."""
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


def _screens_apply(screens: dict, applies: bool) -> None:
    """``screen_rtol``/``screen_margin`` belong to the screened final pass of shooting's
    ``newton="fast"`` flow route; given anywhere else (where they would do nothing):
    InputError naming the field."""
    for k, val in screens.items():
        if val is not None and not applies:
            raise InputError(f"{k}: applies only to method='shooting' with newton='fast' and "
                             f"floquet='flow' (the screened final pass), got {val!r}")


@limited_blas
def orbit_continuation(system: System, vary: str, bounds, start, *, unbalances=(),
                 ds: float = 0.05, ds_min: float = 1e-3, ds_max: float = 0.2,
                 max_points: int = 50, direction: int = 1, param_scale: float | None = None,
                 rtol: float = 1e-8, atol_m: float = 1e-12, tol: float = 1e-6,
                 max_iter: int = 8, max_steps: int = 200000, fd_step: float = 1e-4,
                 n_out: int = 101, sensitivity_rtol: float | None = None,
                 newton: str = DEFAULT_NEWTON, screen_rtol: float | None = None,
                 screen_margin: float | None = None, method: str = "shooting",
                 harmonics: int | None = None, time_points: int | None = None,
                 floquet: str | None = None, floquet_margin: float | None = None,
                 floquet_tol: float | None = None, progress=None) -> BranchResult:
    """Continue the periodic orbit ``start`` over ``vary`` within ``bounds``.

    Parameters
    ----------
    vary
        ``"chamber_pressure_pa"`` (Pa), ``"speed_hz"`` (Hz) or ``"config_ay_m"`` (m, the
        active bearing's vertical configuration); the other operating values are the start's.
        With ``method="harmonic_balance"`` also a numeric model field path (e.g.
        ``"bearings.*.viscosity_pa_s"``, SI unit of the field): the system re-assembled at
        every value the core's corrector visits (:mod:`rotordyn.analysis.hb_field`; the
        start an orbit of ``system`` as passed, at its value of the field; docs/nonlinear.md,
        "Branches of limit cycles over a model field").
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
        cheaper (as for :func:`rotordyn.periodic_orbit`). With ``floquet="samples"``: of the
        flows that recheck close points only.
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
        ``newton="fast"`` with ``floquet="flow"`` only (given elsewhere: InputError; defaults
        1e-4 and 0.005): each point's final pass
        (sensitivities in the error test) runs first at the sensitivity tolerance
        ``screen_rtol``, and again at
        ``sensitivity_rtol`` where the verdict is not safe at the looser one:
        ||μ_c| − 1| < ``screen_margin`` or |μ_trivial − 1| > ``screen_margin``. Each
        point's ``stats["monodromy_rtol"]`` says which tolerance its multipliers have
        (``screen_margin`` 0: never repeated, for measurements).
    method
        ``"shooting"`` (default: the correctors above) or ``"harmonic_balance"``: each
        corrector is Newton on the orbit's Fourier coefficients, its frequency and the
        parameter (the AFT residual of ``rd.periodic_orbit(method="harmonic_balance")``),
        bordered by ∂R/∂p (exact for p_c and a_y, a central difference of ``fd_step`` for
        the speed) and the arclength row; ``tol`` is then the scaled AFT residual, ``ds``
        measures the coefficients / L, ω / ω_start and the parameter; ``rtol``,
        ``atol_m``, ``max_steps`` and ``sensitivity_rtol`` apply to the Floquet rechecks'
        flows only; ``newton`` does not apply (docs/nonlinear.md, "Continuation by harmonic
        balance"). Every point is a :class:`PeriodicOrbitResult` whose ``stats["method"]``
        names its method.
    harmonics, time_points
        Harmonic balance only: H (default 8) and the samples per period M ≥ 2H + 1
        (default 4H).
    floquet, floquet_margin
        Both methods. Shooting: ``"flow"`` (default) each converged point integrated once
        more with the sensitivities in CVODES's error test at ``sensitivity_rtol`` (its
        monodromy gives the multipliers and the tangent); ``"samples"`` no such pass (the
        tangent from the last Newton flow's sensitivities outside the error test), the
        multipliers from the films' linearisations at the orbit's ``n_out`` − 1 samples
        (4th-order Magnus, no flow), recomputed by one sensitivity flow at
        ``sensitivity_rtol`` where the critical multiplier is within ``floquet_margin``
        (default 0.01) of the unit circle or the trivial one is off 1 by more than half of
        it — the screen of the harmonic-balance corrector (docs/nonlinear.md, "Cheap
        multipliers on a shooting branch"; measured with ``newton="exact"``: with
        ``"fast"`` its screened final pass can be cheaper); a film closing at a sample is
        status ``"rub"``.
        Harmonic balance: ``"samples"`` (default) the same from the samples of the HB orbit;
        ``"hill"`` the multipliers by Hill's method from the converged orbit's HB Jacobian
        (no film solve beyond its max(M, 8H) linearisations), recomputed by the flow where
        the critical one is within ``floquet_margin`` + 3 × the trivial one's error of the
        unit circle (docs/nonlinear.md, "Floquet multipliers by Hill's method");
        ``"flow"`` the flow at every point. Each point's ``stats["floquet"]`` says which
        route gave its multipliers (``"samples"``, ``"refined"``, ``"hill"`` or ``"flow"``);
        the branch's ``stats["flow_rechecks"]`` counts the flow's rechecks (shooting: of the
        accepted points; harmonic balance: of every corrector).
    floquet_tol
        ``floquet="samples"`` only (both methods), in [0, 0.5] (default 0): > 0
        refines a point's multipliers where the screen calls its verdict close (the band of
        ``floquet_margin``) by the Magnus product at doubling step counts until |μ_c|
        moves by at most ``floquet_tol``·max(1, |μ_c|) (``periodic_orbit``'s
        ``floquet_tol``); the point's route is then ``"refined"`` with
        ``stats["floquet_error"]``, and the flow recomputes it only where the refinement
        leaves the verdict unresolved (not converged, or | |μ_c| − 1 | within its error).
        0: the flow at every close point.
    progress
        None, or a callable(point_index, BranchResult-so-far message) for progress lines.

    Returns
    -------
    BranchResult
        status ``"ok"`` with at least the start point; ``"not_converged"`` when the start
        itself does not converge under these options.
    """
    setup = prepare(system, vary, bounds, start, unbalances, param_scale, n_out)
    ds, ds_min, ds_max, max_points, direction = v.arclength_steps(ds, ds_min, ds_max,
                                                                  max_points, direction)
    v.in_range("rtol", rtol, 1e-14, 1e-3)
    v.positive("atol_m", atol_m)
    v.positive("tol", tol)
    v.integer("max_iter", max_iter, lo=1, hi=1000)
    v.integer("max_steps", max_steps, lo=1)
    v.in_range("fd_step", fd_step, 1e-10, 0.1)
    if sensitivity_rtol is not None:
        sensitivity_rtol = v.in_range("sensitivity_rtol", sensitivity_rtol, 1e-14, 0.1)
    newton = v.choice("newton", newton, NEWTON_MODES)
    method = v.choice("method", method, METHODS)
    if setup.field is not None and method != "harmonic_balance":
        raise field_method_error(setup.vary)
    screens = {"screen_rtol": screen_rtol, "screen_margin": screen_margin}
    if method == "harmonic_balance":
        _screens_apply(screens, False)
        if newton != DEFAULT_NEWTON:
            raise InputError(f"newton: applies only to method='shooting' (the correctors of "
                             f"harmonic balance are Newton on its coefficients), got "
                             f"{newton!r}")
        return hbc.hb_branch(setup, start, ds=ds, ds_min=ds_min, ds_max=ds_max,
                             max_points=max_points, direction=direction, rtol=rtol,
                             atol_m=atol_m, tol=tol, max_iter=max_iter, max_steps=max_steps,
                             fd_step=fd_step, sensitivity_rtol=sensitivity_rtol,
                             harmonics=harmonics, time_points=time_points, floquet=floquet,
                             floquet_margin=floquet_margin, floquet_tol=floquet_tol,
                             progress=progress)
    given = {"harmonics": harmonics, "time_points": time_points}
    for k in HB_OPTIONS:
        if given[k] is not None:
            raise InputError(f"{k}: applies only to method='harmonic_balance'")
    floquet, margin, ftol = floquet_options(floquet, floquet_margin, floquet_tol,
                                            SHOOTING_FLOQUET, SHOOTING_FLOQUET[0])
    _screens_apply(screens, newton == "fast" and floquet == "flow")
    if floquet == "flow" and floquet_margin is not None:  # as the command line refuses it
        raise InputError(f"floquet_margin: applies only to floquet='samples' with shooting "
                         f"(the flow route screens nothing), got {floquet_margin!r}")
    vary, lo, hi, asm, n, kind = (setup.vary, setup.lo, setup.hi, setup.asm, setup.n,
                                  setup.kind)
    bcs, base, to_core = setup.bcs, setup.base, setup.to_core
    p_start = setup.p_start
    inp = _core.ContinuationInput()
    if setup.config_direction is not None:
        inp.config_direction = setup.config_direction
    inp.parameter = getattr(_core.ContinuationParameter, PARAM[vary])
    inp.subharmonic = setup.subharmonic
    inp.fd_step = float(fd_step)
    inp.direction = int(direction)

    L = start.length_scale_m
    omega = setup.omega
    w = max(abs(omega), 2 * np.pi / start.period_s)
    scale = np.concatenate([np.full(n, L), np.full(n, L * w),
                            [start.period_s, setup.param_scale * to_core]])
    inp.scale = scale
    opt = _core.ShootingOptions()
    c = _core.CvodeOptions()
    c.rtol, c.atol_position = float(rtol), float(atol_m)
    c.atol_velocity = float(atol_m) * max(w, 1.0)
    c.max_steps = int(max_steps)
    opt.cvode, opt.tol, opt.max_iter = c, float(tol), int(max_iter)
    if sensitivity_rtol is not None:
        opt.sensitivity_rtol = sensitivity_rtol
    opt.floquet = getattr(_core.ShootingFloquet, floquet)
    opt.floquet_margin, opt.floquet_tol = margin, ftol
    if newton == "exact":
        newton = "sensitivities"
    opt.broyden = newton in ("broyden", "fast")
    if newton == "fast":
        opt.parameter_sensitivity = True
        opt.screen_rtol = v.in_range("screen_rtol", 1e-4 if screen_rtol is None
                                     else screen_rtol, 1e-14, 0.1)
        opt.screen_margin = v.in_range("screen_margin", 0.005 if screen_margin is None
                                       else screen_margin, 0.0, 0.5)

    def point_result(step, p_core):
        extra = {"method": "shooting", "floquet": step.floquet_route}
        if floquet == "samples":
            extra.update(floquet_samples_modulus=float(step.screen_critical_modulus),
                         floquet_samples_trivial_error=float(step.screen_trivial_error))
            if step.floquet_route == "refined":
                extra["floquet_error"] = float(step.floquet_error)
        return setup.point_result(step.orbit, p_core, extra_stats=extra)

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
    stats = {"method": "shooting", "floquet": floquet, "floquet_margin": margin,
             "floquet_tol": ftol, "correctors": 1, "failed_correctors": 0,
             "flows": first.orbit.iterations,
             "sensitivity_flows": first.orbit.sensitivity_flows, "fd_flows": first.fd_flows,
             "flow_rechecks": 0, "refined": 0}
    if first.orbit.status != "ok":
        return setup.failed(first.orbit.message, stats)

    def accept(step):
        if floquet == "samples":  # the points' routes (the flow route has no choice)
            stats["flow_rechecks"] += int(step.floquet_route == "flow")
            stats["refined"] += int(step.floquet_steps > 0)
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
        bad, o_msg = rejected(o.status, o.message, step.tangent, t)
        if bad:
            stats["failed_correctors"] += 1
            message = o_msg
            h, stop = halved(h, ds_min, o.status, o.message, stop)
            if h is None:
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
            hopf = hopf_estimate(orbits, o_new, vary)
            stop = "hopf"
            break
        accept(step)
        arcl.append(arcl[-1] + h)
        # a quick corrector (Broyden: its flows are cheaper and converge superlinearly, one
        # more is allowed) lets the step grow. The flows are counted as on the flow route:
        # Newton with sensitivities ends there with the final pass, which floquet="samples"
        # does not run (Broyden's last flow is repeated with sensitivities on both routes),
        # so both routes take the same steps
        flows = o.iterations + (floquet == "samples" and newton == "sensitivities")
        if flows <= (3 if newton == "sensitivities" else 4):
            h = min(h * 1.5, ds_max)

    br = assemble(vary, kind, orbits, tangents, arcl, bcs, (lo, hi), stop, message, stats)
    if hopf is not None:
        br = dataclasses.replace(br, bifurcations=br.bifurcations + (hopf,))
    return br


def _offset(o: PeriodicOrbitResult, dx: np.ndarray) -> np.ndarray:
    x = np.concatenate([o.r, o.v], axis=1)
    return (x[0] - x[:-1].mean(axis=0)) / dx


def _offset_dot(a: PeriodicOrbitResult, b: PeriodicOrbitResult, dx: np.ndarray) -> float:
    return float(np.dot(_offset(a, dx), _offset(b, dx)))
