"""Same inputs, same answer, whatever ran before (issue 13, DESIGN §5): a random sequence of
other analyses on the same System (other operating points, linearisations, transients,
Campbell diagrams, bearing solves) before a call does not change the call's result.

Coordinate-free comparisons: the sorted eigenvalues, the journal eccentricities and minimum
film thicknesses, and the equilibrium itself. Without a warm start (``warm_start=False``) the
result is identical bit for bit (each Reynolds solve starts its cavitation set from its own
inputs). With the default warm start the equilibrium starts from the previous one, so the
answer may move within the equilibrium tolerance: tol = 1e-10 of the load gives positions to
within ~1e-9 c and eigenvalues to a relative 1e-8 (the tolerance the thread test also uses).
"""

import numpy as np
import pytest

import rotordyn as rd

POINT = (50.0, 0.15e6, -1.85e-3)  # the paper's operating point (a_y = -1.85 mm, 50 Hz)
C = 3e-4


def _others(rig):
    """Calls that leave state behind in the System's solvers (films, warm starts)."""
    return [
        lambda: rd.equilibrium(rig, 70.0, 0.4e6, 0.0),
        lambda: rd.equilibrium(rig, 20.0, 0.05e6, -1.85e-3, method="successive"),
        lambda: rd.stability(rig, 35.0, 0.25e6, -1.0e-3),
        lambda: rd.linearize(rig, 50.0, 0.1e6, -1.85e-3, method="finite_difference"),
        lambda: rd.equilibrium(rig, 1e-6, 0.15e6, -1.85e-3),  # a failed point
        lambda: rd.transient(rig, 0.004, 50.0, 0.1e6, -1.85e-3, n_out=5,
                             disturbance_m=(2e-5, -1e-5)),
        lambda: rd.campbell(rig, [30.0, 45.0], 0.4e6, n_modes=4),
        lambda: rig.bearings[0].journal_bearing().forces(x_m=1e-4, y_m=-1.2e-4, speed_hz=50,
                                                         vx_m_s=0.05, vy_m_s=-0.02),
    ]


def _observe(rig, **kw):
    e = rd.equilibrium(rig, *POINT, **kw)
    st = rd.stability(rig, *POINT, **kw)
    assert e.status == "ok" and st.status == "ok", (e.message, st.message)
    return {"r": e.r, "eps": e.eccentricity_ratio, "h_min": e.h_min_m,
            "lam": np.sort_complex(st.eigenvalues)}


@pytest.fixture(scope="module")
def cold_reference():
    return _observe(rd.models.paper_rig(), warm_start=False)


@pytest.mark.parametrize("seed", [0, 1])
def test_call_order_does_not_change_a_cold_result(cold_reference, seed):
    """warm_start=False: bit for bit, after a random order of other calls."""
    rig = rd.models.paper_rig()
    others = _others(rig)
    rng = np.random.default_rng(seed)
    for i in rng.permutation(len(others))[:4]:
        others[i]()
    got = _observe(rig, warm_start=False)
    for k, ref in cold_reference.items():
        np.testing.assert_array_equal(got[k], ref, err_msg=f"{k} (seed {seed})")


@pytest.mark.parametrize("seed", [3])
def test_call_order_moves_a_warm_result_within_the_tolerance(cold_reference, seed):
    """Default warm start: within the equilibrium tolerance (positions 1e-9 c, eigenvalues
    relative 1e-8)."""
    rig = rd.models.paper_rig()
    others = _others(rig)
    rng = np.random.default_rng(seed)
    for i in rng.permutation(len(others))[:4]:
        others[i]()
    got = _observe(rig)
    np.testing.assert_allclose(got["r"], cold_reference["r"], rtol=0, atol=1e-9 * C)
    np.testing.assert_allclose(got["h_min"], cold_reference["h_min"], rtol=0, atol=1e-9 * C)
    np.testing.assert_allclose(got["lam"], cold_reference["lam"], rtol=1e-8)
