"""Sweep analyses against references: the adaptive boundary of a rigid rotor on two short
bearings against Lund's analytic threshold curve, thresholds per line against
:func:`rotordyn.threshold`, the unbalance response against :func:`rotordyn.unbalance_response`.

References: J. W. Lund, PhD thesis, RPI (1966), in the form of Friswell, Penny, Garvey & Lees,
Dynamics of Rotating Machines (2010) §5.6; short-bearing (Ocvirk, NACA TN 2808, 1952) load and
coefficients (Friswell et al. §5.5) — the closed forms live in tests/test_linear_references.py.
"""

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.sweep import run_sweep

sys.path.insert(0, str(Path(__file__).parent))
from test_linear_references import rigid_rotor, short_bearing_case  # noqa: E402


def _write(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


BOUNDARY = """
schema = "rotordyn/sweep/1"
name = "lund-boundary"
model = "{model}"
analysis = "boundary"
chunk_size = 16

[grid]
"rotor.disks.0.mass_kg" = {{start = 0.2, stop = 1.4, num = 5}}
speed_hz = {{start = 110.0, stop = 150.0, num = 5}}

[options]
x = "rotor.disks.0.mass_kg"
y = "speed_hz"
resolution = 33
"""


def test_boundary_against_lund_closed_form(tmp_path):
    """The adaptive boundary of the rigid rotor (massless rigid shaft, disk of mass m at
    mid-span, two L/D = 1/8 Gümbel bearings) in the (m, speed) plane against Lund's threshold
    with the short-bearing coefficients: for every boundary vertex, the closed-form threshold
    speed at that mass, within 1 % (the finite L/D and film grid alone give ≤ 0.33 % for
    ε ≤ 0.5, tests/test_linear_references.py; the fine grid's 1.25 Hz step adds the linear
    interpolation of max Re λ). The refinement evaluates far fewer points than the 33 × 33
    grid it resolves."""
    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125).to_toml(model)
    res = run_sweep(_write(tmp_path, BOUNDARY.format(model=model)), tmp_path / "o", threads=2)
    ds = sw.open(tmp_path / "o")
    b = ds.boundary()
    assert len(b) > 20 and b["line"].nunique() == 1
    epss = np.linspace(0.05, 0.6, 23)
    masses = [short_bearing_case(e, 0.125)[2] for e in epss]

    def f_lund(m):
        e = brentq(lambda e: short_bearing_case(e, 0.125)[2] - m, 0.02, 0.7, xtol=1e-12)
        return short_bearing_case(e, 0.125)[0]

    assert masses[0] < 0.2 and masses[-1] > 1.4
    err = [abs(f - f_lund(m)) / f_lund(m)
           for m, f in zip(b["rotor.disks.0.mass_kg"], b["speed_hz"])]
    assert max(err) < 0.01, max(err)
    n_eval = ds.frame["point_id"].nunique()
    # one row per mode of each evaluated point (a failed point: one row)
    assert n_eval == len(ds.frame.drop_duplicates("point_id")) and n_eval < 0.5 * 33 * 33
    assert (ds.frame.groupby("point_id").size() > 1).all()
    assert res.counts["failed"] == 0 and set(ds.frame["level"]) == {0, 1, 2, 3}
    # below the curve stable, above unstable
    fr = ds.frame
    lo = fr[fr["speed_hz"] == 110.0]
    hi = fr[fr["speed_hz"] == 150.0]
    assert lo["point_stable"].astype(bool).all() and not hi["point_stable"].astype(bool).any()


THRESHOLD = """
schema = "rotordyn/sweep/1"
name = "t-threshold"
model = "paper-rig"
analysis = "threshold"
chunk_size = 1

[grid]
config_ay_m = [-1.85e-3, -1.5e-3]
chamber_pressure_pa = {start = 0.0, stop = 0.3e6, num = 7}
speed_hz = 50.0

[options]
vary = "chamber_pressure_pa"
"""


def test_threshold_per_line_matches_api(tmp_path):
    """One row per crossing of each line of the remaining axes; the root equals
    rotordyn.threshold's (Brent on the same max Re λ) to its tolerance."""
    res = run_sweep(_write(tmp_path, THRESHOLD), tmp_path / "o", threads=2)
    df = res.to_frame()
    assert res.complete and set(df["config_ay_m"]) == {-1.85e-3, -1.5e-3}
    rig = rd.models.paper_rig()
    for ay, g in df.groupby("config_ay_m"):
        th = rd.threshold(rig, "chamber_pressure_pa", bounds=(0.0, 0.3e6), n_scan=7,
                          config_ay_m=ay)
        got = g[g["status"] == "ok"]["value"].to_numpy()
        want = np.asarray(th.crossings, dtype=float)
        assert len(got) == len(want)
        np.testing.assert_allclose(got, want, rtol=1e-4)
        assert (g["i_chamber_pressure_pa"].isna()).all()
        if not len(want):
            assert (g["status"] == "no_crossing").all() and len(g) == 1
    assert (df["status"] == "ok").sum() >= 2  # a band: both crossings kept


TRACK = """
schema = "rotordyn/sweep/1"
name = "t-track"
model = "friswell-5.9.1"
analysis = "stability"
chunk_size = 100

[grid]
speed_hz = [0.0, {speed}]
"supports.0.kxx_n_per_m" = {{start = 0.5e6, stop = 2.0e6, num = 30}}

[options]
n_modes = 4
line = "supports.0.kxx_n_per_m"
"""


def test_mode_tracking_through_a_crossing_and_a_veering(tmp_path):
    """Friswell et al. (2010) Example 5.9.1 with the x-stiffness of bearing 0 swept through
    the isotropic 1 MN/m. At rest the x and y modes are uncoupled: the y modes keep the
    isotropic rotor's frequencies 86.658 and 274.313 rad/s whatever k_xx, and the x modes
    cross them. Tracking (MAC) keeps each id on one shape: the tracked y modes are constant
    while the frequency-sorted slots swap. At 4000 rev/min the gyroscopic coupling makes the
    curves veer: the tracked ids follow the continuous branches (never swap), whose
    frequencies bracket the isotropic rotor's 85.389 (BW) and 87.796 (FW) rad/s at
    k_xx = 1 MN/m, each with one whirl direction."""
    res = run_sweep(_write(tmp_path, TRACK.format(speed=4000 / 60)), tmp_path / "o",
                    threads=1)
    df = res.to_frame()
    assert res.complete and (df["status"] == "ok").all()
    k = "supports.0.kxx_n_per_m"
    rest = df[df["speed_hz"] == 0.0].pivot(index=k, columns="mode_id", values="freq_hz")
    w_y = [86.658 / (2 * math.pi), 274.313 / (2 * math.pi)]
    const = [j for j in rest.columns if np.ptp(rest[j]) < 1e-6 * rest[j].mean()]
    assert len(const) == 2
    np.testing.assert_allclose(sorted(rest[const].mean()), w_y, rtol=2e-5)
    slot = df[df["speed_hz"] == 0.0].pivot(index=k, columns="mode", values="mode_id")
    assert (slot[1] != slot[1].iloc[0]).any()  # the sorted slot 1 changes mode: a crossing
    spin = df[df["speed_hz"] > 0]
    ids = spin.pivot(index=k, columns="mode", values="mode_id")
    assert (ids[1] == ids[1].iloc[0]).all() and (ids[2] == ids[2].iloc[0]).all()  # veering
    f = spin.pivot(index=k, columns="mode_id", values="freq_hz")
    kk = f.index.to_numpy()
    i = np.searchsorted(kk, 1e6)
    assert f.iloc[i - 1, 0] < 85.389 / (2 * math.pi) < f.iloc[i, 0]
    assert f.iloc[i - 1, 1] < 87.796 / (2 * math.pi) < f.iloc[i, 1]
    wh = spin.pivot(index=k, columns="mode_id", values="whirl")
    assert all(wh[j].nunique() == 1 for j in wh.columns)


RUNUP = """
schema = "rotordyn/sweep/1"
name = "t-runup"
model = "paper-rig"
analysis = "run-up"
chunk_size = 1

[grid]
chamber_pressure_pa = 0.4e6
config_ay_m = 0.0

[options]
unbalances = [[6, 2.0e-5, 0.0]]
start_hz = 30.0
stop_hz = 50.0
rate_hz_per_s = 15.0
"""


def test_run_up_passes_the_critical_speed_late_and_lower(tmp_path):
    """A nonlinear run-up (Ω ramped at 15 Hz/s through the first critical speed, unbalance at
    disk B) against the steady linear unbalance response of the same rig: the run-up's peak
    comes later than the steady critical speed and is lower (the classical run-up shift and
    attenuation of a rotor accelerated through a resonance; e.g. Genta, Dynamics of Rotating
    Systems (2005) §4.11), but within 10 % of its speed."""
    res = run_sweep(_write(tmp_path, RUNUP), tmp_path / "o", threads=1)
    df = res.to_frame()
    assert res.complete and (df["status"] == "ok").all()
    assert df["revolution"].is_monotonic_increasing and df["speed_hz"].is_monotonic_increasing
    assert df["speed_hz"].iloc[0] == pytest.approx(30.0, abs=0.5)
    rig = rd.models.paper_rig()
    st = rig.bearings[-1].station
    sp = np.arange(30.0, 50.01, 0.25)
    u = rd.unbalance_response(rig, [(6, 2.0e-5, 0.0)], sp, stations=[st],
                              chamber_pressure_pa=0.4e6, config_ay_m=0.0)
    amp = np.abs(u.x[:, 0])
    f_steady = u.speeds_hz[np.argmax(amp)]  # the refined grid, not the one asked for
    i = df["amplitude_x_m"].idxmax()
    f_run = df.loc[i, "speed_hz"]
    assert f_steady < f_run < 1.1 * f_steady
    assert df.loc[i, "amplitude_x_m"] < amp.max()


UNBALANCE = """
schema = "rotordyn/sweep/1"
name = "t-unbalance"
model = "paper-rig"
analysis = "unbalance"
chunk_size = 20

[grid]
chamber_pressure_pa = [0.2e6, 0.4e6]
speed_hz = {start = 20.0, stop = 60.0, num = 41}

[options]
unbalances = [[6, 2.0e-5, 0.0]]
operating_speed_hz = [50.0, 55.0]
"""


def test_unbalance_lines_match_the_api(tmp_path):
    """Each speed line equals rotordyn.unbalance_response (same equilibria, K_H, D_H and
    complex solve) to 1e-6 at the grid speeds, and a peak row sits at the grid speed nearest
    each of UnbalanceResult.peaks' critical speeds."""
    res = run_sweep(_write(tmp_path, UNBALANCE), tmp_path / "o", threads=2)
    df = res.to_frame()
    assert res.complete and (df["status"] == "ok").all() and len(df) == 82
    rig = rd.models.paper_rig()
    for pc, g in df.groupby("chamber_pressure_pa"):
        u = rd.unbalance_response(rig, [(6, 2.0e-5, 0.0)], g["speed_hz"].to_numpy(),
                                  chamber_pressure_pa=pc, operating_speed_hz=(50.0, 55.0))
        on_grid = np.isin(u.speeds_hz, g["speed_hz"].to_numpy())  # the API refines peaks
        np.testing.assert_allclose(g["amplitude_x_m"], np.abs(u.x[on_grid, 0]), rtol=1e-6)
        pk = u.peaks()
        got = g[g["peak"].astype(bool)]
        assert len(got) == len(pk) >= 1
        # the sweep's peak is a parabola through the 1 Hz grid (the API refines the speeds
        # near a peak): within half a grid step
        np.testing.assert_allclose(got["critical_speed_hz"], pk["critical_speed_hz"], atol=0.5)
        assert np.all(np.abs(got["speed_hz"].to_numpy() - got["critical_speed_hz"]) <= 0.5)
        assert (got["amplification_factor"] > 1).all()
