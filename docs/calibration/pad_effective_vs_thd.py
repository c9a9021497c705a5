"""The effective-temperature pad model against the THD pad film (issue 20; docs/film-physics.md,
"Effective-temperature pad bearings"): the numbers that section quotes.

1. The ROSS-like tilting-pad case of the THD section (5 pads of 60°, preload 0.5,
   D = 101.6 mm, c = 74.9 µm, L = 50.8 mm, 3000 rpm, 72 × 12 nodes, load (864.9, −2611.2) N),
   with our ISO VG 32 Walther law (not ROSS's exponential law) supplied at 40 °C, adiabatic,
   λ = 0: per pad T_eff (k = 0.5 and 1) against the THD mean, outlet temperatures, power
   loss, ε, K; the CPU time of each (one thread, `--repeat` interleaved runs, medians).
2. The 5-pad bearing of tests/test_film_thd_pads.py (D = 0.1 m, c = 0.1 mm, 4 kN, 100 Hz,
   supply 45 °C) with carry-over λ = 0 and 0.5: the two models side by side, and the flow
   each passes on to the next pad (both the pad's mass balance Q − Q_s; the THD pad's until
   2026-12-03 was its trailing-edge cells' flux into the gap, 2.3–5.8 Q).

    python docs/calibration/pad_effective_vs_thd.py [--repeat 5]
"""

import argparse
import os
import time

import numpy as np

from rotordyn.bearings import Oil, TiltingPadBearing

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def fmt(a, p=2):
    return "[" + ", ".join(f"{x:.{p}f}" for x in np.asarray(a)) + "]"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    print(f"load average {os.getloadavg()}")
    tp = TiltingPadBearing(station=0, diameter_m=101.6e-3, length_m=50.8e-3,
                           clearance_m=74.9e-6, viscosity_pa_s=VG32.viscosity_pa_s(40.0),
                           n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5, preload=0.5,
                           orientation_deg=18.0, pad_thickness_m=12.7e-3, n_circ=72, n_axial=12)
    kw = dict(load_n=(864.9, -2611.2), speed_hz=50.0, oil=VG32, supply_temperature_c=40.0)
    runs = {"isothermal": lambda: tp.full_coefficients(50.0, kw["load_n"]),
            "effective k=0.5": lambda: tp.thermal_equilibrium(**kw, model="effective"),
            "effective k=1": lambda: tp.thermal_equilibrium(**kw, model="effective",
                                                            effective_factor=1.0),
            "thd": lambda: tp.thermal_equilibrium(**kw)}
    cpu = {k: [] for k in runs}
    out = {}
    for _ in range(args.repeat):  # interleaved
        for k, f in runs.items():
            t = time.process_time()
            out[k] = f()
            cpu[k].append(time.process_time() - t)
    h = out["thd"]
    print("1. ROSS-like case, lambda = 0, pads at 18/90/162/234/306 deg")
    print(f"   THD:  eps {h.eccentricity_ratio:.4f}, iterations {h.iterations}, P "
          f"{h.power_loss_w_total:.1f} W; T_mean {fmt(h.mean_temperature_c)}; T_max "
          f"{fmt(h.max_temperature_c)}; T_out {fmt(h.outlet_temperature_c)}; K/1e7 "
          f"{fmt(h.K.ravel() / 1e7)}")
    for k in ("effective k=0.5", "effective k=1"):
        e = out[k]
        print(f"   {k}: eps {e.eccentricity_ratio:.4f}, iterations {e.iterations}, P "
              f"{e.power_loss_w_total:.1f} W; T_eff {fmt(e.effective_temperature_c)}; T_out "
              f"{fmt(e.outlet_temperature_c)}; K/1e7 {fmt(e.K.ravel() / 1e7)}")
        print(f"      T_eff - T_mean(THD) {fmt(e.effective_temperature_c - h.mean_temperature_c)}"
              f", T_out - T_out(THD) {fmt(e.outlet_temperature_c - h.outlet_temperature_c)}")
    iso = np.median(cpu["isothermal"])
    for k, c in cpu.items():
        print(f"   CPU {k}: {1e3 * np.median(c):.1f} ms ({np.median(c) / iso:.1f}x isothermal)")
    print("2. 5-pad bearing, 4 kN, 100 Hz, supply 45 degC")
    b = TiltingPadBearing(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                          viscosity_pa_s=0.02, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                          preload=0.3, n_circ=72, n_axial=6)
    for lam in (0.0, 0.5):
        kw2 = dict(load_n=(0.0, -4000.0), speed_hz=100.0, oil=VG32, supply_temperature_c=45.0,
                   carry_over=lam)
        e = b.thermal_equilibrium(**kw2, model="effective")
        h = b.thermal_equilibrium(**kw2)
        print(f"   lambda {lam}: effective eps {e.eccentricity_ratio:.4f}, T_max "
              f"{e.max_temperature_c_total:.2f}, T_in {fmt(e.inlet_temperature_c)}, passed on "
              f"(Q - Q_s)/Q {fmt(e.outlet_flow_m3_s / e.film_flow_m3_s)}")
        print(f"               THD eps {h.eccentricity_ratio:.4f}, T_max "
              f"{h.max_temperature_c_total:.2f}, T_in {fmt(h.inlet_temperature_c)}, passed on "
              f"Q_out/Q {fmt(h.outlet_flow_m3_s / h.film_flow_m3_s)}, fresh "
              f"{fmt(h.supply_flow_m3_s * 1e6, 1)} cm3/s")
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
