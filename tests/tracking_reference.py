"""The NumPy/SciPy mode tracking that ``rotordyn.analysis.tracking.track_modes`` used before the
tracking moved into the C++ core (issue 22: it was ~10 % of a sweep's stability chunk), kept as
the reference of tests/test_tracking_core.py: the same ids on the same inputs."""

from __future__ import annotations

import numpy as np


def track_modes_reference(eigenvalues: np.ndarray, shapes=None, *, weight: np.ndarray | None = None,
                eig_weight: float = 0.2, min_mac: float = 0.3) -> np.ndarray:
    """The former rotordyn.analysis.tracking.track_modes, as it was (same arguments and ids)."""
    from scipy.optimize import linear_sum_assignment
    lam = np.asarray(eigenvalues, dtype=complex)
    n_pts, k = lam.shape
    phi = None
    if shapes is not None:
        if isinstance(shapes, (list, tuple)):
            n = max((np.asarray(s).shape[0] for s in shapes if s is not None), default=0)
            phi = np.full((n_pts, n, k), np.nan + 0j)
            for i, s in enumerate(shapes):
                if s is None:
                    continue
                s = np.asarray(s, dtype=complex)
                phi[i, :, :s.shape[1]] = s
        else:
            phi = np.asarray(shapes, dtype=complex)

    ids = np.full((n_pts, k), -1, dtype=np.int64)
    next_id = 0
    # Where every id was last seen: (point, slot), in id order (ids are 0, 1, ... in order of
    # creation). The weighted shapes W φ and the norms φ^H W φ of every point are formed once
    # (one batched product) instead of at every comparison; the MAC is then the same quotient.
    last_pt: list[int] = []
    last_slot: list[int] = []
    if phi is not None:
        wphi = phi if weight is None else np.matmul(np.asarray(weight), phi)
        with np.errstate(invalid="ignore"):
            nrm = np.real(np.einsum("pik,pik->pk", phi.conj(), wphi))
    # which slots hold a mode, every point at once (no arithmetic: the same booleans)
    present_all = np.isfinite(lam)
    if phi is not None:
        present_all &= np.all(np.isfinite(phi), axis=1)
    # one errstate for the whole line (entering it per point cost as much as the MAC)
    with np.errstate(invalid="ignore", divide="ignore"):
        for i in range(n_pts):
            slots = np.nonzero(present_all[i])[0]
            if slots.size == 0:
                continue
            assigned = {}
            if last_pt:
                kp, ks = np.asarray(last_pt), np.asarray(last_slot)
                lk = lam[kp, ks]
                li = lam[i, slots]
                scale = max(np.abs(lk).max(), np.abs(li).max(), 1e-300)
                dist = np.abs(li[:, None] - lk[None, :]) / scale
                if phi is not None:
                    m = _mac_known(phi[i][:, slots], nrm[i, slots], wphi[kp, :, ks].T,
                                   nrm[kp, ks])
                else:
                    m = np.ones_like(dist)
                cost = (1.0 - m) + eig_weight * dist
                rows, cols = linear_sum_assignment(cost)
                for r, c in zip(rows.tolist(), cols.tolist()):
                    if (m[r, c] < min_mac) if phi is not None else (dist[r, c] > 0.1):
                        continue
                    assigned[int(slots[r])] = c
            for s in slots.tolist():
                if s not in assigned:
                    assigned[s] = next_id
                    next_id += 1
                    last_pt.append(i)
                    last_slot.append(s)
                j = assigned[s]
                ids[i, s] = j
                last_pt[j], last_slot[j] = i, s
    return ids


def _mac_known(a: np.ndarray, na: np.ndarray, wb: np.ndarray, nb: np.ndarray) -> np.ndarray:
    """:func:`mac` from precomputed parts (inside the caller's errstate): shapes ``a`` (n, ka)
    with norms ``na`` (ka,), the weighted shapes W b (n, kb) with norms ``nb`` (kb,)."""
    cross = np.abs(a.conj().T @ wb) ** 2
    den = na[:, None] * nb[None, :]
    ok = den > 0
    return np.clip(np.where(ok, cross / np.where(ok, den, 1.0), 0.0), 0.0, 1.0)
