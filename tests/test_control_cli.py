"""`rotordyn control schedule|closed-loop`: files written under --out, the summary's numbers
consistent with the library (the closed loop of the unstable rig point is stable and its
nonlinear run decays below the open loop's), exit code 2 naming the field on bad input."""

import json

import numpy as np
import pandas as pd

from rotordyn.cli import main


def test_closed_loop_cli_writes_summary_and_series(tmp_path, capsys):
    out = tmp_path / "cl"
    rc = main(["control", "closed-loop", "paper-rig", "--config-ay-m", "-1.85e-3",
               "--chamber-pressure-pa", "0.05e6", "--t-end-s", "0.3", "--n-out", "601",
               "--out", str(out), "--json"])
    assert rc == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["open_loop_max_real_1_per_s"] > 0 > s["closed_loop_max_real_1_per_s"]
    assert s["closed_loop_final_amplitude_m"] < 0.1 * s["open_loop_final_amplitude_m"]
    # the margins of the tuned PD (docs/control.md §3.1): both gain margins, with frequencies
    m = s["margins"]
    assert 0 < m["gain_margin_lower"] < 1 < m["gain_margin_upper"] < 10
    assert m["gain_margin_lower_hz"] > 0 and m["gain_margin_upper_hz"] > 0
    assert 0 < m["delay_margin_s"] < 1 and 0 < m["disk_margin"] < 2
    assert s["margins_message"] == "ok"
    ts = pd.read_csv(out / "timeseries.csv")
    assert len(ts) == 601 and (ts.chamber_pressure_pa >= 0).all()
    assert (out / "closed_loop.png").stat().st_size > 0
    assert json.loads(capsys.readouterr().out)["law"] == "pd"


def test_schedule_cli(tmp_path):
    out = tmp_path / "s"
    rc = main(["control", "schedule", "paper-rig", "--unbalance", "6", "2e-5", "0",
               "--stations", "4", "6", "--config-ay-m", "0", "--speed-hz", "34", "42", "2",
               "--pressure-pa", "0", "0.6e6", "0.2e6", "--min-damping", "0", "--out", str(out)])
    assert rc == 0
    sch = pd.read_csv(out / "schedule.csv")
    grid = pd.read_csv(out / "grid.csv")
    assert len(sch) == 5 and len(grid) == 5 * 4
    # the chosen pressure is the feasible grid point with the smallest objective
    for _, row in sch.iterrows():
        g = grid[(grid.speed_hz == row.speed_hz) & grid.feasible]
        if len(g):
            assert row.objective_m == g.objective_m.min()
            assert np.isclose(row.chamber_pressure_pa,
                              g.chamber_pressure_pa[g.objective_m.idxmin()])
    # with a slope limit the schedule moves at most 0.1 MPa/Hz (0.2 MPa per 2 Hz step)
    out2 = tmp_path / "s2"
    assert main(["control", "schedule", "paper-rig", "--unbalance", "6", "2e-5", "0",
                 "--stations", "4", "6", "--config-ay-m", "0", "--speed-hz", "34", "42", "2",
                 "--pressure-pa", "0", "0.6e6", "0.2e6", "--min-damping", "0",
                 "--smooth-pa-per-hz", "0.05e6", "--out", str(out2)]) == 0
    s2 = pd.read_csv(out2 / "schedule.csv").dropna()
    assert np.all(np.abs(np.diff(s2.chamber_pressure_pa)) <= 0.1e6 + 1e-6)
    # the min-max path cannot beat the pointwise choice's worst point
    assert s2.objective_m.max() >= sch.objective_m.max() - 1e-15


def test_control_cli_bad_input_exit_2(tmp_path, capsys):
    rc = main(["control", "closed-loop", "paper-rig", "--computation-delay-s", "-1e-3",
               "--out", str(tmp_path)])
    assert rc == 2 and "--computation-delay-s" in capsys.readouterr().err
    rc = main(["control", "closed-loop", "paper-rig", "--computation-delay-s", "1e-3",
               "--pade-order", "0", "--out", str(tmp_path)])
    assert rc == 2 and "--pade-order" in capsys.readouterr().err
    rc = main(["control", "closed-loop", "paper-rig", "--valve-hz", "-3", "--out", str(tmp_path)])
    assert rc == 2
    assert "--valve-hz" in capsys.readouterr().err
    rc = main(["control", "schedule", "paper-rig", "--unbalance", "6", "2e-5", "0",
               "--speed-hz", "40", "30", "1", "--out", str(tmp_path)])
    assert rc == 2
    assert "--speed-hz" in capsys.readouterr().err
    rc = main(["control", "closed-loop", "paper-rig", "--t-end-s", "0", "--out", str(tmp_path)])
    assert rc == 2
    assert "--t-end-s" in capsys.readouterr().err
