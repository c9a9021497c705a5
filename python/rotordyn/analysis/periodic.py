"""Periodic orbits of the nonlinear system (paper eq. 12, every film by the Reynolds equation,
sleeve and pad coordinates included) by single shooting, with their Floquet multipliers
(docs/nonlinear.md): self-excited limit cycles (the oil whirl of paper Fig. 11) and orbits
forced by unbalance (period k·2π/Ω)."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis import harmonic_balance as hbal
from rotordyn.analysis.assembly import assembled, chamber_pressure
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.model.system import System
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.results.periodic import PeriodicOrbitResult
from rotordyn.results.transient import TransientResult
from rotordyn.units import hz_to_rad_s

KINDS = ("autonomous", "forced")
METHODS = ("shooting", "harmonic_balance")
#: shooting's sources of the monodromy (harmonic balance: harmonic_balance.FLOQUET)
SHOOTING_FLOQUET = ("flow", "samples", "none")
NEWTON = ("broyden", "sensitivities")
FORCED_STARTS = ("linear", "equilibrium")
SENSITIVITY_SOLVES = ("blocked", "columns")


def period_from_transient(result: TransientResult, bearing: int = 0,
                          last_fraction: float = 0.5) -> float:
    """Period of the motion at the end of a transient, s: the mean spacing of the upward
    crossings of the journal's horizontal displacement through its mean over the last
    ``last_fraction`` of the run (crossing times interpolated linearly between samples).
    InputError when fewer than three crossings (the run has not settled on an oscillation,
    or is sampled too coarsely)."""
    n = max(8, int(len(result.t) * last_fraction))
    t = np.asarray(result.t[-n:], dtype=float)
    x = np.asarray(result.journal_x_m[-n:, bearing], dtype=float)
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(x))):
        raise InputError("start: the transient has non-finite samples in its last part "
                         f"(status {result.status!r})")
    z = x - x.mean()
    k = np.nonzero((z[:-1] < 0) & (z[1:] >= 0))[0]
    if k.size < 3:
        raise InputError(f"start: the last {last_fraction:g} of the transient has {k.size} "
                         "upward crossings of the journal's mean position (at least 3 needed "
                         "to estimate a period): it has not settled on an oscillation, or its "
                         "output is too coarse (raise n_out)")
    tc = t[k] - z[k] * (t[k + 1] - t[k]) / (z[k + 1] - z[k])
    return float(np.mean(np.diff(tc)))


@limited_blas
def periodic_orbit(system: System, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
                   config_ay_m: float | None = None, *, kind: str = "autonomous",
                   start=None, period_s: float | None = None, subharmonic: int = 1,
                   unbalances=(), n_out: int = 201, rtol: float = 1e-8,
                   atol_m: float = 1e-12, tol: float = 1e-6, max_iter: int = 30,
                   max_steps: int = 200000,
                   sensitivity_error_control: bool = False,
                   sensitivity_rtol: float | None = None,
                   newton: str = "sensitivities", method: str = "shooting",
                   harmonics: int = 8, time_points: int | None = None,
                   floquet: str | None = None, floquet_tol: float = 1e-3,
                   floquet_max_steps: int = 0,
                   start_amplitude_c: float | None = None,
                   forced_start: str = "linear",
                   bdf_max_order: int = 5,
                   sensitivity_solve: str = "columns") -> PeriodicOrbitResult:
    """Periodic orbit of eq. 12 by single shooting, with its Floquet multipliers.

    Unknowns: the state x0 = (r, ṙ) (2n) at t0, and for ``kind="autonomous"`` the period T
    (with the phase condition that the new start lies on the hyperplane through the previous
    one normal to the flow). Newton on R = x(t0 + T) − x0, with the monodromy matrix
    Φ = ∂x(t0 + T)/∂x0 from CVODES forward sensitivities integrated with the orbit
    (docs/nonlinear.md: method and accuracy). The Floquet multipliers are the eigenvalues
    of Φ.

    Parameters
    ----------
    speed_hz, chamber_pressure_pa, config_ay_m
        The operating point, as for :func:`rotordyn.transient` (constant speed and pressure).
    kind
        ``"autonomous"``: a self-excited limit cycle (no unbalance; period unknown);
        ``"forced"``: the orbit forced by ``unbalances`` [(station, mass_kg_m, phase_deg)]
        with period ``subharmonic``/``speed_hz`` (``period_s``, if given, must equal it).
    start
        A :class:`~rotordyn.results.TransientResult` (its last sample is the start, at its
        time t0 for a forced orbit, and for an autonomous one the period is estimated from
        its last half unless ``period_s`` is given), or a state: an array (2n,) = (r, ṙ) or a
        pair (r (n,), ṙ (n,)) in m and m/s. None (forced orbits only: an autonomous cycle
        needs a start on or near it; harmonic balance excepted, below): by
        ``forced_start``.
    period_s
        s; autonomous: the first guess (required with a state start); forced: optional.
    n_out
        Samples of the converged orbit over one period.
    rtol, atol_m
        CVODES tolerances (positions atol_m, velocities atol_m·max(Ω, 2π/T)); the
        sensitivities are in the error test with the same relative tolerance.
    tol
        Convergence: the largest component of x(t0 + T) − x0 below tol × (the smallest
        film clearance; velocities: × max(Ω, 2π/T)). A full Newton step that lowers the
        residual by less than half has met the flows' own error: with ``floquet`` "samples"
        or "none" their state tolerances (rtol, atol_m) are then tightened tenfold, at most
        twice (``stats["flow_tol_factor"]`` 0.1 or 0.01), before the sensitivities go into
        the error test; with "flow" they go into it at once (docs/nonlinear.md, "The
        residual's floor").
    max_iter, max_steps
        Newton iterations; CVODES steps per period.
    sensitivity_error_control
        Keep the sensitivities in CVODES's error test during the Newton iterations too
        (default: only in the final pass over the converged orbit, which gives the reported
        monodromy and multipliers).
    sensitivity_rtol
        Relative tolerance of the sensitivities in the error test (default ``rtol``): the
        accuracy of the monodromy matrix and the multipliers; looser is cheaper.
    newton
        The matrix of the Newton iterations before the final pass: ``"sensitivities"``
        (default) Φ from sensitivities in every iteration; ``"broyden"`` Φ from one flow with
        sensitivities, then Broyden's rank-one secant updates from flows without them (each
        as cheap as a transient period), refreshed by sensitivities when a step does not
        halve the residual. Both converge to the orbit within tol; Broyden stops just under
        tol where Newton overshoots far below it (docs/nonlinear.md).
    method
        ``"shooting"`` (default, above) or ``"harmonic_balance"``: the Fourier coefficients
        of the positions (``harmonics`` H, ``time_points`` M ≥ 2H + 1 samples per period,
        default 4H) by Newton on the AFT residual of eq. 12 (film forces and K_H, D_H by
        Reynolds at each sample); ``tol`` is then the scaled residual (units of the smallest
        clearance), ``rtol``/``atol_m`` only matter for a state start (one flow) and for
        ``floquet="flow"``; newton, sensitivity_error_control do not apply. Start: a
        TransientResult (its last period resampled), a state with period_s (one flow), or
        for an autonomous cycle None: the equilibrium plus its least-damped whirl mode with
        the journal at ``start_amplitude_c`` of the clearance (docs/nonlinear.md); None
        (default): 0.3, then 0.6, then 0.9 until one converges (an oil whip's cycle near the
        clearance is out of reach from 0.3; the result's ``stats["start_amplitude_c"]`` is
        the start that converged, every start tried is in the message of a failure).
    floquet
        shooting: ``"flow"`` (default) the converged orbit integrated once more with the
        sensitivities in CVODES's error test; ``"samples"`` no such pass, the monodromy by
        4th-order Magnus on the converged orbit's film linearisations at its ``n_out`` − 1
        samples, refined on the orbit's trigonometric interpolant as below (the exponentials
        take a flexible rotor's stiff bending modes exactly, where the error-controlled pass
        resolves them with nanosecond steps: the overhung pump, docs/nonlinear.md); ``"none"``
        the orbit only (no multipliers: ``stability_resolved`` False).
        Harmonic balance: ``"samples"`` (default; the monodromy from the converged orbit's M
        linearisations, 4th-order Magnus, no film solve), ``"hill"`` (Hill's method: the
        eigenvalues of the Hill matrix of the linearised orbit, from the harmonic-balance
        Jacobian on max(M, 8H) samples, one exponent kept per family by the centroid of its
        eigenvector's harmonics; no film solve beyond those linearisations), ``"flow"`` (one
        CVODES sensitivity flow at ``sensitivity_rtol``) or ``"none"`` (docs/nonlinear.md,
        "Floquet multipliers by Hill's method": their accuracy measured against the flow).
    floquet_tol, floquet_max_steps
        ``floquet="samples"`` (shooting: from the ``n_out`` − 1 samples, at most 128 of them
        per sample by default; ``floquet_tol`` > 0): the monodromy is refined on the orbit
        itself (the films
        linearised between the samples, 4th-order Magnus with Simpson nodes, the steps per
        period doubled from M/2, at most ``floquet_max_steps``, default 128M) until |μ_c|
        moves by at most ``floquet_tol``·max(1, |μ_c|) between two levels;
        ``stats["floquet_error"]`` is that last change and ``stats["floquet_resolved"]`` is
        False (``stability_resolved`` of the result) when it did not converge or | |μ_c| − 1 |
        ≤ the error: the stable/unstable verdict is then not decided (use ``"flow"``).
        ``floquet_tol=0``: the former single product from the M samples (A(τ) interpolated),
        no error estimate (docs/nonlinear.md, "Refined sample multipliers").
    forced_start
        A forced orbit with ``start=None``: ``"linear"`` (default) the linearised system's
        unbalance response at the static equilibrium, r_e + Re(q e^{iΩt}) (the films' K_H,
        D_H there; halved while a film would close to a tenth of its clearance:
        ``stats["linear_start_scale"]``), the orbit's first harmonic at small unbalance;
        ``"equilibrium"`` the static equilibrium at rest (the start before; docs/nonlinear.md
        "Forced orbits from the linear response").
    bdf_max_order
        Highest BDF order of the CVODES flows (1–5, default 5), as for
        :func:`rotordyn.transient`: 2 can pay on a flexible rotor whose lightly damped
        bending modes hold orders 3–5 at their stability limit (``stats["order_reductions"]``
        many per flow) at loose tolerances (the overhung pump at atol 1e-9 m: 839 steps per
        period instead of 2,562); at atol_m 1e-12 it took more steps there (12,709 against
        8,345; docs/nonlinear.md "Shooting on a flexible rotor").
    sensitivity_solve
        The corrector of the monodromy's sensitivity columns: ``"columns"`` (default)
        CVODES's own corrector, one back-substitution per column with its lagged Newton
        matrix; ``"blocked"`` (opt-in) all 2n columns in one solve per iteration with the
        exact matrix I − γA (2.45× less CPU on the pump's Newton flows; it changes the
        Newton path, so three tests measured on the columns' path differ: not the default
        yet, docs/nonlinear.md). Same error tests.

    Returns
    -------
    PeriodicOrbitResult
        status ``"ok"``, or ``"not_converged"`` (Newton did not converge: the start is not
        near a periodic orbit), ``"rub"`` (a film closed) with a message; multipliers only
        for ``"ok"``.
    """
    kind = v.choice("kind", kind, KINDS)
    forced_start = v.choice("forced_start", forced_start, FORCED_STARTS)
    start_scale = sigma = None
    method = v.choice("method", method, METHODS)
    hb = method == "harmonic_balance"
    if floquet is None:
        floquet = "samples" if hb else "flow"
    elif not hb:
        floquet = v.choice("floquet", floquet, SHOOTING_FLOQUET)
        if floquet == "samples":
            v.in_range("floquet_tol", floquet_tol, 0.0, 0.5, lo_open=True)
            v.integer("floquet_max_steps", floquet_max_steps, lo=0)
    if hb:
        m_hb = hbal.time_points_for(harmonics, time_points)
        if start_amplitude_c is not None:
            v.in_range("start_amplitude_c", start_amplitude_c, 1e-6, 0.99)
        elif kind == "autonomous" and start is None:
            return _amplitude_ladder(locals())
    v.speed("speed_hz", speed_hz)
    chamber_pressure(system, chamber_pressure_pa)
    if config_ay_m is not None:
        v.finite("config_ay_m", config_ay_m)
    v.integer("n_out", n_out, lo=2, hi=1_000_000)
    v.integer("subharmonic", subharmonic, lo=1, hi=1000)
    v.in_range("rtol", rtol, 1e-14, 1e-3)
    v.positive("atol_m", atol_m)
    v.positive("tol", tol)
    v.integer("max_iter", max_iter, lo=1, hi=1000)
    v.integer("max_steps", max_steps, lo=1)
    if period_s is not None:
        period_s = v.positive("period_s", period_s)
    asm = assembled(system)
    n = asm.n
    ub_list = v.unbalances("unbalances", unbalances, system.rotor.n_stations)
    if kind == "autonomous" and ub_list:
        raise InputError("unbalances: an autonomous limit cycle has no unbalance forcing; use "
                         "kind='forced' for the unbalance response")
    if kind == "forced":
        if not ub_list:
            raise InputError("unbalances: kind='forced' needs at least one unbalance "
                             "(station, mass_kg_m, phase_deg)")
        if speed_hz == 0:
            raise InputError("speed_hz: a forced orbit needs a speed != 0 Hz")
        t_rev = subharmonic / abs(float(speed_hz))
        if period_s is not None and abs(period_s - t_rev) > 1e-9 * t_rev:
            raise InputError(f"period_s: a forced orbit has the period subharmonic/speed_hz = "
                             f"{t_rev:.9g} s, got {period_s:.9g} s (set subharmonic for "
                             "k-fold periods)")
        period_s = t_rev
    a = asm.config_vector(config_ay_m)

    t0 = 0.0
    samples = None
    if isinstance(start, TransientResult):
        if start.status not in ("ok", "contact") or len(start.t) < 2:
            raise InputError(f"start: the transient did not finish (status {start.status!r}: "
                             f"{start.message})")
        if start.r.shape[1] != n:
            raise InputError(f"start: the transient has {start.r.shape[1]} coordinates, the "
                             f"system {n}")
        r0, v0 = np.array(start.r[-1], dtype=float), np.array(start.v[-1], dtype=float)
        t0 = float(start.t[-1]) if kind == "forced" else 0.0
        if period_s is None:
            period_s = period_from_transient(start)
        if hb:
            samples, t_first = hbal.samples_from_transient(start, float(period_s), m_hb)
            r0, v0 = samples[0].copy(), np.zeros(n)
            t0 = t_first if kind == "forced" else 0.0
    elif start is None:
        if hb and kind == "autonomous":
            e = equilibrium(system, speed_hz, chamber_pressure_pa, config_ay_m, warm_start=False)
            if e.status not in CONVERGED:
                raise ConvergenceError(f"periodic_orbit: no equilibrium to start from "
                                       f"({e.status}: {e.message}); give start")
            samples, p_lin = hbal.samples_from_equilibrium(
                asm, hz_to_rad_s(float(speed_hz)), np.array(e.r, dtype=float),
                float(start_amplitude_c), m_hb)
            r0, v0 = samples[0].copy(), np.zeros(n)
            if period_s is None:
                period_s = p_lin
        elif kind == "autonomous":
            raise InputError("start: an autonomous limit cycle needs a start on or near it: a "
                             "TransientResult that settled on the cycle, or a state (r, v) "
                             "with period_s")
        else:
            e = equilibrium(system, speed_hz, chamber_pressure_pa, config_ay_m,
                            warm_start=False)
            if e.status not in CONVERGED:
                raise ConvergenceError(f"periodic_orbit: no equilibrium to start from "
                                       f"({e.status}: {e.message}); give start")
            r0, v0 = np.array(e.r, dtype=float), np.zeros(n)
            if forced_start == "linear":
                # the linear unbalance response at the equilibrium: the orbit's first
                # harmonic at small unbalance (scaled down where it would close a film)
                uc, us = _unbalance_vectors(asm, ub_list)
                om = hz_to_rad_s(float(speed_hz))
                q, sigma = hbal.linear_forced_response(asm, om, r0, uc, us)
                lin, start_scale = hbal.forced_start(asm, om, r0, q, subharmonic,
                                                     m_hb if hb else 32)
                if hb:
                    samples = lin
                else:
                    r0, v0 = lin[0].copy(), start_scale * np.real(1j * om * q)
            elif hb:
                samples = np.repeat(r0[None, :], m_hb, axis=0)
    else:
        if isinstance(start, (tuple, list)) and len(start) == 2:
            r0, v0 = v.vector("start[0]", start[0], n), v.vector("start[1]", start[1], n)
        else:
            x = v.vector("start", start, 2 * n)
            r0, v0 = x[:n].copy(), x[n:].copy()
        if period_s is None:
            raise InputError("period_s: an autonomous orbit from a state start needs a first "
                             "guess of the period (s, > 0)")
    h0 = np.asarray(asm.solver.film_h_min(r0), dtype=float)
    if np.any(h0 <= 0):
        k = int(np.argmin(h0))
        raise InputError(f"start: the start closes film '{asm.model.films[k].name}' (minimum "
                         f"film thickness {h0[k]:.3g} m)")

    uc, us = _unbalance_vectors(asm, ub_list)

    # the linear start's scale (1: the linear response itself; < 1: halved to keep the films
    # open); absent for any other start
    start_stats = {} if start_scale is None else {"linear_start_scale": float(start_scale)}
    if hb and kind == "autonomous" and start is None:  # the whirl-mode start's amplitude
        start_stats["start_amplitude_c"] = float(start_amplitude_c)
    omega = hz_to_rad_s(float(speed_hz))
    inp = _core.PeriodicInput()
    inp.kind = _core.OrbitKind.autonomous if kind == "autonomous" else _core.OrbitKind.forced
    inp.omega = omega
    inp.chamber_pressure = float(chamber_pressure_pa)
    inp.a = a
    inp.unbalance_cos, inp.unbalance_sin = (uc, us) if ub_list else (np.zeros(0), np.zeros(0))
    inp.r0, inp.v0 = r0, v0
    inp.t0 = t0
    inp.period = float(period_s)
    inp.n_out = int(n_out)
    c = _core.CvodeOptions()
    c.rtol, c.atol_position = float(rtol), float(atol_m)
    c.atol_velocity = float(atol_m) * max(abs(omega), 2 * np.pi / float(period_s), 1.0)
    c.max_steps = int(max_steps)
    c.max_order = v.integer("bdf_max_order", bdf_max_order, lo=1, hi=5)
    if sensitivity_rtol is not None:
        v.in_range("sensitivity_rtol", sensitivity_rtol, 1e-14, 0.1)
    if hb:
        res = hbal.solve(asm, inp, samples, harmonics=harmonics, time_points=m_hb, tol=tol,
                         max_iter=max_iter, floquet=floquet, cvode=c,
                         sensitivity_rtol=sensitivity_rtol, floquet_tol=floquet_tol,
                         floquet_max_steps=floquet_max_steps)
        return _with_hint(orbit_result(asm, res.orbit, kind, float(speed_hz),
                                       float(chamber_pressure_pa), a,
                                       extra_stats={**hbal.hb_stats(res), **start_stats}),
                          start_scale, sigma)
    opt = _core.ShootingOptions()
    opt.cvode = c
    opt.tol = float(tol)
    opt.max_iter = int(max_iter)
    if sensitivity_rtol is not None:
        opt.sensitivity_rtol = v.in_range("sensitivity_rtol", sensitivity_rtol, 1e-14, 0.1)
    opt.sensitivity_error_control = v.boolean("sensitivity_error_control",
                                              sensitivity_error_control)
    opt.broyden = v.choice("newton", newton, NEWTON) == "broyden"
    opt.blocked_sensitivities = v.choice("sensitivity_solve", sensitivity_solve,
                                         SENSITIVITY_SOLVES) == "blocked"
    opt.floquet = getattr(_core.ShootingFloquet, floquet)
    if floquet == "samples":
        opt.floquet_tol = float(floquet_tol)
        opt.floquet_max_steps = int(floquet_max_steps)
    res = _core.periodic_orbit(asm.solver, inp, opt)
    return _with_hint(orbit_result(asm, res, kind, float(speed_hz), float(chamber_pressure_pa),
                                   a, extra_stats={**shooting_floquet_stats(res, floquet),
                                                   **start_stats}), start_scale, sigma)


def shooting_floquet_stats(res, floquet: str) -> dict:
    """``stats`` entries of shooting's monodromy: its route, and for ``"samples"`` the
    refinement's error estimate, whether it met floquet_tol, the verdict's resolution
    (converged and | |μ_c| − 1 | > the error), steps and film linearisations."""
    out = {"floquet_route": floquet}
    if floquet != "samples" or res.status != "ok":
        return out
    return {**out, **hbal.refined_entries(res.floquet, res)}


#: the start amplitudes (fractions of the clearance) tried in turn for a harmonic-balance
#: limit cycle from the equilibrium when none is given
START_AMPLITUDES_C = (0.3, 0.6, 0.9)


def _amplitude_ladder(kw: dict) -> PeriodicOrbitResult:
    """periodic_orbit with ``kw`` (its arguments) from each of START_AMPLITUDES_C until one
    converges; the last failure names every start tried."""
    args = {k: kw[k] for k in ("system", "speed_hz", "chamber_pressure_pa", "config_ay_m")}
    opts = {k: kw[k] for k in ("kind", "start", "period_s", "subharmonic", "unbalances",
                               "n_out", "rtol", "atol_m", "tol", "max_iter", "max_steps",
                               "sensitivity_error_control", "sensitivity_rtol", "newton",
                               "method", "harmonics", "time_points", "floquet",
                               "forced_start", "bdf_max_order", "sensitivity_solve",
                               "floquet_tol", "floquet_max_steps")}
    res, closed, tried = None, None, []
    for amp in START_AMPLITUDES_C:
        try:
            got = periodic_orbit(*args.values(), **opts, start_amplitude_c=amp)
        except InputError as exc:  # a start that large closes a film: no larger one is tried
            if not str(exc).startswith("start: the start closes film"):
                raise
            closed = f"{amp:g} closes a film"
            break
        tried.append(f"{amp:g}")
        if got.ok:
            return got
        res = got
    if res is None:
        raise InputError(f"start_amplitude_c: every start from the equilibrium's whirl mode "
                         f"closes a film ({closed}); give a smaller start_amplitude_c")
    why = (f"at {', '.join(tried)} of the clearance in turn"
           + (f"; a start of {closed}" if closed else ""))
    return dataclasses.replace(res, message=f"{res.message} (started from the equilibrium's "
                                            f"whirl mode {why})")


def _with_hint(res: PeriodicOrbitResult, start_scale, sigma) -> PeriodicOrbitResult:
    """A forced orbit from the linear start that failed: its message says what to do next
    (the settling time from the equilibrium's least-damped mode, or that there is none)."""
    if res.ok or start_scale is None:
        return res
    how = ("the linear unbalance response at the equilibrium" if start_scale == 1.0 else
           f"the linear unbalance response at the equilibrium scaled by {start_scale:.3g} "
           "(at full size it closes a film to a tenth of its clearance: a large orbit)")
    if not np.isfinite(sigma):
        what = ("the equilibrium's eigenvalues are not known (no settling time to suggest): "
                "run a transient to see where the motion goes")
    elif sigma < 0:
        settle = np.log(100.0) / -sigma
        what = (f"the equilibrium's least-damped mode decays as exp({sigma:.4g} t), so a "
                f"transient with the unbalance settles to 1 % in about {settle:.3g} s: give "
                f"start=rotordyn.transient(system, {settle:.3g}, ..., unbalances=...) "
                f"(command line: --settle-s {settle:.3g}), or continue the orbit over the "
                "speed from a speed where it converged (rotordyn.continuation)")
    else:
        what = (f"the equilibrium is unstable (an eigenvalue with real part {sigma:.4g} 1/s): "
                "there may be no stable forced orbit near it (a whirl beside the unbalance "
                "response); run a transient to see where the motion goes")
    return dataclasses.replace(res, message=f"{res.message}; started from {how}; {what}")


def _unbalance_vectors(asm, ub_list) -> tuple[np.ndarray, np.ndarray]:
    """u_c, u_s (n,): the unbalance force is Ω² (u_c cos Ωt + u_s sin Ωt)."""
    uc, us = np.zeros(asm.n), np.zeros(asm.n)
    for st, me, ph in ub_list:
        L = asm.station_load_matrix(st)
        p = np.radians(ph)
        uc += me * (L[:, 0] * np.cos(p) + L[:, 1] * np.sin(p))
        us += me * (-L[:, 0] * np.sin(p) + L[:, 1] * np.cos(p))
    return uc, us


def orbit_result(asm, res, kind: str, speed_hz: float, chamber_pressure_pa: float,
                 a: np.ndarray, extra_stats: dict | None = None) -> PeriodicOrbitResult:
    """The :class:`PeriodicOrbitResult` of a C++ shooting (or corrector) result ``res`` at
    the operating point (speed_hz, chamber_pressure_pa, configuration a (n,))."""
    n = asm.n
    status, message = res.status, res.message
    bcs = asm.bearings
    ok = status == "ok"
    r = np.asarray(res.r) if ok else np.zeros((0, n))
    vv = np.asarray(res.v) if ok else np.zeros((0, n))
    fl = res.floquet
    mu = np.asarray(fl.multipliers, dtype=complex) if ok else np.zeros(0, dtype=complex)
    if ok and not (np.all(np.isfinite(r)) and np.all(np.isfinite(mu))):
        status, message, ok = "error", "non-finite orbit or multipliers reported as ok", False
    stats = {}
    if ok and mu.size == 0:  # floquet="none": no verdict (not "unstable")
        stats["floquet_resolved"] = False
    return PeriodicOrbitResult(
        kind=kind, speed_hz=float(speed_hz), chamber_pressure_pa=float(chamber_pressure_pa),
        config_ay_m=float(a[bcs[0].jy]) if bcs else 0.0,
        period_s=float(res.period), t=np.asarray(res.t) if ok else np.zeros(0), r=r, v=vv,
        journal_x_m=r[:, [bc.jx for bc in bcs]], journal_y_m=r[:, [bc.jy for bc in bcs]],
        clearance_m=np.array([bc.clearance_m for bc in bcs]),
        bearing_names=tuple(bc.name for bc in bcs),
        monodromy=np.asarray(res.monodromy) if ok else np.zeros((0, 0)),
        multipliers=mu, trivial_index=int(fl.trivial) if ok else -1,
        critical_index=int(fl.critical) if ok else -1, stable=bool(fl.stable) and ok,
        critical_type=fl.critical_type if ok else "",
        residuals=np.asarray(res.residuals, dtype=float), length_scale_m=float(res.length_scale),
        stats={"iterations": res.iterations, "steps": res.steps, "rhs_evals": res.rhs_evals,
               "sens_rhs_evals": res.sens_rhs_evals, "jac_evals": res.jac_evals,
               "reynolds_solves": res.reynolds_solves,
               "sensitivity_flows": res.sensitivity_flows,
               "order_reductions": res.order_reductions,
               "sens_linear_solves": res.sens_linear_solves,
               "sens_factorizations": res.sens_factorizations,
               "monodromy_rtol": float(res.monodromy_rtol),
               "flow_tol_factor": float(getattr(res, "flow_tol_factor", 1.0)),
               "newton_correction": float(res.newton_correction), **(extra_stats or {}),
               **stats},
        status=status, message=message)
