"""A fold of static equilibria: a rigid rotor on two short (Ocvirk) bearings with a magnet at
one journal (issue 19; docs/nonlinear.md "A fold of equilibria").

Model (tests/magnet_fold_reference.py): a 4.0 kg rigid shaft (50 mm, 0.26 m, E = 1000 ×
steel) on two plain bearings D = 50 mm, L/D = 0.25, c = 50 µm, μ = 0.02 Pa·s with the core's
short π film (``FixedGeometryBearing(kind="partial_arc", arc_deg=360, film_model="short",
cavitation="gumbel")``), and a magnet pulling the journal B0 down: a linear support at station
0 with kyy = −1.5e7 N/m. Closed form (no rotordyn code): Ocvirk's load and attitude give the
journal's equilibria as C Ω f(ε) = P + k_m c d(ε); folds where the parameter is stationary.

Prints: the closed-form folds over the speed; the branch's folds, Hopf point and cost on four
film grids; the unstable count on each sheet; rd.equilibrium from 16 starts at three speeds;
the folds over the magnet's stiffness at 142 Hz.

Run:  .venv/bin/python docs/calibration/equilibrium_fold.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests"))
import rotordyn as rd  # noqa: E402
from magnet_fold_reference import MagnetFold, rotordyn_model  # noqa: E402
from rotordyn.analysis.assembly import assembled  # noqa: E402


def _cpu(fn):
    t = time.process_time()
    out = fn()
    return out, time.process_time() - t


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="the 720-node film only")
    args = ap.parse_args()
    print(f"load {os.getloadavg()[0]:.1f} (1 min); one thread")
    ref = MagnetFold()
    print(f"load share P = {ref.P:.4f} N, C = {ref.C:.6g} N·s, k_m = {ref.k_m:g} N/m")
    folds = ref.speed_folds()
    print("closed form, folds over the speed: "
          + ", ".join(f"{f:.5f} Hz (e/c {e:.5f})" for e, f in folds))

    grids = (720,) if args.quick else (360, 720, 1440, 2880)
    for nc in grids:
        s = rotordyn_model(n_circ=nc)
        br, cpu = _cpu(lambda: rd.continuation(s, "speed_hz", (120.0, 170.0), direction=-1))
        line = ", ".join(f"{b['kind']} {b['parameter']:.5f} Hz (e/c "
                         f"{br.eccentricity_at(b):.5f}{'' if b['smooth'] else ', non-smooth'})"
                         for b in br.bifurcations)
        err = [b["parameter"] / f - 1 for b, (_, f) in zip(
            sorted((b for b in br.bifurcations if b["kind"] == "fold"),
                   key=lambda b: b["parameter"]), folds)]
        print(f"{nc:5d} x 8: {len(br)} points, {cpu:.2f} s CPU: {line}; fold error "
              + ", ".join(f"{x:+.2e}" for x in err))
        if nc == 720:
            br720 = br
    br = br720
    print("720 x 8, the sheets (speed, e/c of B0, unstable eigenvalues, least-damped "
          "eigenvalue):")
    idx = sorted({0, len(br) - 1} | {b["index"] + d for b in br.bifurcations for d in (-1, 0)})
    for i in idx:
        print(f"  {i:3d}: {br.parameter[i]:9.4f} Hz  e/c {br.eccentricity_ratio[i, 0]:.4f}  "
              f"n_unstable {br.n_unstable[i]}  max Re {br.max_real_1_per_s[i]:9.3f} 1/s at "
              f"{br.freq_hz[i]:.3f} Hz{'  stable' if br.stable[i] else ''}")
    worst = max(abs(ref.speed_hz(e) / p - 1) for p, e in zip(br.parameter,
                                                               br.eccentricity_ratio[:, 0]))
    print(f"every point against the closed-form curve: worst {worst:.2e} of the speed")

    s = rotordyn_model(n_circ=720)
    b0 = assembled(s).bearings[0]
    c = s.bearings[0].clearance_m
    for speed in (130.0, 142.0, 155.0):
        base = np.asarray(rd.equilibrium(s, speed).r)
        found, status = [], {}
        t = time.process_time()
        for eps in (0.1, 0.3, 0.5, 0.7):
            for ang in (0.0, 90.0, 180.0, 270.0):
                r0 = base.copy()
                r0[b0.jx] = eps * c * math.cos(math.radians(ang))
                r0[b0.jy] = eps * c * math.sin(math.radians(ang))
                e = rd.equilibrium(s, speed, r0=r0, max_iter=30)
                status[e.status] = status.get(e.status, 0) + 1
                if e.status == "ok" and all(abs(float(e.eccentricity_ratio[0]) - x) > 1e-6
                                            for x in found):
                    found.append(float(e.eccentricity_ratio[0]))
        print(f"{speed:.0f} Hz, 16 starts ({time.process_time() - t:.2f} s CPU, {status}): "
              f"e/c {', '.join(f'{x:.6f}' for x in sorted(found))}; closed form "
              f"{', '.join(f'{x:.6f}' for x in ref.equilibria(speed))}")

    kb = ref.magnet_folds(142.0)
    print("closed form, folds over the magnet at 142 Hz: "
          + ", ".join(f"k_m {k:.6g} N/m (e/c {e:.5f})" for e, k in kb))
    for nc in (360, 720):
        s = rotordyn_model(n_circ=nc)
        br, cpu = _cpu(lambda: rd.continuation(s, "supports.0.kyy_n_per_m", (-1.7e7, -1.4e7),
                                               speed_hz=142.0, direction=-1, ds_max=0.2))
        fk = sorted(-b["parameter"] for b in br.bifurcations if b["kind"] == "fold")
        print(f"{nc:5d} x 8: {len(br)} points, {cpu:.2f} s CPU: "
              + ", ".join(f"{b['kind']} kyy {b['parameter']:.6g}" for b in br.bifurcations)
              + "; fold error " + ", ".join(f"{a / k - 1:+.2e}" for a, (_, k) in
                                            zip(fk, sorted(kb, key=lambda x: x[1]))))


if __name__ == "__main__":
    main()
