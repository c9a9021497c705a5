"""What shaft material damping changes on a large rotor: stability's max Re λ and the cost of
a nonlinear transient.

    python benchmarks/bench_shaft_damping.py [--zeta 0.002] [--speed 50] [--revs 10] [--repeat 1] [--unbalance 0.05]

Model: tests/data/models/turbine_two_axial_groove.toml (4.3 t steam turbine, 3.6 m, two
turbulent two-axial-groove bearings), full FE model (no reduction: its free bending modes
reach 9-12 kHz). β is chosen for a damping ratio ``zeta`` at the first bending mode of the
rotor at rest on rigid supports at its bearing stations: β = 2ζ/ω₁.

Printed for β = 0 (baseline) and β: the stability at ``speed`` Hz — max Re λ with the
frequency and kind of the mode that holds it, and the least damped mode below 100 Hz (the
film-coupled modes) — then transients of ``revs`` revolutions from the equilibrium (CVODE
BDF, the package's default tolerances), excited by an unbalance at the mid-span disk (smooth)
and by the journal node alone displaced by 0.1 c (a kink in the full FE model, which rings
every bending mode): the largest difference of the two runs' journal orbits (in
clearances), CVODE steps, stability-limit order
reductions, right-hand sides, Jacobians, and the median wall and CPU time of interleaved
repeats (default 1: the undamped run takes ~20 s CPU), with the machine load before and
after.
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from _common import footer, header  # noqa: E402

import rotordyn as rd  # noqa: E402

MODEL = Path(__file__).resolve().parents[1] / "tests" / "data" / "models" / \
    "turbine_two_axial_groove.toml"


def first_bending_rad_s(s: rd.System) -> float:
    """ω₁ of the rotor at rest on rigid supports at its bearing stations, rad/s."""
    rigid = dataclasses.replace(s, bearings=(), supports=tuple(
        rd.Support(b.station) for b in s.bearings))
    return float(rd.modes(rigid, 0.0, n_modes=2).eigenvalues.imag[0])


def stability_line(tag: str, s: rd.System, speed: float) -> None:
    st = rd.stability(s, speed)
    lam = st.eigenvalues
    i = int(np.argmax(lam.real))
    low = np.abs(lam.imag) / (2 * math.pi) < 100.0
    j = int(np.flatnonzero(low)[np.argmax(lam.real[low])])
    print(f"{tag}: stable={st.stable}; max Re λ {lam.real[i]:.4g} 1/s at "
          f"{lam.imag[i] / (2 * math.pi):.1f} Hz ({st.kind[i]}, {st.whirl[i]}); least damped "
          f"mode below 100 Hz: Re λ {lam.real[j]:.4g} 1/s at {lam.imag[j] / (2 * math.pi):.2f} Hz "
          f"(ζ {-lam.real[j] / abs(lam[j]):.4f}); {lam.size} eigenvalues")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--zeta", type=float, default=0.002)
    ap.add_argument("--speed", type=float, default=50.0)
    ap.add_argument("--revs", type=float, default=10.0)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--unbalance", type=float, default=0.05, help="kg·m at station 3")
    a = ap.parse_args()
    header("shaft material damping on the turbine model (full FE model)")
    s0 = rd.System.from_toml(MODEL)
    w1 = first_bending_rad_s(s0)
    beta = 2 * a.zeta / w1
    s1 = dataclasses.replace(s0, rotor=dataclasses.replace(s0.rotor, damping_beta_s=beta))
    print(f"first bending mode on rigid supports {w1 / (2 * math.pi):.2f} Hz; β = 2ζ/ω₁ = "
          f"{beta:.4g} s for ζ = {a.zeta}")
    hi = rd.modes(dataclasses.replace(s1, bearings=(), supports=tuple(
        rd.Support(b.station) for b in s1.bearings)), 0.0, n_modes=40).eigenvalues
    print(f"  (ζ = βω/2 at the highest of 40 rigid-support modes, {hi.imag[-1] / 2 / math.pi:.0f}"
          f" Hz: {beta * hi.imag[-1] / 2:.3f})")
    stability_line("β = 0    ", s0, a.speed)
    stability_line(f"β = {beta:.3g}", s1, a.speed)
    c = s0.bearings[0].clearance_m
    t_end = a.revs / a.speed
    starts = {  # two excitations: a smooth one, and the journal node alone displaced
        f"unbalance {a.unbalance} kg·m at station 3": dict(unbalances=[(3, a.unbalance, 0.0)]),
        "journal disturbed by 0.1 c": dict(disturbance_m=(0.0, 0.1 * c)),
    }
    cases = {"β = 0": s0, f"β = {beta:.3g}": s1}
    for name, kw in starts.items():
        print(f"-- transient, {a.revs:g} revolutions at {a.speed:g} Hz from the equilibrium, {name}")
        times = {k: ([], []) for k in cases}
        last = {}
        for _ in range(a.repeat):  # interleaved repeats: β = 0, β, β = 0, ...
            for tag, s in cases.items():
                w0, c0 = time.perf_counter(), time.process_time()
                tr = rd.transient(s, t_end, a.speed, n_out=2001, **kw)
                times[tag][0].append(time.perf_counter() - w0)
                times[tag][1].append(time.process_time() - c0)
                last[tag] = tr
                st = tr.stats
                print(f"{tag}: status {tr.status}; steps {st['steps']}, stability-limit order "
                      f"reductions {st['stab_lim_order_reductions']}, rhs {st['rhs_evals']}, "
                      f"Jacobians {st['jac_evals']}, error-test fails "
                      f"{st['error_test_fails']}; {times[tag][0][-1]:.1f} s wall, "
                      f"{times[tag][1][-1]:.2f} s CPU", flush=True)
        a0, a1 = (last[k] for k in cases)
        dj = np.hypot(a1.journal_x_m - a0.journal_x_m, a1.journal_y_m - a0.journal_y_m)
        amp = np.hypot(a0.journal_x_m - a0.journal_x_m[0], a0.journal_y_m - a0.journal_y_m[0])
        print(f"journal orbits, β against β = 0: largest difference {dj.max() / c:.2e} c "
              f"(the undamped run's largest excursion from the start: {amp.max() / c:.2e} c)")
        for tag, (w, cpu) in times.items():
            print(f"{tag}: median {statistics.median(w):.2f} s wall, "
                  f"{statistics.median(cpu):.2f} s CPU over {a.repeat} interleaved repeat(s)")
    footer()


if __name__ == "__main__":
    main()
