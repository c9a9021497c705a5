"""Periodic orbits by shooting and their Floquet multipliers (issue 19, docs/nonlinear.md).

References:
* closed form: a rotor on linear supports forced by unbalance has the periodic orbit
  r(t) = K⁻¹(Q − K a) + Re(X e^{iΩt}), (K − Ω² M + iΩ(C + ΩG)) X = Ω² (u_c − i u_s), and the
  Floquet multipliers exp(λ_k T) (λ_k the eigenvalues of the first-order system matrix);
* the nonlinear orbits (plain journal bearings, Reynolds equation with cavitation) against
  transients: a stable forced orbit is where a transient settles, and the distance of a
  transient started off the orbit shrinks per period by the critical Floquet multiplier.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.periodic import period_from_transient, periodic_orbit

from orbit_forms import forced_orbit

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def linear_system():
    return rd.System.from_toml(MODELS / "compressor_linear.toml")


@pytest.fixture(scope="module")
def plain_system():
    return rd.System.from_toml(MODELS / "compressor_plain.toml")


def state_matrix(asm, omega):
    m = asm.model
    M, K, C, G = (np.asarray(x) for x in (m.M, m.K, m.C, m.G))
    n = M.shape[0]
    Mi = np.linalg.inv(M)
    return np.block([[np.zeros((n, n)), np.eye(n)], [-Mi @ K, -Mi @ (C + omega * G)]])


def test_forced_orbit_of_a_linear_rotor_equals_the_closed_form(linear_system):
    """Closed form (module docstring) to 1e-6 of the orbit's amplitude, and the multipliers
    exp(λT) to 1e-6 (absolute: |μ| ≤ 1; the sensitivities are in CVODES's error test at
    rtol 1e-9)."""
    f = 60.0
    ub = [(3, 1e-3, 30.0)]
    res = periodic_orbit(linear_system, f, kind="forced", unbalances=ub, rtol=1e-9,
                         atol_m=1e-13)
    assert res.status == "ok", res.message
    r_exact, amp = forced_orbit(linear_system, f, res.t, ub)
    asm = assembled(linear_system)
    w = 2 * np.pi * f
    assert np.abs(res.r - r_exact).max() < 1e-6 * amp
    assert res.period_s == pytest.approx(1 / f, rel=1e-15)
    lam = np.linalg.eigvals(state_matrix(asm, w))
    mu_exact = np.exp(lam * res.period_s)
    mu = res.multipliers
    # pair each exact multiplier with the nearest computed one
    d = np.abs(mu_exact[:, None] - mu[None, :]).min(axis=1)
    assert d.max() < 1e-6
    assert res.stable and res.trivial_index == -1


def test_forced_orbit_on_journal_bearings_is_where_the_transient_settles(plain_system):
    """A stable unbalance-forced orbit on plain journal bearings (Reynolds, cavitation):
    a transient started from the equilibrium settles on it. After 12 revolutions the
    transient is within the decay of its slowest mode (|μ|^12 of the start's distance) of
    the orbit: compared at the orbit's own start phase, 1e-3 of the orbit amplitude."""
    f = 50.0
    ub = [(3, 2e-4, 0.0)]
    res = periodic_orbit(plain_system, f, kind="forced", unbalances=ub)
    assert res.status == "ok", res.message
    assert res.stable
    assert res.critical_type in ("fold", "period_doubling", "neimark_sacker")
    tr = rd.transient(plain_system, 12 / f, f, unbalances=ub, n_out=12 * 40 + 1, rtol=1e-9,
                      atol_m=1e-13)
    assert tr.status == "ok"
    amp = res.amplitude(0)
    d_end = np.abs(tr.r[-1] - res.r[0]).max()
    assert d_end < 1e-3 * amp


def test_floquet_multiplier_equals_the_decay_of_a_transient_off_the_orbit(plain_system):
    """Started off the forced orbit along the (real part of the) eigenvector of the critical
    multiplier μ_c (a complex pair here), a transient's deviation from the orbit, sampled once
    per period and expressed in the eigenvector basis of the monodromy matrix, shrinks by
    |μ_c| per period along that eigenvector (1 % of the clearance: the linear regime): the
    ratio over two periods within 2 %. The transient (CVODE, rtol 1e-10) knows nothing of the
    sensitivities."""
    f = 50.0
    ub = [(3, 2e-4, 0.0)]
    res = periodic_orbit(plain_system, f, kind="forced", unbalances=ub, rtol=1e-9, tol=1e-7)
    assert res.status == "ok", res.message
    mu_c = res.critical_multiplier
    w, V = np.linalg.eig(res.monodromy)
    k = int(np.argmin(np.abs(w - mu_c)))
    n = res.r.shape[1]
    x0 = np.concatenate([res.r[0], res.v[0]])
    dvec = np.real(V[:, k])
    dvec = dvec / np.abs(dvec[:n]).max() * 1e-2 * res.length_scale_m
    per = 40
    tr = rd.transient(plain_system, 3 / f, f, unbalances=ub, r0=x0[:n] + dvec[:n],
                      v0=x0[n:] + dvec[n:], n_out=3 * per + 1, rtol=1e-10, atol_m=1e-14)
    assert tr.status == "ok"
    Vi = np.linalg.inv(V)
    z = [abs((Vi @ (np.concatenate([tr.r[i * per], tr.v[i * per]]) - x0))[k])
         for i in range(3)]
    ratio = (z[2] / z[0]) ** 0.5
    assert ratio == pytest.approx(abs(mu_c), rel=0.02)


def test_bad_inputs_name_the_field(linear_system):
    with pytest.raises(rd.InputError, match="period_s"):
        periodic_orbit(linear_system, 50.0, start=np.zeros(20), period_s=-1.0)
    with pytest.raises(rd.InputError, match="period_s"):
        periodic_orbit(linear_system, 50.0, start=np.zeros(20), period_s=0.0)
    with pytest.raises(rd.InputError, match="kind"):
        periodic_orbit(linear_system, 50.0, kind="chaotic")
    with pytest.raises(rd.InputError, match="start"):
        periodic_orbit(linear_system, 50.0)  # autonomous without a start
    with pytest.raises(rd.InputError, match="unbalances"):
        periodic_orbit(linear_system, 50.0, kind="forced")
    with pytest.raises(rd.InputError, match="unbalances"):
        periodic_orbit(linear_system, 50.0, start=np.zeros(20), period_s=0.02,
                       unbalances=[(3, 1e-3, 0.0)])
    with pytest.raises(rd.InputError, match="period_s"):
        periodic_orbit(linear_system, 50.0, kind="forced", unbalances=[(3, 1e-3, 0.0)],
                       period_s=0.03)
    with pytest.raises(rd.InputError, match="start"):
        periodic_orbit(linear_system, 50.0, start=np.zeros(7), period_s=0.02)


def test_a_start_that_is_not_on_a_cycle_is_a_status(linear_system):
    """The linear rotor has no limit cycle: shooting from an arbitrary state fails with
    status not_converged (singular Newton matrix or no convergence), no multipliers."""
    x = np.zeros(20)
    x[1] = 1e-5
    res = periodic_orbit(linear_system, 50.0, start=x, period_s=0.01, max_iter=5)
    assert res.status == "not_converged"
    assert res.multipliers.size == 0 and not res.stable
    assert "not_converged" in repr(res)


def test_a_small_orbit_about_a_weakly_damped_equilibrium_is_not_a_cycle(linear_system):
    """The linear rotor with its supports' damping cut to 2e-3 N·s/m: the least-damped mode
    has |μ| = 1 − 1.7e-8 per period, so any small orbit along it closes within tol after one
    period although a linear system has no limit cycle (near a Hopf point the same happens
    beside the real cycle: docs/nonlinear.md). The Newton correction at the converged start is
    half the orbit's extent: refused (status not_converged, no multipliers); before, such an
    orbit came back ok. A converged orbit reports its correction (far below tol)."""
    sup = tuple(dataclasses.replace(p, cxx_n_s_per_m=2e-3, cyy_n_s_per_m=2e-3)
                for p in linear_system.supports)
    light = dataclasses.replace(linear_system, supports=sup)
    A = state_matrix(assembled(light), 2 * np.pi * 50.0)
    lam, V = np.linalg.eig(A)
    k = int(np.argmax(np.where(lam.imag > 0, lam.real, -np.inf)))
    T = 2 * np.pi / lam[k].imag
    assert abs(abs(np.exp(lam[k] * T)) - 1) < 1e-7
    n = A.shape[0] // 2
    r_eq = np.asarray(rd.equilibrium(light, 50.0).r)
    v = V[:, k].real / np.max(np.abs(V[:n, k].real)) * 1e-7
    for tol in (1e-9, 1e-7):
        res = periodic_orbit(light, 50.0, start=np.concatenate([r_eq, np.zeros(n)]) + v,
                             period_s=T, rtol=1e-10, tol=tol, max_iter=5)
        assert res.status == "not_converged" and "not resolved" in res.message
        assert res.multipliers.size == 0 and not res.stable
    ub = [(3, 1e-3, 30.0)]
    ok = periodic_orbit(linear_system, 60.0, kind="forced", unbalances=ub, rtol=1e-9, tol=1e-8)
    assert ok.ok and 0 <= ok.stats["newton_correction"] < 1e-8


def test_period_from_transient_needs_an_oscillation(plain_system):
    tr = rd.transient(plain_system, 0.02, 50.0, n_out=41)
    with pytest.raises(rd.InputError, match="start"):
        period_from_transient(tr)


def test_trivial_multiplier_of_a_limit_cycle_is_one():
    """The paper rig at a_y = −1.85 mm, 50 Hz, p_c = 0.05 MPa with a full (uncavitated) film
    on a coarse grid (36 × 6, for speed):
    a smooth vector field, whose stable self-excited cycle (found from a transient's last
    part) has the trivial Floquet multiplier 1 (the flow direction: Φ f(x0) = f(x0)) to 1e-8
    with the sensitivities in the error test (the final pass) at rtol 1e-9 (measured 4.6e-9,
    5.7e-10 at rtol 1e-10).
    With cavitation (Swift–Stieber active set, or Gumbel's clip) the film force has kinks and
    the same check plateaus near 1e-7 (docs/nonlinear.md)."""
    rig = rd.models.paper_rig()
    b = rig.bearings[0]
    rig = dataclasses.replace(rig, bearings=(dataclasses.replace(
        b, cavitation="none", n_circ=36, n_axial=6),) + tuple(rig.bearings[1:]))
    tr = rd.transient(rig, 1.5, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5),
                      n_out=7501)
    assert tr.status == "ok"
    res = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=tr, rtol=1e-9, atol_m=1e-12,
                            tol=1e-8)
    assert res.status == "ok", res.message
    assert res.kind == "autonomous" and res.trivial_index >= 0
    assert abs(res.trivial_multiplier - 1) < 1e-8
    assert res.stable and res.critical_type == "neimark_sacker"
    assert 1 / res.period_s / 50.0 == pytest.approx(0.49, abs=0.02)  # half-frequency whirl
    df = res.to_frame()
    assert {"t_s", "journal_x_m", "journal_y_m", "period_s", "stable"} <= set(df.columns)
    assert len(res.multipliers_frame()) == 18
    assert "stable" in repr(res) and "neimark_sacker" in repr(res)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ax, axm = res.plot()
    assert len(axm.lines) >= 3  # unit circle, multipliers, trivial, critical
    plt.close("all")


def test_nonlinear_forced_orbit_equals_harmonic_balance():
    """A short rotor on two plain journal bearings with a full (uncavitated) film, 15 Hz, a
    large unbalance (orbit 15 µm = 0.15 c, second harmonic 5 % of the first: nonlinear):
    the forced orbit by shooting against an independent harmonic balance of the same
    equations (12 harmonics, 64 time points, film forces from the same core, Galerkin
    residual solved by MINPACK's hybrd), to 1e-6 of the amplitude (measured 2.7e-9; the
    smooth film makes the Fourier coefficients decay geometrically, 3e-14 at harmonic 12).
    The orbit is unstable (a multiplier outside the unit circle): shooting finds it anyway."""
    import scipy.optimize as so

    from test_harmonic_balance import smooth_rotor_system

    system = smooth_rotor_system()
    f, ub = 15.0, [(2, 8e-3, 0.0)]
    # From the equilibrium (the start this was measured from): from the linear start the
    # orbit is the same to 1e-9 of the amplitude and to 3e-10 in hybr's scaled residual, but
    # hybr's finite-difference exploration then closes a film (ContactError) or stalls —
    # hybr's fragility on this stiff system, not the orbit's (docs/nonlinear.md).
    res = periodic_orbit(system, f, kind="forced", unbalances=ub, rtol=1e-10, atol_m=1e-15,
                         tol=1e-9, forced_start="equilibrium")
    assert res.status == "ok", res.message
    assert not res.stable

    asm = assembled(system)
    m = asm.model
    M, K, C, G = (np.asarray(x) for x in (m.M, m.K, m.C, m.G))
    n, w = M.shape[0], 2 * np.pi * f
    L = asm.station_load_matrix(2)
    uc, us = 8e-3 * L[:, 0], 8e-3 * L[:, 1]
    F0 = np.asarray(m.Q) - K @ asm.config_vector(None)
    H, Nt = 12, 64
    k = np.arange(1, H + 1)
    tt = np.arange(Nt) / Nt / f
    Cm, Sm = np.cos(np.outer(w * tt, k)), np.sin(np.outer(w * tt, k))

    def unpack(z):
        z = z.reshape(2 * H + 1, n)
        return z[0], z[1:H + 1], z[H + 1:]

    def resid(z):
        c0, a, b = unpack(z)
        r = c0 + Cm @ a + Sm @ b
        v = -(Sm * (w * k)) @ a + (Cm * (w * k)) @ b
        acc = -(Cm * (w * k) ** 2) @ a - (Sm * (w * k) ** 2) @ b
        Hf = np.array([asm.solver.film_forces(r[i], v[i], w) for i in range(Nt)])
        R = acc @ M.T + v @ (C + w * G).T + r @ K.T - Hf - F0 \
            - w**2 * (np.outer(np.cos(w * tt), uc) + np.outer(np.sin(w * tt), us))
        return np.concatenate([R.mean(0), (2 * Cm.T @ R / Nt).ravel(),
                               (2 * Sm.T @ R / Nt).ravel()]) / np.abs(F0).max()

    rs, ts = res.r[:-1], res.t[:-1]
    C2, S2 = np.cos(np.outer(w * ts, k)), np.sin(np.outer(w * ts, k))
    z0 = np.concatenate([rs.mean(0), (2 * C2.T @ rs / len(ts)).ravel(),
                         (2 * S2.T @ rs / len(ts)).ravel()])
    sol = so.root(resid, z0, method="hybr", options={"xtol": 1e-13})
    assert sol.success and np.abs(sol.fun).max() < 1e-12
    c0, a, b = unpack(sol.x)
    r_hb = c0 + C2 @ a + S2 @ b
    amp = np.abs(rs - rs.mean(0)).max()
    assert np.hypot(a[1], b[1]).max() > 0.02 * np.hypot(a[0], b[0]).max()  # nonlinear
    assert np.abs(r_hb - rs).max() < 1e-6 * amp


def test_cli_periodic_orbit(capsys):
    """``rotordyn periodic-orbit``: a forced orbit of the linear compressor (JSON), and bad
    input (a forced orbit without unbalance) exits 2 naming the flag's field."""
    import json

    from rotordyn.cli import main

    model = str(MODELS / "compressor_linear.toml")
    assert main(["periodic-orbit", model, "--kind", "forced", "--speed-hz", "60",
                 "--unbalance", "3,1e-3,30", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "ok" and out["stable"] and out["period_s"] == pytest.approx(1 / 60)
    assert main(["periodic-orbit", model, "--kind", "forced"]) == 2
    assert "unbalances" in capsys.readouterr().err


def test_floquet_classification_of_known_matrices():
    """The critical multiplier's type from matrices with known eigenvalues."""
    from rotordyn import _core

    def rot(a, r):
        return r * np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])

    cases = [(np.diag([1.2, 0.5]), False, "fold", False),
             (np.diag([-1.1, 0.3]), False, "period_doubling", False),
             (np.block([[rot(0.7, 1.05), np.zeros((2, 1))], [np.zeros((1, 2)), 0.2]]), False,
              "neimark_sacker", False),
             (np.diag([1.0 + 1e-12, -0.9, 0.5]), True, "period_doubling", True)]
    for Phi, autonomous, kind, stable in cases:
        fl = _core.floquet(Phi, autonomous)
        assert fl.critical_type == kind and fl.stable == stable
        assert (fl.trivial >= 0) == autonomous
    with pytest.raises(rd.InputError, match="monodromy"):
        _core.floquet(np.zeros((2, 3)), False)


def test_flow_map_monodromy_equals_the_matrix_exponential(linear_system):
    """On a linear system Φ = exp(A T) exactly; flow_map (sensitivities in the error test,
    rtol 1e-10) to 1e-6 of max |exp(A T)| entrywise in the scaled coordinates (measured
    1.4e-7: the global error of 10 ms of stiff, damped modes)."""
    import scipy.linalg

    from rotordyn import _core

    asm = assembled(linear_system)
    n = asm.n
    w = 2 * np.pi * 40.0
    inp = _core.PeriodicInput()
    inp.kind = _core.OrbitKind.autonomous
    inp.omega = w
    inp.a = asm.config_vector(None)
    inp.r0, inp.v0 = np.full(n, 1e-6), np.zeros(n)
    inp.period = 0.01
    opt = _core.CvodeOptions()
    opt.rtol, opt.atol_position, opt.atol_velocity = 1e-10, 1e-14, 1e-14 * w
    _, Phi = _core.flow_map(asm.solver, inp, opt)
    E = scipy.linalg.expm(state_matrix(asm, w) * 0.01)
    D = np.concatenate([np.ones(n), np.full(n, w)])
    Ez, Pz = E * D[None, :] / D[:, None], np.asarray(Phi) * D[None, :] / D[:, None]
    assert np.abs(Pz - Ez).max() < 1e-6 * np.abs(Ez).max()


def test_subharmonic_and_transient_start_of_a_forced_orbit(plain_system):
    """Two consistency checks on the plain-bearing compressor: (1) with subharmonic=2 the
    same (stable, period-1) orbit is found over two revolutions, with the multipliers
    squared; (2) a forced orbit started from a transient's last sample (t0 = 12.25
    revolutions, so the rotor angle is a quarter turn on) is the same orbit shifted by a
    quarter period. Orbit amplitude 0.44 µm; agreement 3e-6 of the clearance."""
    f, ub = 50.0, [(3, 2e-4, 0.0)]
    one = periodic_orbit(plain_system, f, kind="forced", unbalances=ub, rtol=1e-8, tol=1e-6)
    two = periodic_orbit(plain_system, f, kind="forced", unbalances=ub, rtol=1e-8, tol=1e-6,
                         subharmonic=2, n_out=401)
    assert one.status == two.status == "ok"
    assert two.period_s == pytest.approx(2 * one.period_s, rel=1e-15)
    # each orbit is within about tol·L / (1 − |μ_c|) of the true one (residual tol 1e-6 of
    # the length scale L, the clearance; |μ_c| = 0.19): compared at 3 tol·L
    err = 3e-6 * one.length_scale_m
    assert np.abs(two.r[:201] - one.r).max() < err
    mu1, mu2 = one.multipliers[:4], two.multipliers[:4]
    assert np.abs(np.sort(np.abs(mu1) ** 2) - np.sort(np.abs(mu2))).max() < 1e-4
    tr = rd.transient(plain_system, 12.25 / f, f, unbalances=ub, n_out=491)
    late = periodic_orbit(plain_system, f, kind="forced", unbalances=ub, start=tr, rtol=1e-8,
                          tol=1e-6)
    assert late.status == "ok"
    assert late.t[0] == pytest.approx(12.25 / f)
    assert np.abs(late.r[0] - one.r[50]).max() < err


def test_same_inputs_same_orbit_whatever_ran_before(plain_system):
    """Each flow starts the films' cavitation sets afresh and the forced start is the
    equilibrium from the concentric start: a repeated call, after other analyses on the
    same system, gives the same orbit and multipliers bit for bit."""
    kw = dict(kind="forced", unbalances=[(3, 2e-4, 0.0)], rtol=1e-6, atol_m=1e-10, tol=1e-4)
    a = periodic_orbit(plain_system, 50.0, **kw)
    rd.stability(plain_system, 70.0)
    rd.transient(plain_system, 0.01, 30.0, n_out=11)
    b = periodic_orbit(plain_system, 50.0, **kw)
    assert a.status == b.status == "ok"
    assert np.array_equal(a.r, b.r) and np.array_equal(a.multipliers, b.multipliers)


def test_broyden_newton_finds_the_same_orbit_with_fewer_sensitivity_flows(plain_system):
    """Newton with Broyden's secant updates between flows without sensitivities
    (newton="broyden") against Newton with the monodromy from sensitivities in every
    iteration (the default), from the same
    start (the static equilibrium) on plain journal bearings with cavitation: the same orbit
    within the convergence tolerance, the same multipliers (both from the final pass with the
    sensitivities in the error test, at nearly the same start), and no more flows with
    sensitivities (here as many: the refresh rule — a step that does not halve the residual
    — fires on this start). An unknown ``newton`` is an InputError naming it."""
    f, ub = 50.0, [(3, 2e-4, 0.0)]
    # the start measured (from the linear unbalance response Broyden needs 5 flows with
    # sensitivities against Newton's 4: docs/nonlinear.md)
    kw = dict(kind="forced", unbalances=ub, rtol=1e-9, tol=1e-7, forced_start="equilibrium")
    a = periodic_orbit(plain_system, f, newton="broyden", **kw)
    b = periodic_orbit(plain_system, f, **kw)
    assert a.status == "ok" and b.status == "ok", (a.message, b.message)
    L = a.length_scale_m
    assert np.abs(a.r - b.r).max() < 10 * 1e-7 * L
    assert np.abs(a.multipliers - b.multipliers).max() < 1e-5
    assert a.stats["sensitivity_flows"] <= b.stats["sensitivity_flows"]
    assert b.stats["sensitivity_flows"] == b.stats["iterations"]
    with pytest.raises(rd.InputError, match="newton"):
        periodic_orbit(plain_system, f, newton="chord", **kw)
