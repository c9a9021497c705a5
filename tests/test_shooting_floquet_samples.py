"""Shooting's monodromy from the orbit's samples (``floquet="samples"``, 2026-12-06).

The reported monodromy came only from one more flow over the converged orbit with the
sensitivities in CVODES's error test. On a flexible rotor that pass resolves the stiff bending
modes its unit-vector columns excite: on the overhung pump (tests/data/models/pump_overhung.toml,
50 Hz, 5e-4 kg·m, blocked corrector) it was 73 000 of the solve's 96 000 steps, 101 s CPU in
all against 23 s with the samples (every multiplier within 2e-5; ``python
benchmarks/bench_shooting_flexible.py --floquet``, docs/nonlinear.md). ``"samples"`` takes the
4th-order Magnus product of the films' linearisations at the orbit's samples, refined on its
trigonometric interpolant (harmonic balance's refined route); ``"none"`` reports no
multipliers and no verdict."""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
UB = [(3, 2e-4, 0.0)]


@pytest.fixture(scope="module")
def compressor():
    return rd.System.from_toml(MODELS / "compressor_plain.toml")


@pytest.fixture(scope="module")
def orbits(compressor):
    return {fq: rd.periodic_orbit(compressor, 50.0, kind="forced", unbalances=UB, rtol=1e-9,
                                  tol=1e-7, floquet=fq)
            for fq in ("flow", "samples", "none")}


def test_samples_give_the_flows_multipliers_on_a_forced_orbit(orbits):
    """The compressor on plain bearings (Reynolds with cavitation), 50 Hz: the same orbit to
    the integration's accuracy (the Newton path is the same; the flow route reports the
    orbit of its extra pass, which here the stall rule had already made the last Newton
    flow), every multiplier within 2e-6 of the
    error-controlled flow's (measured 6.4e-7; |mu_c| 0.1913777 against 0.1913771) and within
    the refinement's own estimate plus that; the estimate met floquet_tol."""
    a, b = orbits["flow"], orbits["samples"]
    assert a.ok and b.ok, (a.message, b.message)
    L = a.length_scale_m
    assert np.abs(a.r - b.r).max() < 10 * 1e-7 * L     # 10 tol of the residual scale
    d = np.abs(a.multipliers[:, None] - b.multipliers[None, :]).min(axis=1)
    assert d.max() < 2e-6
    assert abs(abs(a.critical_multiplier) - abs(b.critical_multiplier)) <= \
        b.stats["floquet_error"] + 2e-6
    s = b.stats
    assert s["floquet_route"] == "samples" and a.stats["floquet_route"] == "flow"
    assert s["floquet_converged"] and s["floquet_resolved"] and b.stability_resolved
    assert s["floquet_error"] <= 1e-3 * max(1.0, abs(b.critical_multiplier))
    # 200 samples, then at least one refined level (each doubles the linearisations)
    assert s["floquet_steps"] >= 200 and s["floquet_linearizations"] >= 400
    assert b.stable == a.stable and b.critical_type == a.critical_type
    assert "±" in repr(b) and "stable" in repr(b)
    assert a.stats["monodromy_rtol"] == 1e-9 and b.stats["monodromy_rtol"] == 0.0


def test_none_reports_the_orbit_without_a_verdict(orbits):
    a, c = orbits["flow"], orbits["none"]
    assert c.ok and np.abs(a.r - c.r).max() < 10 * 1e-7 * a.length_scale_m
    assert c.multipliers.size == 0 and c.monodromy.size == 0
    assert not c.stability_resolved and "stability unresolved" in repr(c)
    assert c.critical_multiplier is None
    assert not c.to_frame().stability_resolved.any()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ax, _ = c.plot()   # no verdict: neither the stable blue nor the unstable red
    assert ax.lines[1].get_color() == "tab:gray"
    assert "unresolved" in ax.get_legend().get_texts()[1].get_text()
    plt.close("all")
    assert orbits["samples"].to_frame().stability_resolved.all()


def test_samples_on_a_limit_cycle_refine_until_the_trivial_multiplier_is_one():
    """An autonomous cycle (the paper rig's whirl at a_y = -1.85 mm, 0.05 MPa, full film on a
    36 x 6 grid, as tests/test_periodic.py). The shooting orbit is the integrator's, so its
    trivial multiplier must be 1: the refinement goes on until it is within floquet_tol
    (stopping on |mu_c|'s move alone left it 0.07 off at 3,200 steps with |mu_c| 2.8e-4 off the
    flow's; now 12,800 steps, 3.2e-4 and 1.3e-6). The critical multiplier within 1e-4 of the
    flow's, the error estimate at least the trivial one's distance, the verdict resolved."""
    rig = rd.models.paper_rig()
    b = rig.bearings[0]
    rig = dataclasses.replace(rig, bearings=(dataclasses.replace(
        b, cavitation="none", n_circ=36, n_axial=6),) + tuple(rig.bearings[1:]))
    tr = rd.transient(rig, 1.5, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=7501)
    kw = dict(start=tr, rtol=1e-9, atol_m=1e-12, tol=1e-8)
    a = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, **kw)
    s = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, floquet="samples", **kw)
    assert a.ok and s.ok, (a.message, s.message)
    assert s.trivial_index >= 0
    assert abs(s.trivial_multiplier - 1) <= 1e-3
    assert abs(abs(s.critical_multiplier) - abs(a.critical_multiplier)) < 1e-4
    err = s.stats["floquet_error"]
    assert abs(s.trivial_multiplier - 1) <= err
    assert s.stats["floquet_converged"] and s.stability_resolved and s.stable == a.stable


def test_bad_floquet_options_name_the_field(compressor):
    kw = dict(kind="forced", unbalances=UB)
    with pytest.raises(InputError, match="floquet"):
        rd.periodic_orbit(compressor, 50.0, floquet="hill", **kw)  # harmonic balance only
    with pytest.raises(InputError, match="floquet_tol"):
        rd.periodic_orbit(compressor, 50.0, floquet="samples", floquet_tol=0.0, **kw)
    with pytest.raises(InputError, match="floquet_max_steps"):
        rd.periodic_orbit(compressor, 50.0, floquet="samples", floquet_max_steps=-1, **kw)


def test_cli_floquet_with_shooting(capsys):
    model = str(MODELS / "compressor_plain.toml")
    base = ["periodic-orbit", model, "--kind", "forced", "--unbalance", "3,2e-4,0",
            "--speed-hz", "50", "--json"]
    assert main(base + ["--floquet", "samples", "--floquet-tol", "1e-3"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "ok" and out["method"] == "shooting"
    assert out["floquet"] == "samples" and out["stats"]["floquet_route"] == "samples"
    assert out["stability_resolved"] is True
    assert main(base + ["--floquet", "hill"]) == 2
    assert "--floquet: with --method shooting expected one of flow, samples, none, got " \
        "'hill'" in capsys.readouterr().err
    assert main(base + ["--floquet-tol", "1e-3"]) == 2
    assert "--floquet-tol: applies only to --floquet samples" in capsys.readouterr().err
