"""Tracked ``mode_id`` along a line of a sweep (the innermost varying axis: speed for a
Campbell sweep, or p_c, a_y, any model field): :func:`rotordyn.analysis.tracking.track_modes`
(MAC on the mass-weighted mode shapes plus eigenvalue distance, one-to-one assignment) over the
points of the line, in line order. Ids start at 0 at the line's first point, as in
:class:`rotordyn.results.CampbellResult`."""

from __future__ import annotations

import numpy as np


def track_line(rows: list, line: list, weight: np.ndarray | None = None) -> None:
    """Set ``mode_id`` in ``rows`` for one line: ``line`` holds (row index of the point's
    block, eigenvalues (k,), modes (n, k)) per point, in line order."""
    from rotordyn.analysis.tracking import track_modes

    k = max(len(lam) for _, lam, _ in line)
    n = line[0][2].shape[0]
    lam = np.full((len(line), k), np.nan + 0j)
    phi = np.full((len(line), n, k), np.nan + 0j)
    for i, (_, lm, ph) in enumerate(line):
        lam[i, :len(lm)] = lm
        phi[i, :, :ph.shape[1]] = ph
    ids = track_modes(lam, phi, weight=weight)
    for i, (at, lm, _) in enumerate(line):
        rows[at]["mode_id"] = ids[i, :len(lm)].astype(np.int64)
