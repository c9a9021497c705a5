"""Bearing elements beyond the plain and active journal bearings (issue 12), one module per
element: speed-dependent coefficient tables (:class:`TableBearing`), fixed-geometry
multi-lobe / partial-arc bearings (:class:`FixedGeometryBearing`), tilting-pad bearings
(:class:`TiltingPadBearing`) and squeeze-film dampers (:class:`SqueezeFilmDamper`). Each can
be placed in a :class:`rotordyn.System` (``bearings=...``, TOML ``[[bearing]] type = ...``)
and also used standalone (forces, coefficient tables over speed)."""

from rotordyn.bearings._element import CoefficientTable
from rotordyn.bearings.fixed_geometry import FixedGeometryBearing
from rotordyn.bearings.ross_io import system_from_ross, to_ross_bearing
from rotordyn.bearings.squeeze_film import (SqueezeFilmDamper, end_plate_seal_conductance,
                                            long_damper_orbit_forces, short_damper_orbit_forces)
from rotordyn.bearings.table import TableBearing
from rotordyn.bearings.tilting_pad import TiltingPadBearing

__all__ = ["CoefficientTable", "FixedGeometryBearing", "SqueezeFilmDamper", "TableBearing",
           "TiltingPadBearing", "end_plate_seal_conductance", "long_damper_orbit_forces",
           "short_damper_orbit_forces", "system_from_ross",
           "to_ross_bearing"]
