"""`rotordyn thermal MODEL` with oil properties on the command line (found 2026-12-05 on a
user's five-stage compressor; docs/model-file.md: "an argument or option given overrides the
model's value for every bearing").

Before: on a model with `[thermal]`, `--specific-heat-j-per-kg-k` and `--density-kg-m3` were
silently ignored without an `--oil-*` law (the answer bit for bit the model's), and with a law
the model's `[thermal.oil]` density and specific heat were silently replaced by 870 kg/m³ and
2000 J/(kg K) — on a turbulent model whose films have the oil's 865 kg/m³ the command then
refused "a turbulent film's density ... must be the thermal oil's, oil.density_kg_m3 = 870".
Now each given property overrides the model's oil, and a law of its own keeps the model's
density and specific heat unless they are given; the JSON equals the API's
`system_thermal_equilibrium` with that oil to round-off."""

from __future__ import annotations

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.bearings import Oil

MODELS = Path(__file__).parent / "data" / "models"
TURB = MODELS / "compressor5_plain_thermal.toml"  # turbulent films, oil 865 kg/m3, 1950 J/(kg K)
LAMINAR = MODELS / "compressor_plain_thermal.toml"


def _thermal_json(model, *args):
    p = subprocess.run([sys.executable, "-m", "rotordyn", "thermal", str(model), "--speed-hz",
                        "150", "--json", *map(str, args)], capture_output=True, text=True,
                       timeout=300)
    return p, (json.loads(p.stdout) if p.returncode in (0, 1) and p.stdout else None)


def _api(path, oil=None, **kw):
    s = rd.System.from_toml(path)
    return rd.system_thermal_equilibrium(s, speed_hz=150.0, oil=oil, **kw).to_frame()


def _same(d, frame):
    got = np.array([r["max_temperature_c"] for r in d["bearings"]])
    np.testing.assert_allclose(got, frame.max_temperature_c.to_numpy(), rtol=1e-12)
    got = np.array([r["power_loss_w"] for r in d["bearings"]])
    np.testing.assert_allclose(got, frame.power_loss_w.to_numpy(), rtol=1e-12)


def test_specific_heat_and_density_override_the_models_oil():
    base = rd.System.from_toml(LAMINAR).thermal.oil
    _, plain = _thermal_json(LAMINAR)
    p, d = _thermal_json(LAMINAR, "--specific-heat-j-per-kg-k", 1500)
    assert p.returncode == 0, p.stderr
    _same(d, _api(LAMINAR, dataclasses.replace(base, specific_heat_j_per_kg_k=1500.0)))
    # less heat capacity: hotter films than the model's 2000 J/(kg K)
    assert all(a["max_temperature_c"] > b["max_temperature_c"] + 1.0
               for a, b in zip(d["bearings"], plain["bearings"]))
    p, d = _thermal_json(LAMINAR, "--density-kg-m3", 800)
    assert p.returncode == 0, p.stderr
    _same(d, _api(LAMINAR, dataclasses.replace(base, density_kg_m3=800.0)))


def test_a_law_of_its_own_keeps_the_models_density_and_specific_heat():
    p, d = _thermal_json(TURB, "--oil-exponential", 0.03, 40, 0.03, "--supply-temperature-c", 50)
    assert p.returncode == 0, p.stderr
    oil = Oil(viscosity_law="exponential", mu_ref_pa_s=0.03, t_ref_c=40.0, beta_1_per_k=0.03,
              density_kg_m3=865.0, specific_heat_j_per_kg_k=1950.0)
    _same(d, _api(TURB, oil, supply_temperature_c=50.0))
    # given on the command line, they win (here a density the turbulent films do not have)
    p, _ = _thermal_json(TURB, "--oil-exponential", 0.03, 40, 0.03, "--supply-temperature-c",
                         50, "--density-kg-m3", 870)
    assert p.returncode == 2 and "density_kg_m3" in p.stderr and "870" in p.stderr


@pytest.mark.parametrize("opt,val,field", [("--specific-heat-j-per-kg-k", -5, "specific_heat"),
                                           ("--density-kg-m3", 0, "density_kg_m3")])
def test_bad_property_is_refused_naming_it(opt, val, field):
    p, _ = _thermal_json(LAMINAR, opt, val)
    assert p.returncode == 2 and field in p.stderr


# An option of the other thermal model was silently ignored by the system call (the standalone
# film refuses it: "an option of model='thd' only"): `system_thermal_equilibrium(...,
# journal_htc_w_m2k=500)` or `wall_htc="film"` on the effective-temperature model (adiabatic)
# gave the model's answer bit for bit, `rotordyn thermal --journal-htc-w-m2k 500` too; and
# `effective_factor=` with the THD film. Now each is refused naming it.
@pytest.mark.parametrize("kw,field", [({"journal_htc_w_m2k": 500.0}, "journal_htc_w_m2k"),
                                      ({"bush_temperature_c": 60.0}, "bush_temperature_c"),
                                      ({"wall_htc": "film"}, "wall_htc")])
def test_thd_wall_options_refused_on_the_effective_model(kw, field):
    s = rd.System.from_toml(TURB)
    assert s.thermal.model == "effective"
    with pytest.raises(rd.InputError, match=f"^{field}: an option of model='thd' only"):
        rd.system_thermal_equilibrium(s, speed_hz=150.0, **kw)
    with pytest.raises(rd.InputError, match=f"^thermal.{field}: an option"):
        rd.stability(s, 150.0, thermal=kw)
    # the THD film takes them
    r = rd.system_thermal_equilibrium(s, speed_hz=150.0, model="thd", **kw)
    assert r.status == "ok"


def test_effective_factor_refused_on_the_thd_film():
    s = rd.System.from_toml(TURB)
    with pytest.raises(rd.InputError, match="^effective_factor: an option of model='effective'"):
        rd.system_thermal_equilibrium(s, speed_hz=150.0, model="thd", effective_factor=0.7)


def test_cli_wall_option_on_the_effective_model_is_refused_naming_it():
    p, _ = _thermal_json(TURB, "--journal-htc-w-m2k", 500)
    assert p.returncode == 2 and "--journal-htc-w-m2k" in p.stderr
    p, d = _thermal_json(TURB, "--journal-htc-w-m2k", 500, "--model", "thd")
    assert p.returncode == 0, p.stderr
    _same(d, _api(TURB, model="thd", journal_htc_w_m2k=500.0))


# `rotordyn bearing` at a point of its own (a plain film by its dimensions, loaded, supplied)
BEARING = ["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
           "--n-circ", "48", "--n-axial", "8", "--supply-temperature-c", "45", "--oil-walther",
           "40", "32", "100", "5.4", "--density-kg-m3", "860", "--speed-hz", "150", "--load-n",
           "0", "-1500"]


@pytest.mark.parametrize("command", ["thermal", "bearing"])
@pytest.mark.parametrize("args, message", [
    (["--model", "effective", "--bush-htc-w-m2k", "500"],
     "rotordyn: error: --bush-htc-w-m2k: an option of --model thd only (the "
     "effective-temperature model is adiabatic)"),
    (["--model", "thd", "--effective-factor", "0.5"],
     "rotordyn: error: --effective-factor: an option of --model effective only (the THD film "
     "has no effective temperature: the energy equation gives the field)")])
def test_cli_other_model_option_is_the_apis_rule_in_flag_names(command, args, message, capsys):
    """`rotordyn thermal` and `rotordyn bearing` refuse an option of the other model by the
    API's one rule (analysis.thermal.refuse_other_model_options), named as their flags (each
    kept its own copy of the rule)."""
    from rotordyn.cli import main

    argv = ["thermal", str(TURB), "--speed-hz", "150"] if command == "thermal" else BEARING
    assert main([*argv, *args]) == 2
    assert capsys.readouterr().err.strip() == message


def test_thermal_keywords_take_the_thd_wall_options():
    """`thermal={"model": "thd", "wall_htc": "film"}` (docs: a dict of
    system_thermal_equilibrium's keywords) was refused: "thermal.wall_htc: not a keyword of
    system_thermal_equilibrium; expected one of [..., 'walls']" — the signature's **walls
    listed by its own name. Now the dynamics run at the same thermal equilibrium as the
    direct call, bit for bit."""
    s = rd.System.from_toml(TURB)
    kw = {"model": "thd", "wall_htc": "film"}
    st = rd.stability(s, 150.0, thermal=kw)
    r = rd.system_thermal_equilibrium(s, speed_hz=150.0, **kw)
    np.testing.assert_array_equal(st.thermal.max_temperature_c, r.max_temperature_c)
    np.testing.assert_array_equal(st.eigenvalues, rd.stability(r.system, 150.0).eigenvalues)
    # the film's own conduction to walls at the supply temperature cools it (here by > 10 K)
    plain = rd.system_thermal_equilibrium(s, speed_hz=150.0, model="thd")
    assert np.all(r.max_temperature_c < plain.max_temperature_c - 10.0)
    c = rd.campbell(s, [150.0], n_modes=4, thermal=kw)
    np.testing.assert_array_equal(c.thermal[0].max_temperature_c, r.max_temperature_c)


def test_terminal_table_keeps_the_axial_place_of_the_minimum_film_in_m():
    """`rotordyn thermal`'s table printed an aligned journal's ``h_min_z`` (0, the mid-plane)
    as ``h_min_z_um`` and a tilted one's (±L/2, an edge) as ``h_min_z_m``: the same column
    under two names and units. An axial place stays in m; the films and positions go to µm."""
    import pandas as pd

    from rotordyn.cli.common import table_text

    for z in (0.0, 0.0225):
        head = table_text(pd.DataFrame({"h_min_m": [69e-6], "h_min_z_m": [z],
                                        "journal_x_m": [2e-5]})).split("\n")[0].split()
        assert head == ["h_min_um", "h_min_z_m", "journal_x_um"], head
