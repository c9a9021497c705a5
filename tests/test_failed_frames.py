"""A failed equilibrium's table has no state (the rule "a result is either right or marked as
not right"): ``EquilibriumResult.to_frame()`` and ``SystemThermalResult.to_frame()`` write NaN
in the position, film, sleeve and tilt columns of a result that did not converge — as the
sweep rows always did — and keep the inputs, counters, status and message; the attributes keep
the last iterate for diagnosis. Before, the frames showed the last iterate's journal position
beside a failed status. On the compressor of tests/data/models on plain bearings (not the paper
rig)."""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd

MODEL = Path(__file__).parent / "data" / "models" / "compressor_plain_thermal.toml"
STATE = ["journal_x_m", "journal_y_m", "x_over_c", "y_over_c", "eccentricity_ratio", "h_min_m",
         "h_min_angle_deg"]


@pytest.fixture(scope="module")
def compressor():
    return rd.System.from_toml(MODEL)


def test_a_failed_equilibrium_frame_has_no_position(compressor):
    # a film of 1e-6 Pa s cannot carry the rotor at 150 Hz: no equilibrium
    thin = dataclasses.replace(compressor, bearings=[
        dataclasses.replace(b, viscosity_pa_s=1e-6) for b in compressor.bearings])
    e = rd.equilibrium(thin, speed_hz=150.0, warm_start=False)
    assert e.status == "no_equilibrium" and not e.converged
    assert np.all(np.isfinite(e.journal_x_m))  # the last iterate, kept for diagnosis
    df = e.to_frame()
    assert df[STATE].isna().all().all()
    assert list(df["status"]) == ["no_equilibrium"] * 2
    assert df["message"].str.contains("no equilibrium").all()
    assert (df["speed_hz"] == 150.0).all() and (df["iterations"] > 0).all()
    assert np.isfinite(df["residual"]).all()
    ok = rd.equilibrium(compressor, speed_hz=150.0)
    assert ok.status == "ok" and np.isfinite(ok.to_frame()[STATE].to_numpy()).all()


def test_a_failed_thermal_frame_has_no_state(compressor):
    t = rd.system_thermal_equilibrium(compressor, speed_hz=150.0)
    assert t.status == "ok"
    good = t.to_frame()
    assert np.isfinite(good[["max_temperature_c", "journal_x_m", "h_min_m"]].to_numpy()).all()
    # a real failure, not a relabelled success: both housings misaligned by 3.95 mrad (the
    # aligned shaft's edge gap 1.25 um, tests/test_tilt_use.py) close the films, so the
    # thermal equilibrium's system equilibrium has no solution
    tilted = dataclasses.replace(compressor, bearings=[
        dataclasses.replace(b, n_circ=48, n_axial=6, tilt=True, config_theta_y_rad=3.95e-3)
        for b in compressor.bearings])
    f = rd.system_thermal_equilibrium(tilted, speed_hz=150.0)
    assert f.status in ("no_equilibrium", "not_converged") and f.message
    bad = f.to_frame()
    state = [c for c in bad.columns if c not in ("speed_hz", "supply_temperature_c", "bearing",
                                                   "thermal_model", "status", "message")]
    assert "max_temperature_c" in state and "journal_x_m" in state
    assert bad[state].isna().all().all()
    assert list(bad["status"]) == [f.status] * 2 and (bad["message"] == f.message).all()
    assert (bad["supply_temperature_c"] == good["supply_temperature_c"]).all()


def test_an_unbalance_sweep_row_of_a_failed_speed_has_no_peak_verdict():
    """``peak`` (BOOL) is null, not False, at a speed without a converged equilibrium (no
    response there); the column keeps its True/False where the equilibrium converged. The
    active compressor at p_c = 1e9 Pa (no equilibrium) beside p_c = 0, each speed at its own
    thermal equilibrium (tests/test_thermal_sweep.py's case)."""
    from test_thermal_sweep import CASES, _job

    from rotordyn.sweep.work import run_chunk

    model, analysis, options, axes = CASES["unbalance-no-equilibrium"]
    job = _job(model(), analysis, options, axes)
    t = run_chunk(job, 2, 0, int(np.prod(job.shape))).to_pandas()
    failed = t["status"] != "ok"
    assert failed.any() and (~failed).any()
    assert t.loc[failed, "peak"].isna().all()
    assert t.loc[~failed, "peak"].notna().all()
