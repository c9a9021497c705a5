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
    asm = assembled(linear_system)
    m = asm.model
    w = 2 * np.pi * f
    M, K, C, G = (np.asarray(x) for x in (m.M, m.K, m.C, m.G))
    n = M.shape[0]
    uc, us = np.zeros(n), np.zeros(n)
    for st, me, ph in ub:
        L = asm.station_load_matrix(st)
        p = np.radians(ph)
        uc += me * (L[:, 0] * np.cos(p) + L[:, 1] * np.sin(p))
        us += me * (-L[:, 0] * np.sin(p) + L[:, 1] * np.cos(p))
    a = asm.config_vector(None)
    rs = np.linalg.solve(K, np.asarray(m.Q) - K @ a)
    X = np.linalg.solve(K - w**2 * M + 1j * w * (C + w * G), w**2 * (uc - 1j * us))
    r_exact = rs[None, :] + np.real(X[None, :] * np.exp(1j * w * res.t[:, None]))
    amp = np.abs(X).max()
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
