"""Continuation of static equilibria (rotordyn.continuation with start="equilibrium",
analysis/equilibrium_branch.py; docs/nonlinear.md "Continuation of equilibria").

Guards: the Hopf point located on a branch equals the threshold machinery's (rd.hopf /
rd.threshold: Brent on max Re λ at fixed parameter, an independent route — the branch refines
by Brent on its arclength); the branch's points are the equilibria rd.equilibrium finds at
the same parameter; a branch over a model field (a clearance) whose Hopf point is checked by
the threshold in speed on the system with that field value; a failed equilibrium ends the
branch with its status and is never linearised; bad input names the field.

Model: the compressor on two plain bearings (tests/data/models/compressor_plain.toml) on a
36 x 6 film grid (Hopf speed 126.5 Hz), and the paper rig on 36 x 6 for the p_c branch with
two crossings. Tolerances: rd.threshold's default xtol is 1e-6 of its bounds' span (5e-5 Hz
over 100-150 Hz, 0.3 Pa over 0-0.3 MPa); the branch refines to 1e-12 in the arclength, so
the two agree within the threshold's xtol. A branch point and a direct equilibrium are the
same root polished by the core (to round-off); 1e-9 c is the equilibrium tolerance 1e-10 of
the load times the films' compliance, with margin.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.model.paths import set_field
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def compressor():
    return coarse_models.compressor_plain()


@pytest.fixture(scope="module")
def speed_branch(compressor):
    return rd.continuation(compressor, "speed_hz", (100.0, 150.0), start="equilibrium")


def test_speed_branch_hopf_equals_threshold(compressor, speed_branch):
    br = speed_branch
    assert br.ok and br.stop == "bound" and isinstance(br, rd.EquilibriumBranchResult)
    assert br.parameter[0] == 100.0 and br.parameter[-1] == pytest.approx(150.0, abs=1e-12)
    hopfs = [b for b in br.bifurcations if b["kind"] == "hopf"]
    assert len(hopfs) == 1 and hopfs[0]["refined"]
    h = rd.hopf(compressor, "speed_hz", bounds=(100.0, 150.0))
    assert h.ok
    assert hopfs[0]["parameter"] == pytest.approx(h.value, abs=5e-5)
    assert hopfs[0]["smooth"]
    assert hopfs[0]["whirl_frequency_hz"] == pytest.approx(h.whirl_frequency_hz, abs=1e-3)
    assert abs(hopfs[0]["eigenvalue"].real) < 1e-6
    # stable below, unstable above; max Re λ changes sign at the same index
    i = hopfs[0]["index"]
    assert br.stable[:i].all() and not br.stable[i:].any()
    assert br.max_real_1_per_s[i - 1] < 0 < br.max_real_1_per_s[i]
    assert br.parameter[i - 1] < h.value < br.parameter[i]
    assert np.all(np.diff(br.parameter) > 0)  # no fold of equilibria on this branch
    assert not [b for b in br.bifurcations if b["kind"] != "hopf"]


def test_points_equal_direct_equilibria(compressor, speed_branch):
    br = speed_branch
    c = compressor.bearings[0].clearance_m
    for i in (0, 5, len(br) // 2, len(br) - 1):
        e = rd.equilibrium(compressor, float(br.parameter[i]))
        assert e.status == "ok"
        assert np.abs(np.asarray(e.r) - br.r[i]).max() < 1e-9 * c
        np.testing.assert_allclose(br.eccentricity_ratio[i], e.eccentricity_ratio, atol=1e-9)
        st = rd.stability(compressor, float(br.parameter[i]))
        assert br.max_real_1_per_s[i] == pytest.approx(float(st.eigenvalues.real.max()),
                                                       abs=1e-6)
    df = br.to_frame()
    assert len(df) == 2 * len(br)
    for col in ("point", "bearing", "speed_hz", "eccentricity_ratio", "max_real_1_per_s",
                "stable", "bifurcation", "status"):
        assert col in df
    assert set(df["status"]) == {"ok"}
    bf = br.bifurcations_frame()
    assert list(bf["kind"]) == ["hopf", "hopf"]  # one row per bearing
    import matplotlib

    matplotlib.use("Agg")
    ax = br.plot()
    assert ax.get_xlabel().startswith("speed")
    assert "hopf" in repr(br)


def test_model_field_branch_clearance(compressor):
    """Both bearings' clearance from 100 µm down at 130 Hz (above the Hopf speed): the
    equilibrium restabilises at one Hopf point, where rd.threshold in speed on the system
    with that clearance finds 130 Hz (an independent route through the same linearisation)."""
    path = "bearings.*.clearance_m"
    br = rd.continuation(compressor, path, (0.6e-4, 1.0e-4), speed_hz=130.0, direction=-1,
                         ds=0.05, ds_max=0.1)
    assert br.ok and br.stop == "bound" and br.parameter[-1] == pytest.approx(0.6e-4)
    hp = br.hopf_points()
    assert len(hp) == 1
    # a scan node on the root itself (130 Hz of 120-140 Hz): after the tests before this one
    # its re-evaluation differed in the last bits and made Brent's bracket fail (status
    # error); the bracket now keeps the scan's own end values
    th = rd.threshold(set_field(compressor, path, hp[0]), "speed_hz", bounds=(120.0, 140.0))
    assert th.status == "ok", th.message
    assert th.value == pytest.approx(130.0, abs=2e-4)
    assert not br.stable[0] and br.stable[-1]
    e = rd.equilibrium(set_field(compressor, path, float(br.parameter[2])), 130.0)
    assert np.abs(np.asarray(e.r) - br.r[2]).max() < 1e-9 * 1e-4
    assert "clearance_m" in br.to_frame().columns[2]


@pytest.fixture(scope="module")
def coarse_rig():
    return coarse_models.paper_rig()


def test_rig_pressure_branch_two_crossings(coarse_rig):
    """The rig at a_y = −1.85 mm, 50 Hz (36 x 6 film): over p_c the equilibrium is unstable
    between two Hopf points (the Fig. 9 lobe); both equal rd.threshold's crossings, and both
    are smooth crossings."""
    rig = coarse_rig
    br = rd.continuation(rig, "chamber_pressure_pa", (0.0, 0.1e6), speed_hz=50.0,
                         config_ay_m=-1.85e-3)
    th = rd.threshold(rig, bounds=(0.0, 0.1e6), speed_hz=50.0, config_ay_m=-1.85e-3)
    assert len(th.crossings) == 2
    np.testing.assert_allclose(br.hopf_points(), th.crossings, atol=0.1)
    i, j = (b["index"] for b in br.bifurcations)
    assert br.stable[:i].all() and not br.stable[i:j].any() and br.stable[j:].all()
    assert all(b["smooth"] for b in br.bifurcations)


def test_rig_speed_branch_non_smooth_crossing(coarse_rig):
    """The rig at a_y = 0, 0.4 MPa on the 36 x 6 film: max Re λ jumps from −0.006 to +0.33
    1/s at 112.797 Hz (a node of the film changes its cavitation state; measured by
    rd.stability at 112.79701 and 112.7971 Hz): the branch locates it where rd.threshold does
    and reports it as a non-smooth Hopf crossing, with both sides' values."""
    br = rd.continuation(coarse_rig, "speed_hz", (20.0, 150.0), chamber_pressure_pa=0.4e6,
                         config_ay_m=0.0)
    (b,) = br.bifurcations
    assert b["kind"] == "hopf" and b["refined"] and not b["smooth"]
    assert b["parameter"] == pytest.approx(112.797, abs=1e-3)
    lo, hi = b["jump"]
    assert -0.01 < lo < 0 and 0.3 < hi < 0.36
    assert "non-smooth" in repr(br) and "non-smooth" in b["message"]
    assert not br.bifurcations_frame()["smooth"].any()


def test_failed_equilibrium_ends_the_branch(compressor, monkeypatch):
    """A point whose equilibrium fails ends the branch with that status: no point beyond,
    nothing linearised there."""
    import rotordyn.analysis.equilibrium_branch as eb

    real = eb.equilibrium
    calls = []

    def failing(system, speed_hz, *a, **kw):
        e = real(system, speed_hz, *a, **kw)
        if speed_hz > 110.0:
            return dataclasses.replace(e, status="not_converged", message="forced failure")
        calls.append(speed_hz)
        return e

    monkeypatch.setattr(eb, "equilibrium", failing)
    lin = []
    real_lin = eb._linear_from
    monkeypatch.setattr(eb, "_linear_from", lambda asm, e, *a: (lin.append(e.status),
                                                                real_lin(asm, e, *a))[1])
    br = rd.continuation(compressor, "speed_hz", (100.0, 150.0))
    assert br.ok and br.stop == "not_converged" and "forced failure" in br.message
    assert br.parameter.max() <= 110.0 and len(br) >= 2
    assert set(lin) == {"ok"} and len(lin) == len(br)
    # a failed start: the status, no points
    monkeypatch.setattr(eb, "equilibrium", lambda *a, **kw: dataclasses.replace(
        real(*a, **kw), status="no_equilibrium", message="closed"))
    br = rd.continuation(compressor, "speed_hz", (100.0, 150.0))
    assert br.status == "no_equilibrium" and len(br) == 0 and "closed" in br.message
    assert "no points" in repr(br)


def test_bad_input_names_the_field(compressor):
    with pytest.raises(rd.InputError, match="vary"):
        rd.continuation(compressor, "clearance", (1e-4, 2e-4))
    with pytest.raises(rd.InputError, match="vary"):
        rd.continuation(compressor, "bearings.0.clearence_m", (1e-4, 2e-4))
    with pytest.raises(rd.InputError, match="vary"):
        rd.continuation(compressor, "bearings.7.clearance_m", (1e-4, 2e-4))
    with pytest.raises(rd.InputError, match="bounds"):
        rd.continuation(compressor, "speed_hz", (150.0, 100.0))
    with pytest.raises(rd.InputError, match="bounds"):
        rd.continuation(compressor, "bearings.*.clearance_m", (2e-4, 3e-4))  # start outside
    with pytest.raises(rd.InputError, match="bounds"):
        rd.continuation(compressor, "speed_hz", (-10.0, 100.0))
    with pytest.raises(rd.InputError, match="rtol"):
        rd.continuation(compressor, "speed_hz", (100.0, 150.0), rtol=1e-6)
    with pytest.raises(rd.InputError, match="start"):
        rd.continuation(compressor, "speed_hz", (100.0, 150.0), start="cycle")
    with pytest.raises(rd.InputError, match="ds"):
        rd.continuation(compressor, "speed_hz", (100.0, 150.0), ds=0.0)
    with pytest.raises(rd.InputError, match="direction"):
        rd.continuation(compressor, "speed_hz", (100.0, 150.0), direction=0)


def test_a_bound_that_closes_the_film_is_a_change_not_an_error(compressor):
    """The "does the field act" check linearises the films at both bounds: at a clearance of
    1 µm the start's journal position closes the film. That counts as a change (as for
    orbit branches); it raised a bare ContactError from the check before any branch point."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the 1 µm clearance's plausibility warning
        br = rd.continuation(compressor, "bearings.*.clearance_m", (1e-6, 1e-4),
                             speed_hz=130.0, direction=-1)
    assert br.status == "ok" and len(br.to_frame()) > 3
