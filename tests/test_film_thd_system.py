"""Thermo-hydrodynamic films in a system (issue 20): the compressor of tests/data/models on two
plain journal bearings with ``model="thd"``.

The rotor on two bearings is statically determinate: each bearing carries its share of the
weight whatever its temperature field, so the system's THD equilibrium must equal, bearing by
bearing, the standalone THD equilibrium (JournalBearing.thermal_equilibrium(model="thd"),
checked in tests/test_film_thd.py) under the load its film carries: temperatures to 1e-4 K,
positions to 1e-6 of the clearance. The returned system carries each film's frozen viscosity
field: its equilibrium reproduces the thermal one, its stability and Campbell diagram run, its
transient follows the linear model at small amplitude; the model file's ``[thermal] model = "thd"`` round-trips and selects the THD film.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import Oil
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def _compressor():
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


def test_system_thd_equals_standalone_bearings_and_its_dynamics_run():
    s = _compressor()
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, oil=VG32,
                                              supply_temperature_c=45.0, model="thd")
    assert res.status == "ok", res.message
    assert res.thermal_model == "thd" and len(res.temperature_c) == 2
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    assert e.status == "ok"
    np.testing.assert_allclose(e.r, res.r, atol=1e-6 * s.bearings[0].clearance_m)
    ff = np.asarray(e.film_force_n)
    for k, b in enumerate(s.bearings):
        bc = rotordyn.analysis.assembly.assembled(res.system).bearings[k]
        r = b.journal_bearing().thermal_equilibrium(
            load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=150.0, oil=VG32,
            supply_temperature_c=45.0, model="thd")
        assert r.max_temperature_c == pytest.approx(res.max_temperature_c[k], abs=1e-4)
        assert r.mean_temperature_c == pytest.approx(res.effective_temperature_c[k], abs=1e-4)
        np.testing.assert_allclose(r.temperature_c, res.temperature_c[k], atol=1e-4)
        assert (r.x_m, r.y_m) == pytest.approx((res.journal_x_m[k], res.journal_y_m[k]),
                                               abs=1e-6 * b.clearance_m)
    assert rotordyn.stability(res.system, speed_hz=150.0).status == "ok"
    cb = rotordyn.campbell(res.system, speeds_hz=[120.0, 150.0])
    assert len(cb.to_frame()) > 0
    assert set(res.to_frame()["thermal_model"]) == {"thd"}


def test_thermal_table_model_selector_round_trip_and_bad_input(tmp_path):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(
        s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings),
        thermal=dataclasses.replace(s.thermal, model="thd", bush_htc_w_m2k=500.0))
    p = tmp_path / "m.toml"
    p.write_text(s.to_toml())
    back = rotordyn.System.from_toml(p)
    assert back.thermal == s.thermal
    a = rotordyn.system_thermal_equilibrium(back, speed_hz=150.0)
    b = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, model="thd", bush_htc_w_m2k=500.0)
    assert a.thermal_model == "thd"
    np.testing.assert_array_equal(a.max_temperature_c, b.max_temperature_c)
    with pytest.raises(InputError, match="model"):
        dataclasses.replace(s.thermal, model="hot")
    with pytest.raises(InputError, match="journal_htc_w_m2k"):
        dataclasses.replace(s.thermal, journal_htc_w_m2k=float("nan"))
    with pytest.raises(InputError, match="bush_htc_w_m2k"):
        rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, bush_htc_w_m2k=-1.0)


def test_thermal_sweep_with_the_thd_film_equals_direct_calls(tmp_path):
    """The ``thermal`` sweep analysis on a model whose ``[thermal] model = "thd"``, over the
    bush's heat-transfer coefficient: each point equals the direct call (1e-9)."""
    from thermal_sweep_check import sweep_points

    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(
        s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings),
        thermal=dataclasses.replace(s.thermal, model="thd"))
    tmax = []
    for _, g, r in sweep_points(tmp_path, s, "thermal.bush_htc_w_m2k", [0.0, 2000.0]):
        for c in ("effective_temperature_c", "max_temperature_c", "power_loss_w", "journal_y_m"):
            np.testing.assert_allclose(g[c].to_numpy(), getattr(r, c), rtol=1e-9, atol=1e-15)
        tmax.append(r.max_temperature_c[0])
    assert tmax[0] > tmax[1]  # heat to the bush cools the film


def test_thd_system_transient_follows_the_linear_model_at_small_amplitude():
    """The frozen fields reach the transient: a 0.2 µm disturbance of the THD equilibrium
    decays as the linear model at the same fields predicts (3 % of the amplitude), and the
    run starts from the THD equilibrium."""
    import scipy.linalg

    s = _compressor()
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, oil=VG32,
                                              supply_temperature_c=45.0, model="thd")
    hot = res.system
    lm = rotordyn.linearize(hot, speed_hz=150.0)
    np.testing.assert_allclose(lm.equilibrium.r, res.r, atol=1e-6 * s.bearings[0].clearance_m)
    n = lm.M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(lm.M, lm.K), -np.linalg.solve(lm.M, lm.D)]])
    tr = rotordyn.transient(hot, t_end_s=0.004, speed_hz=150.0, disturbance_m=(0.2e-6, 0.0),
                            n_out=9)
    assert tr.status == "ok", tr.message
    x0 = np.concatenate([tr.r[0] - lm.equilibrium.r, np.zeros(n)])
    lin = np.array([(scipy.linalg.expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - lm.equilibrium.r
    assert np.max(np.abs(dev[:, 0] - lin[:, 0])) < 0.03 * np.max(np.abs(lin[:, 0]))
