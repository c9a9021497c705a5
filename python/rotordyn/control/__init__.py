"""Control-law synthesis with the active journal bearing (paper title and §7): design on the
linear model (plant with actuator, model reduction, LQR/LQG, PD/PID, H∞ where slycot is
importable, open-loop p_c(Ω) schedules, the synchronous bound), one module per method. The
laws, speed profiles, pressure schedules and the actuator that run in the nonlinear transient
are described in :mod:`rotordyn.operation` (re-exported here)."""

from rotordyn.analysis.measurement import measurement_matrix
from rotordyn.operation import Actuator, Controller, PressureSchedule, SpeedProfile

__all__ = ["Actuator", "Controller", "PressureSchedule", "SpeedProfile", "measurement_matrix"]

# the rows of a robust sweep and their worst cases (the sweep itself: rotordyn.sweep.robust)
from rotordyn.control.robust import RobustResult  # noqa: E402

__all__ += ["RobustResult"]
