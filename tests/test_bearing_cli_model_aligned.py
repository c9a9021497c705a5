"""``rotordyn bearing --model-file MODEL --bearing NAME`` without a tilt: a model file's bearing
aligned with the journal, as the system solves it (issue 20; docs/bearings.md, "One bearing
of a model file"). Before, the command refused to run without ``--theta-x-rad``/
``--theta-y-rad``.

Checks (models of tests/data/models, none the paper rig):
* plain (compressor_plain.toml, NDE bearing, 72 × 16) and fixed geometry (the turbine's
  two-axial-groove B1, turbulent): at the system's equilibrium journal position the command's
  K, C equal the system's K_H, D_H block at that station (1e-9 of the largest entry: the
  same C++ film), and under the film force there as ``--load-n`` its equilibrium returns the
  system's position (1e-6 c);
* plain: the record equals the dimensions path's for the same film bit for bit;
* tilting pads (compressor_tilting_pad.toml, 36 × 6): the bearing's coefficient table at the
  speed (1e-12), and the 2×2 block of the zero-tilt misaligned equilibrium's 4×4 (a different
  code path: the four-coordinate pad films) to 1e-6;
* thermal (THD and effective; the plain compressor, its tilting pads, the turbine's lobes):
  the bearing's own ``thermal_equilibrium`` aligned (1e-12), and the K, C of the zero-tilt
  tilted thermal equilibrium's translational block (1e-6);
* text output and the refusals (a tilting-pad bearing needs ``--load-n``; a thermal table).
"""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import Oil
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
PLAIN = str(MODELS / "compressor_plain.toml")
PLAIN_THERMAL = str(MODELS / "compressor_plain_thermal.toml")
PADS = str(MODELS / "compressor_tilting_pad.toml")
TURBINE = str(MODELS / "turbine_two_axial_groove.toml")
TURBINE_THD = str(MODELS / "turbine_two_axial_groove_thd.toml")
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
OIL = ["--supply-temperature-c", "45", "--oil-walther", "40", "32", "100", "5.4",
       "--carry-over", "0.5"]
GRID = ["--n-circ", "36", "--n-axial", "6"]


def _json(capsys, *argv):
    code = main(["bearing", *argv, "--json"])
    out = capsys.readouterr().out
    return code, (json.loads(out) if out else None)


def _system_point(path, name, f):
    """The system's equilibrium journal position at bearing ``name`` and its K_H, D_H block."""
    s = rotordyn.System.from_toml(path)
    b = next(b for b in s.bearings if b.name == name)
    lin = rotordyn.linearize(s, speed_hz=f, warm_start=False)
    assert lin.equilibrium.status == "ok"
    idx = [lin.labels.index(f"station{b.station}.{a}") for a in "xy"]
    r = np.asarray(lin.equilibrium.r)
    return b, [float(v) for v in r[idx]], lin.KH[np.ix_(idx, idx)], lin.DH[np.ix_(idx, idx)]


@pytest.mark.parametrize("path,name,f", [(PLAIN, "NDE bearing", 150.0), (TURBINE, "B1", 50.0)])
def test_plain_and_fixed_geometry_equal_the_systems_film(capsys, path, name, f):
    b, (x, y), KH, DH = _system_point(path, name, f)
    code, r = _json(capsys, "--model-file", path, "--bearing", name, "--speed-hz", repr(f),
                    "--x-m", repr(x), "--y-m", repr(y))
    assert code == 0
    np.testing.assert_allclose(r["k_n_per_m"], KH, rtol=0, atol=1e-9 * np.abs(KH).max())
    np.testing.assert_allclose(r["c_n_s_per_m"], DH, rtol=0, atol=1e-9 * np.abs(DH).max())
    assert "k_4x4_si" not in r and "film_moment_n_m" not in r  # the aligned record
    load = [-v for v in r["force_n"]]  # the film force there as the bearing's load
    code, e = _json(capsys, "--model-file", path, "--bearing", name, "--speed-hz", repr(f),
                    "--load-n", *map(repr, load))
    assert code == 0
    assert abs(e["journal_x_m"] - x) < 1e-6 * b.clearance_m
    assert abs(e["journal_y_m"] - y) < 1e-6 * b.clearance_m
    np.testing.assert_allclose(e["k_n_per_m"], KH, rtol=0, atol=1e-4 * np.abs(KH).max())
    if path == PLAIN:  # the dimensions path of the same film: the same record, bit for bit
        code, d = _json(capsys, "--diameter-m", repr(b.diameter_m), "--length-m",
                        repr(b.length_m), "--clearance-m", repr(b.clearance_m),
                        "--viscosity-pa-s", repr(b.viscosity_pa_s), "--speed-hz", repr(f),
                        "--load-n", *map(repr, load))
        assert code == 0
        for k in ("journal_x_m", "journal_y_m", "force_n", "k_n_per_m", "c_n_s_per_m",
                  "friction_torque_n_m", "side_flow_m3_s", "h_min_m"):
            assert d[k] == e[k], k


def test_tilting_pads_equal_the_bearing_and_the_zero_tilt_film(capsys):
    from rotordyn.bearings.tilt_pads import pad_misaligned_equilibrium

    code, r = _json(capsys, "--model-file", PADS, "--bearing", "NDE bearing", *GRID,
                    "--speed-hz", "150", "--load-n", "0", "-1500")
    assert code == 0 and r["equilibrium"]["status"] == "ok"
    b = dataclasses.replace(rotordyn.System.from_toml(PADS).bearings[0], n_circ=36, n_axial=6)
    t = b.coefficient_table([150.0], (0.0, -1500.0))
    np.testing.assert_allclose(r["k_n_per_m"], t.K[0], rtol=1e-12)
    np.testing.assert_allclose(r["c_n_s_per_m"], t.C[0], rtol=1e-12)
    assert len(r["pad_tilts_rad"]) == 5
    m = pad_misaligned_equilibrium(b, load_n=(0.0, -1500.0), speed_hz=150.0,
                                   coefficients=True)
    assert abs(r["journal_x_m"] - m.x_m) < 1e-6 * b.clearance_m
    assert abs(r["journal_y_m"] - m.y_m) < 1e-6 * b.clearance_m
    for key, A in (("k_n_per_m", m.K), ("c_n_s_per_m", m.C)):
        np.testing.assert_allclose(r[key], A[:2, :2], rtol=0,
                                   atol=1e-6 * np.abs(A[:2, :2]).max())
    np.testing.assert_allclose(r["pad_tilts_rad"], m.film.pad_tilts_rad, rtol=0,
                               atol=1e-6 * np.abs(m.film.pad_tilts_rad).max())
    assert main(["bearing", "--model-file", PADS, "--bearing", "NDE bearing", *GRID,
                 "--speed-hz", "150", "--load-n", "0", "-1500"]) == 0
    out = capsys.readouterr().out
    assert "pad tilts" in out and "K [N/m]" in out and "synchronous" in out


@pytest.mark.parametrize("path,name,model,load", [
    (PLAIN_THERMAL, "NDE bearing", "thd", ("0", "-1000")),
    (PLAIN_THERMAL, "NDE bearing", "effective", ("0", "-1000")),
    (PADS, "NDE bearing", "thd", ("0", "-1500")),
    (PADS, "NDE bearing", "effective", ("0", "-1500")),
    (TURBINE_THD, "B1", "thd", ("0", "-20000")),
])
def test_thermal_equals_the_bearing_and_the_zero_tilt_film(capsys, path, name, model, load):
    turbine = path == TURBINE_THD  # its turbulent films' density is the oil's, 860 kg/m³
    f = 50.0 if turbine else 150.0
    rho = ["--density-kg-m3", "860"] if turbine else []
    code, r = _json(capsys, "--model-file", path, "--bearing", name, *GRID, "--speed-hz",
                    repr(f), "--load-n", *load, *OIL, *rho, "--model", model)
    assert code == 0
    b = next(b for b in rotordyn.System.from_toml(path).bearings if b.name == name)
    b = dataclasses.replace(b, n_circ=36, n_axial=6)
    oil = dataclasses.replace(VG32, density_kg_m3=860.0) if turbine else VG32
    kw = dict(load_n=tuple(map(float, load)), speed_hz=f, oil=oil, supply_temperature_c=45.0,
              carry_over=0.5, supply_flow_m3_s=0.0, model=model)
    if model == "effective":
        kw["effective_factor"] = 0.5
    a = b.thermal_equilibrium(**kw, tilt=False)
    assert (r["journal_x_m"], r["journal_y_m"]) == pytest.approx((a.x_m, a.y_m), rel=1e-12)
    np.testing.assert_allclose(r["k_n_per_m"], a.K, rtol=1e-12)
    np.testing.assert_allclose(r["c_n_s_per_m"], a.C, rtol=1e-12)
    assert r["thermal"]["max_temperature_c"] == pytest.approx(
        float(np.max(a.max_temperature_c)), rel=1e-12)
    t = b.thermal_equilibrium(**kw, tilt=True)  # the four-coordinate film at zero tilt
    assert abs(r["journal_x_m"] - t.x_m) < 1e-6 * b.clearance_m
    assert abs(r["journal_y_m"] - t.y_m) < 1e-6 * b.clearance_m
    for key, A in (("k_n_per_m", t.K4), ("c_n_s_per_m", t.C4)):
        np.testing.assert_allclose(r[key], A[:2, :2], rtol=0,
                                   atol=1e-6 * np.abs(A[:2, :2]).max())
    assert "k_4x4_si" not in r


def test_aligned_text_and_refusals(capsys):
    assert main(["bearing", "--model-file", TURBINE_THD, "--bearing", "B1", *GRID,
                 "--speed-hz", "50", "--load-n", "0", "-20000", *OIL, "--density-kg-m3", "860",
                 "--model", "thd"]) == 0
    out = capsys.readouterr().out
    assert "thermal equilibrium (thd model, ok)" in out and "K [N/m]" in out
    assert main(["bearing", "--model-file", TURBINE, "--bearing", "B1", "--speed-hz", "50",
                 "--x-m", "0", "--y-m", "-1e-4"]) == 0
    out = capsys.readouterr().out
    assert "force on journal" in out and "h_min" in out
    base = ["bearing", "--model-file", PADS, "--bearing", "NDE bearing", *GRID]
    assert main([*base, "--speed-hz", "150", "--x-m", "0", "--y-m", "-1e-5"]) == 2
    assert "--load-n" in capsys.readouterr().err
    assert main([*base, "--speeds-hz", "100:150:50", "--load-n", "0", "-1500", *OIL]) == 2
    assert "--speeds-hz" in capsys.readouterr().err
    assert main([*base, "--load-n", "0", "-1500"]) == 2  # neither speed nor table
    assert "--speed-hz" in capsys.readouterr().err
    # a coefficient table of the model's bearing (isothermal)
    code, _ = _json(capsys, "--model-file", PADS, "--bearing", "NDE bearing", *GRID,
                    "--speeds-hz", "100:150:50", "--load-n", "0", "-1500")
    assert code == 0
