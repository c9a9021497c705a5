"""Independent reference for the Hopf point of a rigid symmetric rotor on two identical short
(Ocvirk) bearings with the π film (Gumbel: p = 0 where the short-bearing pressure is negative):
closed-form film, exact Taylor coefficients, Kuznetsov's l1 — written without rotordyn.

Film (the project's frame: h = c − x cos φ − y sin φ, φ from +x with the rotation, y up): the
short-bearing Reynolds equation ∂z(h³/(12μ) ∂z p) = G, G = (ω/2) ∂h/∂φ + ∂h/∂t, gives
p = 6μG/h³·(z² − L²/4), positive where G < 0. With X = x/c, X' = ẋ/(cω), H = h/c,
g = G/(cω) = (X sin φ − Y cos φ)/2 − X' cos φ − Y' sin φ = A sin(φ + δ), the π film is
φ ∈ (π − δ, 2π − δ) and the force on the journal is

    F = −∫∫ p (cos φ, sin φ) R dφ dz = z_factor · μ R L³ ω / c² · ∫_{π−δ}^{2π−δ} g/H³ (cos φ, sin φ) dφ,

z_factor = 1 for the exact ∫(z² − L²/4)dz = −L³/6 (1 − 1/n_axial² for a trapezoidal z-rule
with n_axial intervals). With φ = π − δ + π t the limits are fixed, the integrand is analytic in
the state, and Gauss–Legendre in t is exact to round-off.

Derivatives: F is continued to complex states (numpy's complex arctan, cos, sin): the Taylor
coefficients of s ↦ F(x0 + s u) along any complex direction u are the discrete Cauchy
integrals c_k = mean_j F(x0 + r e^{iθ_j} u) e^{−ikθ_j} / r^k (trapezoid on the circle, exact to
round-off for an analytic F) — no difference quotients, no fits. B(u, v), C(u, u, v) follow by
polarisation; l1 by Kuznetsov (Elements of Applied Bifurcation Theory, 3rd ed., eq. 3.20).

Rotor: total mass m on two identical bearings at its ends, gravity −y; the cylindrical whirl is
one journal with m_b = m/2 and the load W_b = m_b g (the conical whirl is not modelled: the
caller checks that the rotordyn crossing is the cylindrical one)."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, fsolve

_T, _WT = np.polynomial.legendre.leggauss(96)
_T = 0.5 * (_T + 1.0)
_WT = 0.5 * _WT


def pi_film_force(X, Y, Xd, Yd, a0b0=None):
    """Dimensionless π-film short-bearing force f (2,) = ∫ g/H³ (cos φ, sin φ) dφ over g < 0, at
    the (possibly complex) state X = x/c, Y = y/c, Xd = ẋ/(cω), Yd = ẏ/(cω). ``a0b0``: the real
    (a, b) of the base point, so that δ is continued analytically from it (complex states)."""
    a = 0.5 * X - Yd
    b = -0.5 * Y - Xd
    if a0b0 is None:
        delta = np.arctan2(b, a)
    else:
        a0, b0 = a0b0
        delta = math.atan2(b0, a0) + np.arctan((b * a0 - a * b0) / (a * a0 + b * b0))
    phi = math.pi - delta + math.pi * _T
    c, s = np.cos(phi), np.sin(phi)
    g = 0.5 * (X * s - Y * c) - Xd * c - Yd * s
    H = 1.0 - X * c - Y * s
    w = math.pi * _WT * g / H ** 3
    return np.array([np.sum(w * c), np.sum(w * s)])


class RigidRotorShortBearings:
    """Cylindrical whirl of a rigid symmetric rotor (total mass ``mass_kg``) on two identical
    short π-film bearings (D, L, c, μ), gravity ``gravity`` m/s² along −y."""

    def __init__(self, *, mass_kg, diameter_m, length_m, clearance_m, viscosity_pa_s,
                 gravity=9.81, z_factor=1.0):
        self.mb = 0.5 * mass_kg
        self.W = self.mb * gravity
        self.R, self.L, self.c, self.mu = 0.5 * diameter_m, length_m, clearance_m, viscosity_pa_s
        self.zf = z_factor

    def force_scale(self, w):
        return self.zf * self.mu * self.R * self.L ** 3 * w / self.c ** 2

    def sommerfeld(self, speed_hz):
        """S = μ N L D / W_b · (R/c)² (N in rev/s, W_b the load per bearing)."""
        return self.mu * speed_hz * self.L * 2 * self.R / self.W * (self.R / self.c) ** 2

    def equilibrium(self, speed_hz):
        """Journal (x, y), m, under W_b at ``speed_hz`` (the π film balances the load)."""
        w = 2 * math.pi * speed_hz
        k = self.force_scale(w)
        # start: Ocvirk's load W = kε(16ε² + π²(1−ε²))^{1/2}/(4(1−ε²)²) and attitude
        # tan ψ = π(1−ε²)^{1/2}/(4ε) from the load line (−y) in the direction of rotation
        e = brentq(lambda e: k * e * math.sqrt(16 * e * e + math.pi ** 2 * (1 - e * e))
                   / (4 * (1 - e * e) ** 2) - self.W, 1e-12, 1 - 1e-12, xtol=1e-15)
        psi = math.atan2(math.pi * math.sqrt(1 - e * e), 4 * e)
        z = e * np.array([math.cos(1.5 * math.pi + psi), math.sin(1.5 * math.pi + psi)])

        def res(z):
            return k * pi_film_force(z[0], z[1], 0.0, 0.0).real / self.W - np.array([0.0, 1.0])
        z = fsolve(res, z, xtol=1e-14)
        return z * self.c

    def field(self, speed_hz, x0):
        """f(u) of ẋ = f(x), x = (x, y, ẋ, ẏ) SI, complex-analytic about the real x0."""
        w = 2 * math.pi * speed_hz
        k, c = self.force_scale(w), self.c
        X0, Y0, Xd0, Yd0 = x0[0] / c, x0[1] / c, x0[2] / (c * w), x0[3] / (c * w)
        ab = (0.5 * X0 - Yd0, -0.5 * Y0 - Xd0)

        def f(u):
            F = k * pi_film_force(u[0] / c, u[1] / c, u[2] / (c * w), u[3] / (c * w), ab)
            return np.array([u[2], u[3], F[0] / self.mb, F[1] / self.mb - self.W / self.mb])
        return f

    @staticmethod
    def taylor(f, x0, u, r, n=16, kmax=3):
        """Taylor coefficients c_0..c_kmax of s ↦ f(x0 + s u), u complex (Cauchy integrals on
        |s| = r with n points)."""
        th = 2 * math.pi * np.arange(n) / n
        z = r * np.exp(1j * th)
        vals = np.array([f(x0 + zj * u) for zj in z])  # (n, N)
        return [np.mean(vals * np.exp(-1j * k * th)[:, None], axis=0) / r ** k
                for k in range(kmax + 1)]

    def state(self, speed_hz):
        xy = self.equilibrium(speed_hz)
        return np.array([xy[0], xy[1], 0.0, 0.0])

    def jacobian(self, speed_hz, x0=None):
        x0 = self.state(speed_hz) if x0 is None else x0
        f = self.field(speed_hz, x0)
        w = 2 * math.pi * speed_hz
        sc = np.array([self.c, self.c, self.c * w, self.c * w])
        A = np.zeros((4, 4))
        for j in range(4):
            e = np.zeros(4)
            e[j] = sc[j]
            A[:, j] = self.taylor(f, x0, e, 1e-2, n=8, kmax=1)[1].real / sc[j]
        return A

    def critical(self, speed_hz):
        lam = np.linalg.eigvals(self.jacobian(speed_hz))
        up = lam[lam.imag > 0]
        return up[np.argmax(up.real)]

    def hopf_speed(self, lo_hz, hi_hz):
        return brentq(lambda s: self.critical(s).real, lo_hz, hi_hz, xtol=1e-12, rtol=1e-13)

    def lyapunov(self, speed_hz):
        """At the Hopf speed: dict with l1 (in the scaled coordinates (x/c, ẋ/(cω_s)),
        ω_s = max(Ω, ω), ⟨q, q⟩ = 1), omega (1/s), alpha_prime (dRe λ/d speed_hz, 1/(s·Hz)),
        kappa (semi-major² of the journal orbit per Hz from the Hopf speed, m²/Hz), eps0,
        the equilibrium x0, and the cycle side ("above"/"below" the Hopf speed)."""
        x0 = self.state(speed_hz)
        A = self.jacobian(speed_hz, x0)
        lam, V = np.linalg.eig(A)
        k = int(np.argmax(np.where(lam.imag > 0, lam.real, -np.inf)))
        om = lam[k].imag
        W = 2 * math.pi * speed_hz
        d = np.array([self.c, self.c, self.c * max(W, om), self.c * max(W, om)])
        As = A * d[None, :] / d[:, None]
        lam_s, V = np.linalg.eig(As)
        q = V[:, int(np.argmin(abs(lam_s - 1j * om)))]
        q = q / np.linalg.norm(q)
        lt, P = np.linalg.eig(As.T)
        p = P[:, int(np.argmin(abs(lt + 1j * om)))]
        p = p / np.conj(np.vdot(p, q))
        fs_phys = self.field(speed_hz, x0)

        def fs(xs):  # the scaled field about x0
            return fs_phys(x0 + d * xs) / d
        z0 = np.zeros(4)
        r = 2e-2

        def D2(u):
            return 2 * self.taylor(fs, z0, u, r)[2]

        def D3(u):
            return 6 * self.taylor(fs, z0, u, r)[3]

        def B(u, v):
            return 0.25 * (D2(u + v) - D2(u - v))

        def C(u, v):  # C(u, u, v)
            return (D3(u + v) - D3(u - v) - 2 * D3(v)) / 6
        qb = np.conj(q)
        w1 = np.linalg.solve(As, B(q, qb))
        w2 = np.linalg.solve(2j * om * np.eye(4) - As, B(q, q))
        l1 = (np.vdot(p, C(q, qb)) - 2 * np.vdot(p, B(q, w1))
              + np.vdot(p, B(qb, w2))).real / (2 * om)
        ds = 1e-4 * speed_hz
        ap = (self.critical(speed_hz + ds).real - self.critical(speed_hz - ds).real) / (2 * ds)
        wq = (q * d)[:2]
        th = np.linspace(0, 2 * math.pi, 3601)
        semi2 = np.max(np.abs(2 * np.real(np.outer(np.exp(1j * th), wq))) ** 2 @ np.ones(2))
        z2 = abs(ap / (om * l1))
        return {"l1": l1, "omega": om, "alpha_prime": ap, "kappa": semi2 * z2,
                "eps0": math.hypot(x0[0], x0[1]) / self.c, "x0": x0,
                "cycle_side": "above" if -ap / l1 > 0 else "below",
                "sommerfeld": self.sommerfeld(speed_hz)}


# -- the model under test (rotordyn), with the reference's parameters -------------------------

#: the rotor: a steel-density cylinder D_s = 0.1 m, 0.3245 m long (20.0 kg) with E = 2.1e14 Pa
#: (1000 × steel: the shaft's bending flexibility is ~1e-5 of the films'), bearings at both
#: ends; the bearings: D = 50 mm, L = 12.5 mm (L/D = 0.25), c = 50 µm
ROTOR = dict(shaft_diameter_m=0.1, shaft_length_m=0.3245, density_kg_m3=7850.0)
BEARING = dict(diameter_m=0.05, length_m=0.0125, clearance_m=5e-5)


def rotor_mass_kg():
    return ROTOR["density_kg_m3"] * math.pi / 4 * ROTOR["shaft_diameter_m"] ** 2 \
        * ROTOR["shaft_length_m"]


def reference(viscosity_pa_s, n_axial):
    """The reference for :func:`rotordyn_model` (z_factor of its trapezoidal z-rule)."""
    return RigidRotorShortBearings(mass_kg=rotor_mass_kg(), viscosity_pa_s=viscosity_pa_s,
                                   z_factor=1 - 1 / n_axial ** 2, **BEARING)


def rotordyn_model(viscosity_pa_s, n_circ=360, n_axial=8, cavitation="gumbel"):
    """rotordyn System: the rigid rotor on two FixedGeometryBearing(partial_arc 360°,
    film_model="short") at stations 0 and 2, no reduction."""
    import rotordyn as rd
    from rotordyn.bearings import FixedGeometryBearing

    mat = rd.Material("rigid", density_kg_m3=ROTOR["density_kg_m3"], young_pa=2.1e14)
    half = rd.ShaftSection(length_m=0.5 * ROTOR["shaft_length_m"],
                           outer_diameter_m=ROTOR["shaft_diameter_m"], material="rigid")
    rotor = rd.Rotor(sections=(half, half))
    brg = [FixedGeometryBearing(station=s, kind="partial_arc", arc_deg=360.0,
                                cavitation=cavitation, film_model="short", n_circ=n_circ,
                                n_axial=n_axial, viscosity_pa_s=viscosity_pa_s,
                                name=f"B{s}", **BEARING) for s in (0, 2)]
    return rd.System(rotor=rotor, materials=(mat,), bearings=tuple(brg),
                     name="rigid rotor on two short bearings")
