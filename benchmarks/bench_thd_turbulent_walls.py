"""The turbulent THD film's wall heat transfer (docs/film-physics.md, "Turbulent films with a
temperature field"): the large fast bearing of tests/test_thd_turbulent.py (D 0.3 m, L 0.15 m,
c 0.45 mm, 100 Hz, 60 kN, VG 32 supplied at 45 °C, turbulence "ng_pan") with its walls (the
film's own coefficients, the journal from its heat balance, a 30 mm steel bush cooled by oil at
its back, 1000 W/(m² K)), the film-side coefficients with the eddy conductivity against the laminar film's
(ThdOptions.wall_eddy_conductivity = False: the model before), in one run: the results, and
the CPU per equilibrium (median of interleaved repeats).

Run:  python benchmarks/bench_thd_turbulent_walls.py [--grid 48x12] [--repeat 5]
Protocol (benchmarks/_common.py): one BLAS/OpenMP thread for both sides (pinned and printed),
interleaved repeats, medians, CPU beside wall time, the machine load before and after.
"""

import argparse
import math
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import footer, header  # noqa: E402

import rotordyn  # noqa: E402
from rotordyn import _core  # noqa: E402
from rotordyn.bearings import Oil  # noqa: E402
from rotordyn.bearings.thd import run_thd_equilibrium, thd_options  # noqa: E402

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0, conductivity_w_per_m_k=0.13)
WALLS = dict(wall_htc="film", journal_wall="balance", bush_wall="conduction",
             bush_thickness_m=0.03, bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=1000.0)


def run(b, eddy, walls=True):
    g, grid = b.to_core()
    s = _core.ReynoldsSolver(g, grid, b.cavitation)
    o = thd_options(supply_temperature_c=45.0, **(WALLS if walls else {}))
    o.wall_eddy_conductivity = eddy
    c0, w0 = time.process_time(), time.perf_counter()
    r = run_thd_equilibrium(s, VG32, o, (0.0, -60e3), 100.0, b.clearance_m)
    return r, time.process_time() - c0, time.perf_counter() - w0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--grid", default="48x12")
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    nc, na = (int(x) for x in a.grid.split("x"))
    header("turbulent THD film's wall heat transfer")
    out = {}
    for turb in ("laminar", "ng_pan"):
        b = rotordyn.JournalBearing(diameter_m=0.3, length_m=0.15, clearance_m=4.5e-4,
                                    viscosity_pa_s=0.02, turbulence=turb, density_kg_m3=870.0,
                                    n_circ=nc, n_axial=na)
        rows = {"adiabatic": run(b, True, walls=False)[0]}
        cpu = {True: [], False: []}
        wall = {True: [], False: []}
        for _ in range(a.repeat):  # interleaved
            for eddy in (False, True):
                r, c, w = run(b, eddy)
                cpu[eddy].append(c)
                wall[eddy].append(w)
                rows["walls, eddy" if eddy else "walls, laminar coefficient"] = r
        out[turb] = (rows, cpu, wall)
    mu45 = VG32.viscosity_pa_s(45.0)
    print(f"grid {nc} x {na}; Re_h at h = c and 45 degC: "
          f"{870.0 * 2 * math.pi * 100.0 * 0.15 * 4.5e-4 / mu45:.0f}")
    print(f"{'film':8s} {'walls':28s} {'T_max':>7s} {'T_mean':>7s} {'T_J':>7s} {'T_wall':>7s} "
          f"{'P kW':>6s} {'Q_bush kW':>9s} {'eps':>6s} {'iters':>5s}")
    for turb, (rows, cpu, wall) in out.items():
        for name, r in rows.items():
            print(f"{turb:8s} {name:28s} {r.max_temperature_c:7.2f} {r.mean_temperature_c:7.2f} "
                  f"{r.journal_temperature_c:7.2f} {r.max_wall_temperature_c:7.2f} "
                  f"{r.power_loss_w / 1e3:6.1f} {r.heat_to_bush_w / 1e3:9.2f} "
                  f"{r.eccentricity_ratio:6.3f} {r.iterations:5d}")
        print(f"{'':8s} CPU s median (laminar coefficient / eddy): "
              f"{statistics.median(cpu[False]):.3f} / {statistics.median(cpu[True]):.3f} "
              f"(ratio {statistics.median(cpu[True]) / statistics.median(cpu[False]):.2f}); "
              f"wall s {statistics.median(wall[False]):.3f} / {statistics.median(wall[True]):.3f}")
    footer()


if __name__ == "__main__":
    main()
