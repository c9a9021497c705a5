"""Checks of a sweep axis's values as a set and as a sequence, at spec load.

Every axis value is a key of its points' rows (the axis column), so a value given twice is two
points with the same key: a duplicated row set that a join or a pivot on the axis columns mixes
silently. Along a line (the axis a chunk keeps whole) the order matters too: the equilibrium is
continued from the previous point, modes are tracked between neighbours and a threshold is
bracketed between neighbouring values, so a line that turns back (``[120, 40, 200]``) gives one
crossing per turn and mode ids that follow the listing, not the physics. A decreasing line (a
run-down) is as good as an increasing one.
"""

from __future__ import annotations

import numpy as np

from rotordyn.errors import InputError


def check_unique(name: str, vals) -> None:
    """InputError naming ``grid.<name>[j]`` if it repeats an earlier value of the axis."""
    a = np.asarray(vals, dtype=float)
    if a.size < 2:
        return
    order = np.argsort(a, kind="stable")
    same = np.flatnonzero(a[order][1:] == a[order][:-1])
    if same.size:
        first, j = sorted((int(order[same[0]]), int(order[same[0] + 1])))
        raise InputError(f"grid.{name}[{j}]: {vals[j]!r} repeats grid.{name}[{first}]; give "
                         "each value of an axis once (its column is the points' key)")


def check_monotonic(name: str, vals, why: str) -> None:
    """InputError naming ``grid.<name>[k]`` where the line turns back (``why``: what the
    order is used for)."""
    d = np.diff(np.asarray(vals, dtype=float))
    if d.size < 2:
        return
    up = d[0] > 0
    bad = np.flatnonzero(d <= 0 if up else d >= 0)
    if bad.size:
        k = int(bad[0])
        raise InputError(f"grid.{name}[{k + 1}]: the values must "
                         f"{'increase' if up else 'decrease'} along the line (the equilibrium "
                         f"is continued and {why} between neighbours), got {vals[k]!r} then "
                         f"{vals[k + 1]!r}; sort them")
