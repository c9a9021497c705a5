"""History independence of the system analyses (issue 11 acceptance; issue 13 "call order
changes results by 1e-12 to 8e-8 relative even with warm_start=False").

The films start every solve from a prediction of their own inputs, and every public call
starts its first equilibrium cold (python/rotordyn/_common/calls.py: nothing of an earlier
call survives into it), so an equilibrium and its linearisation are bit-for-bit the same
whatever ran before, with ``warm_start`` at its default or off. A start from elsewhere (``r0``,
the equilibrium of another point) converges to the tolerance and then takes full Newton steps
down to the round-off floor, so the answer is the discrete root to round-off: asserted to
1e-12 relative (the figure issue 11 asks for).
"""

import numpy as np
import pytest

import rotordyn as rd

POINT = (50.0, 0.15e6, -1.85e-3)  # the paper's rig, Table 1 operating point


def _random_history(rig, rng):
    for _ in range(4):
        speed = float(rng.uniform(30.0, 60.0))
        pc = float(rng.uniform(0.0, 0.3e6))
        ay = float(rng.uniform(-2.0e-3, 0.0))
        what = rng.integers(3)
        if what == 0:
            rd.equilibrium(rig, speed, pc, ay)
        elif what == 1:
            rd.linearize(rig, speed, pc, ay)
        else:
            rd.linearize(rig, speed, pc, ay, method="finite_difference")


@pytest.mark.parametrize("start", ["cold", "default", "r0"])
def test_equilibrium_and_linearisation_do_not_depend_on_call_order(start):
    rig = rd.models.paper_rig()
    e0 = rd.equilibrium(rig, *POINT, warm_start=False)
    l0 = rd.linearize(rig, *POINT, r0=e0.r)
    _random_history(rig, np.random.default_rng(11))
    kw = {"cold": {"warm_start": False}, "default": {},
          "r0": {"r0": rd.equilibrium(rig, 40.0, 0.1e6, -1.5e-3).r}}[start]
    e1 = rd.equilibrium(rig, *POINT, **kw)
    l1 = rd.linearize(rig, *POINT, r0=e1.r)
    assert e0.status == e1.status == "ok"
    if start == "r0":
        scale = np.abs(e0.r).max()
        assert np.abs(e1.r - e0.r).max() <= 1e-12 * scale
        for a, b in ((l0.KH, l1.KH), (l0.DH, l1.DH)):
            assert np.abs(a - b).max() <= 1e-12 * np.abs(a).max()
    else:
        assert np.array_equal(e0.r, e1.r)
        assert np.array_equal(l0.KH, l1.KH) and np.array_equal(l0.DH, l1.DH)
