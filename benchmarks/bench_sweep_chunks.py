"""Sweep chunks as one C++ call (issue 22) on the paper rig: the stability chunk
(``_core.stability_batch``), the equilibrium chunk (``_core.equilibrium_batch``), the threshold
line (``_core.threshold_line``: scan + Brent), the unbalance line (``_core.unbalance_sweep``)
and a boundary-refinement chunk (``_core.max_real_batch``), each timed three ways in the same
run: the chunk (``run_chunk`` whole: points, the C++ call, the columnar rows and the arrow
table), the bare C++ call it makes (inputs prepared outside the timing, a fresh solver inside:
the honest baseline, goal chunk <= 1.1x) and, where one existed, the per-point Python loop it
replaced (reproduced below: the same core calls one point at a time, SciPy's brentq for the
threshold; the bare loop without rows). Interleaved repeats, medians, wall and CPU, BLAS
pinned to one thread, load printed.

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


def threshold_input(asm, pcs):
    """The threshold_line input of one line over p_c at a_y = -1.85 mm, 50 Hz."""
    t = _core.ThresholdLineInput()
    a = asm.config_vector(-1.85e-3)
    n = len(pcs)
    t.x, t.omega, t.pressure = list(pcs), [hz_to_rad_s(50.0)] * n, list(pcs)
    t.a, t.valid = np.tile(a, (n, 1)), [1] * n
    t.axis = _core.ThresholdAxis.chamber_pressure
    t.options = equilibrium_options({})
    t.xy_pairs, t.rot_pairs = asm.rotor.xy_pairs(), asm.rotor.rot_pairs()
    t.sleeve = [i for bc in asm.bearings for i in bc.sleeve]
    return t


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
    c, b = t["chunk"], t["bare"]
    print(f"-- {label} ({n} points)")
    print(f"   bare C++ call (baseline)        {b}  ({1e3 * b.cpu / n:.3f} ms CPU/point)")
    if "loop" in t:
        o = t["loop"]
        print(f"   per-point Python loop (before)  {o}  ({1e3 * o.cpu / n:.3f} ms CPU/point)")
    print(f"   chunk (run_chunk whole)         {c}  ({1e3 * c.cpu / n:.3f} ms CPU/point)")
    print(f"   chunk / bare call: CPU {c.cpu / b.cpu:.3f}x, wall {c.wall / b.wall:.3f}x "
          f"(goal <= 1.1x)" + (f"; loop / chunk CPU {t['loop'].cpu / c.cpu:.2f}x"
                                 if "loop" in t else ""))


def bare_inputs(asm, pts):
    """(omega, pressure, a, restart) of points (f, pc, ay, same_line), as a chunk builds them."""
    return (np.array([hz_to_rad_s(f) for f, _, _, _ in pts]), np.array([p[1] for p in pts]),
            np.array([asm.config_vector(p[2]) for p in pts]),
            [0 if p[3] else 1 for p in pts])


def bare_stability(asm, inp):
    from rotordyn.analysis.linear import FD_REL_STEP

    return _core.stability_batch(
        _core.SystemSolver(asm.model), *inp, equilibrium_options({}), 0, False, FD_REL_STEP,
        asm.rotor.xy_pairs(), asm.rotor.rot_pairs(),
        [i for bc in asm.bearings for i in bc.sleeve])


def bare_max_real(asm, inp):
    b = _core.MaxRealBatchInput()
    b.omega, b.pressure, b.a, b.restart = inp
    b.valid = [1] * len(b.restart)
    b.options = equilibrium_options({})
    b.xy_pairs, b.rot_pairs = asm.rotor.xy_pairs(), asm.rotor.rot_pairs()
    b.sleeve = [i for bc in asm.bearings for i in bc.sleeve]
    return _core.max_real_batch(_core.SystemSolver(asm.model), b)


def boundary_loop(job, pids):
    variants = Variants(base_system(job.model_toml), job.model_toml)
    r_prev, prev = None, None
    for pid in pids:
        idx, p = job.point(pid)
        asm = variants.get(p)
        line = prev is not None and prev[0] == idx[0]
        prev = idx
        try:
            r_prev = max_real(job, asm, p, r_prev if line else None, {}, False)[3]
        except (rd.RotordynError, ArithmeticError, ValueError):
            r_prev = None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    header("sweep chunks: one C++ call vs the per-point loops")
    s = rd.models.paper_rig()
    toml = s.to_toml()
    asm = Assembled(s)

    ays, pcs = [-1.85e-3, -1.5e-3, 0.0, 1.0e-3], list(np.linspace(0.0, 0.3e6, 25))
    pts = [(50.0, pc, ay, k > 0) for ay in ays for k, pc in enumerate(pcs)]
    n = len(pts)
    inp = bare_inputs(asm, pts)
    axes = {"config_ay_m": ays, "chamber_pressure_pa": pcs, "speed_hz": [50.0]}
    job = Job("b", toml, "stability", {}, axes)
    show("stability chunk, Fig. 9 lines over p_c", n, interleaved(
        {"bare": lambda: bare_stability(asm, inp), "chunk": lambda: run_chunk(job, 0, 0, n)},
        repeat=a.repeat))

    job = Job("b", toml, "equilibrium", {}, axes)
    show("equilibrium chunk, Fig. 9 lines over p_c", n, interleaved(
        {"loop": lambda: eq_loop(asm, pts), "chunk": lambda: run_chunk(job, 0, 0, n),
         "bare": lambda: _core.equilibrium_batch(_core.SystemSolver(asm.model), *inp,
                                                 equilibrium_options({}))},
        repeat=a.repeat))

    # a boundary-refinement chunk: every other point of the Fig. 9 lines (runs along p_c)
    job = Job("b", toml, "boundary", {}, axes)
    pids = list(range(0, n, 2))
    bpts = [(50.0, pcs[q % 25], ays[q // 25], k > 0 and q // 25 == pids[k - 1] // 25)
            for k, q in enumerate(pids)]
    binp = bare_inputs(asm, bpts)
    show("boundary-refinement chunk, every other point of the lines", len(pids), interleaved(
        {"loop": lambda: boundary_loop(job, pids), "chunk": lambda: run_chunk(job, 0, 0, 0, pids),
         "bare": lambda: bare_max_real(asm, binp)}, repeat=a.repeat))

    axes = {"config_ay_m": [-1.85e-3], "speed_hz": [50.0],
            "chamber_pressure_pa": list(np.linspace(0, 0.3e6, 13))}
    job = Job("b", toml, "threshold", {"vary": "chamber_pressure_pa"}, axes)
    tin = threshold_input(asm, axes["chamber_pressure_pa"])
    show("threshold line over p_c at a_y = -1.85 mm (scan of 13 + Brent on each crossing)", 13,
         interleaved({"loop": lambda: threshold_loop(job, "chamber_pressure_pa"),
                      "chunk": lambda: run_chunk(job, 0, 0, 13),
                      "bare": lambda: _core.threshold_line(_core.SystemSolver(asm.model), tin)},
                     repeat=a.repeat))

    speeds = list(np.arange(10.0, 121.0, 1.0))
    job = Job("b", toml, "unbalance", {"unbalances": [[6, 2e-5, 0.0]], "stations": [6, 4]},
              {"chamber_pressure_pa": [0.2e6], "speed_hz": speeds})
    O = np.concatenate([asm.station_output_matrix(q) for q in (6, 4)], axis=0)
    F1 = asm.unbalance_load([(6, 2e-5, 0.0)])
    om = hz_to_rad_s(np.array(speeds))
    A0 = np.tile(asm.config_vector(None), (len(speeds), 1))

    def bare_unbalance():
        return _core.unbalance_sweep(asm.model, om, np.full(len(speeds), 0.2e6), A0,
                                     np.zeros(0), equilibrium_options({}), np.zeros((0, 0)), F1,
                                     O, False, 0.0, False, False, [], [], 1, True)

    show("unbalance line 10-120 Hz at p_c = 0.2 MPa", len(speeds), interleaved(
        {"loop": lambda: unbalance_loop(asm, [(6, 2e-5, 0.0)], speeds, 0.2e6, [6, 4]),
         "chunk": lambda: run_chunk(job, 0, 0, len(speeds)), "bare": bare_unbalance},
        repeat=a.repeat))
    footer()


if __name__ == "__main__":
    main()
