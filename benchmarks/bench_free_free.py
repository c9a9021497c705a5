"""Cost of the rigid-body rule on a free-free rotor (cpp/src/modal_rigid.cpp): the O(n³)
mass-scaled rank analysis of K, made once per ModalOperator / Campbell call, against the same
rotor on two stiff linear supports (K regular: the analysis is never made).

    .venv/bin/python benchmarks/bench_free_free.py [--repeat 5] [--n-elements 100]

Protocol (benchmarks/_common.py): one BLAS/OpenMP thread, the two sides timed in interleaved
repeats, medians of wall and CPU time, load before and after. Each modal call is made on a new
model object (the System and ModalOperator caches cleared), so the rank analysis is in every
timed call; a Campbell diagram of 20 speeds makes it once.
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from _common import fmt, footer, header, interleaved  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.analysis.modes import clear_cache  # noqa: E402

MAT = rd.Material("steel", 7850.0, 2.1e11, 0.3)


def rotor(n_el: int, supported: bool) -> rd.System:
    secs = (rd.ShaftSection(1.5, 0.05, n_elements=n_el),)
    sup = ()
    if supported:
        sup = tuple(rd.Support(st, "linear", kxx_n_per_m=1e7, kyy_n_per_m=1e7) for st in (0, 1))
    return rd.System(rotor=rd.Rotor(secs), materials=(MAT,), supports=sup,
                     reduction=rd.Reduction(method="none"))


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--n-elements", type=int, default=100)
    a = ap.parse_args(argv)
    header(f"free-free rotor, {a.n_elements} elements ({4 * (a.n_elements + 1)} DOF)")
    free, sup = rotor(a.n_elements, False), rotor(a.n_elements, True)
    speeds = np.linspace(0.0, 100.0, 20)

    def modes(s):
        def f():
            clear_cache()
            rd.modes(s, speed_hz=10.0, n_modes=6)
        return f

    def campbell(s):
        def f():
            clear_cache()
            rd.rotor_campbell(s, speeds, n_modes=6)
        return f

    for what, mk in (("modes, 6 modes at 10 Hz", modes), ("rotor_campbell, 20 speeds", campbell)):
        t = interleaved({"supported": mk(sup), "free-free": mk(free)}, repeat=a.repeat)
        s, f = t["supported"], t["free-free"]
        print(f"{what:28s} supported {fmt(s.wall)} (CPU {fmt(s.cpu)})  free-free "
              f"{fmt(f.wall)} (CPU {fmt(f.cpu)})  ratio free/supported CPU {f.cpu / s.cpu:5.2f}")
    footer()


if __name__ == "__main__":
    main()
