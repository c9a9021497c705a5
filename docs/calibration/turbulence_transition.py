"""The turbulent film's laminar-to-turbulent transition on a large plain bearing (issue 20;
docs/film-physics.md, "Transition"): D = 0.3 m, L = 0.15 m, c = 0.45 mm, μ = 20 mPa·s,
ρ = 870 kg/m³ (Re_h at the clearance = 18.4 × speed_hz), 60 kN down, 72 × 16 grid,
Swift–Stieber. Per speed: the film's Re_h range at the equilibrium, and for the laminar film,
the Ng–Pan–Elrod film acting at every Re_h, and the same with the ramps 500–1000 (the range
ROSS's Suganami–Szeri eddy viscosity ramps over) and 1000–2000: eccentricity ratio, power
loss (friction torque × ω) and K_yy, C_yy. Then the THD film with its walls (film
coefficients, journal from its balance, a conducting bush; ISO VG 32 at 45 °C) at 100 Hz:
maximum film temperature, heat through the bush, power loss.

Run ``python docs/calibration/turbulence_transition.py``.
"""

import math

import numpy as np

import rotordyn
from rotordyn.bearings import Oil

BIG = dict(diameter_m=0.3, length_m=0.15, clearance_m=4.5e-4, viscosity_pa_s=0.02,
           n_circ=72, n_axial=16, density_kg_m3=870.0)
LOAD = (0.0, -60e3)
MODELS = {"laminar": dict(turbulence="laminar"),
          "ng_pan": dict(turbulence="ng_pan"),
          "ramp 500-1000": dict(turbulence="ng_pan", turbulence_onset_re=500.0,
                                turbulence_full_re=1000.0),
          "ramp 1000-2000": dict(turbulence="ng_pan", turbulence_onset_re=1000.0,
                                 turbulence_full_re=2000.0)}
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0, conductivity_w_per_m_k=0.13)
THD = dict(model="thd", wall_htc="film", journal_wall="balance", bush_wall="conduction",
           bush_thickness_m=0.03, bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=1000.0)


def main():
    for f in (50.0, 100.0, 200.0):
        w = 2.0 * math.pi * f
        re_c = BIG["density_kg_m3"] * w * 0.5 * BIG["diameter_m"] * BIG["clearance_m"] / \
            BIG["viscosity_pa_s"]
        print(f"\n{f:g} Hz (Re_h at the clearance {re_c:.0f})")
        for name, kw in MODELS.items():
            b = rotordyn.JournalBearing(**BIG, **kw)
            e = b.static_equilibrium(load_n=LOAD, speed_hz=f)
            r = b.solve(x_m=e.x_m, y_m=e.y_m, speed_hz=f)
            K, C = b.coefficients(x_m=e.x_m, y_m=e.y_m, speed_hz=f)
            eps = e.eccentricity_ratio
            print(f"  {name:15s} eps {eps:.4f}  Re_h {re_c * (1 - eps):5.0f}-{re_c * (1 + eps):5.0f}"
                  f"  power {r.friction_torque_n_m * w / 1e3:7.3f} kW  Kyy {K[1, 1]:.4e} N/m"
                  f"  Cyy {C[1, 1]:.4e} N s/m")
    print("\nTHD with walls, 100 Hz, ISO VG 32 at 45 degC")
    for name, kw in MODELS.items():
        b = rotordyn.JournalBearing(**{**BIG, "n_circ": 36, "n_axial": 8}, **kw)
        r = b.thermal_equilibrium(load_n=LOAD, speed_hz=100.0, oil=VG32,
                                  supply_temperature_c=45.0, **THD)
        print(f"  {name:15s} {r.status}  T_max {r.max_temperature_c:.2f} degC  eps "
              f"{r.eccentricity_ratio:.4f}  bush {r.heat_to_bush_w / 1e3:.3f} kW  power "
              f"{r.power_loss_w / 1e3:.3f} kW")


if __name__ == "__main__":
    main()
