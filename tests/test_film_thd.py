"""Thermo-hydrodynamic (THD) film of a plain journal bearing (issue 20; docs/film-physics.md
§"Thermo-hydrodynamic film"): the energy equation over the Reynolds grid, μ(T) per node,
iterated with the equilibrium (C++ ``thd_equilibrium``).

Checks:
* a temperature-independent viscosity (exponential law with β = 1e-300: μ(T) = μ_ref exactly)
  gives the isothermal film bit for bit (pressure at the same journal position; K, C), and a
  uniform viscosity field equal to the solver's viscosity likewise;
* energy balance of the adiabatic film on a mass-conserving (Elrod–Adams) film: the heat the
  flows carry out of the film (side leakage and the flow back to the inlet, minus the inlet
  flow, at their temperatures; recomputed here from the returned face flows and temperature
  field) equals the dissipation of the film's cells to round-off (1e-9), and with wall heat
  transfer the walls' share closes it the same way; the whole bearing (side leakage, the flow
  not carried over, every cell's walls) takes the reported power loss to 1e-9;
* the dissipation (μU²θ/h + h³|∇p|²/12μ) against the friction power torque·ω: on a full
  film they are equal to round-off (the discrete identity pᵀA p = pᵀb);
* grid convergence of T_max: the observed order of the first-order upwind energy equation
  (72×16 … 288×64);
* the THD mean temperature against the effective-temperature model's T_eff (k = 0.5) on the
  same case, within the band stated in the docs;
* bad input names the field.
No published THD benchmark (e.g. Ferron, Frêne & Boncompain 1983) is among the project's
references, so none is compared here (docs/film-physics.md says so).
"""

import math

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import Groove, Oil
from rotordyn.errors import InputError

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
GEO = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4)
LOAD, SPEED, TS = (0.0, -5000.0), 100.0, 45.0


def _bearing(n_circ=72, n_axial=16, **kw):
    return rotordyn.JournalBearing(viscosity_pa_s=VG32.viscosity_pa_s(TS), n_circ=n_circ,
                                   n_axial=n_axial, **GEO, **kw)


def test_temperature_independent_viscosity_is_the_isothermal_film_bit_for_bit():
    flat = Oil(viscosity_law="exponential", mu_ref_pa_s=0.02, t_ref_c=40.0, beta_1_per_k=1e-300)
    assert flat.viscosity_pa_s(90.0) == 0.02
    b = _bearing()
    r = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=flat, supply_temperature_c=TS,
                              model="thd")
    assert r.status == "ok" and r.max_temperature_c > TS + 5.0  # the film heats, μ stays
    assert np.all(r.viscosity_pa_s == 0.02)
    iso = rotordyn.JournalBearing(viscosity_pa_s=0.02, n_circ=72, n_axial=16, **GEO)
    e = iso.static_equilibrium(load_n=LOAD, speed_hz=SPEED)
    assert (r.x_m, r.y_m) == pytest.approx((e.x_m, e.y_m), rel=1e-12, abs=1e-18)
    # same position, same pressure, bit for bit; K, C too
    g, grid = iso.to_core()
    s_iso = _core.ReynoldsSolver(g, grid, "reynolds")
    s_fld = _core.ReynoldsSolver(g, grid, "reynolds")
    s_fld.set_viscosity_field(np.full((72, 17), 0.02))
    w = 2 * math.pi * SPEED
    p0 = np.array(s_iso.rigid(r.x_m, r.y_m, 0.0, 0.0, w).p_pa)
    p1 = np.array(s_fld.rigid(r.x_m, r.y_m, 0.0, 0.0, w).p_pa)
    assert np.array_equal(p0, p1)
    c0, c1 = s_iso.coefficients(r.x_m, r.y_m, w), s_fld.coefficients(r.x_m, r.y_m, w)
    assert np.array_equal(np.array(c0.K), np.array(c1.K))
    assert np.array_equal(np.array(c0.C), np.array(c1.C))
    np.testing.assert_allclose(r.K, np.array(c0.K), rtol=1e-9)


def _balance(r, rho_c, ts):
    """Heat carried out of the film by the flows (W), the dissipation of its cells (W) and
    the worst relative mass defect of an inner cell, recomputed from the face flows and the
    temperature field (upwind face temperatures; tests/thd_balance.py)."""
    from thd_balance import balance

    heat, diss, _, mass = balance(r.temperature_c, r.inlet_mask, r.flows, rho_c, ts)
    return heat, diss, mass


def _heat_out(r, rho_c, ts, lam):
    """The whole bearing's heat out relative to T_s (W): side leakage, the part of the flow
    reaching the inlet that is not carried over, the walls (each cell's, the inlet's at T_in)."""
    return (rho_c * (r.side_flow_m3_s * (r.side_temperature_c - ts) + (1.0 - lam)
                     * r.recirculation_flow_m3_s * (r.recirculation_temperature_c - ts))
            + r.heat_to_journal_w + r.heat_to_bush_w)


def test_energy_balance_adiabatic_and_with_walls():
    b = _bearing(cavitation="jfo", grooves=[Groove(center_deg=90.0, width_deg=20.0)])
    rc = VG32.density_kg_m3 * VG32.specific_heat_j_per_kg_k
    r = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                              model="thd", carry_over=0.5)
    assert r.status == "ok"
    out, diss, mass = _balance(r, rc, TS)
    assert mass < 1e-8                      # the film's cells conserve mass (Elrod–Adams)
    assert out == pytest.approx(diss, rel=1e-9)
    assert r.heat_to_journal_w == 0.0 and r.heat_to_bush_w == 0.0
    assert r.inlet_temperature_c > TS       # hot oil carried over
    # the whole bearing against its reported power (the film's cells' dissipation: a groove's
    # nodes are not film, "Heat of the inlet cells"; the ungrooved full film, whose inlet
    # column is film: tests/test_thd_inlet_heat.py)
    assert _heat_out(r, rc, TS, 0.5) == pytest.approx(r.power_loss_w, rel=1e-9)
    assert r.power_loss_w == pytest.approx(diss, rel=1e-12)
    # with heat transfer to journal and bush: flows + walls = dissipation
    w = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                              model="thd", carry_over=0.5, journal_htc_w_m2k=2000.0,
                              bush_htc_w_m2k=1000.0)
    out_w, diss_w, _ = _balance(w, rc, TS)
    assert w.heat_to_journal_w > 0.0 and w.heat_to_bush_w > 0.0
    fw = w.inlet_mask == 0                  # the film's cells: their walls close their balance
    A, T = w.flows["area_m2"], w.temperature_c
    walls_film = (A * (2000.0 * (T - TS) + 1000.0 * (T - TS)))[fw].sum()
    assert out_w + walls_film == pytest.approx(diss_w, rel=1e-9)
    assert _heat_out(w, rc, TS, 0.5) == pytest.approx(w.power_loss_w, rel=1e-9)
    assert w.max_temperature_c < r.max_temperature_c


def test_dissipation_against_friction_power():
    """Σ Φ and torque·ω: on a full film (no cavitation, θ = 1) the face dissipation c Δp²
    summed is pᵀA p = pᵀb, the discrete form of ∫ (U h/2) ∂p/∂x: the two agree to round-off
    (1e-12) on every grid. On the Elrod–Adams film the torque counts the end half-cells of the
    cavitated zone as full (θ = 1 on the end rows) where the energy equation takes their inner
    rows' fill: a first-order gap (observed -0.51 % at 72×16, -0.26 % at 144×32). Σ Φ over
    every cell, the groove's included: the power loss leaves the groove's nodes out (they are
    not film, docs/film-physics.md "Heat of the inlet cells"), the torque has them."""
    def gap(n, m, cav):
        r = _bearing(n, m, cavitation=cav, grooves=[Groove(center_deg=90.0)]).thermal_equilibrium(
            load_n=(0.0, -1000.0), speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
            model="thd")
        groove = np.asarray(r.inlet_mask) > 0
        diss = np.asarray(r.flows["dissipation_w"])
        assert r.power_loss_w == pytest.approx(diss[~groove].sum(), rel=1e-12)
        return abs(diss.sum() / r.friction_power_w - 1.0)
    for n, m in ((36, 8), (72, 16), (144, 32)):
        assert gap(n, m, "none") < 1e-12
    g1, g2 = gap(72, 16, "jfo"), gap(144, 32, "jfo")
    assert g1 < 6e-3 and 0.7 < math.log2(g1 / g2) < 1.3, (g1, g2)


def test_grid_convergence_of_the_maximum_temperature():
    """T_max of the Elrod–Adams film on 72×16, 144×32, 288×64: the successive differences
    shrink at the upwind scheme's first order (observed 1.09; band [0.8, 1.4]); the 288×64
    value is within 1 % of the rise of the Richardson extrapolate (observed 0.5 %)."""
    t = []
    for n, m in ((72, 16), (144, 32), (288, 64)):
        r = _bearing(n, m, cavitation="jfo", grooves=[Groove(center_deg=90.0, width_deg=20.0)]
                     ).thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                           supply_temperature_c=TS, model="thd")
        t.append(r.max_temperature_c)
    d = np.diff(t)
    order = math.log2(d[0] / d[1])
    assert 0.8 < order < 1.4, (t, order)
    ext = t[-1] + d[-1] / (2.0 ** order - 1.0)
    assert abs(t[-1] - ext) < 0.01 * (ext - TS), (t, ext)


def test_thd_mean_temperature_against_the_effective_model():
    """Same bearing (Swift–Stieber, no groove), oil, supply: the THD film's area-mean
    temperature and the effective model's T_eff (k = 0.5) agree within 35 % of the effective
    model's rise (observed: THD 59.2 degC, effective 55.8 degC, rise 10.8 K: 31 %); the THD
    maximum lies above the effective T_eff, the eccentricities within 0.03."""
    b = _bearing()
    th = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                               model="thd")
    ef = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS)
    rise = ef.effective_temperature_c - TS
    assert abs(th.mean_temperature_c - ef.effective_temperature_c) < 0.35 * rise
    assert th.max_temperature_c > ef.effective_temperature_c
    assert abs(th.eccentricity_ratio - ef.eccentricity_ratio) < 0.03
    df = th.to_frame()
    assert df.loc[0, "thermal_model"] == "thd" and len(th.temperature_frame()) == 72 * 17


def test_thd_bad_input_names_the_field():
    b = _bearing()
    kw = dict(load_n=LOAD, speed_hz=SPEED, supply_temperature_c=TS, model="thd")
    with pytest.raises(InputError, match="specific_heat_j_per_kg_k"):
        Oil(specific_heat_j_per_kg_k=-2000.0)
    with pytest.raises(InputError, match="journal_htc_w_m2k"):
        b.thermal_equilibrium(oil=VG32, journal_htc_w_m2k=float("nan"), **kw)
    with pytest.raises(InputError, match="bush_htc_w_m2k"):
        b.thermal_equilibrium(oil=VG32, bush_htc_w_m2k=float("inf"), **kw)
    with pytest.raises(InputError, match="bush_htc_w_m2k"):
        b.thermal_equilibrium(oil=VG32, bush_htc_w_m2k=-1.0, **kw)
    with pytest.raises(InputError, match="model"):
        b.thermal_equilibrium(oil=VG32, load_n=LOAD, speed_hz=SPEED, supply_temperature_c=TS,
                              model="adiabatic")
    g, grid = b.to_core()
    s = _core.ReynoldsSolver(g, grid, "reynolds")
    with pytest.raises(InputError, match="viscosity_pa_s"):
        s.set_viscosity_field(np.full((72, 16), 0.02))
    with pytest.raises(InputError, match="viscosity_pa_s"):
        s.set_viscosity_field(np.full((72, 17), -0.02))
