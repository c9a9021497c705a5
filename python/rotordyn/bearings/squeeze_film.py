"""Squeeze-film damper: a non-rotating journal (the damper ring, held by an anti-rotation pin
or a centring spring) whirling in an oil film. The film is the plain bearing's finite-length
Reynolds film with no surface speed (``spin_factor`` = 0): only the squeeze term ∂h/∂t
acts, so its forces are nonlinear in the transient and linearised (D_H) for the linear
analyses. ``cavitation``: ``"none"`` is the uncavitated full (2π) film, ``"gumbel"`` the
π film (negative pressures clipped), ``"reynolds"`` Swift–Stieber. A centring spring
``centring_spring_n_per_m`` acts in parallel (isotropic).

``film_model``: ``"finite"`` (default, the finite-length Reynolds equation above) or
``"short"``, the short-damper model of DyRoBeS/XLTRC users: the circumferential pressure flow
is neglected, p = 6μ (∂h/∂t)(z² − L²/4)/h³ node by node (the Reynolds core's
``short_bearing`` option; clipped at 0 for the π film), for any journal motion — the closed
forms below are its circular-orbit case, and the finite film tends to it as L/D → 0. Open
ends only.

Ends: open (p = 0 at z = ±L/2, default) or end seals, ``end_seal_conductance_m3_per_pa_s_per_m``
= G_s: each end is a flow restriction whose axial leakage per unit circumference equals G_s
times the film pressure above the ambient (0),

    q_z = −(h³/12μ) ∂p/∂z = ±G_s p   at z = ±L/2          (a Robin condition)

solved in the Reynolds core (end node rows on half cells). G_s → ∞ is the open damper,
G_s → 0 the fully sealed one, whose pressure no longer varies along z: the long-bearing
(infinitely long) damper. This is the lumped end-seal model of SFD analyses: end-seal
leakage proportional to the pressure difference across the seal (as in Marmol & Vance,
"Squeeze film damper characteristics for gas turbine engines", ASME J. Mech. Des. 100 (1978)
139–146, and San Andrés' *Squeeze Film Dampers* notes, "end seals"; we worked from secondary
descriptions, the papers themselves were not available to us). For an end-plate seal (a thin
annular gap of clearance c_s and axial land length ℓ_s; plane Poiseuille flow per unit
width) G_s = c_s³/(12 μ ℓ_s): :func:`end_plate_seal_conductance`. A fully sealed film
(G_s = 0) without a supply has no pressure level, so G_s must be > 0, and at least
1e-8 c³/(12μL): the long-bearing limit is reached once G_s ≪ c³/(12μL) (to ~1e-5 at 1e-6),
while far below it the pressure level, set by the seal alone, is lost in round-off (measured:
a π-film damper's C_eq 0.07 % off at 1e-12, wrong at 1e-15).

Closed forms (short damper, L/D → 0, open ends; circular centred orbit of radius e = εc at
whirl speed ν): integrating p = (6μ ∂h/∂t / h³)(z² − L²/4) over z and φ,

    full film:  F_r = 0,                               F_t = −μRL³ν ε π / (c² (1 − ε²)^{3/2})
    π film:     F_r = −2 μRL³ν ε² / (c² (1 − ε²)²),   F_t = −μRL³ν ε π / (2 c² (1 − ε²)^{3/2})

i.e. C_tt = π μ R L³ / (2 c³ (1 − ε²)^{3/2}) for the π film (Vance, *Rotordynamics of
Turbomachinery*, Wiley 1988, §6; San Andrés, *Squeeze film dampers*, Texas A&M lecture
notes, eqs. for the short open-ends SFD). ``short_damper_orbit_forces`` evaluates them.

Long damper (L/D → ∞, or fully sealed ends: ∂p/∂z = 0), same orbit, θ = φ − νt measured from
the minimum film, h = c(1 − ε cos θ), ∂h/∂t = −eν sin θ. The 1-D Reynolds equation
d/dθ(h³ p') = −12μR² eν sin θ integrates to h³ p' = 12μR² eν cos θ + A; periodicity
(Sommerfeld integrals J₁ = ∫dθ/(1−ε cos θ)³ = π(2+ε²)/(1−ε²)^{5/2},
J₂ = ∫cos θ dθ/(1−ε cos θ)³ = 3πε/(1−ε²)^{5/2}) gives A = −12μR² eν·3ε/(2+ε²), and the
sealed-end limit fixes the level (zero net leakage: mean end pressure 0), so p is odd in θ,
positive on 0 < θ < π. Forces F = −∫∫ p (cos φ, sin φ) R dφ dz (by parts):

    full film:  F_r = 0,                                   F_t = −24πμR³Lνε / (c²(2+ε²)(1−ε²)^{1/2})
    π film:     F_r = −24μR³Lνε² / (c²(2+ε²)(1−ε²)),       F_t = −12πμR³Lνε / (c²(2+ε²)(1−ε²)^{1/2})

i.e. C_tt = −F_t/(eν) = 12πμL(R/c)³/((2+ε²)(1−ε²)^{1/2}) for the π film (Vance 1988 §6;
San Andrés, long SFD; written "12πμRL(R/c)³" in the task text, one R too many: N·s, not
N·s/m). ``long_damper_orbit_forces`` evaluates them; tests/test_sfd_end_seals.py checks
them by quadrature of the 1-D pressure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings._film import SystemParts, check_film_fields, pad_film
from rotordyn.errors import InputError


def short_damper_orbit_forces(*, diameter_m, length_m, clearance_m, viscosity_pa_s,
                              eccentricity_ratio, whirl_hz, film: str = "pi"):
    """(F_r, F_t), N: radial and tangential film force on a short open-ends damper journal in
    a circular centred orbit (closed form, module docstring). film: "pi" or "full"."""
    R, L, c, mu = 0.5 * diameter_m, length_m, clearance_m, viscosity_pa_s
    eps = v.in_range("eccentricity_ratio", eccentricity_ratio, 0.0, 1.0, hi_open=True)
    nu = 2 * math.pi * v.finite("whirl_hz", whirl_hz)
    a = mu * R * L ** 3 * nu / c ** 2
    if film == "full":
        return 0.0, -a * eps * math.pi / (1 - eps ** 2) ** 1.5
    if film == "pi":
        return (-a * 2 * eps ** 2 / (1 - eps ** 2) ** 2,
                -a * eps * math.pi / (2 * (1 - eps ** 2) ** 1.5))
    raise InputError(f"film: expected 'pi' or 'full', got {film!r}")


def long_damper_orbit_forces(*, diameter_m, length_m, clearance_m, viscosity_pa_s,
                             eccentricity_ratio, whirl_hz, film: str = "pi"):
    """(F_r, F_t), N: radial and tangential film force on a long (or fully end-sealed)
    damper journal in a circular centred orbit (closed form, module docstring)."""
    R, L, c, mu = 0.5 * diameter_m, length_m, clearance_m, viscosity_pa_s
    eps = v.in_range("eccentricity_ratio", eccentricity_ratio, 0.0, 1.0, hi_open=True)
    nu = 2 * math.pi * v.finite("whirl_hz", whirl_hz)
    a = mu * R ** 3 * L * nu * eps / (c ** 2 * (2 + eps ** 2))
    ft = -24 * math.pi * a / math.sqrt(1 - eps ** 2)
    if film == "full":
        return 0.0, ft
    if film == "pi":
        return -24 * a * eps / (1 - eps ** 2), 0.5 * ft
    raise InputError(f"film: expected 'pi' or 'full', got {film!r}")


def end_plate_seal_conductance(*, gap_m: float, land_length_m: float,
                               viscosity_pa_s: float) -> float:
    """G_s = c_s³/(12 μ ℓ_s), m²/(Pa·s): end-seal conductance of an end plate leaving an
    annular gap c_s over a land of axial length ℓ_s (plane Poiseuille flow, per unit
    circumference), for ``end_seal_conductance_m3_per_pa_s_per_m``."""
    cs = v.positive("gap_m", gap_m)
    ls = v.positive("land_length_m", land_length_m)
    mu = v.positive("viscosity_pa_s", viscosity_pa_s)
    return cs ** 3 / (12.0 * mu * ls)


@dataclass(frozen=True, slots=True)
class SqueezeFilmDamper:
    """Squeeze-film damper at ``station`` (module docstring)."""

    station: int
    diameter_m: float
    length_m: float
    clearance_m: float
    viscosity_pa_s: float
    cavitation: str = "gumbel"
    centring_spring_n_per_m: float = 0.0
    n_circ: int = 72
    n_axial: int = 16
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""
    end_seal_conductance_m3_per_pa_s_per_m: float | None = None
    film_model: str = "finite"

    def __post_init__(self):
        self.check("squeeze_film_damper", None)

    def check(self, where: str, n_stations: int | None) -> None:
        check_film_fields(self, where, n_stations)
        if self.cavitation == "jfo":
            raise InputError(f"{where}.cavitation: 'jfo' needs a supply groove; use 'none' (full "
                             "film), 'gumbel' (π film) or 'reynolds'")
        v.non_negative(f"{where}.centring_spring_n_per_m", self.centring_spring_n_per_m)
        v.choice(f"{where}.film_model", self.film_model, ("finite", "short"))
        g = self.end_seal_conductance_m3_per_pa_s_per_m
        if g is not None and self.film_model == "short":
            raise InputError(f"{where}.end_seal_conductance_m3_per_pa_s_per_m: the short "
                             "damper model has open ends (use film_model = 'finite' with seals)")
        if g is not None:
            f = f"{where}.end_seal_conductance_m3_per_pa_s_per_m"
            try:
                g = v.positive(f, g)  # the shared number rule, with the seal's own hint
            except InputError:
                raise InputError(f"{f}: expected a finite seal conductance > 0 m²/(Pa·s) (omit "
                                 f"it for open ends; a fully sealed film without a supply has "
                                 f"no pressure level: use a small value), got {g!r}") from None
            g_min = 1e-8 * self.clearance_m ** 3 / (12 * self.viscosity_pa_s * self.length_m)
            if g < g_min:
                raise InputError(f"{f}: expected >= 1e-8 clearance_m³/(12 viscosity_pa_s "
                                 f"length_m) = {g_min:.6g} m²/(Pa·s) (tighter is the fully "
                                 f"sealed limit; its pressure level would be lost in "
                                 f"round-off), got {g!r}")

    def films(self, jx: int, jy: int, name: str) -> list:
        return [pad_film(name=name, diameter_m=self.diameter_m, length_m=self.length_m,
                         clearance_m=self.clearance_m, viscosity_pa_s=self.viscosity_pa_s,
                         cavitation=self.cavitation, start_rad=0.0, arc_rad=2 * math.pi,
                         pivot_rad=0.0, preload=0.0, n_circ=self.n_circ, n_axial=self.n_axial,
                         coords=[jx, jy], spin=0.0,
                         end_seal_conductance=self.end_seal_conductance_m3_per_pa_s_per_m,
                         short_bearing=self.film_model == "short")]

    def _spring(self, jx: int, jy: int, name: str) -> list:
        if self.centring_spring_n_per_m == 0.0:
            return []
        t = _core.TableCoupling()
        t.name, t.coords = f"{name}.centring_spring", [int(jx), int(jy)]
        k = self.centring_spring_n_per_m
        t.omegas = np.array([0.0])
        t.K = np.array([[k, 0.0, 0.0, k]])
        t.C = np.zeros((1, 4))
        return [t]

    def system_parts(self, jx: int, jy: int, first_extra: int, name: str) -> SystemParts:
        return SystemParts(films=self.films(jx, jy, name), tables=self._spring(jx, jy, name))

    # -- standalone -----------------------------------------------------------------------
    def _solver(self):
        model = _core.SystemModel()
        z = np.zeros((2, 2))
        model.M, model.K, model.C, model.G = z, z, z, z
        model.Q, model.chamber = np.zeros(2), np.zeros(2)
        model.films = [p.coupling for p in self.films(0, 1, self.name or "damper")]
        return _core.SystemSolver(model)

    def forces(self, *, x_m: float, y_m: float, vx_m_s: float, vy_m_s: float) -> np.ndarray:
        """Film force (Fx, Fy) on the damper journal at (x, y) moving at (vx, vy), N (the
        centring spring not included)."""
        r = np.array([v.finite("x_m", x_m), v.finite("y_m", y_m)])
        if np.hypot(*r) >= self.clearance_m:
            raise InputError(f"x_m, y_m: expected a journal inside the clearance circle "
                             f"(|r| < {self.clearance_m:g} m)")
        rd = np.array([v.finite("vx_m_s", vx_m_s), v.finite("vy_m_s", vy_m_s)])
        return np.asarray(self._solver().film_forces(r, rd, 0.0))

    def orbit_coefficients(self, *, eccentricity_ratio: float, whirl_hz: float) -> dict:
        """Equivalent linear coefficients of a circular centred orbit (radius εc, whirl ν):
        radial and tangential forces F_r, F_t (N), K_eq = −F_r/e (N/m) and C_eq = −F_t/(eν)
        (N·s/m), the usual way to linearise a cavitated damper for linear analyses."""
        # below 1e-6 the orbit is the linear limit (and e = εc underflows): use K, C at the
        # centre (coefficient_table) instead
        eps = v.in_range("eccentricity_ratio", eccentricity_ratio, 1e-6, 1.0, hi_open=True)
        nu = 2 * math.pi * v.finite("whirl_hz", whirl_hz)
        if nu == 0:
            raise InputError("whirl_hz: expected a nonzero whirl frequency")
        e = eps * self.clearance_m
        fr, ft = self.forces(x_m=e, y_m=0.0, vx_m_s=0.0, vy_m_s=e * nu)
        return {"f_r_n": float(fr), "f_t_n": float(ft), "k_eq_n_per_m": float(-fr / e),
                "c_eq_n_s_per_m": float(-ft / (e * nu))}
