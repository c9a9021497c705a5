"""``bdf_max_order``: CVODE's highest BDF order on an unreduced rotor without material damping.

The 4.3 t steam-turbine rotor of tests/data/models (18 Timoshenko elements, no reduction, two
turbulent two-axial-groove bearings) has free bending modes at 9–12 kHz with Re λ ≈ -0.01 1/s,
outside the stability region of BDF orders 3–5 at the steps the film motion allows; CVODE's
stability-limit detection lowered the order over and over (measured: 10 revolutions at 55 Hz,
45,621 steps, 1,039 order reductions, 16 s CPU). Order 2 is A-stable (Hairer & Wanner, Solving
ODEs II, §V.2): 1,130 steps, 0.44 s, and closer to a tight reference. The test runs one
revolution (measured: order 5 3,761 steps, 110 reductions, 2.9 % off the reference; order 2
352 steps, 0 reductions, 2.6 % off) against a reference at rtol 1e-8 (order 5: it agrees with
an order-2 run at that tolerance to 1.6e-4 of the motion).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.errors import InputError

TURBINE = Path(__file__).parent / "data" / "models" / "turbine_two_axial_groove.toml"


def _run(s, order, rtol=1e-6, atol=1e-9):
    return rd.transient(s, 1 / 55.0, 55.0, unbalances=[(3, 2e-3, 0.0)], n_out=33, rtol=rtol,
                        atol_m=atol, bdf_max_order=order, record_film_moments=False)


def test_order_two_on_an_undamped_unreduced_rotor():
    s = rd.System.from_toml(TURBINE)
    hi, lo = _run(s, 5), _run(s, 2)
    assert hi.status == "ok" and lo.status == "ok"
    # the premise: order 5 keeps hitting its stability limit, order 2 never does
    assert hi.stats["stab_lim_order_reductions"] > 50
    assert lo.stats["stab_lim_order_reductions"] == 0
    assert lo.stats["steps"] * 5 < hi.stats["steps"]
    ref = _run(s, 5, rtol=1e-8, atol=1e-12)
    # the unbalance motion about the static position, against the reference
    d = lambda tr: tr.r - ref.r[0]  # noqa: E731
    amp = np.abs(d(ref)).max()
    assert np.abs(d(lo) - d(ref)).max() < 0.05 * amp


def test_bdf_max_order_is_checked():
    s = rd.System.from_toml(TURBINE)
    for bad in (0, 6, 2.0, True):
        with pytest.raises(InputError, match="bdf_max_order"):
            rd.transient(s, 0.01, 55.0, bdf_max_order=bad)
