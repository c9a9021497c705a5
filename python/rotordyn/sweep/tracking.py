"""Tracked ``mode_id`` along the lines of a sweep chunk (the innermost varying axis: speed for
a Campbell sweep, or p_c, a_y, any model field): :func:`rotordyn.analysis.tracking.track_lines`
(MAC on the mass-weighted mode shapes plus eigenvalue distance, one-to-one assignment) over the
points of every line, in line order, one C++ call for the lines that share a weighting matrix.
Ids start at 0 at each line's first point, as in :class:`rotordyn.results.CampbellResult`."""

from __future__ import annotations

import numpy as np


def track_points(points: list) -> dict:
    """``mode_id`` of tracked points: ``points`` holds (key, eigenvalues (k_i,), modes (n, k_i),
    line_start, weight (n, n)) per point in chunk order; a line is weighted by its last point's
    ``weight`` (the former per-line rule). Returns {key: (k_i,) int64 ids}."""
    from rotordyn.analysis.tracking import track_lines

    # lines, then runs of consecutive lines weighted by one matrix (one call each)
    lines: list[list] = []
    for p in points:
        if p[3] or not lines:
            lines.append([])
        lines[-1].append(p)
    out: dict = {}
    a = 0
    while a < len(lines):
        w = lines[a][-1][4]
        b = a + 1
        while b < len(lines) and lines[b][-1][4] is w:
            b += 1
        group = [p for line in lines[a:b] for p in line]
        k = max(len(p[1]) for p in group)
        lam = np.full((len(group), k), np.nan + 0j)
        for i, p in enumerate(group):
            lam[i, :len(p[1])] = p[1]
        starts = [i == 0 or p[3] for i, p in enumerate(group)]
        ids = track_lines(lam, [p[2] for p in group], np.asarray(w, dtype=float), starts)
        for i, p in enumerate(group):
            out[p[0]] = ids[i, :len(p[1])]
        a = b
    return out


def track_line(rows: list, line: list, weight: np.ndarray | None = None) -> None:
    """Set ``mode_id`` in ``rows`` for one line: ``line`` holds (row index of the point's
    block, eigenvalues (k,), modes (n, k)) per point, in line order."""
    w = np.zeros((0, 0)) if weight is None else weight
    got = track_points([(at, lm, ph, i == 0, w) for i, (at, lm, ph) in enumerate(line)])
    for at, ids in got.items():
        rows[at]["mode_id"] = ids
