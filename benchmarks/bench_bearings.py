"""Bearing-element benchmarks (issue 12), not a test.

1. A 20-speed coefficient table (equilibrium + K, C per speed) of a plain bearing on the
   default grid (72 × 16), one thread: goal < 0.5 s. Baseline in the same run: the same 20
   points through the standalone JournalBearing API (static_equilibrium + coefficients per
   speed, Python loop).
2. Tilting-pad coefficients at one operating point (equilibrium of the journal and every pad,
   then the synchronous reduced K, C): ROSS's ``TiltingPad`` example case (5 pads of 60°,
   preload 0.5, D = 101.6 mm, 3000 rpm, load (884, −2670) N) at ROSS's default grid
   (nx = nz = 30 per pad) beside this package at the equal grid (30 intervals per pad,
   n_axial = 30), when ross-rotordynamics is installed. ROSS's model is thermo-hydrodynamic
   (``thermal_type="adiabatic"``, its cheapest) and with ``equilibrium_type=
   "match_eccentricity"`` it optimises only the pad angles at a given eccentricity; ours is
   isoviscous (μ of ISO VG 32 at 40 °C, 0.028 Pa·s) and solves the full equilibrium from the
   load (pad assembly, C++ pad_equilibrium.cpp). Goal: ≥ 50× faster. Printed: our equilibrium
   (eccentricity, attitude), path and Reynolds solves, the synchronous K, C, and ROSS's film
   force at its given eccentricity and its K, C (THD vs isoviscous: only roughly comparable).

Medians of interleaved repeats, wall and CPU time, one BLAS/OpenMP thread, machine load
printed before and after (the machine is shared: figures are noisy).

    .venv/bin/python benchmarks/bench_bearings.py [--repeat 5] [--ross-repeat 1]
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
from _common import fmt, import_ross  # noqa: E402

import rotordyn  # noqa: E402
from rotordyn.bearings import TiltingPadBearing  # noqa: E402


def timed(fn):
    w0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - w0, time.process_time() - c0, out


def interleaved(fns: dict, repeat: int) -> dict:
    res = {k: [] for k in fns}
    for k, fn in fns.items():  # warm-up
        fn()
    for _ in range(repeat):
        for k, fn in fns.items():
            w, c, _ = timed(fn)
            res[k].append((w, c))
    return {k: (statistics.median(x[0] for x in v), statistics.median(x[1] for x in v))
            for k, v in res.items()}


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--ross-repeat", type=int, default=1)
    args = ap.parse_args(argv)
    print(f"load average before: {load()}  (2-core shared machine: noisy)")

    # 1. 20-speed table
    jb = rotordyn.JournalBearing(diameter_m=0.05, length_m=0.025, clearance_m=5e-5,
                                 viscosity_pa_s=0.02)
    speeds = np.arange(10.0, 201.0, 10.0)
    load_n = (0.0, -300.0)

    def table():
        return jb.coefficient_table(speeds, load_n, n_threads=1)

    def loop():
        out = []
        for f in speeds:
            e = jb.static_equilibrium(load_n=load_n, speed_hz=f)
            out.append(jb.coefficients(x_m=e.x_m, y_m=e.y_m, speed_hz=f))
        return out

    t = interleaved({"table": table, "loop": loop}, args.repeat)
    print(f"20-speed coefficient table, 72x16 grid, 1 thread: wall {fmt(t['table'][0])}, "
          f"cpu {fmt(t['table'][1])} (goal < 0.5 s); baseline Python loop over the "
          f"standalone API: wall {fmt(t['loop'][0])}, cpu {fmt(t['loop'][1])}")

    # 2. tilting pad vs ROSS
    D, c, L = 101.6e-3, 74.9e-6, 50.8e-3
    pivots = [18.0, 90.0, 162.0, 234.0, 306.0]
    W = (884.05, -2670.4)
    tp = TiltingPadBearing(station=0, diameter_m=D, length_m=L, clearance_m=c,
                           viscosity_pa_s=0.028, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                           preload=0.5, orientation_deg=pivots[0], pad_thickness_m=12.7e-3,
                           n_circ=180, n_axial=30)

    def ours_tp():
        return tp.coefficient_table([50.0], W)

    ross = import_ross()
    fns = {"tp": ours_tp}
    if ross is not None:
        import contextlib
        import io
        import warnings

        Q_ = ross.Q_

        def ross_tp():
            with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
                warnings.simplefilter("ignore")
                return ross.TiltingPad(
                    n=1, frequency=Q_([3000], "RPM"), equilibrium_type="match_eccentricity",
                    journal_diameter=D, radial_clearance=c, pad_thickness=12.7e-3,
                    pivot_angle=Q_(pivots, "deg"), pad_arc=Q_([60] * 5, "deg"),
                    pad_axial_length=Q_([L] * 5, "m"), pre_load=[0.5] * 5, offset=[0.5] * 5,
                    lubricant="ISOVG32", oil_supply_temperature=Q_(40, "degC"),
                    eccentricity=0.35, attitude_angle=Q_(287.5, "deg"),
                    load=[W[0], W[1]], thermal_type="adiabatic", nx=30, nz=30)

    # interleaved: ours `repeat` times per ROSS run (ROSS takes seconds)
    ours_t, ross_t, ross_el = [], [], None
    ours_tp()  # warm-up (imports, first allocation), both sides alike
    if ross is not None:
        ross_tp()
    for k in range(max(args.repeat, args.ross_repeat if ross is not None else 0)):
        if k < args.repeat:
            ours_t.append(timed(ours_tp)[:2])
        if ross is not None and k < args.ross_repeat:
            w, cpu, ross_el = timed(ross_tp)
            ross_t.append((w, cpu))
    ow = statistics.median(x[0] for x in ours_t)
    oc = statistics.median(x[1] for x in ours_t)
    res = ours_tp()
    x, y = res.x_m[0], res.y_m[0]
    print(f"tilting pad, ROSS's example (5 pads of 60 deg, preload 0.5, 3000 rpm, load "
          f"({W[0]:g}, {W[1]:g}) N, 30x30 per pad), equilibrium + synchronous K, C: wall "
          f"{fmt(ow)}, cpu {fmt(oc)} (median of {len(ours_t)}); status {res.status[0]}, path "
          f"{res.path[0]}, {res.reynolds_solves[0]} pad Reynolds solves (equilibrium)")
    print(f"  ours (isoviscous 0.028 Pa s): eps {np.hypot(x, y) / c:.4f}, journal at "
          f"{np.degrees(np.arctan2(y, x)) % 360:.2f} deg (load direction "
          f"{np.degrees(np.arctan2(W[1], W[0])) % 360:.2f} deg)")
    print(f"  ours K [N/m] {np.array2string(res.K[0].ravel(), precision=4)}  "
          f"C [N s/m] {np.array2string(res.C[0].ravel(), precision=4)}")
    if ross is None:
        print("ROSS not installed: no tilting-pad baseline (pip install ross-rotordynamics "
              "'plotly<7' into a scratch venv)")
    else:
        rw = statistics.median(x[0] for x in ross_t)
        rc = statistics.median(x[1] for x in ross_t)

        def first(v):
            return float(np.ravel(v)[0])

        fx = first(ross_el.force_x_total_list[-1]) if ross_el.force_x_total_list else np.nan
        fy = first(ross_el.force_y_total_list[-1]) if ross_el.force_y_total_list else np.nan
        kr = np.array([first(getattr(ross_el, k)) for k in ("kxx", "kxy", "kyx", "kyy")])
        cr = np.array([first(getattr(ross_el, k)) for k in ("cxx", "cxy", "cyx", "cyy")])
        print(f"ROSS {ross.__version__} TiltingPad (THD adiabatic, match_eccentricity: pad "
              f"angles at the given eps 0.35 at 287.5 deg, 30x30): wall {fmt(rw)}, cpu "
              f"{fmt(rc)} over {len(ross_t)} run(s); its film force there ({fx:.1f}, {fy:.1f}) N")
        print(f"  ROSS K [N/m] {np.array2string(kr, precision=4)}  C [N s/m] "
              f"{np.array2string(cr, precision=4)}")
        print(f"  -> ours is {rc / oc:.0f}x faster in CPU time ({rw / ow:.0f}x wall) (goal >= 50x)")
    print(f"load average after: {load()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
