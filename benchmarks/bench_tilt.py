"""Benchmark: journal tilt (issue 20) — the force and moments of a tilted journal beside the
force of the same journal untilted (goal: tilt adds <= 1.5x to a force).

Run ``python benchmarks/bench_tilt.py [--repeat 7]``. Protocol (benchmarks/_common.py): one
BLAS/OpenMP thread, the sides timed in interleaved repeats, medians, wall and CPU time side by
side, the machine load before and after.

Bearing: D = 50 mm, L = 40 mm, c = 0.1 mm, μ = 0.02 Pa·s, Swift–Stieber film, 72×16 grid,
50 Hz, journal near (0.3 c, −0.5 c), every call at a new x (x·(1 + 1e-4 k): the system film
would reuse a solve at unchanged inputs). Sides (each reuses its solver; 20 calls per repeat):
* ``untilted``: ``JournalBearing.forces`` (today's standalone film: the aligned journal's
  film is mirror-symmetric in z and solved on the half grid);
* ``untilted, system film``: the same film through ``tilted_forces`` at zero tilt (the
  four-coordinate system film; same half-grid solve);
* ``untilted, full grid``: the standalone film with the half-grid shortcut off (what any film
  that is not symmetric in z costs);
* ``tilted``: ``tilted_forces`` at θ = (0.2, −0.3) c/L (forces and moments; full grid).

Then the same for an elliptical (two-lobe, preload 0.5) ``FixedGeometryBearing`` of the same
size and grid (each lobe 36 × 16 on its mapped grid): ``untilted`` its two-coordinate lobe
films (one cached solver, ``film_forces``), ``untilted, 4-coordinate`` ``tilted_forces`` at
zero tilt, ``tilted`` at the same θ.
"""

from __future__ import annotations

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn  # noqa: E402
from rotordyn.bearings.tilt import tilted_forces  # noqa: E402

C, L = 1e-4, 0.04


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args(argv)
    header("journal tilt (issue 20)")
    geo = dict(diameter_m=0.05, length_m=L, clearance_m=C, viscosity_pa_s=0.02, n_circ=72,
               n_axial=16)
    b = rotordyn.JournalBearing(**geo)
    full = rotordyn.JournalBearing(**geo)
    full.solver().use_axial_symmetry = False
    tb = rotordyn.JournalBearing(**geo)
    st = dict(x_m=0.3 * C, y_m=-0.5 * C, speed_hz=50.0)
    th = dict(theta_x_rad=0.2 * C / L, theta_y_rad=-0.3 * C / L)
    # every call at a new position (the system film reuses a solve at unchanged inputs)
    count = [0]

    def pos():
        count[0] += 1
        return dict(st, x_m=st["x_m"] * (1.0 + 1e-4 * (count[0] % 1000)))

    t = interleaved({
        "untilted": lambda: b.forces(**pos()),
        "untilted, system film": lambda: tilted_forces(tb, **pos()),
        "untilted, full grid": lambda: full.forces(**pos()),
        "tilted": lambda: tilted_forces(tb, **pos(), **th),
    }, repeat=args.repeat, number=20)
    for k, v in t.items():
        print(f"force, 72x16 (eps 0.58, 50 Hz): {k:24s} {v}")
    base = t["untilted"]
    for k in ("untilted, system film", "untilted, full grid", "tilted"):
        print(f"  ratio {k} / untilted: {t[k].wall / base.wall:.2f}x wall, "
              f"{t[k].cpu / base.cpu:.2f}x CPU")
    print(f"  ratio tilted / untilted full grid: {t['tilted'].wall / t['untilted, full grid'].wall:.2f}x"
          f" wall, {t['tilted'].cpu / t['untilted, full grid'].cpu:.2f}x CPU (goal <= 1.5x "
          "against the untilted force; CPU is the figure when the wall time shows a busy machine)")
    f = tilted_forces(tb, **st, **th)
    print(f"tilted film: F = ({f.force_n[0]:.4g}, {f.force_n[1]:.4g}) N, M = "
          f"({f.moment_n_m[0]:.4g}, {f.moment_n_m[1]:.4g}) N m, h_min = {f.h_min_m:.4g} m at "
          f"phi = {f.h_min_angle_deg:.1f} deg, z = {f.h_min_z_m:+.4g} m")
    lobes(args.repeat, geo, st, th)
    footer()
    return 0


def lobes(repeat, geo, st, th) -> None:
    import math

    import numpy as np

    from rotordyn.bearings import FixedGeometryBearing

    fb = FixedGeometryBearing(station=0, kind="elliptical", **geo)
    s2 = fb._solver()  # the untilted lobes: two coordinates, one cached solver
    w = 2 * math.pi * st["speed_hz"]
    count = [0]

    def pos():
        count[0] += 1
        return dict(st, x_m=st["x_m"] * (1.0 + 1e-4 * (count[0] % 1000)))

    def untilted():
        p = pos()
        return s2.film_forces(np.array([p["x_m"], p["y_m"]]), np.zeros(2), w)

    t = interleaved({
        "untilted": untilted,
        "untilted, 4-coordinate": lambda: tilted_forces(fb, **pos()),
        "tilted": lambda: tilted_forces(fb, **pos(), **th),
    }, repeat=repeat, number=20)
    for k, v in t.items():
        print(f"elliptical force, 72x16: {k:24s} {v}")
    base = t["untilted"]
    for k in ("untilted, 4-coordinate", "tilted"):
        print(f"  ratio {k} / untilted: {t[k].wall / base.wall:.2f}x wall, "
              f"{t[k].cpu / base.cpu:.2f}x CPU")
    f = tilted_forces(fb, **st, **th)
    print(f"tilted elliptical: F = ({f.force_n[0]:.4g}, {f.force_n[1]:.4g}) N, M = "
          f"({f.moment_n_m[0]:.4g}, {f.moment_n_m[1]:.4g}) N m, h_min = {f.h_min_m:.4g} m at "
          f"phi = {f.h_min_angle_deg:.1f} deg, z = {f.h_min_z_m:+.4g} m")


if __name__ == "__main__":
    raise SystemExit(main())
