"""Thermo-hydrodynamic film of the active journal bearing in a system (issue 20;
docs/film-physics.md §"THD active bearing"): the paper rig (rotordyn.models.paper_rig(),
coarse 36 × 8 film) with ``system_thermal_equilibrium(model="thd")`` at a_y = −1.85 mm, 50 Hz.

The active bearing's film thickness includes the sleeve's inward deformation w(φ) = W r_s
(eq. 3); the sleeve coordinates r_s are part of the equilibrium the energy equation is
iterated with. Checks:
* a temperature-independent viscosity (exponential law, β = 1e-300: μ(T) = μ_ref exactly)
  gives the isothermal rig bit for bit: the equilibrium (rotor and sleeve coordinates) and
  K_H, D_H (``array_equal``) while the film heats;
* the field is the energy equation's fixed point on the deformed film: a standalone Reynolds
  solve built here from the bearing's geometry, with h = c − x cos φ − y sin φ − W r_s
  computed here from the sleeve's interpolation matrix and the returned field's viscosities,
  and the energy equation on it, give the returned temperature field (1e-5 K; the
  iteration's tolerance is 1e-6 K); the rigid-bush film (w = 0) at the same journal position
  gives a field that differs by more than 0.1 K, so the check sees the sleeve;
* energy balance on the mass-conserving (Elrod–Adams) active film, recomputed from the
  returned face flows and temperatures: heat carried out = dissipation (1e-9) adiabatic with
  carry-over, and with heat transfer to the bush (flows + wall = dissipation, 1e-9);
* K_H with the field frozen (perturbation method) equals central finite differences of the
  film forces of the returned system (1e-5 of the largest entry) and differs from the
  isothermal K_H at the supply viscosity by more than that;
* the returned system reproduces the equilibrium (rotor and sleeve, 1e-9 c), its stability
  runs, its transient follows its linear model at small amplitude (1 %), the model file
  round-trips ([thermal] model = "thd"; the frozen field of the returned system as
  ``viscosity_field_pa_s``) and gives the same answers; the thermal sweep and the CLI equal
  the direct call;
* ``threshold(..., thermal=...)`` (each evaluation at its own thermal equilibrium): a flat oil
  gives the isothermal threshold to round-off; with VG 46 max Re λ of the thermal film is zero
  at its threshold and positive at the isothermal one;
* the effective-temperature model likewise: the power loss and flows of the deformed film at
  μ(T_eff) recomputed here (1e-6) close its heat balance (1e-9);
* bad input names the field.
"""

import dataclasses
import math

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings import Oil, ThermalModel
from rotordyn.errors import InputError
from thd_balance import balance

VG46 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=46.0, t2_c=100.0, nu2_mm2_s=6.8,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
AY, SPEED, PC, TS = -1.85e-3, 50.0, 0.2e6, 40.0


def _rig(cavitation="reynolds"):
    s = rd.models.paper_rig()
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8, cavitation=cavitation)
        if isinstance(b, rd.ActiveJournalBearing) else b for b in s.bearings))


def _active(s):
    return next(i for i, b in enumerate(s.bearings) if isinstance(b, rd.ActiveJournalBearing))


def _thd(s, **kw):
    kw = {"oil": VG46, "supply_temperature_c": TS, "chamber_pressure_pa": PC,
          "config_ay_m": AY, "model": "thd", **kw}
    return rd.system_thermal_equilibrium(s, speed_hz=SPEED, **kw)


def test_temperature_independent_viscosity_is_the_isothermal_active_bearing_bit_for_bit():
    flat = Oil(viscosity_law="exponential", mu_ref_pa_s=0.04, t_ref_c=40.0, beta_1_per_k=1e-300)
    s = _rig()
    assert s.bearings[_active(s)].viscosity_pa_s == 0.04
    r = _thd(s, oil=flat)
    assert r.status == "ok" and r.max_temperature_c[0] > TS + 0.5  # the film heats, μ stays
    assert np.all(r.flows[0]["viscosity_pa_s"] == 0.04)
    iso = rd.equilibrium(s, speed_hz=SPEED, chamber_pressure_pa=PC, config_ay_m=AY,
                         warm_start=False)
    assert np.array_equal(r.r, iso.r)  # rotor and sleeve coordinates
    hot = rd.equilibrium(r.system, speed_hz=SPEED, chamber_pressure_pa=PC, warm_start=False)
    assert np.array_equal(hot.r, iso.r)
    l0 = rd.linearize(s, speed_hz=SPEED, chamber_pressure_pa=PC, config_ay_m=AY)
    l1 = rd.linearize(r.system, speed_hz=SPEED, chamber_pressure_pa=PC)
    assert np.array_equal(l0.KH, l1.KH) and np.array_equal(l0.DH, l1.DH)


def _standalone_field(s, r, field, with_sleeve):
    """The energy equation's field on a Reynolds solve of the active film built here: its
    geometry, the returned viscosity field and h from the returned coordinates."""
    i = _active(s)
    b = s.bearings[i]
    asm = assembled(s)
    bc = next(c for c in asm.bearings if c.index == i)
    g, grid = b.journal_bearing().to_core()
    sol = _core.ReynoldsSolver(g, grid, b.cavitation)
    sol.set_viscosity_field(field)
    phi = 2 * np.pi * np.arange(b.n_circ) / b.n_circ
    w = asm.sleeves[i].interpolation_matrix(phi) @ r.r[list(bc.sleeve)]
    h = b.clearance_m - r.r[bc.jx] * np.cos(phi) - r.r[bc.jy] * np.sin(phi)
    if with_sleeve:
        h = h - w
    h = np.repeat(h[:, None], b.n_axial + 1, axis=1)
    omega = 2 * math.pi * SPEED
    fs = sol.solve(h, np.zeros_like(h), omega)
    opt = _core.ThdOptions()
    opt.supply_temperature_c = TS
    return np.array(_core.thd_energy(sol, fs, VG46.to_core(), opt, omega).temperature_c), w


def test_the_field_is_the_energy_equation_on_the_deformed_film():
    s = _rig()
    r = _thd(s)
    assert r.status == "ok", r.message
    field = r.flows[0]["viscosity_pa_s"]
    np.testing.assert_allclose(field, VG46.viscosity_pa_s(r.temperature_c[0]), rtol=1e-6)
    T, w = _standalone_field(s, r, field, True)
    assert np.max(np.abs(w)) > 0.3 * s.bearings[_active(s)].clearance_m  # a deformed sleeve
    np.testing.assert_allclose(T, r.temperature_c[0], atol=1e-5)
    T_rigid, _ = _standalone_field(s, r, field, False)
    assert np.max(np.abs(T_rigid - r.temperature_c[0])) > 0.1


def test_effective_temperature_film_of_the_active_bearing():
    """The effective-temperature model on the active bearing: the returned system's active
    bearing is isoviscous at μ(T_eff); a Reynolds solve built here at that viscosity on the
    deformed film (h from the returned coordinates, w = W r_s) gives the returned power loss
    (torque·ω), film (groove) flow and side flow (1e-6), which close the heat balance
    P = ρ c_p ΔT (Q − Q_s/2) (1e-9); the rigid-bush film at the same journal position gives a
    power loss more than 1 % away."""
    s = _rig()
    i = _active(s)
    r = _thd(s, model="effective")
    assert r.status == "ok", r.message
    mu = r.viscosity_pa_s[0]
    assert mu == pytest.approx(VG46.viscosity_pa_s(r.effective_temperature_c[0]), rel=1e-12)
    b = r.system.bearings[i]
    assert b.viscosity_pa_s == mu and b.viscosity_field_pa_s is None
    rc = VG46.density_kg_m3 * VG46.specific_heat_j_per_kg_k
    assert r.power_loss_w[0] == pytest.approx(
        rc * r.temperature_rise_k[0] * (r.film_flow_m3_s[0] - 0.5 * r.side_flow_m3_s[0]),
        rel=1e-9)
    assert r.effective_temperature_c[0] == pytest.approx(TS + 0.5 * r.temperature_rise_k[0],
                                                         abs=1e-6)
    asm = assembled(s)
    bc = next(c for c in asm.bearings if c.index == i)
    g, grid = b.journal_bearing().to_core()
    phi = 2 * np.pi * np.arange(b.n_circ) / b.n_circ
    w = asm.sleeves[i].interpolation_matrix(phi) @ r.r[list(bc.sleeve)]
    omega = 2 * math.pi * SPEED
    out = []
    for ww in (w, 0.0 * w):
        sol = _core.ReynoldsSolver(g, grid, b.cavitation)
        h = b.clearance_m - r.r[bc.jx] * np.cos(phi) - r.r[bc.jy] * np.sin(phi) - ww
        h = np.repeat(h[:, None], b.n_axial + 1, axis=1)
        fs = sol.solve(h, np.zeros_like(h), omega)
        # Q: the groove's inflow, or (a groove the film flows into, as here where the sleeve
        # lifts the journal towards the top groove) the flow after the maximum film
        q = fs.inlet_flow_m3_s if fs.inlet_flow_m3_s > 0 else _core.max_film_flow(sol, fs, omega)
        out.append((fs.friction_torque_nm * omega, q, fs.side_flow_m3_s))
    assert out[0] == pytest.approx((r.power_loss_w[0], r.film_flow_m3_s[0],
                                    r.side_flow_m3_s[0]), rel=1e-6)
    assert abs(out[1][0] / out[0][0] - 1.0) > 0.01


@pytest.mark.parametrize("bush_htc", [0.0, 2000.0])
def test_energy_balance_of_the_active_film(bush_htc):
    s = _rig("jfo")
    r = _thd(s, carry_over=0.5, bush_htc_w_m2k=bush_htc)
    assert r.status == "ok", r.message
    out, diss, wall, mass = balance(r.temperature_c[0], r.inlet_mask[0], r.flows[0],
                                    VG46.density_kg_m3 * VG46.specific_heat_j_per_kg_k, TS,
                                    bush_htc, TS)
    assert mass < 1e-8  # the Elrod–Adams film's cells conserve mass
    assert diss > 10.0 and r.inlet_temperature_c[0] > TS  # heated; hot oil carried over
    assert out + wall == pytest.approx(diss, rel=1e-9)
    assert (wall > 0.05 * diss) == (bush_htc > 0)


def test_stiffness_with_the_field_frozen_and_the_returned_system():
    s = _rig()
    r = _thd(s)
    hot = r.system
    assert hot.bearings[_active(s)].config_ay_m == AY  # the offsets used travel with it
    e = rd.equilibrium(hot, speed_hz=SPEED, chamber_pressure_pa=PC, warm_start=False)
    assert e.status == "ok"
    np.testing.assert_allclose(e.r, r.r, atol=1e-9 * s.bearings[_active(s)].clearance_m)
    lp = rd.linearize(hot, speed_hz=SPEED, chamber_pressure_pa=PC)
    lf = rd.linearize(hot, speed_hz=SPEED, chamber_pressure_pa=PC, method="finite_difference")
    li = rd.linearize(s, speed_hz=SPEED, chamber_pressure_pa=PC, config_ay_m=AY)
    scale = np.max(np.abs(lp.KH))
    assert np.max(np.abs(lp.KH - lf.KH)) < 1e-5 * scale
    assert np.max(np.abs(lp.KH - li.KH)) > 1e-3 * scale  # the warm film is softer
    st = rd.stability(hot, speed_hz=SPEED, chamber_pressure_pa=PC)
    assert st.status == "ok" and np.all(np.isfinite(st.eigenvalues))


def test_transient_of_the_returned_system_follows_its_linear_model():
    """The frozen field reaches the transient: a 0.2 µm disturbance of the active journal at
    the THD equilibrium follows the linear model at the same field (1 % of the amplitude;
    observed 0.09 %) and the run stays at the THD equilibrium, which lies further from the
    isothermal one than the disturbance (so an isothermal film would drift away)."""
    import scipy.linalg

    s = _rig()
    r = _thd(s)
    lm = rd.linearize(r.system, speed_hz=SPEED, chamber_pressure_pa=PC)
    n = lm.M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(lm.M, lm.K), -np.linalg.solve(lm.M, lm.D)]])
    tr = rd.transient(r.system, t_end_s=0.004, speed_hz=SPEED, chamber_pressure_pa=PC,
                      disturbance_m=(0.2e-6, 0.0), n_out=9)
    assert tr.status == "ok", tr.message
    jx = next(b for b in assembled(r.system).bearings if b.active).jx
    x0 = np.concatenate([tr.r[0] - lm.equilibrium.r, np.zeros(n)])
    assert abs(x0[jx]) == pytest.approx(0.2e-6, rel=1e-6)
    lin = np.array([(scipy.linalg.expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - lm.equilibrium.r
    assert np.max(np.abs(dev[:, jx] - lin[:, jx])) < 0.01 * np.max(np.abs(lin[:, jx]))
    iso = rd.equilibrium(s, speed_hz=SPEED, chamber_pressure_pa=PC, config_ay_m=AY)
    assert np.max(np.abs(iso.r - r.r)) > 0.2e-6


def test_threshold_with_the_thd_film():
    """``threshold(..., thermal=...)``: each evaluation at its own thermal equilibrium. With a
    temperature-independent oil it is the isothermal threshold to round-off; with VG 46 the
    rig is still unstable (thermal film) at the isothermal threshold, the thermal film's max
    Re λ is zero at its own threshold (1e-4 1/s; the slope is ~1.4e-4 1/s per Pa) and changes
    sign 100 Pa either side of it."""
    flat = Oil(viscosity_law="exponential", mu_ref_pa_s=0.04, t_ref_c=40.0, beta_1_per_k=1e-300)
    s = _rig()
    kw = dict(bounds=(0.03e6, 0.09e6), speed_hz=SPEED, config_ay_m=AY, n_scan=4)
    iso = rd.threshold(s, **kw)
    assert iso.status == "ok" and len(iso.crossings) == 1
    f = rd.threshold(s, **kw, thermal=dict(oil=flat, supply_temperature_c=TS, model="thd"))
    # equal to round-off: each equilibrium warm-starts from the last one this process solved
    # and is polished to the round-off floor, so two identical calls differ by ~2e-13
    # relative (three isothermal calls in one process: 57043.39329712198, …13173, …139955 Pa)
    np.testing.assert_allclose(f.crossings, iso.crossings, rtol=1e-11, atol=0.0)
    th = dict(oil=VG46, supply_temperature_c=TS, model="thd")
    h = rd.threshold(s, **kw, thermal=th)
    assert h.status == "ok" and h.stable_side == "above"

    def growth(pc):
        t = _thd(s, chamber_pressure_pa=pc)
        st = rd.stability(t.system, speed_hz=SPEED, chamber_pressure_pa=pc)
        return float(np.max(st.eigenvalues.real))
    assert growth(iso.value) > 0.0
    assert abs(growth(h.value)) < 1e-4
    assert growth(h.value - 100.0) > 0.0 > growth(h.value + 100.0)
    with pytest.raises(InputError, match="thermal.chamber_pressure_pa"):
        rd.threshold(s, **kw, thermal=dict(th, chamber_pressure_pa=1e5))
    with pytest.raises(InputError, match="thermal.oli"):
        rd.threshold(s, **kw, thermal=dict(oli=VG46))


def test_model_file_round_trip_with_the_thd_active_bearing(tmp_path):
    s = _rig()
    i = _active(s)
    s = dataclasses.replace(
        s, thermal=ThermalModel(supply_temperature_c=TS, oil=VG46, model="thd"),
        bearings=tuple(dataclasses.replace(b, config_ay_m=AY) if k == i else b
                       for k, b in enumerate(s.bearings)))
    p = tmp_path / "rig.toml"
    s.to_toml(p)
    back = rd.System.from_toml(p)
    assert back.thermal == s.thermal and back.bearings == s.bearings
    a = rd.system_thermal_equilibrium(back, speed_hz=SPEED, chamber_pressure_pa=PC)
    b = _thd(s, config_ay_m=None)
    assert a.thermal_model == "thd" and a.status == "ok"
    np.testing.assert_array_equal(a.temperature_c[0], b.temperature_c[0])
    np.testing.assert_array_equal(a.r, b.r)
    p2 = tmp_path / "hot.toml"
    a.system.to_toml(p2)
    hot = rd.System.from_toml(p2)
    assert hot.bearings[i].viscosity_field_pa_s == a.system.bearings[i].viscosity_field_pa_s
    e0 = rd.equilibrium(a.system, speed_hz=SPEED, chamber_pressure_pa=PC, warm_start=False)
    e1 = rd.equilibrium(hot, speed_hz=SPEED, chamber_pressure_pa=PC, warm_start=False)
    np.testing.assert_array_equal(e0.r, e1.r)
    fr = a.to_frame()
    assert list(fr["bearing"]) == [s.bearings[i].name or f"bearing[{i}]"]
    for c in ("max_temperature_c", "effective_temperature_c", "power_loss_w",
              "film_flow_m3_s", "side_flow_m3_s"):
        assert np.isfinite(fr[c]).all() and (fr[c] > 0).all()


def test_bad_input_names_the_field():
    s = _rig()
    i = _active(s)
    b = s.bearings[i]
    with pytest.raises(InputError, match="viscosity_field_pa_s"):
        dataclasses.replace(b, viscosity_field_pa_s=np.full((b.n_circ, b.n_axial), 0.04))
    with pytest.raises(InputError, match="viscosity_field_pa_s"):
        dataclasses.replace(b, viscosity_field_pa_s=np.full((b.n_circ, b.n_axial + 1), -1.0))
    with pytest.raises(InputError, match="chamber_pressure_pa"):
        _thd(s, chamber_pressure_pa=-1.0)
    with pytest.raises(InputError, match="config_ay_m"):
        _thd(s, config_ay_m=float("nan"))
    with pytest.raises(InputError, match="bush_htc_w_m2k"):
        _thd(s, bush_htc_w_m2k=-1.0)
    with pytest.raises(InputError, match="bearings"):
        _thd(s, bearings=[len(s.bearings)])


def test_cli_thermal_on_the_rig_with_the_housing_offset(tmp_path, capsys):
    """``rotordyn thermal`` with ``--config-ay-m`` (refused before) prints the Python call's
    numbers (1e-9) on the rig's file."""
    import json

    from rotordyn.cli import main

    s = _rig()
    p = tmp_path / "rig.toml"
    s.to_toml(p)
    assert main(["thermal", str(p), "--speed-hz", str(SPEED), "--chamber-pressure-pa",
                 str(PC), "--config-ay-m", str(AY), "--supply-temperature-c", str(TS),
                 "--oil-walther", "40", "46", "100", "6.8", "--density-kg-m3", "870",
                 "--specific-heat-j-per-kg-k", "2000", "--model", "thd", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    r = _thd(s)
    assert out["thermal_model"] == "thd" and out["status"] == "ok"
    for col in ("max_temperature_c", "effective_temperature_c", "power_loss_w",
                "film_flow_m3_s", "side_flow_m3_s"):
        np.testing.assert_allclose([row[col] for row in out["bearings"]], getattr(r, col),
                                   rtol=1e-9)


def test_thermal_sweep_on_the_rig_equals_direct_calls(tmp_path):
    """The ``thermal`` sweep analysis on the rig with ``[thermal] model = "thd"``, over p_c
    and the active bearing's own housing offset: every row equals the direct call (1e-9)."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep
    from rotordyn.sweep.paths import set_field

    s = _rig()
    i = _active(s)
    s = dataclasses.replace(s, thermal=ThermalModel(supply_temperature_c=TS, oil=VG46,
                                                    model="thd"))
    s.to_toml(tmp_path / "m.toml")
    ay = f"bearings.{s.bearings[i].name.replace(' ', '_')}.config_ay_m"
    spec = tmp_path / "s.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "thd"\nmodel = "m.toml"\n'
                    'analysis = "thermal"\nchunk_size = 2\n[grid]\n'
                    f'chamber_pressure_pa = [1e5, 2e5]\n"{ay}" = [-1.85e-3, -1.7e-3]\n'
                    f'speed_hz = {SPEED}\n')
    res = run_sweep(spec, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    assert len(fr) == 4 and (fr["status"] == "ok").all()
    for _, row in fr.iterrows():
        m = set_field(s, ay, float(row[ay]))
        r = rd.system_thermal_equilibrium(m, speed_hz=SPEED,
                                          chamber_pressure_pa=float(row["chamber_pressure_pa"]))
        for c in ("max_temperature_c", "effective_temperature_c", "power_loss_w",
                  "journal_x_m", "journal_y_m"):
            assert row[c] == pytest.approx(getattr(r, c)[0], rel=1e-9, abs=1e-15)
    assert fr["max_temperature_c"].nunique() == 4


def test_not_the_rig_compressor_with_an_active_bearing():
    """The THD film on a rotor that is not the rig: tests/data/models/compressor_active.toml
    (a plain NDE bearing beside an active DE bearing, 150 Hz, 0.3 MPa, no a_y offset). A
    temperature-independent oil gives the isothermal system bit for bit (both films, rotor and
    sleeve coordinates, K_H, D_H); ISO VG 46 heats both films, the returned system reproduces
    the thermal equilibrium (its frozen fields) and linearises to finite K_H, D_H."""
    from pathlib import Path

    s = rd.System.from_toml(Path(__file__).parent / "data" / "models" / "compressor_active.toml")
    speed, pc = 150.0, 0.3e6
    mu = {b.viscosity_pa_s for b in s.bearings if hasattr(b, "viscosity_pa_s")}
    assert len(mu) == 1
    flat = Oil(viscosity_law="exponential", mu_ref_pa_s=mu.pop(), t_ref_c=40.0,
               beta_1_per_k=1e-300)
    kw = {"speed_hz": speed, "chamber_pressure_pa": pc, "model": "thd",
          "supply_temperature_c": TS}
    r = rd.system_thermal_equilibrium(s, oil=flat, **kw)
    assert r.status == "ok"
    iso = rd.equilibrium(s, speed_hz=speed, chamber_pressure_pa=pc, warm_start=False)
    assert np.array_equal(r.r, iso.r)
    l0 = rd.linearize(s, speed_hz=speed, chamber_pressure_pa=pc)
    l1 = rd.linearize(r.system, speed_hz=speed, chamber_pressure_pa=pc)
    assert np.array_equal(l0.KH, l1.KH) and np.array_equal(l0.DH, l1.DH)
    hot = rd.system_thermal_equilibrium(s, oil=VG46, **kw)
    assert hot.status == "ok" and len(hot.max_temperature_c) == 2
    assert all(t > TS + 1.0 for t in hot.max_temperature_c)
    again = rd.equilibrium(hot.system, speed_hz=speed, chamber_pressure_pa=pc, warm_start=False)
    assert np.max(np.abs(again.r - hot.r)) < 1e-9 * s.bearings[_active(s)].clearance_m
    lin = rd.linearize(hot.system, speed_hz=speed, chamber_pressure_pa=pc)
    assert np.isfinite(lin.KH).all() and np.isfinite(lin.DH).all()
    assert not np.array_equal(lin.KH, l0.KH)


def test_threshold_does_not_depend_on_what_ran_before():
    """Each threshold call's first equilibrium starts cold: three identical calls with other
    work between them give one value bit for bit (they differed by ~2e-13 relative when the
    first equilibrium warm-started from whatever the process had solved last)."""
    s = _rig()
    kw = dict(bounds=(0.03e6, 0.09e6), speed_hz=SPEED, config_ay_m=AY, n_scan=4)
    first = rd.threshold(s, **kw).value
    rd.equilibrium(s, 80.0, 0.3e6, AY)
    second = rd.threshold(s, **kw).value
    rd.stability(s, 30.0, 0.1e6, 0.0)
    assert rd.threshold(s, **kw).value == second == first
