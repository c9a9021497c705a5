"""Cost and accuracy of the refined sample multipliers of one harmonic-balance orbit
(``floquet="samples"``: the films linearised between the samples, Simpson-node Magnus, steps
doubled until |μ_c| moves by ≤ floquet_tol) against the former single product from the
M samples (``floquet_tol=0``: A(τ) interpolated, 4 Magnus steps per sample interval) and one
CVODES sensitivity flow (the reference), with ``"none"`` as the cost of the orbit alone
(docs/nonlinear.md, "Refined sample multipliers").

Orbits (tol 1e-8, the same orbit re-solved by each route from its converged state):
  compressor  the compressor's 0.9 c oil-whip cycle at 130 Hz, plain bearings 36 × 6
              (tests/data/models/compressor_plain.toml), H = 8, M = 32
  train-guyan the motor–fan train, Guyan-reduced to its 7 stations' translations (14
              coordinates, tests/data/models/motor_fan_train_guyan7.toml), 110 Hz, the whirl
              cycle from the equilibrium start at 0.9 c, H = 8, M = 32
  train       the full train (84 coordinates, tests/data/models/motor_fan_train.toml), same
              cycle: no flow reference by default (minutes of CPU; --train-flow)
Timings: medians of interleaved repeats, one thread, CPU beside wall, load printed.

    python benchmarks/bench_floquet_refine.py                        # compressor, train-guyan
    python benchmarks/bench_floquet_refine.py --model train --repeat 1
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved, print_load  # noqa: E402
from bench_hill import compressor_orbit  # noqa: E402

import rotordyn as rd  # noqa: E402

MODELS = Path(__file__).parent.parent / "tests" / "data" / "models"


def compressor(h: int, m: int | None):
    return compressor_orbit(h, m)  # bench_hill's case (the same cycle in both benchmarks)


def train(name: str):
    def make(h: int, m: int | None):
        s = rd.System.from_toml(MODELS / name)
        op = (110.0, 0.0, None)
        return s, op, rd.periodic_orbit(s, *op, method="harmonic_balance", harmonics=h,
                                        time_points=m, tol=1e-8, floquet="none",
                                        start_amplitude_c=0.9)
    return make


def run(name: str, make, args, flow: bool) -> None:
    system, op, o = make(args.harmonics, args.samples)
    assert o.ok, o.message
    print(f"\n{name}: {o}\n  n = {o.r.shape[1]} coordinates, H = {args.harmonics}, "
          f"M = {o.stats['time_points']}")
    kw = dict(start=(o.r[0], o.v[0]), period_s=o.period_s, method="harmonic_balance",
              harmonics=args.harmonics, time_points=args.samples, tol=1e-8, rtol=args.srtol,
              sensitivity_rtol=args.srtol)
    routes = {"none": dict(floquet="none"), "samples old": dict(floquet="samples", floquet_tol=0),
              "refined": dict(floquet="samples")}
    for tol in args.extra_tol:
        routes[f"refined {tol:g}"] = dict(floquet="samples", floquet_tol=tol,
                                          floquet_max_steps=args.max_steps)
    if flow:
        routes["flow"] = dict(floquet="flow")
    res = {}

    def solve(route):
        def f():
            res[route] = rd.periodic_orbit(system, *op, **routes[route], **kw)
        return f

    t = interleaved({r: solve(r) for r in routes}, repeat=args.repeat, warmup=0)
    assert all(res[r].ok for r in routes), {r: res[r].message for r in routes}
    mu_ref = abs(res["flow"].critical_multiplier) if flow else np.nan
    if flow:
        print(f"  flow (reference, sensitivity_rtol {args.srtol:g}): |mu_c| {mu_ref:.6f}, "
              f"trivial error {abs(res['flow'].trivial_multiplier - 1):.1e}")
    base = t["none"].cpu
    print(f"  {'route':>16} {'CPU s':>8} {'wall s':>8} {'CPU-none':>9} {'|mu_c|':>10} "
          f"{'- flow':>9} {'estimate':>9} {'resolved':>8} {'steps':>6} {'lins':>6} "
          f"{'trivial':>8}  |mu_c| per level")
    for r in routes:
        x = res[r]
        mc = abs(x.critical_multiplier) if x.critical_multiplier is not None else np.nan
        te = abs(x.trivial_multiplier - 1) if x.trivial_multiplier is not None else np.nan
        st = x.stats
        levels = " ".join(f"{v:.5g}" for v in st.get("floquet_moduli", ()))
        print(f"  {r:>16} {t[r].cpu:8.2f} {t[r].wall:8.2f} {t[r].cpu - base:9.2f} {mc:10.6f} "
              f"{mc - mu_ref:+9.1e} {st.get('floquet_error', np.nan):9.1e} "
              f"{str(x.stability_resolved):>8} {st.get('floquet_steps', 0):6d} "
              f"{st.get('floquet_linearizations', 0):6d} {te:8.1e}  {levels}")
    print_load(f"after {name}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", choices=("compressor", "train-guyan", "train", "both"),
                    default="both", help="both: compressor and train-guyan")
    ap.add_argument("--harmonics", type=int, default=8)
    ap.add_argument("--samples", type=int, default=None, help="M (default 4H)")
    ap.add_argument("--repeat", type=int, default=3, help="interleaved repeats")
    ap.add_argument("--srtol", type=float, default=1e-8,
                    help="the flow's rtol and sensitivity_rtol (the reference)")
    ap.add_argument("--extra-tol", type=float, nargs="*", default=[1e-5],
                    help="more refined runs at these floquet_tol (with --max-steps)")
    ap.add_argument("--max-steps", type=int, default=0, help="their floquet_max_steps")
    ap.add_argument("--train-flow", action="store_true", help="the full train's flow too")
    args = ap.parse_args()
    header(f"bench_floquet_refine: sample multipliers of one HB orbit, H = {args.harmonics}, "
           f"repeat {args.repeat}")
    if args.model in ("compressor", "both"):
        run("compressor whip cycle, 130 Hz (36 x 6)", compressor, args, True)
    if args.model in ("train-guyan", "both"):
        run("motor-fan train, Guyan (14), 110 Hz", train("motor_fan_train_guyan7.toml"), args,
            True)
    if args.model == "train":
        run("motor-fan train, full (84), 110 Hz", train("motor_fan_train.toml"), args,
            args.train_flow)
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
