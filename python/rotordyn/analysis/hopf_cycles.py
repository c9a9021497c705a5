"""The cycles born at a Hopf point at given amplitudes, by harmonic balance with the
parameter free (``rd.hopf_cycles``; docs/nonlinear.md, "The cycles at a Hopf point"): the
check of l1's verdict by the start of the branch itself, at the amplitudes an engineer cares
about.

At each amplitude a (a fraction of the smallest film clearance) one C++ call
(``_core.hb_continuation_step``) solves the harmonic-balance equations of eq. 12 for the
Fourier coefficients, the frequency and the parameter, bordered by the phase condition and
by an amplitude condition: the projection of the harmonics on the previous cycle's (the
leading-order cycle x_e + 2 Re(z q e^{iωt}) for the first) equals the target. Natural
continuation in amplitude: each cycle starts from the previous one scaled to the next
amplitude (a failed step is retried from up to 8 intermediate amplitudes). Floquet
multipliers as in the harmonic-balance continuation (samples, a CVODES flow where the
verdict is not safe from the samples)."""

from __future__ import annotations

import math

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis import harmonic_balance as hbal
from rotordyn.analysis.hb_continuation import (FLOQUET, FLOQUET_MARGIN, HARMONICS,
                                               corrector_options)
from rotordyn.analysis.orbit_branch import PARAM, setup_at
from rotordyn.errors import InputError
from rotordyn.results.hopf import HopfResult
from rotordyn.results.hopf_cycles import HopfCyclesResult

#: default amplitudes, fractions of the smallest film clearance
AMPLITUDES_C = (0.01, 0.02, 0.05, 0.1)
#: retries of a failed amplitude step: 2, 4, 8 sub-steps
_SUBSTEPS = (2, 4, 8)


def check_amplitudes(name: str, amplitudes_c) -> np.ndarray:
    """1 to 50 increasing fractions of the clearance in (0, 0.9] (InputError naming
    ``name``)."""
    try:
        amps = np.atleast_1d(np.asarray(amplitudes_c, dtype=float))
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected numbers, got {amplitudes_c!r}") from None
    if amps.ndim != 1 or not 1 <= amps.size <= 50:
        raise InputError(f"{name}: expected 1 to 50 values, got shape {amps.shape}")
    if not (np.all(np.isfinite(amps)) and np.all(amps > 0) and np.all(amps <= 0.9)):
        raise InputError(f"{name}: each in (0, 0.9] (fractions of the clearance), got "
                         f"{amps.tolist()}")
    if np.any(np.diff(amps) <= 0):
        raise InputError(f"{name}: expected increasing values, got {amps.tolist()}")
    return amps


@limited_blas
def hopf_cycles(system, result: HopfResult, amplitudes_c=AMPLITUDES_C, *,
                harmonics: int = HARMONICS, time_points: int | None = None,
                tol: float = 1e-10, rtol: float = 1e-8, atol_m: float = 1e-12,
                floquet: str = "samples", floquet_margin: float = FLOQUET_MARGIN,
                max_iter: int = 30,
                max_steps: int = 200000) -> HopfCyclesResult:
    """The limit cycles of the branch born at the Hopf point ``result`` (of
    :func:`rotordyn.hopf` on the same ``system``) at the amplitudes ``amplitudes_c``
    (fractions of the smallest film clearance, the HopfResult's ``length_scale_m``; each in
    (0, 0.9], sorted ascending): where each one is in ``result.vary`` (its side of the Hopf
    point), its period and Floquet stability. Cycles on the side where the equilibrium is
    stable coexist with it (a hard onset with hysteresis, whatever l1's sign says at smaller
    amplitudes); cycles on the unstable side that are stable are a soft onset.
    ``harmonics``, ``time_points``, ``tol``, ``max_iter`` as in
    ``rd.periodic_orbit(method="harmonic_balance")``; ``rtol``, ``atol_m``, ``max_steps``
    the CVODES options of the Floquet flow; ``floquet`` (``"samples"``, ``"hill"`` or
    ``"flow"``) and ``floquet_margin`` as in the harmonic-balance continuation (near the Hopf
    point |μ_c| is near 1, so every cycle is rechecked by the flow unless the margin is 0:
    on a stiff model the flow dominates the cost, and ``floquet="hill"`` with
    ``floquet_margin=0`` gives the stability from the Hill matrix alone). Rows that do not
    converge have their status and message; the rows after them start from the last converged
    cycle. A row whose corrector took no Newton step (the start already met ``tol``:
    very small amplitudes) is ``unresolved``, kept with its orbit but left out of the
    verdicts."""
    if not isinstance(result, HopfResult) or not result.ok:
        raise InputError("result: expected a HopfResult with status ok (from rotordyn.hopf)")
    if result.vary not in PARAM:
        raise InputError(f"result: a Hopf point over the model field {result.vary}; the "
                         "cycles at given amplitudes vary chamber_pressure_pa, speed_hz or "
                         "config_ay_m (a field's cycles: rotordyn.analysis.hopf.hopf_branch)")
    amps = check_amplitudes("amplitudes_c", amplitudes_c)
    h_ = v.integer("harmonics", harmonics, lo=1, hi=64)
    m_hb = hbal.time_points_for(h_, time_points)
    v.in_range("tol", tol, 1e-14, 1e-2)
    v.in_range("rtol", rtol, 1e-14, 1e-2)
    v.positive("atol_m", atol_m)
    floquet = v.choice("floquet", floquet, FLOQUET)
    v.in_range("floquet_margin", floquet_margin, 0.0, 0.5)
    v.integer("max_iter", max_iter, lo=1, hi=1000)
    v.integer("max_steps", max_steps, lo=100, hi=100_000_000)

    vary, p_h = result.vary, float(result.value)
    fixed = dict(result.fixed)
    spd = p_h if vary == "speed_hz" else float(result.speed_hz)
    pc = p_h if vary == "chamber_pressure_pa" else float(fixed.get("chamber_pressure_pa")
                                                          or 0.0)
    ay = p_h if vary == "config_ay_m" else fixed.get("config_ay_m")
    if ay is None:  # the model's own a_y (setup_at keeps its configuration vector then)
        from rotordyn.analysis.assembly import assembled

        asm0 = assembled(system)
        ay = float(asm0.config_vector(None)[asm0.bearings[0].jy]) if asm0.bearings else 0.0
    # the parameter's scale in the bordered system (the bounds only set it: the cycles'
    # parameter is free)
    span = 0.5 * max(abs(p_h), 1.0) if vary != "config_ay_m" else max(abs(p_h), 1e-3)
    w0 = 2 * math.pi * result.whirl_frequency_hz
    setup = setup_at(system, vary, (p_h - span, p_h + span), "autonomous", spd, pc, float(ay),
                     0.0, 1.0 / result.whirl_frequency_hz, (), None, 201)
    asm, n = setup.asm, setup.n
    if result.x_equilibrium.size != 2 * n:
        raise InputError(f"result: its state has {result.x_equilibrium.size} entries, the "
                         f"system {2 * n} (a HopfResult of another system)")
    nb = 2 * h_ + 1
    nn = nb * n
    L = float(result.length_scale_m)
    to_core = setup.to_core
    scale = np.array([L, w0, setup.param_scale * to_core])
    sfull = np.concatenate([np.full(nn, L), scale[1:]])

    inp = _core.HbContinuationInput()
    inp.base = setup.base
    inp.parameter = getattr(_core.ContinuationParameter, PARAM[vary])
    if setup.config_direction is not None:
        inp.config_direction = setup.config_direction
    inp.subharmonic = 1
    inp.fd_step = 1e-6
    inp.direction = 1
    inp.scale = scale
    opt = corrector_options(h_, m_hb, tol, max_iter, floquet, floquet_margin, rtol, atol_m,
                            max(abs(setup.omega), w0, 1.0), max_steps)

    def solve(y_prev):
        """The cycle whose harmonics project on y_prev's as y_prev's own do."""
        t = np.zeros_like(y_prev)
        t[n:nn] = (y_prev / sfull)[n:nn]
        t /= np.linalg.norm(t)
        inp.coefficients = np.ascontiguousarray(y_prev[:nn].reshape(nb, n))
        inp.frequency = float(y_prev[nn])
        inp.p = float(y_prev[nn + 1])
        inp.y_prev = y_prev
        inp.tangent = t
        inp.ds = 0.0
        return _core.hb_continuation_step(asm.solver, inp, opt)

    def scaled(y, a_from, a_to):
        y = y.copy()
        y[n:nn] *= a_to / a_from
        return y

    # the leading-order cycle at the first amplitude: the largest journal semi-major axis
    # (amplitude_coefficient / z2_per_unit per |z|²) equal to a·L
    q = np.asarray(result.q)[:n]
    per_z2 = float(np.max(result.amplitude_coefficient)) / float(result.z2_per_unit)
    z0 = np.zeros((nb, n))
    z0[0] = np.asarray(result.x_equilibrium)[:n]
    z0[1], z0[2] = 2 * q.real, -2 * q.imag
    y_unit = np.concatenate([z0.ravel(), [w0, p_h * to_core]])
    y_last, a_last = None, None
    rows = []
    stats = {"correctors": 0, "newton_iterations": 0, "flow_rechecks": 0, "substeps": 0}
    for a in amps:
        step, y_new = None, None
        for k in ((1,) if y_last is None else (1,) + _SUBSTEPS):
            stats["substeps"] += k - 1
            if y_last is None:  # the leading-order cycle at this amplitude
                y_cur, a_cur = y_unit.copy(), 1.0
                y_cur[n:nn] *= L / math.sqrt(per_z2)
            else:
                y_cur, a_cur = y_last, a_last
            for a_t in ([a] if k == 1 else np.geomspace(a_last, a, k + 1)[1:]):
                step = solve(scaled(y_cur, a_cur, a_t))
                stats["correctors"] += 1
                stats["newton_iterations"] += int(step.hb.orbit.iterations)
                stats["flow_rechecks"] += int(step.floquet_route == "flow")
                if step.hb.orbit.status != "ok":
                    y_cur = None
                    break
                y_cur = np.concatenate([np.asarray(step.hb.coefficients).ravel(),
                                        [step.hb.frequency, step.p]])
                a_cur = float(a_t)
            if y_cur is not None:
                y_new = y_cur
                break
        if y_new is None:
            rows.append({"amplitude_c": float(a), "status": step.hb.orbit.status,
                         "message": step.hb.orbit.message, "orbit": None, "value": math.nan})
            continue
        o = setup.point_result(step.hb.orbit, step.p, extra_stats={
            **hbal.hb_stats(step.hb), "floquet": step.floquet_route})
        status, message = "ok", ""
        if int(step.hb.orbit.iterations) == 0:
            # the start already satisfied the residual: no Newton step, the parameter is the
            # leading-order estimate's, never corrected
            status = "unresolved"
            message = (f"the start satisfies the harmonic-balance residual (tol {tol:g}) at "
                       f"{a:g} c: the cycle's {vary} is not resolved at this amplitude (a "
                       "larger amplitude, or a smaller tol)")
        rows.append({"amplitude_c": float(a), "status": status, "message": message,
                     "orbit": o, "value": float(step.p / to_core),
                     "floquet": step.floquet_route})
        y_last, a_last = y_new, float(a)
    return HopfCyclesResult.from_rows(result, rows, stats, harmonics=h_, time_points=int(m_hb))
