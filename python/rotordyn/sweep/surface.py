"""The boundary surface by columns (issue 22): the crossings of every fine ``y`` column of a
3-D boundary sweep over (x, y, z), each certified by its two bracketing fine nodes, from about
two evaluated points per crossing instead of the corners of every mixed fine cube.

A column is the line of ``resolution`` fine nodes along ``y`` at one fine (x, z) node. Its
crossings are the fine intervals [j, j + 1] whose end nodes differ in state (stable, unstable,
failed), both evaluated. The plan (:class:`ColumnPlan`):

1. The coarse grid is evaluated; every coarse column is bisected along ``y`` between nodes of
   different states down to one fine step (each crossing found by bisection).
2. The (x, z) plane is refined as a quadtree of cells whose corners are resolved columns: a
   cell whose four corner columns are all one state from end to end holds no crossing and is
   left; an active cell is split at its middle fine node along each axis wider than one step.
   A new column lies halfway between two resolved *parents* (the ends of the cell edge it
   halves; a cell centre: between the two new edge columns beside it, resolved first).
3. A new column takes its parents' states wherever they agree and their crossings do not lie
   (no evaluation there). The rest (the *uncertain* nodes) is resolved: each crossing is
   predicted where the parents' interpolated crossings average and the two nodes of the
   predicted interval are evaluated; a prediction that does not bracket a change falls back
   to bisection between the nearest known nodes of different state, and a known node next
   to a change that was only inferred is evaluated, so every crossing ends between two
   evaluated nodes.

Assumption (as the cell refinement's): no crossing hides where the parents agree, i.e. the
surface is resolved by the coarse grid and does not fold between two neighbouring resolved
columns; the crossings then equal those of the dense column (tests/test_sweep_surface.py,
against dense grids of analytic fields and dense columns of a model).

Each requested point also has a *source* (:attr:`ColumnPlan.source`): evaluated nodes and
weights whose combined equilibria start its Newton iteration (interpolated between the
column's nodes or the two parents', else the nearest), so a point costs about two Reynolds
solves of the equilibrium; the equilibrium is polished to round-off, so the start changes the
cost, not the answer.
"""

from __future__ import annotations

from bisect import bisect_left
from collections import Counter

import numpy as np

UNKNOWN = -1


class ColumnPlan:
    """The plan in fine indices (i, j, k) along (x, y, z), columns along y.

    ``points`` holds the nodes to evaluate now (never evaluated before); :meth:`advance` takes
    their results ``{(i, j, k): (state, value)}`` (state 0 stable, 1 unstable, 2 failed;
    value max Re λ, NaN when failed) and moves on; False when every column is resolved.
    ``states`` (nx, ny, nz) holds every resolved column's states (evaluated or inferred),
    :data:`UNKNOWN` elsewhere; ``evaluated`` marks the evaluated nodes."""

    def __init__(self, xn, yn, zn, shape):
        self.shape = tuple(int(s) for s in shape)
        nx, ny, nz = self.shape
        self.xn, self.yn, self.zn = sorted(xn), sorted(yn), sorted(zn)
        self.states = np.full(self.shape, UNKNOWN, np.int8)
        self.evaluated = np.zeros(self.shape, bool)
        self.values: dict = {}
        self._ev: dict = {}  # (i, k) -> sorted evaluated j of the column
        self._uni = np.full((nx, nz), UNKNOWN - 1, np.int8)  # a resolved column's one state
        self.level = 0
        self.source: dict = {}
        # columns being resolved: (i, k) -> [known (j -> state), inferred (not evaluated)
        # nodes among them, uncertain mask, seeds still to evaluate]
        self._open: dict = {}
        self._parents: dict = {}
        # cells of the (x, z) plane (one z node: a boundary curve, cells of zero z width)
        zi = list(zip(self.zn, self.zn[1:])) or [(self.zn[0], self.zn[0])]
        self.cells = [(a, b, c, d) for a, b in zip(self.xn, self.xn[1:]) for c, d in zi]
        self._centres: list = []
        self._check: set = set()  # resolved columns to check against their neighbours
        self._before: dict = {}
        self._kind: dict = {}
        self._sig: dict = {}  # (i, k) -> a resolved column's states run by run
        # points requested by reason: coarse grid, seed (a new column's predicted interval or
        # its first bisection), bisect, confirm (an inferred node next to a change), check
        self.stats = Counter()
        self.points = {(i, j, k) for i in self.xn for j in self.yn for k in self.zn}
        self._phase = "coarse"
        self.stats["coarse"] = len(self.points)

    # -- results --------------------------------------------------------------------------
    def advance(self, results) -> bool:
        """Record ``results`` of the current points; plan the next ones (False: done)."""
        for idx, (s, v) in results.items():
            self.evaluated[idx] = True
            self.states[idx] = s
            self.values[idx] = v
            self._ev.setdefault((idx[0], idx[2]), []).append(idx[1])
        for c in {(i, k) for i, _, k in results}:
            self._ev[c].sort()
        if self._phase == "coarse":
            for i in self.xn:
                for k in self.zn:
                    self._open[(i, k)] = [{j: int(self.states[i, j, k]) for j in self.yn},
                                          set(), np.ones(self.shape[1], bool), []]
            self._phase = "resolve"
        else:
            for (i, j, k) in results:
                col = self._open.get((i, k))
                if col is not None:
                    self._update(col, (i, k), j)
        self.level += 1
        while True:
            pts = self._requests()
            if pts:
                self.points = pts
                return True
            self._close()
            opened = False
            while self._check and not opened:
                opened = self._recheck()
            if opened:
                continue
            if not self._next_columns():
                self.points = set()
                return False

    def _update(self, col, c, j):
        """An evaluated node of an open column: replaces an inferred one; a change from the
        inferred state moves the uncertain region one node outward."""
        known, assumed, unc, _ = col
        s = int(self.states[c[0], j, c[1]])
        if j in assumed:
            assumed.discard(j)
            if s != known[j]:
                unc[j] = True
                for q in (j - 1, j + 1):
                    if 0 <= q < len(unc) and not unc[q] and q not in known:
                        known[q] = known[j]  # the parents' agreed state beyond
                        assumed.add(q)
                        unc[q] = True
        known[j] = s

    def _requests(self) -> set:
        """Per open column: its seeds once (the predicted intervals' nodes), then the node
        between known nodes of different states more than one step apart (the predicted one
        if inside, else the middle), or an inferred node next to a change (to be evaluated)."""
        pts = set()
        for c, col in self._open.items():
            known, assumed, _, seeds = col
            if seeds:
                new = {(c[0], j, c[1]) for j in seeds} - pts
                self.stats[self._kind.pop(c, "seed")] += len(new)
                pts |= new
                col[3] = []
                continue
            js = sorted(known)
            for u, w in zip(js, js[1:]):
                if known[u] == known[w]:
                    continue
                if w - u > 1:
                    q, why = self._mid(c, u, w), "bisect"
                else:
                    q, why = u if u in assumed else (w if w in assumed else None), "confirm"
                if q is not None and (c[0], q, c[1]) not in pts:
                    pts.add((c[0], q, c[1]))
                    self.stats[why] += 1
        self.source = {p: self._nearest(p) for p in pts}
        return pts

    def _mid(self, c, u, w):
        """Between known nodes u < w of different states: the predicted crossing's node if it
        lies strictly inside, else the middle node."""
        pred = self._parents.get(c, (None, None))[1]
        if pred:
            for q0 in pred:
                for q in (q0, q0 + 1):
                    if u < q < w:
                        return q
        return (u + w) // 2

    def _nearest(self, p):
        """The start of point ``p``: [(node, weight), ...] of evaluated nodes whose
        equilibria, so weighted, approximate its own to second order where it can: linear
        interpolation between the column's nearest nodes below and above (when close), the
        mean of the two parents' nodes beside it, extrapolation from the column's two
        nearest nodes on one side; else the nearest evaluated node of the column or its
        parents (fine steps)."""
        i, j, k = p
        own = self._ev.get((i, k)) or []
        m = bisect_left(own, j)
        lo = own[m - 1] if m > 0 else None
        hi = own[m] if m < len(own) else None
        if lo is not None and hi is not None and (j - lo) * (hi - j) <= 4:
            return [((i, lo, k), (hi - j) / (hi - lo)), ((i, hi, k), (j - lo) / (hi - lo))]
        par = self._parents.get((i, k), ((), None))[0]
        if par:
            near = []
            for ci, ck in par:
                ev = self._ev.get((ci, ck))
                q = ev[min(range(len(ev)), key=lambda t: abs(ev[t] - j))] if ev else None
                near.append(None if q is None or abs(q - j) > 1 else (ci, q, ck))
            if None not in near:
                return [(near[0], 0.5), (near[1], 0.5)]
        if lo is not None and hi is not None:
            return [((i, lo, k), (hi - j) / (hi - lo)), ((i, hi, k), (j - lo) / (hi - lo))]
        side = own[max(m - 2, 0):m] if lo is not None else own[m:m + 2]
        if len(side) == 2 and max(abs(q - j) for q in side) <= 3:
            a, b = sorted(side, key=lambda q: abs(q - j))  # a nearer: r_a + t (r_a - r_b)
            t = (j - a) / (a - b)
            return [((i, a, k), 1 + t), ((i, b, k), -t)]
        best, dist = None, None
        for ci, ck in [(i, k), *par]:
            ev = self._ev.get((ci, ck))
            if not ev:
                continue
            n = bisect_left(ev, j)
            for q in ev[max(n - 1, 0):n + 1]:
                d = abs(q - j) + abs(ci - i) + abs(ck - k)
                if dist is None or d < dist:
                    best, dist = (ci, q, ck), d
        return [(best, 1.0)] if best is not None else []

    def _close(self):
        """Every open column resolved: its states from the known nodes (evaluated or agreed by
        its parents), constant between known nodes of one state (all columns at once)."""
        if not self._open:
            return
        ii, kk = (np.array(v) for v in zip(*self._open))
        out = self.states[ii, :, kk]
        for r, c in enumerate(self._open):  # a rechecked column: again from its evaluations
            if c in self._before:
                out[r, ~self.evaluated[c[0], :, c[1]]] = UNKNOWN
        idx = np.where(out != UNKNOWN, np.arange(out.shape[1])[None, :], -1)
        np.maximum.accumulate(idx, axis=1, out=idx)
        first = np.argmax(out != UNKNOWN, axis=1)
        idx = np.where(idx < 0, first[:, None], idx)
        out = np.take_along_axis(out, idx, axis=1)
        before = self._before
        for r, c in enumerate(self._open):  # check new columns; recheck around changed ones
            if c not in before:
                self._check.add(c)
            elif (before[c] != out[r]).any():
                self._check.update(self._neighbours(c))
        self._before = {}
        self.states[ii, :, kk] = out
        self._uni[ii, kk] = np.where((out == out[:, :1]).all(axis=1), out[:, 0], UNKNOWN - 1)
        self._sig.update(zip(self._open, _signatures(out)))
        self._open.clear()
        self._parents.clear()

    def _signature(self, c):
        u = int(self._uni[c])
        if u >= 0:
            return (u,)
        sig = self._sig.get(c)
        if sig is None:
            sig = self._sig[c] = _signatures(self.states[c[0], :, c[1]][None, :])[0]
        return sig

    def _neighbours(self, c):
        """The nearest resolved columns of ``c`` along -x, +x, -z, +z (those that exist)."""
        i, k = c
        out = []
        for line, at, mk in ((self.states[:, 0, k], i, lambda q: (q, k)),
                             (self.states[i, 0, :], k, lambda q: (i, q))):
            r = np.flatnonzero(line != UNKNOWN)
            m = np.searchsorted(r, at)
            if m > 0:
                out.append(mk(int(r[m - 1])))
            if m < len(r) and r[m] == at:
                m += 1
            if m < len(r):
                out.append(mk(int(r[m])))
        return out

    def _recheck(self) -> bool:
        """Resolved columns against their nearest resolved neighbours along x and z: a
        neighbour's change that the column does not match (no change of the same kind within
        three times their distance, at least two steps) is a pocket or sliver beside it, so
        the column's inferred nodes there are evaluated, and the middle of the runs of
        inferred nodes beside it where the two differ (a pocket narrowing towards the
        column); repeated on the neighbours of every column whose states change, and on a
        neighbour that does not match one of the column's changes."""
        check, self._check = self._check, set()
        for c in sorted(check):
            col = self.states[c[0], :, c[1]]
            if (col == UNKNOWN).any():
                continue
            ev = self.evaluated[c[0], :, c[1]]
            sc = self._signature(c)
            cc = None
            seeds = set()
            for q in self._neighbours(c):
                if self._signature(q) == sc:
                    continue  # the same sequence of states: explained by the column's own
                if cc is None:
                    cc = np.flatnonzero(col[1:] != col[:-1])
                p = self.states[q[0], :, q[1]]
                pc = np.flatnonzero(p[1:] != p[:-1])
                if len(pc) == len(cc) and (p[pc] == col[cc]).all() and \
                        (p[pc + 1] == col[cc + 1]).all() and p[0] == col[0]:
                    continue  # the same sequence of changes: explained by the column's own
                dmax = max(2, 3 * (abs(q[0] - c[0]) + abs(q[1] - c[1])))
                lone_p = _unmatched(p, pc, col, cc, dmax)
                eq = self.evaluated[q[0], :, q[1]]
                if any(p[j] == p[j + 1] and not (eq[j] and eq[j + 1])
                       for j in _unmatched(col, cc, p, pc, dmax)):
                    self._check.add(q)  # the neighbour lacks one of this column's changes
                if not lone_p:
                    continue
                for j in lone_p:
                    if col[j] == col[j + 1] and not (ev[j] and ev[j + 1]):
                        seeds.update(int(u) for u in (j, j + 1) if not ev[u])
                d = np.concatenate(([0], (p != col).astype(np.int8), [0]))
                e = np.flatnonzero(np.diff(d))
                for u, w in zip(e[::2], e[1::2]):  # runs [u, w) touching a lone change
                    if any(u - 1 <= j < w for j in lone_p):
                        free = np.flatnonzero(~ev[u:w]) + u  # its inferred node nearest
                        if free.size:                      # the middle
                            seeds.add(int(free[np.argmin(np.abs(free - 0.5 * (u + w - 1)))]))
            if seeds:
                known = {int(j): int(col[j]) for j in np.flatnonzero(ev)}
                self._open[c] = [known, set(), np.ones(len(col), bool), sorted(seeds)]
                self._kind[c] = "check"
                self._before[c] = col.copy()
        return bool(self._open)

    # -- the (x, z) quadtree -------------------------------------------------------------
    def _next_columns(self) -> bool:
        """Open the next columns: the centres of the cells split last (between their new edge
        columns), else split the active cells and open their edge columns."""
        if self._centres:
            new, self._centres = self._centres, []
            return self._open_columns(new)
        cells, edges, centres = [], [], []
        for cell in self.cells:
            x0, x1, z0, z1 = cell
            if x1 - x0 <= 1 and z1 - z0 <= 1:
                continue
            u = {int(self._uni[x, z]) for x in (x0, x1) for z in (z0, z1)}
            if len(u) == 1 and UNKNOWN not in u and UNKNOWN - 1 not in u:
                self._fill_cell(cell, u.pop())
                continue
            xm = (x0 + x1) // 2 if x1 - x0 > 1 else None
            zm = (z0 + z1) // 2 if z1 - z0 > 1 else None
            if xm is not None:
                edges += [((xm, z), ((x0, z), (x1, z))) for z in (z0, z1)]
            if zm is not None:
                edges += [((x, zm), ((x, z0), (x, z1))) for x in (x0, x1)]
            if xm is not None and zm is not None:
                centres.append(((xm, zm), ((x0, zm), (x1, zm))))
            xs = [(x0, xm), (xm, x1)] if xm is not None else [(x0, x1)]
            zs = [(z0, zm), (zm, z1)] if zm is not None else [(z0, z1)]
            cells += [(a, b, c, d) for a, b in xs for c, d in zs]
        self.cells = cells
        self._centres = centres
        if not edges and not centres:
            return False
        if not edges:
            new, self._centres = self._centres, []
            return self._open_columns(new)
        return self._open_columns(edges) or self._next_columns()

    def _fill_cell(self, cell, s):
        """A cell whose corner columns are one state end to end: its columns take it."""
        x0, x1, z0, z1 = cell
        blk = self.states[x0:x1 + 1, :, z0:z1 + 1]
        blk[blk == UNKNOWN] = s
        self._uni[x0:x1 + 1, z0:z1 + 1] = s

    def _open_columns(self, new) -> bool:
        """Open each new column (once) from its two parents: agreed nodes inferred, the rest
        uncertain with the crossings predicted (the mean of the parents' interpolated
        crossings, pairwise, where both have the same sequence of changes); True if any
        column needs evaluations. All columns' arrays at once."""
        sel = {}
        for c, par in new:
            if c not in sel and self.states[c[0], 0, c[1]] == UNKNOWN:
                sel[c] = par
        if not sel:
            return False
        cs = list(sel)
        ci, ck = (np.array(v) for v in zip(*cs))
        p1 = np.array([sel[c][0] for c in cs])
        p2 = np.array([sel[c][1] for c in cs])
        A = self.states[p1[:, 0], :, p1[:, 1]]
        B = self.states[p2[:, 0], :, p2[:, 1]]
        n = A.shape[1]
        chA, chB = A[:, 1:] != A[:, :-1], B[:, 1:] != B[:, :-1]
        ch = chA | chB | (A[:, 1:] != B[:, 1:])
        unc = A != B
        unc[:, 1:] |= ch
        unc[:, :-1] |= ch
        nb = np.zeros_like(unc)
        nb[:, :-1] = unc[:, 1:]
        nb[:, 1:] |= unc[:, :-1]
        nb &= ~unc
        self.states[ci, :, ck] = np.where(unc, UNKNOWN, A)
        done = ~unc.any(axis=1)
        rd = np.flatnonzero(done)
        self._check.update(cs[r] for r in rd)
        self._sig.update(zip((cs[r] for r in rd), _signatures(A[done])))
        self._uni[ci[done], ck[done]] = np.where((A[done] == A[done, :1]).all(axis=1),
                                                 A[done, 0], UNKNOWN - 1)
        na, nb_ = chA.sum(axis=1), chB.sum(axis=1)
        _, ja = np.nonzero(chA)
        _, jb = np.nonzero(chB)
        sa, sb = np.r_[0, np.cumsum(na)], np.r_[0, np.cumsum(nb_)]
        for r in np.flatnonzero(~done):
            c = cs[r]
            par = sel[c]
            ur = unc[r]
            known = {int(j): int(A[r, j]) for j in np.flatnonzero(nb[r])}
            pred = []
            if na[r] == nb_[r] and na[r]:
                xa, xb = ja[sa[r]:sa[r + 1]], jb[sb[r]:sb[r + 1]]
                if (A[r, xa] == B[r, xb]).all() and (A[r, xa + 1] == B[r, xb + 1]).all():
                    pred = [int(np.floor(0.5 * (self._frac(par[0], int(u))
                                                 + self._frac(par[1], int(w)))))
                            for u, w in zip(xa, xb)]
            seeds = sorted({j for q in pred for j in (q, q + 1) if 0 <= j < n and ur[j]})
            if not seeds:  # no prediction: start at the middle of each uncertain run
                runs = np.flatnonzero(np.diff(np.concatenate(([0], ur.astype(np.int8), [0]))))
                seeds = [int((a + e - 1) // 2) for a, e in zip(runs[::2], runs[1::2])]
            # an uncertain run at an end of the column has no inferred node beyond it to
            # bound it: its end node is evaluated too
            seeds = sorted(set(seeds) | {j for j in (0, n - 1) if ur[j]})
            self._open[c] = [known, set(known), ur, seeds]
            self._parents[c] = (par, pred)
        return bool(self._open)

    def _frac(self, col, j):
        """The crossing position (fine index) in [j, j + 1] of a resolved column: linear
        interpolation of max Re λ (the middle when a node failed)."""
        v0 = self.values.get((col[0], j, col[1]), np.nan)
        v1 = self.values.get((col[0], j + 1, col[1]), np.nan)
        if np.isfinite(v0) and np.isfinite(v1) and v0 != v1:
            return j + min(max(v0 / (v0 - v1), 0.0), 1.0 - 1e-9)
        return j + 0.5


def _signatures(rows) -> list:
    """Per profile (a row of states): its states run by run, a tuple."""
    rows = np.asarray(rows)
    r, j = np.nonzero(rows[:, 1:] != rows[:, :-1])
    after = rows[r, j + 1].tolist()
    cuts = np.searchsorted(r, np.arange(len(rows) + 1)).tolist()
    first = rows[:, 0].tolist()
    return [(first[t], *after[cuts[t]:cuts[t + 1]]) for t in range(len(rows))]


def _unmatched(p, pc, col, cc, dmax) -> list:
    """The changes of profile ``p`` (lower nodes ``pc``) with no change of the same kind
    (states below and above) in ``col`` (lower nodes ``cc``) within ``dmax`` nodes, each of
    ``col``'s changes matching one of ``p``'s at most (nearest first)."""
    free = [int(j) for j in cc]
    out = []
    for j in pc:
        best = None
        for t, jc in enumerate(free):
            if abs(jc - j) <= dmax and col[jc] == p[j] and col[jc + 1] == p[j + 1] and \
                    (best is None or abs(jc - j) < abs(free[best] - j)):
                best = t
        if best is None:
            out.append(int(j))
        else:
            free.pop(best)
    return out


def column_field(states, evaluated, values) -> np.ndarray:
    """A (nx, ny) field for the zero contour of one slice resolved by columns: max Re λ at the
    evaluated nodes, elsewhere the linear function of its column's nearest crossing (through
    the crossing's two evaluated nodes); ± the largest |max Re λ| of the slice at a node whose
    extrapolation has the wrong sign or whose column has no crossing with two values; NaN at
    failed and unresolved nodes. Its zero contour cuts each column between the two nodes of
    every crossing exactly where the dense column's linear interpolation does."""
    S, E, V = np.asarray(states), np.asarray(evaluated, bool), np.asarray(values, float)
    nx, ny = S.shape
    big = np.nanmax(np.abs(np.where(E, V, np.nan))) if E.any() else 1.0
    big = 1.0 if not np.isfinite(big) or big == 0 else big
    F = np.where(S == 0, -big, np.where(S == 1, big, np.nan))
    br = np.zeros((nx, ny), bool)  # lower node of a crossing with two values
    br[:, :-1] = (E[:, :-1] & E[:, 1:] & (S[:, :-1] != S[:, 1:]) & np.isfinite(V[:, :-1])
                  & np.isfinite(V[:, 1:]) & (S[:, :-1] != 2) & (S[:, 1:] != 2))
    if br.any():
        jj = np.arange(ny)[None, :]
        lo = np.where(br, jj, -1)
        np.maximum.accumulate(lo, axis=1, out=lo)  # last crossing at or below
        hi = np.where(br, jj, ny)
        hi = np.minimum.accumulate(hi[:, ::-1], axis=1)[:, ::-1]  # first at or above
        use_hi = (hi < ny) & ((lo < 0) | (hi - jj < jj - lo))
        b = np.where(use_hi, hi, lo)
        ok = b >= 0
        bi = np.clip(b, 0, ny - 2)
        ii = np.arange(nx)[:, None]
        v0, v1 = V[ii, bi], V[ii, bi + 1]
        G = v0 + (jj - bi) * (v1 - v0)
        good = ok & ((S == 0) & (G < 0) | (S == 1) & (G >= 0))
        F = np.where(good, G, F)
    F = np.where(E & np.isfinite(V), V, F)
    return np.where((S == 0) | (S == 1), F, np.nan)
