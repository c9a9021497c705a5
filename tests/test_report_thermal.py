"""The report's thermal section (issue 20; rotordyn.report.thermal): for a model with an oil
system (``[thermal]``) ``rotordyn report`` shows, per thermal film (pad, lobe) at a few analysed
speeds, the temperatures, power loss and flows of the thermal equilibrium, per bearing the
hottest film and the total power loss, and K, C at the thermal equilibrium (field frozen).

Compared: the written tables (bearing_thermal.csv, bearing_thermal_coefficients.csv) equal
the direct calls (system_thermal_equilibrium, then bearing_coefficients of its returned system)
at the same speeds (1e-9: same inputs, same C++ calls); the text and HTML show them; a model
whose thermal model does not apply to its bearings gets a note, not a crash; a model without
an oil system gets no section. Models: the compressor of tests/data/models on 5-pad tilting
pads and on three-lobe bearings with the THD oil system (coarse grids), two speeds.
"""

import contextlib
import dataclasses
import io
from pathlib import Path

import numpy as np
import pandas as pd

import rotordyn
from rotordyn.analysis.bearing_coefficients import bearing_coefficients
from rotordyn.cli import main
from rotordyn.report.thermal import thermal_frames
from test_film_thd_pad_system import compressor_fixed, compressor_tilting_pad

SPEEDS = (120.0, 160.0)


def _report(tmp_path, s):
    path = tmp_path / "m.toml"
    s.to_toml(path)
    out = tmp_path / "out"
    args = ["report", str(path), "--out", str(out), "--speeds-hz", "120:160:40"]
    text, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(text), contextlib.redirect_stderr(err):
        code = main(args)
    assert code == 0, err.getvalue()
    return out, (out / "report.txt").read_text(encoding="utf-8")


def _check_tables(out, s):
    th = pd.read_csv(out / "bearing_thermal.csv")
    kc = pd.read_csv(out / "bearing_thermal_coefficients.csv")
    assert sorted(set(th["speed_hz"])) == list(SPEEDS)
    for f in SPEEDS:
        r = rotordyn.system_thermal_equilibrium(s, speed_hz=f)
        g = th[th["speed_hz"] == f]
        assert list(g["bearing"]) == list(r.bearing_names)
        for c in ("max_temperature_c", "effective_temperature_c", "inlet_temperature_c",
                  "power_loss_w", "film_flow_m3_s", "supply_flow_m3_s", "journal_y_m"):
            np.testing.assert_allclose(g[c].to_numpy(), getattr(r, c), rtol=1e-9)
        ref = bearing_coefficients(r.system, [f])
        k = kc[kc["speed_hz"] == f]
        for c in ("kxx_n_per_m", "kxy_n_per_m", "kyy_n_per_m", "cxx_n_s_per_m", "cyy_n_s_per_m"):
            np.testing.assert_allclose(k[c].to_numpy(), ref[c].to_numpy(), rtol=1e-9)
        # the frozen field's K differs from the isothermal film's (the report's section 2b)
        iso = bearing_coefficients(s, [f])
        assert np.all(np.abs(k["kyy_n_per_m"].to_numpy() / iso["kyy_n_per_m"].to_numpy() - 1)
                      > 1e-3)
    return th


def test_text_report_shows_pad_temperatures_power_loss_and_thermal_coefficients(tmp_path):
    s = compressor_tilting_pad()
    out, text = _report(tmp_path, s)
    th = _check_tables(out, s)
    assert "bearing temperatures and power loss at the thermal equilibrium (thermal model thd" \
        in text
    assert "NDE bearing.pad4" in text and "power loss (W)" in text
    assert "bearing coefficients at the thermal equilibrium" in text
    # the per-bearing totals: the hottest pad, the pads' power loss summed
    g = th[(th["speed_hz"] == 160.0) & th["bearing"].str.startswith("DE bearing.")]
    block = text[text.index("per bearing (its films together"):].splitlines()
    line = next(x for x in block if x.split()[:3] == ["DE", "bearing", "160"])
    assert line.split()[3:5] == [f"{g['max_temperature_c'].max():.2f}",
                                 f"{g['power_loss_w'].sum():.4g}"]
    assert (out / "bearing_thermal.png").stat().st_size > 0


def test_html_section_on_lobes_and_the_critical_speed_map_with_per_bearing_oil(tmp_path):
    """The HTML section (rotordyn.report.thermal.thermal_html, as write_html places it) on
    three-lobe bearings: the lobes' rows and the coefficients at the thermal equilibrium; the
    figure and tables written (write_thermal) equal the direct calls. And the critical speed
    map of a model whose [thermal] has a [[thermal.film]] entry: it stopped the HTML report
    with exit 2 before (the bearing-free rotor kept an oil system naming a bearing it no
    longer had)."""
    from rotordyn.report.criteria import critical_speed_map
    from rotordyn.report.html import _table, svg
    from rotordyn.report.thermal import thermal_html, write_thermal

    s = compressor_fixed("three_lobe")
    assert s.thermal.films
    th, kc, note = thermal_frames(s, np.array(SPEEDS), 0.0, None)
    write_thermal(th, kc, tmp_path)
    _check_tables(tmp_path, s)
    page = thermal_html(th, kc, note, svg, _table)
    assert page.startswith("<h2>2c. Bearing temperatures and power loss</h2>")
    assert "DE bearing.lobe2" in page and "<svg" in page
    assert "Bearing coefficients at the thermal equilibrium" in page
    assert f"{th['max_temperature_c'].iloc[-1]:.2f}" in page
    ks, f, stations = critical_speed_map(s, n_k=3)
    assert np.all(np.isfinite(f[:, 0])) and stations == [1, 5]


def test_thermal_section_notes_and_absence():
    s = compressor_tilting_pad()
    eff = dataclasses.replace(s, thermal=dataclasses.replace(s.thermal, model="effective"))
    th, kc, note = thermal_frames(eff, np.array(SPEEDS), 0.0, None)
    # the effective model per pad now applies: one row per pad film and speed, with K, C
    assert note.startswith("thermal model effective") and kc is not None
    assert set(th["thermal_model"]) == {"effective"} and len(th) % 10 == 0
    assert th["bearing"].str.contains(r"\.pad\d").all() and (th["status"] == "ok").all()
    assert thermal_frames(dataclasses.replace(s, thermal=None), np.array(SPEEDS), 0.0,
                          None) == (None, None, "")


def test_critical_speeds_on_thermal_films(tmp_path):
    """Section 3c / the text report's "critical speeds on thermal films": the Campbell diagram
    and the API unbalance response with every speed at its own thermal equilibrium (field
    frozen), on the compressor on plain bearings (36 x 8). critical_speeds_thermal.csv equals
    critical_speed_table of the direct calls (rotordyn.campbell and the API response with
    thermal=True: same calls, exact) and differs from the isothermal critical speeds; the
    effective model on a pad bearing evaluated (per pad), and no section without an oil
    system."""
    from pathlib import Path

    from rotordyn.report.criteria import speed_range
    from rotordyn.report.sections import (api_response, critical_speed_table,
                                          thermal_critical_speeds)

    s = rotordyn.System.from_toml(Path(__file__).parent / "data" / "models"
                                  / "compressor_plain_thermal.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))
    path = tmp_path / "m.toml"
    s.to_toml(path)
    out = tmp_path / "out"
    text, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(text), contextlib.redirect_stderr(err):
        assert main(["report", str(path), "--out", str(out), "--speeds-hz", "100:200:10"]) == 0
    report = (out / "report.txt").read_text(encoding="utf-8")
    assert "critical speeds on thermal films (thermal model effective" in report
    got = pd.read_csv(out / "critical_speeds_thermal.csv")
    from rotordyn.cli.common import speeds

    rng = speed_range(s, None, speeds("100:200:10"), None, False)
    sp = rng.speeds_hz
    c = rotordyn.campbell(s, sp, 0.0, None, thermal=True)
    u, *_ = api_response(s, sp, rng.n_mc_hz, 0.0, None, None, thermal=True)
    want = critical_speed_table(c, u)
    assert len(got) == len(want) > 0
    np.testing.assert_array_equal(got["speed_hz"].to_numpy(), want["speed_hz"].to_numpy())
    iso = pd.read_csv(out / "critical_speeds.csv")
    assert not np.array_equal(iso["speed_hz"].to_numpy(), got["speed_hz"].to_numpy())
    pads = compressor_tilting_pad()
    eff = dataclasses.replace(pads, thermal=dataclasses.replace(pads.thermal, model="effective"))
    crit, note, _ = thermal_critical_speeds(eff, rng, 0.0, None)
    # the effective model now runs per pad (before: "not evaluated: model: ...")
    assert crit is not None, note
    assert thermal_critical_speeds(dataclasses.replace(s, thermal=None), rng, 0.0, None) == \
        (None, "", None)


def test_isothermal_sections_are_labelled_for_a_model_with_an_oil_system():
    """With ``[thermal]`` the report's unbalance (4) and stability (5) sections are computed on
    the isothermal films: the HTML says so there and points to the thermal ones; a model
    without an oil system gets no label."""
    from rotordyn.report.html import _isothermal_note

    models = Path(__file__).parent / "data" / "models"
    hot = rotordyn.System.from_toml(models / "compressor_plain_thermal.toml")
    cold = rotordyn.System.from_toml(models / "compressor_plain.toml")
    assert hot.thermal is not None and "Isothermal films" in _isothermal_note(hot)
    assert "section 3c" in _isothermal_note(hot)
    assert _isothermal_note(cold) == ""
