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

Then tilting pads (five 60° pads, preload 0.5, load between pads, D = 100 mm, L = 50 mm,
c = 0.1 mm, μ = 0.018 Pa·s, 72×16 per 360° (12 × 16 per pad), 100 Hz, W = 1500 N; every call
at a new load or pose):
* standalone operating point: ``untilted`` today's ``coefficient_table`` at one speed (the
  pads' equilibrium under W and the synchronous 2×2, one C++ call) against ``tilted, rocker``
  and ``tilted, spherical``: ``misaligned_equilibrium`` at θ = (0.2, −0.3) c/L and the
  synchronous 4×4 ``tilted_coefficients`` there (the pads solved twice); ``one call``: the
  same from ``pad_misaligned_equilibrium(..., coefficients=True)`` (linearised about the
  equilibrium's own films);
* the film at a held pose with the pads in equilibrium (``tilted_forces``) at zero tilt and
  tilted, rocker and spherical;
* the compressor of tests/data/models on its two tilting-pad bearings (72×16): equilibrium and
  stability at 150 Hz from the centred state, aligned (``tilt = false``) against ``tilt =
  true`` with both housings misaligned by θy = 0.3 mrad, rocker and spherical pivots.
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
          f"({f.film_moment_n_m[0]:.4g}, {f.film_moment_n_m[1]:.4g}) N m, h_min = {f.h_min_m:.4g} m at "
          f"phi = {f.h_min_angle_deg:.1f} deg, z = {f.h_min_z_m:+.4g} m")
    lobes(args.repeat, geo, st, th)
    pads(args.repeat)
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
          f"({f.film_moment_n_m[0]:.4g}, {f.film_moment_n_m[1]:.4g}) N m, h_min = {f.h_min_m:.4g} m at "
          f"phi = {f.h_min_angle_deg:.1f} deg, z = {f.h_min_z_m:+.4g} m")


def pads(repeat) -> None:
    import dataclasses
    from pathlib import Path

    from rotordyn.bearings import (TiltingPadBearing, misaligned_equilibrium,
                                   tilted_coefficients)
    from rotordyn.bearings.tilt_pads import pad_misaligned_equilibrium

    geo = dict(station=0, diameter_m=0.1, length_m=0.05, clearance_m=C, viscosity_pa_s=0.018,
               n_pads=5, pad_arc_deg=60.0, preload=0.5, n_circ=72, n_axial=16)
    flat = TiltingPadBearing(**geo)
    rock = TiltingPadBearing(**geo, tilt=True)
    sph = TiltingPadBearing(**geo, tilt=True, pivot_type="spherical")
    th = dict(theta_x_rad=0.2 * C / 0.05, theta_y_rad=-0.3 * C / 0.05)
    count = [0]

    def load():
        count[0] += 1
        return (0.0, -1500.0 * (1.0 + 1e-4 * (count[0] % 1000)))

    def point(b):
        m = misaligned_equilibrium(b, load_n=load(), speed_hz=100.0, **th)
        return tilted_coefficients(b, x_m=m.x_m, y_m=m.y_m, speed_hz=100.0, **th)

    def one_call(b):
        return pad_misaligned_equilibrium(b, load_n=load(), speed_hz=100.0, coefficients=True,
                                          **th)

    t = interleaved({
        "untilted": lambda: flat.coefficient_table([100.0], load()),
        "tilted, rocker": lambda: point(rock),
        "tilted, spherical": lambda: point(sph),
        "tilted, rocker, one call": lambda: one_call(rock),
        "tilted, spherical, one call": lambda: one_call(sph),
    }, repeat=repeat, number=5)
    for k, v in t.items():
        print(f"tilting pads, equilibrium + K, C (5 x 60 deg, 72x16): {k:27s} {v}")
    for k in ("tilted, rocker", "tilted, spherical", "tilted, rocker, one call",
              "tilted, spherical, one call"):
        print(f"  ratio {k} / untilted: {t[k].wall / t['untilted'].wall:.2f}x wall, "
              f"{t[k].cpu / t['untilted'].cpu:.2f}x CPU")
    m = misaligned_equilibrium(rock, load_n=(0.0, -1500.0), speed_hz=100.0, **th)
    print(f"  rocker at theta: e = ({m.x_m / C:.4f}, {m.y_m / C:.4f}) c, M = "
          f"({m.film_moment_n_m[0]:.4g}, {m.film_moment_n_m[1]:.4g}) N m, h_min = {m.h_min_m:.4g} m at "
          f"z = {m.h_min_z_m:+.4g} m, path {m.path}")

    def pose():
        count[0] += 1
        return dict(x_m=0.1 * C * (1.0 + 1e-4 * (count[0] % 1000)), y_m=-0.3 * C,
                    speed_hz=100.0)

    t = interleaved({
        "zero tilt, rocker": lambda: tilted_forces(rock, **pose()),
        "tilted, rocker": lambda: tilted_forces(rock, **pose(), **th),
        "tilted, spherical": lambda: tilted_forces(sph, **pose(), **th),
    }, repeat=repeat, number=10)
    for k, v in t.items():
        print(f"tilting pads, film at a held pose (pads solved): {k:20s} {v}")
    for k in ("tilted, rocker", "tilted, spherical"):
        print(f"  ratio {k} / zero tilt: {t[k].wall / t['zero tilt, rocker'].wall:.2f}x wall, "
              f"{t[k].cpu / t['zero tilt, rocker'].cpu:.2f}x CPU")

    models = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"
    s0 = rotordyn.System.from_toml(models / "compressor_tilting_pad.toml")

    def system(**kw):
        return dataclasses.replace(s0, bearings=tuple(dataclasses.replace(b, **kw)
                                                      for b in s0.bearings))

    systems = {"aligned": system(),
               "misaligned, rocker": system(tilt=True, config_theta_y_rad=3e-4),
               "misaligned, spherical": system(tilt=True, config_theta_y_rad=3e-4,
                                               pivot_type="spherical")}

    def run(s):
        rotordyn.equilibrium(s, speed_hz=150.0, warm_start=False)
        return rotordyn.stability(s, speed_hz=150.0, warm_start=False)

    for s in systems.values():
        run(s)  # assembly (cached per system) outside the timing
    t = interleaved({k: (lambda s=s: run(s)) for k, s in systems.items()}, repeat=repeat,
                    number=1)
    for k, v in t.items():
        print(f"compressor on tilting pads, equilibrium + stability (150 Hz): {k:22s} {v}")
    for k in ("misaligned, rocker", "misaligned, spherical"):
        print(f"  ratio {k} / aligned: {t[k].wall / t['aligned'].wall:.2f}x wall, "
              f"{t[k].cpu / t['aligned'].cpu:.2f}x CPU")
    for k, s in systems.items():
        e = rotordyn.equilibrium(s, speed_hz=150.0, warm_start=False)
        st = rotordyn.stability(s, speed_hz=150.0)
        print(f"  {k}: h_min = {e.h_min_m[0]:.4g}, {e.h_min_m[1]:.4g} m, "
              f"{e.reynolds_solves} Reynolds solves, max Re(lambda) = "
              f"{max(st.eigenvalues.real):.4g} 1/s, {len(st.eigenvalues)} eigenvalues")


if __name__ == "__main__":
    raise SystemExit(main())
