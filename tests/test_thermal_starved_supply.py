"""A metered oil supply below the film's demand (docs/film-physics.md, "A metered supply below
the film's demand"): the shortfall is made up by more hot oil, λ_eff = (Q − Q_f)/Q_r, so the
inlet mixing Q T_in = Q_f T_s + λ_eff Q_r T_r is mass-conserving; a film with Q_f + Q_r < Q is
starved (status "starved", never ok).

Found 2026-12-05 by a user-level check: with `supply_flow_m3_s` = Q_f > 0 both thermal models
mixed (Q_f + λ Q_r) T_in = Q_f T_s + λ Q_r T_out whatever the film drew, so where
Q_f + λ Q_r < Q part of the film's inflow was outside the heat balance, with status ok; at
1e-7 m³/s on the compressor's DE bearing the THD film returned ok with a 136 °C inlet.

Checked (each check reads `carry_over_effective` or the status "starved", which the code before
did not have; the balances below also fail with the given λ in place of λ_eff, as the code
before mixed):
* mass: Q_f + λ_eff Q_r = Q to 1e-12 (plain films, effective and THD; per pad on tilting pads);
* heat: what leaves the bearing (side leakage and the hot oil not carried over, relative to
  T_s) equals the power loss to 1e-9, ρ c [Q_s (T_side − T_s) + (1 − λ_eff) Q_r (T_r − T_s)]
  = P (plain, effective: T_side = T_in + ΔT/2, T_r = T_max; THD: the reported mixing-cup
  temperatures) — an identity only when Q_f = Q_s + (1 − λ_eff) Q_r;
* continuity through the switch Q_f = Q − λ Q_r; above it the mixing is the one before
  (T_in = T_s + λ Q_r ΔT / Q_f with the given λ);
* starved: the compressor's DE bearing at 1e-7 m³/s, both models, standalone (StarvedFilmError,
  status "starved"), in the system ("starved", naming the bearing, NaN outputs) and in a
  `thermal` sweep row (status "starved").
Models: the compressor of tests/data/models (plain and tilting pads), not the paper rig, and
the THD tests' 100 mm bearing.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn
from rotordyn.bearings import Groove, Oil, TiltingPadBearing
from rotordyn.errors import ConvergenceError, StarvedFilmError

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
RC = 870.0 * 2000.0
GEO = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4)
LOAD, SPEED, TS = (0.0, -5000.0), 100.0, 45.0
C150 = 150.0  # Hz, the compressor's speed


def _plain(**kw):
    return rotordyn.JournalBearing(viscosity_pa_s=VG32.viscosity_pa_s(TS), n_circ=72,
                                   n_axial=16, **GEO, **kw)


def _effective(b, qf, lam=0.4):
    return b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                 supply_temperature_c=TS, carry_over=lam, supply_flow_m3_s=qf)


def test_plain_effective_shortfall_is_mass_conserving_and_the_heat_balance_closes():
    b, lam = _plain(), 0.4
    own = _effective(b, 0.0, lam)  # the film's own demand Q − λ Q_r
    assert own.carry_over_effective == lam
    qs0 = own.side_flow_m3_s
    qf = qs0 + 0.4 * (own.supply_flow_m3_s - qs0)  # between the side flow and the demand
    r = _effective(b, qf, lam)
    assert r.status == "ok"
    Q, Qs = r.film_flow_m3_s, r.side_flow_m3_s
    Qr, dT = Q - Qs, r.temperature_rise_k
    lam_e = r.carry_over_effective
    assert lam < lam_e < 1.0  # more hot oil than λ Q_r: the shortfall
    assert r.supply_flow_m3_s == qf
    assert qf + lam_e * Qr == pytest.approx(Q, rel=1e-12)  # mass
    assert qf + lam * Qr < 0.9 * Q                          # (the rule before lost > 10 %)
    # the mixing, mass-conserving: Q T_in = Q_f T_s + λ_eff Q_r T_max
    assert Q * r.inlet_temperature_c == pytest.approx(
        qf * TS + lam_e * Qr * r.max_temperature_c, rel=1e-12)
    # the film's balance and the bearing's: side leakage at the mean rise, the hot oil not
    # carried over at T_max, relative to the supply
    assert RC * dT * (Q - 0.5 * Qs) == pytest.approx(r.power_loss_w, rel=1e-9)
    out = RC * (Qs * (r.inlet_temperature_c + 0.5 * dT - TS)
                + (1.0 - lam_e) * Qr * (r.max_temperature_c - TS))
    assert out == pytest.approx(r.power_loss_w, rel=1e-9)
    # (with the given λ, as the code before mixed, the same sum misses the power: 2.4 %)
    t_in_old = TS + lam * Qr * dT / qf
    out_old = RC * (Qs * (t_in_old + 0.5 * dT - TS) + (1.0 - lam) * Qr * (t_in_old + dT - TS))
    assert abs(out_old / r.power_loss_w - 1.0) > 0.01
    df = r.to_frame()
    assert df["carry_over_effective"].iloc[0] == lam_e


def test_plain_effective_continuous_through_the_switch_and_unchanged_above_it():
    b, lam = _plain(), 0.4
    own = _effective(b, 0.0, lam)
    d0 = own.supply_flow_m3_s  # the demand Q − λ Q_r at the equilibrium
    at = _effective(b, d0, lam)  # metered exactly at the demand: the film's own answer
    assert at.carry_over_effective == lam
    assert at.effective_temperature_c == pytest.approx(own.effective_temperature_c, abs=1e-5)
    rise = own.max_temperature_c - TS
    gaps = []
    for delta in (1e-3, 1e-4):
        up, dn = _effective(b, d0 * (1 + delta), lam), _effective(b, d0 * (1 - delta), lam)
        assert up.carry_over_effective == lam  # above: the given λ, the mixing before
        qr = up.film_flow_m3_s - up.side_flow_m3_s
        assert up.inlet_temperature_c == pytest.approx(
            TS + lam * qr * up.temperature_rise_k / up.supply_flow_m3_s, rel=1e-12)
        assert dn.carry_over_effective > lam  # below: the shortfall made up
        assert dn.carry_over_effective == pytest.approx(lam, rel=10 * delta)
        gaps.append(max(abs(x.max_temperature_c - own.max_temperature_c) for x in (up, dn)))
        assert gaps[-1] <= 5.0 * delta * rise + 2e-5  # no jump (tol_k 1e-6 K on T_eff)
    assert gaps[1] < 0.3 * gaps[0]  # and it closes with δ (first order: 0.1)
    # below the switch the film runs hotter than the rule before made it (which lost oil)
    dn = _effective(b, d0 - 0.3 * (d0 - own.side_flow_m3_s), lam)
    qr = dn.film_flow_m3_s - dn.side_flow_m3_s
    assert dn.inlet_temperature_c > TS + lam * qr * dn.temperature_rise_k / dn.supply_flow_m3_s


def _heat_out(r, lam_e):
    """The THD bearing's heat out relative to T_s (W): side leakage, the part of the flow
    reaching the inlet not carried over, the walls (tests/test_film_thd.py)."""
    return (RC * (r.side_flow_m3_s * (r.side_temperature_c - TS) + (1.0 - lam_e)
                  * r.recirculation_flow_m3_s * (r.recirculation_temperature_c - TS))
            + r.heat_to_journal_w + r.heat_to_bush_w)


def test_plain_thd_shortfall_is_mass_conserving_and_the_heat_balance_closes():
    b, lam = _plain(cavitation="jfo", grooves=[Groove(center_deg=90.0, width_deg=20.0)]), 0.5
    kw = dict(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS, model="thd",
              carry_over=lam)
    own = b.thermal_equilibrium(**kw)
    assert own.status == "ok" and own.carry_over_effective == lam
    qs0 = own.side_flow_m3_s
    qf = qs0 + 0.4 * (own.supply_flow_m3_s - qs0)
    r = b.thermal_equilibrium(**kw, supply_flow_m3_s=qf)
    assert r.status == "ok"
    Q, Qr, lam_e = r.film_flow_m3_s, r.recirculation_flow_m3_s, r.carry_over_effective
    assert lam < lam_e < 1.0
    assert qf + lam_e * Qr == pytest.approx(Q, rel=1e-12)
    # the groove's mixing (its nodes are not film: no source) and the whole bearing
    assert Q * r.inlet_temperature_c == pytest.approx(
        qf * TS + lam_e * Qr * r.recirculation_temperature_c, rel=1e-10)
    assert _heat_out(r, lam_e) == pytest.approx(r.power_loss_w, rel=1e-9)
    assert abs(_heat_out(r, lam) / r.power_loss_w - 1.0) > 0.05  # the given λ: no balance
    assert r.inlet_temperature_c > own.inlet_temperature_c  # less fresh oil: hotter inlet
    # the switch: metered just above the demand is the mixing before, just below continuous
    d0 = own.supply_flow_m3_s
    up = b.thermal_equilibrium(**kw, supply_flow_m3_s=d0 * (1 + 1e-4))
    dn = b.thermal_equilibrium(**kw, supply_flow_m3_s=d0 * (1 - 1e-4))
    assert up.carry_over_effective == lam and dn.carry_over_effective > lam
    for x in (up, dn):
        assert x.max_temperature_c == pytest.approx(own.max_temperature_c,
                                                    abs=5e-4 * (own.max_temperature_c - TS))


def _pads_ring(r, lam):
    """Per pad (upstream pad j − 1, rotation positive): the mass and the mixing of its inlet."""
    n = len(r.film_flow_m3_s)
    made_up = 0
    for j in range(n):
        u = (j - 1) % n
        Q, qf, qo = r.film_flow_m3_s[j], r.supply_flow_m3_s[j], r.outlet_flow_m3_s[u]
        lam_e = r.carry_over_effective[j]
        if qf + lam * qo < Q:  # a shortfall: made up by hot oil, mass-conserving
            made_up += 1
            assert lam < lam_e <= 1.0
            assert qf + lam_e * qo == pytest.approx(Q, rel=1e-12)
            # hotter than the rule before mixed it (λ Q_out,u with the metered share alone)
            t_old = (qf * TS + lam * qo * r.outlet_temperature_c[u]) / (qf + lam * qo)
            assert r.inlet_temperature_c[j] > t_old + 0.01
        else:  # the given λ (a surplus mixes at the inlet and leaves there)
            assert lam_e == lam
        tin = (qf * TS + lam_e * qo * r.outlet_temperature_c[u]) / (qf + lam_e * qo)
        assert r.inlet_temperature_c[j] == pytest.approx(tin, abs=1e-9)
    return made_up


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_tilting_pads_share_a_short_supply_mass_conserving(model):
    b = TiltingPadBearing(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                          viscosity_pa_s=0.02, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                          preload=0.3, n_circ=48, n_axial=6)
    lam = 0.3
    kw = dict(load_n=(0.0, -4000.0), speed_hz=100.0, oil=VG32, supply_temperature_c=TS,
              carry_over=lam, model=model)
    own = b.thermal_equilibrium(**kw)
    assert np.all(own.carry_over_effective == lam)
    # a metered supply shared equally, each share between the most any pad needs to be fed
    # (Q − Q_out,u) and the largest demand (Q − λ Q_out,u): the loaded pads are short, the
    # unloaded ones get a surplus (at 70 % of the pads' total demand the loaded pad starves)
    up = np.roll(own.outlet_flow_m3_s, 1)
    need = np.max(own.film_flow_m3_s - up)
    dem = np.max(own.film_flow_m3_s - lam * up)
    qf = 5 * (need + 0.5 * (dem - need))
    r = b.thermal_equilibrium(**kw, supply_flow_m3_s=qf)
    assert r.status == "ok"
    np.testing.assert_allclose(r.supply_flow_m3_s, qf / 5, rtol=1e-12)
    assert _pads_ring(r, lam) >= 1
    if model == "effective":  # each pad's own balance
        dT = r.outlet_temperature_c - r.inlet_temperature_c
        np.testing.assert_allclose(RC * dT * (r.film_flow_m3_s - 0.5 * r.side_flow_m3_s),
                                   r.power_loss_w, rtol=1e-9)
    assert "carry_over_effective" in r.to_frame().columns


# --- the compressor of tests/data/models: its DE bearing starved ---------------------------

def _compressor(model, qf, pads=False):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    th = s.thermal
    films = tuple(dataclasses.replace(f, supply_flow_m3_s=qf) if f.bearing == "DE bearing"
                  else f for f in th.films)
    th = dataclasses.replace(th, model=model, films=films)
    if pads:
        p = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
        return dataclasses.replace(p, bearings=tuple(
            dataclasses.replace(b, n_circ=48, n_axial=6) for b in p.bearings), thermal=th)
    return dataclasses.replace(s, thermal=th)


@pytest.mark.parametrize("model", ["effective", "thd"])
@pytest.mark.parametrize("pads", [False, True], ids=["plain", "tilting_pad"])
def test_compressor_de_bearing_metered_below_demand_and_starved(model, pads):
    # metered below the demand, fed: the plain DE film at 8e-5 m³/s, the pads at the model's
    # 3e-4 shared by five (at 8e-5 a loaded pad starves)
    qf = 3e-4 if pads else 8e-5
    s = _compressor(model, qf, pads)
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=C150)
    assert res.status == "ok", res.message
    de = np.array([n.startswith("DE") for n in res.bearing_names])
    lam_e = res.carry_over_effective
    np.testing.assert_array_equal(lam_e[~de], 0.6)  # the NDE bearing: its own demand
    assert np.all(lam_e[de] >= 0.4) and np.any(lam_e[de] > 0.4)  # metered short
    if not pads:  # the plain DE film: mass (effective: Q_r = Q − Q_s)
        i = int(np.flatnonzero(de)[0])
        Q, Qs = res.film_flow_m3_s[i], res.side_flow_m3_s[i]
        assert res.supply_flow_m3_s[i] == qf
        if model == "effective":
            assert qf + lam_e[i] * (Q - Qs) == pytest.approx(Q, rel=1e-12)
    assert "carry_over_effective" in res.to_frame().columns
    # 1e-7 m³/s: the DE film starved — a status, not ok, not a crash, no thermal state
    st = rotordyn.system_thermal_equilibrium(_compressor(model, 1e-7, pads), speed_hz=C150)
    assert st.status == "starved"
    assert "starved" in st.message and "DE bearing" in st.message
    assert f"Q_f = {1e-7 / 5 if pads else 1e-7:g}" in st.message  # a pad: its share
    assert "Q - Q_r" in st.message
    df = st.to_frame()
    assert (df.status == "starved").all() and df.max_temperature_c.isna().all()
    # never linearised: stability at the thermal point raises with the status
    with pytest.raises(StarvedFilmError, match="not linearised") as info:
        rotordyn.stability(_compressor(model, 1e-7, pads), speed_hz=C150, thermal=True)
    assert info.value.status == "starved"


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_standalone_de_bearing_starved_raises_with_the_status(model):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    th = s.thermal
    de = next(b for b in s.bearings if b.name == "DE bearing")
    from rotordyn.analysis.assembly import assembled

    ff = np.asarray(rotordyn.equilibrium(s, speed_hz=C150).film_force_n)
    bc = assembled(s).bearings[[b.name for b in s.bearings].index("DE bearing")]
    kw = dict(load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=C150, oil=th.oil,
              supply_temperature_c=th.supply_temperature_c, carry_over=0.4, model=model)
    ok = de.thermal_equilibrium(**kw, supply_flow_m3_s=8e-5)
    assert ok.status == "ok" and ok.carry_over_effective > 0.4
    with pytest.raises(StarvedFilmError, match="starved") as info:
        de.thermal_equilibrium(**kw, supply_flow_m3_s=1e-7)
    assert info.value.status == "starved"
    assert isinstance(info.value, ConvergenceError)
    assert "Q_f = 1e-07" in str(info.value)


def test_thermal_sweep_row_of_a_starved_point(tmp_path):
    from rotordyn.sweep import run_sweep

    s = _compressor("effective", 8e-5)
    s.to_toml(tmp_path / "m.toml")
    spec = tmp_path / "s.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "starved"\nmodel = "m.toml"\n'
                    'analysis = "thermal"\n[grid]\n'
                    '"thermal.films.DE_bearing.supply_flow_m3_s" = [1e-7, 8e-5]\n'
                    f"speed_hz = [{C150}]\n")
    run_sweep(spec, tmp_path / "o", threads=1, progress=False)
    df = pd.read_parquet(tmp_path / "o")
    col = "thermal.films.DE_bearing.supply_flow_m3_s"
    bad, good = df[df[col] == 1e-7], df[df[col] == 8e-5]
    assert len(bad) >= 1 and (bad.status == "starved").all()
    assert bad.message.str.contains("DE bearing").all()
    assert (good.status == "ok").all() and len(good) == 2
    assert math.isnan(float(bad.max_temperature_c.iloc[0]))
    # the row carries the carry-over the mixing used, as the API's frame (it had no column)
    api = rotordyn.system_thermal_equilibrium(s, speed_hz=C150).to_frame()
    for name in ("NDE bearing", "DE bearing"):
        row = good[good.bearing == name]
        want = float(api.loc[api.bearing == name, "carry_over_effective"].iloc[0])
        assert float(row.carry_over_effective.iloc[0]) == pytest.approx(want, rel=1e-9)
    assert math.isnan(float(bad.carry_over_effective.iloc[0]))


def test_starved_pad_bearing_message_gives_the_bearings_supply():
    """A starved tilting-pad bearing's message is in the user's terms: the supply is given per
    bearing and shared equally by its pads, so the message gives the bearing's supply, the
    pad count and the bearing supply its shortfall estimates under equal shares (it gave the
    pad's share and a per-pad minimum below what the user had already set); 5 % above that
    estimate this bearing is fed (the compressor on its 5-pad bearings, 150 Hz; an estimate,
    not a bound, in general)."""
    import re

    th = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    s = dataclasses.replace(s, thermal=dataclasses.replace(th, films=()))
    r = rotordyn.system_thermal_equilibrium(s, speed_hz=C150, supply_flow_m3_s=5e-5)
    assert r.status == "starved"
    assert "the bearing's metered supply 5e-05 m^3/s is shared equally by its 5 pads" in \
        r.message and "this pad's share Q_f = 1e-05 m^3/s" in r.message
    least = float(re.search(r"estimates a bearing supply of ([0-9.e+-]+) m\^3/s", r.message)
                  .group(1))
    assert least > 5e-5
    fed = rotordyn.system_thermal_equilibrium(s, speed_hz=C150, supply_flow_m3_s=1.05 * least)
    assert fed.status == "ok", fed.message
