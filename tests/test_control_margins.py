"""Stability margins (rotordyn.control.margins), each against an independent computation:

- closed forms (generic loops, no rotor): L = k/(s+1)³ has its phase crossover at ω = √3
  with |L| = k/8 (upper gain margin 8/k), its gain crossover at ω_c = √(k^{2/3} − 1) with
  PM = π − 3 arctan ω_c and delay margin PM/ω_c; L = k/(s+1)² has the balanced disk margin
  α = 2/‖S − T‖∞ with ‖S − T‖∞² = 1 + 4k/(2√(k²+4) + 4 − 2k) at ω² = 1 + √(k² + 4)
  (|S − T|² = 1 − 4k(1 − u)/((1 + k − u)² + 4u), u = ω², maximised in closed form).
  Tolerances 1e-10 relative: the margins are roots refined to round-off.
- the paper rig's tuned PD, LQG and H∞ laws: the gain margins equal the loop gains α at which
  the closed loop u = α K y has an eigenvalue on the imaginary axis (Brent on the closed-loop
  matrix's largest Re λ, 1e-4 as the issue asks; observed ~1e-9); the delay margin equals the
  delay at which the closed loop with a 6th-order Padé delay turns unstable (1e-6) and the
  exact delay puts 1 + L e^{−iωτ} at 0 (1e-9); peak |S| and the balanced disk margin equal
  the test's own dense evaluation (numpy solves on the unscaled matrices, its own grid and a
  bounded scalar search, 1e-9) and, to its accuracy on these sharp peaks (2e-3),
  python-control's L∞ norm (SLICOT AB13DD: Hamiltonian level sets, another algorithm).
- a loop that is not closed-loop stable is refused (InputError naming the controller), and
  closed_loop() then reports no margins, with the reason.
- several measurements: loop-at-a-time gain margins equal the eigenvalue scan with only that
  channel scaled; the multivariable disk margin of a decoupled loop is the least of its
  channels' closed forms; the 2-channel μ closed form equals a brute-force D-scale search.
- a model that is not the rig: the compressor on plain bearings with a decentralised PD
  force feedback at the middle impeller (a magnetic-bearing-like loop, 2 channels).
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

import rotordyn as rd
from rotordyn.control import lti
from rotordyn.control import margins as mg
from rotordyn.control.closedloop import closed_loop, closed_loop_matrix
from rotordyn.control.plant import plant
from rotordyn.errors import InputError

control = pytest.importorskip("control")

AY, PC = -1.85e-3, 0.05e6
MODELS = "tests/data/models"


def tf_loop(num, den):
    return control.ss(control.tf(num, den))


# ------------------------------------------------------------------------------ closed forms

@pytest.mark.parametrize("k", [2.0, 5.0])
def test_gain_phase_delay_margins_closed_form(k):
    m = mg.loop_margins(tf_loop([k], [1, 3, 3, 1]))
    assert m.gain_margin_upper == pytest.approx(8 / k, rel=1e-10)
    assert 2 * math.pi * m.gain_margin_upper_hz == pytest.approx(math.sqrt(3), rel=1e-10)
    assert m.gain_margin_lower == 0.0
    wc = math.sqrt(k ** (2 / 3) - 1)
    pm = math.pi - 3 * math.atan(wc)
    assert 2 * math.pi * m.phase_margin_hz == pytest.approx(wc, rel=1e-10)
    assert m.phase_margin_deg == pytest.approx(math.degrees(pm), rel=1e-10)
    assert m.delay_margin_s == pytest.approx(pm / wc, rel=1e-10)


@pytest.mark.parametrize("k", [0.5, 3.0, 20.0])
def test_disk_margin_closed_form(k):
    m = mg.loop_margins(tf_loop([k], [1, 2, 1]))
    c = math.sqrt(k * k + 4)
    alpha = 2 / math.sqrt(1 + 4 * k / (2 * c + 4 - 2 * k))
    d = m.disk
    assert d.alpha == pytest.approx(alpha, rel=1e-10)
    assert 2 * math.pi * d.frequency_hz == pytest.approx(math.sqrt(1 + c), rel=1e-6)
    assert d.gain_hi == pytest.approx((2 + alpha) / (2 - alpha), rel=1e-10)
    assert d.gain_lo * d.gain_hi == pytest.approx(1.0, rel=1e-12)
    assert d.phase_deg == pytest.approx(math.degrees(2 * math.atan(alpha / 2)), rel=1e-10)
    # skewed: σ = 1 is 1/‖S‖∞ and σ = −1 is 1/‖T‖∞ (the peaks located separately)
    assert m.disk_margin(1.0).alpha == pytest.approx(1 / m.peak_sensitivity, rel=1e-12)
    assert m.disk_margin(-1.0).alpha == pytest.approx(1 / m.peak_complementary, rel=1e-12)


def test_integrator_loop_has_the_textbook_disk_margin():
    """L = a/s: S − T is all-pass, α = 2, gains (0, ∞), phase 90° (Seiler et al. 2020)."""
    m = mg.loop_margins(tf_loop([3.0], [1, 0]))
    assert m.disk.alpha == pytest.approx(2.0, rel=1e-12)
    assert m.disk.gain_lo < 1e-12 and m.disk.gain_hi > 1e12  # (0, ∞) to round-off
    assert m.disk.phase_deg == pytest.approx(90.0, rel=1e-12)


def test_unstable_loop_is_refused():
    with pytest.raises(InputError, match="not stable"):
        mg.loop_margins(tf_loop([10.0], [1, 3, 3, 1]))  # k > 8
    with pytest.raises(InputError, match="sigma"):
        mg.loop_margins(tf_loop([2.0], [1, 3, 3, 1])).disk_margin(math.nan)
    with pytest.raises(InputError, match="loop"):
        mg.loop_margins(control.ss(np.eye(2), np.eye(2), np.eye(2), np.zeros((2, 2))))
    with pytest.raises(InputError, match="loop.A"):
        mg.loop_margins(([[math.inf]], [[1.0]], [[1.0]], [[0.0]]))


# ------------------------------------------------------------------------- the rig's laws

@pytest.fixture(scope="module")
def rig_laws():
    from rotordyn.control.lqr import lqg
    from rotordyn.control.pid import tune_pd
    from rotordyn.control.reduction import balanced_truncation, modal_truncation

    rig = rd.models.paper_rig()
    p = plant(rig, 50.0, PC, AY, measurements=[("journal", 0)])
    laws = {"pd": tune_pd(p)[0], "lqg": lqg(modal_truncation(p, 500.0)[0])}
    try:
        from rotordyn.control.hinf import hinf
        pdist = plant(rig, 50.0, PC, AY, measurements=[("journal", 0)],
                      disturbance_stations=[4])
        laws["hinf"] = hinf(balanced_truncation(pdist, 8)[0])
    except ImportError:
        pass
    return p, laws


def _max_real(p, k):
    return float(np.linalg.eigvals(closed_loop_matrix(p, k)).real.max())


def _scaled_plant(p):
    """The test's own state scaling: positions / c, velocities / (2π·50 Hz·c), valve / 1e5."""
    n = p.n_mech
    s = np.concatenate([np.full(n, 3e-4), np.full(n, 2 * np.pi * 50 * 3e-4),
                        np.full(p.A.shape[0] - 2 * n, 1e5)])
    return control.ss(p.A / s[:, None] * s[None, :], p.B / s[:, None], p.C * s[None, :],
                      np.zeros((p.C.shape[0], 1)))


def _numpy_response(k, s):
    """K(s) by a dense solve (numpy), independent of rotordyn's balanced evaluation."""
    if k.n_states == 0:
        return k.D
    return k.C @ np.linalg.solve(s * np.eye(k.n_states) - k.A, k.B) + k.D


@pytest.mark.parametrize("law", ["pd", "lqg", "hinf"])
def test_rig_margins_against_independent_computations(rig_laws, law):
    p, laws = rig_laws
    if law not in laws:
        pytest.skip("slycot is not installed (H∞ synthesis)")
    k = laws[law]
    cl = closed_loop(p, k)
    m = cl.margins.input
    # gain margins: the closed loop of α K turns unstable exactly there
    for alpha in (m.gain_margin_lower, m.gain_margin_upper):
        assert math.isfinite(alpha)
        root = brentq(lambda a: _max_real(p, k.scaled(a)), alpha * 0.97, alpha * 1.03,
                      xtol=1e-14, rtol=1e-13)
        assert root == pytest.approx(alpha, rel=1e-4)
    assert _max_real(p, k.scaled(m.gain_margin_lower * 1.01)) < 0
    assert _max_real(p, k.scaled(m.gain_margin_upper * 0.99)) < 0
    # delay margin: 6th-order Padé delay before the valve
    def with_delay(tau):
        num, den = control.pade(tau, 6)
        kd = control.ss(control.tf(num, den)) * k.to_control()  # ss series (a tf product
            # would convert the controller to a polynomial fraction)
        return _max_real(p, type(k).from_lti(kd, k.measurements))
    tau = m.delay_margin_s
    assert with_delay(0.99 * tau) < 0 < with_delay(1.01 * tau)
    assert brentq(with_delay, 0.9 * tau, 1.1 * tau, xtol=1e-15) == pytest.approx(tau, rel=1e-6)
    # the exact delay: 1 + L(iω_c) e^{−iω_c τ} = 0 at the crossover of the least delay margin
    wc = 2 * np.pi * m.delay_margin_hz
    Lc = -(_numpy_response(k, 1j * wc) @ _scaled_plant(p)(1j * wc))[0, 0]
    assert abs(1 + Lc * np.exp(-1j * wc * tau)) < 1e-9
    # peak |S| and disk margin: the test's own dense evaluation (numpy solves on the unscaled
    # matrices) on its own grid, refined by a bounded scalar search
    def dense_L(f):
        s = 2j * np.pi * f
        G = p.C @ np.linalg.solve(s * np.eye(p.A.shape[0]) - p.A, p.B)
        return -(_numpy_response(k, s) @ G)[0, 0]

    lam = np.linalg.eigvals(closed_loop_matrix(p, k))  # sharp peaks sit at lightly damped poles
    fd = np.abs(lam.imag[lam.imag > 0]) / (2 * np.pi)
    grid = np.unique(np.concatenate([np.geomspace(0.1, 5000.0, 1200),
                                     (fd[:, None] * (1 + np.linspace(-2e-3, 2e-3, 9))).ravel()]))
    for fun, mine in ((lambda L: abs(1 / (1 + L)), m.peak_sensitivity),
                      (lambda L: abs(1 / (1 + L) - 0.5), 1 / m.disk.alpha)):
        vals = np.array([fun(dense_L(f)) for f in grid])
        i = int(np.argmax(vals))
        r = minimize_scalar(lambda lf: -fun(dense_L(np.exp(lf))), method="bounded",
                            bounds=(np.log(grid[max(i - 1, 0)]), np.log(grid[i + 1])),
                            options={"xatol": 1e-13})
        assert mine >= -r.fun * (1 - 1e-12) and mine == pytest.approx(-r.fun, rel=1e-9)
    # python-control's L∞ norm (SLICOT AB13DD, Hamiltonian level sets) agrees to its own
    # accuracy on this sharp peak (observed 6e-6 .. 6e-4 depending on the realisation)
    L = -(k.to_control() * _scaled_plant(p))
    ns, _ = control.linfnorm(control.feedback(control.ss([], [], [], [[1.0]]), L))
    assert m.peak_sensitivity == pytest.approx(ns, rel=2e-3)


def test_rig_pd_values_of_the_issue(rig_laws):
    """Issue 24 measured the tuned PD as stable for loop gains in (0.064, 1.53), disk margin
    ±3.5 dB / ±22.6°, delay margins 9.6 and 5.5 ms. The 9.6 ms is |PM|/ω_c at the 20.15 Hz
    crossover, whose phase margin is −69.9°: a delay adds lag, so that crossover reaches −1
    only after 360° − 69.9° of lag, at 40.0 ms (the Padé test above confirms the least, 5.5 ms,
    on the closed loop)."""
    p, laws = rig_laws
    m = closed_loop(p, laws["pd"]).margins.input
    assert (round(m.gain_margin_lower, 3), round(m.gain_margin_upper, 2)) == (0.064, 1.53)
    assert round(m.disk.gain_db[1], 1) == 3.5 and round(m.disk.phase_deg, 1) == 22.6
    assert sorted(np.round(m.delay_margins_s * 1e3, 1)) == [5.5, 40.0]


def test_unstable_rig_loop_reports_no_margins(rig_laws):
    p, laws = rig_laws
    k = laws["pd"]
    m = closed_loop(p, k).margins.input
    bad = k.scaled(1.2 * m.gain_margin_upper)
    cl = closed_loop(p, bad)
    assert not cl.stable and cl.margins is None and "not stable" in cl.margins_message
    assert math.isnan(cl.gain_margin_upper) and math.isnan(cl.disk_margin)
    with pytest.raises(InputError, match="controller"):
        mg.margins(p, bad)


def test_rig_loop_at_a_time_and_multiloop(rig_laws):
    """The journal measurement is two signals (x, y): each channel's gain margins equal the
    eigenvalue scan with only that channel scaled; the simultaneous disk margin is no larger
    than any single channel's."""
    p, laws = rig_laws
    k = laws["lqg"]
    ms = mg.margins(p, k)
    assert len(ms.outputs) == 2 and ms.multiloop is not None and ms.multiloop.exact
    for i, m in enumerate(ms.outputs):
        def scaled(a):
            s = np.ones(2)
            s[i] = a
            return k.with_options(B=k.B * s[None, :], D=k.D * s[None, :])
        for alpha in (m.gain_margin_lower, m.gain_margin_upper):
            if 0 < alpha < math.inf:
                root = brentq(lambda a: _max_real(p, scaled(a)), alpha * 0.97, alpha * 1.03,
                              xtol=1e-14)
                assert root == pytest.approx(alpha, rel=1e-4)
        assert ms.multiloop.disk.alpha <= m.disk.alpha * (1 + 1e-9)
    frame = ms.to_frame()
    assert {"input (valve command)", "outputs (multivariable)"} <= set(frame.loop)


# ------------------------------------------------------------------------ multivariable

def test_multiloop_disk_of_a_decoupled_loop_is_the_least_channel():
    k1, k2 = 3.0, 20.0
    P = control.append(tf_loop([k1], [1, 2, 1]), tf_loop([k2], [1, 2, 1]))
    K = control.ss([], [], [], -np.eye(2))  # u = −y
    ml = mg.multiloop_disk_margin(P, K)
    def alpha(k):
        c = math.sqrt(k * k + 4)
        return 2 / math.sqrt(1 + 4 * k / (2 * c + 4 - 2 * k))
    assert ml.disk.alpha == pytest.approx(min(alpha(k1), alpha(k2)), rel=1e-8)
    outs = mg.loop_at_a_time(P, K)
    assert [o.disk.alpha for o in outs] == pytest.approx([alpha(k1), alpha(k2)], rel=1e-10)


def test_mu_two_channel_closed_form_equals_a_d_scale_search():
    rng = np.random.default_rng(3)
    d = np.exp(np.linspace(-9, 9, 40001))
    for _ in range(10):
        M = rng.normal(size=(2, 2)) + 1j * rng.normal(size=(2, 2))
        DMD = np.empty((d.size, 2, 2), complex)
        DMD[:, 0, 0], DMD[:, 1, 1] = M[0, 0], M[1, 1]
        DMD[:, 0, 1], DMD[:, 1, 0] = M[0, 1] / d, M[1, 0] * d
        brute = np.linalg.svd(DMD, compute_uv=False)[:, 0].min()
        mu = mg.mu_diag(M)
        assert mu <= brute * (1 + 1e-12) and mu == pytest.approx(brute, rel=1e-6)
    assert mg.mu_diag(np.diag([2.0, -3.0j])) == pytest.approx(3.0, rel=1e-15)


def test_compressor_pd_force_feedback_margins():
    """Not the rig: the compressor on plain bearings at 100 Hz, decentralised PD force
    feedback (k_p 5e7 N/m, k_d 2e4 N·s/m, derivative filter 0.2 ms, 1 ms actuator lag) at
    the middle impeller; each channel's upper gain margin equals the eigenvalue scan."""
    sysc = rd.System.from_toml(f"{MODELS}/compressor_plain.toml")
    ss = rd.statespace(sysc, inputs=[("force", 3)], outputs=[("displacement", 3)],
                       speed_hz=100.0)
    law = -(control.tf([5e7], [1]) + control.tf([2e4, 0], [2e-4, 1])) \
        * control.tf([1], [1e-3, 1])
    K = control.append(control.ss(law), control.ss(law))
    P = lti.as_ss("plant", (ss.A, ss.B, ss.C, ss.D))
    Ks = lti.as_ss("controller", K)
    outs = mg.loop_at_a_time(P, Ks)
    for i, m in enumerate(outs):
        def max_real(a):
            s = np.ones(2)
            s[i] = a
            Ka = lti.SS(Ks.A, Ks.B * s[None, :], Ks.C, Ks.D * s[None, :])
            return float(np.linalg.eigvals(lti.feedback_A(P, Ka)).real.max())
        gm = m.gain_margin_upper
        assert 1 < gm < 20
        assert brentq(max_real, 0.9 * gm, 1.1 * gm, xtol=1e-14) == pytest.approx(gm, rel=1e-4)
        assert m.delay_margin_s > 0 and m.peak_sensitivity > 1
    ml = mg.multiloop_disk_margin(P, Ks)
    assert 0 < ml.disk.alpha <= min(o.disk.alpha for o in outs)
    with pytest.raises(InputError, match="controller"):
        mg.multiloop_disk_margin(P, lti.SS(Ks.A, Ks.B, 30 * Ks.C, 30 * Ks.D))


def test_closed_loop_without_margins(rig_laws):
    p, laws = rig_laws
    cl = closed_loop(p, laws["pd"], with_margins=False)
    assert cl.margins is None and "with_margins=False" in cl.margins_message
    assert cl.max_real == closed_loop(p, laws["pd"]).max_real
    with pytest.raises(InputError, match="with_margins"):
        closed_loop(p, laws["pd"], with_margins="no")


def _same_margins(a, b, rtol=1e-9):
    sa, sb = a.summary(), b.summary()
    for key in sa:
        x, y = np.asarray(sa[key], float), np.asarray(sb[key], float)
        assert np.array_equal(np.isnan(x), np.isnan(y)), key
        ok = ~np.isnan(x)
        np.testing.assert_allclose(x[ok], y[ok], rtol=rtol, atol=0, err_msg=key)
    for f in ("gain_margins", "phase_margins_deg", "delay_margins_s"):
        np.testing.assert_allclose(getattr(a, f), getattr(b, f), rtol=rtol, atol=0, err_msg=f)


def test_partial_fractions_equal_the_direct_solves(rig_laws):
    """The grid by partial fractions (one eigen-decomposition, rotordyn.control.loop_response)
    gives the margins of the direct solve per frequency (modal=False, the path before it) to
    1e-9 relative (observed 1e-15 on 40 random operating points of the rig and the
    compressor: the refinements and reported values are direct solves in both)."""
    p, laws = rig_laws
    for k in laws.values():
        L = lti.loop_at_input(mg.plant_ss(p), mg.controller_ss(k))
        a, b = mg.loop_margins(L), mg.loop_margins(L, modal=False)
        assert a.response == "partial fractions" and b.response == "direct solves"
        _same_margins(a, b)
        for sigma in (-1.0, 1.0):
            assert a.disk_margin(sigma).alpha == pytest.approx(b.disk_margin(sigma).alpha,
                                                               rel=1e-9)


def test_partial_fractions_on_the_compressor():
    """Not the rig: the compressor with an active DE bearing and a PD with its derivative
    filter; the checked grid values equal the direct solves (1e-6, the check's tolerance) and
    the margins equal the direct path's (1e-9)."""
    from pathlib import Path

    from rotordyn.control import Actuator
    from rotordyn.control import loop_response as lr
    from rotordyn.control.pid import pid

    s = rd.System.from_toml(Path(__file__).parent / "data" / "models" / "compressor_active.toml")
    k = pid(2e9, 2e5)
    p = plant(s, 92.6, 0.293e6, measurements=k.measurements, actuator=Actuator(),
              equilibrium={"warm_start": False})
    L = lti.loop_at_input(mg.plant_ss(p), mg.controller_ss(k))
    _same_margins(mg.loop_margins(L), mg.loop_margins(L, modal=False))
    ss = lti.balanced(L)
    r = lr.Response(ss)
    w = lr.grid_from([r.lam, lr.poles(lr.closed_A(ss), None)], None)
    Lg, _ = r.on_grid(w)
    assert r.redone < w.size
    np.testing.assert_allclose(Lg, lti.freqresp(ss, w)[:, 0, 0], rtol=1e-6, atol=1e-9)
    with pytest.raises(InputError, match="modal"):
        mg.loop_margins(L, modal="yes")
