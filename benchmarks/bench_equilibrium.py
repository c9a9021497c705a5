"""Benchmark: one full static equilibrium (paper eq. 14) of the paper's rig, cold and warm.

Run ``python benchmarks/bench_equilibrium.py [--repeat 9] [--wall] [--no-scipy]``. Operating
points: W = 50 Hz, a_y = −1.85 mm, p_c from the ``params`` grid (Table 1's pressures), film
grid 72 × 16 (the rig's default), one thread. For each it prints the median time and the
count of Reynolds solves of

* Newton from a **cold** start (``warm_start=False``: concentric journal, undeformed sleeve);
* Newton from a **warm** start: the equilibrium at 0.99 p_c is solved (untimed) just before,
  then the timed call at p_c starts from it (a sweep or a continuation step);
* the same two through the C++ ``SystemSolver.equilibrium`` directly (no Python wrapper);

and, as baselines measured in the same run,

* the paper's successive substitution (eq. 16, automatic P_m) cold and warm — the method the
  paper used;
* the same damped Newton written in NumPy around a SciPy sparse Reynolds solve (the
  ``ScipyReynolds`` finite-volume discretisation of benchmarks/bench_reynolds.py, with the
  system's film-thickness shapes, Swift–Stieber active set, SuperLU, perturbation K_H), warm
  start; its equilibrium is checked against ours in the same run.

Goal (issue 4): a warm-started equilibrium of the rig under 2 ms on one core.
Structure follows asv (``params`` × ``param_names``) with a warm-up call.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
from _common import footer, header  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn import _core  # noqa: E402
from rotordyn.analysis.assembly import assembled  # noqa: E402

params = ([0.10e6, 0.15e6, 0.20e6, 0.25e6],)
param_names = ("chamber_pressure_pa",)
SPEED_HZ, AY_M = 50.0, -1.85e-3
CLOCK = time.thread_time  # CPU time of this thread (the machine is shared); --wall for wall


TOTALS = {"wall": 0.0, "cpu": 0.0}  # every timed call, both clocks (printed at the end)


def timed(fn):
    t0, w0, c0 = CLOCK(), time.perf_counter(), time.process_time()
    out = fn()
    t = CLOCK() - t0
    TOTALS["wall"] += time.perf_counter() - w0
    TOTALS["cpu"] += time.process_time() - c0
    return t, out


def median_of(repeat, setup, fn):
    """Median over ``repeat`` of the time of fn() after an untimed setup(); plus the last
    result. One untimed warm-up round first."""
    setup()
    fn()
    ts, out = [], None
    for _ in range(repeat):
        setup()
        t, out = timed(fn)
        ts.append(t)
    return statistics.median(ts), out


class ScipyNewton:
    """The C++ damped Newton (line search on ‖R‖∞, Jacobian K + K_H) in NumPy around the
    SciPy Reynolds solve of bench_reynolds.py, on the rig's assembled model."""

    def __init__(self, asm):
        from bench_reynolds import ScipyReynolds  # same discretisation, groove at 90°

        self.asm = asm
        f = asm.model.films[0]
        self.coords = list(f.coords)
        self.shape = np.asarray(f.shape)  # (n_circ, n_coords): ∂h/∂r_k
        g = f.grid
        self.ref = ScipyReynolds(g.n_circ, g.n_axial, f.cavitation)
        self.K = np.asarray(asm.model.K)
        self.Q = np.asarray(asm.model.Q)
        self.ch = np.asarray(asm.model.chamber)
        self.c = f.geometry.clearance_m
        self.solves = 0

    def _film(self, r):
        h1 = self.c + self.shape @ r[self.coords]
        return np.repeat(h1[:, None], self.ref.K1, 1)

    def forces(self, r, omega):
        ref = self.ref
        h = self._film(r)
        A, B, b = ref.operator(h, np.zeros_like(h), omega)
        import scipy.sparse as sp
        import scipy.sparse.linalg as spla

        n = ref.n
        act = np.zeros(n, bool) if ref.active is None else ref.active.copy()
        for _ in range(200):  # Swift–Stieber primal–dual active set (as bench_reynolds)
            ina = ~act
            lu = spla.splu(sp.csc_matrix(A[ina][:, ina]))
            p = np.zeros(n)
            p[ina] = lu.solve(b[ina])
            mu_ = A @ p - b
            new = np.where(act, mu_ >= -1e-13 * np.abs(b).max(), p < -1e-13 * np.abs(p).max())
            if np.array_equal(new, act):
                break
            act = new
        ref.active = act
        self.solves += 1
        self.state = (lu, ~act, h, p, omega)
        P = np.zeros((ref.N, ref.K1))
        P[ref.jj, ref.kk] = p
        H = np.zeros(len(r))
        H[self.coords] = self._integrate(P)
        return H

    def _integrate(self, P):
        ref = self.ref
        g = (P * ref.wk).sum(1) * ref.R * ref.dphi * ref.dz
        return self.shape.T @ g

    def stiffness(self):
        ref = self.ref
        lu, free, h, p, omega = self.state
        P = np.zeros((ref.N, ref.K1))
        P[ref.jj, ref.kk] = p
        th = np.ones((ref.N, ref.K1))
        zero = np.zeros_like(h)
        n = len(self.K)
        KH = np.zeros((n, n))
        for j, cj in enumerate(self.coords):
            dh = np.repeat(self.shape[:, j:j + 1], ref.K1, 1)
            rr = ref.residual_derivative(h, dh, zero, P, th, omega)
            dp = np.zeros(ref.n)
            dp[free] = lu.solve(-rr[free])
            DP = np.zeros((ref.N, ref.K1))
            DP[ref.jj, ref.kk] = dp
            KH[self.coords, cj] = -self._integrate(DP)
        return KH

    def equilibrium(self, pc, a, r0, omega, tol=1e-10, max_iter=100):
        F = self.Q + pc * self.ch - self.K @ a
        scale = max(np.abs(self.Q).max(), np.abs(self.K @ a).max(), np.abs(pc * self.ch).max())
        r = r0.copy()
        H = self.forces(r, omega)
        R = self.K @ r - H - F
        res = np.abs(R).max() / scale
        it = 0
        while res >= tol and it < max_iter:
            dr = np.linalg.solve(self.K + self.stiffness(), -R)
            t = 1.0
            for _ in range(40):
                rt = r + t * dr
                Ht = self.forces(rt, omega)
                Rt = self.K @ rt - Ht - F
                rest = np.abs(Rt).max() / scale
                if rest <= (1 - 1e-4 * t) * res or rest < tol:
                    break
                t *= 0.5
            r, H, R, res = rt, Ht, Rt, rest
            it += 1
        return r, it, res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=9)
    ap.add_argument("--wall", action="store_true", help="wall-clock instead of thread CPU time")
    ap.add_argument("--no-scipy", action="store_true", help="skip the SciPy Newton baseline")
    ap.add_argument("--no-successive", action="store_true",
                    help="skip the successive-substitution baseline (about 0.5 s per call)")
    args = ap.parse_args(argv)
    global CLOCK
    if args.wall:
        CLOCK = time.perf_counter
    header("bench_equilibrium: the rig's static equilibrium (Newton vs successive vs SciPy)")
    rig = rd.models.paper_rig()
    asm = assembled(rig)
    a = asm.config_vector(AY_M)
    omega = 2 * np.pi * SPEED_HZ
    b = rig.bearings[0]
    print(f"rotordyn {rd.__version__}; paper rig, W = {SPEED_HZ} Hz, a_y = {AY_M * 1e3} mm, "
          f"film {b.n_circ}x{b.n_axial} ({b.cavitation}), {asm.n} coordinates; medians of "
          f"{args.repeat}, one thread, {'wall-clock' if args.wall else 'thread CPU'} time; "
          "'solves' = Reynolds solves of the timed call")
    hdr = (f"{'p_c MPa':>7} | {'Newton cold':>11} {'solves':>6} | {'warm':>9} {'solves':>6} | "
           f"{'C++ cold':>9} {'C++ warm':>9} | {'successive cold':>15} {'solves':>6} "
           f"{'warm':>9} {'solves':>6} | {'SciPy Newton warm':>17} {'solves':>6} {'ratio':>6}"
           f" {'|dr|/c':>8}")
    print(hdr)
    print("-" * len(hdr))
    opt = _core.EquilibriumOptions()
    warm_times = []
    for pc in params[0]:
        pc0 = 0.99 * pc
        t_cold, e_cold = median_of(args.repeat, lambda: None, lambda: rd.equilibrium(
            rig, SPEED_HZ, pc, AY_M, warm_start=False))
        t_warm, e_warm = median_of(
            args.repeat, lambda: rd.equilibrium(rig, SPEED_HZ, pc0, AY_M, warm_start=False),
            lambda: rd.equilibrium(rig, SPEED_HZ, pc, AY_M))
        warm_times.append(t_warm)
        r_prev = rd.equilibrium(rig, SPEED_HZ, pc0, AY_M, warm_start=False).r
        t_ccold, _ = median_of(args.repeat, lambda: None, lambda: asm.solver.equilibrium(
            omega, pc, a, np.zeros(0), opt))
        t_cwarm, _ = median_of(args.repeat, lambda: asm.solver.equilibrium(
            omega, pc0, a, np.zeros(0), opt), lambda: asm.solver.equilibrium(
            omega, pc, a, r_prev, opt))
        line = (f"{pc / 1e6:7.2f} | {t_cold * 1e3:8.3f} ms {e_cold.reynolds_solves:6d} | "
                f"{t_warm * 1e3:6.3f} ms {e_warm.reynolds_solves:6d} | {t_ccold * 1e3:6.3f} ms "
                f"{t_cwarm * 1e3:6.3f} ms |")
        if not args.no_successive:
            reps = max(1, min(3, args.repeat))
            t_sc, s_c = median_of(reps, lambda: None, lambda: rd.equilibrium(
                rig, SPEED_HZ, pc, AY_M, method="successive", warm_start=False))
            t_sw, s_w = median_of(reps, lambda: None, lambda: rd.equilibrium(
                rig, SPEED_HZ, pc, AY_M, method="successive", r0=r_prev))
            line += (f" {t_sc * 1e3:12.1f} ms {s_c.reynolds_solves:6d} {t_sw * 1e3:6.1f} ms "
                     f"{s_w.reynolds_solves:6d} |")
        else:
            line += f" {'-':>15} {'-':>6} {'-':>9} {'-':>6} |"
        if not args.no_scipy:
            sn = ScipyNewton(asm)
            reps = max(1, min(5, args.repeat))

            def sc_setup():
                sn.ref.active = None
                sn.equilibrium(pc0, a, np.zeros(asm.n), omega)
                sn.solves = 0

            t_sp, (r_sp, it_sp, res_sp) = median_of(
                reps, sc_setup, lambda: sn.equilibrium(pc, a, r_prev, omega))
            dr = np.abs(r_sp - e_warm.r).max() / b.clearance_m
            line += (f" {t_sp * 1e3:14.2f} ms {sn.solves:6d} "
                     f"{t_sp / t_warm:5.0f}x {dr:8.1e}")
        print(line, flush=True)
    print(f"\nwarm-started Newton, median over the pressures: {statistics.median(warm_times) * 1e3:.3f}"
          f" ms (goal < 2 ms)")
    print(f"all timed calls: {TOTALS['wall']:.3f} s wall, {TOTALS['cpu']:.3f} s CPU of the "
          "process (the table is in the clock named above; wall >> CPU means a busy machine)")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
