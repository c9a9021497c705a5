"""``grid_check`` (l1 again with every film grid refined twice; a type that changes with the
grid is ``degenerate``; docs/nonlinear.md "l1 on cavitated films") in the sweep analysis
``hopf`` (``options.grid_check``, column ``l1_refined``) and on the command line
(``rotordyn hopf --grid-check``), against rotordyn.hopf(..., grid_check=True).

Model: the compressor on two plain bearings (tests/data/models/compressor_plain.toml on a
36 × 6 film grid, refined to 72 × 12; Hopf speed ≈ 126 Hz), two lines of the NDE bearing's
clearance. Tolerances as the rig's hopf rows (tests/test_hopf.py): the sweep solves each
crossing's equilibrium cold on a fresh solver, rotordyn.hopf on this thread's (the same root
polished to round-off): l1 and l1_refined 1e-6 relative, the type equal; 1 thread and 2 worker
processes bit for bit."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.model.paths import set_field
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"

SWEEP = """schema = "rotordyn/sweep/1"
name = "hopf-grid-check"
model = "{model}"
analysis = "hopf"
chunk_size = 1

[grid]
speed_hz = {{start = 100.0, stop = 150.0, num = 6}}
bearings.0.clearance_m = [0.9e-4, 1.0e-4]

[options]
vary = "speed_hz"
{options}
"""


@pytest.fixture(scope="module")
def compressor(tmp_path_factory):
    s = coarse_models.compressor_plain()
    path = tmp_path_factory.mktemp("model") / "compressor_36x6.toml"
    s.to_toml(path)
    return s, str(path)


def _run(tmp_path, model, options, name, **kw):
    from rotordyn.sweep import open as open_dataset
    from rotordyn.sweep import run_sweep

    spec = tmp_path / f"{name}.toml"
    spec.write_text(SWEEP.format(model=model, options=options))
    assert run_sweep(spec, tmp_path / name, progress=False, **kw).complete
    return open_dataset(tmp_path / name).frame


def test_hopf_sweep_grid_check_rows_equal_rotordyn_hopf(compressor, tmp_path):
    """Each crossing's l1, l1_refined, l1_error and type equal rotordyn.hopf(at=crossing,
    grid_check=True) on the line's model; l1 and dRe λ/dp are those of the sweep without the
    check (it only adds l1_refined and widens the error); without it l1_refined is NaN; the
    rows are the same bit for bit on 1 thread and in 2 worker processes."""
    s, model = compressor
    fa = _run(tmp_path, model, "grid_check = true", "a", threads=1)
    fb = _run(tmp_path, model, "grid_check = true", "b", workers=2)
    pd.testing.assert_frame_equal(fa, fb, check_exact=True)
    plain = _run(tmp_path, model, "", "plain", threads=1)
    ok = fa[fa["status"] == "ok"]
    assert len(ok) == 2 and np.all(np.isfinite(ok["l1_refined"]))
    assert plain["l1_refined"].isna().all()
    np.testing.assert_array_equal(ok["l1"], plain[plain["status"] == "ok"]["l1"])
    np.testing.assert_array_equal(ok["value"], plain[plain["status"] == "ok"]["value"])
    assert np.all(ok["l1_error"].to_numpy()
                  >= plain[plain["status"] == "ok"]["l1_error"].to_numpy())
    for _, row in ok.iterrows():
        line = set_field(s, "bearings.0.clearance_m", float(row["bearings.0.clearance_m"]))
        h = rd.hopf(line, "speed_hz", at=float(row["value"]), grid_check=True)
        assert h.ok
        assert row["l1"] == pytest.approx(h.l1, rel=1e-6)
        assert row["l1_refined"] == pytest.approx(h.l1_refined, rel=1e-6)
        assert row["l1_error"] == pytest.approx(h.l1_error, rel=1e-6)
        assert row["hopf_type"] == h.type
        # the check decides the type: |l1| against max(fit error, |l1_refined − l1|)
        err = max(float(plain.loc[row.name, "l1_error"]), abs(row["l1_refined"] - row["l1"]))
        assert row["l1_error"] == pytest.approx(err, rel=1e-12)
        assert (row["hopf_type"] == "degenerate") == (abs(row["l1"]) < 3 * err)


def test_hopf_sweep_grid_check_option_is_checked(compressor, tmp_path):
    from rotordyn.sweep import SweepSpec

    _, model = compressor
    bad = tmp_path / "bad.toml"
    bad.write_text(SWEEP.format(model=model, options='grid_check = "yes"'))
    with pytest.raises(rd.InputError, match="options.grid_check: expected true or false"):
        SweepSpec.from_toml(bad)


def test_cli_hopf_grid_check_equals_api(compressor, capsys):
    """``rotordyn hopf --grid-check --json``: l1, l1_refined, l1_error and the type of
    rotordyn.hopf(..., grid_check=True); without the flag l1_refined is null and the JSON
    says grid_check false; the text output names the refined l1."""
    from rotordyn.cli import main

    s, model = compressor
    h = rd.hopf(s, "speed_hz", bounds=(100.0, 150.0), grid_check=True)
    assert h.ok and math.isfinite(h.l1_refined)
    args = ["hopf", model, "--vary", "speed_hz", "--bounds", "100", "150"]
    assert main(args + ["--grid-check", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["grid_check"] is True and rec["value"] == pytest.approx(h.value, rel=1e-12)
    for key, val in (("l1", h.l1), ("l1_refined", h.l1_refined), ("l1_error", h.l1_error)):
        assert rec[key] == pytest.approx(val, rel=1e-6), key
    assert rec["type"] == h.type
    assert main(args + ["--json"]) == 0
    rec0 = json.loads(capsys.readouterr().out)
    assert rec0["grid_check"] is False and rec0["l1_refined"] is None
    assert rec0["l1"] == pytest.approx(h.l1, rel=1e-6)
    assert main(args + ["--grid-check"]) == 0
    assert "on the refined films" in capsys.readouterr().out
