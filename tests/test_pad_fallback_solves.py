"""The Reynolds solves an equilibrium reports include its fallback's: where the pad assembly
does not converge, the tilting-pad equilibrium (C++ pad_system_equilibrium) runs the tilt
homotopy's stages and a last Newton, and reported only that last Newton's solves (34 for a call
that made ~4·10⁴, 0.45 s CPU: the compressor on misaligned spherical pads at 20 Hz). Now the
count is the whole call's: the first attempt + the homotopy's stages + the answer's Newton.

That compressor case now converges through the pad assembly (tests/test_pad_rank_one_pads.py:
a pad with pressure on one node made the reduced Newton's step NaN); the fallback runs here on
the case of tests/test_pad_equilibrium_failure.py (two narrow pads loaded between them, a side
load: no equilibrium at any speed), through the bound C++ function. Not the paper rig."""

import math

import numpy as np

from rotordyn import _core
from rotordyn.bearings import TiltingPadBearing
from rotordyn.bearings._film import standalone_model
from test_pad_equilibrium_failure import CASE, LOAD


def test_a_homotopy_equilibrium_counts_every_solve_of_the_call():
    parts = TiltingPadBearing(**CASE).system_parts(0, 1, 2, "bearing")
    model = standalone_model(parts, np.array(LOAD))
    n = 2 + parts.n_extra
    w, zero, P = 2 * math.pi * 1.9, np.zeros(n), np.asarray(parts.penalty)
    opt = _core.EquilibriumOptions()
    e = _core.pad_system_equilibrium(_core.SystemSolver(model), model, w, 0.0, zero, zero,
                                     np.zeros(0), opt, P)
    assert e.path == "homotopy"
    # the parts, each from a fresh solver (a solve's count does not depend on what ran before)
    first = _core.SystemSolver(model).equilibrium(w, 0.0, zero, zero, opt)
    start = _core.homotopy_start(model, w, 0.0, zero, np.zeros(0), opt, P)
    last = _core.SystemSolver(model).equilibrium(w, 0.0, zero, start, opt)
    assert first.path != "pad_assembly"  # why the fallback ran
    np.testing.assert_allclose(last.r, e.r, rtol=0, atol=1e-15)
    # the homotopy's own stages are the difference: more than both Newtons together here
    # (measured 1.07·10⁵ against 379 + 379)
    stages = e.reynolds_solves - first.reynolds_solves - last.reynolds_solves
    assert stages > first.reynolds_solves + last.reynolds_solves, (
        e.reynolds_solves, first.reynolds_solves, last.reynolds_solves)
