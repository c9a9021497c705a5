"""Free-free rotors: the rigid-body roots are dropped by one rule on both modal paths, and what
is left matches closed forms.

The rule (cpp/src/modal_rigid.cpp): K's rigid-body motions come from the rank of the
Jacobi-scaled stiffness J⁻¹KJ⁻¹ (J = diag √K_ii), so the verdict is the same in any units and at
any length scale;
on the rigid-body subspace the pencil has 2d roots, the regular ones being the eigenvalues of
−M_r⁻¹D_r (a spinning free rotor's nutation), the rest zero; every root below 10 √ε ω_max is
dropped but the one each regular root claims.

References:
- Free-free Euler–Bernoulli beam: ω_n = (β_n L)² √(EI/(ρA L⁴)), β_n L = 4.73004074,
  7.85320462, 10.99560784, 14.13716549 (Blevins, Formulas for Natural Frequency and Mode
  Shape, 1979, Table 8-1).
- A free rigid rotor spinning at Ω (Euler's equations, small tilts): a precession root at zero
  and a forward nutation at Ω I_p/I_t, I_t about the centre of mass (e.g. Genta, Dynamics of
  Rotating Systems, 2005, §4.3 — the free rotor). A flexible rotor's nutation departs from it
  by O(Ω²) (the gyroscopic moment bends the shaft): observed order 2.0 here, asserted ±0.3.

The models: a 1 m, 50 mm steel shaft in 20 elements (84 DOF: above the 48 of the dense limit,
so a call for a few modes takes the sparse shift-invert path, one for all of them the dense
one) with a 10 kg disk at 0.25 m, free or pinned at one end; and the overhung pump of
tests/data/models.
"""

import math
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as sl

import rotordyn as rd
import rotordyn._core as core

E, NU, RHO = 2.1e11, 0.3, 7850.0
MAT = rd.Material("steel", RHO, E, NU)
PUMP = Path(__file__).parent / "data" / "models" / "pump_overhung.toml"
EPS = np.finfo(float).eps
BETA_L = np.array([4.73004074, 7.85320462, 10.99560784, 14.13716549])

L_SHAFT, D_SHAFT, Z_DISK = 1.0, 0.05, 0.25
M_DISK, IP_DISK, ID_DISK = 10.0, 0.08, 0.045


def disk_on_shaft() -> rd.System:
    secs = (rd.ShaftSection(Z_DISK, D_SHAFT, n_elements=5),
            rd.ShaftSection(L_SHAFT - Z_DISK, D_SHAFT, n_elements=15))
    return rd.System(rotor=rd.Rotor(secs, (rd.Disk(1, M_DISK, IP_DISK, ID_DISK),)),
                     materials=(MAT,), reduction=rd.Reduction(method="none"))


def rigid_inertias():
    """(I_p, I_t) of the whole rotor, I_t about its centre of mass: the disk's, and the shaft's
    as a solid cylinder (m (L²/12 + r²/4) about its middle, polar m r²/2)."""
    r = D_SHAFT / 2
    ms = RHO * math.pi * r**2 * L_SHAFT
    zc = (ms * L_SHAFT / 2 + M_DISK * Z_DISK) / (ms + M_DISK)
    it = (ID_DISK + M_DISK * (Z_DISK - zc) ** 2
          + ms * (L_SHAFT**2 / 12 + r**2 / 4) + ms * (L_SHAFT / 2 - zc) ** 2)
    return IP_DISK + ms * r**2 / 2, it


def omega_max(M, K):
    return math.sqrt(sl.eigh(K, M, eigvals_only=True)[-1])


def both_paths(c, speed_hz, n_modes):
    """(sparse, dense) eigenvalues of the constrained rotor ``c`` at ``speed_hz``: a few modes
    (shift-invert) and all of them (dgeev)."""
    D = np.asarray(c.C) + 2 * np.pi * speed_hz * np.asarray(c.G)
    out = []
    for k in (n_modes, 0):
        r = core.modal(c.M, D, c.K, list(c.xy), k, False, list(c.rot))
        out.append(np.asarray(r.eigenvalues))
    return out


@pytest.mark.parametrize("length_m", [0.1, 1.0, 10.0])
def test_free_free_euler_bernoulli_shaft_has_only_its_bending_modes(length_m):
    """No rigid-body root is left, on either path, for a short, a 1 m and a long shaft (the
    rank verdict is that of the Jacobi-scaled stiffness, the same for all three), and the first
    four bending pairs are the closed form's (20 elements: errors measured 2.2e-6 … 1.7e-4,
    the h⁴ discretisation error)."""
    d = length_m / 40
    s = rd.System(rotor=rd.Rotor((rd.ShaftSection(length_m, d, n_elements=20),)),
                  materials=(MAT,), reduction=rd.Reduction(method="none"))
    c = core.constrain(s.to_core(shear=False, rotary_inertia=False))
    area, inertia = math.pi * d**2 / 4, math.pi * d**4 / 64
    exact = (BETA_L / length_m) ** 2 * math.sqrt(E * inertia / (RHO * area))
    for w in both_paths(c, 0.0, 8):
        f = w.imag[:8]
        np.testing.assert_allclose(f[0::2], exact, rtol=3e-4)
        np.testing.assert_allclose(f[1::2], exact, rtol=3e-4)  # both planes
        assert np.all(np.abs(w.real) < 1e-6 * np.abs(w))  # undamped: no spread root left


def test_free_rotor_nutation_is_kept_at_low_speed_and_follows_the_closed_form():
    """The nutation Ω I_p/I_t is the first mode at every speed on both paths, forward, and the
    only root below the first bending pair. At 0.1 Hz it is 0.031 rad/s, below the 10 √ε ω_max
    (0.05 rad/s) under which the old rule dropped the 2d smallest roots (the dense path lost
    it); there the rigid-body subspace's root stands in for the solver's (measured 8e-12 off
    the closed form on both paths, damping zero; the dense solver's own root was 1.3e-3 off).
    Above the cut the solvers' roots are kept, each refined by its structured Rayleigh
    quotient on this conservative pencil (the dense one was 2.6e-5 off at 1 Hz with a damping
    ratio of −7e-6, now 9.0e-7 and 0: tests/test_modes_conservative_zeta.py), and above a few Hz
    the shaft's flexibility lowers the nutation by O(Ω²): 3.4e-5 at 10 Hz, 3.1e-4 at 30 Hz."""
    s = disk_on_shaft()
    c = core.constrain(s.to_core())
    ip, it = rigid_inertias()
    w_max = omega_max(np.asarray(c.M), np.asarray(c.K))
    low = 0.1
    assert 2 * np.pi * low * ip / it < 10 * math.sqrt(EPS) * w_max
    rel = {}
    for hz, rtol, zeta in ((low, 1e-9, 1e-12), (1.0, 1e-4, 1e-4), (10.0, 1e-4, 1e-4),
                           (30.0, 1e-3, 1e-4)):
        nut = 2 * np.pi * hz * ip / it
        for w in both_paths(c, hz, 6):
            assert w.imag[0] == pytest.approx(nut, rel=rtol), (hz, w[:3])
            assert w.imag[1] > 1000.0  # the first bending pair: nothing between
            assert abs(w.real[0]) < zeta * nut
        rel[hz] = w.imag[0] / nut - 1
    m = rd.modes(s, speed_hz=low, n_modes=3).to_frame()  # the ModalOperator path
    assert m["whirl"].iloc[0] == "forward"
    assert m["freq_hz"].iloc[0] == pytest.approx(low * ip / it, rel=1e-9)
    order = math.log(rel[30.0] / rel[10.0]) / math.log(3.0)
    assert rel[10.0] < 0 and order == pytest.approx(2.0, abs=0.3)


def test_free_rotor_campbell_tracks_the_nutation():
    """rotor_campbell (Krylov starts shared between speeds, one rigid-body analysis for all)
    gives the same nutation: Ω I_p/I_t at each speed, from 0.1 Hz up (measured within 6.9e-6
    up to 3 Hz, 3.4e-5 at 10 Hz where the shaft's flexibility shows)."""
    s = disk_on_shaft()
    ip, it = rigid_inertias()
    sp = np.array([0.1, 0.3, 1.0, 3.0, 10.0])
    c = rd.rotor_campbell(s, sp, n_modes=3)
    f = np.asarray(c.eigenvalues).imag[:, 0] / (2 * np.pi)
    np.testing.assert_allclose(f, sp * ip / it, rtol=1e-4)
    assert np.all(np.asarray(c.eigenvalues).imag[:, 1] > 1000.0)


def test_rotor_pinned_at_one_end_two_rigid_motions():
    """The disk-on-shaft on one rigid support at its end (x, y held, tilts free: d = 2). The
    sparse path used to factorise the singular K about σ = 0 (SparseLU keeps rounding-level
    pivots) and returned Ritz values such as −2346 + 997i and +564 + 825i rad/s beside the
    dense solver's 737.8i; now it shifts and agrees with the dense path (measured 2.7e-8 at
    rest, 2.6e-6 at 10 Hz). The nutation about the pin is Ω I_p/I_t,pin (I_t about the end):
    at 0.2 Hz (below the cut, 0.018 rad/s) 3.5e-12 off on both paths, at 10 Hz 4.4e-6 (sparse)
    and 7.0e-6 (dense)."""
    s = disk_on_shaft()
    s = rd.System(rotor=s.rotor, materials=s.materials, supports=(rd.Support(0),),
                  reduction=s.reduction)
    c = core.constrain(s.to_core())
    r = D_SHAFT / 2
    ms = RHO * math.pi * r**2 * L_SHAFT
    it_pin = ID_DISK + M_DISK * Z_DISK**2 + ms * (L_SHAFT**2 / 3 + r**2 / 4)
    ip = IP_DISK + ms * r**2 / 2
    sparse, dense = both_paths(c, 0.0, 6)
    np.testing.assert_allclose(sparse[:6], dense[:6], rtol=1e-6)
    assert np.all(np.abs(sparse[:6].real) < 1e-6 * np.abs(sparse[:6]))
    for hz, rtol in ((0.2, 1e-9), (10.0, 1e-4)):
        sparse, dense = both_paths(c, hz, 6)
        np.testing.assert_allclose(sparse[:6], dense[:6], rtol=1e-4)
        for w in (sparse, dense):
            assert w.imag[0] == pytest.approx(2 * np.pi * hz * ip / it_pin, rel=rtol)
            assert w.imag[1] > 700.0


def _pump(support_n_per_m=None):
    text = PUMP.read_text()
    if support_n_per_m is not None:
        for st in (1, 2):
            text += (f'\n[[support]]\nstation = {st}\ntype = "linear"\nname = "soft {st}"\n'
                     f'kxx_n_per_m = {support_n_per_m}\nkyy_n_per_m = {support_n_per_m}\n')
    s = rd.System.from_toml(text, is_text=True)
    return core.constrain(s.to_core())


@pytest.mark.parametrize("support_n_per_m, speed_hz", [(None, 0.0), (None, 0.02), (200.0, 0.0)])
def test_verdict_does_not_depend_on_the_units(support_n_per_m, speed_hz):
    """The same pump with its translations in mm, m or km (M, C, G, K scaled as S X S): the
    same modes, to rounding. Free at rest: six bending roots, no rigid one; free at 0.02 Hz: the
    nutation (0.017 rad/s, below the old rule's cut) first; on 200 N/m supports (K regular):
    the four support modes at 1.4 and 4.8 rad/s first. With the old rule's K-pivot test the
    200 N/m supports read regular in m but singular in mm (pivots 8.5e-10 and 2.2e-12 of the
    largest, threshold 1e-11)."""
    c = _pump(support_n_per_m)
    M, C, G, K = (np.asarray(x) for x in (c.M, c.C, c.G, c.K))
    trans = [i for p in c.xy for i in p]
    answers = []
    for scale in (1e-3, 1.0, 1e3):
        S = np.ones(M.shape[0])
        S[trans] = scale
        SS = np.outer(S, S)
        D = (C + 2 * np.pi * speed_hz * G) * SS
        r = core.modal(M * SS, D, K * SS, list(c.xy), 0, False, list(c.rot))
        answers.append(np.asarray(r.eigenvalues)[:8])
    for a in answers[::2]:
        np.testing.assert_allclose(a, answers[1], rtol=1e-8, atol=1e-9 * np.abs(answers[1]).max())
    f = answers[1].imag
    if support_n_per_m is not None:
        np.testing.assert_allclose(f[:4], [1.446, 1.446, 4.776, 4.776], rtol=1e-3)
    elif speed_hz > 0:
        assert 0.01 < f[0] < 0.03 and f[1] > 1000.0
    else:
        assert f[0] > 1000.0
