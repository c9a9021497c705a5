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
    assert n_eval == len(ds.frame) and n_eval < 0.5 * 33 * 33
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
