"""The 50-point limit-cycle branch of the paper rig: the corrector modes against the default in
one run (issue 19's goal: a 50-point branch ≤ 30 s CPU on one core; docs/nonlinear.md prints
these numbers).

Rig (``rd.models.paper_rig()``) at 50 Hz, a_y = −1.85 mm. Start: the stable cycle at
p_c = 0.05 MPa (paper Fig. 11) from a 0.6 s transient (journal disturbed by 0.1 c upwards)
and :func:`rotordyn.periodic_orbit` (rtol 1e-6, tol 1e-4). Branch: p_c upwards towards the
Hopf point (bounds 0–0.12 MPa) at rtol 1e-6, tol 1e-4 with a **constant** arclength step
(ds = ds_max, default 0.0125: ≈ 50 points from 0.05 MPa to the Hopf point at 0.05706 MPa —
the resolution at which the amplitude's √(p_H − p) shape near the Hopf point is drawn; the
step control of the 6-point branch of bench_continuation.py would reach the Hopf point in
6 points). A constant step gives every mode the same predictor sequence, so the points
correspond one to one.

Printed per mode: CPU and wall of the branch (one thread), the corrector statistics, and
against the baseline (the first mode, ``sensitivities`` = today's default, in the same run):
the largest point distance (state in the length scale, period relative, p_c in Pa), the
largest difference of |μ_c|, equal stability flags and critical types, the same
bifurcations (kinds, parameters). Load printed before and after each mode.

    python benchmarks/bench_branch_fast.py                       # default, broyden, fast
    python benchmarks/bench_branch_fast.py --modes sensitivities fast --ds 0.05
    python benchmarks/bench_branch_fast.py --modes sensitivities fast:1e-4:0   # never re-run
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, print_load  # noqa: E402

import rotordyn as rd  # noqa: E402

SPEED_HZ, PC_PA, AY_M, C_M = 50.0, 0.05e6, -1.85e-3, 3e-4
KW = {"rtol": 1e-6, "tol": 1e-4}


def compare(base, br) -> str:
    """Point-by-point comparison of two branches with the same predictor sequence."""
    n = min(len(base), len(br))
    lines = [f"points {len(br)} (baseline {len(base)})"]
    if n == 0:
        return lines[0]
    dx = 0.0
    for a, b in zip(base.orbits[:n], br.orbits[:n]):
        L = a.length_scale_m
        dx = max(dx, float(np.max(np.abs(a.r[0] - b.r[0]))) / L)
    dT = float(np.max(np.abs(base.period_s[:n] - br.period_s[:n]) / base.period_s[:n]))
    dp = float(np.max(np.abs(base.parameter[:n] - br.parameter[:n])))
    dA = float(np.max(np.abs(base.amplitude_m[:n, 0] - br.amplitude_m[:n, 0])) / C_M)
    dmu = float(np.max(np.abs(base.max_multiplier[:n] - br.max_multiplier[:n])))
    same_stab = bool(np.array_equal(base.stable[:n], br.stable[:n]))
    same_type = base.critical_type[:n] == br.critical_type[:n]
    bk = [(b["kind"], round(b["parameter"], 1)) for b in base.bifurcations]
    fk = [(b["kind"], round(b["parameter"], 1)) for b in br.bifurcations]
    lines.append(f"max |dr0|/L {dx:.2e}, |dA|/c {dA:.2e}, |dT|/T {dT:.2e}, |dp_c| {dp:.3g} Pa, "
                 f"max ||mu_c| diff| {dmu:.2e}")
    lines.append(f"stability flags equal: {same_stab}; critical types equal: {same_type}")
    lines.append(f"bifurcations: {fk} (baseline {bk})")
    return "\n  ".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ds", type=float, default=0.0125)
    ap.add_argument("--max-points", type=int, default=50)
    ap.add_argument("--modes", nargs="+", default=["sensitivities", "broyden", "fast"],
                    help="newton modes; fast:SCREEN_RTOL:SCREEN_MARGIN sets the screening")
    ap.add_argument("--quiet", action="store_true", help="no per-point table")
    args = ap.parse_args()
    header("bench_branch_fast: rig limit-cycle branch over p_c, 50 Hz, a_y = -1.85 mm, "
           f"ds = ds_max = {args.ds}, max_points {args.max_points}")
    rig = rd.models.paper_rig()
    w0, c0 = time.perf_counter(), time.process_time()
    tr = rd.transient(rig, 0.6, SPEED_HZ, PC_PA, AY_M, disturbance_m=(0.0, 0.1 * C_M),
                      n_out=6001)
    cyc = rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=tr, **KW)
    print(f"start: {cyc} ({time.perf_counter() - w0:.1f} s wall, "
          f"{time.process_time() - c0:.1f} s CPU)")
    base = None
    for mode in args.modes:
        print_load(f"before {mode}")
        w0, c0 = time.perf_counter(), time.process_time()
        name, *extra = mode.split(":")  # fast:SCREEN_RTOL:SCREEN_MARGIN
        sk = dict(zip(("screen_rtol", "screen_margin"), map(float, extra)))
        br = rd.continuation(rig, "chamber_pressure_pa", (0.0, 0.12e6), cyc, ds=args.ds,
                             ds_max=args.ds, max_points=args.max_points, newton=name, **sk,
                             **KW)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        print(f"\n[{mode}] {br}")
        if not args.quiet:
            print(f"{'p_c MPa':>10} {'amplitude µm':>13} {'period ms':>10} {'|mu_c|':>8} "
                  f"{'type':>15} stable")
            for i in range(len(br)):
                print(f"{br.parameter[i] / 1e6:10.6f} {br.amplitude_m[i, 0] * 1e6:13.2f} "
                      f"{br.period_s[i] * 1e3:10.4f} {br.max_multiplier[i]:8.4f} "
                      f"{br.critical_type[i]:>15} {bool(br.stable[i])}")
        for b in br.bifurcations:
            print(f"bifurcation: {b['kind']} at p_c = {b['parameter'] / 1e6:.6f} MPa")
        mr = [o.stats["monodromy_rtol"] for o in br.orbits]
        print("monodromy tolerance per point: " + ", ".join(
            f"{r:g} x {mr.count(r)}" for r in sorted(set(mr))))
        print(f"stop: {br.stop} {br.message}; {br.stats}")
        print(f"[{mode}] {len(br)} points: {wall:.2f} s wall, {cpu:.2f} s CPU "
              f"({cpu / max(len(br), 1):.3f} s CPU per point)")
        if base is None:
            base = br
        else:
            print(f"[{mode}] against [{args.modes[0]}]:\n  {compare(base, br)}")
            n = min(len(base), len(br))
            d = np.abs(base.max_multiplier[:n] - br.max_multiplier[:n])
            print(f"  ||mu_c| diff| per point (|mu_c| of the baseline): " + ", ".join(
                f"{m:.4f}:{x:.1e}" for m, x in zip(base.max_multiplier[:n], d)))
        print_load(f"after {mode}")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
