"""Steady unbalance response of the linearised system (paper §5: forced response under the
centrifugal forces of imbalance), with speed-dependent bearing coefficients."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import assembled, chamber_pressure
from rotordyn.analysis.equilibrium import equilibrium_options
from rotordyn.analysis.linear import FD_REL_STEP, LINEARIZATION_METHODS
from rotordyn.errors import ConvergenceError, InputError
from rotordyn._common.status import point_messages
from rotordyn.results.equilibrium import CONVERGED
from rotordyn._common import validate as v
from rotordyn.model.system import System
from rotordyn.results.unbalance import RIPPLE_PROMINENCE, UnbalanceResult, half_power_walk
from rotordyn.units import hz_to_rad_s


REFINE_LEVELS = 6    # at most 6 refinements of a peak: 1 Hz grid → 1/4⁶ Hz ≈ 0.25 mHz
REFINE_POINTS = 3    # new speeds on each side of a peak per refinement (spacing / 4)
BAND_TOL_REL = 2e-3  # half-power speeds bracketed to 0.2 % of N_c (AF converged to ~1 %)


def _unresolved_peaks(u: UnbalanceResult) -> list[int]:
    """Indices of local maxima (of |x|, |y| or the orbit's major axis at any station) whose
    neighbours are not both above the half-power level a/√2, or farther apart than
    2 BAND_TOL_REL × N_c: the peak lies between grid points and its height, speed and
    half-power band (AF) are not resolved yet."""
    out = set()
    s = u.speeds_hz
    for a in (np.abs(u.x), np.abs(u.y), u.major_m):
        for k in range(a.shape[1]):
            v = a[:, k]
            for i in range(1, len(v) - 1):
                if v[i] > v[i - 1] and v[i] >= v[i + 1] and (
                        min(v[i - 1], v[i + 1]) < v[i] / np.sqrt(2)
                        or s[i + 1] - s[i - 1] > 2 * BAND_TOL_REL * s[i]) \
                        and not _ripple(v, i):
                    out.add(i)
    return sorted(out)


def _ripple(v, i) -> bool:
    """Whether the local maximum v[i] rises less than RIPPLE_PROMINENCE of its height above
    the valley separating it from a higher one: film-coefficient ripple, which
    :meth:`UnbalanceResult.peaks` does not count, so the grid is not refined for it (an
    undersampled resonance stands well above its sampled neighbours, so it is not one)."""
    from scipy.signal import peak_prominences

    v = np.nan_to_num(v, nan=0.0)
    return bool(peak_prominences(v, [i])[0][0] < RIPPLE_PROMINENCE * v[i])


def _unresolved_bands(u: UnbalanceResult) -> list[tuple[float, float]]:
    """Grid intervals holding a half-power speed N₁ or N₂ of a peak of the orbit's major axis
    (what :meth:`UnbalanceResult.peaks` reads), at any station, wider than BAND_TOL_REL × N_c:
    the AF interpolated across them is not converged, so a station's AF depended on which
    other stations refined the grid (issue 18). A side whose walk climbs into another
    resonance first has no half-power speed (``peaks()`` calls its AF unresolved): nothing to
    refine there (the walk went on past the neighbour, refining a band no AF reads)."""
    s = u.speeds_hz
    out = []
    for k in range(u.major_m.shape[1]):
        v = u.major_m[:, k]
        for i in range(1, len(v) - 1):
            if not (v[i] > v[i - 1] and v[i] >= v[i + 1]) or _ripple(v, i):
                continue
            half = v[i] / np.sqrt(2)
            tol = BAND_TOL_REL * s[i]
            for step in (-1, 1):
                j, cut = half_power_walk(v, i, half, step)
                lo, hi = (j, j + 1) if step < 0 else (j - 1, j)
                if not cut and v[j] <= half and s[hi] - s[lo] > tol:
                    out.append((s[lo], s[hi]))
    return out


def _merge(a: UnbalanceResult, b: UnbalanceResult) -> UnbalanceResult:
    sp = np.concatenate([a.speeds_hz, b.speeds_hz])
    o = np.argsort(sp, kind="stable")
    return UnbalanceResult(sp[o], a.stations, np.concatenate([a.x, b.x])[o],
                           np.concatenate([a.y, b.y])[o],
                           np.concatenate([a.point_status, b.point_status])[o], a.unbalances,
                           a.operating_speed_hz,
                           None if a.max_real_1_per_s is None else
                           np.concatenate([a.max_real_1_per_s, b.max_real_1_per_s])[o],
                           thermal=tuple(np.array(a.thermal + b.thermal, dtype=object)[o])
                           if a.thermal else (),
                           point_message=np.concatenate([a.point_message, b.point_message])[o])


def _linear_rotor(system, asm, sp, chamber_pressure_pa, config_ay_m, F1, Cout, X, Y, status,
                  message):
    """A system without bearing elements: its linear model is M, C + ΩG, K at every speed
    and its equilibrium does not depend on the speed, so the equilibrium is solved once (its
    status is every speed's) and all speeds are one C++ call (one symbolic analysis of the
    pencil, a numeric LU per speed): the numbers each speed factorises are those of the
    per-speed loop (K_H = D_H = 0). Fills X, Y, status, message in place. Not with rotating
    shaft damping (K + Ω K_c and the equilibrium change with the speed: the per-speed path)."""
    from rotordyn.analysis.equilibrium import equilibrium
    from rotordyn.errors import RotordynError

    try:
        e = equilibrium(system, float(sp[0]), chamber_pressure_pa, config_ay_m)
    except RotordynError as exc:
        status[:] = "error"
        message[:] = [f"{type(exc).__name__}: {exc}"] * len(message)
        return
    status[:] = e.status
    if e.status not in CONVERGED:
        message[:] = [e.message] * len(message)
        return
    m = asm.model
    O = np.concatenate(Cout, axis=0)  # (2 n_out, n): x, y of each output station
    Z = np.asarray(_core.harmonic_sweep(m.M, m.C, m.G, m.K, hz_to_rad_s(sp), F1, O))
    X[:] = Z[:, 0::2]
    Y[:] = Z[:, 1::2]


def _with_bearings(system, asm, sp, chamber_pressure_pa, config_ay_m, method, check, threads,
                   F1, Cout, X, Y, status, max_real, message):
    """All speeds in one C++ call (``_core.unbalance_sweep``): per speed the equilibrium
    continued from the last converged one (the first from this system's last equilibrium, as
    :func:`rotordyn.equilibrium` warm-starts), K_H(Ω), D_H(Ω) (eq. 18), then
    (K + K_H − Ω² M + iΩ (C + ΩG + D_H)) q = Ω² F₁ and, with ``check``, the largest real part
    of eq. 19's eigenvalues: the numbers the per-speed path (equilibrium, linearize,
    harmonic_response, modal) computed. Fills X, Y, status, max_real, message in place;
    ConvergenceError where the dynamic stiffness is singular (as the per-speed solve raised)."""
    a = np.tile(asm.config_vector(config_ay_m, None), (sp.size, 1))
    r0 = asm.last_r if asm.last_r is not None else np.zeros(0)
    pen = asm.pad_penalty if asm.pad_penalty is not None else np.zeros((0, 0))
    O = np.concatenate(Cout, axis=0)  # (2 n_out, n): x, y of each output station
    res = _core.unbalance_sweep(
        asm.model, hz_to_rad_s(sp), np.full(sp.size, float(chamber_pressure_pa)), a, r0, equilibrium_options(),
        pen, F1, O, method == "finite_difference", FD_REL_STEP, bool(asm.bearings), check,
        asm.rotor.xy_pairs(), asm.rotor.rot_pairs(), int(threads))
    st = list(res.status)
    ok = [i for i, s in enumerate(st) if s == "ok"]
    if ok:  # the warm start of the next equilibrium of this system, as equilibrium() keeps it
        asm.last_r = np.array(np.asarray(res.r)[ok[-1]])
    for i, msg in enumerate(res.solve_error):
        if msg:
            raise ConvergenceError(f"unbalance response at {sp[i]:g} Hz: {msg}")
    status[:] = st
    message[:] = list(res.message)
    Z = np.asarray(res.Y)
    X[:] = Z[:, 0::2]
    Y[:] = Z[:, 1::2]
    if check:
        max_real[:] = np.asarray(res.max_real)


@limited_blas
def unbalance_response(system: System, unbalances, speeds_hz, *, stations=None,
                       chamber_pressure_pa: float = 0.0, config_ay_m: float | None = None,
                       operating_speed_hz=None, method: str = "perturbation",
                       refine: bool = True, check_stability: bool | None = None,
                       threads: int = 1, thermal=None) -> UnbalanceResult:
    """Response to rotating unbalances ``[(station, mass_kg_m, phase_deg), ...]`` (m·e in
    kg·m; the force at station is m e Ω² (cos(Ωt + φ), sin(Ωt + φ)), turning with the rotor).

    At every speed the equilibrium is continued, K_H and D_H recomputed, and
    (K − Ω² M + iΩ D) X = F solved. ``stations``: output stations (default: the unbalanced
    ones). ``operating_speed_hz``: (min, max) operating speeds for the API 684 separation
    margins of :meth:`UnbalanceResult.peaks`. ``refine``: add speeds around every resonance
    peak until both neighbours of the peak lie above its half-power level (at most
    ``REFINE_LEVELS`` quarterings of the spacing) and the half-power speeds are bracketed to
    ``BAND_TOL_REL`` of the critical speed, so that neither the peak nor its AF is missed
    between the given speeds and a station's peaks do not depend (beyond that) on which other
    stations are asked for (the returned ``speeds_hz`` include the added ones).
    ``check_stability``: also the largest real part of the linear system's eigenvalues at every
    speed (``max_real_1_per_s``; above the threshold of instability there is no steady
    unbalance response, and ``stable`` says so); default: when the system has bearing
    elements (a rotor on symmetric supports cannot lose stability).
    ``threads``: the speeds of a system with bearing elements are solved in one C++ call
    (GIL released); 1 (default) continues the equilibrium over all speeds in order, k > 1
    splits them into k contiguous blocks on k threads, each continued from the same start.
    ``thermal`` (None, True: the model's ``[thermal]``, or a dict of
    :func:`rotordyn.system_thermal_equilibrium` keywords): every speed at its own thermal
    equilibrium (cold start, field frozen for K_H, D_H; the result's ``thermal`` per speed;
    a failed thermal equilibrium is a NaN row with its status; :mod:`.thermal_dynamics`).
    """
    if refine:
        kw = dict(stations=stations, chamber_pressure_pa=chamber_pressure_pa,
                  config_ay_m=config_ay_m, operating_speed_hz=operating_speed_hz,
                  method=method, refine=False, check_stability=check_stability,
                  threads=threads, thermal=thermal)
        u = unbalance_response(system, unbalances, speeds_hz, **kw)
        for _ in range(REFINE_LEVELS):
            sp = u.speeds_hz
            new = []
            gaps = [(sp[i - 1], sp[i]) for i in _unresolved_peaks(u)]
            gaps += [(sp[i], sp[i + 1]) for i in _unresolved_peaks(u)]
            for lo, hi in gaps + _unresolved_bands(u):
                new.extend(lo + (hi - lo) * np.arange(1, REFINE_POINTS + 1)
                           / (REFINE_POINTS + 1))
            new = np.unique(np.asarray(new))
            new = new[~np.isin(new, sp)]
            if new.size == 0:
                break
            u = _merge(u, unbalance_response(system, unbalances, new, **kw))
        return u
    ub = v.unbalances("unbalances", unbalances, system.rotor.n_stations)
    if not ub:
        raise InputError("unbalances: expected at least one (station, mass_kg_m, phase_deg)")
    sp = v.speeds("speeds_hz", speeds_hz, positive_only=True)
    chamber_pressure(system, chamber_pressure_pa)
    if config_ay_m is not None:
        v.finite("config_ay_m", config_ay_m)
    if operating_speed_hz is not None:
        lo, hi = v.bounds("operating_speed_hz", operating_speed_hz)
        if not 0 < lo:
            raise InputError("operating_speed_hz: expected (min, max) with 0 < min <= max")
        operating_speed_hz = (lo, hi)
    v.choice("method", method, LINEARIZATION_METHODS)
    threads = v.integer("threads", threads, lo=1, hi=1024)
    check = bool(system.bearings) if check_stability is None else \
        v.boolean("check_stability", check_stability)
    if thermal is not None and thermal is not False:
        from rotordyn.analysis.thermal_dynamics import thermal_keywords, thermal_unbalance

        return thermal_unbalance(unbalance_response, system, ub, sp, dict(
            stations=stations, chamber_pressure_pa=chamber_pressure_pa,
            config_ay_m=config_ay_m, operating_speed_hz=operating_speed_hz, method=method,
            check_stability=check, threads=threads), thermal_keywords(thermal))
    asm = assembled(system)
    outs = tuple(stations) if stations is not None else tuple(dict.fromkeys(s for s, _, _ in ub))
    Cout = [asm.station_output_matrix(s) for s in outs]
    F1 = asm.unbalance_load(ub)  # per Ω²
    X = np.full((sp.size, len(outs)), np.nan + 0j)
    Y = np.full((sp.size, len(outs)), np.nan + 0j)
    status = np.empty(sp.size, dtype=object)
    max_real = np.full(sp.size, np.nan) if check else None
    message = [""] * sp.size
    if not system.bearings and not check and not system.rotor.has_rotating_damping:
        _linear_rotor(system, asm, sp, chamber_pressure_pa, config_ay_m, F1, Cout, X, Y,
                      status, message)
        return UnbalanceResult(sp, outs, X, Y, status.astype(str), tuple(ub),
                               operating_speed_hz, max_real,
                               point_message=point_messages(status, message))
    _with_bearings(system, asm, sp, chamber_pressure_pa, config_ay_m, method, check, threads,
                   F1, Cout, X, Y, status, max_real, message)
    return UnbalanceResult(sp, outs, X, Y, status.astype(str), tuple(ub), operating_speed_hz,
                           max_real, point_message=point_messages(status, message))
