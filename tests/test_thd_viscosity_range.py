"""A THD film whose temperature leaves the oil's viscosity law's range (issue 20;
docs/film-physics.md, "Effective-temperature thermal model": "a film hotter than ``t_max_c``
is a ConvergenceError").

The THD iterations clamp the node temperatures to [t_min_c, t_max_c] before evaluating μ(T).
When the film's fixed point lies above t_max_c the clamped iteration settles with nodes held at
t_max_c while the energy equation asks for more there. Before the fix both the standalone
(``thd_equilibrium``) and the system (``thermal_system_equilibrium``) loops measured their
residual on the unclamped field, so such a film never "settled": 200 iterations and then
"the film temperature(s) did not settle", status ``not_converged`` in a system — a wrong cause
(the effective-temperature model says "exceeds the viscosity law's range" at once). Now the
residual is the clamped map's, so the iteration stops at that clamped fixed point and the
range check names t_max_c. Found on the compressor of tests/data/models on misaligned
turbulent tilting pads (a supply-temperature sweep), checked here on plain bearings, standalone
and in a system, and on the tilting pads.
"""

import dataclasses
from pathlib import Path

import pytest

import rotordyn as rd
from rotordyn.errors import ConvergenceError
from rotordyn.sweep.work import Job, run_chunk

MODELS = Path(__file__).parent / "data" / "models"


def _plain_thd(supply_c):
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    th = dataclasses.replace(s.thermal, model="thd", supply_temperature_c=supply_c)
    bs = tuple(dataclasses.replace(b, n_circ=48, n_axial=6) for b in s.bearings)
    return dataclasses.replace(s, bearings=bs, thermal=th)


def test_standalone_thd_film_beyond_t_max_names_the_range():
    oil = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal.oil
    b = rd.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                          viscosity_pa_s=0.018, n_circ=48, n_axial=6)
    # the same bearing at 190 degC supply: T_max 195.2 degC, inside the range (control)
    ok = b.thermal_equilibrium(load_n=(0.0, -1000.0), speed_hz=150.0, oil=oil,
                               supply_temperature_c=190.0, model="thd")
    assert ok.max_temperature_c < oil.t_max_c
    with pytest.raises(ConvergenceError, match=r"viscosity law's range \(t_max_c = 200"):
        b.thermal_equilibrium(load_n=(0.0, -3000.0), speed_hz=150.0, oil=oil,
                              supply_temperature_c=198.0, model="thd")


def test_system_thd_film_beyond_t_max_names_the_range():
    # 150 degC supply: inside the range (THD T_max 169 degC at 150 Hz); 190 degC: the THD film
    # runs past 200 degC (the effective model's at 197 degC supply, T_max 200.4 degC; 195 degC
    # before the DE bearing's metered supply was a fed 3e-4 m³/s, 2026-12-06)
    assert rd.system_thermal_equilibrium(_plain_thd(150.0), speed_hz=150.0).status == "ok"
    for model, supply in (("thd", 190.0), ("effective", 197.0)):
        with pytest.raises(ConvergenceError, match=r"viscosity law's range \(t_max_c = 200"):
            rd.system_thermal_equilibrium(_plain_thd(supply), speed_hz=150.0, model=model)


def test_thd_tilting_pads_beyond_t_max_are_an_error_row_naming_the_range():
    # the pads' own demand (no metered DE entry: its 3e-4 m³/s, shared by five pads, starves
    # the loaded DE pad at a 199 degC supply, whose thin oil leaks more, 2026-12-06)
    th = dataclasses.replace(
        rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal, model="thd",
        films=())
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    s = dataclasses.replace(s, thermal=th, bearings=tuple(
        dataclasses.replace(b, n_circ=48, n_axial=6) for b in s.bearings))
    with pytest.raises(ConvergenceError, match="viscosity law's range"):
        rd.system_thermal_equilibrium(s, speed_hz=150.0, supply_temperature_c=199.0)
    job = Job("t", s.to_toml(), "thermal", {},
              {"thermal.supply_temperature_c": [45.0, 199.0], "speed_hz": [150.0]})
    job.meta = {"sweep_id": "t"}
    t = run_chunk(job, 0, 0, 2).to_pandas()
    hot = t[t["thermal.supply_temperature_c"] == 199.0]
    cold = t.drop(hot.index)
    assert len(hot) >= 1 and set(hot["status"]) == {"error"}  # a raised point: one row
    assert hot["message"].str.contains("viscosity law's range").all()
    assert len(cold) == 10 and set(cold["status"]) == {"ok"}  # one row per pad
