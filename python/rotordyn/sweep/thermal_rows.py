"""Stability, Campbell and unbalance sweep chunks at each point's own thermal equilibrium
(``options.thermal``, issue 20; docs/sweeps.md) as columnar blocks (:mod:`.columns`): per
point the model's ``[thermal]`` oil system is brought to its thermal equilibrium (cold start),
then the analysis runs on the system with that temperature (viscosity) field frozen — the
numbers of the direct calls ``rotordyn.stability(..., thermal=...)``,
``campbell(..., thermal=...)``, ``unbalance_response(..., thermal=...)``
(:mod:`rotordyn.analysis.thermal_dynamics`). The frozen system differs from point to point,
so there is no batch: one block per point (its modes or its stations), joined per run of
points (:func:`rotordyn.sweep.columns.merge`), no dict per row.

Each row carries the point's thermal outputs
(:data:`rotordyn.results.thermal.THERMAL_POINT_COLUMNS`): per film (list columns, in the order
of ``film``) the effective and maximum temperature and the power loss, and their summaries. A
point whose thermal equilibrium fails is one row with that status and its thermal columns
(NaN), never linearised. The rows are those of the former dict-per-row code
(tests/sweep_thermal_rows_reference.py, tests/test_thermal_sweep.py).
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn.analysis.thermal_dynamics import thermal_point
from rotordyn.errors import RotordynError
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.results.modes import log_dec, settled_real
from rotordyn.results.thermal import THERMAL_POINT_COLUMNS, thermal_point_values
from rotordyn.sweep.columns import merge
from rotordyn.sweep.points import STATUS, operating, point_list, ref_bearing, stable_modes
from rotordyn.sweep.tilt_rows import equilibrium_tilt, repeat_lists
from rotordyn.sweep.tracking import track_line

_LISTS = THERMAL_POINT_COLUMNS[:4]
_CATCH = (RotordynError, ArithmeticError, ValueError)


def thermal_columns(t, m: int = 1) -> dict:
    """The thermal outputs of one point (a SystemThermalResult; NaN where it failed;
    :func:`rotordyn.results.thermal.thermal_point_values`) for a block of ``m`` rows: the
    per-film lists as (m,) object arrays of that list, the summaries as scalars."""
    out = thermal_point_values(t)
    for name in _LISTS:
        col = np.empty(m, dtype=object)
        for i in range(m):  # one list per row (not a 2-D array)
            col[i] = out[name]
        out[name] = col
    return out


def _kw(opts):
    return dict(opts.get("thermal") or {})


def _status(s):
    return s if s in STATUS else "error"


def _fail(k, status, message, th=None):
    return (np.array([k]), {"status": status, "message": message, **(th or {})})


def _point(p, asm, opts):
    """(thermal result or None, stability result or None, failed block columns or None)."""
    from rotordyn.analysis.linear import stability

    try:
        f, pc, _ = operating(asm, p)
        t = thermal_point(asm.system, f, pc, p.get("config_ay_m"), _kw(opts))
    except _CATCH as exc:
        return None, None, {"status": "error", "message": f"{type(exc).__name__}: {exc}"}
    if t.status not in CONVERGED:  # never linearised
        return t, None, {"status": _status(t.status),
                         "message": f"thermal equilibrium: {t.message}"}
    try:
        st = stability(t.system, f, pc, p.get("config_ay_m"), n_modes=opts.get("n_modes"),
                       method=opts.get("linearization", "perturbation"), warm_start=False,
                       **{k: opts[k] for k in ("tol", "max_iter") if k in opts})
    except _CATCH as exc:
        return t, None, {"status": "error", "message": f"{type(exc).__name__}: {exc}"}
    if st.status not in CONVERGED or not len(st.eigenvalues):
        return t, None, {"status": _status(st.status),
                         "message": st.message or "no equilibrium"}
    return t, st, None


def stab_blocks(job, variants, chunk_id, pids, asms):
    """One row per mode of each point (the stability/Campbell columns, mode ids tracked along
    each line as the isothermal chunk does; a failed point: one row), each point at its own
    thermal equilibrium."""
    items = point_list(job, variants, pids, asms)
    got = [(None, None, {"status": "error", "message": it[4]}) if it[4]
           else _point(it[0], it[1], it[2]) for it in items]
    ids: list = [None] * len(items)
    if job.options.get("track", True):  # a failed point does not end a line
        buf, weight = [], None
        for k, (t, st, _) in enumerate(got):
            if not items[k][3] and buf:
                _track(buf, weight, ids)
                buf = []
            if st is not None and st.modes is not None:
                buf.append((k, st.eigenvalues, st.modes))
                weight = np.asarray(st.linear.M)
        if buf:
            _track(buf, weight, ids)
    blocks = []
    for k, (t, st, fail) in enumerate(got):
        th = thermal_columns(t) if t is not None else None
        if st is None:
            blocks.append(_fail(k, fail["status"], fail["message"], th))
        else:
            blocks.append(_modes_block(k, st, t, ids[k], items[k][1],
                                       job.options.get("bearing")))
    return merge(blocks)


def _track(buf, weight, ids):
    rows = {k: {} for k, _, _ in buf}
    track_line(rows, buf, weight)
    for k, r in rows.items():
        ids[k] = r["mode_id"]


def _modes_block(k, st, t, ids, asm, bearing=None):
    lam = st.eigenvalues
    n = len(lam)
    with np.errstate(divide="ignore", invalid="ignore"):
        ms = stable_modes(lam[None, :])[0]
        re = settled_real(lam[None, :])[0]
        ab = np.abs(lam)
        dr = np.where(ab > 0, -re / ab, np.nan)
        ld = log_dec(lam)  # the API's: −inf for a growing real root (a divergence)
    e = st.linear.equilibrium
    bc = ref_bearing(asm, bearing)
    hm = np.atleast_1d(e.h_min_m)
    kind = np.array([str(x) if x in ("rotor", "sleeve", "pad") else None for x in st.kind],
                    dtype=object)  # "pad": a tilting pad's own mode, as rotordyn.stability
    tilt = (repeat_lists([equilibrium_tilt(asm, e)], [n])
            if any(b.rot for b in asm.bearings) else {})
    return (np.full(n, k, dtype=np.int64), {**tilt,
        "mode_id": (np.arange(n) if ids is None else np.asarray(ids)).astype(np.int64),
        "mode": np.arange(1, n + 1, dtype=np.int64), "freq_hz": lam.imag / (2 * np.pi),
        "eig_real_1_per_s": lam.real, "damping_ratio": dr, "log_dec": ld,
        "whirl": np.array([str(w) for w in st.whirl], dtype=object), "kind": kind,
        # the point's verdict and max Re λ over every root (not only an n_modes cut)
        "mode_stable": np.asarray(ms, dtype=bool), "point_stable": bool(st.stable),
        "max_real_1_per_s": float(st.max_real_1_per_s),
        "journal_x_m": float(e.r[bc.jx]) if bc else math.nan,
        "journal_y_m": float(e.r[bc.jy]) if bc else math.nan,
        "h_min_m": float(np.nanmin(hm)) if len(hm) else math.nan,
        "iterations": int(e.iterations), "status": _status(st.status),
        "message": st.message, **thermal_columns(t, n)})


def unbalance_blocks(job, variants, chunk_id, pids, asms):
    """One row per (speed, station) along each speed line (the innermost axis), each speed at
    its own thermal equilibrium (:func:`rotordyn.unbalance_response` with ``thermal``, no
    refinement, with the stability check: ``point_stable``)."""
    from rotordyn.analysis.thermal_dynamics import thermal_unbalance
    from rotordyn.analysis.unbalance import unbalance_response
    from rotordyn.sweep.lines import unbalance_columns

    items = point_list(job, variants, pids, asms)
    n_line = job.shape[-1]
    blocks = []
    for at in range(0, len(items), n_line):
        line = items[at:at + n_line]
        k = at + np.arange(len(line))
        p0, asm, opts, _, err = line[0]
        if err:
            blocks.append((k, {"status": "error", "message": err}))
            continue
        ub = [tuple(u) for u in opts["unbalances"]]
        stations = tuple(opts.get("stations") or dict.fromkeys(int(u[0]) for u in ub))
        speeds = np.array([it[0].get("speed_hz", 50.0) for it in line])
        try:
            _, pc, _ = operating(asm, p0)
            res = thermal_unbalance(unbalance_response, asm.system, ub, speeds, dict(
                stations=stations, chamber_pressure_pa=pc, config_ay_m=p0.get("config_ay_m"),
                operating_speed_hz=tuple(opts["operating_speed_hz"])
                if "operating_speed_hz" in opts else None,
                method=opts.get("linearization", "perturbation"), check_stability=True,
                threads=1), _kw(opts))
        except _CATCH as exc:
            blocks.append((k, {"status": "error", "message": f"{type(exc).__name__}: {exc}"}))
            continue
        status = [_status(x) for x in res.point_status]
        msg = list(res.point_message)  # why a speed failed: the thermal status or exception
        cols = unbalance_columns(res, speeds, stations, status, msg)
        ns = len(stations)
        for i, t in enumerate(res.thermal):  # one block per speed, merged per run
            c = {name: v[i * ns:(i + 1) * ns] for name, v in cols.items()}
            if t is not None:
                c.update(thermal_columns(t, ns))
            blocks.append((np.full(ns, at + i, dtype=np.int64), c))
    return merge(blocks)
