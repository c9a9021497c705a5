"""Result objects (frozen dataclasses of numpy arrays with ``.to_frame()`` and ``.plot()``)."""

from rotordyn.results.campbell import CampbellResult
from rotordyn.results.equilibrium import EquilibriumResult
from rotordyn.results.modes import ModesResult
from rotordyn.results.stability import LinearModel, StabilityResult

__all__ = ["ModesResult", "CampbellResult", "EquilibriumResult", "LinearModel", "StabilityResult"]
