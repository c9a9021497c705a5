"""Pseudo-arclength continuation of periodic orbits (issue 19, docs/nonlinear.md).

References:
* closed form: a rotor on linear supports forced by unbalance has the periodic orbit
  r(t) = K⁻¹(Q − K a) + Re(X e^{iΩt}), (K − Ω² M + iΩ(C + ΩG)) X = Ω² (u_c − i u_s), at every
  speed of the branch;
* the linear threshold (the equilibrium's least-damped eigenvalue through zero, Brent on the
  scan of ``rotordyn.threshold``): a branch of limit cycles ends where it meets it (Hopf).
"""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd

from orbit_forms import forced_orbit
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"
UB = [(3, 1e-3, 30.0)]


@pytest.fixture(scope="module")
def linear_system():
    return rd.System.from_toml(MODELS / "compressor_linear.toml")


@pytest.fixture(scope="module")
def linear_orbit(linear_system):
    res = rd.periodic_orbit(linear_system, 60.0, kind="forced", unbalances=UB, rtol=1e-9,
                            atol_m=1e-13)
    assert res.ok, res.message
    return res


def test_forced_branch_over_speed_equals_the_closed_form_at_every_point(linear_system,
                                                                         linear_orbit,
                                                                         tmp_path):
    """Every corrected point of a speed branch (60 Hz upwards, 5 points) is the closed-form
    orbit at the speed the corrector chose, to 1e-6 of the largest displacement (static sag
    plus whirl; CVODES at rtol 1e-9, shooting tol 1e-7); the period follows
    1/speed; the arclength grows and the speeds increase (no turning point on a linear
    rotor)."""
    br = rd.continuation(linear_system, "speed_hz", (50.0, 200.0), linear_orbit,
                         unbalances=UB, ds=0.05, max_points=5, rtol=1e-9, atol_m=1e-13,
                         tol=1e-7)
    assert br.ok and len(br) == 5, br.message
    assert np.all(np.diff(br.parameter) > 0) and br.parameter[-1] > 61.0
    assert np.all(np.diff(br.arclength) > 0)
    assert br.period_s == pytest.approx(1 / br.parameter, rel=1e-12)
    for o in br.orbits:
        r_exact, amp = forced_orbit(linear_system, o.speed_hz, o.t, UB)
        assert np.abs(o.r - r_exact).max() < 1e-6 * np.abs(r_exact).max()
    assert np.all(br.stable) and br.bifurcations == ()
    df = br.to_frame()
    assert {"speed_hz", "amplitude_m", "period_s", "max_multiplier", "stable",
            "bifurcation"} <= set(df.columns)
    assert len(df) == 5 * len(br.bearing_names)
    assert "BranchResult ok" in repr(br) and "speed" in repr(br)
    back = rd.BranchResult.load(br.save(tmp_path / "branch.npz"))
    assert np.array_equal(back.parameter, br.parameter) and len(back.orbits) == 5
    assert np.array_equal(back.orbits[2].r, br.orbits[2].r)


def test_direction_minus_one_walks_down(linear_system, linear_orbit):
    """direction=-1 leaves the start towards lower speeds; the branch stops at the bound."""
    br = rd.continuation(linear_system, "speed_hz", (58.0, 200.0), linear_orbit,
                         unbalances=UB, ds=0.1, ds_max=0.2, max_points=30, direction=-1,
                         tol=1e-6)
    assert br.ok and br.stop == "bound"
    assert np.all(np.diff(br.parameter) < 0) and br.parameter.min() >= 58.0


def test_broyden_correctors_land_on_the_closed_form_with_fewer_sensitivity_flows(
        linear_system, linear_orbit):
    """Correctors that start from the previous point's matrix and update it by Broyden from
    flows without sensitivities (newton="broyden") against correctors with the sensitivities
    and ∂R/∂p at every iteration (the default): every point is the closed-form orbit at its
    speed, to 1e-6 of the largest displacement with sensitivities, to 1e-5 with Broyden
    (measured 1.46e-6: it stops just under tol = 1e-7), and the Broyden branch integrates no more flows with sensitivities (here as
    many: the refresh rule fires)."""
    kw = dict(unbalances=UB, ds=0.05, max_points=4, rtol=1e-9, atol_m=1e-13, tol=1e-7)
    a = rd.continuation(linear_system, "speed_hz", (50.0, 200.0), linear_orbit,
                        newton="broyden", **kw)
    b = rd.continuation(linear_system, "speed_hz", (50.0, 200.0), linear_orbit, **kw)
    assert a.ok and b.ok and len(a) == len(b) == 4, (a.message, b.message)
    def worst(br):
        e = 0.0
        for o in br.orbits:
            r_exact, _ = forced_orbit(linear_system, o.speed_hz, o.t, UB)
            e = max(e, np.abs(o.r - r_exact).max() / np.abs(r_exact).max())
        return e

    e_a, e_b = worst(a), worst(b)
    assert e_b < 1e-6
    assert e_a < 1e-5  # Broyden stops just under tol; Newton overshoots far below it
    assert a.stats["sensitivity_flows"] <= b.stats["sensitivity_flows"]
    assert b.stats["sensitivity_flows"] == b.stats["flows"]


@pytest.mark.parametrize("kw, field", [
    ({"vary": "clearance"}, "vary"),
    ({"bounds": (70.0, 80.0)}, "bounds"),
    ({"bounds": (80.0, 70.0)}, "bounds"),
    ({"ds": 0.0}, "ds"),
    ({"ds": -0.1}, "ds"),
    ({"unbalances": ()}, "unbalances"),
    ({"start": "orbit"}, "start"),
    ({"direction": 0}, "direction"),
])
def test_bad_input_names_the_field(linear_system, linear_orbit, kw, field):
    args = {"vary": "speed_hz", "bounds": (50.0, 80.0), "start": linear_orbit,
            "unbalances": UB}
    args.update(kw)
    with pytest.raises(rd.InputError, match=field):
        rd.continuation(linear_system, args.pop("vary"), args.pop("bounds"), args.pop("start"),
                        **args)


def test_cli_continuation(capsys, tmp_path):
    """``rotordyn continuation`` prints the branch table (exit 0); a bad --vary is refused by
    the parser and a start outside --bounds is an InputError (exit 2)."""
    from rotordyn.cli import main

    model = str(MODELS / "compressor_linear.toml")
    fig = tmp_path / "branch.png"
    assert main(["continuation", model, "--kind", "forced", "--speed-hz", "60",
                 "--unbalance", "3,1e-3,30", "--vary", "speed_hz", "--bounds", "55", "80",
                 "--max-points", "3", "--plot", str(fig)]) == 0
    out = capsys.readouterr().out
    assert "BranchResult ok" in out and "speed_hz" in out and "max_multiplier" in out
    assert fig.stat().st_size > 0
    assert main(["continuation", model, "--kind", "forced", "--speed-hz", "60",
                 "--unbalance", "3,1e-3,30", "--vary", "speed_hz", "--bounds", "70",
                 "80"]) == 2
    assert "bounds" in capsys.readouterr().err


def test_cli_continuation_newton_fast_and_exact(capsys):
    """``rotordyn continuation --newton fast|exact`` reaches the continuation's correctors:
    the forced speed branch of the compressor on linear supports (3 points, rtol 1e-9, tol
    1e-7) by each gives the same points — the closed-form orbits at their speeds, so the two
    agree to the correctors' tol: parameter within 1e-6 Hz·(tol/1e-7), amplitude 1e-6
    relative (measured ≤ 1e-9 Hz and ≤ 2e-10) — and the fast one spends fewer flows with
    sensitivities; the JSON says which corrector ran. An unknown value is refused by the parser
    (exit 2) with the option's name and the allowed values."""
    import json

    from rotordyn.cli import main

    model = str(MODELS / "compressor_linear.toml")
    base = ["continuation", model, "--kind", "forced", "--speed-hz", "60", "--unbalance",
            "3,1e-3,30", "--vary", "speed_hz", "--bounds", "55", "80", "--max-points", "3",
            "--rtol", "1e-9", "--tol", "1e-7", "--json"]
    out = {}
    for mode in ("exact", "fast"):
        assert main(base + ["--newton", mode]) == 0
        out[mode] = json.loads(capsys.readouterr().out)
        assert out[mode]["newton"] == mode and out[mode]["status"] == "ok"
    e, f = out["exact"], out["fast"]
    assert len(e["parameter"]) == len(f["parameter"]) == 3
    np.testing.assert_allclose(f["parameter"], e["parameter"], atol=1e-6)
    np.testing.assert_allclose(f["amplitude_m"], e["amplitude_m"], rtol=1e-6)
    assert f["stable"] == e["stable"]
    assert f["stats"]["sensitivity_flows"] < e["stats"]["sensitivity_flows"]
    assert main(base + ["--newton", "secant"]) == 2
    err = capsys.readouterr().err
    assert "--newton" in err and "'exact'" in err and "'fast'" in err


def test_cli_continuation_help_says_what_each_newton_does(capsys):
    from rotordyn.cli import main

    with pytest.raises(SystemExit):
        main(["continuation", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "--newton {exact,fast}" in text
    assert "exact = Newton" in text and "fast = Broyden" in text


def test_continuation_newton_names(linear_system, linear_orbit):
    """``newton="exact"`` is the default ``"sensitivities"`` under the CLI's name (the same
    flows and points bit for bit); an unknown name is an InputError listing the allowed."""
    kw = dict(unbalances=UB, rtol=1e-9, tol=1e-7, max_points=2)
    a = rd.continuation(linear_system, "speed_hz", (55.0, 80.0), linear_orbit,
                        newton="exact", **kw)
    b = rd.continuation(linear_system, "speed_hz", (55.0, 80.0), linear_orbit,
                        newton="sensitivities", **kw)
    np.testing.assert_array_equal(a.parameter, b.parameter)
    np.testing.assert_array_equal(a.amplitude_m, b.amplitude_m)
    assert a.stats == b.stats
    with pytest.raises(rd.InputError, match="newton.*'exact', 'fast'"):
        rd.continuation(linear_system, "speed_hz", (55.0, 80.0), linear_orbit,
                        newton="secant", **kw)


@pytest.fixture(scope="module")
def coarse_rig_cycle():
    """The paper rig (36 × 6 film grid for speed) and its stable cycle at a_y = −1.85 mm,
    50 Hz, 0.05 MPa from a 0.6 s transient."""
    
    rig = coarse_models.paper_rig()
    tr = rd.transient(rig, 0.6, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=6001)
    cyc = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=tr, rtol=1e-6, tol=1e-4)
    assert cyc.ok, cyc.message
    return rig, cyc


def test_cycle_branch_over_ay_is_made_of_cycles(coarse_rig_cycle):
    """vary="config_ay_m" (the active bearing's a_y, m): 3 points from −1.85 mm upwards; each
    point, solved again independently by shooting at its own a_y from its own start,
    converges at once (residual below tol on the first flow) to the same period (1e-6) —
    the corrector's points are cycles of eq. 12 at the a_y it reports; the amplitude falls
    as a_y rises towards the Hopf point (bench_continuation --others)."""
    rig, cyc = coarse_rig_cycle
    br = rd.continuation(rig, "config_ay_m", (-3e-3, 0.0), cyc, rtol=1e-6, tol=1e-4,
                         ds=0.05, max_points=3)
    assert br.ok and len(br) == 3, br.message
    assert np.all(np.diff(br.parameter) > 0) and br.parameter[0] == pytest.approx(-1.85e-3)
    assert np.all(np.diff(br.amplitude_m[:, 0]) < 0)
    o = br.orbits[-1]
    again = rd.periodic_orbit(rig, 50.0, 0.05e6, float(br.parameter[-1]),
                              start=(o.r[0], o.v[0]), period_s=o.period_s, rtol=1e-6,
                              tol=1e-4)
    assert again.ok and again.residuals[0] < 1e-4
    assert again.period_s == pytest.approx(o.period_s, rel=1e-6)


def test_cycle_branch_turns_at_the_hopf_point_of_the_linear_threshold(coarse_rig_cycle):
    """Past a turning point: the paper rig's limit cycle (a_y = −1.85 mm, 50 Hz; a coarse
    36 × 6 film grid for speed) continued upwards in p_c from 0.05 MPa shrinks onto the
    equilibrium. Along the branch of starts x0 the parameter turns back there (p = p_H + c·A²
    with the signed amplitude A through 0): the corrector converges on the point beyond the
    turn (its p_c below the turn), and the turning point p_H estimated from the branch
    equals the linear threshold of the same model (an independent solve: the equilibrium's
    eigenvalue through zero, Brent) within 1 % (measured 0.46 % with ds = 0.1), the period
    there the linear whirl period within 1 %. Every cycle is stable and the amplitude falls
    monotonically: a supercritical Hopf point."""
    rig, cyc = coarse_rig_cycle
    br = rd.continuation(rig, "chamber_pressure_pa", (0.04e6, 0.08e6), cyc, rtol=1e-6,
                         tol=1e-4, ds=0.1, ds_max=0.4, max_points=12)
    assert br.ok and br.stop == "hopf", (br.stop, br.message)
    assert np.all(br.stable) and np.all(np.diff(br.amplitude_m[:, 0]) < 0)
    assert np.all(np.diff(br.parameter) > 0)
    hopf = br.bifurcations[-1]
    assert hopf["kind"] == "hopf"
    assert hopf["beyond_parameter"] < hopf["parameter"]
    th = rd.threshold(rig, bounds=(0.04e6, 0.08e6), speed_hz=50.0, config_ay_m=-1.85e-3)
    assert hopf["parameter"] == pytest.approx(th.value, rel=1e-2)
    assert 1 / hopf["period_s"] == pytest.approx(th.whirl_frequency_hz, rel=1e-2)
    assert "hopf" in repr(br) and "hopf" in set(br.to_frame()["bifurcation"])
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ax = br.plot()
    # every point stable: one solid polyline through all of them (runs of one style are
    # drawn as one line), the points, the Hopf marker
    solid = [ln for ln in ax.lines if ln.get_linestyle() == "-"]
    assert len(solid) == 1 and len(solid[0].get_xdata()) == len(br)
    plt.close("all")


@pytest.fixture(scope="module")
def whip_branch():
    """The oil-whip cycle of the compressor on plain journal bearings (36 × 6 film grid for
    speed; linear threshold 126.5 Hz) at 130 Hz, reached from the equilibrium disturbed by
    0.6 c, continued down in speed past its fold (7 points)."""
    
    s = coarse_models.compressor_plain()
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, rtol=1e-6, tol=1e-4)
    assert cyc.ok and cyc.stable, cyc.message
    br = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, rtol=1e-6, tol=1e-4, ds=0.1,
                         ds_max=0.3, max_points=7, direction=-1)
    return s, br


def test_continuation_past_a_fold_of_whip_cycles(whip_branch):
    """Continuation past a fold (saddle-node of cycles), verified two ways:
    * the two independent signs of a fold agree: the branch's dp/ds (the tangent of the
      bordered corrector, ∂R/∂p by finite differences) changes sign between the same two
      points where the critical Floquet multiplier (CVODES sensitivities) crosses +1, and the
      fold located by each (linear interpolation in the arclength) agrees within 0.1 Hz
      (measured 121.86 Hz from the tangent; 121.69 Hz at fd973e0, before a merge changed the step sizes);
    * two independent shooting solves at one speed between the fold and the start, from
      a point on each side of the fold, converge on two different cycles: the outer one
      stable, the inner one unstable (the hysteresis of a fold)."""
    s, br = whip_branch
    assert br.ok and len(br) == 7, br.message
    folds = [b for b in br.bifurcations if b["kind"] == "fold"]
    assert len(folds) == 1
    k = folds[0]["index"]
    assert br.tangent_p[k - 1] < 0 < br.tangent_p[k]
    assert br.max_multiplier[k - 1] < 1 < br.max_multiplier[k]
    assert br.stable[k - 1] and not br.stable[k]
    m0, m1 = br.max_multiplier[k - 1], br.max_multiplier[k]
    w = (1 - m0) / (m1 - m0)
    p_mu = br.parameter[k - 1] + w * (br.parameter[k] - br.parameter[k - 1])
    assert folds[0]["parameter"] == pytest.approx(p_mu, abs=0.1)
    assert br.parameter.min() == pytest.approx(folds[0]["parameter"], abs=0.1)
    # beyond the fold the branch comes back: two cycles at one speed
    j = int(np.argmax(br.parameter[k:])) + k
    f = float(br.parameter[j])
    # the stable point before the fold nearest above that speed (the branch's step sizes
    # decide which points exist; any of them on the outer branch starts the outer cycle)
    above = [m for m in range(k) if br.parameter[m] > f]
    assert above and all(br.stable[m] for m in above)
    i = min(above, key=lambda m: br.parameter[m] - f)
    outer = rd.periodic_orbit(s, f, start=(br.orbits[i].r[0], br.orbits[i].v[0]),
                              period_s=br.period_s[i], rtol=1e-6, tol=1e-4)
    inner = rd.periodic_orbit(s, f, start=(br.orbits[j].r[0], br.orbits[j].v[0]),
                              period_s=br.period_s[j], rtol=1e-6, tol=1e-4)
    assert outer.ok and inner.ok, (outer.message, inner.message)
    assert outer.stable and not inner.stable
    assert outer.amplitude(0) > inner.amplitude(0) + 2e-6
    assert inner.amplitude(0) == pytest.approx(br.amplitude_m[j, 0], rel=1e-3)


def test_config_branch_needs_an_active_bearing(linear_system, linear_orbit):
    """vary="config_ay_m" on a system without an active bearing: InputError naming
    config_ay_m (the configuration addresses the active bearing)."""
    with pytest.raises(rd.InputError, match="config_ay_m"):
        rd.continuation(linear_system, "config_ay_m", (-1e-3, 1e-3), linear_orbit,
                        unbalances=UB)
