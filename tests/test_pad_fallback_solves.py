"""The Reynolds solves an equilibrium reports include its fallback's: where the pad assembly
does not converge, the tilting-pad equilibrium (C++ pad_system_equilibrium) runs the tilt
homotopy's stages and a last Newton, and reported only that last Newton's solves (34 for a call
that made ~4·10⁴, 0.45 s CPU: the compressor on misaligned spherical pads at 20 Hz). Now the
count is the whole call's: the first attempt + the homotopy's stages + the answer's Newton.
Not the paper rig: the compressor of tests/data/models on 5-pad spherical-pivot bearings."""

import dataclasses
import math
from pathlib import Path

import numpy as np

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.equilibrium import equilibrium_options

MODEL = Path(__file__).parent / "data" / "models" / "compressor_tilting_pad.toml"


def test_a_homotopy_equilibrium_counts_every_solve_of_the_call():
    s0 = rd.System.from_toml(MODEL)
    s = dataclasses.replace(s0, bearings=tuple(
        dataclasses.replace(b, tilt=True, config_theta_y_rad=3e-4, pivot_type="spherical")
        for b in s0.bearings))
    e = rd.equilibrium(s, speed_hz=20.0, warm_start=False)
    assert e.status == "ok" and e.path == "homotopy"
    asm = assembled(s)
    w, a, opt = 2 * math.pi * 20.0, asm.config_vector(None, None), equilibrium_options()
    # the parts, each from a fresh solver (a solve's count does not depend on what ran before)
    first = _core.SystemSolver(asm.model).equilibrium(w, 0.0, a, np.zeros(0), opt)
    start = _core.homotopy_start(asm.model, w, 0.0, a, np.zeros(0), opt, asm.pad_penalty)
    last = _core.SystemSolver(asm.model).equilibrium(w, 0.0, a, start, opt)
    assert first.path != "pad_assembly"  # why the fallback ran
    np.testing.assert_allclose(last.r, e.r, rtol=0, atol=1e-15)
    # the homotopy's own stages are the difference: more than both Newtons together here
    stages = e.reynolds_solves - first.reynolds_solves - last.reynolds_solves
    assert stages > first.reynolds_solves + last.reynolds_solves
