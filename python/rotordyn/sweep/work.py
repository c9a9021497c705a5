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

from rotordyn._common import validate as v
from rotordyn.analysis.thermal import system_thermal_equilibrium
from rotordyn.analysis.transient import transient
from rotordyn.operation import SpeedProfile
from rotordyn.sweep.blocks import boundary_blocks, eq_blocks, stab_blocks
from rotordyn.sweep.columns import block_table, identity
from rotordyn.sweep.lines import threshold_line, unbalance_line
from rotordyn.errors import RotordynError
from rotordyn.sweep.points import (CONVERGED, STATUS, Variants, base_system, fail_row, operating,
                                   points, ref_bearing, solve_equilibrium)
from rotordyn.sweep.robust_rows import outputs as robust_outputs, robust_rows

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


# a stability / Campbell / unbalance sweep with ``options.thermal`` (:mod:`.thermal_rows`):
# the point's thermal outputs, per film (lists in the order of ``film``) and summarised
THERMAL_OUTPUTS = {"film": pa.list_(STR), "film_effective_temperature_c": pa.list_(F64),
                   "film_max_temperature_c": pa.list_(F64), "film_power_loss_w": pa.list_(F64),
                   "max_temperature_c": F64, "power_loss_w": F64, "thermal_iterations": I64}
THERMAL_ANALYSES = ("stability", "campbell", "unbalance")


def thermal_on(job) -> bool:
    return job.analysis in THERMAL_ANALYSES and job.options.get("thermal") is not None


def schema(analysis: str, axes: list[str], thermal: bool = False) -> pa.Schema:
    """The fixed arrow schema of a sweep's rows (every chunk is cast to it); ``thermal``:
    with the thermal outputs of ``options.thermal``."""
    fields = [pa.field("sweep_id", pa.dictionary(pa.int8(), STR)),
              pa.field("point_id", I64), pa.field("chunk_id", I64)]
    base = ["speed_hz", "chamber_pressure_pa", "config_ay_m"]
    for a in base + [a for a in axes if a not in base]:
        fields.append(pa.field(a, F64))
    for a in axes:
        fields.append(pa.field(f"i_{a}", I32))
    for k, t in OUTPUTS[analysis].items():
        fields.append(pa.field(k, t[0] if isinstance(t, tuple) else t))
    if thermal:
        fields += [pa.field(k, t) for k, t in THERMAL_OUTPUTS.items()]
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
        self.starts = {}  # point_id -> starting equilibrium (a boundary surface's level)
        self.return_equilibria = False  # boundary chunks: the equilibria in the metadata
        self.meta = {}    # provenance and units, stored in every part's schema metadata

    def point(self, pid: int):
        """(index tuple, {axis: value}) of point ``pid``."""
        idx = np.unravel_index(pid, self.shape)
        return tuple(int(i) for i in idx), {a: vals[i] for (a, vals), i in
                                            zip(self.axes.items(), idx)}


EQUILIBRIA = b"rotordyn:equilibria"  # schema metadata of a boundary chunk (not stored)


def pack_equilibria(R) -> bytes:
    R = np.ascontiguousarray(R, dtype="<f8")
    return np.array(R.shape, dtype="<i8").tobytes() + R.tobytes()


def pop_equilibria(table: pa.Table):
    """(table without the equilibria, (n_pts, n) equilibria or None)."""
    md = dict(table.schema.metadata or {})
    raw = md.pop(EQUILIBRIA, None)
    if raw is None:
        return table, None
    shape = tuple(np.frombuffer(raw[:16], dtype="<i8"))
    R = np.frombuffer(raw[16:], dtype="<f8").reshape(shape)
    return table.replace_schema_metadata(md or None), R


def run_chunk(job: Job, chunk_id: int, lo: int, hi: int, pids=None) -> pa.Table:
    """Rows of points [lo, hi) (or of the listed point ids ``pids``, for the adaptive
    boundary) as a table with :func:`schema`."""
    base = base_system(job.model_toml)
    variants = Variants(base, job.model_toml)
    if pids is None and thermal_on(job):  # each point at its own thermal equilibrium
        from rotordyn.sweep import thermal_rows

        rows: list[dict] = []
        (thermal_rows.unbalance_rows if job.analysis == "unbalance" else
         thermal_rows.stab_rows)(job, variants, chunk_id, lo, hi, rows)
        return to_table(job, rows)
    if pids is not None or job.analysis in _BLOCKS:
        pl = list(range(lo, hi)) if pids is None else list(pids)
        asms: list = [None] * len(pl)
        eqs: list = []
        if pids is not None:
            blocks = boundary_blocks(job, variants, chunk_id, pl, asms,
                                     equilibria=eqs if job.return_equilibria else None)
        else:
            blocks = _BLOCKS[job.analysis](job, variants, chunk_id, pl, asms)
        t = block_table(job, schema(job.analysis, list(job.axes)), categories(job.analysis),
                        identity(job, chunk_id, pl, asms), blocks)
        if eqs:  # the points' equilibria, for the next refinement level's starts
            t = t.replace_schema_metadata({**(t.schema.metadata or {}),
                                           EQUILIBRIA: pack_equilibria(eqs[0])})
        return t
    rows: list[dict] = []
    _ANALYSIS[job.analysis](job, variants, chunk_id, lo, hi, rows)
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


_ANALYSIS = {"thermal": _thermal_rows, "waterfall": _wf_rows, "run-up": _runup_rows,
             "robust": robust_rows}


def _threshold_blocks(job, variants, chunk_id, pids, asms):
    lo = pids[0] if len(pids) else 0
    return [b for s, e in _lines(job, lo, lo + len(pids))
            for b in threshold_line(job, variants, s, e, s - lo, asms)]


def _unbalance_blocks(job, variants, chunk_id, pids, asms):
    lo = pids[0] if len(pids) else 0
    return [b for s, e in _lines(job, lo, lo + len(pids))
            for b in unbalance_line(job, variants, s, e, s - lo, asms)]


# Analyses whose chunk is built as columnar blocks (:mod:`.columns`, :mod:`.blocks`).
_BLOCKS = {"equilibrium": eq_blocks, "stability": stab_blocks, "campbell": stab_blocks,
           "threshold": _threshold_blocks, "unbalance": _unbalance_blocks}


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
    sch = schema(job.analysis, list(job.axes), thermal_on(job))
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
