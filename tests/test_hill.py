"""Floquet multipliers by Hill's method (cpp/src/hill.cpp; ``floquet="hill"`` of
``rd.periodic_orbit(method="harmonic_balance")`` and of the harmonic-balance continuation;
docs/nonlinear.md "Floquet multipliers by Hill's method").

References:
* a closed form: a constant-coefficient 2-DOF system written in a frame rotating at Ω, seen
  from the fixed frame (r = R(Ωt) q), has damping and stiffness periodic with period π/Ω; as
  R(π) = −I its multipliers over that period are exactly −e^{λ_q T} (λ_q the roots of the
  rotating frame's m λ² + c_i λ + k_i);
* the shooting (CVODES sensitivities, tests/test_periodic.py) of the same orbit at tight
  tolerances: an independent method on the same C++ right-hand side;
* the trivial multiplier of an autonomous cycle, exactly 1 (the flow direction);
* a parametrically excited 2-DOF system (no closed form): its monodromy integrated by
  scipy's DOP853 at rtol 1e-13, and the observed convergence in H.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

from scipy.integrate import solve_ivp

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.periodic import periodic_orbit
from rotordyn.errors import InputError

from test_harmonic_balance import smooth_rotor_system
import coarse_models  # noqa: E402

HB = "harmonic_balance"
MODELS = Path(__file__).parent / "data" / "models"
CENTROID, IMAGINARY = _core.HillSelection.centroid, _core.HillSelection.imaginary


def rotating_frame_system(spin, c, k, m=1.0, samples=32):
    """M, G(τ_j), D(τ_j) of m q'' + diag(c) q' + diag(k) q = 0 in a frame rotating at `spin`
    rad/s, in fixed coordinates r = R(θ) q, θ = spin·t = τ/2 (τ = ω t, ω = 2·spin):
    m (r'' − 2ΩJ r' − Ω² r) + R C Rᵀ (r' − ΩJ r) + R K Rᵀ r = 0."""
    Jm = np.array([[0.0, -1.0], [1.0, 0.0]])
    G, D = [], []
    for j in range(samples):
        th = np.pi * j / samples
        R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
        Cr, Kr = R @ np.diag(c) @ R.T, R @ np.diag(k) @ R.T
        D.append(-2 * m * spin * Jm + Cr)
        G.append(-m * spin**2 * np.eye(2) - spin * Cr @ Jm + Kr)
    return m * np.eye(2), G, D


def rotating_frame_multipliers(spin, c, k, m=1.0):
    """The exact multipliers over T = π/spin: −e^{λ_q T}."""
    lam = np.concatenate([np.roots([m, ci, ki]) for ci, ki in zip(c, k)]).astype(complex)
    return -np.exp(lam * np.pi / spin)


def test_closed_form_of_a_rotating_anisotropic_system():
    """Hill's multipliers of the rotating-frame system equal −e^{λ_q T} to 1e-12 for H = 2
    and 8 (measured ≤ 1e-14: the coefficients have one harmonic, the truncation is exact to
    round-off), and so do the eigenvalues of the monodromy rebuilt from the Hill eigenvectors.
    The overdamped coordinate gives two real negative multipliers (each a family λ ± iω/2
    whose two central copies are conjugates of each other): they count once and are
    reported real."""
    spin, c, k = 1.3, (0.2, 5.0), (4.0, 4.0)
    exact = np.sort_complex(rotating_frame_multipliers(spin, c, k))
    mass, G, D = rotating_frame_system(spin, c, k)
    for h in (2, 8):
        r = _core.hill_floquet(mass, G, D, 2 * spin, h)
        mu = np.asarray(r.multipliers)
        assert mu.shape == (4,)
        assert np.abs(np.sort_complex(mu) - exact).max() < 1e-12
        assert np.abs(np.sort_complex(np.linalg.eigvals(r.monodromy)) - exact).max() < 1e-12
        neg = mu[np.abs(mu.imag) < 1e-3]
        assert len(neg) == 2 and np.all(neg.imag == 0) and np.all(neg.real < 0)
        assert len(r.eigenvalues) == 4 * (2 * h + 1)


def test_selection_rule_keeps_the_central_copy():
    """A family whose frequency (12 ω) lies beyond H ω (H = 4): its copies in the fundamental
    strip |Im λ| ≤ ω/2 are not resolved by the truncation. The centroid rule (eigenvectors on
    the central harmonics, |κ| ≤ 0.75) keeps the accurate copies: multipliers to 1e-10
    (measured 6e-14); the imaginary-part rule takes truncation artefacts at the edge of the
    Hill matrix (|κ| = H) and is off by more than 0.5 (measured 1.07): the rule matters and
    the test can fail. One exponent per family: no two kept exponents are copies."""
    spin = 1.3
    c, k = (0.2, 0.5), (4.0, (24 * spin) ** 2)
    exact = np.sort_complex(rotating_frame_multipliers(spin, c, k))
    mass, G, D = rotating_frame_system(spin, c, k)
    w = 2 * spin
    good = _core.hill_floquet(mass, G, D, w, 4, CENTROID)
    bad = _core.hill_floquet(mass, G, D, w, 4, IMAGINARY)
    assert np.abs(np.sort_complex(np.asarray(good.multipliers)) - exact).max() < 1e-10
    assert np.abs(np.sort_complex(np.asarray(bad.multipliers)) - exact).max() > 0.5
    assert np.all(np.abs(np.asarray(good.centroids)) <= 0.75)
    assert np.abs(np.asarray(bad.centroids)).max() >= 3.5
    lam, kap = np.asarray(good.exponents), np.asarray(good.centroids)
    for i in range(4):
        for j in range(i + 1, 4):
            m = np.round((lam[i] - lam[j]).imag / w)
            copy = m != 0 and abs(lam[i] - lam[j] - 1j * m * w) < 0.01 * w \
                and abs(kap[i] - kap[j] + m) < 0.25
            assert not copy


def parametric_system(samples):
    """M, G(τ_j), D of x'' + C x' + (K0 + K1 cos τ + K2 sin 2τ) x = 0 (2 DOF, ω = 2 rad/s:
    near the first parametric resonance of its 1.7–2.3 rad/s modes, unstable)."""
    K0 = np.array([[3.0, -0.5], [-0.5, 5.0]])
    K1 = np.array([[1.2, 0.3], [0.3, -0.8]])
    K2 = np.array([[0.0, 0.4], [0.4, 0.6]])
    C = np.diag([0.05, 0.1])
    tau = 2 * np.pi * np.arange(samples) / samples
    return np.eye(2), [K0 + K1 * np.cos(t) + K2 * np.sin(2 * t) for t in tau], [C] * samples, \
        (K0, K1, K2, C)


def test_convergence_with_harmonics_on_a_parametric_system():
    """Hill's multipliers of a parametrically excited 2-DOF system against its monodromy
    integrated by DOP853 (rtol 1e-13): the error falls by more than 10× per added harmonic
    from H = 1 to 4 and is below 1e-11 from H = 6 (measured 0.21, 1.6e-3, 1.8e-6, 8.8e-8,
    then 8.4e-13 at H = 6 and 1.9e-14 at H = 8: faster than geometric, the coefficients
    have two harmonics)."""
    w = 2.0
    *_, (K0, K1, K2, C) = parametric_system(1)

    def rhs(t, y):
        Y = y.reshape(4, 4)
        K = K0 + K1 * np.cos(w * t) + K2 * np.sin(2 * w * t)
        return np.vstack([Y[2:], -C @ Y[2:] - K @ Y[:2]]).ravel()

    sol = solve_ivp(rhs, (0.0, 2 * np.pi / w), np.eye(4).ravel(), method="DOP853",
                    rtol=1e-13, atol=1e-14)
    ref = np.linalg.eigvals(sol.y[:, -1].reshape(4, 4))
    assert np.abs(ref).max() > 1.04  # the parametric resonance: an unstable pair

    def err(h):
        mass, G, D, _ = parametric_system(max(4 * h, 8))
        mu = np.asarray(_core.hill_floquet(mass, G, D, w, h).multipliers)
        return max(np.abs(mu - m).min() for m in ref)

    e = [err(h) for h in (1, 2, 3, 4)]
    assert all(b < 0.1 * a for a, b in zip(e, e[1:])), e
    assert err(6) < 1e-11 and err(8) < 1e-11


def test_hill_equals_shooting_on_a_smooth_forced_orbit():
    """The smooth rotor's unbalance-forced orbit (15 Hz, unstable, |μ_c| = 1.025): Hill's
    multipliers from the harmonic-balance Jacobian against shooting at rtol 1e-10. The error
    falls by more than 10× per harmonic from H = 2 to 4 (measured 4.9e-6, 1.3e-7, 3.8e-9) and
    is within 1e-8 at H = 8 (measured 4.3e-10 — the shooting's own accuracy — where the
    samples' Magnus monodromy is off by 2.5e-4, test > 1e-5); the same instability. At H = 4
    the monodromy rebuilt from the Floquet solutions has the multipliers as eigenvalues (at
    H ≥ 8 it is left empty: two kept exponents of the films' stiff, unresolved families give
    near-dependent solutions, rcond 4e-16 measured)."""
    s = smooth_rotor_system()
    f, ub = 15.0, [(2, 8e-3, 0.0)]
    sh = periodic_orbit(s, f, kind="forced", unbalances=ub, rtol=1e-10, atol_m=1e-15, tol=1e-9)
    assert sh.ok, sh.message
    ref = np.sort_complex(sh.multipliers)

    def hb(h, floquet="hill", **extra):
        o = periodic_orbit(s, f, kind="forced", unbalances=ub, method=HB, harmonics=h,
                           tol=1e-12, floquet=floquet, **extra)
        assert o.ok, o.message
        return o, np.abs(np.sort_complex(o.multipliers) - ref).max()

    runs = [hb(h) for h in (2, 3, 4)]
    e = [r[1] for r in runs]
    assert all(b < 0.1 * a for a, b in zip(e, e[1:])), e
    o4 = runs[-1][0]  # the monodromy the exponents and eigenvectors give has them
    assert o4.monodromy.shape == (8, 8)
    mu4 = np.sort_complex(o4.multipliers)
    assert np.abs(np.sort_complex(np.linalg.eigvals(o4.monodromy)) - mu4).max() < 1e-9
    o, e8 = hb(8)
    assert e8 < 1e-8
    assert hb(8, "samples", floquet_tol=0)[1] > 1e-5  # the interpolated product
    assert not o.stable and not sh.stable
    assert o.critical_type == sh.critical_type == "neimark_sacker"
    assert o.stats["monodromy_rtol"] == 0.0


def test_trivial_multiplier_of_an_autonomous_cycle():
    """The rig's self-excited cycle on a smooth (uncavitated) film (36 × 6, 50 Hz, 0.05 MPa)
    by harmonic balance with H = 12: Hill's trivial multiplier is 1 to 1e-6 with M = 8H
    samples (measured 9.5e-8) — exactly 1 where the discrete residual is shift-equivariant,
    so its error is the AFT's aliasing: 6.4e-4 with M = 4H (measured; test > 1e-5) — and the
    critical multiplier is the shooting's within 1e-4 (measured 2.3e-5)."""
    rig = rd.models.paper_rig()
    b = rig.bearings[0]
    rig = dataclasses.replace(rig, bearings=(dataclasses.replace(
        b, cavitation="none", n_circ=36, n_axial=6),) + tuple(rig.bearings[1:]))
    tr = rd.transient(rig, 1.5, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=6001)
    kw = dict(start=tr, method=HB, harmonics=12, tol=1e-10, floquet="hill")
    fine = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, time_points=96, **kw)
    coarse = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, time_points=48, **kw)
    assert fine.ok and coarse.ok, (fine.message, coarse.message)
    assert abs(fine.trivial_multiplier - 1) < 1e-6
    assert abs(coarse.trivial_multiplier - 1) > 1e-5
    sh = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=(fine.r[0], fine.v[0]),
                           period_s=fine.period_s, rtol=1e-9, atol_m=1e-12, tol=1e-8)
    assert sh.ok, sh.message
    assert abs(abs(fine.critical_multiplier) - abs(sh.critical_multiplier)) < 1e-4
    assert fine.stable and sh.stable


@pytest.mark.parametrize("change, field", [
    (dict(harmonics=0), "harmonics"),
    (dict(harmonics=201), "harmonics"),
    (dict(omega=0.0), "omega"),
    (dict(omega=np.nan), "omega"),
    (dict(mass=np.zeros((2, 2))), "mass"),
    (dict(mass=np.eye(3)), "stiffness"),
    (dict(stiffness_samples=8), "stiffness, damping"),
    (dict(damping_bad=np.ones((3, 3))), "damping"),
    (dict(stiffness_nan=True), "stiffness"),
])
def test_bad_input_names_the_field(change, field):
    """Too few samples (< 2H + 1) or unequal counts, wrong shapes, non-finite values, a
    singular mass, ω ≤ 0, H outside [1, 200]: InputError naming the field."""
    mass, G, D = rotating_frame_system(1.3, (0.2, 5.0), (4.0, 4.0), samples=16)
    h, w = 4, 2.6
    h = change.get("harmonics", h)
    w = change.get("omega", w)
    mass = change.get("mass", mass)
    if "stiffness_samples" in change:
        G = G[:change["stiffness_samples"]]
    if "damping_bad" in change:
        D = D[:-1] + [change["damping_bad"]]
    if "stiffness_nan" in change:
        G = G[:-1] + [np.full((2, 2), np.nan)]
    with pytest.raises(InputError, match=field):
        _core.hill_floquet(mass, G, D, w, h)


def test_periodic_orbit_floquet_route_is_checked():
    """``floquet`` of rd.periodic_orbit accepts "hill" and names the field with the allowed
    values otherwise."""
    s = smooth_rotor_system()
    with pytest.raises(InputError, match="floquet.*hill"):
        periodic_orbit(s, 15.0, method=HB, start=(np.zeros(4), np.zeros(4)), period_s=0.01,
                       floquet="magnus")


def test_whip_cycle_of_the_compressor_by_hill():
    """An autonomous cycle on a cavitated film that is not the paper rig: the compressor's
    0.9 c oil-whip cycle at 130 Hz (plain bearings, 36 × 6) by harmonic balance (H = 8) from
    a 0.4 s transient. Hill's multipliers against one CVODES sensitivity flow from the same
    HB orbit (sensitivity_rtol 1e-6): |μ_c| within 1e-2 (measured 3.7e-3), the trivial
    multiplier 1 within 1e-2 (measured 2.9e-3: the kinks of the cavitated film, against
    9.5e-8 on a smooth one above), the same stability; the samples' Magnus monodromy of the
    same orbit interpolated from the M samples (``floquet_tol=0``) has a trivial error above
    10 × Hill's (measured 0.117: why the branch's samples route sends most whip points to the
    flow, docs/nonlinear.md) and |μ_c| off by 5.8e-2, more than 2 × the refined product's
    estimate (the default: 0.8182 ± 1.3e-2, converged at 1024 steps, its trivial error the
    larger part), which agrees with the flow (0.8274) within that estimate."""
    s = coarse_models.compressor_plain()
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    kw = dict(start=tr, method=HB, harmonics=8, tol=1e-8)
    hill = rd.periodic_orbit(s, 130.0, floquet="hill", **kw)
    assert hill.ok, hill.message
    start = dict(start=(hill.r[0], hill.v[0]), period_s=hill.period_s)
    kw.update(start)
    flow = rd.periodic_orbit(s, 130.0, floquet="flow", rtol=1e-6, sensitivity_rtol=1e-6, **kw)
    samples = rd.periodic_orbit(s, 130.0, floquet="samples", floquet_tol=0, **kw)
    refined = rd.periodic_orbit(s, 130.0, floquet="samples", **kw)
    assert flow.ok and samples.ok and refined.ok, (flow.message, samples.message,
                                                   refined.message)
    # the refined samples (the default): |μ_c| within their own estimate (+ 1e-4 for the
    # flow) of the flow's, where the interpolated product is off by more than 2 × that
    ref = abs(flow.critical_multiplier)
    err = refined.stats["floquet_error"] + 1e-4
    assert abs(abs(refined.critical_multiplier) - ref) <= err
    assert abs(abs(samples.critical_multiplier) - ref) > 2 * err
    assert refined.stability_resolved and refined.stable
    assert abs(abs(hill.critical_multiplier) - abs(flow.critical_multiplier)) < 1e-2
    et = abs(hill.trivial_multiplier - 1)
    assert et < 1e-2
    assert abs(samples.trivial_multiplier - 1) > 10 * et
    assert hill.stable and flow.stable


def test_hb_branch_with_hill_multipliers_equals_shooting():
    """rd.continuation(method="harmonic_balance", floquet="hill") on the smooth rotor's
    forced orbit (15 Hz up, H = 8, 3 points, as tests/test_hb_continuation.py with H = 12):
    every point's multipliers by Hill's method (route "hill": |μ_c| ≈ 1.025 is outside the
    recheck band, margin 0.01 + 3 × 0 for a forced orbit), each within 1e-7 of the shooting
    at that point's speed (rtol 1e-10, from the point's state; measured ≤ 4.9e-10), its
    floquet_hill_modulus the reported |μ_c|, no flow recheck."""
    s = smooth_rotor_system()
    ub = [(2, 8e-3, 0.0)]
    o = rd.periodic_orbit(s, 15.0, kind="forced", unbalances=ub, method=HB, harmonics=8,
                          tol=1e-12)
    assert o.ok, o.message
    br = rd.continuation(s, "speed_hz", (10.0, 20.0), o, unbalances=ub, method=HB,
                         harmonics=8, tol=1e-11, ds=0.05, ds_max=0.05, max_points=3,
                         floquet="hill")
    assert br.ok and len(br) == 3, br.message
    assert br.stats["flow_rechecks"] == 0
    for p in br.orbits:
        assert p.stats["floquet"] == "hill"
        assert p.stats["floquet_hill_modulus"] == pytest.approx(abs(p.critical_multiplier),
                                                                rel=1e-14)
        sh = rd.periodic_orbit(s, p.speed_hz, kind="forced", unbalances=ub,
                               start=(p.r[0], p.v[0]), rtol=1e-10, atol_m=1e-15, tol=1e-9)
        assert sh.ok, sh.message
        d = np.abs(np.sort_complex(p.multipliers) - np.sort_complex(sh.multipliers)).max()
        assert d < 1e-7, d
        assert not p.stable and not sh.stable


def test_core_checks_hill_time_points():
    """The C++ option hill_time_points (samples of the Jacobian of the Hill matrix: 0 for
    max(M, 8H), else ≥ 2H + 1) is checked with an InputError naming it."""
    from rotordyn.analysis.assembly import assembled

    asm = assembled(smooth_rotor_system())
    inp = _core.PeriodicInput()
    inp.kind = _core.OrbitKind.autonomous
    inp.omega = 2 * np.pi * 15
    inp.a = np.zeros(asm.n)
    inp.r0, inp.v0 = np.zeros(asm.n), np.zeros(asm.n)
    inp.period = 0.01
    o = _core.HarmonicBalanceOptions()
    o.harmonics, o.floquet, o.hill_time_points = 4, _core.HbFloquet.hill, 8
    with pytest.raises(InputError, match="hill_time_points"):
        _core.harmonic_balance(asm.solver, inp, np.zeros((0, asm.n)), o)


def test_cli_branch_by_hill_on_a_linear_rotor_is_the_closed_form(capsys):
    """``rotordyn continuation --method harmonic_balance --floquet hill`` on the compressor on
    linear supports (forced, 60 Hz up, H = 2): a constant-coefficient system, whose Floquet
    multipliers over T = 1/f are exactly e^{λ_i T} (λ_i its eigenvalues, rd.modes at that
    speed): every point's |μ_c| within 1e-9 relative of max e^{Re λ_i T} (measured 5.6e-14),
    every point by the "hill" route (the JSON names it)."""
    from rotordyn.cli import main

    model = str(MODELS / "compressor_linear.toml")
    assert main(["continuation", model, "--kind", "forced", "--speed-hz", "60", "--unbalance",
                 "3,1e-3,30", "--vary", "speed_hz", "--bounds", "55", "80", "--max-points",
                 "3", "--tol", "1e-10", "--method", HB, "--harmonics", "2", "--floquet",
                 "hill", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "ok" and out["floquet_route"] == ["hill"] * 3
    s = rd.System.from_toml(model)
    for f, mu in zip(out["parameter"], out["max_multiplier"]):
        lam = np.asarray(rd.modes(s, f).eigenvalues)
        assert mu == pytest.approx(np.exp(lam.real.max() / f), rel=1e-9)
