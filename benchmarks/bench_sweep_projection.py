"""A measured projection of a 10⁶-point Fig. 9 map on 2 cores (issue 22): `rotordyn sweep`
from the command line (start included) with `--threads 2` on a 10⁴-point map (100 × 100) and
on a ~10⁵-point map (316 × 316), chunk 250; wall and CPU (all processes) of each, the cost per
point at both sizes (their ratio shows whether the cost grows with the map) and 10⁶ × the
per-point wall and CPU of the larger run. The load average is printed before and after; on a
shared machine the wall figure is an upper bound of what 2 free cores would take.

``--baseline PYTHONPATH``: each size is also run with that PYTHONPATH (e.g. another checkout's
installed package, the code before a change), baseline and this tree alternating
``--repeat`` times; the medians and their CPU ratio are printed beside each other.

    python benchmarks/bench_sweep_projection.py [--sizes 100 316] [--threads 2]
        [--baseline PATH [--repeat 2]]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from bench_sweep_cli import run  # noqa: E402

SPEC = """schema = "rotordyn/sweep/1"
name = "fig9-map-{n}x{n}"
model = "paper-rig"
analysis = "stability"
chunk_size = 250

[grid]
config_ay_m = {{start = -2.5e-3, stop = 2.5e-3, num = {n}}}
chamber_pressure_pa = {{start = 0.0, stop = 0.3e6, num = {n}}}
speed_hz = 50.0
"""


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", type=int, nargs="+", default=[100, 316])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--baseline", default=None,
                    help="PYTHONPATH of the baseline package, run alternately with this tree")
    ap.add_argument("--repeat", type=int, default=1,
                    help="runs per size and side (medians; with --baseline)")
    args = ap.parse_args()
    exe = str(Path(sys.executable).with_name("rotordyn"))
    print(f"load average before: {load()} on {os.cpu_count()} cores")
    sides = [("this tree", None)]
    if args.baseline:
        sides = [("baseline", {"PYTHONPATH": args.baseline}),
                 ("this tree", {"PYTHONPATH": os.environ.get("PYTHONPATH", "")})]
    per, base = [], []
    with tempfile.TemporaryDirectory() as d:
        for n in args.sizes:
            sp = Path(d) / f"fig9-{n}.toml"
            sp.write_text(SPEC.format(n=n))
            out = Path(d) / "out"
            pts = n * n
            got: dict = {name: [] for name, _ in sides}
            for _ in range(args.repeat if args.baseline else 1):
                for name, env in sides:
                    shutil.rmtree(out, ignore_errors=True)
                    w, c, res = run([exe, "sweep", str(sp), "--out", str(out), "--json",
                                     "--threads", str(args.threads)], env)
                    got[name].append((w, c))
                    print(f"{name}: {n} x {n} = {pts} points, --threads {args.threads}: "
                          f"{w:.1f} s wall, {c:.1f} s CPU; {1e3 * w / pts:.3f} ms wall/point, "
                          f"{1e3 * c / pts:.3f} ms CPU/point; ok {res['ok']}, failed "
                          f"{res['failed']}, unstable {res['unstable']}; load now {load()}",
                          flush=True)
            med = {k: (statistics.median(x[0] for x in v), statistics.median(x[1] for x in v))
                   for k, v in got.items()}
            w, c = med["this tree"]
            per.append((pts, w / pts, c / pts))
            if args.baseline:
                wb, cb = med["baseline"]
                base.append((pts, wb / pts, cb / pts))
                print(f"{n} x {n}, medians of {args.repeat}: this tree / baseline CPU "
                      f"{c / cb:.3f}x ({1e3 * c / pts:.3f} vs {1e3 * cb / pts:.3f} ms CPU/point), "
                      f"wall {w / wb:.3f}x")
    if base:
        pb, wb1, cb1 = base[-1]
        print(f"baseline projection from the {pb}-point run: {1e6 * wb1 / 60:.1f} min wall, "
              f"{1e6 * cb1 / 60:.1f} CPU-min, {1e6 * cb1 / 60 / args.threads:.1f} min on "
              f"{args.threads} free cores")
    (p0, w0, c0), (p1, w1, c1) = per[0], per[-1]
    print(f"per-point cost, {p1} vs {p0} points: wall {w1 / w0:.2f}x, CPU {c1 / c0:.2f}x")
    print(f"projection to 10^6 points from the {p1}-point run: {1e6 * w1 / 60:.1f} min wall "
          f"(at this load), {1e6 * c1 / 60:.1f} CPU-min, i.e. "
          f"{1e6 * c1 / 60 / args.threads:.1f} min on {args.threads} free cores")
    print(f"load average after: {load()}")


if __name__ == "__main__":
    main()
