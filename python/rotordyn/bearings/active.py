"""The active journal bearing (paper §2-3) placed in a system: a 360° bush whose lower arc is a
flexible sleeve (:mod:`rotordyn.bearings.sleeve`), pushed toward the journal by the chamber
pressure p_c; its film is the plain journal bearing's (:mod:`rotordyn.bearings.journal`) with
the sleeve's deformation in the thickness (eq. 3)."""

from __future__ import annotations

from dataclasses import dataclass

from rotordyn._common import validate as v
from rotordyn.bearings._film import check_tilt_fields
from rotordyn.bearings.fluid_film import check_placed_film, film_model, freeze_viscosity_field
from rotordyn.bearings.journal import Groove, JournalBearing
from rotordyn.bearings.sleeve import FlexibleSleeve
from rotordyn.errors import InputError


@dataclass(frozen=True, slots=True)
class ActiveJournalBearing:
    """The active journal bearing (paper §2-3): a 360° bush whose lower arc is a flexible
    sleeve, pushed toward the journal by the chamber pressure p_c acting on its outer face
    over the film-angle arc [chamber_start_deg, chamber_end_deg] (default: the whole sleeve).
    The sleeve's condensed master coordinates become system coordinates (eq. 12-13)."""

    station: int
    diameter_m: float
    length_m: float
    clearance_m: float
    viscosity_pa_s: float
    sleeve: FlexibleSleeve | None = None
    chamber_start_deg: float | None = None
    chamber_end_deg: float | None = None
    cavitation: str = "reynolds"
    n_circ: int = 72
    n_axial: int = 16
    grooves: tuple[Groove, ...] = ()
    turbulence: str = "laminar"
    density_kg_m3: float | None = None
    # the turbulent film's optional laminar-to-turbulent transition (Re_h at which the
    # corrections start and are full; both or neither; docs/film-physics.md)
    turbulence_onset_re: float | None = None
    turbulence_full_re: float | None = None
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""
    # journal tilt: the film (and its sleeve) couples to the station's rotations; housing
    # misalignment (rad) at those rotations (as FluidFilmBearing, docs/film-physics.md)
    tilt: bool = False
    config_theta_x_rad: float = 0.0
    config_theta_y_rad: float = 0.0
    # a frozen viscosity per node, Pa·s, (n_circ, n_axial + 1) as a tuple of rows (the THD
    # film's temperature field at its thermal equilibrium, sleeve deformation included);
    # None: viscosity_pa_s everywhere (as FluidFilmBearing)
    viscosity_field_pa_s: tuple | None = None

    def __post_init__(self):
        object.__setattr__(self, "grooves", tuple(self.grooves))
        freeze_viscosity_field(self)

    def check(self, where: str, n_stations: int) -> None:
        check_placed_film(self, where, n_stations)
        check_tilt_fields(self, where)
        if not isinstance(self.sleeve, FlexibleSleeve):
            raise InputError(f"{where}.sleeve: expected a FlexibleSleeve, got {self.sleeve!r}")
        inner = self.sleeve.radius_m - 0.5 * self.sleeve.thickness_m
        if inner <= 0.5 * self.diameter_m:  # issue 13: a sleeve inside the journal
            raise InputError(
                f"{where}.sleeve.radius_m: the sleeve's inner face (radius_m - thickness_m/2 "
                f"= {inner:g} m) must lie outside the journal (diameter_m/2 = "
                f"{0.5 * self.diameter_m:g} m; nominally diameter_m/2 + clearance_m), got "
                f"radius_m = {self.sleeve.radius_m!r}")
        lo = self.sleeve.clamp_deg + 90.0
        hi = lo + self.sleeve.arc_deg
        for f in ("chamber_start_deg", "chamber_end_deg"):
            val = getattr(self, f)
            if val is not None:
                val = v.finite(f"{where}.{f}", val)
                if not lo - 1e-9 <= val <= hi + 1e-9:
                    raise InputError(f"{where}.{f}: expected a film angle in the sleeve's arc "
                                     f"[{lo:g}, {hi:g}] deg, got {val!r}")
        if (self.chamber_start_deg is not None and self.chamber_end_deg is not None
                and self.chamber_end_deg <= self.chamber_start_deg):
            raise InputError(f"{where}.chamber_end_deg: expected a value > chamber_start_deg "
                             f"= {self.chamber_start_deg!r}, got {self.chamber_end_deg!r}")

    def journal_bearing(self) -> JournalBearing:
        """The film model of the bush with the sleeve undeformed."""
        return film_model(self)
