"""The cost and accuracy of the Floquet multipliers of one harmonic-balance orbit by route:
Hill's method (``floquet="hill"``) against the samples' Magnus monodromy (``"samples"``,
the default) and one CVODES sensitivity flow (``"flow"``, the reference), with ``"none"`` as
the cost of the orbit alone (docs/nonlinear.md, "Floquet multipliers by Hill's method").

Orbits (H = 8, M = 32, tol 1e-8): the paper rig's cycle at 50 Hz, p_c = 0.05 MPa, a_y =
−1.85 mm (as built), and the compressor's oil-whip cycle at 130 Hz on plain bearings (36 × 6,
tests/data/models/compressor_plain.toml). Each route solves the same orbit from the same
converged state (the Newton takes one or two iterations), so route − none is the
multipliers' cost. Timings: medians of interleaved repeats (none, samples, hill, flow, none,
…), one thread, CPU beside wall, load printed. Accuracy: |μ_c| and the trivial multiplier's
error of each route against the flow at ``--srtol`` (its own trivial error printed).

    python benchmarks/bench_hill.py                 # both orbits, 3 repeats
    python benchmarks/bench_hill.py --model compressor --repeat 5 --harmonics 12
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved, print_load  # noqa: E402

import rotordyn as rd  # noqa: E402

MODELS = Path(__file__).parent.parent / "tests" / "data" / "models"
ROUTES = ("none", "samples", "hill", "flow")


def rig_orbit(h: int):
    rig = rd.models.paper_rig()
    op = (50.0, 0.05e6, -1.85e-3)
    tr = rd.transient(rig, 0.6, *op, disturbance_m=(0.0, 3e-5), n_out=6001)
    return rig, op, rd.periodic_orbit(rig, *op, start=tr, method="harmonic_balance",
                                      harmonics=h, tol=1e-8, floquet="none")


def compressor_orbit(h: int, m: int | None = None):
    """The compressor's oil-whip cycle at 130 Hz (plain bearings 36 × 6) by harmonic balance
    with H = h, M = m (None: 4H), from a settled transient; (system, operating point, orbit)."""
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                              for b in s.bearings))
    op = (130.0, 0.0, None)
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    return s, op, rd.periodic_orbit(s, *op, start=tr, method="harmonic_balance", harmonics=h,
                                    time_points=m, tol=1e-8, floquet="none")


def run(name: str, make, args) -> None:
    system, op, o = make(args.harmonics)
    assert o.ok, o.message
    n = o.r.shape[1]
    print(f"\n{name}: {o}\n  n = {n} coordinates: Hill matrix {2 * n * (2 * args.harmonics + 1)}"
          f" rows (2n(2H + 1)); Jacobian for Hill on max(M, 8H) = "
          f"{max(4 * args.harmonics, 8 * args.harmonics)} samples")
    kw = dict(start=(o.r[0], o.v[0]), period_s=o.period_s, method="harmonic_balance",
              harmonics=args.harmonics, tol=1e-8, rtol=args.srtol, sensitivity_rtol=args.srtol)
    res = {}

    def solve(route):
        def f():
            res[route] = rd.periodic_orbit(system, *op, floquet=route, **kw)
        return f

    t = interleaved({r: solve(r) for r in ROUTES}, repeat=args.repeat, warmup=1)
    ref = res["flow"]
    assert all(res[r].ok for r in ROUTES), {r: res[r].message for r in ROUTES}
    mu_ref = abs(ref.critical_multiplier)
    print(f"  flow (reference, sensitivity_rtol {args.srtol:g}): |mu_c| {mu_ref:.6f}, trivial "
          f"error {abs(ref.trivial_multiplier - 1):.1e}")
    base = t["none"].cpu
    print(f"  {'route':>8} {'CPU ms':>9} {'wall ms':>9} {'CPU - none':>11} {'|mu_c|':>9} "
          f"{'- flow':>9} {'trivial err':>11} {'linearisations':>14}")
    for r in ROUTES:
        o = res[r]
        mc = abs(o.critical_multiplier) if o.critical_multiplier is not None else np.nan
        te = abs(o.trivial_multiplier - 1) if o.trivial_multiplier is not None else np.nan
        print(f"  {r:>8} {t[r].cpu * 1e3:9.1f} {t[r].wall * 1e3:9.1f} "
              f"{(t[r].cpu - base) * 1e3:11.1f} {mc:9.6f} {mc - mu_ref:+9.1e} {te:11.1e} "
              f"{o.stats.get('linearizations', 0):14d}")
    print(f"  CPU per repeat: " + ", ".join(f"{r} {[round(c * 1e3, 1) for c in t[r].cpus]}"
                                            for r in ROUTES))
    print_load(f"after {name}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", choices=("rig", "compressor", "both"), default="both")
    ap.add_argument("--harmonics", type=int, default=8)
    ap.add_argument("--repeat", type=int, default=3, help="interleaved repeats")
    ap.add_argument("--srtol", type=float, default=1e-8,
                    help="the flow's rtol and sensitivity_rtol (the reference)")
    args = ap.parse_args()
    header(f"bench_hill: Floquet routes of one HB orbit, H = {args.harmonics}, "
           f"repeat {args.repeat}")
    if args.model in ("rig", "both"):
        run("rig, 50 Hz, 0.05 MPa, a_y = -1.85 mm (as built)", rig_orbit, args)
    if args.model in ("compressor", "both"):
        run("compressor whip cycle, 130 Hz (36 x 6)", compressor_orbit, args)
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
