"""Cheap Floquet multipliers on a shooting branch (``rd.continuation(method="shooting",
floquet="samples")``, docs/nonlinear.md "Cheap multipliers on a shooting branch"): each point's
multipliers from the films' linearisations at the converged orbit's samples, the
error-controlled sensitivity flow only where the verdict is within ``floquet_margin`` of the
unit circle (the screen of the harmonic-balance corrector).

References:
* the flow route (``floquet="flow"``, CVODES forward sensitivities in the error test) on the
  same branch: the compressor's oil-whip cycles on plain bearings past their fold
  (tests/test_continuation.py, ``whip_branch``), the model off the paper rig;
* closed form: a rotor on linear supports (tests/data/models/compressor_linear.toml) is
  time-invariant, so the multipliers of any orbit are exp(λT), λ its eigenvalues
  (``rd.stability``), T the forcing period.
"""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd

import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"
UB = [(3, 1e-3, 30.0)]
WHIP = dict(rtol=1e-6, tol=1e-4, ds=0.1, ds_max=0.3, max_points=7, direction=-1)


@pytest.fixture(scope="module")
def whip_pair():
    """The 7-point whip branch (130 Hz down past the fold) by both routes."""
    s = coarse_models.compressor_plain()
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, rtol=1e-6, tol=1e-4)
    assert cyc.ok and cyc.stable, cyc.message
    flow = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, **WHIP)
    samples = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, floquet="samples", **WHIP)
    return s, flow, samples, cyc


def test_samples_route_gives_the_flows_multipliers_and_fold(whip_pair):
    """At every point of the samples branch the flow's multipliers of the same orbit
    (``rd.periodic_orbit``, floquet="flow", from the point's state: CVODES sensitivities in
    the error test) equal the reported ones: |μ_c| within 5e-3, half the screen's margin
    (measured ≤ 2.8e-3 where the samples' product is kept; the samples' monodromy from 100
    film linearisations, 4th-order Magnus; the point at 121.67 Hz, |μ_c| 1.149 from the
    samples against the flow's 1.007, is caught by its trivial error 0.046 and rechecked),
    the same verdict and type. Both branches
    have the same bifurcations: one fold, 4 stable points before it and unstable ones after;
    its estimates agree within 0.2 Hz (0.16 % of the speed: the points differ — the samples
    route's tangent comes from the Newton flow's sensitivities outside the error test —
    and the fold is interpolated between them), each within 0.1 Hz of its branch's lowest
    speed."""
    s, flow, samples, _ = whip_pair
    assert flow.ok and samples.ok, (flow.message, samples.message)
    assert len(samples) == len(flow) == 7
    assert samples.parameter[0] == flow.parameter[0]
    for o, f in zip(samples.orbits, samples.parameter):
        ref = rd.periodic_orbit(s, float(f), start=(o.r[0], o.v[0]), period_s=o.period_s,
                                rtol=1e-6, tol=1e-4)
        assert ref.ok, ref.message
        assert abs(abs(o.critical_multiplier) - abs(ref.critical_multiplier)) < 5e-3, \
            (f, o.stats["floquet"], o.critical_multiplier, ref.critical_multiplier)
        assert o.stable == ref.stable and o.critical_type == ref.critical_type
    for br in (flow, samples):
        assert [b["kind"] for b in br.bifurcations] == ["fold"]
        k = br.bifurcations[0]["index"]
        assert k == 4 and np.all(br.stable[:k]) and not np.any(br.stable[k:])
        assert br.parameter.min() == pytest.approx(br.bifurcations[0]["parameter"], abs=0.1)
    assert samples.bifurcations[0]["parameter"] == pytest.approx(
        flow.bifurcations[0]["parameter"], abs=0.2)


def test_routes_follow_the_screen_and_close_points_are_rechecked(whip_pair):
    """Every point of the flow route says "flow"; on the samples route a point is rechecked
    by the flow exactly where its samples' |μ_c| is within floquet_margin (0.01) of 1 or its
    trivial multiplier is off 1 by more than 0.005 — the point next to the fold is one — and
    its reported multipliers are then the flow's (monodromy_rtol = rtol); the others keep
    the samples' (monodromy_rtol 0), and the branch's flow_rechecks counts the rechecks.
    The flow route's points integrate a final pass the samples route saves: fewer CVODES
    steps per point wherever no recheck ran."""
    _, flow, samples, _ = whip_pair
    assert {o.stats["floquet"] for o in flow.orbits} == {"flow"}
    routes = [o.stats["floquet"] for o in samples.orbits]
    for o, route in zip(samples.orbits, routes):
        close = (abs(o.stats["floquet_samples_modulus"] - 1.0) < 0.01
                 or o.stats["floquet_samples_trivial_error"] > 0.005)
        assert route == ("flow" if close else "samples"), (route, o.stats)
        assert o.stats["monodromy_rtol"] == (1e-6 if route == "flow" else 0.0)
    k = next(b["index"] for b in samples.bifurcations if b["kind"] == "fold")
    assert "flow" in (routes[k - 1], routes[k])
    assert samples.stats["flow_rechecks"] == routes.count("flow") >= 1
    assert "samples" in routes
    for a, b, route in zip(flow.orbits[1:], samples.orbits[1:], routes[1:]):
        if route == "samples":
            assert b.stats["steps"] < a.stats["steps"]


def test_floquet_tol_refines_close_points_before_the_flow(whip_pair):
    """floquet_tol > 0: the points the screen calls close are refined first (the Magnus
    product at doubling step counts; the branch's stats["refined"] counts them) and go to the
    flow only where the refinement leaves the verdict unresolved. On the whip branch both
    close points (121.97 and 121.67 Hz) stay unresolved — the refinement needs the trivial
    multiplier within floquet_tol of 1 — so their multipliers are the flow's, and every
    point is the floquet_tol = 0 branch's: the same routes and |μ_c| to 1e-9."""
    s, _, samples, cyc = whip_pair
    br = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, floquet="samples",
                         floquet_tol=1e-3, **WHIP)
    assert br.ok and br.stats["floquet_tol"] == 1e-3
    routes = [o.stats["floquet"] for o in br.orbits]
    assert br.stats["refined"] == routes.count("flow") + routes.count("refined") >= 1
    assert routes == [o.stats["floquet"] for o in samples.orbits]
    assert np.allclose(br.max_multiplier, samples.max_multiplier, rtol=0, atol=1e-9)


def test_linear_rotor_multipliers_are_exp_lambda_t():
    """Closed form: on linear supports the system is time-invariant, so every forced orbit's
    multipliers are exp(λT) (λ the eigenvalues, T = 1/f): the samples route with margin 0 (no
    recheck) gives the largest modulus within 1e-6 relative at each point of a branch over
    the speed, route "samples"."""
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    start = rd.periodic_orbit(s, 60.0, kind="forced", unbalances=UB, rtol=1e-9, atol_m=1e-13)
    assert start.ok, start.message
    br = rd.continuation(s, "speed_hz", (50.0, 80.0), start, unbalances=UB, rtol=1e-9,
                         atol_m=1e-13, ds=0.1, max_points=3, floquet="samples",
                         floquet_margin=0.0)
    assert br.ok and len(br) == 3, br.message
    for o, f in zip(br.orbits, br.parameter):
        assert o.stats["floquet"] == "samples"
        lam = rd.stability(s, float(f)).eigenvalues
        expected = np.exp(np.max(lam.real) / f)
        assert np.max(np.abs(o.multipliers)) == pytest.approx(expected, rel=1e-6)


@pytest.mark.parametrize("kw,field", [
    ({"floquet": "hill"}, "floquet"),
    ({"floquet": "none"}, "floquet"),
    ({"floquet": "samples", "floquet_tol": 0.7}, "floquet_tol"),
    ({"floquet": "samples", "floquet_tol": -1e-3}, "floquet_tol"),
    ({"floquet": "flow", "floquet_tol": 1e-3}, "floquet_tol"),
    ({"floquet": "samples", "floquet_margin": 0.6}, "floquet_margin"),
    ({"floquet": "flow", "floquet_margin": 0.1}, "floquet_margin"),  # the flow screens nothing
])
def test_bad_floquet_options_of_a_shooting_branch(kw, field):
    """Shooting has the routes "flow" and "samples" (Hill's method needs harmonic balance's
    Jacobian): anything else, a floquet_tol outside [0, 0.5] or with the flow route, a
    margin outside [0, 0.5] → InputError naming the field (and the allowed routes)."""
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    start = rd.periodic_orbit(s, 60.0, kind="forced", unbalances=UB, rtol=1e-9, atol_m=1e-13)
    with pytest.raises(rd.InputError, match=field) as ei:
        rd.continuation(s, "speed_hz", (50.0, 80.0), start, unbalances=UB, max_points=2, **kw)
    if field == "floquet":
        assert "'flow', 'samples'" in str(ei.value)


def test_command_line_shooting_branch_takes_floquet_samples(capsys):
    """``rotordyn continuation --floquet samples`` with shooting (it exited 2: "--floquet:
    applies only to --method harmonic_balance" although the API takes it): the JSON's
    routes are the samples' and the largest multiplier of each point is exp(λT) of the
    linear rotor as in the API test above; --floquet hill with shooting, --floquet-tol with
    the flow route and --floquet-margin with the flow route exit 2 naming the flag."""
    import json

    from rotordyn.cli import main

    model = str(MODELS / "compressor_linear.toml")
    base = ["continuation", model, "--kind", "forced", "--speed-hz", "60", "--unbalance",
            "3,1e-3,30", "--vary", "speed_hz", "--bounds", "50", "80", "--max-points", "3",
            "--ds", "0.1", "--rtol", "1e-9"]
    assert main(base + ["--floquet", "samples", "--floquet-margin", "0", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "ok" and out["floquet_route"] == ["samples"] * 3, out
    s = rd.System.from_toml(model)
    for f, mu in zip(out["parameter"], out["max_multiplier"]):
        lam = rd.stability(s, float(f)).eigenvalues
        assert mu == pytest.approx(np.exp(np.max(lam.real) / f), rel=1e-5)
    for extra, flag in ((["--floquet", "hill"], "--floquet"),
                        (["--floquet-tol", "1e-3"], "--floquet-tol"),
                        (["--floquet", "flow", "--floquet-margin", "0.1"], "--floquet-margin"),
                        (["--floquet", "samples", "--floquet-tol", "0.7"], "--floquet-tol")):
        assert main(base + extra) == 2, extra
        assert flag in capsys.readouterr().err
