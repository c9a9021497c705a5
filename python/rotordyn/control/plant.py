"""The plant for control design: the linearised system (paper eq. 19, :func:`rotordyn.statespace`)
in series with the actuator, input = chamber-pressure command increment (Pa), outputs = the
controller's measurements (m, m/s), plus optional force inputs at rotor stations (N) as
disturbances."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotordyn.analysis.measurement import measurement_matrix
from rotordyn.analysis.statespace import statespace
from rotordyn._common import validate as v
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
    disturbance_names: tuple = ()

    @property
    def poles(self) -> np.ndarray:
        return np.linalg.eigvals(self.A)

    @property
    def input_names(self) -> tuple:
        """The command (Pa), then the disturbance forces (N), as :meth:`to_control` names them."""
        return ("chamber_pressure_command_pa",) + tuple(self.disturbance_names)

    @property
    def performance_names(self) -> tuple:
        b = int(self.info.get("performance_bearing", 0))
        return tuple(f"performance_{n}" for n in
                     (f"journal_x_m[{b}]", f"journal_y_m[{b}]")[:self.C_perf.shape[0]])

    def matrices(self):
        """(A, B, C, D) of the whole plant: inputs [u; d], outputs [y; z] (measurements, then
        the performance output), D with a reduced plant's feedthrough (every input to every
        output where the reduction kept it: ``info["feedthrough_all"]``, else its command →
        measurement part ``info["feedthrough"]``)."""
        B = np.hstack([self.B, self.Bd])
        C = np.vstack([self.C, self.C_perf])
        D = np.zeros((C.shape[0], B.shape[1]))
        Dall = self.info.get("feedthrough_all")
        Dr = self.info.get("feedthrough")
        if Dall is not None:
            D[:] = Dall
        elif Dr is not None:
            D[:self.C.shape[0], :1] = Dr
        return self.A, B, C, D

    def frequency_response(self, freqs_hz) -> np.ndarray:
        """G(i2πf) of :meth:`matrices`, (n_f, n_y + n_z, 1 + n_d) complex (outputs' unit per
        input's unit: m/Pa, m/N, ...), evaluated on the balanced realisation
        (:mod:`rotordyn._common.balance`)."""
        from rotordyn.control import lti

        f = chk.frequencies_any("freqs_hz", freqs_hz)
        A, B, C, D = self.matrices()
        return lti.freqresp(lti.balanced(lti.SS(A, B, C, D)), 2 * np.pi * f)

    def to_control(self, *, balanced: bool = True):
        """python-control ``StateSpace`` of the whole plant (:meth:`matrices`): every input
        and output named (:attr:`input_names`; the measurements' names, then
        :attr:`performance_names`), a reduced plant's feedthrough kept. ``balanced`` (default):
        states scaled by powers of two (x̃ = x / 2^e, exact; each state's name carries its
        ``·2^-e``) so that python-control evaluates it to round-off with or without slycot
        (unscaled, SLICOT's TB05AD Hessenberg reduction loses up to every digit: issue 24);
        the transfer function is the same either way."""
        import control

        from rotordyn._common.balance import scaled, scaled_state_names, state_scaling

        v.boolean("balanced", balanced)
        A, B, C, D = self.matrices()
        names = list(self.state_names)
        if balanced:
            t = state_scaling(A, B, C)
            A, B, C = scaled(A, B, C, t)
            names = scaled_state_names(names, t)
        return control.ss(A, B, C, D, inputs=list(self.input_names),
                          outputs=[str(n) for n in self.output_names] + list(
                              self.performance_names),
                          states=names, name=f"plant_{self.speed_hz:g}Hz")


    def to_scipy(self, output: int = 0, input: int = 0):
        """``scipy.signal.ZerosPolesGain`` from input ``input`` to output ``output`` of
        :meth:`matrices` (SciPy's frequency responses are SISO and convert a state space to
        polynomials; the factors here come from the balanced model:
        :func:`rotordyn.control.lti.zpk`)."""
        import scipy.signal as sig

        from rotordyn.control import lti

        A, B, C, D = self.matrices()
        i = v.integer("output", output, lo=0, hi=C.shape[0] - 1)
        j = v.integer("input", input, lo=0, hi=B.shape[1] - 1)
        z, p_, k = lti.zpk(lti.SS(A, B[:, j:j + 1], C[i:i + 1], D[i:i + 1, j:j + 1]))
        return sig.ZerosPolesGain(z, p_, k)


def active_bearing_index(system) -> int:
    """Index of the (first) active journal bearing in ``system.bearings``: the bearing whose
    journal the designs weigh (``C_perf``) and that the laws measure by default; 0 for a
    model without one (statespace refuses the chamber-pressure input there anyway)."""
    from rotordyn.bearings import ActiveJournalBearing

    return next((i for i, b in enumerate(system.bearings)
                 if isinstance(b, ActiveJournalBearing)), 0)


def plant(system, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
          config_ay_m: float | None = None, *, measurements=(("journal", 0),),
          actuator: Actuator | None = None, disturbance_stations=(),
          equilibrium: dict | None = None) -> Plant:
    """Linear plant about the equilibrium at (speed, p_c, a_y) with the actuator's lag
    (Actuator(): a 100 Hz second-order valve; ``Actuator.ideal()`` for none).
    ``equilibrium``: keywords of :func:`rotordyn.equilibrium` (e.g. ``{"warm_start": False}``
    for a result that does not depend on what this thread solved before).
    ``measurements``: default journal 0, as :func:`rotordyn.control.pid.pid`'s ``bearing``
    (a law and its plant read the same signals); the performance output ``C_perf`` is the
    active bearing's journal wherever it sits."""
    speed_hz, chamber_pressure_pa, config_ay_m = chk.operating_point(
        system, speed_hz, chamber_pressure_pa, config_ay_m)
    act = chk.actuator(actuator)
    ia = active_bearing_index(system)
    meas = parse_measurements(measurements)
    measurement_matrix(system, meas)  # a measurement that does not exist: before the solve
    empty = not isinstance(disturbance_stations, (str, bytes, dict, int, np.integer)) \
        and hasattr(disturbance_stations, "__len__") and len(disturbance_stations) == 0
    dist = () if empty else chk.stations(system, disturbance_stations, "disturbance_stations")
    inputs = [("chamber_pressure",)] + [("force", s) for s in dist]
    if equilibrium is not None and not isinstance(equilibrium, dict):
        raise InputError(f"equilibrium: expected a dict of equilibrium keywords, got "
                         f"{type(equilibrium).__name__}")
    ss = statespace(system, inputs=inputs, speed_hz=speed_hz,
                    chamber_pressure_pa=chamber_pressure_pa, config_ay_m=config_ay_m,
                    **(equilibrium or {}))
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
    # the performance output is the active bearing's journal, wherever it is in the model
    # (the compressor_active model has it second: journal 0 there is the plain NDE bearing)
    Cj, _ = measurement_matrix(system, [("journal", ia)])
    Cp = np.hstack([Cj, np.zeros((2, na))])
    states = tuple(ss.state_names) + tuple(f"actuator_{i}" for i in range(na))
    return Plant(A, B, C, Bd, Cp, meas, names, states, act, float(speed_hz),
                 float(chamber_pressure_pa), config_ay_m, n2 // 2,
                 info={"performance_bearing": ia,
                       "performance_clearance_m": float(system.bearings[ia].clearance_m)
                       if system.bearings else None,
                       "equilibrium_r": np.asarray(ss.linear.equilibrium.r, float),
                       "equilibrium_status": str(ss.linear.equilibrium.status)},
                 disturbance_names=tuple(str(x) for x in ss.input_names[1:]))


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
