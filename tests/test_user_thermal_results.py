"""A user's results at thermal equilibria are kept as every other result (README: "Every
result can be kept: result.save(...), rd.load_result(...) gives it back equal"; "stability,
Campbell and unbalance response with each speed at its own thermal equilibrium ... Results
save and load").

Found 2026-12-05 on a five-stage compressor of the user's own (not the rig, not the test
compressor): ``rd.stability(..., thermal=True).save(p)`` raised "save:
StabilityResult.thermal.system: a System is not a result object" (Campbell and unbalance
alike), and ``rd.system_thermal_equilibrium(...)`` had no ``save`` at all. The frozen model a
thermal result carries is now stored as its model file (``System.to_toml``, lossless) and read
back with ``System.from_toml``: the loaded result is equal field by field, and its frozen
system gives the saved eigenvalues bit for bit.

Model: tests/data/models/compressor5_tilting_pad_thd.toml (5-pad rocker pads, THD oil system,
tilting journals, DE housing misaligned 0.2 mrad, Ng-Pan films with a transition ramp)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from test_result_store import assert_same

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def tp():
    return rd.System.from_toml(MODELS / "compressor5_tilting_pad_thd.toml")


def _round_trip(r, tmp_path, name):
    p = r.save(tmp_path / f"{name}.npz")
    back = rd.load_result(p)
    assert_same(r, back)
    assert_same(type(r).load(p), r)
    return back


def test_system_thermal_equilibrium_saves_and_loads_equal(tp, tmp_path):
    r = rd.system_thermal_equilibrium(tp, speed_hz=150.0)
    assert r.status == "ok"
    back = _round_trip(r, tmp_path, "thermal")
    assert back.system == r.system  # the frozen THD fields of every pad, exactly
    e1, e2 = rd.stability(r.system, 150.0), rd.stability(back.system, 150.0)
    np.testing.assert_array_equal(e1.eigenvalues, e2.eigenvalues)
    assert back.to_frame().equals(r.to_frame())
    assert back.pads_frame().equals(r.pads_frame())


def test_thermal_stability_campbell_unbalance_save_and_load_equal(tp, tmp_path):
    st = rd.stability(tp, 150.0, n_modes=6, thermal=True)
    back = _round_trip(st, tmp_path, "stability")
    assert back.thermal is not None and back.thermal.status == "ok"
    np.testing.assert_array_equal(rd.stability(back.thermal.system, 150.0).eigenvalues,
                                  rd.stability(st.thermal.system, 150.0).eigenvalues)
    c = rd.campbell(tp, [100.0, 150.0], n_modes=6, thermal=True)
    assert len(_round_trip(c, tmp_path, "campbell").thermal) == 2
    u = rd.unbalance_response(tp, [(4, 1e-4, 0.0)], [100.0, 150.0], stations=[4],
                              thermal=True, refine=False)
    assert len(_round_trip(u, tmp_path, "unbalance").thermal) == 2
