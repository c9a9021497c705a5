"""rotordyn: vibration analysis and control-law synthesis of multi-bearing rotors on
fluid-film and active journal bearings (C++ core, Python API)."""

from __future__ import annotations

from rotordyn import _core
from rotordyn.errors import (
    ContactError,
    ConvergenceError,
    InputError,
    RotordynError,
    SundialsError,
)
from rotordyn.bearing import BearingEquilibrium, FilmResult, Groove, JournalBearing, PressureField
from rotordyn.sleeve import FlexibleSleeve, SleeveResult, paper_rig_sleeve
from rotordyn.model import (
    STEEL,
    ActiveJournalBearing,
    Disk,
    FluidFilmBearing,
    Material,
    Reduction,
    Rotor,
    ShaftSection,
    Support,
    System,
)
from rotordyn.analysis import (
    campbell,
    equilibrium,
    linearize,
    modes,
    rotor_campbell,
    stability,
    stability_boundary,
    statespace,
    threshold,
    transient,
    unbalance_response,
)
from rotordyn.results import (
    CampbellResult,
    EquilibriumResult,
    LinearModel,
    ModesResult,
    StabilityResult,
)
from rotordyn import models
from rotordyn._threads import get_blas_threads, set_blas_threads

__version__ = "0.1.0"


def build_info() -> dict[str, str]:
    """Versions of rotordyn and of the Eigen, SUNDIALS and SuiteSparse it was built with."""
    info = dict(_core.build_info())
    info["python_package"] = __version__
    return info


__all__ = [
    "__version__",
    "build_info",
    "set_blas_threads",
    "get_blas_threads",
    # errors
    "RotordynError",
    "InputError",
    "ConvergenceError",
    "ContactError",
    "SundialsError",
    # model
    "Material",
    "STEEL",
    "ShaftSection",
    "Disk",
    "Support",
    "Rotor",
    "Reduction",
    "System",
    "FluidFilmBearing",
    "ActiveJournalBearing",
    "FlexibleSleeve",
    "paper_rig_sleeve",
    "models",
    # journal bearing (standalone film model)
    "JournalBearing",
    "Groove",
    "BearingEquilibrium",
    "FilmResult",
    "PressureField",
    # analyses and results
    "modes",
    "rotor_campbell",
    "campbell",
    "equilibrium",
    "linearize",
    "stability",
    "threshold",
    "stability_boundary",
    "unbalance_response",
    "statespace",
    "transient",
    "ModesResult",
    "LinearModel",
    "StabilityResult",
    "CampbellResult",
    "EquilibriumResult",
    "SleeveResult",
]
