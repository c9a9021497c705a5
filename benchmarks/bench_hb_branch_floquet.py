"""The refined Floquet product on a harmonic-balance branch (``rd.continuation(...,
method="harmonic_balance", floquet_tol=...)``, docs/nonlinear.md "Continuation by harmonic
balance"): the compressor on plain bearings (tests/data/models/compressor_plain.toml, 36 × 6
film grid), its oil-whip cycle at 130 Hz (HB from a 0.4 s transient) continued down in
speed past the fold near 121.7 Hz, the branch of tests/test_hb_continuation.py (ds 0.1,
rtol 1e-6, sensitivity_rtol 1e-5), with ``floquet_tol`` 0 (the baseline: the flow at every
point the screen calls close) and 1e-3 (those points refined first, the flow only where the
refinement leaves the verdict unresolved), timed in interleaved repeats (median; CPU beside
wall, one thread, load printed). Printed per point: the route, |μ_c| and the verdict of both,
and the fold of both.

    python benchmarks/bench_hb_branch_floquet.py [--repeat 2] [--max-points 7]
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn as rd  # noqa: E402

HB = "harmonic_balance"
MODEL = Path(__file__).parent.parent / "tests" / "data" / "models" / "compressor_plain.toml"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--max-points", type=int, default=7)
    ap.add_argument("--floquet-tol", type=float, default=1e-3)
    args = ap.parse_args()
    header("bench_hb_branch_floquet: compressor whip branch by HB, floquet_tol 0 against "
           f"{args.floquet_tol:g}")
    s = rd.System.from_toml(MODEL)
    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                              for b in s.bearings))
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, method=HB, tol=1e-8)
    print("start:", cyc)
    out = {}

    def branch(ftol):
        def run():
            out[ftol] = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, method=HB,
                                        tol=1e-8, ds=0.1, ds_max=0.1,
                                        max_points=args.max_points, direction=-1,
                                        rtol=1e-6, sensitivity_rtol=1e-5, floquet_tol=ftol)
        return run

    t = interleaved({"floquet_tol 0": branch(0.0),
                     f"floquet_tol {args.floquet_tol:g}": branch(args.floquet_tol)},
                    repeat=args.repeat, warmup=0)
    a, b = out[0.0], out[args.floquet_tol]
    print(f"{'speed Hz':>9} | {'route':>8} {'|mu_c|':>8} stable | {'route':>8} {'|mu_c|':>8} "
          f"{'error':>8} stable")
    for i in range(min(len(a), len(b))):
        ea = b.orbits[i].stats.get("floquet_error", np.nan)
        print(f"{a.parameter[i]:9.4f} | {a.orbits[i].stats['floquet']:>8} "
              f"{a.max_multiplier[i]:8.4f} {bool(a.stable[i])!s:>6} | "
              f"{b.orbits[i].stats['floquet']:>8} {b.max_multiplier[i]:8.4f} {ea:8.1e} "
              f"{bool(b.stable[i])!s:>6}")
    for name, br in (("0", a), (f"{args.floquet_tol:g}", b)):
        bif = ", ".join(f"{x['kind']} at {x['parameter']:.4f} Hz" for x in br.bifurcations)
        print(f"floquet_tol {name}: {len(br)} points, flow rechecks "
              f"{br.stats['flow_rechecks']}, refined {br.stats['refined']}; {bif}")
    for k, v in t.items():
        print(f"{k}: {v}")
    ka, kb = list(t)
    print(f"CPU ratio (refined / baseline): {t[kb].cpu / t[ka].cpu:.3f}")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
