"""Every pad's state at a system equilibrium (EquilibriumResult.pads / pads_frame(), the CLI's
per-pad table): pivot, tilt, peak pressure, minimum film and the "unloaded" flag (a pad whose
film carries no pressure; unloaded top pads are the ones that flutter)."""

import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.cli import main as cli

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def compressor():
    return rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")


def test_top_pads_unloaded_at_low_speed_loaded_at_high_speed(compressor):
    """5 pads, load between pads (pivots 306, 18, 90, 162, 234 deg): at 40 Hz the top pad (90
    deg) is pressure-free in both bearings (round-off pressures, < 1e-6 Pa), every other pad
    carries > 1e4 Pa; at 150 Hz the film pressurises every pad."""
    lo = rd.equilibrium(compressor, 40.0)
    df = lo.pads_frame()
    assert len(df) == 10 and list(df.columns) == ["bearing", "pad", "pivot_deg", "tilt_rad",
                                                   "p_max_pa", "h_min_m", "unloaded"]
    top = np.isclose(df.pivot_deg, 90.0)
    assert df.unloaded[top].all() and not df.unloaded[~top].any()
    assert (df.p_max_pa[top] < 1e-6).all() and (df.p_max_pa[~top] > 1e4).all()
    hi = rd.equilibrium(compressor, 150.0).pads_frame()
    assert not hi.unloaded.any() and (hi.p_max_pa > 1e5).all()


def test_pad_values_agree_with_the_bearing_values(compressor):
    """The pads' minimum films reduce to the bearing's h_min; the mirror pads about the
    vertical load (306 and 234 deg) carry the same peak pressure (the film of a centre-pivot
    pad is mirrored by reversing the rotation, the journal sits on the vertical: 1e-9);
    the tilts are the standalone bearing's δ_k = (η_k − q_t)/ℓ of the same coordinates."""
    e = rd.equilibrium(compressor, 40.0)
    df = e.pads_frame()
    for i, name in enumerate(e.bearing_names):
        d = df[df.bearing == name]
        assert d.h_min_m.min() == pytest.approx(e.h_min_m[i], rel=1e-12)
        p = dict(zip(d.pivot_deg, d.p_max_pa))
        assert p[306.0] == pytest.approx(p[234.0], rel=1e-9)
        assert p[18.0] == pytest.approx(p[162.0], rel=1e-9)
        asm = assembled(compressor)
        bc = asm.bearings[i]
        b = compressor.bearings[i]
        r_local = np.r_[e.r[bc.jx], e.r[bc.jy], e.r[list(bc.extra)]]
        np.testing.assert_allclose(d.tilt_rad, b.pad_tilts_rad(r_local), rtol=0, atol=1e-15)
    rec = e.bearing(e.bearing_names[0])
    assert rec["pad_unloaded"] == [False, False, True, False, False]


def test_no_pads_rows_without_pads_or_without_equilibrium(compressor):
    plain = rd.System.from_toml(MODELS / "compressor_plain.toml")
    assert rd.equilibrium(plain, 40.0).pads == {}
    assert len(rd.equilibrium(plain, 40.0).pads_frame()) == 0
    failed = rd.equilibrium(compressor, 1e-3)  # too slow to float the rotor
    assert not failed.converged
    assert failed.pads == {} and len(failed.pads_frame()) == 0


def test_tilted_pads_on_a_load_on_pad_pump(capsys):
    """The overhung pump (4 pads, load on pad, preload 0.25, tilt on, misaligned housing): the
    pad facing the journal's displacement carries the most pressure (the overhung impeller
    lifts the NDE journal onto its top pad, the DE journal sits on its bottom pad), the
    preload keeps every pad pressured; the CLI's JSON and text print the pads."""
    pump = MODELS / "pump_overhung_tilting_pad.toml"
    e = rd.equilibrium(rd.System.from_toml(pump), 30.0)
    assert e.converged
    df = e.pads_frame()
    assert not df.unloaded.any()
    for i, name in enumerate(e.bearing_names):
        d = df[df.bearing == name].set_index("pivot_deg")
        towards = np.degrees(np.arctan2(e.journal_y_m[i], e.journal_x_m[i])) % 360.0
        assert d.p_max_pa.idxmax() == pytest.approx(90.0 * round(towards / 90.0) % 360.0)
    assert e.journal_y_m[0] > 0 > e.journal_y_m[1]
    assert cli(["equilibrium", str(pump), "--speed-hz", "30", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    b = rec["bearings"][e.bearing_names[0]]
    assert b["pad_unloaded"] == [False] * 4
    np.testing.assert_allclose(b["pad_p_max_pa"], df[df.bearing == e.bearing_names[0]].p_max_pa,
                               rtol=1e-12)
    assert cli(["equilibrium", str(pump), "--speed-hz", "30"]) == 0
    out = capsys.readouterr().out
    assert "p_max_pa" in out and "unloaded" in out
