"""Adaptive stability boundary (paper Fig. 9/10 at the resolution of a fine grid for a few
percent of its points).

The fine grid has ``resolution`` points per axis over the range of the spec's two axes ``x``,
``y``; the coarse grid (the spec's values, each on its nearest fine node, so any resolution
fits) is evaluated first (max Re λ at each point). A cell whose four corners do not all share
one state (stable, unstable, failed) holds the boundary: it is split at its middle fine node
along each axis where it is wider than one fine step (halves differ by one step when the width
is odd), and the new corners are evaluated; this repeats until the mixed cells are one fine
step wide (:class:`Refinement`). The boundary is the zero contour, over the evaluated fine
points (linear interpolation on each cell edge), of the stability map's field
(:mod:`.boundary_modes`: the Re λ of the tracked modes that go unstable somewhere; max Re λ's
sign at every point, but the crossing mode's Re λ between points, where max Re λ of an
undamped rotor is a bystander's and its zero hugged the stable node), stored as polylines in
``_boundary.parquet``; the evaluated points' modes are the dataset's rows (one per mode as a
stability sweep's, ``mode_id`` tracked from a neighbour point), with the ``level`` that asked
for them.

With ``z`` (a third axis, e.g. speed) the boundary surface over (x, y, z) is found by
columns along y by default (``refine = "columns"``, :mod:`rotordyn.sweep.surface`: each
column's crossings certified by their two fine nodes, about two points per crossing, each
point started from its neighbours' equilibria), or with ``refine = "cells"`` by the same
refinement over boxes of eight corners; it is stored as the zero contour of every z slice of
the fine grid that holds a sign change (a ``z`` column beside ``line``, ``vertex``, ``x``,
``y``; by columns, drawn on :func:`rotordyn.sweep.surface.column_field`).

Limitation (as any marching refinement): a stable or unstable island smaller than a coarse
cell, whose corners all share one state, is not seen; choose the coarse grid accordingly.
"""

from __future__ import annotations

import itertools
import math
import os
from pathlib import Path

import numpy as np

from rotordyn.sweep.execution import (Progress, SweepInterrupted, SweepResult, executor,
                                      group_size)
from rotordyn.sweep.spec import boundary_axes, fine_axes
from rotordyn.sweep.store import BOUNDARY, Store, part_metadata, task_key
from rotordyn.sweep.boundary_modes import ModeTracks, with_ids
from rotordyn.sweep.surface import ColumnPlan, column_field
from rotordyn.sweep.points import base_system
from rotordyn.sweep.work import Job, job_schema, pop_equilibria


def _classify(table) -> dict[int, tuple[int, float, float]]:
    """point_id -> (state: 0 stable, 1 unstable, 2 failed; max Re λ; its frequency), from
    each point's first row (its mode rows share them)."""
    pid = table.column("point_id").to_numpy()
    first = np.r_[0, np.flatnonzero(np.diff(pid)) + 1] if len(pid) else np.zeros(0, int)
    st = table.column("status").cast("string").to_numpy(zero_copy_only=False)[first]
    y = table.column("max_real_1_per_s").to_numpy(zero_copy_only=False)[first]
    fr = table.column("max_real_freq_hz").to_numpy(zero_copy_only=False)[first]
    ps = table.column("point_stable").to_numpy(zero_copy_only=False)[first]
    out = {}
    for p, s, v, f, good in zip(pid[first], st, y, fr, ps):
        ok = s in ("ok", "contact") and v is not None and math.isfinite(v)
        # the row's verdict (round-off band included), not max Re λ's raw sign
        out[int(p)] = ((0 if good else 1) if ok else 2, float(v) if ok else math.nan,
                       float(f) if ok else math.nan)
    return out


def _halves(a: int, b: int) -> tuple[tuple[int, int], ...]:
    """The fine-index interval [a, b] split at its middle node, or itself if one step wide."""
    if b - a <= 1:
        return ((a, b),)
    m = (a + b) // 2
    return ((a, m), (m, b))


class Refinement:
    """The refinement's plan in fine indices, independent of how points are evaluated, in
    two or three dimensions (a boundary curve or surface).

    ``points`` holds the fine nodes (index tuples) the current ``level`` needs (some may be
    known already); :meth:`advance` takes the states of all nodes evaluated so far (mapping
    index tuple -> 0 stable, 1 unstable, 2 failed) and moves to the next level. A cell is a
    tuple of (lo, hi) fine-index intervals, one per axis, of any widths."""

    def __init__(self, *nodes):
        grids = [sorted(n) for n in nodes]
        self.cells = list(itertools.product(*[list(zip(g, g[1:])) for g in grids]))
        self.points = set(itertools.product(*grids))
        self.level = 0

    def advance(self, state) -> bool:
        """Split the mixed cells; False (and no points) when none is left to split."""
        cells, pts = [], set()
        for cell in self.cells:
            if all(b - a <= 1 for a, b in cell) or len(
                    {state[c] for c in itertools.product(*cell)}) == 1:
                continue
            for sub in itertools.product(*[_halves(a, b) for a, b in cell]):
                cells.append(sub)
                pts.update(itertools.product(*sub))
        self.cells, self.points = cells, pts
        self.level += 1
        return bool(cells)


def polylines(xs, ys, z) -> list[np.ndarray]:
    """Zero contour of ``z`` (nx, ny; NaN = not evaluated) as (k, 2) polylines."""
    import contourpy

    zm = np.ma.masked_invalid(z)
    gen = contourpy.contour_generator(np.asarray(ys), np.asarray(xs), zm,
                                      line_type=contourpy.LineType.Separate)
    return [ln[:, ::-1] for ln in gen.lines(0.0) if len(ln) >= 2]


class _States:
    """(i, j) -> state view of the point_id-keyed results."""

    def __init__(self, state, pid):
        self.state, self.pid = state, pid

    def __getitem__(self, idx):
        return self.state[self.pid(*idx)][0]


def run_boundary(spec, header, model_toml, out, *, scheduler=None, workers=None, threads=None,
                 resume=True, progress=None, worker_timeout=30.0):
    import pyarrow as pa
    import pyarrow.parquet as pq

    ax, nodes = fine_axes(spec)
    refined = boundary_axes(spec)
    x, y = refined[:2]
    z = refined[2] if len(refined) == 3 else None
    shape = tuple(len(ax[a]) for a in refined)
    header = {**header, "axes": ax, "n_points": None, "n_chunks": None, "group": None}
    job = Job(spec.name, model_toml, spec.analysis, spec.options, ax)
    # a resume refuses parts of another row schema (Store._check_schemas)
    store = Store(out, header, resume=resume, group=1,
                  schema=job_schema(job, base_system(model_toml)),
                  spec_aliases=(spec.legacy_hash(),))
    job.key = task_key(header)
    job.meta = part_metadata(header)
    base = int(np.ravel_multi_index(tuple(0 for _ in ax), tuple(len(v) for v in ax.values())))

    strides = [int(np.prod(shape[d + 1:])) for d in range(len(shape))]

    def pid(*idx):
        return base + sum(i * st for i, st in zip(idx, strides))

    by_cols = spec.options.get("refine", "columns" if z is not None else "cells") == "columns"
    if by_cols:  # the surface (or curve) by columns along y: plan indices (i, j, k)
        plan = ColumnPlan(nodes[x], nodes[y], nodes[z] if z else [0],
                          shape if z else shape + (1,))
        s0, s1, s2 = (strides + [0])[:3]
        job.return_equilibria = True

        def pid3(p):  # point_id of plan index (i, j, k) (k = 0 for a curve)
            return base + p[0] * s0 + p[1] * s1 + p[2] * s2
    else:
        plan = Refinement(*[nodes[a] for a in refined])
    state: dict[int, tuple] = {}
    modes = ModeTracks(bool(spec.options.get("exclude_sleeve_modes", False)))

    def fine_index(p):
        return np.unravel_index(p - base, shape)
    eqs: dict[int, np.ndarray] = {}  # point_id -> equilibrium (columns: starts of the next)
    cid = 0
    ex = None
    bar = Progress(1, 0, {}, enabled=None if progress is None else bool(progress))
    try:
        while True:
            idxs = sorted(plan.points)
            size = spec.chunk_size
            if by_cols:  # independent points (own starts): few large chunks per level
                new = sorted(q for q in map(pid3, idxs) if q not in state)
                size = max(size, 100, min(2000, -(-len(new) // 8)))
                job.starts = {}
                for p, src in plan.source.items():
                    rs = [eqs.get(pid3(q)) for q, _ in src]
                    if src and all(r is not None for r in rs):
                        job.starts[pid3(p)] = sum(w * r for (_, w), r in zip(src, rs))
                    elif any(r is not None for r in rs):  # the nearest one solved
                        job.starts[pid3(p)] = next(r for r in rs if r is not None)
            else:
                new = sorted(q for q in (pid(*i) for i in idxs) if q not in state)
            chunks = [(cid + k, new[a:a + size])
                      for k, a in enumerate(range(0, len(new), size))]
            cid += len(chunks)
            bar.n += len(chunks)
            todo = []
            done = store.done_chunks()
            for c, pl in chunks:
                t = store.table(c) if c in done else None
                if t is not None and sorted(set(t.column("point_id").to_pylist())) == pl:
                    state.update(_classify(t))
                    modes.add_tracked(ModeTracks.rows(t), fine_index, plan.level)
                    bar.update({})
                else:
                    todo.append((c, 0, 0, pl))
            if todo:
                job.level = plan.level
                if ex is None:
                    ex = executor(scheduler, workers or min(len(todo), os.cpu_count() or 1),
                                  threads, worker_timeout, bar)
                pls = {t[0]: t[3] for t in todo}
                got = []
                for c, (table, cnt) in ex.map(job, todo):
                    table, R = pop_equilibria(table)
                    if by_cols and R is not None and R.shape[1]:
                        good = np.isfinite(R).all(axis=1)
                        eqs.update(zip(np.asarray(pls[c])[good].tolist(), R[good]))
                    got.append((c, table, cnt))
                    state.update(_classify(table))
                    bar.update(cnt)
                # the level's modes tracked from their parents (in point-id order, whatever
                # finished first), then its chunks stored with their ids
                rows = {}
                for _, table, _ in got:
                    rows.update(ModeTracks.rows(table))
                ids = modes.track(rows, fine_index, plan.level)
                for c, table, cnt in sorted(got, key=lambda g: g[0]):
                    store.add(c, with_ids(table, ids), cnt, 0)
            if by_cols:
                more = plan.advance({i: state[pid3(i)][:2] for i in idxs})
            else:
                more = plan.advance(_States(state, pid))
            if not more:
                break
    except KeyboardInterrupt:
        bar.close()
        store.close()
        raise SweepInterrupted(f"interrupted: {len(store.done_chunks())} chunks saved in "
                               f"{str(out)!r}; run the same command again to resume") from None
    finally:
        if ex is not None:
            ex.close()
    try:
        bar.close()
        store.group = group_size(cid, spec.max_files)
        store.compact_complete(cid)
        vals = np.full(shape, np.nan)
        # the map's rule (the verdict's sign at each point, strictly negative at a stable
        # one: a conservative region's Re λ = 0 is the band's lower edge, so no zero contour
        # runs through it)
        for p, v in modes.field().items():
            if state[p][0] != 2:
                vals[np.unravel_index(p - base, shape)] = v
        rows = {"line": [], "vertex": [], x: [], y: []}
        if z is not None:
            rows[z] = []
        slices = [(None, vals)] if z is None else [(k, vals[:, :, k]) for k in range(shape[2])]
        n_line = 0
        for k, zk in slices:
            fin = zk[np.isfinite(zk)]
            if z is not None and (fin.size == 0 or (fin < 0).all() or (fin >= 0).all()):
                continue  # nothing evaluated on this slice changes sign
            if by_cols:
                kk = 0 if k is None else k
                zk = column_field(plan.states[:, :, kk], plan.evaluated[:, :, kk], zk)
            for ln in polylines(ax[x], ax[y], zk):
                rows["line"] += [n_line] * len(ln)
                rows["vertex"] += list(range(len(ln)))
                rows[x] += ln[:, 0].tolist()
                rows[y] += ln[:, 1].tolist()
                if z is not None:
                    rows[z] += [ax[z][k]] * len(ln)
                n_line += 1
        t = pa.table({"line": pa.array(rows["line"], pa.int64()),
                      "vertex": pa.array(rows["vertex"], pa.int64()),
                      **{a: pa.array(rows[a], pa.float64()) for a in refined}})
        buf = pa.BufferOutputStream()
        pq.write_table(t, buf)
        store.add_aux(BOUNDARY, buf.getvalue().to_pybytes())
        entries = store.chunk_entries()
        counts = {k: sum(c.get(k, 0) for c in entries.values())
                  for k in ("ok", "failed", "unstable")}
        man = {**header, "n_chunks": cid, "n_points": len(state),
               "fine_points": int(np.prod(shape))}
        if by_cols:  # the points this run asked for, by reason (resumed chunks included)
            man["points_by_reason"] = dict(plan.stats)
        return SweepResult(Path(out), man, len(entries), cid, counts, tuple(store.dropped))
    finally:
        store.close()
