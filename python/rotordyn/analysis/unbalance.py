"""Steady unbalance response of the linearised system (paper §5: forced response under the
centrifugal forces of imbalance), with speed-dependent bearing coefficients."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import continued_linear_models
from rotordyn.errors import InputError
from rotordyn.results.equilibrium import CONVERGED
from rotordyn._common import validate as v
from rotordyn.model.system import System
from rotordyn.results.unbalance import UnbalanceResult
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
                        or s[i + 1] - s[i - 1] > 2 * BAND_TOL_REL * s[i]):
                    out.add(i)
    return sorted(out)


def _unresolved_bands(u: UnbalanceResult) -> list[tuple[float, float]]:
    """Grid intervals holding a half-power speed N₁ or N₂ of a peak of the orbit's major axis
    (what :meth:`UnbalanceResult.peaks` reads), at any station, wider than BAND_TOL_REL × N_c:
    the AF interpolated across them is not converged, so a station's AF depended on which
    other stations refined the grid (issue 18)."""
    s = u.speeds_hz
    out = []
    for k in range(u.major_m.shape[1]):
        v = u.major_m[:, k]
        for i in range(1, len(v) - 1):
            if not (v[i] > v[i - 1] and v[i] >= v[i + 1]):
                continue
            half = v[i] / np.sqrt(2)
            tol = BAND_TOL_REL * s[i]
            j = i
            while j > 0 and v[j] > half:
                j -= 1
            if v[j] <= half and s[j + 1] - s[j] > tol:
                out.append((s[j], s[j + 1]))
            j = i
            while j < len(v) - 1 and v[j] > half:
                j += 1
            if v[j] <= half and s[j] - s[j - 1] > tol:
                out.append((s[j - 1], s[j]))
    return out


def _merge(a: UnbalanceResult, b: UnbalanceResult) -> UnbalanceResult:
    sp = np.concatenate([a.speeds_hz, b.speeds_hz])
    o = np.argsort(sp, kind="stable")
    return UnbalanceResult(sp[o], a.stations, np.concatenate([a.x, b.x])[o],
                           np.concatenate([a.y, b.y])[o],
                           np.concatenate([a.point_status, b.point_status])[o], a.unbalances,
                           a.operating_speed_hz,
                           None if a.max_real_1_per_s is None else
                           np.concatenate([a.max_real_1_per_s, b.max_real_1_per_s])[o])


def _linear_rotor(system, asm, sp, chamber_pressure_pa, config_ay_m, F1, Cout, X, Y, status):
    """A system without bearing elements: its linear model is M, C + ΩG, K at every speed
    and its equilibrium does not depend on the speed, so the equilibrium is solved once (its
    status is every speed's) and all speeds are one C++ call (one symbolic analysis of the
    pencil, a numeric LU per speed): the numbers each speed factorises are those of the
    per-speed loop (K_H = D_H = 0). Fills X, Y, status in place."""
    from rotordyn.analysis.equilibrium import equilibrium
    from rotordyn.errors import RotordynError

    try:
        e = equilibrium(system, float(sp[0]), chamber_pressure_pa, config_ay_m)
    except RotordynError:
        status[:] = "error"
        return
    status[:] = e.status
    if e.status not in CONVERGED:
        return
    m = asm.model
    O = np.concatenate(Cout, axis=0)  # (2 n_out, n): x, y of each output station
    Z = np.asarray(_core.harmonic_sweep(m.M, m.C, m.G, m.K, hz_to_rad_s(sp), F1, O))
    X[:] = Z[:, 0::2]
    Y[:] = Z[:, 1::2]


@limited_blas
def unbalance_response(system: System, unbalances, speeds_hz, *, stations=None,
                       chamber_pressure_pa: float = 0.0, config_ay_m: float | None = None,
                       operating_speed_hz=None, method: str = "perturbation",
                       refine: bool = True, check_stability: bool | None = None
                       ) -> UnbalanceResult:
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
    """
    if refine:
        kw = dict(stations=stations, chamber_pressure_pa=chamber_pressure_pa,
                  config_ay_m=config_ay_m, operating_speed_hz=operating_speed_hz,
                  method=method, refine=False, check_stability=check_stability)
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
    v.non_negative("chamber_pressure_pa", chamber_pressure_pa)
    if config_ay_m is not None:
        v.finite("config_ay_m", config_ay_m)
    if operating_speed_hz is not None:
        lo, hi = v.bounds("operating_speed_hz", operating_speed_hz)
        if not 0 < lo:
            raise InputError("operating_speed_hz: expected (min, max) with 0 < min <= max")
        operating_speed_hz = (lo, hi)
    check = bool(system.bearings) if check_stability is None else \
        v.boolean("check_stability", check_stability)
    asm = assembled(system)
    outs = tuple(stations) if stations is not None else tuple(dict.fromkeys(s for s, _, _ in ub))
    Cout = [asm.station_output_matrix(s) for s in outs]
    F1 = asm.unbalance_load(ub)  # per Ω²
    X = np.full((sp.size, len(outs)), np.nan + 0j)
    Y = np.full((sp.size, len(outs)), np.nan + 0j)
    status = np.empty(sp.size, dtype=object)
    max_real = np.full(sp.size, np.nan) if check else None
    if not system.bearings and not check:
        _linear_rotor(system, asm, sp, chamber_pressure_pa, config_ay_m, F1, Cout, X, Y,
                      status)
        return UnbalanceResult(sp, outs, X, Y, status.astype(str), tuple(ub),
                               operating_speed_hz, max_real)
    for i, stt, lm in continued_linear_models(system, sp, chamber_pressure_pa, config_ay_m,
                                              method, continue_on=CONVERGED):
        status[i] = stt
        if stt not in CONVERGED:
            continue
        w = hz_to_rad_s(float(sp[i]))
        # (K − Ω² M + iΩ D) q = Ω² F1: sparse LU in the core (FE rotors are banded).
        q = np.asarray(_core.harmonic_response(lm.M, lm.D, lm.K, w, (w**2 * F1)[:, None]))[:, 0]
        for k, Co in enumerate(Cout):
            X[i, k], Y[i, k] = Co @ q
        if check:
            lam = np.asarray(_core.modal(lm.M, lm.D, lm.K, asm.rotor.xy_pairs(), 0, False,
                                         asm.rotor.rot_pairs()).eigenvalues)
            max_real[i] = float(np.max(lam.real)) if lam.size else np.nan
    return UnbalanceResult(sp, outs, X, Y, status.astype(str), tuple(ub), operating_speed_hz,
                           max_real)
