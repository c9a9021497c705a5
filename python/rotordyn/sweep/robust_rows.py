"""The ``robust`` sweep analysis (docs/control.md §2.7): a fixed feedback law closed around the
plant re-linearised at every grid point (operating values and model fields), one row per point
with the closed loop's verdict and margins (:func:`rotordyn.control.robust.closed_loop_point`);
its options (the law and the valve as tables) and output columns. The one-call front end is
:func:`rotordyn.sweep.robust.robust`.

A point whose equilibrium fails is a row with that status and no verdict (``point_stable``
null); an unstable point has its verdict and no margins.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control.robust import (ACTUATOR_KEYS, MARGIN_COLS, ZONES, build_controller,
                                     closed_loop_point, eigen_columns, margin_columns)
from rotordyn.errors import InputError, RotordynError

CONTROLLER_KEYS = ("A", "B", "C", "D", "measurements", "sample_time_s", "computation_delay_s",
                   "name")


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


# --------------------------------------------------------------------------------- rows

def outputs(F64, BOOL, cat):
    """Output columns of a robust row (after the ids and axes)."""
    cols = {"journal_x_m": F64, "journal_y_m": F64, "point_stable": BOOL,
            "max_real_1_per_s": F64, "max_real_freq_hz": F64, "min_damping_ratio": F64,
            "min_damping_freq_hz": F64}
    cols.update({c: F64 for c in MARGIN_COLS})
    cols.update({"disk_gain_db": F64, "disk_phase_deg": F64, "peak_sensitivity_db": F64,
                 "iso_zone": cat(ZONES)})
    return cols


def robust_blocks(job, variants, chunk_id, pids, asms):
    """One row per point (module docstring), as columnar blocks: the closed-loop verdict and
    margins of a point are a Python computation around per-point core calls (equilibrium,
    linearisation, the closed loop's eigenvalues and frequency responses) with no batch in
    the core, so the chunk loops over its points; each point's columns are one block, joined
    into one block per run of points (:func:`rotordyn.sweep.columns.merge`)."""
    from rotordyn._common.status import CONVERGED
    from rotordyn.analysis.equilibrium import equilibrium
    from rotordyn.errors import ConvergenceError
    from rotordyn.sweep.columns import merge
    from rotordyn.sweep.points import STATUS, point_list, ref_bearing

    opts = job.options
    k = build_controller(opts["controller"])
    act = None
    if "actuator" in opts:
        from rotordyn.operation.actuator import Actuator

        act = Actuator(**opts["actuator"])
    eq = {key: opts[key] for key in ("method", "tol", "max_iter") if key in opts}
    with_m = bool(opts.get("margins", True))
    pade = int(opts.get("pade_order", 6))
    cont = bool(opts.get("continuation", True))
    r_prev = None
    blocks = []
    for n, (p, asm, _, line, err) in enumerate(point_list(job, variants, pids, asms)):
        at = np.array([n])
        if err:
            blocks.append((at, {"status": "error", "message": err}))
            r_prev = None
            continue
        f = p.get("speed_hz", 50.0)
        pc = p.get("chamber_pressure_pa", 0.0)
        ay = p.get("config_ay_m")
        # along a line (chunks hold whole lines: deterministic) the equilibrium starts from the
        # previous point's; cold otherwise, and again cold when the continued solve fails
        starts = ([{"r0": r_prev}] if cont and line and r_prev is not None else []) + [{}]
        r_prev = None
        for start in starts:
            try:
                pl, lam, m, msg = closed_loop_point(asm.system, k, f, pc, ay, actuator=act,
                                                    equilibrium={**eq, **start},
                                                    with_margins=with_m, pade_order=pade)
                failure = None
                break
            except ConvergenceError as exc:
                failure = exc
            except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
                failure = exc
                break
        if isinstance(failure, ConvergenceError):
            e = equilibrium(asm.system, f, pc, ay, warm_start=False, **eq)
            st = e.status if e.status in STATUS and e.status not in CONVERGED else "error"
            blocks.append((at, {"status": st, "message": f"no closed-loop verdict: {failure}"}))
            continue
        if failure is not None:
            blocks.append((at, {"status": "error",
                                "message": f"{type(failure).__name__}: {failure}"}))
            continue
        if pl.info.get("equilibrium_status") == "ok":
            r_prev = pl.info.get("equilibrium_r")
        bc = ref_bearing(asm)
        r = pl.info.get("equilibrium_r")
        jx = float(r[bc.jx]) if bc is not None and r is not None else math.nan
        jy = float(r[bc.jy]) if bc is not None and r is not None else math.nan
        blocks.append((at, {"journal_x_m": jx, "journal_y_m": jy, **eigen_columns(lam),
                            **margin_columns(m),
                            "status": pl.info.get("equilibrium_status", "ok"),
                            "message": msg}))
    return merge(blocks)


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
