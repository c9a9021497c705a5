"""Guards issue 18's "``n_modes`` counts tilting-pad coordinates": on the compressor on two 5-pad
tilting-pad bearings (tests/data/models) the pads' own modes lie among the rotor's at low speed
(19.3 Hz at 20 Hz running speed), so a cut to the lowest n modes lost rotor branches from the
Campbell diagram and the stability table. The cut now counts the rotor's modes; pad modes below
it are listed besides them (kind "pad"). The reference is the same analysis without a cut."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import rotordyn as rd

MODELS = Path(__file__).parent / "data" / "models"


def _rotor_freqs(freqs, kind):
    f = np.asarray(freqs)
    return f[(np.asarray(kind) == "rotor") & np.isfinite(f)]  # empty slots are NaN


def test_stability_cut_counts_rotor_modes_not_pads():
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    full = rd.stability(s, 20.0)
    assert "pad" in set(full.kind[:6])  # the case: a pad mode among the lowest rotor modes
    cut = rd.stability(s, 20.0, n_modes=4)
    rf = _rotor_freqs(cut.frequencies_hz, cut.kind)
    assert rf.size == 4
    np.testing.assert_allclose(rf, _rotor_freqs(full.frequencies_hz, full.kind)[:4], rtol=1e-9)
    assert set(cut.to_frame()["kind"].astype(str)) <= {"rotor", "pad"}  # "pad" is a category


def test_campbell_keeps_every_rotor_branch():
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    sp = np.array([20.0, 40.0, 60.0])
    full = rd.campbell(s, sp)
    cut = rd.campbell(s, sp, n_modes=4)
    for i in range(sp.size):
        rf = _rotor_freqs(cut.frequencies_hz[i], cut.kind[i])
        assert rf.size == 4, (sp[i], cut.kind[i])
        np.testing.assert_allclose(rf, _rotor_freqs(full.frequencies_hz[i], full.kind[i])[:4],
                                   rtol=1e-9)


def test_mode_window_rule():
    from rotordyn.analysis.linear import mode_window

    kind = np.array(["rotor", "pad", "rotor", "pad", "rotor", "pad"])
    assert list(mode_window(kind, 2)) == [0, 1, 2]
    assert list(mode_window(kind, 3)) == [0, 1, 2, 3, 4]
    assert list(mode_window(np.array(["pad", "pad"]), 2)) == []
