"""Analyses: verbs returning ``*Result`` objects."""

from rotordyn.analysis.campbell import campbell
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.analysis.level1 import level1
from rotordyn.analysis.linear import linearize, stability
from rotordyn.analysis.statespace import statespace
from rotordyn.analysis.static import static
from rotordyn.analysis.transient import transient
from rotordyn.analysis.unbalance import unbalance_response
from rotordyn.analysis.threshold import stability_boundary, threshold
from rotordyn.analysis.periodic import periodic_orbit
from rotordyn.analysis.continuation import continuation
from rotordyn.analysis.modes import RotorMatrices, modes, rotor_campbell
from rotordyn.analysis.thermal import system_thermal_equilibrium
from rotordyn.analysis.hopf import hopf
from rotordyn.analysis.hopf_cycles import hopf_cycles

__all__ = ["level1", "static", "campbell", "modes", "rotor_campbell", "equilibrium", "linearize",
           "stability", "threshold", "stability_boundary", "unbalance_response", "statespace",
           "transient", "periodic_orbit", "continuation", "RotorMatrices",
           "system_thermal_equilibrium"]
__all__ += ["hopf", "hopf_cycles"]
