"""The second built-in calibration of the paper's rig, ``paper-rig-hs`` (half-Sommerfeld film),
against the numbers it was fitted to (reference paper §6.1 Table 1 and §6.2 threshold).

Fit: docs/calibration/paper_rig_bearing.py --hs-model (sleeve E, ρ and chamber arc; Table 1,
the sleeve's condensed frequencies and the linear threshold 0.098 MPa at a_y = −1.85 mm,
W = 50 Hz together; docs/paper-rig.md, "Cavitation model"). Honest tolerances, from that fit:

* threshold: the rounded model gives 0.0972 MPa (−0.8 %); tolerance 3 % (the 25-point scan
  with parabola refinement resolves the crossing to well under 1 %);
* Table 1: no sleeve or chamber brings the half-Sommerfeld locus closer than 0.0335 c (its y/c
  rises too slowly with p_c); tolerance 0.036 c — three and a half times the Swift–Stieber
  model's 0.01 c (tests/test_paper_rig_equilibrium.py), and it says so;
* the sleeve's condensed frequencies: the same E/ρ as ``paper-rig`` (equal to 1e-3).
"""

import numpy as np
import pytest

import rotordyn as rd

PC_PA = np.array([0.10e6, 0.15e6, 0.20e6, 0.25e6])
PAPER_X = np.array([0.1583, 0.2915, 0.4096, 0.4988])  # paper's frame: ours is −x
PAPER_Y = np.array([0.0554, 0.1234, 0.2122, 0.3023])


@pytest.fixture(scope="module")
def hs():
    return rd.models.load("paper-rig-hs")


def test_it_is_the_half_sommerfeld_variant_of_the_rig(hs):
    base = rd.models.paper_rig()
    assert hs.name == "paper-rig-hs" and rd.models.paper_rig_hs() == hs
    assert hs.bearings[0].cavitation == "gumbel" and base.bearings[0].cavitation == "reynolds"
    assert hs.rotor == base.rotor
    f_hs = hs.bearings[0].sleeve.condense().freq_condensed_hz
    f_b = base.bearings[0].sleeve.condense().freq_condensed_hz
    np.testing.assert_allclose(f_hs, f_b, rtol=1e-3)


def test_threshold_is_the_papers(hs):
    t = rd.threshold(hs, "chamber_pressure_pa", bounds=(0.02e6, 0.3e6), speed_hz=50.0,
                     config_ay_m=-1.85e-3)
    assert t.status == "ok" and t.stable_side == "above"
    assert t.value == pytest.approx(0.098e6, rel=0.03)


def test_table1_within_the_fits_misfit(hs):
    x, y = [], []
    for pc in PC_PA:
        e = rd.equilibrium(hs, 50.0, pc, -1.85e-3)
        assert e.status == "ok", e.message
        x.append(-e.x_over_c[0])
        y.append(e.y_over_c[0])
    err = max(np.abs(np.array(x) - PAPER_X).max(), np.abs(np.array(y) - PAPER_Y).max())
    assert err < 0.036
    assert err > 0.02  # the documented limitation of this film: if it vanished, recheck docs
