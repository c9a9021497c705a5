"""Limit-cycle branches over a model field (docs/nonlinear.md, "Branches of limit cycles over
a model field"): their cost against a branch over the speed in the same run, and the branch
over the clearance that ends at the Hopf point, against the equilibrium branch's Hopf point
and the threshold over the field.

Model: tests/data/models/compressor_plain.toml on a 36 × 6 film grid at 130 Hz; start: the
stable whip cycle from a 0.4 s transient (journal disturbed by 0.6 c) by harmonic balance
(H = 8, tol 1e-8).

1. Cost: ``--points`` points (default 6) with a constant step (ds = ds_max = 0.1) over both
   bearings' viscosity (0.010–0.030 Pa·s, upwards) and over the speed (120–140 Hz, upwards),
   harmonic-balance correctors, tol 1e-8, rtol 1e-6, sensitivity_rtol 1e-5, timed in
   ``--repeat`` interleaved repeats (medians; CPU beside wall; load printed), with each
   branch's corrector statistics.
2. The clearance branch (both bearings, 100 µm downwards to 50 µm, ds 0.1, ds_max 0.2,
   up to 25 points) from the whip cycle: its folds and its Hopf end, against the equilibrium
   branch over the clearance (Hopf refined by Brent on the arclength) and rd.threshold over
   the field (scan and Brent over rebuilt models).

    python benchmarks/bench_field_branch.py
    python benchmarks/bench_field_branch.py --repeat 3 --points 6
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved, print_load  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
HB = "harmonic_balance"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--points", type=int, default=6)
    args = ap.parse_args()
    header("limit-cycle branches over a model field (compressor 36 x 6, 130 Hz)")
    import rotordyn as rd

    s = rd.System.from_toml(ROOT / "tests" / "data" / "models" / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                              for b in s.bearings))
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, method=HB, tol=1e-8)
    print(f"start: {cyc!r}")
    kw = dict(method=HB, tol=1e-8, ds=0.1, ds_max=0.1, max_points=args.points, rtol=1e-6,
              sensitivity_rtol=1e-5)
    out = {}

    def run(name, vary, bounds):
        def fn():
            out[name] = rd.continuation(s, vary, bounds, cyc, **kw)
        return fn

    t = interleaved({"viscosity": run("viscosity", "bearings.*.viscosity_pa_s", (0.01, 0.03)),
                     "speed": run("speed", "speed_hz", (120.0, 140.0))},
                    repeat=args.repeat, warmup=0)
    for name in ("viscosity", "speed"):
        br = out[name]
        st = br.stats
        print(f"{name:9s}: {t[name]} for {len(br)} points "
              f"({t[name].cpu / len(br):.3f} s CPU per point); correctors {st['correctors']}, "
              f"Newton {st['newton_iterations']}, evaluations {st['evaluations']}, "
              f"fd evaluations {st['fd_evaluations']}, flow rechecks {st['flow_rechecks']}"
              + (f", assemblies {st['assemblies']}" if "assemblies" in st else ""))
        print(f"           {br!r}")
    print(f"CPU ratio viscosity / speed: {t['viscosity'].cpu / t['speed'].cpu:.2f}")
    print_load("after the cost runs")

    path = "bearings.*.clearance_m"
    c0, w0 = time.process_time(), time.perf_counter()
    br = rd.continuation(s, path, (0.5e-4, 1.2e-4), cyc, method=HB, tol=1e-8, ds=0.1,
                         ds_max=0.2, max_points=25, direction=-1, rtol=1e-6,
                         sensitivity_rtol=1e-5)
    cpu, wall = time.process_time() - c0, time.perf_counter() - w0
    print(f"clearance branch: {wall:.2f} s wall, {cpu:.2f} s CPU, {len(br)} points, stop "
          f"{br.stop}; {br.stats}")
    for b in br.bifurcations:
        print(f"  {b['kind']:5s} at {b['parameter'] * 1e6:.5f} µm (index {b['index']})")
    eq = rd.continuation(s, path, (0.6e-4, 1.0e-4), speed_hz=130.0, direction=-1, ds=0.05,
                         ds_max=0.1)
    th = rd.threshold(s, path, bounds=(0.6e-4, 1.0e-4), speed_hz=130.0)
    hp = eq.hopf_points()
    print(f"equilibrium branch Hopf: {[f'{x * 1e6:.5f} µm' for x in hp]}; threshold over the "
          f"field: {th.value * 1e6:.5f} µm (xtol {th.xtol:.1e} m)")
    end = [b for b in br.bifurcations if b["kind"] == "hopf"]
    if end and hp:
        print(f"orbit branch's Hopf end − equilibrium branch's: "
              f"{(end[0]['parameter'] - hp[0]) * 1e9:.3f} nm")
    footer()


if __name__ == "__main__":
    main()
