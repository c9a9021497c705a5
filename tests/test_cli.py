"""CLI: JSON outputs and exit codes (0 ok, 2 bad input naming the field)."""

import json
import subprocess
import sys

import pytest


def run(*args):
    return subprocess.run([sys.executable, "-m", "rotordyn.cli", *args], capture_output=True,
                          text=True)


def test_modes_paper_rig_json_has_full_and_condensed():
    p = run("modes", "paper-rig", "--reduction", "guyan", "--json", "--without-bearings")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    f, g = d["frequencies_hz"], d["full_frequencies_hz"]
    assert f == sorted(f) and len(f) == 6 and len(g) == 6
    assert abs(f[0] - 10.43) / 10.43 < 0.01


def test_modes_full_model_json():
    p = run("modes", "friswell-5.9.1", "--speed-hz", str(4000 / 60), "--json", "--n-modes", "4")
    d = json.loads(p.stdout)
    assert "full_frequencies_hz" not in d and len(d["frequencies_hz"]) == 4


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (("modes", "no-such-model"), "model"),
        (("modes", "paper-rig", "--speed-hz", "fast"), "--speed-hz"),
        (("modes", "paper-rig", "--n-modes", "0", "--without-bearings"), "n_modes"),
        (("modes", "paper-rig", "--reduction", "magic"), "--reduction"),
    ],
)
def test_bad_input_exits_2_naming_the_field(args, needle):
    p = run(*args)
    assert p.returncode == 2
    assert needle in p.stderr


def test_toml_path_model(tmp_path):
    import rotordyn as rd

    path = tmp_path / "rig.toml"
    rd.models.paper_rig().to_toml(path)
    p = run("modes", str(path), "--json", "--without-bearings")
    assert p.returncode == 0
    bad = tmp_path / "bad.toml"
    bad.write_text(path.read_text().replace("mass_kg = ", "mass_kg = -", 1))  # disk[0]
    p = run("modes", str(bad), "--json")
    assert p.returncode == 2 and "disk[0].mass_kg" in p.stderr


def test_equilibrium_cli_json_and_negative_config():
    p = run("equilibrium", "paper-rig", "--speed-hz", "50", "--chamber-pressure-pa", "1.5e5",
            "--config-ay-m", "-1.85e-3", "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    assert d["status"] == "ok" and d["residual"] < 1e-8
    assert isinstance(d["bearings"], dict) and len(d["bearings"]) == 1
    b = next(iter(d["bearings"].values()))
    assert b["config_ay_m"] == -1.85e-3 and abs(b["x_over_c"]) < 1 and len(b["sleeve_m"]) == 3


def test_equilibrium_cli_bad_pressure_exits_2():
    p = run("equilibrium", "paper-rig", "--chamber-pressure-pa", "-5")
    assert p.returncode == 2 and "chamber_pressure_pa" in p.stderr


def test_python_m_rotordyn_is_the_command():
    p = subprocess.run([sys.executable, "-m", "rotordyn", "--version"], capture_output=True,
                       text=True)
    q = run("--version")
    assert p.returncode == 0 == q.returncode, p.stderr
    assert p.stdout == q.stdout and p.stdout.strip()
