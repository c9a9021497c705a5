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


def max_real(job, asm, p, r0, opts, exclude_sleeve, verdict=False):
    """(max Re λ, its frequency Hz, status, equilibrium r or None) at point ``p``; with
    ``verdict`` the first entry is the threshold's function instead
    (:func:`rotordyn.results.modes.verdict_real`: max Re λ with the verdict's sign)."""
    f, pc, a = pt.operating(asm, p)
    e = pt.solve_equilibrium(asm, f, pc, a, r0, opts)
    if e.status not in pt.CONVERGED:
        return math.nan, math.nan, e.status, None
    lam, _, _, kind = pt.eigen(asm, e, f, opts, None)
    if exclude_sleeve:
        lam = lam[kind != "sleeve"]
    i = int(np.argmax(lam.real))
    if verdict:
        from rotordyn.results.modes import verdict_real
        return verdict_real(lam), float(lam[i].imag / (2 * np.pi)), e.status, np.asarray(e.r)
    return float(lam[i].real), float(lam[i].imag / (2 * np.pi)), e.status, np.asarray(e.r)


def _stable_side(xs, stable, i) -> str:
    """Which side of the crossing in the bracket [x_i, x_{i+1}] is stable, in the varied
    value (not in scan order: a line scanned from its largest value down has its stable
    point second when the stable side is below). ``stable``: the points' verdicts (1 stable,
    0 unstable: the round-off band's rule, not max Re λ's raw sign, which called a
    conservative point's +1e-12 unstable)."""
    x_stable, x_other = (xs[i], xs[i + 1]) if stable[i] == 1 else (xs[i + 1], xs[i])
    return "below" if x_stable < x_other else "above"


_AXIS = {"speed_hz": _core.ThresholdAxis.speed,
         "chamber_pressure_pa": _core.ThresholdAxis.chamber_pressure,
         "config_ay_m": _core.ThresholdAxis.config}


def threshold_line(job, variants, lo, hi, at, asms, scan=None):
    """Blocks of one row per crossing of max Re λ = 0 along the line [lo, hi) (the varied axis
    is innermost; the line's rows carry the identity of its first point, chunk-local index
    ``at``); a line without one is a ``no_crossing`` row. ``scan``: a dict that receives
    ``y`` (hi − lo,), max Re λ (1/s) at each grid point of the line (NaN: no equilibrium)."""
    vary = job.options["vary"]
    excl = bool(job.options.get("exclude_sleeve_modes", False))
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        return [(np.array([at]), {"status": "error", "message": str(exc)})]
    asms[at:at + hi - lo] = [asm] * (hi - lo)
    speed0 = p0.get("speed_hz", 50.0)
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
    verdicts = np.asarray(res.stable, dtype=np.int64)
    if scan is not None:
        scan["y"] = ys.copy()
        scan["stable"] = verdicts.copy()
    roots, freqs = list(res.root), list(res.root_freq)
    k = len(roots)
    if k:
        speeds = roots if vary == "speed_hz" else [speed0] * k
        return [(np.full(k, at), {
            f"i_{vary}": None, vary: roots, "crossing": np.arange(1, k + 1),
            "value": roots, "whirl_frequency_hz": freqs,
            "whirl_ratio": [fr / sp if sp else math.nan for fr, sp in zip(freqs, speeds)],
            "stable_side": [_stable_side(xs, verdicts, i) for i in res.bracket],
            "evaluations": list(res.evaluations), "status": list(res.status),
            "message": list(res.message)})]
    good = verdicts[verdicts >= 0]
    what = ("no point of the line has an equilibrium" if not good.size else
            f"{'stable' if good.all() else 'unstable'} at all {good.size} points"
            if good.min() == good.max() else
            "the verdict changes only across failed points")
    return [(np.array([at]), {f"i_{vary}": None, vary: math.nan, "crossing": 0,
                              "value": math.nan, "evaluations": len(xs),
                              "status": "no_crossing",
                              "message": f"the stability verdict does not change along "
                                         f"{vary}: {what}"})]


def unbalance_line(job, variants, lo, hi, at, asms):
    """Blocks of the unbalance response along the speed line [lo, hi) (its first point at
    chunk-local index ``at``): one row per (speed, station), with ``peak`` rows carrying the
    amplification factor and separation margin (API 684)."""
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        return [(np.array([at]), {"status": "error", "message": str(exc)})]
    n = hi - lo
    asms[at:at + n] = [asm] * n
    opts = pt.point_options(job, p0)
    ub = opts["unbalances"]
    stations = tuple(opts.get("stations") or dict.fromkeys(int(u[0]) for u in ub))
    Cout = [asm.station_output_matrix(s) for s in stations]
    F1 = asm.unbalance_load(ub)
    X = np.full((n, len(stations)), np.nan + 0j)
    Y = np.full((n, len(stations)), np.nan + 0j)
    max_real = np.full(n, np.nan)
    speeds, ops = [], []
    status, msg = [None] * n, [None] * n
    for k, pid in enumerate(range(lo, hi)):
        _, p = job.point(pid)
        speeds.append(p.get("speed_hz", 50.0))
        try:
            ops.append(pt.operating(asm, p))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            ops.append(None)
            status[k], msg[k] = "error", f"{type(exc).__name__}: {exc}"
    # runs of valid points: one C++ call each (equilibrium continued along the run, cold
    # after a failure, K_H/D_H, the harmonic solve at each speed, the largest Re λ there: above
    # the threshold of instability the response is no steady orbit, ``point_stable`` says so)
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
            pt.equilibrium_options(opts), np.zeros((0, 0)), F1, O, False, 0.0, False, True,
            asm.rotor.xy_pairs(), asm.rotor.rot_pairs(), 1, True)
        Z = np.asarray(res.Y)
        X[k:j + 1], Y[k:j + 1] = Z[:, 0::2], Z[:, 1::2]
        max_real[k:j + 1] = np.asarray(res.max_real)
        for i, (st, m) in enumerate(zip(res.status, res.message)):
            status[k + i], msg[k + i] = (st if st in pt.STATUS else "error"), m
        k = j + 1
    res = UnbalanceResult(np.asarray(speeds), stations, X, Y, np.asarray(status),
                          tuple(map(tuple, ub)),
                          tuple(opts["operating_speed_hz"]) if "operating_speed_hz" in opts
                          else None, max_real_1_per_s=max_real,
                          point_message=np.asarray(msg, dtype=object))
    return [(np.repeat(at + np.arange(n), len(stations)),
             unbalance_columns(res, speeds, stations, status, msg))]


def _peak_column(peak, status):
    """(n·ns,) ``peak``: null at a speed without a converged equilibrium (no response there, so
    no verdict either way; it read False), else whether a peak sits at that speed."""
    from rotordyn._common.status import CONVERGED
    failed = np.array([str(x) not in CONVERGED for x in status], dtype=bool)
    if not failed.any():
        return peak.ravel()
    out = peak.astype(object)
    out[failed, :] = None
    return out.ravel()


def _stable_column(res, status, ns):
    """(n·ns,) ``point_stable``: the speed's linear verdict (:attr:`UnbalanceResult.stable`,
    the stability rows' rule), null where no equilibrium converged (nothing linearised)."""
    from rotordyn._common.status import CONVERGED
    failed = np.array([str(x) not in CONVERGED for x in status], dtype=bool)
    out = np.asarray(res.stable, dtype=bool).astype(object)
    out[failed] = None
    return np.repeat(out, ns)


def unbalance_columns(res, speeds, stations, status, msg) -> dict:
    """The (speed, station) columns of an unbalance line (flat, speed-major) from its
    :class:`UnbalanceResult`: amplitudes, phases, orbit axes, the peaks' critical speed, AF
    and separation margin (API 684), and the speed's stability verdict ``point_stable``
    (``res`` computed with the stability check)."""
    n = len(speeds)
    X, Y = res.x, res.y
    major, minor = res.major_m, res.minor_m
    ns = len(stations)
    peak = np.zeros((n, ns), bool)
    crit, amp, sep = (np.full((n, ns), math.nan) for _ in range(3))
    for j, st in enumerate(stations):
        pk = res.peaks(st)
        for _, r in pk.iterrows():
            i = int(np.argmin(np.abs(np.asarray(speeds) - r["critical_speed_hz"])))
            peak[i, j] = True
            crit[i, j] = float(r["critical_speed_hz"])
            amp[i, j] = float(r["amplification_factor"])
            sep[i, j] = float(r.get("separation_margin_pct", math.nan))
    return {
        "station": np.tile(np.array(stations, dtype=np.int64), n),
        # |z| by hypot (the scalar abs of each entry: numpy's vectorised complex abs can
        # differ from it in the last bit)
        "amplitude_x_m": np.hypot(X.real, X.imag).ravel(),
        "amplitude_y_m": np.hypot(Y.real, Y.imag).ravel(),
        "phase_x_deg": np.degrees(np.angle(X)).ravel(),
        "phase_y_deg": np.degrees(np.angle(Y)).ravel(),
        "major_m": np.asarray(major, dtype=float).ravel(),
        "minor_m": np.asarray(minor, dtype=float).ravel(), "peak": _peak_column(peak, status),
        "critical_speed_hz": crit.ravel(), "amplification_factor": amp.ravel(),
        "separation_margin_pct": sep.ravel(),
        "point_stable": _stable_column(res, status, ns),
        "status": np.repeat(np.array(status, dtype=object), ns),
        "message": np.repeat(np.array(msg, dtype=object), ns)}


def block_rows(job, chunk_id, lo, hi, asms, blocks, rows):
    """The rows of ``blocks`` over the points [lo, hi) (chunk-local indices from 0, models
    ``asms``) as dicts appended to ``rows``, identity columns included (for the analyses
    that build on crossings row by row)."""
    from rotordyn.sweep.columns import identity

    ident = identity(job, chunk_id, np.arange(lo, hi), asms)
    for pts, cols in blocks:
        for j, k in enumerate(pts):
            row = {name: v[k].item() if hasattr(v[k], "item") else v[k]
                   for name, v in ident.items()}
            for name, v in cols.items():
                x = v if np.isscalar(v) or v is None else v[j]
                row[name] = x.item() if hasattr(x, "item") else x
            rows.append(row)
