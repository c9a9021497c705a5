"""The nonlinear unbalance response as a branch of forced periodic orbits continued over the
speed (issue 19, item 2; docs/nonlinear.md, "The rig in the speed domain").

References:
* small unbalance: the forced orbit of eq. 12 tends to the linear unbalance response
  (K_H − Ω² M + iΩ D_H) X = F at the same equilibrium (``rotordyn.unbalance_response``,
  perturbation coefficients of the same film grid); the 1× orbit's largest distance from its
  mean is the ellipse's semi-major axis, and the nonlinear correction is O(|X|/c);
* a constant-speed transient from the static equilibrium settles on the forced orbit: after
  N revolutions its last revolution equals the branch's orbit at that speed sample by sample
  (both anchored at the rotor angle Ωt, t0 = 0).
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


def _coarse(system, n_circ=36, n_axial=6):
    return dataclasses.replace(system, bearings=tuple(
        dataclasses.replace(b, n_circ=n_circ, n_axial=n_axial) for b in system.bearings))


def test_compressor_speed_branch_equals_the_linear_unbalance_response_at_small_unbalance():
    """Compressor on two plain journal bearings (36 × 6 film grid), a small unbalance at the
    middle impeller (orbits 1.6e-3 c to 5.5e-3 c): every point of the forced-orbit branch
    continued over the speed from 40 Hz to ~112 Hz (6 points, below the oil-whip threshold
    126.5 Hz) has, at both journals, the amplitude of the linear unbalance response at the
    corrector's speed within 1 % (measured: 0.27 % at most); the speeds increase, the
    period is 1/speed."""
    s = _coarse(rd.System.from_toml(MODELS / "compressor_plain.toml"))
    ub = [(3, 1e-4, 0.0)]
    o = rd.periodic_orbit(s, 40.0, kind="forced", unbalances=ub, rtol=1e-8, tol=1e-6)
    assert o.ok, o.message
    br = rd.continuation(s, "speed_hz", (35.0, 120.0), o, unbalances=ub, rtol=1e-8, tol=1e-6,
                         ds=0.2, ds_max=0.3, max_points=6, n_out=401)
    assert br.ok and len(br) == 6, br.message
    assert br.parameter[-1] > 100.0
    assert np.all(np.diff(br.parameter) > 0)
    stations = [b.station for b in s.bearings]
    lin = rd.unbalance_response(s, ub, br.parameter, stations=stations, refine=False)
    for i, orb in enumerate(br.orbits):
        assert orb.period_s == pytest.approx(1.0 / br.parameter[i], rel=1e-12)
        for b in range(len(stations)):
            assert orb.amplitude(b) < 1e-2 * orb.clearance_m[b]
            assert orb.amplitude(b) == pytest.approx(lin.major_m[i, b], rel=1e-2), (i, b)


def test_rig_speed_branch_point_equals_the_settled_transient():
    """The paper rig (36 × 6 film grid for speed) at a_y = 0, p_c = 0.4 MPa, 2e-5 kg·m at
    disk B (the docs' Fig. 13 waterfall): the second point of the forced-orbit branch
    continued over the speed from 60 Hz, against a constant-speed transient at the speed the
    corrector chose, from the static equilibrium, 600 revolutions (the least-damped mode
    decays at ~0.6 1/s: |μ| = 0.99 per revolution): the last revolution equals the branch's
    orbit sample by sample within 0.5 % of its amplitude in every coordinate (measured
    0.16 %) and in amplitude at the journal within 0.5 % (measured 0.02 %)."""
    rig = coarse_models.paper_rig()
    ub = [(6, 2e-5, 0.0)]
    o = rd.periodic_orbit(rig, 60.0, 0.4e6, 0.0, kind="forced", unbalances=ub, rtol=1e-8,
                          tol=1e-6)
    assert o.ok, o.message
    br = rd.continuation(rig, "speed_hz", (50.0, 80.0), o, unbalances=ub, rtol=1e-8,
                         tol=1e-6, ds=0.05, max_points=2, n_out=101)
    assert br.ok and len(br) == 2, br.message
    orb, speed = br.orbits[1], float(br.parameter[1])
    assert 60.5 < speed < 80.0 and orb.period_s == pytest.approx(1.0 / speed, rel=1e-12)
    revs = 600
    tr = rd.transient(rig, revs / speed, speed, 0.4e6, 0.0, unbalances=ub,
                      n_out=revs * 100 + 1, rtol=1e-8, atol_m=1e-12)
    assert tr.status == "ok", tr.message
    last = slice((revs - 1) * 100, revs * 100 + 1)
    scale = np.max(np.abs(orb.r - orb.r.mean(axis=0)))
    assert np.max(np.abs(tr.r[last] - orb.r)) < 5e-3 * scale
    x, y = tr.journal_x_m[last, 0], tr.journal_y_m[last, 0]
    a_tr = np.max(np.hypot(x - x.mean(), y - y.mean()))
    assert a_tr == pytest.approx(orb.amplitude(0), rel=5e-3)
