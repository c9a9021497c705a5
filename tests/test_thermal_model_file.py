"""The thermal model in the model file (issue 20): ``[thermal]`` (one oil system),
``[thermal.oil]`` and per-bearing ``[[thermal.film]]`` entries, on the compressor on plain
bearings (tests/data/models/compressor_plain_thermal.toml: compressor_plain.toml plus its oil
system). Read/write round trip, validation naming the TOML path, the analysis and CLI taking
the model's oil system, and its fields as sweep axes giving the direct calls' answers (same
C++ call on the same inputs: 1e-9 relative)."""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.analysis import system_thermal_equilibrium
from rotordyn.bearings import Oil, ThermalFilm, ThermalModel
from rotordyn.cli import main
from rotordyn.errors import InputError
from rotordyn.sweep import run_sweep
from rotordyn.sweep.paths import set_field

MODELS = Path(__file__).parent / "data" / "models"
THERMAL = MODELS / "compressor_plain_thermal.toml"
SPEED = 150.0  # Hz


def _model():
    return rotordyn.System.from_toml(THERMAL)


def test_round_trip_and_plain_model_unchanged():
    s = _model()
    assert s.thermal == ThermalModel(
        supply_temperature_c=45.0, carry_over=0.6,
        oil=Oil(density_kg_m3=860.0, specific_heat_j_per_kg_k=2000.0),
        films=(ThermalFilm(bearing="DE bearing", carry_over=0.4, supply_flow_m3_s=3e-4),))
    assert rotordyn.System.from_toml(s.to_toml(), is_text=True) == s
    plain = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    assert plain.thermal is None and "[thermal]" not in plain.to_toml()
    # the thermal file is the plain model plus its oil system
    assert dataclasses.replace(s, thermal=None, name=plain.name,
                               description=plain.description) == plain


def _text(**edit):
    text = THERMAL.read_text()
    for old, new in edit.items():
        assert old in text
        text = text.replace(old, new)
    return text


@pytest.mark.parametrize("old,new,match", [
    ("supply_temperature_c = 45.0\n", "", r"^thermal\.supply_temperature_c: missing"),
    ("supply_temperature_c = 45.0", "supply_temperature_c = 250.0",
     r"^thermal\.supply_temperature_c: expected a temperature in the oil's range"),
    ("carry_over = 0.6", "carry_over = 1.5", r"^thermal\.carry_over: expected 0 <= carry_over"),
    ("effective_factor = 0.5", "effective_factor = 0.2", r"^thermal\.effective_factor"),
    ("specific_heat_j_per_kg_k = 2000.0", "specific_heat_j_per_kg_k = -1.0",
     r"^thermal\.oil\.specific_heat_j_per_kg_k"),
    ("nu2_mm2_s = 5.4", "nu2_mm2_s = 50.0", r"^thermal\.oil\."),
    ("t1_c = 40.0", "t1_c = 40.0\ncolour = 1", r"^thermal\.oil\.colour: unknown key"),
    ("bearing = \"DE bearing\"", "bearing = \"DE bearing\"\nflow = 1.0",
     r"^thermal\.film\[0\]\.flow: unknown key"),
    ("supply_flow_m3_s = 3.0e-4", "supply_flow_m3_s = -3.0e-4",
     r"^thermal\.film\[0\]\.supply_flow_m3_s: expected >= 0"),
    ("bearing = \"DE bearing\"", "bearing = \"DE\"",
     r"^thermal\.film\[0\]\.bearing: expected the name of a plain or active journal bearing"),
])
def test_bad_thermal_input_names_the_toml_path(old, new, match):
    with pytest.raises(InputError, match=match):
        rotordyn.System.from_toml(_text(**{old: new}), is_text=True)


def test_thermal_film_entry_on_a_table_bearing_says_why():
    """A ``[[thermal.film]]`` entry naming a bearing that has no film (a coefficient table)
    says what that bearing is (before: only "expected ... of the model ['NDE bearing'], got 'DE
    bearing'", which reads as a misspelt name)."""
    table = (MODELS / "compressor_table.toml").read_text()
    de = table.index("[[bearing]]", table.index("[[bearing]]") + 1)
    plain = THERMAL.read_text()
    first = plain.index("[[bearing]]")
    nde = plain[first:plain.index("[[bearing]]", first + 1)]
    text = table[:table.index("[[bearing]]")] + nde + table[de:] + \
        plain[plain.index("[thermal]"):]
    with pytest.raises(InputError, match=r"^thermal\.film\[0\]\.bearing: .*\['NDE bearing'\], "
                       r"got 'DE bearing' \(a TableBearing: it has no film"):
        rotordyn.System.from_toml(text, is_text=True)


def test_analysis_and_cli_take_the_models_oil_system(capsys):
    s = _model()
    r = system_thermal_equilibrium(s, speed_hz=SPEED)
    assert r.status == "ok" and r.bearing_names == ("NDE bearing", "DE bearing")
    # the same call with every input given explicitly: the NDE's (the [thermal] defaults)
    # for both bearings. The rotor is statically determinate (each bearing's load does not
    # depend on its film), so the NDE's answer is the same to round-off and only the DE's
    # own [[thermal.film]] entry changes the DE's
    th = s.thermal
    plain = dataclasses.replace(s, thermal=None)
    same = system_thermal_equilibrium(plain, speed_hz=SPEED, oil=th.oil,
                                      supply_temperature_c=45.0, carry_over=0.6)
    assert same.status == "ok"
    np.testing.assert_allclose(r.effective_temperature_c[0], same.effective_temperature_c[0],
                               rtol=1e-9)
    assert r.supply_flow_m3_s[1] == pytest.approx(3e-4, rel=1e-12)  # the DE's metered flow
    assert abs(r.effective_temperature_c[1] - same.effective_temperature_c[1]) > 1.0
    # an explicit argument overrides the model for every bearing
    over = system_thermal_equilibrium(s, speed_hz=SPEED, carry_over=0.6, supply_flow_m3_s=0.0)
    np.testing.assert_allclose(over.effective_temperature_c, same.effective_temperature_c,
                               rtol=1e-9)
    with pytest.raises(InputError, match="^oil: the model has no \\[thermal\\] table"):
        system_thermal_equilibrium(plain, speed_hz=SPEED)
    # the CLI: no thermal options needed with the model's [thermal]
    assert main(["thermal", str(THERMAL), "--speed-hz", str(SPEED), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    got = [b["effective_temperature_c"] for b in out["bearings"]]
    np.testing.assert_allclose(got, r.effective_temperature_c, rtol=1e-9)
    assert main(["thermal", str(THERMAL), "--speed-hz", str(SPEED), "--json",
                 "--supply-temperature-c", "55"]) == 0
    out = json.loads(capsys.readouterr().out)
    hot = system_thermal_equilibrium(s, speed_hz=SPEED, supply_temperature_c=55.0)
    np.testing.assert_allclose([b["effective_temperature_c"] for b in out["bearings"]],
                               hot.effective_temperature_c, rtol=1e-9)


def test_sweep_over_supply_temperature_and_carry_over_equals_direct_calls(tmp_path):
    s = _model()
    s.to_toml(tmp_path / "m.toml")
    axes = ["thermal.supply_temperature_c", "thermal.films.DE_bearing.carry_over"]
    grid = ('"thermal.supply_temperature_c" = [35.0, 50.0, 65.0]\n'
            '"thermal.films.DE_bearing.carry_over" = [0.2, 0.7]\n'
            f'speed_hz = {SPEED}\n')
    spec = tmp_path / "s.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "th"\nmodel = "m.toml"\n'
                    f'analysis = "thermal"\nchunk_size = 4\n[grid]\n{grid}')
    res = run_sweep(spec, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    assert fr["point_id"].nunique() == 6 and (fr["status"] == "ok").all() and len(fr) == 12
    teff = []
    for pid, g in fr.groupby("point_id"):
        m = s
        for a in axes:
            m = set_field(m, a, float(g.iloc[0][a]))
        r = system_thermal_equilibrium(m, speed_hz=SPEED)
        assert list(g["bearing"]) == list(r.bearing_names)
        for c in ("effective_temperature_c", "max_temperature_c", "viscosity_pa_s",
                  "power_loss_w", "side_flow_m3_s", "journal_x_m", "journal_y_m"):
            np.testing.assert_allclose(g[c].to_numpy(), getattr(r, c), rtol=1e-9, atol=1e-15)
        teff.append(r.effective_temperature_c[0])
    assert np.ptp(teff) > 5.0  # the supply temperature really moves the film (K)
    # a configuration axis is refused for the thermal analysis
    text = spec.read_text()
    spec.write_text(text + "config_ay_m = [0.0, 1e-5]\n")
    with pytest.raises(InputError, match="grid.config_ay_m: not available"):
        sw.SweepSpec.from_toml(spec)
    # ... and a model without [thermal] at load, before any point runs
    dataclasses.replace(s, thermal=None).to_toml(tmp_path / "m.toml")
    spec.write_text(text.replace('"thermal.films.DE_bearing.carry_over" = [0.2, 0.7]\n', "")
                    .replace('"thermal.supply_temperature_c" = [35.0, 50.0, 65.0]\n', ""))
    with pytest.raises(InputError, match="^analysis: 'thermal' needs the model's oil system"):
        sw.SweepSpec.from_toml(spec)


def test_every_thermal_number_is_a_model_path():
    s = _model()
    for path, val in (("thermal.supply_temperature_c", 50.0), ("thermal.carry_over", 0.3),
                      ("thermal.effective_factor", 0.7), ("thermal.supply_flow_m3_s", 1e-5),
                      ("thermal.oil.nu1_mm2_s", 46.0), ("thermal.oil.density_kg_m3", 880.0),
                      ("thermal.films.DE_bearing.supply_flow_m3_s", 3e-5),
                      ("thermal.films.0.effective_factor", 0.8)):
        s2 = set_field(s, path, val)
        assert s2 != s and rotordyn.System.from_toml(s2.to_toml(), is_text=True) == s2
    with pytest.raises(InputError, match=r"grid\.thermal\.carry_over: .*carry_over: expected 0"):
        set_field(s, "thermal.carry_over", 2.0)
    with pytest.raises(InputError, match=r"grid\.thermal\.oil\.viscosity_law: .*not a numeric"):
        set_field(s, "thermal.oil.viscosity_law", 1.0)
    with pytest.raises(InputError, match=r"thermal\.films\.NDE: no element 'NDE'.*'DE bearing'"):
        set_field(s, "thermal.films.NDE.carry_over", 0.1)


def test_thermal_film_entry_on_an_active_bearing():
    """A ``[[thermal.film]]`` entry may name an active journal bearing (docs/model-file.md; the
    thermal models take it: docs/film-physics.md, "THD active bearing"). Before: refused at
    load, "expected the name of a plain journal bearing ... got 'DE active bearing'". On the
    compressor with an active DE bearing (tests/data/models/compressor_active.toml) and the
    plain-thermal model's oil system, the entry's metered supply flow and carry-over reach the
    active film (effective model, 150 Hz, p_c = 0), the plain NDE film keeps its own demand,
    and the model file round-trips."""
    text = (MODELS / "compressor_active.toml").read_text().replace(
        "n_circ = 72\nn_axial = 16", "n_circ = 48\nn_axial = 8")
    oil = THERMAL.read_text()
    text += "\n" + oil[oil.index("[thermal]"):].replace('bearing = "DE bearing"',
                                                         'bearing = "DE active bearing"')
    s = rotordyn.System.from_toml(text, is_text=True)
    assert s.thermal.films[0].bearing == "DE active bearing"
    assert rotordyn.System.from_toml(s.to_toml(), is_text=True) == s
    r = system_thermal_equilibrium(s, speed_hz=SPEED, model="effective")
    assert r.status == "ok"
    fr = r.to_frame().set_index("bearing")
    assert fr.loc["DE active bearing", "supply_flow_m3_s"] == pytest.approx(3e-4, rel=1e-12)
    assert fr.loc["NDE bearing", "supply_flow_m3_s"] != pytest.approx(3e-4, rel=1e-3)
    lam = system_thermal_equilibrium(s, speed_hz=SPEED, model="effective", carry_over=0.4,
                                     supply_flow_m3_s=3e-4).to_frame().set_index("bearing")
    assert fr.loc["DE active bearing", "effective_temperature_c"] == pytest.approx(
        lam.loc["DE active bearing", "effective_temperature_c"], abs=1e-4)
