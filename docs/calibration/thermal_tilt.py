"""Thermal films with a tilted journal (issue 20; docs/film-physics.md, "Thermal films with a
tilted journal"):

1. standalone: an elliptical bearing (D = 0.1 m, L = 0.05 m, C_b = 0.1 mm, 72 × 16), 4 kN,
   100 Hz, ISO VG 32 supplied at 45 °C, λ = 0.5, THD, the journal held at a tilt θy relative
   to the bearing: edge film, the hottest film temperature and where it is, the moment, and
   the CPU time against the untilted bearing;
2. the compressor of tests/data/models on two elliptical / three-lobe bearings (72 × 16) with
   its oil system (compressor_plain_thermal.toml's ``[thermal]``, THD), both housings
   misaligned by θy, 150 Hz: per bearing the hottest lobe's T_max, the edge film, and the
   least damped eigenvalue at the thermal equilibrium (``stability(thermal=True)``) beside the
   isothermal one.

Run ``python docs/calibration/thermal_tilt.py [--repeat 5]``.
"""

import argparse
import dataclasses
import os
import time
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.bearings import FixedGeometryBearing, Oil

MODEL = (Path(__file__).resolve().parents[2] / "tests" / "data" / "models"
         / "compressor_plain_thermal.toml")
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def compressor(kind, theta_y):
    s = rotordyn.System.from_toml(MODEL)
    bs = tuple(FixedGeometryBearing(station=b.station, name=b.name, diameter_m=b.diameter_m,
                                    length_m=b.length_m, clearance_m=b.clearance_m,
                                    viscosity_pa_s=b.viscosity_pa_s, kind=kind, tilt=True,
                                    config_theta_y_rad=theta_y) for b in s.bearings)
    return dataclasses.replace(s, bearings=bs, thermal=dataclasses.replace(s.thermal, model="thd"))


def cpu(fn, repeat):
    ts = []
    for _ in range(repeat):
        t0 = time.process_time()
        fn()
        ts.append(time.process_time() - t0)
    return float(np.median(ts))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    print(f"load average {os.getloadavg()}")
    b = FixedGeometryBearing(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                             viscosity_pa_s=0.02, kind="elliptical", tilt=True)
    kw = dict(load_n=(0.0, -4000.0), speed_hz=100.0, oil=VG32, supply_temperature_c=45.0,
              carry_over=0.5)
    print("1. standalone elliptical bearing, 72 x 16, 4 kN, 100 Hz")
    print("| theta_y (mrad) | h_min (um), z (mm) | T_max (degC), z of the hottest node (mm) | "
          "T_mean loaded lobe (degC) | eps | M_x, M_y (N m) | P (W) |")
    print("|---|---|---|---|---|---|---|")
    for th in (0.0, 0.2, 0.4, 0.6):
        r = b.thermal_equilibrium(**kw, theta_y_rad=th * 1e-3)
        k = int(np.argmax(r.max_temperature_c))
        T = r.temperature_c[k]
        kz = np.unravel_index(np.argmax(T), T.shape)[1]
        z = -0.5 * b.length_m + b.length_m * kz / (T.shape[1] - 1)
        print(f"| {th:.1f} | {r.h_min_m * 1e6:.2f}, {r.h_min_z_m * 1e3:+.1f} | "
              f"{r.max_temperature_c_total:.2f}, {z * 1e3:+.1f} | "
              f"{r.mean_temperature_c[k]:.2f} | {r.eccentricity_ratio:.4f} | "
              f"{r.film_moment_n_m[0]:+.3f}, {r.film_moment_n_m[1]:+.3f} | {r.power_loss_w_total:.1f} |")
    untilted = dataclasses.replace(b, tilt=False)
    t0 = cpu(lambda: untilted.thermal_equilibrium(**kw), args.repeat)
    t1 = cpu(lambda: b.thermal_equilibrium(**kw, theta_y_rad=4e-4), args.repeat)
    print(f"CPU (median of {args.repeat}): untilted {t0 * 1e3:.1f} ms, tilted 0.4 mrad with "
          f"K4, C4 {t1 * 1e3:.1f} ms ({t1 / t0:.2f}x)")
    print("2. compressor, 150 Hz, THD oil system, both housings misaligned by theta_y")
    print("| kind | theta_y (mrad) | T_max hottest lobe NDE / DE (degC) | h_min NDE / DE (um) | "
          "max Re lambda, thermal (1/s) | max Re lambda, isothermal (1/s) |")
    print("|---|---|---|---|---|---|")
    for kind in ("elliptical", "three_lobe"):
        for th in (0.0, 0.2, 0.4):
            s = compressor(kind, th * 1e-3)
            res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0)
            e = rotordyn.equilibrium(res.system, speed_hz=150.0)
            lt = rotordyn.stability(s, speed_hz=150.0, thermal=True).eigenvalues.real.max()
            li = rotordyn.stability(s, speed_hz=150.0).eigenvalues.real.max()
            hot = [max(t for n, t in zip(res.bearing_names, res.max_temperature_c)
                       if n.startswith(b.name + ".")) for b in s.bearings]
            print(f"| {kind} | {th:.1f} | {hot[0]:.2f} / {hot[1]:.2f} | "
                  f"{e.h_min_m[0] * 1e6:.2f} / {e.h_min_m[1] * 1e6:.2f} | {lt:.3f} | {li:.3f} |")
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
