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
