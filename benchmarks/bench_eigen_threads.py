"""Eigen's own threads in the C++ core: one thread (the package's default,
``rotordyn.set_eigen_threads(1)``) against Eigen's OpenMP default (``set_eigen_threads(None)``:
as many threads as OpenMP, here the cores) and, as a reference, OpenMP itself on one thread
(the batches' loops too, as ``OMP_NUM_THREADS=1`` does).

Analyses as users call them, on the turbine (two-axial-groove bearings) and the compressor
(plain bearings): stability at one speed, a Campbell diagram (12 speeds), a short transient
and a stability sweep chunk (``run_chunk``, 12 points). The three settings in interleaved
repeats in the same process, medians, wall and CPU of the process, load printed before and
after. The BLAS stays at one thread (the package's default) on every side.

With ``--cli``: also the command ``rotordyn stability MODEL`` as a whole process (import
included; the child's CPU from ``RUSAGE_CHILDREN``) under ``ROTORDYN_EIGEN_THREADS=default``,
``=1`` and ``OMP_NUM_THREADS=1``, interleaved, medians.

    python benchmarks/bench_eigen_threads.py [--repeat 5] [--cli]
"""

from __future__ import annotations

import argparse
from pathlib import Path

from threadpoolctl import threadpool_limits

from _common import footer, interleaved, print_load

import rotordyn as rd
from rotordyn.sweep.work import Job, run_chunk

MODELS = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"


def analyses(name, speed):
    s = rd.System.from_toml(MODELS / name)
    speeds = [speed * (0.5 + 0.05 * k) for k in range(12)]
    job = Job("b", s.to_toml(), "stability", {}, {"speed_hz": speeds})
    return {
        "stability": lambda: rd.stability(s, speed),
        "campbell (12 speeds)": lambda: rd.campbell(s, speeds),
        "transient (2 revolutions)": lambda: rd.transient(s, 2.0 / speed, speed, n_out=65),
        "sweep chunk (12 points)": lambda: run_chunk(job, 0, 0, len(speeds)),
    }


def setting(eigen, omp_one=False):
    def run(fn):
        rd.set_eigen_threads(eigen)
        if omp_one:
            with threadpool_limits(limits=1, user_api="openmp"):
                fn()
        else:
            fn()
        rd.set_eigen_threads(1)
    return run


SETTINGS = {"eigen=OpenMP default (before)": setting(None),
            "eigen=1 (the default now)": setting(1),
            "OpenMP=1 everywhere (ref.)": setting(None, omp_one=True)}


def cli(repeat):
    import os
    import resource
    import statistics
    import subprocess
    import sys
    import time

    exe = [sys.executable, "-m", "rotordyn", "stability"]
    envs = {"ROTORDYN_EIGEN_THREADS=default (before)": {"ROTORDYN_EIGEN_THREADS": "default"},
            "ROTORDYN_EIGEN_THREADS=1 (now)": {"ROTORDYN_EIGEN_THREADS": "1"},
            "OMP_NUM_THREADS=1 (ref.)": {"ROTORDYN_EIGEN_THREADS": "default",
                                         "OMP_NUM_THREADS": "1"}}
    for name, speed in (("turbine_two_axial_groove.toml", 55.0),
                        ("compressor_plain.toml", 150.0)):
        w = {k: [] for k in envs}
        c = {k: [] for k in envs}
        for _ in range(repeat):
            for k, extra in envs.items():
                env = {**os.environ, **extra}
                if "OMP_NUM_THREADS" not in extra:
                    env.pop("OMP_NUM_THREADS", None)
                r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
                t0 = time.perf_counter()
                subprocess.run(exe + [str(MODELS / name), "--speed-hz", str(speed)], env=env,
                               check=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
                r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
                w[k].append(time.perf_counter() - t0)
                c[k].append(r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime)
        print(f"-- rotordyn stability {name} --speed-hz {speed:g} (whole process)")
        base = statistics.median(c["ROTORDYN_EIGEN_THREADS=default (before)"])
        for k in envs:
            cm = statistics.median(c[k])
            print(f"    {k:40s} {statistics.median(w[k]):6.2f} s wall {cm:6.2f} s CPU"
                  f"   CPU/before {cm / base:5.2f}")
        print_load("    load")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--cli", action="store_true", help="also the command as a whole process")
    a = ap.parse_args()
    print("== Eigen's threads in the core: one thread vs OpenMP's count")
    print_load("machine before")
    for name, speed in (("turbine_two_axial_groove.toml", 55.0), ("compressor_plain.toml", 150.0)):
        print(f"-- {name}")
        for label, fn in analyses(name, speed).items():
            t = interleaved({k: (lambda run=run, fn=fn: run(fn)) for k, run in SETTINGS.items()},
                            repeat=a.repeat)
            base = t["eigen=OpenMP default (before)"]
            print(f"  {label}")
            for k, v in t.items():
                print(f"    {k:32s} {v.wall * 1e3:8.1f} ms wall {v.cpu * 1e3:8.1f} ms CPU"
                      f"   CPU/before {v.cpu / base.cpu:5.2f}")
            print_load("    load")
    if a.cli:
        cli(a.repeat)
    footer()


if __name__ == "__main__":
    main()
