"""Tilting-pad journal bearing: pads on pivots, each pad's tilt a coordinate of the system
(with the pad's inertia), optionally its radial pivot displacement (pivot stiffness and pad
mass), so the full eigen-analysis and the transient see the pad dynamics; and the reduced
2×2 coefficients (synchronous, or at a given whirl frequency) for users who want them.

Geometry (``_film.py``): pad k's pivot at ψ_k; the pad spans ``pad_arc_deg`` with the pivot
at the fraction ``pivot_offset`` of the arc from its leading edge; load ``"between"`` pads
puts the pivots at 270° ± 180°/n (pads straddle the downward load), ``"on"`` puts pad 0's
pivot at 270°. Film of pad k with the journal at (x, y), tilt δ_k (rad, positive with the
rotation, about the pivot at the radius R + t, t = ``pad_thickness_m``) and pivot
displacement u_k (outward along ψ_k):

    h = C_p − (C_p − C_b) cos(φ − ψ_k) − x cos φ − y sin φ − (R + t) δ_k sin(φ − ψ_k)
        + u_k cos(φ − ψ_k).

The film moment about the pivot and the radial pivot force follow by virtual work from the
shape columns (−(R + t) sin(φ − ψ), cos(φ − ψ)). A pad is in equilibrium when its film
moment is zero (plus ``tilt_stiffness_n_m_per_rad``·δ if the pivot resists tilt; the key was
``tilt_stiffness_nm_per_rad`` before, still read with a deprecation warning: "nm" reads as
nanometres against the suffix vocabulary's ``_n_per_m``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.status import CONVERGED
from rotordyn.bearings._film import (SystemParts, check_arc, check_film_fields, check_load,
                                     check_speeds, operating_table, pad_film, speed_limit)
from rotordyn.bearings.coefficients import coefficient_table
from rotordyn.bearings.pad_thd import (freeze_fields, pad_fields, pad_model_options,
                                        pad_thd_equilibrium)
from rotordyn.errors import InputError


@dataclass(frozen=True, slots=True)
class TiltingPadBearing:
    """Tilting-pad journal bearing at ``station`` (module docstring for the geometry)."""

    station: int
    diameter_m: float
    length_m: float
    clearance_m: float
    viscosity_pa_s: float
    n_pads: int = 4
    pad_arc_deg: float = 80.0
    pivot_offset: float = 0.5
    preload: float = 0.0
    load: str = "between"
    orientation_deg: float | None = None
    pad_inertia_kg_m2: float = 1e-4
    pad_thickness_m: float = 0.0
    tilt_stiffness_n_m_per_rad: float = 0.0
    pivot_stiffness_n_per_m: float = 0.0
    pad_mass_kg: float = 0.0
    cavitation: str = "reynolds"
    n_circ: int = 72
    n_axial: int = 16
    turbulence: str = "laminar"
    density_kg_m3: float | None = None
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""
    # journal tilt (the film on the station's rotations, as fixed-geometry and plain
    # bearings have it): not yet for pads, refused (the core's pad-by-pad equilibrium takes
    # no pad film with axial weights)
    tilt: bool = False
    # a frozen viscosity per node and pad, Pa·s: per pad (N_pad, n_axial + 1) as nested tuples
    # (the THD pads' temperature fields at their thermal equilibrium, pad_thd.py); None:
    # viscosity_pa_s everywhere
    viscosity_field_pa_s: tuple | None = None
    # deprecated spelling of tilt_stiffness_n_m_per_rad (read, moved there, then None)
    tilt_stiffness_nm_per_rad: float | None = None

    def __post_init__(self):
        old = self.tilt_stiffness_nm_per_rad
        if old is not None:
            import warnings

            from rotordyn.errors import RotordynDeprecationWarning

            if self.tilt_stiffness_n_m_per_rad != 0.0:
                raise InputError("tilt_stiffness_nm_per_rad: the old name of "
                                 "tilt_stiffness_n_m_per_rad; give one of them, not both")
            warnings.warn("tilt_stiffness_nm_per_rad is renamed tilt_stiffness_n_m_per_rad "
                          "(N·m/rad; 'nm' read as nanometres); the old key is read for now",
                          RotordynDeprecationWarning, stacklevel=3)
            object.__setattr__(self, "tilt_stiffness_n_m_per_rad", old)
            object.__setattr__(self, "tilt_stiffness_nm_per_rad", None)
        if self.viscosity_field_pa_s is not None:
            object.__setattr__(self, "viscosity_field_pa_s",
                               freeze_fields(self.viscosity_field_pa_s))
        self.check("tilting_pad_bearing", None)

    def check(self, where: str, n_stations: int | None) -> None:
        check_film_fields(self, where, n_stations)
        v.integer(f"{where}.n_pads", self.n_pads, lo=1, hi=32)
        v.in_range(f"{where}.pad_arc_deg", self.pad_arc_deg, 0.0, 360.0 / self.n_pads,
                   lo_open=True, hi_open=True)
        check_arc(f"{where}.pad_arc_deg", self.pad_arc_deg, self)
        if self.tilt is not False:
            raise InputError(f"{where}.tilt: journal tilt is not available for tilting-pad "
                             f"bearings yet (the pads' films are solved without the journal's "
                             f"rotations); expected false, got {self.tilt!r}")
        v.in_range(f"{where}.pivot_offset", self.pivot_offset, 0.0, 1.0, lo_open=True,
                   hi_open=True)
        v.in_range(f"{where}.preload", self.preload, 0.0, 1.0, hi_open=True)
        v.choice(f"{where}.load", self.load, ("between", "on"))
        if self.orientation_deg is not None:
            v.finite(f"{where}.orientation_deg", self.orientation_deg)
        v.positive(f"{where}.pad_inertia_kg_m2", self.pad_inertia_kg_m2)
        v.non_negative(f"{where}.pad_thickness_m", self.pad_thickness_m)
        v.non_negative(f"{where}.tilt_stiffness_n_m_per_rad", self.tilt_stiffness_n_m_per_rad)
        v.non_negative(f"{where}.pivot_stiffness_n_per_m", self.pivot_stiffness_n_per_m)
        v.non_negative(f"{where}.pad_mass_kg", self.pad_mass_kg)
        if self.pivot_stiffness_n_per_m > 0 and not self.pad_mass_kg > 0:
            raise InputError(f"{where}.pad_mass_kg: expected a value > 0 with a flexible pivot "
                             f"(pivot_stiffness_n_per_m = {self.pivot_stiffness_n_per_m:g})")
        if self.cavitation == "jfo":
            raise InputError(f"{where}.cavitation: 'jfo' is not supported on tilting pads; use "
                             "'reynolds', 'gumbel' or 'none'")

    # -- geometry -------------------------------------------------------------------------
    def pivot_angles_deg(self) -> np.ndarray:
        """(n_pads,) pivot angles ψ_k, deg."""
        if self.orientation_deg is not None:
            first = self.orientation_deg
        else:
            first = 270.0 + (180.0 / self.n_pads if self.load == "between" else 0.0)
        return (first + 360.0 / self.n_pads * np.arange(self.n_pads)) % 360.0

    @property
    def flexible_pivot(self) -> bool:
        return self.pivot_stiffness_n_per_m > 0

    @property
    def dofs_per_pad(self) -> int:
        return 2 if self.flexible_pivot else 1

    @property
    def lever_m(self) -> float:
        """Pivot lever ℓ = R + t, m."""
        return 0.5 * self.diameter_m + self.pad_thickness_m

    def system_parts(self, jx: int, jy: int, first_extra: int, name: str) -> SystemParts:
        """Pad coordinates: η_k = q·t_k + ℓ δ_k, the journal's tangential offset relative to
        tilted pad k (t_k the unit tangent at the pivot), m, and with a flexible pivot u_k.
        In (q, η) each pad's film depends on the journal only through its radial offset
        ξ_k = q·n_k: h = base − ξ_k cos θ − η_k sin θ + u_k cos θ (θ = φ − ψ_k). This keeps
        Newton's steps from dragging a pad into the pressure-free (fully divergent) branch
        when the journal moves tangentially to it. Tilt δ_k = (η_k − q·t_k)/ℓ: the pad's
        kinetic energy ½ I δ̇² and tilt spring ½ k_t δ² couple η_k with the journal in M, K."""
        lever = self.lever_m
        arc = math.radians(self.pad_arc_deg)
        films, labels = [], []
        npd = self.dofs_per_pad
        n = npd * self.n_pads
        M = np.zeros((2 + n, 2 + n))
        K = np.zeros((2 + n, 2 + n))
        P = np.zeros((2 + n, 2 + n))
        groups = []  # each pad's own coordinates (tilt, pivot): the pad-assembly equilibrium
        for k, psi_deg in enumerate(self.pivot_angles_deg()):
            psi = math.radians(psi_deg)
            cp, sp = math.cos(psi), math.sin(psi)
            start = psi - self.pivot_offset * arc
            ik = 2 + npd * k
            coords = [jx, jy, first_extra + npd * k]
            shapes = [lambda phi, psi=psi: -np.sin(phi - psi)]
            labels.append(f"{name}.pad{k}.eta")
            a = np.zeros(2 + n)  # δ_k = a · [qx, qy, extras]
            a[0], a[1], a[ik] = sp / lever, -cp / lever, 1.0 / lever
            M += self.pad_inertia_kg_m2 * np.outer(a, a)
            K += self.tilt_stiffness_n_m_per_rad * np.outer(a, a)
            P += np.outer(a, a)  # fallback equilibrium homotopy: tilts held at 0 first
            groups.append([ik] + ([ik + 1] if self.flexible_pivot else []))
            if self.flexible_pivot:
                coords.append(first_extra + npd * k + 1)
                shapes.append(lambda phi, psi=psi: np.cos(phi - psi))
                labels.append(f"{name}.pad{k}.pivot")
                M[ik + 1, ik + 1] = self.pad_mass_kg
                P[ik + 1, ik + 1] = 1.0 / lever ** 2  # and pivots at u = 0
                K[ik + 1, ik + 1] = self.pivot_stiffness_n_per_m
            pf = pad_film(
                name=f"{name}.pad{k}", diameter_m=self.diameter_m, length_m=self.length_m,
                clearance_m=self.clearance_m, viscosity_pa_s=self.viscosity_pa_s,
                cavitation=self.cavitation, start_rad=start, arc_rad=arc, pivot_rad=psi,
                preload=self.preload, n_circ=self.n_circ, n_axial=self.n_axial, coords=coords,
                extra_shapes=shapes, turbulence=self.turbulence, density_kg_m3=self.density_kg_m3)
            # journal columns in (q, η): −cos θ n_k (the tangential part is carried by η)
            S = np.asarray(pf.coupling.shape).copy()
            on = pf.on_pad
            th = pf.phi[on] - psi
            S[on, 0] = -np.cos(th) * cp
            S[on, 1] = -np.cos(th) * sp
            pf.coupling.shape = S
            films.append(pf)
        pad_fields(self.viscosity_field_pa_s, films, f"{name}.viscosity_field_pa_s")
        return SystemParts(films=films, tables=[], n_extra=n, M=M, K=K,
                           C=np.zeros((2 + n, 2 + n)), labels=tuple(labels), penalty=P,
                           pad_groups=groups)

    def pad_tilts_rad(self, r) -> np.ndarray:
        """Pad tilts δ_k (rad) from standalone coordinates r = [x, y, pad coordinates...]."""
        r = np.asarray(r, dtype=float)
        psi = np.radians(self.pivot_angles_deg())
        eta = r[2::self.dofs_per_pad][: self.n_pads]
        qt = -r[0] * np.sin(psi) + r[1] * np.cos(psi)
        return (eta - qt) / self.lever_m

    # -- standalone -----------------------------------------------------------------------
    def coefficient_table(self, speeds_hz, load_n, *, whirl_ratio: float | None = 1.0,
                          n_threads: int = 1):
        """Equilibrium (journal and pads) under ``load_n`` (N) and the journal's 2×2 K, C with
        the pad coordinates condensed at the whirl frequency ``whirl_ratio``·Ω (1:
        synchronous; None: static condensation), per speed (Hz), parallel over speeds."""
        if whirl_ratio is not None:
            v.finite("whirl_ratio", whirl_ratio)
        parts = self.system_parts(0, 1, 2, self.name or "bearing")
        return coefficient_table(parts, load_n, speeds_hz, self.clearance_m,
                                 n_threads=n_threads, whirl_ratio=whirl_ratio)

    def full_coefficients(self, speed_hz: float, load_n):
        """The unreduced coefficients at one speed: (r, K, C, M) with r the equilibrium
        (journal x, y then the pad coordinates η_k [, u_k], see :meth:`system_parts`;
        :meth:`pad_tilts_rad` gives the tilts) and K, C, M (2 + n_pad_dofs square)."""
        parts = self.system_parts(0, 1, 2, self.name or "bearing")
        r, K, C, status, message, M = operating_table(
            parts, check_load(load_n), check_speeds(speed_hz, *speed_limit(parts.films)))

        if status[0] not in CONVERGED:  # ok, or contact (converged with a thin film)
            from rotordyn.errors import ConvergenceError

            raise ConvergenceError(f"tilting-pad equilibrium: {status[0]}: {message[0]}")
        return r[0], K[0], C[0], M

    def thermal_equilibrium(self, *, load_n, speed_hz: float, oil, supply_temperature_c: float,
                            carry_over: float = 0.0, supply_flow_m3_s: float = 0.0,
                            journal_htc_w_m2k: float = 0.0, bush_htc_w_m2k: float = 0.0,
                            journal_temperature_c: float | None = None,
                            bush_temperature_c: float | None = None, tol_k: float = 1e-6,
                            model: str = "thd", effective_factor: float = 0.5,
                            whirl_ratio: float | None = 1.0, **walls):
        """Thermo-hydrodynamic equilibrium under ``load_n`` (N) at ``speed_hz``: per pad the
        energy equation, μ(T) per node of ``oil`` (:class:`rotordyn.bearings.Oil`), the
        inlet of each pad mixing supply oil at ``supply_temperature_c`` °C with the part
        ``carry_over`` λ of the hot oil leaving the upstream pad (Ettles' carry-over),
        ``supply_flow_m3_s`` the bearing's fresh oil (0: each pad's demand), heat-transfer
        coefficients W/(m² K) to journal and pads (0: adiabatic) at the wall temperatures °C
        (None: the supply temperature) — iterated with the pad equilibrium (journal and tilts)
        in one C++ call, to max |ΔT| <= ``tol_k`` K. K, C (2×2, reduced over the pads at
        ``whirl_ratio``·Ω; None: static condensation) with the temperature field frozen:
        a :class:`rotordyn.bearings.pad_thd.PadThdResult` (module ``pad_thd`` for the
        model).

        ``model="effective"``: the effective-temperature model per pad instead (each pad
        isoviscous at μ(T_eff), T_eff = T_in + ``effective_factor`` ΔT, ΔT from the pad's
        power loss and flows, the same inlet mixing; the wall options are THD-only;
        docs/film-physics.md §"Effective-temperature pad bearings").

        ``walls``: the THD film's heat paths (:mod:`rotordyn.bearings.thd_walls`:
        ``wall_htc``, ``journal_wall = "balance"`` — one journal temperature from the heat
        balance over all pads —, ``bush_wall = "conduction"`` with the pad's
        ``bush_thickness_m``, ``bush_conductivity_w_per_m_k``, ``back_htc_w_m2k``,
        ``back_temperature_c``)."""
        if whirl_ratio is not None:
            v.finite("whirl_ratio", whirl_ratio)
        opts = pad_model_options(model, supply_temperature_c=supply_temperature_c,
                                 supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                                 effective_factor=effective_factor, tol_k=tol_k,
                                 journal_htc_w_m2k=journal_htc_w_m2k,
                                 bush_htc_w_m2k=bush_htc_w_m2k,
                                 journal_temperature_c=journal_temperature_c,
                                 bush_temperature_c=bush_temperature_c, **walls)
        parts = self.system_parts(0, 1, 2, self.name or "bearing")
        return pad_thd_equilibrium(parts, oil=oil, opts=opts, load_n=load_n, speed_hz=speed_hz,
                                   clearance_m=self.clearance_m, whirl_ratio=whirl_ratio,
                                   tilts=self.pad_tilts_rad)

    def pad_films(self):
        """The pads' C++ film couplings on the standalone coordinates (x, y, pad dofs)."""
        return self.system_parts(0, 1, 2, self.name or "bearing").films


