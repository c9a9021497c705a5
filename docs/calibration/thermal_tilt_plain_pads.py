"""Standalone thermal equilibrium of a plain journal bearing and a 5-pad tilting-pad bearing
with a tilted journal (issue 20; docs/film-physics.md, "Thermal films with a tilted journal"):

1. a plain bearing of the compressor's size (D = 0.1 m, L = 0.05 m, c = 0.1 mm, 72 × 16),
   4 kN, 100 Hz, ISO VG 32 supplied at 45 °C, λ = 0.5, THD and effective temperature, the
   journal held at a tilt θy relative to the bearing;
2. the compressor's 5-pad rocker tilting-pad bearing (tests/data/models/compressor_tilting_pad
   .toml, 60° pads, preload 0.3, load between pads, 72 × 16), 1.5 kN, 150 Hz, THD;

per tilt: the edge film and its z, T_max, ε, the moments, the power loss; and the CPU time
of the tilted call against the untilted one (interleaved repeats, medians).

Run ``python docs/calibration/thermal_tilt_plain_pads.py [--repeat 5]``.
"""

import argparse
import dataclasses
import os
import time
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.bearings import Oil

MODELS = Path(__file__).resolve().parents[2] / "tests" / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def medians(fns, repeat):
    ts = [[] for _ in fns]
    for _ in range(repeat):
        for k, fn in enumerate(fns):
            t0 = time.process_time()
            fn()
            ts[k].append(time.process_time() - t0)
    return [float(np.median(t)) for t in ts]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    print(f"load average {os.getloadavg()}")
    plain = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                    viscosity_pa_s=0.02, n_circ=72, n_axial=16)
    kw = dict(load_n=(0.0, -4000.0), speed_hz=100.0, oil=VG32, supply_temperature_c=45.0,
              carry_over=0.5)
    print("plain bearing: model | th_y mrad | h_min um, z mm | T_max C | eps | Mx, My N m | P W")
    for model in ("thd", "effective"):
        for th in (0.0, 2e-4, 4e-4, 6e-4):
            r = plain.thermal_equilibrium(**kw, model=model, theta_y_rad=th, tilt=True)
            print(f"{model} | {th * 1e3:.1f} | {r.h_min_m * 1e6:.2f}, {r.h_min_z_m * 1e3:+.1f} | "
                  f"{r.max_temperature_c:.2f} | {r.eccentricity_ratio:.4f} | "
                  f"{r.film_moment_n_m[0]:+.3f}, {r.film_moment_n_m[1]:+.3f} | {r.power_loss_w:.1f}")
        t = medians([lambda: plain.thermal_equilibrium(**kw, model=model),
                     lambda: plain.thermal_equilibrium(**kw, model=model, theta_y_rad=4e-4)],
                    args.repeat)
        print(f"{model} CPU: untilted {t[0] * 1e3:.1f} ms, tilted 0.4 mrad {t[1] * 1e3:.1f} ms "
              f"({t[1] / t[0]:.2f}x)")
    pads = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml").bearings[0]
    pads = dataclasses.replace(pads, n_circ=72, n_axial=16, tilt=True)
    pkw = dict(load_n=(0.0, -1500.0), speed_hz=150.0, oil=VG32, supply_temperature_c=45.0,
               carry_over=0.5)
    print("5-pad bearing, THD: th_y mrad | h_min um, z mm | T_max C | eps | Mx, My N m | P W")
    for th in (0.0, 2e-4, 4e-4, 8e-4):
        r = pads.thermal_equilibrium(**pkw, theta_y_rad=th)
        print(f"{th * 1e3:.1f} | {r.h_min_m * 1e6:.2f}, {r.h_min_z_m * 1e3:+.1f} | "
              f"{r.max_temperature_c_total:.2f} | {r.eccentricity_ratio:.4f} | "
              f"{r.film_moment_n_m[0]:+.3f}, {r.film_moment_n_m[1]:+.3f} | {r.power_loss_w_total:.1f}")
    untilted = dataclasses.replace(pads, tilt=False)
    t = medians([lambda: untilted.thermal_equilibrium(**pkw),
                 lambda: pads.thermal_equilibrium(**pkw, theta_y_rad=4e-4)], args.repeat)
    print(f"pads CPU: untilted {t[0] * 1e3:.1f} ms, tilted 0.4 mrad {t[1] * 1e3:.1f} ms "
          f"({t[1] / t[0]:.2f}x)")
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
