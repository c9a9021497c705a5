"""The plain journal bearing placed at a rotor station (:class:`FluidFilmBearing`): its fields,
checks and standalone film model (:class:`rotordyn.bearings.journal.JournalBearing`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn.bearings._film import check_film_fields, check_tilt_fields
from rotordyn.bearings.journal import Groove, JournalBearing, check_supply_flow
from rotordyn.errors import InputError


def check_placed_film(b, where: str, n_stations: int) -> None:
    """The checks of a plain or active journal bearing placed at a rotor station."""
    check_film_fields(b, where, n_stations)  # with the unit-slip warnings
    for i, g in enumerate(b.grooves):
        if not isinstance(g, Groove):
            raise InputError(f"{where}.grooves[{i}]: expected a Groove, got {type(g).__name__}")


def freeze_viscosity_field(b) -> None:
    """Check and freeze ``b.viscosity_field_pa_s`` (a plain or active journal bearing's frozen
    viscosity per node, Pa·s, (n_circ, n_axial + 1); None: ``viscosity_pa_s`` everywhere) as
    a tuple of rows. InputError naming the field: finite values > 0 of the grid's shape."""
    if b.viscosity_field_pa_s is None:
        return
    try:
        a = np.asarray(b.viscosity_field_pa_s, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"viscosity_field_pa_s: expected finite values > 0 of shape "
                         f"({b.n_circ}, {b.n_axial + 1}), got "
                         f"{type(b.viscosity_field_pa_s).__name__}") from None
    if a.shape != (b.n_circ, b.n_axial + 1) or not np.all(np.isfinite(a)) \
            or not np.all(a > 0.0):
        raise InputError(f"viscosity_field_pa_s: expected finite values > 0 of shape "
                         f"({b.n_circ}, {b.n_axial + 1}), got shape {a.shape}")
    object.__setattr__(b, "viscosity_field_pa_s", tuple(map(tuple, a.tolist())))


def film_model(b) -> JournalBearing:
    return JournalBearing(diameter_m=b.diameter_m, length_m=b.length_m,
                          clearance_m=b.clearance_m, viscosity_pa_s=b.viscosity_pa_s,
                          n_circ=b.n_circ, n_axial=b.n_axial, cavitation=b.cavitation,
                          grooves=b.grooves, turbulence=b.turbulence,
                          density_kg_m3=b.density_kg_m3,
                          turbulence_onset_re=b.turbulence_onset_re,
                          turbulence_full_re=b.turbulence_full_re,
                          supply_flow_m3_s=getattr(b, "supply_flow_m3_s", None))



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
    turbulence: str = "laminar"
    density_kg_m3: float | None = None
    # the turbulent film's optional laminar-to-turbulent transition (Re_h at which the
    # corrections start and are full; both or neither; docs/film-physics.md)
    turbulence_onset_re: float | None = None
    turbulence_full_re: float | None = None
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""
    # journal tilt (docs/film-physics.md): the film couples to the station's rotations too;
    # the housing's angular misalignment (rad, right-hand rule about x, y) is the
    # configuration a at those rotations
    tilt: bool = False
    config_theta_x_rad: float = 0.0
    config_theta_y_rad: float = 0.0
    # a frozen viscosity per node, Pa·s, (n_circ, n_axial + 1) as a tuple of rows (the THD
    # film's temperature field at its thermal equilibrium); None: viscosity_pa_s everywhere
    viscosity_field_pa_s: tuple | None = None
    # a metered oil supply to the grooves, m³/s (cavitation = "jfo" with a groove; None:
    # flooded grooves); below the flooded demand the film is starved (docs/film-physics.md,
    # "A starved film")
    supply_flow_m3_s: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "grooves", tuple(self.grooves))
        freeze_viscosity_field(self)

    def check(self, where: str, n_stations: int) -> None:
        check_placed_film(self, where, n_stations)
        check_tilt_fields(self, where)
        check_supply_flow(self.supply_flow_m3_s, self.cavitation, self.grooves, f"{where}.")

    def journal_bearing(self) -> JournalBearing:
        """The standalone film model (forces, coefficients) of this bearing."""
        return film_model(self)

    def thermal_equilibrium(self, *, load_n, speed_hz: float, oil,
                            supply_temperature_c: float, supply_flow_m3_s: float = 0.0,
                            carry_over: float = 0.0, effective_factor: float = 0.5,
                            tol_k: float = 1e-6, model: str = "effective",
                            theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                            tilt: bool | None = None, **thd):
        """The standalone thermal equilibrium of this bearing's film under ``load_n`` (N) at
        ``speed_hz``: :meth:`rotordyn.JournalBearing.thermal_equilibrium`'s signature and
        result (``model="effective"`` or ``"thd"``, the THD keyword options, the journal's
        tilt ``theta_x_rad``, ``theta_y_rad`` relative to the bearing, rad).

        Of this bearing's own fields: the film (geometry, grid, cavitation, grooves,
        turbulence) is used; ``viscosity_pa_s`` and a frozen ``viscosity_field_pa_s`` are not
        (the oil's law replaces them, as for JournalBearing); ``tilt`` (None: this bearing's
        own ``tilt`` field) gives the tilted film's outputs (moments, edge film, K4, C4) even
        at zero tilt. The housing's ``config_theta_x_rad``, ``config_theta_y_rad`` are not
        applied: they are the housing's misalignment against the shaft line of a system,
        whose journal rotation is the system's to find; standalone the journal's tilt
        relative to the bearing is given here (as for the fixed-geometry and tilting-pad
        bearings; ``config_ax_m``, ``config_ay_m`` likewise)."""
        tilted = self.tilt if tilt is None else v.boolean("tilt", tilt)
        return film_model(self).thermal_equilibrium(
            load_n=load_n, speed_hz=speed_hz, oil=oil,
            supply_temperature_c=supply_temperature_c, supply_flow_m3_s=supply_flow_m3_s,
            carry_over=carry_over, effective_factor=effective_factor, tol_k=tol_k,
            model=model, theta_x_rad=theta_x_rad, theta_y_rad=theta_y_rad, tilt=tilted,
            **thd)


__all__ = ["FluidFilmBearing", "check_placed_film", "film_model", "freeze_viscosity_field"]
