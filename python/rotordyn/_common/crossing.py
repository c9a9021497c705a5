"""The field whose zero is a stability boundary, one rule for the stability map
(:func:`rotordyn.plot.maps.critical_field`) and the adaptive boundary sweep
(:mod:`rotordyn.sweep.boundary`).

At each point: the largest Re λ among the tracked modes (``mode_id``) that are unstable at
some point of the set, else (no such mode there) max Re λ, Re λ within the round-off band
counting as the band's lower edge (−1e-9 max(|λ|, 1): never 0, never round-off's sign). Its
sign is the point's verdict at every point (a point with an unstable mode has that mode in
the set; a stable point has every banded Re λ < 0), but between points it follows the modes that cross: max Re λ of a rotor without
material damping is a bystander bending mode's -0.01 1/s over the whole stable side, so the
linear zero of max Re λ between a stable and an unstable point hugs the stable one (a turbine
on a 10 Hz speed grid: 60.01 Hz where ``rotordyn threshold`` bisects 61.58 Hz), while the
crossing mode's own Re λ is nearly linear there.
"""

from __future__ import annotations

import numpy as np


def banded(re, mag) -> np.ndarray:
    """Re λ with the round-off band (``rotordyn.results.modes.ROUND_OFF_REL``) moved to its
    lower edge: |Re λ| < ROUND_OFF_REL·max(|λ|, 1) becomes −ROUND_OFF_REL·max(|λ|, 1). Its
    sign is the mode's verdict (``mode_stable``) and it is never 0: a conservative region's
    Re λ = 0 ± round-off is strictly negative, so no zero contour runs through it."""
    from rotordyn import _core  # the core's band (results.modes.ROUND_OFF_REL reads it too)

    re = np.asarray(re, dtype=float)
    band = float(_core.ROUND_OFF_REL) * np.maximum(np.asarray(mag, dtype=float), 1.0)
    with np.errstate(invalid="ignore"):
        return np.where(np.abs(re) < band, -band, re)


def critical_values(point, mode_id, re, mag) -> tuple[np.ndarray, np.ndarray]:
    """(points (m,), field (m,)) from per-mode rows: ``point`` (n_rows,) any sortable key of
    the row's point, ``mode_id`` (n_rows,) int, ``re`` (n_rows,) Re λ (1/s; the rows of one
    point are all its modes that count, e.g. the rotor's), ``mag`` (n_rows,) |λ| (1/s): Re λ
    in the round-off band counts as the band's lower edge (:func:`banded`), so the field's
    sign is the point's verdict and it is strictly negative at a stable point. ``points``
    are the unique keys, sorted; a point whose rows are all non-finite gets NaN."""
    point, mode_id = np.asarray(point), np.asarray(mode_id)
    re = banded(re, mag)
    keys, inv = np.unique(point, return_inverse=True)
    inv = inv.ravel()
    crit = np.unique(mode_id[re > 0])
    in_crit = np.isin(mode_id, crit) & np.isfinite(re)
    allm = np.full(len(keys), -np.inf)
    np.maximum.at(allm, inv[np.isfinite(re)], re[np.isfinite(re)])
    best = np.full(len(keys), -np.inf)
    np.maximum.at(best, inv[in_crit], re[in_crit])
    has = np.zeros(len(keys), bool)
    has[inv[in_crit]] = True
    out = np.where(has, best, allm)
    return keys, np.where(np.isfinite(out), out, np.nan)
