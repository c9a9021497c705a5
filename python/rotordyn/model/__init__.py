"""Model description: frozen dataclasses mirrored one-to-one by the TOML model format."""

from rotordyn.model.bearings import ActiveJournalBearing, FluidFilmBearing
from rotordyn.model.rotor import STEEL, Disk, Material, Rotor, ShaftSection, Support
from rotordyn.model.system import Reduction, System

__all__ = ["FluidFilmBearing", "ActiveJournalBearing", "Material", "STEEL", "ShaftSection", "Disk", "Support", "Rotor", "Reduction", "System"]
