"""The ``robust`` sweep analysis: a fixed feedback law closed around the plant re-linearised at
every grid point (operating values and model fields), one row per point with the closed loop's
stability verdict and margins (:mod:`rotordyn.control.robust` is the one-call front end).

Per point: the equilibrium solved cold (``warm_start=False``: a row does not depend on the
chunk, thread or order it ran in), the plant of :func:`rotordyn.control.plant.plant` (valve
included), the closed-loop eigenvalues (continuous law: [A + B D_k C, B C_k; B_k C, A_k]; a
discrete law: the exact sampled-data loop, λ = ln z / T; a computation delay as in
:func:`rotordyn.control.closedloop.closed_loop`) and, when the loop is stable, the margins of
the loop broken at the valve command, L = −K G (:func:`rotordyn.control.margins.loop_margins`:
gain margins below/above 1, phase, delay and disk margins, peak |S|, located exactly). A point
whose equilibrium fails is a row with that status and no verdict (``point_stable`` null).

Sensitivity zones after ISO 14839-3:2006 (Mechanical vibration — Vibration of rotating
machinery equipped with active magnetic bearings — Part 3: Evaluation of stability margin),
peak |S| = max_ω |1/(1 + L(iω))|: zone A ≤ 3 (9.5 dB), B ≤ 4 (12 dB), C ≤ 5 (14 dB), D
above. The limits are those of the standard's evaluation table as quoted in the AMB
literature; we did not hold the standard's text. ROSS (petrobras/ross,
``Rotor.run_amb_sensitivity`` and ``SensitivityResults``, read at commit 631a249) computes the
peak sensitivity "according to ISO 14839-3" per bearing axis (``max_abs_sensitivities``) but
implements no zone limits, so there was nothing there to check these numbers against.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.errors import InputError, RotordynError

# zone upper limits of the peak sensitivity (ISO 14839-3, module docstring)
ISO_ZONES = (("A", 3.0), ("B", 4.0), ("C", 5.0))
ZONES = ["A", "B", "C", "D"]
ACTUATOR_KEYS = ("order", "time_constant_s", "natural_frequency_hz", "damping", "p_min_pa",
                 "p_max_pa", "rate_limit_pa_s")
CONTROLLER_KEYS = ("A", "B", "C", "D", "measurements", "sample_time_s", "computation_delay_s",
                   "name")
OPERATING = ("speed_hz", "chamber_pressure_pa", "config_ay_m")


def iso_zone(peak_sensitivity: float) -> str | None:
    """Zone A/B/C/D of a peak sensitivity (a number ≥ 1 for a stable loop; None if NaN)."""
    if not math.isfinite(peak_sensitivity):
        return None if math.isnan(peak_sensitivity) else "D"
    for zone, hi in ISO_ZONES:
        if peak_sensitivity <= hi:
            return zone
    return "D"


# ----------------------------------------------------------------------------- options

def _matrix(f, x):
    if not isinstance(x, list) or any(not isinstance(r, list) for r in x):
        raise InputError(f"{f}: expected a matrix (a list of rows), got {x!r}")
    return [[v.finite(f"{f}[{i}][{j}]", e) for j, e in enumerate(r)] for i, r in enumerate(x)]


def controller_option(f, x) -> dict:
    """``options.controller``: the law as a table {A, B, C, D, measurements, sample_time_s,
    computation_delay_s, name}; checked by building the Controller."""
    if not isinstance(x, dict):
        raise InputError(f"{f}: expected a table {{A, B, C, D, measurements, ...}}, got {x!r}")
    for k in x:
        if k not in CONTROLLER_KEYS:
            raise InputError(f"{f}.{k}: unknown key (allowed: {', '.join(CONTROLLER_KEYS)})")
    for k in ("D", "measurements"):
        if k not in x:
            raise InputError(f"{f}.{k}: required")
    out = {k: _matrix(f"{f}.{k}", x.get(k, [])) for k in "ABCD"}
    meas = x["measurements"]
    if not isinstance(meas, list):
        raise InputError(f"{f}.measurements: expected a list of [kind, index], got {meas!r}")
    out["measurements"] = [list(m) if isinstance(m, (list, tuple)) else m for m in meas]
    for k in ("sample_time_s", "computation_delay_s"):
        if x.get(k) is not None:
            out[k] = v.finite(f"{f}.{k}", x[k])
    out["name"] = v.text(f"{f}.name", x.get("name", "controller"))
    try:
        build_controller(out)
    except InputError as exc:
        raise InputError(f"{f}: {exc}") from None
    return out


def build_controller(d: dict):
    """The :class:`~rotordyn.control.Controller` of an ``options.controller`` table."""
    from rotordyn.operation.controller import Controller

    D = np.asarray(d["D"], float).reshape(1, -1) if d["D"] else np.zeros((1, 0))
    ny = D.shape[1]
    nk = len(d["A"])
    A = np.asarray(d["A"], float).reshape(nk, nk) if nk else np.zeros((0, 0))
    B = np.asarray(d["B"], float).reshape(nk, ny) if nk else np.zeros((0, ny))
    C = np.asarray(d["C"], float).reshape(1, nk) if nk else np.zeros((1, 0))
    return Controller(A, B, C, D, [tuple(m) for m in d["measurements"]],
                      sample_time_s=d.get("sample_time_s"),
                      computation_delay_s=d.get("computation_delay_s") or 0.0,
                      name=d.get("name", "controller"))


def controller_table(k) -> dict:
    """A Controller as an ``options.controller`` table (plain floats: TOML/JSON-ready)."""
    d = {"A": k.A.tolist(), "B": k.B.tolist(), "C": k.C.tolist(), "D": k.D.tolist(),
         "measurements": [list(m) for m in k.measurements], "name": k.name}
    if k.sample_time_s is not None:
        d["sample_time_s"] = float(k.sample_time_s)
    if k.computation_delay_s:
        d["computation_delay_s"] = float(k.computation_delay_s)
    return d


def actuator_option(f, x) -> dict:
    """``options.actuator``: the valve as a table of :class:`~rotordyn.control.Actuator`
    fields (default: ``Actuator()``)."""
    from rotordyn.operation.actuator import Actuator

    if not isinstance(x, dict):
        raise InputError(f"{f}: expected a table of Actuator fields, got {x!r}")
    for k in x:
        if k not in ACTUATOR_KEYS:
            raise InputError(f"{f}.{k}: unknown key (allowed: {', '.join(ACTUATOR_KEYS)})")
    try:
        Actuator(**x)
    except InputError as exc:
        raise InputError(f"{f}: {exc}") from None
    except TypeError as exc:
        raise InputError(f"{f}: {exc}") from None
    return dict(x)


def actuator_table(a) -> dict:
    return {k: (float(getattr(a, k)) if k != "order" else int(a.order)) for k in ACTUATOR_KEYS}


# --------------------------------------------------------------------------------- rows

_MARGIN_COLS = ("gain_margin_lower", "gain_margin_lower_hz", "gain_margin_upper",
                "gain_margin_upper_hz", "phase_margin_deg", "phase_margin_hz",
                "delay_margin_s", "delay_margin_hz", "peak_sensitivity",
                "peak_sensitivity_hz", "disk_margin", "disk_margin_hz")


def outputs(F64, BOOL, cat):
    """Output columns of a robust row (after the ids and axes)."""
    cols = {"journal_x_m": F64, "journal_y_m": F64, "point_stable": BOOL,
            "max_real_1_per_s": F64, "max_real_freq_hz": F64, "min_damping_ratio": F64,
            "min_damping_freq_hz": F64}
    cols.update({c: F64 for c in _MARGIN_COLS})
    cols.update({"disk_gain_db": F64, "disk_phase_deg": F64, "peak_sensitivity_db": F64,
                 "iso_zone": cat(ZONES)})
    return cols


def closed_loop_point(system, k, speed_hz, pc, ay, *, actuator=None, equilibrium=None,
                      with_margins=True, pade_order=6):
    """(plant, closed-loop eigenvalues λ (1/s), loop margins or None, message) of the law
    ``k`` at one operating point (module docstring). Raises what the plant raises (a
    ConvergenceError when the equilibrium fails)."""
    from rotordyn.control import lti
    from rotordyn.control.closedloop import closed_loop
    from rotordyn.control.delay import with_pade_delay
    from rotordyn.control.margins import controller_ss, loop_margins, plant_ss
    from rotordyn.control.plant import plant

    p = plant(system, speed_hz, pc, ay, measurements=k.measurements, actuator=actuator,
              equilibrium={"warm_start": False, **(equilibrium or {})})
    cl = closed_loop(p, k, freqs_hz=[1.0, 2.0], pade_order=pade_order, with_margins=False)
    lam = cl.eigenvalues
    if not np.all(np.isfinite(lam)):
        raise ArithmeticError("non-finite closed-loop eigenvalues")
    if not (with_margins and lam.real.max() < 0):
        msg = "margins not computed" if lam.real.max() < 0 else \
            f"unstable closed loop (largest Re λ = {lam.real.max():.6g} 1/s): no margins"
        return p, lam, None, msg
    tau = k.computation_delay_s
    kk = with_pade_delay(k, tau, pade_order) if tau and not k.discrete else k
    P = plant_ss(p, kk.sample_time_s, tau if kk.discrete else 0.0)
    m = loop_margins(lti.loop_at_input(P, controller_ss(kk)), name="input (valve command)")
    return p, lam, m, ""


def margin_columns(m) -> dict:
    """The margin columns of a row from :class:`~rotordyn.control.margins.LoopMargins`."""
    if m is None:
        return {}
    d = m.disk
    ps = float(m.peak_sensitivity)
    return {"gain_margin_lower": m.gain_margin_lower,
            "gain_margin_lower_hz": m.gain_margin_lower_hz,
            "gain_margin_upper": m.gain_margin_upper,
            "gain_margin_upper_hz": m.gain_margin_upper_hz,
            "phase_margin_deg": m.phase_margin_deg, "phase_margin_hz": m.phase_margin_hz,
            "delay_margin_s": m.delay_margin_s, "delay_margin_hz": m.delay_margin_hz,
            "peak_sensitivity": ps, "peak_sensitivity_hz": m.peak_sensitivity_hz,
            "peak_sensitivity_db": 20 * math.log10(ps) if ps > 0 else math.nan,
            "disk_margin": d.alpha, "disk_margin_hz": d.frequency_hz,
            "disk_gain_db": d.gain_db[1], "disk_phase_deg": d.phase_deg,
            "iso_zone": iso_zone(ps)}


def eigen_columns(lam) -> dict:
    from rotordyn.results.modes import damping_ratio

    z = damping_ratio(lam)
    i, j = int(np.argmax(lam.real)), int(np.argmin(z))
    return {"point_stable": bool(lam.real.max() < 0),
            "max_real_1_per_s": float(lam.real[i]),
            "max_real_freq_hz": float(abs(lam.imag[i]) / (2 * np.pi)),
            "min_damping_ratio": float(z[j]),
            "min_damping_freq_hz": float(abs(lam.imag[j]) / (2 * np.pi))}


def robust_rows(job, variants, chunk_id, lo, hi, rows):
    """One row per point (module docstring)."""
    from rotordyn._common.status import CONVERGED
    from rotordyn.analysis.equilibrium import equilibrium
    from rotordyn.errors import ConvergenceError
    from rotordyn.sweep.points import STATUS, fail_row, points, ref_bearing

    opts = job.options
    k = build_controller(opts["controller"])
    act = None
    if "actuator" in opts:
        from rotordyn.operation.actuator import Actuator

        act = Actuator(**opts["actuator"])
    eq = {key: opts[key] for key in ("method", "tol", "max_iter") if key in opts}
    with_m = bool(opts.get("margins", True))
    pade = int(opts.get("pade_order", 6))
    for row, p, asm, _, _, err in points(job, variants, chunk_id, lo, hi):
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        f = p.get("speed_hz", 50.0)
        pc = p.get("chamber_pressure_pa", 0.0)
        ay = p.get("config_ay_m")
        try:
            pl, lam, m, msg = closed_loop_point(asm.system, k, f, pc, ay, actuator=act,
                                                equilibrium=eq, with_margins=with_m,
                                                pade_order=pade)
        except ConvergenceError as exc:
            e = equilibrium(asm.system, f, pc, ay, warm_start=False, **eq)
            st = e.status if e.status in STATUS and e.status not in CONVERGED else "error"
            rows.append(fail_row(row, st, f"no closed-loop verdict: {exc}"))
            continue
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            rows.append(fail_row(row, "error", f"{type(exc).__name__}: {exc}"))
            continue
        bc = ref_bearing(asm)
        r = pl.info.get("equilibrium_r")
        jx = float(r[bc.jx]) if bc is not None and r is not None else math.nan
        jy = float(r[bc.jy]) if bc is not None and r is not None else math.nan
        rows.append({**row, "journal_x_m": jx, "journal_y_m": jy, **eigen_columns(lam),
                     **margin_columns(m),
                     "status": pl.info.get("equilibrium_status", "ok"), "message": msg})


def check_model(system, options) -> None:
    """The model has an active bearing (the plant's input) and the law's measurements exist
    on it (InputError naming ``options.controller.measurements`` otherwise)."""
    from rotordyn.analysis.measurement import measurement_matrix
    from rotordyn.bearings import ActiveJournalBearing

    if not any(isinstance(b, ActiveJournalBearing) for b in system.bearings):
        raise InputError("analysis: 'robust' closes the loop through the chamber pressure of an "
                         "active journal bearing, and the model has none")
    try:
        measurement_matrix(system, [tuple(m) for m in options["controller"]["measurements"]])
    except InputError as exc:
        raise InputError(f"options.controller.measurements: {exc}") from None
