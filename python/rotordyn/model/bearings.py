"""Fluid-film bearings placed in a system: a plain journal bearing or the active journal
bearing (flexible sleeve + pressure chamber), each at a rotor station with its housing offset
(the configuration ``a`` of eq. 7-9: ``config_ax_m``, ``config_ay_m``; a_y > 0 above the line
through the reference bearings)."""

from __future__ import annotations

from dataclasses import dataclass

from rotordyn.bearing import CAVITATION_MODELS, Groove, JournalBearing
from rotordyn.errors import InputError
from rotordyn import _validate as v
from rotordyn import plausibility
from rotordyn.sleeve import FlexibleSleeve


def check_film_fields(b, where: str, n_stations: int | None) -> None:
    """The fields every film element has (station, D, L, c, μ, cavitation, grid,
    configuration); ``n_stations`` None skips the station range (a standalone element)."""
    if n_stations is not None:
        v.integer(f"{where}.station", b.station, lo=0, hi=n_stations - 1)
    v.positive(f"{where}.diameter_m", b.diameter_m)
    v.positive(f"{where}.length_m", b.length_m)
    c = v.positive(f"{where}.clearance_m", b.clearance_m)
    if c >= 0.1 * b.diameter_m:
        raise InputError(f"{where}.clearance_m: expected a value in (0, 0.1 × diameter_m), "
                         f"got {b.clearance_m!r}")
    v.positive(f"{where}.viscosity_pa_s", b.viscosity_pa_s)
    v.choice(f"{where}.cavitation", b.cavitation, CAVITATION_MODELS)
    v.integer(f"{where}.n_circ", b.n_circ, lo=12, hi=4096)
    v.integer(f"{where}.n_axial", b.n_axial, lo=2, hi=1024)
    v.finite(f"{where}.config_ax_m", b.config_ax_m)
    v.finite(f"{where}.config_ay_m", b.config_ay_m)


def _check_film(b, where: str, n_stations: int) -> None:
    v.text(f"{where}.name", b.name)
    check_film_fields(b, where, n_stations)
    plausibility.length(f"{where}.diameter_m", b.diameter_m)
    plausibility.clearance(f"{where}.clearance_m", b.clearance_m, b.diameter_m)
    plausibility.viscosity(f"{where}.viscosity_pa_s", b.viscosity_pa_s)
    plausibility.housing_offset(f"{where}.config_ax_m", b.config_ax_m, b.clearance_m)
    plausibility.housing_offset(f"{where}.config_ay_m", b.config_ay_m, b.clearance_m)
    for i, g in enumerate(b.grooves):
        if not isinstance(g, Groove):
            raise InputError(f"{where}.grooves[{i}]: expected a Groove, got {type(g).__name__}")


def _film_model(b) -> JournalBearing:
    return JournalBearing(diameter_m=b.diameter_m, length_m=b.length_m,
                          clearance_m=b.clearance_m, viscosity_pa_s=b.viscosity_pa_s,
                          n_circ=b.n_circ, n_axial=b.n_axial, cavitation=b.cavitation,
                          grooves=b.grooves)


@dataclass(frozen=True, slots=True)
class FluidFilmBearing:
    """Plain 360° journal bearing at ``station`` (film model: :class:`rotordyn.JournalBearing`)."""

    station: int
    diameter_m: float
    length_m: float
    clearance_m: float
    viscosity_pa_s: float
    cavitation: str = "reynolds"
    n_circ: int = 72
    n_axial: int = 16
    grooves: tuple[Groove, ...] = ()
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""

    def __post_init__(self):
        object.__setattr__(self, "grooves", tuple(self.grooves))

    def check(self, where: str, n_stations: int) -> None:
        _check_film(self, where, n_stations)

    def journal_bearing(self) -> JournalBearing:
        """The standalone film model (forces, coefficients) of this bearing."""
        return _film_model(self)


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
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""

    def __post_init__(self):
        object.__setattr__(self, "grooves", tuple(self.grooves))

    def check(self, where: str, n_stations: int) -> None:
        _check_film(self, where, n_stations)
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
        return _film_model(self)


def _bearing_types() -> dict:
    from rotordyn.bearings import (FixedGeometryBearing, SqueezeFilmDamper, TableBearing,
                                   TiltingPadBearing)

    return {"journal": FluidFilmBearing, "active_journal": ActiveJournalBearing,
            "fixed_geometry": FixedGeometryBearing, "tilting_pad": TiltingPadBearing,
            "squeeze_film_damper": SqueezeFilmDamper, "table": TableBearing}


BEARING_TYPES = _bearing_types()
