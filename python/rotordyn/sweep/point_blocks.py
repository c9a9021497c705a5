"""Thermal, waterfall and run-up chunks as columnar blocks (issue 22): the work of a point is
one C++ call the core has no batch of (``thermal_system_equilibrium``: the effective-
temperature fixed point; ``integrate``: a transient of tens of revolutions), so the chunk
loops over its points; the cold equilibria the transients start from are one
``equilibrium_batch`` call per run of points on one model (:func:`_cold_starts`). Each point's
outputs become whole arrays (one block per point: its bearings, its spectrum lines, its
revolutions), joined into one block per run of points (:func:`rotordyn.sweep.columns.merge`)
with no dict per row.

The rows are those of the former dict-per-row loops (same calls, same values, same order):
tests/test_sweep_columns_points.py.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.analysis.thermal import system_thermal_equilibrium
from rotordyn.analysis.transient import transient
from rotordyn.errors import RotordynError
from rotordyn.operation import SpeedProfile
from rotordyn.results.thermal import WALL_COLUMNS
from rotordyn.sweep.columns import merge
from rotordyn.sweep.tilt_rows import THERMAL_TILT_OUTPUTS
from rotordyn.sweep.points import (CONVERGED, STATUS, equilibrium_options, operating,
                                   point_list, ref_bearing, segments, solve_equilibrium)
from rotordyn.units import hz_to_rad_s

THERMAL_COLUMNS = ("effective_temperature_c", "max_temperature_c", "inlet_temperature_c",
                   "temperature_rise_k", "viscosity_pa_s", "power_loss_w", "film_flow_m3_s",
                   "side_flow_m3_s", "supply_flow_m3_s",
                   # the carry-over the mixing used: λ, or (Q − Q_f)/Q_r where a metered
                   # supply fell short of the demand
                   "carry_over_effective", "journal_x_m", "journal_y_m",
                   # the THD films' walls (NaN for the effective model)
                   "journal_temperature_c", "max_wall_temperature_c", "heat_to_journal_w",
                   "heat_to_bush_w",
                   # the minimum film at the thermal equilibrium and its axial position
                   "h_min_m", "h_min_z_m")
_CATCH = (RotordynError, ArithmeticError, ValueError)


def _fail(k, status, message):
    return (np.array([k]), {"status": status, "message": message})


def _status(s):
    return s if s in STATUS else "error"


def thermal_blocks(job, variants, chunk_id, pids, asms):
    """Effective-temperature system equilibria (the model's ``[thermal]``, every field of
    which is an axis: ``thermal.supply_temperature_c``, ``thermal.oil.nu1_mm2_s``,
    ``thermal.films.<bearing>.carry_over``...), one row per plain journal bearing; each
    point starts cold (same answer as a direct call)."""
    blocks = []
    for k, (p, asm, opts, _, err) in enumerate(point_list(job, variants, pids, asms)):
        if err:
            blocks.append(_fail(k, "error", err))
            continue
        try:
            f, pc, _ = operating(asm, p)
            r = system_thermal_equilibrium(asm.system, speed_hz=f, chamber_pressure_pa=pc,
                                           tol_k=opts.get("tol_k", 1e-6))
        except _CATCH as exc:
            blocks.append(_fail(k, "error", str(exc)))
            continue
        nb = len(r.bearing_names)
        ok = r.status in CONVERGED
        cols = {c: (np.asarray(r.wall(c) if c in WALL_COLUMNS or c.startswith("h_min")
                               or c == "carry_over_effective"
                               else getattr(r, c),
                               dtype=np.float64)[:nb] if ok
                    else np.full(nb, math.nan)) for c in THERMAL_COLUMNS}
        if r.tilt is not None:  # a tilting model: its films' rotations and moments (NaN
            # for an untilted film; the result's NaN where the equilibrium failed)
            cols.update({c: np.asarray(r.tilt[c], dtype=np.float64)[:nb] if ok
                         else np.full(nb, math.nan) for c in THERMAL_TILT_OUTPUTS})
        cols.update(bearing=np.array(list(r.bearing_names), dtype=object),
                    iterations=int(r.iterations), status=_status(r.status), message=r.message)
        blocks.append((np.full(nb, k, dtype=np.int64), cols))
    return merge(blocks)


def _start(asm, f, pc, a, e=None):
    """The cold-started equilibrium a transient point starts from (not the thread's last
    one: the rows must not depend on what ran before), or (status, message); ``e``: that
    equilibrium already solved (:func:`_cold_starts`)."""
    if e is None:
        e = solve_equilibrium(asm, f, pc, a, None, {})
    if e.status not in CONVERGED:
        return (_status(e.status), f"no equilibrium to start from: {e.message}")
    return np.asarray(e.r)


class _Eq:
    """One point of an ``EquilibriumBatchResult`` (what :func:`_start` reads)."""

    __slots__ = ("status", "message", "r")

    def __init__(self, status, message, r):
        self.status, self.message, self.r = status, message, r


def _cold_starts(items, op):
    """The cold equilibria of a chunk's transient points as one ``equilibrium_batch`` per run
    of points on one model (every point restarted: the same solves as one
    ``solver.equilibrium`` call each with no start). ``op(asm, p, opts)`` gives (f, pc, a) or
    raises; such points, and those the batch reports ``error`` for (a solve that raised:
    the per-point path words its message), are left out and solved per point as before.
    Returns {point index: _Eq}."""
    errs = [it[4] for it in items]
    ops = [None] * len(items)
    for k, it in enumerate(items):
        if not errs[k]:
            try:
                ops[k] = op(it[1], it[0], it[2])
            except _CATCH:
                errs[k] = "refused"
    out = {}
    for i, j, good in segments(items, errs):
        if not good:
            continue
        o = ops[i:j]
        res = _core.equilibrium_batch(
            items[i][1].solver, np.array([hz_to_rad_s(x[0]) for x in o]),
            np.array([x[1] for x in o]), np.array([x[2] for x in o]), [1] * (j - i),
            equilibrium_options({}))
        R = np.asarray(res.r)
        for q in range(j - i):
            if res.status[q] != "error":
                out[i + q] = _Eq(res.status[q], res.message[q], R[q])
    return out


def _transients(items, op, integrate, blocks):
    """The transient of each point of ``items`` (:func:`point_list`) from its cold
    equilibrium (:func:`_cold_starts`): ``op(asm, p, opts)`` gives (f, pc, a) at the start,
    ``integrate(asm, p, opts, f, pc, r0)`` runs the transient. Yields (k, asm, opts, f, tr)
    per point that ran; a point that could not start or raised is a failed row appended to
    ``blocks``."""
    eqs = _cold_starts(items, op)
    for k, (p, asm, opts, _, err) in enumerate(items):
        if err:
            blocks.append(_fail(k, "error", err))
            continue
        try:
            f, pc, a = op(asm, p, opts)
            r0 = _start(asm, f, pc, a, eqs.get(k))
            if isinstance(r0, tuple):
                blocks.append(_fail(k, *r0))
                continue
            tr = integrate(asm, p, opts, f, pc, r0)
        except _CATCH as exc:
            blocks.append(_fail(k, "error", f"{type(exc).__name__}: {exc}"))
            continue
        yield k, asm, opts, f, tr


def waterfall_blocks(job, variants, chunk_id, pids, asms):
    """A transient per point (cold equilibrium, then ``revolutions`` revolutions with the
    unbalances) and the amplitude spectra of x and y over its second half: one row per
    spectral line up to ``max_frequency_hz`` (else ``max_harmonic`` × speed)."""
    blocks = []

    def op(asm, p, opts):
        f, pc, a = operating(asm, p)
        v.positive("speed_hz", f)
        return f, pc, a

    def integrate(asm, p, opts, f, pc, r0):
        revs = int(opts.get("revolutions", 60))
        spr = int(opts.get("samples_per_revolution", 64))
        ub = [tuple(u) for u in opts.get("unbalances", [])]
        return transient(asm.system, revs / f, f, pc, p.get("config_ay_m"), r0=r0,
                         unbalances=ub, n_out=revs * spr + 1,
                         rtol=float(opts.get("rtol", 1e-6)),
                         rub_fraction=float(opts.get("rub_fraction", 1e-3)),
                         bdf_max_order=int(opts.get("bdf_max_order", 5)))

    for k, asm, opts, f, tr in _transients(point_list(job, variants, pids, asms), op,
                                           integrate, blocks):
        if tr.status not in CONVERGED:  # "contact": integrated from a contact equilibrium
            blocks.append(_fail(k, _status(tr.status), tr.message))
            continue
        bc = ref_bearing(asm, job.options.get("bearing"))
        j = bc.index if bc else 0  # the journal of the row's journal_bearing
        freq, ax = tr.spectrum(j, last_fraction=0.5, axis="x")
        _, ay_ = tr.spectrum(j, last_fraction=0.5, axis="y")
        # max_frequency_hz: every speed's spectrum over the same span (a waterfall's traces
        # then line up); else up to max_harmonic × speed
        fmax = opts.get("max_frequency_hz")
        keep = freq <= (float(fmax) if fmax is not None
                        else float(opts.get("max_harmonic", 4.0)) * f)
        fr = np.asarray(freq[keep], dtype=np.float64)
        blocks.append((np.full(fr.size, k, dtype=np.int64), {
            "freq_hz": fr, "amplitude_x_m": np.asarray(ax[keep], dtype=np.float64),
            "amplitude_y_m": np.asarray(ay_[keep], dtype=np.float64), "order": fr / f,
            "status": tr.status, "message": tr.message}))
    return merge(blocks)


def _per_revolution(rev, revs_reached, sp, t, x, y, h):
    """Columns of the revolutions ``revs_reached`` with at least two samples: mean speed and
    time, half peak-to-peak x and y, smallest film (the samples of each revolution are one
    slice when ``rev`` is sorted, as it is for a positive speed; else a mask)."""
    out = {n: [] for n in ("revolution", "speed_hz", "time_s", "amplitude_x_m",
                           "amplitude_y_m", "h_min_m")}
    srt = bool(np.all(rev[1:] >= rev[:-1]))
    for n_rev in revs_reached:
        if srt:
            m = slice(int(np.searchsorted(rev, n_rev, "left")),
                      int(np.searchsorted(rev, n_rev, "right")))
            cnt = m.stop - m.start
        else:
            m = rev == n_rev
            cnt = int(m.sum())
        if cnt < 2:
            continue
        out["revolution"].append(int(n_rev))
        out["speed_hz"].append(float(sp[m].mean()))
        out["time_s"].append(float(t[m].mean()))
        out["amplitude_x_m"].append(float(np.ptp(x[m]) / 2))
        out["amplitude_y_m"].append(float(np.ptp(y[m]) / 2))
        out["h_min_m"].append(float(h[m].min()))
    return {n: np.asarray(c, dtype=np.int64 if n == "revolution" else np.float64)
            for n, c in out.items()}


def runup_blocks(job, variants, chunk_id, pids, asms):
    """A nonlinear run-up (or coast-down) per point: Ω(t) ramps from start_hz to stop_hz at
    rate_hz_per_s (rotordyn.control.SpeedProfile); one row per revolution with its mean
    speed (in ``speed_hz``), the half peak-to-peak journal motion of the active (or first)
    bearing and the smallest film over that revolution."""
    blocks = []

    def op(asm, p, opts):
        return operating(asm, {**p, "speed_hz": opts["start_hz"]})

    def integrate(asm, p, opts, f0, pc, r0):
        f1, rate = opts["stop_hz"], opts["rate_hz_per_s"]
        T = abs(f1 - f0) / rate
        spr = int(opts.get("samples_per_revolution", 32))
        revs = (f0 + f1) / 2 * T
        return transient(asm.system, T, chamber_pressure_pa=pc,
                         config_ay_m=p.get("config_ay_m"),
                         speed=SpeedProfile.ramp(f0, f1, rate), r0=r0,
                         unbalances=[tuple(u) for u in opts["unbalances"]],
                         n_out=int(revs * spr) + 1, rtol=float(opts.get("rtol", 1e-6)),
                         rub_fraction=float(opts.get("rub_fraction", 1e-3)),
                         bdf_max_order=int(opts.get("bdf_max_order", 5)))

    for k, asm, opts, _, tr in _transients(point_list(job, variants, pids, asms), op,
                                           integrate, blocks):
        bc = ref_bearing(asm, job.options.get("bearing"))
        j = bc.index if bc else 0
        # the rows reached (a failed run, e.g. "rub", leaves NaN rows after it stopped)
        done = np.isfinite(np.asarray(tr.angle_rad)) & np.all(np.isfinite(tr.r), axis=1)
        rev = np.floor(np.asarray(tr.angle_rad)[done] / (2 * np.pi)).astype(np.int64)
        revs_reached = np.unique(rev)
        if tr.status not in CONVERGED and revs_reached.size:
            revs_reached = revs_reached[:-1]  # a stopped run's last revolution is partial
        cols = _per_revolution(rev, revs_reached, np.asarray(tr.speed_hz_t)[done],
                               np.asarray(tr.t)[done], np.asarray(tr.journal_x_m)[done, j],
                               np.asarray(tr.journal_y_m)[done, j],
                               np.asarray(tr.h_min_m)[done, j])
        m = cols["revolution"].size
        if m:
            cols.update(status=_status(tr.status), message=tr.message)
            blocks.append((np.full(m, k, dtype=np.int64), cols))
        elif tr.status != "ok":  # stopped before one whole revolution
            blocks.append(_fail(k, _status(tr.status), tr.message))
    return merge(blocks)
