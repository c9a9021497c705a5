"""Analyses whose unit of work is a line of the grid (the innermost axis, all other axes
fixed): the threshold of instability (every crossing along the line, each refined by Brent's
method) and the unbalance response along speed (peaks, amplification factors, separation
margins). Each line starts cold and continues its equilibria along the line, as a chunk
does, so its rows do not depend on where it ran."""

from __future__ import annotations

import math

import numpy as np

from rotordyn import _core
from rotordyn.errors import RotordynError
from rotordyn.results.unbalance import UnbalanceResult
from rotordyn.sweep import points as pt
from rotordyn.units import hz_to_rad_s


def max_real(job, asm, p, r0, opts, exclude_sleeve):
    """(max Re λ, its frequency Hz, status, equilibrium r or None) at point ``p``."""
    f, pc, a = pt.operating(asm, p)
    e = pt.solve_equilibrium(asm, f, pc, a, r0, opts)
    if e.status not in pt.CONVERGED:
        return math.nan, math.nan, e.status, None
    lam, _, _, kind = pt.eigen(asm, e, f, opts, None)
    if exclude_sleeve:
        lam = lam[kind == "rotor"]
    i = int(np.argmax(lam.real))
    return float(lam[i].real), float(lam[i].imag / (2 * np.pi)), e.status, np.asarray(e.r)


_AXIS = {"speed_hz": _core.ThresholdAxis.speed,
         "chamber_pressure_pa": _core.ThresholdAxis.chamber_pressure,
         "config_ay_m": _core.ThresholdAxis.config}


def threshold_line(job, variants, chunk_id, lo, hi, rows, scan=None):
    """One row per crossing of max Re λ = 0 along the line [lo, hi) (the varied axis is
    innermost); a line without one is a ``no_crossing`` row. ``scan``: a dict that receives
    ``y`` (hi − lo,), max Re λ (1/s) at each grid point of the line (NaN: no equilibrium)."""
    vary = job.options["vary"]
    excl = bool(job.options.get("exclude_sleeve_modes", False))
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        rows.append(pt.fail_row(pt.common_row(job, lo, chunk_id, idx0, p0, None), "error", str(exc)))
        return
    row = pt.common_row(job, lo, chunk_id, idx0, p0, asm)
    row[f"i_{vary}"] = None
    opts = pt.point_options(job, p0)
    xs, om, pcs, avs, valid = [], [], [], [], []
    for pid in range(lo, hi):
        _, p = job.point(pid)
        xs.append(p[vary])
        try:
            f, pc, a = pt.operating(asm, p)
            om.append(hz_to_rad_s(f))
            pcs.append(pc)
            avs.append(a)
            valid.append(1)
        except (RotordynError, ArithmeticError, ValueError):
            om.append(math.nan)
            pcs.append(math.nan)
            avs.append(np.zeros(asm.n))
            valid.append(0)
    inp = _core.ThresholdLineInput()
    inp.x, inp.omega, inp.pressure, inp.a, inp.valid = xs, om, pcs, np.array(avs), valid
    inp.axis = _AXIS[vary]
    if vary == "config_ay_m":
        d = np.flatnonzero(asm.config_vector(1.0) != asm.config_vector(2.0))
        inp.config_index = int(d[0]) if d.size == 1 else -1
    inp.options = pt.equilibrium_options(opts)
    inp.exclude_sleeve = excl
    if "xtol" in job.options:
        inp.xtol, inp.xtol_given = float(job.options["xtol"]), True
    inp.xy_pairs, inp.rot_pairs = asm.rotor.xy_pairs(), asm.rotor.rot_pairs()
    inp.sleeve = [i for bc in asm.bearings for i in bc.sleeve]
    # one C++ call: the scan (equilibria continued along the line, eigen-analysis) and every
    # sign change refined by Brent's method (SciPy's brentq, step for step)
    res = _core.threshold_line(asm.solver, inp)
    ys = np.asarray(res.y)
    if scan is not None:
        scan["y"] = ys.copy()
    evals = len(xs)
    found = 0
    for i, x, fr, status, msg, evals in zip(res.bracket, res.root, res.root_freq, res.status,
                                            res.message, res.evaluations):
        y0 = ys[i]
        found += 1
        speed = x if vary == "speed_hz" else row["speed_hz"]
        rows.append({**row, vary: x, "crossing": found, "value": x,
                     "whirl_frequency_hz": fr, "whirl_ratio": fr / speed if speed else math.nan,
                     "stable_side": "below" if y0 < 0 else "above", "evaluations": evals,
                     "status": status, "message": msg})
    if not found:
        good = [y for y in ys.tolist() if math.isfinite(y)]
        what = ("no point of the line has an equilibrium" if not good else
                f"{'unstable' if min(good) > 0 else 'stable'} at all {len(good)} points")
        rows.append({**row, vary: math.nan, "crossing": 0, "value": math.nan,
                     "evaluations": evals, "status": "no_crossing",
                     "message": f"max Re λ does not change sign along {vary}: {what}"})


def unbalance_line(job, variants, chunk_id, lo, hi, rows):
    """Unbalance response along the speed line [lo, hi): one row per (speed, station), with
    ``peak`` rows carrying the amplification factor and separation margin (API 684)."""
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        rows.append(pt.fail_row(pt.common_row(job, lo, chunk_id, idx0, p0, None), "error", str(exc)))
        return
    opts = pt.point_options(job, p0)
    ub = opts["unbalances"]
    stations = tuple(opts.get("stations") or dict.fromkeys(int(u[0]) for u in ub))
    Cout = [asm.station_output_matrix(s) for s in stations]
    F1 = asm.unbalance_load(ub)
    n = hi - lo
    X = np.full((n, len(stations)), np.nan + 0j)
    Y = np.full((n, len(stations)), np.nan + 0j)
    base, speeds, ops = [], [], []
    status, msg = [None] * n, [None] * n
    for k, pid in enumerate(range(lo, hi)):
        idx, p = job.point(pid)
        base.append(pt.common_row(job, pid, chunk_id, idx, p, asm))
        speeds.append(p.get("speed_hz", 50.0))
        try:
            ops.append(pt.operating(asm, p))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            ops.append(None)
            status[k], msg[k] = "error", f"{type(exc).__name__}: {exc}"
    # runs of valid points: one C++ call each (equilibrium continued along the run, cold
    # after a failure, K_H/D_H, the harmonic solve at each speed)
    O = np.concatenate(Cout, axis=0)  # (2 n_out, n): x, y of each output station
    k = 0
    while k < n:
        if ops[k] is None:
            k += 1
            continue
        j = k
        while j + 1 < n and ops[j + 1] is not None:
            j += 1
        run = ops[k:j + 1]
        res = _core.unbalance_sweep(
            asm.model, hz_to_rad_s(np.array([o[0] for o in run])),
            np.array([o[1] for o in run]), np.array([o[2] for o in run]), np.zeros(0),
            pt.equilibrium_options(opts), np.zeros((0, 0)), F1, O, False, 0.0, False, False,
            [], [], 1, True)
        Z = np.asarray(res.Y)
        X[k:j + 1], Y[k:j + 1] = Z[:, 0::2], Z[:, 1::2]
        for i, (st, m) in enumerate(zip(res.status, res.message)):
            status[k + i], msg[k + i] = (st if st in pt.STATUS else "error"), m
        k = j + 1
    res = UnbalanceResult(np.asarray(speeds), stations, X, Y, np.asarray(status),
                          tuple(map(tuple, ub)),
                          tuple(opts["operating_speed_hz"]) if "operating_speed_hz" in opts
                          else None)
    major, minor = res.major_m, res.minor_m
    peaks = {}
    for j, st in enumerate(stations):
        pk = res.peaks(st)
        for _, r in pk.iterrows():
            i = int(np.argmin(np.abs(np.asarray(speeds) - r["critical_speed_hz"])))
            peaks[(i, j)] = r
    for k in range(n):
        for j, st in enumerate(stations):
            pk = peaks.get((k, j))
            rows.append({**base[k], "station": int(st),
                         "amplitude_x_m": float(abs(X[k, j])), "amplitude_y_m": float(abs(Y[k, j])),
                         "phase_x_deg": float(np.degrees(np.angle(X[k, j]))),
                         "phase_y_deg": float(np.degrees(np.angle(Y[k, j]))),
                         "major_m": float(major[k, j]), "minor_m": float(minor[k, j]),
                         "peak": pk is not None,
                         "critical_speed_hz": float(pk["critical_speed_hz"])
                         if pk is not None else math.nan,
                         "amplification_factor": float(pk["amplification_factor"])
                         if pk is not None else math.nan,
                         "separation_margin_pct": float(pk.get("separation_margin_pct",
                                                               math.nan))
                         if pk is not None else math.nan,
                         "status": status[k], "message": msg[k]})
