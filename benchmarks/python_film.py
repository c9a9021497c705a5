"""The system's film forces written in NumPy/SciPy only: a baseline for bench_control.py.

What a user without rotordyn's core would write to drive the rig from ``solve_ivp``: the same
finite-volume Reynolds equation as ``cpp/src/reynolds_setup.cpp`` (full grid, open ends at
p = 0, grooves as prescribed nodes, Couette and squeeze terms), the same Swift–Stieber
cavitation (p ≥ 0, A p − b ≥ 0, complementary) by the same primal–dual active-set iteration,
started from the last call's set, SuperLU (``scipy.sparse.linalg.splu``) for each linear
solve, and the forces by virtual work, H = Sᵀ ∫ p dz (eq. 12's film forces). The discrete
problem is the core's, so the forces agree with ``SystemSolver.film_forces`` to round-off
(``check_against_core``; tests/test_python_reference_film.py).

Open ends and ``cavitation='reynolds'`` films only (the paper rig); no tables, pads or seals.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu


class PythonFilm:
    """One film: the grid, its fixed nodes and its sparse pattern, built once."""

    def __init__(self, fc):
        g, grid = fc.geometry, fc.grid
        if fc.cavitation != "reynolds":
            raise ValueError(f"cavitation: expected 'reynolds', got {fc.cavitation!r}")
        if np.isfinite(g.end_seal_conductance) or g.short_bearing:
            raise ValueError("open ends and the finite-length film only")
        self.N, self.K1 = grid.n_circ, grid.n_axial + 1
        N, K1 = self.N, self.K1
        self.R, self.L, self.c, self.mu = 0.5 * g.diameter_m, g.length_m, g.clearance_m, g.viscosity_pa_s
        self.dphi, self.dz = 2 * np.pi / N, self.L / grid.n_axial
        self.coords = np.asarray(fc.coords)
        self.shape = np.asarray(fc.shape)  # (N, n_coords)
        self.base_h = np.asarray(fc.base_h)
        self.spin = fc.spin_factor
        fixed = np.zeros((N, K1), bool)
        pfix = np.zeros((N, K1))
        fixed[:, 0] = fixed[:, -1] = True
        for gv in g.grooves:
            centre = np.deg2rad(np.fmod(gv.center_deg, 360.0) % 360.0)
            half = 0.5 * np.deg2rad(gv.width_deg)
            cols = []
            if gv.width_deg > 0:
                d = np.remainder(np.arange(N) * self.dphi - centre + np.pi, 2 * np.pi) - np.pi
                cols = list(np.nonzero(np.abs(d) <= half * (1 + 1e-12) + 1e-12)[0])
            if not cols:
                cols = [int(np.rint(centre / self.dphi)) % N]
            for j in cols:
                fixed[j, 1:-1] = True
                pfix[j, 1:-1] = gv.pressure_pa
        self.fixed, self.pfix = fixed.ravel(), pfix.ravel()
        n_nodes = N * K1
        unk = np.full(n_nodes, -1)
        free = np.nonzero(~self.fixed)[0]
        unk[free] = np.arange(free.size)
        self.free, self.unk, self.n = free, unk, free.size
        node = np.arange(n_nodes)
        self.east = (node + K1) % n_nodes
        self.west = (node - K1) % n_nodes
        # 5-point pattern over the unknowns: (row, col, kind) with kind e/w/n/s; the values come
        # from the face conductances of the column's node.
        rows, cols, kinds = [], [], []
        for kind, nb in (("e", self.east[free]), ("w", self.west[free]),
                         ("n", free + 1), ("s", free - 1)):
            ok = unk[nb] >= 0
            rows.append(unk[nb[ok]])
            cols.append(np.nonzero(ok)[0])
            kinds.append(np.full(ok.sum(), "ewns".index(kind)))
        rows, cols, kinds = map(np.concatenate, (rows, cols, kinds))
        self.off_rows, self.off_cols, self.off_kind = rows, cols, kinds
        # CSC structure of [diagonal; couplings] built once: each call only permutes values
        n = free.size
        all_r = np.concatenate([np.arange(n), rows])
        all_c = np.concatenate([np.arange(n), cols])
        self.order = np.lexsort((all_r, all_c))
        self.indices = all_r[self.order].astype(np.int32)
        self.indptr = np.searchsorted(all_c[self.order], np.arange(n + 1)).astype(np.int32)
        self.ent_r, self.ent_c = all_r, all_c
        wz = np.full(K1, self.R * self.dphi * self.dz)
        wz[0] *= 0.5
        wz[-1] *= 0.5
        self.wz = wz
        self.active = None  # the last converged cavitation set (continuation)

    def pressure(self, h, hdot, omega):
        """Node pressures (N·K1,) of the Swift–Stieber film for node arrays h, hdot (m, m/s)."""
        N, K1 = self.N, self.K1
        h2, hd = h.reshape(N, K1), hdot.reshape(N, K1)
        he = 0.5 * (h2 + np.roll(h2, -1, axis=0))
        cE = (self.dz / (12 * self.mu * self.R * self.dphi) * he**3).ravel()
        qE = (0.5 * omega * self.R * self.dz * he).ravel()
        src = (self.R * self.dphi * self.dz * hd).ravel()
        hn = 0.5 * (h2[:, :-1] + h2[:, 1:])
        cN = np.zeros((N, K1))
        cN[:, :-1] = self.R * self.dphi / (12 * self.mu * self.dz) * hn**3
        cN = cN.ravel()
        f, e, w = self.free, self.east[self.free], self.west[self.free]
        diag = cE[f] + cE[w] + cN[f] + cN[f - 1]
        b = -(qE[f] - qE[w]) - src[f]
        pf, fx = self.pfix, self.fixed
        b += np.where(fx[e], cE[f] * pf[e], 0.0) + np.where(fx[w], cE[w] * pf[w], 0.0)
        b += np.where(fx[f + 1], cN[f] * pf[f + 1], 0.0) + np.where(fx[f - 1], cN[f - 1] * pf[f - 1], 0.0)
        # coupling value of entry (row = neighbour unknown, col = i): −conductance of the shared face
        fc = f[self.off_cols]
        face = np.select([self.off_kind == 0, self.off_kind == 1, self.off_kind == 2],
                         [cE[fc], cE[self.west[fc]], cN[fc]], cN[fc - 1])
        n = self.n
        vals = np.concatenate([diag, -face])
        A_full = sp.csc_matrix((vals[self.order], self.indices, self.indptr), shape=(n, n))
        act = np.zeros(n, bool) if self.active is None else self.active.copy()
        bscale = np.abs(b).max()
        pfix_scale = np.abs(pf).max()
        for _ in range(100 + n // 4):
            # cavitated unknowns decoupled in place (unit row and column, p = 0)
            cut = act[self.ent_r] | act[self.ent_c]
            v = np.where(cut, 0.0, vals)
            v[:n] = np.where(act, 1.0, diag)
            A = sp.csc_matrix((v[self.order], self.indices, self.indptr), shape=(n, n))
            lu = splu(A, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                      options=dict(SymmetricMode=True))
            p = lu.solve(np.where(act, 0.0, b))
            p[act] = 0.0
            mu_ = A_full @ p - b
            pscale = max(pfix_scale, np.abs(p).max())
            nxt = np.where(act, mu_ >= -1e-13 * bscale, p < -1e-13 * pscale)
            if np.array_equal(nxt, act):
                self.active = act
                out = pf.copy()
                out[f] = p
                return out
            act = nxt
        raise RuntimeError("active set did not converge")

    def forces(self, r, v, omega):
        """Generalised film forces on the film's coordinates, (n_coords,)."""
        rc, vc = r[self.coords], v[self.coords]
        sphi, vphi = self.shape @ rc, self.shape @ vc
        if self.base_h.size == 0:
            h = np.repeat((sphi + self.c)[:, None], self.K1, axis=1)
        elif self.base_h.shape[1] == 1:
            h = np.repeat((self.base_h[:, 0] + sphi)[:, None], self.K1, axis=1)
        else:
            h = self.base_h + sphi[:, None]
        if not h.min() > 0:
            raise RuntimeError("contact")
        hdot = np.repeat(vphi[:, None], self.K1, axis=1)
        p = self.pressure(h.ravel(), hdot.ravel(), self.spin * omega).reshape(self.N, self.K1)
        return self.shape.T @ (p @ self.wz)


class PythonFilmForces:
    """H(r, ṙ, Ω) of the whole system (films only), like ``SystemSolver.film_forces``."""

    def __init__(self, model):
        if len(model.tables) or len(model.pad_coords):
            raise ValueError("films only (no tables or pads)")
        self.n = np.asarray(model.M).shape[0]
        self.films = [PythonFilm(fc) for fc in model.films]

    def __call__(self, r, v, omega):
        H = np.zeros(self.n)
        for f in self.films:
            H[f.coords] += f.forces(r, v, omega)
        return H


def check_against_core(solver, forces, states, omega):
    """Largest |H_python − H_core| / max|H_core| over ``states`` ((r, v) pairs)."""
    worst = 0.0
    for r, v in states:
        hc = np.asarray(solver.film_forces(r, v, omega))
        hp = forces(r, v, omega)
        worst = max(worst, np.abs(hp - hc).max() / np.abs(hc).max())
    return worst
