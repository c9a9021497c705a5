"""Control-law synthesis on the linear model (rotordyn.control), verified against
python-control and on the nonlinear transient.

- LQR: the closed-loop eigenvalues of A − B K from rotordyn equal python-control's
  ``control.lqr`` on the same (A, B, Q, R) to 1e-6 relative per eigenvalue, and the stable
  eigenvalues of the Hamiltonian [[A, −B R⁻¹ Bᵀ], [−Q, −Aᵀ]] (the exact LQR closed-loop
  spectrum) to 1e-9; gains agree to 1e-5 of the largest. python-control solves the unscaled
  Riccati equation of a plant whose entries span 1e-8..1e8 (its eigenvalues are ~7e-8 off the
  Hamiltonian's); rotordyn solves it in scaled states (2.6e-11 off). python-control is pinned
  to its SciPy solver (``method="scipy"``): with slycot installed (the ``hinf`` extra) its
  default becomes SLICOT's SB02MD, which on this unscaled problem is 5 % off in the gains and
  52 % in the eigenvalues (the Hamiltonian check below shows whose error that is).
- The rig at a_y = −1.85 mm, 50 Hz, p_c = 0.05 MPa is linearly unstable (max Re λ ≈ +2.4 1/s,
  docs/transient-and-sweeps.md); the tuned PD law with the default 100 Hz valve makes the
  linear closed loop stable, and the nonlinear closed-loop run from a 0.1 c disturbance
  decays (amplitude over the last 0.1 s below 5 % of the disturbance) where the open loop
  keeps a limit cycle (docs/control.md gives the numbers).
- Modal truncation keeps the plant's low-frequency response: stated relative H∞ error
  below 1e-3 when only the fast sleeve modes are dropped.
"""

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.control import Actuator, Controller
from rotordyn.control.closedloop import closed_loop
from rotordyn.control.lqr import default_weights, lqg, lqr
from rotordyn.control.pid import pid, tune_pd
from rotordyn.control.plant import plant
from rotordyn.control.reduction import modal_truncation

C_RIG, AY, PC_UNSTABLE = 3e-4, -1.85e-3, 0.05e6


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


@pytest.fixture(scope="module")
def unstable_plant(rig):
    return plant(rig, 50.0, PC_UNSTABLE, AY, measurements=[("journal", 0)])


def test_lqr_eigenvalues_equal_python_control(unstable_plant):
    import control

    p = unstable_plant
    Q, R = default_weights(p)
    K, E = lqr(p, Q, R)
    Kc, _, Ec = control.lqr(p.A, p.B, Q, R, method="scipy")
    assert np.abs(K - Kc).max() < 1e-5 * np.abs(Kc).max()
    a, b = np.sort_complex(E), np.sort_complex(np.asarray(Ec))
    assert np.all(np.abs(a - b) <= 1e-6 * np.abs(b))
    H = np.block([[p.A, -p.B @ np.linalg.solve(R, p.B.T)], [-Q, -p.A.T]])
    lh = np.linalg.eigvals(H)
    ham = np.sort_complex(lh[lh.real < 0])
    assert np.all(np.abs(a - ham) <= 1e-9 * np.abs(ham))
    assert E.real.max() < 0 < p.poles.real.max()


def test_pd_stabilises_the_unstable_rig_linear_and_nonlinear(rig, unstable_plant):
    k, cl = tune_pd(unstable_plant)
    assert unstable_plant.poles.real.max() > 1.0  # unstable without feedback
    assert cl.stable and cl.max_real < -1.0
    d = (0.0, 0.1 * C_RIG)
    kw = dict(disturbance_m=d, n_out=1201, rtol=1e-7, atol_m=1e-11)
    ol = rd.transient(rig, 0.6, 50.0, PC_UNSTABLE, AY, **kw)
    cl_nl = rd.transient(rig, 0.6, 50.0, PC_UNSTABLE, AY, controller=k,
                         actuator=unstable_plant.actuator, **kw)
    assert ol.status == cl_nl.status == "ok", (ol.message, cl_nl.message)
    last = ol.t > 0.5
    amp = lambda tr: np.hypot(tr.journal_x_m[last, 0] - tr.equilibrium_r[2],  # noqa: E731
                              tr.journal_y_m[last, 0] - tr.equilibrium_r[3]).max()
    assert amp(ol) > 0.1 * C_RIG  # grows towards the limit cycle
    assert amp(cl_nl) < 0.05 * 0.1 * C_RIG
    p = cl_nl.chamber_pressure_actual_pa
    assert p.min() >= 0.0 and p.max() <= Actuator().p_max_pa


def test_controller_objects_accept_python_control_and_check_sizes(unstable_plant):
    import control

    k = pid(1e9, 1e5)
    sys = k.to_control()
    k2 = Controller.from_lti(sys, [("journal", 0)])
    assert np.allclose(closed_loop(unstable_plant, k).eigenvalues.real.max(),
                       closed_loop(unstable_plant, k2).eigenvalues.real.max())
    # python-control systems are accepted directly (the plant's measurements as inputs)
    assert np.isclose(closed_loop(unstable_plant, sys).max_real,
                      closed_loop(unstable_plant, k).max_real)
    tf = control.tf([1e3], [1e-3, 1])
    with pytest.raises(rd.InputError, match="controller: expected 2 inputs"):
        closed_loop(unstable_plant, Controller.from_lti(tf, [("journal", 0)]))  # 1 input
    kz = Controller.from_lti(control.c2d(sys, 1e-4), [("journal", 0)])
    assert kz.discrete and kz.sample_time_s == 1e-4
    # Sampled-data loop (ZOH): the least-damped eigenvalue converges to the continuous loop's
    # as T -> 0. The tuned PD places two eigenvalues almost on top of each other (−9.614 and
    # −9.617 1/s, the optimum of the least damping), and a near-double eigenvalue moves as
    # √(perturbation): observed 6.6 % at T = 1e-4 s, 1.8 % at 1e-5 s.
    kt, clt = tune_pd(unstable_plant)
    errs = []
    for T in (1e-4, 1e-5):
        kzt = Controller.from_lti(control.c2d(kt.to_control(), T), [("journal", 0)])
        clz = closed_loop(unstable_plant, kzt)
        assert clz.stable
        errs.append(abs(clz.max_real / clt.max_real - 1))
    assert errs[1] < 0.03 and errs[1] < errs[0] / 2
    from rotordyn.control.closedloop import closed_loop_matrix

    with pytest.raises(rd.InputError, match="sample_time_s"):
        closed_loop_matrix(unstable_plant, kz)


def test_modal_truncation_states_its_error(unstable_plant):
    pr, info = modal_truncation(unstable_plant, 500.0)
    assert info["order"] < info["full_order"]
    assert info["relative_error"] < 1e-3
    kq = lqg(pr)
    assert kq.n_states == info["order"]
    assert closed_loop(unstable_plant, kq).stable  # the reduced design works on the full plant


def test_balanced_truncation_obeys_its_hankel_bound(unstable_plant):
    """Glover's bound ‖G − G_r‖∞ ≤ 2 Σ dropped Hankel singular values (stable part; the
    unstable part is kept whole, so the reduced plant keeps the unstable poles exactly). The
    measured error is the max over a 400-point grid, so it can only under-estimate the norm:
    it must lie below the bound."""
    from rotordyn.control.reduction import balanced_truncation

    p = unstable_plant
    unstable = np.sort_complex(p.poles[p.poles.real > 0])
    errs = []
    for order in (8, 12):
        r, info = balanced_truncation(p, order)
        assert r.A.shape == (order, order)
        assert info["hinf_error_scaled"] <= info["bound_scaled"] * (1 + 1e-9)
        ru = np.sort_complex(np.linalg.eigvals(r.A)[np.linalg.eigvals(r.A).real > 0])
        assert np.allclose(ru, unstable, rtol=1e-8)
        errs.append(info["relative_error"])
    assert errs[1] < errs[0] < 0.05
    with pytest.raises(rd.InputError, match="order"):
        balanced_truncation(p, 1)  # fewer states than the unstable part
