"""``rotordyn bearing --theta-x-rad/--theta-y-rad`` with a thermal model (issue 20;
docs/film-physics.md, "Plain and tilting-pad bearings, standalone"). Before, the command
refused a tilt together with ``--supply-temperature-c`` (InputError, exit 2); now it solves
the tilted thermal equilibrium (effective or THD) and records the thermal outputs beside the
tilt outputs under the names of the untilted thermal record and of the isothermal tilted
record.

Bearing: the compressor's NDE bearing of tests/data/models/compressor_plain_thermal.toml
(D = 0.1 m, L = 0.05 m, c = 0.1 mm; 36 × 6 here) with its oil system (VG 32, 45 °C supply,
carry-over 0.6), 4 kN at 100 Hz — not the paper rig. The command's numbers equal the model
bearing's own ``thermal_equilibrium`` (another entry: the model file's FluidFilmBearing) to
1e-12 relative (observed: bit for bit; the same C++ call)."""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
TX, TY = 0.5e-4, 2e-4
GEO = ["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
       "--n-circ", "36", "--n-axial", "6"]
SPEED, LOAD = ["--speed-hz", "100"], ["--load-n", "0", "-4000"]
OIL = ["--supply-temperature-c", "45", "--oil-walther", "40", "32", "100", "5.4",
       "--density-kg-m3", "860", "--carry-over", "0.6"]
BASE = GEO + SPEED + LOAD + OIL
TILT = ["--theta-x-rad", repr(TX), "--theta-y-rad", repr(TY)]


def _run(capsys, *extra):
    code = main([*BASE, *extra, "--json"])
    out = capsys.readouterr().out
    return code, (json.loads(out) if out else None)


def _api(model):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    b = dataclasses.replace(s.bearings[0], n_circ=36, n_axial=6)
    th = s.thermal
    kw = {} if model == "thd" else {"effective_factor": 0.5}
    return b.thermal_equilibrium(load_n=(0.0, -4000.0), speed_hz=100.0, oil=th.oil,
                                 model=model, supply_temperature_c=45.0, carry_over=0.6,
                                 theta_x_rad=TX, theta_y_rad=TY, **kw)


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_tilted_thermal_record_equals_the_api(capsys, model):
    code, r = _run(capsys, "--model", model, *TILT)
    assert code == 0
    a = _api(model)
    assert (r["journal_x_m"], r["journal_y_m"]) == pytest.approx((a.x_m, a.y_m), rel=1e-12)
    assert r["thermal"]["max_temperature_c"] == pytest.approx(a.max_temperature_c, rel=1e-12)
    assert r["thermal"]["power_loss_w"] == pytest.approx(a.power_loss_w, rel=1e-12)
    np.testing.assert_allclose(r["film_moment_n_m"], a.film_moment_n_m, rtol=1e-12)
    assert (r["h_min_m"], r["h_min_z_m"]) == pytest.approx((a.h_min_m, a.h_min_z_m), rel=1e-12)
    assert r["h_min_z_m"] == pytest.approx(0.025)  # the thin edge
    for key, ref in (("k_4x4_si", a.K4), ("c_4x4_si", a.C4)):
        np.testing.assert_allclose(r[key], ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max())
    np.testing.assert_array_equal(r["k_n_per_m"], np.array(r["k_4x4_si"])[:2, :2])
    np.testing.assert_array_equal(r["c_n_s_per_m"], np.array(r["c_4x4_si"])[:2, :2])
    assert (r["journal_theta_x_rad"], r["journal_theta_y_rad"]) == (TX, TY)
    assert r["thermal"]["film_moment_y_n_m"] == r["film_moment_n_m"][1]
    if model == "effective":  # the hot film at the tilted pose carries the load
        np.testing.assert_allclose(r["force_n"], [0.0, 4000.0], atol=1e-7 * 4000.0)


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_key_names_are_those_of_the_two_records(capsys, model):
    """Every key of the tilted thermal record is a key of the untilted thermal record or of
    the isothermal tilted record, with the same meaning; of the two, only the isothermal
    film's journal velocities and misaligned-equilibrium block are absent, and with the
    effective model the untilted film's friction torque (the tilted film solve gives none).
    Both tilted records carry ``force_n``, the frozen film's force at the returned pose (the
    result's; before 2026-12-05 the THD record had none, as the untilted THD record has
    none)."""
    code, th = _run(capsys, "--model", model, *TILT)
    code0, plain = _run(capsys, "--model", model)
    iso = main(["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m",
                "1e-4", "--viscosity-pa-s", "0.02", "--n-circ", "36", "--n-axial", "6",
                "--speed-hz", "100", "--load-n", "0", "-4000", *TILT, "--json"])
    iso_rec = json.loads(capsys.readouterr().out)
    assert code == code0 == iso == 0
    assert set(th) <= set(plain) | set(iso_rec)
    missing = (set(plain) | set(iso_rec)) - set(th)
    assert missing == ({"equilibrium", "journal_vx_m_s", "journal_vy_m_s"}
                       | ({"friction_torque_n_m"} if model == "effective" else set()))
    assert "force_n" in th and ("force_n" in plain) == (model == "effective")
    np.testing.assert_allclose(th["force_n"], [0.0, 4000.0], atol=1e-7 * 4000.0)
    for k in ("k_4x4_units", "c_4x4_units", "coordinates"):
        assert th[k] == iso_rec[k]


def test_text_output_and_refusals(capsys):
    assert main([*BASE, "--model", "thd", *TILT]) == 0
    out = capsys.readouterr().out
    assert "THD equilibrium" in out and "moment: Mx" in out and "theta_y" in out
    assert "temperature frozen" in out and "z = 0.025" in out
    assert main([*BASE, *TILT]) == 0
    out = capsys.readouterr().out
    assert "T_eff" in out and "force on journal" in out and "moment: Mx" in out
    # a tilt closing the film at an edge (θ L/2 >= c): the thermal path names the tilt too
    assert main([*BASE, "--theta-y-rad", "5e-3"]) == 2
    assert "theta" in capsys.readouterr().err
    # really unsupported: a coefficient table over speeds (the aligned film's), and a given
    # journal position (the thermal model solves the equilibrium under the load)
    assert main([*GEO, *LOAD, *OIL, "--speeds-hz", "50:100:50", *TILT]) == 2
    assert "--speeds-hz" in capsys.readouterr().err
    assert main([*GEO, *SPEED, *OIL, "--x-m", "0", "--y-m", "0", *TILT]) == 2
    assert "--load-n" in capsys.readouterr().err


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_failed_tilted_thermal_equilibrium_is_a_status_record(capsys, model):
    """400 kN on this 0.1 m × 0.05 m bearing: the equilibrium runs into the contact limit
    (no_equilibrium). Before: one 'rotordyn: failed: ...' line on stderr, exit 1, and with
    --json no record at all; now the record of the point (exit 1)."""
    code = main([*GEO, *SPEED, "--load-n", "0", "-400000", *OIL, "--model", model, *TILT,
                 "--json"])
    r = json.loads(capsys.readouterr().out)
    assert code == 1 and r["status"] == "no_equilibrium" and "contact" not in r["status"]
    assert "minimum film" in r["message"] and r["load_n"] == [0.0, -400000.0]
    assert (r["journal_theta_x_rad"], r["journal_theta_y_rad"]) == (TX, TY)
    assert r["thermal_model"] == model and r["speed_hz"] == 100.0
    assert not {"thermal", "k_4x4_si", "film_moment_n_m", "force_n"} & set(r)
