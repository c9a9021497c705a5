"""A tilting-pad rotor whose stability verdict flips where a pad starts to carry load
(docs/bearings.md, "A pad at the onset of loading"; rotordyn.results.pad_load).

Found by QA (qa21, 2026-12-06) on a steam-turbine-like rotor on two 4-pad tilting-pad bearings
loaded between pads (tests/data/models/steam_turbine_tilting_pad.toml, 2.2 t, not the paper
rig): `rotordyn stability` said UNSTABLE (ζ ≈ −0.005) from 119.8 Hz to ≈ 130 Hz, stable
before and after; a transient agreed (a 31 nm limit cycle at 121 Hz, decay at 119 Hz).

Physics or numerics (measured 2026-12-06, docs/bearings.md has the table): finite differences
give the perturbation method's eigenvalues; the pad equilibria are at round-off; pad inertia
1e-5 instead of 1e-2 kg m² leaves ζ at −0.0044; the band stays under grid refinement and
moves with the onset of top-pad loading (48 × 8: from 119.8 Hz; 96 × 16 and 144 × 24: from
≈ 115.5 Hz, ζ −0.0036 and −0.0031 there). The mechanism: the top pad's tilt stiffness is
proportional to its load and vanishes at the onset while its coupling with the journal stays
finite (the one-sided derivative of the film at the edge of its pressure-free set). The
verdict is the model's and is kept; the result, `rotordyn stability` and the report now name
the pads whose load is near zero, so the user knows the verdict is sensitive.

Checks: the verdict on both sides of the onset (kept), the note present exactly where a top
pad carries load below 5 % of the bottom pads' (none while it is unloaded), the mechanism's
numbers from the linear model (tilt stiffness ≤ 1 % of the loaded pad's, coupling ≥ 10 % of
it), finite differences against the perturbation method (1e-6 in ζ), the 96 × 16 grid (the
onset and the flag move together), the CLI's note (text and --json) and the report's items.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.report.pad_onset import pad_onset_items
from rotordyn.results.pad_load import LIGHT_PAD_REL, light_pads

MODEL = Path(__file__).parent / "data" / "models" / "steam_turbine_tilting_pad.toml"
TOP = (1, 2)  # the upper pads of either bearing (pivots at 135° and 45°... in pivot order)


@pytest.fixture(scope="module")
def turbine():
    return rd.System.from_toml(MODEL)


def _bending_zeta(st):
    """ζ of the two ≈ 26 Hz rotor modes (the wheel's bending pair)."""
    f = st.frequencies_hz
    j = [k for k in range(len(f)) if st.kind[k] == "rotor" and 24 < f[k] < 28
         and st.damping_ratio[k] < 0.5]
    assert len(j) == 2, f
    return st.damping_ratio[j]


def test_onset_of_pad_loading_flips_the_verdict_and_is_named(turbine):
    before = rd.stability(turbine, 119.5)
    after = rd.stability(turbine, 119.8)
    pf = before.linear.equilibrium.pads_frame()
    assert pf[pf.pad.isin(TOP)].unloaded.all()  # the top pads carry nothing yet
    assert before.stable and np.all(_bending_zeta(before) > 0.009)
    assert before.pad_load_note == ""
    # the verdict is kept: unstable, the bending pair at ζ ≈ −0.0046
    assert not after.stable
    assert np.all(_bending_zeta(after) < -0.003)
    light = light_pads(after.linear.equilibrium)
    assert {(b, k) for b, k, *_ in light} == {(b, k) for b in ("DE bearing", "NDE bearing")
                                               for k in TOP}
    assert all(0 < p < LIGHT_PAD_REL * top for *_, p, top in light)
    note = after.pad_load_note
    assert "near-zero pad load at 119.8 Hz" in note and "'DE bearing' pad 1" in note
    assert "sensitive" in note
    assert repr(after).endswith("; 4 tilting pads near zero load (pad_load_note)>")


def test_the_mechanism_vanishing_tilt_stiffness_finite_coupling(turbine):
    lm = rd.linearize(turbine, 119.8)
    lab = list(lm.labels)
    K = np.asarray(lm.KH)
    x = lab.index("station1.x")
    top, bottom = lab.index("DE bearing.pad1.eta"), lab.index("DE bearing.pad0.eta")
    assert 0 < K[top, top] < 0.01 * K[bottom, bottom]  # tilt stiffness ∝ its tiny load
    assert abs(K[x, top]) > 0.1 * abs(K[x, bottom])    # its coupling does not vanish
    assert abs(K[top, x]) > 0.1 * abs(K[bottom, x])


def test_finite_differences_agree(turbine):
    p = _bending_zeta(rd.stability(turbine, 119.8))
    fd = _bending_zeta(rd.stability(turbine, 119.8, method="finite_difference"))
    np.testing.assert_allclose(fd, p, atol=1e-6)


def test_finer_grid_moves_the_onset_and_the_flag_with_it(turbine):
    fine = dataclasses.replace(turbine, bearings=tuple(
        dataclasses.replace(b, n_circ=96, n_axial=16) for b in turbine.bearings))
    s115, s118 = rd.stability(fine, 115.0), rd.stability(fine, 118.0)
    assert s115.stable and s115.pad_load_note == ""
    assert not s118.stable and "'NDE bearing' pad 2" in s118.pad_load_note
    # the report's items over the coefficient speeds' equilibria name the onset
    items = pad_onset_items([s115.linear.equilibrium, s118.linear.equilibrium])
    assert "'DE bearing' pad 1 starts to carry load between 115 and 118 Hz" in items


def test_cli_stability_prints_the_note(turbine, capsys):
    code = main(["stability", str(MODEL), "--speed-hz", "119.8"])
    err = capsys.readouterr().err
    assert code == 0 and "UNSTABLE" in err
    assert "note: near-zero pad load at 119.8 Hz" in err
    code = main(["stability", str(MODEL), "--speed-hz", "119.8", "--json"])
    rec = json.loads(capsys.readouterr().out)
    assert rec["stable"] is False and "'NDE bearing' pad 1" in rec["pad_load_note"]
    main(["stability", str(MODEL), "--speed-hz", "119.5", "--json"])
    assert json.loads(capsys.readouterr().out)["pad_load_note"] == ""
