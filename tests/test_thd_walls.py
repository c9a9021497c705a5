"""The THD film's heat paths to its walls (issue 20; docs/film-physics.md "Heat paths to the
journal and through the bush or pad"; C++ thd_walls.cpp): the journal's temperature from its
own heat balance, 1-D conduction through the bush (pad) to a convecting back face, and the
film-side coefficient from the film's own cross-film conduction.

What is compared, and why the tolerances:
* limits: an insulating bush (k_b = 0) or an insulated back face (h_o = 0) passes no heat: the
  adiabatic film bit for bit (the cells' wall coefficients are exactly 0) on a plain bearing
  and on tilting pads; a bush of no thickness whose back face holds its oil's temperature
  (h_o = 1e12) is the fixed-wall film at that temperature — to 1e-6 K (the surface differs
  from T_o by h_B/(h_B + h_o) of the film's excess, 1e-9 of it);
* the heat balance of the discrete equations, recomputed here from the returned face flows and
  fields: convected + conducted to journal and bush = dissipation (1e-9, round-off of sums of
  ~1e3 terms); each cell's flux into the bush from the film side equals U (T_w − T_o) through
  the bush (1e-9 relative); the journal from its balance takes no net heat (1e-9 of the
  dissipation), and with a given uniform coefficient sits at the area mean of the film's
  cells (1e-9 K: the balance Σ h_J A (T − T_J) = 0 in closed form); on tilting pads the
  journal's balance spans all pads (Σ_pads = 0, one journal temperature);
* a system (the compressor of tests/data/models on plain bearings, statically determinate):
  the system's THD equilibrium with these walls equals each bearing's standalone one under
  the load its film carries (1e-4 K, 1e-6 c, as tests/test_film_thd_system.py); stability at
  each point's own thermal equilibrium (thermal=True) runs; the model file round-trips the
  new ``[thermal]`` keys; a sweep over ``thermal.bush_conductivity_w_per_m_k`` equals the
  direct calls (1e-9) and a more conducting bush cools the film;
* bad input names the field.
Coarse grids (36 × 8 plain, 12 intervals per 60° pad × 6): each test a few seconds.
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import Groove, Oil, TiltingPadBearing
from rotordyn.errors import InputError
from thd_balance import balance, pad_balance

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0, conductivity_w_per_m_k=0.13)
RC = VG32.density_kg_m3 * VG32.specific_heat_j_per_kg_k
LOAD, SPEED, TS = (0.0, -5000.0), 100.0, 45.0
PAD = dict(bush_wall="conduction", bush_thickness_m=0.02, bush_conductivity_w_per_m_k=50.0,
           back_htc_w_m2k=300.0)   # a steel bush or pad, 20 mm, oil around its back
FILM = dict(wall_htc="film", journal_wall="balance", **PAD)
U = 1.0 / (PAD["bush_thickness_m"] / PAD["bush_conductivity_w_per_m_k"]
           + 1.0 / PAD["back_htc_w_m2k"])   # through the bush and its back face, W/(m² K)


def _plain(**kw):
    return rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                   viscosity_pa_s=0.02, n_circ=36, n_axial=8, **kw)


def _grooved():
    return _plain(cavitation="jfo", grooves=[Groove(center_deg=90.0, width_deg=20.0)])


def _run(b, **kw):
    r = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                              model="thd", **kw)
    assert r.status == "ok", r.message
    return r


def _tp():
    return TiltingPadBearing(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                             viscosity_pa_s=0.02, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                             preload=0.3, n_circ=72, n_axial=6)


def _tp_run(tp, **kw):
    r = tp.thermal_equilibrium(load_n=(0.0, -4000.0), speed_hz=SPEED, oil=VG32,
                               supply_temperature_c=TS, carry_over=0.5, **kw)
    assert r.status == "ok", r.message
    return r


def _film_h(b, r):
    """The film thickness at the nodes (n_circ, n_axial + 1) of a plain aligned bearing."""
    phi = 2.0 * np.pi * np.arange(b.n_circ) / b.n_circ
    h = b.clearance_m - r.x_m * np.cos(phi) - r.y_m * np.sin(phi)
    return np.repeat(h[:, None], b.n_axial + 1, axis=1)


def test_insulating_bush_is_the_adiabatic_film_bit_for_bit():
    b = _plain()
    ad = _run(b, bush_htc_w_m2k=0.0)
    for walls in (dict(bush_conductivity_w_per_m_k=0.0, back_htc_w_m2k=300.0),
                  dict(bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=0.0)):
        r = _run(b, bush_htc_w_m2k=2000.0, bush_wall="conduction", bush_thickness_m=0.02,
                 **walls)
        assert np.array_equal(r.temperature_c, ad.temperature_c)
        assert (r.x_m, r.y_m) == (ad.x_m, ad.y_m)
        assert np.array_equal(r.K, ad.K) and np.array_equal(r.C, ad.C)
        assert r.heat_to_bush_w == 0.0 and r.heat_to_journal_w == 0.0
        # no heat crosses: the bush surface is at the film's temperature
        np.testing.assert_array_equal(r.wall_temperature_c, r.temperature_c)
    tp = _tp()
    pad_ad = _tp_run(tp)
    pads = _tp_run(tp, bush_htc_w_m2k=2000.0, bush_wall="conduction", bush_thickness_m=0.02,
                   bush_conductivity_w_per_m_k=0.0, back_htc_w_m2k=300.0)
    for a, c in zip(pads.temperature_c, pad_ad.temperature_c):
        assert np.array_equal(a, c)
    assert np.array_equal(pads.r, pad_ad.r) and np.array_equal(pads.K, pad_ad.K)


def test_thin_bush_with_an_infinite_back_htc_is_the_fixed_wall_film():
    b = _plain()
    for side in (dict(bush_htc_w_m2k=2000.0),   # a given film-side coefficient
                 dict(wall_htc="film")):        # the film's own conduction
        fixed = _run(b, bush_temperature_c=50.0, **side)
        thin = _run(b, bush_wall="conduction", bush_thickness_m=1e-9,
                    bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=1e12,
                    back_temperature_c=50.0, **side)
        assert abs(fixed.heat_to_bush_w) > 10.0
        np.testing.assert_allclose(thin.temperature_c, fixed.temperature_c, rtol=0, atol=1e-6)
        assert thin.heat_to_bush_w == pytest.approx(fixed.heat_to_bush_w, rel=1e-6)
        np.testing.assert_allclose(thin.wall_temperature_c[fixed.inlet_mask == 0], 50.0,
                                   atol=1e-6)


def test_heat_balance_closes_and_the_journal_takes_no_net_heat():
    b = _grooved()
    r = _run(b, carry_over=0.5, **FILM)
    out, diss, _, mass = balance(r.temperature_c, r.inlet_mask, r.flows, RC, TS)
    assert mass < 1e-8
    assert out + r.heat_to_journal_w + r.heat_to_bush_w == pytest.approx(diss, rel=1e-9)
    assert abs(r.heat_to_journal_w) < 1e-9 * diss
    assert r.heat_to_bush_w > 0.01 * diss          # the bush carries a share (2 % here)
    film = r.inlet_mask == 0
    T, Tw, TJ = r.temperature_c, r.wall_temperature_c, r.journal_temperature_c
    assert T[film].min() < TJ < T[film].max()
    # each cell: the film side (parabolic cross-film profile) = 1-D conduction + back face
    h, th, A = _film_h(b, r), r.flows["fill"], r.flows["area_m2"]
    c = th * VG32.conductivity_w_per_m_k / h
    q_film = c * (6 * T - 2 * TJ - 4 * Tw)
    np.testing.assert_allclose(q_film[film], U * (Tw[film] - TS), rtol=1e-9, atol=1e-9)
    assert (A * U * (Tw - TS))[film].sum() == pytest.approx(r.heat_to_bush_w, rel=1e-9)
    qj = (A * c * (6 * T - 4 * TJ - 2 * Tw))[film].sum()
    assert abs(qj) < 1e-9 * diss
    # the whole bearing: convected out (side leakage, the part of Q_r not carried over) +
    # walls = power_loss_w (the film's cells' dissipation: a groove's nodes are not film,
    # docs/film-physics.md "Heat of the inlet cells")
    conv = RC * (r.side_flow_m3_s * (r.side_temperature_c - TS)
                 + 0.5 * r.recirculation_flow_m3_s * (r.recirculation_temperature_c - TS))
    assert conv + r.heat_to_journal_w + r.heat_to_bush_w == pytest.approx(r.power_loss_w,
                                                                          rel=1e-9)
    # against the adiabatic film: the bush cools it, the journal evens it out
    ad = _run(b, carry_over=0.5)
    assert r.max_temperature_c < ad.max_temperature_c
    # a given uniform journal coefficient: the balance puts the journal at the area mean of
    # the film's cells (Σ h_J A (T − T_J) = 0)
    g = _run(b, carry_over=0.5, journal_htc_w_m2k=3000.0, journal_wall="balance")
    Ag = g.flows["area_m2"][film]
    assert g.journal_temperature_c == pytest.approx(
        (Ag * g.temperature_c[film]).sum() / Ag.sum(), abs=1e-9)
    assert abs(g.heat_to_journal_w) < 1e-9 * diss
    out_g, diss_g, _, _ = balance(g.temperature_c, g.inlet_mask, g.flows, RC, TS)
    assert out_g + g.heat_to_journal_w == pytest.approx(diss_g, rel=1e-9)
    # the inlet mixing with the recirculated oil at its reported (mixing-cup) temperature
    q_f = r.film_flow_m3_s - 0.5 * r.recirculation_flow_m3_s
    assert r.inlet_temperature_c == pytest.approx(
        (q_f * TS + 0.5 * r.recirculation_flow_m3_s * r.recirculation_temperature_c)
        / (q_f + 0.5 * r.recirculation_flow_m3_s), abs=1e-9)
    fr = r.to_frame()
    assert fr["journal_temperature_c"].iloc[0] == TJ
    assert fr["max_wall_temperature_c"].iloc[0] == pytest.approx(Tw[film].max())


def test_tilting_pads_share_one_journal_and_conduct_through_the_pads():
    tp = _tp()
    r = _tp_run(tp, **FILM)
    ad = _tp_run(tp)
    P = r.power_loss_w.sum()
    assert np.all(r.journal_temperature_c == r.journal_temperature_c[0])
    assert abs(r.heat_to_journal_w.sum()) < 1e-9 * P     # the journal's balance over all pads
    assert np.ptp(r.heat_to_journal_w) > 1e-3 * P        # ... which moves heat between them
    for k in range(tp.n_pads):
        D = r.inlet_mask[k] > 0
        out, diss, _ = pad_balance(r.temperature_c[k], D, r.flows[k], RC, TS)
        assert out + r.heat_to_journal_w[k] + r.heat_to_bush_w[k] == pytest.approx(diss,
                                                                                   rel=1e-9)
        # Ettles' mixing with the upstream pad's outlet (its mixing-cup temperature, which
        # carries the journal's temperature too)
        u = (k - 1) % tp.n_pads
        carried = min(0.5 * r.outlet_flow_m3_s[u], r.film_flow_m3_s[k])
        t_mix = ((r.film_flow_m3_s[k] - carried) * TS + carried * r.outlet_temperature_c[u]) \
            / r.film_flow_m3_s[k]
        assert r.inlet_temperature_c[k] == pytest.approx(t_mix, abs=1e-9)
        # into the pad: through it and its back face, U (T_w − T_o) per area
        qb = (r.flows[k]["area_m2"] * U * (r.wall_temperature_c[k] - TS))[~D].sum()
        assert qb == pytest.approx(r.heat_to_bush_w[k], rel=1e-9)
    assert np.all(r.heat_to_bush_w > 0.0)
    assert r.max_temperature_c_total < ad.max_temperature_c_total
    # the pad's surface (what a thermocouple in the pad reads) may exceed the film's cross-film
    # mean where the journal is cooler than the film: the parabola peaks near the pad
    assert r.max_wall_temperature_c_total > TS
    fr = r.to_frame()
    assert fr["heat_to_journal_w"].iloc[-1] == pytest.approx(r.heat_to_journal_w.sum())


def _compressor():
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    th = dataclasses.replace(s.thermal, model="thd", oil=VG32, **FILM)
    return dataclasses.replace(s, thermal=th, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


def test_compressor_with_the_walls_in_a_system(tmp_path):
    s = _compressor()
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0)
    assert res.status == "ok", res.message
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    ff = np.asarray(e.film_force_n)
    for k, b in enumerate(s.bearings):   # statically determinate: bearing by bearing
        bc = rotordyn.analysis.assembly.assembled(res.system).bearings[k]
        own = s.thermal.film(b.name)
        r = b.journal_bearing().thermal_equilibrium(
            load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=150.0, oil=VG32,
            supply_temperature_c=45.0, model="thd", carry_over=own.carry_over,
            supply_flow_m3_s=own.supply_flow_m3_s, **FILM)
        np.testing.assert_allclose(r.temperature_c, res.temperature_c[k], atol=1e-4)
        assert r.journal_temperature_c == pytest.approx(res.journal_temperature_c[k], abs=1e-4)
        assert (r.x_m, r.y_m) == pytest.approx((res.journal_x_m[k], res.journal_y_m[k]),
                                               abs=1e-6 * b.clearance_m)
        assert abs(res.heat_to_journal_w[k]) < 1e-9 * res.power_loss_w[k]
    fr = res.to_frame()
    assert np.all(fr["heat_to_bush_w"] > 0.0)
    st = rotordyn.stability(s, 150.0, thermal=True)
    assert st.status == "ok" and st.thermal.thermal_model == "thd"
    np.testing.assert_allclose(st.thermal.max_temperature_c, res.max_temperature_c, atol=1e-9)
    # the model file round-trips the walls and gives the same answer
    p = tmp_path / "m.toml"
    p.write_text(s.to_toml())
    text = p.read_text()
    for key in ("wall_htc", "journal_wall", "bush_wall", "bush_conductivity_w_per_m_k",
                "back_htc_w_m2k", "conductivity_w_per_m_k"):
        assert key in text
    back = rotordyn.System.from_toml(p)
    assert back.thermal == s.thermal
    b2 = rotordyn.system_thermal_equilibrium(back, speed_hz=150.0)
    np.testing.assert_array_equal(b2.max_temperature_c, res.max_temperature_c)


def test_sweep_over_the_bush_conductivity_equals_direct_calls(tmp_path):
    from thermal_sweep_check import sweep_points

    tmax = []
    for _, g, r in sweep_points(tmp_path, _compressor(), "thermal.bush_conductivity_w_per_m_k",
                                [0.0, 50.0]):
        for c in ("max_temperature_c", "journal_temperature_c", "heat_to_bush_w",
                  "max_wall_temperature_c"):
            np.testing.assert_allclose(g[c].to_numpy(), r.wall(c) if c != "max_temperature_c"
                                       else r.max_temperature_c, rtol=1e-9, atol=1e-12)
        tmax.append(r.max_temperature_c[0])
    assert tmax[1] < tmax[0]    # a conducting bush cools the film


def test_bad_wall_input_names_the_field():
    b = _plain()

    def run(**kw):
        return b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                     supply_temperature_c=TS, model="thd", **kw)
    bad = [(dict(bush_wall="conduction", bush_conductivity_w_per_m_k=-1.0),
            "bush_conductivity_w_per_m_k"),
           (dict(bush_wall="conduction", bush_thickness_m=-0.01), "bush_thickness_m"),
           (dict(bush_wall="conduction", back_htc_w_m2k=float("nan")), "back_htc_w_m2k"),
           (dict(bush_thickness_m=0.01), "bush_thickness_m"),     # without conduction
           (dict(back_temperature_c=50.0), "back_temperature_c"),
           (dict(bush_wall="conduction", bush_temperature_c=50.0), "bush_temperature_c"),
           (dict(journal_wall="balance", journal_htc_w_m2k=100.0, journal_temperature_c=50.0),
            "journal_temperature_c"),
           (dict(journal_wall="balance"), "journal_htc_w_m2k"),   # no path to the journal
           (dict(wall_htc="film", bush_htc_w_m2k=100.0), "bush_htc_w_m2k"),
           (dict(journal_wall="hot"), "journal_wall"), (dict(bush_wall="x"), "bush_wall"),
           (dict(wall_htc="nusselt"), "wall_htc"), (dict(bush_walls="fixed"), "bush_walls")]
    for kw, field in bad:
        with pytest.raises(InputError, match=field):
            run(**kw)
    with pytest.raises(InputError, match="conductivity_w_per_m_k"):
        Oil(conductivity_w_per_m_k=-0.1)
    with pytest.raises(InputError, match="oil.conductivity_w_per_m_k"):
        b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, supply_temperature_c=TS,
                              oil=dataclasses.replace(VG32, conductivity_w_per_m_k=0.0),
                              model="thd", wall_htc="film", journal_wall="balance")
    with pytest.raises(InputError, match="thermal.bush_conductivity_w_per_m_k"):
        dataclasses.replace(_compressor().thermal, bush_conductivity_w_per_m_k=-2.0)
    with pytest.raises(InputError, match="bush_thickness_m"):
        _tp().thermal_equilibrium(load_n=(0.0, -4000.0), speed_hz=SPEED, oil=VG32,
                                  supply_temperature_c=TS, bush_thickness_m=0.02)
    with pytest.raises(InputError, match="journal_wall"):   # THD only
        _tp().thermal_equilibrium(load_n=(0.0, -4000.0), speed_hz=SPEED, oil=VG32,
                                  supply_temperature_c=TS, model="effective",
                                  journal_wall="balance")
    o = _core.ThdOptions()   # the core's own check, before any solve
    o.bush_conduction = True
    o.bush_conductivity_w_per_m_k = -3.0
    with pytest.raises(InputError, match="bush_conductivity_w_per_m_k"):
        o.validate(VG32.to_core())
    assert math.isnan(_core.ThdOptions().back_temperature_c)
