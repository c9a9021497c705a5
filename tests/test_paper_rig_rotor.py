"""The reference paper's rig rotor (§6): calibrated model (docs/paper-rig.md) against the
published condensed frequencies, and the Guyan condensation against the full model.

Paper: "the final condensed models have almost identical eigenvalues ... up to the second
mode", third ~5 % off; condensed rotor frequencies 10.43, 43.04, 106.38 Hz; 11.24 kg;
26 elements, 104 DOF, 3 stations x 2 DOF. Tolerances are the issue's: condensed within 1 %
of the paper, first two Guyan frequencies within 0.5 % of the full model's.
"""

import numpy as np
import pytest

import rotordyn as rd

PAPER_HZ = np.array([10.43, 43.04, 106.38])


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_given_data(rig):
    assert rig.rotor.n_elements == 26
    assert 4 * (rig.rotor.n_elements + 1) == 108  # free-free FE DOFs; 104 after supports
    z = rig.rotor.station_positions_m()
    assert z[-1] == pytest.approx(2.0, abs=1e-12)
    bb = [z[s.station] for s in rig.supports if s.type == "rigid"]
    assert bb[1] - bb[0] == pytest.approx(1.7, abs=1e-12)
    assert z[4] - bb[0] == pytest.approx(0.663, abs=1e-12)  # active-bearing station
    assert rig.mass_kg == pytest.approx(11.24, rel=1e-3)
    assert len(rig.reduction.master_stations) == 3 and 4 in rig.reduction.master_stations


def test_condensed_frequencies_match_paper(rig):
    r = rd.modes(rig, 0.0, reduction="guyan", without_bearings=True)
    f = r.frequencies_hz[::2]
    np.testing.assert_allclose(f, PAPER_HZ, rtol=0.01)
    np.testing.assert_allclose(r.frequencies_hz[1::2], f, rtol=1e-9)  # isotropic planes


def test_guyan_first_two_within_half_percent_of_full(rig):
    r = rd.modes(rig, 0.0, reduction="guyan", without_bearings=True)
    err = np.abs(r.frequency_errors()[::2])
    assert np.all(err[:2] < 0.005), err
    assert 0.01 < err[2] < 0.08  # the paper's "about 5 %" regime, not exact
    assert np.all(r.frequencies_hz >= r.full.frequencies_hz - 1e-9)  # Rayleigh: upper bound


@pytest.mark.parametrize("method", ["irs", "craig-bampton"])
def test_better_reductions_reduce_the_error(rig, method):
    import dataclasses

    s = dataclasses.replace(rig, reduction=dataclasses.replace(rig.reduction, n_modes=3))
    g = np.abs(rd.modes(s, 0.0, reduction="guyan", without_bearings=True).frequency_errors()[::2])
    b = np.abs(rd.modes(s, 0.0, reduction=method, without_bearings=True).frequency_errors()[::2][:3])
    assert b[2] < 0.25 * g[2], (b, g)
    assert np.all(b < 0.01)


def test_gyroscopic_split_grows_with_speed(rig):
    r = rd.modes(rig, 50.0, reduction="none", n_modes=6, without_bearings=True)
    f = r.frequencies_hz
    assert list(r.whirl[:2]) == ["backward", "forward"]
    assert f[1] > f[0]


def test_rotor_pinned_at_the_journal_near_the_papers_critical_speeds(rig):
    """The rotor with x, y fixed at the journal (station 4) too: the paper's critical speeds at
    p_c = 0.4 MPa, 39 and 90 Hz (§6.3), where the film pins the journal (docs/
    paper-rig-stability.md §4), are calibration targets (docs/calibration/paper_rig_rotor.py).
    The fit's compromise with the free frequencies and the Guyan bound leaves −1.7 % and
    −1.0 % (38.32, 89.14 Hz); 2 % bounds it, while the rotor fitted to the free frequencies
    alone (35.5, 80.0 Hz: −9 %, −11 %) fails."""
    import dataclasses

    pinned = dataclasses.replace(
        rig, bearings=(), supports=rig.supports + (rd.Support(4),),
        reduction=rd.Reduction((2, 6), "guyan"))
    f = rd.modes(pinned, 0.0, reduction="none", n_modes=4, without_bearings=True).frequencies_hz[::2][:2]
    np.testing.assert_allclose(f, [39.0, 90.0], rtol=0.02)
