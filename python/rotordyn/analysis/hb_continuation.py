"""Pseudo-arclength continuation of periodic orbits by harmonic balance
(``rd.continuation(..., method="harmonic_balance")``; docs/nonlinear.md, "Continuation by
harmonic balance"): the branch loop (predictor along the tangent, step control, bounds, the
Hopf end) runs here; each corrector is one C++ call (``_core.hb_continuation_step``: Newton on
the Fourier coefficients, the frequency and the parameter, bordered by ∂R/∂p and the arclength
row, the AFT residual and Jacobian of ``rd.periodic_orbit(method="harmonic_balance")``). Each
point's Floquet multipliers come from the samples' linearisations, and where the verdict is
not safe from the samples (``floquet_margin``) from their refined product (``floquet_tol`` >
0) or one CVODES sensitivity flow; every point's ``stats["floquet"]`` says which."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn.analysis import harmonic_balance as hbal
from rotordyn.analysis.hb_field import field_systems
from rotordyn.analysis.orbit_branch import (FLOQUET_MARGIN, PARAM, BranchSetup, assemble,
                                            floquet_options, halved, hopf_estimate, rejected)
from rotordyn.analysis.periodic import periodic_orbit
from rotordyn.errors import InputError
from rotordyn.results.continuation import BranchResult
from rotordyn.results.periodic import PeriodicOrbitResult

#: the Floquet routes of a branch point (``"none"`` would leave the stability unknown)
FLOQUET = ("samples", "hill", "flow")
#: defaults of the harmonic-balance options of a branch
HARMONICS = 8


def start_coefficients(start: PeriodicOrbitResult, harmonics: int) -> np.ndarray:
    """(2H + 1, n) Fourier coefficients of the start orbit's positions (rows c0, a_1, b_1, …):
    a harmonic-balance orbit's own (truncated or padded to H), else the projection of its
    samples over one period (equally spaced, the repeated endpoint left out; at least 2H + 1
    of them)."""
    nb = 2 * harmonics + 1
    n = start.r.shape[1]
    z = start.stats.get("coefficients")
    if start.stats.get("method") == "harmonic_balance" and z is not None \
            and np.shape(z)[1:] == (n,):
        z = np.asarray(z, dtype=float)
        out = np.zeros((nb, n))
        k = min(nb, z.shape[0])
        out[:k] = z[:k]
        return out
    t = np.asarray(start.t, dtype=float)
    r = np.asarray(start.r, dtype=float)[:-1]
    m0 = r.shape[0]
    if m0 < nb:
        raise InputError(f"start: the orbit has {m0} samples per period; harmonic balance with "
                         f"{harmonics} harmonics needs at least 2H + 1 = {nb} (solve the start "
                         "with a larger n_out)")
    dt = np.diff(t)
    if not np.allclose(dt, start.period_s / m0, rtol=1e-6, atol=0.0):
        raise InputError("start: the orbit's samples are not equally spaced over one period")
    tau = 2 * np.pi * np.arange(m0) / m0
    out = np.zeros((nb, n))
    out[0] = r.mean(axis=0)
    for k in range(1, harmonics + 1):
        out[2 * k - 1] = 2.0 / m0 * np.cos(k * tau) @ r
        out[2 * k] = 2.0 / m0 * np.sin(k * tau) @ r
    return out


def needs_flow(o: PeriodicOrbitResult, margin: float) -> bool:
    """Whether the multipliers of ``o`` from the samples do not give a safe verdict: the
    critical one within ``margin`` of the unit circle (or none), or the trivial one off 1 by
    more than ``margin`` / 2 (the samples' monodromy is poor: its |μ_c| error was measured up
    to about 1.5 × the trivial multiplier's; the rule of the C++ corrector)."""
    mc, mt = o.critical_multiplier, o.trivial_multiplier
    return (mc is None or abs(abs(mc) - 1.0) < margin
            or (mt is not None and abs(mt - 1.0) > 0.5 * margin))


def screen_stats(step, floquet: str) -> dict:
    """The screening route's |μ_c| and trivial error of a corrector step, keyed by the route:
    ``floquet_hill_*`` (floquet "hill") or ``floquet_samples_*`` (the samples: floquet
    "samples", and "flow" where they are computed for the record)."""
    screen = "hill" if floquet == "hill" else "samples"
    return {f"floquet_{screen}_modulus": float(step.screen_critical_modulus),
            f"floquet_{screen}_trivial_error": float(step.screen_trivial_error)}


def corrector_options(harmonics: int, time_points: int, tol: float, max_iter: int,
                      floquet: str, margin: float, rtol: float, atol_m: float,
                      velocity_scale: float, max_steps: int,
                      sensitivity_rtol: float | None = None, floquet_tol: float = 0.0):
    """The ``_core.HbContinuationOptions`` of a harmonic-balance corrector: H, M, the Newton
    tolerance and iterations, the Floquet route, margin and refinement tolerance, and the
    CVODES options of the flow (atol on velocities = ``atol_m`` × ``velocity_scale``, rad/s)."""
    c = _core.CvodeOptions()
    c.rtol, c.atol_position = float(rtol), float(atol_m)
    c.atol_velocity = float(atol_m) * float(velocity_scale)
    c.max_steps = int(max_steps)
    ho = _core.HarmonicBalanceOptions()
    ho.harmonics, ho.time_points = int(harmonics), int(time_points)
    ho.tol, ho.max_iter = float(tol), int(max_iter)
    ho.floquet = getattr(_core.HbFloquet, floquet)
    # > 0: a close screen is refined before the flow (finish_point, hb_detail.cpp)
    ho.floquet_tol = float(floquet_tol)
    ho.cvode = c
    if sensitivity_rtol is not None:
        ho.sensitivity_rtol = float(sensitivity_rtol)
    opt = _core.HbContinuationOptions()
    opt.hb = ho
    opt.floquet_margin = float(margin)
    return opt


def checked_orbit(system, speed_hz: float, chamber_pressure_pa: float, config_ay_m, *, start,
                  period_s: float, harmonics: int = HARMONICS, time_points: int | None = None,
                  n_out: int = 201, rtol: float = 1e-8, tol: float = 1e-6,
                  sensitivity_rtol: float | None = None,
                  margin: float = FLOQUET_MARGIN) -> PeriodicOrbitResult:
    """A limit cycle by harmonic balance from a state ``start`` (r, ṙ) with a period guess,
    its multipliers from the samples, or — where :func:`needs_flow` — from one CVODES
    sensitivity flow from the converged orbit (the rule of the branch's points);
    ``stats["floquet"]`` says which."""
    kw = dict(method="harmonic_balance", harmonics=harmonics, time_points=time_points,
              n_out=n_out, rtol=rtol, tol=tol, sensitivity_rtol=sensitivity_rtol)
    o = periodic_orbit(system, speed_hz, chamber_pressure_pa, config_ay_m, start=start,
                       period_s=period_s, floquet="samples", floquet_tol=0.0, **kw)
    # (floquet_tol 0: the single product from the samples, screened by needs_flow as the
    # branch's C++ corrector screens its points; the refinement is not used here yet.)
    route = "samples"
    if o.ok and needs_flow(o, margin):
        o = periodic_orbit(system, speed_hz, chamber_pressure_pa, config_ay_m,
                           start=(o.r[0], o.v[0]), period_s=o.period_s, floquet="flow", **kw)
        route = "flow"
    return dataclasses.replace(o, stats={**o.stats, "floquet": route})


def hb_branch(setup: BranchSetup, start: PeriodicOrbitResult, *, ds: float, ds_min: float,
              ds_max: float, max_points: int, direction: int, rtol: float, atol_m: float,
              tol: float, max_iter: int, max_steps: int, fd_step: float,
              sensitivity_rtol: float | None, harmonics: int | None,
              time_points: int | None, floquet: str | None, floquet_margin: float | None,
              floquet_tol: float | None = None, progress=None) -> BranchResult:
    """The branch of ``setup`` from ``start`` by harmonic-balance correctors (the options
    checked by :func:`rotordyn.analysis.continuation.orbit_continuation`, which calls this)."""
    h_ = HARMONICS if harmonics is None else harmonics
    m_hb = hbal.time_points_for(h_, time_points)
    h_ = int(h_)
    floquet, margin, ftol = floquet_options(floquet, floquet_margin, floquet_tol, FLOQUET,
                                            "samples")
    asm, n, kind = setup.asm, setup.n, setup.kind
    nb = 2 * h_ + 1
    nn = nb * n
    z0 = start_coefficients(start, h_)
    w0 = 2 * np.pi / float(start.period_s)

    inp = _core.HbContinuationInput()
    inp.base = setup.base
    if setup.field is None:
        inp.parameter = getattr(_core.ContinuationParameter, PARAM[setup.vary])
    if setup.config_direction is not None:
        inp.config_direction = setup.config_direction
    inp.subharmonic = setup.subharmonic
    inp.fd_step = float(fd_step)
    inp.direction = int(direction)
    to_core = setup.to_core
    L = float(start.length_scale_m)
    scale = np.array([L, w0, setup.param_scale * to_core])
    inp.scale = scale
    sfull = np.concatenate([np.full(nn, L), scale[1:]])

    opt = corrector_options(h_, m_hb, tol, max_iter, floquet, margin, rtol, atol_m,
                            max(abs(setup.omega), w0, 1.0), max_steps, sensitivity_rtol,
                            ftol)

    # a model field: the core asks for the system re-assembled at every value it visits
    systems = asm.solver if setup.field is None else field_systems(setup)

    def correct(z, w, p_core, y_prev, tangent, step_ds):
        inp.coefficients = np.ascontiguousarray(z.reshape(nb, n))
        inp.frequency = float(w)
        inp.p = float(p_core)
        inp.y_prev = y_prev
        inp.tangent = tangent
        inp.ds = float(step_ds)
        return _core.hb_continuation_step(systems, inp, opt)

    stats = {"method": "harmonic_balance", "harmonics": h_, "time_points": int(m_hb),
             "floquet": floquet, "floquet_margin": float(margin), "floquet_tol": ftol,
             "correctors": 0, "failed_correctors": 0, "newton_iterations": 0,
             "evaluations": 0, "linearizations": 0, "fd_evaluations": 0, "flow_rechecks": 0,
             "refined": 0}

    def tally(step):
        stats["correctors"] += 1
        stats["newton_iterations"] += int(step.hb.orbit.iterations)
        stats["evaluations"] += int(step.hb.evaluations)
        stats["linearizations"] += int(step.hb.linearizations)
        stats["fd_evaluations"] += int(step.fd_evaluations)
        stats["flow_rechecks"] += int(step.floquet_route == "flow")
        stats["refined"] += int(step.floquet_steps > 0)  # refined (then maybe the flow)

    def result(step):
        return setup.point_result(step.hb.orbit, step.p, extra_stats={
            **hbal.hb_stats(step.hb), "floquet": step.floquet_route,
            **screen_stats(step, floquet),
            **({"floquet_error": float(step.floquet_error)}
               if step.floquet_route == "refined" else {}),
            "fd_evaluations": int(step.fd_evaluations)})

    p0 = setup.p_start * to_core
    y_start = np.concatenate([z0.ravel(), [w0, p0]])
    first = correct(z0.ravel(), w0, p0, y_start, np.zeros(0), 0.0)
    tally(first)
    if first.hb.orbit.status != "ok":
        return setup.failed(first.hb.orbit.message, stats)
    orbits, ys, tangents, arcl = [], [], [], []

    def accept(step, o):
        orbits.append(o)
        ys.append(np.concatenate([np.asarray(step.hb.coefficients).ravel(),
                                  [step.hb.frequency, step.p]]))
        tangents.append(np.asarray(step.tangent, dtype=float))
        if progress is not None:
            progress(len(orbits) - 1, repr(o))

    accept(first, result(first))
    arcl.append(0.0)
    lo, hi = setup.lo, setup.hi
    stop, message, hopf = "max_points", "", None
    h = ds
    while len(orbits) < max_points:
        y, t = ys[-1], tangents[-1]
        yp = y + h * t * sfull
        step = correct(yp[:nn], yp[nn], yp[nn + 1], y, t, h)
        tally(step)
        o_core = step.hb.orbit
        bad, msg = rejected(o_core.status, o_core.message, step.tangent, t)
        if bad:
            stats["failed_correctors"] += 1
            message = msg
            h, stop = halved(h, ds_min, o_core.status, o_core.message, stop)
            if h is None:
                break
            continue
        if not lo <= step.p / to_core <= hi:
            stop = "bound"
            break
        o_new = result(step)
        # through a Hopf point the cycles shrink onto the equilibrium and the branch passes
        # through it onto the same family half a period on: the harmonics turn round
        if kind == "autonomous" and float(np.dot(y[n:nn], np.asarray(
                step.hb.coefficients).ravel()[n:])) < 0:
            hopf = hopf_estimate(orbits, o_new, setup.vary)
            stop = "hopf"
            break
        accept(step, o_new)
        arcl.append(arcl[-1] + h)
        if o_core.iterations <= 3:  # a quick corrector lets the step grow
            h = min(h * 1.5, ds_max)
    if setup.field is not None:
        stats["assemblies"] = setup.field.assemblies
    br = assemble(setup.vary, kind, orbits, tangents, arcl, setup.bcs, (lo, hi), stop,
                  message, stats)
    if hopf is not None:
        br = dataclasses.replace(br, bifurcations=br.bifurcations + (hopf,))
    return br
