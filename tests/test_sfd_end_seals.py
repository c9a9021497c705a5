"""Squeeze-film damper end seals: the Robin axial boundary condition of the Reynolds core
(−(h³/12μ) ∂p/∂z = ±G_s p at z = ±L/2; ``end_seal_conductance``).

Sources
-------
* Long (infinitely long, or fully end-sealed: ∂p/∂z = 0) damper in a circular centred orbit,
  J. M. Vance, *Rotordynamics of Turbomachinery*, Wiley 1988, ch. 6; L. San Andrés, *Squeeze
  Film Dampers*, Texas A&M lecture notes (long SFD): π film
  C_tt = 12πμL(R/c)³/((2+ε²)(1−ε²)^{1/2}) (= 12πμR³L/(c³…), N·s/m), F_r = −24μR³Lνε²/(c²(2+ε²)(1−ε²)); full film
  twice the π film's F_t, F_r = 0. The closed forms (derived in
  ``rotordyn.bearings.squeeze_film``) are first checked here independently by numerical
  quadrature of the 1-D long-bearing pressure (scipy.integrate.quad, 1e-7).
* G_s → 0 (sealed): the finite damper (L/D = 1/4) tends to the long damper, within 1 %
  (observed ≤ 0.1 % at n_circ = 144: the circumferential discretisation error, second order).
* G_s → ∞: the open-ends damper (p = 0 at the ends), observed relative difference ~ 4 c³/
  (12 μ L G_s); within 1e-5 at G_s = 1e6 c³/(12μL).
* In between the damping C_tt falls monotonically as the seal opens (more leakage, less
  squeeze pressure), for the full, π and Swift–Stieber films.
* The discrete linearisation (perturbation solve) with end seals equals central finite
  differences of the nonlinear solves (1e-5), and the film conserves mass: with a full film the
  groove's supply equals the leakage through the seals (1e-10).
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad

import rotordyn
from rotordyn import _core
from rotordyn.bearings import (SqueezeFilmDamper, end_plate_seal_conductance,
                               long_damper_orbit_forces)
from rotordyn.errors import InputError

D, L, C_RAD, MU, NU_HZ = 0.1, 0.025, 2e-4, 0.01, 30.0
G0 = C_RAD ** 3 / (12 * MU * L)  # the film's own axial conductance scale, m²/(Pa·s)


def _damper(cav, g, n_circ=72, n_axial=8):
    return SqueezeFilmDamper(station=0, diameter_m=D, length_m=L, clearance_m=C_RAD,
                             viscosity_pa_s=MU, cavitation=cav, n_circ=n_circ, n_axial=n_axial,
                             end_seal_conductance_m3_per_pa_s_per_m=g)


def _long_by_quadrature(eps, film):
    """(F_r, F_t) of the long damper from the 1-D pressure integrated numerically."""
    R, c, mu, nu = D / 2, C_RAD, MU, 2 * math.pi * NU_HZ
    e = eps * c
    h = lambda t: c * (1 - eps * math.cos(t))  # noqa: E731
    a = 12 * mu * R ** 2 * e * nu
    # h³ p' = a cos θ + A, A from periodicity of p
    i1 = quad(lambda t: 1 / h(t) ** 3, 0, 2 * math.pi, epsabs=0, epsrel=1e-11)[0]
    i2 = quad(lambda t: math.cos(t) / h(t) ** 3, 0, 2 * math.pi, epsabs=0, epsrel=1e-11)[0]
    A = -a * i2 / i1
    dp = lambda t: (a * math.cos(t) + A) / h(t) ** 3  # noqa: E731
    pa = 1e-11 * a / c ** 3  # p returns to 0 at 2π: an absolute tolerance too
    p = lambda t: quad(dp, 0, t, epsabs=pa, epsrel=1e-10)[0]  # noqa: E731  p(0) = 0: odd
    hi = math.pi if film == "pi" else 2 * math.pi  # p > 0 on (0, π)
    tol = 1e-10 * abs(p(math.pi / 2))  # F_r of the full film is 0: an absolute tolerance
    fr = -R * L * quad(lambda t: p(t) * math.cos(t), 0, hi, epsabs=tol, epsrel=1e-9)[0]
    ft = -R * L * quad(lambda t: p(t) * math.sin(t), 0, hi, epsabs=tol, epsrel=1e-9)[0]
    return fr, ft


@pytest.mark.parametrize("film", ["pi", "full"])
@pytest.mark.parametrize("eps", [0.2, 0.5, 0.8])
def test_long_damper_closed_forms_by_quadrature(film, eps):
    fr, ft = long_damper_orbit_forces(diameter_m=D, length_m=L, clearance_m=C_RAD,
                                      viscosity_pa_s=MU, eccentricity_ratio=eps, whirl_hz=NU_HZ,
                                      film=film)
    qr, qt = _long_by_quadrature(eps, film)
    assert ft == pytest.approx(qt, rel=1e-7)
    assert fr == pytest.approx(qr, rel=1e-7, abs=1e-7 * abs(qt))
    R = D / 2
    ctt = 12 * math.pi * MU * L * (R / C_RAD) ** 3 / ((2 + eps ** 2) * math.sqrt(1 - eps ** 2))
    assert -ft / (eps * C_RAD * 2 * math.pi * NU_HZ) == pytest.approx(
        ctt * (1 if film == "pi" else 2), rel=1e-12)


@pytest.mark.parametrize("film, cav", [("pi", "gumbel"), ("full", "none")])
@pytest.mark.parametrize("eps", [0.2, 0.5, 0.7])
def test_sealed_damper_tends_to_long_damper(film, cav, eps):
    fr, ft = long_damper_orbit_forces(diameter_m=D, length_m=L, clearance_m=C_RAD,
                                      viscosity_pa_s=MU, eccentricity_ratio=eps, whirl_hz=NU_HZ,
                                      film=film)
    o = _damper(cav, 1e-6 * G0, n_circ=144, n_axial=4).orbit_coefficients(
        eccentricity_ratio=eps, whirl_hz=NU_HZ)
    assert o["f_t_n"] == pytest.approx(ft, rel=0.01)
    if film == "pi":
        assert o["f_r_n"] == pytest.approx(fr, rel=0.01)
    else:
        assert abs(o["f_r_n"]) < 1e-9 * abs(ft)


@pytest.mark.parametrize("cav", ["gumbel", "none", "reynolds"])
def test_seal_conductance_between_open_and_sealed(cav):
    """C_eq falls monotonically from the sealed to the open damper; G_s = 1e6 G0 is the open
    damper within 1e-5."""
    open_ = _damper(cav, None).orbit_coefficients(eccentricity_ratio=0.5, whirl_hz=NU_HZ)
    lams = [1e-6, 1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1e4, 1e6]
    c = [_damper(cav, lam * G0).orbit_coefficients(eccentricity_ratio=0.5, whirl_hz=NU_HZ)
         for lam in lams]
    ceq = np.array([o["c_eq_n_s_per_m"] for o in c])
    assert np.all(np.diff(ceq) < 0), ceq
    assert ceq[-1] == pytest.approx(open_["c_eq_n_s_per_m"], rel=1e-5)
    assert c[-1]["k_eq_n_per_m"] == pytest.approx(open_["k_eq_n_per_m"], rel=1e-5,
                                                  abs=1e-5 * ceq[-1] * 2 * math.pi * NU_HZ)
    assert ceq[0] > 30 * ceq[-1]  # sealing multiplies the damping (long vs short: ~ (D/L)²)


def _solver(cav, n_axial, g, grooves=()):
    geo = _core.JournalBearingGeometry()
    geo.diameter_m, geo.length_m, geo.clearance_m, geo.viscosity_pa_s = 0.05, 0.03, 1e-4, 0.02
    geo.grooves = [_core.Groove(*gr) for gr in grooves]
    geo.end_seal_conductance = g
    return _core.ReynoldsSolver(geo, _core.FilmGrid(36, n_axial), cav)


@pytest.mark.parametrize("cav", ["none", "gumbel", "reynolds"])
@pytest.mark.parametrize("n_axial", [6, 7])
def test_linearisation_with_seals_matches_finite_differences(cav, n_axial):
    g = 1e-4 ** 3 / (12 * 0.02 * 0.03)
    s = _solver(cav, n_axial, g)
    w = 2 * math.pi * 50.0
    dc = s.coefficients(3e-5, -5e-5, w)
    fd = s.coefficients_fd(3e-5, -5e-5, w, rel_step=1e-6)
    np.testing.assert_allclose(dc.K, fd.K, rtol=0, atol=1e-5 * np.abs(fd.K).max())
    np.testing.assert_allclose(dc.C, fd.C, rtol=0, atol=1e-5 * np.abs(fd.C).max())
    # a misaligned journal (h varies along z: the full system) and a non-symmetric perturbation
    z, phi = np.asarray(s.z_m), np.asarray(s.phi_rad)
    h = 1e-4 - 4e-5 * np.cos(phi)[:, None] * (1 + 8 * z[None, :]) - 2e-5 * np.sin(phi)[:, None]
    hd = 2e-3 * np.sin(phi)[:, None] * (1 + 5 * z[None, :])
    dh = np.cos(phi - 0.3)[:, None] * (1 + 20 * z[None, :])
    s.solve(h, hd, w)
    lin = np.asarray(s.integrate_force(s.linearize(dh, np.zeros_like(h))))
    dq = 1e-11
    fp = np.asarray(s.solve(h + dq * dh, hd, w).force_n)
    fm = np.asarray(s.solve(h - dq * dh, hd, w).force_n)
    np.testing.assert_allclose(lin, (fp - fm) / (2 * dq), rtol=0,
                               atol=1e-5 * np.abs(lin).max())


def test_seals_conserve_mass_and_change_nothing_when_open():
    """Full film with a supply groove: supply = leakage through the seals. The solver's end
    rows are unknowns only with seals."""
    g = 1e-4 ** 3 / (12 * 0.02 * 0.03)
    s = _solver("none", 8, g, grooves=[(90.0, 20.0, 2e5)])
    sol = s.rigid(2e-5, -4e-5, 0.0, 0.0, 2 * math.pi * 50.0)
    assert sol.side_flow_m3_s > 0
    assert sol.inlet_flow_m3_s == pytest.approx(sol.side_flow_m3_s, rel=1e-10)
    p = np.asarray(sol.p_pa)
    assert np.all(p[:, 0] != 0) and np.allclose(p[:, 0], p[:, -1], rtol=1e-12, atol=0)
    assert np.asarray(s.dirichlet_mask())[:, [0, -1]].sum() == 0
    so = _solver("none", 8, math.inf, grooves=[(90.0, 20.0, 2e5)])
    assert np.all(np.asarray(so.dirichlet_mask())[:, [0, -1]] == 1)
    so_sol = so.rigid(2e-5, -4e-5, 0.0, 0.0, 2 * math.pi * 50.0)
    assert so_sol.inlet_flow_m3_s == pytest.approx(so_sol.side_flow_m3_s, rel=1e-10)
    assert sol.side_flow_m3_s < so_sol.side_flow_m3_s  # the seals restrict the leakage


def test_end_plate_conductance_and_input_errors():
    assert end_plate_seal_conductance(gap_m=5e-5, land_length_m=2e-3, viscosity_pa_s=0.01) == \
        pytest.approx(5e-5 ** 3 / (12 * 0.01 * 2e-3), rel=1e-15)
    with pytest.raises(InputError, match="gap_m"):
        end_plate_seal_conductance(gap_m=0.0, land_length_m=2e-3, viscosity_pa_s=0.01)
    for bad in (0.0, -1e-9, math.nan, math.inf, True, "1e-9", 1e-12 * G0):
        with pytest.raises(InputError, match="end_seal_conductance_m3_per_pa_s_per_m"):
            _damper("gumbel", bad)
    g0 = 1e-4 ** 3 / (12 * 0.02 * 0.03)
    for bad in (0.0, -1.0, math.nan, 0.9e-8 * g0):
        with pytest.raises(InputError, match="end_seal_conductance"):
            _solver("none", 6, bad)
    _solver("none", 6, 1.01e-8 * g0)  # the bound: the sealed limit, still well conditioned
    with pytest.raises(InputError, match=r"end_seal_conductance_m3_per_pa_s_per_m: expected >= 1e-8"):
        _damper("gumbel", 0.9e-8 * G0)
    with pytest.raises(InputError, match="end_seal_conductance.*jfo"):
        _solver("jfo", 6, 1e-9, grooves=[(90.0, 20.0, 1e5)])


def test_sealed_damper_toml_round_trip_and_sweep_axis():
    from rotordyn.sweep.paths import set_field

    text = """
schema = "rotordyn/model/1"
[material.steel]
density_kg_m3 = 7850.0
young_pa = 2.1e11
poisson = 0.3
[rotor]
[[rotor.section]]
length_m = 0.3
outer_diameter_m = 0.04
[[bearing]]
type = "squeeze_film_damper"
station = 0
diameter_m = 0.1
length_m = 0.025
clearance_m = 2e-4
viscosity_pa_s = 0.01
centring_spring_n_per_m = 1e6
end_seal_conductance_m3_per_pa_s_per_m = 2.5e-9
[[bearing]]
type = "squeeze_film_damper"
station = 1
diameter_m = 0.1
length_m = 0.025
clearance_m = 2e-4
viscosity_pa_s = 0.01
centring_spring_n_per_m = 1e6
"""
    s = rotordyn.System.from_toml(text, is_text=True)
    assert s.bearings[0].end_seal_conductance_m3_per_pa_s_per_m == 2.5e-9
    assert s.bearings[1].end_seal_conductance_m3_per_pa_s_per_m is None
    assert rotordyn.System.from_toml(s.to_toml(), is_text=True) == s
    s2 = set_field(s, "bearings.1.end_seal_conductance_m3_per_pa_s_per_m", 1e-9)
    assert s2.bearings[1].end_seal_conductance_m3_per_pa_s_per_m == 1e-9
    with pytest.raises(InputError, match="end_seal_conductance"):
        set_field(s, "bearings.0.end_seal_conductance_m3_per_pa_s_per_m", 0.0)
