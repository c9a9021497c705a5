"""Python smoke run for `make sanitize`: every C++ entry point once, with the sanitizer build
of rotordyn._core (ASan + UBSan + LeakSanitizer preloaded by the Makefile). A sanitizer
report aborts the interpreter with a non-zero exit; this script only has to reach its end.

Covers the calls that failed under AddressSanitizer in issue 13 (the sleeve condensation:
``rd.equilibrium(rd.models.paper_rig(), 50, 0.15e6, -1.85e-3)``) plus each analysis, the three
cavitation models of the bearing, a transient, the error paths (C++ exceptions crossing into
Python) and a thread pool (the GIL released around solves).
"""

from __future__ import annotations

import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np


def main() -> int:
    import rotordyn as rd

    where = rd._core.__file__
    if "asan" not in where:
        print(f"sanitize_smoke: rotordyn._core comes from {where}, not the sanitizer build",
              file=sys.stderr)
        return 1
    rig = rd.models.paper_rig()
    e = rd.equilibrium(rig, 50, 0.15e6, -1.85e-3)  # the issue-13 ASan failure
    assert e.status == "ok", e.message
    st = rd.stability(rig, 50, 0.15e6, -1.85e-3)
    assert np.all(np.isfinite(st.eigenvalues))
    rd.stability(rig, 1e-6, 0.15e6, -1.85e-3)  # a failed equilibrium
    rd.linearize(rig, 50, 0.15e6, -1.85e-3, method="finite_difference")
    rd.campbell(rig, [20.0, 40.0], 0.4e6, n_modes=6)
    rd.unbalance_response(rig, [(3, 1e-5, 0.0)], [30.0, 40.0], chamber_pressure_pa=0.4e6)
    rd.statespace(rig, speed_hz=50, chamber_pressure_pa=0.15e6, config_ay_m=-1.85e-3)
    rd.modes(rig, without_bearings=True)
    rd.rotor_campbell(rig, [0.0, 50.0], n_modes=4, without_bearings=True)
    tr = rd.transient(rig, 0.02, 50, 0.15e6, -1.85e-3, disturbance_m=(1e-5, 0.0), n_out=21)
    assert np.all(np.isfinite(tr.r)), tr.message
    for cav in ("gumbel", "reynolds", "jfo"):
        b = rd.JournalBearing(diameter_m=0.05, length_m=0.04, clearance_m=3e-4,
                              viscosity_pa_s=0.04, n_circ=32, n_axial=8, cavitation=cav,
                              grooves=[rd.Groove(center_deg=90.0, width_deg=10.0,
                                                 pressure_pa=1e4)])
        b.forces(x_m=1e-4, y_m=-1e-4, speed_hz=50.0, vx_m_s=1e-3, vy_m_s=-1e-3)
        b.coefficients(x_m=1e-4, y_m=-1e-4, speed_hz=50.0)
        b.pressure(x_m=1e-4, y_m=-1e-4, speed_hz=50.0)
        b.static_equilibrium(load_n=(0.0, -100.0), speed_hz=50.0)
    rd.paper_rig_sleeve().condense()
    for bad in (lambda: rd.equilibrium(rig, float("nan")),
                lambda: rd.JournalBearing(diameter_m=-1.0, length_m=0.04, clearance_m=3e-4,
                                          viscosity_pa_s=0.04),
                lambda: b.forces(x_m=1.0, y_m=0.0, speed_hz=50.0)):
        try:
            bad()
        except rd.RotordynError:
            pass
    with ThreadPoolExecutor(max_workers=2) as ex:
        list(ex.map(lambda pc: rd.equilibrium(rd.models.paper_rig(), 50, pc, -1.85e-3).r,
                    [0.1e6, 0.2e6]))
    # this wave's entry points: shooting + continuation (CVODES sensitivities), the modal
    # operator and the one-call unbalance sweep (rotor without bearing elements), turbulence,
    # the thermal equilibrium (standalone and in a system), Level I
    from pathlib import Path

    models = Path(__file__).resolve().parent.parent / "tests" / "data" / "models"
    lin = rd.System.from_toml(models / "compressor_linear.toml")
    ub = [(3, 1e-3, 30.0)]
    orbit = rd.periodic_orbit(lin, 60.0, kind="forced", unbalances=ub)
    assert orbit.ok, orbit.message
    br = rd.continuation(lin, "speed_hz", (50.0, 200.0), orbit, unbalances=ub, ds=0.05,
                         max_points=3)
    assert br.ok, br.message
    rd.modes(lin, n_modes=6)
    rd.modes(lin, n_modes=6)  # the cached operator
    rd.unbalance_response(lin, ub, [40.0, 80.0, 120.0])
    rd.level1(lin, 150.0, stages=[rd.Stage(station=3, power_w=1.5e6, diameter_m=0.4,
                                           height_m=0.02, density_ratio=1.3)])
    tb = rd.JournalBearing(diameter_m=0.2, length_m=0.1, clearance_m=2e-4, viscosity_pa_s=0.003,
                           n_circ=36, n_axial=8, turbulence="ng_pan", density_kg_m3=860.0)
    tb.forces(x_m=5e-5, y_m=-5e-5, speed_hz=150.0, vx_m_s=1e-3, vy_m_s=0.0)
    tb.coefficients(x_m=5e-5, y_m=-5e-5, speed_hz=150.0)
    from rotordyn.bearings import Oil

    vg32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
               density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
    th = rd.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.02,
                           n_circ=36, n_axial=8)
    r = th.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=vg32,
                               supply_temperature_c=45.0, carry_over=0.3)
    assert r.status == "ok"
    rd.system_thermal_equilibrium(rd.System.from_toml(models / "compressor_plain_thermal.toml"),
                                  speed_hz=150.0)
    print("sanitize_smoke: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
