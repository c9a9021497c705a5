"""Reynolds solver against the short- and long-bearing closed forms (reference tier b).

Sources
-------
* Short (Ocvirk, π-film) bearing: F. W. Ocvirk, NACA TN 2808 (1952); load
  W = μωRL³/(4c²)·ε√(16ε² + π²(1−ε²))/(1−ε²)², attitude tan φ = π√(1−ε²)/(4ε); stiffness and
  damping from M. I. Friswell, J. E. T. Penny, S. D. Garvey, A. W. Lees, *Dynamics of Rotating
  Machines* (CUP 2010), §5.5 (u horizontal, v up, load along −v, rotation from u to v — the
  DESIGN.md frame, so no conversion is needed).
* Long bearing: A. Sommerfeld, Z. Math. Phys. 50 (1904) 97–155 (full film,
  W = 12πμωR³Lε/(c²(2+ε²)√(1−ε²)), attitude 90°) and the half-Sommerfeld (Gümbel) film,
  W = 6μωR³Lε√(π² − ε²(π²−4))/(c²(2+ε²)(1−ε²)), as in Hamrock, *Fundamentals of Fluid Film
  Lubrication*, ch. 10.

The closed forms are limits: the finite bearing approaches them as L/D → 0 or ∞. The tests
therefore assert the observed trend (the deviation shrinks monotonically, for the long bearing
as 1/(L/D)) and a final tolerance at the smallest/largest L/D computed, which is the remaining
finite-length effect plus the O(Δφ²) discretisation error (≈0.5 % at 144 nodes); the Ocvirk model
is a half-Sommerfeld film, so the solver runs with ``cavitation="gumbel"`` there.
"""

import math

import numpy as np
import pytest

import rotordyn

PI = math.pi
D, C_RAD, MU, N_HZ = 0.05, 1e-4, 0.02, 20.0
OMEGA = 2 * PI * N_HZ
R = D / 2


def friswell_short(eps):
    """Dimensionless short-bearing a (K c/W) and b (C c ω/W), Friswell et al. §5.5."""
    h0 = 1 / (PI**2 * (1 - eps**2) + 16 * eps**2) ** 1.5
    s = math.sqrt(1 - eps**2)
    a = np.array(
        [
            [
                4 * h0 * (PI**2 * (2 - eps**2) + 16 * eps**2),
                h0 * PI * (PI**2 * (1 - eps**2) ** 2 - 16 * eps**4) / (eps * s),
            ],
            [
                -h0 * PI * (PI**2 * (1 - eps**2) * (1 + 2 * eps**2) + 32 * eps**2 * (1 + eps**2))
                / (eps * s),
                4 * h0 * (PI**2 * (1 + 2 * eps**2) + 32 * eps**2 * (1 + eps**2) / (1 - eps**2)),
            ],
        ]
    )
    bxy = -8 * h0 * (PI**2 * (1 + 2 * eps**2) - 16 * eps**2)
    b = np.array(
        [
            [2 * h0 * PI * s * (PI**2 * (1 + 2 * eps**2) - 16 * eps**2) / eps, bxy],
            [bxy, 2 * h0 * PI * (PI**2 * (1 - eps**2) ** 2 + 48 * eps**2) / (eps * s)],
        ]
    )
    return a, b


def ocvirk_load(eps, L):
    return (
        MU * OMEGA * R * L**3 / (4 * C_RAD**2) * eps
        * math.sqrt(16 * eps**2 + PI**2 * (1 - eps**2)) / (1 - eps**2) ** 2
    )


@pytest.mark.parametrize("eps", [0.3, 0.6])
def test_short_bearing_limit_load_attitude_and_coefficients(eps):
    att_sh = math.degrees(math.atan(PI * math.sqrt(1 - eps**2) / (4 * eps)))
    a_ref, b_ref = friswell_short(eps)
    th = math.radians(-90.0 + att_sh)  # Ocvirk equilibrium: load down, journal turned with rotation
    x, y = eps * C_RAD * math.cos(th), eps * C_RAD * math.sin(th)
    errs = []
    for ld in (0.5, 0.25, 0.125, 0.0625):
        L = ld * D
        b = rotordyn.JournalBearing(
            diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
            n_circ=144, n_axial=16, cavitation="gumbel",
        )
        W = ocvirk_load(eps, L)
        eq = b.static_equilibrium(load_n=(0.0, -W), speed_hz=N_HZ)
        K, C = b.coefficients(x_m=x, y_m=y, speed_hz=N_HZ)
        f = b.forces(x_m=x, y_m=y, speed_hz=N_HZ)
        a, bb = K * C_RAD / W, C * C_RAD * OMEGA / W
        errs.append(
            (
                abs(np.linalg.norm(f) / W - 1),  # load at the Ocvirk position
                abs(eq.eccentricity_ratio / eps - 1),
                abs(eq.attitude_angle_deg - att_sh),
                np.max(np.abs(a / a_ref - 1)),
                np.max(np.abs(bb / b_ref - 1)),
            )
        )
    errs = np.array(errs)
    # observed trend: every deviation shrinks as L/D -> 0
    assert np.all(np.diff(errs, axis=0) < 0), errs
    w_err, eps_err, att_err, k_err, c_err = errs[-1]
    assert w_err < 0.015  # load at the Ocvirk position, L/D = 1/16
    assert eps_err < 0.01  # eccentricity at the Ocvirk load
    assert att_err < 0.5  # deg
    assert k_err < 0.03 and c_err < 0.03  # all eight coefficients


@pytest.mark.parametrize(
    "cavitation, closed_form",
    [
        ("none", lambda eps, L: 12 * PI * MU * OMEGA * R**3 * L * eps
         / (C_RAD**2 * (2 + eps**2) * math.sqrt(1 - eps**2))),
        ("gumbel", lambda eps, L: 6 * MU * OMEGA * R**3 * L * eps
         * math.sqrt(PI**2 - eps**2 * (PI**2 - 4)) / (C_RAD**2 * (2 + eps**2) * (1 - eps**2))),
    ],
)
def test_long_bearing_limit(cavitation, closed_form):
    eps = 0.5
    deficits = []
    for ld in (2, 4, 8, 16):
        L = ld * D
        b = rotordyn.JournalBearing(
            diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
            n_circ=96, n_axial=8 * ld, cavitation=cavitation,
        )
        f = b.forces(x_m=0.0, y_m=-eps * C_RAD, speed_hz=N_HZ)
        deficits.append(1 - np.linalg.norm(f) / closed_form(eps, L))
        if cavitation == "none":  # full Sommerfeld: force perpendicular to the line of centres
            assert abs(f[1]) < 1e-8 * abs(f[0])
    d = np.array(deficits)
    assert np.all(d > 0) and np.all(np.diff(d) < 0)
    # end leakage deficit ∝ D/L: each doubling of L/D halves it (within 5 %)
    np.testing.assert_allclose(d[:-1] / d[1:], 2.0, rtol=0.05)
    assert d[-1] < 0.06


def test_petroff_torque_concentric():
    """Concentric journal: friction torque T = 2πμωR³L/c exactly (uniform Couette shear)."""
    b = rotordyn.JournalBearing(diameter_m=D, length_m=D, clearance_m=C_RAD, viscosity_pa_s=MU,
                                n_circ=36, n_axial=8)
    r = b.solve(x_m=0.0, y_m=0.0, speed_hz=N_HZ)
    assert r.friction_torque_n_m == pytest.approx(2 * PI * MU * OMEGA * R**3 * D / C_RAD, rel=1e-12)
    assert np.linalg.norm(r.force_n) < 1e-9
