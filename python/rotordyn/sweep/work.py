"""What one chunk of a sweep does (inside a worker): the points [lo, hi) of the grid, computed
in order from a fresh solver state, into one pyarrow table with the analysis's fixed schema.

Determinism: a chunk builds its own :class:`Assembled` (no thread cache, no warm state from an
earlier chunk), starts its first equilibrium cold and continues only along a line (points that
differ in the innermost axis alone), so a chunk's rows are the same bit for bit whichever
worker, thread or resume computes it. A point that fails (bad value, no equilibrium, contact,
solver error) is a row with ``status``/``message``; the chunk goes on.
"""

from __future__ import annotations

import numpy as np
import pyarrow as pa

from rotordyn.sweep.blocks import boundary_blocks, eq_blocks, stab_blocks
from rotordyn.sweep.columns import block_table, identity
from rotordyn.sweep.hopf_rows import hopf_line_blocks
from rotordyn.sweep.lines import threshold_line, unbalance_line
from rotordyn.sweep.point_blocks import runup_blocks, thermal_blocks, waterfall_blocks
from rotordyn.sweep.points import STATUS, Variants, base_system
from rotordyn.sweep.robust_rows import outputs as robust_outputs, robust_blocks
from rotordyn.sweep.thermal_rows import (stab_blocks as thermal_stab_blocks,
                                         unbalance_blocks as thermal_unbalance_blocks)
from rotordyn.sweep.tilt_rows import THERMAL_TILT_OUTPUTS, TILT_OUTPUTS, tilt_on


WHIRL = ["forward", "backward", "planar"]
KIND = ["rotor", "sleeve", "pad"]
F64, I64, I32, BOOL, STR = pa.float64(), pa.int64(), pa.int32(), pa.bool_(), pa.string()


def _cat(values):
    return pa.dictionary(pa.int8(), pa.string()), values


# Output columns (after the ids and axes) per analysis: name -> arrow type (or a
# (dictionary type, categories) pair for categoricals).
OUTPUTS = {
    "equilibrium": {"bearing": STR, "journal_x_m": F64, "journal_y_m": F64, "x_over_c": F64,
                    "y_over_c": F64, "h_min_m": F64, "iterations": I64, "residual": F64,
                    # tilting films (tilt = true; NaN elsewhere): the journal's rotations
                    # relative to the housing, the axial position of the minimum film and
                    # the films' moments on the journal
                    "journal_theta_x_rad": F64, "journal_theta_y_rad": F64, "h_min_z_m": F64,
                    "film_moment_x_n_m": F64, "film_moment_y_n_m": F64},
    "thermal": {"bearing": STR, "effective_temperature_c": F64, "max_temperature_c": F64,
                "inlet_temperature_c": F64, "temperature_rise_k": F64, "viscosity_pa_s": F64,
                "power_loss_w": F64, "film_flow_m3_s": F64, "side_flow_m3_s": F64,
                "supply_flow_m3_s": F64, "carry_over_effective": F64, "journal_x_m": F64,
                "journal_y_m": F64, "journal_temperature_c": F64, "max_wall_temperature_c": F64,
                "heat_to_journal_w": F64, "heat_to_bush_w": F64, "h_min_m": F64,
                "h_min_z_m": F64, "iterations": I64},
    "stability": {"mode_id": I64, "mode": I64, "freq_hz": F64, "eig_real_1_per_s": F64,
                  "damping_ratio": F64, "log_dec": F64, "whirl": _cat(WHIRL),
                  "kind": _cat(KIND), "mode_stable": BOOL, "point_stable": BOOL,
                  "max_real_1_per_s": F64, "journal_x_m": F64, "journal_y_m": F64,
                  "h_min_m": F64, "iterations": I64},
    "threshold": {"crossing": I64, "value": F64, "whirl_frequency_hz": F64,
                  "whirl_ratio": F64, "stable_side": STR, "evaluations": I64},
    # one row per mode as a stability sweep's (mode_id tracked from a neighbour point), with
    # the frequency of max Re λ's mode and the refinement level that asked for the point
    "boundary": {"mode_id": I64, "mode": I64, "freq_hz": F64, "eig_real_1_per_s": F64,
                 "damping_ratio": F64, "log_dec": F64, "whirl": _cat(WHIRL),
                 "kind": _cat(KIND), "mode_stable": BOOL, "point_stable": BOOL,
                 "max_real_1_per_s": F64, "max_real_freq_hz": F64, "level": I64},
    "unbalance": {"station": I64, "amplitude_x_m": F64, "amplitude_y_m": F64,
                  "phase_x_deg": F64, "phase_y_deg": F64, "major_m": F64, "minor_m": F64,
                  "peak": BOOL, "critical_speed_hz": F64, "amplification_factor": F64,
                  "separation_margin_pct": F64, "point_stable": BOOL},
    "waterfall": {"freq_hz": F64, "order": F64, "amplitude_x_m": F64, "amplitude_y_m": F64},
    "run-up": {"revolution": I64, "time_s": F64, "amplitude_x_m": F64, "amplitude_y_m": F64,
               "h_min_m": F64},
}
OUTPUTS["campbell"] = OUTPUTS["stability"]
OUTPUTS["hopf"] = {**OUTPUTS["threshold"], "l1": F64, "l1_error": F64, "hopf_type": STR,
                   "alpha_prime": F64, "amplitude_coefficient_m2": F64,
                   "l1_refined": F64}  # options.grid_check (NaN: not checked)
OUTPUTS["robust"] = robust_outputs(F64, BOOL, _cat)
OUTPUTS["limit_cycle"] = {"record": _cat(["hopf", "cycle"]), **OUTPUTS["hopf"],
                          "cycle": I64, "bearing": STR, "amplitude_m": F64, "amplitude_c": F64,
                          "period_s": F64, "max_multiplier": F64, "critical_type": STR,
                          "stable": BOOL, "equilibrium_stable": BOOL, "max_real_1_per_s": F64,
                          "coexists_with_stable_equilibrium": BOOL, "bistable": BOOL,
                          "newton_iterations": I64, "method": STR}


# a stability / Campbell / unbalance sweep with ``options.thermal`` (:mod:`.thermal_rows`):
# the point's thermal outputs, per film (lists in the order of ``film``) and summarised
# (rotordyn.results.thermal.THERMAL_POINT_COLUMNS)
THERMAL_OUTPUTS = {"film": pa.list_(STR), "film_effective_temperature_c": pa.list_(F64),
                   "film_max_temperature_c": pa.list_(F64), "film_power_loss_w": pa.list_(F64),
                   "max_temperature_c": F64, "power_loss_w": F64, "thermal_iterations": I64}
THERMAL_ANALYSES = ("stability", "campbell", "unbalance")


def thermal_on(job) -> bool:
    """Whether ``job`` runs each point at its own thermal equilibrium (``options.thermal``)."""
    return job.analysis in THERMAL_ANALYSES and job.options.get("thermal") is not None


def schema(analysis: str, axes: list[str], thermal: bool = False,
           tilt: bool = False) -> pa.Schema:
    """The fixed arrow schema of a sweep's rows (every chunk is cast to it); ``thermal``:
    with the thermal outputs of ``options.thermal``; ``tilt``: with the tilting films'
    per-bearing list columns (:mod:`.tilt_rows`; the thermal analysis's rows, one per film:
    its bearing's rotations and moments, flat)."""
    fields = [pa.field("sweep_id", pa.dictionary(pa.int8(), STR)),
              pa.field("point_id", I64), pa.field("chunk_id", I64)]
    base = ["speed_hz", "chamber_pressure_pa", "config_ay_m"]
    for a in base + [a for a in axes if a not in base]:
        fields.append(pa.field(a, F64))
    for a in axes:
        fields.append(pa.field(f"i_{a}", I32))
    if "bearing" not in OUTPUTS[analysis]:  # rows of one bearing each name it there
        # the bearing whose journal the rows' journal_*/config_ay_m columns describe
        fields.append(pa.field("journal_bearing", STR))
    for k, t in OUTPUTS[analysis].items():
        fields.append(pa.field(k, t[0] if isinstance(t, tuple) else t))
    if thermal:
        fields += [pa.field(k, t) for k, t in THERMAL_OUTPUTS.items()]
    if tilt:
        fields += [pa.field(k, t) for k, t in (THERMAL_TILT_OUTPUTS if analysis == "thermal"
                                               else TILT_OUTPUTS).items()]
    fields += [pa.field("status", pa.dictionary(pa.int8(), STR)), pa.field("message", STR)]
    return pa.schema(fields)


def job_schema(job, base) -> pa.Schema:
    """The rows' schema of ``job`` on the model ``base`` (the chunks' and what a resume
    expects of the parts already written, :class:`rotordyn.sweep.store.Store`)."""
    return schema(job.analysis, list(job.axes), thermal_on(job), tilt_on(job, base))


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
    pl = list(range(lo, hi)) if pids is None else list(pids)
    asms: list = [None] * len(pl)
    eqs: list = []
    if pids is not None:
        blocks = boundary_blocks(job, variants, chunk_id, pl, asms,
                                 equilibria=eqs if job.return_equilibria else None)
    elif thermal_on(job):  # each point at its own thermal equilibrium
        blocks = (thermal_unbalance_blocks if job.analysis == "unbalance" else
                  thermal_stab_blocks)(job, variants, chunk_id, pl, asms)
    else:
        blocks = _BLOCKS[job.analysis](job, variants, chunk_id, pl, asms)
    t = block_table(job, job_schema(job, base), categories(job.analysis),
                    identity(job, chunk_id, pl, asms), blocks)
    if eqs:  # the points' equilibria, for the next refinement level's starts
        t = t.replace_schema_metadata({**(t.schema.metadata or {}),
                                       EQUILIBRIA: pack_equilibria(eqs[0])})
    return t


def _lines(job, lo, hi):
    """Split [lo, hi) into lines of the innermost axis."""
    n = job.shape[-1]
    for s in range(lo, hi, n):
        yield s, min(s + n, hi)


def _threshold_blocks(job, variants, chunk_id, pids, asms):
    lo = pids[0] if len(pids) else 0
    return [b for s, e in _lines(job, lo, lo + len(pids))
            for b in threshold_line(job, variants, s, e, s - lo, asms)]


def _unbalance_blocks(job, variants, chunk_id, pids, asms):
    lo = pids[0] if len(pids) else 0
    return [b for s, e in _lines(job, lo, lo + len(pids))
            for b in unbalance_line(job, variants, s, e, s - lo, asms)]


def _hopf_blocks(job, variants, chunk_id, pids, asms):
    lo = pids[0] if len(pids) else 0
    return [b for s, e in _lines(job, lo, lo + len(pids))
            for b in hopf_line_blocks(job, variants, s, e, s - lo, asms)]


# Every analysis's chunk as columnar blocks (:mod:`.columns`; docs/sweeps.md, the audit).
_BLOCKS = {"equilibrium": eq_blocks, "stability": stab_blocks, "campbell": stab_blocks,
           "threshold": _threshold_blocks, "unbalance": _unbalance_blocks,
           "hopf": _hopf_blocks, "thermal": thermal_blocks, "waterfall": waterfall_blocks,
           "run-up": runup_blocks, "robust": robust_blocks}


def _limit_cycle_blocks(job, variants, chunk_id, pids, asms):
    from rotordyn.sweep.limit_cycle_rows import limit_cycle_line

    lo = pids[0] if len(pids) else 0
    return [b for s, e in _lines(job, lo, lo + len(pids))
            for b in limit_cycle_line(job, variants, s, e, s - lo, asms)]


_BLOCKS["limit_cycle"] = _limit_cycle_blocks
