"""What one chunk of a sweep does (inside a worker): the points [lo, hi) of the grid, computed
in order from a fresh solver state, into one pyarrow table with the analysis's fixed schema.

Determinism: a chunk builds its own :class:`Assembled` (no thread cache, no warm state from an
earlier chunk), starts its first equilibrium cold and continues only along a line (points that
differ in the innermost axis alone), so a chunk's rows are the same bit for bit whichever
worker, thread or resume computes it. A point that fails (bad value, no equilibrium, contact,
solver error) is a row with ``status``/``message``; the chunk goes on.
"""

from __future__ import annotations

import math

import numpy as np
import pyarrow as pa

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.whirl import WHIRL_NAMES
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.analysis.thermal import system_thermal_equilibrium
from rotordyn.analysis.transient import transient
from rotordyn.operation import SpeedProfile
from rotordyn.results.modes import settled_real
from rotordyn.sweep.lines import max_real, threshold_line, unbalance_line
from rotordyn.errors import RotordynError
from rotordyn.sweep.points import (CONVERGED, STATUS, Variants, base_system, equilibrium_options, fail_row, operating, points, ref_bearing,
                                   solve_equilibrium, stable_modes)
from rotordyn.sweep.tracking import track_line
from rotordyn.sweep.robust_rows import outputs as robust_outputs, robust_rows
from rotordyn.units import hz_to_rad_s

WHIRL = ["forward", "backward", "planar"]
KIND = ["rotor", "sleeve"]
F64, I64, I32, BOOL, STR = pa.float64(), pa.int64(), pa.int32(), pa.bool_(), pa.string()


def _cat(values):
    return pa.dictionary(pa.int8(), pa.string()), values


# Output columns (after the ids and axes) per analysis: name -> arrow type (or a
# (dictionary type, categories) pair for categoricals).
OUTPUTS = {
    "equilibrium": {"bearing": STR, "journal_x_m": F64, "journal_y_m": F64, "x_over_c": F64,
                    "y_over_c": F64, "h_min_m": F64, "iterations": I64, "residual": F64,
                    # tilting films (tilt = true; NaN elsewhere): the journal's rotations
                    # relative to the housing and the axial position of the minimum film
                    "journal_theta_x_rad": F64, "journal_theta_y_rad": F64, "h_min_z_m": F64},
    "thermal": {"bearing": STR, "effective_temperature_c": F64, "max_temperature_c": F64,
                "inlet_temperature_c": F64, "temperature_rise_k": F64, "viscosity_pa_s": F64,
                "power_loss_w": F64, "film_flow_m3_s": F64, "side_flow_m3_s": F64,
                "supply_flow_m3_s": F64, "journal_x_m": F64, "journal_y_m": F64,
                "iterations": I64},
    "stability": {"mode_id": I64, "mode": I64, "freq_hz": F64, "eig_real_1_per_s": F64,
                  "damping_ratio": F64, "log_dec": F64, "whirl": _cat(WHIRL),
                  "kind": _cat(KIND), "mode_stable": BOOL, "point_stable": BOOL,
                  "max_real_1_per_s": F64, "journal_x_m": F64, "journal_y_m": F64,
                  "h_min_m": F64, "iterations": I64},
    "threshold": {"crossing": I64, "value": F64, "whirl_frequency_hz": F64,
                  "whirl_ratio": F64, "stable_side": STR, "evaluations": I64},
    "boundary": {"max_real_1_per_s": F64, "freq_hz": F64, "point_stable": BOOL, "level": I64},
    "unbalance": {"station": I64, "amplitude_x_m": F64, "amplitude_y_m": F64,
                  "phase_x_deg": F64, "phase_y_deg": F64, "major_m": F64, "minor_m": F64,
                  "peak": BOOL, "critical_speed_hz": F64, "amplification_factor": F64,
                  "separation_margin_pct": F64},
    "waterfall": {"freq_hz": F64, "order": F64, "amplitude_x_m": F64, "amplitude_y_m": F64},
    "run-up": {"revolution": I64, "time_s": F64, "amplitude_x_m": F64, "amplitude_y_m": F64,
               "h_min_m": F64},
}
OUTPUTS["campbell"] = OUTPUTS["stability"]
OUTPUTS["hopf"] = {**OUTPUTS["threshold"], "l1": F64, "l1_error": F64, "hopf_type": STR,
                   "alpha_prime": F64, "amplitude_coefficient_m2": F64}
OUTPUTS["robust"] = robust_outputs(F64, BOOL, _cat)
OUTPUTS["limit_cycle"] = {"record": _cat(["hopf", "cycle"]), **OUTPUTS["hopf"],
                          "cycle": I64, "bearing": STR, "amplitude_m": F64, "amplitude_c": F64,
                          "period_s": F64, "max_multiplier": F64, "critical_type": STR,
                          "stable": BOOL, "equilibrium_stable": BOOL, "max_real_1_per_s": F64,
                          "coexists_with_stable_equilibrium": BOOL, "bistable": BOOL,
                          "newton_iterations": I64}


def schema(analysis: str, axes: list[str]) -> pa.Schema:
    """The fixed arrow schema of a sweep's rows (every chunk is cast to it)."""
    fields = [pa.field("sweep_id", pa.dictionary(pa.int8(), STR)),
              pa.field("point_id", I64), pa.field("chunk_id", I64)]
    base = ["speed_hz", "chamber_pressure_pa", "config_ay_m"]
    for a in base + [a for a in axes if a not in base]:
        fields.append(pa.field(a, F64))
    for a in axes:
        fields.append(pa.field(f"i_{a}", I32))
    for k, t in OUTPUTS[analysis].items():
        fields.append(pa.field(k, t[0] if isinstance(t, tuple) else t))
    fields += [pa.field("status", pa.dictionary(pa.int8(), STR)), pa.field("message", STR)]
    return pa.schema(fields)


def categories(analysis: str) -> dict:
    cats = {"status": STATUS}
    if analysis == "limit_cycle":
        from rotordyn.sweep.limit_cycle_rows import CYCLE_STATUS

        cats["status"] = STATUS + CYCLE_STATUS
    for k, t in OUTPUTS[analysis].items():
        if isinstance(t, tuple):
            cats[k] = t[1]
    return cats


class Job:
    """Everything a worker needs, shipped once per task (small: model TOML text, axes)."""

    def __init__(self, sweep_id, model_toml, analysis, options, axes: dict):
        self.sweep_id = sweep_id
        self.model_toml = model_toml
        self.analysis = analysis
        self.options = options
        self.axes = axes  # ordered: first outermost
        self.shape = tuple(len(x) for x in axes.values())
        varying = [i for i, n in enumerate(self.shape) if n > 1]
        self.line_pos = varying[-1] if varying else 0  # continuation runs along this axis
        self.key = ""     # spec hash (task names)
        self.level = 0    # refinement level (boundary)
        self.meta = {}    # provenance and units, stored in every part's schema metadata

    def point(self, pid: int):
        """(index tuple, {axis: value}) of point ``pid``."""
        idx = np.unravel_index(pid, self.shape)
        return tuple(int(i) for i in idx), {a: vals[i] for (a, vals), i in
                                            zip(self.axes.items(), idx)}


def run_chunk(job: Job, chunk_id: int, lo: int, hi: int, pids=None) -> pa.Table:
    """Rows of points [lo, hi) (or of the listed point ids ``pids``, for the adaptive
    boundary) as a table with :func:`schema`."""
    rows: list[dict] = []
    base = base_system(job.model_toml)
    variants = Variants(base, job.model_toml)
    if pids is not None:
        _boundary_rows(job, variants, chunk_id, pids, rows)
    else:
        _ANALYSIS[job.analysis](job, variants, chunk_id, lo, hi, rows)
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
                         "status": st if st in STATUS else "error", "message": msg})


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


def _threshold_rows(job, variants, chunk_id, lo, hi, rows):

    for s, e in _lines(job, lo, hi):
        threshold_line(job, variants, chunk_id, s, e, rows)


def _unbalance_rows(job, variants, chunk_id, lo, hi, rows):

    for s, e in _lines(job, lo, hi):
        unbalance_line(job, variants, chunk_id, s, e, rows)


def _boundary_rows(job, variants, chunk_id, pids, rows):
    """One row per listed point: max Re λ (rotor modes only with exclude_sleeve_modes), its
    frequency, point_stable; ``level`` is set by the driver."""

    excl = bool(job.options.get("exclude_sleeve_modes", False))
    r_prev = None
    for row, p, asm, opts, line, err in points(job, variants, chunk_id, 0, 0, pids):
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        try:
            y, fr, st, r = max_real(job, asm, p, r_prev if line else None, opts, excl)
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            rows.append(fail_row(row, "error", f"{type(exc).__name__}: {exc}"))
            r_prev = None
            continue
        r_prev = r
        if r is None:
            rows.append(fail_row(row, st if st in STATUS else "error", "no equilibrium"))
            continue
        rows.append({**row, "max_real_1_per_s": y, "freq_hz": fr, "point_stable": y < 0,
                     "level": job.level, "status": st, "message": ""})


_ANALYSIS = {"equilibrium": _eq_rows, "thermal": _thermal_rows, "stability": _stab_rows,
             "campbell": _stab_rows,
             "waterfall": _wf_rows, "threshold": _threshold_rows,
             "unbalance": _unbalance_rows, "run-up": _runup_rows, "robust": robust_rows}


def _hopf_rows(job, variants, chunk_id, lo, hi, rows):
    from rotordyn.sweep.hopf_rows import hopf_line

    for s, e in _lines(job, lo, hi):
        hopf_line(job, variants, chunk_id, s, e, rows)


_ANALYSIS["hopf"] = _hopf_rows


def _limit_cycle_rows(job, variants, chunk_id, lo, hi, rows):
    from rotordyn.sweep.limit_cycle_rows import limit_cycle_line

    for s, e in _lines(job, lo, hi):
        limit_cycle_line(job, variants, chunk_id, s, e, rows)


_ANALYSIS["limit_cycle"] = _limit_cycle_rows


def to_table(job: Job, rows: list[dict]) -> pa.Table:
    """Rows (dicts) to the fixed schema: missing values are nulls, categoricals use the fixed
    category lists so every part has the same dictionary."""
    sch = schema(job.analysis, list(job.axes))
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
