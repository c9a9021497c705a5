"""Stability, Campbell and unbalance at each point's own thermal equilibrium (issue 20): the
Python API's ``thermal=`` and the sweeps' ``options.thermal`` on the compressor of
tests/data/models (plain journal and tilting-pad bearings), rotordyn.analysis.thermal_dynamics.

* a flat-viscosity oil (μ(T) = the bearings' own μ) gives the isothermal numbers bit for bit;
* each sweep row equals the direct API call at its point (1e-9);
* hotter supply oil lowers the films' viscosity and the whirl frequency of the film mode;
* a failed thermal equilibrium is a status row, never linearised;
* bad input: InputError naming the field.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.bearings import Oil
from rotordyn.errors import InputError
from rotordyn.sweep.work import Job, run_chunk

MODELS = Path(__file__).parent / "data" / "models"
FLAT = Oil(viscosity_law="exponential", mu_ref_pa_s=0.018, t_ref_c=40.0, beta_1_per_k=1e-300)


def _plain():
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


def _pads():
    th = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    return dataclasses.replace(s, thermal=dataclasses.replace(th, model="thd"))


def test_flat_oil_is_isothermal_bit_for_bit():
    s = _plain()
    iso = rd.stability(s, 150.0)
    th = rd.stability(s, 150.0, thermal=dict(oil=FLAT))
    assert th.thermal.status == "ok"
    assert np.array_equal(th.eigenvalues, iso.eigenvalues)
    c0 = rd.campbell(s, [100.0, 150.0], n_modes=4)
    c1 = rd.campbell(s, [100.0, 150.0], n_modes=4, thermal=dict(oil=FLAT))
    # Campbell: every speed cold at its thermal equilibrium vs the isothermal continuation
    np.testing.assert_allclose(c1.eigenvalues, c0.eigenvalues, rtol=1e-9)
    ub = [(3, 1e-4, 0.0)]
    u0 = rd.unbalance_response(s, ub, [100.0, 150.0], refine=False)
    u1 = rd.unbalance_response(s, ub, [100.0, 150.0], refine=False, thermal=dict(oil=FLAT))
    np.testing.assert_allclose(u1.x, u0.x, rtol=1e-9)
    assert len(u1.thermal) == 2


def test_hotter_oil_softens_the_films():
    s = _plain()
    cold = rd.stability(s, 150.0, thermal=dict(supply_temperature_c=40.0))
    hot = rd.stability(s, 150.0, thermal=dict(supply_temperature_c=70.0))
    assert np.all(hot.thermal.effective_temperature_c > cold.thermal.effective_temperature_c)
    assert np.all(hot.thermal.viscosity_pa_s < cold.thermal.viscosity_pa_s)
    # thinner oil: a more eccentric journal, lower damping of the least damped mode
    kc = cold.linear.KH
    kh = hot.linear.KH
    assert np.trace(np.abs(kh)) != np.trace(np.abs(kc))
    assert abs(hot.thermal.journal_y_m[0]) > abs(cold.thermal.journal_y_m[0])


def test_tilting_pad_thd_stability():
    s = _pads()
    st = rd.stability(s, 100.0, thermal=True, n_modes=6)
    assert st.status == "ok" and st.thermal.thermal_model == "thd"
    assert np.all(st.thermal.max_temperature_c > s.thermal.supply_temperature_c)


def test_bad_input_names_the_field():
    s = _plain()
    with pytest.raises(InputError, match="thermal.speed_hz"):
        rd.stability(s, 150.0, thermal=dict(speed_hz=3.0))
    with pytest.raises(InputError, match="thermal.bogus"):
        rd.campbell(s, [100.0, 150.0], thermal=dict(bogus=1))
    with pytest.raises(InputError, match="thermal"):
        rd.unbalance_response(s, [(3, 1e-4, 0.0)], [100.0], thermal="hot")
    from rotordyn.sweep.spec import OPTIONS
    with pytest.raises(InputError, match="options.thermal.carry_over"):
        OPTIONS["stability"]["thermal"]("options.thermal", {"carry_over": 2.0})
    with pytest.raises(InputError, match="options.thermal.oil"):
        OPTIONS["campbell"]["thermal"]("options.thermal", {"oil": 2.0})


def _job(analysis, options, axes, system=None):
    job = Job("s", (system or _plain()).to_toml(), analysis, options, axes)
    job.meta = {"sweep_id": "s"}
    return job


def test_sweep_rows_equal_the_api():
    s = _plain()
    job = _job("stability", {"thermal": {}, "n_modes": 4}, {"speed_hz": [100.0, 150.0]})
    t = run_chunk(job, 0, 0, 2).to_pandas()
    assert set(t["status"]) == {"ok"}
    for f, g in t.groupby("speed_hz"):
        st = rd.stability(s, f, n_modes=4, thermal=True)
        np.testing.assert_allclose(g["eig_real_1_per_s"], st.eigenvalues.real, rtol=1e-9)
        np.testing.assert_allclose(g["freq_hz"], st.eigenvalues.imag / 2 / np.pi, rtol=1e-9)
        np.testing.assert_allclose(list(g["film_effective_temperature_c"].iloc[0]),
                                   st.thermal.effective_temperature_c, rtol=1e-9)
        assert g["power_loss_w"].iloc[0] == pytest.approx(st.thermal.power_loss_w.sum(),
                                                          rel=1e-9)
    ub = [[3, 1e-4, 0.0]]
    job = _job("unbalance", {"thermal": {}, "unbalances": ub}, {"speed_hz": [100.0, 150.0]})
    t = run_chunk(job, 0, 0, 2).to_pandas()
    u = rd.unbalance_response(s, [tuple(x) for x in ub], [100.0, 150.0], refine=False,
                              thermal=True)
    np.testing.assert_allclose(t["amplitude_x_m"], np.abs(u.x[:, 0]), rtol=1e-9)
    assert np.all(t["max_temperature_c"] > 45.0)


def test_sweep_flat_oil_rows_equal_isothermal_rows():
    s = _plain()
    th = dataclasses.replace(s.thermal, oil=FLAT)
    flat = dataclasses.replace(s, thermal=th)
    axes = {"speed_hz": [100.0, 150.0]}
    a = run_chunk(_job("campbell", {"n_modes": 4}, axes, flat), 0, 0, 2).to_pandas()
    b = run_chunk(_job("campbell", {"n_modes": 4, "thermal": {}}, axes, flat), 0, 0,
                  2).to_pandas()
    for c in ("mode_id", "mode", "whirl", "kind", "point_stable", "status"):
        assert list(a[c]) == list(b[c]), c
    for c in ("freq_hz", "eig_real_1_per_s", "damping_ratio", "journal_x_m", "journal_y_m"):
        np.testing.assert_allclose(b[c], a[c], rtol=1e-9, atol=1e-15)


def test_failed_thermal_equilibrium_is_a_status_row():
    s = _plain()
    # 197 degC supply: the film leaves the viscosity law's range (t_max_c = 200 degC); the
    # thermal equilibrium fails and the point is never linearised (195 degC before the DE
    # bearing's metered supply was raised to a fed 3e-4 m³/s, 2026-12-06)
    job = _job("stability", {"thermal": {"supply_temperature_c": 197.0}},
               {"speed_hz": [150.0, 160.0]})
    t = run_chunk(job, 0, 0, 2).to_pandas()
    assert len(t) == 2 and set(t["status"]) == {"error"}
    assert t["message"].str.contains("viscosity law's range").all()
    assert t["eig_real_1_per_s"].isna().all()
    c = rd.campbell(s, [150.0, 160.0], thermal=dict(supply_temperature_c=197.0))
    assert list(c.point_status) == ["error", "error"] and np.isnan(c.eigenvalues).all()
    with pytest.raises(rd.errors.ConvergenceError, match="viscosity law"):
        rd.stability(s, 150.0, thermal=dict(supply_temperature_c=197.0))


def test_a_failed_speed_says_why_in_the_api_results_and_unbalance_rows():
    """Campbell and unbalance results at thermal equilibria keep why a speed failed
    (``point_message``; Campbell's ``to_frame()`` message column), as the sweep's stability and
    Campbell rows did. Before: the API's Campbell rows said status ``error`` with an empty
    message and the unbalance sweep rows only ``error``, so the cause (here the film past the
    viscosity law's t_max_c at 150 Hz, while 100 Hz stays inside at a 197 degC supply) was
    lost."""
    s = _plain()
    th = dict(supply_temperature_c=197.0)
    c = rd.campbell(s, [100.0, 150.0], n_modes=2, thermal=th)
    assert list(c.point_status) == ["ok", "error"]
    assert c.point_message[0] is None and "viscosity law's range" in c.point_message[1]
    f = c.to_frame()
    assert f[f["speed_hz"] == 150.0]["message"].str.startswith("ConvergenceError: ").all()
    assert (f[f["speed_hz"] == 100.0]["message"] == "").all()  # as every frame writes it
    u = rd.unbalance_response(s, [(3, 1e-4, 0.0)], [100.0, 150.0], refine=False, thermal=th)
    assert list(u.point_status) == ["ok", "error"]
    assert list(u.point_message) == list(c.point_message)
    job = _job("unbalance", {"unbalances": [[3, 1e-4, 0.0]], "thermal": th},
               {"speed_hz": [100.0, 150.0]})
    t = run_chunk(job, 0, 0, 2).to_pandas()
    bad = t[t["speed_hz"] == 150.0]
    assert len(bad) and (bad["status"] == "error").all()
    assert bad["message"].str.contains("viscosity law's range").all()


@pytest.mark.parametrize("kw, match", [
    ({"model": "x"}, r"^thermal\.model: expected one of"),
    ({"carry_over": 2.0}, r"^thermal\.carry_over: expected 0 <= carry_over"),
    ({"supply_temperature_c": 300.0}, r"^thermal\.supply_temperature_c: expected a temperature"),
    ({"tol_k": -1.0}, r"^thermal\.tol_k: "),
])
def test_a_bad_thermal_keyword_value_is_named_as_given(kw, match):
    """A bad value among the ``thermal=`` keywords of stability, Campbell and the unbalance
    response names ``thermal.<key>`` (before: only the key, e.g. "model: expected ...", as if
    the call's own argument ``model`` were wrong)."""
    s = _plain()
    with pytest.raises(InputError, match=match):
        rd.stability(s, 150.0, thermal=kw)
    with pytest.raises(InputError, match=match):
        rd.campbell(s, [150.0], thermal=kw)
    with pytest.raises(InputError, match=match):
        rd.unbalance_response(s, [(3, 1e-4, 0.0)], [150.0], refine=False, thermal=kw)


def test_model_level_refusals_raise_not_rows():
    """A zero speed is bad input: InputError naming the field, not an ``error`` row per speed
    (before: a Campbell diagram of NaN rows). The effective model on tilting pads, once a
    model-level refusal, now runs per pad: every Campbell row at a thermal equilibrium with
    finite pad temperatures."""
    pads = _pads()
    eff = dataclasses.replace(pads, thermal=dataclasses.replace(pads.thermal, model="effective"))
    c = rd.campbell(eff, [100.0, 150.0], thermal=True)
    f = c.to_frame()
    assert len(f) > 0 and (f["status"] == "ok").all()
    found = f["freq_hz"].notna()  # unfilled mode slots are NaN, as in an isothermal Campbell
    assert found.sum() >= 10 and np.all(np.isfinite(f.loc[found, "log_dec"]))
    assert np.all(f["max_temperature_c"] > eff.thermal.supply_temperature_c)
    assert all(len(t) == 10 and np.all(np.isfinite(t)) for t in f["film_effective_temperature_c"])
    s = _plain()
    with pytest.raises(InputError, match="speeds_hz"):
        rd.campbell(s, [0.0, 100.0], thermal=True)
    with pytest.raises(InputError, match="speeds_hz"):
        rd.unbalance_response(s, [(3, 1e-4, 0.0)], [0.0, 100.0], thermal=True, refine=False)
