"""The fast corrector route of the continuation (``newton="fast"``, issue 19's 50-point branch;
docs/nonlinear.md, "The 50-point branch"): Broyden correctors from the previous point's
matrix, ∂R/∂p from a CVODES parameter-sensitivity column instead of two flows at p ± h, and
each point's final pass screened at a looser sensitivity tolerance (repeated at the full one
where the stability verdict is not safe there).

Reference: the default route (``newton="sensitivities"``: Newton with the monodromy and the
central-difference ∂R/∂p at every iteration, every final pass at the full tolerance) on the
same model, start and constant step — an independent computation of the same branch. Both
correctors stop below ``tol`` = 1e-4 in the scaled residual, so a point may move by about
tol/(1 − |μ_c|) of the length scale (|μ_c| ≤ 0.998 on this branch) and its successors follow
it along the branch: the tolerances below are that bound, not the round-off."""


import numpy as np
import pytest

import rotordyn as rd
import coarse_models  # noqa: E402

TOL = 1e-4


@pytest.fixture(scope="module")
def rig_cycle():
    """The paper rig (36 × 6 film grid for speed) and its stable cycle at a_y = −1.85 mm,
    50 Hz, 0.05 MPa from a 0.6 s transient (as tests/test_continuation.py)."""
    rig = coarse_models.paper_rig()
    tr = rd.transient(rig, 0.6, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=6001)
    cyc = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=tr, rtol=1e-6, tol=TOL)
    assert cyc.ok, cyc.message
    return rig, cyc


def _branch(rig, cyc, vary, bounds, newton, **kw):
    return rd.continuation(rig, vary, bounds, cyc, rtol=1e-6, tol=TOL, ds=0.1, ds_max=0.1,
                           max_points=12, newton=newton, **kw)


def _same_branch(ref, fast, *, dp, damp_c):
    assert fast.ok and ref.ok
    assert len(fast) == len(ref) and fast.stop == ref.stop
    np.testing.assert_array_equal(fast.stable, ref.stable)
    # the type where |μ_c| < 0.99: nearer 1 the radial multiplier and the trivial one form a
    # near-double eigenvalue that the eigen-solver may return as a pair 1 ± 0.002j (the
    # default route calls it neimark_sacker at 0.99965 − 0.0023j, Broyden and fast fold)
    far = ref.max_multiplier < 0.99
    assert np.array(fast.critical_type)[far].tolist() == np.array(ref.critical_type)[far].tolist()
    assert np.max(np.abs(fast.parameter - ref.parameter)) < dp
    amp = np.abs(fast.amplitude_m[:, 0] - ref.amplitude_m[:, 0]) / ref.clearance_m[0]
    assert np.max(amp) < damp_c
    np.testing.assert_allclose(fast.period_s, ref.period_s, rtol=1e-4)
    np.testing.assert_allclose(fast.max_multiplier, ref.max_multiplier, atol=5e-3)
    assert [b["kind"] for b in fast.bifurcations] == [b["kind"] for b in ref.bifurcations]


def test_fast_route_gives_the_default_branch_to_the_hopf_point(rig_cycle):
    """p_c from 0.05 MPa up to the Hopf end (ds = 0.1 constant: 8 points, then the turn):
    the fast route's points equal the default's — p_c within 100 Pa (0.17 %), amplitude
    within 1e-3 c, period 1e-4 relative, |μ_c| within 5e-3 (measured: 73 Pa, 4.7e-4 c,
    2.9e-3 at the 19 µm point, where |μ_c| = 0.997 makes a point uncertain by up to
    tol/(1 − |μ_c|) ≈ 0.03 L along the branch and the branch rises by ~350 Pa per 20 µm;
    |μ_c| differs by that shift times dμ/dp ≈ 6e-5 per Pa; elsewhere ≤ 25 Pa) —, the same
    stability flags, the same critical types where |μ_c| < 0.99, the same bifurcation list
    (the Hopf end) with p_H within 50 Pa (measured 27 Pa). Fewer flows with sensitivities
    and no finite-difference flows (∂R/∂p from the parameter column). Every point whose
    critical multiplier lies within the screening margin of the unit circle (or whose trivial
    multiplier is off by more than a tenth of it) carries the full tolerance
    (``stats["monodromy_rtol"]`` = rtol): the verdicts near 1 are error-controlled at
    the full tolerance, and the others say they are not."""
    rig, cyc = rig_cycle
    bounds = (0.04e6, 0.08e6)
    ref = _branch(rig, cyc, "chamber_pressure_pa", bounds, "sensitivities")
    fast = _branch(rig, cyc, "chamber_pressure_pa", bounds, "fast")
    assert ref.stop == "hopf" and len(ref) >= 6, (ref.stop, len(ref))
    _same_branch(ref, fast, dp=100.0, damp_c=1e-3)
    assert fast.bifurcations[-1]["parameter"] == pytest.approx(
        ref.bifurcations[-1]["parameter"], abs=50.0)
    assert fast.stats["fd_flows"] == 0 < ref.stats["fd_flows"]
    assert fast.stats["sensitivity_flows"] < ref.stats["sensitivity_flows"]
    for o in fast.orbits:
        near = (abs(abs(o.critical_multiplier) - 1) < 5e-3
                or abs(o.trivial_multiplier - 1) > 5e-3)
        assert o.stats["monodromy_rtol"] == (1e-6 if near else 1e-4)
    assert any(o.stats["monodromy_rtol"] == 1e-4 for o in fast.orbits)  # screening used
    assert all(o.stats["monodromy_rtol"] == 1e-6 for o in ref.orbits)


def test_fast_route_over_ay_uses_the_spring_force_derivative(rig_cycle):
    """vary="config_ay_m": ∂f/∂a_y (−M⁻¹K times the configuration direction) in the
    parameter column; 4 points upwards from −1.85 mm equal the default route's (a_y within
    1e-7 m, amplitude 1e-3 c, same flags)."""
    rig, cyc = rig_cycle
    kw = {"max_points": 4}
    ref = rd.continuation(rig, "config_ay_m", (-3e-3, 0.0), cyc, rtol=1e-6, tol=TOL, ds=0.05,
                          ds_max=0.05, newton="sensitivities", **kw)
    fast = rd.continuation(rig, "config_ay_m", (-3e-3, 0.0), cyc, rtol=1e-6, tol=TOL, ds=0.05,
                           ds_max=0.05, newton="fast", **kw)
    _same_branch(ref, fast, dp=1e-7, damp_c=1e-3)
    assert np.all(np.diff(fast.parameter) > 0)
    assert fast.stats["fd_flows"] == 0


@pytest.fixture(scope="module")
def whip_branches():
    """A model that is not the rig: the compressor on plain bearings (36 × 6 film grid), its
    oil-whip cycle at 130 Hz from a 0.4 s transient (equilibrium disturbed by 0.6 c),
    continued down in speed (tests/test_continuation.py, docs/nonlinear.md "A fold") with a
    constant step ds = ds_max = 0.1 — the same predictor sequence for both routes, so the
    points correspond one to one — for 6 points: four stable cycles, the fold near
    121.7 Hz, two unstable ones. The speed has no parameter sensitivity: ``fast`` keeps the
    central-difference ∂R/∂p (Broyden and the screening remain)."""
    from pathlib import Path

    s = coarse_models.compressor_plain()
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, rtol=1e-6, tol=TOL)
    assert cyc.ok and cyc.stable, cyc.message
    kw = dict(rtol=1e-6, tol=TOL, ds=0.1, ds_max=0.1, max_points=6, direction=-1)
    ref = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, newton="exact", **kw)
    fast = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, newton="fast", **kw)
    return ref, fast


def test_fast_route_gives_the_exact_whip_branch_through_its_fold(whip_branches):
    """The compressor's whip branch by ``fast`` against ``exact`` (the reference: Newton with
    the monodromy and ∂R/∂p at every iteration, every monodromy at 1e-6): the same 6 points —
    speed within 0.02 Hz, amplitude 1e-3 c, period 2e-4 relative, |μ_c| 5e-3 (measured on the
    24-point branch of bench_branch_fast.py --model compressor: 0.009 Hz, 2.4e-4 c, 9.2e-5,
    1.9e-3 at the point just past the fold, |μ_c| = 1.0035; the bound tol/(1 − |μ_c|) on a
    point's shift is largest there) —, the same stability flags (stable before the fold,
    unstable after), the same critical types where ||μ_c| − 1| > 0.01, the same bifurcations
    (one fold) with the fold within 0.02 Hz (measured 0.004 Hz); both folds at the branch's
    turn (dp/ds through 0 and |μ_c| through 1 between the same two points). No flow is saved on
    ∂R/∂p (the speed's FD flows remain) but fewer flows carry sensitivities; the points with
    |μ_c| within the screening margin of 1 have the full tolerance."""
    ref, fast = whip_branches
    assert ref.ok and fast.ok and len(ref) == len(fast) == 6 and ref.stop == fast.stop
    np.testing.assert_array_equal(fast.stable, ref.stable)
    assert ref.stable[:4].all() and not ref.stable[4:].any()
    far = np.abs(ref.max_multiplier - 1) > 0.01
    assert np.array(fast.critical_type)[far].tolist() == np.array(ref.critical_type)[far].tolist()
    assert np.max(np.abs(fast.parameter - ref.parameter)) < 0.02
    c = ref.clearance_m[0]
    assert np.max(np.abs(fast.amplitude_m[:, 0] - ref.amplitude_m[:, 0])) / c < 1e-3
    np.testing.assert_allclose(fast.period_s, ref.period_s, rtol=2e-4)
    np.testing.assert_allclose(fast.max_multiplier, ref.max_multiplier, atol=5e-3)
    kinds = [b["kind"] for b in ref.bifurcations]
    assert kinds == [b["kind"] for b in fast.bifurcations] == ["fold"]
    assert fast.bifurcations[0]["parameter"] == pytest.approx(ref.bifurcations[0]["parameter"],
                                                              abs=0.02)
    for br in (ref, fast):
        k = br.bifurcations[0]["index"]
        assert br.tangent_p[k - 1] < 0 < br.tangent_p[k]
        assert br.max_multiplier[k - 1] < 1 < br.max_multiplier[k]
    assert fast.stats["sensitivity_flows"] < ref.stats["sensitivity_flows"]
    for o in fast.orbits:
        if abs(abs(o.critical_multiplier) - 1) < 5e-3:
            assert o.stats["monodromy_rtol"] == 1e-6


@pytest.mark.parametrize("kw, field", [({"screen_rtol": 0.5}, "screen_rtol"),
                                       ({"screen_margin": -1.0}, "screen_margin"),
                                       ({"newton": "secant"}, "newton")])
def test_fast_route_bad_input_names_the_field(rig_cycle, kw, field):
    rig, cyc = rig_cycle
    args = {"newton": "fast", **kw}
    with pytest.raises(rd.errors.InputError, match=field):
        rd.continuation(rig, "chamber_pressure_pa", (0.04e6, 0.08e6), cyc, **args)


@pytest.mark.parametrize("route", [{"newton": "fast", "floquet": "samples"},
                                   {"newton": "exact"}, {"newton": "broyden"},
                                   {"method": "harmonic_balance"}])
@pytest.mark.parametrize("field", ["screen_rtol", "screen_margin"])
def test_screen_options_are_refused_where_nothing_is_screened(rig_cycle, route, field):
    """screen_rtol/screen_margin tune only the fast flow route's screened final pass: given
    with the samples route, another Newton or harmonic balance they did nothing, silently."""
    rig, cyc = rig_cycle
    with pytest.raises(rd.errors.InputError, match=f"{field}: applies only to "
                                                   "method='shooting' with newton='fast'"):
        rd.continuation(rig, "chamber_pressure_pa", (0.04e6, 0.08e6), cyc, **route,
                        **{field: 1e-3})
