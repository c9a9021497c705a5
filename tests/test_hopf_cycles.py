"""rd.hopf_cycles: the cycles born at a Hopf point at given amplitudes, by harmonic balance
with the parameter free (docs/nonlinear.md, "The cycles at a Hopf point")."""

from __future__ import annotations

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def coarse_rig():
    """The paper rig with a 36 × 6 film grid, whose film force is smooth over ±2 % of the
    clearance about the Hopf point's equilibrium (tests/test_hopf.py)."""
    return coarse_models.paper_rig()


@pytest.fixture(scope="module")
def compressor():
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    return s, rd.hopf(s, "speed_hz", bounds=(100.0, 200.0))


def test_smooth_piece_cycles_follow_the_normal_form(coarse_rig):
    """Rig at a_y = −1.85 mm, 50 Hz, 36 × 6: l1 from fits inside the smooth piece (±1 %:
    −0.0745), supercritical. The cycles at 0.5 % and 2 % of the clearance lie below p_H
    (the unstable side), stable, with A² = κ |p − p_H| within 1 % (measured 0.9984 and
    1.0012): the normal form's amplitude checked by the branch's own start. The 2 % cycle
    equals the cycle shot at its p_c (single shooting, another method) within 0.2 % in
    amplitude and 1e-4 in period."""
    h = rd.hopf(coarse_rig, bounds=(0.04e6, 0.08e6), speed_hz=50.0, config_ay_m=-1.85e-3,
                fd_step=0.01)
    assert h.ok and h.type == "supercritical" and h.cycle_side == "below"
    r = rd.hopf_cycles(coarse_rig, h, (0.005, 0.02))
    assert r.statuses == ("ok", "ok")
    assert r.side == ("below", "below") and not r.on_stable_side.any()
    assert r.stable.all() and np.all(r.max_multiplier < 1)
    assert r.onset == "soft" and r.l1_side_confirmed is True
    assert np.allclose(r.leading_order_ratio, 1.0, atol=0.01)
    # the requested amplitude is held by the projection: the journal's within 1 %
    L = h.length_scale_m
    assert np.allclose(r.amplitude_m[:, 0] / L, r.amplitude_c, rtol=0.01)
    o = r.orbits[1]
    shot = rd.periodic_orbit(coarse_rig, 50.0, float(r.value[1]), -1.85e-3,
                             start=(o.r[0], o.v[0]), period_s=o.period_s, rtol=1e-9, tol=1e-8)
    assert shot.ok, shot.message
    assert shot.amplitude(0) == pytest.approx(o.amplitude(0), rel=2e-3)
    assert shot.period_s == pytest.approx(o.period_s, rel=1e-4)
    df = r.to_frame()
    assert list(df["side"]) == ["below", "below"] and "chamber_pressure_pa" in df
    assert "soft onset" in repr(r)


def test_compressor_cycles_show_the_small_hysteresis_l1_predicts(compressor):
    """Compressor on plain bearings (not the rig), over the speed: l1 > 0 (subcritical) at
    125.807 Hz. The cycles of 0.1 % and 1 % of the clearance lie below the Hopf speed
    (coexisting with the stable equilibrium: a hard onset) and are unstable; by 10 % the
    branch has folded back above the Hopf speed and its cycles are stable (the weak
    hysteresis docs/nonlinear.md describes: measured 0.036–0.055 Hz below, fold near 2 %)."""
    s, h = compressor
    assert h.ok and h.type == "subcritical" and h.cycle_side == "below"
    r = rd.hopf_cycles(s, h, (0.001, 0.01, 0.1))
    assert r.statuses == ("ok", "ok", "ok")
    assert r.side == ("below", "below", "above")
    assert list(r.stable) == [False, False, True]
    assert r.onset == "hard" and r.l1_side_confirmed is True
    assert np.all(np.abs(r.distance) < 0.2)  # Hz: a weak hysteresis
    assert "hard onset" in repr(r)


def test_same_answer_twice_and_bad_input(compressor):
    s, h = compressor
    a = rd.hopf_cycles(s, h, (0.01,))
    b = rd.hopf_cycles(s, h, 0.01)
    assert a.value[0] == b.value[0] and np.array_equal(a.amplitude_m, b.amplitude_m)
    for bad in ((), (0.0,), (-0.1,), (1.0,), (0.02, 0.01), (float("nan"),)):
        with pytest.raises(rd.InputError, match="amplitudes_c"):
            rd.hopf_cycles(s, h, bad)
    with pytest.raises(rd.InputError, match="harmonics"):
        rd.hopf_cycles(s, h, harmonics=0)
    failed = dataclasses.replace(h, status="no_crossing", message="x")
    with pytest.raises(rd.InputError, match="result"):
        rd.hopf_cycles(s, failed)
    with pytest.raises(rd.InputError, match="result"):
        rd.hopf_cycles(s, "not a result")
    rig = rd.models.paper_rig()
    with pytest.raises(rd.InputError, match="result"):
        rd.hopf_cycles(rig, h)  # a HopfResult of another system


def test_cli_hopf_cycles(compressor):
    """`rotordyn hopf --cycles A [A ...]` prints the cycles (and `--json` carries them): the
    API's numbers."""
    s, h = compressor
    model = str(MODELS / "compressor_plain.toml")
    out = subprocess.run([sys.executable, "-m", "rotordyn.cli", "hopf", model, "--bounds",
                          "100", "200", "--cycles", "0.01", "--json"], capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    rec = json.loads(out.stdout)
    api = rd.hopf_cycles(s, h, (0.01,))
    cyc = rec["cycles"]
    assert cyc["onset"] == "hard" and cyc["rows"][0]["side"] == "below"
    assert cyc["rows"][0]["speed_hz"] == pytest.approx(api.value[0], rel=1e-9)
    txt = subprocess.run([sys.executable, "-m", "rotordyn.cli", "hopf", model, "--bounds",
                          "100", "200", "--cycles", "0.01"], capture_output=True, text=True,
                         timeout=300)
    assert txt.returncode == 0 and "hard onset" in txt.stdout
    bad = subprocess.run([sys.executable, "-m", "rotordyn.cli", "hopf", model, "--bounds",
                          "100", "200", "--cycles", "2"], capture_output=True, text=True,
                         timeout=300)
    assert bad.returncode == 2 and "--cycles" in bad.stderr
    hill = subprocess.run([sys.executable, "-m", "rotordyn.cli", "hopf", model, "--bounds",
                           "100", "200", "--cycles", "0.01", "--floquet", "hill",
                           "--floquet-margin", "0", "--json"], capture_output=True, text=True,
                          timeout=300)
    assert hill.returncode == 0, hill.stderr
    row = json.loads(hill.stdout)["cycles"]["rows"][0]
    assert row["floquet"] == "hill" and row["speed_hz"] == pytest.approx(api.value[0], rel=1e-9)
    # a model field: refused by name before the Hopf solve
    for flags, named in ((["--floquet", "hill"], "--floquet"),
                         (["--cycles", "0.01", "--floquet-margin", "2"], "--floquet-margin"),
                         (["--vary", "bearings.*.clearance_m", "--cycles", "0.01"],
                          "--cycles")):
        out = subprocess.run([sys.executable, "-m", "rotordyn.cli", "hopf", model, "--bounds",
                              "100", "200", *flags], capture_output=True, text=True,
                             timeout=300)
        assert out.returncode == 2 and named in out.stderr.splitlines()[-1], out.stderr
