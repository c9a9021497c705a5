"""Fixed-geometry and tilting-pad films: independent checks where no published table was
available to us (issue 12).

* Rotational symmetry: an n-lobe bearing (or n-pad tilting-pad bearing) is invariant under a
  rotation by 360°/n, so F(Rq) = R F(q) for the film force and K(R W) = R K Rᵀ for the
  coefficients under a rotated load. This checks each lobe's/pad's mapping onto its own
  Reynolds grid (start angle, scale, pivot): forces to 1e-9; tilting-pad coefficients at the
  equilibrium to 1e-7 of the largest (equilibria polished to round-off).
* Mirror symmetry: a geometry symmetric about the y axis (lobes centred on it) gives
  F_x(−x, y, −ω) = −F_x(x, y, ω) and F_y(−x, y, −ω) = F_y(x, y, ω).
* Limits: preload 0 makes the elliptical bearing the two-axial-groove bearing (exactly);
  a very stiff pivot makes the flexible-pivot tilting pad the rigid-pivot one; with load on a
  pad, a pivot spring acts in series with the loaded pad's film (within −5 %/+10 %).
* Grid convergence: the observed order of the elliptical bearing's force from grids h, h/2,
  h/4 (uncavitated film, smooth solution) is 2 ± 0.3 (second-order finite volumes).
* Pressure dam: the dam's pocket adds a downward force on a centred journal (its purpose:
  load the journal in light-load, high-speed service).
"""

import math

import numpy as np
import pytest

from rotordyn.bearings import FixedGeometryBearing, TiltingPadBearing

D, C, MU = 0.05, 1e-4, 0.02
KW = dict(diameter_m=D, length_m=0.5 * D, clearance_m=C, viscosity_pa_s=MU)


def _rot(a):
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


@pytest.mark.parametrize("kind, n", [("elliptical", 2), ("offset_halves", 2), ("three_lobe", 3),
                                     ("four_lobe", 4)])
def test_lobed_bearing_rotational_symmetry(kind, n):
    b = FixedGeometryBearing(station=0, kind=kind, n_circ=72, n_axial=8, **KW)
    q = np.array([1.5e-5, -2.5e-5])
    R = _rot(2 * math.pi / n)
    F = b.forces(x_m=q[0], y_m=q[1], speed_hz=30.0)
    q2 = R @ q
    F2 = b.forces(x_m=q2[0], y_m=q2[1], speed_hz=30.0)
    np.testing.assert_allclose(F2, R @ F, rtol=1e-9, atol=1e-9 * np.abs(F).max())
    assert np.abs(F).max() > 1.0


@pytest.mark.parametrize("kind", ["two_axial_groove", "elliptical", "three_lobe", "four_lobe"])
def test_mirror_symmetry(kind):
    b = FixedGeometryBearing(station=0, kind=kind, n_circ=72, n_axial=8, **KW)
    F = b.forces(x_m=1e-5, y_m=-3e-5, speed_hz=25.0)
    Fm = b.forces(x_m=-1e-5, y_m=-3e-5, speed_hz=-25.0)
    np.testing.assert_allclose(Fm, [-F[0], F[1]], rtol=1e-9, atol=1e-9 * np.abs(F).max())


def test_elliptical_without_preload_is_two_axial_groove():
    e = FixedGeometryBearing(station=0, kind="elliptical", preload=0.0, n_circ=72, n_axial=8, **KW)
    t = FixedGeometryBearing(station=0, kind="two_axial_groove", n_circ=72, n_axial=8, **KW)
    a = e.coefficient_table([20.0, 60.0], (0.0, -400.0))
    b = t.coefficient_table([20.0, 60.0], (0.0, -400.0))
    np.testing.assert_array_equal(a.K, b.K)
    np.testing.assert_array_equal(a.C, b.C)
    p = FixedGeometryBearing(station=0, kind="elliptical", n_circ=72, n_axial=8, **KW)
    c = p.coefficient_table([20.0, 60.0], (0.0, -400.0))
    assert c.K[0, 1, 1] > b.K[0, 1, 1]  # preload stiffens the bearing


def test_elliptical_grid_convergence_order():
    F = []
    for nc, na in ((36, 6), (72, 12), (144, 24)):
        b = FixedGeometryBearing(station=0, kind="elliptical", cavitation="none", n_circ=nc,
                                 n_axial=na, **KW)
        F.append(b.forces(x_m=1e-5, y_m=-2e-5, speed_hz=30.0))
    F = np.array(F)
    order = math.log2(np.linalg.norm(F[0] - F[1]) / np.linalg.norm(F[1] - F[2]))
    assert abs(order - 2.0) < 0.3, order


def test_pressure_dam_pushes_the_journal_down():
    kw = dict(station=0, kind="pressure_dam", n_circ=72, n_axial=8, **KW)
    plain = FixedGeometryBearing(dam_depth_m=0.0, **kw).forces(x_m=0.0, y_m=-1e-6, speed_hz=50.0)
    dam = FixedGeometryBearing(dam_depth_m=2 * C, **kw).forces(x_m=0.0, y_m=-1e-6, speed_hz=50.0)
    assert dam[1] < plain[1] - 0.1 * abs(plain[1])


@pytest.mark.parametrize("load", ["between", "on"])
def test_tilting_pad_rotational_symmetry_of_coefficients(load):
    tp = TiltingPadBearing(station=0, n_pads=4, pad_arc_deg=72.0, preload=0.3, load=load,
                           pad_inertia_kg_m2=2e-5, n_circ=72, n_axial=8, **KW)
    W = np.array([0.0, -600.0])
    R = _rot(math.pi / 2)
    a = tp.coefficient_table([40.0], W)
    b = tp.coefficient_table([40.0], R @ W)
    for A, B in ((a.K[0], b.K[0]), (a.C[0], b.C[0])):
        # 1e-7 of the largest entry (observed ~1e-15): the pad-assembly equilibrium is
        # polished to round-off on both loads (the tolerance-converged homotopy needed 1e-4)
        np.testing.assert_allclose(B, R @ A @ R.T, rtol=0, atol=1e-7 * np.abs(A).max())


def test_flexible_pivot_limits():
    kw = dict(station=0, n_pads=4, pad_arc_deg=72.0, preload=0.3, load="on",
              pad_inertia_kg_m2=2e-5, n_circ=72, n_axial=8, **KW)
    rigid = TiltingPadBearing(**kw).coefficient_table([40.0], (0.0, -600.0))
    stiff = TiltingPadBearing(pivot_stiffness_n_per_m=1e13, pad_mass_kg=0.05,
                              **kw).coefficient_table([40.0], (0.0, -600.0))
    kp = 5e7
    soft = TiltingPadBearing(pivot_stiffness_n_per_m=kp, pad_mass_kg=0.05,
                             **kw).coefficient_table([40.0], (0.0, -600.0))
    np.testing.assert_allclose(stiff.K, rigid.K, rtol=1e-4)
    # load on pad: the loaded pad's film carries K_yy almost alone, so a pivot spring k_p
    # puts it in series, K_yy ≈ 1/(1/K_yy,rigid + 1/k_p) (the side pads add a little)
    series = 1.0 / (1.0 / rigid.K[0, 1, 1] + 1.0 / kp)
    assert 0.95 < soft.K[0, 1, 1] / series < 1.1, (soft.K[0, 1, 1], series)
