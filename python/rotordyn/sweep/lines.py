"""Analyses whose unit of work is a line of the grid (the innermost axis, all other axes
fixed): the threshold of instability (every crossing along the line, each refined by Brent's
method) and the unbalance response along speed (peaks, amplification factors, separation
margins). Each line starts cold and continues its equilibria along the line, as a chunk
does, so its rows do not depend on where it ran."""

from __future__ import annotations

import math

import numpy as np

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


def threshold_line(job, variants, chunk_id, lo, hi, rows):
    """One row per crossing of max Re λ = 0 along the line [lo, hi) (the varied axis is
    innermost); a line without one is a ``no_crossing`` row."""
    from scipy.optimize import brentq

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
    xs, ys, fs, rs = [], [], [], []
    r0 = None
    evals = 0
    for pid in range(lo, hi):
        _, p = job.point(pid)
        try:
            y, fr, st, r = max_real(job, asm, p, r0, opts, excl)
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError):
            y, fr, r = math.nan, math.nan, None
        evals += 1
        r0 = r if r is not None else None
        xs.append(p[vary])
        ys.append(y)
        fs.append(fr)
        rs.append(r)
    found = 0
    for i in range(len(xs) - 1):
        y0, y1 = ys[i], ys[i + 1]
        if not (math.isfinite(y0) and math.isfinite(y1)) or y0 * y1 >= 0:
            continue
        start = rs[i]
        _, pbase = job.point(lo + i)

        def g(x, pbase=pbase, start=start):
            nonlocal evals
            evals += 1
            q = dict(pbase)
            q[vary] = float(x)
            y, _, _, _ = max_real(job, asm, q, start, opts, excl)
            if not math.isfinite(y):
                raise ArithmeticError("no equilibrium inside the bracket")
            return y

        span = abs(xs[i + 1] - xs[i])
        try:
            x = brentq(g, xs[i], xs[i + 1], xtol=job.options.get("xtol", span * 1e-8),
                       rtol=4 * np.finfo(float).eps, maxiter=100)
            q = dict(pbase)
            q[vary] = x
            _, fr, _, _ = max_real(job, asm, q, start, opts, excl)
            status, msg = "ok", ""
        except (RotordynError, ArithmeticError, ValueError, RuntimeError) as exc:
            x, fr, status, msg = math.nan, math.nan, "error", f"{type(exc).__name__}: {exc}"
        found += 1
        speed = q["speed_hz"] if "speed_hz" in q else row["speed_hz"]
        rows.append({**row, vary: x, "crossing": found, "value": x,
                     "whirl_frequency_hz": fr, "whirl_ratio": fr / speed if speed else math.nan,
                     "stable_side": "below" if y0 < 0 else "above", "evaluations": evals,
                     "status": status, "message": msg})
    if not found:
        good = [y for y in ys if math.isfinite(y)]
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
    base, status, msg, speeds = [], [], [], []
    r0 = None
    m = asm.model
    M, C0, G, K0 = (np.asarray(x) for x in (m.M, m.C, m.G, m.K))
    for k, pid in enumerate(range(lo, hi)):
        idx, p = job.point(pid)
        base.append(pt.common_row(job, pid, chunk_id, idx, p, asm))
        speeds.append(p.get("speed_hz", 50.0))
        try:
            f, pc, a = pt.operating(asm, p)
            e = pt.solve_equilibrium(asm, f, pc, a, r0, opts)
            status.append(e.status if e.status in pt.STATUS else "error")
            msg.append(e.message)
            if e.status not in pt.CONVERGED:
                r0 = None
                continue
            r0 = np.asarray(e.r)
            om = hz_to_rad_s(f)
            lin = asm.solver.linearize(r0, np.zeros(asm.n), om)
            Mw = np.asarray(m.mass_at(om)) if m.has_table_mass() else M  # table masses
            Z = (K0 + np.asarray(lin.KH)) - om**2 * Mw + 1j * om * (C0 + om * G
                                                                    + np.asarray(lin.DH))
            q = np.linalg.solve(Z, om**2 * F1)
            for j, Co in enumerate(Cout):
                X[k, j], Y[k, j] = Co @ q
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            status.append("error")
            msg.append(f"{type(exc).__name__}: {exc}")
            r0 = None
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
