"""The THD tilting-pad bearing against a published experiment (issue 20; docs/film-physics.md,
"Published THD experiment: Fillon, Bligoud & Frêne's tilting-pad bearing").

Fillon, M., Bligoud, J.-C., Frêne, J. (1992), "Experimental study of tilting-pad journal
bearings — comparison with theoretical thermoelastohydrodynamic results", ASME J. Tribol.
114(3), 579–588: a 4-pad bearing, load between pivots, D = 100 mm, L = 70 mm, 75° pads, pivot
offset 0.5, preload 0.47 on a machined pad clearance of 148 µm (assembled 78.4 µm), ISO VG 32
supplied at 40 °C (μ(40 °C) = 0.0277 Pa·s, β = 0.0341 1/K, ρ = 860 kg/m³, c = 1951.8 J/(kg K)),
10 kN. The numbers as transcribed in ROSS's tests (petrobras/ross,
ross/tests/test_fluid_film_literature.py, commit 0d49af8), which give the geometry and oil from
Kim, Palazzolo & Gadangi (1994, Tribol. Trans. 37(4), Table 3) and Gadangi & Palazzolo (1995,
J. Tribol. 117(2), Table 1), and the measured maximum pad temperatures digitized (±1 °C) from
Fig. 20 of Kim, Palazzolo & Gadangi (1994):

    rpm                       1000   2000   3000   4000
    measured max pad T (°C)   49.5   59.5   67.5   76.5
    the paper's TEHD (°C)     43.7   53.4   63.2   72.9

This script builds the bearing in rotordyn (THD pads: adiabatic, or with heat transfer to the
pads; carry-over λ = 0, 0.5, 1) and prints T_max of the hottest pad, ε and the power loss per
speed, and the grid convergence at 4000 rpm. Run
``python docs/calibration/fillon_tilting_pad.py [--grid 16x8]``.

Then the same with the walls' own heat paths (rotordyn.bearings.thd_walls; docs/film-physics.md
"Heat paths to the journal and through the bush or pad"), every value stated with its source,
none fitted to the measurement:

* film side: the film's own conduction across its thickness (``wall_htc = "film"``), with the
  oil's conductivity k = 0.149 W/(m K) — ROSS's transcription of the case's lubricant, the
  same source as its density and specific heat;
* journal: its temperature from its heat balance over the four pads (``journal_wall =
  "balance"``), the classical assumption of tilting-pad THD/TEHD analyses (the shaft rotates
  through every pad and settles where it takes no net heat);
* pads: 1-D conduction through the pad, ``bush_thickness_m`` 20 mm (ROSS's build of the case,
  which gives the geometry as tabulated by Kim, Palazzolo & Gadangi 1994), ``
  bush_conductivity_w_per_m_k`` 50 W/(m K) (steel; 41–64 W/(m K) for carbon and low-alloy
  steels at 300 K, Incropera & DeWitt, Table A.1; the babbitt layer, not given, is not
  modelled), the back face in the housing's oil at ``back_htc_w_m2k`` 300 W/(m² K) (forced
  convection along a flat plate, Nu = 0.664 Re^½ Pr^⅓ over the pad's 65 mm arc in VG 32 at
  45 °C, Pr ≈ 306: 160 W/(m² K) at 0.1 m/s, 500 at 1 m/s of oil along the back) at the supply
  temperature ``back_temperature_c`` 40 °C (the housing's oil is warmer: the sensitivity
  below puts it at the pads' mean outlet temperature).

The measured quantity is the pad's temperature (its babbitt surface): the result's
``max_wall_temperature_c_total`` (the pad surface over the film's cells), beside the film's
``max_temperature_c_total``.
"""

import argparse
import dataclasses
import time

import numpy as np

from rotordyn.bearings import Oil, TiltingPadBearing

SPEEDS_RPM = (1000.0, 2000.0, 3000.0, 4000.0)
MEASURED_C = (49.5, 59.5, 67.5, 76.5)
TEHD_C = (43.7, 53.4, 63.2, 72.9)
MU40, BETA = 0.0277, 0.0341
OIL = Oil(viscosity_law="exponential", mu_ref_pa_s=MU40, t_ref_c=40.0, beta_1_per_k=BETA,
          density_kg_m3=860.0, specific_heat_j_per_kg_k=1951.8)
TS = 40.0
LOAD = (0.0, -10000.0)
K_OIL = 0.149   # W/(m K), ROSS's transcription of the case's oil
WALLS = dict(wall_htc="film", journal_wall="balance", bush_wall="conduction",
             bush_thickness_m=0.02, bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=300.0)


def bearing(per_pad: int, n_axial: int) -> TiltingPadBearing:
    """The 4-pad bearing with ``per_pad`` intervals per 75° pad (the grid spacing is uniform
    round the circle: n_circ = per_pad · 360/75)."""
    n_circ = int(round(per_pad * 360.0 / 75.0))
    return TiltingPadBearing(station=0, diameter_m=0.1, length_m=0.07,
                             clearance_m=148e-6 * (1.0 - 0.47), viscosity_pa_s=MU40,
                             n_pads=4, pad_arc_deg=75.0, pivot_offset=0.5, preload=0.47,
                             load="between", n_circ=n_circ, n_axial=n_axial)


def run(tp, rpm, **kw):
    oil = dataclasses.replace(OIL, conductivity_w_per_m_k=K_OIL) if "wall_htc" in kw else OIL
    return tp.thermal_equilibrium(load_n=LOAD, speed_hz=rpm / 60.0, oil=oil,
                                  supply_temperature_c=TS, **kw)


def walls(tp) -> None:
    """The bearing with the walls' heat paths (module docstring): per λ the hottest pad
    surface and film, the journal's temperature, ε, the outer steps and the CPU time (beside
    the adiabatic film in the same run); the sensitivity to the wall data; grid convergence."""
    print("\nwith the walls' heat paths (film conduction k = 0.149, journal from its balance, "
          "20 mm steel pads k_b = 50, back face h_o = 300 at 40 degC):")
    for lam in (0.0, 0.5, 1.0):
        t0 = time.process_time()
        rows = [(rpm, run(tp, rpm, carry_over=lam, **WALLS)) for rpm in SPEEDS_RPM]
        cpu = time.process_time() - t0
        t0 = time.process_time()
        ad = [run(tp, rpm, carry_over=lam) for rpm in SPEEDS_RPM]
        cpu_ad = time.process_time() - t0
        print(f"  λ = {lam}: {cpu:.2f} s CPU (adiabatic, same speeds: {cpu_ad:.2f} s)")
        for (rpm, r), a, meas in zip(rows, ad, MEASURED_C):
            tw = r.max_wall_temperature_c_total
            print(f"    {rpm:6.0f} rpm {r.status:>4}  pad surface {tw:6.2f} °C "
                  f"(Δ {tw - meas:+6.2f} vs {meas:4.1f})  film {r.max_temperature_c_total:6.2f}  journal "
                  f"{r.journal_temperature_c[0]:6.2f}  ε {r.eccentricity_ratio:.3f}  P "
                  f"{r.power_loss_w_total:6.1f} W  to pads {r.heat_to_bush_w.sum():6.1f} W  "
                  f"steps {r.iterations} (adiabatic {a.iterations})")
    print("  sensitivity at λ = 0.5 (pad surface, 1000 / 4000 rpm):")
    for label, kw in (("k_b 40", dict(bush_conductivity_w_per_m_k=40.0)),
                      ("k_b 60", dict(bush_conductivity_w_per_m_k=60.0)),
                      ("h_o 150", dict(back_htc_w_m2k=150.0)),
                      ("h_o 500", dict(back_htc_w_m2k=500.0)),
                      ("insulated pads (h_o 0)", dict(back_htc_w_m2k=0.0)),
                      ("k_oil 0.13", None)):
        out = []
        for rpm in (1000.0, 4000.0):
            w = dict(WALLS, **(kw or {}))
            if kw is None:
                oil = dataclasses.replace(OIL, conductivity_w_per_m_k=0.13)
                r = tp.thermal_equilibrium(load_n=LOAD, speed_hz=rpm / 60.0, oil=oil,
                                           supply_temperature_c=TS, carry_over=0.5, **w)
            else:
                r = run(tp, rpm, carry_over=0.5, **w)
            out.append(f"{r.max_wall_temperature_c_total:6.2f}")
        print(f"    {label:24s} {' / '.join(out)} °C")
    out = []
    for rpm in (1000.0, 4000.0):  # the back face's oil at the pads' mean outlet temperature
        to = TS
        for _ in range(20):
            r = run(tp, rpm, carry_over=0.5, **dict(WALLS, back_temperature_c=to))
            tn = float(np.sum(r.outlet_flow_m3_s * r.outlet_temperature_c)
                       / np.sum(r.outlet_flow_m3_s))
            if abs(tn - to) < 1e-4:
                break
            to = tn
        out.append(f"{r.max_wall_temperature_c_total:6.2f} (T_o {to:.1f})")
    print(f"    {'T_o = mean pad outlet':24s} {' / '.join(out)} °C")
    print("  grid convergence at 4000 rpm, λ = 0.5 (pad surface, film, journal):")
    for pp, na in ((8, 4), (16, 8), (32, 16), (64, 32)):
        r = run(bearing(pp, na), 4000.0, carry_over=0.5, **WALLS)
        print(f"    {pp:3d}/pad x {na:3d}: {r.max_wall_temperature_c_total:.3f}, "
              f"{r.max_temperature_c_total:.3f}, {r.journal_temperature_c[0]:.3f} °C")


def peclet(tp, r, rpm, k_oil=0.149):
    """The hottest pad's film Péclet number ρ c U h² / (k R β_pad): heat convected along the
    pad against heat conducted across the film to the walls (h from the pad's inflow, the
    Couette flux U h L / 2 at its leading edge). Adiabatic films need Pe ≫ 1; k_oil
    W/(m K) as ROSS's transcription of the oil."""
    i = int(np.argmax(r.max_temperature_c))
    u = np.pi * tp.diameter_m * rpm / 60.0
    h = 2.0 * r.film_flow_m3_s[i] / (u * tp.length_m)
    rc = OIL.density_kg_m3 * OIL.specific_heat_j_per_kg_k
    return rc * u * h ** 2 / (k_oil * tp.diameter_m / 2 * np.radians(tp.pad_arc_deg)), h


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--grid", default="16x8", help="intervals per pad x axial intervals")
    a = ap.parse_args()
    per_pad, n_ax = (int(s) for s in a.grid.split("x"))
    tp = bearing(per_pad, n_ax)
    print(f"grid: {tp.n_circ} x {tp.n_axial} (n_circ x n_axial)")
    cases = [("adiabatic, λ=0", dict(carry_over=0.0)),
             ("adiabatic, λ=0.5", dict(carry_over=0.5)),
             ("adiabatic, λ=1", dict(carry_over=1.0)),
             ("pads h=500, λ=0.5", dict(carry_over=0.5, bush_htc_w_m2k=500.0,
                                         bush_temperature_c=TS))]
    for label, kw in cases:
        t0 = time.process_time()
        rows = []
        for rpm in SPEEDS_RPM:
            r = run(tp, rpm, **kw)
            e = r.eccentricity_ratio
            pe, h = peclet(tp, r, rpm)
            i = int(np.argmax(r.max_temperature_c))
            rise = r.outlet_temperature_c[i] - r.inlet_temperature_c[i]
            rows.append((rpm, r.status, r.max_temperature_c_total, e, r.power_loss_w_total,
                         pe, h, r.inlet_temperature_c[i], rise))
        cpu = time.process_time() - t0
        print(f"\n{label}  ({cpu:.2f} s CPU)")
        for (rpm, st, tmax, e, p, pe, h, tin, rise), meas, tehd in zip(rows, MEASURED_C,
                                                                        TEHD_C):
            print(f"  {rpm:6.0f} rpm {st:>4}  T_max {tmax:6.2f} °C  measured {meas:5.1f}"
                  f"  (Δ {tmax - meas:+6.2f})  TEHD {tehd:5.1f}  ε {e:.3f}  P {p:7.1f} W"
                  f"  hottest pad: T_in {tin:5.2f} °C, T_out − T_in {rise:5.2f} K,"
                  f" h_LE {h * 1e6:5.1f} µm, Pe {pe:5.1f}")
    print("\ngrid convergence at 4000 rpm, adiabatic, λ = 0.5:")
    for pp, na in ((8, 4), (16, 8), (32, 16), (64, 32)):
        r = run(bearing(pp, na), 4000.0, carry_over=0.5)
        print(f"  {pp:3d}/pad x {na:3d}: T_max {r.max_temperature_c_total:.3f} °C")
    walls(tp)


if __name__ == "__main__":
    main()
