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

The chunks with no batch in the core (thermal, waterfall, run-up, robust, hopf: a per-point
thermal fixed point, transient, closed-loop margin computation or l1 normal form) are timed
the same way with ``--points``: the chunk, the bare per-point work (the same analysis calls,
no rows) and the former dict-per-row chunk (tests/sweep_point_rows_reference.py).

    python benchmarks/bench_sweep_chunks.py [--repeat 5] [--points] [--only-points]
        [--only-stability]
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


def show_points(label, n, t):
    c, b, d = t["chunk"], t["bare"], t["dict"]
    print(f"-- {label} ({n} points)")
    print(f"   bare per-point work (baseline)  {b}  ({1e3 * b.cpu / n:.3f} ms CPU/point)")
    print(f"   dict-per-row chunk (before)     {d}")
    print(f"   columnar chunk (run_chunk)      {c}")
    print(f"   chunk / bare: CPU {c.cpu / b.cpu:.3f}x, wall {c.wall / b.wall:.3f}x; "
          f"dict / chunk CPU {d.cpu / c.cpu:.3f}x")


def points_chunks(repeat):
    """The chunks whose points each cost one unbatched analysis (module docstring)."""
    import sys
    from pathlib import Path

    from rotordyn.analysis.thermal import system_thermal_equilibrium
    from rotordyn.analysis.transient import transient
    from rotordyn.control.pid import tune_pd
    from rotordyn.control.plant import plant
    from rotordyn.control.robust import build_controller, closed_loop_point
    from rotordyn.operation import SpeedProfile
    from rotordyn.analysis.hopf import FD_STEP
    from rotordyn.sweep.hopf_rows import _one
    from rotordyn.sweep.paths import set_field
    from rotordyn.sweep.points import point_options, solve_equilibrium
    from rotordyn.sweep.robust import build_spec

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    import sweep_point_rows_reference as ref

    def timed(label, job, bare, n):
        show_points(label, n, interleaved(
            {"bare": bare, "chunk": lambda: run_chunk(job, 0, 0, n),
             "dict": lambda: ref.run_chunk(job, 0, 0, n)}, repeat=repeat))

    models = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"
    th = rd.System.from_toml(str(models / "compressor_plain_thermal.toml"))
    axes = {"thermal.supply_temperature_c": [40.0, 50.0], "speed_hz": [100.0, 125.0, 150.0]}
    job = Job("b", th.to_toml(), "thermal", {}, axes)
    var = {t: set_field(th, "thermal.supply_temperature_c", t) for t in axes[
        "thermal.supply_temperature_c"]}
    timed("thermal chunk, compressor on plain thermal films", job, lambda: [
        system_thermal_equilibrium(var[t], speed_hz=f) for t in var for f in axes["speed_hz"]],
        6)

    s = rd.models.paper_rig()
    ub = [(6, 2e-5, 0.0)]
    speeds = [40.0, 45.0, 50.0]
    job = Job("b", s.to_toml(), "waterfall", {"unbalances": [list(u) for u in ub],
                                              "revolutions": 20, "samples_per_revolution": 32},
              {"chamber_pressure_pa": [0.2e6], "speed_hz": speeds})

    asm = Assembled(s)  # the assembly outside the timing (a chunk's is cached per process)

    def bare_wf():
        asm.solver = _core.SystemSolver(asm.model)  # a fresh solver, as a chunk's
        for f in speeds:
            e = solve_equilibrium(asm, f, 0.2e6, asm.config_vector(None), None, {})
            tr = transient(asm.system, 20 / f, f, 0.2e6, None, r0=np.asarray(e.r),
                           unbalances=ub, n_out=20 * 32 + 1, rtol=1e-6, rub_fraction=1e-3)
            tr.spectrum(last_fraction=0.5, axis="x")
            tr.spectrum(last_fraction=0.5, axis="y")

    timed("waterfall chunk, rig, 20 revolutions per speed", job, bare_wf, len(speeds))

    pcs = [0.2e6, 0.3e6]
    job = Job("b", s.to_toml(), "run-up", {"unbalances": [list(u) for u in ub],
                                           "start_hz": 30.0, "stop_hz": 36.0,
                                           "rate_hz_per_s": 15.0},
              {"chamber_pressure_pa": pcs})

    def bare_runup():
        asm.solver = _core.SystemSolver(asm.model)
        for pc in pcs:
            e = solve_equilibrium(asm, 30.0, pc, asm.config_vector(None), None, {})
            T = 6.0 / 15.0
            transient(asm.system, T, chamber_pressure_pa=pc, speed=SpeedProfile.ramp(
                30.0, 36.0, 15.0), r0=np.asarray(e.r), unbalances=ub,
                n_out=int(33.0 * T * 32) + 1, rtol=1e-6, rub_fraction=1e-3)

    timed("run-up chunk, rig 30-36 Hz at 15 Hz/s", job, bare_runup, len(pcs))

    p = plant(s, 50.0, 0.05e6, -1.85e-3, measurements=[("journal", 0)],
              equilibrium={"warm_start": False})
    law = tune_pd(p)[0]
    rspeeds = [30.0, 40.0, 50.0, 60.0]
    for margins in (False, True):
        spec = build_spec(s, law, {"chamber_pressure_pa": 0.05e6, "config_ay_m": -1.85e-3,
                                   "speed_hz": rspeeds}, margins=margins)
        job = Job("b", s.to_toml(), "robust", spec.options, spec.axes)
        k = build_controller(spec.options["controller"])

        def bare_robust(margins=margins, k=k):
            r0 = None
            for f in rspeeds:
                eq = {"r0": r0} if r0 is not None else {}
                pl = closed_loop_point(s, k, f, 0.05e6, -1.85e-3, equilibrium=eq,
                                       with_margins=margins, pade_order=6)[0]
                r0 = pl.info.get("equilibrium_r")

        timed(f"robust chunk, rig with the tuned PD, margins {margins}", job, bare_robust,
              len(rspeeds))

    hp = [0.0, 0.1e6, 0.2e6, 0.3e6, 0.4e6]
    job = Job("b", s.to_toml(), "hopf", {"vary": "chamber_pressure_pa"},
              {"speed_hz": [80.0], "config_ay_m": [1.5e-3], "chamber_pressure_pa": hp})
    asm0 = Assembled(s)
    tin = threshold_input(asm0, hp)
    tin.omega = [hz_to_rad_s(80.0)] * len(hp)
    tin.a = np.tile(asm0.config_vector(1.5e-3), (len(hp), 1))

    def bare_hopf():
        variants = Variants(base_system(job.model_toml), job.model_toml)
        _, p0 = job.point(0)
        asm = variants.get(p0)
        res = _core.threshold_line(asm.solver, tin)
        for x, fr in zip(res.root, res.root_freq):
            q = {**p0, "chamber_pressure_pa": x}
            _one(job, asm, q, "chamber_pressure_pa", fr, hp[-1] - hp[0],
                 point_options(job, q), False, FD_STEP)

    timed("hopf chunk, rig line over p_c at 80 Hz, a_y = 1.5 mm (two crossings)", job,
          bare_hopf, len(hp))


def thermal_dynamics_chunks(repeat):
    """The stability and unbalance chunks with ``options.thermal`` (each point at its own
    thermal equilibrium, field frozen; no batch: every point's frozen system is another model)
    against their bare per-point API calls and the former dict-per-row chunk."""
    import sys
    from pathlib import Path

    from rotordyn.sweep.paths import set_field

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    import sweep_thermal_rows_reference as ref

    models = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"
    th = rd.System.from_toml(str(models / "compressor_plain_thermal.toml"))
    axes = {"thermal.supply_temperature_c": [40.0, 50.0], "speed_hz": [100.0, 125.0, 150.0]}
    var = {t: set_field(th, "thermal.supply_temperature_c", t) for t in axes[
        "thermal.supply_temperature_c"]}
    job = Job("b", th.to_toml(), "stability", {"thermal": {}, "n_modes": 6}, axes)
    show_points("stability chunk with options.thermal, compressor on plain films", 6,
                interleaved({"bare": lambda: [rd.stability(var[t], f, n_modes=6, thermal=True)
                                              for t in var for f in axes["speed_hz"]],
                             "chunk": lambda: run_chunk(job, 0, 0, 6),
                             "dict": lambda: ref.run_chunk(job, 0, 0, 6)}, repeat=repeat))
    ub = [(3, 1e-4, 0.0)]
    job = Job("b", th.to_toml(), "unbalance", {"thermal": {}, "unbalances": [list(ub[0])]},
              axes)
    show_points("unbalance chunk with options.thermal, same", 6, interleaved(
        {"bare": lambda: [rd.unbalance_response(var[t], ub, axes["speed_hz"], refine=False,
                                                check_stability=False, thermal=True)
                          for t in var],
         "chunk": lambda: run_chunk(job, 0, 0, 6),
         "dict": lambda: ref.run_chunk(job, 0, 0, 6)}, repeat=repeat))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--points", action="store_true",
                    help="also the thermal, waterfall, run-up, robust and hopf chunks")
    ap.add_argument("--only-points", action="store_true", help="only those")
    ap.add_argument("--only-stability", action="store_true",
                    help="only the stability chunk (the goal chunk <= 1.1x its call)")
    ap.add_argument("--thermal-dynamics", action="store_true",
                    help="only the stability and unbalance chunks with options.thermal")
    a = ap.parse_args()
    header("sweep chunks: one C++ call vs the per-point loops")
    if a.thermal_dynamics:
        thermal_dynamics_chunks(a.repeat)
        footer()
        return
    if a.only_points:
        points_chunks(a.repeat)
        footer()
        return
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
    if a.only_stability:
        footer()
        return

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
    if a.points:
        points_chunks(a.repeat)
    footer()


if __name__ == "__main__":
    main()
