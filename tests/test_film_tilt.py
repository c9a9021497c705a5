"""Journal tilt and bearing misalignment of a plain journal bearing (issue 20).

References:
* the untilted film (zero tilt: today's system film bit for bit, today's standalone pressure
  bit for bit);
* parity: the film of a tilt −θ is the mirror z → −z of the film of +θ, so the forces are
  even and the moments odd in the tilt, at any (x, y), to round-off;
* closed form: the linearised full-Sommerfeld (cavitation "none") film of a centred journal.
  A tilt θ (or tilt velocity ω_θ) perturbs h by z δ(φ) with δ = θx sin φ − θy cos φ; with
  h = c at leading order the Reynolds equation (c³/12μ)(p_φφ/R² + p_zz) = (ω/2) ∂h/∂φ + ∂h/∂t
  separates, p = f(z)·(θx cos φ + θy sin φ) with f'' − f/R² = (6μω/c³) z, f(±L/2) = 0:
  f = K0 (−z + (L/2) sinh(z/R)/sinh(L/2R)), K0 = 6μωR²/c³. With
  B = L³/12 − 2R a² coth(a/R) + 2R² a (a = L/2; B → L⁵/(720 R²) as L/R → 0, the
  short-bearing limit) the moment coefficients (ΔH = −K Δr − C Δṙ) are
      K[θx, θy] = −K[θy, θx] = 6π μ ω R³ B / c³,   C[θx, θx] = C[θy, θy] = 12π μ R³ B / c³,
  and every force–tilt and direct tilt stiffness term is 0. The discrete film converges to it
  at second order (observed order checked).
* K and C on the rotations against central differences of the forces and moments.
"""

import math

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings.tilt import (misaligned_equilibrium, tilt_coupling, tilted_coefficients,
                                    tilted_forces)

D, L, C, MU = 0.05, 0.04, 1e-4, 0.02
F_HZ = 50.0


def bearing(n_circ=72, n_axial=16, cavitation="reynolds", length_m=L):
    return rotordyn.JournalBearing(diameter_m=D, length_m=length_m, clearance_m=C,
                                   viscosity_pa_s=MU, n_circ=n_circ, n_axial=n_axial,
                                   cavitation=cavitation)


def untilted_system_film(b):
    """Today's plain film in a system: coordinates (x, y), shape (−cos φ, −sin φ)."""
    f = tilt_coupling(b, [0, 1])
    f.shape = np.ascontiguousarray(f.shape[:, :2])
    f.axial_weight = np.zeros((0, 0))
    m = _core.SystemModel()
    z = np.zeros((2, 2))
    m.M, m.K, m.C, m.G = z, z, z, z
    m.Q, m.chamber = np.zeros(2), np.zeros(2)
    m.films = [f]
    return _core.SystemSolver(m)


def test_zero_tilt_is_the_untilted_film_bit_for_bit():
    b = bearing()
    x, y = 0.3 * C, -0.5 * C
    w = 2 * math.pi * F_HZ
    t = tilted_forces(b, x_m=x, y_m=y, speed_hz=F_HZ, vx_m_s=1e-3, vy_m_s=-2e-3)
    s2 = untilted_system_film(b)
    H2 = np.asarray(s2.film_forces(np.array([x, y]), np.array([1e-3, -2e-3]), w))
    assert np.array_equal(t.force_n, H2)
    # the aligned film is symmetric in z: its moments vanish to the round-off of the sum
    assert np.abs(t.film_moment_n_m).max() < 1e-14 * np.abs(H2).max() * L
    # the pressure is today's system film's bit for bit, and the standalone bearing's (which
    # builds h in its own order) to round-off
    p4 = np.asarray(b._local.tilt_solver.last_pressure(0))
    assert np.array_equal(p4, np.asarray(s2.last_pressure(0)))
    p1 = b.pressure(x_m=x, y_m=y, speed_hz=F_HZ, vx_m_s=1e-3, vy_m_s=-2e-3).p_pa
    np.testing.assert_allclose(p4, p1, rtol=0, atol=1e-11 * np.abs(p1).max())
    K4, C4 = tilted_coefficients(b, x_m=x, y_m=y, speed_hz=F_HZ)
    lin = s2.linearize(np.array([x, y]), np.zeros(2), w)
    assert np.array_equal(K4[:2, :2], np.asarray(lin.KH))
    assert np.array_equal(C4[:2, :2], np.asarray(lin.DH))
    # and the standalone bearing's force to round-off (its own quadrature loop)
    np.testing.assert_allclose(t.force_n, b.forces(x_m=x, y_m=y, speed_hz=F_HZ, vx_m_s=1e-3,
                                                   vy_m_s=-2e-3), rtol=1e-12)


@pytest.mark.parametrize("x,y", [(0.0, 0.0), (0.2 * C, -0.6 * C)])
def test_opposite_tilts_mirror_each_other(x, y):
    b = bearing()
    th = (0.2 * C / L, -0.3 * C / L)
    p = tilted_forces(b, x_m=x, y_m=y, speed_hz=F_HZ, theta_x_rad=th[0], theta_y_rad=th[1])
    m = tilted_forces(b, x_m=x, y_m=y, speed_hz=F_HZ, theta_x_rad=-th[0], theta_y_rad=-th[1])
    scale = np.abs(p.force_n).max() + 1e-3
    np.testing.assert_allclose(m.force_n, p.force_n, rtol=0, atol=1e-11 * scale)
    np.testing.assert_allclose(m.film_moment_n_m, -p.film_moment_n_m, rtol=0,
                               atol=1e-11 * np.abs(p.film_moment_n_m).max())
    assert m.h_min_m == pytest.approx(p.h_min_m, rel=1e-14)
    assert m.h_min_z_m == pytest.approx(-p.h_min_z_m, abs=1e-15)
    assert np.abs(p.film_moment_n_m).max() > 1e-3  # a real moment, not a zero


def test_centred_tilt_gives_no_force_and_a_first_order_moment_with_its_sign():
    """Concentric journal, Swift–Stieber film: the tilted film is invariant under
    (φ, z) → (φ + π, −z), so its net force vanishes at every tilt (to round-off) while the
    moment is first order in θ. A tilt θy > 0 (journal axis towards +x at z > 0) gives
    Mx < 0: at z > 0 the journal is displaced towards +x, and the converging film below it
    (φ in (π, 2π), rotation from +x to +y) pushes it towards +y there and towards −y at
    z < 0: Mx = −∫ z dFy < 0."""
    b = bearing()
    ms = []
    for th in (0.2 * C / L, 0.1 * C / L):
        t = tilted_forces(b, x_m=0.0, y_m=0.0, speed_hz=F_HZ, theta_y_rad=th)
        assert t.film_moment_n_m[0] < 0
        assert np.hypot(*t.force_n) < 1e-12 * np.hypot(*t.film_moment_n_m) / L
        ms.append(np.hypot(*t.film_moment_n_m))
    order_m = math.log(ms[0] / ms[1]) / math.log(2.0)
    assert abs(order_m - 1.0) < 0.02, order_m


@pytest.mark.parametrize("cavitation", ["none", "gumbel", "reynolds"])
def test_small_tilt_changes_the_force_at_second_order(cavitation):
    """Loaded (eccentric) journal: F(θ) − F(0) is even in θ (mirror z → −z), so it is
    second order (observed order 2.00 for the full and the half-Sommerfeld films), while the
    moment is first order. The discrete Swift–Stieber film is only piecewise smooth in θ
    (cavitation-boundary nodes switch as the tilt grows: observed orders 1.5-2.5), so there
    the force change is checked against the first-order scale of the moment instead."""
    b = bearing(cavitation=cavitation)
    x, y = 0.2 * C, -0.6 * C
    f0 = tilted_forces(b, x_m=x, y_m=y, speed_hz=F_HZ).force_n
    df, dm = [], []
    for th in (0.04 * C / L, 0.02 * C / L, 0.01 * C / L):
        t = tilted_forces(b, x_m=x, y_m=y, speed_hz=F_HZ, theta_x_rad=-0.5 * th,
                          theta_y_rad=th)
        df.append(np.hypot(*(t.force_n - f0)))
        dm.append(np.hypot(*t.film_moment_n_m))
    om = np.log(np.array(dm[:-1]) / dm[1:]) / math.log(2.0)
    assert np.all(np.abs(om - 1.0) < 0.02), om
    if cavitation == "reynolds":
        assert df[-1] < 0.05 * dm[-1] / (0.5 * L), (df, dm)
    else:
        of = np.log(np.array(df[:-1]) / df[1:]) / math.log(2.0)
        assert np.all(np.abs(of - 2.0) < 0.05), of


def closed_form_moment_coefficients(length_m, omega):
    R, a = 0.5 * D, 0.5 * length_m
    B = length_m ** 3 / 12 - 2 * R * a * a / math.tanh(a / R) + 2 * R * R * a
    k = 6 * math.pi * MU * omega * R ** 3 * B / C ** 3
    c = 12 * math.pi * MU * R ** 3 * B / C ** 3
    return k, c


def test_centred_full_film_tilt_coefficients_converge_to_the_closed_form_at_second_order():
    w = 2 * math.pi * F_HZ
    k_ref, c_ref = closed_form_moment_coefficients(L, w)
    errs = []
    for n_circ, n_axial in ((24, 8), (48, 16), (96, 32)):
        b = bearing(n_circ=n_circ, n_axial=n_axial, cavitation="none")
        K, Cm = tilted_coefficients(b, x_m=0.0, y_m=0.0, speed_hz=F_HZ)
        scale_k, scale_c = abs(k_ref), abs(c_ref)
        # the structure: no force-tilt coupling, no direct tilt stiffness, no cross damping
        assert np.abs(K[:2, 2:]).max() < 1e-9 * scale_k / L
        assert np.abs(K[2:, :2]).max() < 1e-9 * scale_k / L
        assert abs(K[2, 2]) < 1e-9 * scale_k and abs(K[3, 3]) < 1e-9 * scale_k
        assert abs(Cm[2, 3]) < 1e-9 * scale_c and abs(Cm[3, 2]) < 1e-9 * scale_c
        assert K[2, 3] == pytest.approx(-K[3, 2], rel=1e-12)
        errs.append((K[2, 3] / k_ref - 1, Cm[2, 2] / c_ref - 1, Cm[3, 3] / c_ref - 1))
    e = np.array(errs)  # observed 24x8: -9.1 %, 48x16: -2.3 %, 96x32: -0.59 % (K and C)
    assert np.abs(e[-1]).max() < 1e-2, e
    orders = np.log(e[:-1] / e[1:]) / math.log(2.0)
    assert np.all(np.abs(orders - 2.0) < 0.1), orders
    # Richardson extrapolation of the two finest grids removes the h² term
    rich = (4 * e[2] - e[1]) / 3
    assert np.abs(rich).max() < 2e-4, rich


def test_tilt_coefficients_match_finite_differences_of_forces_and_moments():
    b = bearing(n_circ=48, n_axial=12)
    kw = dict(x_m=0.25 * C, y_m=-0.55 * C, speed_hz=F_HZ, theta_x_rad=0.15 * C / L,
              theta_y_rad=-0.2 * C / L)
    K, Cm = tilted_coefficients(b, **kw)
    Kf, Cf = tilted_coefficients(b, method="finite_difference", rel_step=1e-6, **kw)
    for A, B in ((K, Kf), (Cm, Cf)):
        # compare per block (units differ): forces/moments on translations/rotations
        for rows in (slice(0, 2), slice(2, 4)):
            for cols in (slice(0, 2), slice(2, 4)):
                blk, ref = A[rows, cols], B[rows, cols]
                np.testing.assert_allclose(blk, ref, rtol=0,
                                           atol=2e-5 * np.abs(ref).max())
    assert np.abs(K[2:, 2:]).max() > 0 and np.abs(K[:2, 2:]).max() > 0


def test_edge_minimum_film_and_its_location():
    b = bearing()
    th = 0.5 * C / L
    t = tilted_forces(b, x_m=0.0, y_m=0.0, speed_hz=F_HZ, theta_y_rad=th)
    # h = c − θy z cos φ: thinnest at φ = 0, z = +L/2
    assert t.h_min_m == pytest.approx(C - th * L / 2, rel=1e-14)
    assert t.h_min_angle_deg == 0.0
    assert t.h_min_z_m == pytest.approx(L / 2, rel=1e-14)
    u = tilted_forces(b, x_m=0.0, y_m=-0.3 * C, speed_hz=F_HZ)
    assert u.h_min_z_m == 0.0  # uniform along z: no edge


def test_misaligned_equilibrium_zero_tilt_and_load_balance():
    b = bearing()
    load = (0.0, -200.0)
    e0 = misaligned_equilibrium(b, load_n=load, speed_hz=F_HZ)
    ref = b.static_equilibrium(load_n=load, speed_hz=F_HZ)
    assert e0.status == "ok"
    assert e0.x_m == pytest.approx(ref.x_m, abs=1e-9 * C)
    assert e0.y_m == pytest.approx(ref.y_m, abs=1e-9 * C)
    th = 0.3 * C / L
    e = misaligned_equilibrium(b, load_n=load, speed_hz=F_HZ, theta_y_rad=th)
    assert e.status == "ok"
    np.testing.assert_allclose(e.force_n, -np.asarray(load), rtol=0, atol=1e-8 * 200.0)
    assert e.h_min_m < e0.h_min_m  # the edge film is thinner than the aligned minimum
    assert abs(e.h_min_z_m) == pytest.approx(L / 2)
    assert np.abs(e.film_moment_n_m).max() > 0


@pytest.mark.parametrize("kw,field", [
    (dict(theta_x_rad=float("nan")), "theta_x_rad"),
    (dict(theta_y_rad=float("inf")), "theta_y_rad"),
    (dict(theta_y_rad=2.01 * C / L), "theta_x_rad, theta_y_rad"),
    (dict(x_m=0.5 * C, theta_y_rad=1.01 * C / L), "theta_x_rad, theta_y_rad"),
])
def test_bad_tilt_raises_input_error_naming_the_field(kw, field):
    b = bearing(n_circ=24, n_axial=4)
    args = dict(x_m=0.0, y_m=0.0, speed_hz=F_HZ)
    args.update(kw)
    with pytest.raises(rotordyn.InputError, match=field.replace(",", ",")):
        tilted_forces(b, **args)
    with pytest.raises(rotordyn.InputError, match=field):
        tilted_coefficients(b, **args)
    args.pop("x_m"), args.pop("y_m")
    if "x_m" not in kw:
        with pytest.raises(rotordyn.InputError, match=field):
            misaligned_equilibrium(b, load_n=(0.0, -10.0), **args)


def test_core_refuses_bad_axial_weights():
    """The core's own checks (SystemModel.validate): the weight's shape, finite values; a pad's
    film may carry weights (tilting pads with journal tilt), and its pitch flags must match
    the pad groups (one per group, 0 or 1, a pitch after the tilt [and pivot])."""
    b = bearing(n_circ=24, n_axial=4)

    def model(weight, pads=(), pitch=()):
        f = tilt_coupling(b, [0, 1, 2, 3])
        f.axial_weight = weight
        m = _core.SystemModel()
        z = np.zeros((4, 4))
        m.M, m.K, m.C, m.G = z, z, z, z
        m.Q, m.chamber = np.zeros(4), np.zeros(4)
        m.films = [f]
        m.pad_coords = [list(p) for p in pads]
        m.pad_pitch = list(pitch)
        return m

    with pytest.raises(rotordyn.InputError, match=r"films\[0\]\.axial_weight: expected"):
        _core.SystemSolver(model(np.ones((4, 3))))
    w = np.ones((4, 5))
    w[2, 1] = np.nan
    with pytest.raises(rotordyn.InputError, match=r"films\[0\]\.axial_weight: expected finite"):
        _core.SystemSolver(model(w))
    _core.SystemSolver(model(np.ones((4, 5)), pads=[(2,)]))  # accepted
    _core.SystemSolver(model(np.ones((4, 5)), pads=[(2, 3)], pitch=[1]))  # tilt, pitch
    with pytest.raises(rotordyn.InputError, match=r"pad_pitch: expected one flag per pad"):
        _core.SystemSolver(model(np.ones((4, 5)), pads=[(2,)], pitch=[1, 0]))
    with pytest.raises(rotordyn.InputError, match=r"pad_pitch\[0\]: expected 0 or 1"):
        _core.SystemSolver(model(np.ones((4, 5)), pads=[(2, 3)], pitch=[2]))
    with pytest.raises(rotordyn.InputError, match=r"pad_coords\[0\]: expected 2 \(tilt, pitch\)"):
        _core.SystemSolver(model(np.ones((4, 5)), pads=[(2,)], pitch=[1]))


def short_bearing_tilted(length_m, x, y, tx, ty, omega, nphi=720, nz=2001):
    """Forces and moments (Fx, Fy, Mx, My) of the full-film short bearing with the tilted
    thickness h(φ, z) = c − (x + θy z) cos φ − (y − θx z) sin φ, by independent quadrature:
    on each φ line ∂z(h³ ∂z p) = 6μω ∂h/∂φ, so h³ p_z = G(z) + A with G = ∫ 6μω h_φ dz and
    p = ∫ (G + A)/h³ dz, A from p(±L/2) = 0 (trapezoidal cumulative integrals on nz points;
    the φ sums of smooth periodic integrands on nphi points)."""
    from scipy.integrate import cumulative_trapezoid

    R = 0.5 * D
    phi = 2 * np.pi * np.arange(nphi) / nphi
    z = np.linspace(-0.5 * length_m, 0.5 * length_m, nz)
    P, Z = np.meshgrid(phi, z, indexing="ij")
    h = C - (x + ty * Z) * np.cos(P) - (y - tx * Z) * np.sin(P)
    h_phi = (x + ty * Z) * np.sin(P) - (y - tx * Z) * np.cos(P)
    G = cumulative_trapezoid(6 * MU * omega * h_phi, z, axis=1, initial=0)
    I1 = cumulative_trapezoid(G / h ** 3, z, axis=1, initial=0)
    I2 = cumulative_trapezoid(1 / h ** 3, z, axis=1, initial=0)
    p = I1 - (I1[:, -1] / I2[:, -1])[:, None] * I2

    def integ(g):
        return 2 * np.pi / nphi * R * np.trapezoid(np.sum(p * g, axis=0), z)

    return np.array([-integ(np.cos(P)), -integ(np.sin(P)), integ(Z * np.sin(P)),
                     -integ(Z * np.cos(P))])


def test_tilted_film_tends_to_the_short_bearing_at_second_order_in_l_over_d():
    """Nonlinear check at a finite tilt and eccentricity (ε = 0.5 at mid-plane, edge
    eccentricity ≈ 0.68), full film: the finite-length film (n_axial → ∞ by Richardson
    extrapolation of 64 and 128 intervals; the axial error is second order) against the
    short-bearing quadrature above. The finite-length correction is O((L/D)²): the relative
    differences of the moments fall by 4 per halving of L/D (observed 3.9-4.1; forces
    3.2-3.7 with the circumferential grid's floor ~1e-4), to < 0.5 % at L/D = 1/64."""
    w = 2 * math.pi * F_HZ
    errs = []
    for ld in (1 / 16, 1 / 32, 1 / 64):
        Lb = ld * D
        st = dict(x_m=0.3 * C, y_m=-0.4 * C, theta_x_rad=0.2 * C / Lb, theta_y_rad=-0.3 * C / Lb)
        ref = short_bearing_tilted(Lb, st["x_m"], st["y_m"], st["theta_x_rad"],
                                   st["theta_y_rad"], w)
        got = []
        for na in (64, 128):
            t = tilted_forces(bearing(n_circ=288, n_axial=na, cavitation="none", length_m=Lb),
                              speed_hz=F_HZ, **st)
            got.append(np.concatenate([t.force_n, t.film_moment_n_m]))
        rich = got[1] + (got[1] - got[0]) / 3
        errs.append(rich / ref - 1)
    e = np.array(errs)
    assert np.all(np.abs(e[-1]) < 5e-3), e
    ratio = np.abs(e[:-1, 2:] / e[1:, 2:])
    assert np.all((ratio > 3.5) & (ratio < 4.5)), ratio
    rf = np.abs(e[:-1, :2] / e[1:, :2])
    assert np.all(rf > 2.8), rf
