"""Turbulent lubrication (issue 20): the Ng–Pan–Elrod linearised turbulent film.

Model (docs/film-physics.md): the Poiseuille conductances h³/(12μ) become h³/(k_x μ) around
and h³/(k_z μ) along, with the curve fits of Taylor & Dowson (1974, J. Lubr. Technol. 96(1)
36–46) to the coefficients of Ng & Pan (1965, J. Basic Eng. 87, 675–688) and Elrod & Ng
(1967): k_x = 12 + 0.0136 Re_h^0.90, k_z = 12 + 0.0043 Re_h^0.96, and the Couette wall-shear
factor C_f = 1 + 0.0012 Re_h^0.94, at the local film Reynolds number Re_h = ρ|ω|R h/μ.

Checks: the closed forms of the coefficients; Re → 0 equals the laminar film (and the
laminar model with a density given is today's film bit for bit); the turbulent short bearing
against an independent quadrature of its closed-form pressure; the finite film's turbulent
load gain against the short-bearing one at L/D = 1/8; perturbation K, C against finite
differences of the force (smooth and stepped films); the compressor model of tests/data with
turbulence on (equilibrium, K, C, TOML round trip, a density sweep axis); bad input.
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

import rotordyn
from rotordyn import _core
from rotordyn.bearings import FixedGeometryBearing
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"


def kx(re):
    return 12.0 + 0.0136 * re ** 0.90


def kz(re):
    return 12.0 + 0.0043 * re ** 0.96


@pytest.mark.parametrize("re", [0.0, 1.0, 300.0, 1000.0, 2000.0, 1e4, 1e5])
def test_coefficients_are_the_published_closed_forms(re):
    """Taylor & Dowson (1974) fits of the Ng–Pan–Elrod coefficients, evaluated to round-off
    (e.g. Re = 1e4: k_x = 66.14, k_z = 41.75); laminar: 12, 12, 1 at every Re."""
    got = _core.turbulence_factors("ng_pan", re)
    np.testing.assert_allclose(got, (kx(re), kz(re), 1.0 + 0.0012 * re ** 0.94), rtol=1e-15)
    assert _core.turbulence_factors("laminar", re) == (12.0, 12.0, 1.0)
    if re == 1e4:
        np.testing.assert_allclose(got[:2], (66.14, 41.75), atol=0.005)


def _bearing(**kw):
    base = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.01,
                n_circ=36, n_axial=8)
    return rotordyn.JournalBearing(**{**base, **kw})


def test_laminar_with_density_is_todays_film_bit_for_bit():
    a, b = _bearing(), _bearing(density_kg_m3=860.0)
    st = dict(x_m=2e-5, y_m=-5e-5, speed_hz=300.0)
    assert np.array_equal(a.forces(**st), b.forces(**st))
    for ka, kb in zip(a.coefficients(**st), b.coefficients(**st)):
        assert np.array_equal(ka, kb)


def test_reynolds_number_to_zero_is_laminar():
    """Re_h ~ 1e-9: the coefficients differ from 12 by ~1e-10, so forces, K and C equal the
    laminar ones to ~1e-10 relative (and the turbulent film differs clearly at Re ~ 1e3)."""
    st = dict(x_m=2e-5, y_m=-5e-5, speed_hz=300.0)
    lam = _bearing()
    tiny = _bearing(turbulence="ng_pan", density_kg_m3=1e-8)
    np.testing.assert_allclose(tiny.forces(**st), lam.forces(**st), rtol=1e-9)
    for a, b in zip(tiny.coefficients(**st), lam.coefficients(**st)):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-9 * np.abs(b).max())
    turb = _bearing(turbulence="ng_pan", density_kg_m3=860.0, viscosity_pa_s=0.003)
    lam3 = _bearing(viscosity_pa_s=0.003)
    re = 860.0 * 2 * math.pi * 300.0 * 0.05 * 1e-4 / 0.003  # Re at h = c: 2.7e3
    assert re > 2000
    ratio = np.hypot(*turb.forces(**st)) / np.hypot(*lam3.forces(**st))
    assert 1.1 < ratio < kx(2 * re) / 12.0


def _short_core(turbulence, rho, L, n_circ=720, n_axial=16):
    g = _core.JournalBearingGeometry()
    g.diameter_m, g.length_m, g.clearance_m, g.viscosity_pa_s = 0.1, L, 1e-4, 0.003
    g.short_bearing = True
    g.turbulence = turbulence
    g.density_kg_m3 = rho
    return _core.ReynoldsSolver(g, _core.FilmGrid(n_circ, n_axial), "reynolds")


def test_turbulent_short_bearing_closed_form():
    """Short (Ocvirk) turbulent film: the axial flow balance gives
    p = (k_z(h)/2) μ s (z² − L²/4)/h³, s = (ω/2) ∂h/∂φ, clipped at 0; with the journal at
    (0, −e), h = c + e sin φ, so F = R (L³/6) ∫_{cos φ < 0} (k_z/2) μ (ω/2) e cos φ/h³ (cos φ,
    sin φ) dφ (quadrature to 1e-10). The core integrates z with the trapezoidal rule (factor
    1 − 1/n_axial² on the parabola, applied to the reference) and φ on 720 nodes with
    central differences: 1e-4."""
    R, L, c, mu, rho, f, e = 0.05, 0.02, 1e-4, 0.003, 860.0, 300.0, 6e-5
    w = 2 * math.pi * f
    s = _short_core("ng_pan", rho, L)
    F = np.asarray(s.force(0.0, -e, 0.0, 0.0, w))

    def integrand(phi, comp):
        h = c + e * math.sin(phi)
        k = kz(rho * w * R * h / mu)
        p_per = 0.5 * k * mu * 0.5 * w * e * math.cos(phi) / h ** 3  # × (z² − L²/4)
        return p_per * (math.cos(phi), math.sin(phi))[comp]

    ref = np.array([R * (L ** 3 / 6.0) * quad(integrand, math.pi / 2, 3 * math.pi / 2,
                                              args=(i,), epsabs=0, epsrel=1e-11)[0]
                    for i in (0, 1)])
    ref *= 1.0 - 1.0 / 16 ** 2
    np.testing.assert_allclose(F, ref, rtol=1e-4, atol=1e-4 * np.hypot(*ref))
    lam = np.asarray(_short_core("laminar", rho, L).force(0.0, -e, 0.0, 0.0, w))
    assert np.hypot(*F) > 1.2 * np.hypot(*lam)


def test_finite_film_turbulent_gain_matches_short_bearing():
    """At L/D = 1/8 the axial Poiseuille flow dominates; the turbulent/laminar load ratio of the
    finite film equals the short film's to within 1 % (the laminar loads themselves differ by
    ~5 %: the short-bearing approximation's own error at this L/D)."""
    L, rho, f, st = 0.0125, 860.0, 300.0, (0.0, -6e-5, 0.0, 0.0)
    w = 2 * math.pi * f
    b = dict(diameter_m=0.1, length_m=L, clearance_m=1e-4, viscosity_pa_s=0.003, n_circ=144,
             n_axial=16)
    fin = {t: np.hypot(*rotordyn.JournalBearing(**b, turbulence=t, density_kg_m3=rho).forces(
        x_m=st[0], y_m=st[1], speed_hz=f)) for t in ("laminar", "ng_pan")}
    sh = {t: np.hypot(*_short_core(t, rho, L, 144, 16).force(*st, w)) for t in fin}
    assert fin["ng_pan"] / fin["laminar"] == pytest.approx(sh["ng_pan"] / sh["laminar"], rel=0.01)
    assert fin["ng_pan"] / fin["laminar"] > 1.2


@pytest.mark.parametrize("cavitation", ["reynolds", "gumbel", "jfo"])
def test_perturbation_coefficients_match_finite_differences(cavitation):
    """The perturbation solve differentiates the turbulent conductances h³·12/k(Re_h) too:
    K, C equal central differences of the force (step 1e-6 c) to 1e-5 of max |K|, |C|."""
    grooves = (rotordyn.Groove(center_deg=90.0, width_deg=10.0),) if cavitation == "jfo" else ()
    b = _bearing(turbulence="ng_pan", density_kg_m3=860.0, viscosity_pa_s=0.003,
                 cavitation=cavitation, grooves=grooves)
    st = dict(x_m=1.5e-5, y_m=-5e-5, speed_hz=300.0)
    Kp, Cp = b.coefficients(**st)
    Kf, Cf = b.coefficients(**st, method="finite_difference")
    np.testing.assert_allclose(Kp, Kf, atol=1e-5 * np.abs(Kf).max())
    np.testing.assert_allclose(Cp, Cf, atol=1e-5 * np.abs(Cf).max())


def test_pressure_dam_turbulent_coefficients_match_finite_differences():
    """A stepped film (pressure dam pocket): the step faces take Re_h at their effective film
    cbrt(G3); K by perturbation equals central differences of the force to 1e-5."""
    b = FixedGeometryBearing(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                             viscosity_pa_s=0.003, kind="pressure_dam", dam_depth_m=2e-4,
                             n_circ=48, n_axial=8, turbulence="ng_pan", density_kg_m3=860.0)
    x, y, f, d = 1e-5, -4e-5, 300.0, 1e-10
    K, _ = b.coefficients(x_m=x, y_m=y, speed_hz=f)
    fd = np.column_stack([
        -(b.forces(x_m=x + d, y_m=y, speed_hz=f) - b.forces(x_m=x - d, y_m=y, speed_hz=f)) / (2 * d),
        -(b.forces(x_m=x, y_m=y + d, speed_hz=f) - b.forces(x_m=x, y_m=y - d, speed_hz=f)) / (2 * d)])
    np.testing.assert_allclose(K, fd, atol=1e-5 * np.abs(fd).max())


def _compressor(turbulence):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    if turbulence:
        s = dataclasses.replace(s, bearings=tuple(
            dataclasses.replace(b, turbulence="ng_pan", density_kg_m3=860.0, viscosity_pa_s=0.006,
                                n_circ=36, n_axial=8) for b in s.bearings))
    else:
        s = dataclasses.replace(s, bearings=tuple(
            dataclasses.replace(b, viscosity_pa_s=0.006, n_circ=36, n_axial=8)
            for b in s.bearings))
    return s


def test_compressor_with_turbulence_equilibrium_coefficients_and_toml():
    """The compressor of tests/data on plain bearings (μ = 6 mPa·s, ρ = 860 kg/m³, 250 Hz:
    Re_h at the clearance ≈ 1.1e3): the equilibrium converges, the turbulent films carry the
    load at a smaller eccentricity, their K differ from the laminar ones, and the TOML round
    trip keeps the fields."""
    lam, turb = _compressor(False), _compressor(True)
    el = rotordyn.equilibrium(lam, speed_hz=250.0)
    et = rotordyn.equilibrium(turb, speed_hz=250.0)
    assert el.status == "ok" and et.status == "ok"
    ll = rotordyn.linearize(lam, speed_hz=250.0)
    lt = rotordyn.linearize(turb, speed_hz=250.0)
    kl, kt = np.asarray(ll.K), np.asarray(lt.K)
    assert np.all(np.isfinite(kt))
    jl = [abs(j) for j in np.asarray(el.r)[:4]]
    jt = [abs(j) for j in np.asarray(et.r)[:4]]
    assert max(jt) < max(jl)
    # r[0], r[1]: the first bearing's journal x, y; K[0, 1] is the film's alone (the rotor
    # couples no x to y): the turbulent cross-coupling differs by tens of per cent
    assert abs(kt[0, 1] - kl[0, 1]) > 0.1 * abs(kl[0, 1])
    s2 = rotordyn.System.from_toml(turb.to_toml(), is_text=True)
    assert s2.bearings == turb.bearings
    assert 'turbulence = "ng_pan"' in turb.to_toml()


def test_density_is_a_sweep_axis():
    from rotordyn.sweep.paths import get_field, set_field

    s = _compressor(True)
    s2 = set_field(s, "bearings.0.density_kg_m3", 900.0)
    assert get_field(s2, "bearings.0.density_kg_m3") == [900.0]


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="turbulence"):
        _bearing(turbulence="k-epsilon")
    with pytest.raises(InputError, match="density_kg_m3"):
        _bearing(turbulence="ng_pan")
    with pytest.raises(InputError, match="density_kg_m3"):
        _bearing(turbulence="ng_pan", density_kg_m3=-1.0)
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    bad = dataclasses.replace(s.bearings[0], turbulence="ng_pan")
    with pytest.raises(InputError, match=r"density_kg_m3"):
        dataclasses.replace(s, bearings=(bad, s.bearings[1])).validate() \
            if hasattr(s, "validate") else rotordyn.System(**{**{f.name: getattr(s, f.name)
                                                                for f in dataclasses.fields(s)},
                                                             "bearings": (bad, s.bearings[1])})
    g = _core.JournalBearingGeometry()
    g.turbulence = "ng_pan"
    with pytest.raises(InputError, match="density_kg_m3"):
        g.validate()


def test_tilting_pad_compressor_with_turbulence():
    """The compressor on tilting pads (tests/data/models) with turbulent pads (μ = 6 mPa·s,
    ρ = 860 kg/m³, 250 Hz): the pad-assembly equilibrium converges, the journals sit closer to
    the centre than with laminar pads (the turbulent film is stiffer at equal viscosity), the
    linearisation is finite, and the fields survive the TOML round trip."""
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")

    def with_pads(**kw):
        return dataclasses.replace(s, bearings=tuple(
            dataclasses.replace(b, viscosity_pa_s=0.006, n_circ=36, n_axial=6, **kw)
            for b in s.bearings))

    lam, turb = with_pads(), with_pads(turbulence="ng_pan", density_kg_m3=860.0)
    el = rotordyn.equilibrium(lam, speed_hz=250.0)
    et = rotordyn.equilibrium(turb, speed_hz=250.0)
    assert el.status == "ok" and et.status == "ok"
    assert np.abs(np.asarray(et.r)[:2]).max() < np.abs(np.asarray(el.r)[:2]).max()
    assert np.all(np.isfinite(np.asarray(rotordyn.linearize(turb, speed_hz=250.0).K)))
    assert rotordyn.System.from_toml(turb.to_toml(), is_text=True).bearings == turb.bearings


def test_compressor_with_turbulence_stability_campbell_transient_and_sweep_axis():
    """Turbulent plain bearings in the compressor: stability and a Campbell diagram run, a
    small-amplitude transient follows the linear model (3 % of the peak, as for the other
    elements in tests/test_bearing_elements_system.py: the transient calls the same turbulent
    film through the system's Reynolds solves), and the density is a sweep axis that moves
    the operating point."""
    import scipy.linalg

    from rotordyn.sweep.paths import set_field

    s, f = _compressor(True), 250.0
    assert rotordyn.stability(s, speed_hz=f).status == "ok"
    cb = rotordyn.campbell(s, [150.0, 250.0])
    assert np.all(np.asarray(cb.point_status) == "ok")
    lm = rotordyn.linearize(s, speed_hz=f)
    n = lm.M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(lm.M, lm.K), -np.linalg.solve(lm.M, lm.D)]])
    tr = rotordyn.transient(s, t_end_s=0.004, speed_hz=f, disturbance_m=(0.2e-6, 0.0), n_out=9)
    assert tr.status == "ok", tr.message
    x0 = np.concatenate([tr.r[0] - lm.equilibrium.r, np.zeros(n)])
    lin = np.array([(scipy.linalg.expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - lm.equilibrium.r
    assert np.max(np.abs(dev[:, 0] - lin[:, 0])) < 0.03 * np.max(np.abs(lin[:, 0]))
    s2 = set_field(s, "bearings.*.density_kg_m3", 2000.0)
    e1, e2 = rotordyn.equilibrium(s, speed_hz=f), rotordyn.equilibrium(s2, speed_hz=f)
    assert e1.status == e2.status == "ok"
    assert not np.allclose(e1.r[:4], e2.r[:4], rtol=1e-6, atol=0)
