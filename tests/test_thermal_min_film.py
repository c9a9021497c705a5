"""The minimum film at the thermal equilibrium (issue 20; docs/film-physics.md): the hot film's
h_min and its axial position per thermal film (``SystemThermalResult.h_min_m``,
``h_min_z_m``, ``to_frame()``, the ``thermal`` sweep rows, ``rotordyn thermal``, the report's
thermal table). Before, no thermal output had it: the report's film table is at the model's
isothermal viscosity, which on the compressor below overstates the hot film's h_min.

Checked on the compressor of tests/data/models (not the paper rig) with its oil system (THD),
both housings misaligned by 0.3 mrad, turbulent films, on plain bearings and on 5-pad rocker
bearings (48 × 6 and 60 × 6 grids):
* per bearing the thinnest of its films equals the frozen system's equilibrium h_min (the same
  fields; the equilibrium re-solved from the frozen state: 1e-9 relative) and sits at the edge
  z = ±L/2 the misalignment closes;
* the hot film is thinner than the isothermal one at the model's viscosity;
* the sweep rows equal the direct call (1e-12).
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.sweep.work import Job, run_chunk

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0
L = 0.05


def _compressor(pads=False):
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    th = dataclasses.replace(s.thermal, model="thd")
    src = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml").bearings if pads \
        else s.bearings
    bs = tuple(dataclasses.replace(b, n_circ=60 if pads else 48, n_axial=6, tilt=True,
                                   config_theta_y_rad=3e-4, turbulence="ng_pan",
                                   density_kg_m3=860.0) for b in src)
    return dataclasses.replace(s, bearings=bs, thermal=th)


@pytest.mark.parametrize("pads", [False, True])
def test_hot_min_film_is_the_frozen_systems(pads):
    s = _compressor(pads)
    t = rd.system_thermal_equilibrium(s, speed_hz=F_HZ)
    assert t.status == "ok"
    e = rd.equilibrium(t.system, F_HZ).to_frame()
    iso = rd.equilibrium(s, F_HZ).to_frame()
    fr = t.to_frame()
    for i, b in enumerate(s.bearings):
        mine = fr[fr["bearing"].str.startswith(b.name)]
        k = int(np.argmin(mine["h_min_m"]))
        assert mine["h_min_m"].iloc[k] == pytest.approx(e["h_min_m"][i], rel=1e-9)
        assert abs(mine["h_min_z_m"].iloc[k]) == pytest.approx(L / 2)
        assert mine["h_min_m"].iloc[k] < iso["h_min_m"][i]  # the hot film is thinner
    assert np.array_equal(fr["h_min_m"], t.h_min_m)


def test_sweep_rows_and_a_failed_point():
    s = _compressor()
    job = Job("t", s.to_toml(), "thermal", {},
              {"thermal.supply_temperature_c": [45.0, 199.0], "speed_hz": [F_HZ]})
    job.meta = {"sweep_id": "t"}
    rows = run_chunk(job, 0, 0, 2).to_pandas()
    ok = rows[rows["thermal.supply_temperature_c"] == 45.0]
    t = rd.system_thermal_equilibrium(s, speed_hz=F_HZ)
    np.testing.assert_allclose(ok["h_min_m"], t.h_min_m, rtol=1e-12)
    np.testing.assert_allclose(ok["h_min_z_m"], t.h_min_z_m, rtol=1e-12)
    bad = rows[rows["thermal.supply_temperature_c"] == 199.0]
    assert (bad["status"] == "error").all() and bad["h_min_m"].isna().all()
