"""Branches of limit cycles over a model field (``rd.continuation(system,
"bearings.*.viscosity_pa_s", bounds, orbit, method="harmonic_balance")``,
the core's corrector with the systems of analysis/hb_field.py; docs/nonlinear.md "Branches
over a model field"), the threshold and
the Hopf point over a field, and the cycles born there (analysis/hopf.py ``hopf_branch``).

Model: the compressor on two plain bearings (tests/data/models/compressor_plain.toml) on a
36 x 6 film grid at 130 Hz, above its Hopf speed (126.5 Hz): the oil-whip cycle (0.9 c).

References (independent routes):
* each branch point against the orbit solved on the model rebuilt with that field value
  (``set_field``), by harmonic balance from the point's state (same discretisation: agreement
  to the correctors' tolerance) and by shooting (CVODES flow, an independent method: the
  H = 8 truncation, measured 1.1e-3 … 2.4e-3 c on these whip cycles in test_hb_continuation);
* the Hopf point over the clearance against Brent's method on max Re λ of ``rd.stability``
  over models rebuilt at each clearance (written here, not the library's threshold);
* the first cycles from the Hopf point against the normal form's amplitude
  sqrt(coefficient · |p − p_H|) (leading order: the error is O(|p − p_H|)).
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import rotordyn as rd
from rotordyn.analysis.hopf import hopf_branch
from rotordyn.cli import main
from rotordyn.errors import InputError
from rotordyn.model.paths import set_field
import coarse_models  # noqa: E402

HB = "harmonic_balance"
MODELS = Path(__file__).parent / "data" / "models"
VISC = "bearings.*.viscosity_pa_s"
CLEAR = "bearings.*.clearance_m"
SPEED = 130.0


@pytest.fixture(scope="module")
def compressor():
    return coarse_models.compressor_plain()


@pytest.fixture(scope="module")
def whip(compressor):
    """The oil-whip cycle at 130 Hz by HB from a 0.4 s transient (as test_hb_continuation)."""
    tr = rd.transient(compressor, 0.4, SPEED, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(compressor, SPEED, start=tr, method=HB, tol=1e-8)
    assert cyc.ok and cyc.stable, cyc.message
    return cyc


def _spectrum(o, harmonics=8) -> np.ndarray:
    """(H + 1, n) the magnitudes of each coordinate's harmonics 0…H over one period (from the
    equally spaced samples, the repeated endpoint left out): independent of the phase, which
    an autonomous orbit does not fix."""
    z = np.fft.rfft(np.asarray(o.r)[:-1], axis=0) / (len(o.t) - 1)
    return np.abs(z[:harmonics + 1])


def _visc_branch(compressor, whip, max_points=4):
    return rd.continuation(compressor, VISC, (0.010, 0.025), whip, method=HB, tol=1e-10,
                           ds=0.1, ds_max=0.2, max_points=max_points, rtol=1e-6,
                           sensitivity_rtol=1e-5)


@pytest.fixture(scope="module")
def visc_branch(compressor, whip):
    return _visc_branch(compressor, whip)


def test_viscosity_branch_equals_orbits_of_rebuilt_models(compressor, visc_branch):
    """Every point of the branch over both viscosities (0.018 → 0.0247 Pa·s) against the
    orbit on the model rebuilt with that viscosity, by harmonic balance from the point's state
    (tol 1e-10, multipliers by the flow): the magnitude of every harmonic of every coordinate
    (the phase of a cycle is free) within 3e-5 c, the period within 1e-5, |μ_c| within 1e-3.
    Measured: 1.0e-5, 6.4e-6, 1.3e-6, 3.7e-7 c; periods 1.6e-6 … 1.5e-7; |μ_c| 1.0e-4 …
    1.5e-4. The baseline is the start point itself (no field change: 1.0e-5 c, the same on a
    speed branch): an HB solve from a state lands that far from the branch's cycle on this
    cavitated film. The field acts: the amplitude changes by more than 100 × the tolerance
    along the branch. (HB against shooting on these whip cycles: test_hb_continuation.)"""
    br = visc_branch
    c = compressor.bearings[0].clearance_m
    assert br.ok and br.stop in ("bound", "max_points") and len(br) == 4, br.message
    assert br.vary == VISC and br.parameter[0] == pytest.approx(0.018)
    assert np.all(np.diff(br.parameter) > 0)
    assert br.stats["method"] == HB and br.stats["assemblies"] > len(br)
    for i, o in enumerate(br.orbits):
        assert o.stats["field"] == VISC and o.stats["field_value"] == br.parameter[i]
        s_i = set_field(compressor, VISC, float(br.parameter[i]))
        ref = rd.periodic_orbit(s_i, SPEED, start=(o.r[0], o.v[0]), period_s=o.period_s,
                                method=HB, tol=1e-10, n_out=len(o.t), floquet="flow",
                                rtol=1e-6, sensitivity_rtol=1e-5)
        assert ref.ok, ref.message
        dev = np.abs(_spectrum(o) - _spectrum(ref)).max() / c
        assert dev < 3e-5, dev
        assert br.period_s[i] == pytest.approx(ref.period_s, rel=1e-5)
        assert br.max_multiplier[i] == pytest.approx(abs(ref.critical_multiplier), abs=1e-3)
    assert abs(br.amplitude_m[-1, 0] - br.amplitude_m[0, 0]) > 100 * 3e-5 * c
    df = br.to_frame()
    assert VISC in df.columns and len(df) == 2 * len(br)


def test_same_answer_twice(compressor, whip, visc_branch):
    """Determinism: the branch again (after other branches and rebuilt models ran) is the
    same to the last bit."""
    again = _visc_branch(compressor, whip, max_points=3)
    n = len(again)
    assert n == 3
    for name in ("parameter", "amplitude_m", "period_s", "max_multiplier", "arclength"):
        assert np.array_equal(getattr(again, name), getattr(visc_branch, name)[:n]), name


@pytest.fixture(scope="module")
def clearance_hopf(compressor):
    """The equilibrium branch over both clearances at 130 Hz from 100 µm down: one Hopf
    point (test_equilibrium_branch), refined by Brent on the arclength."""
    br = rd.continuation(compressor, CLEAR, (0.6e-4, 1.0e-4), speed_hz=SPEED, direction=-1,
                         ds=0.05, ds_max=0.1)
    assert br.ok
    hp = [b for b in br.bifurcations if b["kind"] == "hopf"]
    assert len(hp) == 1 and hp[0]["refined"] and hp[0]["smooth"]
    return hp[0]


def test_hopf_over_clearance_equals_bisection_of_rebuilt_models(compressor, clearance_hopf):
    """The Hopf point of the equilibrium branch over the clearance equals the root of max
    Re λ (rd.stability on the model rebuilt at each clearance, Brent to 1e-13 m) within
    1e-11 m (1e-7 c; measured 2e-13 m), and rd.threshold over the field (its scan and Brent
    over rebuilt models) within its xtol (4e-11 m). The HopfResult there has the branch's
    whirl frequency."""
    def max_re(c):
        st = rd.stability(set_field(compressor, CLEAR, float(c)), SPEED)
        assert st.status == "ok"
        return float(st.eigenvalues.real.max())

    root = brentq(max_re, 0.9e-4, 1.0e-4, xtol=1e-13, rtol=1e-13)
    assert abs(clearance_hopf["parameter"] - root) < 1e-11
    th = rd.threshold(compressor, CLEAR, bounds=(0.6e-4, 1.0e-4), speed_hz=SPEED)
    assert th.status == "ok" and th.stable_side == "below"
    assert th.value == pytest.approx(root, abs=th.xtol)
    h = rd.hopf(compressor, CLEAR, at=clearance_hopf["parameter"], speed_hz=SPEED)
    assert h.ok and h.vary == CLEAR and h.fixed["speed_hz"] == SPEED
    assert h.whirl_frequency_hz == pytest.approx(clearance_hopf["whirl_frequency_hz"],
                                                 abs=1e-4)
    assert h.clearance_m == pytest.approx([clearance_hopf["parameter"]] * 2, rel=1e-12)


def test_cycles_born_at_the_hopf_point_over_clearance(compressor, clearance_hopf):
    """From the Hopf point over the clearance (l1 < 0 here: small stable cycles at larger
    clearance, on the unstable side): hopf_branch's first cycle 1e-10 m from the point has
    the normal form's amplitude within 3 % (measured 1.7 %) and the whirl period within 1e-3;
    along the branch the amplitude grows and every point is the orbit of the model rebuilt
    with its clearance (HB from the point's state: every harmonic's magnitude within 5e-3 of
    the cycle's amplitude, measured 7.9e-4; the radial multiplier is 1 − 1e-5 here, so the
    amplitude moves by the solver's tolerance over 1 − |μ|)."""
    h = rd.hopf(compressor, CLEAR, at=clearance_hopf["parameter"], speed_hz=SPEED)
    assert h.cycle_side == "above" and h.type == "supercritical"
    br = hopf_branch(compressor, h, (0.8e-4, 1.0e-4), distance=1e-10, max_points=3,
                     tol=1e-8)
    assert br.ok and len(br) == 3 and br.stats["method"] == HB, br.message
    # shooting over a field is refused before the first cycle is solved (it was refused by
    # the continuation only after a shooting solve of that cycle)
    with pytest.raises(InputError, match=r"^method: a branch over the model field "):
        hopf_branch(compressor, h, (0.8e-4, 1.0e-4), distance=1e-10, method="shooting")
    p0 = br.parameter[0]
    assert p0 == pytest.approx(h.value + 1e-10, abs=1e-15)
    assert br.amplitude_m[0, 0] == pytest.approx(h.amplitude(p0), rel=0.03)
    assert br.period_s[0] == pytest.approx(1 / h.whirl_frequency_hz, rel=1e-3)
    assert np.all(np.diff(br.amplitude_m[:, 0]) > 0)
    for i in (1, 2):
        o = br.orbits[i]
        ref = rd.periodic_orbit(set_field(compressor, CLEAR, float(br.parameter[i])), SPEED,
                                start=(o.r[0], o.v[0]), period_s=o.period_s, method=HB,
                                tol=1e-10, n_out=len(o.t))
        assert ref.ok, ref.message
        amp = np.abs(o.r - o.r.mean(0)).max()
        assert np.abs(_spectrum(o) - _spectrum(ref)).max() < 5e-3 * amp


# ------------------------------------------------------------------------------ bad input
@pytest.mark.parametrize("vary, match", [
    ("bearings.0.clearence_m", r"^vary: unknown parameter 'bearings.0.clearence_m'"),
    ("bearings.7.clearance_m", r"^vary: unknown parameter 'bearings.7.clearance_m'"),
    ("bearings.0.cavitation", r"^vary: unknown parameter 'bearings.0.cavitation'"),
    ("bearings.0.n_circ", r"^vary: bearings.0.n_circ is an integer field"),
    ("bearings.0.station", r"^vary: bearings.0.station is an integer field"),
])
def test_bad_field_names_the_field(compressor, whip, vary, match):
    """An unknown path, a text field, an integer field (not continuous): InputError naming
    ``vary`` and the path, before any orbit is solved."""
    with pytest.raises(InputError, match=match):
        rd.continuation(compressor, vary, (0.0, 1.0), whip, method=HB)


def test_field_that_does_not_act_names_the_field(compressor, whip):
    """A disk's diameter with its mass and inertias given changes nothing of eq. 12 (the
    branch would be one point repeated): InputError naming ``vary``."""
    disks = tuple(dataclasses.replace(d, outer_diameter_m=0.4) for d in compressor.rotor.disks)
    s = dataclasses.replace(compressor, rotor=dataclasses.replace(compressor.rotor,
                                                                  disks=disks))
    with pytest.raises(InputError, match=r"^vary: rotor.disks.0.outer_diameter_m does not "
                                         "act on the model"):
        rd.continuation(s, "rotor.disks.0.outer_diameter_m", (0.3, 0.5), whip, method=HB)


def test_field_branch_refuses_shooting_and_bounds_without_the_start(compressor, whip):
    with pytest.raises(InputError, match=r"^method: a branch over the model field "
                                         r"bearings.\*.viscosity_pa_s has harmonic-balance "
                                         r"correctors only \(method='harmonic_balance'"):
        rd.continuation(compressor, VISC, (0.01, 0.03), whip)
    with pytest.raises(InputError, match=r"^bounds: .* must contain the start's "
                                         r"bearings.\*.viscosity_pa_s = 0.018"):
        rd.continuation(compressor, VISC, (0.02, 0.03), whip, method=HB)
    mixed = set_field(compressor, "bearings.0.viscosity_pa_s", 0.02)
    with pytest.raises(InputError, match=r"^vary: bearings.\*.viscosity_pa_s selects fields "
                                         "with different values"):
        rd.continuation(mixed, VISC, (0.01, 0.03), whip, method=HB)
    with pytest.raises(InputError, match=r"^bounds: the model refuses"):
        rd.continuation(compressor, CLEAR, (-1e-4, 2e-4), whip, method=HB)


def test_cli_continuation_over_a_field(compressor, whip, visc_branch, tmp_path, capsys):
    """``rotordyn continuation --vary bearings.*.viscosity_pa_s --method harmonic_balance``:
    the start cycle from a 0.4 s settling transient, then the branch; its points are the API
    branch's within 1e-6 c in amplitude (both start on the same whip cycle, measured ≤ 1e-9 c);
    shooting with a field exits 2 naming --method."""
    model = tmp_path / "compressor_36x6.toml"
    compressor.to_toml(model)
    args = ["continuation", str(model), "--vary", VISC, "--bounds", "0.010", "0.025",
            "--speed-hz", "130", "--settle-s", "0.4", "--disturbance-c", "0.6",
            "--ds", "0.1", "--max-points", "3", "--tol", "1e-8", "--rtol", "1e-6", "--json"]
    assert main(args + ["--method", HB]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["status"] == "ok" and rec["vary"] == VISC and rec["method"] == HB
    p = np.asarray(rec["parameter"])
    assert len(p) == 3 and p[0] == pytest.approx(0.018)
    c = compressor.bearings[0].clearance_m
    amp = np.asarray(rec["amplitude_m"])[:, 0]
    assert abs(amp[0] - visc_branch.amplitude_m[0, 0]) < 1e-6 * c
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith("rotordyn: error: --method:") and VISC in err


def test_cli_continuation_from_the_hopf_point_over_a_field(compressor, clearance_hopf,
                                                           tmp_path, capsys):
    """``rotordyn continuation --start hopf --vary bearings.*.clearance_m``: the Hopf point of
    the threshold in --bounds (the equilibrium branch's within 1e-11 m), harmonic-balance
    correctors without --method (a field has no others), the first cycle at --hopf-distance
    on the cycles' side; the start flags of an orbit are refused, --hopf-distance elsewhere
    too."""
    model = tmp_path / "compressor_36x6.toml"
    compressor.to_toml(model)
    args = ["continuation", str(model), "--start", "hopf", "--vary", CLEAR, "--bounds",
            "9e-5", "1e-4", "--speed-hz", "130", "--hopf-distance", "1e-10",
            "--max-points", "3", "--tol", "1e-8", "--rtol", "1e-6"]
    assert main(args + ["--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["status"] == "ok" and rec["start"] == "hopf" and rec["method"] == HB
    assert abs(rec["hopf"]["value"] - clearance_hopf["parameter"]) < 1e-11
    assert rec["hopf"]["cycle_side"] == "above"
    assert rec["parameter"][0] == pytest.approx(rec["hopf"]["value"] + 1e-10, abs=1e-15)
    assert len(rec["parameter"]) == 3
    assert main(args + ["--settle-s", "0.1"]) == 2
    assert capsys.readouterr().err.startswith("rotordyn: error: --settle-s: does not apply "
                                              "to --start hopf")
    assert main(["continuation", str(model), "--vary", CLEAR, "--bounds", "9e-5", "1e-4",
                 "--method", HB, "--hopf-distance", "1e-10"]) == 2
    assert capsys.readouterr().err.startswith("rotordyn: error: --hopf-distance: applies "
                                              "only to --start hopf")


@pytest.mark.parametrize("vary, bounds", [("supports.*.kyy_n_per_m", (0.5e8, 3e8)),
                                          ("rotor.disks.1.mass_kg", (10.0, 60.0))])
def test_forced_branch_over_a_field_is_the_closed_form(vary, bounds):
    """The unbalance-forced orbit of the compressor on linear supports (H = 1, tol 1e-11)
    continued over the supports' vertical stiffness (K) or an impeller's mass (M): every
    point equals the closed form on the model rebuilt with its value (tests/orbit_forms.py)
    within 1e-10 of the amplitude (measured ≤ 1.2e-14), while the field moves the orbit by
    1–14 % of it along the branch (the closed form of the unchanged model is off by that)."""
    from orbit_forms import forced_orbit

    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    ub = [(3, 1e-3, 30.0)]
    o = rd.periodic_orbit(s, 60.0, kind="forced", unbalances=ub, method=HB, harmonics=1,
                          tol=1e-12)
    br = rd.continuation(s, vary, bounds, o, unbalances=ub, method=HB, harmonics=1,
                         tol=1e-11, ds=0.05, max_points=4)
    assert br.ok and len(br) == 4 and br.kind == "forced" and np.all(np.diff(br.parameter) > 0)
    moved = []
    for p, pt in zip(br.parameter, br.orbits):
        r_exact, _ = forced_orbit(set_field(s, vary, float(p)), pt.speed_hz, pt.t, ub)
        scale = np.abs(r_exact).max()
        assert np.abs(pt.r - r_exact).max() < 1e-10 * scale
        r_fixed, _ = forced_orbit(s, pt.speed_hz, pt.t, ub)
        moved.append(np.abs(r_fixed - r_exact).max() / scale)
    assert moved[0] == 0.0 and min(moved[1:]) > 1e-2


def test_threshold_over_a_field_refuses_a_bound_the_model_refuses(compressor):
    with pytest.raises(InputError, match=r"^bounds: the model refuses bearings.\*.clearance_m"):
        rd.threshold(compressor, CLEAR, bounds=(-1e-4, 1e-4), speed_hz=SPEED)
    with pytest.raises(InputError, match=r"^vary: bearings.0.n_axial is an integer field"):
        rd.hopf(compressor, "bearings.0.n_axial", bounds=(4, 8), speed_hz=SPEED)


def test_core_corrector_asks_the_field_systems():
    """The core's corrector over a field gets each system from the Python provider
    (``field_systems``): a value the model refuses (an impeller mass < 0) is the step's status
    with the model's message, a provider that raises passes its exception through the core
    call, and at an accepted value the step converges on the rebuilt model (the forced orbit
    of the compressor on linear supports, H = 1: its closed form there within 1e-10 of the
    amplitude, measured 2.2e-15), with ∂R/∂p by two residual evaluations per Newton iteration."""
    from orbit_forms import forced_orbit
    from rotordyn import _core
    from rotordyn.analysis.hb_continuation import corrector_options, start_coefficients
    from rotordyn.analysis.hb_field import field_systems
    from rotordyn.analysis.orbit_branch import prepare

    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    ub = [(3, 1e-3, 30.0)]
    o = rd.periodic_orbit(s, 60.0, kind="forced", unbalances=ub, method=HB, harmonics=1,
                          tol=1e-12)
    vary = "rotor.disks.1.mass_kg"
    setup = prepare(s, vary, (10.0, 60.0), o, ub, None, 11)
    z, w = start_coefficients(o, 1), 2 * np.pi * 60.0
    inp = _core.HbContinuationInput()
    inp.base, inp.coefficients, inp.frequency = setup.base, z, w
    inp.scale = np.array([float(o.length_scale_m), w, 50.0])
    opt = corrector_options(1, 4, 1e-11, 20, "samples", 0.01, 1e-8, 1e-9, w, 10000)

    def step(system_at, p):
        inp.p, inp.y_prev = p, np.concatenate([z.ravel(), [w, p]])
        return _core.hb_continuation_step(system_at, inp, opt)

    bad = step(field_systems(setup), -5.0)
    assert bad.hb.orbit.status == "not_converged" and len(bad.tangent) == 0
    assert bad.hb.orbit.message.startswith("harmonic balance at the predicted point: the "
                                           f"model refuses {vary} = -5: ")

    def broken(p):
        raise RuntimeError(f"no system at {p}")

    with pytest.raises(RuntimeError, match="no system at 20.0"):
        step(broken, 20.0)
    ok = step(field_systems(setup), 20.0)
    assert ok.hb.orbit.status == "ok" and ok.p == 20.0 and ok.hb.orbit.iterations >= 1
    assert ok.fd_evaluations == 2 * (ok.hb.orbit.iterations + 1)
    t = np.linspace(0.0, 2 * np.pi / w, 9)
    r_exact, _ = forced_orbit(set_field(s, vary, 20.0), 60.0, t, ub)
    basis = np.stack([np.ones_like(t), np.cos(w * t), np.sin(w * t)], axis=1)
    r = basis @ np.asarray(ok.hb.coefficients)
    assert np.abs(r - r_exact).max() < 1e-10 * np.abs(r_exact).max()


def test_cycles_at_amplitudes_refuse_a_field_hopf_point(compressor, clearance_hopf):
    h = rd.hopf(compressor, CLEAR, at=clearance_hopf["parameter"], speed_hz=SPEED)
    with pytest.raises(InputError, match=r"^result: a Hopf point over the model field "
                                         r"bearings.\*.clearance_m"):
        rd.hopf_cycles(compressor, h, (0.01,))


def test_field_branch_multipliers_by_hill(compressor, whip, visc_branch):
    """floquet="hill" on a branch over a field (Hill's method on each point's HB Jacobian on
    the rebuilt model): the same points (parameter and amplitude within 1e-9 relative: the
    correctors do not depend on the route) and Hill's |μ_c| (margin 0: no flow recheck) within
    1e-2 of the flow's (the reference branch takes the flow by the samples' rule here;
    Hill's accuracy on these whip cycles at H = 8: docs/nonlinear.md)."""
    br = rd.continuation(compressor, VISC, (0.010, 0.025), whip, method=HB, tol=1e-10,
                         ds=0.1, ds_max=0.2, max_points=4, rtol=1e-6, sensitivity_rtol=1e-5,
                         floquet="hill", floquet_margin=0.0)
    assert br.ok and len(br) == 4
    # margin 0: no point is rechecked by the flow, so Hill's |μ| is what is compared below
    assert {o.stats["floquet"] for o in br.orbits} == {"hill"}
    np.testing.assert_allclose(br.parameter, visc_branch.parameter, rtol=1e-9)
    np.testing.assert_allclose(br.amplitude_m, visc_branch.amplitude_m, rtol=1e-9)
    assert np.abs(br.max_multiplier - visc_branch.max_multiplier).max() < 1e-2
