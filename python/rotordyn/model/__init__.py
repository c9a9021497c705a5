"""Model description: frozen dataclasses mirrored one-to-one by the TOML model format
(:mod:`.rotor` materials, shaft sections, disks, supports and the reduction; :mod:`.stage` the
aerodynamic stages of API 617 Level I; :mod:`.system` the
whole system; :mod:`.toml_io` the file format), the built-in models (:mod:`.builtin`, TOML files
under ``data/``) and ROSS rotors as systems (:mod:`.ross_io`). The bearing elements a system
holds are in :mod:`rotordyn.bearings`."""

from rotordyn.bearings import ActiveJournalBearing, FluidFilmBearing
from rotordyn.model.ross_io import system_from_ross
from rotordyn.model.rotor import STEEL, Disk, Material, Reduction, Rotor, ShaftSection, Support
from rotordyn.model.stage import Stage
from rotordyn.model.system import System

__all__ = ["FluidFilmBearing", "ActiveJournalBearing", "Material", "STEEL", "ShaftSection",
           "Disk", "Support", "Rotor", "Reduction", "Stage", "System", "system_from_ross"]
