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
                lambda: b.forces(x_m=1.0, y_m=0.0, speed_hz=50.0),
                lambda: rd._core.track_modes(np.zeros((2, 2), complex), [np.eye(2)],
                                             np.zeros((0, 0)), []),
                lambda: rd._core.linear_assignment(np.array([[0.0, np.nan]]))):
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
    # harmonic balance: one orbit and a branch with its corrector (the Floquet flow route too)
    hb = rd.periodic_orbit(lin, 60.0, kind="forced", unbalances=ub, method="harmonic_balance",
                           harmonics=2)
    assert hb.ok, hb.message
    br = rd.continuation(lin, "speed_hz", (50.0, 200.0), hb, unbalances=ub, ds=0.05,
                         max_points=3, method="harmonic_balance", harmonics=2, floquet="flow")
    assert br.ok, br.message
    # over a model field: the core's corrector calls back into Python for each system (the
    # GIL taken for the call, the re-assembled solvers held by the core while it uses them)
    br = rd.continuation(lin, "supports.*.kyy_n_per_m", (0.5e8, 3e8), hb, unbalances=ub,
                         ds=0.05, max_points=3, method="harmonic_balance", harmonics=2)
    assert br.ok and br.stats["assemblies"] > 3, br.message
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
    # issues 19, 20, 22, 24 (second wave): the THD film, journal tilt (standalone and in a
    # system), the one-call unbalance sweep with bearing elements and sweep chunks
    # (equilibrium batch, threshold line), Hopf, the adaptive law in the transient
    import dataclasses

    from rotordyn.bearings import tilted_coefficients, tilted_forces
    from rotordyn.sweep.work import Job, run_chunk

    r = th.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=vg32,
                               supply_temperature_c=45.0, carry_over=0.3, model="thd")
    assert r.status == "ok", r.message
    tilted_forces(th, x_m=1e-5, y_m=-2e-5, speed_hz=100.0, theta_x_rad=1e-4, theta_y_rad=-5e-5,
                  vx_m_s=1e-4, wy_rad_s=1e-2)
    tilted_coefficients(th, x_m=1e-5, y_m=-2e-5, speed_hz=100.0, theta_x_rad=1e-4)
    plain = rd.System.from_toml(models / "compressor_plain.toml")
    tilted = dataclasses.replace(plain, bearings=tuple(
        dataclasses.replace(b, tilt=True, n_circ=36, n_axial=8, config_theta_x_rad=1e-4)
        for b in plain.bearings))
    assert rd.equilibrium(tilted, 150.0).status == "ok"
    rd.stability(tilted, 150.0)
    rd.unbalance_response(plain, ub, [60.0, 90.0, 120.0], threads=2)
    run_chunk(Job("s", rig.to_toml(), "equilibrium", {},
                  {"config_ay_m": [-1.85e-3], "chamber_pressure_pa": [0.0, 0.1e6],
                   "speed_hz": [50.0]}), 0, 0, 2)
    run_chunk(Job("s", rig.to_toml(), "threshold", {"vary": "chamber_pressure_pa"},
                  {"config_ay_m": [-1.85e-3], "speed_hz": [50.0],
                   "chamber_pressure_pa": [0.0, 0.1e6, 0.2e6]}), 0, 0, 3)
    # a boundary-refinement chunk (max_real_batch): a refused point, a gap, a new line
    run_chunk(Job("s", rig.to_toml(), "boundary", {"exclude_sleeve_modes": True},
                  {"config_ay_m": [-1.85e-3, 0.0], "chamber_pressure_pa": [-1.0, 0.0, 0.1e6,
                                                                           0.2e6]}),
              0, 0, 0, [0, 1, 3, 4, 5])
    from rotordyn.control import Actuator
    from rotordyn.control.adaptive import AdaptiveRejection
    from rotordyn.control.antiwindup import with_anti_windup
    from rotordyn.control.gain_schedule import gain_schedule
    from rotordyn.control.pid import pid

    law = gain_schedule([pid(1.2e9, 2.0e6), pid(0.6e9, 3.5e6)], np.array([45.0, 55.0]))
    rd.transient(rig, 0.01, 50.0, 0.05e6, -1.85e-3, controller=law, n_out=11)
    aw = with_anti_windup(pid(1.0e9, 2.5e6, 1.0e9 / 0.05))
    rd.transient(rig, 0.01, 50.0, 0.15e6, -1.85e-3, controller=aw, n_out=11,
                 actuator=Actuator(order=1, p_min_pa=0.149e6, p_max_pa=0.151e6))
    # conditioning with the schedule beyond the valve, and a sample-and-hold law's correction
    from rotordyn.control import PressureSchedule
    from rotordyn.control.export import discretise

    k = pid(1.0e9, 2.5e6, 1.0e9 / 0.05)
    sched = PressureSchedule.time_table([0.0, 0.005], [0.15e6, 0.3e6])
    for law in (with_anti_windup(k, mode="conditioning"),
                with_anti_windup(discretise(k, 5e-4).with_options(computation_delay_s=2e-4))):
        rd.transient(rig, 0.01, 50.0, config_ay_m=-1.85e-3, pressure=sched, controller=law,
                     n_out=11, actuator=Actuator(order=1, p_min_pa=0.0, p_max_pa=0.2e6))
    ad = AdaptiveRejection([("journal", 0)], [50.0], [[1e-9 + 1e-9j, 1e-9]], 1.0, p0_pa=2e4)
    rd.transient(rig, 0.01, 50.0, 0.5e6, -1.85e-3, adaptive=ad, unbalances=[(6, 2e-5, 0.0)],
                 n_out=11)
    # the latest wave's entry points: the eigenvalues past an n_modes cut (stability's verdict
    # over every root) and the root picker on a statically indeterminate train; rotating
    # shaft damping (Ω K_c in the solver's H) through equilibrium, stability and a transient;
    # the refined HB Floquet product on a model with films (k > 0 film columns; the linear
    # model above has none); shooting's blocked sensitivity solve where SUNDIALS has it;
    # every pad's state at a tilting-pad equilibrium
    train = rd.System.from_toml(models / "motor_fan_train_guyan.toml")
    st = rd.stability(train, 25.0, n_modes=4)
    assert st.all_eigenvalues.size > st.eigenvalues.size
    spin = dataclasses.replace(plain, rotor=dataclasses.replace(
        plain.rotor, damping_beta_s=4e-5, damping_rotating=True), bearings=(dataclasses.replace(
            plain.bearings[0], config_ay_m=1e-5),) + plain.bearings[1:])  # with an offset
    assert rd.equilibrium(spin, 150.0).status == "ok"
    rd.stability(spin, 150.0)
    rd.transient(spin, 0.005, 150.0, disturbance_m=(1e-6, 0.0), n_out=6)
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9, shear_modulus_pa=81.2e9)
    smooth = rd.System(
        rotor=rd.Rotor(tuple(rd.ShaftSection(length_m=0.1, outer_diameter_m=0.1)
                             for _ in range(4)), ()),
        materials=(steel,), reduction=rd.Reduction(master_stations=(0, 4), method="guyan"),
        bearings=tuple(rd.FluidFilmBearing(st_, diameter_m=0.05, length_m=0.025,
                                           clearance_m=1e-4, viscosity_pa_s=0.03, n_circ=36,
                                           n_axial=6, cavitation="none") for st_ in (0, 4)))
    hb = rd.periodic_orbit(smooth, 15.0, kind="forced", unbalances=[(2, 8e-3, 0.0)],
                           method="harmonic_balance", harmonics=4, floquet="samples",
                           floquet_tol=1e-4)
    assert hb.ok, hb.message
    try:
        sh = rd.periodic_orbit(lin, 60.0, kind="forced", unbalances=ub,
                               sensitivity_solve="blocked")
        assert sh.ok, sh.message
    except rd.InputError as exc:  # SUNDIALS before 6: refused by name
        assert "sensitivity_solve" in str(exc), exc
    # shooting's monodromy from the orbit's samples (the refined Magnus product on a shooting
    # orbit's films) and its "none"
    for fq in ("samples", "none"):
        sh = rd.periodic_orbit(smooth, 15.0, kind="forced", unbalances=[(2, 8e-3, 0.0)],
                               floquet=fq, n_out=41)
        assert sh.ok, sh.message
    # the thermal pads' continuous fill near the degenerate band (an unloaded pad) and the
    # thermal equilibrium's per-pad outputs
    gth = rd.system_thermal_equilibrium(rd.System.from_toml(
        models / "generator_tilting_pad.toml"), speed_hz=18.79)
    assert gth.status == "ok" and len(gth.pads_frame()) == 10
    pads = rd.equilibrium(rd.System.from_toml(models / "compressor_tilting_pad.toml"), 40.0)
    assert pads.pads_frame().unloaded.sum() == 2
    print("sanitize_smoke: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
