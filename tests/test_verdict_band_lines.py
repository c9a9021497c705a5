"""The threshold line, its ``stable_side``, the limit-cycle rows' scan verdicts and the gain
schedule's ``stable`` on the one verdict rule (the round-off band of Re λ,
``rotordyn.results.modes.point_stable``), not the raw sign of max Re λ.

The case: the compressor of tests/data/models/compressor_table.toml on coefficient tables
without damping whose cross-coupling is 0 up to 50 Hz and grows linearly above it. Up to
50 Hz the rotor is conservative (symmetric stiffness, gyroscopic D only: max Re λ exactly 0
after the conservative-root refinement); above it the undamped cross-coupling makes it
unstable at once. The threshold is therefore 50 Hz (within the band's width: the verdict
flips where the growing root leaves |Re λ| < 1e-9 |λ|). On the raw sign the conservative
point's y = 0 made no bracket with its unstable neighbour (y0·y1 = 0): "no crossing".
"""

import math
import re
from pathlib import Path

import numpy as np

import rotordyn as rd
from rotordyn.results.modes import point_stable, verdict_real
from rotordyn.sweep import run_sweep
import rotordyn.sweep as sw

MODELS = Path(__file__).parent / "data" / "models"
ONSET_HZ = 50.0


def _conservative_below_onset() -> str:
    t = (MODELS / "compressor_table.toml").read_text()
    t = t.replace("speeds_hz = [0.0, 100.0, 200.0]", f"speeds_hz = [0.0, {ONSET_HZ}, 200.0]")
    t = t.replace("kxx_n_per_m = [1.0e8, 1.2e8, 1.5e8]", "kxx_n_per_m = [1.0e8, 1.0e8, 1.0e8]")
    t = t.replace("kyy_n_per_m = [1.5e8, 1.8e8, 2.2e8]", "kyy_n_per_m = [1.5e8, 1.5e8, 1.5e8]")
    t = t.replace("kxy_n_per_m = [0.0, 2.0e7, 4.0e7]", "kxy_n_per_m = [0.0, 0.0, 4.0e7]")
    t = t.replace("kyx_n_per_m = [0.0, -2.0e7, -4.0e7]", "kyx_n_per_m = [0.0, 0.0, -4.0e7]")
    t = re.sub(r"c(xx|yy)_n_s_per_m = .*\n", "", t)
    assert t.count("[0.0, 0.0, 4.0e7]") == 2 and "n_s_per_m" not in t
    return t


def _threshold(tmp_path, speeds):
    model = tmp_path / "m.toml"
    model.write_text(_conservative_below_onset())
    (tmp_path / "t.toml").write_text(
        f'schema = "rotordyn/sweep/1"\nname = "t"\nmodel = "{model.as_posix()}"\n'
        'analysis = "threshold"\n[grid]\nspeed_hz = ' + repr([float(s) for s in speeds])
        + '\n[options]\nvary = "speed_hz"\n')
    assert run_sweep(tmp_path / "t.toml", tmp_path / "o", threads=1, progress=False).complete
    return sw.open(tmp_path / "o").frame, rd.System.from_toml(model)


def test_the_case_is_conservative_below_the_onset_and_unstable_above(tmp_path):
    _, s = _threshold(tmp_path, [30.0, 70.0])
    lo, hi = rd.stability(s, 30.0), rd.stability(s, 70.0)
    # the raw sign cannot bracket it: max Re λ is not below 0 on the stable side
    assert lo.stable and lo.eigenvalues.real.max() >= 0.0
    assert not hi.stable and hi.eigenvalues.real.max() > 0.0
    assert verdict_real(lo.eigenvalues) < 0 < verdict_real(hi.eigenvalues)


def test_threshold_line_brackets_by_the_verdict(tmp_path):
    fr, s = _threshold(tmp_path, [30.0, 40.0, 60.0, 70.0])
    assert len(fr) == 1, fr[["status", "message"]]
    row = fr.iloc[0]
    assert str(row["status"]) == "ok" and row["crossing"] == 1
    assert abs(row["value"] - ONSET_HZ) <= 1e-6 * ONSET_HZ
    assert row["stable_side"] == "below"
    # either side of the root: the API's verdict
    assert rd.stability(s, row["value"] - 1e-3).stable
    assert not rd.stability(s, row["value"] + 1e-3).stable


def test_threshold_line_scanned_downwards_keeps_the_stable_side(tmp_path):
    fr, _ = _threshold(tmp_path, [70.0, 60.0, 40.0, 30.0])
    row = fr.iloc[0]
    assert str(row["status"]) == "ok" and abs(row["value"] - ONSET_HZ) <= 1e-6 * ONSET_HZ
    assert row["stable_side"] == "below"


def test_a_conservative_line_has_no_crossing_and_says_stable(tmp_path):
    fr, _ = _threshold(tmp_path, [10.0, 20.0, 30.0, 40.0])
    assert len(fr) == 1 and str(fr.iloc[0]["status"]) == "no_crossing"
    assert "stable at all 4 points" in fr.iloc[0]["message"]


def test_the_scan_verdicts_are_the_apis(tmp_path):
    """The scan handed to the limit-cycle rows (``equilibrium_stable``): the verdict per point,
    the API's; the raw rule (``max Re λ < 0``) said False at the conservative points."""
    from rotordyn.sweep.work import Job
    from rotordyn.sweep.lines import threshold_line
    from rotordyn.sweep.points import Variants, base_system

    model = tmp_path / "m.toml"
    model.write_text(_conservative_below_onset())
    s = rd.System.from_toml(model)
    speeds = [20.0, 40.0, 60.0]
    job = Job("t", s.to_toml(), "threshold", {"vary": "speed_hz"}, {"speed_hz": speeds})
    scan = {}
    threshold_line(job, Variants(base_system(job.model_toml), job.model_toml), 0, 3, 0,
                   [None] * 3, scan)
    want = [int(rd.stability(s, f).stable) for f in speeds]
    assert list(scan["stable"]) == want == [1, 1, 0]
    assert not (np.asarray(scan["y"])[:2] < 0).any()  # what the raw rule read as unstable


def test_gain_schedule_with_an_undamped_injection_oscillator_is_stable():
    """A scheduled law carrying a fixed-frequency injection oscillator (ẋ_k = [[0, w],
    [−w, 0]] x_k, u = C_k x_k, not driven by the measurements: an identification signal
    generator) on the compressor with the active bearing: the closed loop is block
    triangular, so its roots are the plant's (damped by the films) and ±i w, marginally
    stable. ``stable`` is the verdict of every speed (as ``closed_loop(...).stable``); the raw
    rule ``max Re λ < 0`` called the oscillator's Re λ = 0 (or its round-off) unstable."""
    from rotordyn.control import Actuator, Controller
    from rotordyn.control.closedloop import closed_loop
    from rotordyn.control.gain_schedule import gain_schedule, law_at_speed, schedule_stability
    from rotordyn.control.plant import plant
    from rotordyn.control.pid import pid

    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    meas = pid(1.0e8, 0.0).measurements
    w = 2 * np.pi * 30.0
    A = np.array([[0.0, w], [-w, 0.0]])
    B = np.zeros((2, 2))
    ks = [Controller(A, B, np.array([[c, 0.0]]), np.zeros((1, 2)), meas)
          for c in (1.0e3, 2.0e3)]
    law = gain_schedule(ks, [40.0, 60.0])
    st = schedule_stability(s, law, actuator=Actuator.ideal(), n_between=1)
    assert st.speed_hz.size == 3
    for i, f in enumerate(st.speed_hz):
        ref = closed_loop(plant(s, float(f), actuator=Actuator.ideal()),
                          law_at_speed(law, float(f)), with_margins=False)
        assert ref.stable and st.point_stable[i]
    assert st.stable
    # the test can fail: the oscillator's Re λ is 0 or round-off, never below the band
    assert np.nanmax(st.max_real_1_per_s) >= 0.0  # exactly 0 here (block triangular)
    assert st.to_frame()["point_stable"].all()


def test_boundary_map_over_a_conservative_region(tmp_path):
    """A boundary sweep over (pull stiffness × speed) on the undamped compressor of
    tests/test_verdict_one_rule.py: divergent for a strong pull, conservative (max Re λ =
    round-off, +1e-13 here) for a weak one. The field of both the stored boundary and the
    stability-map plot is strictly negative at every stable point, so the plot's zero contour
    is the stored boundary: one line along the last stable node column. Before, the plot's
    field was the raw round-off (+1e-13) there: no zero contour at all and the conservative
    region shaded unstable."""
    from rotordyn.plot.maps import _map_arrays
    from rotordyn.sweep.boundary import polylines

    t = (MODELS / "compressor_linear.toml").read_text()
    t = re.sub(r"c(xx|yy)_n_s_per_m = .*\n", "", t).replace("kyy_n_per_m = 1.5e8",
                                                             "kyy_n_per_m = 1.0e8")
    t += ('\n[[support]]\ntype = "linear"\nname = "pull"\nstation = 3\n'
          "kxx_n_per_m = -1.0e6\nkyy_n_per_m = 0.0\n")
    pull = "supports.2.kxx_n_per_m"
    (tmp_path / "m.toml").write_text(t)
    (tmp_path / "b.toml").write_text(
        f'schema = "rotordyn/sweep/1"\nmodel = "{(tmp_path / "m.toml").as_posix()}"\n'
        f'name = "b"\nanalysis = "boundary"\n[grid]\n"{pull}" = [-4.0e8, -1.0e6]\n'
        f'speed_hz = [20.0, 60.0]\n[options]\nx = "{pull}"\ny = "speed_hz"\nresolution = 9\n')
    assert run_sweep(tmp_path / "b.toml", tmp_path / "o", threads=1, progress=False).complete
    ds = sw.open(tmp_path / "o")
    fr = ds.frame
    first = fr.groupby("point_id").first()
    stable = first[first["point_stable"].astype(bool)]
    # the case: a conservative stable region (max Re λ not below 0) beside a divergent one
    assert len(stable) and (stable["max_real_1_per_s"] >= 0).all()
    assert (~first["point_stable"].astype(bool)).any()
    assert stable[pull].nunique() >= 2  # a region, not only the grid's edge
    edge = stable[pull].min()  # the stable node column next to the divergent side
    b = ds.boundary()
    # at the stable node (its field -5e-7 1/s beside +250 1/s: 2e-9 of the fine step off)
    assert len(b)
    np.testing.assert_allclose(b[pull], edge, rtol=1e-8)
    xs, ys, _, _, B = _map_arrays(fr, [pull, "speed_hz"], True)
    ok = np.isfinite(B)
    st_grid = np.isin(xs, stable[pull].unique())[:, None] & ok
    assert (B[st_grid] < 0).all() and (B[ok & ~st_grid] > 0).all()
    lines = polylines(xs, ys, B)
    assert len(lines) == 1
    np.testing.assert_allclose(lines[0][:, 0], edge, rtol=1e-8)


def test_api_threshold_brackets_by_the_verdict(tmp_path):
    """``rd.threshold`` (the API's scan + Brent) on the same case: the conservative points'
    max Re λ = 0 (or round-off) is the verdict "stable", so the scan brackets the onset with
    its unstable neighbour and Brent's method finds it. On the raw sign the scan's y0·y1 = 0
    made no bracket ("no_crossing") or called the stable side "above"."""
    model = tmp_path / "m.toml"
    model.write_text(_conservative_below_onset())
    s = rd.System.from_toml(model)
    t = rd.threshold(s, "speed_hz", bounds=(30.0, 70.0), n_scan=5)
    assert t.status == "ok", t.message
    assert abs(t.value - ONSET_HZ) <= 1e-6 * ONSET_HZ
    assert t.stable_side == "below" and t.crossings == (t.value,)
    sc = t.scan
    below = sc[sc["speed_hz"] < ONSET_HZ - 1e-3]
    # the case can fail the raw rule: the stable side's max Re λ is not below 0
    assert len(below) and (below["max_real_1_per_s"] >= 0).all()
    assert below["stable"].all() and (below["verdict_real_1_per_s"] < 0).all()
    for x, st in zip(sc["speed_hz"], sc["stable"]):  # the scan's verdict is the API's
        assert bool(st) == rd.stability(s, float(x)).stable
    # either side of the root: the API's verdict
    assert rd.stability(s, t.value - 1e-3).stable
    assert not rd.stability(s, t.value + 1e-3).stable


def test_api_threshold_over_a_conservative_range_says_stable(tmp_path):
    model = tmp_path / "m.toml"
    model.write_text(_conservative_below_onset())
    s = rd.System.from_toml(model)
    t = rd.threshold(s, "speed_hz", bounds=(10.0, 40.0), n_scan=4)
    assert t.status == "no_crossing" and math.isnan(t.value)
    assert "stable at all 4 scanned points" in t.message
    assert (t.scan["max_real_1_per_s"] >= 0).all() and t.scan["stable"].all()
