"""``--thermal`` / ``--thermal-model`` of ``rotordyn stability``, ``campbell`` and ``unbalance``
and ``options.thermal`` of ``rotordyn sweep`` (issue 20), on the compressor on plain bearings
with its oil system (tests/data/models/compressor_plain_thermal.toml, not the paper rig):
exit 0 with the thermal columns present and equal to the Python calls' (1e-12 relative: the
same calls), exit 2 with a message naming the field on bad input."""

import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.results.thermal import THERMAL_POINT_COLUMNS

MODELS = Path(__file__).parent / "data" / "models"
THERMAL = str(MODELS / "compressor_plain_thermal.toml")
PLAIN = str(MODELS / "compressor_plain.toml")  # no [thermal] table
NAMES = ["NDE bearing", "DE bearing"]


@pytest.fixture(scope="module")
def system():
    return rd.System.from_toml(THERMAL)


def test_stability_thermal(capsys, system):
    assert main(["stability", THERMAL, "--speed-hz", "150", "--thermal", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    t = out["thermal"]
    assert t["status"] == "ok" and t["model"] == "effective" and t["film"] == NAMES
    ref = rd.stability(system, 150.0, thermal=True)
    np.testing.assert_allclose(t["effective_temperature_c"],
                               ref.thermal.effective_temperature_c, rtol=1e-12)
    np.testing.assert_allclose(out["modes"]["eig_real_1_per_s"],
                               ref.eigenvalues.real[:len(out["modes"]["eig_real_1_per_s"])],
                               rtol=1e-12)
    # the isothermal call prints no thermal state
    assert main(["stability", THERMAL, "--speed-hz", "150", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["thermal"] is None
    assert main(["stability", THERMAL, "--speed-hz", "150", "--thermal",
                 "--thermal-model", "thd"]) == 0
    err = capsys.readouterr().err
    assert "thd model, field frozen" in err and "T_eff" in err


def test_campbell_thermal(capsys, system):
    assert main(["campbell", THERMAL, "--speeds-hz", "100,150", "--thermal", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert len(out["thermal"]) == 2 and out["point_status"] == ["ok", "ok"]
    ref = rd.campbell(system, [100.0, 150.0], thermal=True)
    for t, r in zip(out["thermal"], ref.thermal):
        assert t["film"] == NAMES and t["status"] == "ok"
        np.testing.assert_allclose(t["max_temperature_c"], r.max_temperature_c, rtol=1e-12)
    assert main(["campbell", THERMAL, "--speeds-hz", "100,150", "--thermal"]) == 0
    err = capsys.readouterr().err
    assert "each speed at its own thermal equilibrium" in err and "150 Hz: T_max" in err


def test_unbalance_thermal(capsys, system):
    assert main(["unbalance", THERMAL, "--unbalance", "3,1e-4,0", "--speeds-hz", "100,150",
                 "--thermal", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    resp = out["response"]
    for c in THERMAL_POINT_COLUMNS:
        assert c in resp, c
    assert all(f == NAMES for f in resp["film"])
    assert np.all(np.isfinite(resp["max_temperature_c"]))
    ref = rd.unbalance_response(system, [(3, 1e-4, 0.0)], [100.0, 150.0], thermal=True)
    np.testing.assert_allclose(resp["amplitude_x_m"], np.abs(ref.x[:, 0]), rtol=1e-12)
    np.testing.assert_allclose(resp["power_loss_w"],
                               [t.power_loss_w.sum() for t in ref.thermal], rtol=1e-12)
    assert len(out["thermal"]) == len(resp["speed_hz"])


@pytest.mark.parametrize("args, field", [
    (["stability", THERMAL, "--thermal-model", "thd"], "--thermal-model"),
    (["stability", PLAIN, "--thermal"], "--thermal"),
    (["campbell", PLAIN, "--speeds-hz", "100,150", "--thermal"], "--thermal"),
    (["unbalance", PLAIN, "--unbalance", "3,1e-4,0", "--speeds-hz", "100", "--thermal"],
     "--thermal"),
    (["campbell", THERMAL, "--speeds-hz", "100,150", "--thermal", "--thermal-model", "hot"],
     "--thermal-model"),
])
def test_bad_input_exit_2_names_the_field(capsys, args, field):
    try:
        code = main(args)
    except SystemExit as exc:  # argparse's own refusal (a choice outside the list)
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err
    assert field in err
    assert "Traceback" not in err


SPEC = """
schema = "rotordyn/sweep/1"
name = "t-thermal-cli"
model = "{model}"
analysis = "stability"

[grid]
speed_hz = [100.0, 150.0]

[options.thermal]
{thermal}
"""


@pytest.mark.parametrize("model, thermal, field", [
    (THERMAL, "carry_over = 2.0", "options.thermal.carry_over"),
    (THERMAL, "oil = 3.0", "options.thermal.oil"),
    (PLAIN, "tol_k = 1e-6", "options.thermal"),
])
def test_sweep_bad_thermal_options_exit_2(tmp_path, capsys, model, thermal, field):
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC.format(model=Path(model).as_posix(), thermal=thermal))
    assert main(["sweep", str(spec), "--out", str(tmp_path / "o"), "--threads", "1"]) == 2
    err = capsys.readouterr().err
    assert field in err and "Traceback" not in err
    assert not (tmp_path / "o").exists() or not list((tmp_path / "o").glob("*.parquet"))


def test_a_failed_speed_says_why_on_the_command_line(tmp_path, capsys, system):
    """A speed whose thermal equilibrium raised (the oil law's range ends at 80 degC; the NDE
    film exceeds it at 200 Hz, not at 100 Hz; 85 degC and the DE film before the DE bearing's
    metered supply was raised to a fed 3e-4 m³/s, 2026-12-06): its --json thermal entry is its
    status and why (it was null) and the text summary gives the reason (it said only "thermal
    equilibrium failed")."""
    import dataclasses

    oil = dataclasses.replace(system.thermal.oil, t_max_c=80.0)
    s = dataclasses.replace(system, thermal=dataclasses.replace(system.thermal, oil=oil),
                            bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=8)
                                           for b in system.bearings))
    path = str(tmp_path / "m.toml")
    s.to_toml(path)
    assert main(["campbell", path, "--speeds-hz", "100,200", "--thermal", "--json"]) == 0
    th = json.loads(capsys.readouterr().out)["thermal"]
    assert th[0]["status"] == "ok" and th[1]["status"] == "error"
    assert "t_max_c = 80 degC" in th[1]["message"]
    assert main(["unbalance", path, "--unbalance", "3,1e-4,0", "--speeds-hz", "100,200",
                 "--thermal"]) == 0
    err = capsys.readouterr().err
    assert "200 Hz: thermal equilibrium failed (ConvergenceError: " in err
    assert "viscosity law's range (t_max_c = 80 degC)" in err


def test_threshold_thermal(tmp_path, capsys, system):
    """``rotordyn threshold --thermal``: each scanned point at its own thermal equilibrium, as
    ``rotordyn.threshold(..., thermal=True)`` (the flag was missing; exit 2 naming --thermal
    on a model without an oil system)."""
    import dataclasses

    s = dataclasses.replace(system, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=8)
                                                   for b in system.bearings))
    path = str(tmp_path / "m.toml")
    s.to_toml(path)
    args = ["threshold", path, "--vary", "speed_hz", "--bounds", "120", "130", "--n-scan", "3"]
    assert main(args + ["--thermal", "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    ref = rd.threshold(s, "speed_hz", bounds=(120.0, 130.0), n_scan=3, thermal=True)
    assert got["status"] == "ok" and got["speed_hz"] == ref.value
    assert main(["threshold", PLAIN, "--vary", "speed_hz", "--bounds", "120", "130",
                 "--thermal"]) == 2
    assert "--thermal" in capsys.readouterr().err
