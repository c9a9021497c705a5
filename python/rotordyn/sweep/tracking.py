"""Tracked mode ids along a line of a sweep (speed, or any innermost axis): eigenvector
continuity by the modal assurance criterion, MAC_ij = |φ_iᴴ φ_j|² / (|φ_i|² |φ_j|²), with a
one-to-one assignment between neighbouring points (Hungarian method on 1 − MAC)."""

from __future__ import annotations

import numpy as np


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(k_a, k_b) MAC between the columns of complex mode matrices a (n, k_a), b (n, k_b)."""
    num = np.abs(a.conj().T @ b) ** 2
    den = np.outer(np.sum(np.abs(a) ** 2, 0), np.sum(np.abs(b) ** 2, 0))
    return num / np.where(den > 0, den, 1.0)


def assign(prev: np.ndarray, cur: np.ndarray) -> np.ndarray:
    """For each column of ``cur``, the index of the column of ``prev`` it continues (−1: new)."""
    from scipy.optimize import linear_sum_assignment

    m = mac(prev, cur)
    r, c = linear_sum_assignment(-m)
    out = np.full(cur.shape[1], -1)
    out[c] = r
    return out


def track_line(rows: list, line: list) -> None:
    """Set ``mode_id`` in ``rows`` for the points of one line: ``line`` holds
    (first row index, n modes, modes (n, k), eigenvalues) per point in line order. Ids start
    1..k at the first point (ascending frequency); a mode continues the id of the mode of the
    previous point it matches; an unmatched mode gets a new id."""
    prev_phi = prev_ids = None
    next_id = 1
    for first, k, phi, _lam in line:
        if prev_phi is None:
            ids = np.arange(1, k + 1)
            next_id = k + 1
        else:
            a = assign(prev_phi, phi)
            ids = np.empty(k, dtype=int)
            for j in range(k):
                if a[j] >= 0:
                    ids[j] = prev_ids[a[j]]
                else:
                    ids[j] = next_id
                    next_id += 1
        for j in range(k):
            rows[first + j]["mode_id"] = int(ids[j])
        prev_phi, prev_ids = phi, ids
