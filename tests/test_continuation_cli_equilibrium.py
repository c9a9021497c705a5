"""``rotordyn continuation --start equilibrium`` (docs/nonlinear.md "Continuation of
equilibria"): the command line's branch equals rotordyn.continuation(start="equilibrium") bit
for bit, its table, JSON, --plot and --out files, and bad input as exit 2 with one line naming
the flag. Model: the compressor on two plain bearings (tests/data/models/compressor_plain.toml
on a 36 × 6 film grid, written to a TOML file: Hopf speed 126.5 Hz). The fold model's branch
over a model field through the CLI: tests/test_equilibrium_fold.py."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.cli import main
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def compressor(tmp_path_factory):
    s = coarse_models.compressor_plain()
    path = tmp_path_factory.mktemp("model") / "compressor_36x6.toml"
    s.to_toml(path)
    return s, str(path)


def test_cli_speed_branch_equals_api(compressor, tmp_path, capsys):
    """The speed branch 100 → 150 Hz: the JSON record (points, eccentricities, max Re λ,
    unstable counts, the Hopf point) is the API's bit for bit; the text output has the branch
    and its bifurcations; --out writes branch.csv (= to_frame), bifurcations.csv, branch.json
    (= the --json record) and branch.png; --plot the figure."""
    s, model = compressor
    args = ["continuation", model, "--start", "equilibrium", "--vary", "speed_hz",
            "--bounds", "100", "150"]
    out = tmp_path / "out"
    assert main(args + ["--json", "--out", str(out)]) == 0
    rec = json.loads(capsys.readouterr().out)
    br = rd.continuation(s, "speed_hz", (100.0, 150.0), start="equilibrium")
    assert rec["status"] == "ok" and rec["stop"] == br.stop == "bound"
    assert rec["start"] == "equilibrium" and rec["vary"] == "speed_hz"
    assert rec["bearings"] == list(br.bearing_names)
    for key in ("parameter", "eccentricity_ratio", "journal_x_m", "journal_y_m",
                "max_real_1_per_s", "freq_hz", "n_unstable", "stable", "tangent_p"):
        assert rec[key] == getattr(br, key).tolist(), key
    assert [(b["kind"], b["parameter"]) for b in rec["bifurcations"]] == [
        (b["kind"], b["parameter"]) for b in br.bifurcations]
    assert [b["kind"] for b in rec["bifurcations"]] == ["hopf"]
    assert rec["bifurcations"][0]["parameter"] == pytest.approx(126.5, abs=0.01)
    df = pd.read_csv(out / "branch.csv")
    ref = br.to_frame()
    assert list(df.columns) == list(ref.columns) and len(df) == len(ref)
    for c in ("speed_hz", "eccentricity_ratio", "max_real_1_per_s"):
        np.testing.assert_array_equal(df[c].to_numpy(), ref[c].to_numpy())
    assert list(pd.read_csv(out / "bifurcations.csv")["kind"]) == ["hopf", "hopf"]
    assert json.loads((out / "branch.json").read_text()) == rec
    assert (out / "branch.png").stat().st_size > 0
    fig = tmp_path / "eq.png"
    assert main(args + ["--plot", str(fig)]) == 0
    text = capsys.readouterr().out
    assert "EquilibriumBranchResult ok" in text and "eccentricity_ratio" in text
    assert "bifurcations:" in text and "hopf" in text
    assert fig.stat().st_size > 0


def test_cli_field_branch_equals_api(compressor, capsys):
    """A model field: both clearances from 100 µm down at 130 Hz (the text output and the
    JSON equal the API's branch; 6 points)."""
    s, model = compressor
    args = ["continuation", model, "--start", "equilibrium", "--vary",
            "bearings.*.clearance_m", "--bounds", "60e-6", "100e-6", "--speed-hz", "130",
            "--direction", "-1", "--max-points", "6", "--json"]
    assert main(args) == 0
    rec = json.loads(capsys.readouterr().out)
    br = rd.continuation(s, "bearings.*.clearance_m", (60e-6, 100e-6), speed_hz=130.0,
                         direction=-1, max_points=6)
    assert rec["parameter"] == br.parameter.tolist() and len(br) == 6
    assert rec["parameter"][0] == 100e-6 and rec["stop"] == "max_points"
    assert rec["fixed"] == {"speed_hz": 130.0, "chamber_pressure_pa": 0.0,
                            "config_ay_m": None}
    assert rec["max_real_1_per_s"] == br.max_real_1_per_s.tolist()


@pytest.mark.parametrize("extra, flag, says", [
    (["--vary", "bearings.*.clearence_m", "--bounds", "6e-5", "1e-4"], "--vary", "unknown"),
    (["--vary", "clearance", "--bounds", "6e-5", "1e-4"], "--vary", "unknown"),
    (["--vary", "speed_hz", "--bounds", "150", "100"], "--bounds", ""),
    (["--vary", "bearings.*.clearance_m", "--bounds", "2e-4", "3e-4"], "--bounds",
     "must contain"),
    (["--vary", "speed_hz", "--bounds", "-10", "100"], "--bounds", "0 Hz"),
    (["--vary", "chamber_pressure_pa", "--bounds", "0", "1e5"], "--vary",
     "active journal bearing"),
    (["--vary", "config_ay_m", "--bounds", "-1e-4", "1e-4"], "--vary", "config_ay_m"),
    (["--vary", "speed_hz", "--bounds", "100", "150", "--ds", "0"], "--ds", ""),
    (["--vary", "speed_hz", "--bounds", "100", "150", "--max-points", "0"], "--max-points",
     ""),
    (["--vary", "speed_hz", "--bounds", "100", "150", "--rtol", "1e-6"], "--rtol",
     "--start orbit"),
    (["--vary", "speed_hz", "--bounds", "100", "150", "--unbalance", "3,1e-3,0"],
     "--unbalance", "--start orbit"),
    (["--vary", "speed_hz", "--bounds", "100", "150", "--newton", "fast"], "--newton",
     "--start orbit"),
    (["--vary", "speed_hz", "--bounds", "100", "150", "--kind", "forced"], "--kind",
     "--start orbit"),
])
def test_cli_bad_input_names_the_flag(compressor, capsys, extra, flag, says):
    """Exit 2 and one line on stderr naming the flag (before any branch point is solved)."""
    _, model = compressor
    assert main(["continuation", model, "--start", "equilibrium"] + extra) == 2
    cap = capsys.readouterr()
    err = cap.err.strip()
    assert len(err.splitlines()) == 1 and cap.out == ""
    assert err.startswith(f"rotordyn: error: {flag}:") and says in err, err


def test_a_field_that_does_not_act_on_the_model_is_refused(compressor, capsys, tmp_path):
    """A disk's outer diameter is read by drawings only when its mass and inertias are given:
    a branch over it would repeat one point. The API refuses it naming vary (the matrices,
    loads and film forces equal at both bounds), the CLI naming --vary; a field that acts
    (the disk's mass) is accepted."""
    s, _ = compressor
    disks = list(s.rotor.disks)
    disks[0] = dataclasses.replace(disks[0], outer_diameter_m=0.4)
    s = dataclasses.replace(s, rotor=dataclasses.replace(s.rotor, disks=tuple(disks)))
    with pytest.raises(rd.InputError, match="^vary: rotor.disks.0.outer_diameter_m does "
                                            "not act on the model"):
        rd.continuation(s, "rotor.disks.0.outer_diameter_m", (0.3, 0.5), speed_hz=100.0)
    br = rd.continuation(s, "rotor.disks.0.mass_kg", (25.0, 35.0), speed_hz=100.0,
                         max_points=2)
    assert br.ok and len(br) == 2 and br.eccentricity_ratio[1, 0] != br.eccentricity_ratio[0, 0]
    path = tmp_path / "m.toml"
    s.to_toml(path)
    assert main(["continuation", str(path), "--start", "equilibrium", "--vary",
                 "rotor.disks.0.outer_diameter_m", "--bounds", "0.3", "0.5"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("rotordyn: error: --vary: rotor.disks.0.outer_diameter_m does not "
                          "act on the model")


def test_cli_orbit_start_refuses_equilibrium_flags_and_fields(compressor, capsys):
    """The orbit branch (the default --start) by shooting takes p_c, speed or a_y only (a
    model field: harmonic-balance correctors) and not the equilibrium's --no-refine: exit 2
    naming the flag before the start orbit is solved."""
    _, model = compressor
    assert main(["continuation", model, "--vary", "bearings.0.clearance_m", "--bounds",
                 "6e-5", "1e-4"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("rotordyn: error: --method:") and "bearings.0.clearance_m" in err
    assert "--method harmonic_balance" in err
    assert main(["continuation", model, "--vary", "bearings.0.clearence_m", "--bounds",
                 "6e-5", "1e-4", "--method", "harmonic_balance"]) == 2
    assert capsys.readouterr().err.startswith("rotordyn: error: --vary: unknown parameter "
                                              "'bearings.0.clearence_m'")
    assert main(["continuation", model, "--vary", "speed_hz", "--bounds", "100", "150",
                 "--no-refine"]) == 2
    assert capsys.readouterr().err.startswith("rotordyn: error: --no-refine:")
