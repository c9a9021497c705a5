"""How much could the film temperature move the paper rig's threshold (a_y = −1.85 mm, 50 Hz;
model 0.057 MPa, paper 0.098 MPa)? An estimate, not the THD rig (issue 20; docs/film-physics.md,
"The paper rig and temperature").

The rig has no plain journal bearing (ball bearings at the ends, rigid supports) and the
thermal models do not cover its active bearing (`system_thermal_equilibrium` refuses the rig:
printed below). So the estimate takes a proxy film: a rigid-bush plain journal bearing with the
active bearing's geometry (D = 50 mm, L = 40 mm, c = 0.3 mm, supply line at 90°, Reynolds
cavitation, 72 × 16) under the film force the active bearing carries at the isothermal
threshold's equilibrium, at 50 Hz, and runs its effective-temperature (λ = 0, k = 0.5; and
λ = 0.8, k = 1 as a hot bound) and adiabatic THD equilibria. The rig is then rerun
isothermally with the active bearing's viscosity at μ(T_eff) and at μ(T_mean) of the THD film
(one viscosity: the active bearing stays isoviscous, its sleeve and chambers untouched).

Oil (an assumption: the paper gives only η = 0.04 Pa·s): ISO VG 46 (Walther through 46 mm²/s
at 40 °C and 6.8 mm²/s at 100 °C, ρ = 870 kg/m³, c_p = 2000 J/(kg K)) supplied at 40 °C, where
μ = 0.040 Pa·s, the paper's η.

Run:  .venv/bin/python docs/calibration/paper_rig_thermal.py   (~1 min on 2 shared cores)
"""

from __future__ import annotations

import dataclasses

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings import Oil

AY_M = -1.85e-3
SPEED_HZ = 50.0
PC_BOUNDS = (0.0, 0.3e6)
SUPPLY_C = 40.0
VG46 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=46.0, t2_c=100.0, nu2_mm2_s=6.8,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def with_viscosity(rig, mu):
    return dataclasses.replace(rig, bearings=tuple(
        dataclasses.replace(b, viscosity_pa_s=mu) if isinstance(b, rd.ActiveJournalBearing)
        else b for b in rig.bearings))


def crossings(system):
    th = rd.threshold(system, "chamber_pressure_pa", bounds=PC_BOUNDS, speed_hz=SPEED_HZ,
                      config_ay_m=AY_M)
    return ", ".join(f"{x / 1e6:.4f}" for x in th.crossings) or "none"


def main() -> int:
    rig = rd.models.paper_rig()
    try:
        rd.system_thermal_equilibrium(rig, speed_hz=SPEED_HZ, oil=VG46,
                                      supply_temperature_c=SUPPLY_C)
    except rd.InputError as e:
        print(f"system thermal model on the rig: InputError: {e}")
    ab = next(b for b in rig.bearings if isinstance(b, rd.ActiveJournalBearing))
    print(f"oil ISO VG 46 at {SUPPLY_C:g} degC: mu = {VG46.viscosity_pa_s(SUPPLY_C):.4f} Pa s "
          f"(rig: {ab.viscosity_pa_s} Pa s)")
    iso = crossings(rig)
    print(f"isothermal rig: threshold crossings p_c = {iso} MPa")
    pc = float(iso.split(", ")[-1]) * 1e6
    e = rd.equilibrium(rig, speed_hz=SPEED_HZ, chamber_pressure_pa=pc, config_ay_m=AY_M)
    bc = next(b for b in assembled(rig).bearings if b.active)
    f = [float(e.film_force_n[bc.jx]), float(e.film_force_n[bc.jy])]  # on the journal
    load = (-f[0], -f[1])  # the load the film carries: minus the film force on the journal
    print(f"active bearing at p_c = {pc / 1e6:.4f} MPa: film force ({f[0]:.1f}, {f[1]:.1f}) N, "
          f"eps = {float(e.eccentricity_ratio[0]):.3f}")
    proxy = rd.JournalBearing(diameter_m=ab.diameter_m, length_m=ab.length_m,
                              clearance_m=ab.clearance_m, viscosity_pa_s=ab.viscosity_pa_s,
                              n_circ=ab.n_circ, n_axial=ab.n_axial, cavitation=ab.cavitation,
                              grooves=ab.grooves)
    eff = proxy.thermal_equilibrium(load_n=load, speed_hz=SPEED_HZ, oil=VG46,
                                    supply_temperature_c=SUPPLY_C)
    thd = proxy.thermal_equilibrium(load_n=load, speed_hz=SPEED_HZ, oil=VG46,
                                    supply_temperature_c=SUPPLY_C, model="thd")
    print(f"proxy plain film, effective: T_eff = {eff.effective_temperature_c:.2f} degC, "
          f"T_max = {eff.max_temperature_c:.2f}, P = {eff.power_loss_w:.3g} W, "
          f"mu = {eff.viscosity_pa_s:.4f} Pa s")
    hot = proxy.thermal_equilibrium(load_n=load, speed_hz=SPEED_HZ, oil=VG46,
                                    supply_temperature_c=SUPPLY_C, carry_over=0.8,
                                    effective_factor=1.0)
    print(f"proxy plain film, effective with carry-over 0.8 and k = 1 (a hot bound): T_eff = "
          f"{hot.effective_temperature_c:.2f} degC, mu = {hot.viscosity_pa_s:.4f} Pa s")
    mu_thd = VG46.viscosity_pa_s(thd.mean_temperature_c)
    print(f"proxy plain film, THD (adiabatic): T_mean = {thd.mean_temperature_c:.2f} degC, "
          f"T_max = {thd.max_temperature_c:.2f}, P = {thd.power_loss_w:.3g} W, "
          f"mu(T_mean) = {mu_thd:.4f} Pa s")
    for name, mu in (("effective", eff.viscosity_pa_s), ("THD mean", mu_thd),
                     ("hot bound", hot.viscosity_pa_s)):
        print(f"rig with the active bearing at mu = {mu:.4f} Pa s ({name}): threshold "
              f"crossings p_c = {crossings(with_viscosity(rig, mu))} MPa")
    print("paper: 0.098 MPa")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
