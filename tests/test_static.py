"""Guards the static analysis (issue 18; ROSS's run_static): deflection, shear force, bending
moment and reactions at the equilibrium.

References: a uniform Euler–Bernoulli beam under its weight w (N/m) (Timoshenko & Young,
*Theory of Structures*; any strength-of-materials text): on two supports R = wL/2,
M(L/2) = wL²/8, y(L/2) = −5wL⁴/(384EI); on three equal-span supports (0, L, 2L) with the
middle one raised by δ: superposing the continuous beam (R_end = 3wL/8, R_mid = 5wL/4,
M_mid = −wL²/8) and the simply supported 2L beam pushed up at mid-span by P = 6EIδ/L³
(R_end −P/2, M_mid −PL/2). The rotor is Timoshenko (shear), so a slender shaft (d/L = 0.02)
is used and the tolerance is 0.3 % (the shear terms are ~0.1 %). On the paper rig and the
compressor, the reactions are checked against the equilibrium's own film forces and the weight
(to round-off)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.bearings import TableBearing

MODELS = Path(__file__).parent / "data" / "models"
STEEL = rd.Material("steel", density_kg_m3=7850.0, young_pa=2.1e11, poisson=0.3)


def _beam(n_spans, d=0.02, L=1.0, n=20):
    secs = tuple(rd.ShaftSection(L, d, n_elements=n) for _ in range(n_spans))
    w = STEEL.density_kg_m3 * np.pi / 4 * d**2 * 9.81
    EI = STEEL.young_pa * np.pi * d**4 / 64
    return rd.Rotor(secs), w, EI, L


def test_two_supports_closed_form():
    rotor, w, EI, L = _beam(2, L=0.5)
    s = rd.System(rotor=rotor, materials=(STEEL,), supports=(rd.Support(0), rd.Support(2)))
    r = rd.static(s)
    span = 2 * 0.5
    np.testing.assert_allclose(r.reactions["force_y_n"], w * span / 2, rtol=1e-9)
    j = int(np.argmin(abs(r.section_positions_m - span / 2)))
    assert r.moment_yz_n_m[j] == pytest.approx(w * span**2 / 8, rel=1e-6)
    assert r.deflection_y_m.min() == pytest.approx(-5 * w * span**4 / (384 * EI), rel=3e-3)
    assert r.shear_y_n[0] == pytest.approx(w * span / 2, rel=1e-9)
    assert r.shear_y_n[-1] == pytest.approx(-w * span / 2, rel=1e-9)
    assert np.allclose(r.deflection_x_m, 0) and np.allclose(r.moment_xz_n_m, 0, atol=1e-9)


@pytest.mark.parametrize("delta", [0.0, 1e-3, -5e-4])
def test_three_supports_one_offset_closed_form(delta):
    """The paper's configuration vector in miniature: the middle support (a very stiff table
    bearing, k = 1e12 N/m) raised by a_y = δ shares the weight differently."""
    rotor, w, EI, L = _beam(2)
    mid = TableBearing(station=1, speeds_hz=(0.0, 100.0), kxx_n_per_m=(1e12, 1e12),
                       kyy_n_per_m=(1e12, 1e12), config_ay_m=delta, name="middle")
    s = rd.System(rotor=rotor, materials=(STEEL,), supports=(rd.Support(0), rd.Support(2)),
                  bearings=(mid,))
    r = rd.static(s, speed_hz=10.0)
    assert r.status == "ok"
    P = 6 * EI * delta / L**3
    R = r.reactions.set_index("station")["force_y_n"]
    assert R[1] == pytest.approx(5 * w * L / 4 + P, rel=3e-3, abs=1e-3 * w * L)
    assert R[0] == pytest.approx(3 * w * L / 8 - P / 2, rel=3e-3, abs=1e-3 * w * L)
    assert R[2] == pytest.approx(R[0], rel=1e-6)
    j = int(np.argmin(abs(r.section_positions_m - L)))
    assert r.moment_yz_n_m[j] == pytest.approx(-w * L**2 / 8 - P * L / 2, rel=3e-3)
    assert R.sum() == pytest.approx(r.weight_n, rel=1e-9)
    k = int(np.argmin(abs(r.node_positions_m - L)))
    assert r.deflection_y_m[k] == pytest.approx(delta, abs=1e-8)


def test_paper_rig_reactions_are_the_films_and_carry_the_weight():
    rig = rd.models.paper_rig()
    e = rd.equilibrium(rig, 50.0, 0.15e6, -1.85e-3)
    r = rd.static(rig, 50.0, 0.15e6, -1.85e-3)
    act = r.reactions[r.reactions["kind"] == "active_journal"].iloc[0]
    from rotordyn.analysis.assembly import assembled

    bc = assembled(rig).bearings[0]
    assert act["force_y_n"] == pytest.approx(e.film_force_n[bc.jy], rel=1e-12)
    assert act["force_x_n"] == pytest.approx(e.film_force_n[bc.jx], rel=1e-12)
    assert r.reactions["force_y_n"].sum() == pytest.approx(r.weight_n, rel=1e-9)
    assert r.reactions["force_x_n"].sum() == pytest.approx(0.0, abs=1e-9 * r.weight_n)
    # the journal's absolute position = its equilibrium position + the housing offset
    st = rig.bearings[0].station
    k = int(rig.rotor.station_nodes()[st])
    assert r.deflection_y_m[k] == pytest.approx(e.journal_y_m[0] - 1.85e-3, rel=1e-9)
    assert r.weight_n == pytest.approx(rig.mass_kg * 9.81, rel=1e-9)


def test_compressor_on_plain_bearings_and_the_cli(tmp_path, capsys):
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    r = rd.static(s, 100.0)
    assert set(r.reactions["kind"]) == {"journal"}
    assert r.reactions["force_y_n"].sum() == pytest.approx(r.weight_n, rel=1e-9)
    assert r.moment_yz_n_m.max() > 0  # sagging between the bearings
    df = r.to_frame()
    assert {"z_m", "shear_y_n", "moment_yz_n_m", "deflection_y_m"} <= set(df)
    # N·m is spelt _n_m, as tilt_stiffness_n_m_per_rad (never _nm: nanometres)
    from rotordyn.units import unit_of

    assert not [c for c in df if c.endswith("_nm")]
    assert unit_of("moment_yz_n_m") == unit_of("friction_torque_n_m") == "N·m"
    r.plot(system=s)[0].figure.savefig(tmp_path / "s.png")
    from rotordyn.cli import main

    assert main(["static", str(MODELS / "compressor_plain.toml"), "--speed-hz", "100",
                 "--plot", str(tmp_path / "c.png"), "--json"]) == 0
    import json

    rec = json.loads(capsys.readouterr().out)
    assert rec["status"] == "ok" and len(rec["reactions"]) == 2
    assert "moment_yz_n_m" in rec["along"] and "moment_yz_nm" not in rec["along"]
    # a N·m column is no length: the table never converts it to µm as "moment_yz_n_um"
    from rotordyn.cli.common import table_text

    assert "moment_yz_n_m" in table_text(r.to_frame().head(3).assign(
        moment_yz_n_m=lambda d: d["moment_yz_n_m"] * 1e-6))


def test_failed_equilibrium_is_a_status_never_a_deflection():
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    r = rd.static(s, 1e-4)  # no film pressure to carry the rotor
    if r.status in ("ok", "contact"):
        pytest.skip("the film carried the rotor at 0.1 mHz")
    assert np.isnan(r.deflection_y_m).all() and np.isnan(r.moment_yz_n_m).all()
    assert r.reactions.empty


def test_free_rotor_is_refused():
    rotor, *_ = _beam(1)
    with pytest.raises(rd.InputError, match="supports"):
        rd.static(rd.System(rotor=rotor, materials=(STEEL,)))
