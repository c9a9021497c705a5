"""Every bearing element, one module each, on one shared film code (:mod:`._film`):

* :mod:`.journal` the plain journal bearing: the standalone finite-length film
  (:class:`JournalBearing`, issue 3) and the bearing placed in a system
  (:class:`FluidFilmBearing`);
* :mod:`.active` the active journal bearing (:class:`ActiveJournalBearing`, paper §2-3) and
  :mod:`.sleeve` its flexible sleeve (:class:`FlexibleSleeve`, three-step condensation);
* :mod:`.fixed_geometry` multi-lobe / partial-arc bearings, :mod:`.tilting_pad` tilting-pad
  bearings, :mod:`.squeeze_film` squeeze-film dampers, :mod:`.table` speed-dependent
  coefficient tables (issue 12);
* :mod:`.coefficients` the standalone coefficient table over speed of any film element,
  :mod:`.ross_io` a bearing element as a ROSS ``BearingElement``;
* :mod:`.thermal` the oil (:class:`Oil`, viscosity–temperature laws) and the
  effective-temperature equilibrium of a plain film (:class:`ThermalEquilibriumResult`);
* :mod:`.tilt` a tilted or misaligned journal in a plain, lobed or tilting-pad film: forces
  and moments (:func:`tilted_forces`), 4×4 K, C over (x, y, θx, θy), the equilibrium at an
  imposed tilt (tilting pads: :mod:`.tilt_pads`, the pads at their equilibrium).

Each can be placed in a :class:`rotordyn.System` (``bearings=...``, TOML ``[[bearing]] type =
...``, the names of :data:`BEARING_TYPES`) and also used standalone (forces, coefficient tables
over speed)."""

from rotordyn.bearings.active import ActiveJournalBearing
from rotordyn.bearings.coefficients import CoefficientTable
from rotordyn.bearings.fixed_geometry import FixedGeometryBearing
from rotordyn.bearings.fluid_film import FluidFilmBearing
from rotordyn.bearings.journal import (BearingEquilibrium, FilmResult, Groove, JournalBearing,
                                       PressureField)
from rotordyn.bearings.ross_io import to_ross_bearing
from rotordyn.bearings.sleeve import FlexibleSleeve, SleeveResult, paper_rig_sleeve
from rotordyn.bearings.squeeze_film import (SqueezeFilmDamper, end_plate_seal_conductance,
                                            long_damper_orbit_forces, short_damper_orbit_forces)
from rotordyn.bearings.table import TableBearing
from rotordyn.bearings.thermal import Oil, ThermalEquilibriumResult, ThermalFilm, ThermalModel
from rotordyn.bearings.tilting_pad import TiltingPadBearing
from rotordyn.bearings.tilt import (MisalignedEquilibrium, TiltedFilm, misaligned_equilibrium,
                                    tilted_coefficients, tilted_forces)
from rotordyn.bearings.thd import THERMAL_MODELS, ThdEquilibriumResult
from rotordyn.bearings.pad_thd import PadThdResult

BEARING_TYPES = {"journal": FluidFilmBearing, "active_journal": ActiveJournalBearing,
                 "fixed_geometry": FixedGeometryBearing, "tilting_pad": TiltingPadBearing,
                 "squeeze_film_damper": SqueezeFilmDamper, "table": TableBearing}
"""The element of each TOML ``[[bearing]] type``."""

__all__ = ["ActiveJournalBearing", "BEARING_TYPES", "BearingEquilibrium", "CoefficientTable",
           "FilmResult", "FixedGeometryBearing", "FlexibleSleeve", "FluidFilmBearing", "Groove",
           "JournalBearing", "Oil", "PressureField", "SleeveResult", "SqueezeFilmDamper", "TableBearing",
           "ThermalEquilibriumResult", "ThermalFilm", "ThermalModel", "TiltingPadBearing",
           "end_plate_seal_conductance", "long_damper_orbit_forces",
           "paper_rig_sleeve", "short_damper_orbit_forces", "to_ross_bearing",
           "THERMAL_MODELS", "ThdEquilibriumResult"]
__all__ += ["MisalignedEquilibrium", "TiltedFilm", "misaligned_equilibrium",
            "tilted_coefficients", "tilted_forces"]
__all__ += ["PadThdResult"]
