"""The model-file reference (docs/model-file.md) stays true to the reader (issue 18).

Guards: every ```toml block of the page loads with ``System.from_toml`` — a whole model when
it has ``schema = ...``, otherwise a fragment put into a small base model (a 1 m steel rotor
of four sections, stations 0-4, no supports, no reduction) — without a warning (pytest turns
unit-slip warnings into errors, so the examples are realistic), and every key the block
writes is found in the built ``System`` with the value written (the element of each
``[[bearing]]`` is the class of its ``type``); every example round-trips through
``to_toml()``; every bearing ``type`` of ``rotordyn.bearings.BEARING_TYPES``, every
fixed-geometry ``kind``, every reduction method and support type has an example, and every
field of every element the format reads is named in the page. The names are read from the
package, so a new element, kind or field without documentation fails here. Exact
comparisons: the reader stores what it reads (ints and floats compare equal in Python).
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import pytest
import rotordyn as rd
import tomllib
from rotordyn.bearings import BEARING_TYPES, FlexibleSleeve, Groove, Oil, ThermalFilm, ThermalModel
from rotordyn.bearings.fixed_geometry import KINDS
from rotordyn.model.rotor import REDUCTION_METHODS

DOC = Path(__file__).resolve().parents[1] / "docs" / "model-file.md"
TEXT = DOC.read_text(encoding="utf-8")
BLOCKS = re.findall(r"^```toml\n(.*?)^```", TEXT, flags=re.DOTALL | re.MULTILINE)

BASE_MATERIAL = """
[material.steel]
density_kg_m3 = 7850.0
young_pa = 2.1e11
poisson = 0.3
"""
BASE_ROTOR = "\n[rotor]\n" + """
[[rotor.section]]
length_m = 0.25
outer_diameter_m = 0.05
""" * 4


def model_text(block: str) -> str:
    """A whole model as written, or the fragment inside the base model (top-level keys of the
    fragment come before any table, the base's tables after the fragment's)."""
    if re.search(r"^schema\s*=", block, flags=re.MULTILINE):
        return block
    text = 'schema = "rotordyn/model/1"\n' + block
    if "[material.steel]" not in block:
        text += BASE_MATERIAL
    if "[[rotor.section]]" not in block:
        text += BASE_ROTOR
    elif "[rotor]" not in block:
        text = text.replace("[[rotor.section]]", "[rotor]\n[[rotor.section]]", 1) \
            + BASE_ROTOR.replace("\n[rotor]\n", "\n")
    return text


def load(block: str) -> rd.System:
    return rd.System.from_toml(model_text(block), is_text=True)


def same(built, written, where: str) -> None:
    """``written`` (a TOML value) is what the model holds in ``built``."""
    if isinstance(written, dict):
        for k, val in written.items():
            assert hasattr(built, k), f"{where}.{k}: not a field of {type(built).__name__}"
            same(getattr(built, k), val, f"{where}.{k}")
    elif isinstance(written, list):
        assert len(built) == len(written), f"{where}: {built!r} != {written!r}"
        for i, (b, w) in enumerate(zip(built, written)):
            same(b, w, f"{where}[{i}]")
    else:
        assert type(built) is not bool or type(written) is bool, where
        assert built == written, f"{where}: model holds {built!r}, the doc writes {written!r}"


def check_written(s: rd.System, doc: dict) -> None:
    for k in ("name", "description", "gravity_m_s2"):
        if k in doc:
            same(getattr(s, k), doc[k], k)
    for name, t in doc.get("material", {}).items():
        same(s.material(name), t, f"material.{name}")
    for k, val in doc.get("rotor", {}).items():  # the rotor's own keys (material damping)
        if k != "section":
            same(getattr(s.rotor, k), val, f"rotor.{k}")
    secs = doc.get("rotor", {}).get("section", [])
    for i, t in enumerate(secs):
        same(s.rotor.sections[i], t, f"rotor.section[{i}]")
    assert len(s.rotor.disks) == len(doc.get("disk", []))
    for i, t in enumerate(doc.get("disk", [])):
        d = s.rotor.disks[i]
        same(d, t, f"disk[{i}]")
        assert d.mass_kg > 0 and d.ip_kg_m2 > 0 and d.id_kg_m2 > 0
    assert len(s.supports) == len(doc.get("support", []))
    for i, t in enumerate(doc.get("support", [])):
        same(s.supports[i], t, f"support[{i}]")
    if "reduction" in doc:
        same(s.reduction, doc["reduction"], "reduction")
    assert len(s.stages) == len(doc.get("stage", []))
    for i, t in enumerate(doc.get("stage", [])):
        same(s.stages[i], t, f"stage[{i}]")
    assert len(s.bearings) == len(doc.get("bearing", []))
    for i, t in enumerate(doc.get("bearing", [])):
        b = s.bearings[i]
        assert type(b) is BEARING_TYPES[t["type"]], f"bearing[{i}].type"
        same(b, {k: val for k, val in t.items() if k != "type"}, f"bearing[{i}]")
    if "thermal" in doc:
        t = dict(doc["thermal"])
        films = t.pop("film", [])
        same(s.thermal, t, "thermal")
        same(s.thermal.films, films, "thermal.film")
    else:
        assert s.thermal is None


def test_the_page_has_examples():
    assert len(BLOCKS) >= 15


@pytest.mark.parametrize("block", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_example_loads_with_the_values_written(block):
    s = load(block)
    check_written(s, tomllib.loads(block))


@pytest.mark.parametrize("block", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_example_round_trips(block):
    s = load(block)
    assert rd.System.from_toml(s.to_toml(), is_text=True) == s


def _written() -> list[dict]:
    return [tomllib.loads(b) for b in BLOCKS]


def test_every_bearing_type_and_kind_has_an_example():
    bearings = [t for d in _written() for t in d.get("bearing", [])]
    types = {t["type"] for t in bearings}
    kinds = {t.get("kind", "two_axial_groove") for t in bearings if t["type"] == "fixed_geometry"}
    assert set(BEARING_TYPES) - types == set(), "bearing types without an example"
    assert set(KINDS) - kinds == set(), "fixed_geometry kinds without an example"
    flexible = [t for t in bearings if t.get("pivot_stiffness_n_per_m", 0) > 0]
    assert flexible, "no flexible-pivot tilting pad"
    assert any("sleeve" in t for t in bearings) and any("grooves" in t for t in bearings)


def test_every_reduction_method_and_support_type_has_an_example():
    docs = _written()
    methods = {d["reduction"].get("method") for d in docs if "reduction" in d}
    assert set(REDUCTION_METHODS) - methods == set()
    types = {t.get("type", "rigid") for d in docs for t in d.get("support", [])}
    assert types == {"rigid", "linear"}
    disks = [t for d in docs for t in d.get("disk", [])]
    assert any("mass_kg" in t for t in disks) and any("mass_kg" not in t for t in disks)
    stages = {t.get("type", "centrifugal") for d in docs for t in d.get("stage", [])}
    assert stages == {"centrifugal", "axial"}
    assert any("thermal" in d and d["thermal"].get("film") for d in docs)


def test_every_field_is_named_on_the_page():
    classes = [rd.Material, rd.Rotor, rd.ShaftSection, rd.Disk, rd.Support, rd.Stage, rd.Reduction, Groove,
               FlexibleSleeve, Oil, ThermalModel, ThermalFilm, *BEARING_TYPES.values()]
    # Material.name is the table's key ([material.<name>]), not a key of its own
    missing = [f"{c.__name__}.{f.name}" for c in classes for f in dataclasses.fields(c)
               if f"`{f.name}`" not in TEXT and f"`[bearing.{f.name}]`" not in TEXT
               and (c, f.name) != (rd.Material, "name")
               and (c, f.name) not in ((rd.Rotor, "sections"), (rd.Rotor, "disks"))]
    assert missing == []
    for key in ("schema", "name", "description", "gravity_m_s2", "type"):
        assert f"`{key}`" in TEXT


def test_a_broken_example_fails():
    """The checks above bite: a mistyped key and a wrong value are caught."""
    block = next(b for b in BLOCKS if 'type = "tilting_pad"' in b)
    with pytest.raises(rd.InputError, match=r"bearing\[0\]\.pad_arc: unknown key"):
        load(block.replace("pad_arc_deg", "pad_arc"))
    written = tomllib.loads(block)
    written["bearing"][0]["n_pads"] += 1
    with pytest.raises(AssertionError, match="n_pads"):
        check_written(load(block), written)
