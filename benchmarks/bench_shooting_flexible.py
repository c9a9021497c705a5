"""Forced orbit of the overhung pump by shooting: the sensitivity corrector (blocked against
CVODES's column-by-column one) and the BDF order, measured in the same run
(docs/nonlinear.md, "Shooting on a flexible rotor").

Model ``tests/data/models/pump_overhung.toml`` (36 coordinates, 72 monodromy columns) at
``--speed-hz``, ``--unbalance`` kg·m at the impeller (station 3), rtol 1e-8, tol 1e-6, from the
linear unbalance response. Part 1: the first two Newton flows with sensitivities
(``max_iter=1``, ``tol=1e-12``: no final pass, then status not_converged) for the
combinations of ``sensitivity_solve`` (columns: the path before) and ``bdf_max_order``, once
each (the path before, columns at order 5, takes minutes: ``--skip-old``). Part 2
(``--final``): the whole solve, whose final pass has the sensitivities in the error test
(capped at 2000 steps per output interval). Part 3 (``--others``): the compressor's forced
orbit and the paper rig's limit cycle, blocked against columns, median of ``--repeat``
interleaved repeats (same orbit, same multipliers, CPU). Part 4 (``--floquet``): the whole
pump solve (blocked) with the monodromy from the final error-controlled flow (``floquet=
"flow"``, the default) against the Magnus product on the orbit's samples (``"samples"``, no
final pass), once each for each corrector of ``--floquet-solves`` (the flow takes minutes):
CPU, wall, the residuals, the flows' tolerance factor after a stall and the multipliers.
One thread, load printed.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved, print_load  # noqa: E402

import rotordyn as rd  # noqa: E402

MODELS = Path(__file__).parent.parent / "tests" / "data" / "models"


def cpu(fn):
    c0, w0 = time.process_time(), time.perf_counter()
    out = fn()
    return out, time.process_time() - c0, time.perf_counter() - w0


def row(name, r, c, w):
    s = r.stats
    print(f"  {name:22s} {r.status:13s} {c:7.2f} s CPU {w:7.2f} s wall  flows "
          f"{s['iterations']:2d}  steps {s['steps']:6d}  order reductions "
          f"{s['order_reductions']:4d}  sensitivity solves {s['sens_linear_solves']:8d}  "
          f"factorisations {s['sens_factorizations']:5d}", flush=True)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--speed-hz", type=float, default=50.0)
    ap.add_argument("--unbalance", type=float, default=5e-4)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--skip-old", action="store_true",
                    help="part 1 without the path before (columns, order 5: minutes)")
    ap.add_argument("--floquet-routes", default="samples,flow",
                    help="part 4: the floquet routes to run, comma-separated")
    ap.add_argument("--no-part1", action="store_true",
                    help="skip part 1 (the first two Newton flows)")
    ap.add_argument("--final", action="store_true",
                    help="part 2: the whole solve with its final error-controlled pass")
    ap.add_argument("--others", action="store_true", help="part 3: compressor and rig")
    ap.add_argument("--floquet", action="store_true",
                    help="part 4: the monodromy from the final flow against the samples")
    ap.add_argument("--floquet-solves", default="columns,blocked",
                    help="part 4: the sensitivity correctors to run, comma-separated "
                         "(columns: the default; blocked: opt-in)")
    args = ap.parse_args()
    header("forced orbit of the overhung pump by shooting: blocked sensitivities (opt-in), BDF order")
    pump = rd.System.from_toml(MODELS / "pump_overhung.toml")
    ub = [(3, args.unbalance, 0.0)]
    f = args.speed_hz

    def shoot(**kw):
        return rd.periodic_orbit(pump, f, kind="forced", unbalances=ub, **kw)

    hb = shoot(method="harmonic_balance", tol=1e-10)
    print(f"harmonic balance (H = 8, tol 1e-10): {hb.status}, amplitude "
          f"{hb.amplitude(0) * 1e6:.4g} µm (NDE), |mu_c| {abs(hb.critical_multiplier):.5f}")

    combos = [] if args.no_part1 else [("blocked", 2), ("blocked", 5), ("columns", 2)]
    if combos:
        print("\npart 1: the two Newton flows with sensitivities (max_iter=1, tol 1e-12: no "
              "final pass)")
    if combos and not args.skip_old:
        combos.append(("columns", 5))
    for solve, order in combos:
        r, c, w = cpu(lambda: shoot(max_iter=1, tol=1e-12, sensitivity_solve=solve,
                                    bdf_max_order=order))
        row(f"{solve}, order {order}", r, c, w)
        print(f"    residuals {np.array2string(np.asarray(r.residuals), precision=2)}")
        print_load("    load")
    if args.final:
        print("\npart 2: the whole solve (blocked, order 2), max_steps 2000 per output "
              "interval")
        r, c, w = cpu(lambda: shoot(bdf_max_order=2, max_steps=2000,
                                    sensitivity_solve="blocked"))
        row("blocked, order 2", r, c, w)
        print(f"    {r.message[:300]}")
    if args.others:
        print("\npart 3: other models, blocked against columns (median of interleaved)")
        comp = rd.System.from_toml(MODELS / "compressor_plain.toml")
        rig = rd.models.paper_rig()
        tr = rd.transient(rig, 0.6, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5),
                          n_out=6001)
        cases = {
            "compressor forced 50 Hz": lambda s: rd.periodic_orbit(
                comp, 50.0, kind="forced", unbalances=[(3, 2e-4, 0.0)], rtol=1e-9, tol=1e-7,
                sensitivity_solve=s),
            "rig limit cycle 0.05 MPa": lambda s: rd.periodic_orbit(
                rig, 50.0, 0.05e6, -1.85e-3, start=tr, rtol=1e-6, tol=1e-4,
                sensitivity_rtol=1e-3, sensitivity_solve=s),
        }
        for name, fn in cases.items():
            out = {}
            tt = interleaved({s: (lambda s=s: out.__setitem__(s, fn(s)))
                              for s in ("columns", "blocked")}, repeat=args.repeat, warmup=0)
            a, b = out["columns"], out["blocked"]
            print(f"  {name}:")
            for s in ("columns", "blocked"):
                row(s, out[s], tt[s].cpu, tt[s].wall)
            if a.ok and b.ok:
                amp = np.abs(a.r - a.r.mean(axis=0)).max()
                mu_a = np.sort_complex(a.multipliers)
                mu_b = np.sort_complex(b.multipliers)
                print(f"    orbits differ by {np.abs(a.r - b.r).max() / amp:.1e} of the "
                      f"amplitude; |mu_c| {abs(a.critical_multiplier):.6f} / "
                      f"{abs(b.critical_multiplier):.6f}; multipliers differ by "
                      f"{np.abs(mu_a - mu_b).max():.1e}; CPU ratio "
                      f"{tt['columns'].cpu / tt['blocked'].cpu:.2f}x")
    if args.floquet:
        print("\npart 4: the whole solve (order 5), the monodromy from the final flow against "
              f"the orbit's samples; correctors {args.floquet_solves}")
        for solve in args.floquet_solves.split(","):
            out = {}
            for fq in args.floquet_routes.split(","):
                r, c, w = cpu(lambda: shoot(sensitivity_solve=solve, floquet=fq))
                out[fq] = r
                row(f"{solve}, floquet {fq}", r, c, w)
                print(f"    residuals {np.array2string(np.asarray(r.residuals), precision=2)}"
                      f"  flow_tol_factor {r.stats['flow_tol_factor']:g}"
                      f"  sensitivity flows {r.stats['sensitivity_flows']}")
                if r.ok:
                    print(f"    |mu| {np.array2string(np.abs(r.multipliers[:6]), precision=6)}"
                          f"  error estimate {r.stats.get('floquet_error')}")
                else:
                    print(f"    {r.message[:300]}")
                print_load("    load")
            a, b = out.get("flow"), out.get("samples")
            if a is not None and b is not None and a.ok and b.ok:
                d = np.abs(a.multipliers[:, None] - b.multipliers[None, :]).min(axis=1)
                print(f"    every flow multiplier within {d.max():.1e} of a samples multiplier; "
                      f"|mu_c| {abs(a.critical_multiplier):.6f} / "
                      f"{abs(b.critical_multiplier):.6f}; harmonic balance "
                      f"{abs(hb.critical_multiplier):.6f}")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
