"""Error paths of the journal bearing API and CLI (tier g): bad input raises
``rotordyn.InputError`` naming the field and its allowed range before any solve; contact and
non-convergence reach Python as ``RotordynError`` subclasses; the CLI exits 2 on bad input.
No numerical tolerance is involved."""

import json
import math
import subprocess
import sys

import numpy as np
import pytest

import rotordyn
from rotordyn import _core

GOOD = dict(diameter_m=0.05, length_m=0.04, clearance_m=3e-4, viscosity_pa_s=0.04)


@pytest.mark.parametrize(
    "field, value, words",
    [
        ("clearance_m", 0.0, "clearance_m"),
        ("clearance_m", -1e-4, "clearance_m"),
        ("clearance_m", 0.03, "clearance_m"),
        ("diameter_m", math.nan, "diameter_m"),
        ("length_m", math.inf, "length_m"),
        ("viscosity_pa_s", -0.04, "viscosity_pa_s"),
        ("n_circ", 8, "n_circ"),
        ("n_axial", 1, "n_axial"),
        ("n_circ", 72.5, "n_circ"),
        ("cavitation", "elrod", "cavitation"),
        ("grooves", [(90.0, 0.0, 0.0)], "grooves[0]"),
    ],
)
def test_constructor_rejects_bad_input(field, value, words):
    kw = dict(GOOD, **{field: value})
    with pytest.raises(rotordyn.InputError, match=words.replace("[", r"\[").replace("]", r"\]")):
        rotordyn.JournalBearing(**kw)


def test_groove_validation():
    with pytest.raises(rotordyn.InputError, match="width_deg"):
        rotordyn.Groove(90.0, 400.0, 0.0)
    with pytest.raises(rotordyn.InputError, match="pressure_pa"):
        rotordyn.Groove(90.0, 0.0, -1.0)
    with pytest.raises(rotordyn.InputError, match="center_deg"):
        rotordyn.Groove(math.nan)


def test_operating_point_validation():
    b = rotordyn.JournalBearing(**GOOD, n_circ=24, n_axial=4)
    with pytest.raises(rotordyn.InputError, match="eccentricity ratio.*< 1"):
        b.forces(x_m=3e-4, y_m=0.0, speed_hz=50.0)
    with pytest.raises(rotordyn.InputError, match="eccentricity"):
        b.coefficients(x_m=2.5e-4, y_m=-2.5e-4, speed_hz=50.0)
    with pytest.raises(rotordyn.InputError, match="x_m"):
        b.forces(x_m=math.nan, y_m=0.0, speed_hz=50.0)
    with pytest.raises(rotordyn.InputError, match="speed_hz"):
        b.forces(x_m=0.0, y_m=0.0, speed_hz=math.inf)
    with pytest.raises(rotordyn.InputError, match="vy_m_s"):
        b.forces(x_m=0.0, y_m=0.0, speed_hz=1.0, vy_m_s=math.nan)
    with pytest.raises(rotordyn.InputError, match="method"):
        b.coefficients(x_m=0.0, y_m=-1e-4, speed_hz=50.0, method="magic")
    with pytest.raises(rotordyn.InputError, match="load_n"):
        b.static_equilibrium(load_n=(0.0, math.inf), speed_hz=50.0)
    with pytest.raises(rotordyn.InputError, match="speed_hz"):
        b.static_equilibrium(load_n=(0.0, -100.0), speed_hz=0.0)
    with pytest.raises(rotordyn.InputError, match="eccentricity"):
        b.forces_batch(x_m=[0.0, 3.1e-4], y_m=0.0, speed_hz=50.0)


def test_core_errors_reach_python_as_rotordyn_errors():
    g, grid = rotordyn.JournalBearing(**GOOD, n_circ=24, n_axial=4).to_core()
    s = _core.ReynoldsSolver(g, grid, "reynolds")
    h = np.full((24, 5), 3e-4)
    h[5, 2] = -1e-6
    with pytest.raises(rotordyn.ContactError, match="film thickness"):
        s.solve(h, np.zeros((24, 5)), 100.0)
    with pytest.raises(rotordyn.InputError, match=r"h: expected shape \(24, 5\)"):
        s.solve(np.full((24, 4), 3e-4), np.zeros((24, 4)), 100.0)
    with pytest.raises(rotordyn.InputError, match="eccentricity"):
        s.rigid(4e-4, 0.0, 0.0, 0.0, 10.0)
    with pytest.raises(rotordyn.InputError, match="cavitation"):
        _core.ReynoldsSolver(g, grid, "bogus")
    # an impossible load (far beyond the film's capacity at this speed) is a ConvergenceError
    b = rotordyn.JournalBearing(**GOOD, n_circ=24, n_axial=4)
    with pytest.raises(rotordyn.ConvergenceError):
        b.static_equilibrium(load_n=(0.0, -1e12), speed_hz=1.0)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "rotordyn.cli", "bearing", *args],
                          capture_output=True, text=True)


def test_cli_bearing_json_equilibrium():
    r = _cli("--diameter-m", "0.05", "--length-m", "0.04", "--clearance-m", "3e-4",
             "--viscosity-pa-s", "0.04", "--groove", "90,0,0", "--speed-hz", "50",
             "--load-n", "0", "-500", "--json")
    assert r.returncode == 0, r.stderr
    rec = json.loads(r.stdout)
    assert rec["equilibrium"]["residual_rel"] < 1e-8
    assert rec["force_n"][1] == pytest.approx(500.0, rel=1e-8)
    assert np.array(rec["k_n_per_m"]).shape == (2, 2)
    b = rotordyn.JournalBearing(**GOOD, grooves=[rotordyn.Groove(90.0)])
    eq = b.static_equilibrium(load_n=(0.0, -500.0), speed_hz=50.0)
    assert rec["equilibrium"]["x_m"] == pytest.approx(eq.x_m, rel=1e-9)


@pytest.mark.parametrize(
    "args, field",
    [
        (["--clearance-m=-3e-4", "--x-m", "0", "--y-m", "0"], "clearance_m"),
        (["--clearance-m", "3e-4", "--x-m", "3e-4", "--y-m", "0"], "eccentricity"),
        (["--clearance-m", "nan", "--x-m", "0", "--y-m", "0"], "clearance_m"),
        (["--clearance-m", "3e-4", "--n-circ", "6", "--x-m", "0", "--y-m", "0"], "n_circ"),
        (["--clearance-m", "3e-4", "--groove", "a,b", "--x-m", "0", "--y-m", "0"], "--groove"),
        (["--clearance-m", "3e-4"], "--x-m"),
    ],
)
def test_cli_bearing_bad_input_exits_2(args, field):
    r = _cli("--diameter-m", "0.05", "--length-m", "0.04", "--viscosity-pa-s", "0.04",
             "--speed-hz", "50", *args)
    assert r.returncode == 2
    assert field in r.stderr
    assert "Traceback" not in r.stderr
