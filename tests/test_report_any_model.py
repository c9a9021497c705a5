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

import html
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
        code = main(["report", str(MODELS / f"{name}.toml"), "--out", str(d), "--html",
                     str(page), "--operating-speed-hz", "140", "170"])
        out[name] = (code, page.read_text(encoding="utf-8"))
    return out


@pytest.mark.parametrize("name", NAMES)
def test_report_completes_on_any_model(reports, name):
    code, page = reports[name]
    assert code == 0
    assert re.search(r"Overall: <span class=\"\w+\">(PASS|FAIL|NOT RESOLVED)</span>", page)
    assert page.count("<svg") >= 5  # drawing, map, Campbell, Bode per station, log dec
    assert "analysed speeds" in page and "125 %" in page  # API 684 range from the operating one
    # no [[stage]] data in these models: API 617 Level I is said not evaluated, not invented
    assert "API 617 Level I" in page and "not evaluated (no stage data)" in page


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
