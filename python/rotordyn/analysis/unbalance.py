"""Steady unbalance response of the linearised system (paper §5: forced response under the
centrifugal forces of imbalance), with speed-dependent bearing coefficients."""

from __future__ import annotations

from rotordyn._threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import continued_linear_models
from rotordyn.errors import InputError
from rotordyn import _validate as v
from rotordyn.model.system import System
from rotordyn.results.unbalance import UnbalanceResult
from rotordyn.units import hz_to_rad_s


@limited_blas
def unbalance_response(system: System, unbalances, speeds_hz, *, stations=None,
                       chamber_pressure_pa: float = 0.0, config_ay_m: float | None = None,
                       operating_speed_hz=None, method: str = "perturbation") -> UnbalanceResult:
    """Response to rotating unbalances ``[(station, mass_kg_m, phase_deg), ...]`` (m·e in
    kg·m; the force at station is m e Ω² (cos(Ωt + φ), sin(Ωt + φ)), turning with the rotor).

    At every speed the equilibrium is continued, K_H and D_H recomputed, and
    (K − Ω² M + iΩ D) X = F solved. ``stations``: output stations (default: the unbalanced
    ones). ``operating_speed_hz``: (min, max) operating speeds for the API 684 separation
    margins of :meth:`UnbalanceResult.peaks`.
    """
    ub = []
    try:
        for i, u in enumerate(unbalances):
            st, me, ph = u
            v.integer(f"unbalances[{i}].station", int(st) if isinstance(st, (int, np.integer))
                      else st, lo=0, hi=system.rotor.n_stations - 1)
            ub.append((int(st), v.finite(f"unbalances[{i}].mass_kg_m", me),
                       v.finite(f"unbalances[{i}].phase_deg", ph)))
    except (TypeError, ValueError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError("unbalances: expected a list of (station, mass_kg_m, phase_deg)") from None
    if not ub:
        raise InputError("unbalances: expected at least one (station, mass_kg_m, phase_deg)")
    sp = np.asarray(speeds_hz, dtype=float)
    if sp.ndim != 1 or sp.size == 0 or not np.all(np.isfinite(sp)) or np.any(sp <= 0):
        raise InputError("speeds_hz: expected a non-empty 1-D array of positive speeds")
    if sp.size > 1 and np.any(np.diff(sp) <= 0):
        raise InputError("speeds_hz: expected strictly increasing speeds")
    if operating_speed_hz is not None:
        lo, hi = (float(x) for x in operating_speed_hz)
        if not 0 < lo <= hi:
            raise InputError("operating_speed_hz: expected (min, max) with 0 < min <= max")
        operating_speed_hz = (lo, hi)
    asm = assembled(system)
    outs = tuple(stations) if stations is not None else tuple(dict.fromkeys(s for s, _, _ in ub))
    Cout = [asm.station_output_matrix(s) for s in outs]
    F1 = np.zeros(asm.n, dtype=complex)  # per Ω²
    for st, me, ph in ub:
        fxy = me * np.exp(1j * np.radians(ph)) * np.array([1.0, -1j])
        F1 += asm.station_load_matrix(st) @ fxy
    X = np.full((sp.size, len(outs)), np.nan + 0j)
    Y = np.full((sp.size, len(outs)), np.nan + 0j)
    status = np.empty(sp.size, dtype=object)
    for i, stt, lm in continued_linear_models(system, sp, chamber_pressure_pa, config_ay_m,
                                              method, continue_on=("ok", "contact")):
        status[i] = stt
        if stt not in ("ok", "contact"):
            continue
        w = hz_to_rad_s(float(sp[i]))
        # (K − Ω² M + iΩ D) q = Ω² F1: sparse LU in the core (FE rotors are banded).
        q = np.asarray(_core.harmonic_response(lm.M, lm.D, lm.K, w, (w**2 * F1)[:, None]))[:, 0]
        for k, Co in enumerate(Cout):
            X[i, k], Y[i, k] = Co @ q
    return UnbalanceResult(sp, outs, X, Y, status.astype(str), tuple(ub), operating_speed_hz)
