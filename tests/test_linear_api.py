"""The linear toolchain on the paper's rig: internal consistency of its parts.

- The state-space poles are the stability eigenvalues (same linear model, two code paths).
- Campbell critical speeds (1× crossings of forward rotor modes) and the unbalance-response
  peaks agree: to the speed grid's resolution (1.5 Hz) for the lightly damped first mode; to
  5 % for the second, whose damping ratio (~0.1) and close backward partner shift the peak.
- The stability table is tidy and the modes split into rotor and sleeve families (by where
  the kinetic energy of each mode lies).
"""

import json
import subprocess
import sys

import numpy as np
import pytest

import rotordyn as rd


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_stability_table_and_kinds(rig):
    st = rd.stability(rig, 50.0, 0.15e6, -1.85e-3)
    df = st.to_frame()
    assert list(df.columns[:4]) == ["speed_hz", "chamber_pressure_pa", "config_ay_m", "mode"]
    # The sleeve's own modes sit kHz above the rotor's; in the film they are heavily damped
    # (one may be overdamped and carry no frequency at all).
    assert (df["kind"] == "sleeve").sum() >= 1
    assert df.loc[df["kind"] == "sleeve", "freq_hz"].min() > 1000.0
    assert df.loc[df["kind"] == "rotor", "freq_hz"].iloc[:3].max() < 100.0
    assert st.rotor_shapes.shape[:2] == (rig.rotor.n_elements + 1, 4)
    assert st.sleeve_shapes[0].shape[0] == 3 * rig.bearings[0].sleeve.n_elements
    assert st.stable == (st.max_real_1_per_s < 0)


def test_statespace_poles_are_the_eigenvalues(rig):
    ss = rd.statespace(rig, inputs=["chamber_pressure", ("force", 6)],
                       outputs=[("displacement", 4), ("journal", 0), ("sleeve", 0)],
                       speed_hz=50.0, chamber_pressure_pa=0.15e6, config_ay_m=-1.85e-3)
    assert ss.A.shape == (18, 18) and ss.B.shape == (18, 3) and ss.C.shape == (7, 18)
    st = rd.stability(rig, 50.0, 0.15e6, -1.85e-3)
    p = ss.poles
    p = np.sort_complex(p[p.imag > 1e-6])
    lam = np.sort_complex(st.eigenvalues[st.eigenvalues.imag > 1e-6])
    np.testing.assert_allclose(p, lam, rtol=1e-8)
    # The journal output and the station-4 displacement differ only by the housing motion
    # (none here): same rows.
    np.testing.assert_allclose(ss.C[0:2], ss.C[2:4], atol=1e-12)


def test_campbell_critical_speeds_match_unbalance_peaks(rig):
    speeds = np.arange(20.0, 101.0, 1.0)
    c = rd.campbell(rig, speeds, chamber_pressure_pa=0.4e6, config_ay_m=0.0)
    crit = c.critical_speeds()["speed_hz"].to_numpy()
    u = rd.unbalance_response(rig, [(6, 1e-4, 0.0)], speeds, stations=[6],
                              chamber_pressure_pa=0.4e6, config_ay_m=0.0)
    peaks = u.peaks(6)["critical_speed_hz"].to_numpy()
    assert len(crit) >= 2 and len(peaks) >= 1
    assert abs(peaks[0] - crit[0]) < 1.5, (crit, peaks)
    if len(peaks) > 1:
        assert abs(peaks[1] - crit[1]) < 0.05 * crit[1], (crit, peaks)


def test_no_bearing_system_is_linear_supports_only():
    """Friswell's rotor on its 1 MN/m supports: stability eigenvalues = rotor modes."""
    s = rd.models.friswell_5_9_1()
    st = rd.stability(s, 4000 / 60)
    m = rd.modes(s, 4000 / 60, reduction="none", n_modes=6)
    np.testing.assert_allclose(st.eigenvalues[:6], m.eigenvalues, rtol=1e-9)


def run(*args):
    return subprocess.run([sys.executable, "-m", "rotordyn.cli", *args], capture_output=True,
                          text=True)


def test_cli_threshold_and_campbell_json():
    p = run("threshold", "paper-rig", "--speed-hz", "50", "--config-ay-m", "-1.85e-3",
            "--bounds", "2e4", "3e5", "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    assert d["status"] == "ok" and 2e4 < d["chamber_pressure_pa"] < 3e5
    assert 0.3 < d["whirl_frequency_hz"] / 50.0 < 0.7
    p = run("campbell", "paper-rig", "--chamber-pressure-pa", "4e5", "--speeds-hz", "5:120:1",
            "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    assert len(d["critical_speeds_hz"]) >= 2


def test_cli_threshold_no_crossing_and_bad_bounds():
    p = run("threshold", "paper-rig", "--config-ay-m", "-1.85e-3", "--bounds", "2e5", "3e5",
            "--json")
    assert p.returncode == 0
    d = json.loads(p.stdout)
    assert d["status"] == "no_crossing"
    assert d["chamber_pressure_pa"] is None or np.isnan(d["chamber_pressure_pa"])
    p = run("threshold", "paper-rig", "--bounds", "3e5", "1e5")
    assert p.returncode == 2 and "bounds" in p.stderr


def test_cli_unbalance_reports_api_margins():
    p = run("unbalance", "paper-rig", "--unbalance", "6,1e-4,0", "--chamber-pressure-pa", "4e5",
            "--speeds-hz", "20:100:1", "--operating-speed-hz", "50", "60", "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    pk = d["peaks"]["6"]
    assert pk and {"amplification_factor", "separation_margin_pct", "required_margin_pct"} <= set(pk[0])
    p = run("unbalance", "paper-rig", "--unbalance", "6;1e-4")
    assert p.returncode == 2 and "--unbalance" in p.stderr


def test_statespace_to_python_control(rig):
    """The exported model as a python-control StateSpace: same poles, same DC gain."""
    control = pytest.importorskip("control")
    ss = rd.statespace(rig, inputs=["chamber_pressure"], outputs=[("journal", 0)],
                       speed_hz=50.0, chamber_pressure_pa=0.15e6, config_ay_m=-1.85e-3)
    sys_ = ss.to_control()
    assert isinstance(sys_, control.StateSpace)
    np.testing.assert_allclose(np.sort_complex(control.poles(sys_)), np.sort_complex(ss.poles),
                               rtol=1e-9)
    np.testing.assert_allclose(np.asarray(control.dcgain(sys_)).ravel(),
                               ss.frequency_response([0.0])[0].real.ravel(), rtol=1e-8)
