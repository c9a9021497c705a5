"""The report's speed range on a model with bearing tables (tests/data/models/
compressor_table.toml: both tables over 0–200 Hz, no extrapolation). Before, the report without
an operating speed ran its static analysis at N_mc = the second undamped critical on stiff
bearings (525 Hz) and stopped with "speed 656.375 Hz is outside its table": an engineer's own
table-bearing model could not be reported at all. Now the range stays inside the tables and
says so (docs/report.md)."""

import contextlib
import dataclasses
import io
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.report.criteria import speed_range, table_window

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def table_model():
    return rd.System.from_toml(MODELS / "compressor_table.toml")


def test_automatic_range_is_cut_at_the_tables(table_model):
    free = dataclasses.replace(table_model, bearings=tuple(
        dataclasses.replace(b, extrapolate=True) for b in table_model.bearings))
    wide = speed_range(free)  # extrapolating tables cover every speed: the criticals' range
    assert wide.speeds_hz[-1] > 600.0 and table_window(free) is None
    r = speed_range(table_model)
    assert r.speeds_hz[-1] == pytest.approx(200.0) and r.speeds_hz[0] >= 0.0
    assert np.all(np.diff(r.speeds_hz) > 0) and r.speeds_hz.size >= 60
    assert r.n_mc_hz == pytest.approx(200.0 / 1.25)
    assert "table of bearing 'NDE bearing' ends at 200 Hz" in r.why
    assert "extrapolate = true" in r.why
    # an operating range whose 125 % passes the tables: cut there, N_mc kept
    r = speed_range(table_model, (140.0, 170.0))
    assert r.speeds_hz[-1] == pytest.approx(200.0) and r.n_mc_hz == 170.0
    assert "cut to" in r.why
    # within the tables: unchanged
    assert speed_range(table_model, (100.0, 150.0)).speeds_hz[-1] == pytest.approx(187.5)


def test_given_speeds_and_refusals(table_model):
    r = speed_range(table_model, None, np.arange(20.0, 241.0, 20.0))
    assert r.speeds_hz[-1] == 200.0 and "2 of them outside the bearing tables dropped" in r.why
    with pytest.raises(rd.InputError, match="--speeds-hz"):
        speed_range(table_model, None, np.array([250.0, 300.0]))
    with pytest.raises(rd.InputError, match="--operating-speed-hz.*210 Hz.*0–200 Hz"):
        speed_range(table_model, (150.0, 210.0))


def test_report_of_a_table_model_without_operating_speed(tmp_path):
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = main(["report", str(MODELS / "compressor_table.toml"), "--out", str(tmp_path)])
    assert code == 0, err.getvalue()
    text = (tmp_path / "report.txt").read_text(encoding="utf-8")
    lo = speed_range(rd.System.from_toml(MODELS / "compressor_table.toml")).speeds_hz[0]
    from rotordyn.report.criteria import critical_speed_map

    second = critical_speed_map(rd.System.from_toml(MODELS / "compressor_table.toml"))[1][-1, 1]
    assert lo == pytest.approx(0.02 * 1.25 * second, rel=1e-12)  # 2 % of 125 % of it
    assert f"critical speeds over {lo:.4g}–200 Hz" in text
    assert "ends at 200 Hz" in text


def test_campbell_and_unbalance_default_speeds_come_from_the_model(capsys):
    """`rotordyn campbell` / `unbalance` without --speeds-hz: the paper's 5–120 Hz only on its
    rig; on another machine the report's range (said on stderr). Before, every model got
    5:120:1, so the compressor's criticals at 141 and 149 Hz were "no 1× crossing"."""
    import argparse

    from rotordyn.cli.analyses import _speeds

    ns = argparse.Namespace(speeds_hz=None)
    np.testing.assert_array_equal(_speeds(ns, rd.models.paper_rig()), np.arange(5.0, 121.0))
    assert main(["campbell", str(MODELS / "compressor_table.toml")]) == 0
    cap = capsys.readouterr()
    lo = speed_range(rd.System.from_toml(MODELS / "compressor_table.toml")).speeds_hz[0]
    assert f"speeds: 121 from {lo:.4g} to 200 Hz" in cap.err and "ends at 200 Hz" in cap.err
    # a forward 1× crossing beyond the rig's 120 Hz (the API's own Campbell diagram finds it)
    crit = rd.campbell(rd.System.from_toml(MODELS / "compressor_table.toml"),
                       np.linspace(lo, 200.0, 121)).critical_speeds()
    first = float(crit["speed_hz"].iloc[0])
    assert first > 120.0 and f"{first:g}"[:5] in cap.out
    assert main(["unbalance", str(MODELS / "compressor_linear.toml"), "--unbalance", "3,1e-4,0",
                 "--operating-speed-hz", "100", "120"]) == 0
    assert "speeds: 121 from 3 to 150 Hz (2 %…125 % of the maximum operating speed 120 Hz" \
        in capsys.readouterr().err


def test_tables_above_the_models_own_n_mc(table_model):
    """Tables over 170–210 Hz and no operating speed: the model's own N_mc (168 Hz, the
    tables' top / 1.25) is moved into the tables instead of refusing an option the user never
    gave (review finding); tables far above the criticals give their own range."""
    def shifted(lo, hi):
        return dataclasses.replace(table_model, bearings=tuple(
            dataclasses.replace(b, speeds_hz=(lo, 0.5 * (lo + hi), hi))
            for b in table_model.bearings))
    r = speed_range(shifted(170.0, 210.0))
    assert r.speeds_hz[0] == pytest.approx(170.0) and r.speeds_hz[-1] == pytest.approx(210.0)
    assert r.n_mc_hz == pytest.approx(170.0) and "inside the tables" in r.why
    r = speed_range(shifted(2000.0, 2100.0))
    assert r.speeds_hz[0] == pytest.approx(2000.0) and r.speeds_hz[-1] == pytest.approx(2100.0)
    assert np.all(np.diff(r.speeds_hz) > 0)
    with pytest.raises(rd.InputError, match="--operating-speed-hz"):
        speed_range(shifted(170.0, 210.0), (100.0, 150.0))


def test_log_dec_of_a_neutral_real_root_is_zero():
    from rotordyn.results.modes import log_dec

    np.testing.assert_array_equal(log_dec(np.array([0j, 1e-13 + 0j, -1.0 + 0j, 1.0 + 0j])),
                                  [0.0, 0.0, np.inf, -np.inf])
