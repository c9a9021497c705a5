"""Benchmark: the starved mass-conserving film (docs/film-physics.md, "A starved film") beside
the flooded one — the cost of meeting a metered groove supply.

Run ``python benchmarks/bench_starved_film.py [--repeat 7]``. Protocol (benchmarks/_common.py):
one BLAS/OpenMP thread, the sides timed in interleaved repeats, medians, wall and CPU time
side by side, the machine load before and after.

Bearing: D = 50 mm, L = 25 mm, c = 0.1 mm, μ = 0.02 Pa·s, an Elrod–Adams (jfo) film with one
axial groove at 90° (p = 0), 72×16 grid, 50 Hz, journal near (0.3 c, −0.5 c) (ε ≈ 0.58), every
call at a new position. Sides: the flooded film (no supply), and the film fed 50 % and 25 % of
what the flooded film draws there (a Brent root on the groove state: one flooded solve and
5–9 more); the forces, and the forces with K, C (held supply).
"""

from __future__ import annotations

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn  # noqa: E402
from rotordyn import Groove, JournalBearing  # noqa: E402

C = 1e-4


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args(argv)
    header("starved jfo film (metered groove supply)")

    def bearing(supply=None):
        return JournalBearing(diameter_m=0.05, length_m=0.025, clearance_m=C,
                              viscosity_pa_s=0.02, n_circ=72, n_axial=16, cavitation="jfo",
                              grooves=[Groove(90.0, 0.0, 0.0)], supply_flow_m3_s=supply)

    st = dict(x_m=0.3 * C, y_m=-0.5 * C, speed_hz=50.0)
    q = bearing().solve(**st).inlet_flow_m3_s
    sides = {"flooded": bearing(), "fed 50 %": bearing(0.5 * q), "fed 25 %": bearing(0.25 * q)}
    count = [0]

    def pos():
        count[0] += 1
        return dict(st, x_m=st["x_m"] * (1.0 + 1e-4 * (count[0] % 1000)))

    for what, call in (("force", lambda b: b.forces(**pos())),
                       ("force + K, C", lambda b: b.coefficients(**pos()))):
        t = interleaved({k: (lambda b=b: call(b)) for k, b in sides.items()},
                        repeat=args.repeat, number=10)
        for k, v in t.items():
            print(f"{what}, 72x16: {k:10s} {v}")
        base = t["flooded"]
        for k in ("fed 50 %", "fed 25 %"):
            print(f"  ratio {k} / flooded: {t[k].wall / base.wall:.2f}x wall, "
                  f"{t[k].cpu / base.cpu:.2f}x CPU")
    for k, b in sides.items():
        r = b.solve(**st)
        print(f"{k}: inlet fill {r.inlet_fill:.4f}, inflow {r.inlet_flow_m3_s:.4g} m^3/s, full "
              f"film from {r.full_film_start_deg:.1f} deg, F = ({r.force_n[0]:.4g}, "
              f"{r.force_n[1]:.4g}) N")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
