"""Fixed-geometry journal bearings from one general film geometry (``_film.py``): partial arc,
two-axial-groove, elliptical (two-lobe), offset halves, three- and four-lobe and pressure
dam, with preload m and lobe offset α as fields, on the plain bearing's Reynolds core and
cavitation models.

Lobe k (k = 0 … n−1) is centred at ``orientation_deg`` + k·360°/n (φ from +x with the
rotation; 270° is straight down, under a gravity load) and spans 360°/n − ``groove_width_deg``;
the grooves between lobes hold ``supply_pressure_pa``. Its minimum clearance C_b
(``clearance_m``, the assembled clearance) is at the fraction α (``offset``) of its arc from
the leading edge; its machined clearance is C_p = C_b/(1 − m).

kinds (defaults: n lobes, orientation, preload, offset):
* ``partial_arc``: one arc of ``arc_deg`` centred at ``orientation_deg`` (270°), m = 0;
  ``arc_deg = 360`` is the plain bearing.
* ``two_axial_groove``: 2 cylindrical lobes, grooves at the horizontal split (lobes at 270°
  and 90°).
* ``elliptical``: 2 lobes at 270°/90°, m = 0.5, α = 0.5 (lemon bore).
* ``offset_halves``: 2 lobes at 270°/90°, m = 0.5, α = 1.0 (halves displaced horizontally).
* ``three_lobe``: 3 lobes, first centred at 270° (load on a lobe), m = 0.5, α = 0.5.
* ``four_lobe``: 4 lobes centred at 225°, 315°, 45°, 135° (load between lobes), m = 0.5.
* ``pressure_dam``: two-axial-groove with a relief pocket of depth ``dam_depth_m`` and axial
  width ``dam_width_fraction``·L in the upper lobe, from its leading edge over
  ``dam_arc_deg``, ending at the dam step.

Journal tilt (``tilt = True``; docs/film-physics.md, "Journal tilt and bearing misalignment"):
every lobe's film couples to the journal's rotations (θx, θy) too, with the plain bearing's
convention: at the axial position z the journal centre is at (x + θy z, y − θx z), so a lobe's
thickness is h(φ, z) = C_p − (C_p − C_b) cos(φ − φ_p) − (x + θy z) cos φ − (y − θx z) sin φ
(shapes sin φ, −cos φ with axial weight z on the lobe's nodes), and the lobes' films carry
the moments Mx = ∫∫ p z sin φ dA, My = −∫∫ p z cos φ dA. ``config_theta_x_rad``,
``config_theta_y_rad``: the housing's angular misalignment (the configuration a at the
station's rotations), as for the plain bearing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings._film import (SystemParts, check_arc, check_film_fields, pad_film,
                                     tilt_fields)
from rotordyn.bearings.coefficients import coefficient_table
from rotordyn.bearings.pad_thd import (freeze_fields, pad_fields, pad_model_options,
                                        pad_thd_equilibrium)
from rotordyn.errors import ClosedFilmError, InputError

KINDS = {  # n lobes, orientation deg, preload, offset
    "partial_arc": (1, 270.0, 0.0, 0.5),
    "two_axial_groove": (2, 270.0, 0.0, 0.5),
    "elliptical": (2, 270.0, 0.5, 0.5),
    "offset_halves": (2, 270.0, 0.5, 1.0),
    "three_lobe": (3, 270.0, 0.5, 0.5),
    "four_lobe": (4, 225.0, 0.5, 0.5),
    "pressure_dam": (2, 270.0, 0.0, 0.5),
}


@dataclass(frozen=True, slots=True)
class FixedGeometryBearing:
    """Fixed-geometry (multi-lobe / partial arc) journal bearing at ``station``. ``None``
    fields take the kind's default (module docstring)."""

    station: int
    diameter_m: float
    length_m: float
    clearance_m: float
    viscosity_pa_s: float
    kind: str = "two_axial_groove"
    preload: float | None = None
    offset: float | None = None
    orientation_deg: float | None = None
    groove_width_deg: float = 20.0
    arc_deg: float = 150.0
    supply_pressure_pa: float = 0.0
    dam_depth_m: float = 0.0
    dam_arc_deg: float = 125.0
    dam_width_fraction: float = 0.5
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
    # journal tilt: the lobes' films couple to the station's rotations too; the housing's
    # angular misalignment (rad, right-hand rule about x, y) is the configuration a at them
    tilt: bool = False
    config_theta_x_rad: float = 0.0
    config_theta_y_rad: float = 0.0
    # "finite" (the finite-length Reynolds film) or "short": the core's short-bearing (Ocvirk)
    # film, p = 6μG/h³·(z² − L²/4) node by node (plain 360° bearing only: partial_arc, 360°)
    film_model: str = "finite"
    # a frozen viscosity per node and lobe, Pa·s (the THD lobes' fields, pad_thd.py); None:
    # viscosity_pa_s everywhere
    viscosity_field_pa_s: tuple | None = None

    def __post_init__(self):
        if self.viscosity_field_pa_s is not None:
            object.__setattr__(self, "viscosity_field_pa_s",
                               freeze_fields(self.viscosity_field_pa_s))
        self.check("fixed_geometry_bearing", None)

    # -- resolved geometry ----------------------------------------------------------------
    @property
    def n_lobes(self) -> int:
        return KINDS[self.kind][0]

    def resolved(self) -> tuple[float, float, float]:
        """(preload, offset, orientation_deg) with the kind's defaults filled in."""
        _, o, m, a = KINDS[self.kind]
        return (m if self.preload is None else self.preload,
                a if self.offset is None else self.offset,
                o if self.orientation_deg is None else self.orientation_deg)

    def lobe_arc_deg(self) -> float:
        if self.kind == "partial_arc":
            return float(self.arc_deg)
        return 360.0 / self.n_lobes - self.groove_width_deg

    def check(self, where: str, n_stations: int | None) -> None:
        check_film_fields(self, where, n_stations)
        v.choice(f"{where}.kind", self.kind, tuple(KINDS))
        if self.preload is not None:
            v.in_range(f"{where}.preload", self.preload, 0.0, 1.0, hi_open=True)
        if self.offset is not None:
            v.in_range(f"{where}.offset", self.offset, 0.0, 1.0)
        if self.orientation_deg is not None:
            v.finite(f"{where}.orientation_deg", self.orientation_deg)
        v.in_range(f"{where}.arc_deg", self.arc_deg, 0.0, 360.0, lo_open=True)
        v.non_negative(f"{where}.supply_pressure_pa", self.supply_pressure_pa)
        if self.kind != "partial_arc":
            v.in_range(f"{where}.groove_width_deg", self.groove_width_deg, 0.0,
                       360.0 / self.n_lobes, lo_open=True, hi_open=True)
        check_arc(f"{where}.{'arc_deg' if self.kind == 'partial_arc' else 'groove_width_deg'}",
                  self.lobe_arc_deg(), self)
        v.non_negative(f"{where}.dam_depth_m", self.dam_depth_m)
        if self.kind == "pressure_dam":
            v.in_range(f"{where}.dam_arc_deg", self.dam_arc_deg, 0.0, self.lobe_arc_deg(),
                       lo_open=True)
            v.in_range(f"{where}.dam_width_fraction", self.dam_width_fraction, 0.0, 1.0,
                       lo_open=True)
        if self.cavitation == "jfo" and self.kind == "partial_arc" and self.arc_deg == 360.0:
            raise InputError(f"{where}.cavitation: 'jfo' needs a supply groove; a 360° arc has none")
        v.choice(f"{where}.film_model", self.film_model, ("finite", "short"))
        if self.film_model == "short" and not (self.kind == "partial_arc"
                                               and self.arc_deg == 360.0):
            raise InputError(f"{where}.film_model: 'short' (the short-bearing film: open ends, "
                             f"no grooves) needs kind = 'partial_arc' with arc_deg = 360, got "
                             f"kind = {self.kind!r}, arc_deg = {self.arc_deg!r}")
        self._check_tilt(where)

    def _check_tilt(self, where: str) -> None:
        """``tilt`` (bool), the misalignment (finite, only with tilt, and not closing any
        lobe's film at an edge for a journal on the shaft line: :meth:`edge_film` > 0)."""
        tx, ty = tilt_fields(self, where)
        if self.tilt and self.film_model != "finite":
            raise InputError(f"{where}.film_model: tilt = true needs the finite-length film "
                             f"(film_model = 'finite'), got {self.film_model!r}")
        h, z = self.edge_film(0.0, 0.0, tx, ty)
        if not h > 0.0:
            raise ClosedFilmError(
                f"{where}.config_theta_x_rad, config_theta_y_rad: the misalignment closes a "
                f"lobe's film at the edge z = {z:+g} m (minimum film {h:g} m); expected a "
                f"misalignment whose edge film stays > 0 (for a 360° arc without preload: "
                f"sqrt(theta_x² + theta_y²)·length_m/2 < clearance_m = {self.clearance_m:g} m)")

    def edge_film(self, x: float, y: float, theta_x: float, theta_y: float
                  ) -> tuple[float, float]:
        """The smallest film thickness (m) of the continuous lobe geometry of a journal at
        (x, y) (m, mid-plane) tilted by (θx, θy) rad, and the edge z (m) where it is: a lobe's
        h(φ) = C_p − |A| cos(φ − arg A), A = (C_p − C_b) e^{iφ_p} + (x + θy z) + i(y − θx z),
        is least at arg A if that lies on the arc, else at an arc end; the axis is straight,
        so the least film over z is at an edge (z = ±L/2)."""
        m, alpha, orient = self.resolved()
        Cb = self.clearance_m
        Cp = Cb / (1.0 - m)
        arc = math.radians(self.lobe_arc_deg())
        best, where = math.inf, 0.0
        for z in (-0.5 * self.length_m, 0.5 * self.length_m):
            ex, ey = x + theta_y * z, y - theta_x * z
            for k in range(self.n_lobes):
                start = math.radians(orient + k * 360.0 / self.n_lobes) - 0.5 * arc
                piv = start + alpha * arc
                ax, ay = (Cp - Cb) * math.cos(piv) + ex, (Cp - Cb) * math.sin(piv) + ey
                a, psi = math.hypot(ax, ay), math.atan2(ay, ax)
                if (psi - start) % (2 * math.pi) <= arc:
                    h = Cp - a
                else:
                    h = Cp - a * max(math.cos(start - psi), math.cos(start + arc - psi))
                if h < best:
                    best, where = h, z
        return best, where

    # -- films ----------------------------------------------------------------------------
    def films(self, jx: int, jy: int, name: str, spin: float = 1.0, rot=()) -> list:
        """One film per lobe on the journal's x, y (``jx``, ``jy``) and, with ``rot`` (two
        indices: θx, θy), on its rotations: shapes (−cos φ, −sin φ, sin φ, −cos φ) on the
        lobe's nodes, axial weights (1, 1, z, z) (module docstring)."""
        m, alpha, orient = self.resolved()
        arc = math.radians(self.lobe_arc_deg())
        out = []
        for k in range(self.n_lobes):
            centre = math.radians(orient + k * 360.0 / self.n_lobes)
            start = centre - 0.5 * arc
            if abs(arc - 2 * math.pi) < 1e-12:
                start = 0.0  # the plain bearing's grid (φ_0 = 0)
            pockets = ()
            if self.kind == "pressure_dam" and self.dam_depth_m > 0 and k == 1:
                zw = 0.5 * self.dam_width_fraction * self.length_m
                pockets = ((0.0, math.radians(self.dam_arc_deg), -zw, zw, self.dam_depth_m),)
            out.append(pad_film(
                name=f"{name}.lobe{k}" if self.n_lobes > 1 else name,
                diameter_m=self.diameter_m, length_m=self.length_m, clearance_m=self.clearance_m,
                viscosity_pa_s=self.viscosity_pa_s, cavitation=self.cavitation, start_rad=start,
                arc_rad=arc, pivot_rad=start + alpha * arc, preload=m, n_circ=self.n_circ,
                n_axial=self.n_axial, coords=[jx, jy] + list(rot),
                extra_shapes=(np.sin, lambda p: -np.cos(p)) if rot else (),
                supply_pressure_pa=self.supply_pressure_pa,
                spin=spin, pockets=pockets, turbulence=self.turbulence,
                density_kg_m3=self.density_kg_m3, short_bearing=self.film_model == "short",
                turbulence_onset_re=self.turbulence_onset_re,
                turbulence_full_re=self.turbulence_full_re))
            if rot:  # rotations: ∂h/∂θ = S(φ)·z (the weight-1 coordinates first, as untilted)
                z = np.linspace(-0.5 * self.length_m, 0.5 * self.length_m, self.n_axial + 1)
                out[-1].coupling.axial_weight = np.ascontiguousarray(
                    np.vstack([np.ones_like(z), np.ones_like(z), z, z]))
        pad_fields(self.viscosity_field_pa_s, out, f"{name}.viscosity_field_pa_s")
        return out

    def system_parts(self, jx: int, jy: int, first_extra: int, name: str,
                     rot=()) -> SystemParts:
        """The lobes' films on the journal (and, with ``rot``, the station's θx, θy)."""
        return SystemParts(films=self.films(jx, jy, name, rot=rot), tables=[])

    # -- standalone -----------------------------------------------------------------------
    def _solver(self):
        model = _core.SystemModel()
        z = np.zeros((2, 2))
        model.M, model.K, model.C, model.G = z, z, z, z
        model.Q, model.chamber = np.zeros(2), np.zeros(2)
        model.films = [p.coupling for p in self.films(0, 1, self.name or "bearing")]
        return _core.SystemSolver(model)

    def forces(self, *, x_m: float, y_m: float, speed_hz: float, vx_m_s: float = 0.0,
               vy_m_s: float = 0.0) -> np.ndarray:
        """Film force (Fx, Fy) on a rigid journal at (x, y) moving at (vx, vy), N."""
        r = np.array([v.finite("x_m", x_m), v.finite("y_m", y_m)])
        m = self.resolved()[0]
        if np.hypot(*r) >= self.clearance_m / (1.0 - m):
            raise InputError(f"x_m, y_m: expected a journal inside the machined clearance "
                             f"circle (|r| < {self.clearance_m / (1.0 - m):g} m)")
        rd = np.array([v.finite("vx_m_s", vx_m_s), v.finite("vy_m_s", vy_m_s)])
        w = 2 * math.pi * v.finite("speed_hz", speed_hz)
        return np.asarray(self._solver().film_forces(r, rd, w))

    def coefficients(self, *, x_m: float, y_m: float, speed_hz: float):
        """K (N/m), C (N·s/m), 2×2, at the journal position (x, y) (perturbation method)."""
        self.forces(x_m=x_m, y_m=y_m, speed_hz=speed_hz)  # validates the position
        lin = self._solver().linearize(np.array([x_m, y_m], dtype=float), np.zeros(2),
                                       2 * math.pi * float(speed_hz))
        return np.asarray(lin.KH), np.asarray(lin.DH)

    def coefficient_table(self, speeds_hz, load_n, *, n_threads: int = 1):
        """Equilibrium under ``load_n`` (N, on the journal) and K, C at each speed (Hz),
        parallel over speeds (``n_threads``, 0: all cores): a :class:`CoefficientTable`."""
        parts = SystemParts(films=self.films(0, 1, self.name or "bearing"), tables=[])
        return coefficient_table(parts, load_n, speeds_hz, self.clearance_m, n_threads=n_threads)

    def thermal_equilibrium(self, *, load_n, speed_hz: float, oil, supply_temperature_c: float,
                            carry_over: float = 0.0, supply_flow_m3_s: float = 0.0,
                            journal_htc_w_m2k: float = 0.0, bush_htc_w_m2k: float = 0.0,
                            journal_temperature_c: float | None = None,
                            bush_temperature_c: float | None = None, tol_k: float = 1e-6,
                            model: str = "thd", effective_factor: float = 0.5,
                            theta_x_rad: float = 0.0, theta_y_rad: float = 0.0, tilt: bool | None = None,
                            **walls):
        """Thermo-hydrodynamic equilibrium of the lobes under ``load_n`` (N) at ``speed_hz``
        (as :meth:`rotordyn.bearings.TiltingPadBearing.thermal_equilibrium`: per lobe the
        energy equation, each lobe's inlet groove mixing supply oil with the part
        ``carry_over`` of the upstream lobe's hot oil) and K, C with the field frozen: a
        :class:`rotordyn.bearings.pad_thd.PadThdResult` (no pad tilts). ``model="effective"``:
        the effective-temperature model per lobe (``effective_factor`` k), as for tilting
        pads.

        ``theta_x_rad``, ``theta_y_rad`` (inputs; the result names them ``journal_theta_*``): the
        journal's tilt relative to the bearing (rad; as
        :func:`rotordyn.bearings.tilt.misaligned_equilibrium`; a pose that closes a lobe's
        film at an edge is an InputError naming them). With a tilt, or with ``tilt`` True
        (None: the bearing's own field), the lobes' films carry it (:mod:`rotordyn.bearings.tilt_thermal`) and the result
        adds the moments, the edge film and K4, C4 (4×4 over x, y, θx, θy) at the frozen
        field. (``config_theta_x_rad``, ``config_theta_y_rad`` are the housing's misalignment
        in a system; standalone, give the journal's tilt here.) ``walls``: the THD film's heat
        paths (:mod:`rotordyn.bearings.thd_walls`), as for tilting pads."""
        opts = pad_model_options(model, supply_temperature_c=supply_temperature_c,
                                 supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                                 effective_factor=effective_factor, tol_k=tol_k,
                                 journal_htc_w_m2k=journal_htc_w_m2k,
                                 bush_htc_w_m2k=bush_htc_w_m2k,
                                 journal_temperature_c=journal_temperature_c,
                                 bush_temperature_c=bush_temperature_c, **walls)
        tilted = self.tilt if tilt is None else v.boolean("tilt", tilt)
        if tilted or theta_x_rad != 0.0 or theta_y_rad != 0.0:
            from rotordyn.bearings.tilt_thermal import tilted_thermal_equilibrium

            return tilted_thermal_equilibrium(self, theta_x_rad=theta_x_rad,
                                              theta_y_rad=theta_y_rad, oil=oil, opts=opts,
                                              load_n=load_n, speed_hz=speed_hz)
        parts = SystemParts(films=self.films(0, 1, self.name or "bearing"), tables=[])
        return pad_thd_equilibrium(parts, oil=oil, opts=opts, load_n=load_n, speed_hz=speed_hz,
                                   clearance_m=self.clearance_m, whirl_ratio=None)
