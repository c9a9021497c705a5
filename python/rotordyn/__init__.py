"""rotordyn: vibration analysis and control-law synthesis of multi-bearing rotors on
fluid-film and active journal bearings (C++ core, Python API).

The package root is a table of contents: every name below is defined in one room and only
re-exported here; no module of the package imports the root (docs/architecture.md).

* :mod:`rotordyn.bearings` every bearing element (plain, active with its sleeve,
  fixed-geometry, tilting-pad, squeeze-film, tables)
* :mod:`rotordyn.model` rotor, system, TOML model files, built-in models
* :mod:`rotordyn.operation` speed profiles, pressure schedules, actuator, controllers in the loop
* :mod:`rotordyn.analysis` equilibrium, linearisation, stability, Campbell, unbalance,
  state space, transient
* :mod:`rotordyn.results` the result objects (``to_frame()``, ``plot()``)
* :mod:`rotordyn.plot` figures
* :mod:`rotordyn.control` control-law synthesis
* :mod:`rotordyn.sweep` sweeps on dask into parquet
* :mod:`rotordyn.report`, :mod:`rotordyn.cli` the report and the ``rotordyn`` command
* :mod:`rotordyn.errors`, :mod:`rotordyn.units`
"""

from __future__ import annotations

from rotordyn._common.info import __version__, build_info
from rotordyn._common.threads import (get_blas_threads, get_eigen_threads, set_blas_threads,
                                      set_eigen_threads)
from rotordyn.analysis import (
    campbell,
    continuation,
    equilibrium,
    level1,
    linearize,
    modes,
    periodic_orbit,
    rotor_campbell,
    stability,
    stability_boundary,
    static,
    statespace,
    system_thermal_equilibrium,
    threshold,
    transient,
    unbalance_response,
)
from rotordyn.bearings import (
    ActiveJournalBearing,
    BearingEquilibrium,
    FilmResult,
    FlexibleSleeve,
    FluidFilmBearing,
    Groove,
    JournalBearing,
    PressureField,
    SleeveResult,
    paper_rig_sleeve,
)
from rotordyn.errors import (
    ContactError,
    ConvergenceError,
    InputError,
    OutputError,
    RotordynError,
    SundialsError,
)
from rotordyn.model import (
    STEEL,
    Disk,
    Material,
    Reduction,
    Rotor,
    ShaftSection,
    Stage,
    Support,
    System,
    system_from_ross,
)
from rotordyn.model import builtin as models
from rotordyn.results import (
    BranchResult,
    CampbellResult,
    EquilibriumResult,
    Level1Result,
    LinearModel,
    ModesResult,
    PeriodicOrbitResult,
    StabilityResult,
    StaticResult,
    load_result,
)
from rotordyn.analysis import hopf, hopf_cycles
from rotordyn.results import HopfCyclesResult, HopfResult
from rotordyn.results import EquilibriumBranchResult

__all__ = [
    "__version__",
    "build_info",
    "set_blas_threads",
    "get_blas_threads",
    "set_eigen_threads",
    "get_eigen_threads",
    # errors
    "RotordynError",
    "InputError",
    "OutputError",
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
    "Stage",
    "System",
    "FluidFilmBearing",
    "ActiveJournalBearing",
    "FlexibleSleeve",
    "paper_rig_sleeve",
    "models",
    "system_from_ross",
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
    "level1",
    "threshold",
    "stability_boundary",
    "static",
    "unbalance_response",
    "statespace",
    "transient",
    "load_result",
    "periodic_orbit",
    "PeriodicOrbitResult",
    "system_thermal_equilibrium",
    "continuation",
    "BranchResult",
    "ModesResult",
    "LinearModel",
    "StabilityResult",
    "Level1Result",
    "StaticResult",
    "CampbellResult",
    "EquilibriumResult",
    "SleeveResult",
    "hopf",
    "hopf_cycles",
    "HopfCyclesResult",
    "HopfResult",
    "EquilibriumBranchResult",
]
