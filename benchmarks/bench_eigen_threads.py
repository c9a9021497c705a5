"""Eigen's own threads in the C++ core: one thread (the package's default,
``rotordyn.set_eigen_threads(1)``) against Eigen's OpenMP default (``set_eigen_threads(None)``:
as many threads as OpenMP, here the cores) and, as a reference, OpenMP itself on one thread
(the batches' loops too, as ``OMP_NUM_THREADS=1`` does).

Analyses as users call them, on the turbine (two-axial-groove bearings) and the compressor
(plain bearings): stability at one speed, a Campbell diagram (12 speeds), a short transient
and a stability sweep chunk (``run_chunk``, 12 points). The three settings in interleaved
repeats in the same process, medians, wall and CPU of the process, load printed before and
after. The BLAS stays at one thread (the package's default) on every side.

    python benchmarks/bench_eigen_threads.py [--repeat 5]
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
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
    footer()


if __name__ == "__main__":
    main()
