"""Control-law synthesis with the active journal bearing (paper title and §7): time-varying
operation of the nonlinear transient (speed profiles, pressure schedules, actuator), LTI
controllers in the loop, and their design on the linear model (plant with actuator, model
reduction, LQR/LQG, PD/PID, H∞ where slycot is importable, open-loop p_c(Ω) schedules)."""

from rotordyn.control.controller import Controller
from rotordyn.control.measurement import measurement_matrix
from rotordyn.control.operation import Actuator, PressureSchedule, SpeedProfile

__all__ = ["Actuator", "Controller", "PressureSchedule", "SpeedProfile", "measurement_matrix"]
