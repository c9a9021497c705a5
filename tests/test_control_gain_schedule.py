"""Gain scheduling of a feedback law over the speed (issue 24).

References and tolerances:
- Interpolating PD laws of common structure (pid() with one τ_d) element by element is
  interpolating the gains: the law at Ω equals pid(k_p(Ω), k_d(Ω)) with linearly
  interpolated gains to 1e-12 relative.
- In the transient the C++ right-hand side interpolates at Ω(t): at a grid speed the
  scheduled run equals the fixed design bit for bit (s = 0 adds nothing); a schedule of
  identical designs equals the fixed law bit for bit through a ramp; between grid points it
  equals the fixed law_at_speed() run to 1e-6 of the motion at rtol 1e-10 (s computed in
  rad/s in C++ and in Hz in Python differs in the last bits, and CVODE's step sequence with
  it), while the nearest design differs by more than 1000 times that.
- Stability check: at the design points equal to closed_loop() of each design (1e-12).
- A grid not covering the run → InputError naming controller.schedule_speed_hz.
"""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.control import Actuator, SpeedProfile
from rotordyn.control.closedloop import closed_loop
from rotordyn.control.gain_schedule import (gain_schedule, law_at_speed, schedule_stability)
from rotordyn.control.lqr import lqg
from rotordyn.control.pid import pid
from rotordyn.control.plant import plant
from rotordyn.errors import InputError

C_RIG, AY, PC = 3e-4, -1.85e-3, 0.05e6
MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def two_pd():
    return [pid(1.2e9, 2.0e6), pid(0.6e9, 3.5e6)], np.array([45.0, 55.0])


def test_interpolation_is_interpolation_of_the_gains():
    ks, sp = two_pd()
    law = gain_schedule(ks, sp)
    for f in (45.0, 47.5, 51.0, 55.0):
        s = (f - 45.0) / 10.0
        ref = pid(1.2e9 + (0.6e9 - 1.2e9) * s, 2.0e6 + (3.5e6 - 2.0e6) * s)
        k = law_at_speed(law, f)
        for M, R in ((k.A, ref.A), (k.B, ref.B), (k.C, ref.C), (k.D, ref.D)):
            assert np.allclose(M, R, rtol=1e-12, atol=0)


def test_transient_at_grid_and_between(rig):
    ks, sp = two_pd()
    law = gain_schedule(ks, sp)
    act = Actuator()
    kw = dict(disturbance_m=(0.0, 0.05 * C_RIG), n_out=101, actuator=act)
    a = rd.transient(rig, 0.03, 55.0, PC, AY, controller=law, **kw)
    b = rd.transient(rig, 0.03, 55.0, PC, AY, controller=ks[1], **kw)
    assert np.array_equal(a.r, b.r) and np.array_equal(a.controller_states, b.controller_states)
    kw.update(rtol=1e-10, atol_m=1e-15)
    c = rd.transient(rig, 0.03, 51.0, PC, AY, controller=law, **kw)
    d = rd.transient(rig, 0.03, 51.0, PC, AY, controller=law_at_speed(law, 51.0), **kw)
    e = rd.transient(rig, 0.03, 51.0, PC, AY, controller=ks[0], **kw)
    err = np.abs(c.r - d.r).max()
    assert err < 1e-6 * np.abs(d.r - d.equilibrium_r).max()
    assert np.abs(e.r - d.r).max() > 1e3 * err  # the interpolation matters at this speed


def test_identical_designs_equal_the_fixed_law_through_a_ramp(rig):
    k = pid(1.0e9, 2.5e6)
    law = gain_schedule([k, k, k], [40.0, 50.0, 60.0])
    prof = SpeedProfile.ramp(45.0, 55.0, 200.0)
    kw = dict(disturbance_m=(0.0, 0.05 * C_RIG), n_out=51, actuator=Actuator(), speed=prof)
    a = rd.transient(rig, 0.05, chamber_pressure_pa=PC, config_ay_m=AY, controller=law, **kw)
    b = rd.transient(rig, 0.05, chamber_pressure_pa=PC, config_ay_m=AY, controller=k, **kw)
    assert np.array_equal(a.r, b.r)


def test_stability_check_matches_the_designs(rig):
    act = Actuator()
    ks, sp = two_pd()
    law = gain_schedule(ks, sp)
    st = schedule_stability(rig, law, chamber_pressure_pa=PC, config_ay_m=AY, actuator=act,
                            n_between=2)
    assert st.speed_hz.size == 4 and st.design.sum() == 2
    for f, k in zip(sp, ks):
        ref = closed_loop(plant(rig, f, PC, AY, actuator=act), k, with_margins=False)
        i = int(np.flatnonzero(st.speed_hz == f)[0])
        assert abs(st.max_real_1_per_s[i] - ref.max_real) <= 1e-12 * max(1, abs(ref.max_real))
    assert len(st.to_frame()) == 4


def test_grid_not_covering_the_run_names_the_field(rig):
    ks, sp = two_pd()
    law = gain_schedule(ks, sp)
    with pytest.raises(InputError, match="controller.schedule_speed_hz"):
        rd.transient(rig, 0.01, 60.0, PC, AY, controller=law)
    with pytest.raises(InputError, match="controller.schedule_speed_hz"):
        rd.transient(rig, 0.2, chamber_pressure_pa=PC, config_ay_m=AY, controller=law,
                     speed=SpeedProfile.ramp(45.0, 70.0, 100.0))


def test_designs_without_common_structure_are_refused(rig):
    p1 = plant(rig, 45.0, PC, AY, actuator=Actuator())
    p2 = plant(rig, 55.0, PC, AY, actuator=Actuator())
    from rotordyn.control.reduction import modal_truncation

    k1, k2 = lqg(modal_truncation(p1, 500.0)[0]), lqg(modal_truncation(p2, 500.0)[0])
    with pytest.raises(InputError, match=r"designs\[1\]"):
        gain_schedule([k1, k2], [45.0, 55.0])
    with pytest.raises(InputError, match="speeds_hz"):
        gain_schedule(two_pd()[0], [55.0, 45.0])


def test_not_the_rig_compressor_with_an_active_bearing():
    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    ks = [pid(2e9, 2e5), pid(3e9, 3e5)]
    law = gain_schedule(ks, [40.0, 80.0])
    st = schedule_stability(s, law, chamber_pressure_pa=0.2e6, actuator=Actuator(),
                            n_between=1)
    for f, k in zip((40.0, 80.0), ks):
        ref = closed_loop(plant(s, f, 0.2e6, actuator=Actuator()), k, with_margins=False)
        i = int(np.flatnonzero(st.speed_hz == f)[0])
        assert abs(st.max_real_1_per_s[i] - ref.max_real) <= 1e-12 * max(1, abs(ref.max_real))
    tr = rd.transient(s, 0.05, chamber_pressure_pa=0.2e6, controller=law, actuator=Actuator(),
                      speed=SpeedProfile.ramp(50.0, 70.0, 400.0), n_out=51,
                      disturbance_m=(0.0, 5e-6))
    assert tr.status == "ok", tr.message
