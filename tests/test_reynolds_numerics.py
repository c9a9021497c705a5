"""Numerical properties of the Reynolds solver (tiers d and f): derivative consistency, observed
order of grid convergence, equilibrium residual, mass conservation of the ``jfo`` model,
frame-rotation invariance, batch/single consistency, pickling and thread use.

Sources: the convergence-order method is Roache, *Verification and Validation in
Computational Science and Engineering* (1998), ch. 5 (observed order p = log2(e_h/e_{h/2}) from
successive differences on grids refined by 2); the p–θ mass-conserving model is Elrod & Adams
(1974) / Jakobsson & Floberg (1957), in the complementarity form of Giacopini et al., ASME J.
Tribol. 132 (2010) 041702.

Tolerances: FD vs perturbation K, C 1 % (the issue's requirement; central differences with a
step 1e-6·c agree to ~1e-8 where the cavitation set does not switch within the step); observed
order 2 ± 0.3 (tier d); equilibrium residual 1e-8 of the load (the issue's requirement); jfo
inflow = outflow to 1e-9 relative (the direct sparse solve leaves round-off only); with the
supply line at the maximum film thickness no film reforms downstream of the rupture, so jfo and
reynolds give the same field (1e-9 relative).
"""

import math
import pickle
import threading

import numpy as np
import pytest

import rotordyn

D, C_RAD, MU, N_HZ = 0.05, 1e-4, 0.02, 20.0
MODELS = ["none", "gumbel", "reynolds", "jfo"]


def bearing(cav="reynolds", n_circ=72, n_axial=16, grooves=(rotordyn.Groove(90.0, 0.0, 0.0),),
            length_m=0.04):
    return rotordyn.JournalBearing(diameter_m=D, length_m=length_m, clearance_m=C_RAD,
                                   viscosity_pa_s=MU, n_circ=n_circ, n_axial=n_axial,
                                   cavitation=cav, grooves=list(grooves))


@pytest.mark.parametrize("cav", MODELS)
@pytest.mark.parametrize("pos", [(0.0, -0.6e-4), (0.35e-4, -0.55e-4), (-0.2e-4, -0.3e-4)])
def test_perturbation_matches_finite_difference(cav, pos):
    b = bearing(cav)
    K, C = b.coefficients(x_m=pos[0], y_m=pos[1], speed_hz=N_HZ, method="perturbation")
    Kf, Cf = b.coefficients(x_m=pos[0], y_m=pos[1], speed_hz=N_HZ, method="finite_difference")
    assert np.max(np.abs(K - Kf)) <= 0.01 * np.max(np.abs(K))
    assert np.max(np.abs(C - Cf)) <= 0.01 * np.max(np.abs(C))
    np.testing.assert_allclose(K, Kf, rtol=0.01, atol=1e-3 * np.max(np.abs(K)))
    np.testing.assert_allclose(C, Cf, rtol=0.01, atol=1e-3 * np.max(np.abs(C)))


@pytest.mark.parametrize("cav", MODELS)
def test_observed_order_of_grid_convergence(cav):
    loads = []
    # the 24×6 grid is still pre-asymptotic for the clipped (gumbel) film: start at 48×12
    for n_circ, n_axial in [(48, 12), (96, 24), (192, 48), (384, 96)]:
        b = bearing(cav, n_circ, n_axial, length_m=D)
        loads.append(np.linalg.norm(b.forces(x_m=0.35e-4, y_m=-0.45e-4, speed_hz=N_HZ)))
    d = np.diff(loads)
    orders = np.log2(d[:-1] / d[1:])
    assert np.all(np.abs(orders - 2.0) <= 0.3), orders


@pytest.mark.parametrize("cav", MODELS)
@pytest.mark.parametrize("load", [(0.0, -50.0), (0.0, -2000.0), (300.0, -300.0)])
def test_static_equilibrium_balances_load(cav, load):
    b = bearing(cav)
    eq = b.static_equilibrium(load_n=load, speed_hz=N_HZ)
    f = b.forces(x_m=eq.x_m, y_m=eq.y_m, speed_hz=N_HZ)
    W = math.hypot(*load)
    assert np.linalg.norm(f + np.array(load)) <= 1e-8 * W
    assert 0.0 < eq.eccentricity_ratio < 1.0
    R = D / 2
    assert eq.sommerfeld == pytest.approx(MU * N_HZ * 0.04 * D / W * (R / C_RAD) ** 2, rel=1e-12)
    if cav != "none":  # journal displaced along the load, turned with the rotation
        assert 0.0 < eq.attitude_angle_deg < 90.0


@pytest.mark.parametrize("pos", [(0.0, -0.6e-4), (0.35e-4, -0.55e-4), (0.6e-4, 0.3e-4)])
def test_jfo_conserves_mass_and_reynolds_does_not(pos):
    bj = bearing("jfo")
    r = bj.solve(x_m=pos[0], y_m=pos[1], speed_hz=N_HZ)
    assert r.inlet_flow_m3_s > 0.0
    assert r.inlet_flow_m3_s == pytest.approx(r.side_flow_m3_s, rel=1e-9)
    field = bj.pressure(x_m=pos[0], y_m=pos[1], speed_hz=N_HZ)
    assert field.theta.min() >= 0.0 and field.theta.max() <= 1.0
    assert np.all(field.p_pa[field.theta < 1.0] == 0.0)  # complementarity p (1 - θ) = 0
    br = bearing("reynolds")
    rr = br.solve(x_m=pos[0], y_m=pos[1], speed_hz=N_HZ)
    # Swift–Stieber creates mass where the film re-forms: the balance fails by > 1 %.
    assert abs(rr.inlet_flow_m3_s - rr.side_flow_m3_s) > 0.01 * rr.side_flow_m3_s


def test_jfo_equals_reynolds_without_reformation():
    """Supply line at h_max: the film ruptures once and re-forms only at the groove."""
    pj = bearing("jfo").pressure(x_m=0.0, y_m=-0.7e-4, speed_hz=N_HZ)
    pr = bearing("reynolds").pressure(x_m=0.0, y_m=-0.7e-4, speed_hz=N_HZ)
    np.testing.assert_allclose(pj.p_pa, pr.p_pa, rtol=0, atol=1e-9 * pr.p_pa.max())
    assert pj.theta.min() < 0.9  # there is a cavitated zone


def test_jfo_with_reformation_differs_from_reynolds_and_supply_groove():
    """Pressurised groove upstream of a diverging gap: the film ruptures after the groove and
    re-forms before the load zone. jfo still balances its flows, and because the re-formed film
    is only partly filled its load differs from Swift–Stieber's (which refills it for free)."""
    g = [rotordyn.Groove(45.0, 10.0, 2.0e4)]
    fj = bearing("jfo", grooves=g).solve(x_m=0.5e-4, y_m=-0.4e-4, speed_hz=N_HZ)
    fr = bearing("reynolds", grooves=g).solve(x_m=0.5e-4, y_m=-0.4e-4, speed_hz=N_HZ)
    assert fj.inlet_flow_m3_s == pytest.approx(fj.side_flow_m3_s, rel=1e-9)
    assert np.linalg.norm(fj.force_n - fr.force_n) > 0.01 * np.linalg.norm(fr.force_n)
    assert abs(fr.inlet_flow_m3_s - fr.side_flow_m3_s) > 0.1 * fr.side_flow_m3_s


@pytest.mark.parametrize("cav", ["none", "gumbel", "reynolds"])
def test_frame_rotation_invariance_without_grooves(cav):
    """A bush without grooves is isotropic: rotating the journal position by a grid angle
    rotates the force and K, C by the same angle (exactly, on the grid). (Not jfo: it needs a
    supply groove, which breaks the isotropy.)"""
    b = bearing(cav, grooves=())
    q = np.array([0.3e-4, -0.5e-4])
    a = 2 * math.pi * 7 / 72
    Rm = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    f0 = b.forces(x_m=q[0], y_m=q[1], speed_hz=N_HZ)
    K0, C0 = b.coefficients(x_m=q[0], y_m=q[1], speed_hz=N_HZ)
    q1 = Rm @ q
    f1 = b.forces(x_m=q1[0], y_m=q1[1], speed_hz=N_HZ)
    K1, C1 = b.coefficients(x_m=q1[0], y_m=q1[1], speed_hz=N_HZ)
    np.testing.assert_allclose(f1, Rm @ f0, atol=1e-9 * np.linalg.norm(f0))
    np.testing.assert_allclose(K1, Rm @ K0 @ Rm.T, atol=1e-8 * np.abs(K0).max())
    np.testing.assert_allclose(C1, Rm @ C0 @ Rm.T, atol=1e-8 * np.abs(C0).max())


def test_pressure_field_integrates_to_the_force_and_squeeze_damps():
    b = bearing("reynolds")
    pf = b.pressure(x_m=0.2e-4, y_m=-0.5e-4, speed_hz=N_HZ)
    assert pf.p_pa.shape == (72, 17) and pf.phi_rad.shape == (72,) and pf.z_m.shape == (17,)
    assert pf.p_pa.min() >= 0.0 and np.all(pf.p_pa[:, [0, -1]] == 0.0)
    R = D / 2
    w = np.ones(17)
    w[[0, -1]] = 0.5
    dA = R * (2 * math.pi / 72) * (0.04 / 16)
    fx = -np.sum(pf.p_pa * np.cos(pf.phi_rad)[:, None] * w) * dA
    fy = -np.sum(pf.p_pa * np.sin(pf.phi_rad)[:, None] * w) * dA
    np.testing.assert_allclose([fx, fy], pf.force_n, rtol=1e-12)
    np.testing.assert_allclose(pf.h_m[:, 5], C_RAD - 0.2e-4 * np.cos(pf.phi_rad)
                               + 0.5e-4 * np.sin(pf.phi_rad), rtol=1e-14)
    # pure squeeze (no rotation): a journal moving down is pushed back up
    f = b.forces(x_m=0.0, y_m=0.0, speed_hz=0.0, vx_m_s=0.0, vy_m_s=-1e-3)
    assert f[1] > 0 and abs(f[0]) < 1e-9 * f[1]
    assert pf.to_frame().shape == (72 * 17, 5)


def test_batch_matches_single_calls_and_pickles():
    b = bearing("reynolds")
    x = np.linspace(-0.3e-4, 0.3e-4, 5)
    y = np.full(5, -0.5e-4)
    fb = b.forces_batch(x_m=x, y_m=y, speed_hz=N_HZ, vy_m_s=1e-4)
    fs = np.array([b.forces(x_m=xi, y_m=yi, speed_hz=N_HZ, vy_m_s=1e-4) for xi, yi in zip(x, y)])
    np.testing.assert_allclose(fb, fs, rtol=1e-12)
    cb = b.coefficients_batch(x_m=x, y_m=y, speed_hz=N_HZ)
    K, C = b.coefficients(x_m=x[2], y_m=y[2], speed_hz=N_HZ)
    np.testing.assert_allclose(cb["K"][2], K, rtol=1e-10)
    np.testing.assert_allclose(cb["C"][2], C, rtol=1e-10)
    b2 = pickle.loads(pickle.dumps(b))
    assert b2 == b
    np.testing.assert_allclose(b2.forces(x_m=x[0], y_m=y[0], speed_hz=N_HZ),
                               b.forces(x_m=x[0], y_m=y[0], speed_hz=N_HZ), rtol=1e-12)


def test_threads_share_one_bearing_object():
    """Each thread gets its own C++ solver; results equal the serial ones."""
    b = bearing("reynolds")
    pts = [(0.1e-4 * k, -0.5e-4) for k in range(-3, 4)]
    ref = [b.forces(x_m=x, y_m=y, speed_hz=N_HZ) for x, y in pts]
    out = {}

    def work(i):
        out[i] = [b.forces(x_m=x, y_m=y, speed_hz=N_HZ) for x, y in pts]

    ts = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    for i in range(4):
        np.testing.assert_allclose(out[i], ref, rtol=1e-12)


def test_jfo_needs_a_supply():
    """Without a supply groove the steady mass-conserving film content is undetermined (any
    uniform θ·h balances): rejected as bad input naming the field."""
    with pytest.raises(rotordyn.InputError, match="grooves"):
        bearing("jfo", grooves=())


@pytest.mark.parametrize("cav", MODELS)
def test_axial_symmetry_reduction_is_exact(cav):
    """The half-grid path (symmetric film) equals the full grid to round-off, for the field,
    K and C, and for a non-symmetric perturbation of a symmetric base state."""
    b = bearing(cav, grooves=(rotordyn.Groove(90.0), rotordyn.Groove(200.0, 20.0, 1e4)))
    s = b.solver()
    w = 2 * math.pi * N_HZ
    p_half = np.array(s.rigid(0.3e-4, -0.5e-4, 1e-4, 2e-4, w).p_pa)
    kc_half = s.coefficients(0.3e-4, -0.5e-4, w)
    dh = np.random.default_rng(1).standard_normal((72, 17)) * 1e-7
    dp_half = np.array(s.linearize(dh, np.zeros_like(dh)))
    s.use_axial_symmetry = False
    s.reset()
    p_full = np.array(s.rigid(0.3e-4, -0.5e-4, 1e-4, 2e-4, w).p_pa)
    kc_full = s.coefficients(0.3e-4, -0.5e-4, w)
    dp_full = np.array(s.linearize(dh, np.zeros_like(dh)))
    np.testing.assert_allclose(p_half, p_full, rtol=0, atol=1e-12 * p_full.max())
    np.testing.assert_allclose(kc_half.K, kc_full.K, rtol=0, atol=1e-12 * np.abs(kc_full.K).max())
    np.testing.assert_allclose(kc_half.C, kc_full.C, rtol=0, atol=1e-12 * np.abs(kc_full.C).max())
    np.testing.assert_allclose(dp_half, dp_full, rtol=0, atol=1e-12 * np.abs(dp_full).max())
    assert not np.allclose(dp_full, dp_full[:, ::-1])  # the perturbation really is asymmetric


@pytest.mark.parametrize("cav", MODELS)
def test_general_film_linearisation_matches_finite_difference(cav):
    """General h(φ, z) (misaligned journal, not symmetric in z) and a sleeve-like inward bump
    w(φ, z) as the perturbation (issue 4 reuses this path): the linearised pressure change
    integrates to the central-difference force change within 1e-4 relative (FD step 1e-4 of
    the bump amplitude; the frozen-set derivative is exact away from set switches)."""
    b = bearing(cav, grooves=(rotordyn.Groove(90.0),))
    s = b.solver()
    phi = np.asarray(s.phi_rad)[:, None]
    z = np.asarray(s.z_m)[None, :]
    h = C_RAD - (0.3e-4 + 0.4e-3 * z) * np.cos(phi) - (-0.5e-4 + 0.2e-3 * z) * np.sin(phi)
    h = np.ascontiguousarray(h)
    bump = np.ascontiguousarray(
        -np.exp(-((phi - 4.5) ** 2) / 0.2) * (1 - (2 * z / 0.04) ** 2) * np.ones_like(h))
    zero = np.zeros_like(h)
    w = 2 * math.pi * N_HZ
    s.solve(h, zero, w)
    df = np.asarray(s.integrate_force(s.linearize(bump, zero)))
    dfv = np.asarray(s.integrate_force(s.linearize(zero, bump)))
    eps = 1e-4 * C_RAD
    fp = np.asarray(s.solve(h + eps * bump, zero, w).force_n)
    fm = np.asarray(s.solve(h - eps * bump, zero, w).force_n)
    np.testing.assert_allclose(df, (fp - fm) / (2 * eps), rtol=1e-4,
                               atol=1e-4 * np.linalg.norm(df))
    ev = 1e-4 * C_RAD * w
    gp = np.asarray(s.solve(h, ev * bump, w).force_n)
    gm = np.asarray(s.solve(h, -ev * bump, w).force_n)
    np.testing.assert_allclose(dfv, (gp - gm) / (2 * ev), rtol=1e-4,
                               atol=1e-4 * np.linalg.norm(dfv))


@pytest.mark.parametrize("cav", ["gumbel", "reynolds", "jfo"])
def test_static_equilibrium_is_robust_over_load_direction_and_size(cav):
    """Light to heavy loads (eccentricity ratio ~0.003 to ~0.97) in four directions (one of
    them towards the supply groove) and both rotation senses: Newton (with the steepest-descent
    fallback and load continuation) always lands on the equilibrium to 1e-8 of the load.
    (jfo is not loaded at 75°: the journal then lifts towards the only supply line, which sits
    just upstream of the minimum film; the mass-conserving film is starved and carries almost
    nothing — a physical effect the Swift–Stieber model misses — and the solver says so.)"""
    b = bearing(cav, n_circ=36, n_axial=8)
    for W in (1.0, 100.0, 3000.0):
        for ang in (-90.0, 0.0, 75.0, 160.0) if cav != "jfo" else (-90.0, 0.0, 160.0):
            for f in (50.0, -30.0):
                load = (W * math.cos(math.radians(ang)), W * math.sin(math.radians(ang)))
                eq = b.static_equilibrium(load_n=load, speed_hz=f)
                assert eq.residual_rel <= 1e-8, (W, ang, f)
                assert 0.0 < eq.eccentricity_ratio < 1.0
    if cav == "jfo":
        with pytest.raises(rotordyn.ConvergenceError, match="carries at most"):
            b.static_equilibrium(load_n=(25.9, 96.6), speed_hz=50.0)


def test_batch_threads_and_failing_points():
    """A threaded batch equals the serial one; failing points are NaN rows with a status
    (on_error="nan") or raise the matching rotordyn error after the batch (default)."""
    b = bearing("reynolds")
    rng = np.random.default_rng(3)
    e = rng.uniform(0.0, 0.9, 40)
    a = rng.uniform(0.0, 2 * math.pi, 40)
    x, y = e * C_RAD * np.cos(a), e * C_RAD * np.sin(a)
    f1 = b.forces_batch(x_m=x, y_m=y, speed_hz=N_HZ)
    f2 = b.forces_batch(x_m=x, y_m=y, speed_hz=N_HZ, n_threads=3)
    np.testing.assert_allclose(f2, f1, rtol=1e-10, atol=1e-12 * np.abs(f1).max())
    c1 = b.coefficients_batch(x_m=x, y_m=y, speed_hz=N_HZ)
    c2 = b.coefficients_batch(x_m=x, y_m=y, speed_hz=N_HZ, n_threads=2)
    np.testing.assert_allclose(c2["K"], c1["K"], rtol=1e-9, atol=1e-9 * np.abs(c1["K"]).max())
    assert np.all(c1["status"] == 0)
    x_bad = x.copy()
    x_bad[[5, 17]] = 2 * C_RAD  # eccentricity ratio > 1
    fn = b.forces_batch(x_m=x_bad, y_m=y, speed_hz=N_HZ, n_threads=2, on_error="nan")
    assert np.all(np.isnan(fn[[5, 17]])) and np.all(np.isfinite(np.delete(fn, [5, 17], 0)))
    np.testing.assert_allclose(np.delete(fn, [5, 17], 0), np.delete(f1, [5, 17], 0), rtol=1e-10)
    cb = b.coefficients_batch(x_m=x_bad, y_m=y, speed_hz=N_HZ, on_error="nan")
    assert list(np.flatnonzero(cb["status"])) == [5, 17] and "eccentricity" in cb["message"][5]
    with pytest.raises(rotordyn.InputError, match="eccentricity"):
        b.forces_batch(x_m=x_bad, y_m=y, speed_hz=N_HZ)
