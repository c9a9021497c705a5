"""THD film: the whole bearing's energy balance against its power loss, and the documented
cases' T_max / T_mean / position (docs/film-physics.md "Heat of the inlet cells").

Balance (relative to the supply temperature T_s): the heat the side flows carry out,
ρc Q_s (T_side − T_s), the part of the flow reaching the inlet that is not carried over,
ρc (1 − λ) Q_r (T_r − T_s), and the walls' heat, against power_loss_w (Σ Φ over every cell).
Run: python docs/calibration/thd_inlet_heat.py   (prints one line per case)
"""
import numpy as np

import rotordyn
from rotordyn.bearings import Groove, JournalBearing, Oil

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
GEO = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4)
RC = 870.0 * 2000.0


def heat_out(r, lam, ts, rc=RC):
    conv = rc * (r.side_flow_m3_s * (r.side_temperature_c - ts)
                 + (1.0 - lam) * r.recirculation_flow_m3_s * (r.recirculation_temperature_c - ts))
    return conv + r.heat_to_journal_w + r.heat_to_bush_w


def line(tag, r, lam, ts):
    print(f"{tag:38s} Tmax {r.max_temperature_c:.4f} Tmean {r.mean_temperature_c:.4f} "
          f"Tin {r.inlet_temperature_c:.4f} eps {r.eccentricity_ratio:.5f} "
          f"att {np.degrees(np.arctan2(r.x_m, -r.y_m)):.3f} P {r.power_loss_w:.2f} "
          f"out/P {heat_out(r, lam, ts) / r.power_loss_w:.12f}", flush=True)


def main():
    for cav, gr in (("reynolds", []), ("none", []), ("jfo", [Groove(center_deg=90.0, width_deg=20.0)])):
        for nc, na in ((36, 8), (72, 16), (144, 32)):
            b = JournalBearing(viscosity_pa_s=VG32.viscosity_pa_s(45.0), n_circ=nc, n_axial=na,
                               cavitation=cav, grooves=gr, **GEO)
            for lam in (0.0, 0.5):
                r = b.thermal_equilibrium(load_n=(0, -5000.0), speed_hz=100.0, oil=VG32,
                                          supply_temperature_c=45.0, model="thd", carry_over=lam)
                line(f"{cav} g{len(gr)} {nc}x{na} lam {lam}", r, lam, 45.0)
            r = b.thermal_equilibrium(load_n=(0, -5000.0), speed_hz=100.0, oil=VG32,
                                      supply_temperature_c=45.0, model="thd", carry_over=0.5,
                                      journal_htc_w_m2k=2000.0, bush_htc_w_m2k=1000.0)
            line(f"{cav} g{len(gr)} {nc}x{na} lam 0.5 htc", r, 0.5, 45.0)
            r = b.thermal_equilibrium(load_n=(0, -5000.0), speed_hz=100.0, oil=VG32,
                                      supply_temperature_c=45.0, model="thd", carry_over=0.5,
                                      wall_htc="film", journal_wall="balance",
                                      bush_wall="conduction", bush_thickness_m=0.01,
                                      bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=500.0)
            line(f"{cav} g{len(gr)} {nc}x{na} lam 0.5 walls", r, 0.5, 45.0)


if __name__ == "__main__":
    main()
