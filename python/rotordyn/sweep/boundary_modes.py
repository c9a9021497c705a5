"""Tracked modes of an adaptive boundary sweep (:mod:`.boundary`) and the field whose zero is
its boundary.

The refinement evaluates scattered fine nodes, level by level, so modes are tracked along a
tree rather than along lines: each point of a level takes as parent the nearest point
(fine-index distance, then the smaller point id) of the earlier levels (on the first level,
the coarse grid: the nearest with a smaller point id, i.e. the previous coarse node); its
modes take the ids of the parent's modes they are assigned to (optimal one-to-one assignment
on the eigenvalue distance, the tracking of :func:`rotordyn.analysis.tracking.track_lines`
without shapes, all of a level's pairs in one C++ call); a mode with no partner gets a new
id. The ids depend on the plan only (never on which chunk finished first); a resumed sweep
may number new ids differently, never which modes share one, so its boundary is the same.

The boundary is the zero of :func:`rotordyn._common.crossing.critical_values` over the
evaluated points (the stability map's rule): the Re λ of the modes that go unstable somewhere,
which follows the crossing mode between a stable and an unstable node, where max Re λ of a
rotor without material damping is a bystander's -0.01 1/s on the stable side.
"""

from __future__ import annotations

import numpy as np

from rotordyn._common.crossing import critical_values


class ModeTracks:
    """Per evaluated point: its eigenvalues, which count for the boundary (the rotor's with
    ``exclude_sleeve``), its fine-grid index and its tracked mode ids."""

    def __init__(self, exclude_sleeve: bool):
        self.exclude_sleeve = exclude_sleeve
        self.lam: dict = {}    # point_id -> (k,) complex
        self.use: dict = {}    # point_id -> (k,) bool: counts for the boundary
        self.ids: dict = {}    # point_id -> (k,) int64 tracked ids
        self.index: dict = {}  # point_id -> fine-grid index tuple
        self.level: dict = {}  # point_id -> the refinement level that evaluated it
        self.next_id = 0

    @staticmethod
    def rows(table) -> dict:
        """point_id -> (eigenvalues, kinds, mode ids) of a chunk's converged mode rows."""
        pid = table.column("point_id").to_numpy()
        mid = table.column("mode_id").to_numpy(zero_copy_only=False)
        re = table.column("eig_real_1_per_s").to_numpy(zero_copy_only=False)
        fr = table.column("freq_hz").to_numpy(zero_copy_only=False)
        kind = table.column("kind").cast("string").to_numpy(zero_copy_only=False)
        ok = np.array([m is not None and np.isfinite(m) for m in mid.astype(float)])
        out: dict = {}
        if not ok.any():
            return out
        pid, mid, kind = pid[ok], mid[ok].astype(np.int64), kind[ok]
        lam = re[ok].astype(float) + 2j * np.pi * fr[ok].astype(float)
        cuts = np.flatnonzero(np.diff(pid)) + 1
        for a, b in zip(np.r_[0, cuts], np.r_[cuts, len(pid)]):
            out[int(pid[a])] = (lam[a:b], kind[a:b], mid[a:b])
        return out

    def add_tracked(self, rows: dict, index, level: int) -> None:
        """Points of ``level`` whose rows already hold tracked ids (a resumed sweep's chunks;
        the ids' numbers may differ from an uninterrupted run's, never which modes share
        one)."""
        for p, (lam, kind, mid) in rows.items():
            self._put(p, lam, kind, index(p), level)
            self.ids[p] = mid
            self.next_id = max(self.next_id, int(mid.max()) + 1 if len(mid) else 0)

    def _put(self, p, lam, kind, idx, level):
        self.level[p] = level
        self.lam[p] = lam
        self.use[p] = (kind != "sleeve") if self.exclude_sleeve else np.ones(len(lam), bool)
        self.index[p] = np.asarray(idx)

    def track(self, rows: dict, index, level: int) -> dict:
        """Track the new points ``rows`` (point_id -> (eigenvalues, kinds, slots)) of
        ``level`` from their parents; returns point_id -> ids."""
        from rotordyn.analysis.tracking import track_lines

        new = sorted(rows)
        if not new:
            return {}
        for p in new:
            self._put(p, rows[p][0], rows[p][1], index(p), level)
        parent = self._parents(new, level)
        pairs = [p for p in new if p in parent]
        rel = {}
        if pairs:
            k = max(max(len(self.lam[p]), len(self.lam[parent[p]])) for p in pairs)
            L = np.full((2 * len(pairs), k), np.nan + 0j)
            for q, p in enumerate(pairs):
                L[2 * q, :len(self.lam[parent[p]])] = self.lam[parent[p]]
                L[2 * q + 1, :len(self.lam[p])] = self.lam[p]
            got = track_lines(L, [], np.zeros((0, 0)), [q % 2 == 0 for q in range(len(L))])
            rel = {p: got[2 * q + 1, :len(self.lam[p])] for q, p in enumerate(pairs)}
        out = {}
        for p in new:  # in point-id order: a parent of this level is resolved before
            if p not in rel:
                ids = np.arange(self.next_id, self.next_id + len(self.lam[p]), dtype=np.int64)
            else:
                pid_ids, r = self.ids[parent[p]], rel[p]
                hit = (r >= 0) & (r < len(pid_ids))
                ids = np.where(hit, pid_ids[np.clip(r, 0, max(len(pid_ids) - 1, 0))], -1)
                fresh = np.flatnonzero(~hit)  # modes without a partner: new ids
                ids[fresh] = self.next_id + np.arange(len(fresh))
                self.next_id += len(fresh)
                ids = ids.astype(np.int64)
            self.next_id = max(self.next_id, int(ids.max()) + 1 if len(ids) else 0)
            self.ids[p] = out[p] = ids
        return out

    def _parents(self, new: list, level: int) -> dict:
        """point_id -> its parent: the nearest point of earlier levels (fine-index distance,
        a k-d tree; the smallest id among the nearest found); on the first level evaluated,
        the nearest of that level's points with a smaller point id (then the smaller id)."""
        old = np.array(sorted(p for p, lv in self.level.items() if lv < level), dtype=np.int64)
        at = np.array([self.index[p] for p in new], dtype=float).reshape(len(new), -1)
        out = {}
        if len(old):
            from scipy.spatial import cKDTree

            pos = np.array([self.index[p] for p in old], dtype=float).reshape(len(old), -1)
            k = min(len(old), 8)
            d, j = cKDTree(pos).query(at, k=k, p=1)
            d, j = d.reshape(len(new), k), j.reshape(len(new), k)
            for q, p in enumerate(new):
                m = d[q] == d[q].min()
                out[p] = int(old[j[q][m]].min())
            return out
        same = np.array(sorted(p for p, lv in self.level.items() if lv == level),
                        dtype=np.int64)
        pos = np.array([self.index[p] for p in same], dtype=float).reshape(len(same), -1)
        for q, p in enumerate(new):
            n = int(np.searchsorted(same, p))  # the level's points with a smaller id
            if n:
                dist = np.abs(pos[:n] - at[q][None]).sum(axis=1)
                out[p] = int(same[int(np.argmin(dist))])  # the first (smallest id) at the min
        return out

    def field(self) -> dict:
        """point_id -> the boundary's field (:func:`critical_values` over every point)."""
        ps = sorted(self.ids)
        if not ps:
            return {}
        key = np.concatenate([np.full(int(self.use[p].sum()), p) for p in ps])
        mid = np.concatenate([self.ids[p][self.use[p]] for p in ps])
        lam = np.concatenate([self.lam[p][self.use[p]] for p in ps])
        pts, val = critical_values(key, mid, lam.real, np.abs(lam))
        return dict(zip(pts.tolist(), val.tolist()))


def with_ids(table, ids: dict):
    """``table`` with its mode rows' ``mode_id`` set from ``ids`` (point_id -> ids, rows of a
    point in slot order)."""
    import pyarrow as pa

    pid = table.column("point_id").to_numpy()
    mid = table.column("mode_id").to_numpy(zero_copy_only=False)
    out = np.array(mid, dtype=object)
    cuts = np.flatnonzero(np.diff(pid)) + 1
    for a, b in zip(np.r_[0, cuts], np.r_[cuts, len(pid)]):  # a point's rows, slot order
        v = ids.get(int(pid[a]))
        if v is not None:
            out[a:b] = v.tolist()
    col = pa.array(out.tolist(), type=pa.int64())
    return table.set_column(table.schema.get_field_index("mode_id"), "mode_id", col)
