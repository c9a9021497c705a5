"""Computation delay in the linear loop (rotordyn.control.delay, issue 24):

- the Padé approximant's realisation equals python-control's ``pade`` polynomials (1e-10),
  is all-pass (|P| = 1 to 1e-13), and its stated phase error equals the angle of
  P(iω) e^{iωτ} computed directly (1e-12), shrinking with the order;
- a generic loop k/(s+1)³ (closed-form delay margin τ_m = PM/ω_c) delayed by τ₁ through an
  8th-order Padé keeps a delay margin τ_m − τ₁ (to the Padé phase error at ω_c, 1e-7);
- the rig's PD law, continuous: the closed loop with a delay turns unstable at the delay
  margin (1e-6, order 6); discrete (sample-and-hold of the computation): a delay of one full
  sample equals the law followed by z⁻¹ (the closed-loop eigenvalues, 1e-9), a fractional
  delay equals the sampled plant propagated piecewise by the test (u[k−1] for τ, then u[k])
  (1e-12), no delay is the plain ZOH loop; the sampled loop's gain margins equal the scan of
  the spectral radius of the closed loop with α K (1e-6);
- bad input: a negative or non-finite delay, a delay beyond the sample time, a Padé order
  outside 1..20 raise an InputError naming the field.
"""

import math

import numpy as np
import pytest
from scipy.linalg import expm
from scipy.optimize import brentq

import rotordyn as rd
from rotordyn.control import Controller, lti
from rotordyn.control import margins as mg
from rotordyn.control.closedloop import closed_loop, closed_loop_matrix
from rotordyn.control.delay import (pade, pade_phase_error, with_pade_delay,
                                    with_sample_delay)
from rotordyn.control.plant import plant
from rotordyn.errors import InputError

control = pytest.importorskip("control")
AY, PC = -1.85e-3, 0.05e6


@pytest.mark.parametrize("order", [1, 3, 6, 10])
def test_pade_realisation_and_its_error(order):
    tau = 2.5e-3
    P = pade(tau, order)
    num, den = control.pade(tau, order)
    f = np.geomspace(1.0, 400.0, 30)
    s = 2j * np.pi * f
    ref = np.polyval(num, s) / np.polyval(den, s)
    G = lti.freqresp(P, 2 * np.pi * f)[:, 0, 0]
    assert np.max(np.abs(G - ref)) < 1e-10
    assert np.max(np.abs(np.abs(G) - 1)) < 1e-13
    err = pade_phase_error(tau, order, f)
    assert np.max(np.abs(err - np.angle(G * np.exp(s * tau)))) < 1e-12
    if order > 1:
        assert np.all(np.abs(err) <= np.abs(pade_phase_error(tau, order - 1, f)) + 1e-13)


def test_delay_margin_of_a_delayed_generic_loop():
    k = 2.0
    wc = math.sqrt(k ** (2 / 3) - 1)
    tau_m = (math.pi - 3 * math.atan(wc)) / wc
    L = lti.as_ss("loop", control.ss(control.tf([k], [1, 3, 3, 1])))
    tau1 = 0.4
    P = pade(tau1, 8)
    Ld = lti.SS(np.block([[L.A, np.zeros((3, 8))], [P.B @ L.C, P.A]]),
                np.vstack([L.B, np.zeros((8, 1))]), np.hstack([P.D @ L.C, P.C]), P.D @ L.D)
    m = mg.loop_margins(Ld)
    eps = abs(pade_phase_error(tau1, 8, wc / (2 * math.pi))[0])
    assert eps < 1e-6
    assert m.delay_margin_s == pytest.approx(tau_m - tau1, abs=2 * eps / wc + 1e-12)


@pytest.fixture(scope="module")
def pd_law():
    from rotordyn.control.pid import tune_pd

    # a cold equilibrium: the eigenvalue checks below are at round-off (1e-9), and a warm
    # start left by an earlier test moves the operating point within the solver's tolerance
    p = plant(rd.models.paper_rig(), 50.0, PC, AY, measurements=[("journal", 0)],
              equilibrium={"warm_start": False})
    return p, tune_pd(p)[0]


def test_continuous_law_with_delay_turns_unstable_at_its_delay_margin(pd_law):
    p, k = pd_law
    dm = closed_loop(p, k).delay_margin_s
    mr = lambda tau: closed_loop_matrix(p, with_pade_delay(k, tau, 6))  # noqa: E731
    root = brentq(lambda t: np.linalg.eigvals(mr(t)).real.max(), 0.8 * dm, 1.2 * dm,
                  xtol=1e-15)
    assert root == pytest.approx(dm, rel=1e-6)
    cl = closed_loop(p, k, computation_delay_s=0.5 * dm)
    assert cl.stable and cl.delay_margin_s == pytest.approx(0.5 * dm, rel=1e-6)
    assert not closed_loop(p, k, computation_delay_s=1.1 * dm).stable


def test_discrete_law_with_computation_delay(pd_law):
    from rotordyn.control.export import discretise

    p, k = pd_law
    T = 2e-4
    kd = discretise(k, T)
    # one full sample: the same as the law followed by z^-1 (the test's own augmentation)
    nk = kd.n_states
    A = np.block([[kd.A, np.zeros((nk, 1))], [kd.C, np.zeros((1, 1))]])
    kz = kd.with_options(A=A, B=np.vstack([kd.B, kd.D]), C=np.hstack([np.zeros((1, nk)),
                                                                        [[1.0]]]),
                         D=np.zeros_like(kd.D))
    ks = with_sample_delay(kd)
    assert all(np.array_equal(getattr(ks, m), getattr(kz, m)) for m in "ABCD")
    a = np.sort_complex(closed_loop(p, kd, computation_delay_s=T).eigenvalues)
    b = np.sort_complex(closed_loop(p, kz).eigenvalues)
    assert a.size == b.size
    # two routes to one loop (the delayed hold in the plant vs the z^-1 in the law): the
    # closed-loop matrix has ‖A_d‖ ≈ 2.6e9 (unscaled plant states) and eigenvalue condition
    # numbers up to 1.7e12, so LAPACK's results may differ far above round-off of λ; measured:
    # z within 6e-11, λ = ln z / T within 1.46e-9 relative (numpy 2.4; < 1e-9 on an earlier
    # machine). 1e-8 keeps a decade above that; a delay 1 % short of the sample (0.99 T) moves
    # the eigenvalues by 6.5e-3 relative, 0.9 T by 6.7e-2: the check still sees a wrong delay.
    assert np.max(np.abs(a - b) / np.abs(b)) < 1e-8
    c = np.sort_complex(closed_loop(p, kd, computation_delay_s=0.99 * T).eigenvalues)
    assert c.size != b.size or np.max(np.abs(c - b) / np.abs(b)) > 1e-3
    # a fractional delay: propagate the sampled plant piecewise
    tau = 0.3 * T
    Ps = mg.plant_ss(p, T, tau)
    n = p.A.shape[0]

    def step(x, up, u):
        Eh = expm(np.block([[p.A, p.B], [np.zeros((1, n + 1))]]) * tau)
        x1 = Eh[:n, :n] @ x + Eh[:n, n:] @ up
        Er = expm(np.block([[p.A, p.B], [np.zeros((1, n + 1))]]) * (T - tau))
        return Er[:n, :n] @ x1 + Er[:n, n:] @ u
    rng = np.random.default_rng(2)
    x, up, u = rng.normal(size=n) * 1e-5, rng.normal(size=1) * 1e3, rng.normal(size=1) * 1e3
    xa = Ps.A @ np.concatenate([x, up]) + Ps.B @ u
    ref = step(x, up, u)
    assert np.max(np.abs(xa[:n] - ref)) <= 1e-12 * np.max(np.abs(ref))
    assert xa[n] == u[0]
    cl = closed_loop(p, kd, computation_delay_s=tau)
    assert cl.stable and cl.margins is not None
    # the sampled-data gain margins: |z| = 1 crossings of the loop with α K (the test's scan)
    K = lti.SS(kd.A, kd.B, kd.C, kd.D, T)

    def log_rho(a):
        Ka = lti.SS(K.A, K.B, a * K.C, a * K.D, T)
        return np.log(np.abs(np.linalg.eigvals(lti.feedback_A(Ps, Ka)))).max()
    for alpha in (cl.gain_margin_lower, cl.gain_margin_upper):
        assert brentq(log_rho, 0.95 * alpha, 1.05 * alpha, xtol=1e-15) == pytest.approx(
            alpha, rel=1e-6)
    assert cl.delay_margin_s < closed_loop(p, kd).delay_margin_s
    # no delay: the plain ZOH loop
    assert np.array_equal(closed_loop(p, kd, computation_delay_s=0.0).eigenvalues,
                          closed_loop(p, kd).eigenvalues)


def test_delay_bad_input(pd_law):
    p, k = pd_law
    with pytest.raises(InputError, match="computation_delay_s"):
        closed_loop(p, k, computation_delay_s=-1e-3)
    with pytest.raises(InputError, match="computation_delay_s"):
        closed_loop(p, k, computation_delay_s=math.nan)
    with pytest.raises(InputError, match="computation_delay_s"):
        closed_loop(p, k.with_options(sample_time_s=1e-4), computation_delay_s=2e-4)
    with pytest.raises(InputError, match="pade_order"):
        closed_loop(p, k, computation_delay_s=1e-3, pade_order=0)
    with pytest.raises(InputError, match="delay_s"):
        pade(-1.0)
    with pytest.raises(InputError, match="pade_order"):
        pade(1e-3, 30)
    with pytest.raises(InputError, match="controller"):
        with_pade_delay(Controller.static([[1.0, 0.0]], [("journal", 0)],
                                          sample_time_s=1e-3), 1e-3)


def test_delayed_laws_in_the_nonlinear_transient(pd_law):
    """The PD law with a Padé computation delay runs in the CVODE transient: from a 0.01 c
    disturbance at the unstable point it decays with half the delay margin and grows with
    1.3 times it, as the linear closed loop says (its max Re λ: −7.45 and +8.29 1/s)."""
    p, k = pd_law
    dm = closed_loop(p, k).delay_margin_s
    rig = rd.models.paper_rig()
    kw = dict(disturbance_m=(0.0, 0.01 * 3e-4), n_out=301, rtol=1e-7, atol_m=1e-12)
    amp = []
    for factor in (0.5, 1.3):
        lin = closed_loop(p, k, computation_delay_s=factor * dm)
        kd = with_pade_delay(k, factor * dm, 6)
        tr = rd.transient(rig, 0.3, 50.0, PC, AY, controller=kd, actuator=p.actuator, **kw)
        assert tr.status == "ok", tr.message
        d = np.hypot(tr.journal_x_m[:, 0] - tr.equilibrium_r[2],
                     tr.journal_y_m[:, 0] - tr.equilibrium_r[3])
        amp.append((d[tr.t > 0.25].max(), lin.max_real))
    (a_stable, l_stable), (a_unst, l_unst) = amp
    assert l_stable < 0 < l_unst
    assert a_stable < 0.5 * 0.01 * 3e-4 < 0.01 * 3e-4 < a_unst
    with pytest.raises(InputError, match="controller.sample_time_s"):
        with_sample_delay(k)


def test_discrete_computation_delay_in_the_transient(pd_law):
    """The C++ loop applies a discrete law's command at kT + τ: with a static law and outputs
    every T/2, the recorded command at each output time is D·y(kT) of the last sample whose
    application time has passed (0 before the first), to round-off; τ = T runs the same as
    the law with the one-sample delay as a state (with_sample_delay)."""
    from rotordyn.control.export import discretise

    rig = rd.models.paper_rig()
    T = 1e-4
    kw = dict(disturbance_m=(0.0, 3e-6), rtol=1e-8, atol_m=1e-12)
    gain = -1e8
    for tau in (0.5 * T, 0.3 * T):
        k = Controller.static([[0.0, gain]], [("journal", 0)], sample_time_s=T,
                              computation_delay_s=tau)
        n_out = 201 if tau == 0.5 * T else 101
        tr = rd.transient(rig, 0.01, 50.0, PC, AY, controller=k, n_out=n_out, **kw)
        assert tr.status == "ok", tr.message
        y = tr.journal_y_m[:, 0] - tr.equilibrium_r[3]
        t = tr.t
        on_sample = np.isclose(t / T, np.rint(t / T), rtol=0, atol=1e-6)
        ys = dict(zip(np.rint(t[on_sample] / T).astype(int), y[on_sample]))
        kk = np.floor((t - tau) / T + 1e-6).astype(int)
        for ti, ki, ui in zip(t, kk, tr.controller_output_pa):
            if ki < 0:
                assert ui == 0.0
            elif ki in ys:
                assert ui == pytest.approx(gain * ys[ki], rel=1e-12, abs=1e-9)
    p, kc = pd_law
    kd = discretise(kc, T)
    a = rd.transient(rig, 0.02, 50.0, PC, AY, n_out=41,
                     controller=kd.with_options(computation_delay_s=T), **kw)
    b = rd.transient(rig, 0.02, 50.0, PC, AY, n_out=41, controller=with_sample_delay(kd), **kw)
    c = rd.transient(rig, 0.02, 50.0, PC, AY, n_out=41, controller=kd, **kw)
    assert a.status == b.status == c.status == "ok"
    amp = np.max(np.abs(a.r - a.equilibrium_r))
    assert np.max(np.abs(a.r - b.r)) <= 1e-12 * amp  # observed: bit for bit
    assert np.max(np.abs(a.r - c.r)) > 1e-2 * amp    # the delay matters (observed 8 %)
    with pytest.raises(InputError, match="controller.computation_delay_s"):
        kd.with_options(computation_delay_s=2 * T)
    with pytest.raises(InputError, match="controller.computation_delay_s"):
        kc.with_options(computation_delay_s=1e-4)
    with pytest.raises(InputError, match="computation_delay_s"):
        closed_loop(p, kd.with_options(computation_delay_s=0.5 * T), computation_delay_s=T)
