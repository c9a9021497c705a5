"""How the machine is run in the nonlinear transient: the speed profile and the chamber-
pressure command over time (:mod:`.profiles`), the valve between command and chamber
(:mod:`.actuator`), a feedback law in the loop (:mod:`.controller`) and what it measures
(:mod:`.measurement`). Plain descriptions converted to the C++ core; they are designed by
:mod:`rotordyn.control` and run by :func:`rotordyn.transient`."""

from rotordyn.operation.actuator import Actuator
from rotordyn.operation.controller import Controller
from rotordyn.operation.profiles import PressureSchedule, SpeedProfile

__all__ = ["Actuator", "Controller", "PressureSchedule", "SpeedProfile"]
