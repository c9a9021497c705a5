"""Benchmark: Reynolds solver (force and (K, C) set) — cycled positions before/after the
cavitation-set prediction, a SciPy implementation of the same discretisation, and ROSS's
fluid-film bearing when a Python with ``ross`` is available.

Run ``python benchmarks/bench_reynolds.py [--repeat 5] [--points 32] [--ross-python PATH]
[--baseline-path DIR]``.
Protocol (benchmarks/_common.py): one BLAS/OpenMP thread per side, the sides of each ratio
timed in interleaved repeats, medians of the repeats, **wall time and CPU time of the same
calls side by side** (ratios use wall time on both sides), the machine load before and after.
For every grid (36×8, 72×16, 144×32, 144×31) and cavitation model it prints, per call:

* force at one fixed position (``same``), and cycling through ``--points`` random positions
  (ε 0.05–0.85, any angle) — each solve on its own, as in a sweep or a transient;
* the same cycled force and the (K, C) set (perturbation method: one solve, four linearised
  solves) **before** (cavitation set started from the empty set, the algorithm before issue 11)
  and **after** (started from the coarse-grid prediction), with the mean active-set
  iterations of each — measured in the same run, interleaved;
* the cycled force with the exact axial-symmetry reduction off (full grid);
* the SciPy baseline (scipy.sparse + SuperLU, the same primal–dual active set / p–θ iteration,
  checked against the C++ forces) on a quarter of the points.

``--baseline-path DIR`` adds the same-run comparison with another build of rotordyn (``DIR``
holds its ``rotordyn`` package with its compiled ``_core``, e.g. the previous commit's
``python/`` with that build's ``_core`` copied in): the cycled force and (K, C) of every grid and
model, each side timed in its own interpreter (ours in this one, the other in a worker started
with ``PYTHONPATH=DIR``), rounds interleaved, medians, wall and CPU, and the largest relative
difference of the two builds' forces, K and C on the same positions.

ROSS rows: ``FluidFlow`` (ROSS 2.x, finite differences, solve-then-clip film, no groove) builds
a new object per point; ours is given both reusing its solver and building a new bearing per
point. ROSS runs in its own interpreter (``--ross-python``, never our dependency); its rounds
are interleaved with ours and timed inside that interpreter with the same two clocks.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import footer, header, interleaved  # noqa: E402

import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
import scipy.sparse.linalg as spla  # noqa: E402

import rotordyn  # noqa: E402

D, L, C_RAD, MU, SPEED_HZ = 0.05, 0.04, 3e-4, 0.04, 50.0
POS = (1.0e-4, -1.5e-4)  # operating point, m (eccentricity ratio 0.60)
GROOVES = [rotordyn.Groove(90.0, 0.0, 0.0)]

params = ([(36, 8), (72, 16), (144, 32), (144, 31)], ["gumbel", "reynolds", "jfo"])
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


def cycled_positions(n, seed=0):
    """n random journal positions, eccentricity ratio 0.05–0.85, any angle (m)."""
    rng = np.random.default_rng(seed)
    e = C_RAD * (0.05 + 0.8 * rng.random(n))
    a = 2 * math.pi * rng.random(n)
    return [(float(x), float(y)) for x, y in zip(e * np.cos(a), e * np.sin(a))]


def us(t, n=1):
    """'wall/CPU' in µs per call."""
    return f"{t.wall / n * 1e6:6.0f}/{t.cpu / n * 1e6:<5.0f}"


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
force()  # warm-up (imports, numba/JIT caches)
tf, cf, tk, ck = [], [], [], []
for _ in range(repeat):
    t0, c0 = time.perf_counter(), time.process_time(); ff, F = force()
    tf.append(time.perf_counter() - t0); cf.append(time.process_time() - c0)
    t0, c0 = time.perf_counter(), time.process_time()
    calculate_stiffness_and_damping_coefficients(ff)
    tk.append(time.perf_counter() - t0); ck.append(time.process_time() - c0)
print(json.dumps({"force_wall": tf, "force_cpu": cf, "kc_wall": tk, "kc_cpu": ck,
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
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1",
               NUMBA_NUM_THREADS="1")
    r = subprocess.run([exe, "-c", ROSS_SNIPPET, *args], capture_output=True, text=True,
                       timeout=3600, env=env)
    if r.returncode != 0:
        return {"error": r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "failed"}
    return json.loads(r.stdout.strip().splitlines()[-1])


BASELINE_WORKER = r"""
import json, sys, time
import rotordyn
D, L, C_RAD, MU = (float(a) for a in sys.argv[1:5])
print(json.dumps({"file": rotordyn.__file__, "version": rotordyn.__version__}), flush=True)
solvers = {}
for line in sys.stdin:
    cmd = json.loads(line)
    key = (tuple(cmd["grid"]), cmd["cav"])
    if key not in solvers:
        solvers[key] = rotordyn.JournalBearing(
            diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU, n_circ=key[0][0],
            n_axial=key[0][1], cavitation=key[1],
            grooves=[rotordyn.Groove(*g) for g in cmd["grooves"]]).solver()
    s, pts, om = solvers[key], cmd["pts"], cmd["omega"]
    if cmd["what"] == "force":
        fn = lambda: [s.force(p, q, 0.0, 0.0, om) for p, q in pts]
        val = lambda r: [list(map(float, f)) for f in r]
    else:
        fn = lambda: [s.coefficients(p, q, om) for p, q in pts]
        val = lambda r: [[float(v) for v in (*k.K.ravel(), *k.C.ravel())] for k in r]
    if cmd.get("values"):
        print(json.dumps({"values": val(fn())}), flush=True)
        continue
    w0, c0 = time.perf_counter(), time.process_time()
    fn()
    print(json.dumps({"wall": time.perf_counter() - w0, "cpu": time.process_time() - c0}),
          flush=True)
"""


class BaselineBuild:
    """Another build of rotordyn in its own interpreter (``PYTHONPATH=path``), driven over a
    pipe: one timed round (or the values) per request."""

    def __init__(self, path):
        import subprocess

        env = dict(os.environ, PYTHONPATH=os.path.abspath(path), OMP_NUM_THREADS="1",
                   OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1")
        self.proc = subprocess.Popen(
            [sys.executable, "-c", BASELINE_WORKER, *(str(v) for v in (D, L, C_RAD, MU))],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, env=env)
        import json

        self.info = json.loads(self.proc.stdout.readline())

    def ask(self, **cmd):
        import json

        self.proc.stdin.write(json.dumps(cmd) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError("baseline worker failed (see its stderr above)")
        return json.loads(line)

    def close(self):
        self.proc.stdin.close()
        self.proc.wait(timeout=60)


def bench_baseline(path, grids, models, pts, omega, repeat):
    """This build against the build at ``path``: cycled force and (K, C) per call, rounds
    interleaved (one of ours, one of theirs), medians of ``repeat``; prints one row per grid and
    model with both builds' wall/CPU µs, the CPU and wall ratios (this / baseline), and the
    largest difference of forces, K and C relative to each quantity's largest magnitude."""
    med = statistics.median
    base = BaselineBuild(path)
    print(f"\nthis build ({rotordyn.__file__}) vs the build at {path} "
          f"({base.info['file']}; same run; rounds interleaved, medians of "
          f"{repeat}; per call over {len(pts)} cycled positions; 'wall/CPU' in µs; "
          f"ratio = this / baseline):")
    print(f"  {'grid':>8} {'model':>8} | {'F base':>12} {'F this':>12} {'CPU':>6} {'wall':>6} | "
          f"{'KC base':>12} {'KC this':>12} {'CPU':>6} {'wall':>6} | {'dF':>7} {'dK,C':>7}")
    grooves = [(g.center_deg, g.width_deg, g.pressure_pa) for g in GROOVES]
    try:
        for grid in grids:
            for cav in models:
                s = rotordyn.JournalBearing(
                    diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
                    n_circ=grid[0], n_axial=grid[1], cavitation=cav, grooves=GROOVES).solver()
                fns = {"force": lambda: [s.force(p, q, 0.0, 0.0, omega) for p, q in pts],
                       "kc": lambda: [s.coefficients(p, q, omega) for p, q in pts]}
                req = dict(grid=list(grid), cav=cav, grooves=grooves, pts=pts, omega=omega)
                ours = {k: ([], []) for k in fns}
                theirs = {k: ([], []) for k in fns}
                for k, fn in fns.items():  # warm-up (first solves build the coarse solvers)
                    fn()
                    base.ask(what=k, **req)
                for _ in range(repeat):
                    for k, fn in fns.items():
                        w0, c0 = time.perf_counter(), time.process_time()
                        fn()
                        ours[k][0].append(time.perf_counter() - w0)
                        ours[k][1].append(time.process_time() - c0)
                        r = base.ask(what=k, **req)
                        theirs[k][0].append(r["wall"])
                        theirs[k][1].append(r["cpu"])
                f_this = np.array([s.force(p, q, 0.0, 0.0, omega) for p, q in pts])
                f_base = np.array(base.ask(what="force", values=True, **req)["values"])
                k_this = np.array([[*k.K.ravel(), *k.C.ravel()]
                                   for k in (s.coefficients(p, q, omega) for p, q in pts)])
                k_base = np.array(base.ask(what="kc", values=True, **req)["values"])
                d_f = np.abs(f_this - f_base).max() / np.abs(f_base).max()
                d_k = max(np.abs(k_this[:, c] - k_base[:, c]).max() / np.abs(k_base[:, c]).max()
                          for c in (slice(0, 4), slice(4, 8)))
                n = len(pts)
                row = [f"  {grid[0]:>4}x{grid[1]:<3} {cav:>8} |"]
                for k in fns:
                    bw, bc = med(theirs[k][0]) / n, med(theirs[k][1]) / n
                    tw, tc = med(ours[k][0]) / n, med(ours[k][1]) / n
                    row.append(f" {bw * 1e6:6.0f}/{bc * 1e6:<5.0f} {tw * 1e6:6.0f}/{tc * 1e6:<5.0f}"
                               f" {tc / bc:6.2f} {tw / bw:6.2f} |")
                print("".join(row) + f" {d_f:7.1e} {d_k:7.1e}", flush=True)
    finally:
        base.close()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--points", type=int, default=32, help="cycled positions per repeat")
    ap.add_argument("--grids", default="36x8,72x16,144x32,144x31")
    ap.add_argument("--models", default="gumbel,reynolds,jfo")
    ap.add_argument("--no-scipy", action="store_true")
    ap.add_argument("--ross-python", default=None,
                    help="python of a venv with ross-rotordynamics (used if ross is not importable)")
    ap.add_argument("--baseline-path", default=None,
                    help="directory holding another build's rotordyn package: same-run "
                         "comparison of the cycled force and (K, C) with that build")
    ap.add_argument("--baseline-only", action="store_true",
                    help="with --baseline-path: only that comparison (and the load)")
    args = ap.parse_args(argv)
    header("bench_reynolds: Reynolds film force and (K, C)")
    omega = 2 * math.pi * SPEED_HZ
    pts = cycled_positions(args.points)
    grids = [tuple(int(v) for v in g.split("x")) for g in args.grids.split(",")]
    models = args.models.split(",")
    print(f"rotordyn {rotordyn.__version__}; D={D} L={L} c={C_RAD} mu={MU} speed={SPEED_HZ} Hz, "
          f"one supply line at 90 deg; per call, median of {args.repeat} interleaved repeats x "
          f"{args.points} cycled positions; 'wall/CPU' in µs")
    hdr = (f"{'grid':>8} {'model':>8} | {'F same':>12} | {'F cycled before':>15} "
           f"{'after':>12} {'its':>9} | {'KC before':>12} {'after':>12} | {'F full grid':>12} | "
           f"{'scipy F':>8} {'x F':>5} | {'dev':>7}")
    if args.baseline_path:
        bench_baseline(args.baseline_path, grids, models, pts, omega, args.repeat)
        if args.baseline_only:
            footer()
            return 0
    print(hdr)
    print("-" * len(hdr))
    for grid in grids:
        for cav in models:
            mk = lambda: rotordyn.JournalBearing(  # noqa: E731
                diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
                n_circ=grid[0], n_axial=grid[1], cavitation=cav, grooves=GROOVES)
            s, s0, sf = mk().solver(), mk().solver(), mk().solver()
            s0.predict_cavitation = False  # before: cavitation set from the empty set
            sf.use_axial_symmetry = False
            its = [np.mean([x.rigid(p, q, 0.0, 0.0, omega).iterations for p, q in pts])
                   for x in (s0, s)]

            def loop(fn):
                return lambda: [fn(p, q) for p, q in pts]

            t = interleaved({
                "same": lambda: [s.force(*POS, 0.0, 0.0, omega) for _ in pts],
                "before": loop(lambda p, q: s0.force(p, q, 0.0, 0.0, omega)),
                "after": loop(lambda p, q: s.force(p, q, 0.0, 0.0, omega)),
                "kc_before": loop(lambda p, q: s0.coefficients(p, q, omega)),
                "kc_after": loop(lambda p, q: s.coefficients(p, q, omega)),
                "full": loop(lambda p, q: sf.force(p, q, 0.0, 0.0, omega)),
            }, repeat=args.repeat)
            n = len(pts)
            line = (f"{grid[0]:>4}x{grid[1]:<3} {cav:>8} | {us(t['same'], n)} | "
                    f"{us(t['before'], n):>15} {us(t['after'], n)} {its[0]:4.1f}>{its[1]:<4.1f}| "
                    f"{us(t['kc_before'], n)} {us(t['kc_after'], n)} | {us(t['full'], n)} |")
            if not args.no_scipy and grid[1] % 2 == 0:
                ref = ScipyReynolds(grid[0], grid[1], cav)
                sp = pts[: max(4, n // 4)]
                ts = interleaved({"scipy": lambda: [ref.solve(p, q, 0.0, 0.0, omega)
                                                    for p, q in sp],
                                  "ours": lambda: [s.force(p, q, 0.0, 0.0, omega) for p, q in sp]},
                                 repeat=max(1, args.repeat // 2))
                f_py, _ = ref.solve(*POS, 0.0, 0.0, omega)
                f_c = s.force(*POS, 0.0, 0.0, omega)
                dev = np.linalg.norm(f_py - f_c) / np.linalg.norm(f_c)
                line += (f" {ts['scipy'].wall / len(sp) * 1e6:6.0f}us "
                         f"{ts['scipy'].wall / ts['ours'].wall:4.0f}x | {dev:7.1e}")
            print(line, flush=True)
    # Banded vs sparse factorisation (reynolds_band.cpp): the same cycled positions, the same
    # solver class with band_factor on and off, interleaved; without a groove the film is
    # periodic and only a wholly cavitated ring opens it; a zero-width supply line always does.
    print(f"\nbanded vs sparse LDLT (reynolds cavitation, force per call, cycled positions; "
          f"'band' = share of solves whose final factorisation was banded):")
    for grid in grids:
        for label, grooves in (("no groove", ()), ("supply line", GROOVES)):
            mk = lambda: rotordyn.JournalBearing(  # noqa: E731
                diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
                n_circ=grid[0], n_axial=grid[1], cavitation="reynolds", grooves=grooves)
            sb, ss = mk().solver(), mk().solver()
            ss.band_factor = False
            used = []
            for p, q in pts:
                sb.rigid(p, q, 0.0, 0.0, omega)
                used.append(sb.band_factor_used)
            dev = max(np.abs(np.asarray(sb.force(p, q, 0.0, 0.0, omega))
                             - np.asarray(ss.force(p, q, 0.0, 0.0, omega))).max()
                      / np.abs(np.asarray(ss.force(p, q, 0.0, 0.0, omega))).max() for p, q in pts)
            t = interleaved({
                "band": lambda: [sb.force(p, q, 0.0, 0.0, omega) for p, q in pts],
                "sparse": lambda: [ss.force(p, q, 0.0, 0.0, omega) for p, q in pts],
            }, repeat=args.repeat)
            n = len(pts)
            print(f"  {grid[0]:>4}x{grid[1]:<3} {label:>11}: band {us(t['band'], n)}  sparse "
                  f"{us(t['sparse'], n)}  = {t['sparse'].wall / t['band'].wall:4.2f}x wall "
                  f"({t['sparse'].cpu / t['band'].cpu:4.2f}x CPU); band {np.mean(used):4.0%}; "
                  f"largest force difference {dev:.1e}", flush=True)
    for grid in [g for g in grids if g in ((36, 8), (72, 16))]:
        b = rotordyn.JournalBearing(diameter_m=D, length_m=L, clearance_m=C_RAD,
                                    viscosity_pa_s=MU, n_circ=grid[0], n_axial=grid[1],
                                    cavitation="gumbel")
        s = b.solver()

        def fresh_force():
            rotordyn.JournalBearing(diameter_m=D, length_m=L, clearance_m=C_RAD,
                                    viscosity_pa_s=MU, n_circ=grid[0], n_axial=grid[1],
                                    cavitation="gumbel").forces(x_m=POS[0], y_m=POS[1],
                                                                speed_hz=SPEED_HZ)

        ross = {"force_wall": [], "force_cpu": [], "kc_wall": [], "kc_cpu": []}
        ours = {k: [] for k in ("f_reuse", "f_new", "kc")}
        failed = None
        for _ in range(args.repeat):  # interleaved rounds: ours, then one ROSS round
            t = interleaved({"f_reuse": lambda: s.force(*POS, 0.0, 0.0, omega),
                             "f_new": fresh_force,
                             "kc": lambda: s.coefficients(*POS, omega)}, repeat=3)
            for k in ours:
                ours[k].append(t[k])
            res = bench_ross(grid[0], grid[1], 1, args.ross_python)
            if res is None or "error" in res:
                failed = "not importable and no --ross-python given" if res is None else \
                    res["error"]
                break
            for k in ross:
                ross[k] += res[k]
        if failed:
            print(f"ROSS {grid[0]}x{grid[1]}: skipped ({failed})")
            continue
        med = statistics.median
        rw, rc = med(ross["force_wall"]), med(ross["force_cpu"])
        kw, kcpu = med(ross["kc_wall"]), med(ross["kc_cpu"])
        fw = med(x.wall for x in ours["f_reuse"])
        fc = med(x.cpu for x in ours["f_reuse"])
        nw = med(x.wall for x in ours["f_new"])
        nc = med(x.cpu for x in ours["f_new"])
        cw = med(x.wall for x in ours["kc"])
        cc = med(x.cpu for x in ours["kc"])
        f_ours = np.linalg.norm(b.forces(x_m=POS[0], y_m=POS[1], speed_hz=SPEED_HZ))
        print(f"ROSS FluidFlow {grid[0]}x{grid[1]} vs ours (gumbel, no groove), wall (CPU) per "
              f"call, median of {args.repeat} interleaved rounds:\n"
              f"  force: ROSS {rw * 1e3:.1f} ms ({rc * 1e3:.1f}); ours {fw * 1e6:.0f} us "
              f"({fc * 1e6:.0f}) reusing the solver = {rw / fw:.0f}x wall ({rc / fc:.0f}x CPU), "
              f"{nw * 1e6:.0f} us ({nc * 1e6:.0f}) with a new bearing per point = "
              f"{rw / nw:.0f}x wall ({rc / nc:.0f}x CPU)\n"
              f"  K,C:   ROSS {kw * 1e3:.0f} ms ({kcpu * 1e3:.0f}); ours {cw * 1e6:.0f} us "
              f"({cc * 1e6:.0f}) = {kw / cw:.0f}x wall ({kcpu / cc:.0f}x CPU);  |F| ROSS "
              f"{res['force_n']:.1f} N, ours {f_ours:.1f} N")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
