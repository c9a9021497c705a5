"""The 10⁴-point Fig. 9 map (100 × 100, chunk 100) from the command line, start included
(issue 22): `rotordyn sweep` with --threads 1 (the baseline, in the same run), --threads 2
and --workers 2, repeats interleaved; medians of wall time and of CPU time (the command and
every process it started: driver, worker processes), the load average before and after.

Goal: --workers 2 never slower than --threads 1 at this size; <= 7 s wall on 2 free cores.
    python benchmarks/bench_sweep_cli.py [--n 100] [--repeats 3]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SPEC = """schema = "rotordyn/sweep/1"
name = "fig9-map-{n}x{n}"
model = "paper-rig"
analysis = "stability"
chunk_size = 100

[grid]
config_ay_m = {{start = -2.5e-3, stop = 2.5e-3, num = {n}}}
chamber_pressure_pa = {{start = 0.0, stop = 0.3e6, num = {n}}}
speed_hz = 50.0
"""
MODES = (("--threads 1", ["--threads", "1"]), ("--threads 2", ["--threads", "2"]),
         ("--workers 2", ["--workers", "2"]))


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def run(cmd: list[str], env: dict | None = None) -> tuple[float, float, dict]:
    """Wall and CPU (user + system of the command and its reaped descendants) of one run;
    env: variables set for the command on top of the current ones."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, check=True,
                       env={**os.environ, "OMP_NUM_THREADS": "1", **(env or {})})
    w = time.perf_counter() - w0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    return w, cpu, json.loads(p.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100, help="points per axis (n x n map)")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    exe = str(Path(sys.executable).with_name("rotordyn"))
    print(f"load average before: {load()} (2-core machine shared with other work: wall "
          "times are noisy, CPU times less so)")
    times: dict[str, list] = {m: [] for m, _ in MODES}
    with tempfile.TemporaryDirectory() as d:
        sp = Path(d) / "fig9.toml"
        sp.write_text(SPEC.format(n=args.n))
        counts = {}
        for _ in range(args.repeats):
            for m, flags in MODES:
                out = Path(d) / "out"
                shutil.rmtree(out, ignore_errors=True)
                w, c, res = run([exe, "sweep", str(sp), "--out", str(out), "--json", *flags])
                times[m].append((w, c))
                counts[m] = {k: res[k] for k in ("ok", "failed", "unstable")}
    base_w = statistics.median(w for w, _ in times["--threads 1"])
    print(f"Fig. 9 map {args.n}x{args.n} = {args.n ** 2} points, chunk 100, "
          f"`rotordyn sweep` start included, median of {args.repeats}:")
    for m, _ in MODES:
        w = statistics.median(x for x, _ in times[m])
        c = statistics.median(x for _, x in times[m])
        print(f"  {m}: {w:6.2f} s wall, {c:6.2f} s CPU (all processes), "
              f"{w / base_w:.2f}x the --threads 1 wall; runs "
              + " ".join(f"{x:.1f}" for x, _ in times[m]) + f" s; {counts[m]}")
    same = len({json.dumps(c, sort_keys=True) for c in counts.values()}) == 1
    print(f"point counts equal across modes: {same}")
    print(f"load average after: {load()}")


if __name__ == "__main__":
    main()
