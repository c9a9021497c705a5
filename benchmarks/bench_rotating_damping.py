"""Rotating (internal) shaft damping on a fluid-film compressor: what it changes and what the
circulatory term costs.

    python benchmarks/bench_rotating_damping.py [--zeta 0.01] [--speed 100] [--revs 10] [--repeat 3]

Model: tests/data/models/compressor_plain.toml (three-impeller compressor rotor, 1.2 m, two
plain journal bearings), its own grids. β is chosen for a damping ratio ``zeta`` at the first
bending mode of the rotor at rest on rigid supports at its bearing stations: β = 2ζ/ω₁; the
same β is used stationary (``damping_rotating = false``) and rotating.

Printed for both: the journals' equilibrium at ``speed`` Hz (the rotating case's sideways
shift), max Re λ there, the speed threshold of instability (``rotordyn.threshold`` over
``speed_hz`` in [20, 400] Hz) with the whirl frequency, and a transient of ``revs``
revolutions from the equilibrium with an unbalance at the middle impeller: CVODE steps,
right-hand sides, Jacobians and the median wall and CPU time of interleaved repeats (the
rotating case adds a dense Ω K_c r to each right-hand side and Ω K_c to each Jacobian).
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn as rd  # noqa: E402

MODEL = Path(__file__).resolve().parents[1] / "tests" / "data" / "models" / \
    "compressor_plain.toml"


def first_bending_rad_s(s: rd.System) -> float:
    """ω₁ of the rotor at rest on rigid supports at its bearing stations, rad/s."""
    rigid = dataclasses.replace(s, bearings=(), supports=tuple(
        rd.Support(b.station) for b in s.bearings), reduction=rd.Reduction())
    return float(rd.modes(rigid, 0.0, n_modes=2).eigenvalues.imag[0])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--zeta", type=float, default=0.01)
    ap.add_argument("--speed", type=float, default=100.0)
    ap.add_argument("--revs", type=float, default=10.0)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    header("rotating shaft damping on the plain-bearing compressor")
    s0 = rd.System.from_toml(MODEL)
    w1 = first_bending_rad_s(s0)
    beta = 2 * a.zeta / w1
    print(f"first bending mode on rigid supports {w1 / (2 * math.pi):.2f} Hz; β = 2ζ/ω₁ = "
          f"{beta:.4g} s for ζ = {a.zeta}")
    cases = {rot: dataclasses.replace(s0, rotor=dataclasses.replace(
        s0.rotor, damping_beta_s=beta, damping_rotating=rot)) for rot in (False, True)}
    c = s0.bearings[0].clearance_m
    for rot, s in cases.items():
        tag = "rotating  " if rot else "stationary"
        e = rd.equilibrium(s, a.speed)
        st = rd.stability(s, a.speed)
        i = int(np.argmax(st.eigenvalues.real))
        print(f"{tag}: equilibrium at {a.speed:g} Hz, journals x/c "
              f"{np.array2string(e.journal_x_m / c, precision=5)}, y/c "
              f"{np.array2string(e.journal_y_m / c, precision=5)}; max Re λ "
              f"{st.eigenvalues.real[i]:.4g} 1/s at {st.eigenvalues.imag[i] / 2 / math.pi:.2f} "
              f"Hz ({st.whirl[i]})", flush=True)
        th = rd.threshold(s, "speed_hz", bounds=(20.0, 400.0))
        print(f"{tag}: speed threshold {th.value:.3f} Hz (status {th.status}, stable "
              f"{th.stable_side}), whirl {th.whirl_frequency_hz:.2f} Hz", flush=True)
    t_end = a.revs / a.speed
    kw = dict(unbalances=[(3, 1e-3, 0.0)], n_out=501)
    runs = {}

    def run(rot):
        def go():
            runs[rot] = rd.transient(cases[rot], t_end, a.speed, **kw)
        return go

    times = interleaved({"stationary": run(False), "rotating": run(True)}, repeat=a.repeat,
                        warmup=0)
    for rot, tag in ((False, "stationary"), (True, "rotating")):
        st = runs[rot].stats
        print(f"{tag}: transient {a.revs:g} revolutions at {a.speed:g} Hz, status "
              f"{runs[rot].status}; steps {st['steps']}, rhs {st['rhs_evals']}, Jacobians "
              f"{st['jac_evals']}; median {times[tag]} over {a.repeat} interleaved repeat(s)")
    d = np.hypot(runs[True].journal_x_m - runs[False].journal_x_m,
                 runs[True].journal_y_m - runs[False].journal_y_m)
    print(f"journal orbits, rotating against stationary: largest difference {d.max() / c:.3e} c")
    footer()


if __name__ == "__main__":
    main()
