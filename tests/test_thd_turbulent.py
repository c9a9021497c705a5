"""Turbulent films with a temperature field (issue 20): the Ng–Pan–Elrod film (Ng & Pan 1965,
J. Basic Eng. 87, 675–688; fits of Taylor & Dowson 1974, J. Lubr. Technol. 96(1) 36–46) with a
viscosity per node, as the THD film and the frozen fields of the thermal dynamics give it.

Model (docs/film-physics.md, "Turbulent films with a temperature field"): every face's
Poiseuille conductance h³/(k μ_face) takes k at the face's own Re_h = ρ|ω|R h/μ_face, every
node's Couette wall shear C_f μ U/h its node's Re_h; the energy equation's dissipation takes
the same C_f (so it is the friction power the torque gives).

Checks:
* a uniform field equal to the film's viscosity is the turbulent film bit for bit (p, K, C);
* a uniform field 2μ on a μ film equals the turbulent film of viscosity 2μ (Re_h halves with
  it; the film that kept the reference Re_h differs by > 5 % at Re_h ≈ 2000);
* density → 0 with a field is the laminar film with that field;
* on a full film (no cavitation) the THD dissipation equals the friction power to round-off
  (the discrete identity pᵀA p = pᵀb with C_f in both);
* a temperature-independent oil: the turbulent THD equilibrium is the isothermal turbulent one;
* perturbation K, C of a turbulent film with a non-uniform field against central
  differences of its forces;
* a large fast bearing (D = 0.3 m, 100 Hz, Re_h ≈ 1900 at h = c): the turbulent THD film
  loses more power and runs hotter than the laminar THD film;
* the compressor on tilting pads with turbulent pads and its oil system: stability with the
  thermal equilibrium runs (effective and THD), and the effective model's pad power loss
  includes the turbulent wall shear (it did not: 0.6 % below the laminar pads' loss).
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import Oil

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
# large, fast: D = 0.3 m, c = 0.45 mm, 100 Hz: Re_h = ρ ω R c / μ ≈ 870·628·0.15·4.5e-4/0.0194
BIG = dict(diameter_m=0.3, length_m=0.15, clearance_m=4.5e-4)
SPEED, TS = 100.0, 45.0
W = 2.0 * math.pi * SPEED
LOAD = (0.0, -60e3)


def _solver(mu, rho=870.0, turbulence="ng_pan", n_circ=48, n_axial=12, field=None,
            cavitation="reynolds"):
    b = rotordyn.JournalBearing(viscosity_pa_s=mu, turbulence=turbulence, density_kg_m3=rho,
                                n_circ=n_circ, n_axial=n_axial, **BIG)
    g, grid = b.to_core()
    s = _core.ReynoldsSolver(g, grid, cavitation)
    if field is not None:
        s.set_viscosity_field(np.full((n_circ, n_axial + 1), field)
                              if np.ndim(field) == 0 else field)
    return s


def _state(s, x=1.5e-4, y=-2.4e-4):
    sol = s.rigid(x, y, 0.0, 0.0, W)
    c = s.coefficients(x, y, W)
    return np.array(sol.p_pa), np.array(sol.force_n), np.array(c.K), np.array(c.C)


def test_uniform_field_is_the_turbulent_film_bit_for_bit():
    mu = VG32.viscosity_pa_s(50.0)
    a, b = _state(_solver(mu)), _state(_solver(mu, field=mu))
    assert abs(870.0 * W * 0.15 * 4.5e-4 / mu - 1900.0) < 150.0  # the Re_h this checks at
    for u, v in zip(a, b):
        assert np.array_equal(u, v)


def test_field_sets_the_local_reynolds_number():
    mu = VG32.viscosity_pa_s(50.0)
    got = _state(_solver(mu, field=2.0 * mu))
    ref = _state(_solver(2.0 * mu))
    for u, v in zip(got, ref):
        np.testing.assert_allclose(u, v, rtol=1e-11, atol=1e-11 * np.abs(v).max())
    # the film that kept the reference viscosity's Re_h (a 2μ film at twice the density)
    kept = _state(_solver(2.0 * mu, rho=2 * 870.0))
    assert np.linalg.norm(kept[1] - got[1]) > 0.05 * np.linalg.norm(got[1])


def test_density_to_zero_with_a_field_is_the_laminar_field():
    mu = VG32.viscosity_pa_s(50.0)
    rng = np.random.default_rng(3)
    field = mu * (1.0 + 0.5 * rng.random((48, 13)))
    t = _state(_solver(mu, rho=1e-12, field=field))
    lam = _state(_solver(mu, turbulence="laminar", field=field))
    for u, v in zip(t, lam):
        np.testing.assert_allclose(u, v, rtol=1e-9, atol=1e-9 * np.abs(v).max())


def _big(turbulence="ng_pan", n_circ=48, n_axial=12, cavitation="reynolds", **kw):
    return rotordyn.JournalBearing(viscosity_pa_s=VG32.viscosity_pa_s(TS), n_circ=n_circ,
                                   n_axial=n_axial, turbulence=turbulence,
                                   density_kg_m3=VG32.density_kg_m3, cavitation=cavitation,
                                   **BIG, **kw)


def test_turbulent_full_film_dissipation_is_the_friction_power():
    """On a full film the face dissipation (turbulent conductances) plus the Couette C_f μU²/h
    is the friction power torque·ω to round-off, as for the laminar film
    (tests/test_film_thd.py); without C_f in the dissipation it was 10–20 % low here."""
    for n, m in ((36, 8), (72, 16)):
        r = _big(n_circ=n, n_axial=m, cavitation="none").thermal_equilibrium(
            load_n=(0.0, -20e3), speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
            model="thd")
        assert r.status == "ok"
        assert abs(r.power_loss_w / r.friction_power_w - 1.0) < 1e-12, (n, m)


def test_temperature_independent_oil_is_the_isothermal_turbulent_film():
    flat = Oil(viscosity_law="exponential", mu_ref_pa_s=0.02, t_ref_c=40.0, beta_1_per_k=1e-300,
               density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
    b = rotordyn.JournalBearing(viscosity_pa_s=0.02, n_circ=48, n_axial=12,
                                turbulence="ng_pan", density_kg_m3=870.0, **BIG)
    r = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=flat, supply_temperature_c=TS,
                              model="thd")
    assert r.status == "ok" and r.max_temperature_c > TS + 5.0
    e = b.static_equilibrium(load_n=LOAD, speed_hz=SPEED)
    assert (r.x_m, r.y_m) == pytest.approx((e.x_m, e.y_m), rel=1e-10, abs=1e-16)
    K, C = b.coefficients(x_m=r.x_m, y_m=r.y_m, speed_hz=SPEED)
    np.testing.assert_allclose(r.K, K, rtol=1e-8, atol=1e-8 * np.abs(K).max())
    np.testing.assert_allclose(r.C, C, rtol=1e-8, atol=1e-8 * np.abs(C).max())


def test_perturbation_coefficients_with_a_field_against_finite_differences():
    mu = VG32.viscosity_pa_s(55.0)
    z = np.linspace(-1.0, 1.0, 13)
    phi = np.arange(48) * 2 * np.pi / 48
    field = mu * (1.0 + 0.3 * np.cos(phi)[:, None] + 0.2 * z[None, :] ** 2)
    s = _solver(mu, field=field)
    x, y = 1.5e-4, -2.4e-4
    c = s.coefficients(x, y, W)
    K, C = np.array(c.K), np.array(c.C)
    d, v = 1e-7 * 4.5e-4, 1e-6 * W * 4.5e-4

    def f(dx=0.0, dy=0.0, vx=0.0, vy=0.0):
        return np.array(s.rigid(x + dx, y + dy, vx, vy, W).force_n)
    Kfd = -np.column_stack([(f(dx=d) - f(dx=-d)) / (2 * d), (f(dy=d) - f(dy=-d)) / (2 * d)])
    Cfd = -np.column_stack([(f(vx=v) - f(vx=-v)) / (2 * v), (f(vy=v) - f(vy=-v)) / (2 * v)])
    # measured 4.0e-10 (K) and 4.3e-11 (C) of the largest entry at these steps
    np.testing.assert_allclose(K, Kfd, rtol=0, atol=1e-8 * np.abs(K).max())
    np.testing.assert_allclose(C, Cfd, rtol=0, atol=1e-9 * np.abs(C).max())


def test_large_fast_bearing_turbulent_thd_runs_hotter_than_laminar():
    lam = _big("laminar").thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                               supply_temperature_c=TS, model="thd")
    tur = _big().thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                     supply_temperature_c=TS, model="thd")
    assert lam.status == "ok" and tur.status == "ok"
    assert tur.power_loss_w > 1.2 * lam.power_loss_w
    assert tur.max_temperature_c > lam.max_temperature_c + 2.0
    assert np.all(np.isfinite(tur.K)) and np.all(np.isfinite(tur.C))


def _pads(turbulence):
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    th = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    th = dataclasses.replace(th, films=())
    return dataclasses.replace(s, thermal=th, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6, turbulence=turbulence,
                            density_kg_m3=860.0) for b in s.bearings))


def test_tilting_pad_compressor_turbulent_thermal_stability():
    lam, tur = _pads("laminar"), _pads("ng_pan")
    pl = rotordyn.stability(lam, 150.0, thermal=True)
    pt = rotordyn.stability(tur, 150.0, thermal=True)
    assert pl.thermal.status == "ok" and pt.thermal.status == "ok"
    # the turbulent wall shear adds to every pad's loss (Re_h ≈ 200-450: C_f ≈ 1.2-1.4)
    ratio = np.asarray(pt.thermal.power_loss_w) / np.asarray(pl.thermal.power_loss_w)
    assert np.all(ratio > 1.05), ratio
    assert np.all(np.isfinite(pt.eigenvalues))
    thd = rotordyn.stability(tur, 150.0, thermal=dict(model="thd"))
    assert thd.thermal.status == "ok" and np.all(np.isfinite(thd.eigenvalues))
    # the two thermal models' pad losses agree within the effective model's own spread
    np.testing.assert_allclose(thd.thermal.power_loss_w, pt.thermal.power_loss_w, rtol=0.05)
