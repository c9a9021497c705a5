"""Figures of the Swift–Stieber THD film that the cavitated cells' fill moves
(docs/film-physics.md, "Thermo-hydrodynamic film", "Fill of a cavitated cell next to the full
film"): the benchmark plain bearing (D = 0.1 m, L = 0.05 m, c = 0.1 mm, VG 32 at 45 °C, 5 kN,
100 Hz, no groove) on 36 × 8 … 288 × 64 with T_max, T_mean, ε and the power loss (and the
observed orders of T_max and P), beside the effective model; and the tilted plain bearing of
"Plain and tilting-pad bearings, standalone" (72 × 16, 4 kN, 100 Hz, λ = 0.5) at θy = 0 …
0.6 mrad.

Run ``python docs/calibration/thd_fill_figures.py [--fine]`` (--fine adds 288 × 64).
"""

import math
import sys

import numpy as np

import rotordyn
from rotordyn.bearings import Oil

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
GEO = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4)


def bearing(n, m):
    return rotordyn.JournalBearing(viscosity_pa_s=VG32.viscosity_pa_s(45.0), n_circ=n,
                                   n_axial=m, **GEO)


def main(fine):
    grids = [(36, 8), (72, 16), (144, 32)] + ([(288, 64)] if fine else [])
    tm, pw = [], []
    print("grid     T_max (C)  T_mean (C)  eps      P (W)    cavitated cells")
    for n, m in grids:
        r = bearing(n, m).thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                                              supply_temperature_c=45.0, model="thd")
        tm.append(r.max_temperature_c)
        pw.append(r.power_loss_w)
        print(f"{n}x{m:<4d}  {r.max_temperature_c:.4f}   {r.mean_temperature_c:.4f}    "
              f"{r.eccentricity_ratio:.5f}  {r.power_loss_w:.2f}  "
              f"{int((np.asarray(r.flows['fill']) < 1).sum())}")
    for name, v in (("T_max", tm), ("P", pw)):
        d = np.diff(v)
        orders = [math.log2(d[i] / d[i + 1]) if d[i] * d[i + 1] > 0 else float("nan")
                  for i in range(len(d) - 1)]
        print(f"{name}: differences {np.round(d, 4).tolist()}, observed orders "
              f"{np.round(orders, 2).tolist()}")
    ef = bearing(72, 16).thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                                             supply_temperature_c=45.0)
    print(f"effective (72x16): T_eff {ef.effective_temperature_c:.4f} eps "
          f"{ef.eccentricity_ratio:.5f} P {ef.power_loss_w:.2f}")
    print("tilted plain THD (72x16, 4 kN, 100 Hz, lambda 0.5)")
    b = rotordyn.JournalBearing(viscosity_pa_s=0.02, n_circ=72, n_axial=16, **GEO)
    for t in (0.0, 0.2, 0.4, 0.6):
        r = b.thermal_equilibrium(load_n=(0.0, -4000.0), speed_hz=100.0, oil=VG32, model="thd",
                                  supply_temperature_c=45.0, carry_over=0.5,
                                  theta_y_rad=t * 1e-3, tilt=True)
        print(f"  {t:.1f} mrad: h_min {r.h_min_m * 1e6:.2f} um T_max {r.max_temperature_c:.4f} "
              f"eps {r.eccentricity_ratio:.5f} P {r.power_loss_w:.2f} "
              f"M {np.round(np.asarray(r.film_moment_n_m), 4).tolist()}")


if __name__ == "__main__":
    main("--fine" in sys.argv)
