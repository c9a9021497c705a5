"""Tilting pads' own modes in the sweep rows by the API's rules, on the generator of
tests/data/models/generator_tilting_pad.toml (two 5-pad tilting-pad bearings, 50 Hz):

- a stability sweep's ``n_modes`` counts the rotor's modes as ``rotordyn.stability``'s does
  (:func:`rotordyn.analysis.linear.mode_window`: the pads' roots below the highest kept mode
  listed beside them, never counted). The batch's own cut counted the pad roots, so at 50 Hz
  ``n_modes = 4`` kept the 2.30 Hz pad root in a rotor mode's slot;
- a boundary sweep's rows name the pads' roots ``pad`` (more than half of the kinetic energy
  in the pads' tilt/pivot coordinates), as the stability rows and the API do; they said
  ``rotor``.
Points as tests/test_generator_system.py's (there the sweep's numbers equal the API's).
"""

import dataclasses
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.sweep import run_sweep

MODEL = Path(__file__).parent / "data" / "models" / "generator_tilting_pad.toml"
CLEARANCES = (1.6e-4, 1.8e-4)
N_MODES = 4


@pytest.fixture(scope="module")
def gen():
    return rd.System.from_toml(MODEL)


def _api(gen, c, f, **kw):
    s = dataclasses.replace(gen, bearings=(dataclasses.replace(gen.bearings[0], clearance_m=c),
                                           gen.bearings[1]))
    return rd.stability(s, f, **kw).to_frame()


def _run(tmp_path, analysis, grid, options=""):
    spec = tmp_path / f"{analysis}.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "g"\nmodel = "{MODEL.as_posix()}"\n'
                    f'analysis = "{analysis}"\n[grid]\n{grid}[options]\n{options}')
    res = run_sweep(spec, tmp_path / analysis, threads=1, progress=False)
    assert res.complete and res.counts["failed"] == 0
    return pd.read_parquet(tmp_path / analysis)


def test_n_modes_counts_rotor_modes_as_the_api(tmp_path, gen):
    fr = _run(tmp_path, "stability",
              f'"bearings.DE_bearing.clearance_m" = {list(CLEARANCES)!r}\nspeed_hz = 50.0\n',
              f"n_modes = {N_MODES}\n")
    assert fr["point_id"].nunique() == 2
    for _, g in fr.groupby("point_id"):
        api = _api(gen, g["bearings.DE_bearing.clearance_m"].iloc[0], 50.0, n_modes=N_MODES)
        kind = list(g["kind"].astype(str))
        # the cut kept N_MODES modes that are not the pads' own, with a pad root listed below
        # them (the batch's cut counted it: N_MODES rows in all, one of them a pad root)
        assert sum(k != "pad" for k in kind) == N_MODES and "pad" in kind
        assert kind == list(api["kind"].astype(str))
        np.testing.assert_allclose(g["freq_hz"].to_numpy(), api["freq_hz"].to_numpy(),
                                   rtol=1e-9)
        assert g["point_stable"].all()


def test_boundary_rows_name_the_pad_modes(tmp_path, gen):
    fr = _run(tmp_path, "boundary",
              f'"bearings.DE_bearing.clearance_m" = {list(CLEARANCES)!r}\n'
              "speed_hz = [49.0, 50.0]\n",
              'x = "bearings.DE_bearing.clearance_m"\ny = "speed_hz"\nresolution = 3\n')
    assert fr["point_id"].nunique() == 4
    for _, g in fr.groupby("point_id"):
        api = _api(gen, g["bearings.DE_bearing.clearance_m"].iloc[0], g["speed_hz"].iloc[0])
        kind = list(g["kind"].astype(str))
        assert "pad" in kind
        # the API's kinds, mode for mode (slot order: ascending damped frequency)
        order = np.argsort(g["mode"].to_numpy())
        np.testing.assert_allclose(g["freq_hz"].to_numpy()[order],
                                   api["freq_hz"].to_numpy()[:len(g)], rtol=1e-9)
        assert [kind[i] for i in order] == list(api["kind"].astype(str))[:len(g)]
