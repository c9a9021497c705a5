"""Standalone thermal equilibrium of plain journal bearings and tilting-pad bearings with a
tilted journal (issue 20; docs/film-physics.md, "Thermal films with a tilted journal"):
``JournalBearing.thermal_equilibrium(..., theta_x_rad, theta_y_rad | tilt=True)`` (THD and
effective-temperature models) and ``TiltingPadBearing.thermal_equilibrium(..., theta_x_rad,
theta_y_rad)`` (``tilt = True``). Before, both refused the tilt (InputError "a tilted
journal's standalone thermal equilibrium is FixedGeometryBearing.thermal_equilibrium's").

Bearings of the compressor of tests/data/models (not the paper rig): a plain bearing
D = 0.1 m, L = 0.05 m, c = 0.1 mm (48 × 8) under 4 kN at 100 Hz, and its 5-pad rocker
tilting-pad bearing (60° pads, preload 0.3, load between pads; 48 × 6) under 1.5 kN at
150 Hz; VG 32 supplied at 45 °C.

What is compared, and why the tolerances:
* zero tilt, tilting pads: the pads' films with the tilt held as exact zeros in their base
  films (the tilted path) against the untilted bearing's own films: bit for bit (position,
  pad tilts, temperature fields, K, C);
* zero tilt, plain bearing: the tilted path (the four-coordinate film reduced by the imposed
  tilt into a full (φ, z) base thickness) against the untilted film built independently as a
  plain two-coordinate coupling in the same core call: bit for bit; against the untilted
  standalone result (``JournalBearing.thermal_equilibrium`` without a tilt, whose Newton is
  the ReynoldsSolver's, not the system core's) to that Newton's tolerance: position 1e-7 c,
  temperatures 1e-6 K (tol_k 1e-9 here; observed ~1e-10 c, ~1e-9 K);
* a tilt and its opposite mirror each other in z (h(φ, z; −θ) = h(φ, −z; θ)): the same
  position (1e-9 c), the fields mirrored (1e-8 K), opposite moments (1e-8 of their size), the
  edge film at the opposite edge;
* the returned pose is an equilibrium of the frozen-field film: the standalone tilted film of
  the frozen bearing (``tilted_forces`` with the THD field or μ(T_eff); another film builder
  and the pads' own equilibrium) at the returned (x, y, θ) carries the load to 1e-8 of it
  (the polished Newton's tolerance is 1e-10), and its moments, edge film and 4×4 K, C equal
  the result's (1e-8);
* a tilt closing the film at an edge, a non-finite tilt, a non-boolean ``tilt``: InputError
  naming the field.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import FluidFilmBearing, Oil
from rotordyn.bearings.thd import thd_options
from rotordyn.bearings.thermal import thermal_options
from rotordyn.bearings.tilt import tilted_coefficients, tilted_forces
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
PLAIN = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.02,
             n_circ=48, n_axial=8)
KW = dict(load_n=(0.0, -4000.0), speed_hz=100.0, oil=VG32, supply_temperature_c=45.0,
          carry_over=0.5, tol_k=1e-9)
PKW = dict(load_n=(0.0, -1500.0), speed_hz=150.0, oil=VG32, supply_temperature_c=45.0,
           carry_over=0.5)


def _plain():
    return rotordyn.JournalBearing(**PLAIN)


def _pads(**kw):
    b = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml").bearings[0]
    return dataclasses.replace(b, n_circ=48, n_axial=6, **kw)


def _untilted_core(model):
    """The untilted plain film as a two-coordinate coupling (no tilt columns, no base
    thickness) in the system core's thermal call, built here independently."""
    b = _plain()
    g, grid = b.to_core()
    f = _core.FilmCoupling()
    f.name, f.geometry, f.grid, f.cavitation = "bearing", g, grid, b.cavitation
    f.coords = [0, 1]
    phi = 2 * np.pi * np.arange(b.n_circ) / b.n_circ
    f.shape = np.column_stack([-np.cos(phi), -np.sin(phi)])
    m = _core.SystemModel()
    z2 = np.zeros((2, 2))
    m.M, m.K, m.C, m.G = z2, z2, z2, z2
    m.Q, m.chamber = np.array(KW["load_n"], dtype=float), np.zeros(2)
    m.films = [f]
    tf = _core.ThermalFilm()
    tf.film, tf.oil, tf.thd = 0, VG32.to_core(), model == "thd"
    if model == "thd":
        tf.thd_options = thd_options(supply_temperature_c=45.0, carry_over=0.5, tol_k=1e-9)
    else:
        tf.options = thermal_options(supply_temperature_c=45.0, carry_over=0.5, tol_k=1e-9)
    opt = _core.EquilibriumOptions()
    opt.polish = True
    return _core.thermal_system_equilibrium(m, [tf], 2 * np.pi * KW["speed_hz"], 0.0,
                                            np.zeros(2), opt)


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_plain_zero_tilt_is_the_untilted_film(model):
    b = _plain()
    t = b.thermal_equilibrium(**KW, model=model, tilt=True)
    ref = _untilted_core(model)
    st = ref.films[0]
    assert t.status == "ok" and ref.equilibrium.status == "ok"
    assert (t.x_m, t.y_m) == tuple(ref.equilibrium.r)
    assert t.max_temperature_c == st.max_temperature_c
    assert t.power_loss_w == st.power_loss_w and t.iterations == ref.iterations
    if model == "thd":
        assert np.array_equal(t.temperature_c, np.array(st.temperature_c))
        assert t.mean_temperature_c == st.mean_temperature_c
    else:
        assert t.effective_temperature_c == st.effective_temperature_c
    assert t.K4.shape == (4, 4) and np.abs(t.film_moment_n_m).max() < 1e-9  # even in z: none
    assert t.h_min_z_m == 0.0
    # the untilted standalone result (another Newton) to its tolerance
    u = b.thermal_equilibrium(**KW, model=model)
    assert u.K is not None and getattr(u, "K4", None) is None
    c = b.clearance_m
    assert (t.x_m, t.y_m) == pytest.approx((u.x_m, u.y_m), abs=1e-7 * c)
    assert t.max_temperature_c == pytest.approx(u.max_temperature_c, abs=1e-6)
    assert t.power_loss_w == pytest.approx(u.power_loss_w, rel=1e-6)
    np.testing.assert_allclose(t.K, u.K, atol=1e-6 * np.abs(u.K).max())
    np.testing.assert_allclose(t.C, u.C, atol=1e-6 * np.abs(u.C).max())
    if model == "thd":
        np.testing.assert_allclose(t.temperature_c, u.temperature_c, atol=1e-6)
        assert t.side_temperature_c == pytest.approx(u.side_temperature_c, abs=1e-6)
        assert t.friction_power_w == pytest.approx(u.friction_power_w, rel=1e-6)


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_plain_tilt_and_its_opposite_mirror(model):
    b = _plain()
    p = b.thermal_equilibrium(**KW, model=model, theta_x_rad=-1e-4, theta_y_rad=3e-4)
    m = b.thermal_equilibrium(**KW, model=model, theta_x_rad=1e-4, theta_y_rad=-3e-4)
    c, L = b.clearance_m, b.length_m
    assert p.status == m.status == "ok"
    assert (p.x_m, p.y_m) == pytest.approx((m.x_m, m.y_m), abs=1e-9 * c)
    assert p.max_temperature_c == pytest.approx(m.max_temperature_c, abs=1e-8)
    scale = np.abs(p.film_moment_n_m).max()
    assert scale > 0.1  # N·m
    np.testing.assert_allclose(p.film_moment_n_m, -m.film_moment_n_m, atol=1e-8 * scale)
    assert p.h_min_m == pytest.approx(m.h_min_m, rel=1e-8)
    assert abs(p.h_min_z_m) == pytest.approx(L / 2) and p.h_min_z_m == -m.h_min_z_m
    assert p.h_min_m < c * (1 - p.eccentricity_ratio)  # the edge film is the thinnest
    if model == "thd":
        np.testing.assert_allclose(p.temperature_c, m.temperature_c[:, ::-1], atol=1e-8)
    fr = p.to_frame()
    assert fr["journal_theta_y_rad"].iloc[0] == 3e-4
    assert fr["film_moment_x_n_m"].iloc[0] == p.film_moment_n_m[0]


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_plain_returned_pose_balances_the_load_in_the_frozen_film(model):
    b = _plain()
    tx, ty = 2e-4, -4e-4
    r = b.thermal_equilibrium(**KW, model=model, theta_x_rad=tx, theta_y_rad=ty)
    frozen = FluidFilmBearing(station=0, cavitation=b.cavitation, **{
        **PLAIN, "viscosity_pa_s": float(np.mean(r.viscosity_pa_s))},
        viscosity_field_pa_s=r.viscosity_pa_s if model == "thd" else None)
    f = tilted_forces(frozen, x_m=r.x_m, y_m=r.y_m, speed_hz=KW["speed_hz"], theta_x_rad=tx,
                      theta_y_rad=ty)
    W = 4000.0
    np.testing.assert_allclose(f.force_n, -np.array(KW["load_n"]), atol=1e-8 * W)
    np.testing.assert_allclose(f.film_moment_n_m, r.film_moment_n_m, rtol=1e-8)
    assert f.h_min_m == pytest.approx(r.h_min_m, rel=1e-12) and f.h_min_z_m == r.h_min_z_m
    K, C = tilted_coefficients(frozen, x_m=r.x_m, y_m=r.y_m, speed_hz=KW["speed_hz"],
                               theta_x_rad=tx, theta_y_rad=ty)
    np.testing.assert_allclose(r.K4, K, atol=1e-8 * np.abs(K).max())
    np.testing.assert_allclose(r.C4, C, atol=1e-8 * np.abs(C).max())


def test_plain_bad_tilt_names_the_field():
    b = _plain()
    with pytest.raises(InputError, match="theta_x_rad, theta_y_rad: the tilted journal closes"):
        b.thermal_equilibrium(**KW, theta_y_rad=4.5e-3)  # |θ|·L/2 = 112 µm > c
    with pytest.raises(InputError, match="theta_x_rad"):
        b.thermal_equilibrium(**KW, model="thd", theta_x_rad=float("inf"))
    with pytest.raises(InputError, match="tilt"):
        b.thermal_equilibrium(**KW, tilt="yes")


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_pads_zero_tilt_is_the_untilted_bearing(model):
    a = _pads().thermal_equilibrium(**PKW, model=model)
    b = _pads(tilt=True).thermal_equilibrium(**PKW, model=model)
    assert a.status == b.status == "ok"
    assert (a.x_m, a.y_m) == (b.x_m, b.y_m)
    assert np.array_equal(a.pad_tilts_rad, b.pad_tilts_rad)
    for p, q in zip(a.viscosity_pa_s, b.viscosity_pa_s):
        assert np.array_equal(p, q)
    for p, q in zip(a.temperature_c, b.temperature_c):
        assert np.array_equal(p, q)
    assert np.array_equal(a.max_temperature_c, b.max_temperature_c)
    assert np.array_equal(a.K, b.K) and np.array_equal(a.C, b.C)
    assert a.K4 is None and b.K4.shape == (4, 4)
    np.testing.assert_allclose(b.K4[:2, :2], a.K, atol=1e-9 * np.abs(a.K).max())
    np.testing.assert_allclose(b.C4[:2, :2], a.C, atol=1e-9 * np.abs(a.C).max())
    assert np.abs(b.film_moment_n_m).max() < 1e-9


def test_pads_tilt_and_its_opposite_mirror_and_balance_the_load():
    from rotordyn.bearings.tilt_pads import pad_tilted_forces

    b = _pads(tilt=True)
    th = 6e-4  # |θ|·L/2 = 15 µm = 0.15 c
    p = b.thermal_equilibrium(**PKW, theta_y_rad=th)
    m = b.thermal_equilibrium(**PKW, theta_y_rad=-th)
    c, L = b.clearance_m, b.length_m
    assert p.status == m.status == "ok"
    assert (p.x_m, p.y_m) == pytest.approx((m.x_m, m.y_m), abs=1e-9 * c)
    np.testing.assert_allclose(p.pad_tilts_rad, m.pad_tilts_rad, atol=1e-9 * c / b.length_m)
    for a, q in zip(p.temperature_c, m.temperature_c):
        np.testing.assert_allclose(a, q[:, ::-1], atol=1e-8)
    scale = np.abs(p.film_moment_n_m).max()
    assert scale > 0.1
    np.testing.assert_allclose(p.film_moment_n_m, -m.film_moment_n_m, atol=1e-8 * scale)
    assert p.h_min_z_m == pytest.approx(L / 2) and m.h_min_z_m == pytest.approx(-L / 2)
    u = _pads().thermal_equilibrium(**PKW)
    assert p.max_temperature_c_total > u.max_temperature_c_total  # the thin edge is hotter
    # the frozen-field bearing at the returned pose: the pads in equilibrium carry the load
    frozen = dataclasses.replace(b, viscosity_field_pa_s=p.viscosity_pa_s)
    f = pad_tilted_forces(frozen, x_m=p.x_m, y_m=p.y_m, speed_hz=PKW["speed_hz"],
                          theta_y_rad=th)
    np.testing.assert_allclose(f.force_n, -np.array(PKW["load_n"]), atol=1e-8 * 1500.0)
    np.testing.assert_allclose(f.film_moment_n_m, p.film_moment_n_m, rtol=1e-7)
    np.testing.assert_allclose(f.pad_tilts_rad, p.pad_tilts_rad, rtol=1e-7, atol=1e-12)
    with pytest.raises(InputError, match="theta_x_rad, theta_y_rad: the tilted journal closes"):
        b.thermal_equilibrium(**PKW, theta_x_rad=5e-3)
    with pytest.raises(InputError, match="theta_y_rad"):
        b.thermal_equilibrium(**PKW, theta_y_rad=float("nan"))


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_plain_equals_the_system_at_the_journal_tilt_and_film_load(model):
    """The compressor (tests/data/models/compressor_plain_thermal.toml, its oil system) on
    plain bearings with ``tilt = true``, both housings misaligned by 0.2 mrad about y: the
    rotor on two bearings is statically determinate, so each bearing's standalone tilted
    thermal equilibrium under the load its film carries, at the journal's tilt the system
    found, is the system's (two outer iterations to |ΔT| ≤ 1e-6 K apart): temperatures
    1e-5 K, position 1e-6 c, moments 1e-6 (observed 1e-7 K, 1e-9 c). (Until 2026-12-05 the
    THD NDE film had two fixed points at +0.3 mrad, 0.37 K apart, from a cavitated cell's
    fill jumping 0.646 ↔ 1; the fill is continuous now and the two calls agree there:
    tests/test_thd_fill_continuity.py, docs/film-physics.md, "Unique since 2026-12-05".)"""
    from rotordyn.analysis.assembly import assembled

    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6, tilt=True, config_theta_y_rad=2e-4)
        for b in s.bearings))
    th = s.thermal
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, model=model)
    assert res.status == "ok", res.message
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    ff = np.asarray(e.film_force_n)
    asm = assembled(res.system)
    for k, b in enumerate(s.bearings):
        bc = asm.bearings[k]
        own = th.film(b.name)
        tilt = e.tilt[k]
        sa = b.journal_bearing().thermal_equilibrium(
            load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=150.0, oil=th.oil, model=model,
            supply_temperature_c=th.supply_temperature_c, carry_over=own.carry_over,
            supply_flow_m3_s=own.supply_flow_m3_s,
            **({} if model == "thd" else {"effective_factor": own.effective_factor}),
            theta_x_rad=tilt["journal_theta_x_rad"], theta_y_rad=tilt["journal_theta_y_rad"])
        assert sa.status == "ok"
        assert sa.max_temperature_c == pytest.approx(res.max_temperature_c[k], abs=1e-5)
        if model == "thd":
            np.testing.assert_allclose(sa.temperature_c, res.temperature_c[k], atol=1e-5)
        c = b.clearance_m
        assert (sa.x_m, sa.y_m) == pytest.approx((res.journal_x_m[k], res.journal_y_m[k]),
                                                 abs=1e-6 * c)
        np.testing.assert_allclose(sa.film_moment_n_m, ff[list(bc.rot)], rtol=1e-6)
        assert sa.h_min_z_m == pytest.approx(tilt["h_min_z_m"])


@pytest.mark.parametrize("model", ["thd", "effective"])
def test_spherical_pads_pitch_with_the_tilt(model):
    """Spherical pivots (the pads pitch, a coordinate each, measured from γ = θ·t_k): the
    tilted thermal equilibrium converges, θ and −θ give opposite moments and the same
    position, and the frozen-field bearing's pads, re-solved at the returned pose, carry the
    load (1e-8) with the same moments (1e-7). The pads pitching with the journal carry a
    tenth of the rocker pads' moment (docs, "Tilting-pad bearings")."""
    from rotordyn.bearings.tilt_pads import pad_tilted_forces

    b = _pads(tilt=True, pivot_type="spherical")
    p = b.thermal_equilibrium(**PKW, model=model, theta_y_rad=6e-4)
    m = b.thermal_equilibrium(**PKW, model=model, theta_y_rad=-6e-4)
    assert p.status == m.status == "ok"
    assert (p.x_m, p.y_m) == pytest.approx((m.x_m, m.y_m), abs=1e-9 * b.clearance_m)
    scale = np.abs(p.film_moment_n_m).max()
    np.testing.assert_allclose(p.film_moment_n_m, -m.film_moment_n_m, atol=1e-8 * scale)
    rocker = _pads(tilt=True).thermal_equilibrium(**PKW, model=model, theta_y_rad=6e-4)
    assert scale < 0.2 * np.abs(rocker.film_moment_n_m).max()
    frozen = dataclasses.replace(b, viscosity_field_pa_s=p.viscosity_pa_s)
    f = pad_tilted_forces(frozen, x_m=p.x_m, y_m=p.y_m, speed_hz=PKW["speed_hz"],
                          theta_y_rad=6e-4)
    np.testing.assert_allclose(f.force_n, -np.array(PKW["load_n"]), atol=1e-8 * 1500.0)
    np.testing.assert_allclose(f.film_moment_n_m, p.film_moment_n_m, rtol=1e-7, atol=1e-9 * scale)


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_untilted_thermal_result_carries_its_minimum_film(model):
    """Review 2026-12-05: the tilt fields made an untilted result's ``h_min_m`` NaN beside
    status ok. It is the film's minimum c − e at the equilibrium, as the core's own film solve
    at that position reports it (an independent path: JournalBearing.solve)."""
    b = _plain()
    u = b.thermal_equilibrium(**KW, model=model)
    assert u.status == "ok"
    f = b.solve(x_m=u.x_m, y_m=u.y_m, speed_hz=KW["speed_hz"])
    assert u.h_min_m == pytest.approx(f.h_min_m, rel=1e-14)
    assert u.h_min_angle_deg == pytest.approx(f.h_min_angle_deg, abs=1e-9)
    assert 0.0 < u.h_min_m < PLAIN["clearance_m"]


def test_tilt_argument_is_accepted_by_every_bearing_type():
    """Review 2026-12-05: JournalBearing and a model's plain bearing took ``tilt=True``
    (the tilted outputs at zero tilt), the tilting-pad and fixed-geometry bearings refused it
    ("tilt: not an option"); they take it now, with the same meaning: at zero tilt the
    result carries the 4×4 K, C, and ``tilt=None`` is the bearing's own field."""
    pads = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml").bearings[0]
    kw = dict(PKW, model="effective")
    t = pads.thermal_equilibrium(**kw, tilt=True)
    u = pads.thermal_equilibrium(**kw)
    assert t.K4 is not None and t.K4.shape == (4, 4) and getattr(u, "K4", None) is None
    np.testing.assert_allclose(t.K4[:2, :2], u.K, rtol=1e-6, atol=1e-6 * np.abs(u.K).max())
