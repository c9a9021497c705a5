"""Nonlinear transient (paper eq. 12) with SUNDIALS CVODE.

References and tolerances:
- A linear rotor (Friswell Example 5.9.1 on its 1 MN/m supports): the free response equals
  the exact solution expm(A t) x0 of the state equation; CVODE at rtol 1e-8 agrees to 1e-4 of
  each coordinate's range (error accumulated over ~5e4 steps of a stiff FE model).
- The paper rig near a stable equilibrium: a disturbance of 1e-3 c follows the linearised
  model (eq. 19) to 2 % of the disturbance over 0.1 s (the film is weakly nonlinear there).
- An unbalance at a stable point: the steady orbit's amplitude equals the linear unbalance
  response to 3 % (small unbalance, last revolutions after the transient has decayed).
- Beyond the linear threshold the disturbed journal grows into a bounded forward limit cycle
  whose frequency is the linear whirl frequency ± 10 % (paper §6.2, Fig. 11).
"""

import numpy as np
import pytest
from scipy.linalg import expm

import rotordyn as rd
from rotordyn.analysis.assembly import assembled


def test_linear_rotor_matches_matrix_exponential():
    s = rd.models.friswell_5_9_1()
    asm = assembled(s)
    n = asm.n
    r0 = 1e-4 * asm.station_output_matrix(2)[1]  # lift station 2 by 0.1 mm
    tr = rd.transient(s, 0.05, speed_hz=4000 / 60, r0=r0, n_out=51, rtol=1e-8, atol_m=1e-13)
    assert tr.status == "ok", tr.message
    lm = rd.linearize(s, 4000 / 60)
    A = lm.state_matrix()
    # Exact solution about the static (gravity) deflection r_g = K⁻¹ Q.
    rg = np.linalg.solve(lm.K, asm.model.Q)
    x0 = np.concatenate([r0 - rg, np.zeros(n)])
    ref = np.array([rg + (expm(A * t) @ x0)[:n] for t in tr.t])
    scale = np.abs(ref).max(axis=0) + 1e-30  # per coordinate (translations, rotations)
    assert (np.abs(tr.r - ref) / scale).max() < 1e-4


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_small_disturbance_follows_linear_model(rig):
    c = 3e-4
    pc, ay = 0.15e6, -1.85e-3
    d = 1e-3 * c
    tr = rd.transient(rig, 0.1, 50.0, pc, ay, disturbance_m=(d, 0.0), n_out=101, rtol=1e-8,
                      atol_m=1e-12)
    assert tr.status == "ok", tr.message
    lm = rd.linearize(rig, 50.0, pc, ay)
    n = len(lm.labels)
    A = lm.state_matrix()
    x0 = np.concatenate([tr.r[0] - tr.equilibrium_r, np.zeros(n)])
    lin = np.array([(expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - tr.equilibrium_r
    j = [2, 3]  # active-bearing journal
    assert np.abs(dev[:, j] - lin[:, j]).max() < 0.02 * d


def test_unbalance_orbit_matches_linear_response(rig):
    pc, ay, f = 0.15e6, -1.85e-3, 50.0
    ub = [(6, 2e-6, 0.0)]
    tr = rd.transient(rig, 1.0, f, pc, ay, unbalances=ub, n_out=2001, rtol=1e-8, atol_m=1e-12)
    assert tr.status == "ok", tr.message
    u = rd.unbalance_response(rig, ub, [f], stations=[4], chamber_pressure_pa=pc,
                              config_ay_m=ay)
    last = tr.t > 0.8
    x = tr.journal_x_m[last, 0]
    amp_nl = 0.5 * (x.max() - x.min())
    assert amp_nl == pytest.approx(abs(u.x[0, 0]), rel=0.03)


def test_beyond_threshold_a_bounded_forward_limit_cycle(rig):
    pc, ay = 0.03e6, -1.85e-3
    st = rd.stability(rig, 50.0, pc, ay)
    assert not st.stable
    i = int(np.argmax(st.eigenvalues.real))
    tr = rd.transient(rig, 1.0, 50.0, pc, ay, disturbance_m=(0.0, 3e-5), n_out=4001)
    assert tr.status == "ok", tr.message
    assert tr.amplitude() > 0.3 * 3e-4  # grew from 0.1 c
    assert np.nanmin(tr.h_min_m) > 0  # bounded, no contact
    f, a = tr.spectrum(last_fraction=0.5)
    fpk = f[np.argmax(a[1:]) + 1]
    assert fpk == pytest.approx(st.frequencies_hz[i], rel=0.10)
    # forward whirl: the orbit turns with the rotation (positive signed area)
    x = tr.journal_x_m[-1000:, 0] - tr.journal_x_m[-1000:, 0].mean()
    y = tr.journal_y_m[-1000:, 0] - tr.journal_y_m[-1000:, 0].mean()
    assert np.sum(x[:-1] * y[1:] - x[1:] * y[:-1]) > 0


def test_failures_are_statuses_and_bad_input_errors(rig):
    tr = rd.transient(rig, 0.5, 50.0, 0.03e6, -1.85e-3, disturbance_m=(0.0, 3e-5),
                      max_steps=20)
    assert tr.status == "not_converged" and "CV_TOO_MUCH_WORK" in tr.message
    assert np.isnan(tr.r[-1]).all() and np.isfinite(tr.r[0]).all()
    with pytest.raises(rd.InputError, match="t_end_s"):
        rd.transient(rig, -1.0)
    with pytest.raises(rd.InputError, match="r0"):
        rd.transient(rig, 0.1, r0=np.zeros(3))


def test_recorded_min_film_is_the_geometric_one(rig):
    """The transient records h_min from the geometry h = c − x cos φ − y sin φ − w(φ) (eq. 3)
    at the grid angles, without a Reynolds solve: it must equal the minimum over the nodes that
    a film solve at the same state reports (same nodes, same formula: to round-off), and the
    recorded value at each output time must be that of the recorded positions."""
    asm = assembled(rig)
    s = asm.solver
    w = 2 * np.pi * 50.0
    tr = rd.transient(rig, 0.02, 50.0, 0.15e6, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=9)
    assert tr.status == "ok", tr.message
    rng = np.random.default_rng(1)
    for i in range(len(tr.t)):
        r = tr.r[i]
        geo = np.asarray(s.film_h_min(r))
        np.testing.assert_allclose(tr.h_min_m[i], geo, rtol=0, atol=0)
        s.film_forces(r + 1e-7 * rng.standard_normal(asm.n), np.zeros(asm.n), w)  # move away
        s.film_forces(r, tr.v[i], w)
        np.testing.assert_allclose(geo, s.last_h_min, rtol=0, atol=1e-18)
    with pytest.raises(rd.InputError, match="r"):
        s.film_h_min(np.zeros(asm.n + 1))


def test_a_run_does_not_depend_on_what_ran_before(rig):
    """The films continue their cavitation sets from one right-hand side to the next inside a
    run (ReynoldsSolver continuation, switched on afresh at the run's start): a run is a
    function of its inputs, bit for bit, whatever the solver solved before; and the films are
    back to predicted starts afterwards (an equilibrium after a run equals a fresh one)."""
    args = (0.05, 50.0, 0.05e6, -1.85e-3)
    kw = dict(disturbance_m=(0.0, 3e-5), n_out=101)
    a = rd.transient(rig, *args, **kw)
    e0 = rd.equilibrium(rig, 40.0, 0.1e6, -1.0e-3, warm_start=False)
    rd.stability(rig, 70.0, 0.3e6, 0.0)
    b = rd.transient(rig, *args, **kw)
    assert a.status == b.status == "ok"
    np.testing.assert_array_equal(a.r, b.r)
    np.testing.assert_array_equal(a.h_min_m, b.h_min_m)
    e1 = rd.equilibrium(rig, 40.0, 0.1e6, -1.0e-3, warm_start=False)
    np.testing.assert_array_equal(e0.r, e1.r)


def test_the_path_does_not_depend_on_the_output_times(rig):
    """CVODE steps toward t_end and interpolates each output (since the speed work of
    docs/performance.md): the steps, and so the states at common output times, are the same
    for any output grid, bit for bit (before, the first step was sized from the first output
    time, so n_out changed the whole path)."""
    kw = dict(disturbance_m=(0.0, 3e-5))
    a = rd.transient(rig, 0.04, 50.0, 0.15e6, -1.85e-3, n_out=41, **kw)
    b = rd.transient(rig, 0.04, 50.0, 0.15e6, -1.85e-3, n_out=81, **kw)
    c = rd.transient(rig, 0.04, 50.0, 0.15e6, -1.85e-3, n_out=2, **kw)
    assert a.status == b.status == c.status == "ok"
    assert a.stats == b.stats == c.stats
    assert np.array_equal(a.r, b.r[::2]) and np.array_equal(a.v, b.v[::2])
    assert np.array_equal(a.r[-1], c.r[-1])
