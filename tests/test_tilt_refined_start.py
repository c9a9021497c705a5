"""The full-grid Swift–Stieber solve starts from a refined prediction of its cavitation set
(ReynoldsSolver.refine_prediction, cpp/src/reynolds_refine.cpp): a tilted journal's film, plain
and elliptical, both senses of rotation, gives the same pressures bit for bit, so the same
forces, moments and K, C (checked to 1e-12 of each quantity's scale), with fewer active-set
iterations than the coarse start alone; and the standalone film's solver says so too.

Reference: the coarse start (the switch off), today's algorithm; the complementarity problem
has one solution and the loop's answer is the factorisation of the set it ends at.
"""

import math

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import FixedGeometryBearing
from rotordyn.bearings.tilt import _solver, tilted_coefficients, tilted_forces

D, L, C, MU = 0.05, 0.04, 1e-4, 0.02
GEO = dict(diameter_m=D, length_m=L, clearance_m=C, viscosity_pa_s=MU, n_circ=72, n_axial=16)
POSES = [(0.3, -0.5, 0.2, -0.3), (-0.4, 0.2, 0.4, 0.3), (0.1, 0.45, -0.3, 0.1)]


def _both(bearing, speed_hz, pose):
    x, y, tx, ty = pose
    kw = dict(x_m=x * C, y_m=y * C, speed_hz=speed_hz, theta_x_rad=tx * C / L,
              theta_y_rad=ty * C / L)
    s = _solver(bearing)
    out = {}
    try:
        for on in (False, True):
            s.set_refine_prediction(on)
            it0 = s.reynolds_iterations
            f = tilted_forces(bearing, **kw)
            its = s.reynolds_iterations - it0
            p = [np.array(s.last_pressure(i)) for i in range(2 if isinstance(
                bearing, FixedGeometryBearing) else 1)]
            K, Cm = tilted_coefficients(bearing, **kw)
            out[on] = (np.r_[f.force_n, f.film_moment_n_m], p, K, Cm, its)
    finally:
        s.set_refine_prediction(True)
    return out


@pytest.mark.parametrize("kind", ["plain", "elliptical"])
def test_refined_start_gives_the_same_tilted_film(kind):
    b = (rotordyn.JournalBearing(**GEO) if kind == "plain"
         else FixedGeometryBearing(station=0, kind="elliptical", **GEO))
    its = {False: 0, True: 0}
    for speed in (50.0, -50.0):
        for pose in POSES:
            out = _both(b, speed, pose)
            (h0, p0, K0, C0, i0), (h1, p1, K1, C1, i1) = out[False], out[True]
            for a, c in zip(p0, p1):
                assert np.array_equal(a, c)  # the same pressures, so the same set
                assert np.array_equal(a == 0.0, c == 0.0)
            assert np.abs(h1 - h0).max() <= 1e-12 * np.abs(h0).max()
            assert np.abs(K1 - K0).max() <= 1e-12 * np.abs(K0).max()
            assert np.abs(C1 - C0).max() <= 1e-12 * np.abs(C0).max()
            its[False] += i0
            its[True] += i1
    # the plain film: 2.9 -> 1.5 iterations per solve observed; the lobes iterate less anyway
    assert its[True] < its[False] if kind == "plain" else its[True] <= its[False]


def test_standalone_full_grid_switch():
    """The untilted standalone film with the half-grid shortcut off (full grid): the same force
    and pressure either way; the half grid never takes the refinement (its answers unchanged)."""
    b = rotordyn.JournalBearing(**GEO)
    s = b.solver()
    assert s.refine_prediction
    s.use_axial_symmetry = False
    w = 2 * math.pi * 50.0
    res = {}
    for on in (False, True):
        s.refine_prediction = on
        r = s.rigid(0.3 * C, -0.5 * C, 0.0, 0.0, w)
        res[on] = (np.array(r.p_pa), r.iterations)
    assert np.array_equal(res[False][0], res[True][0])
    assert res[True][1] <= res[False][1]
