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
   load. Goal: ≥ 50× faster.

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
    tp = TiltingPadBearing(station=0, diameter_m=D, length_m=L, clearance_m=c,
                           viscosity_pa_s=0.028, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                           preload=0.5, orientation_deg=pivots[0], pad_thickness_m=12.7e-3,
                           n_circ=180, n_axial=30)
    ours = interleaved({"tp": lambda: tp.coefficient_table([50.0], (884.05, -2670.4))},
                       args.repeat)["tp"]
    res = tp.coefficient_table([50.0], (884.05, -2670.4))
    print(f"tilting pad (5 pads, 30x30 per pad), equilibrium + synchronous K, C: wall "
          f"{fmt(ours[0])}, cpu {fmt(ours[1])}; status {res.status[0]}, "
          f"eps {np.hypot(res.x_m[0], res.y_m[0]) / c:.3f}")
    ross = import_ross()
    if ross is None:
        print("ROSS not installed: no tilting-pad baseline (pip install 'rotordyn[ross]')")
    else:
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
                    load=[8.8405e02, -2.6704e03], thermal_type="adiabatic", nx=30, nz=30)
        w, cpu, _ = timed(ross_tp)  # one run: it takes long
        walls, cpus = [w], [cpu]
        for _ in range(args.ross_repeat - 1):
            w, cpu, _ = timed(ross_tp)
            walls.append(w)
            cpus.append(cpu)
        rw, rc = statistics.median(walls), statistics.median(cpus)
        print(f"ROSS {ross.__version__} TiltingPad (THD adiabatic, match_eccentricity, 30x30): "
              f"wall {fmt(rw)}, cpu {fmt(rc)} over {len(walls)} run(s) -> ours is "
              f"{rc / ours[1]:.0f}x faster in CPU time ({rw / ours[0]:.0f}x wall) (goal >= 50x)")
    print(f"load average after: {load()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
