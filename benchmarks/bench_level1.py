"""API 617 Level I beside ROSS's ``Rotor.run_level1`` on the same rotor (issue 18): the log
decrements at ROSS's Q steps, ROSS's log decrement at rotordyn's root-found Q_0, and the time
of each.

    .venv/bin/python benchmarks/bench_level1.py [--repeat 5]

The rotor (tests/test_level1_ross.py): a uniform steel shaft of 4 Timoshenko elements of 0.375 m,
Ø 50 mm, a disk (Ø 280 mm, 70 mm wide) at the middle node, two anisotropic linear bearings
(k_xx = 1 MN/m, k_yy = 0.8 MN/m, c = 200 N·s/m) at the ends, 500 rad/s; imported into rotordyn
with ``system_from_ross``. Q at the mid-span node in both.

Protocol (benchmarks/_common.py): one BLAS/OpenMP thread, interleaved repeats, medians of wall
and CPU time, machine load before and after. ROSS memoises run_modal per rotor: its caches are
cleared before each timed call. ROSS's first run_modal of a process takes ~17 s of one-off
start-up (not timed: the warm-up call). ROSS: ``run_level1(n=2, stiffness_range=(0, Q_max),
num=9)`` — 9 equally spaced Q, the log decrement of the first non-backward mode at each, no
Q_0. rotordyn: ``level1(system, speed)`` — Q_0 by bracketing and Brent's method, the first
forward mode followed by its shape, and a 25-point curve besides (34 points with the 9 Q of ROSS).
"""

from __future__ import annotations

import argparse
import os
import sys
import warnings

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from _common import (clear_ross_caches, fmt, footer, header, import_ross,  # noqa: E402
                     interleaved)

import rotordyn as rd  # noqa: E402
from rotordyn.model import system_from_ross  # noqa: E402

SPEED = 500.0  # rad/s
Q_MAX = 4.0e4  # N/m


def ross_rotor(ross):
    steel = ross.Material(name="bench_level1", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [ross.ShaftElement(0.375, 0.0, 0.05, material=steel, shear_effects=True,
                               rotary_inertia=True, gyroscopic=True) for _ in range(4)]
    disk = ross.DiskElement.from_geometry(n=2, material=steel, width=0.07, i_d=0.05, o_d=0.28)
    brg = [ross.BearingElement(n, kxx=1e6, kyy=0.8e6, cxx=200.0, cyy=200.0) for n in (0, 4)]
    return ross.Rotor(shaft, [disk], brg, rated_w=SPEED)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    header("API 617 Level I: rotordyn.level1 beside ROSS run_level1")
    ross = import_ross()
    if ross is None:
        print("ROSS not installed (pip install ross-rotordynamics 'plotly<7'): nothing to compare")
        return
    warnings.simplefilter("ignore")
    rotor = ross_rotor(ross)
    s = system_from_ross(rotor)
    qs = np.linspace(0.0, Q_MAX, 9)

    def run_ross():
        clear_ross_caches(rotor)
        return rotor.run_level1(n=2, stiffness_range=(0.0, Q_MAX), num=qs.size)

    def run_rd():
        return rd.level1(s, SPEED / (2 * np.pi), q_points_n_per_m=qs)

    t = interleaved({"ross": run_ross, "rd": run_rd}, repeat=args.repeat)
    lv, r = run_ross(), run_rd()
    ours = r.to_frame().set_index("applied_q_n_per_m").loc[qs]
    print(f"\n1) log decrement of the judged mode at ROSS's Q steps (speed {SPEED:g} rad/s, Q at "
          "the mid-span node)")
    print(f"{'Q (N/m)':>10} {'ROSS δ':>12} {'rotordyn δ':>12} {'difference':>11} "
          f"{'f rotordyn (Hz)':>16}")
    for q, a, b, f in zip(qs, lv.log_dec, ours["log_dec"], ours["freq_hz"]):
        print(f"{q:10.4g} {a:12.6f} {b:12.6f} {b - a:11.2e} {f:16.4f}")
    at = rotor.run_level1(n=2, stiffness_range=(r.q0_n_per_m, r.q0_n_per_m), num=1)
    print(f"\n2) rotordyn Q_0 = {r.q0_n_per_m:.6g} N/m (Brent); ROSS's δ there: "
          f"{at.log_dec[0]:.2e}")
    print(f"\n3) time per call (median of {args.repeat}, interleaved)")
    print(f"   ROSS run_level1, 9 Q values:          {t['ross']}")
    print(f"   rotordyn level1, Q_0 + {r.q_n_per_m.size}-point curve: {t['rd']}  "
          f"(ROSS / rotordyn = {t['ross'].wall / t['rd'].wall:.1f})")
    footer()


if __name__ == "__main__":
    main()
