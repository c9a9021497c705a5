"""Nonlinear transient of the system (paper eq. 12) with SUNDIALS CVODE: free response from a
disturbed equilibrium (orbits, limit cycles, paper Fig. 11) and unbalance response (the
waterfall of Fig. 13 is a set of these at increasing speeds)."""

from __future__ import annotations

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.errors import InputError
from rotordyn import _validate as v
from rotordyn.model.system import System
from rotordyn.results.transient import TransientResult
from rotordyn.units import hz_to_rad_s


def transient(system: System, t_end_s: float, speed_hz: float = 50.0,
              chamber_pressure_pa: float = 0.0, config_ay_m: float | None = None, *,
              unbalances=(), disturbance_m=(0.0, 0.0), r0=None, v0=None,
              n_out: int = 2001, rtol: float = 1e-6, atol_m: float = 1e-9,
              max_steps: int = 500000) -> TransientResult:
    """Integrate eq. 12 from t = 0 to ``t_end_s``.

    The start is the static equilibrium (eq. 14) with the journal of the active (or only)
    bearing displaced by ``disturbance_m`` = (dx, dy), unless ``r0``/``v0`` are given.
    ``unbalances``: [(station, mass_kg_m, phase_deg)] rotating with the rotor. Output at
    ``n_out`` uniformly spaced times. A failure (film contact, CVODE giving up) returns the
    rows reached with a ``status`` and the CVODE flag name in ``message``.
    """
    v.positive("t_end_s", t_end_s)
    v.finite("speed_hz", speed_hz)
    v.non_negative("chamber_pressure_pa", chamber_pressure_pa)
    v.integer("n_out", n_out, lo=2, hi=10_000_000)
    v.in_range("rtol", rtol, 0.0, 0.1, lo_open=True)
    v.positive("atol_m", atol_m)
    v.integer("max_steps", max_steps, lo=1)
    asm = assembled(system)
    n = asm.n
    a = asm.config_vector(config_ay_m)
    if r0 is None:
        e = equilibrium(system, speed_hz, chamber_pressure_pa, config_ay_m)
        if e.status not in ("ok", "contact"):
            raise InputError(f"transient: no equilibrium to start from ({e.status}: {e.message});"
                             " give r0")
        r_eq = e.r.copy()
        r_init = r_eq.copy()
        dx, dy = (v.finite("disturbance_m", d) for d in disturbance_m)
        targets = [bc for bc in asm.bearings if bc.active] or asm.bearings[:1]
        if (dx or dy) and not targets:
            raise InputError("disturbance_m: the system has no journal bearing to disturb")
        for bc in targets[:1]:
            r_init[bc.jx] += dx
            r_init[bc.jy] += dy
    else:
        r_init = np.asarray(r0, dtype=float)
        if r_init.shape != (n,):
            raise InputError(f"r0: expected shape ({n},), got {r_init.shape}")
        r_eq = r_init.copy()
    v_init = np.zeros(n) if v0 is None else np.asarray(v0, dtype=float)
    if v_init.shape != (n,):
        raise InputError(f"v0: expected shape ({n},), got {v_init.shape}")

    uc, us = np.zeros(n), np.zeros(n)
    for i, (st, me, ph) in enumerate(unbalances):
        v.finite(f"unbalances[{i}].mass_kg_m", me)
        L = asm.station_load_matrix(st)
        p = np.radians(v.finite(f"unbalances[{i}].phase_deg", ph))
        # F = m e Ω² (cos(Ωt + p), sin(Ωt + p)) = Ω² (u_c cos Ωt + u_s sin Ωt)
        uc += me * (L[:, 0] * np.cos(p) + L[:, 1] * np.sin(p))
        us += me * (-L[:, 0] * np.sin(p) + L[:, 1] * np.cos(p))

    inp = _core.TransientInput()
    inp.omega = hz_to_rad_s(float(speed_hz))
    inp.chamber_pressure = float(chamber_pressure_pa)
    inp.a = a
    inp.unbalance_cos, inp.unbalance_sin = (uc, us) if len(unbalances) else (np.zeros(0), np.zeros(0))
    inp.r0, inp.v0 = r_init, v_init
    inp.t_out = np.linspace(0.0, float(t_end_s), int(n_out))
    opt = _core.CvodeOptions()
    opt.rtol, opt.atol_position = float(rtol), float(atol_m)
    opt.atol_velocity = float(atol_m) * max(hz_to_rad_s(abs(float(speed_hz))), 1.0)
    opt.max_steps = int(max_steps)
    res = _core.integrate(asm.solver, inp, opt)
    r = np.asarray(res.r)
    bcs = asm.bearings
    return TransientResult(
        speed_hz=float(speed_hz), chamber_pressure_pa=float(chamber_pressure_pa),
        config_ay_m=float(a[bcs[0].jy]) if bcs else 0.0,
        t=np.asarray(res.t), r=r, v=np.asarray(res.v),
        journal_x_m=r[:, [bc.jx for bc in bcs]], journal_y_m=r[:, [bc.jy for bc in bcs]],
        clearance_m=np.array([bc.clearance_m for bc in bcs]),
        h_min_m=asm.bearing_h_min(np.asarray(res.h_min)), bearing_names=tuple(bc.name for bc in bcs),
        equilibrium_r=r_eq,
        stats={"steps": res.steps, "rhs_evals": res.rhs_evals, "jac_evals": res.jac_evals,
               "newton_fails": res.newton_fails, "error_test_fails": res.error_test_fails},
        status=res.status, message=res.message)
