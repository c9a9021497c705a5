"""Benchmark: Reynolds solver (force evaluation and K, C set) vs a SciPy implementation of the
same discretisation, and ROSS's fluid-film bearing when ``ross`` is importable.

Run ``python benchmarks/bench_reynolds.py [--repeat 5] [--points 32]``. For every grid
(36×8, 72×16, 144×32) and cavitation model it prints the median time

* per force evaluation along a small orbit (radius 2 % of c) around the operating point, so
  each call is warm-started from the previous one as in an equilibrium iteration, transient or
  sweep ("warm"), and with the warm start reset before every call ("cold");
* per (K, C) set by the perturbation method (one factorisation, four right-hand sides);
* the same two figures with the exact axial-symmetry reduction switched off ("full grid"):
  the aligned rigid journal has a film symmetric about z = 0, which the solver detects and
  solves on the half grid; the SciPy baseline always solves the full grid;

next to the SciPy baseline (scipy.sparse assembly, SuperLU factorisation, the same primal–dual
active set / p–θ iteration in Python; checked against the C++ forces in the same run), both
on one thread. Structure follows asv (``params`` × ``param_names``) with a warm-up call.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
import scipy.sparse.linalg as spla  # noqa: E402

import rotordyn  # noqa: E402

D, L, C_RAD, MU, SPEED_HZ = 0.05, 0.04, 3e-4, 0.04, 50.0
POS = (1.0e-4, -1.5e-4)  # operating point, m (eccentricity ratio 0.60)
GROOVES = [rotordyn.Groove(90.0, 0.0, 0.0)]

params = ([(36, 8), (72, 16), (144, 32)], ["gumbel", "reynolds", "jfo"])
param_names = ("grid", "cavitation")


class ScipyReynolds:
    """The C++ discretisation (node-centred finite volumes, face-averaged h) in NumPy/SciPy."""

    def __init__(self, n_circ, n_axial, cavitation, groove_deg=90.0):
        self.N, self.K1 = n_circ, n_axial + 1
        self.cav = cavitation
        self.R = D / 2
        self.dphi = 2 * math.pi / n_circ
        self.dz = L / n_axial
        self.phi = np.arange(n_circ) * self.dphi
        fixed = np.zeros((self.N, self.K1), bool)
        fixed[:, 0] = fixed[:, -1] = True
        self.groove = np.zeros_like(fixed)
        jg = int(round(math.radians(groove_deg) / self.dphi)) % n_circ
        self.groove[jg, 1:-1] = True
        fixed |= self.groove
        self.fixed = fixed
        self.unk = -np.ones((self.N, self.K1), int)
        self.unk[~fixed] = np.arange((~fixed).sum())
        self.n = int((~fixed).sum())
        self.jj, self.kk = np.nonzero(~fixed)
        self.wk = np.ones(self.K1)
        self.wk[[0, -1]] = 0.5
        self.active = None

    def film(self, x, y, vx, vy, omega):
        cphi, sphi = np.cos(self.phi), np.sin(self.phi)
        h = np.repeat((C_RAD - x * cphi - y * sphi)[:, None], self.K1, 1)
        hd = np.repeat((-vx * cphi - vy * sphi)[:, None], self.K1, 1)
        return h, hd

    def operator(self, h, hd, omega):
        he = 0.5 * (h + np.roll(h, -1, 0))
        cE = he**3 / (12 * MU) * self.dz / (self.R * self.dphi)
        hn = 0.5 * (h[:, :-1] + h[:, 1:])
        cN = np.zeros_like(h)
        cN[:, :-1] = hn**3 / (12 * MU) * self.R * self.dphi / self.dz
        qE = 0.5 * omega * self.R * self.dz * he
        src = self.R * self.dphi * self.dz * hd
        j, k = self.jj, self.kk
        jp, jm = (j + 1) % self.N, (j - 1) % self.N
        i = self.unk[j, k]
        diag = cE[j, k] + cE[jm, k] + cN[j, k] + cN[j, k - 1]
        rows, cols, vals = [i], [i], [diag]
        for (jn, kn, cf) in ((jp, k, cE[j, k]), (jm, k, cE[jm, k]), (j, k + 1, cN[j, k]),
                             (j, k - 1, cN[j, k - 1])):
            nb = self.unk[jn, kn]
            m = nb >= 0
            rows.append(i[m])
            cols.append(nb[m])
            vals.append(-cf[m])
        A = sp.csc_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(self.n, self.n))
        b = -(qE[j, k] - qE[jm, k]) - src[j, k]  # groove and end pressures are 0 here
        # Couette column of r = 1 - θ (ω > 0): -(qE + src) on the diagonal, +qE downstream
        nbE = self.unk[jp, k]
        m = nbE >= 0
        B = sp.csc_matrix(
            (np.concatenate([-(qE[j, k] + src[j, k]), qE[j, k][m]]),
             (np.concatenate([i, nbE[m]]), np.concatenate([i, i[m]]))), shape=(self.n, self.n))
        return A, B, b

    def solve(self, x, y, vx, vy, omega):
        h, hd = self.film(x, y, vx, vy, omega)
        A, B, b = self.operator(h, hd, omega)
        n = self.n
        if self.cav == "gumbel":
            lu = spla.splu(A)
            u = lu.solve(b)
            p = np.maximum(u, 0.0)
            self.state = (lu, A, B, u > 0, h)
            self.u_lin, self.theta_unk = u, np.ones(n)
        else:
            act = np.zeros(n, bool) if self.active is None else self.active.copy()
            for _ in range(200):  # Swift–Stieber primal–dual active set
                ina = ~act
                lu = spla.splu(sp.csc_matrix(A[ina][:, ina]))
                p = np.zeros(n)
                p[ina] = lu.solve(b[ina])
                mu_ = A @ p - b
                new = np.where(act, mu_ >= -1e-13 * np.abs(b).max(), p < -1e-13 * np.abs(p).max())
                if np.array_equal(new, act):
                    break
                act = new
            if self.cav == "jfo":  # p–θ partition, started from the Swift–Stieber set
                for _ in range(200):
                    M = A @ sp.diags((~act).astype(float)) + B @ sp.diags(act.astype(float))
                    lu = spla.splu(sp.csc_matrix(M))
                    u = lu.solve(b)
                    new = np.where(act, u >= -1e-13, u < -1e-13 * np.abs(u).max())
                    if np.array_equal(new, act):
                        break
                    act = new
                p = np.where(act, 0.0, u)
                self.theta_unk = np.where(act, 1.0 - u, 1.0)
            else:
                self.theta_unk = np.ones(n)
            self.u_lin = p
            self.active = act
            self.state = (lu, A, B, ~act, h)
        P = np.zeros((self.N, self.K1))
        P[self.jj, self.kk] = p
        return self.force(P), P

    def force(self, P):
        a = self.R * self.dphi * self.dz
        return -a * np.array([np.sum(P * np.cos(self.phi)[:, None] * self.wk),
                              np.sum(P * np.sin(self.phi)[:, None] * self.wk)])

    def coefficients(self, x, y, omega):
        """K, C by the same perturbation solve (frozen set, shared factorisation)."""
        self.solve(x, y, 0.0, 0.0, omega)
        lu, A, B, free, h = self.state
        P = np.zeros((self.N, self.K1))
        P[self.jj, self.kk] = self.u_lin  # linearisation point: unclipped for gumbel
        th = np.ones((self.N, self.K1))
        th[self.jj, self.kk] = self.theta_unk
        trig = (-np.cos(self.phi)[:, None] * np.ones(self.K1), -np.sin(self.phi)[:, None]
                * np.ones(self.K1))
        zero = np.zeros_like(h)
        cols = []
        for dh, dhd in ((trig[0], zero), (trig[1], zero), (zero, trig[0]), (zero, trig[1])):
            r = self.residual_derivative(h, dh, dhd, P, th, omega)
            if self.cav == "reynolds":
                dp = np.zeros(self.n)
                dp[free] = lu.solve(-r[free])
            else:
                dp = lu.solve(-r)
                dp[~free] = 0.0
            DP = np.zeros((self.N, self.K1))
            DP[self.jj, self.kk] = dp
            cols.append(-self.force(DP))
        return np.column_stack(cols[:2]), np.column_stack(cols[2:])

    def residual_derivative(self, h, dh, dhd, P, th, omega):
        """d/dt of the cell balances at fixed (p, θ) for h + t·dh, ∂h/∂t + t·dhd."""
        he = 0.5 * (h + np.roll(h, -1, 0))
        dhe = 0.5 * (dh + np.roll(dh, -1, 0))
        dcE = 3 * he**2 * dhe / (12 * MU) * self.dz / (self.R * self.dphi)
        dcN = np.zeros_like(h)
        dcN[:, :-1] = (3 * (0.5 * (h[:, :-1] + h[:, 1:])) ** 2 * 0.5 * (dh[:, :-1] + dh[:, 1:])
                       / (12 * MU) * self.R * self.dphi / self.dz)
        dqE = 0.5 * omega * self.R * self.dz * dhe
        dsrc = self.R * self.dphi * self.dz * dhd
        j, k = self.jj, self.kk
        jp, jm = (j + 1) % self.N, (j - 1) % self.N
        return (dcE[j, k] * (P[j, k] - P[jp, k]) + dcE[jm, k] * (P[j, k] - P[jm, k])
                + dcN[j, k] * (P[j, k] - P[j, k + 1]) + dcN[j, k - 1] * (P[j, k] - P[j, k - 1])
                + dqE[j, k] * th[j, k] - dqE[jm, k] * th[jm, k] + dsrc[j, k] * th[j, k])


def orbit(n_points):
    a = np.linspace(0, 2 * math.pi, n_points, endpoint=False)
    r = 0.02 * C_RAD
    return [(POS[0] + r * math.cos(t), POS[1] + r * math.sin(t)) for t in a]


CLOCK = time.thread_time  # CPU time of this thread (the machine may be shared); --wall for wall


def median_time(fn, points, repeat):
    fn(*points[0])  # warm-up
    per = []
    for _ in range(repeat):
        t0 = CLOCK()
        for q in points:
            fn(*q)
        per.append((CLOCK() - t0) / len(points))
    return statistics.median(per)


ROSS_SNIPPET = r"""
import json, math, statistics, sys, time, warnings
warnings.filterwarnings("ignore")
from ross.bearings.fluid_flow import FluidFlow
from ross.bearings.fluid_flow_coefficients import (calculate_oil_film_force,
    calculate_stiffness_and_damping_coefficients)
D, L, c, mu, f, x, y, nc, na, repeat = (float(a) for a in sys.argv[1:])
nc, na, repeat = int(nc), int(na), int(repeat)
R, omega = D / 2, 2 * math.pi * f
def force():
    ff = FluidFlow(nz=na + 1, ntheta=nc + 1, length=L, omega=omega, p_in=0.0, p_out=0.0,
                   radius_rotor=R, radius_stator=R + c, viscosity=mu, density=860.0,
                   eccentricity=math.hypot(x, y), attitude_angle=math.pi / 4,
                   immediately_calculate_pressure_matrix_numerically=False)
    ff.calculate_pressure_matrix_numerical()
    return ff, calculate_oil_film_force(ff, force_type="numerical")
tf, tk = [], []
for _ in range(repeat):
    t0 = time.perf_counter(); ff, F = force(); tf.append(time.perf_counter() - t0)
for _ in range(max(1, repeat // 2)):
    t0 = time.perf_counter(); calculate_stiffness_and_damping_coefficients(ff)
    tk.append(time.perf_counter() - t0)
print(json.dumps({"force_s": statistics.median(tf), "kc_s": statistics.median(tk),
                  "force_n": float(math.hypot(F[0], F[1]))}))
"""


def bench_ross(n_circ, n_axial, repeat, ross_python=None):
    """ROSS 2.x ``FluidFlow`` (finite differences, solve-then-clip film, pure Python assembly) on
    the same bearing and grid, no groove; run in-process if ``ross`` imports, else in the
    interpreter ``ross_python`` (a separate venv, since ROSS is never our dependency)."""
    import json
    import subprocess

    exe = None
    try:
        import ross  # noqa: F401

        exe = sys.executable
    except Exception:
        exe = ross_python
    if exe is None:
        return None
    args = [str(v) for v in (D, L, C_RAD, MU, SPEED_HZ, *POS, n_circ, n_axial, repeat)]
    r = subprocess.run([exe, "-c", ROSS_SNIPPET, *args], capture_output=True, text=True,
                       timeout=3600)
    if r.returncode != 0:
        return {"error": r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "failed"}
    return json.loads(r.stdout.strip().splitlines()[-1])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--points", type=int, default=32, help="orbit points per repeat")
    ap.add_argument("--no-scipy", action="store_true")
    ap.add_argument("--wall", action="store_true", help="wall-clock instead of thread CPU time")
    ap.add_argument("--ross-python", default=None,
                    help="python of a venv with ross-rotordynamics (used if ross is not importable)")
    args = ap.parse_args(argv)
    global CLOCK
    if args.wall:
        CLOCK = time.perf_counter
    omega = 2 * math.pi * SPEED_HZ
    pts = orbit(args.points)
    print(f"rotordyn {rotordyn.__version__}; D={D} L={L} c={C_RAD} mu={MU} speed={SPEED_HZ} Hz, "
          f"journal at {POS} m, one supply line at 90 deg; times are medians of {args.repeat} "
          f"repeats x {args.points} orbit points, one thread, "
          f"{'wall-clock' if args.wall else 'thread CPU'} time")
    hdr = (f"{'grid':>8} {'model':>9} | {'force warm':>10} {'force cold':>10} {'K,C':>9} | "
           f"{'full-grid F':>10} {'KC':>9} | "
           f"{'scipy F':>9} {'scipy KC':>9} {'x F':>6} {'x KC':>6} | {'max|dF|/|F|':>11}")
    print(hdr)
    print("-" * len(hdr))
    for grid in params[0]:
        for cav in params[1]:
            b = rotordyn.JournalBearing(diameter_m=D, length_m=L, clearance_m=C_RAD,
                                        viscosity_pa_s=MU, n_circ=grid[0], n_axial=grid[1],
                                        cavitation=cav, grooves=GROOVES)
            s = b.solver()
            t_warm = median_time(lambda x, y: s.force(x, y, 0.0, 0.0, omega), pts, args.repeat)

            def cold(x, y):
                s.reset()
                s.force(x, y, 0.0, 0.0, omega)

            t_cold = median_time(cold, pts, args.repeat)
            t_kc = median_time(lambda x, y: s.coefficients(x, y, omega), pts, args.repeat)
            # the same without the exact axial-symmetry reduction (full grid, as SciPy does)
            s.use_axial_symmetry = False
            s.reset()
            t_full = median_time(lambda x, y: s.force(x, y, 0.0, 0.0, omega), pts, args.repeat)
            t_kc_full = median_time(lambda x, y: s.coefficients(x, y, omega), pts, args.repeat)
            s.use_axial_symmetry = True
            s.reset()
            line = (f"{grid[0]:>4}x{grid[1]:<3} {cav:>9} | {t_warm * 1e6:>8.0f}us "
                    f"{t_cold * 1e6:>8.0f}us {t_kc * 1e6:>7.0f}us | {t_full * 1e6:>8.0f}us "
                    f"{t_kc_full * 1e6:>7.0f}us |")
            if not args.no_scipy:
                ref = ScipyReynolds(grid[0], grid[1], cav)
                sp_pts = pts[: max(4, len(pts) // 4)]
                reps = max(1, args.repeat // 2)
                t_sf = median_time(lambda x, y: ref.solve(x, y, 0.0, 0.0, omega), sp_pts, reps)
                t_skc = median_time(lambda x, y: ref.coefficients(x, y, omega), sp_pts, reps)
                f_py, _ = ref.solve(*POS, 0.0, 0.0, omega)
                f_c = s.force(*POS, 0.0, 0.0, omega)
                dev = np.linalg.norm(f_py - f_c) / np.linalg.norm(f_c)
                K_py, C_py = ref.coefficients(*POS, omega)
                K_c, C_c = b.coefficients(x_m=POS[0], y_m=POS[1], speed_hz=SPEED_HZ)
                dev = max(dev, np.abs(K_py - K_c).max() / np.abs(K_c).max(),
                          np.abs(C_py - C_c).max() / np.abs(C_c).max())
                line += (f" {t_sf * 1e6:>7.0f}us {t_skc * 1e6:>7.0f}us {t_sf / t_warm:>5.0f}x "
                         f"{t_skc / t_kc:>5.0f}x | {dev:>11.1e}")
            print(line, flush=True)
    rows = []
    for grid in params[0][:2]:
        res = bench_ross(grid[0], grid[1], args.repeat, args.ross_python)
        if res is None:
            print("ROSS: not importable and no --ross-python given; skipped")
            break
        if "error" in res:
            print(f"ROSS {grid}: failed: {res['error']}")
            continue
        b = rotordyn.JournalBearing(diameter_m=D, length_m=L, clearance_m=C_RAD,
                                    viscosity_pa_s=MU, n_circ=grid[0], n_axial=grid[1],
                                    cavitation="gumbel")
        s = b.solver()
        t_f = median_time(lambda x, y: s.force(x, y, 0.0, 0.0, omega), pts, args.repeat)
        t_k = median_time(lambda x, y: s.coefficients(x, y, omega), pts, args.repeat)
        f_ours = np.linalg.norm(b.forces(x_m=POS[0], y_m=POS[1], speed_hz=SPEED_HZ))
        rows.append((grid, res, t_f, t_k, f_ours))
    for grid, res, t_f, t_k, f_ours in rows:
        print(f"ROSS FluidFlow {grid[0]}x{grid[1]} (wall time, new object per point, no groove): "
              f"force {res['force_s'] * 1e3:.1f} ms vs ours (gumbel) {t_f * 1e6:.0f} us "
              f"({res['force_s'] / t_f:.0f}x); K,C {res['kc_s'] * 1e3:.0f} ms vs {t_k * 1e6:.0f} us "
              f"({res['kc_s'] / t_k:.0f}x); |F| ROSS {res['force_n']:.1f} N, ours {f_ours:.1f} N")
    return 0


if __name__ == "__main__":
    sys.exit(main())
