"""Benchmark: film physics of issue 20 — the effective-temperature (thermal) and the
thermo-hydrodynamic (THD) equilibrium + K, C of the 72×16 plain bearing beside the isothermal
equilibrium + K, C (goal <= 5x its cost), and
the turbulent (Ng–Pan–Elrod) force beside the laminar one; the same for systems: the
compressor of tests/data/models (two plain bearings) and the paper rig (its active bearing,
sleeve deformation in the film; a_y = −1.85 mm, 50 Hz, p_c = 0.1 MPa).

Run ``python benchmarks/bench_thermal.py [--repeat 7] [--rig-only]``. Protocol
(benchmarks/_common.py): one BLAS/OpenMP thread, the two sides of each ratio timed in
interleaved repeats, medians, wall and CPU time side by side, the machine load before and
after.

Bearing: D = 0.1 m, L = 0.05 m, c = 0.1 mm, Swift–Stieber film, 72×16 grid, 100 Hz, load
5 kN downwards; oil ISO VG 32 (Walther through 32 mm²/s at 40 °C and 5.4 mm²/s at 100 °C,
ρ = 870 kg/m³, c_p = 2000 J/(kg K)), supply at 45 °C. The isothermal side solves the same
bearing at μ(45 °C) from a cold start, like the thermal side (each call builds nothing: both
reuse their solver).
"""

from __future__ import annotations

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn  # noqa: E402
from rotordyn.bearings import Oil  # noqa: E402

LOAD, SPEED = (0.0, -5000.0), 100.0
OIL = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
          density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
TS = 45.0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--rig-only", action="store_true",
                    help="only the paper rig's active bearing (isothermal vs thermal vs THD)")
    args = ap.parse_args(argv)
    header("thermal and turbulent film (issue 20)")
    if args.rig_only:
        rig_section(args.repeat)
        footer()
        return 0
    geo = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, n_circ=72, n_axial=16)
    mu_s = OIL.viscosity_pa_s(TS)
    iso = rotordyn.JournalBearing(viscosity_pa_s=mu_s, **geo)
    th = rotordyn.JournalBearing(viscosity_pa_s=mu_s, **geo)

    def isothermal():
        e = iso.static_equilibrium(load_n=LOAD, speed_hz=SPEED)
        return iso.coefficients(x_m=e.x_m, y_m=e.y_m, speed_hz=SPEED)

    def thermal():
        return th.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=OIL,
                                      supply_temperature_c=TS)

    thd_b = rotordyn.JournalBearing(viscosity_pa_s=mu_s, **geo)

    def thd():  # the thermo-hydrodynamic film: energy equation, mu(T) per node
        return thd_b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=OIL,
                                         supply_temperature_c=TS, model="thd")

    r = thermal()
    e = iso.static_equilibrium(load_n=LOAD, speed_hz=SPEED)
    print(f"thermal: T_eff = {r.effective_temperature_c:.2f} degC (supply {TS} degC), "
          f"T_max = {r.max_temperature_c:.2f} degC, mu = {r.viscosity_pa_s:.4g} Pa s "
          f"(isothermal {mu_s:.4g}), P = {r.power_loss_w:.4g} W, eps = "
          f"{r.eccentricity_ratio:.4f} (isothermal {e.eccentricity_ratio:.4f}), "
          f"{r.iterations} outer iterations")
    rt = thd()
    print(f"THD: T_max = {rt.max_temperature_c:.2f} degC, T_mean = {rt.mean_temperature_c:.2f} "
          f"degC, P = {rt.power_loss_w:.4g} W, eps = {rt.eccentricity_ratio:.4f}, "
          f"{rt.iterations} outer iterations")
    t = interleaved({"isothermal": isothermal, "thermal": thermal, "thd": thd},
                    repeat=args.repeat)
    print(f"equilibrium + K, C, 72x16: isothermal {t['isothermal']}")
    print(f"                           thermal    {t['thermal']}")
    print(f"                           THD        {t['thd']}")
    print(f"  ratio thermal/isothermal: {t['thermal'].wall / t['isothermal'].wall:.2f}x wall, "
          f"{t['thermal'].cpu / t['isothermal'].cpu:.2f}x CPU (goal <= 5x; CPU is the figure "
          f"when the wall time shows a busy machine)")
    print(f"  ratio THD/isothermal:     {t['thd'].wall / t['isothermal'].wall:.2f}x wall, "
          f"{t['thd'].cpu / t['isothermal'].cpu:.2f}x CPU (goal <= 5x)")

    # the compressor of tests/data/models (two plain bearings, 72x16) in a system: the
    # thermal system equilibrium (one C++ call; a new SystemSolver per outer step) beside the
    # isothermal system equilibrium at mu(supply) from a cold start
    from pathlib import Path
    sysm = rotordyn.System.from_toml(Path(__file__).parent.parent / "tests" / "data" / "models"
                                     / "compressor_plain.toml")
    res = rotordyn.system_thermal_equilibrium(sysm, speed_hz=150.0, oil=OIL,
                                              supply_temperature_c=TS)
    print(f"compressor (150 Hz): T_eff = {', '.join(f'{t:.2f}' for t in res.effective_temperature_c)}"
          f" degC, {res.iterations} outer iterations")
    rs = rotordyn.system_thermal_equilibrium(sysm, speed_hz=150.0, oil=OIL,
                                             supply_temperature_c=TS, model="thd")
    print(f"compressor THD (150 Hz): T_max = {', '.join(f'{t:.2f}' for t in rs.max_temperature_c)}"
          f" degC, {rs.iterations} outer iterations")
    t3 = interleaved({
        "isothermal": lambda: rotordyn.equilibrium(sysm, speed_hz=150.0, warm_start=False),
        "thermal": lambda: rotordyn.system_thermal_equilibrium(sysm, speed_hz=150.0, oil=OIL,
                                                               supply_temperature_c=TS),
        "thd": lambda: rotordyn.system_thermal_equilibrium(sysm, speed_hz=150.0, oil=OIL,
                                                           supply_temperature_c=TS,
                                                           model="thd")},
        repeat=max(3, args.repeat // 2))
    print(f"system equilibrium, compressor: isothermal {t3['isothermal']}")
    print(f"                                thermal    {t3['thermal']}")
    print(f"                                THD        {t3['thd']}")
    print(f"  ratio thermal/isothermal: {t3['thermal'].wall / t3['isothermal'].wall:.2f}x wall, "
          f"{t3['thermal'].cpu / t3['isothermal'].cpu:.2f}x CPU")
    print(f"  ratio THD/isothermal:     {t3['thd'].wall / t3['isothermal'].wall:.2f}x wall, "
          f"{t3['thd'].cpu / t3['isothermal'].cpu:.2f}x CPU")

    rig_section(args.repeat)

    # turbulence on vs off, per force (same position, Re_h at the clearance ~ 2.9e3)
    lam = rotordyn.JournalBearing(viscosity_pa_s=0.003, **geo)
    tur = rotordyn.JournalBearing(viscosity_pa_s=0.003, turbulence="ng_pan", density_kg_m3=870.0,
                                  **geo)
    st = dict(x_m=2e-5, y_m=-5e-5, speed_hz=300.0)
    t2 = interleaved({"laminar": lambda: lam.forces(**st), "ng_pan": lambda: tur.forces(**st)},
                     repeat=args.repeat, number=20)
    print(f"force, 72x16 (eps 0.54, 300 Hz): laminar {t2['laminar']}")
    print(f"                                 ng_pan  {t2['ng_pan']}")
    print(f"  ratio turbulent/laminar: {t2['ng_pan'].wall / t2['laminar'].wall:.2f}x wall, "
          f"{t2['ng_pan'].cpu / t2['laminar'].cpu:.2f}x CPU; "
          f"|F| turbulent/laminar = "
          f"{abs(complex(*tur.forces(**st))) / abs(complex(*lam.forces(**st))):.3f}")
    footer()
    return 0


def rig_section(repeat: int) -> None:
    """The paper rig (active bearing, 72x16, Swift-Stieber) at a_y = -1.85 mm, 50 Hz,
    p_c = 0.1 MPa: the isothermal system equilibrium from a cold start beside the
    effective-temperature and THD system equilibria of its active bearing (one C++ call each;
    oil ISO VG 46 supplied at 40 degC, mu = 0.040 Pa s = the rig's)."""
    rig = rotordyn.models.paper_rig()
    vg46 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=46.0, t2_c=100.0, nu2_mm2_s=6.8,
               density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
    op = dict(speed_hz=50.0, chamber_pressure_pa=0.1e6, config_ay_m=-1.85e-3)

    def therm(model):
        return rotordyn.system_thermal_equilibrium(rig, oil=vg46, supply_temperature_c=40.0,
                                                   model=model, **op)
    for model in ("effective", "thd"):
        r = therm(model)
        print(f"paper rig {model} (0.1 MPa, 50 Hz): {r.status}, T_max = "
              f"{r.max_temperature_c[0]:.2f} degC, T_mean/T_eff = "
              f"{r.effective_temperature_c[0]:.2f} degC, P = {r.power_loss_w[0]:.1f} W, "
              f"{r.iterations} outer iterations")
    t4 = interleaved({
        "isothermal": lambda: rotordyn.equilibrium(rig, warm_start=False, **op),
        "thermal": lambda: therm("effective"),
        "thd": lambda: therm("thd")}, repeat=max(3, repeat // 2))
    print(f"system equilibrium, paper rig:  isothermal {t4['isothermal']}")
    print(f"                                thermal    {t4['thermal']}")
    print(f"                                THD        {t4['thd']}")
    print(f"  ratio thermal/isothermal: {t4['thermal'].wall / t4['isothermal'].wall:.2f}x wall, "
          f"{t4['thermal'].cpu / t4['isothermal'].cpu:.2f}x CPU")
    print(f"  ratio THD/isothermal:     {t4['thd'].wall / t4['isothermal'].wall:.2f}x wall, "
          f"{t4['thd'].cpu / t4['isothermal'].cpu:.2f}x CPU")


if __name__ == "__main__":
    raise SystemExit(main())
