"""The dict-per-row sweep chunks of the thermal, waterfall, run-up, robust, hopf and
limit_cycle analyses as they were before their columnar blocks (issue 22), kept verbatim (from
python/rotordyn/sweep/work.py, robust_rows.py, hopf_rows.py and
limit_cycle_rows.py at 6ea1047) as the reference of
tests/test_sweep_columns_points.py: one dict per row, then the generic
``rotordyn.sweep.work.to_table``."""
# flake8: noqa
import math

import numpy as np
import pyarrow as pa

from rotordyn._common import validate as v
from rotordyn.analysis.hopf import FD_STEP
from rotordyn.analysis.thermal import system_thermal_equilibrium
from rotordyn.analysis.transient import transient
from rotordyn.control.robust import build_controller, closed_loop_point, eigen_columns, margin_columns
from rotordyn.errors import RotordynError
from rotordyn.operation import SpeedProfile
from rotordyn.sweep import points as pt
from rotordyn.sweep.hopf_rows import HOPF_COLUMNS, _one
from rotordyn.sweep.limit_cycle_rows import (CYCLE_COLUMNS, NATURAL_ENDS, _Line,
                                            _branch, _cycle_columns, _same, _shoot,
                                            _short_of_the_end, _starts, _where)
from rotordyn.analysis.assembly import pin_assembled
import copy
from rotordyn.sweep.points import (CONVERGED, STATUS, Variants, base_system, operating,
                                   ref_bearing, solve_equilibrium)
from rotordyn.sweep.work import OUTPUTS, Job
from sweep_rows_reference import common_row, fail_row, points, threshold_line_rows, to_table


def run_chunk(job: Job, chunk_id: int, lo: int, hi: int) -> pa.Table:
    rows: list[dict] = []
    variants = Variants(base_system(job.model_toml), job.model_toml)
    if job.analysis in ("hopf", "limit_cycle"):
        line = hopf_line if job.analysis == "hopf" else limit_cycle_line
        for s, e in _lines(job, lo, hi):
            line(job, variants, chunk_id, s, e, rows)
    else:
        {"thermal": _thermal_rows, "waterfall": _wf_rows, "run-up": _runup_rows,
         "robust": robust_rows}[job.analysis](job, variants, chunk_id, lo, hi, rows)
    return to_table(job, rows)


def _thermal_rows(job, variants, chunk_id, lo, hi, rows):
    """Effective-temperature system equilibria (the model's ``[thermal]``, every field of
    which is an axis: ``thermal.supply_temperature_c``, ``thermal.oil.nu1_mm2_s``,
    ``thermal.films.<bearing>.carry_over``...), one row per plain journal bearing; each point
    starts cold (same answer as a direct call)."""
    cols = [k for k in OUTPUTS["thermal"] if k not in ("bearing", "iterations")]
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, lo, hi):
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        try:
            f, pc, _ = operating(asm, p)
            r = system_thermal_equilibrium(asm.system, speed_hz=f, chamber_pressure_pa=pc,
                                           tol_k=opts.get("tol_k", 1e-6))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            rows.append(fail_row(row, "error", str(exc)))
            continue
        ok = r.status in CONVERGED
        for k, name in enumerate(r.bearing_names):
            vals = {c: float(getattr(r, c)[k]) if ok else math.nan for c in cols}
            rows.append({**row, "bearing": name, **vals, "iterations": int(r.iterations),
                         "status": r.status if r.status in STATUS else "error",
                         "message": r.message})


def _wf_rows(job, variants, chunk_id, lo, hi, rows):
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, lo, hi):
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        try:
            f, pc, a = operating(asm, p)
            v.positive("speed_hz", f)
            r0 = _start(asm, f, pc, a)
            if isinstance(r0, tuple):
                rows.append(fail_row(row, *r0))
                continue
            revs = int(opts.get("revolutions", 60))
            spr = int(opts.get("samples_per_revolution", 64))
            ub = [tuple(u) for u in opts.get("unbalances", [])]
            tr = transient(asm.system, revs / f, f, pc, p.get("config_ay_m"), r0=r0,
                              unbalances=ub, n_out=revs * spr + 1,
                              rtol=float(opts.get("rtol", 1e-6)),
                              rub_fraction=float(opts.get("rub_fraction", 1e-3)))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            rows.append(fail_row(row, "error", f"{type(exc).__name__}: {exc}"))
            continue
        if tr.status not in CONVERGED:  # "contact": integrated from a contact equilibrium
            rows.append(fail_row(row, tr.status if tr.status in STATUS else "error", tr.message))
            continue
        freq, ax = tr.spectrum(last_fraction=0.5, axis="x")
        _, ay_ = tr.spectrum(last_fraction=0.5, axis="y")
        # max_frequency_hz: every speed's spectrum over the same span (a waterfall's traces
        # then line up); else up to max_harmonic × speed
        fmax = opts.get("max_frequency_hz")
        keep = freq <= (float(fmax) if fmax is not None
                        else float(opts.get("max_harmonic", 4.0)) * f)
        for fr, a1, a2 in zip(freq[keep], ax[keep], ay_[keep]):
            rows.append({**row, "freq_hz": float(fr), "amplitude_x_m": float(a1),
                         "amplitude_y_m": float(a2), "order": float(fr / f),
                         "status": tr.status, "message": tr.message})


def _start(asm, f, pc, a):
    """The cold-started equilibrium a transient point starts from (not the thread's last
    one: the rows must not depend on what ran before), or (status, message)."""
    e = solve_equilibrium(asm, f, pc, a, None, {})
    if e.status not in CONVERGED:
        return (e.status if e.status in STATUS else "error",
                f"no equilibrium to start from: {e.message}")
    return np.asarray(e.r)


def _runup_rows(job, variants, chunk_id, lo, hi, rows):
    """A nonlinear run-up (or coast-down) per point: Ω(t) ramps from start_hz to stop_hz at
    rate_hz_per_s (rotordyn.control.SpeedProfile); one row per revolution with its mean
    speed (in ``speed_hz``), the half peak-to-peak journal motion of the active (or first)
    bearing and the smallest film over that revolution."""
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, lo, hi):
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        try:
            _, pc, a = operating(asm, {**p, "speed_hz": opts["start_hz"]})
            f0, f1, rate = opts["start_hz"], opts["stop_hz"], opts["rate_hz_per_s"]
            r0 = _start(asm, f0, pc, a)
            if isinstance(r0, tuple):
                rows.append(fail_row(row, *r0))
                continue
            prof = SpeedProfile.ramp(f0, f1, rate)
            T = abs(f1 - f0) / rate
            spr = int(opts.get("samples_per_revolution", 32))
            revs = (f0 + f1) / 2 * T
            tr = transient(asm.system, T, chamber_pressure_pa=pc,
                              config_ay_m=p.get("config_ay_m"), speed=prof, r0=r0,
                              unbalances=[tuple(u) for u in opts["unbalances"]],
                              n_out=int(revs * spr) + 1, rtol=float(opts.get("rtol", 1e-6)),
                              rub_fraction=float(opts.get("rub_fraction", 1e-3)))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            rows.append(fail_row(row, "error", f"{type(exc).__name__}: {exc}"))
            continue
        bc = ref_bearing(asm)
        k = bc.index if bc else 0
        # the rows reached (a failed run, e.g. "rub", leaves NaN rows after it stopped)
        done = np.isfinite(np.asarray(tr.angle_rad)) & np.all(np.isfinite(tr.r), axis=1)
        rev = np.floor(np.asarray(tr.angle_rad)[done] / (2 * np.pi)).astype(np.int64)
        x, y = np.asarray(tr.journal_x_m)[done, k], np.asarray(tr.journal_y_m)[done, k]
        h = np.asarray(tr.h_min_m)[done, k]
        sp, t = np.asarray(tr.speed_hz_t)[done], np.asarray(tr.t)[done]
        n_rows = len(rows)
        revs_reached = np.unique(rev)
        if tr.status not in CONVERGED and revs_reached.size:
            revs_reached = revs_reached[:-1]  # a stopped run's last revolution is partial
        for n_rev in revs_reached:
            m = rev == n_rev
            if m.sum() < 2:
                continue
            rows.append({**row, "speed_hz": float(sp[m].mean()), "revolution": int(n_rev),
                         "time_s": float(t[m].mean()),
                         "amplitude_x_m": float(np.ptp(x[m]) / 2),
                         "amplitude_y_m": float(np.ptp(y[m]) / 2), "h_min_m": float(h[m].min()),
                         "status": tr.status if tr.status in STATUS else "error",
                         "message": tr.message})
        if tr.status != "ok" and len(rows) == n_rows:  # stopped before one whole revolution
            rows.append(fail_row(row, tr.status if tr.status in STATUS else "error", tr.message))


def _lines(job, lo, hi):
    """Split [lo, hi) into lines of the innermost axis."""
    n = job.shape[-1]
    for s in range(lo, hi, n):
        yield s, min(s + n, hi)


def robust_rows(job, variants, chunk_id, lo, hi, rows):
    """One row per point (module docstring)."""
    from rotordyn._common.status import CONVERGED
    from rotordyn.analysis.equilibrium import equilibrium
    from rotordyn.errors import ConvergenceError
    from rotordyn.sweep.points import STATUS, ref_bearing

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
    for row, p, asm, _, line, err in points(job, variants, chunk_id, lo, hi):
        if err:
            rows.append(fail_row(row, "error", err))
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
            rows.append(fail_row(row, st, f"no closed-loop verdict: {failure}"))
            continue
        if failure is not None:
            rows.append(fail_row(row, "error", f"{type(failure).__name__}: {failure}"))
            continue
        if pl.info.get("equilibrium_status") == "ok":
            r_prev = pl.info.get("equilibrium_r")
        bc = ref_bearing(asm)
        r = pl.info.get("equilibrium_r")
        jx = float(r[bc.jx]) if bc is not None and r is not None else math.nan
        jy = float(r[bc.jy]) if bc is not None and r is not None else math.nan
        rows.append({**row, "journal_x_m": jx, "journal_y_m": jy, **eigen_columns(lam),
                     **margin_columns(m),
                     "status": pl.info.get("equilibrium_status", "ok"), "message": msg})


def hopf_line(job, variants, chunk_id, lo, hi, rows, scan=None):
    """The threshold rows of the line [lo, hi), each crossing with its Hopf columns; a
    failed l1 keeps the crossing and gets status ``error`` with the message. ``scan``: as
    for :func:`~rotordyn.sweep.lines.threshold_line`."""
    vary = job.options["vary"]
    excl = bool(job.options.get("exclude_sleeve_modes", False))
    fd_step = float(job.options.get("fd_step", FD_STEP))
    line = []
    threshold_line_rows(job, variants, chunk_id, lo, hi, line, scan)
    _, p0 = job.point(lo)
    _, p1 = job.point(hi - 1)
    span = abs(p1[vary] - p0[vary])
    for row in line:
        out = {**row, **{c: (math.nan if c != "hopf_type" else "") for c in HOPF_COLUMNS}}
        if row.get("status") == "ok":
            _, p = job.point(row["point_id"])
            p = dict(p)
            p[vary] = row["value"]
            try:
                asm = variants.get(p)
                out.update(_one(job, asm, p, vary, row["whirl_frequency_hz"], span,
                                pt.point_options(job, p), excl, fd_step))
            except (RotordynError, ArithmeticError, ValueError,
                    np.linalg.LinAlgError) as exc:
                out.update(status="error", message=f"l1: {type(exc).__name__}: {exc}")
        rows.append(out)


def limit_cycle_line(job, variants, chunk_id, lo, hi, rows):
    """The rows of the line [lo, hi) (module docstring)."""
    hrows, scan = [], {}
    # the hopf rows without the shooting's ``tol``: the threshold scan, the crossings and
    # l1 read ``tol`` as the equilibrium's tolerance (default 1e-10, as in a hopf sweep)
    hjob = copy.copy(job)
    hjob.options = {k: x for k, x in job.options.items() if k != "tol"}
    hopf_line(hjob, variants, chunk_id, lo, hi, hrows, scan)
    nan_cols = {c: math.nan for c in CYCLE_COLUMNS}
    nan_cols.update(cycle=None, bearing=None, critical_type=None, stable=None,
                    equilibrium_stable=None, coexists_with_stable_equilibrium=None,
                    bistable=None, newton_iterations=None)
    for r in hrows:
        rows.append({**nan_cols, **r, "record": "hopf"})
    vary = job.options["vary"]
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        for pid in range(lo, hi):
            idx, p = job.point(pid)
            rows.append(fail_row({**nan_cols, **common_row(job, pid, chunk_id, idx, p,
                                                                  None), "record": "cycle"},
                                    "failed", str(exc)))
        return
    pin_assembled(asm)
    pts = [job.point(pid) for pid in range(lo, hi)]
    xs = [p[vary] for _, p in pts]
    span = max(xs) - min(xs)
    line = _Line(job, asm, p0, xs)
    ys = scan.get("y", np.full(len(xs), np.nan))
    name, C = _where(asm, job.options.get("station"))
    bc = pt.ref_bearing(asm)
    clearance = bc.clearance_m if (bc is not None and job.options.get("station") is None) \
        else min(b.clearance_m for b in asm.bearings)

    branches, problems = [], []
    for hr in hrows:
        if hr.get("status") != "ok" or not math.isfinite(hr.get("value", math.nan)):
            if hr.get("status") == "error":
                problems.append(f"crossing {hr['crossing']}: {hr['message']}")
            continue
        if any(b[2].stop == "hopf" and abs(b[2].bifurcations[-1]["parameter"] -
                                           hr["value"]) < 1e-2 * span
               and abs(b[1].value - hr["value"]) > 1e-2 * span for b in branches):
            continue  # this crossing ends a branch already continued from another one
        try:
            h, brs, msg = _branch(job, line, hr, span, ys)
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            h, brs, msg = None, [], f"{type(exc).__name__}: {exc}"
        if not brs:
            problems.append(f"crossing {hr['crossing']}: {msg}")
            continue
        hcols = {c: hr[c] for c in ("crossing", "value", "stable_side", "evaluations",
                                    *HOPF_COLUMNS)}
        for br in brs:
            if br.stop not in NATURAL_ENDS:
                problems.append(f"crossing {hr['crossing']}: the branch stopped early "
                                f"({br.stop}: {br.message}) at {vary} = "
                                f"{br.parameter[-1]:.6g}")
            elif br.stop == "bound" and len(br) and _short_of_the_end(br, xs):
                problems.append(f"crossing {hr['crossing']}: the branch left its bounds "
                                f"after {vary} = {br.parameter[-1]:.6g}, short of the "
                                "grid's end value (not bracketed)")
            branches.append((hcols, h, br))

    n = asm.n
    for k, (idx, p) in enumerate(pts):
        row = {**nan_cols, **common_row(job, lo + k, chunk_id, idx, p, asm),
               "record": "cycle"}
        y = float(ys[k])
        eq_st = bool(y < 0) if math.isfinite(y) else None
        row.update(max_real_1_per_s=y, equilibrium_stable=eq_st, bearing=name)
        g = p[vary]
        f = line.operating(g)[0]
        found, failed = [], []
        for hcols, h, br in branches:
            for how, starts in _starts(h, br, g, n, span):
                o, msgs = _shoot(line, h, g, how, starts)
                if o is None:
                    failed.append((hcols, "; ".join(msgs)))
                    continue
                cols = _cycle_columns(o, C, clearance, f)
                if any(_same(c, cols, line.tol, clearance) for _, c in found):
                    continue  # the same cycle reached from two segments
                found.append((hcols, cols))
        found.sort(key=lambda t: t[1]["amplitude_m"])
        bistable = bool(eq_st) and any(c["stable"] for _, c in found)
        for j, (hcols, cols) in enumerate(found):
            rows.append({**row, **hcols, **cols, "cycle": j + 1,
                         "coexists_with_stable_equilibrium": bool(eq_st),
                         "bistable": bistable, "status": "ok", "message": ""})
        for hcols, msg in failed:
            rows.append({**row, **hcols, "cycle": 0, "bistable": bistable,
                         "status": "failed", "message": msg})
        if not found and not failed:
            if problems:
                st, msg = "failed", "; ".join(problems)
            elif not branches:
                st, msg = "no_cycle", "no Hopf point on the line: no cycle branch"
            else:
                st, msg = "no_cycle", "no cycle branch passes this value"
            rows.append({**row, "cycle": 0, "bistable": False,
                         "status": st, "message": msg})
