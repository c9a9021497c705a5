"""Analyses: verbs returning ``*Result`` objects."""

from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.analysis.modes import RotorMatrices, modes, rotor_campbell

__all__ = ["modes", "rotor_campbell", "equilibrium", "RotorMatrices"]
