"""Control laws on a model whose active bearing is not ``bearings[0]``.

tests/data/models/compressor_active.toml lists the plain NDE bearing first and the active DE
bearing second. Before 2026-12-06 the plant's performance output ``C_perf`` (the journal the
LQR/LQG/H∞ designs weigh, documented as the active bearing's) was journal 0 — the plain
bearing's — whatever the model; ``tune_pd`` refused any plant not measuring ``("journal",
0)``, so the active bearing's own journal could not be used; and ``rotordyn control
closed-loop`` measured journal 0 and reported journal 0's deviation while the transient
disturbed the active journal (the first sample of its "journal deviation" was 0, not the
disturbance). The operating point: 170 Hz, p_c = 0.1 MPa, a_y = 0, where the open loop's
max Re λ is +12.2 1/s (oil whip; rotordyn.stability).
"""

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.analysis.measurement import measurement_matrix
from rotordyn.cli import main
from rotordyn.control.plant import plant
from rotordyn.control.pid import tune_pd

MODEL = Path(__file__).parent / "data" / "models" / "compressor_active.toml"
F, PC, AY = 170.0, 0.1e6, 0.0


@pytest.fixture(scope="module")
def system():
    return rd.System.from_toml(MODEL)


def test_performance_output_is_the_active_journal(system):
    from rotordyn.control.plant import active_bearing_index

    assert active_bearing_index(system) == 1
    assert active_bearing_index(rd.models.paper_rig()) == 0
    p = plant(system, F, PC, AY)
    Cj, _ = measurement_matrix(system, [("journal", 1)])
    assert np.array_equal(p.C_perf[:, :Cj.shape[1]], Cj)
    assert not np.any(p.C_perf[:, Cj.shape[1]:])  # nothing on the valve states
    assert p.performance_names == ("performance_journal_x_m[1]", "performance_journal_y_m[1]")


def test_tune_pd_on_the_active_journal(system):
    p = plant(system, F, PC, AY, measurements=[("journal", 1)])
    assert p.poles.real.max() > 5.0  # unstable open loop
    k, cl = tune_pd(p)
    assert k.measurements == (("journal", 1),)
    assert cl.max_real < -5.0
    tr = rd.transient(system, 0.6, F, PC, AY, disturbance_m=(0.0, 5e-6), controller=k,
                      actuator=p.actuator, n_out=1201)
    assert tr.status == "ok"
    y = tr.journal_y_m[:, 1] - tr.equilibrium_r[_jy(system, 1)]
    assert abs(y[0] - 5e-6) < 1e-9  # the disturbed journal is the measured one
    # and the law brings it back: the least damped closed-loop pair decays at 11.1 1/s, the
    # orbit grows to ~1.7e-5 m in the first 0.1 s, then falls ~e^(-11.1 · 0.5) ≈ 4e-3
    assert np.abs(y[-200:]).max() < 0.05 * np.abs(y).max()


def _jy(system, b):
    from rotordyn.analysis.assembly import assembled

    return assembled(system).bearings[b].jy


def test_tune_pd_refuses_other_measurements(system):
    p = plant(system, F, PC, AY, measurements=[("journal", 0), ("journal", 1)])
    with pytest.raises(rd.InputError, match="plant.measurements"):
        tune_pd(p)


def test_closed_loop_cli_acts_on_the_active_journal(system, tmp_path):
    out = tmp_path / "cl"
    rc = main(["control", "closed-loop", str(MODEL), "--speed-hz", str(F),
               "--chamber-pressure-pa", str(PC), "--config-ay-m", "0", "--t-end-s", "0.2",
               "--disturbance-c", "0.05",
               "--n-out", "201", "--out", str(out), "--json"])
    assert rc == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["journal_bearing"] == "DE active bearing"
    assert s["open_loop_max_real_1_per_s"] > 0 > s["closed_loop_max_real_1_per_s"]
    ts = pd.read_csv(out / "timeseries.csv")
    e = rd.equilibrium(system, F, PC, AY, warm_start=False)
    y0 = e.journal_y_m[1]
    # --disturbance-c 0.05 of the 0.1 mm clearance, on the journal it reports
    assert ts.closed_loop_journal_y_m[0] - y0 == pytest.approx(5e-6, abs=1e-9)
    assert ts.open_loop_journal_y_m[0] - y0 == pytest.approx(5e-6, abs=1e-9)
    assert s["closed_loop_status"] == "ok"


def test_design_scale_is_the_active_bearings_clearance(system):
    """The LQR/LQG/H∞ length scale defaults to the performance journal's clearance (0.1 mm
    here), not the paper rig's 0.3 mm it had been on every model (the journal's weight in Q
    was then 9× too small against the command); a given clearance_m is used by the LQG's
    Kalman scaling too (it had been ignored there)."""
    from rotordyn.control.lqr import default_weights, design_clearance, lqg, lqr

    p = plant(system, F, PC, AY, measurements=[("journal", 1)])
    assert p.info["performance_clearance_m"] == 1e-4
    assert design_clearance(p, None) == 1e-4
    Q, R = default_weights(p)
    Qc, Rc = default_weights(p, clearance_m=1e-4)
    Q3, _ = default_weights(p, clearance_m=3e-4)
    assert np.array_equal(Q, Qc) and np.array_equal(R, Rc)
    ia = np.flatnonzero(np.abs(p.C_perf).sum(axis=0))[0]
    assert Q[ia, ia] == pytest.approx(9.0 * Q3[ia, ia], rel=1e-9)
    K, _ = lqr(p)
    assert np.array_equal(K, lqr(p, clearance_m=1e-4)[0])
    # the rig keeps its 0.3 mm (its only bearing is the active one): its designs unchanged
    rig = plant(rd.models.paper_rig(), 50.0, 0.05e6, -1.85e-3)
    assert design_clearance(rig, None) == 3e-4
    k1, k2 = lqg(p), lqg(p, clearance_m=1e-4)
    assert np.array_equal(k1.A, k2.A) and np.array_equal(k1.B, k2.B)
