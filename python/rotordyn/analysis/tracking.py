"""Mode tracking along a line of operating points (speed, chamber pressure, configuration) by
eigenvector continuity: the modal assurance criterion (MAC) between consecutive points,
completed by the eigenvalue distance, and a one-to-one assignment (Hungarian algorithm).

Sorting the modes by frequency at each point mislabels them where two frequency curves cross
(the "mode 1" of a sorted Campbell diagram jumps from one physical mode to another). Tracking
follows each mode's shape instead: through a *crossing* (two modes of different shape whose
frequencies cross) the ids follow the shapes and the curves cross; through a *veering* (the
frequencies approach, do not cross, and the shapes exchange continuously) the ids follow the
continuous branches, provided the points are fine enough to resolve the exchange.

MAC (Allemang & Brown 1982): MAC(a, b) = |a^H W b|² / ((a^H W a)(b^H W b)), with W the identity
or a (mass) weighting matrix.
"""

from __future__ import annotations

import numpy as np

from rotordyn import _core
from rotordyn.errors import InputError

__all__ = ["mac", "track_modes", "track_lines"]


def mac(phi_a: np.ndarray, phi_b: np.ndarray, weight: np.ndarray | None = None) -> np.ndarray:
    """Modal assurance criterion between the columns of ``phi_a`` (n, ka) and ``phi_b`` (n, kb):
    (ka, kb) array in [0, 1]; 1 for proportional shapes (any complex scale). ``weight``: optional
    (n, n) Hermitian positive (semi-)definite matrix, e.g. the mass matrix."""
    a = np.asarray(phi_a, dtype=complex)
    b = np.asarray(phi_b, dtype=complex)
    if a.ndim != 2 or b.ndim != 2 or a.shape[0] != b.shape[0]:
        raise InputError(f"mac: expected shapes (n, ka) and (n, kb), got {a.shape} and {b.shape}")
    wb = b if weight is None else np.asarray(weight) @ b
    wa = a if weight is None else np.asarray(weight) @ a
    cross = np.abs(a.conj().T @ wb) ** 2
    na = np.real(np.einsum("ik,ik->k", a.conj(), wa))
    nb = np.real(np.einsum("ik,ik->k", b.conj(), wb))
    den = np.outer(na, nb)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = np.where(den > 0, cross / np.where(den > 0, den, 1.0), 0.0)
    return np.clip(out, 0.0, 1.0)


def track_modes(eigenvalues: np.ndarray, shapes=None, *, weight: np.ndarray | None = None,
                eig_weight: float = 0.2, min_mac: float = 0.3) -> np.ndarray:
    """Tracked mode ids along a line of points.

    eigenvalues: (n_points, k) complex, 1/s, the modes of each point in any order (NaN for a
    point or a slot without a mode). shapes: (n_points, n, k) complex (or a list of (n, k_i)
    arrays padded to k), the matching mode shapes on one set of coordinates; None tracks by
    eigenvalue proximity alone. Returns ``mode_id``: (n_points, k) int64, the id of each slot,
    -1 where there is no mode. Ids start at 0 in the order of the first point's slots; a mode
    that appears later (e.g. it enters a truncated set of the lowest modes) gets the next
    unused id.

    Each point is matched with the last point where a mode was seen, by the assignment that
    minimises Σ (1 − MAC) + eig_weight·|Δλ|/scale, scale = max(|λ|) over the two points.
    A pair with MAC < ``min_mac`` (with shapes) or whose eigenvalues differ by more than 10 % of
    the scale (without shapes) is not matched: the slot starts a new id (a mode that leaves a
    truncated set and another that enters it are not joined). The assignment is optimal
    (shortest augmenting paths); the work is one C++ call (``_core.track_modes``).
    """
    lam = np.asarray(eigenvalues, dtype=complex)
    if lam.ndim != 2:
        raise InputError(f"eigenvalues: expected shape (n_points, n_modes), got {lam.shape}")
    n_pts, k = lam.shape
    phi = []
    if shapes is not None:
        if isinstance(shapes, (list, tuple)):
            if len(shapes) != n_pts:
                raise InputError(f"shapes: expected {n_pts} arrays (one per point), got "
                                 f"{len(shapes)}")
            n = max((np.asarray(s).shape[0] for s in shapes if s is not None), default=0)
            for s in shapes:
                s = np.zeros((n, 0), complex) if s is None else np.asarray(s, dtype=complex)
                if s.ndim != 2 or s.shape[1] > k:
                    raise InputError(f"shapes: expected arrays of shape (n, <= {k}), got "
                                     f"{s.shape}")
                phi.append(s)
        else:
            arr = np.asarray(shapes, dtype=complex)
            if arr.ndim != 3 or arr.shape[0] != n_pts or arr.shape[2] != k:
                raise InputError(f"shapes: expected shape ({n_pts}, n, {k}), got {arr.shape}")
            phi = list(arr)
    for name, x in (("eig_weight", eig_weight), ("min_mac", min_mac)):
        if not np.isfinite(x) or x < 0:
            raise InputError(f"{name}: expected a finite value >= 0, got {x!r}")
    w = np.zeros((0, 0)) if weight is None or not phi else np.asarray(weight, dtype=float)
    return track_lines(lam, phi, w, [], eig_weight=eig_weight, min_mac=min_mac)


def track_lines(eigenvalues: np.ndarray, shapes: list, weight: np.ndarray, line_start,
                *, eig_weight: float = 0.2, min_mac: float = 0.3) -> np.ndarray:
    """:func:`track_modes` of several lines in one C++ call (no input checks: the sweep's
    chunks): eigenvalues (n_points, k) complex, shapes one (n, k_i) array per point or [],
    weight (n, n) or (0, 0), ``line_start`` (n_points,) true where a line starts (or [] for
    one line). Returns (n_points, k) int64 ids, restarting at 0 on every line."""
    return np.asarray(_core.track_modes(eigenvalues, shapes, weight,
                                        [int(bool(s)) for s in line_start],
                                        eig_weight, min_mac), dtype=np.int64)
