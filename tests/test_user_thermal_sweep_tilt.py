"""A user's thermal sweep of a misaligned machine: the `thermal` analysis over the supply
temperature and the DE housing's misalignment, into parquet, read back with pandas.

Found 2026-12-05 on the five-stage compressor (tests/data/models/compressor5_plain_thermal.toml:
plain bearings, effective-temperature oil system, tilting journals, turbulent films with a
transition ramp): the rows had the temperatures, the flows and the edge film's z, but not the
journal rotations and film moments that `system_thermal_equilibrium(...).to_frame()` and
`rotordyn thermal` give for the same point — a misalignment study's main output silently
dropped. The rows of a model with a tilting film now carry `journal_theta_x_rad`,
`journal_theta_y_rad`, `film_moment_x_n_m`, `film_moment_y_n_m` (flat: one row per film), equal
to the direct call's to 1e-12 relative; a model without a tilting film keeps its schema.
Checked besides: every promised column present, a status per row, a misalignment that
closes the film an `error` row naming the fields, T_max above the supply on every ok row."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.sweep import run_sweep

MODELS = Path(__file__).parent / "data" / "models"
MODEL = MODELS / "compressor5_plain_thermal.toml"
TILT = ["journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m", "film_moment_y_n_m"]
PROMISED = ["bearing", "effective_temperature_c", "max_temperature_c", "inlet_temperature_c",
            "temperature_rise_k", "viscosity_pa_s", "power_loss_w", "film_flow_m3_s",
            "side_flow_m3_s", "supply_flow_m3_s", "journal_x_m", "journal_y_m", "h_min_m",
            "h_min_z_m", "iterations", "status", "message"]


def _spec(tmp_path, model, grid):
    lines = ['schema = "rotordyn/sweep/1"', 'name = "user-thermal-tilt"',
             f'model = "{model}"', 'analysis = "thermal"', "", "[grid]", *grid]
    p = tmp_path / "spec.toml"
    p.write_text("\n".join(lines) + "\n")
    return p


def _direct(system, t_supply, theta):
    th = dataclasses.replace(system.thermal, supply_temperature_c=t_supply)
    b = tuple(dataclasses.replace(x, config_theta_y_rad=theta) if x.name == "DE" else x
              for x in system.bearings)
    return rd.system_thermal_equilibrium(dataclasses.replace(system, thermal=th, bearings=b),
                                         speed_hz=150.0).to_frame()


def test_thermal_sweep_of_a_misaligned_machine_carries_the_moments(tmp_path):
    spec = _spec(tmp_path, MODEL, ['"thermal.supply_temperature_c" = [45.0, 60.0]',
                                   '"bearings.DE.config_theta_y_rad" = [-2e-4, 4e-4, 5e-3]',
                                   "speed_hz = [150.0]"])
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1, progress=False)
    df = pd.read_parquet(out)
    for c in PROMISED + TILT:
        assert c in df.columns, c
    assert len(df) == 2 * 2 * 2 + 2  # two films per ok point, one row per refused point
    bad = df[df["bearings.DE.config_theta_y_rad"] == 5e-3]
    assert (bad.status == "error").all() and len(bad) == 2
    assert bad.message.str.contains("config_theta").all()
    ok = df[df.status == "ok"]
    assert len(ok) == 8
    assert (ok.max_temperature_c > ok["thermal.supply_temperature_c"]).all()
    s = rd.System.from_toml(MODEL)
    for (ts, th), rows in ok.groupby(["thermal.supply_temperature_c",
                                      "bearings.DE.config_theta_y_rad"]):
        ref = _direct(s, ts, th).set_index("bearing")
        rows = rows.set_index("bearing")
        for c in TILT + ["max_temperature_c", "h_min_m", "h_min_z_m"]:
            np.testing.assert_allclose(rows.loc[ref.index, c].to_numpy(), ref[c].to_numpy(),
                                       rtol=1e-12, atol=1e-300, err_msg=f"{c} {ts} {th}")
        # the misaligned DE film carries a moment, its relative rotation ~ -theta
        assert abs(rows.loc["DE", "film_moment_y_n_m"]) > 0.05
        assert rows.loc["DE", "journal_theta_y_rad"] == pytest.approx(-th, rel=0.05)


def test_thermal_sweep_of_an_aligned_model_keeps_its_schema(tmp_path):
    spec = _spec(tmp_path, MODELS / "compressor_plain_thermal.toml",
                 ['"thermal.supply_temperature_c" = [45.0]', "speed_hz = [150.0]"])
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1, progress=False)
    df = pd.read_parquet(out)
    assert not set(TILT) & set(df.columns)
    assert (df.status == "ok").all()
