"""Rotor description: materials, shaft sections (Timoshenko elements), disks, supports and the
reduction (condensation) of the rotor model.

Stations are the section boundaries, numbered 0 … n_sections from the left end; a section with
``n_elements > 1`` is subdivided into equal Timoshenko elements whose inner nodes are not
stations. SI units; field names carry their unit (``length_m``, ``density_kg_m3``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn.errors import InputError
from rotordyn._common import validate as v
from rotordyn._common import plausibility


@dataclass(frozen=True, slots=True)
class Material:
    """Isotropic linear-elastic material. Give ``poisson`` or ``shear_modulus_pa`` (or both:
    then the shear modulus is used and ν = E/(2G) − 1 enters the shear coefficient)."""

    name: str
    density_kg_m3: float
    young_pa: float
    poisson: float = 0.3
    shear_modulus_pa: float | None = None

    def __post_init__(self):
        f = f"material.{self.name}"
        if not isinstance(self.name, str) or not self.name:
            raise InputError(f"material name: expected a non-empty string, got {self.name!r}")
        v.positive(f"{f}.density_kg_m3", self.density_kg_m3)
        v.positive(f"{f}.young_pa", self.young_pa)
        v.in_range(f"{f}.poisson", self.poisson, -1.0, 0.5, lo_open=True, hi_open=True)
        if self.shear_modulus_pa is not None:
            v.positive(f"{f}.shear_modulus_pa", self.shear_modulus_pa)
        plausibility.young_modulus(f"{f}.young_pa", self.young_pa)
        plausibility.density(f"{f}.density_kg_m3", self.density_kg_m3)

    @property
    def shear_modulus(self) -> float:
        """G in Pa."""
        if self.shear_modulus_pa is not None:
            return float(self.shear_modulus_pa)
        return self.young_pa / (2.0 * (1.0 + self.poisson))


STEEL = Material("steel", density_kg_m3=7850.0, young_pa=2.1e11, poisson=0.3)


@dataclass(frozen=True, slots=True)
class ShaftSection:
    """A uniform shaft section between two stations, meshed with ``n_elements`` Timoshenko
    beam elements (shear, rotary inertia, gyroscopics). Solid when inner_diameter_m = 0."""

    length_m: float
    outer_diameter_m: float
    inner_diameter_m: float = 0.0
    material: str = "steel"
    n_elements: int = 1
    shear_coefficient: float | None = None  # None: Cowper's value for the section
    # material damping of this section (None: the rotor's damping_alpha_1_per_s /
    # damping_beta_s): C_e = α M_e + β K_e of each of its elements
    damping_alpha_1_per_s: float | None = None
    damping_beta_s: float | None = None

    def check(self, where: str) -> None:
        """Validate; ``where`` is the field path used in messages (``rotor.section[3]``)."""
        v.positive(f"{where}.length_m", self.length_m)
        v.positive(f"{where}.outer_diameter_m", self.outer_diameter_m)
        v.non_negative(f"{where}.inner_diameter_m", self.inner_diameter_m)
        if self.inner_diameter_m >= self.outer_diameter_m:
            raise InputError(
                f"{where}.inner_diameter_m: expected a value in [0, outer_diameter_m = "
                f"{self.outer_diameter_m}), got {self.inner_diameter_m!r}"
            )
        v.integer(f"{where}.n_elements", self.n_elements, lo=1, hi=10000)
        v.text(f"{where}.material", self.material)
        plausibility.length(f"{where}.outer_diameter_m", self.outer_diameter_m)
        plausibility.length(f"{where}.length_m", self.length_m, plausibility.MAX_SECTION_LENGTH_M)
        if self.shear_coefficient is not None:
            v.in_range(f"{where}.shear_coefficient", self.shear_coefficient, 0.0, 2.0,
                       lo_open=True)
        for f in ("damping_alpha_1_per_s", "damping_beta_s"):
            if getattr(self, f) is not None:
                v.non_negative(f"{where}.{f}", getattr(self, f))

    @property
    def area_m2(self) -> float:
        return math.pi / 4.0 * (self.outer_diameter_m**2 - self.inner_diameter_m**2)

    def mass_kg(self, material: Material) -> float:
        return material.density_kg_m3 * self.area_m2 * self.length_m

    def to_core(self, material: Material, *, shear: bool = True,
                rotary_inertia: bool = True, damping_alpha_1_per_s: float = 0.0,
                damping_beta_s: float = 0.0) -> list:
        """The section's C++ elements (``n_elements`` equal ``_core.ShaftElement``). The
        damping arguments are the rotor's; the section's own values, when given, win."""
        alpha = (damping_alpha_1_per_s if self.damping_alpha_1_per_s is None
                 else self.damping_alpha_1_per_s)
        beta = damping_beta_s if self.damping_beta_s is None else self.damping_beta_s
        out = []
        for _ in range(self.n_elements):
            e = _core.ShaftElement()
            e.length = self.length_m / self.n_elements
            e.outer_diameter = self.outer_diameter_m
            e.inner_diameter = self.inner_diameter_m
            e.density = material.density_kg_m3
            e.young = material.young_pa
            e.shear_modulus = material.shear_modulus
            e.shear_coefficient = -1.0 if self.shear_coefficient is None else self.shear_coefficient
            e.shear = shear
            e.rotary_inertia = rotary_inertia
            e.damping_alpha = float(alpha)
            e.damping_beta = float(beta)
            out.append(e)
        return out

    def M(self, material: Material = STEEL) -> np.ndarray:
        """8×8 mass matrix of one element of this section, DOF (x1, y1, θx1, θy1, x2, …)."""
        return self._one(material)[0]

    def K(self, material: Material = STEEL) -> np.ndarray:
        """8×8 stiffness matrix of one element of this section."""
        return self._one(material)[1]

    def G(self, material: Material = STEEL) -> np.ndarray:
        """8×8 gyroscopic matrix (per unit spin speed, rad/s) of one element."""
        return self._one(material)[2]

    def _one(self, material: Material):
        single = ShaftSection(self.length_m / self.n_elements, self.outer_diameter_m,
                              self.inner_diameter_m, self.material, 1, self.shear_coefficient)
        return _core.element_matrices(single.to_core(material)[0])


@dataclass(frozen=True, slots=True)
class Disk:
    """Rigid disk at a station: mass, polar (ip) and diametral (id) moments of inertia.

    The geometry it was made from (:meth:`from_geometry`: ``outer_diameter_m``,
    ``inner_diameter_m``, ``width_m``, ``material``) is kept when known, for the drawing and the
    model file (the TOML writes it beside the inertias; a TOML disk may give only the geometry
    and its material, the inertias are then computed)."""

    station: int
    mass_kg: float
    ip_kg_m2: float
    id_kg_m2: float
    outer_diameter_m: float | None = None
    inner_diameter_m: float | None = None
    width_m: float | None = None
    material: str = ""
    name: str = ""

    def check(self, where: str, n_stations: int) -> None:
        v.integer(f"{where}.station", self.station, lo=0, hi=n_stations - 1)
        v.non_negative(f"{where}.mass_kg", self.mass_kg)
        v.non_negative(f"{where}.ip_kg_m2", self.ip_kg_m2)
        v.non_negative(f"{where}.id_kg_m2", self.id_kg_m2)
        v.text(f"{where}.material", self.material)
        v.text(f"{where}.name", self.name)
        if self.outer_diameter_m is not None:
            do = v.positive(f"{where}.outer_diameter_m", self.outer_diameter_m)
            plausibility.length(f"{where}.outer_diameter_m", do)
            if self.inner_diameter_m is not None:
                di = v.non_negative(f"{where}.inner_diameter_m", self.inner_diameter_m)
                if di >= do:
                    raise InputError(f"{where}.inner_diameter_m: expected a value below "
                                     f"outer_diameter_m = {do!r}, got {di!r}")
        if self.width_m is not None:
            v.positive(f"{where}.width_m", self.width_m)

    @classmethod
    def from_geometry(cls, station: int, material: Material, width_m: float,
                      outer_diameter_m: float, inner_diameter_m: float = 0.0,
                      name: str = "") -> "Disk":
        """Solid-of-revolution disk: m = ρ π/4 (do² − di²) w, Ip = m (do² + di²)/8,
        Id = Ip/2 + m w²/12. The geometry and the material's name are kept."""
        v.positive("disk.width_m", width_m)
        v.positive("disk.outer_diameter_m", outer_diameter_m)
        v.non_negative("disk.inner_diameter_m", inner_diameter_m)
        if inner_diameter_m >= outer_diameter_m:
            raise InputError(f"disk.inner_diameter_m: expected a value below outer_diameter_m "
                             f"= {outer_diameter_m!r}, got {inner_diameter_m!r}")
        m = material.density_kg_m3 * math.pi / 4 * (outer_diameter_m**2 - inner_diameter_m**2) * width_m
        ip = m * (outer_diameter_m**2 + inner_diameter_m**2) / 8.0
        return cls(station, m, ip, ip / 2.0 + m * width_m**2 / 12.0, float(outer_diameter_m),
                   float(inner_diameter_m), float(width_m), material.name, name)


_SUPPORT_COEFS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m",
                  "cxx_n_s_per_m", "cxy_n_s_per_m", "cyx_n_s_per_m", "cyy_n_s_per_m")


@dataclass(frozen=True, slots=True)
class Support:
    """Support at a station: ``type="rigid"`` fixes x and y (rotations free, e.g. a ball
    bearing), ``type="linear"`` adds a translational spring/damper to ground."""

    station: int
    type: str = "rigid"
    kxx_n_per_m: float = 0.0
    kxy_n_per_m: float = 0.0
    kyx_n_per_m: float = 0.0
    kyy_n_per_m: float = 0.0
    cxx_n_s_per_m: float = 0.0
    cxy_n_s_per_m: float = 0.0
    cyx_n_s_per_m: float = 0.0
    cyy_n_s_per_m: float = 0.0
    name: str = ""

    def check(self, where: str, n_stations: int) -> None:
        v.integer(f"{where}.station", self.station, lo=0, hi=n_stations - 1)
        v.choice(f"{where}.type", self.type, ("rigid", "linear"))
        v.text(f"{where}.name", self.name)
        for c in _SUPPORT_COEFS:
            val = v.finite(f"{where}.{c}", getattr(self, c))
            if self.type == "rigid" and val != 0.0:
                raise InputError(f"{where}.{c}: a rigid support takes no coefficients, got {val!r}")

    def k(self) -> np.ndarray:
        return np.array([[self.kxx_n_per_m, self.kxy_n_per_m], [self.kyx_n_per_m, self.kyy_n_per_m]])

    def c(self) -> np.ndarray:
        return np.array([[self.cxx_n_s_per_m, self.cxy_n_s_per_m],
                         [self.cyx_n_s_per_m, self.cyy_n_s_per_m]])


@dataclass(frozen=True, slots=True)
class Rotor:
    """Shaft sections (left to right) and rigid disks.

    Material damping of the shaft (ROSS's ShaftElement ``alpha``, ``beta``): each element adds
    ``C_e = α M_e + β K_e`` to the damping matrix C, stationary (fixed frame); the disks and
    supports add none. ``damping_alpha_1_per_s`` (α, 1/s) and ``damping_beta_s`` (β, s) hold
    for every section that gives no value of its own. A mode of the undamped rotor at rest on
    rigid supports (circular frequency ω) gets the damping ratio ζ = α/(2ω) + βω/2 (the α
    term exactly only without disks, whose mass takes no α); a hysteretic loss
    factor η at a reference frequency is β = η/ω_ref (:meth:`beta_from_loss_factor`).
    0 (the default) is the undamped shaft.

    ``damping_rotating``: the β part acts in the rotating shaft (internal damping): besides
    β K_e in C, the fixed-frame equations get the circulatory stiffness Ω K_c,
    K_c = −(Σ β_e K_e) J (J turns every node's (x, y) and (θx, θy) by 90° about z), which
    destabilises forward whirl above a threshold speed. Carried by the rotor-alone analyses
    (:func:`rotordyn.modes`, :func:`rotordyn.rotor_campbell`) and by every system analysis
    (the solver's H includes −Ω K_c r, the offsets' −Ω K_c a is a load) and
    :func:`rotordyn.static` (the internal forces include Ω K_c u). α stays stationary (external damping) either way (docs/model-file.md)."""

    sections: tuple[ShaftSection, ...]
    disks: tuple[Disk, ...] = field(default_factory=tuple)
    damping_alpha_1_per_s: float = 0.0
    damping_beta_s: float = 0.0
    damping_rotating: bool = False

    def __post_init__(self):
        object.__setattr__(self, "sections", tuple(self.sections))
        object.__setattr__(self, "disks", tuple(self.disks))
        v.non_negative("rotor.damping_alpha_1_per_s", self.damping_alpha_1_per_s)
        v.non_negative("rotor.damping_beta_s", self.damping_beta_s)
        v.boolean("rotor.damping_rotating", self.damping_rotating)
        if not self.sections:
            raise InputError("rotor.section: expected at least one shaft section, got none")
        for i, s in enumerate(self.sections):
            if not isinstance(s, ShaftSection):
                raise InputError(f"rotor.section[{i}]: expected a ShaftSection, got {type(s).__name__}")
            s.check(f"rotor.section[{i}]")
        for i, d in enumerate(self.disks):
            d.check(f"disk[{i}]", self.n_stations)

    @staticmethod
    def beta_from_loss_factor(loss_factor: float, reference_hz: float) -> float:
        """β (s) of a hysteretic loss factor η matched at one frequency: β = η/(2π f_ref).
        Viscous β damps a mode at ω with ζ = βω/2, i.e. η(ω/ω_ref)/2: equal to the
        hysteretic ζ = η/2 at f_ref only (above it β over-damps, below it under-damps)."""
        eta = v.non_negative("loss_factor", loss_factor)
        f = v.positive("reference_hz", reference_hz)
        return eta / (2.0 * math.pi * f)

    @property
    def has_rotating_damping(self) -> bool:
        """``damping_rotating`` with a β > 0 on some section (the circulatory term exists)."""
        return bool(self.damping_rotating) and any(
            (self.damping_beta_s if s.damping_beta_s is None else s.damping_beta_s) > 0
            for s in self.sections)

    @property
    def n_stations(self) -> int:
        return len(self.sections) + 1

    @property
    def n_elements(self) -> int:
        return sum(s.n_elements for s in self.sections)

    def station_nodes(self) -> np.ndarray:
        """FE node index of each station, shape (n_stations,)."""
        return np.concatenate([[0], np.cumsum([s.n_elements for s in self.sections])]).astype(np.int64)

    def station_positions_m(self) -> np.ndarray:
        """Axial position of each station from the left end, shape (n_stations,), m."""
        return np.concatenate([[0.0], np.cumsum([s.length_m for s in self.sections])])

    def node_positions_m(self) -> np.ndarray:
        """Axial position of each FE node, shape (n_elements + 1,), m."""
        z = [0.0]
        for s in self.sections:
            for _ in range(s.n_elements):
                z.append(z[-1] + s.length_m / s.n_elements)
        return np.array(z)

    @property
    def length_m(self) -> float:
        return float(sum(s.length_m for s in self.sections))


REDUCTION_METHODS = ("none", "guyan", "irs", "craig-bampton")


@dataclass(frozen=True, slots=True)
class Reduction:
    """Condensation of the rotor to translations (x, y) at master stations (paper §4, §6).

    ``method``: ``"guyan"`` (the paper's), ``"irs"`` (improved reduced system) or
    ``"craig-bampton"`` (masters plus ``n_modes`` fixed-interface modes); ``"none"`` keeps the
    full model. Default: ``"guyan"`` when master stations are given, else ``"none"`` (a
    reduction without masters is refused, so every written model file can be analysed)."""

    master_stations: tuple[int, ...] = ()
    method: str | None = None
    n_modes: int = 0

    def __post_init__(self):
        object.__setattr__(self, "master_stations", tuple(
            v.sequence("reduction.master_stations", self.master_stations)))
        if self.method is None:
            object.__setattr__(self, "method", "guyan" if self.master_stations else "none")
        v.choice("reduction.method", self.method, REDUCTION_METHODS)
        if self.method != "none" and not self.master_stations:
            raise InputError(
                f"reduction.master_stations: method {self.method!r} needs at least one master "
                "station (or set method = \"none\" for the full model)")
        v.integer("reduction.n_modes", self.n_modes, lo=0, hi=1000)
        seen = set()
        for i, s in enumerate(self.master_stations):
            v.integer(f"reduction.master_stations[{i}]", s, lo=0)
            if s in seen:
                raise InputError(f"reduction.master_stations[{i}]: station {s} is listed twice")
            seen.add(s)
