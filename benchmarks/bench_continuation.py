"""Limit-cycle branch of the paper rig over the chamber pressure by pseudo-arclength
continuation (issue 19; docs/nonlinear.md prints these numbers).

Rig (``rd.models.paper_rig()``) at 50 Hz, a_y = −1.85 mm. Start: the stable cycle at
p_c = 0.05 MPa (paper Fig. 11) from a 0.6 s transient (journal disturbed by 0.1 c upwards)
and :func:`rotordyn.periodic_orbit` (rtol 1e-6, tol 1e-4). Then
:func:`rotordyn.continuation` over p_c upwards (bounds 0.04–0.12 MPa, ds 0.05, rtol 1e-6,
tol 1e-4), and downwards with ``--down``. Printed: every branch point (p_c, amplitude,
period, |μ_c|, stable), the bifurcations (the Hopf point where the cycle shrinks onto the
equilibrium: p_H by a parabola p(A) through the last points), the linear threshold of the
equilibrium (:func:`rotordyn.threshold`, Brent) and its whirl frequency for comparison, and
the least-damped eigenvalue at 0.1 MPa. Timing: the branch (one run; wall and CPU, one
thread) beside one shooting solve from the same transient (the baseline, median of 3), load
printed.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, measure, pin_threads  # noqa: E402

import rotordyn as rd  # noqa: E402

SPEED_HZ, PC_PA, AY_M, C_M = 50.0, 0.05e6, -1.85e-3, 3e-4
KW = {"rtol": 1e-6, "tol": 1e-4}


def print_branch(br) -> None:
    print(f"{br.vary:>20} {'amplitude µm':>13} {'period ms':>10} {'|mu_c|':>8} "
          f"{'dp/ds':>8} stable")
    for i in range(len(br)):
        print(f"{br.parameter[i]:20.6g} {br.amplitude_m[i, 0] * 1e6:13.2f} "
              f"{br.period_s[i] * 1e3:10.4f} {br.max_multiplier[i]:8.4f} "
              f"{br.tangent_p[i]:8.4f} {bool(br.stable[i])}")
    for b in br.bifurcations:
        print(f"bifurcation: {b['kind']} at {b['parameter']:.6g} (after point {b['index']})")


def compressor_plain():
    """tests/data/models/compressor_plain.toml with both films on 36 × 6 nodes."""
    import dataclasses

    s = rd.System.from_toml(Path(__file__).parent.parent / "tests" / "data" / "models"
                            / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                                 for b in s.bearings))


def whip_cycle(s):
    """The whip cycle at 130 Hz from a 0.4 s transient (journal disturbed by 60 µm)."""
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    return rd.periodic_orbit(s, 130.0, start=tr, **KW)


def whip(args) -> int:
    header("bench_continuation --whip: compressor on plain bearings, oil-whip cycles over "
           "the speed")
    s = compressor_plain()
    th = rd.threshold(s, "speed_hz", bounds=(60.0, 300.0))
    print(f"linear threshold: {th}")
    w0, c0 = time.perf_counter(), time.process_time()
    cyc = whip_cycle(s)
    print("start:", cyc)
    br = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, ds=0.1, ds_max=0.3,
                         max_points=12, direction=-1, newton=args.newton, **KW)
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    print(br)
    print_branch(br)
    print(f"stop: {br.stop} {br.message}; {br.stats}")
    print(f"transient + shooting + {len(br)}-point branch: {wall:.2f} s wall, {cpu:.2f} s CPU")
    footer()
    return 0


def floquet_routes(args) -> int:
    """The whip branch (7 points from 130 Hz down, as tests/test_continuation.py) with
    floquet="flow" (every point's final pass with the sensitivities in the error test) and
    "samples" (the films' linearisations at the samples, the flow only where the verdict is
    close): interleaved repeats, medians of wall and CPU, the ratio, the routes."""
    from _common import interleaved

    header("bench_continuation --floquet: shooting branch, floquet='flow' vs 'samples' "
           "(compressor on plain bearings, 36 x 6, whip branch 130 Hz down, 7 points)")
    s = compressor_plain()
    cyc = whip_cycle(s)
    print(f"newton={args.newton!r}, rtol 1e-6, tol 1e-4, n_out 101 (the default)")
    out = {}

    def run(route):
        def f():
            out[route] = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, ds=0.1,
                                         ds_max=0.3, max_points=7, direction=-1,
                                         newton=args.newton, floquet=route, **KW)
        return f

    t = interleaved({"flow": run("flow"), "samples": run("samples")}, repeat=args.repeat,
                    warmup=0)
    for route in ("flow", "samples"):
        br = out[route]
        print(f"\nfloquet={route!r}: {br}")
        print_branch(br)
        print("routes:", [o.stats.get("floquet") for o in br.orbits],
              "steps:", [o.stats["steps"] for o in br.orbits],
              "film solves:", [o.stats["reynolds_solves"] for o in br.orbits])
        print("sums: steps", sum(o.stats["steps"] for o in br.orbits), "film solves",
              sum(o.stats["reynolds_solves"] for o in br.orbits))
        print(f"stats: {br.stats}")
    for route in ("flow", "samples"):
        print(f"{route:>8}: {t[route]} (median of {args.repeat}; walls "
              f"{', '.join(f'{w:.2f}' for w in t[route].walls)} s)")
    print(f"ratio flow / samples: {t['flow'].wall / t['samples'].wall:.2f} wall, "
          f"{t['flow'].cpu / t['samples'].cpu:.2f} CPU")
    footer()
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ds", type=float, default=0.05)
    ap.add_argument("--max-points", type=int, default=50)
    ap.add_argument("--down", action="store_true", help="also continue towards lower p_c")
    ap.add_argument("--sensitivity-rtol", type=float, default=None,
                    help="monodromy tolerance of the branch (default: rtol = 1e-6)")
    ap.add_argument("--newton", choices=("broyden", "sensitivities", "exact", "fast"),
                    default="broyden",
                    help="the correctors' Newton matrix (default: Broyden updates from the "
                         "previous point's)")
    ap.add_argument("--whip", action="store_true",
                    help="only the oil-whip branch of the compressor on plain bearings "
                         "(tests/data/models/compressor_plain.toml, 36 x 6 film grid) from "
                         "130 Hz down in speed, 12 points: its folds")
    ap.add_argument("--others", action="store_true",
                    help="also continue the start over a_y (-3…0 mm) and the speed (20…120 Hz) "
                         "both ways, 15 points each (several minutes)")
    ap.add_argument("--floquet", action="store_true",
                    help="only the whip branch (7 points) with floquet='flow' against "
                         "floquet='samples', interleaved repeats")
    ap.add_argument("--repeat", type=int, default=3, help="--floquet: repeats of each")
    args = ap.parse_args()
    print(pin_threads(1))
    if args.floquet:
        return floquet_routes(args)
    if args.whip:
        return whip(args)
    header("bench_continuation: paper rig limit-cycle branch over p_c, 50 Hz, a_y = -1.85 mm")
    rig = rd.models.paper_rig()
    tr = rd.transient(rig, 0.6, SPEED_HZ, PC_PA, AY_M, disturbance_m=(0.0, 0.1 * C_M),
                      n_out=6001)
    cyc = rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=tr, **KW)
    print("start:", cyc)
    base = measure(lambda: rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=tr, **KW),
                   repeat=3, warmup=0)
    runs = [("up", 1)] + ([("down", -1)] if args.down else [])
    for name, d in runs:
        w0, c0 = time.perf_counter(), time.process_time()
        br = rd.continuation(rig, "chamber_pressure_pa", (0.0, 0.12e6), cyc, ds=args.ds,
                             max_points=args.max_points, direction=d,
                             sensitivity_rtol=args.sensitivity_rtol, newton=args.newton,
                             **KW)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        print(f"\nbranch {name}: {br}")
        print(f"{'p_c MPa':>10} {'amplitude µm':>13} {'A/c':>6} {'period ms':>10} "
              f"{'|mu_c|':>8} {'type':>15} stable")
        for i in range(len(br)):
            print(f"{br.parameter[i] / 1e6:10.6f} {br.amplitude_m[i, 0] * 1e6:13.2f} "
                  f"{br.amplitude_m[i, 0] / br.clearance_m[0]:6.3f} "
                  f"{br.period_s[i] * 1e3:10.4f} {br.max_multiplier[i]:8.4f} "
                  f"{br.critical_type[i]:>15} {bool(br.stable[i])}")
        for b in br.bifurcations:
            extra = (f", period {b['period_s'] * 1e3:.4f} ms ({1 / b['period_s']:.4f} Hz), "
                     f"p = p_H + b·A + c·A² with c = {b['curvature']:.4g} Pa/m²"
                     if b["kind"] == "hopf" else "")
            print(f"bifurcation: {b['kind']} at p_c = {b['parameter'] / 1e6:.6f} MPa{extra}")
        print(f"stop: {br.stop} {br.message}; {br.stats}")
        print(f"branch {name}: {len(br)} points in {wall:.2f} s wall, {cpu:.2f} s CPU "
              f"({cpu / max(len(br), 1):.2f} s CPU per point); baseline one shooting solve: "
              f"{base}")
    if args.others:
        for vary, bounds, d in [("config_ay_m", (-3e-3, 0.0), 1), ("config_ay_m", (-3e-3, 0.0), -1),
                                ("speed_hz", (20.0, 120.0), 1), ("speed_hz", (20.0, 120.0), -1)]:
            w0 = time.perf_counter()
            br = rd.continuation(rig, vary, bounds, cyc, ds=args.ds, max_points=15,
                                 direction=d, **KW)
            print(f"\n{vary} direction {d:+d}: {br} ({time.perf_counter() - w0:.1f} s wall)")
            print(f"  last point: {br.parameter[-1]:.6g}, amplitude "
                  f"{br.amplitude_m[-1, 0] * 1e6:.1f} µm, |mu_c| {br.max_multiplier[-1]:.4f}")
    th = rd.threshold(rig, bounds=(0.04e6, 0.08e6), speed_hz=SPEED_HZ, config_ay_m=AY_M)
    print(f"\nlinear threshold: {th}")
    st = rd.stability(rig, SPEED_HZ, 0.1e6, AY_M)
    print(f"at 0.1 MPa: {st}")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
