"""``rotordyn bearing --model-file MODEL --bearing NAME`` with a tilt (issue 20;
docs/film-physics.md, "Plain and tilting-pad bearings, standalone"): a model file's
tilting-pad or fixed-geometry bearing at its tilted thermal (or isothermal) operating point,
with the record of the plain bearing's tilted thermal command; a failed tilted thermal
equilibrium is a status record with exit 1, not a traceback or a bare error line.

Bearings (not the paper rig): the compressor's 5-pad rocker bearing of
tests/data/models/compressor_tilting_pad.toml ("NDE bearing", 60° pads, preload 0.3, load
between pads; 36 × 6 here) under 1.5 kN at 150 Hz, VG 32 supplied at 45 °C, carry-over 0.5,
the journal tilted by (0.1, 0.4) mrad; and an elliptical bearing (the compressor's size,
written into a model file here). The command equals the bearing's own
``thermal_equilibrium`` to 1e-12 (observed bit for bit: the same calls); the film's force at
the returned pose carries the load to 1e-6 of it (the frozen fields' film of the returned
pads; the equilibrium's tolerance is 1e-10 of the residual scale)."""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import FixedGeometryBearing, Oil
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
PADS = str(MODELS / "compressor_tilting_pad.toml")
TX, TY = 1e-4, 4e-4
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
OIL = ["--supply-temperature-c", "45", "--oil-walther", "40", "32", "100", "5.4",
       "--carry-over", "0.5"]
TILT = ["--theta-x-rad", repr(TX), "--theta-y-rad", repr(TY)]
GRID = ["--n-circ", "36", "--n-axial", "6"]


def _cli(capsys, model, *extra, bearing="NDE bearing", load=("0", "-1500")):
    argv = ["bearing", "--model-file", model, "--bearing", bearing, *GRID,
            "--speed-hz", "150", "--load-n", *load, *extra]
    code = main([*argv, "--json"])
    out = capsys.readouterr().out
    return code, (json.loads(out) if out else None)


def _pad_bearing():
    b = rotordyn.System.from_toml(PADS).bearings[0]
    return dataclasses.replace(b, n_circ=36, n_axial=6)


def _plain_keys(capsys, model):
    """The keys of the plain bearing's tilted thermal record (the dimensions path)."""
    code = main(["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m",
                 "1e-4", *GRID, "--speed-hz", "150", "--load-n", "0", "-1500", *OIL,
                 "--model", model, *TILT, "--json"])
    assert code == 0
    return set(json.loads(capsys.readouterr().out))


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_tilting_pad_record_equals_the_api_with_the_plain_keys(capsys, model):
    code, r = _cli(capsys, PADS, *OIL, "--model", model, *TILT)
    assert code == 0
    kw = {} if model == "thd" else {"effective_factor": 0.5}
    a = _pad_bearing().thermal_equilibrium(
        load_n=(0.0, -1500.0), speed_hz=150.0, oil=VG32, supply_temperature_c=45.0,
        carry_over=0.5, supply_flow_m3_s=0.0, model=model, theta_x_rad=TX, theta_y_rad=TY,
        tilt=True, **kw)
    assert (r["journal_x_m"], r["journal_y_m"]) == pytest.approx((a.x_m, a.y_m), rel=1e-12)
    assert r["thermal"]["pad"] == "total" and len(r["pads"]) == 5
    assert r["thermal"]["max_temperature_c"] == pytest.approx(a.max_temperature_c_total,
                                                              rel=1e-12)
    np.testing.assert_allclose([p["max_temperature_c"] for p in r["pads"]],
                               a.max_temperature_c, rtol=1e-12)
    np.testing.assert_allclose(r["film_moment_n_m"], a.film_moment_n_m, rtol=1e-12)
    assert r["thermal"]["film_moment_y_n_m"] == r["film_moment_n_m"][1]
    assert (r["h_min_m"], r["h_min_z_m"]) == pytest.approx((a.h_min_m, a.h_min_z_m), rel=1e-12)
    assert r["h_min_z_m"] == pytest.approx(0.025)  # the thin edge (θy > 0: +L/2)
    assert 0.0 <= r["h_min_angle_deg"] < 360.0
    for key, ref in (("k_4x4_si", a.K4), ("c_4x4_si", a.C4)):
        np.testing.assert_allclose(r[key], ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max())
    assert (r["journal_theta_x_rad"], r["journal_theta_y_rad"]) == (TX, TY)
    # the frozen fields' film at the returned pose (pads at their equilibrium) carries the load
    np.testing.assert_allclose(r["force_n"], [0.0, 1500.0], atol=1e-6 * 1500.0)
    assert r["bearing"]["type"] == "tilting_pad" and r["bearing"]["name"] == "NDE bearing"
    # the plain bearing's record keys, plus the per-pad rows
    assert set(r) == _plain_keys(capsys, model) | {"pads"}


def test_tilting_pad_text_and_isothermal(capsys):
    assert main(["bearing", "--model-file", PADS, "--bearing", "DE bearing", *GRID,
                 "--speed-hz", "150", "--load-n", "0", "-1500", *OIL, "--model", "thd",
                 *TILT]) == 0
    out = capsys.readouterr().out
    assert "thermal equilibrium (thd model" in out and "pad_tilt_rad" in out
    assert "moment: Mx" in out and "temperature frozen" in out and "N·m/rad" in out
    # isothermal: the pads' misaligned equilibrium at the bearing's own viscosity
    code, r = _cli(capsys, PADS, *TILT)
    assert code == 0 and r["equilibrium"]["status"] == "ok"
    from rotordyn.bearings.tilt import misaligned_equilibrium
    e = misaligned_equilibrium(_pad_bearing(), load_n=(0.0, -1500.0), speed_hz=150.0,
                               theta_x_rad=TX, theta_y_rad=TY)
    np.testing.assert_allclose(r["film_moment_n_m"], e.film_moment_n_m, rtol=1e-12)


def test_fixed_geometry_bearing_from_a_model_file(tmp_path, capsys):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    lobes = tuple(FixedGeometryBearing(
        kind="elliptical", name=b.name, station=b.station, diameter_m=0.1, length_m=0.05,
        clearance_m=1e-4, viscosity_pa_s=0.02, preload=0.5) for b in s.bearings)
    path = tmp_path / "lobes.toml"
    dataclasses.replace(s, bearings=lobes).to_toml(path)
    code, r = _cli(capsys, str(path), *OIL, "--model", "thd", *TILT,
                   bearing=s.bearings[0].name, load=("0", "-4000"))
    assert code == 0
    b = dataclasses.replace(lobes[0], n_circ=36, n_axial=6)
    a = b.thermal_equilibrium(load_n=(0.0, -4000.0), speed_hz=150.0, oil=VG32,
                              supply_temperature_c=45.0, carry_over=0.5, model="thd",
                              theta_x_rad=TX, theta_y_rad=TY)
    np.testing.assert_allclose(r["film_moment_n_m"], a.film_moment_n_m, rtol=1e-12)
    np.testing.assert_allclose(r["k_4x4_si"], a.K4, rtol=1e-12, atol=1e-12 * np.abs(a.K4).max())
    np.testing.assert_allclose(r["force_n"], [0.0, 4000.0], atol=1e-6 * 4000.0)
    assert r["bearing"]["type"] == "fixed_geometry"
    assert set(r) == _plain_keys(capsys, "thd") | {"pads"}


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_failed_tilted_thermal_equilibrium_is_a_status_record(capsys, model):
    """A load the pads cannot carry (60 kN on this 0.1 m × 0.05 m bearing at 150 Hz: the
    equilibrium runs into the film's contact limit): the record names the status, the
    message and the point's inputs, exit 1; no film outputs or coefficients."""
    load = ("0", "-60000")
    code, r = _cli(capsys, PADS, *OIL, "--model", model, *TILT, load=load)
    assert code == 1
    assert r["status"] not in ("ok", "contact") and r["message"]
    assert r["load_n"] == [0.0, -60000.0] and r["speed_hz"] == 150.0
    assert (r["journal_theta_x_rad"], r["journal_theta_y_rad"]) == (TX, TY)
    assert r["supply_temperature_c"] == 45.0 and r["thermal_model"] == model
    assert not {"k_4x4_si", "film_moment_n_m", "thermal", "force_n"} & set(r)
    # the API raises a ConvergenceError carrying the same status
    with pytest.raises(rotordyn.ConvergenceError) as exc:
        _pad_bearing().thermal_equilibrium(
            load_n=(0.0, -60000.0), speed_hz=150.0, oil=VG32, supply_temperature_c=45.0,
            carry_over=0.5, model=model, theta_x_rad=TX, theta_y_rad=TY)
    assert exc.value.status == r["status"] and exc.value.detail == r["message"]
    # text: one status line with the inputs, exit 1, nothing on stderr
    assert main(["bearing", "--model-file", PADS, "--bearing", "NDE bearing", *GRID,
                 "--speed-hz", "150", "--load-n", *load, *OIL, "--model", model, *TILT]) == 1
    cap = capsys.readouterr()
    assert r["status"] in cap.out and "no film outputs" in cap.out and "-60000" in cap.out
    assert cap.err == ""


def test_model_file_refusals(capsys):
    base = ["bearing", "--model-file", PADS, "--speed-hz", "150", "--load-n", "0", "-1500"]
    assert main([*base, "--bearing", "nope", *TILT]) == 2
    assert "--bearing" in capsys.readouterr().err
    assert main([*base, *TILT]) == 2  # two bearings: name one
    assert "--bearing" in capsys.readouterr().err
    assert main([*base, "--bearing", "NDE bearing", "--diameter-m", "0.1", *TILT]) == 2
    assert "--diameter-m" in capsys.readouterr().err
    assert main(["bearing", "--speed-hz", "150", "--load-n", "0", "-1", *TILT]) == 2
    assert "--diameter-m" in capsys.readouterr().err
    # an oil density without an oil law would be silently ignored: refused
    assert main([*base, "--bearing", "NDE bearing", "--density-kg-m3", "870", *TILT]) == 2
    assert "--density-kg-m3" in capsys.readouterr().err
