"""Guards issue 18's defects of the engineer-facing layer on models other than the paper rig
(tests/data/models: a 1.2 m, 213 kg three-impeller compressor rotor on two plain journal
bearings, on two 5-pad tilting-pad bearings, on two speed-dependent coefficient tables and on
two linear supports):

* ``rotordyn report MODEL --html`` completes on each (it crashed with KeyError
  'critical_speed_hz' whenever a response had no peak in a hard-coded 5–120 Hz, and on a table
  bearing in the rotor drawing);
* API verdicts: no AF below 1 or infinite printed as a number, no margin required below AF 2.5
  (API 684 §2.8.2: critically damped), an AF that cannot be resolved is "not resolved", never
  PASS; the API 617 amplitude limit 25.4 √(12000/N) µm is capped at 25.4 µm;
* ``peaks()`` of a response without a peak is an empty frame with its columns;
* a response computed above the threshold of instability is flagged (``stable``);
* the rotor drawing of a model with table and tilting-pad bearings.
"""

from __future__ import annotations

import contextlib
import html
import io
import re
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn._common.api import af_text, amplification_factor, api_required_margin
from rotordyn.cli import main
from rotordyn.report.criteria import amplitude_limit_um, speed_range
from rotordyn.results.unbalance import PEAK_COLUMNS, UnbalanceResult

MODELS = Path(__file__).parent / "data" / "models"
NAMES = ["compressor_plain", "compressor_tilting_pad", "compressor_table", "compressor_linear"]


def _checks(page: str) -> list[list[str]]:
    """Rows (check, criterion, value, result) of the report's checks table."""
    i = page.index("<table>")
    j = page.index("</table>", i)
    rows = re.findall(r"<tr>(.*?)</tr>", page[i:j])[1:]
    return [[html.unescape(re.sub("<.*?>", "", c)) for c in re.findall(r"<td>(.*?)</td>", r)]
            for r in rows]


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    out = {}
    for name in NAMES:
        d = tmp_path_factory.mktemp(name)
        page = d / "r.html"
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            code = main(["report", str(MODELS / f"{name}.toml"), "--out", str(d), "--html",
                         str(page), "--operating-speed-hz", "140", "170"])
        out[name] = (code, page.read_text(encoding="utf-8"), d, err.getvalue())
    return out


@pytest.mark.parametrize("name", NAMES)
def test_report_completes_on_any_model(reports, name):
    code, page = reports[name][:2]
    assert code == 0
    assert re.search(r"Overall: <span class=\"\w+\">(PASS|FAIL|NOT RESOLVED)</span>", page)
    assert page.count("<svg") >= 5  # drawing, map, Campbell, Bode per station, log dec
    assert "analysed speeds" in page and "125 %" in page  # API 684 range from the operating one
    # no [[stage]] data in these models: API 617 Level I is said not evaluated, not invented
    assert "API 617 Level I" in page and "not evaluated (no stage data)" in page
    # the text report's section names the paper only on the paper's rig
    assert "<h2>7. Text report</h2>" in page and "reference paper" not in page


@pytest.mark.parametrize("name", NAMES)
def test_report_verdicts_follow_the_criteria(reports, name):
    rows = _checks(reports[name][1])
    assert rows
    for check, _, value, result in rows:
        assert result in ("PASS", "FAIL", "not resolved", "n/a",
                          "not evaluated (no stage data)"), (check, result)
        assert "∞" not in value and "inf" not in value.lower()
        for af in re.findall(r"AF [=≤] ([0-9.e+-]+)", value):
            assert float(af) >= 1.0  # below 1 it is written "AF < 1 (no resonance)"
            if float(af) < 2.5:
                assert "required none" in value and result == "PASS"
        if "not resolved" in value.lower() or "AF not resolved" in value:
            assert result == "not resolved"


def test_plain_bearing_whip_is_flagged(reports):
    """The compressor on plain bearings whips near 127 Hz (whirl ratio ~0.5): the report says the
    system is unstable there instead of reporting an unbalance response as a steady orbit."""
    rows = {r[0]: r for r in _checks(reports["compressor_plain"][1])}
    assert rows["linear stability over the speed range"][3] == "FAIL"
    assert rows["stability screening in the operating range"][3] == "FAIL"


def test_report_without_operating_speed_uses_the_criticals(tmp_path):
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    r = speed_range(s)
    assert r.speeds_hz[-1] == pytest.approx(1.25 * r.n_mc_hz)
    assert "second undamped critical" in r.why
    page = tmp_path / "r.html"
    assert main(["report", str(MODELS / "compressor_table.toml"), "--out", str(tmp_path),
                 "--html", str(page), "--speeds-hz", "20:240:20"]) == 0
    assert "as given (--speeds-hz)" in page.read_text(encoding="utf-8")


def test_unbalance_without_a_peak_has_a_columned_frame_and_plots(tmp_path):
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    u = rd.unbalance_response(s, [(3, 1e-4, 0.0)], np.linspace(10, 40, 7), stations=[3])
    pk = u.peaks(3)
    assert pk.empty and tuple(pk.columns) == PEAK_COLUMNS
    a1, _ = u.plot(station=3)
    a1.figure.savefig(tmp_path / "b.png")
    assert main(["unbalance", str(MODELS / "compressor_tilting_pad.toml"), "--unbalance",
                 "3,1e-4,0", "--speeds-hz", "10:40:5", "--plot", str(tmp_path / "u.png")]) == 0


def test_response_above_the_threshold_is_flagged():
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    u = rd.unbalance_response(s, [(3, 1e-4, 0.0)], [60.0, 100.0, 150.0, 160.0], stations=[3],
                              refine=False)
    assert list(u.stable) == [True, True, False, False]
    assert "above the threshold of instability" in repr(u)
    assert not u.to_frame()["point_stable"].iloc[-1]
    lin = rd.unbalance_response(rd.System.from_toml(MODELS / "compressor_linear.toml"),
                                [(3, 1e-4, 0.0)], [60.0, 100.0], stations=[3], refine=False)
    assert lin.max_real_1_per_s is None and lin.stable.all()  # supports only: not checked


def test_af_of_a_broad_hump_is_bounded_not_infinite():
    """A heavily damped response whose half-power speed lies beyond the computed range: the
    band is at least what is in range, so AF is at most Nc/(N2 − s_lo); below 2.5 it is
    critically damped (no margin), above it cannot be judged (not resolved, NaN)."""
    sp = np.linspace(10.0, 100.0, 91)
    nc = 40.0
    a = 1.0 / np.sqrt((1 - (sp / nc) ** 2) ** 2 + (2 * 0.6 * sp / nc) ** 2)  # ζ = 0.6
    u = UnbalanceResult(sp, (0,), a[:, None] + 0j, 1j * a[:, None], np.array(["ok"] * sp.size),
                        ((0, 1e-4, 0.0),), (45.0, 55.0))
    pk = u.peaks(0)
    assert len(pk) == 1
    r = pk.iloc[0]
    assert r["af_kind"] == "upper_bound" and r["amplification_factor"] < 2.5
    assert r["critically_damped"] and r["required_margin_pct"] == 0.0
    assert amplification_factor(40.0, np.nan, 45.0, 39.0, 100.0) == (pytest.approx(np.nan,
                                                                                   nan_ok=True),
                                                                     "unresolved")
    assert np.isnan(api_required_margin(np.nan, True))
    assert api_required_margin(2.4, True) == 0.0
    assert api_required_margin(10.0, False) == pytest.approx(10 + 17 * (1 - 1 / 8.5))
    assert af_text(0.77, "half_power") == "AF < 1 (no resonance)"
    assert af_text(np.nan, "unresolved") == "AF not resolved"


def test_amplitude_limit_is_capped():
    """API 617: 25.4 √(12000/N) µm, not more than 25.4 µm."""
    assert amplitude_limit_um(3000.0) == 25.4
    assert amplitude_limit_um(48000.0) == pytest.approx(12.7)


def test_rotor_drawing_with_table_and_pad_bearings(tmp_path):
    for name in ("compressor_table", "compressor_tilting_pad"):
        assert main(["validate", str(MODELS / f"{name}.toml"), "--plot",
                     str(tmp_path / f"{name}.png")]) == 0


@pytest.mark.parametrize("model,ub,stations,speeds", [
    ("rig", (6, 1e-4, 0.0), ([4], [4, 6]), np.arange(5, 121, 1.0)),
    ("compressor_linear", (3, 1e-4, 0.0), ([1], [1, 3, 5]), np.linspace(20, 250, 47)),
])
def test_peaks_of_a_station_do_not_depend_on_the_others(model, ub, stations, speeds):
    """The refinement brackets every peak and half-power speed to 0.2 % of N_c, so the peaks of
    station 4 are the same whether station 6 is asked for too (88.59 vs 88.70 Hz, AF 8.03 vs
    7.75 before)."""
    s = rd.models.paper_rig() if model == "rig" else rd.System.from_toml(MODELS / f"{model}.toml")
    kw = dict(chamber_pressure_pa=0.4e6, config_ay_m=0.0) if model == "rig" else {}
    a, b = (rd.unbalance_response(s, [ub], speeds, stations=st, **kw).peaks(st[0])
            for st in stations)
    assert len(a) == len(b) and len(a) > 0
    np.testing.assert_allclose(a["critical_speed_hz"], b["critical_speed_hz"], rtol=2e-3)
    np.testing.assert_allclose(a["amplification_factor"], b["amplification_factor"], rtol=2e-2)


def test_report_draws_the_mode_shape_at_each_critical_speed(reports):
    """Issue 18: the mode shape at each critical speed, in the HTML report and as a PNG in the
    CLI's output directory. The compressor on linear supports has a forward critical speed in
    its range; its response peak (168.7 Hz, AF 2.4) has the crossing inside its half-power
    band, so the two are one critical, listed once with both sources."""
    import pandas as pd

    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    code, page, d = reports["compressor_linear"][:3]
    crit = rd.rotor_campbell(s, speed_range(s, (140.0, 170.0)).speeds_hz,
                             n_modes=12).critical_speeds()
    t = pd.read_csv(Path(d) / "critical_speeds.csv")
    assert len(crit) >= 1 and len(t) == len(crit)
    np.testing.assert_allclose(t["campbell_hz"], crit["speed_hz"], rtol=1e-12)
    n = min(len(t), 6)
    assert "3b. Mode shapes at the critical speeds" in page
    assert page.count("<figcaption>Critical speed ") == n
    pngs = sorted(Path(d).glob("critical_mode_*.png"))
    assert len(pngs) == n and all(p.stat().st_size > 20000 for p in pngs)
    from PIL import Image

    for p in Path(d).glob("*.png"):  # every figure of the output directory at 200 dpi
        with Image.open(p) as im:
            assert round(im.info["dpi"][0]) == 200, p.name
    nc = float(crit["speed_hz"].iloc[0])
    assert f"Critical speed 1: {nc:.4g} Hz" in page
    assert t["source"].iloc[0] == ("damped Campbell crossing (1×, forward) + unbalance "
                                   "response peak")


def test_heavily_damped_compressors_get_mode_shapes(reports):
    """Issue 18: on plain and tilting-pad bearings no mode crosses 1× (heavily damped), so the
    report drew no mode shape. Plain bearings: the response peaks (above the whip threshold,
    flagged so) are the critical speeds, each with the damped mode nearest its frequency
    drawn; tilting pads: no 1× crossing, a heavily damped response peak (below). A model
    without any critical speed draws the least damped forward mode with a resonance at N_mc
    (tests/test_report_overdamped.py)."""
    import pandas as pd

    code, page, d = reports["compressor_plain"][:3]
    t = pd.read_csv(Path(d) / "critical_speeds.csv")
    assert len(t) >= 1 and t["campbell_hz"].isna().all()
    assert t["source"].str.startswith("unbalance response peak").all()
    assert t["source"].str.contains("linearly unstable").all()
    assert page.count("<figcaption>Critical speed ") == min(len(t), 6)
    assert "the damped forward mode nearest the unbalance response peak" in page
    # tilting pads: no 1× crossing. Before 2026-12-05 the API unbalance went to the station of
    # an overdamped rigid-body root (29.8 Hz, damping ratio 0.9994: no resonance), excited
    # nothing, and the page said "no critical speed". It now goes to the first forward mode
    # with a resonance (100 Hz, ζ 0.21 at 170 Hz: the middle impeller, station 3), whose
    # response has a peak: heavily damped (AF < 2.5, API 684: no separation margin needed)
    code, page, d = reports["compressor_tilting_pad"][:3]
    t = pd.read_csv(Path(d) / "critical_speeds.csv")
    assert len(t) == 1 and t["campbell_hz"].isna().all()
    assert t["source"].str.startswith("unbalance response peak").all()
    assert (t["amplification_factor"] < 2.5).all() and str(t["stations"].iloc[0]) == "3"
    assert page.count("<figcaption>Critical speed 1") == 1
    assert (Path(d) / "critical_mode_1.png").stat().st_size > 20000


def test_text_report_writes_critical_speeds_mode_shapes_and_coefficients(tmp_path):
    """Issue 18: without --html the output directory had neither the mode shapes nor the
    bearing coefficients; now report.txt lists the critical speeds with their sources, each
    mode shape's file, and the coefficient table, and the files are there."""
    import pandas as pd

    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        assert main(["report", str(MODELS / "compressor_table.toml"), "--out", str(tmp_path),
                     "--operating-speed-hz", "140", "170"]) == 0
    text = (tmp_path / "report.txt").read_text(encoding="utf-8")
    t = pd.read_csv(tmp_path / "critical_speeds.csv")
    assert len(t) >= 2 and set(t["source"]) >= {"damped Campbell crossing (1×, forward)"}
    assert "critical speeds over" in text and "source" in text
    n = min(len(t), 6)
    assert len(list(tmp_path.glob("critical_mode_*.png"))) == n
    assert text.count(".png: mode shape at critical speed") == n
    df = pd.read_csv(tmp_path / "bearing_coefficients.csv")
    assert set(df["bearing"]) == {"NDE bearing", "DE bearing"}
    assert "kxx (MN/m)" in text and (tmp_path / "bearing_coefficients.png").exists()


@pytest.mark.parametrize("name", ["compressor_plain", "compressor_tilting_pad",
                                  "compressor_table"])
def test_report_tabulates_bearing_coefficients_over_speed(reports, name):
    """Each fluid-film (or table) bearing's kxx … cyy over the report's speeds: a table with
    units in the page, a figure, and a CSV with unit-suffixed columns in the output directory;
    none for a rotor on linear supports."""
    import pandas as pd

    code, page, d = reports[name][:3]
    assert "2b. Bearing coefficients over speed" in page
    assert "kxx (MN/m)" in page and "cyy (kN·s/m)" in page
    df = pd.read_csv(Path(d) / "bearing_coefficients.csv")
    assert set(df["bearing"]) == {"NDE bearing", "DE bearing"}
    for c in df.columns:
        if c[0] in "kc" and c[1:3] in ("xx", "xy", "yx", "yy"):
            assert c.endswith("_n_per_m") or c.endswith("_n_s_per_m")
    ok = df[df["status"] == "ok"]
    assert len(ok) > 10 and (ok["kxx_n_per_m"] > 0).all() and (ok["cyy_n_s_per_m"] > 0).all()
    assert (Path(d) / "bearing_coefficients.png").stat().st_size > 20000
    assert "Bearing coefficients" not in reports["compressor_linear"][1]


def test_bearing_coefficients_in_the_system_equal_the_standalone_bearing():
    """The system's tilting-pad coefficients at a speed (pads condensed at synchronous whirl)
    equal the standalone bearing's coefficient table under the static load the system puts on
    it (its reaction): the same equilibrium and the same condensation, to round-off; a table
    bearing gives its table's interpolated coefficients."""
    from rotordyn.analysis.bearing_coefficients import bearing_coefficients

    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    df = bearing_coefficients(s, [150.0, 90.0])
    assert list(df["speed_hz"][:2]) == [90.0, 150.0] and list(df["bearing"][:2]) == [
        "NDE bearing"] * 2
    fy = rd.static(s, 150.0).reactions["force_y_n"].iloc[0]
    ref = s.bearings[0].coefficient_table([150.0], (0.0, -fy)).to_frame().iloc[0]
    row = df[(df["bearing"] == "NDE bearing") & (df["speed_hz"] == 150.0)].iloc[0]
    for c in ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "cxx_n_s_per_m",
              "cxy_n_s_per_m", "cyx_n_s_per_m", "cyy_n_s_per_m"):
        assert row[c] == pytest.approx(ref[c], rel=1e-6, abs=1e-6 * abs(ref["kxx_n_per_m"])
                                       if c[0] == "k" else 1e-6 * abs(ref["cxx_n_s_per_m"]))
    t = rd.System.from_toml(MODELS / "compressor_table.toml")
    K, C = t.bearings[0].coefficients(100.0)
    r = bearing_coefficients(t, [100.0]).iloc[0]
    np.testing.assert_allclose([r["kxx_n_per_m"], r["kxy_n_per_m"], r["kyx_n_per_m"],
                                r["kyy_n_per_m"]], K.ravel(), rtol=1e-12)
    np.testing.assert_allclose([r["cxx_n_s_per_m"], r["cyy_n_s_per_m"]], C.ravel()[[0, 3]],
                               rtol=1e-12)
    with pytest.raises(rd.InputError, match="speeds_hz"):
        bearing_coefficients(t, [-1.0])


@pytest.mark.parametrize("name", ["compressor_table", "compressor_linear"])
def test_report_progress_line_says_which_step_and_how_far(reports, name):
    """A progress line on stderr for the report: each step as [k/n] with the time so far, the
    count never above n, and a closing line. Item lines (``[k/n] text: i/m``, printed when a
    step runs longer than ITEM_INTERVAL_S, e.g. on a loaded machine) repeat the current k."""
    err = reports[name][3]
    lines = re.findall(r"rotordyn report: \[(\d+)/(\d+)\] (.+) \((\d+) s\)", err)
    items = [ln for ln in lines if re.search(r": \d+/\d+$", ln[2])]
    steps = [ln for ln in lines if ln not in items]
    step_of = {s: int(k) for k, _, s, _ in steps}
    for k, _, text, _ in items:
        assert step_of[text.rsplit(": ", 1)[0]] == int(k)
    assert len(steps) >= 6
    assert [int(k) for k, _, _, _ in steps] == list(range(1, len(steps) + 1))
    assert all(int(k) <= int(n) for k, n, _, _ in steps)
    assert any("Campbell diagram, 121 speeds" in s for _, _, s, _ in steps)
    assert any("mode shapes at the critical speeds" in s for _, _, s, _ in steps)
    assert re.search(r"rotordyn report: done, \d+ steps", err)


def test_long_cli_work_says_it_is_running(monkeypatch, capsys):
    """Other commands: a line once the work has run longer than the delay (here 0 s), and its
    time at the end; nothing for short work under the default delay."""
    from rotordyn._common import progress

    args = ["campbell", str(MODELS / "compressor_plain.toml"), "--speeds-hz", "20:200:20"]
    assert main(args) == 0
    assert "running" not in capsys.readouterr().err  # under a second: silent
    monkeypatch.setattr(progress, "DELAY_S", 0.0)
    assert main(args) == 0
    err = capsys.readouterr().err
    assert "rotordyn campbell over speeds 20:200:20 Hz: running" in err
    assert re.search(r"rotordyn campbell over speeds 20:200:20 Hz: done after [0-9.]+ s", err)
    assert main(args[:2] + ["--speeds-hz", "-5:10:5"]) == 2  # bad input: no "done" claimed
    assert "done after" not in capsys.readouterr().err


def test_report_figures_of_the_docs_are_shown_in_a_doc():
    """Every figure docs/figures/regenerate.sh draws from a compressor model's report or sweep
    is shown (as an image) on a docs page: compressor_critical_mode_1.png was generated and
    shown nowhere (issue 18)."""
    root = Path(__file__).resolve().parents[1]
    names = re.findall(r"\$FIG/(compressor_\w+\.png)",
                       (root / "docs" / "figures" / "regenerate.sh").read_text())
    pages = " ".join(p.read_text(encoding="utf-8") for p in (root / "docs").glob("*.md"))
    assert "compressor_critical_mode_1.png" in names
    for n in names:
        assert f"](figures/{n})" in pages, n
        assert (root / "docs" / "figures" / n).stat().st_size > 20000


@pytest.mark.parametrize("name", NAMES)
def test_text_report_has_the_checks_of_the_html(reports, name):
    """report.txt (the main job's text) carries the checks table and overall verdict of the
    HTML report: it had only the critical speeds and coefficients, no verdict at all."""
    page, d = reports[name][1], reports[name][2]
    text = (d / "report.txt").read_text(encoding="utf-8")
    overall = re.search(r"Overall: <span class=\"\w+\">([A-Z ]+)</span>", page).group(1)
    assert f"checks: overall {overall} " in text
    for check, _, value, result in _checks(page):
        line = next((ln for ln in text.splitlines() if f" {check}" in ln and value in ln), None)
        assert line is not None, (check, value)
        assert line.split()[0] == result.split()[0], (line, result)


def test_report_of_an_active_bearing_machine_uses_its_own_bearing_and_configuration(tmp_path):
    """The text report's active-bearing sections on a machine that is not the paper's rig
    (the compressor with a plain NDE bearing [0] and an active DE bearing [1]): they printed
    bearing 0's journal (the plain bearing) as the active bearing's, at the rig's a_y =
    −1.85 mm (18 clearances of this 0.1 mm bearing) and 50 Hz, with "paper" columns of NaN,
    and "p_c = nan MPa (stable ; …)" where no threshold lies in the bounds; the critical speeds
    only over the rig's 5–120 Hz ("critical speeds at p_c = 0.4 MPa: " and nothing, the DE
    mode being at 209 Hz). Now: the active bearing at the model's own configuration and the
    report's speed, the no-crossing said as such, the critical speeds over the report's
    range (API 684: to 125 % of the operating range's top)."""
    model = MODELS / "compressor_active.toml"
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        code = main(["report", str(model), "--out", str(tmp_path), "--operating-speed-hz",
                     "40", "60", "--html", str(tmp_path / "r.html")])
    assert code == 0, err.getvalue()
    text = out.getvalue()
    page = (tmp_path / "r.html").read_text(encoding="utf-8")
    row = next(r for r in _checks(page) if r[0].startswith("threshold of instability"))
    assert row[0] == "threshold of instability at a_y = 0 mm, 50 Hz", row  # not the rig's
    assert "nan" not in row[2], row
    s = rd.System.from_toml(model)
    ia = next(i for i, b in enumerate(s.bearings) if isinstance(b, rd.ActiveJournalBearing))
    assert ia == 1
    assert "equilibrium of the active bearing 'DE active bearing' at its configuration " \
           "a_y = 0 mm, 50 Hz" in text
    lines = text.splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.startswith("equilibrium of the active"))
    for ln, pc in zip(lines[i + 2:i + 7], (0.0, 0.1e6, 0.2e6, 0.3e6, 0.4e6)):
        e = rd.equilibrium(s, 50.0, pc)
        cells = ln.split()
        assert float(cells[0]) == pytest.approx(pc / 1e6)
        assert float(cells[1]) == pytest.approx(e.x_over_c[ia], abs=1e-4)
        assert float(cells[2]) == pytest.approx(e.y_over_c[ia], abs=1e-4)
        assert cells[-1] == "ok"
    assert not re.search(r"\bpaper\b|\bnan\b", text), re.search(r".*(\bpaper\b|\bnan\b).*",
                                                                  text).group(0)
    t = next(ln for ln in lines if ln.startswith("threshold of instability"))
    assert "at its configuration a_y = 0 mm, 50 Hz" in t
    assert re.search(r"p_c = \d\.\d{4} MPa \(stable (above|below);", t) or \
        re.search(r"none in 0–0\.4 MPa \(no_crossing: .*(stable|unstable) at all", t), t
    c = next(ln for ln in lines if ln.startswith("critical speeds at p_c = 0.4 MPa"))
    assert "(1.5–75 Hz)" in c, c  # 2 %…125 % of the top operating speed, 60 Hz
