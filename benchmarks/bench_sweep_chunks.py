"""Sweep chunks as one C++ call (issue 22): the equilibrium chunk (``_core.equilibrium_batch``),
the threshold line (``_core.threshold_line``: scan + Brent) and the unbalance line
(``_core.unbalance_sweep``) against the per-point Python loops they replaced (reproduced
below: the same core calls one point at a time, SciPy's brentq for the threshold), measured
in the same run on the paper rig. The chunk side is ``run_chunk`` whole (rows and the arrow
table included); the loop side is the bare loop without rows, so the ratio understates the
gain. Interleaved repeats, medians, wall and CPU, BLAS pinned to one thread, load printed.

    python benchmarks/bench_sweep_chunks.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from _common import footer, header, interleaved

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import Assembled
from rotordyn.sweep.lines import max_real
from rotordyn.sweep.points import Variants, base_system, equilibrium_options
from rotordyn.sweep.work import Job, run_chunk
from rotordyn.units import hz_to_rad_s


def eq_loop(asm, pts):
    solver = _core.SystemSolver(asm.model)
    o = equilibrium_options({})
    r_prev = None
    for f, pc, ay, line in pts:
        e = solver.equilibrium(hz_to_rad_s(f), pc, asm.config_vector(ay),
                               r_prev if (line and r_prev is not None) else np.zeros(0), o)
        r_prev = np.asarray(e.r) if e.status == "ok" else None


def threshold_loop(job, vary):
    from scipy.optimize import brentq

    variants = Variants(base_system(job.model_toml), job.model_toml)
    _, p0 = job.point(0)
    asm = variants.get(p0)
    xs, ys, rs, r0 = [], [], [], None
    for pid in range(job.shape[-1]):
        _, p = job.point(pid)
        try:
            y, _, _, r = max_real(job, asm, p, r0, {}, False)
        except (rd.RotordynError, ArithmeticError, ValueError):
            y, r = math.nan, None
        r0 = r
        xs.append(p[vary])
        ys.append(y)
        rs.append(r)
    for i in range(len(xs) - 1):
        if not (math.isfinite(ys[i]) and math.isfinite(ys[i + 1])) or ys[i] * ys[i + 1] >= 0:
            continue
        _, pb = job.point(i)

        def g(x, pb=pb, start=rs[i]):
            return max_real(job, asm, {**pb, vary: float(x)}, start, {}, False)[0]

        x = brentq(g, xs[i], xs[i + 1], xtol=abs(xs[i + 1] - xs[i]) * 1e-8,
                   rtol=4 * np.finfo(float).eps, maxiter=100)
        max_real(job, asm, {**pb, vary: x}, rs[i], {}, False)


def unbalance_loop(asm, ub, speeds, pc, stations):
    solver = _core.SystemSolver(asm.model)
    o = equilibrium_options({})
    F1 = asm.unbalance_load(ub)
    m = asm.model
    M, C0, G, K0 = (np.asarray(x) for x in (m.M, m.C, m.G, m.K))
    a = asm.config_vector(None)
    Cout = [asm.station_output_matrix(s) for s in stations]
    r0 = None
    for f in speeds:
        e = solver.equilibrium(hz_to_rad_s(f), pc, a, np.zeros(0) if r0 is None else r0, o)
        if e.status not in ("ok", "contact"):
            r0 = None
            continue
        r0 = np.asarray(e.r)
        om = hz_to_rad_s(f)
        lin = solver.linearize(r0, np.zeros(asm.n), om)
        Z = (K0 + np.asarray(lin.KH)) - om**2 * M + 1j * om * (C0 + om * G + np.asarray(lin.DH))
        q = np.linalg.solve(Z, om**2 * F1)
        for Co in Cout:
            Co @ q


def show(label, n, t):
    o, c = t["loop"], t["chunk"]
    print(f"-- {label} ({n} points)")
    print(f"   per-point Python loop (before)  {o}  ({1e3 * o.cpu / n:.3f} ms CPU/point)")
    print(f"   chunk, one C++ call (after)     {c}  ({1e3 * c.cpu / n:.3f} ms CPU/point; "
          f"loop/chunk CPU {o.cpu / c.cpu:.2f}x, wall {o.wall / c.wall:.2f}x)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    header("sweep chunks: one C++ call vs the per-point loops")
    s = rd.models.paper_rig()
    toml = s.to_toml()
    asm = Assembled(s)

    ays, pcs = [-1.85e-3, -1.5e-3, 0.0, 1.0e-3], list(np.linspace(0.0, 0.3e6, 25))
    job = Job("b", toml, "equilibrium", {}, {"config_ay_m": ays, "chamber_pressure_pa": pcs,
                                              "speed_hz": [50.0]})
    pts = [(50.0, pc, ay, k > 0) for ay in ays for k, pc in enumerate(pcs)]
    n = len(pts)
    show("equilibrium chunk, Fig. 9 lines over p_c", n, interleaved(
        {"loop": lambda: eq_loop(asm, pts), "chunk": lambda: run_chunk(job, 0, 0, n)},
        repeat=a.repeat))

    axes = {"config_ay_m": [-1.85e-3], "speed_hz": [50.0],
            "chamber_pressure_pa": list(np.linspace(0, 0.3e6, 13))}
    job = Job("b", toml, "threshold", {"vary": "chamber_pressure_pa"}, axes)
    show("threshold line over p_c at a_y = -1.85 mm (scan of 13 + Brent on each crossing)", 13,
         interleaved({"loop": lambda: threshold_loop(job, "chamber_pressure_pa"),
                      "chunk": lambda: run_chunk(job, 0, 0, 13)}, repeat=a.repeat))

    speeds = list(np.arange(10.0, 121.0, 1.0))
    job = Job("b", toml, "unbalance", {"unbalances": [[6, 2e-5, 0.0]], "stations": [6, 4]},
              {"chamber_pressure_pa": [0.2e6], "speed_hz": speeds})
    show("unbalance line 10-120 Hz at p_c = 0.2 MPa", len(speeds), interleaved(
        {"loop": lambda: unbalance_loop(asm, [(6, 2e-5, 0.0)], speeds, 0.2e6, [6, 4]),
         "chunk": lambda: run_chunk(job, 0, 0, len(speeds))}, repeat=a.repeat))
    footer()


if __name__ == "__main__":
    main()
