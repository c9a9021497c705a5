"""The shooting flows' sensitivity corrector and BDF order cap (docs/nonlinear.md, "Shooting
on a flexible rotor"): the blocked corrector (all monodromy columns in one solve with the
exact matrix I − γA, opt-in) gives the orbit and the multipliers of CVODES's own
column-by-column corrector; ``bdf_max_order`` reaches the flows."""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def plain_system():
    return rd.System.from_toml(MODELS / "compressor_plain.toml")


def test_blocked_sensitivities_give_the_orbit_and_multipliers_of_the_columns(plain_system):
    """The compressor on plain bearings (Reynolds, cavitation), 50 Hz, 2e-4 kg·m, rtol 1e-9,
    tol 1e-7: the two correctors' orbits within 1e-6 of the amplitude and every multiplier
    within 1e-6 (measured: |mu_c| 0.19137774 both, 3e-9 apart). The blocked corrector solves
    the linear sensitivity system exactly: at most 2 iterations per step (CVODES's own: each
    iteration a back-substitution per column, counted as such), one LU per step attempt."""
    ub = [(3, 2e-4, 0.0)]
    runs = {s: rd.periodic_orbit(plain_system, 50.0, kind="forced", unbalances=ub, rtol=1e-9,
                                 tol=1e-7, sensitivity_solve=s)
            for s in ("columns", "blocked")}
    a, b = runs["columns"], runs["blocked"]
    assert a.ok and b.ok, (a.message, b.message)
    amp = np.abs(a.r - a.r.mean(axis=0)).max()
    assert np.abs(a.r - b.r).max() < 1e-6 * amp
    mu_a, mu_b = a.multipliers, b.multipliers
    d = np.abs(mu_a[:, None] - mu_b[None, :]).min(axis=1)
    assert d.max() < 1e-6
    n2 = a.monodromy.shape[0]
    assert a.stats["sens_factorizations"] == 0
    # one LU per step attempt (measured 5922 for 5822 accepted steps)
    assert 0 < b.stats["sens_factorizations"] <= 1.2 * b.stats["steps"]
    # iterations of the corrector per step (each solves all 2n columns)
    assert b.stats["sens_linear_solves"] / n2 <= 2 * b.stats["steps"]
    assert b.stats["order_reductions"] >= 0


def test_bdf_max_order_reaches_the_flows(plain_system):
    """Order 2 is A-stable (no stability-limit order reduction) and takes another step
    sequence; the orbit is the same within tol; out-of-range orders are an InputError."""
    ub = [(3, 2e-4, 0.0)]
    o5 = rd.periodic_orbit(plain_system, 50.0, kind="forced", unbalances=ub)
    o2 = rd.periodic_orbit(plain_system, 50.0, kind="forced", unbalances=ub, bdf_max_order=2)
    assert o5.ok and o2.ok
    assert o2.stats["order_reductions"] == 0
    assert o2.stats["steps"] != o5.stats["steps"]
    assert np.abs(o2.r - o5.r).max() < 1e-4 * o5.length_scale_m
    for bad in (0, 6):
        with pytest.raises(InputError, match="bdf_max_order"):
            rd.periodic_orbit(plain_system, 50.0, kind="forced", unbalances=ub,
                              bdf_max_order=bad)
    with pytest.raises(InputError, match="sensitivity_solve"):
        rd.periodic_orbit(plain_system, 50.0, kind="forced", unbalances=ub,
                          sensitivity_solve="rows")


def test_a_stalled_newton_tightens_the_flow_before_the_sensitivities_error_test(plain_system):
    """The residual's floor is the flow's own error (docs/nonlinear.md, "The residual's
    floor"): on the compressor (50 Hz, 2e-4 kg·m, rtol 1e-9, tol 1e-7, CVODES's column
    corrector, monodromy from the samples) the Newton residuals go 1.46e-5, 4.95e-7, 3.50e-7 —
    the last step did not halve the residual. Before, that put the sensitivities into the
    error test for the next flow: 5745 steps in all against 951 with the blocked corrector,
    whose path did not stall. Now the state's tolerances are tightened tenfold first
    (measured: 1105 steps, residual 8.5e-8 < tol, flow_tol_factor 0.1). Asserted: converged
    to tol, the factor reported, fewer than twice the blocked corrector's steps, and the
    orbit within 10 tol·L of the error-controlled flow route's (the path before)."""
    ub = [(3, 2e-4, 0.0)]
    kw = dict(kind="forced", unbalances=ub, rtol=1e-9, tol=1e-7)
    cols = rd.periodic_orbit(plain_system, 50.0, floquet="samples", **kw)
    blk = rd.periodic_orbit(plain_system, 50.0, floquet="samples", sensitivity_solve="blocked",
                            **kw)
    ref = rd.periodic_orbit(plain_system, 50.0, floquet="flow", sensitivity_error_control=True,
                            **kw)
    assert cols.ok and blk.ok and ref.ok, (cols.message, blk.message, ref.message)
    assert cols.residuals[-1] < 1e-7
    assert cols.stats["flow_tol_factor"] < 1.0
    assert blk.stats["flow_tol_factor"] == 1.0
    assert cols.stats["steps"] < 2 * blk.stats["steps"]
    L = cols.length_scale_m
    assert np.abs(cols.r - ref.r).max() < 10 * 1e-7 * L
    d = np.abs(cols.multipliers[:, None] - ref.multipliers[None, :]).min(axis=1)
    assert d.max() < 2e-6


def test_a_solve_stopped_after_stalls_says_what_it_tried(plain_system):
    """A solve that runs out of iterations after the stall rule fired reports what was tried
    and that the residual's floor may be the integration's (before: "the start may not be
    near a periodic orbit", whatever happened). The compressor at rtol 1e-4, atol 1e-7 m,
    tol 1e-9, max_iter 5: residuals 6.1e-4, 2.6e-4, 1.35e-5, 7.1e-6 (a fall of less than
    half after a full step: the state's tolerances tightened tenfold), 6.4e-4 (the tighter
    flow's own map: the residual grew, so the sensitivities go into the error test),
    2.1e-4, then the iterations end (measured; with max_iter 8 it converges to 4.5e-14)."""
    r = rd.periodic_orbit(plain_system, 50.0, kind="forced", unbalances=[(3, 2e-4, 0.0)],
                          rtol=1e-4, atol_m=1e-7, tol=1e-9, max_iter=5, floquet="none")
    assert r.status == "not_converged"
    assert "tightened 1 time(s) tenfold and the sensitivities in the error test" in r.message
    assert "floor may be the integration's error" in r.message, r.message
    assert r.stats["flow_tol_factor"] == pytest.approx(0.1)
