"""Guards issue 18: an error in a model file names the field by its path in the file
(``bearing[1].n_pads``), also for the bearing elements that check themselves on construction
(tilting-pad, fixed-geometry, table, squeeze-film), which named their kind instead
(``tilting_pad_bearing.n_pads``) so a user could not tell which ``[[bearing]]`` was wrong.
Every bearing of every example in docs/model-file.md is given a bad ``name`` in turn."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

import rotordyn as rd

sys.path.insert(0, str(Path(__file__).parent))
from test_model_file_doc import BLOCKS, model_text  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


def _bearing_cases():
    for k, block in enumerate(BLOCKS):
        text = model_text(block)
        starts = [m.end() for m in re.finditer(r"^\[\[bearing\]\][^\n]*\n", text, re.MULTILINE)]
        for i, pos in enumerate(starts):
            kind = re.search(r'^type\s*=\s*"(\w+)"', text[pos:], re.MULTILINE).group(1)
            yield pytest.param(text, i, pos, id=f"block{k}-bearing{i}-{kind}")


@pytest.mark.parametrize("text,i,pos", list(_bearing_cases()))
def test_bad_bearing_field_is_named_by_its_path(text, i, pos):
    # a key the element checks (name must be text) inserted as the table's first line
    bad = text[:pos] + "name = 5\n" + re.sub(r"^name\s*=.*\n", "", text[pos:], count=1,
                                             flags=re.MULTILINE) \
        if not re.match(r"(?:[^\[\n][^\n]*\n)*?name\s*=", text[pos:]) else \
        text[:pos] + re.sub(r"^name\s*=.*$", "name = 5", text[pos:], count=1,
                            flags=re.MULTILINE)
    with pytest.raises(rd.InputError) as exc:
        rd.System.from_toml(bad, is_text=True)
    assert str(exc.value).startswith(f"bearing[{i}].name"), str(exc.value)


def test_second_tilting_pad_and_table_speeds_are_named_by_path():
    tp = (MODELS / "compressor_tilting_pad.toml").read_text()
    j = tp.index('name = "DE bearing"')
    bad = tp[:j] + tp[j:].replace("n_pads = 5", "n_pads = 0", 1)
    with pytest.raises(rd.InputError, match=r"^bearing\[1\]\.n_pads: expected an integer"):
        rd.System.from_toml(bad, is_text=True)
    table = (MODELS / "compressor_table.toml").read_text()
    bad = re.sub(r"^speeds_hz\s*=.*$", 'speeds_hz = "fast"', table, count=1,
                 flags=re.MULTILINE)
    with pytest.raises(rd.InputError, match=r"^bearing\[0\]\.speeds_hz: expected a sequence"):
        rd.System.from_toml(bad, is_text=True)
    # the Python API, with no file, still names the element
    with pytest.raises(rd.InputError, match=r"^tilting_pad_bearing\.n_pads"):
        rd.bearings.TiltingPadBearing(station=1, diameter_m=0.1, length_m=0.05,
                                      clearance_m=1e-4, viscosity_pa_s=0.02, n_pads=0)
