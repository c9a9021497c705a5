"""The THD film where a user meets it first (issue 20 follow-ups), on the compressor on plain
bearings (tests/data/models/compressor_plain_thermal.toml, not the paper rig):

* ``[thermal] journal_temperature_c`` / ``bush_temperature_c`` (the walls the THD heat flux
  goes to): TOML round trip; the model's value gives the same C++ call as the explicit
  argument (1e-9 relative); the heat balance's sign (heat flows from the warmer side: a bush
  hotter than the whole film gives heat to it, one colder takes heat from it);
* ``rotordyn thermal --model thd`` and ``rotordyn bearing --model thd``: the numbers they print
  are those of the Python calls (same inputs, 1e-9); bad input exits 2 naming the field.
"""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.analysis import system_thermal_equilibrium
from rotordyn.cli import main
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
THERMAL = MODELS / "compressor_plain_thermal.toml"
SPEED = 150.0  # Hz


def _thd_model(**kw):
    s = rotordyn.System.from_toml(THERMAL)
    return dataclasses.replace(s, thermal=dataclasses.replace(s.thermal, model="thd", **kw))


def test_wall_temperatures_round_trip_and_equal_the_arguments(tmp_path):
    s = _thd_model(bush_htc_w_m2k=800.0, bush_temperature_c=70.0, journal_htc_w_m2k=300.0,
                   journal_temperature_c=50.0)
    path = tmp_path / "m.toml"
    s.to_toml(path)
    text = path.read_text()
    assert "bush_temperature_c = 70.0" in text and "journal_temperature_c = 50.0" in text
    back = rotordyn.System.from_toml(path)
    assert back == s
    a = system_thermal_equilibrium(back, speed_hz=SPEED)
    base = _thd_model(bush_htc_w_m2k=800.0, journal_htc_w_m2k=300.0)
    b = system_thermal_equilibrium(base, speed_hz=SPEED, bush_temperature_c=70.0,
                                   journal_temperature_c=50.0)
    assert a.status == "ok" and a.thermal_model == "thd"
    np.testing.assert_allclose(a.max_temperature_c, b.max_temperature_c, rtol=1e-9)
    np.testing.assert_allclose(a.power_loss_w, b.power_loss_w, rtol=1e-9)
    # the wall temperatures reach the film: the supply-temperature walls give another answer
    c = system_thermal_equilibrium(base, speed_hz=SPEED)
    assert np.all(np.abs(a.effective_temperature_c - c.effective_temperature_c) > 0.1)
    # the dynamics at the frozen fields of the model file's walls run
    assert rotordyn.stability(a.system, speed_hz=SPEED).status == "ok"
    # a model without the keys writes none of them (None: the supply temperature)
    assert "bush_temperature_c" not in _thd_model().to_toml()


def test_heat_flows_from_the_warmer_wall():
    """Second law on the standalone film: a bush above the film's hottest point heats the
    film (heat_to_bush_w < 0) and raises its mean temperature; one at the supply temperature
    (below every film temperature) takes heat (> 0)."""
    s = rotordyn.System.from_toml(THERMAL)
    b = s.bearings[0].journal_bearing()
    kw = dict(load_n=(0.0, -1000.0), speed_hz=SPEED, oil=s.thermal.oil,
              supply_temperature_c=45.0, model="thd", bush_htc_w_m2k=1000.0)
    cold = b.thermal_equilibrium(**kw)
    assert cold.status == "ok" and cold.heat_to_bush_w > 0.0
    hot = b.thermal_equilibrium(**kw, bush_temperature_c=cold.max_temperature_c + 20.0)
    assert hot.status == "ok" and hot.heat_to_bush_w < 0.0
    assert hot.mean_temperature_c > cold.mean_temperature_c


@pytest.mark.parametrize("key,val,match", [
    ("bush_temperature_c", "nan", r"bush_temperature_c"),
    ("journal_temperature_c", '"hot"', r"journal_temperature_c"),
])
def test_bad_wall_temperature_in_the_model_file(tmp_path, key, val, match):
    text = THERMAL.read_text().replace("effective_factor = 0.5\n",
                                       f"effective_factor = 0.5\n{key} = {val}\n", 1)
    with pytest.raises(InputError, match=match):
        rotordyn.System.from_toml(text, is_text=True)


def test_cli_thermal_selects_the_thd_film(capsys):
    s = rotordyn.System.from_toml(THERMAL)
    r = system_thermal_equilibrium(s, speed_hz=SPEED, model="thd", bush_htc_w_m2k=500.0)
    assert main(["thermal", str(THERMAL), "--speed-hz", str(SPEED), "--model", "thd",
                 "--bush-htc-w-m2k", "500", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["thermal_model"] == "thd"
    for col in ("max_temperature_c", "effective_temperature_c", "power_loss_w",
                "film_flow_m3_s", "side_flow_m3_s"):
        np.testing.assert_allclose([row[col] for row in out["bearings"]], getattr(r, col),
                                   rtol=1e-9)
    assert main(["thermal", str(THERMAL), "--speed-hz", str(SPEED), "--model", "thd"]) == 0
    text = capsys.readouterr().out
    assert "thermal model thd" in text and "T_max" in text and "T_mean" in text
    assert "power loss" in text and "side flow" in text
    # the model's own selector stays the default
    assert main(["thermal", str(THERMAL), "--speed-hz", str(SPEED), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["thermal_model"] == "effective"


@pytest.mark.parametrize("extra,field", [
    (["--model", "thd", "--bush-htc-w-m2k", "-1"], "bush_htc_w_m2k"),
    (["--model", "thd", "--journal-temperature-c", "nan"], "journal_temperature_c"),
    (["--model", "thd", "--effective-factor", "0.7"], "--effective-factor"),  # no T_eff
])
def test_cli_thermal_bad_input_names_the_field(capsys, extra, field):
    assert main(["thermal", str(THERMAL), "--speed-hz", str(SPEED), *extra]) == 2
    assert field in capsys.readouterr().err


BEARING = ["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
           "--speed-hz", str(SPEED), "--load-n", "0", "-1000"]
OIL = ["--supply-temperature-c", "45", "--oil-walther", "40", "32", "100", "5.4"]


def test_cli_bearing_thd(capsys):
    s = rotordyn.System.from_toml(THERMAL)
    oil = dataclasses.replace(s.thermal.oil, density_kg_m3=870.0)
    b = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                viscosity_pa_s=oil.viscosity_pa_s(45.0))
    r = b.thermal_equilibrium(load_n=(0.0, -1000.0), speed_hz=SPEED, oil=oil,
                              supply_temperature_c=45.0, model="thd", bush_htc_w_m2k=500.0)
    assert main([*BEARING, *OIL, "--density-kg-m3", "870", "--model", "thd",
                 "--bush-htc-w-m2k", "500", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    t = out["thermal"]
    assert t["thermal_model"] == "thd"
    for f in ("max_temperature_c", "mean_temperature_c", "power_loss_w", "side_flow_m3_s"):
        assert t[f] == pytest.approx(getattr(r, f), rel=1e-9)
    np.testing.assert_allclose(out["k_n_per_m"], r.K, rtol=1e-9)
    assert main([*BEARING, *OIL, "--model", "thd"]) == 0
    text = capsys.readouterr().out
    assert "T_max" in text and "T_mean" in text and "power loss" in text


@pytest.mark.parametrize("extra,field", [
    (["--model", "thd"], "--model"),                                  # no oil
    ([*OIL, "--model", "thd", "--effective-factor", "0.7"], "--effective-factor"),
    ([*OIL, "--bush-htc-w-m2k", "100"], "--bush-htc-w-m2k"),          # effective model
    ([*OIL, "--model", "thd", "--journal-htc-w-m2k", "-5"], "journal_htc_w_m2k"),
])
def test_cli_bearing_thd_bad_input(capsys, extra, field):
    assert main([*BEARING, *extra]) == 2
    assert field in capsys.readouterr().err
