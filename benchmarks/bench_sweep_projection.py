"""A measured projection of a 10⁶-point Fig. 9 map on 2 cores (issue 22): `rotordyn sweep`
from the command line (start included) with `--threads 2` on a 10⁴-point map (100 × 100) and
on a ~10⁵-point map (316 × 316), chunk 250; wall and CPU (all processes) of each, the cost per
point at both sizes (their ratio shows whether the cost grows with the map) and 10⁶ × the
per-point wall and CPU of the larger run. The load average is printed before and after; on a
shared machine the wall figure is an upper bound of what 2 free cores would take.

    python benchmarks/bench_sweep_projection.py [--sizes 100 316] [--threads 2]
"""

from __future__ import annotations

import argparse
import os
import shutil
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
    args = ap.parse_args()
    exe = str(Path(sys.executable).with_name("rotordyn"))
    print(f"load average before: {load()} on {os.cpu_count()} cores")
    per = []
    with tempfile.TemporaryDirectory() as d:
        for n in args.sizes:
            sp = Path(d) / f"fig9-{n}.toml"
            sp.write_text(SPEC.format(n=n))
            out = Path(d) / "out"
            shutil.rmtree(out, ignore_errors=True)
            w, c, res = run([exe, "sweep", str(sp), "--out", str(out), "--json",
                             "--threads", str(args.threads)])
            pts = n * n
            per.append((pts, w / pts, c / pts))
            print(f"{n} x {n} = {pts} points, --threads {args.threads}: {w:.1f} s wall, "
                  f"{c:.1f} s CPU; {1e3 * w / pts:.3f} ms wall/point, {1e3 * c / pts:.3f} ms "
                  f"CPU/point; ok {res['ok']}, failed {res['failed']}, unstable "
                  f"{res['unstable']}; load now {load()}")
    (p0, w0, c0), (p1, w1, c1) = per[0], per[-1]
    print(f"per-point cost, {p1} vs {p0} points: wall {w1 / w0:.2f}x, CPU {c1 / c0:.2f}x")
    print(f"projection to 10^6 points from the {p1}-point run: {1e6 * w1 / 60:.1f} min wall "
          f"(at this load), {1e6 * c1 / 60:.1f} CPU-min, i.e. "
          f"{1e6 * c1 / 60 / args.threads:.1f} min on {args.threads} free cores")
    print(f"load average after: {load()}")


if __name__ == "__main__":
    main()
