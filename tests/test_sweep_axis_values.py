"""Axis values as keys and as lines (the sweep store used as a user would, 2026-12-05).

Before: an axis value given twice (``speed_hz = [40, 60, 60, 80]``,
``"bearings.*.clearance_m" = [1e-4, 1e-4]``) ran twice, its rows with the same key columns
(a join or a pivot on the axes mixed them silently, the computation doubled); a threshold line
listed out of order (``[120, 40, 200, 80, 160]``) reported the one crossing of the compressor
at 114.18 Hz four times, three of them artefacts of the listing with alternating
``stable_side``; a stability line out of order tracked its modes along the listing. Now each is
one InputError at load naming ``grid.<axis>[i]``. A decreasing line (a run-down) is accepted,
and its threshold row said ``stable_side = "above"`` (read in scan order) where the increasing
line says ``"below"``: now both say below, with the same crossing.

Model: the compressor of tests/data/models on plain bearings (not the paper rig)."""

from pathlib import Path

import pandas as pd
import pytest

from rotordyn.errors import InputError
from rotordyn.sweep import run_sweep
from rotordyn.sweep.spec import SweepSpec

MODEL = (Path(__file__).parent / "data" / "models" / "compressor_plain.toml").resolve()


def _spec(tmp_path, grid: str, analysis="stability", options="n_modes = 2", name="t"):
    p = tmp_path / f"{name}.toml"
    p.write_text(f'schema = "rotordyn/sweep/1"\nname = "{name}"\nmodel = "{MODEL}"\n'
                 f'analysis = "{analysis}"\nchunk_size = 5\n[grid]\n{grid}\n'
                 f'[options]\n{options}\n')
    return p


@pytest.mark.parametrize(("grid", "field"), [
    ('speed_hz = [40.0, 60.0, 60.0, 80.0]', r"grid\.speed_hz\[2\]: 60\.0 repeats "
                                             r"grid\.speed_hz\[1\]"),
    ('"bearings.*.clearance_m" = [1e-4, 1.2e-4, 1e-4]\nspeed_hz = 100.0',
     r"grid\.bearings\.\*\.clearance_m\[2\]: 0\.0001 repeats"),
    ('speed_hz = {start = 50.0, stop = 50.0, num = 3}', r"grid\.speed_hz\[1\]: 50\.0 repeats"),
])
def test_a_repeated_axis_value_is_refused(tmp_path, grid, field):
    with pytest.raises(InputError, match=field):
        SweepSpec.from_toml(_spec(tmp_path, grid))


@pytest.mark.parametrize(("analysis", "options"), [
    ("threshold", 'vary = "speed_hz"'), ("stability", "n_modes = 2")])
def test_a_line_out_of_order_is_refused(tmp_path, analysis, options):
    grid = 'speed_hz = [120.0, 40.0, 200.0, 80.0, 160.0]'
    with pytest.raises(InputError, match=r"grid\.speed_hz\[2\]: the values must decrease "
                       r"along the line .* got 40\.0 then 200\.0; sort them"):
        SweepSpec.from_toml(_spec(tmp_path, grid, analysis, options))


def test_outer_axis_in_any_order_and_untracked_lines_are_kept(tmp_path):
    # not a line: the order of an outer axis only orders the points
    SweepSpec.from_toml(_spec(tmp_path, '"bearings.*.clearance_m" = [1.2e-4, 1e-4]\n'
                                        'speed_hz = [40.0, 80.0]'))
    SweepSpec.from_toml(_spec(tmp_path, 'speed_hz = [80.0, 40.0, 60.0]',
                              options="n_modes = 2\ntrack = false"))


def test_threshold_of_a_decreasing_line(tmp_path):
    grid = '"bearings.*.clearance_m" = 1.2e-4\nspeed_hz = '
    rows = {}
    for name, speeds in (("up", "[40.0, 80.0, 120.0, 160.0, 200.0]"),
                         ("down", "[200.0, 160.0, 120.0, 80.0, 40.0]")):
        spec = _spec(tmp_path, grid + speeds, "threshold", 'vary = "speed_hz"', name)
        run_sweep(spec, tmp_path / name, threads=1, progress=False)
        rows[name] = pd.read_parquet(tmp_path / name)
    up, down = rows["up"], rows["down"]
    assert len(up) == len(down) == 1 and (up.status == "ok").all()
    # the same crossing from either end (Brent to 1e-8 of the bracket), stable below it
    assert down.value[0] == pytest.approx(up.value[0], abs=1e-6 * 40.0)
    assert 100.0 < up.value[0] < 130.0
    assert up.stable_side[0] == down.stable_side[0] == "below"
