"""A harmonic-balance limit cycle from the equilibrium without a start amplitude tries 0.3,
0.6 and 0.9 of the clearance in turn. On a three-bearing motor-fan train at 110 Hz, above its
oil-whip threshold (~102 Hz), the whip cycle (115.7 µm, near the 120 µm clearance) is out of
Newton's reach from 0.3: the default call failed and the CLI's advice was a settling
transient (3 min CPU on the unreduced model). Found in an engineer's pass, not on the rig."""

from pathlib import Path

import pytest

import rotordyn as rd

MODEL = Path(__file__).parent / "data" / "models" / "motor_fan_train_guyan.toml"


@pytest.fixture(scope="module")
def train():
    return rd.System.from_toml(MODEL)


def test_default_start_reaches_the_whip_cycle(train):
    low = rd.periodic_orbit(train, 110.0, method="harmonic_balance", start_amplitude_c=0.3)
    assert not low.ok  # the old default start fails here: the test can fail
    res = rd.periodic_orbit(train, 110.0, method="harmonic_balance")
    assert res.ok, res.message
    assert res.stats["start_amplitude_c"] in (0.6, 0.9)
    # the same cycle as an explicit start near its size
    ref = rd.periodic_orbit(train, 110.0, method="harmonic_balance", start_amplitude_c=0.9)
    assert res.period_s == pytest.approx(ref.period_s, rel=1e-6)
    assert res.amplitude(0) == pytest.approx(ref.amplitude(0), rel=1e-6)
    assert 100e-6 < res.amplitude(0) < 120e-6


def test_a_failed_ladder_names_every_start(train):
    """Below the threshold (90 Hz: a stable equilibrium, no cycle to find with 2 Newton
    iterations) the failure names the three starts tried."""
    res = rd.periodic_orbit(train, 90.0, method="harmonic_balance", max_iter=2)
    assert not res.ok
    assert "at 0.3, 0.6" in res.message and "of the clearance in turn" in res.message


def test_cli_floquet_tol(capsys):
    """--floquet-tol reaches the refinement: 0 is the single product (no error estimate),
    the default refines (floquet_error in the stats); with shooting it needs --floquet samples
    (since 2026-12-06 shooting takes it) and a value > 0."""
    import json

    from rotordyn.cli import main

    base = ["periodic-orbit", str(MODEL), "--speed-hz", "110", "--start-amplitude-c", "0.9",
            "--json"]
    assert main(base + ["--method", "harmonic_balance", "--floquet-tol", "0"]) == 0
    assert "floquet_error" not in json.loads(capsys.readouterr().out)["stats"]
    assert main(base + ["--method", "harmonic_balance"]) == 0
    assert json.loads(capsys.readouterr().out)["stats"]["floquet_error"] > 0
    assert main(["periodic-orbit", str(MODEL), "--floquet-tol", "1e-3"]) == 2
    assert "--floquet-tol: applies only to --floquet samples" in capsys.readouterr().err
    assert main(["periodic-orbit", str(MODEL), "--floquet", "samples", "--floquet-tol",
                 "0"]) == 2
    assert "--floquet-tol: with --method shooting expected a value in (0, 0.5]" in \
        capsys.readouterr().err
