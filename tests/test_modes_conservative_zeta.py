"""A conservative gyroscopic system (M, K symmetric, D = Ω G skew, no damping) has purely
imaginary roots (K ≥ 0): its damping ratios are 0. The solvers' own roots carry a rounding of
O(ε ω_max² / |λ|) in Re λ, largest just above the rigid-root cut 10 √ε ω_max (a free
disk-on-shaft's nutation at 0.3 Hz: ζ = -1.8e-4 on the dense path, -6.8e-6 at 1 Hz; a pump on
200 N/m supports: -5.7e-8). Every kept root of such a pencil now takes its vector's
structured Rayleigh quotient (cpp/src/modal_rigid.cpp ``conservative_root``): Re λ exactly 0,
and the frequency second-order accurate (the nutation within 5.4e-6 and 9.0e-7 of Ω I_p/I_t at
0.3 and 1 Hz on either path, where the dense root was 1.0e-4 and 2.6e-5 off).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as sl

from rotordyn import _core as core

sys.path.insert(0, str(Path(__file__).parent))
from test_modes_free_free import _pump, both_paths, disk_on_shaft, rigid_inertias  # noqa: E402

EPS = np.finfo(float).eps


@pytest.mark.parametrize("hz, rtol", [(0.3, 1e-5), (1.0, 1e-5), (3.0, 1e-5), (10.0, 1e-4)])
def test_free_rotor_roots_are_undamped(hz, rtol):
    """Both paths: every root above the cut has Re λ = 0 exactly; the nutation matches
    Ω I_p/I_t to ``rtol`` (above a few Hz the shaft's flexibility departs by O(Ω²): 3.4e-5 at
    10 Hz, tests/test_modes_free_free.py)."""
    c = core.constrain(disk_on_shaft().to_core())
    M, K = np.asarray(c.M), np.asarray(c.K)
    w_max = math.sqrt(sl.eigh(K, M, eigvals_only=True)[-1])
    ip, it = rigid_inertias()
    nut = 2 * np.pi * hz * ip / it
    assert nut > 10 * math.sqrt(EPS) * w_max  # above the cut: the solver's own root
    for w in both_paths(c, hz, 6):
        assert np.all(w.real == 0.0), w[:3]
        assert w.imag[0] == pytest.approx(nut, rel=rtol)


@pytest.mark.parametrize("hz", [0.0, 1.0, 10.0, 50.0])
def test_rotor_on_soft_supports_roots_are_undamped(hz):
    """The overhung pump on 200 N/m linear supports (K regular, four support modes at 0.1-5
    rad/s): both paths, all roots Re λ = 0 exactly; at rest the two planes' frequencies agree
    to 1e-8 and match the symmetric eigenproblem (scipy.linalg.eigh of K, M) to 1e-6."""
    c = _pump(200.0)
    for w in both_paths(c, hz, 6):
        assert np.all(w.real == 0.0), w[np.argmax(np.abs(w.real))]
        if hz == 0.0:
            ref = np.sqrt(sl.eigh(np.asarray(c.K), np.asarray(c.M), eigvals_only=True))
            f = np.sort(w.imag)
            # isotropic at rest: the x and y planes' frequencies are one (measured 1.5e-9
            # and 3e-10 apart on the two paths for the soft support modes, where eigh's own
            # two are 4e-7 apart: its rounding, O(ε ω_max² / ω²), limits the reference)
            np.testing.assert_allclose(f[0::2], f[1::2], rtol=1e-8)
            np.testing.assert_allclose(f, np.sort(ref)[:len(w)], rtol=1e-6)


def test_damped_pencil_is_left_to_the_solver():
    """With any damping (C ≠ 0) the pencil is not conservative: the roots are the solver's
    (a 1e-3 proportional damping gives ζ > 0 on every mode of the supported pump)."""
    c = _pump(200.0)
    M, K = np.asarray(c.M), np.asarray(c.K)
    w = np.asarray(core.modal(M, 1e-3 * K, K, list(c.xy), 0, False, list(c.rot)).eigenvalues)
    assert np.all(w.real < 0)
