"""Guards ``rotordyn modes MODEL --part sleeve`` (rotordyn.cli.sleeve.modes): the table and the
JSON carry the full and condensed frequencies and the paper's, a TOML ``[sleeve]`` table is
read with unknown keys rejected, and unsupported reductions are an InputError."""

import argparse
import json

import numpy as np
import pytest

import rotordyn
from rotordyn.cli import sleeve as cli_sleeve
from rotordyn.bearings.sleeve import paper_rig_sleeve


def _args(**kw):
    base = dict(model="paper-rig", speed_hz=0.0, reduction=None, n_modes=None, json=False)
    base.update(kw)
    return argparse.Namespace(**base)


def test_json_has_full_condensed_and_paper(capsys):
    """The JSON equals the Python API's numbers (same computation) and carries the paper's."""
    assert cli_sleeve.modes(_args(json=True)) == 0
    out = json.loads(capsys.readouterr().out)
    res = paper_rig_sleeve().condense()
    np.testing.assert_allclose(out["frequencies_hz"], res.freq_condensed_hz, rtol=1e-12)
    np.testing.assert_allclose(out["full_frequencies_hz"], res.freq_full_hz, rtol=1e-12)
    assert out["paper_frequencies_hz"] == [490.2, 1754.2, 6175.8]
    assert out["master_stations"] == [7, 14, 20]


def test_table_and_toml(tmp_path, capsys):
    """A TOML [sleeve] table builds the same sleeve as the Python constructor."""
    toml = tmp_path / "s.toml"
    toml.write_text(
        "[sleeve]\nradius_m = 0.0278\nthickness_m = 0.005\nwidth_m = 0.04\narc_deg = 160.0\n"
        "clamp_deg = 105.0\nyoung_pa = 6.2e10\ndensity_kg_m3 = 5890.0\npoisson = 0.34\n"
        "master_stations = [7, 14, 20]\n"
    )
    assert cli_sleeve.load_sleeve(str(toml)) == paper_rig_sleeve()
    assert cli_sleeve.modes(_args(model=str(toml))) == 0
    text = capsys.readouterr().out
    assert "condensed" in text and "508.2" in text  # the calibrated rig sleeve (docs/paper-rig.md)
    toml.write_text("[sleeve]\nradius_mm = 28.0\n")
    with pytest.raises(rotordyn.InputError, match="sleeve.radius_mm"):
        cli_sleeve.load_sleeve(str(toml))


def test_bad_reduction_and_model():
    """IRS/Craig-Bampton are not offered for the sleeve; an unknown model names the field."""
    with pytest.raises(rotordyn.InputError, match="--reduction"):
        cli_sleeve.modes(_args(reduction="irs"))
    with pytest.raises(rotordyn.InputError, match="model"):
        cli_sleeve.modes(_args(model="no-such-model"))
