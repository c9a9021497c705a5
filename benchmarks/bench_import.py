"""Start-up cost of the package and of the command line: ``import rotordyn``,
``rotordyn --help`` and ``rotordyn info`` in fresh interpreters, CPU time (user + system of
the child, from ``RUSAGE_CHILDREN``) and wall time, medians of interleaved repeats. The
baseline in the same run is a bare ``import numpy`` (the floor every rotordyn import pays);
``--against DIR`` adds the same commands with ``PYTHONPATH=DIR`` (e.g. an export of the code
before a change, ``git archive <rev> python | tar -x -C /tmp/base``, with ``_core`` linked),
interleaved with this tree's runs. Also the ``-X importtime`` cumulative time of the top-level
``rotordyn`` import (median) and which heavy libraries ``import rotordyn`` loads.

    python benchmarks/bench_import.py [--repeats 20] [--against /tmp/base/python]
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import time

HEAVY = ("pandas", "matplotlib", "dask", "distributed", "pyarrow", "scipy.optimize",
         "scipy.sparse", "scipy.linalg")
COMMANDS = (("import numpy (floor)", ["-c", "import numpy"]),
            ("import rotordyn", ["-c", "import rotordyn"]),
            ("rotordyn --help", ["-m", "rotordyn.cli", "--help"]),
            ("rotordyn info", ["-m", "rotordyn.cli", "info"]))


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def env_for(path: str | None) -> dict:
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    if path is not None:
        env["PYTHONPATH"] = path
    return env


def run(args: list[str], env: dict) -> tuple[float, float]:
    """Wall and CPU seconds (user + system) of one fresh interpreter running ``args``."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    subprocess.run([sys.executable, *args], env=env, check=True, capture_output=True)
    w = time.perf_counter() - w0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return w, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def importtime_s(env: dict) -> float:
    """Cumulative ``-X importtime`` seconds of the top-level ``rotordyn`` import."""
    p = subprocess.run([sys.executable, "-X", "importtime", "-c", "import rotordyn"], env=env,
                       check=True, capture_output=True, text=True)
    m = re.search(r"\|\s*(\d+) \| rotordyn\s*$", p.stderr, re.M)
    return int(m.group(1)) * 1e-6


def heavy_loaded(env: dict) -> list[str]:
    code = ("import rotordyn, sys; print(' '.join(m for m in %r if m in sys.modules))" % (HEAVY,))
    p = subprocess.run([sys.executable, "-c", code], env=env, check=True, capture_output=True,
                       text=True)
    return p.stdout.split()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=20)
    ap.add_argument("--against", default=None, help="PYTHONPATH of the code to compare with")
    a = ap.parse_args()
    print(f"== start-up cost, {a.repeats} interleaved repeats; python {sys.version.split()[0]}")
    print(f"machine before: load {load()} (1/5/15 min) on {os.cpu_count()} cores")
    sides = [("this", env_for(None))]
    if a.against:
        sides.insert(0, ("against", env_for(a.against)))
    for name, env in sides:
        print(f"[{name}] import rotordyn loads: {heavy_loaded(env) or 'none of ' + ' '.join(HEAVY)}")
    times = {(s, c): [] for s, _ in sides for c, _ in COMMANDS}
    imp = {s: [] for s, _ in sides}
    for _ in range(a.repeats):
        for s, env in sides:
            for c, args in COMMANDS:
                times[s, c].append(run(args, env))
            imp[s].append(importtime_s(env))
    print(f"{'command':24s} {'side':8s} {'CPU ms':>8s} {'wall ms':>8s}")
    for c, _ in COMMANDS:
        for s, _ in sides:
            w = statistics.median(t[0] for t in times[s, c]) * 1e3
            cpu = statistics.median(t[1] for t in times[s, c]) * 1e3
            print(f"{c:24s} {s:8s} {cpu:8.0f} {w:8.0f}")
    for s, _ in sides:
        print(f"-X importtime, cumulative 'rotordyn' [{s}]: {statistics.median(imp[s]) * 1e3:.0f} ms")
    print(f"machine after: load {load()} (1/5/15 min); the machine is shared, compare sides of "
          "one run, not runs")


if __name__ == "__main__":
    main()
