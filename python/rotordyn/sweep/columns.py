"""A chunk's rows as one columnar block (issue 22): the identity and axis columns of the
chunk's points computed at once (numpy), the analysis's outputs as whole arrays per run of
points, and one arrow table built from them, with no dict per row.

A block is ``(pt, cols)``: ``pt`` the chunk-local index of each of its rows' point (int array,
length m), ``cols`` output name -> array of length m or one scalar for every row; a name
absent from ``cols`` takes the point's identity value (:func:`identity`) or is null. The
table is the one the former per-row dicts gave, value for value (their code is kept as the
tests' reference, tests/sweep_rows_reference.py; tests/test_sweep_columns*.py).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pyarrow as pa

from rotordyn.sweep import points as pt_

_NP = {pa.float64(): np.float64, pa.int64(): np.int64, pa.int32(): np.int32,
       pa.bool_(): np.bool_}


def identity(job, chunk_id: int, pids, asms) -> dict:
    """Per point of the chunk (``pids``, their models ``asms``, None for a failed variant):
    ``point_id``, ``chunk_id``, each axis's value and index ``i_<axis>``, and the defaults
    (50 Hz, 0 Pa, the reference bearing's a_y) the former per-row ``common_row`` set."""
    pids = np.asarray(pids, dtype=np.int64)
    n = len(pids)
    idx = np.unravel_index(pids, job.shape) if n else [np.zeros(0, np.int64)] * len(job.shape)
    cols = {"point_id": pids, "chunk_id": np.full(n, chunk_id, np.int64)}
    for (a, vals), i in zip(job.axes.items(), idx):
        cols[f"i_{a}"] = np.asarray(i, dtype=np.int32)
        cols[a] = np.asarray(vals, dtype=np.float64)[i]
    if "speed_hz" not in cols:
        cols["speed_hz"] = np.full(n, 50.0)
    if "chamber_pressure_pa" not in cols:
        cols["chamber_pressure_pa"] = np.zeros(n)
    # the bearing whose journal the rows describe (journal_x_m, ..., and config_ay_m when it
    # is not an axis): options.bearing, else the active bearing, else the first
    ay, names, seen = np.full(n, math.nan), np.full(n, None, dtype=object), {}
    for k, asm in enumerate(asms):
        if asm is None:
            continue
        got = seen.get(id(asm))
        if got is None:
            bc = pt_.ref_bearing(asm, job.options.get("bearing"))
            got = seen[id(asm)] = ((pt_.job_model_ay(asm, bc),
                                    getattr(asm.system.bearings[bc.index], "name", None))
                                   if bc is not None else (math.nan, None))
        ay[k], names[k] = got
    if "config_ay_m" not in cols:
        cols["config_ay_m"] = ay
    cols["journal_bearing"] = names
    return cols


def _parts(name, blocks, ident):
    """Per block: (m, value or None)."""
    for pt, cols in blocks:
        m = len(pt)
        if name in cols:
            yield m, cols[name]
        elif name in ident:
            yield m, ident[name][pt]
        else:
            yield m, None


def _is_scalar(x):
    return not isinstance(x, (np.ndarray, list, tuple))


def _numeric(fld, name, blocks, ident):
    dt = _NP[fld.type]
    vals, mask, nulls = [], [], False
    for m, x in _parts(name, blocks, ident):
        if x is None:
            vals.append(np.zeros(m, dt))
            mask.append(np.ones(m, bool))
            nulls = True
            continue
        if not _is_scalar(x) and np.asarray(x).dtype == object:  # None entries: nulls
            x = np.asarray(x)
            none = np.array([e is None for e in x], dtype=bool)
            vals.append(np.where(none, 0, x).astype(dt))
            mask.append(none)
            nulls = nulls or bool(none.any())
            continue
        vals.append(np.full(m, x, dt) if _is_scalar(x) else np.asarray(x, dtype=dt))
        mask.append(np.zeros(m, bool))
    v = np.concatenate(vals) if vals else np.zeros(0, dt)
    return pa.array(v, type=fld.type, mask=np.concatenate(mask) if nulls else None)


def _strings(name, blocks, ident):
    out: list = []
    for m, x in _parts(name, blocks, ident):
        if x is None or _is_scalar(x):
            out.extend([x] * m)
        else:
            out.extend(x.tolist() if isinstance(x, np.ndarray) else x)
    return out


def _categorical(name, blocks, ident, cats):
    codes, mask, nulls = [], [], False
    lookup = {c: i for i, c in enumerate(cats)}
    for m, x in _parts(name, blocks, ident):
        if x is None:
            codes.append(np.zeros(m, np.int8))
            mask.append(np.ones(m, bool))
            nulls = True
            continue
        if _is_scalar(x):
            codes.append(np.full(m, lookup[x], np.int8))
        else:
            x = np.asarray(x)
            c = np.full(m, -1, np.int8)
            for i, cat in enumerate(cats):
                c[x == cat] = i
            none = (x == None) if x.dtype == object else np.zeros(m, bool)  # noqa: E711
            if (c[~none] < 0).any():
                raise KeyError(str(x[(c < 0) & ~none][0]))
            codes.append(np.where(none, 0, c).astype(np.int8))
            mask.append(none)
            nulls = nulls or bool(none.any())
            continue
        mask.append(np.zeros(m, bool))
    c = np.concatenate(codes) if codes else np.zeros(0, np.int8)
    idx = pa.array(c, type=pa.int8(), mask=np.concatenate(mask) if nulls else None)
    return pa.DictionaryArray.from_arrays(idx, pa.array(cats))


def block_table(job, sch: pa.Schema, cats: dict, ident: dict, blocks: list) -> pa.Table:
    """The chunk's table with schema ``sch`` from ``blocks`` over the points of ``ident``."""
    n = sum(len(b[0]) for b in blocks)
    cols = []
    for fld in sch:
        name = fld.name
        if name == "sweep_id":
            cols.append(pa.DictionaryArray.from_arrays(
                pa.array(np.zeros(n, dtype=np.int8)), pa.array([job.sweep_id])))
        elif name in cats:
            cols.append(_categorical(name, blocks, ident, cats[name]))
        elif name == "message":
            cols.append(pa.array(["" if x is None else str(x)
                                  for x in _strings(name, blocks, ident)], type=fld.type))
        elif fld.type in _NP:
            cols.append(_numeric(fld, name, blocks, ident))
        else:
            cols.append(pa.array(_strings(name, blocks, ident), type=fld.type))
    if job.meta:
        sch = sch.with_metadata({b"rotordyn": json.dumps(job.meta, sort_keys=True).encode()})
    return pa.Table.from_arrays(cols, schema=sch)


def runs(ok) -> list[tuple[int, int, bool]]:
    """Maximal runs [i, j) of equal truth in ``ok``: (i, j, value)."""
    ok = np.asarray(ok, dtype=bool)
    if ok.size == 0:
        return []
    cut = np.flatnonzero(ok[1:] != ok[:-1]) + 1
    edges = [0, *cut.tolist(), ok.size]
    return [(a, b, bool(ok[a])) for a, b in zip(edges, edges[1:])]


def _expand(x, m):
    if not _is_scalar(x):
        return np.asarray(x, dtype=object) if isinstance(x, (list, tuple)) else x
    if isinstance(x, str):
        return np.full(m, x, dtype=object)
    return np.full(m, x)


def merge(blocks: list) -> list:
    """Adjacent blocks with the same column names (and None, i.e. null, in the same columns)
    joined into one: the per-point blocks of a run of points become one block whose columns
    are whole arrays (the same rows, the same values, in the same order)."""
    out: list = []
    group: list = []

    def key(cols):
        return tuple(sorted((k, x is None) for k, x in cols.items()))

    def flush():
        if len(group) == 1:
            out.append(group[0])
        elif group:
            pts = np.concatenate([np.asarray(p, dtype=np.int64) for p, _ in group])
            cols = {}
            for k, x0 in group[0][1].items():
                xs = [c[k] for _, c in group]
                if x0 is None:
                    cols[k] = None
                elif all(_is_scalar(x) for x in xs) and all(type(x) is type(x0) and x == x0
                                                           for x in xs):
                    cols[k] = x0
                else:
                    cols[k] = np.concatenate([_expand(x, len(p))
                                              for (p, _), x in zip(group, xs)])
            out.append((pts, cols))
        group.clear()

    for b in blocks:
        if group and key(b[1]) != key(group[0][1]):
            flush()
        group.append(b)
    flush()
    return out
