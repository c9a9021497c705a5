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

Journal tilt (``tilt = True``; docs/film-physics.md, "Tilting-pad bearings"): every pad's
film couples to the station's rotations (θx, θy) too, with the plain bearing's convention
(the journal centre at z is at (x + θy z, y − θx z)), and the housing's angular
misalignment (``config_theta_x_rad``, ``config_theta_y_rad``) is the configuration at them.
``pivot_type``: ``"rocker"`` (default; a line-contact rocker back or a cylindrical pivot: the
pad rocks about the pivot line and is axially rigid, it cannot follow the journal's slope) or
``"spherical"`` (a ball-and-socket pivot: the pad also pitches, γ_k its rotation about the
tangent t_k at the pivot, right-hand rule, so its surface at z moves outward by γ_k z:
h += γ_k z cos(φ − ψ_k); pitch inertia ``pitch_inertia_kg_m2`` (None: ``pad_inertia_kg_m2``)
and an optional ``pitch_stiffness_n_m_per_rad``). The pad's rotation about its radial axis
(yaw) is not modelled (held). Without ``tilt`` a spherical pivot adds no coordinate: the
aligned film is symmetric in z, so it exerts no pitch moment and the pitch decouples.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.status import CONVERGED
from rotordyn.bearings._film import (SystemParts, check_arc, check_film_fields, check_load,
                                     check_speeds, operating_table, pad_film, speed_limit,
                                     tilt_fields)
from rotordyn.bearings.coefficients import coefficient_table
from rotordyn.bearings.pad_thd import (freeze_fields, pad_fields, pad_model_options,
                                        pad_thd_equilibrium)
from rotordyn.errors import ClosedFilmError, InputError


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
    # the turbulent film's optional laminar-to-turbulent transition (Re_h at which the
    # corrections start and are full; both or neither; docs/film-physics.md)
    turbulence_onset_re: float | None = None
    turbulence_full_re: float | None = None
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""
    # journal tilt: every pad's film couples to the station's rotations too; the housing's
    # angular misalignment (rad, right-hand rule about x, y) is the configuration a at them
    tilt: bool = False
    config_theta_x_rad: float = 0.0
    config_theta_y_rad: float = 0.0
    # "rocker" (axially rigid pads) or "spherical" (pads pitch about the pivot's tangent;
    # with tilt only), module docstring
    pivot_type: str = "rocker"
    pitch_inertia_kg_m2: float | None = None
    pitch_stiffness_n_m_per_rad: float = 0.0
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
        v.choice(f"{where}.pivot_type", self.pivot_type, ("rocker", "spherical"))
        if self.pitch_inertia_kg_m2 is not None:
            v.positive(f"{where}.pitch_inertia_kg_m2", self.pitch_inertia_kg_m2)
        v.non_negative(f"{where}.pitch_stiffness_n_m_per_rad", self.pitch_stiffness_n_m_per_rad)
        self._check_tilt(where)

    def _check_tilt(self, where: str) -> None:
        """``tilt`` (bool), the misalignment (finite, only with tilt, and not closing any pad's
        film at an edge for a journal on the housing's axis: :meth:`edge_film` > 0)."""
        tx, ty = tilt_fields(self, where)
        h, z, k = self.edge_film(0.0, 0.0, tx, ty)
        if not h > 0.0:
            raise ClosedFilmError(
                f"{where}.config_theta_x_rad, config_theta_y_rad: the misalignment closes pad "
                f"{k}'s film at the edge z = {z:+g} m (minimum film {h:g} m with the pads "
                f"untilted{' and pitched to the journal' if self.pitch else ''}); expected a "
                f"misalignment whose edge film stays > 0 (rocker pads: |theta|·length_m/2 below "
                f"about clearance_m = {self.clearance_m:g} m)")

    @property
    def pitch(self) -> bool:
        """The pads pitch (a coordinate each): spherical pivots with journal tilt."""
        return bool(self.tilt) and self.pivot_type == "spherical"

    def edge_film(self, x: float, y: float, theta_x: float, theta_y: float
                  ) -> tuple[float, float, int]:
        """The smallest film thickness (m) over the pads of a journal at (x, y) (m, mid-plane)
        tilted by (θx, θy) rad with the pads untilted (δ = 0, u = 0) and, with spherical
        pivots, pitched parallel to the journal along the pivot line (γ_k = θ·t_k), the edge z
        (m) and the pad where it is. Pad k's h(θ, z) = C_p − |V| cos(θ − arg V) (θ = φ − ψ_k)
        with V = (C_p − C_b + e·n_k − γ_k z, e·t_k), e = (x + θy z, y − θx z), least at arg V
        if that lies on the pad's arc, else at an arc end; at an edge z = ±L/2 (straight
        axis)."""
        Cb = self.clearance_m
        Cp = Cb / (1.0 - self.preload)
        arc = math.radians(self.pad_arc_deg)
        lead, trail = -self.pivot_offset * arc, (1.0 - self.pivot_offset) * arc
        best, where, pad = math.inf, 0.0, 0
        for k, psi_deg in enumerate(self.pivot_angles_deg()):
            psi = math.radians(psi_deg)
            cp, sp = math.cos(psi), math.sin(psi)
            gam = theta_y * cp - theta_x * sp if self.pivot_type == "spherical" else 0.0
            for z in (-0.5 * self.length_m, 0.5 * self.length_m):
                ex, ey = x + theta_y * z, y - theta_x * z
                vn = Cp - Cb + ex * cp + ey * sp - gam * z
                vt = -ex * sp + ey * cp
                a, th = math.hypot(vn, vt), math.atan2(vt, vn)
                if lead <= th <= trail:
                    h = Cp - a
                else:
                    h = Cp - a * max(math.cos(lead - th), math.cos(trail - th))
                if h < best:
                    best, where, pad = h, z, k
        return best, where, pad

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
        """Coordinates per pad of the standalone (aligned) bearing: η, and u with a flexible
        pivot (in a system with tilt and spherical pivots, the pitch γ after them)."""
        return 2 if self.flexible_pivot else 1

    @property
    def lever_m(self) -> float:
        """Pivot lever ℓ = R + t, m."""
        return 0.5 * self.diameter_m + self.pad_thickness_m

    def system_parts(self, jx: int, jy: int, first_extra: int, name: str,
                     rot=()) -> SystemParts:
        """Pad coordinates: η_k = q·t_k + ℓ δ_k, the journal's tangential offset relative to
        tilted pad k (t_k the unit tangent at the pivot), m, and with a flexible pivot u_k.
        In (q, η) each pad's film depends on the journal only through its radial offset
        ξ_k = q·n_k: h = base − ξ_k cos θ − η_k sin θ + u_k cos θ (θ = φ − ψ_k). This keeps
        Newton's steps from dragging a pad into the pressure-free (fully divergent) branch
        when the journal moves tangentially to it. Tilt δ_k = (η_k − q·t_k)/ℓ: the pad's
        kinetic energy ½ I δ̇² and tilt spring ½ k_t δ² couple η_k with the journal in M, K.

        ``rot`` (two indices: the station's θx, θy): every pad's film couples to them too,
        h += z (θx sin φ − θy cos φ) (shapes sin φ, −cos φ with axial weight z), and with
        spherical pivots each pad has its pitch γ_k (rad) after its other coordinates,
        h += γ_k z cos θ, with inertia and stiffness of its own (M, K over [x, y, extras] do
        not involve the rotations)."""
        lever = self.lever_m
        arc = math.radians(self.pad_arc_deg)
        pitch = bool(rot) and self.pivot_type == "spherical"
        films, labels = [], []
        npd = 1 + int(self.flexible_pivot) + int(pitch)
        n = npd * self.n_pads
        M = np.zeros((2 + n, 2 + n))
        K = np.zeros((2 + n, 2 + n))
        P = np.zeros((2 + n, 2 + n))
        groups = []  # each pad's own coordinates (tilt, pivot, pitch): the pad assembly
        z = np.linspace(-0.5 * self.length_m, 0.5 * self.length_m, self.n_axial + 1)
        for k, psi_deg in enumerate(self.pivot_angles_deg()):
            psi = math.radians(psi_deg)
            cp, sp = math.cos(psi), math.sin(psi)
            start = psi - self.pivot_offset * arc
            ik = 2 + npd * k
            coords = [jx, jy] + list(rot) + [first_extra + npd * k]
            shapes = ([np.sin, lambda phi: -np.cos(phi)] if rot else []) + [
                lambda phi, psi=psi: -np.sin(phi - psi)]
            weights = [1.0, 1.0] + ([z, z] if rot else []) + [1.0]
            labels.append(f"{name}.pad{k}.eta")
            a = np.zeros(2 + n)  # δ_k = a · [qx, qy, extras]
            a[0], a[1], a[ik] = sp / lever, -cp / lever, 1.0 / lever
            M += self.pad_inertia_kg_m2 * np.outer(a, a)
            K += self.tilt_stiffness_n_m_per_rad * np.outer(a, a)
            P += np.outer(a, a)  # fallback equilibrium homotopy: tilts held at 0 first
            groups.append([ik] + ([ik + 1] if self.flexible_pivot else [])
                          + ([ik + npd - 1] if pitch else []))
            if self.flexible_pivot:
                coords.append(first_extra + npd * k + 1)
                shapes.append(lambda phi, psi=psi: np.cos(phi - psi))
                weights.append(1.0)
                labels.append(f"{name}.pad{k}.pivot")
                M[ik + 1, ik + 1] = self.pad_mass_kg
                P[ik + 1, ik + 1] = 1.0 / lever ** 2  # and pivots at u = 0
                K[ik + 1, ik + 1] = self.pivot_stiffness_n_per_m
            if pitch:  # γ_k: the pad's surface at z moves outward by γ_k z
                ig = ik + npd - 1
                coords.append(first_extra + npd * k + npd - 1)
                shapes.append(lambda phi, psi=psi: np.cos(phi - psi))
                weights.append(z)
                labels.append(f"{name}.pad{k}.pitch")
                M[ig, ig] = (self.pad_inertia_kg_m2 if self.pitch_inertia_kg_m2 is None
                             else self.pitch_inertia_kg_m2)
                K[ig, ig] = self.pitch_stiffness_n_m_per_rad
                P[ig, ig] = (0.5 * self.length_m / lever) ** 2  # homotopy: edges as the tilt
            pf = pad_film(
                name=f"{name}.pad{k}", diameter_m=self.diameter_m, length_m=self.length_m,
                clearance_m=self.clearance_m, viscosity_pa_s=self.viscosity_pa_s,
                cavitation=self.cavitation, start_rad=start, arc_rad=arc, pivot_rad=psi,
                preload=self.preload, n_circ=self.n_circ, n_axial=self.n_axial, coords=coords,
                extra_shapes=shapes, turbulence=self.turbulence, density_kg_m3=self.density_kg_m3,
                turbulence_onset_re=self.turbulence_onset_re,
                turbulence_full_re=self.turbulence_full_re)
            # journal columns in (q, η): −cos θ n_k (the tangential part is carried by η)
            S = np.asarray(pf.coupling.shape).copy()
            on = pf.on_pad
            th = pf.phi[on] - psi
            S[on, 0] = -np.cos(th) * cp
            S[on, 1] = -np.cos(th) * sp
            pf.coupling.shape = S
            if rot:  # ∂h/∂r_k = S(φ, k)·w(k, z): z on the rotations and the pitch
                pf.coupling.axial_weight = np.ascontiguousarray(
                    np.vstack([np.broadcast_to(w, z.shape) for w in weights]))
            films.append(pf)
        pad_fields(self.viscosity_field_pa_s, films, f"{name}.viscosity_field_pa_s")
        return SystemParts(films=films, tables=[], n_extra=n, M=M, K=K,
                           C=np.zeros((2 + n, 2 + n)), labels=tuple(labels), penalty=P,
                           pad_groups=groups, pad_pitch=[int(pitch)] * len(groups))

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
                            whirl_ratio: float | None = 1.0, theta_x_rad: float = 0.0,
                            theta_y_rad: float = 0.0, tilt: bool | None = None,
                            **walls):
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
        ``back_temperature_c``).

        ``theta_x_rad``, ``theta_y_rad`` (inputs; the result names them ``journal_theta_*``): the
        journal's tilt relative to the bearing (rad; as
        :func:`rotordyn.bearings.tilt.misaligned_equilibrium`; a tilt closing a pad's film at
        an edge is an InputError naming them). With a tilt, or with ``tilt`` True (None: the
        bearing's own ``tilt`` field), the pads' films carry it (:func:`rotordyn.bearings.tilt_thermal.
        pad_tilted_thermal_equilibrium`) and the result adds the moments, the edge film and
        K4, C4 (4×4 over x, y, θx, θy) at the frozen fields."""
        if whirl_ratio is not None:
            v.finite("whirl_ratio", whirl_ratio)
        opts = pad_model_options(model, supply_temperature_c=supply_temperature_c,
                                 supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                                 effective_factor=effective_factor, tol_k=tol_k,
                                 journal_htc_w_m2k=journal_htc_w_m2k,
                                 bush_htc_w_m2k=bush_htc_w_m2k,
                                 journal_temperature_c=journal_temperature_c,
                                 bush_temperature_c=bush_temperature_c, **walls)
        tx, ty = v.finite("theta_x_rad", theta_x_rad), v.finite("theta_y_rad", theta_y_rad)
        tilted = self.tilt if tilt is None else v.boolean("tilt", tilt)
        if tilted or tx != 0.0 or ty != 0.0:
            from rotordyn.bearings.tilt_thermal import pad_tilted_thermal_equilibrium

            return pad_tilted_thermal_equilibrium(self, theta_x_rad=tx, theta_y_rad=ty,
                                                  oil=oil, opts=opts, load_n=load_n,
                                                  speed_hz=speed_hz, whirl_ratio=whirl_ratio)
        parts = self.system_parts(0, 1, 2, self.name or "bearing")
        return pad_thd_equilibrium(parts, oil=oil, opts=opts, load_n=load_n, speed_hz=speed_hz,
                                   clearance_m=self.clearance_m, whirl_ratio=whirl_ratio,
                                   tilts=self.pad_tilts_rad)

    def pad_films(self):
        """The pads' C++ film couplings on the standalone coordinates (x, y, pad dofs)."""
        return self.system_parts(0, 1, 2, self.name or "bearing").films


