"""Result objects (frozen dataclasses of numpy arrays with ``.to_frame()`` and ``.plot()``)."""

from rotordyn.results.campbell import CampbellResult
from rotordyn.results.continuation import BranchResult
from rotordyn.results.equilibrium import EquilibriumResult
from rotordyn.results.level1 import Level1Result
from rotordyn.results.modes import ModesResult
from rotordyn.results.periodic import PeriodicOrbitResult
from rotordyn.results.stability import LinearModel, StabilityResult
from rotordyn.results.threshold import BoundaryResult, ThresholdResult
from rotordyn.results.statespace import StateSpaceResult
from rotordyn.results.static import StaticResult
from rotordyn.results.store import load_result, save_result
from rotordyn.results.thermal import SystemThermalResult
from rotordyn.results.transient import TransientResult
from rotordyn.results.unbalance import UnbalanceResult
from rotordyn.results.hopf import HopfResult
from rotordyn.results.hopf_cycles import HopfCyclesResult

__all__ = ["Level1Result", "ModesResult", "CampbellResult", "EquilibriumResult", "LinearModel",
           "StabilityResult", "ThresholdResult", "BoundaryResult", "UnbalanceResult",
           "StateSpaceResult", "TransientResult", "StaticResult", "PeriodicOrbitResult",
           "BranchResult", "SystemThermalResult", "load_result", "save_result"]
from rotordyn.results.equilibrium_branch import EquilibriumBranchResult

__all__ += ["HopfResult", "HopfCyclesResult", "EquilibriumBranchResult"]
