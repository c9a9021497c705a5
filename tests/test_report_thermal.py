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
import pytest

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
    assert "not evaluated in this report" in _isothermal_note(hot, thermal_shown=False)
    assert _isothermal_note(cold) == ""


def _coarse(name):
    """A compressor model of tests/data/models on a coarse film grid (36 x 8)."""
    s = rotordyn.System.from_toml(Path(__file__).parent / "data" / "models" / f"{name}.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


HTML_SPEEDS = np.arange(100.0, 201.0, 10.0)
HTML_OPERATING = (120.0, 160.0)  # N_mc = 160 Hz = the top speed / 1.25, as without a range


@pytest.fixture(scope="module")
def html_reports(tmp_path_factory):
    """The HTML report of the compressor on plain bearings with its oil system and without it
    (coarse grid, 100–200 Hz in 10 Hz steps, operating range 120–160 Hz): {name: (system,
    page, the text report's lines it gave (text_sink), its directory)}."""
    from rotordyn.report.html import write_html

    out = {}
    for name in ("compressor_plain_thermal", "compressor_plain"):
        d = tmp_path_factory.mktemp(name)
        s = _coarse(name)
        s.to_toml(d / "m.toml")
        sink: list[str] = []
        page = write_html(str(d / "m.toml"), d / "r.html", speeds_hz=HTML_SPEEDS,
                          operating_speed_hz=HTML_OPERATING, progress=False, text_sink=sink)
        out[name] = (s, page.read_text(encoding="utf-8"), sink, d)
    return out


def _cells(page: str, start: str) -> list[list[str]]:
    """The cells of the first table after ``start``."""
    import html
    import re

    i = page.index("<table>", page.index(start))
    rows = re.findall(r"<tr>(.*?)</tr>", page[i:page.index("</table>", i)])
    return [[html.unescape(re.sub("<.*?>", "", c)) for c in re.findall(r"<t[dh]>(.*?)</t[dh]>",
                                                                      r)] for r in rows]


def test_unbalance_and_stability_sections_on_thermal_films(html_reports):
    """Sections 4b and 5a: with [thermal] the unbalance response and the stability screen are
    shown on thermal films beside the isothermal ones (section 3c's results, not recomputed),
    the checks table names the films of each row and has the API checks on both; without an
    oil system none of it. A thermal δ shown equals rotordyn.campbell(thermal=True) at that
    speed, screened as the report does (same calls: the printed 4 digits)."""
    from rotordyn.report.criteria import Checks, stability_screen

    s, page = html_reports["compressor_plain_thermal"][:2]
    assert "<h2>4b. Unbalance response on thermal films</h2>" in page
    assert "<h2>5a. Stability on thermal films</h2>" in page
    assert "unbalance response at station 3, thermal films" in page  # the Bode title
    assert "unbalance response at station 3, isothermal films" in page
    assert "log decrement of the forward rotor modes, thermal films" in page
    assert "sections 4b and 5a (from section 3c" in page  # the isothermal label points there
    checks = _cells(page, "Overall")
    assert checks[0][:2] == ["check", "films"]
    films = {(r[0], r[1]) for r in checks[1:]}
    for name in ("no growing forward mode over the speed range",
                 "orbit against the bearing clearance (station 1)"):
        assert (name, "isothermal films") in films and (name, "thermal films") in films
    assert ("thermal equilibrium at every speed of the Campbell diagram",
            "thermal films") in films
    # all converged: a check that passed (it read "n/a" beside "all 121 speeds converged")
    conv = [r for r in checks[1:] if r[0].startswith("thermal equilibrium at every speed")]
    assert conv and all(r[-1] == "PASS" for r in conv), conv
    rows = _cells(page, "<h2>5a.")
    assert rows[0][-1] == "thermal films: δ" and len(rows) == 1 + HTML_SPEEDS.size
    c = rotordyn.campbell(s, HTML_SPEEDS, 0.0, None, thermal=True)
    ld = stability_screen(Checks(), c, 1.5 * HTML_SPEEDS[-1], None)
    for r in rows[1:]:
        i = int(np.flatnonzero(HTML_SPEEDS == float(r[0]))[0])
        assert float(r[-1]) == float(f"{np.nanmin(ld[i]) + 0.0:.4g}")
        assert float(r[-2]) == float(f"{c.frequencies_hz[i, np.nanargmin(ld[i])]:.4g}")
    cold = html_reports["compressor_plain"][1]
    assert "thermal films" not in cold and "Isothermal films" not in cold
    assert _cells(cold, "Overall")[0][:2] == ["check", "criterion"]


def test_speeds_without_a_thermal_equilibrium_are_marked_not_plotted():
    """A speed whose thermal equilibrium failed (its ``thermal`` entry None or not converged)
    is listed and written "no thermal equilibrium" in the log decrement table, never a number;
    the check says not resolved."""
    from types import SimpleNamespace

    from rotordyn.report.criteria import NOT_RESOLVED, Checks
    from rotordyn.report.thermal_dynamics import (equilibrium_check, failed_text,
                                                  log_dec_rows, no_thermal_equilibrium)

    sp = np.array([100.0, 110.0, 120.0])
    ok = SimpleNamespace(status="ok")
    c = SimpleNamespace(speeds_hz=sp, thermal=(ok, None, SimpleNamespace(status="no_equilibrium")),
                        frequencies_hz=np.array([[50.0], [np.nan], [np.nan]]))
    ld = np.array([[0.3], [np.nan], [np.nan]])
    np.testing.assert_array_equal(no_thermal_equilibrium(c), [110.0, 120.0])
    rows = log_dec_rows(c, ld, c, ld)
    assert rows[0] == ("100", "50", "0.3", "50", "0.3")
    assert rows[1][3:] == rows[2][3:] == ("no thermal equilibrium",) * 2
    assert "110, 120 Hz" in failed_text(no_thermal_equilibrium(c))
    checks = Checks()
    equilibrium_check(checks, c, "the Campbell diagram")
    assert checks.rows[0][3] == NOT_RESOLVED and "2 of 3 speeds failed" in checks.rows[0][2]


def _block(lines, head: str) -> list[str]:
    """The lines of the text report's block starting with ``head`` (to the next blank line)."""
    i = next(k for k, x in enumerate(lines) if x.startswith(head))
    j = next((k for k in range(i + 1, len(lines)) if not lines[k].strip()), len(lines))
    return lines[i:j]


def _text_cells(line: str) -> list[str]:
    import re

    return re.split(r"\s{2,}", line.strip())


def test_text_report_has_the_thermal_unbalance_response_and_stability(html_reports, tmp_path,
                                                                      monkeypatch):
    """report.txt carries sections 4, 4b, 5 and 5a of the HTML report (it had the critical
    speeds on thermal films but no thermal unbalance response or stability lines): per output
    station the resonance peaks with their separation margins and the amplitude checks, and
    the least damped mode at 11 speeds, each block labelled with its films.

    * The HTML report's text (write_html's text_sink, as ``rotordyn report --html`` writes it):
      the peaks of section 4b and the table of section 5a as the HTML shows them, cell by cell.
    * ``rotordyn report --out DIR`` without --html, same model, speeds and operating range:
      report.txt from the isothermal unbalance response to its end (the checks and the overall
      verdict included) equals the HTML report's text line by line, and the thermal Campbell
      diagram and unbalance response are computed once each (section 3c's, reused).
    * Without an oil system the blocks carry no films label and one δ column."""
    s, page, sink, d = html_reports["compressor_plain_thermal"]
    head = "unbalance response on thermal films"
    th = _block(sink, head)
    assert "unbalance response on isothermal films" in "\n".join(sink)
    # the peaks of 4b, text against HTML (every station's table)
    sec = page[page.index("<h2>4b."):page.index("<h2>5.")]
    html_rows = []
    k = 0
    while "<table>" in sec[k:]:
        rows = _cells(sec[k:], "<table>")
        html_rows += [r for r in rows[1:]]
        k = sec.index("</table>", k) + 8
    text_rows = [_text_cells(x) for x in th if x.strip() and _text_cells(x)[0][0].isdigit()]
    assert len(html_rows) >= 1 and text_rows == html_rows
    assert any(x.strip().startswith(("PASS", "FAIL")) and "(station 1)" in x for x in th)
    # section 5a's table
    stab = _block(sink, "stability on isothermal and thermal films")
    i = next(k for k, x in enumerate(stab) if x.strip().startswith("speed (Hz)"))
    table5a = [_text_cells(x) for x in stab[i:i + 1 + HTML_SPEEDS.size]]
    assert table5a == _cells(page, "<h2>5a.")
    assert any("[thermal films]" in x and "stability screening" in x for x in stab)
    # the text report without --html: the same lines, the thermal results computed once
    calls = {"campbell": 0, "unbalance_response": 0}
    for name in calls:
        real = getattr(rotordyn.analysis, name)

        def count(*a, _real=real, _name=name, **kw):
            calls[_name] += kw.get("thermal") is True
            return _real(*a, **kw)
        monkeypatch.setattr(rotordyn.analysis, name, count)
    out = tmp_path / "out"
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        assert main(["report", str(d / "m.toml"), "--out", str(out), "--speeds-hz",
                     "100:200:10", "--operating-speed-hz", "120", "160"]) == 0, err.getvalue()
    assert calls == {"campbell": 1, "unbalance_response": 1}
    text = (out / "report.txt").read_text(encoding="utf-8").splitlines()
    start = "unbalance response on isothermal films"
    a = text[next(k for k, x in enumerate(text) if x.startswith(start)):]
    b = sink[next(k for k, x in enumerate(sink) if x.startswith(start)):]
    assert a == b and a[-1].startswith("  not evaluated (no stage data) API 617 Level I")
    assert any(x.startswith("checks: overall FAIL") for x in a)
    assert any("separation margin" in x and "[thermal films]" in x for x in a)
    # no oil system: no films label, one δ column
    cold = html_reports["compressor_plain"][2]
    assert "thermal films" not in "\n".join(cold) and "isothermal" not in "\n".join(cold)
    assert _block(cold, "unbalance response: API 684")
    stab = _block(cold, "stability: the least damped")
    assert _text_cells(stab[1]) == ["speed (Hz)", "mode (Hz)", "δ"]


def test_text_report_marks_speeds_without_a_thermal_equilibrium(tmp_path):
    """A speed whose thermal equilibrium fails (the oil law's range ends at 80 °C; the NDE film
    exceeds it at 200 Hz, T_max 82.2 °C, and stays below it at 100, 150 and 160 Hz, 76.1 and
    77.4 °C; before the DE bearing's metered supply was raised to a fed 3e-4 m³/s, 2026-12-06:
    85 °C and the DE film at 94.5 °C) is listed and
    written "no thermal equilibrium" in the text report's thermal blocks, never a number: the
    unbalance response and the stability screen on thermal films, the per-film temperature
    table (status "error", n/a: it stopped the whole report with exit 1 before) and the
    checks ("not resolved")."""
    s = _coarse("compressor_plain_thermal")
    oil = dataclasses.replace(s.thermal.oil, t_max_c=80.0)
    s = dataclasses.replace(s, thermal=dataclasses.replace(s.thermal, oil=oil))
    s.to_toml(tmp_path / "m.toml")
    out = tmp_path / "out"
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        assert main(["report", str(tmp_path / "m.toml"), "--out", str(out), "--speeds-hz",
                     "100,125,200", "--operating-speed-hz", "100", "160"]) == 0, err.getvalue()
    lines = (out / "report.txt").read_text(encoding="utf-8").splitlines()
    th = _block(lines, "unbalance response on thermal films")
    assert "  no thermal equilibrium at 1 of 3 speeds (not linearised: no response, no " \
        "eigenvalues there): 200 Hz" in th
    stab = _block(lines, "stability on isothermal and thermal films")
    row = next(_text_cells(x) for x in stab if x.strip().startswith("200 "))
    assert row[3:] == ["no thermal equilibrium"] * 2 and float(row[2]) < 0  # isothermal: δ
    assert any(x.strip().startswith("not resolved thermal equilibrium at every speed of the "
                                    "Campbell diagram [thermal films]: 1 of 3 speeds failed: "
                                    "200 Hz") for x in stab)
    temps = _block(lines, "bearing temperatures and power loss")
    failed = [r for r in map(_text_cells, temps) if r[:2] in (["NDE bearing", "200"],
                                                              ["DE bearing", "200"])]
    assert len(failed) == 2 and all(r[2:10] == ["n/a"] * 8 and r[10] == "error" for r in failed)
    fr = pd.read_csv(out / "bearing_thermal.csv")
    bad = fr[fr["speed_hz"] == 200.0]
    assert (bad["status"] == "error").all() and bad["max_temperature_c"].isna().all()
    assert "t_max_c" in bad["message"].iloc[0]
    assert fr[fr["speed_hz"] < 200.0]["status"].eq("ok").all()
