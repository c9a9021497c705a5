"""Closed form for a fold of static equilibria (issue 19): a rigid rotor on two identical short
(Ocvirk) π-film bearings with a magnet at one journal that pulls it downwards — a linear
support with negative vertical stiffness −k_m at the journal's station (the linearised pull of
a magnet below the journal: a magnetic preload, or one axis of an uncontrolled magnetic
bearing; its bias pull is left out, the weight is the only static load). Written without
rotordyn.

Statics. The magnet acts at the journal's station, so its force passes straight into that
journal's film (a rotor on two supports is statically determinate: the shaft's bending does
not enter): the film at the magnet's journal carries P + k_m δ, P = W/2 the journal's share
of the rotor weight W and δ the journal's downward displacement, with no horizontal load.
Ocvirk's short π film under a vertical load (Friswell et al. 2010 §5.5): the load at
eccentricity ratio ε is W_f = C Ω f(ε), f(ε) = ε (16ε² + π²(1 − ε²))^{1/2} / (4 (1 − ε²)²),
C = z μ R L³ / c² (z = 1 − 1/n_axial² for the trapezoidal rule over n_axial axial intervals,
as tests/short_bearing_hopf_reference.py), and the journal lies at the attitude angle ψ from
the load line, tan ψ = π (1 − ε²)^{1/2} / (4ε), so δ = c ε cos ψ = c d(ε),
d(ε) = 4ε² / (16ε² + π²(1 − ε²))^{1/2}. The equilibria are the solutions of

    C Ω f(ε) = P + k_m c d(ε),   i.e.   Ω(ε) = (P + k_m c d(ε)) / (C f(ε))      (speed)
                                  or   k_m(ε) = (C Ω f(ε) − P) / (c d(ε))     (magnet)

one parameter as an explicit function of ε along the branch. Folds are where that function is
stationary: a strong enough magnet makes the film's vertical stiffness along its locus,
dW_f/dδ = C Ω f'(ε)/(c d'(ε)) (smallest, 1.93 C Ω / c, at ε = 0.27), fall below k_m over a
range of ε: between the two folds three equilibria coexist."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

#: the rotor: a 50 mm steel-density shaft, 0.26 m long (4.0 kg) with E = 1000 × steel (rigid),
#: bearings at both ends (stations 0 and 2); bearings: D = 50 mm, L = 12.5 mm (L/D = 0.25),
#: c = 50 µm, μ = 0.02 Pa·s; the magnet at station 0: k_m = 1.5e7 N/m (negative stiffness)
SHAFT = dict(diameter_m=0.05, length_m=0.26, density_kg_m3=7850.0)
BEARING = dict(diameter_m=0.05, length_m=0.0125, clearance_m=5e-5)
VISCOSITY_PA_S = 0.02
MAGNET_N_PER_M = 1.5e7
GRAVITY = 9.81


def f(e):
    """Ocvirk's dimensionless load W_f / (C Ω)."""
    return e * math.sqrt(16 * e * e + math.pi ** 2 * (1 - e * e)) / (4 * (1 - e * e) ** 2)


def d(e):
    """The journal's displacement along the load line, / c."""
    return 4 * e * e / math.sqrt(16 * e * e + math.pi ** 2 * (1 - e * e))


class MagnetFold:
    """The closed form above for one journal: load share ``P`` (N), magnet ``k_m`` (N/m),
    clearance ``c``, force scale ``C`` (N·s)."""

    def __init__(self, *, n_axial=8, k_m=MAGNET_N_PER_M, viscosity_pa_s=VISCOSITY_PA_S):
        mass = SHAFT["density_kg_m3"] * math.pi / 4 * SHAFT["diameter_m"] ** 2 \
            * SHAFT["length_m"]
        self.P = 0.5 * mass * GRAVITY
        self.k_m = k_m
        self.c = BEARING["clearance_m"]
        R, L = 0.5 * BEARING["diameter_m"], BEARING["length_m"]
        self.C = (1 - 1 / n_axial ** 2) * viscosity_pa_s * R * L ** 3 / self.c ** 2

    def speed_hz(self, e):
        """The speed at which ε is an equilibrium (the magnet fixed)."""
        return (self.P + self.k_m * self.c * d(e)) / (self.C * f(e)) / (2 * math.pi)

    def magnet(self, e, speed_hz):
        """The magnet stiffness k_m (N/m, > 0: the support's kyy is −k_m) at which ε is an
        equilibrium at ``speed_hz``."""
        return (self.C * 2 * math.pi * speed_hz * f(e) - self.P) / (self.c * d(e))

    @staticmethod
    def _stationary(g, lo=0.01, hi=0.95, n=4000):
        """Every (ε, g(ε)) where g is stationary in [lo, hi] (sign changes of a central
        difference on a fine grid, then Brent to 1e-13 in ε)."""
        es = np.linspace(lo, hi, n)
        dg = np.array([g(x + 1e-7) - g(x - 1e-7) for x in es])
        out = []
        for i in np.where(np.sign(dg[1:]) != np.sign(dg[:-1]))[0]:
            e = brentq(lambda x: g(x + 1e-7) - g(x - 1e-7), es[i], es[i + 1], xtol=1e-13)
            out.append((e, g(e)))
        return out

    def speed_folds(self):
        """[(ε, speed_hz)] of the folds over the speed."""
        return self._stationary(self.speed_hz)

    def magnet_folds(self, speed_hz):
        """[(ε, k_m)] of the folds over the magnet stiffness at ``speed_hz``."""
        return self._stationary(lambda e: self.magnet(e, speed_hz))

    def equilibria(self, speed_hz):
        """Every eccentricity ratio of an equilibrium at ``speed_hz`` (the roots of
        Ω(ε) = Ω)."""
        es = np.linspace(0.01, 0.95, 4000)
        g = np.array([self.speed_hz(x) for x in es]) - speed_hz
        return [brentq(lambda x: self.speed_hz(x) - speed_hz, es[i], es[i + 1], xtol=1e-14)
                for i in np.where(np.sign(g[1:]) != np.sign(g[:-1]))[0]]


def rotordyn_model(n_circ=720, n_axial=8, k_m=MAGNET_N_PER_M):
    """The rotordyn System: the rigid shaft on two FixedGeometryBearing(partial_arc 360°,
    film_model="short", Gumbel) at stations 0 and 2, the magnet a linear support at station 0
    with kyy = −k_m; no reduction."""
    import rotordyn as rd
    from rotordyn.bearings import FixedGeometryBearing

    mat = rd.Material("rigid", density_kg_m3=SHAFT["density_kg_m3"], young_pa=2.1e14)
    half = rd.ShaftSection(length_m=0.5 * SHAFT["length_m"],
                           outer_diameter_m=SHAFT["diameter_m"], material="rigid")
    brg = [FixedGeometryBearing(station=s, kind="partial_arc", arc_deg=360.0,
                                cavitation="gumbel", film_model="short", n_circ=n_circ,
                                n_axial=n_axial, viscosity_pa_s=VISCOSITY_PA_S,
                                name=f"B{s}", **BEARING) for s in (0, 2)]
    magnet = rd.Support(station=0, type="linear", kyy_n_per_m=-k_m, name="magnet")
    return rd.System(rotor=rd.Rotor(sections=(half, half)), materials=(mat,),
                     bearings=tuple(brg), supports=(magnet,),
                     name="rigid rotor on short bearings with a magnet at B0")
