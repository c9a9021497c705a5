"""The per-row sweep chunks as they were before the columnar blocks (issue 22), kept verbatim
(from python/rotordyn/sweep/work.py and lines.py at fd973e0) as the reference of
tests/test_sweep_columns.py: one dict per row (or per point), then the generic
``rotordyn.sweep.work.to_table``; boundary points by the per-point Python loop."""
# flake8: noqa
import math

import numpy as np
import pyarrow as pa

from rotordyn import _core
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.errors import RotordynError
from rotordyn.results.modes import settled_real
from rotordyn.results.unbalance import UnbalanceResult
from rotordyn._common.whirl import WHIRL_NAMES
from rotordyn.sweep import points as pt
from rotordyn.sweep.lines import max_real
from rotordyn.sweep.points import (CONVERGED, STATUS, Variants, base_system, equilibrium_options,
                                   job_model_ay, operating, point_options, ref_bearing,
                                   stable_modes)
from tracking_reference import track_modes_reference


def track_line(rows, line, weight=None):
    """The former per-line tracking (NumPy/SciPy, tests/tracking_reference.py)."""
    k = max(len(lam) for _, lam, _ in line)
    n = line[0][2].shape[0]
    lam = np.full((len(line), k), np.nan + 0j)
    phi = np.full((len(line), n, k), np.nan + 0j)
    for i, (_, lm, ph) in enumerate(line):
        lam[i, :len(lm)] = lm
        phi[i, :, :ph.shape[1]] = ph
    ids = track_modes_reference(lam, phi, weight=weight)
    for i, (at, lm, _) in enumerate(line):
        rows[at]["mode_id"] = ids[i, :len(lm)].astype(np.int64)
from rotordyn.sweep.lines import block_rows, threshold_line as threshold_line_blocks
from rotordyn.sweep.work import STR, Job, categories, schema
from rotordyn.units import hz_to_rad_s


def run_chunk(job: Job, chunk_id: int, lo: int, hi: int, pids=None) -> pa.Table:
    """Rows of points [lo, hi) (or of the listed point ids ``pids``, for the adaptive
    boundary) as a table with :func:`schema`."""
    rows: list[dict] = []
    base = base_system(job.model_toml)
    variants = Variants(base, job.model_toml)
    if pids is not None:
        _boundary_rows(job, variants, chunk_id, pids, rows)
    else:
        {"equilibrium": _eq_rows, "stability": _stab_rows, "campbell": _stab_rows,
         "threshold": _threshold_rows, "unbalance": _unbalance_rows}[job.analysis](
            job, variants, chunk_id, lo, hi, rows)
    return to_table(job, rows)


def _eq_rows(job, variants, chunk_id, lo, hi, rows):
    """Equilibria of a chunk through the C++ batch (one call per run of points sharing a
    model and options, continued along the line from "ok" points, cold after a failure):
    one row per bearing, or one error row for a point that raised."""
    items = []  # [row, asm, opts, line, (f, pc, a) or None, error]
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, lo, hi):
        op = None
        if not err:
            try:
                op = operating(asm, p)
            except (RotordynError, ArithmeticError, ValueError) as exc:
                err = str(exc)
        items.append([row, asm, opts, line, op, err])
    i = 0
    while i < len(items):
        if items[i][5]:
            rows.append(fail_row(items[i][0], "error", items[i][5]))
            i += 1
            continue
        j = i
        while j + 1 < len(items) and not items[j + 1][5] and items[j + 1][1] is items[i][1] \
                and items[j + 1][2] == items[i][2]:
            j += 1
        _eq_batch(items[i:j + 1], rows)
        i = j + 1


def _eq_batch(seg, rows):
    asm, opts = seg[0][1], seg[0][2]
    restart = [1 if k == 0 or not it[3] else 0 for k, it in enumerate(seg)]
    res = _core.equilibrium_batch(
        asm.solver, np.array([hz_to_rad_s(it[4][0]) for it in seg]),
        np.array([it[4][1] for it in seg]), np.array([it[4][2] for it in seg]), restart,
        equilibrium_options(opts))
    R, IT, RES = np.asarray(res.r), np.asarray(res.iterations), np.asarray(res.residual)
    # per bearing (a tilting pad has a film per pad, a table bearing none: NaN)
    HM = asm.bearing_h_min(np.asarray(res.h_min))
    HZ = np.asarray(res.h_min_z_m)
    FF = np.asarray(res.film_force)  # the films' H: moments at a tilting film's rotations
    for k, it in enumerate(seg):
        st, msg = res.status[k], res.message[k]
        if st == "error":  # the solve raised
            rows.append(fail_row(it[0], "error", msg))
            continue
        ok = st in CONVERGED
        for b, bc in enumerate(asm.bearings):
            x = float(R[k, bc.jx]) if ok else math.nan
            y = float(R[k, bc.jy]) if ok else math.nan
            c = bc.clearance_m if bc.clearance_m > 0 else math.nan  # a table: no clearance
            tilt = ok and bool(bc.rot)
            rows.append({**it[0], "bearing": bc.name, "journal_x_m": x, "journal_y_m": y,
                         "x_over_c": x / c, "y_over_c": y / c,
                         "h_min_m": float(HM[k, b]) if ok else math.nan,
                         "iterations": int(IT[k]), "residual": float(RES[k]),
                         "journal_theta_x_rad": float(R[k, bc.rot[0]]) if tilt else math.nan,
                         "journal_theta_y_rad": float(R[k, bc.rot[1]]) if tilt else math.nan,
                         "h_min_z_m": float(HZ[k, asm.film_owner.index(bc.index)]) if tilt
                         else math.nan,
                         "film_moment_x_n_m": float(FF[k, bc.rot[0]]) if tilt else math.nan,
                         "film_moment_y_n_m": float(FF[k, bc.rot[1]]) if tilt else math.nan,
                         "status": st if st in STATUS else "error", "message": msg})


def _stab_rows(job, variants, chunk_id, lo, hi, rows):
    """Stability points of a chunk through the C++ batch (one call per run of points sharing
    a model and options): equilibrium continued along the line, K_H/D_H, eigen-analysis."""

    items = []  # (row, asm, opts, line, (f, pc, a) or None, error)
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, lo, hi):
        op = None
        if not err:
            try:
                op = operating(asm, p)
            except RotordynError as exc:
                err = f"{type(exc).__name__}: {exc}"
        items.append([row, asm, opts, line, op, err])
    # runs of consecutive valid points on one model with one set of options
    out: list = [None] * len(items)
    i = 0
    while i < len(items):
        if items[i][5]:
            out[i] = (fail_row(items[i][0], "error", items[i][5]), None, None)
            i += 1
            continue
        j = i
        while j + 1 < len(items) and not items[j + 1][5] and items[j + 1][1] is items[i][1] \
                and items[j + 1][2] == items[i][2]:
            j += 1
        _stab_batch(job, items[i:j + 1], out, i, restart_first=True)
        i = j + 1
    # tracking along lines, rows in point order
    weight = None
    line_buf: list = []

    def flush():
        if job.options.get("track", True) and line_buf:
            track_line(rows, line_buf, weight)
        line_buf.clear()

    for it, o in zip(items, out):
        if not it[3]:
            flush()
        r, lam, phi = o
        if lam is not None:
            line_buf.append((len(rows), lam, phi))
            weight = it[1].mats[0]
        rows.append(r)
    flush()


def _stab_batch(job, seg, out, at, restart_first):

    asm, opts = seg[0][1], seg[0][2]
    n_modes = job.options.get("n_modes") or 0
    o = equilibrium_options(opts)
    restart = [1 if (k == 0 and restart_first) or not it[3] else 0 for k, it in enumerate(seg)]
    res = _core.stability_batch(
        asm.solver, np.array([hz_to_rad_s(it[4][0]) for it in seg]),
        np.array([it[4][1] for it in seg]), np.array([it[4][2] for it in seg]), restart, o,
        int(n_modes), opts.get("linearization", "perturbation") == "finite_difference",
        FD_REL_STEP, asm.rotor.xy_pairs(), asm.rotor.rot_pairs(),
        [i for bc in asm.bearings for i in bc.sleeve])

    bc = ref_bearing(asm)
    status, message = res.status, res.message
    n_eig = np.asarray(res.n_eig)
    R = np.asarray(res.r)
    H = np.asarray(res.h_min)
    EV = np.asarray(res.eigenvalues)
    WH = np.asarray(res.whirl)
    SS = np.asarray(res.sleeve_share)
    IT = np.asarray(res.iterations)
    modes = res.modes
    names = np.array([WHIRL_NAMES[-1], WHIRL_NAMES[0], WHIRL_NAMES[1]])
    # Every per-mode column for the whole batch at once (elementwise: the same numbers as
    # point by point; slots past a point's n_eig are padding, never read).
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        MS = stable_modes(EV)
        RE = settled_real(EV)  # round-off of an undamped mode is 0, not a sign
        AB = np.abs(EV)
        DR = np.where(AB > 0, -RE / AB, np.nan)
        LD = np.where(EV.imag != 0, -2 * np.pi * RE / EV.imag, np.nan)
        FR = EV.imag / (2 * np.pi)
    WN = names[np.clip(WH, -1, 1) + 1]
    KIND = np.where(SS > 0.5, "sleeve", "rotor")
    jx = R[:, bc.jx] if bc else None
    jy = R[:, bc.jy] if bc else None
    for k, it in enumerate(seg):
        row = it[0]
        st = status[k] if status[k] in STATUS else "error"
        ke = int(n_eig[k])
        if st not in CONVERGED or ke == 0:
            out[at + k] = (fail_row(row, st, message[k] or "no equilibrium"), None, None)
            continue
        lam = EV[k, :ke]
        ms = MS[k, :ke]
        hm = H[k]
        out[at + k] = ({**row, "_n": ke, "journal_x_m": float(jx[k]) if bc else math.nan,
                        "journal_y_m": float(jy[k]) if bc else math.nan,
                        "h_min_m": float(np.nanmin(hm)) if hm.size else math.nan,
                        "iterations": int(IT[k]), "point_stable": bool(ms.all()),
                        "max_real_1_per_s": float(lam.real.max()), "mode_id": np.arange(ke),
                        "mode": np.arange(1, ke + 1), "freq_hz": FR[k, :ke],
                        "eig_real_1_per_s": lam.real, "damping_ratio": DR[k, :ke],
                        "log_dec": LD[k, :ke], "whirl": WN[k, :ke], "kind": KIND[k, :ke],
                        "mode_stable": ms, "status": st, "message": message[k]},
                       lam, modes[k])


def _lines(job, lo, hi):
    """Split [lo, hi) into lines of the innermost axis."""
    n = job.shape[-1]
    for s in range(lo, hi, n):
        yield s, min(s + n, hi)


def _threshold_rows(job, variants, chunk_id, lo, hi, rows):

    for s, e in _lines(job, lo, hi):
        threshold_line(job, variants, chunk_id, s, e, rows)


def _unbalance_rows(job, variants, chunk_id, lo, hi, rows):

    for s, e in _lines(job, lo, hi):
        unbalance_line(job, variants, chunk_id, s, e, rows)


def _max_real_modes(job, asm, p, r0, opts, exclude_sleeve):
    """lines.max_real with the point's every mode: (max Re λ, its frequency Hz, status,
    equilibrium r or None, eigenvalues, whirl, kind)."""
    f, pc, a = pt.operating(asm, p)
    e = pt.solve_equilibrium(asm, f, pc, a, r0, opts)
    if e.status not in CONVERGED:
        return math.nan, math.nan, e.status, None, None, None, None
    lam, _, whirl, kind = pt.eigen(asm, e, f, opts, None)
    use = lam[kind == "rotor"] if exclude_sleeve else lam
    i = int(np.argmax(use.real))
    return (float(use[i].real), float(use[i].imag / (2 * np.pi)), e.status, np.asarray(e.r),
            lam, whirl, kind)


def _boundary_rows(job, variants, chunk_id, pids, rows):
    """One row per mode of each listed point (a failed point: one row): the stability rows'
    mode columns (mode_id the slot), max Re λ (rotor modes only with exclude_sleeve_modes)
    and its frequency, point_stable; ``level`` is set by the driver."""

    excl = bool(job.options.get("exclude_sleeve_modes", False))
    r_prev = None
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, 0, 0, pids):
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        try:
            y, fr, st, r, lam, whirl, kind = _max_real_modes(
                job, asm, p, r_prev if line else None, opts, excl)
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            rows.append(fail_row(row, "error", f"{type(exc).__name__}: {exc}"))
            r_prev = None
            continue
        r_prev = r
        if r is None:
            rows.append(fail_row(row, st if st in STATUS else "error", "no equilibrium"))
            continue
        ke = len(lam)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            RE = settled_real(lam)
            AB = np.abs(lam)
            DR = np.where(AB > 0, -RE / AB, np.nan)
            LD = np.where(lam.imag != 0, -2 * np.pi * RE / lam.imag, np.nan)
        rows.append({**row, "_n": ke, "mode_id": np.arange(ke), "mode": np.arange(1, ke + 1),
                     "freq_hz": lam.imag / (2 * np.pi), "eig_real_1_per_s": lam.real,
                     "damping_ratio": DR, "log_dec": LD, "whirl": whirl, "kind": kind,
                     "mode_stable": stable_modes(lam), "point_stable": y < 0,
                     "max_real_1_per_s": y, "max_real_freq_hz": fr,
                     "level": job.level, "status": st, "message": ""})



_AXIS = {"speed_hz": _core.ThresholdAxis.speed,
         "chamber_pressure_pa": _core.ThresholdAxis.chamber_pressure,
         "config_ay_m": _core.ThresholdAxis.config}


def threshold_line(job, variants, chunk_id, lo, hi, rows):
    """One row per crossing of max Re λ = 0 along the line [lo, hi) (the varied axis is
    innermost); a line without one is a ``no_crossing`` row."""
    vary = job.options["vary"]
    excl = bool(job.options.get("exclude_sleeve_modes", False))
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        rows.append(fail_row(common_row(job, lo, chunk_id, idx0, p0, None), "error", str(exc)))
        return
    row = common_row(job, lo, chunk_id, idx0, p0, asm)
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
    verdicts = np.asarray(res.stable)
    evals = len(xs)
    found = 0
    for i, x, fr, status, msg, evals in zip(res.bracket, res.root, res.root_freq, res.status,
                                            res.message, res.evaluations):
        found += 1
        low_stable = (verdicts[i] == 1) == (xs[i] < xs[i + 1])
        speed = x if vary == "speed_hz" else row["speed_hz"]
        rows.append({**row, vary: x, "crossing": found, "value": x,
                     "whirl_frequency_hz": fr, "whirl_ratio": fr / speed if speed else math.nan,
                     "stable_side": "below" if low_stable else "above", "evaluations": evals,
                     "status": status, "message": msg})
    if not found:
        good = verdicts[verdicts >= 0]
        what = ("no point of the line has an equilibrium" if not good.size else
                f"{'stable' if good.all() else 'unstable'} at all {good.size} points"
                if good.min() == good.max() else
                "the verdict changes only across failed points")
        rows.append({**row, vary: math.nan, "crossing": 0, "value": math.nan,
                     "evaluations": evals, "status": "no_crossing",
                     "message": f"the stability verdict does not change along {vary}: "
                                f"{what}"})


def unbalance_line(job, variants, chunk_id, lo, hi, rows):
    """Unbalance response along the speed line [lo, hi): one row per (speed, station), with
    ``peak`` rows carrying the amplification factor and separation margin (API 684)."""
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        rows.append(fail_row(common_row(job, lo, chunk_id, idx0, p0, None), "error", str(exc)))
        return
    opts = pt.point_options(job, p0)
    ub = opts["unbalances"]
    stations = tuple(opts.get("stations") or dict.fromkeys(int(u[0]) for u in ub))
    Cout = [asm.station_output_matrix(s) for s in stations]
    F1 = asm.unbalance_load(ub)
    n = hi - lo
    X = np.full((n, len(stations)), np.nan + 0j)
    Y = np.full((n, len(stations)), np.nan + 0j)
    max_real = np.full(n, np.nan)
    base, speeds, ops = [], [], []
    status, msg = [None] * n, [None] * n
    for k, pid in enumerate(range(lo, hi)):
        idx, p = job.point(pid)
        base.append(common_row(job, pid, chunk_id, idx, p, asm))
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
                          else None, max_real_1_per_s=max_real)
    major, minor = res.major_m, res.minor_m
    solved = np.isin(np.asarray(status, dtype=str), list(pt.CONVERGED))
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
                         "point_stable": bool(res.stable[k]) if solved[k] else None,
                         "status": status[k], "message": msg[k]})


# --- the row-wise helpers the package had before its columnar chunks (moved here from
# rotordyn.sweep.work, points and lines: no chunk of the package uses them any more) ---

def same_line(prev, idx, pos) -> bool:
    """Consecutive points that differ only along the innermost varying axis."""
    return prev is not None and prev[:pos] == idx[:pos] and prev[pos + 1:] == idx[pos + 1:]


def common_row(job, pid, chunk_id, idx, p, asm):
    row = {"point_id": pid, "chunk_id": chunk_id}
    for (a, _), i in zip(job.axes.items(), idx):
        row[f"i_{a}"] = i
    row.update(p)
    row.setdefault("speed_hz", 50.0)
    row.setdefault("chamber_pressure_pa", 0.0)
    bc = ref_bearing(asm, job.options.get("bearing")) if asm is not None else None
    if "config_ay_m" not in row:
        row["config_ay_m"] = (job_model_ay(asm, bc) if bc is not None else math.nan)
    row["journal_bearing"] = asm.system.bearings[bc.index].name if bc is not None else None
    return row


def fail_row(row, status, message):
    return {**row, "status": status, "message": message}


def points(job, variants, chunk_id, lo, hi, pids=None):
    """Yield (row, p, asm, opts, same_line, error) per point; a model-variant error is
    yielded as asm=None with its message."""
    prev = None
    for pid in (range(lo, hi) if pids is None else pids):
        idx, p = job.point(pid)
        try:
            asm = variants.get(p)
            err = None
        except RotordynError as exc:
            asm, err = None, str(exc)
        row = common_row(job, pid, chunk_id, idx, p, asm)
        yield row, p, asm, point_options(job, p), same_line(prev, idx, job.line_pos), err
        prev = idx


def threshold_line_rows(job, variants, chunk_id, lo, hi, rows, scan=None):
    """:func:`threshold_line` as one dict per row appended to ``rows`` (each with its point's
    identity columns)."""
    asms = [None] * (hi - lo)
    blocks = threshold_line_blocks(job, variants, lo, hi, 0, asms, scan=scan)
    block_rows(job, chunk_id, lo, hi, asms, blocks, rows)


def to_table(job: Job, rows: list[dict], sch: pa.Schema | None = None) -> pa.Table:
    """Rows (dicts) to the fixed schema: missing values are nulls, categoricals use the fixed
    category lists so every part has the same dictionary. No chunk builds its rows this way
    any more (every analysis is columnar, :func:`rotordyn.sweep.work.run_chunk`): the
    reference of tests/test_sweep_columns*.py. ``sch``: another schema (the thermal
    columns of ``options.thermal``, tests/sweep_thermal_rows_reference.py)."""
    sch = schema(job.analysis, list(job.axes)) if sch is None else sch
    cats = categories(job.analysis)
    cols = []
    sizes = [r.get("_n", 1) for r in rows]
    n = sum(sizes)
    for fld in sch:
        name = fld.name
        if name == "sweep_id":
            cols.append(pa.DictionaryArray.from_arrays(
                pa.array(np.zeros(n, dtype=np.int8)), pa.array([job.sweep_id])))
            continue
        vals: list = []
        for r, k in zip(rows, sizes):
            x = r.get(name)
            if isinstance(x, np.ndarray):
                vals.extend(x.tolist())
            elif k == 1:
                vals.append(x)
            else:
                vals.extend([x] * k)
        if name in cats:
            code = {c: i for i, c in enumerate(cats[name])}
            codes = pa.array([None if x is None else code[x] for x in vals], type=pa.int8())
            cols.append(pa.DictionaryArray.from_arrays(codes, pa.array(cats[name])))
        elif name == "message":
            cols.append(pa.array(["" if x is None else str(x) for x in vals], type=STR))
        else:
            cols.append(pa.array(vals, type=fld.type, from_pandas=False))
    if job.meta:
        import json

        sch = sch.with_metadata({b"rotordyn": json.dumps(job.meta, sort_keys=True).encode()})
    return pa.Table.from_arrays(cols, schema=sch)
