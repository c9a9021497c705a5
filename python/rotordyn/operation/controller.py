"""An LTI controller in the loop: u = K(s) y_m added to the chamber-pressure command (Pa),
continuous or discrete (sample time, zero-order hold), reading chosen measurements with
optional seeded sensor noise. The same object closes the linear loop
(:mod:`rotordyn.control.closedloop`) and runs inside the nonlinear CVODE transient."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.operation.measurement import parse_measurements


def _mat(name, M):
    return v.matrix(f"controller.{name}", M)


MIN_SAMPLE_TIME_S = 1e-7  # 10 MHz: a sample time (or noise grid) below it is not physical
MAX_SAMPLE_TIME_S = 1.0


def _noise_std(value, ny):
    """A scalar or ``ny`` standard deviations >= 0 (m or m/s)."""
    if np.ndim(value) == 0:
        return v.non_negative("controller.noise_std", value)
    arr = v.vector("controller.noise_std", value, ny)
    if np.any(arr < 0):
        raise InputError(f"controller.noise_std: expected values >= 0, got {float(arr.min())!r}")
    return arr


_OPTIONS = ("sample_time_s", "noise_std", "noise_dt_s", "seed", "name", "info",
            "computation_delay_s", "anti_windup_gain", "anti_windup_mode", "schedule_speed_hz",
            "schedule_law")

# How the valve's saturation reaches the law's states (rotordyn.control.antiwindup):
# "back-calculation" feeds the whole undelivered command back; "conditioning" first clips the
# open-loop part of the command (the schedule) to the valve's range, so only the law's own
# share of the saturation is fed back.
ANTI_WINDUP_MODES = ("back-calculation", "conditioning")


def _options(kw):
    bad = sorted(set(kw) - set(_OPTIONS))
    if bad:
        raise InputError(f"controller: unknown option(s) {', '.join(bad)}; expected any of "
                         f"{', '.join(_OPTIONS)}")


@dataclass(frozen=True)
class Controller:
    """ẋ = A x + B y, u = C x + D y (continuous, ``sample_time_s`` None) or
    x⁺ = A x + B y_k, u_k = C x_k + D y_k held for one sample (discrete), applied
    ``computation_delay_s`` ∈ [0, T] after the sample it was computed from (the controller's
    computation time; exact in the linear loop and in the transient).

    y: the measurements (see :func:`rotordyn.analysis.measurement.measurement_matrix`) minus
    their value at the operating point; u: chamber-pressure command increment, Pa.
    Shapes: A (n_k, n_k), B (n_k, n_y), C (1, n_k), D (1, n_y).
    ``noise_std``: sensor noise standard deviation(s) (m or m/s; scalar or one per signal);
    ``noise_dt_s``: the noise grid of a continuous controller (linearly interpolated).
    ``anti_windup_gain`` (n_k,) and ``anti_windup_mode`` ("back-calculation" or
    "conditioning"): anti-windup in the transient, continuous or discrete
    (:func:`rotordyn.control.antiwindup.with_anti_windup`).
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    measurements: tuple
    sample_time_s: float | None = None
    noise_std: object = 0.0
    noise_dt_s: float = 1e-4
    seed: int = 0
    name: str = "controller"
    info: dict = field(default_factory=dict, compare=False)
    computation_delay_s: float = 0.0
    anti_windup_gain: object = None
    anti_windup_mode: str = "back-calculation"
    schedule_speed_hz: object = None
    schedule_law: object = None

    def __post_init__(self):
        object.__setattr__(self, "measurements", parse_measurements(self.measurements))
        A, B, C, D = (_mat(k, getattr(self, k)) for k in "ABCD")
        nk = A.shape[0] if A.size else 0
        if A.size == 0:
            A = np.zeros((0, 0))
        ny = D.shape[1]
        if A.shape != (nk, nk):
            raise InputError(f"controller.A: expected a square matrix, got shape {A.shape}")
        if C.shape[0] != 1 or D.shape[0] != 1:
            raise InputError(f"controller: expected 1 output (the chamber-pressure command), "
                             f"got {max(C.shape[0], D.shape[0])} (C {C.shape}, D {D.shape})")
        if nk == 0:
            B, C = np.zeros((0, ny)), np.zeros((1, 0))
        if B.shape != (nk, ny) or C.shape != (1, nk):
            raise InputError(f"controller.B/C: expected shapes ({nk}, {ny}) and (1, {nk}), got "
                             f"{B.shape} and {C.shape}")
        for k, M in zip("ABCD", (A, B, C, D)):
            object.__setattr__(self, k, M)
        st = self.sample_time_s
        if st is not None:
            # Bounded by something physical: 10 MHz sampling at the fastest (beyond it the
            # ZOH map e^{AT} is the identity to round-off and ln z / T blows up), 1 Hz at the
            # slowest (slower than any rotor mode of interest; e^{AT} overflows long before
            # T = 1e300).
            try:
                st = v.in_range("controller.sample_time_s", st, MIN_SAMPLE_TIME_S,
                                MAX_SAMPLE_TIME_S)
            except InputError as exc:
                raise InputError(f"{exc} (a discrete controller's sample time, s; None: "
                                 f"continuous)") from None
            object.__setattr__(self, "sample_time_s", st)
        delay = v.in_range("controller.computation_delay_s", self.computation_delay_s, 0.0,
                           MAX_SAMPLE_TIME_S)
        if delay and st is None:
            raise InputError(f"controller.computation_delay_s: a continuous controller takes no "
                             f"computation delay here (got {delay!r} s); use "
                             f"rotordyn.control.delay.with_pade_delay(), or a discrete law")
        if st is not None and delay > st:
            raise InputError(f"controller.computation_delay_s: expected a delay in [0, {st:g}] s "
                             f"(the sample time), got {delay!r}")
        object.__setattr__(self, "computation_delay_s", delay)
        if self.anti_windup_gain is not None:
            L = v.vector("controller.anti_windup_gain", self.anti_windup_gain, nk)
            object.__setattr__(self, "anti_windup_gain", L)
        mode = v.choice("controller.anti_windup_mode", self.anti_windup_mode, ANTI_WINDUP_MODES)
        if mode != "back-calculation" and self.anti_windup_gain is None:
            raise InputError(f"controller.anti_windup_mode: {mode!r} needs an anti-windup gain "
                             f"(controller.anti_windup_gain; rotordyn.control.antiwindup."
                             f"with_anti_windup)")
        if (self.schedule_speed_hz is None) != (self.schedule_law is None):
            raise InputError("controller.schedule_speed_hz/schedule_law: give both (a gain "
                             "schedule, rotordyn.control.gain_schedule) or neither")
        if self.schedule_speed_hz is not None:
            sp = v.vector("controller.schedule_speed_hz", self.schedule_speed_hz)
            if sp.size < 1 or np.any(np.diff(sp) <= 0) or np.any(sp < 0):
                raise InputError(f"controller.schedule_speed_hz: expected strictly increasing "
                                 f"speeds >= 0 Hz, got {sp!r}")
            law = v.matrix("controller.schedule_law", self.schedule_law)
            w = nk * nk + nk * ny + nk + ny
            if law.shape != (sp.size, w):
                raise InputError(f"controller.schedule_law: expected shape ({sp.size}, {w}) "
                                 f"(one [vec A, vec B, C, D] row per grid speed), got "
                                 f"{law.shape}")
            object.__setattr__(self, "schedule_speed_hz", sp)
            object.__setattr__(self, "schedule_law", law)
        object.__setattr__(self, "noise_dt_s", v.in_range(
            "controller.noise_dt_s", self.noise_dt_s, MIN_SAMPLE_TIME_S, MAX_SAMPLE_TIME_S))
        object.__setattr__(self, "noise_std", _noise_std(self.noise_std, ny))
        v.integer("controller.seed", self.seed, lo=0)
        v.text("controller.name", self.name)
        if not isinstance(self.info, dict):
            raise InputError(f"controller.info: expected a dict, got {type(self.info).__name__}")

    @property
    def n_inputs(self) -> int:
        return self.D.shape[1]

    @property
    def n_states(self) -> int:
        return self.A.shape[0]

    @property
    def discrete(self) -> bool:
        return self.sample_time_s is not None

    @classmethod
    def static(cls, gains, measurements, **kw) -> "Controller":
        """u = gains · y (no states), e.g. a PD law on journal displacement and velocity."""
        _options(kw)
        g = v.matrix("controller.gains", gains)
        return cls(np.zeros((0, 0)), np.zeros((0, g.shape[1])), np.zeros((1, 0)), g,
                   measurements, **kw)

    @classmethod
    def from_lti(cls, sys, measurements, **kw) -> "Controller":
        """From a python-control ``StateSpace`` or ``TransferFunction`` (inputs: the
        measurements in order, output: Pa). A discrete system (``dt`` > 0) keeps its sample
        time; ``dt=True`` (unspecified) is rejected."""
        import control

        _options(kw)
        if isinstance(sys, control.TransferFunction):
            sys = control.ss(sys)
        if not isinstance(sys, control.StateSpace):
            raise InputError(f"controller: expected a python-control StateSpace or "
                             f"TransferFunction, got {type(sys).__name__}")
        dt = sys.dt
        if dt is True:
            raise InputError("controller.sample_time_s: the discrete system has an "
                             "unspecified sample time (dt=True); give dt > 0")
        dt = None if dt in (None, 0) else float(dt)
        if "sample_time_s" in kw and kw.pop("sample_time_s") != dt:
            raise InputError("controller.sample_time_s: differs from the system's dt")
        return cls(np.asarray(sys.A), np.asarray(sys.B), np.asarray(sys.C), np.asarray(sys.D),
                   measurements, sample_time_s=dt, **kw)

    def to_control(self, *, balanced: bool = True):
        """The python-control system (dt = sample time, or 0), input names ``y[i]``, output
        ``chamber_pressure_command_pa``. ``balanced`` (default): states scaled by powers of
        two (exact, :mod:`rotordyn._common.balance`; each state's name carries its ``·2^-e``)
        so python-control evaluates it to round-off with or without slycot (an LQG law's
        unscaled states made SLICOT's TB05AD 29 % wrong: issue 24); same transfer function."""
        import control

        from rotordyn._common.balance import scaled, scaled_state_names, state_scaling

        v.boolean("balanced", balanced)
        A, B, C = self.A, self.B, self.C
        names = [f"x[{i}]" for i in range(self.n_states)]
        if balanced and self.n_states:
            t = state_scaling(A, B, C)
            A, B, C = scaled(A, B, C, t)
            names = scaled_state_names(names, t)
        return control.ss(A, B, C, self.D, dt=self.sample_time_s or 0,
                          inputs=[f"y[{i}]" for i in range(self.n_inputs)],
                          outputs=["chamber_pressure_command_pa"], states=names or None,
                          name=self.name)

    def scaled(self, gain: float) -> "Controller":
        """The same controller with its output multiplied by ``gain``."""
        v.finite("gain", gain)
        L = self.anti_windup_gain
        # the same tracking rate C L: L / gain (a zero gain has no output to track)
        L = None if L is None or gain == 0 else L / gain
        return Controller(self.A, self.B, gain * self.C, gain * self.D, self.measurements,
                          self.sample_time_s, self.noise_std, self.noise_dt_s, self.seed,
                          self.name, dict(self.info), self.computation_delay_s, L,
                          self.anti_windup_mode if L is not None else "back-calculation",
                          self.schedule_speed_hz,
                          None if self.schedule_law is None else self._scaled_law(gain))

    def _scaled_law(self, gain):
        nk, ny = self.n_states, self.n_inputs
        law = self.schedule_law.copy()
        law[:, nk * nk + nk * ny:] *= gain  # C and D
        return law

    def with_options(self, **kw) -> "Controller":
        d = dict(A=self.A, B=self.B, C=self.C, D=self.D, measurements=self.measurements,
                 sample_time_s=self.sample_time_s, noise_std=self.noise_std,
                 noise_dt_s=self.noise_dt_s, seed=self.seed, name=self.name, info=self.info,
                 computation_delay_s=self.computation_delay_s,
                 anti_windup_gain=self.anti_windup_gain,
                 anti_windup_mode=self.anti_windup_mode,
                 schedule_speed_hz=self.schedule_speed_hz, schedule_law=self.schedule_law)
        bad = sorted(set(kw) - set(d))
        if bad:
            raise InputError(f"controller: unknown option(s) {', '.join(bad)}; expected any "
                             f"of {', '.join(d)}")
        d.update(kw)
        return Controller(**d)

    def with_washout(self, corner_hz: float) -> "Controller":
        """The controller behind a first-order high-pass s/(s + a), a = 2π·corner_hz, on every
        measurement: slow drifts (the equilibrium moving during a run-up) no longer feed
        the law. States [x_w (n_y); x_k]."""
        v.in_range("corner_hz", corner_hz, 0.0, 1e6, lo_open=True)
        if self.schedule_law is not None:
            raise InputError("controller.schedule_law: add the washout to each design before "
                             "scheduling them (rotordyn.control.gain_schedule)")
        a = 2 * np.pi * corner_hz
        ny, nk = self.n_inputs, self.n_states
        A = np.block([[-a * np.eye(ny), np.zeros((ny, nk))], [-a * self.B, self.A]])
        B = np.vstack([np.eye(ny), self.B])
        C = np.hstack([-a * self.D, self.C])
        info = dict(self.info, washout_hz=corner_hz)
        return self.with_options(A=A, B=B, C=C, D=self.D.copy(), info=info,
                                 name=self.name + "+washout", anti_windup_gain=None,
                                 anti_windup_mode="back-calculation",
                                 schedule_speed_hz=None, schedule_law=None)

    def to_core(self, Cm: np.ndarray, offset: np.ndarray):
        ny = Cm.shape[0]
        if ny != self.n_inputs:
            raise InputError(f"controller: expected {ny} inputs (the measurements "
                             f"{self.measurements} give {ny} signals), got {self.n_inputs}")
        k = _core.Controller()
        k.enabled = True
        k.A, k.B, k.C, k.D = self.A, self.B, self.C, self.D
        k.measurement = Cm
        k.offset = offset
        k.sample_time = float(self.sample_time_s or 0.0)
        k.delay = float(self.computation_delay_s)
        if self.anti_windup_gain is not None:
            k.tracking = self.anti_windup_gain
            k.realise_schedule = self.anti_windup_mode == "conditioning"
        if self.schedule_speed_hz is not None:
            k.schedule_omega = 2 * np.pi * self.schedule_speed_hz
            k.schedule_law = self.schedule_law
        ns = np.broadcast_to(np.asarray(self.noise_std, dtype=float), (ny,)).copy()
        if np.any(ns > 0):
            k.noise_std = ns
            k.noise_dt = float(self.noise_dt_s)
        k.seed = int(self.seed)
        return k


def check_schedule_covers(controller: Controller, lo_hz: float, hi_hz: float) -> None:
    """InputError naming ``controller.schedule_speed_hz`` when the speeds [lo_hz, hi_hz] of a
    run leave the schedule's grid (the law would be held constant beyond its designs)."""
    if controller.schedule_law is None:
        return
    x = controller.schedule_speed_hz
    tol = 1e-9 * max(abs(x[-1]), 1.0)
    if lo_hz < x[0] - tol or hi_hz > x[-1] + tol:
        raise InputError(f"controller.schedule_speed_hz: the schedule's grid {x[0]:g}–"
                         f"{x[-1]:g} Hz does not cover the run's speeds {lo_hz:g}–{hi_hz:g} Hz")


