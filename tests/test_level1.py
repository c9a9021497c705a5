"""API 617 Level I stability analysis (issue 18): the anticipated cross-coupling Q_A of the
stages, the log decrement of the first forward mode against an applied cross-coupled stiffness
Q, Q_0 by root finding, δ_A and the criteria.

References:
* Closed form: a rigid symmetric rotor of mass M on two isotropic supports (k, c each) with Q at
  mid-span moves in its cylindrical mode as a Jeffcott rotor, M z̈ + 2c ż + (2k − iQ) z = 0
  (z = x + iy); the forward root reaches Re λ = 0 at Q_0 = 2c·ω_n, ω_n = √(2k/M), and δ(Q) =
  −2π Re λ/Im λ of that root (e.g. Childs, *Turbomachinery Rotordynamics*, 1993, §3; API 684
  2nd ed. §2.9.2). The FE shaft is made 100× stiffer than steel so its bending changes ω_n by
  ~1e-4; the error falls as 1/E (first order in the shaft's flexibility), checked on two levels.
* API 617 8th ed. §4.8.5 / API 684 2nd ed. §2.9: q_A = B_c C P (ρ_d/ρ_s)/(D_c H_c N), B_c = 3,
  C = 9.55, and the US form (C = 63, hp, in, klbf/in) gives the same q_A.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
K, C = 1.0e6, 500.0  # per support, N/m and N·s/m


def _rigid_rotor(young_pa: float = 2.1e13) -> rd.System:
    mat = rd.Material(name="stiff", density_kg_m3=7850.0, young_pa=young_pa, poisson=0.3)
    sec = rd.ShaftSection(length_m=0.25, outer_diameter_m=0.1, material="stiff", n_elements=2)
    rot = rd.Rotor((sec, sec), (rd.Disk(station=1, mass_kg=20.0, ip_kg_m2=0.1, id_kg_m2=0.05),))
    sup = tuple(rd.Support(st, "linear", kxx_n_per_m=K, kyy_n_per_m=K, cxx_n_s_per_m=C,
                           cyy_n_s_per_m=C) for st in (0, 2))
    return rd.System(rot, materials=(mat,), supports=sup, reduction=rd.Reduction(method="none"))


def _jeffcott_log_dec(m: float, q: float) -> float:
    roots = np.roots([m, 2 * C, 2 * K - 1j * q])
    lam = roots[np.argmax(roots.imag)]  # the forward root
    return float(-2 * np.pi * lam.real / lam.imag)


def test_q0_and_curve_against_the_jeffcott_closed_form():
    s = _rigid_rotor()
    m = s.mass_kg
    q0_exact = 2 * C * np.sqrt(2 * K / m)
    r = rd.level1(s, 50.0)
    assert r.status == "ok" and r.placement[0][0] == "station 1"
    assert r.q0_n_per_m == pytest.approx(q0_exact, rel=3e-4)
    df = r.to_frame()
    ref = np.array([_jeffcott_log_dec(m, q) for q in df["applied_q_n_per_m"]])
    np.testing.assert_allclose(df["log_dec"], ref, rtol=0, atol=2e-4)
    assert abs(df.loc[df["is_q0"], "log_dec"].item()) < 1e-8  # a root, not a grid point
    # the model error is the shaft's flexibility: ten times stiffer, ten times smaller
    e1 = abs(rd.level1(_rigid_rotor(2.1e12), 50.0).q0_n_per_m / q0_exact - 1)
    e2 = abs(r.q0_n_per_m / q0_exact - 1)
    assert np.log10(e1 / e2) == pytest.approx(1.0, abs=0.3)
    # no stage data: computed, not judged
    assert r.verdict() == "not evaluated (no stage data)" and np.isnan(r.q_a_n_per_m)


def test_stage_cross_coupling_formula_si_and_us_forms():
    st = rd.Stage(station=3, power_w=2.0e6, diameter_m=0.4, height_m=0.02, density_ratio=1.4)
    n_rpm = 9000.0
    q = st.cross_coupling_n_per_m(n_rpm / 60)
    assert q == pytest.approx(3 * 9.55 * 2.0e6 * 1.4 / (0.4 * 0.02 * n_rpm))
    hp, d_in, h_in = 2.0e6 / 745.69987, 0.4 / 0.0254, 0.02 / 0.0254
    q_us_klbf_in = 3 * 63.0 * hp * 1.4 / (d_in * h_in * n_rpm)
    assert q == pytest.approx(q_us_klbf_in * 4448.2216 / 0.0254, rel=2e-3)  # C rounded
    ax = rd.Stage(station=3, power_w=2.0e6, diameter_m=0.4, height_m=0.02, type="axial")
    assert ax.cross_coupling_n_per_m(150.0) == pytest.approx(
        1.5 * 9.55 * 2.0e6 / (0.4 * 0.02 * 9000.0))


def _stages(power_w=1.5e6):
    return [dict(station=k, power_w=power_w, diameter_m=0.4, height_m=0.02, density_ratio=1.3)
            for k in (2, 3, 4)]


@pytest.mark.parametrize("name", ["compressor_linear", "compressor_tilting_pad"])
def test_level1_on_the_compressors(name):
    """Between-bearing: Q at mid-span (station 3); the first forward mode is the first bending
    mode (the heavily damped rigid modes on tilting pads, δ ≈ 300, have no resonance and are
    not judged); the criteria from Q_0/Q_A and δ_A."""
    s = rd.System.from_toml(MODELS / f"{name}.toml")
    r = rd.level1(s, 150.0, stages=_stages())
    assert r.placement == (("station 3", 9, 1.0, pytest.approx(0.6)),)  # node 2+4+3
    assert r.q_a_n_per_m == pytest.approx(3 * 3 * 9.55 * 1.5e6 * 1.3 / (0.4 * 0.02 * 9000))
    assert 0.5 < r.log_dec_0 < 2 and 80 < r.freq_0_hz < 170
    assert np.isfinite(r.q0_n_per_m) and r.q0_n_per_m > 0
    d = r.to_frame()
    assert abs(d.loc[d["is_q0"], "log_dec"].item()) < 1e-6
    assert d.loc[d["is_q_a"], "log_dec"].item() == pytest.approx(r.log_dec_a)
    names = [c[0] for c in r.checks()]
    assert any("Q_0/Q_A" in x for x in names) and any("δ_A" in x for x in names)
    # both compressors: Q_0/Q_A ≈ 21 (linear) and 17 (tilting pads), δ_A > 1: Level I passed
    assert r.ratio >= 10 and r.log_dec_a >= 0.1
    assert r.level2_required is False and r.verdict() == "PASS"
    # twenty times the power: Q_A twenty times, the ratio drops below 2: Level II required
    big = rd.level1(s, 150.0, stages=_stages(3e7), csr_limit=2.5)
    assert big.q_a_n_per_m == pytest.approx(20 * r.q_a_n_per_m)
    assert big.q0_n_per_m == pytest.approx(r.q0_n_per_m, rel=1e-6)  # Q_0 does not depend on Q_A
    assert big.ratio < 2 and big.level2_required is True
    assert "FAIL" in big.verdict() and "FAIL" in repr(big)
    ax = r.plot()
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(x.startswith("Q_A") for x in labels) and any(x.startswith("Q_0") for x in labels)
    assert "(MN/m)" in ax.get_xlabel()


def test_screening_needs_the_region_b_boundary():
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    r = rd.level1(s, 150.0, stages=_stages(1.5e7 / 4))  # ratio between 2 and 10
    assert 2 <= r.ratio < 10
    assert r.csr == pytest.approx(150.0 / r.first_critical_hz) and r.csr > 0
    assert r.checks()[-1][3] == "not resolved" and r.level2_required is None
    low = rd.level1(s, 150.0, stages=_stages(1.5e7 / 4), csr_limit=r.csr * 1.1,
                    gas_density_kg_m3=40.0)
    assert low.checks()[-1][3] is True and low.level2_required is False
    high = rd.level1(s, 150.0, stages=_stages(1.5e7 / 4), csr_limit=r.csr * 0.9)
    assert high.checks()[-1][3] is False and high.level2_required is True


def test_plain_bearings_unstable_at_q_zero():
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    r = rd.level1(s, 150.0, stages=_stages())  # above the oil-whip onset
    assert r.q0_n_per_m == 0.0 and r.log_dec_0 < 0 and r.level2_required is True
    assert "no positive damping" in r.message


def test_overhung_stage_centroid_and_each_stage():
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    over = [dict(station=0, power_w=1e6, diameter_m=0.4, height_m=0.02, density_ratio=1.2)]
    r = rd.level1(s, 150.0, stages=over)
    assert r.placement[0][0] == "station 0" and "centroid" in r.placement_why
    both = rd.level1(s, 150.0, stages=over + [dict(over[0], station=6)])  # double overhung
    assert [p[0] for p in both.placement] == ["station 0", "station 6"]
    each = rd.level1(s, 150.0, stages=_stages(), at="stages")
    assert [p[0] for p in each.placement] == ["station 2", "station 3", "station 4"]
    assert sum(p[2] for p in each.placement) == pytest.approx(1.0)


def test_bad_input_names_the_field():
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    bad = [(dict(stages=[dict(_stages()[0], power_w=-1.0)]), "stages\\[0\\].power_w"),
           (dict(stages=[dict(_stages()[0], station=99)]), "stages\\[0\\].station"),
           (dict(stages=[dict(_stages()[0], density_ratio=None)]), "density_ratio"),
           (dict(stages=[dict(_stages()[0], height_m=1.0)]), "height_m"),
           (dict(stages=[dict(_stages()[0], foo=1)]), "stages\\[0\\]"),
           (dict(mode="worst"), "mode"), (dict(at="nowhere"), "at"), (dict(at=42), "at"),
           (dict(csr_limit=-1.0), "csr_limit"), (dict(q_points_n_per_m=[-1.0]), "q_points"),
           (dict(at="centroid"), "at")]
    for kw, field in bad:
        with pytest.raises(rd.InputError, match=field):
            rd.level1(s, 150.0, **kw)
    with pytest.raises(rd.InputError, match="speed_hz"):
        rd.level1(s, -5.0)
    text = s.to_toml() + ("\n[[stage]]\nstation = 9\npower_w = 1e6\ndiameter_m = 0.4\n"
                          "height_m = 0.02\ndensity_ratio = 1.2\n")
    with pytest.raises(rd.InputError, match="stage\\[0\\].station"):
        rd.System.from_toml(text, is_text=True)


def test_stage_data_in_the_model_file_round_trip(tmp_path, capsys):
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    text = s.to_toml() + "".join(
        f"\n[[stage]]\nname = \"impeller {k - 1}\"\nstation = {k}\npower_w = 1.5e6\n"
        "diameter_m = 0.4\nheight_m = 0.02\ndensity_ratio = 1.3\n" for k in (2, 3, 4))
    m = rd.System.from_toml(text, is_text=True)
    assert len(m.stages) == 3 and m.stages[0].name == "impeller 1"
    assert rd.System.from_toml(m.to_toml(), is_text=True) == m
    assert rd.level1(m, 150.0).q_a_n_per_m == pytest.approx(
        rd.level1(s, 150.0, stages=_stages()).q_a_n_per_m)
    path = tmp_path / "c.toml"
    m.to_toml(path)
    assert main(["level1", str(path), "--speed-hz", "150", "--plot",
                 str(tmp_path / "l1.png")]) == 0
    out = capsys.readouterr()
    assert "applied_q_mn_per_m" in out.out and "Q_0/Q_A" in out.err
    assert "-0" not in out.out.split()  # δ at Q_0 (round-off band) printed 0, never "-0"
    assert (tmp_path / "l1.png").stat().st_size > 0
    assert main(["level1", str(MODELS / "compressor_linear.toml"), "--speed-hz", "150"]) == 0
    assert "not evaluated (no stage data)" in capsys.readouterr().err
    assert main(["level1", str(path), "--speed-hz", "150", "--at", "nowhere"]) == 2
    assert main(["level1", str(path), "--speed-hz", "150", "--stage", "2,1e6,0.4"]) == 2
    assert "--stage: expected" in capsys.readouterr().err
    assert main(["level1", str(path), "--speed-hz", "150", "--stage", "2,1e6,0.4,0.02,1.3",
                 "--stage", "4,1e6,0.4,0.02,1.3", "--at", "stages", "--json"]) == 0
    import json

    rec = json.loads(capsys.readouterr().out)
    assert [p[0] for p in rec["placement"]] == ["station 2", "station 4"]
    assert rec["q_a_n_per_m"] == pytest.approx(2 * 3 * 9.55 * 1e6 * 1.3 / (0.4 * 0.02 * 9000))


def test_report_level1_section_echoes_the_inputs(tmp_path):
    """The text and HTML reports of the compressor on linear supports with three stages: the
    Level I section with the stage table (inputs echoed), Q_0, Q_A and PASS/FAIL on the two
    criteria that apply (Q_0/Q_A ≈ 21 ≥ 10: the screening figure does not apply)."""
    import html
    import re

    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    text = s.to_toml() + "".join(
        f"\n[[stage]]\nstation = {k}\npower_w = 1.5e6\ndiameter_m = 0.4\nheight_m = 0.02\n"
        "density_ratio = 1.3\n" for k in (2, 3, 4))
    path = tmp_path / "c.toml"
    path.write_text(text)
    page = tmp_path / "r.html"
    assert main(["report", str(path), "--out", str(tmp_path), "--html", str(page),
                 "--operating-speed-hz", "140", "170"]) == 0
    doc = html.unescape(re.sub("<.*?>", " ", page.read_text(encoding="utf-8")))
    assert "5b. API 617 Level I" in doc and "q_A (MN/m)" in doc and "not evaluated" not in doc
    assert re.search(r"API 617 Level I: Q_0/Q_A\s+Q_0/Q_A ≥ 2\s+Q_0 = [0-9.e+]+ N/m.*?PASS", doc)
    assert re.search(r"API 617 Level I: δ_A\s+δ at Q_A ≥ 0.1\s+δ_A = [0-9.]+.*?PASS", doc)
    assert "API 617 Level I: screening" not in doc  # Q_0/Q_A ≥ 10: the figure does not apply
    assert "Region B boundary CSR" in doc and "not given" in doc
    txt = (tmp_path / "report.txt").read_text()
    assert "API 617 Level I stability analysis" in txt and "verdict: PASS" in txt
    assert (tmp_path / "level1.csv").exists()
    # ten times the power: 2 ≤ Q_0/Q_A < 10, the screening figure decides; with its boundary
    # given on the command line it is judged (here CSR below it: Region A, PASS)
    path.write_text(text.replace("power_w = 1.5e6", "power_w = 4.0e6"))
    assert main(["report", str(path), "--out", str(tmp_path), "--operating-speed-hz", "140",
                 "170", "--gas-density-kg-m3", "40", "--csr-limit", "5"]) == 0
    txt = (tmp_path / "report.txt").read_text()
    assert re.search(r"API 617 Level I: screening: CSR = [0-9.]+, average gas density 40 kg/m³, "
                     r"Region B above CSR 5 \(as given\) .*PASS", txt)


def test_log_dec_at_round_off_is_plus_zero():
    """δ = −2π Re λ/Im λ of an undamped root (Re λ in the round-off band, set to 0) is +0, not
    −0: the Level I table printed δ at Q_0 as "-0" (issue 18)."""
    from rotordyn.cli.common import table_text
    from rotordyn.results.modes import log_dec

    d = log_dec(np.array([1e-13 + 300j, -1e-13 + 300j, 0j]))
    # a neutral real root (λ = 0) is 0 too, as its damping ratio: not +inf ("infinitely
    # damped"), which it was before the 2026-12-05 review
    assert d[0] == 0.0 and not np.signbit(d[0]) and not np.signbit(d[1])
    assert d[2] == 0.0 and not np.signbit(d[2])
    import pandas as pd

    assert table_text(pd.DataFrame({"log_dec": [-0.0, 0.5]})).split()[1] == "0"
