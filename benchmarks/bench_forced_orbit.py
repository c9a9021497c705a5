"""Forced (unbalance) orbit of the overhung pump by harmonic balance: the linear-response start
against the equilibrium start, measured in the same run (docs/nonlinear.md, "Forced orbits from
the linear response").

Model ``tests/data/models/pump_overhung.toml`` (36 coordinates, plain bearings with tilted
films) at ``--speed-hz``, unbalance at the impeller (station 3) of each ``--unbalances``
kg·m, H = 8, M = 32, tol 1e-6, Floquet multipliers from the samples. Both starts run in this
process with this build: the other fixes of that section (Eigen's products on one thread in
an orbit solve, the balanced Magnus exponentials, the film-thickness step cap) are in both
columns; their before figures were measured against the main build and are in the docs.
Median of ``--repeat`` interleaved repeats, wall and CPU, one thread, load printed.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn as rd  # noqa: E402

MODEL = Path(__file__).parent.parent / "tests" / "data" / "models" / "pump_overhung.toml"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--speed-hz", type=float, default=50.0)
    ap.add_argument("--unbalances", type=float, nargs="+", default=[5e-4, 5e-3])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    header("forced orbit of the overhung pump by harmonic balance: linear vs equilibrium start")
    pump = rd.System.from_toml(MODEL)
    for me in args.unbalances:
        runs = {}

        def solve(start, me=me):
            runs[start] = rd.periodic_orbit(pump, args.speed_hz, kind="forced",
                                            unbalances=[(3, me, 0.0)],
                                            method="harmonic_balance", forced_start=start)

        t = interleaved({s: (lambda s=s: solve(s)) for s in ("equilibrium", "linear")},
                        repeat=args.repeat)
        a, b = runs["equilibrium"], runs["linear"]
        print(f"\n{me:g} kg·m at {args.speed_hz:g} Hz: amplitude {a.amplitude(0) * 1e6:.4g} µm "
              f"(NDE), |mu_c| {abs(a.critical_multiplier):.5f}")
        for name, r in runs.items():
            print(f"  {name:12s} {r.status:4s} {r.stats['evaluations']:2d} evaluations  "
                  f"{t[name]}")
        print(f"  ratio equilibrium / linear: {t['equilibrium'].cpu / t['linear'].cpu:.2f}x CPU, "
              f"{t['equilibrium'].wall / t['linear'].wall:.2f}x wall; orbits differ by "
              f"{np.abs(a.r - b.r).max() / a.length_scale_m:.1e} L")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
