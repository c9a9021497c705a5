"""The starved plain journal bearing: a jfo film whose grooves are fed a metered supply
(``supply_flow_m3_s``) below what the flooded film draws (docs/film-physics.md, "A starved
film"; C++ reynolds_starved.cpp).

What is guarded and why the tolerances are what they are:

* the flooded limit: a supply at or above the flooded demand is the flooded film bit for bit
  (``array_equal``: the same operations run);
* mass conservation: the grooves' inflow equals the supply to the root's tolerance (1e-12 of
  the supply, asserted 1e-11) and leaves through the ends (steady jfo films balance their
  finite volumes to round-off, asserted 1e-10);
* a closed form: for a short bearing (L/D = 1/8 and 1/4) the starved film approaches Ocvirk's
  short-bearing pressure over the reduced arc from φ_s, where the oil column θ_in·h_groove
  fills the gap (h(φ_s) = θ_in·h_groove), to the minimum film (the rupture of the short
  film): F. W. Ocvirk, NACA TN 2808 (1952) for the pressure; the reduced arc is the
  striation argument of the Elrod–Adams film (H. G. Elrod, ASME J. Lubr. Technol. 103 (1981)
  350–354; Vincent, Maspeyrot & Frêne, "Starvation and cavitation effects in finite grooved
  journal bearings", Proc. Leeds-Lyon Symp. 1996, use the same inlet condition). The finite
  film's deviation is its finite length (it shrinks with L/D) plus the O(Δφ) of the upwind
  fill; the grid study gives the observed order;
* trends reported qualitatively by Artiles & Heshmat (ASME J. Tribol. 107 (1985) 1–13) and
  Vincent et al. (1996): at a fixed position less supply carries less load; at a fixed load
  less supply runs at a higher eccentricity and a smaller attitude angle;
* the held-supply K, C (perturbation) against central differences of the supplied film;
* bad input names the field; the TOML round trip keeps the field.
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

import rotordyn as rd
from rotordyn import Groove, JournalBearing
from rotordyn.errors import InputError

D, C_RAD, MU, F_HZ = 0.05, 1e-4, 0.02, 50.0
OMEGA = 2 * math.pi * F_HZ
R = D / 2
X, Y = 3e-5, -5e-5  # the journal position of the fixed-position tests (ε = 0.583)
MODELS = Path(__file__).parent / "data" / "models"


def bearing(supply=None, *, L=0.025, n_circ=72, n_axial=12, p_groove=0.0, center=90.0):
    return JournalBearing(diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
                          n_circ=n_circ, n_axial=n_axial, cavitation="jfo",
                          grooves=[Groove(center, 0.0, p_groove)], supply_flow_m3_s=supply)


def demand(**kw):
    return bearing(**kw).solve(x_m=X, y_m=Y, speed_hz=F_HZ).inlet_flow_m3_s


@pytest.mark.parametrize("p_groove", [0.0, 5e4])
def test_flooded_limit_is_the_jfo_film_bit_for_bit(p_groove):
    b0 = bearing(p_groove=p_groove)
    q = demand(p_groove=p_groove)
    for supply in (q, 1.5 * q, 0.0):
        b = bearing(supply, p_groove=p_groove)
        p0 = b0.pressure(x_m=X, y_m=Y, speed_hz=F_HZ)
        p1 = b.pressure(x_m=X, y_m=Y, speed_hz=F_HZ)
        assert np.array_equal(p0.p_pa, p1.p_pa) and np.array_equal(p0.theta, p1.theta)
        assert np.array_equal(p0.force_n, p1.force_n)
        K0, C0 = b0.coefficients(x_m=X, y_m=Y, speed_hz=F_HZ)
        K1, C1 = b.coefficients(x_m=X, y_m=Y, speed_hz=F_HZ)
        assert np.array_equal(K0, K1) and np.array_equal(C0, C1)
        r = b.solve(x_m=X, y_m=Y, speed_hz=F_HZ)
        assert not r.starved and r.inlet_fill == 1.0 and r.groove_pressure_factor == 1.0


@pytest.mark.parametrize("p_groove", [0.0, 5e4])
@pytest.mark.parametrize("frac", [0.95, 0.6, 0.3, 0.1])
def test_inflow_meets_the_supply_and_leaves_through_the_ends(frac, p_groove):
    q = frac * demand(p_groove=p_groove)
    r = bearing(q, p_groove=p_groove).solve(x_m=X, y_m=Y, speed_hz=F_HZ)
    assert r.starved
    assert r.inlet_flow_m3_s == pytest.approx(q, rel=1e-11)
    assert r.side_flow_m3_s == pytest.approx(r.inlet_flow_m3_s, rel=1e-10)
    assert 0.0 < r.inlet_fill <= 1.0 and 0.0 <= r.groove_pressure_factor < 1.0
    if p_groove == 0.0:
        assert r.inlet_fill < 1.0  # a groove at the ambient pressure starves at once


def test_held_supply_coefficients_match_finite_differences():
    b = bearing(0.4 * demand())
    K, C = b.coefficients(x_m=X, y_m=Y, speed_hz=F_HZ)
    Kf, Cf = b.coefficients(x_m=X, y_m=Y, speed_hz=F_HZ, method="finite_difference",
                            rel_step=1e-6)
    # central differences of a piecewise-linear (in the partition) film: O(step) kinks aside,
    # agreement to ~1e-6 of the matrix norm; asserted 1e-4
    assert np.allclose(K, Kf, rtol=0, atol=1e-4 * np.abs(K).max())
    assert np.allclose(C, Cf, rtol=0, atol=1e-4 * np.abs(C).max())


def ocvirk_starved(theta_in, h_groove, L):
    """Ocvirk's short-bearing film over the reduced arc, force on the journal (N) and the
    angle φ_s (deg) where it starts.

    With ψ = φ − φ_e (φ_e the direction of the journal's displacement, h = c(1 − ε cos ψ)),
    the short-bearing pressure p = 3μω (L²/4 − z²)(−∂h/∂φ)/h³ is positive on ψ ∈ (−π, 0);
    the striations carry the column θ_in·h_groove until h(ψ_s) = θ_in·h_groove, i.e.
    cos ψ_s = (1 − θ_in h_groove/c)/ε, ψ_s ∈ (−π, 0), and the short film ruptures at the
    minimum film ψ = 0. Integrating over z (∫(L²/4 − z²)dz = L³/6):
    F = −(μωRL³/2) ∫_{ψ_s}^{0} cε sin(−ψ)/h³ (cos φ, sin φ) dψ. The component along the line
    of centres has the closed form (μωRL³/(2c²ε))[1/u − 1/(2u²)] between u(ψ_s) and u(0)
    (u = 1 − ε cos ψ); the quadrature below is checked against it."""
    e = math.hypot(X, Y)
    eps, phe = e / C_RAD, math.atan2(Y, X)
    cs = (1.0 - theta_in * h_groove / C_RAD) / eps
    psi_s = -math.acos(min(1.0, max(-1.0, cs)))

    def g(s):
        return -C_RAD * eps * math.sin(s) / (C_RAD * (1.0 - eps * math.cos(s))) ** 3

    k = -MU * OMEGA * L**3 / 2.0 * R
    fx = k * quad(lambda s: g(s) * math.cos(s + phe), psi_s, 0.0, epsabs=0, epsrel=1e-12)[0]
    fy = k * quad(lambda s: g(s) * math.sin(s + phe), psi_s, 0.0, epsabs=0, epsrel=1e-12)[0]
    # the closed form of the radial component (along (cos φ_e, sin φ_e))
    u0, us = 1.0 - eps, 1.0 - eps * math.cos(psi_s)
    anti = lambda u: 1.0 / u - 1.0 / (2.0 * u * u)  # noqa: E731
    radial = MU * OMEGA * R * L**3 / (2.0 * C_RAD**2 * eps) * (anti(u0) - anti(us))
    assert fx * math.cos(phe) + fy * math.sin(phe) == pytest.approx(radial, rel=1e-9)
    return np.array([fx, fy]), math.degrees(psi_s + phe) % 360.0


def _starved_short(L, n_circ, n_axial, frac=0.5):
    q = frac * demand(L=L, n_circ=96, n_axial=8)
    return bearing(q, L=L, n_circ=n_circ, n_axial=n_axial).solve(x_m=X, y_m=Y, speed_hz=F_HZ)


def test_short_starved_film_approaches_ocvirk_over_the_reduced_arc():
    """At half the flooded demand (θ_in ≈ 0.64) on 288 × 24 nodes: the load is 7.2 % (L/D =
    1/4) and 2.1 % (1/8) below the reduced-arc Ocvirk load, its direction within 0.33° / 0.10°;
    the flooded film (θ_in = 1) deviates as much (7.0 %, 2.1 %): the deviation is the finite
    length, not the starvation, and falls 3.5x as L/D halves. The full film starts upstream
    of the striation estimate φ_s (the full film's circumferential back-flow, a boundary layer
    of width ~L that the short-bearing limit drops) by 10.8° and 4.7° (~L/D)."""
    out = {}
    for L in (D / 4, D / 8):
        r = _starved_short(L, 288, 24)
        f0 = bearing(L=L, n_circ=288, n_axial=24).solve(x_m=X, y_m=Y, speed_hz=F_HZ)
        assert r.starved and 0.5 < r.inlet_fill < 0.8
        F_o, phi_s = ocvirk_starved(r.inlet_fill, C_RAD - Y, L)  # h at the groove, φ = 90°
        F_1, _ = ocvirk_starved(1.0, C_RAD - Y, L)
        dev = np.linalg.norm(r.force_n) / np.linalg.norm(F_o) - 1.0
        dev_flooded = np.linalg.norm(f0.force_n) / np.linalg.norm(F_1) - 1.0
        turn = math.degrees(math.atan2(r.force_n[1], r.force_n[0])
                            - math.atan2(F_o[1], F_o[0]))
        out[L] = (dev, dev_flooded, turn, phi_s - r.full_film_start_deg)
    (d4, f4, t4, s4), (d8, f8, t8, s8) = out[D / 4], out[D / 8]
    assert -0.075 < d4 < 0 and -0.025 < d8 < 0
    assert abs(d4 - f4) < 0.005 and abs(d8 - f8) < 0.005
    assert d4 / d8 > 3.0
    assert abs(t4) < 0.4 and abs(t8) < 0.15
    assert 0 < s4 < 12.0 and 0 < s8 < 6.5 and 1.6 < s4 / s8 < 2.5


def test_starved_film_grid_convergence_order():
    """The starved load at a fixed supply on 72×6, 144×12, 288×24 (L/D = 1/4): observed order
    log2((W1 − W2)/(W2 − W3)) = 1.98 (second-order pressures; the front moves with the grid
    by whole cells, which does not show at this resolution); asserted 2 ± 0.3."""
    W = [np.linalg.norm(_starved_short(D / 4, n, m).force_n)
         for n, m in ((72, 6), (144, 12), (288, 24))]
    order = math.log2((W[1] - W[0]) / (W[2] - W[1]))
    assert abs(order - 2.0) < 0.3


def test_less_supply_less_load_higher_eccentricity_smaller_attitude():
    """Fixed load 40 N at 50 Hz (S = 1.95): supply as a fraction of the flooded
    film's demand at its equilibrium; the trends Artiles & Heshmat (1985) and Vincent et al.
    (1996) report: ε up, attitude down; at the fixed position the load falls."""
    b0 = bearing()
    e0 = b0.static_equilibrium(load_n=(0.0, -40.0), speed_hz=F_HZ)
    q0 = b0.solve(x_m=e0.x_m, y_m=e0.y_m, speed_hz=F_HZ).inlet_flow_m3_s
    eps, att, load = [e0.eccentricity_ratio], [e0.attitude_angle_deg], []
    for frac in (0.8, 0.5, 0.2):
        b = bearing(frac * q0)
        e = b.static_equilibrium(load_n=(0.0, -40.0), speed_hz=F_HZ)
        assert e.residual_rel < 1e-9
        eps.append(e.eccentricity_ratio)
        att.append(e.attitude_angle_deg)
        load.append(np.linalg.norm(b.forces(x_m=X, y_m=Y, speed_hz=F_HZ)))
    assert np.all(np.diff(eps) > 0.01) and np.all(np.diff(att) < -3.0)
    assert np.all(np.diff(load) < 0.0)


@pytest.mark.parametrize("kw,field", [
    (dict(cavitation="jfo", grooves=[Groove(90.0)], supply_flow_m3_s=-1e-6),
     "supply_flow_m3_s"),
    (dict(cavitation="jfo", grooves=[Groove(90.0)], supply_flow_m3_s=math.nan),
     "supply_flow_m3_s"),
    (dict(cavitation="jfo", grooves=[Groove(90.0)], supply_flow_m3_s="1e-6"),
     "supply_flow_m3_s"),
    (dict(cavitation="reynolds", grooves=[Groove(90.0)], supply_flow_m3_s=1e-6),
     "supply_flow_m3_s"),
    (dict(cavitation="jfo", supply_flow_m3_s=1e-6), "supply_flow_m3_s"),
])
def test_bad_supply_names_the_field(kw, field):
    with pytest.raises(InputError, match=field):
        JournalBearing(diameter_m=D, length_m=0.025, clearance_m=C_RAD, viscosity_pa_s=MU, **kw)


def test_thermal_models_refuse_the_starved_film():
    b = bearing(1e-6)
    with pytest.raises(InputError, match="supply_flow_m3_s"):
        b.thermal_equilibrium(load_n=(0.0, -40.0), speed_hz=F_HZ, oil=None,
                              supply_temperature_c=40.0)


def _compressor(fracs=None, demand_m3_s=None, n_circ=36, n_axial=6):
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    bs = tuple(dataclasses.replace(
        b, cavitation="jfo", grooves=(Groove(90.0),), n_circ=n_circ, n_axial=n_axial,
        supply_flow_m3_s=None if fracs is None else fracs * demand_m3_s[i])
        for i, b in enumerate(s.bearings))
    return dataclasses.replace(s, bearings=bs)


def test_model_file_round_trip_keeps_the_supply():
    s = _compressor(0.5, [2e-5, 3e-5])
    back = rd.System.from_toml(s.to_toml(), is_text=True)
    assert back == s
    assert [b.supply_flow_m3_s for b in back.bearings] == [1e-5, 1.5e-5]
    assert "supply_flow_m3_s = 1e-05" in s.to_toml()
    bad = s.to_toml().replace("supply_flow_m3_s = 1e-05", "supply_flow_m3_s = -1e-05")
    with pytest.raises(InputError, match=r"supply_flow_m3_s"):
        rd.equilibrium(rd.System.from_toml(bad, is_text=True), speed_hz=50.0)


def test_compressor_on_starved_bearings_is_more_stable():
    """tests/data/models/compressor_plain.toml at 150 Hz, both bearings jfo with a groove at
    the top (p = 0) on 36 × 6 nodes: the flooded films whirl (max Re λ = +17.6 1/s); fed half
    and a quarter of their flooded demand the journals run more eccentric with a smaller
    attitude and max Re λ falls by more than 10 1/s (observed −16.2 and −18.2 1/s here; on
    144 × 32 nodes +3.4 and +4.6 against +16.6 flooded: the fall holds on every grid tried,
    12–36 1/s, the starved verdict does not converge on these grids, docs/film-physics.md)."""
    f = 150.0
    s0 = _compressor()
    e0 = rd.equilibrium(s0, speed_hz=f)
    assert e0.status == "ok"
    st0 = rd.stability(s0, speed_hz=f)
    dem = [b.journal_bearing().solve(x_m=e0.journal_x_m[i], y_m=e0.journal_y_m[i],
                                     speed_hz=f).inlet_flow_m3_s
           for i, b in enumerate(s0.bearings)]
    assert st0.max_real_1_per_s > 10.0
    eps_prev = np.asarray(e0.eccentricity_ratio)
    att_prev = np.degrees(np.arctan2(e0.journal_x_m, -np.asarray(e0.journal_y_m)))
    for frac in (0.5, 0.25):
        s = _compressor(frac, dem)
        e = rd.equilibrium(s, speed_hz=f)
        assert e.status == "ok"
        st = rd.stability(s, speed_hz=f)
        assert st.status == "ok"
        assert st.max_real_1_per_s < st0.max_real_1_per_s - 10.0
        att = np.degrees(np.arctan2(e.journal_x_m, -np.asarray(e.journal_y_m)))
        assert np.all(np.asarray(e.eccentricity_ratio) > eps_prev + 0.05)
        assert np.all(att < att_prev - 5.0)
        eps_prev, att_prev = np.asarray(e.eccentricity_ratio), att


def test_reverse_rotation_is_the_mirror_image():
    """Spin reversed and the film mirrored about the groove's vertical line (x → −x): the same
    starved film (θ_in to round-off, forces mirrored, the full film starting at the mirror
    angle 180° − φ) and held-supply K, C equal to central differences (the upwind and the
    groove's Couette flux taken from the east)."""
    q = 0.5 * demand()
    b = bearing(q)
    r = b.solve(x_m=X, y_m=Y, speed_hz=F_HZ)
    m = b.solve(x_m=-X, y_m=Y, speed_hz=-F_HZ)
    assert m.inlet_fill == pytest.approx(r.inlet_fill, rel=1e-12)
    assert m.force_n == pytest.approx([-r.force_n[0], r.force_n[1]], rel=1e-10)
    assert m.full_film_start_deg == pytest.approx((180.0 - r.full_film_start_deg) % 360.0)
    assert m.inlet_flow_m3_s == pytest.approx(q, rel=1e-11)
    K, C = b.coefficients(x_m=-X, y_m=Y, speed_hz=-F_HZ)
    Kf, Cf = b.coefficients(x_m=-X, y_m=Y, speed_hz=-F_HZ, method="finite_difference")
    assert np.allclose(K, Kf, rtol=0, atol=1e-4 * np.abs(K).max())
    assert np.allclose(C, Cf, rtol=0, atol=1e-4 * np.abs(C).max())
