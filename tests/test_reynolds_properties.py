"""Property tests (tier f, hypothesis) of the Reynolds solver: the film force is a continuous,
Lipschitz function of the journal position across changes of the cavitated set, and the
Swift–Stieber solution satisfies its complementarity conditions at arbitrary states (the cell
balances are recomputed here in NumPy: zero residual where p > 0, non-negative outflow where
p = 0 — the clipped half-Sommerfeld field fails this check, the LCP solution passes).

Why the bounds: between two positions δ apart, |ΔF| ≤ |K|·|δ|·(1 + margin); we take the
perturbation stiffness at both ends and a factor 2 for the curvature over the (small, 1e-3·c)
step. A jump of the force when a node enters or leaves the cavitated set would violate it.
Complementarity is checked to 1e-9 of the largest Couette flux (round-off of the direct
solve)."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import rotordyn

C_RAD = 1e-4
B = rotordyn.JournalBearing(diameter_m=0.05, length_m=0.04, clearance_m=C_RAD,
                            viscosity_pa_s=0.02, n_circ=48, n_axial=12, cavitation="reynolds",
                            grooves=[rotordyn.Groove(90.0)])

ecc = st.floats(0.05, 0.9)
ang = st.floats(0.0, 2 * math.pi)


@settings(max_examples=40, deadline=None)
@given(ecc, ang, ang)
def test_force_is_lipschitz_across_cavitation_changes(e, a, d):
    x, y = e * C_RAD * math.cos(a), e * C_RAD * math.sin(a)
    step = 1e-3 * C_RAD
    x2, y2 = x + step * math.cos(d), y + step * math.sin(d)
    f1 = B.forces(x_m=x, y_m=y, speed_hz=20.0)
    f2 = B.forces(x_m=x2, y_m=y2, speed_hz=20.0)
    k1, _ = B.coefficients(x_m=x, y_m=y, speed_hz=20.0)
    k2, _ = B.coefficients(x_m=x2, y_m=y2, speed_hz=20.0)
    kmax = max(np.linalg.norm(k1, 2), np.linalg.norm(k2, 2))
    assert np.linalg.norm(f2 - f1) <= 2.0 * kmax * step


@settings(max_examples=40, deadline=None)
@given(ecc, ang, st.floats(-0.02, 0.02), st.floats(-0.02, 0.02), st.sampled_from([20.0, -20.0]))
def test_swift_stieber_complementarity(e, a, vx, vy, f):
    x, y = e * C_RAD * math.cos(a), e * C_RAD * math.sin(a)
    pf = B.pressure(x_m=x, y_m=y, speed_hz=f, vx_m_s=vx, vy_m_s=vy)
    p, h = pf.p_pa, pf.h_m
    assert p.min() >= 0.0 and np.all(pf.theta == 1.0) and np.all(p[:, [0, -1]] == 0.0)
    # cell balances of the discretisation (docs/journal-bearing.md), recomputed in NumPy
    R, mu, w = 0.025, 0.02, 2 * math.pi * f
    n, k1 = p.shape
    dphi, dz = 2 * math.pi / n, 0.04 / (k1 - 1)
    hdot = (-vx * np.cos(pf.phi_rad) - vy * np.sin(pf.phi_rad))[:, None] * np.ones(k1)
    he = 0.5 * (h + np.roll(h, -1, 0))
    cE = he**3 / (12 * mu) * dz / (R * dphi)
    cN = (0.5 * (h[:, 1:] + h[:, :-1])) ** 3 / (12 * mu) * R * dphi / dz
    qE = 0.5 * w * R * dz * he
    pe, pw = np.roll(p, -1, 0), np.roll(p, 1, 0)
    F = (cE * (p - pe) + np.roll(cE, 1, 0) * (p - pw))[:, 1:-1]
    F += cN[:, 1:] * (p[:, 1:-1] - p[:, 2:]) + cN[:, :-1] * (p[:, 1:-1] - p[:, :-2])
    F += (qE - np.roll(qE, 1, 0))[:, 1:-1] + (R * dphi * dz * hdot)[:, 1:-1]
    film = np.ones(n, bool)
    film[12] = False  # the supply line at 90° (node 12 of 48) holds p = 0
    F, pin = F[film], p[film, 1:-1]
    tol = 1e-9 * np.abs(qE).max()
    assert np.all(np.abs(F[pin > 0]) <= tol)  # Reynolds equation where the film is full
    assert np.all(F[pin == 0] >= -tol)  # cavitated: the multiplier (outflow) is >= 0
