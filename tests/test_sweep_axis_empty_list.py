"""A model-field axis through an empty list is refused, never a column that varies nothing.

`thermal.films.<bearing>.<key>` addresses a `[[thermal.film]]` entry of the model. On a model
whose `[thermal]` has none (tests/data/models/pump6_plain_thermal.toml: one oil system for
both bearings), `"thermal.films.*.carry_over" = [0.0, 0.9]` was accepted and set nothing:
before 2026-12-06 the thermal sweep wrote the column as 0.0 and 0.9 beside rows equal to the
bit (carry_over_effective 0.5, the [thermal] value, in every row), and
`thermal.films.DE_bearing.carry_over` was refused as "no element 'DE_bearing' (an index 0..-1,
'*', 'active' or a name: )". Both now say that the model has no such entry and what to do.
"""

from pathlib import Path

import pytest

import rotordyn as rd
from rotordyn.model.paths import set_field
from rotordyn.sweep.spec import SweepSpec

MODELS = Path(__file__).parent / "data" / "models"
PUMP = MODELS / "pump6_plain_thermal.toml"


@pytest.mark.parametrize("path", ["thermal.films.*.carry_over",
                                  "thermal.films.DE_bearing.carry_over",
                                  "thermal.films.0.carry_over"])
def test_no_film_entries_refused(path):
    s = rd.System.from_toml(PUMP)
    assert s.thermal is not None and not s.thermal.films
    with pytest.raises(rd.InputError, match=r"has no \[\[thermal.film\]\] entry"):
        set_field(s, path, 0.3)


def test_spec_with_such_an_axis_refused_at_load(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(f'''schema = "rotordyn/sweep/1"
name = "pump-carry-over"
model = "{PUMP}"
analysis = "thermal"

[grid]
"thermal.films.*.carry_over" = [0.0, 0.9]
speed_hz = [30.0]
''')
    with pytest.raises(rd.InputError, match=r"grid.thermal.films.\*.carry_over.*no element"):
        SweepSpec.from_toml(spec)


def test_existing_entries_and_bearings_still_swept():
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")  # a DE film entry
    t = set_field(s, "thermal.films.*.carry_over", 0.1)
    assert [f.carry_over for f in t.thermal.films] == [0.1]
    p = set_field(rd.System.from_toml(PUMP), "bearings.*.clearance_m", 9e-5)
    assert [b.clearance_m for b in p.bearings] == [9e-5, 9e-5]


def test_star_over_a_model_without_bearings_refused():
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    assert not s.bearings
    with pytest.raises(rd.InputError, match=r"bearings.\*: no element"):
        set_field(s, "bearings.*.clearance_m", 1e-4)


def test_a_star_under_a_star_skips_an_empty_list_and_refuses_only_when_all_are():
    """``bearings.*.grooves.*`` over a model whose first bearing has no grooves sets the
    second bearing's groove (the empty-list refusal had refused it: review, 2026-12-06);
    over a model where no bearing has a groove it is refused (an axis that varies nothing)."""
    from rotordyn.model.paths import get_field, set_field

    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    assert not s.bearings[0].grooves and s.bearings[1].grooves
    m = set_field(s, "bearings.*.grooves.*.pressure_pa", 2e5)
    assert [g.pressure_pa for g in m.bearings[1].grooves] == [2e5] * len(s.bearings[1].grooves)
    assert get_field(m, "bearings.*.grooves.*.pressure_pa") == [2e5] * len(s.bearings[1].grooves)
    plain = rd.System.from_toml(MODELS / "compressor_plain.toml")
    assert not any(b.grooves for b in plain.bearings)
    with pytest.raises(rd.InputError, match=r"grooves.\*.pressure_pa: no element: every list"):
        set_field(plain, "bearings.*.grooves.*.pressure_pa", 2e5)
