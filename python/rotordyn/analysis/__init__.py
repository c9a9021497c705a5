"""Analyses: verbs returning ``*Result`` objects."""

from rotordyn.analysis.modes import RotorMatrices, modes

__all__ = ["modes", "RotorMatrices"]
