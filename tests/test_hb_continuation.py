"""Continuation of periodic orbits with harmonic-balance correctors
(``rd.continuation(..., method="harmonic_balance")``; docs/nonlinear.md, "Continuation by
harmonic balance").

References:
* the shooting (CVODES flow, Newton with the monodromy from forward sensitivities) of the
  same system at each branch point's own parameter value, started from the point's state — an
  independent method on the same C++ right-hand side;
* on a linear rotor the forced orbit in closed form (tests/orbit_forms.py);
* the linear threshold (``rd.threshold``): a limit-cycle branch ends where it meets it;
* a fold confirmed by two shooting solves at one speed converging on two cycles.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.errors import InputError

from orbit_forms import forced_orbit
from test_harmonic_balance import smooth_rotor_system
import coarse_models  # noqa: E402

HB = "harmonic_balance"
MODELS = Path(__file__).parent / "data" / "models"


def _route_rule(br, margin=0.01):
    """Every point's multipliers come from the samples unless the samples' critical
    multiplier is within ``margin`` of the unit circle or their trivial one is off 1 by
    more than ``margin`` / 2 — then from the flow."""
    for o in br.orbits:
        s = o.stats
        near = (abs(s["floquet_samples_modulus"] - 1) < margin
                or s["floquet_samples_trivial_error"] > margin / 2)
        assert s["floquet"] == ("flow" if near else "samples"), s
        assert o.stats["method"] == HB


# ---------------------------------------------------------------- a smooth film: forced orbits
@pytest.fixture(scope="module")
def smooth_branch():
    """The smooth two-bearing rotor (full film) forced by 8e-3 kg·m: the HB orbit at 15 Hz
    (H = 12) continued up in speed by HB correctors (∂R/∂p by the central difference, the
    period following the speed)."""
    s = smooth_rotor_system()
    ub = [(2, 8e-3, 0.0)]
    o = rd.periodic_orbit(s, 15.0, kind="forced", unbalances=ub, method=HB, harmonics=12,
                          tol=1e-12, n_out=97)
    assert o.ok, o.message
    br = rd.continuation(s, "speed_hz", (10.0, 20.0), o, unbalances=ub, method=HB,
                         harmonics=12, tol=1e-11, ds=0.05, ds_max=0.05, max_points=4,
                         n_out=97, rtol=1e-10)
    return s, ub, br


def test_smooth_forced_branch_equals_shooting_at_its_speeds(smooth_branch):
    """Each point of the HB speed branch against the shooting at that point's speed (rtol
    1e-10, tol 1e-9, started from the point's state): every sample of every coordinate within
    1e-6 of the orbit amplitude (H = 12; measured ≤ 2.9e-9), the multipliers within 1e-4
    (measured ≤ 4.8e-5),
    the same stability (the orbits are unstable, |μ_c| ≈ 1.025); the period is 1/speed to
    1e-12 and the speed grows along the branch."""
    s, ub, br = smooth_branch
    assert br.ok and len(br) == 4, br.message
    assert np.all(np.diff(br.parameter) > 0)
    assert br.period_s == pytest.approx(1 / br.parameter, rel=1e-12)
    assert br.stats["method"] == HB and br.stats["harmonics"] == 12
    for o in br.orbits:
        sh = rd.periodic_orbit(s, o.speed_hz, kind="forced", unbalances=ub,
                               start=(o.r[0], o.v[0]), rtol=1e-10, atol_m=1e-15, tol=1e-9,
                               n_out=97)
        assert sh.ok, sh.message
        amp = np.abs(sh.r - sh.r.mean(0)).max()
        assert np.abs(o.r - sh.r).max() < 1e-6 * amp
        mu_sh, mu_hb = np.sort_complex(sh.multipliers), np.sort_complex(o.multipliers)
        assert np.abs(mu_sh - mu_hb).max() < 1e-4
        assert o.stable == sh.stable
    _route_rule(br)


# -------------------------------------------------------------- the rig: a cavitated film
@pytest.fixture(scope="module")
def rig_hb_branch():
    """The paper rig on a 36 × 6 active film at a_y = −1.85 mm, 50 Hz: its cycle at 0.05 MPa
    by HB from the equilibrium (no transient), continued up in p_c to the Hopf end (ds 0.1)."""
    rig = coarse_models.paper_rig()
    cyc = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, method=HB, tol=1e-8)
    assert cyc.ok, cyc.message
    br = rd.continuation(rig, "chamber_pressure_pa", (0.04e6, 0.08e6), cyc, method=HB,
                         tol=1e-8, ds=0.1, ds_max=0.1, max_points=30, rtol=1e-7)
    return rig, br


def test_rig_branch_equals_shooting_and_ends_at_the_threshold(rig_hb_branch):
    """The rig's HB branch (H = 8): three points against the shooting at their p_c (rtol
    1e-8, tol 1e-7 from the point's state): amplitude within 1e-3 of the clearance and period
    within 1e-4 relative — the accuracy HB reaches on the cavitated film, whose force
    spectrum decays algebraically (docs: HB stalls near 2e-4 of the amplitude on the rig as
    built; on this 36 × 6 grid, measured at all 9 points, 0.4e-4 … 4.4e-4 of the clearance
    at every amplitude — 1e-2 relative at the 10 µm cycle —, the period 3.3e-5) —, |μ_c|
    within 5e-3 (measured 1.0e-3), the
    same stability; the amplitude falling with p_c and every cycle above 0.06 c stable (on
    this grid the small cycles just below the Hopf point fold twice within 40 Pa —
    docs/nonlinear.md, "The rig and the compressor" —: a 10 µm point there is the unstable
    middle cycle, |μ_c| = 1.00003); the branch ends at a Hopf point within 1 % of the linear
    threshold (``rd.threshold``) with the whirl period within 1 %."""
    rig, br = rig_hb_branch
    assert br.ok and br.stop == "hopf", (br.stop, br.message)
    assert len(br) >= 5
    assert np.all(np.diff(br.amplitude_m[:, 0]) < 0)
    big = br.amplitude_m[:, 0] > 0.06 * br.clearance_m[0]
    assert big.sum() >= 5 and np.all(br.stable[big])
    for i in (0, len(br) // 2, len(br) - 1):
        o = br.orbits[i]
        sh = rd.periodic_orbit(rig, 50.0, o.chamber_pressure_pa, -1.85e-3,
                               start=(o.r[0], o.v[0]), period_s=o.period_s, rtol=1e-8,
                               tol=1e-7, n_out=401)
        assert sh.ok, sh.message
        assert abs(o.amplitude() - sh.amplitude()) < 1e-3 * br.clearance_m[0]
        assert abs(o.period_s - sh.period_s) < 1e-4 * sh.period_s
        assert abs(abs(o.critical_multiplier) - abs(sh.critical_multiplier)) < 5e-3
        assert o.stable == sh.stable
    hopf = br.bifurcations[-1]
    assert hopf["kind"] == "hopf"
    th = rd.threshold(rig, bounds=(0.04e6, 0.08e6), speed_hz=50.0, config_ay_m=-1.85e-3)
    assert hopf["parameter"] == pytest.approx(th.value, rel=1e-2)
    assert 1 / hopf["period_s"] == pytest.approx(th.whirl_frequency_hz, rel=1e-2)


def test_rig_branch_rechecks_the_multipliers_near_the_unit_circle(rig_hb_branch):
    """Towards the Hopf point |μ_c| → 1: the points whose samples' critical multiplier is
    within the margin (0.01) of the unit circle take the flow route (one CVODES sensitivity
    flow), the others keep the samples', and both routes occur on this branch; where the flow
    ran, the samples' |μ_c| agrees with it within the margin (the route exists because they
    may not agree better)."""
    _, br = rig_hb_branch
    _route_rule(br)
    routes = [o.stats["floquet"] for o in br.orbits]
    assert "flow" in routes and "samples" in routes
    for o in br.orbits:
        if o.stats["floquet"] == "flow":
            assert abs(o.stats["floquet_samples_modulus"] - abs(o.critical_multiplier)) < 0.01
            assert o.stats["monodromy_rtol"] > 0
        else:
            assert o.stats["monodromy_rtol"] == 0.0


def test_rig_branch_over_ay_uses_the_exact_spring_force_derivative(rig_hb_branch):
    """vary="config_ay_m" (∂R/∂a_y = K·∂a/∂a_y in the constant harmonic, no difference
    quotient): 3 points up from −1.85 mm from the branch's HB cycle; the last against the
    shooting at its a_y (rtol 1e-8, tol 1e-7): amplitude within 1e-3 c, period 1e-4 (measured
    over 4 points: ≤ 4.4e-4 c, 3.3e-5); the amplitude falls as a_y rises towards the Hopf
    point (tests/test_continuation.py's shooting branch)."""
    rig, br0 = rig_hb_branch
    br = rd.continuation(rig, "config_ay_m", (-3e-3, 0.0), br0.orbits[0], method=HB,
                         tol=1e-8, ds=0.05, max_points=3, rtol=1e-7)
    assert br.ok and len(br) == 3, br.message
    assert br.stats["fd_evaluations"] == 0
    assert np.all(np.diff(br.parameter) > 0) and np.all(np.diff(br.amplitude_m[:, 0]) < 0)
    o = br.orbits[-1]
    sh = rd.periodic_orbit(rig, 50.0, 0.05e6, o.config_ay_m, start=(o.r[0], o.v[0]),
                           period_s=o.period_s, rtol=1e-8, tol=1e-7)
    assert sh.ok, sh.message
    assert abs(o.amplitude() - sh.amplitude()) < 1e-3 * br.clearance_m[0]
    assert abs(o.period_s - sh.period_s) < 1e-4 * sh.period_s


# --------------------------------------------------------- a fold: the compressor's oil whip
@pytest.fixture(scope="module")
def whip_hb_branch():
    """The compressor on plain bearings (36 × 6 film grid): its oil-whip cycle at 130 Hz by
    HB from a 0.4 s transient, continued down in speed with HB correctors (ds 0.1 constant)
    past the fold near 121.7 Hz (docs/nonlinear.md "A fold")."""
    s = coarse_models.compressor_plain()
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, method=HB, tol=1e-8)
    assert cyc.ok and cyc.stable, cyc.message
    br = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, method=HB, tol=1e-8, ds=0.1,
                         ds_max=0.1, max_points=7, direction=-1, rtol=1e-6,
                         sensitivity_rtol=1e-5)
    return s, br


def test_hb_branch_continues_past_the_fold_of_the_whip_cycles(whip_hb_branch):
    """Past a fold with HB correctors: dp/ds changes sign between the same two points where
    the critical multiplier crosses +1, the two fold estimates within 0.1 Hz; the fold's
    points took the flow route; beyond the fold two shooting solves at one speed from an
    HB point on each side converge on two different cycles — the outer one stable, the inner
    one unstable (the hysteresis of the fold) — and the inner one is the HB point's cycle
    within 3e-3 of the clearance in amplitude (H = 8 on these 0.8–0.9 c whip cycles: measured
    1.1e-3 … 2.4e-3 c against shooting at the branch's points; 0.9e-3 c here; H = 12 gives
    ≤ 4e-4 c away from the fold). The samples' multipliers are poor on these large orbits (the
    trivial one off 1 by 0.04–0.25): most points take the flow route, by the rule."""
    s, br = whip_hb_branch
    assert br.ok, br.message
    folds = [b for b in br.bifurcations if b["kind"] == "fold"]
    assert len(folds) >= 1
    k = folds[0]["index"]
    assert br.tangent_p[k - 1] < 0 < br.tangent_p[k]
    assert br.max_multiplier[k - 1] < 1 < br.max_multiplier[k]
    m0, m1 = br.max_multiplier[k - 1], br.max_multiplier[k]
    w = (1 - m0) / (m1 - m0)
    p_mu = br.parameter[k - 1] + w * (br.parameter[k] - br.parameter[k - 1])
    assert folds[0]["parameter"] == pytest.approx(p_mu, abs=0.1)
    _route_rule(br)
    j = int(np.argmax(br.parameter[k:])) + k
    f = float(br.parameter[j])
    above = [m for m in range(k) if br.parameter[m] > f]
    assert above and all(br.stable[m] for m in above)
    i = min(above, key=lambda m: br.parameter[m] - f)
    outer = rd.periodic_orbit(s, f, start=(br.orbits[i].r[0], br.orbits[i].v[0]),
                              period_s=br.period_s[i], rtol=1e-6, tol=1e-4,
                              sensitivity_rtol=1e-4)
    inner = rd.periodic_orbit(s, f, start=(br.orbits[j].r[0], br.orbits[j].v[0]),
                              period_s=br.period_s[j], rtol=1e-6, tol=1e-4,
                              sensitivity_rtol=1e-4)
    assert outer.ok and inner.ok, (outer.message, inner.message)
    assert outer.stable and not inner.stable
    assert outer.amplitude(0) > inner.amplitude(0) + 2e-6
    assert abs(inner.amplitude(0) - br.amplitude_m[j, 0]) < 3e-3 * br.clearance_m[0]
    assert sum(o.stats["floquet"] == "flow" for o in br.orbits) >= 4


def test_refined_multipliers_keep_the_fold_and_replace_flows(whip_hb_branch):
    """``floquet_tol`` on the whip branch: the correctors are the same (every point's speed
    and amplitude bit for bit), the points the screen calls close are refined by the Magnus
    product (route "refined") instead of the flow where the refinement resolves the verdict,
    and every point's verdict and the fold are the flow route's, the fold where |μ_c|
    crosses 1 within 0.1 Hz of dp/ds's sign change. |μ_c| of a refined point against the
    flow's at the same point (sensitivity_rtol 1e-5), measured: 0.0097 … 0.021 (within the
    estimate ``floquet_error``, 1.1e-2 … 4.3e-2, at 6 of 7 points) and 0.057 at 121.66 Hz,
    just past the fold (2.7 × its estimate 0.021): test 0.1, the verdict is what must hold."""
    s, base = whip_hb_branch
    cyc = base.orbits[0]
    br = rd.continuation(s, "speed_hz", (100.0, 140.0), cyc, method=HB, tol=1e-8, ds=0.1,
                         ds_max=0.1, max_points=len(base), direction=-1, rtol=1e-6,
                         sensitivity_rtol=1e-5, floquet_tol=1e-3)
    assert br.ok and len(br) == len(base)
    assert np.array_equal(br.parameter, base.parameter)
    assert np.array_equal(br.amplitude_m, base.amplitude_m)
    assert br.stats["floquet_tol"] == 1e-3 and br.stats["refined"] >= 1
    routes = [o.stats["floquet"] for o in br.orbits]
    assert "refined" in routes
    assert br.stats["flow_rechecks"] < base.stats["flow_rechecks"]
    for o, ob in zip(br.orbits, base.orbits):
        if o.stats["floquet"] == "refined":
            assert ob.stats["floquet"] == "flow"  # the baseline's flow there, by the rule
            err = o.stats["floquet_error"]
            assert 0 < err < abs(abs(o.critical_multiplier) - 1)  # a resolved verdict
            assert abs(abs(o.critical_multiplier) - abs(ob.critical_multiplier)) < 0.1
        else:
            assert o.stats["floquet"] == ob.stats["floquet"]
    assert np.array_equal(br.stable, base.stable)
    fb = [b for b in base.bifurcations if b["kind"] == "fold"]
    fr = [b for b in br.bifurcations if b["kind"] == "fold"]
    assert len(fr) == len(fb) >= 1 and fr[0]["index"] == fb[0]["index"]
    k = fr[0]["index"]
    m0, m1 = br.max_multiplier[k - 1], br.max_multiplier[k]
    assert m0 < 1 < m1
    p_mu = br.parameter[k - 1] + (1 - m0) / (m1 - m0) * (br.parameter[k] - br.parameter[k - 1])
    assert fr[0]["parameter"] == pytest.approx(p_mu, abs=0.1)


# ------------------------------------------------------------------ CLI, sweep and bad input
def test_cli_continuation_by_harmonic_balance(capsys):
    """``rotordyn continuation --method harmonic_balance`` on the compressor on linear
    supports (forced by unbalance): every point's amplitude is the closed-form orbit's at its
    speed (one harmonic is exact for a linear rotor; H = 2) to 1e-8; the
    JSON names the method, H, M and each point's Floquet route. HB flags with shooting,
    --newton with harmonic balance, H < 1 and M < 2H + 1 exit 2 naming the flag."""
    from rotordyn.cli import main

    model = str(MODELS / "compressor_linear.toml")
    base = ["continuation", model, "--kind", "forced", "--speed-hz", "60", "--unbalance",
            "3,1e-3,30", "--vary", "speed_hz", "--bounds", "55", "80", "--max-points", "3",
            "--tol", "1e-10"]
    assert main(base + ["--method", HB, "--harmonics", "2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "ok" and out["method"] == HB
    assert out["harmonics"] == 2 and out["time_points"] == 8
    assert out["floquet_route"] == ["samples"] * 3 and out["newton"] is None
    s = rd.System.from_toml(model)
    for f, a in zip(out["parameter"], out["amplitude_m"]):
        # the branch's amplitude of a system without bearings: the largest distance of any
        # coordinate from its mean over the 101 samples of one period from t0 = 0
        r_exact, _ = forced_orbit(s, f, np.linspace(0.0, 1.0 / f, 101), [(3, 1e-3, 30.0)])
        want = np.abs(r_exact - r_exact.mean(axis=0)).max()
        assert a[0] == pytest.approx(want, rel=1e-8)
    assert len(out["parameter"]) == 3 and out["parameter"][-1] > 60.0
    assert main(base + ["--method", HB, "--harmonics", "2"]) == 0
    text = capsys.readouterr().out
    assert "method: harmonic_balance (harmonics = 2, time_points = 8" in text
    assert "floquet" in text
    for extra, flag in ((["--harmonics", "3"], "--harmonics"),
                        (["--method", HB, "--newton", "fast"], "--newton"),
                        (["--method", HB, "--harmonics", "0"], "--harmonics"),
                        (["--method", HB, "--harmonics", "2", "--samples", "4"], "--samples"),
                        (["--floquet-margin", "0.1"], "--floquet-margin"),
                        (["--floquet-tol", "1e-3"], "--floquet-tol"),
                        (["--method", HB, "--harmonics", "2", "--floquet", "hill",
                          "--floquet-tol", "1e-3"], "--floquet-tol"),
                        (["--method", HB, "--harmonics", "2", "--floquet-tol", "0.7"],
                         "--floquet-tol")):
        assert main(base + extra) == 2, extra
        assert flag in capsys.readouterr().err


def test_cli_branch_points_are_the_closed_form(capsys):
    """The branch's own points (not re-solved) against the closed form: the HB continuation of
    the linear rotor's forced orbit, H = 1, at its speeds, to 1e-8."""
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    ub = [(3, 1e-3, 30.0)]
    o = rd.periodic_orbit(s, 60.0, kind="forced", unbalances=ub, method=HB, harmonics=1,
                          tol=1e-12)
    br = rd.continuation(s, "speed_hz", (50.0, 200.0), o, unbalances=ub, method=HB,
                         harmonics=1, tol=1e-11, ds=0.05, max_points=4)
    assert br.ok and len(br) == 4 and np.all(np.diff(br.parameter) > 0)
    for p in br.orbits:
        r_exact, _ = forced_orbit(s, p.speed_hz, p.t, ub)
        assert np.abs(p.r - r_exact).max() < 1e-8 * np.abs(r_exact).max()
        assert p.stats["method"] == HB
    assert br.stats["fd_evaluations"] > 0  # the speed's ∂R/∂p by central differences


@pytest.fixture(scope="module")
def linear_orbit():
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    o = rd.periodic_orbit(s, 60.0, kind="forced", unbalances=[(3, 1e-3, 30.0)], n_out=11)
    assert o.ok
    return s, o


def test_a_start_that_does_not_converge_is_a_status(linear_orbit):
    """A start the first corrector cannot converge under the options (tol 1e-30 in one
    Newton iteration) is a branch with status ``not_converged``, no points, ``stop =
    "start"`` and the corrector's message (never an exception)."""
    s, o = linear_orbit
    br = rd.continuation(s, "speed_hz", (50.0, 80.0), o, unbalances=[(3, 1e-3, 30.0)],
                         method=HB, harmonics=2, tol=1e-30, max_iter=1)
    assert br.status == "not_converged" and br.stop == "start" and len(br) == 0
    assert "did not converge in 1 Newton iterations" in br.message


@pytest.mark.parametrize("kw, field", [
    (dict(method="collocation"), "method"),
    (dict(method=HB, harmonics=0), "harmonics"),
    (dict(method=HB, harmonics=2, time_points=4), "time_points"),
    (dict(method=HB, floquet="none"), "floquet"),
    (dict(method=HB, floquet_margin=-0.1), "floquet_margin"),
    (dict(method=HB, newton="fast"), "newton"),
    (dict(harmonics=4), "harmonics"),
    (dict(floquet_margin=0.6), "floquet_margin"),  # shooting too: in [0, 0.5]
    (dict(floquet_tol=1e-3), "floquet_tol"),  # shooting: refines floquet="samples" only
    (dict(method=HB, floquet_tol=0.6), "floquet_tol"),
    (dict(method=HB, floquet_tol=-1e-3), "floquet_tol"),
    (dict(method=HB, floquet="hill", floquet_tol=1e-3), "floquet_tol"),
    (dict(method=HB, floquet="flow", floquet_tol=1e-3), "floquet_tol"),
    (dict(method=HB, harmonics=8), "start"),  # 10 samples per period < 2H + 1
])
def test_bad_input_names_the_field(linear_orbit, kw, field):
    s, o = linear_orbit
    with pytest.raises(InputError, match=field):
        rd.continuation(s, "speed_hz", (50.0, 80.0), o, unbalances=[(3, 1e-3, 30.0)], **kw)


SWEEP = """schema = "rotordyn/sweep/1"
name = "lc-rig"
model = "paper-rig"
analysis = "limit_cycle"
chunk_size = 1

[grid]
"bearings.active.n_circ" = 36
"bearings.active.n_axial" = 6
config_ay_m = -1.85e-3
chamber_pressure_pa = [0.05e6, 0.055e6, 0.06e6]
speed_hz = 50.0

[options]
vary = "chamber_pressure_pa"
rtol = 1e-6
ds = 0.1
ds_max = 0.3
sensitivity_rtol = 1e-4
max_points = 40
{options}
"""


def _sweep_spec(tmp_path, options, name="s.toml"):
    p = tmp_path / name
    p.write_text(SWEEP.format(options=options))
    return p


def test_limit_cycle_sweep_by_harmonic_balance(tmp_path):
    """``options.method = "harmonic_balance"``: the rig's line over p_c (36 × 6 film, a_y =
    −1.85 mm, 50 Hz; Hopf point 57.49 kPa) by HB — the branch's correctors and the cycle at
    each grid value — against the same sweep by shooting (Broyden correctors, tol 1e-4): the
    same Hopf record, the same statuses (cycles at 50 and 55 kPa, ``no_cycle`` at 60 kPa above
    the Hopf point), the same stability and bistability flags; the amplitude within 1e-3 of
    the clearance, the period within 1e-4, |μ_c| within 5e-3 (measured 3.9e-4 c, 2.5e-5,
    1.0e-3: HB's accuracy on this grid, rig test above, plus the shooting rows' tol / (1 −
    |μ_c|)); every cycle row says its method. The two specs' hashes differ."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep
    from rotordyn.sweep.spec import SweepSpec

    specs = {"hb": _sweep_spec(tmp_path, 'method = "harmonic_balance"\ntol = 1e-6'),
             "sh": _sweep_spec(tmp_path, 'newton = "broyden"\ntol = 1e-4', name="sh.toml")}
    loaded = {k: SweepSpec.from_toml(p) for k, p in specs.items()}
    assert loaded["hb"].options["method"] == HB
    assert loaded["hb"].hash() != loaded["sh"].hash()
    frames = {}
    for k, p in specs.items():
        assert run_sweep(p, tmp_path / k, threads=1, progress=False).complete
        frames[k] = sw.open(tmp_path / k).frame
    hb, sh = frames["hb"], frames["sh"]
    hop = [f[f["record"] == "hopf"] for f in (hb, sh)]
    assert list(hop[0]["value"]) == list(hop[1]["value"])
    assert hop[0]["method"].isna().all()
    c = [f[f["record"] == "cycle"].reset_index(drop=True) for f in (hb, sh)]
    assert list(c[0]["status"]) == list(c[1]["status"]) == ["ok", "ok", "no_cycle"]
    ok = c[0]["status"] == "ok"
    assert list(c[0]["method"][ok]) == [HB, HB] and list(c[1]["method"][ok]) == ["shooting"] * 2
    for col in ("stable", "bistable", "equilibrium_stable"):
        assert list(c[0][col][ok]) == list(c[1][col][ok]), col
    assert (abs(c[0]["amplitude_c"] - c[1]["amplitude_c"])[ok] < 1e-3).all()
    assert (abs(c[0]["period_s"] / c[1]["period_s"] - 1)[ok] < 1e-4).all()
    assert (abs(c[0]["max_multiplier"] - c[1]["max_multiplier"])[ok] < 5e-3).all()


def test_limit_cycle_sweep_method_options_name_the_field(tmp_path):
    """An unknown method, ``newton`` with harmonic balance and ``harmonics`` with shooting, and
    M < 2H + 1 are InputErrors naming the option, before any solve."""
    from rotordyn.sweep.spec import SweepSpec

    for opts, field in (('method = "collocation"', "options.method"),
                        ('method = "harmonic_balance"\nnewton = "fast"', "options.newton"),
                        ("harmonics = 4", "options.harmonics"),
                        ('method = "harmonic_balance"\nharmonics = 4\ntime_points = 8',
                         "options.time_points")):
        with pytest.raises(InputError, match=field):
            SweepSpec.from_toml(_sweep_spec(tmp_path, opts))
