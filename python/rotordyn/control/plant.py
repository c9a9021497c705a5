"""The plant for control design: the linearised system (paper eq. 19, :func:`rotordyn.statespace`)
in series with the actuator, input = chamber-pressure command increment (Pa), outputs = the
controller's measurements (m, m/s), plus optional force inputs at rotor stations (N) as
disturbances."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotordyn.analysis.measurement import measurement_matrix
from rotordyn.analysis.statespace import statespace
from rotordyn.control import _checks as chk
from rotordyn.errors import InputError
from rotordyn.operation.actuator import Actuator
from rotordyn.operation.measurement import parse_measurements


@dataclass(frozen=True)
class Plant:
    """ẋ = A x + B u + B_d d, y = C x; x = [Δr; Δṙ; actuator states] (2n + order).

    u: command increment (Pa, 1 input); d: disturbance forces (N, 2 per station in
    ``disturbance_stations``); y: ``measurements`` (m or m/s); z = C_perf x: the journal of
    the active bearing (m), the default performance output of the designs.
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    Bd: np.ndarray
    C_perf: np.ndarray
    measurements: tuple
    output_names: tuple
    state_names: tuple
    actuator: Actuator
    speed_hz: float
    chamber_pressure_pa: float
    config_ay_m: float | None
    n_mech: int
    info: dict = field(default_factory=dict)

    @property
    def poles(self) -> np.ndarray:
        return np.linalg.eigvals(self.A)

    def to_control(self):
        """python-control StateSpace from u to y."""
        import control

        return control.ss(self.A, self.B, self.C, np.zeros((self.C.shape[0], 1)))


def plant(system, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
          config_ay_m: float | None = None, *, measurements=(("journal", 0),),
          actuator: Actuator | None = None, disturbance_stations=()) -> Plant:
    """Linear plant about the equilibrium at (speed, p_c, a_y) with the actuator's lag
    (Actuator(): a 100 Hz second-order valve; ``Actuator.ideal()`` for none)."""
    speed_hz, chamber_pressure_pa, config_ay_m = chk.operating_point(
        system, speed_hz, chamber_pressure_pa, config_ay_m)
    act = chk.actuator(actuator)
    meas = parse_measurements(measurements)
    measurement_matrix(system, meas)  # a measurement that does not exist: before the solve
    empty = not isinstance(disturbance_stations, (str, bytes, dict, int, np.integer)) \
        and hasattr(disturbance_stations, "__len__") and len(disturbance_stations) == 0
    dist = () if empty else chk.stations(system, disturbance_stations, "disturbance_stations")
    inputs = [("chamber_pressure",)] + [("force", s) for s in dist]
    ss = statespace(system, inputs=inputs, speed_hz=speed_hz,
                    chamber_pressure_pa=chamber_pressure_pa, config_ay_m=config_ay_m)
    n2 = ss.A.shape[0]
    Aa, Ba, Ca = act.statespace()
    na = Aa.shape[0]
    bp = ss.B[:, :1]
    A = np.zeros((n2 + na, n2 + na))
    A[:n2, :n2] = ss.A
    if na:
        A[:n2, n2:] = bp @ Ca
        A[n2:, n2:] = Aa
        B = np.vstack([np.zeros((n2, 1)), Ba])
    else:
        B = bp.copy()
    Bd = np.vstack([ss.B[:, 1:], np.zeros((na, ss.B.shape[1] - 1))])
    Cm, names = measurement_matrix(system, meas)
    C = np.hstack([Cm, np.zeros((Cm.shape[0], na))])
    Cj, _ = measurement_matrix(system, [("journal", 0)])
    Cp = np.hstack([Cj, np.zeros((2, na))])
    states = tuple(ss.state_names) + tuple(f"actuator_{i}" for i in range(na))
    return Plant(A, B, C, Bd, Cp, meas, names, states, act, float(speed_hz),
                 float(chamber_pressure_pa), config_ay_m, n2 // 2)


def as_plant(value, field: str = "plant") -> Plant:
    """``value`` if it is a :class:`Plant` (from :func:`plant` or a reduction of one)."""
    if not isinstance(value, Plant):
        raise InputError(f"{field}: expected a rotordyn.control.plant.Plant (from "
                         f"rotordyn.control.plant.plant()), got {type(value).__name__}")
    return value


def paired(p, k) -> None:
    """A plant and a controller that reads exactly the plant's measurements (InputError
    naming ``controller`` otherwise)."""
    from rotordyn.operation.controller import Controller

    as_plant(p)
    chk.controller(k)
    if not isinstance(k, Controller):  # pragma: no cover - chk.controller refuses it
        raise InputError("controller: expected a rotordyn.control.Controller")
    if k.n_inputs != p.C.shape[0]:
        raise InputError(f"controller: expected {p.C.shape[0]} inputs (the plant's "
                         f"measurements), got {k.n_inputs}")
    if tuple(k.measurements) != tuple(p.measurements):
        raise InputError(f"controller.measurements: expected the plant's measurements "
                         f"{list(p.measurements)}, got {list(k.measurements)}")
