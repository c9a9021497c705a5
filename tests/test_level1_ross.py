"""API 617 Level I against ROSS's ``Rotor.run_level1`` on a shared rotor (issue 18; needs
ross-rotordynamics, skipped otherwise).

The case: a uniform steel shaft (4 Timoshenko elements of 0.375 m, Ø 50 mm), a disk at the
middle node, two anisotropic linear bearings (k_xx = 1 MN/m, k_yy = 0.8 MN/m, c = 200 N·s/m) at
the ends, at 500 rad/s; ROSS's rotor is imported with ``system_from_ross``. ROSS adds
``BearingElement(n, kxy=Q, kyx=-Q)`` at node n (here the mid-span node 2, where rotordyn's
``at="auto"`` puts it) for each Q of ``linspace(*stiffness_range, num)`` and returns the log
decrement of the first mode that is not backward. rotordyn follows the first forward mode by
its shape; on this rotor both are the 18.5 Hz cylindrical mode. The log decrements agree to
rounding (5e-12 seen; ROSS's elements also carry axial and torsional DOFs, uncoupled here),
and ROSS's log decrement at rotordyn's Q_0 (found by root finding; ROSS has none) is zero.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.model import system_from_ross

pytestmark = pytest.mark.ross


def _rotor():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rs = pytest.importorskip("ross")
        steel = rs.Material(name="Steel_level1", rho=7810, E=211e9, G_s=81.2e9)
        shaft = [rs.ShaftElement(0.375, 0.0, 0.05, material=steel, shear_effects=True,
                                 rotary_inertia=True, gyroscopic=True) for _ in range(4)]
        disk = rs.DiskElement.from_geometry(n=2, material=steel, width=0.07, i_d=0.05,
                                            o_d=0.28)
        brg = [rs.BearingElement(n, kxx=1e6, kyy=0.8e6, cxx=200.0, cyy=200.0) for n in (0, 4)]
        return rs.Rotor(shaft, [disk], brg, rated_w=500.0)


def test_level1_log_decrements_equal_ross_run_level1():
    rotor = _rotor()
    qs = np.array([0.0, 1.5e4, 3.0e4])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ross = rotor.run_level1(n=2, stiffness_range=(qs[0], qs[-1]), num=qs.size)
    np.testing.assert_allclose(ross.stiffness_range, qs)
    s = system_from_ross(rotor)
    r = rd.level1(s, 500.0 / (2 * np.pi), q_points_n_per_m=qs)
    assert r.placement[0][0] == "station 2"
    df = r.to_frame().set_index("applied_q_n_per_m")
    ours = df.loc[qs, "log_dec"].to_numpy()
    np.testing.assert_allclose(ours, ross.log_dec, rtol=1e-8, atol=1e-10)  # seen: 5e-12
    assert ours[-1] < 0 < ours[0]  # the range brackets Q_0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        at_q0 = rotor.run_level1(n=2, stiffness_range=(r.q0_n_per_m, r.q0_n_per_m), num=1)
    assert abs(at_q0.log_dec[0]) < 1e-8  # seen: 5e-11
