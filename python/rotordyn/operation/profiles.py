"""Time-varying operation for the nonlinear transient: the speed profile Ω(t) and the chamber-
pressure command p_cmd(t) (constant, table in time, schedule in speed, harmonic or 1×-locked);
the actuator between the command and p_c is :mod:`rotordyn.operation.actuator`."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.units import hz_to_rad_s


def _table(name, x, y, *, x_positive=False):
    x = v.vector(f"{name} abscissae", np.ravel(x) if isinstance(x, np.ndarray) else x)
    y = v.vector(f"{name} values", np.ravel(y) if isinstance(y, np.ndarray) else y)
    if x.size == 0 or x.size != y.size:
        raise InputError(f"{name}: expected arrays of the same non-zero length, got "
                         f"{x.size} and {y.size}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        raise InputError(f"{name}: expected finite values")
    if x.size > 1 and np.any(np.diff(x) <= 0):
        raise InputError(f"{name}: expected strictly increasing abscissae")
    if x_positive and np.any(x < 0):
        raise InputError(f"{name}: expected abscissae >= 0")
    return x, y


@dataclass(frozen=True)
class SpeedProfile:
    """Ω(t): piecewise linear through (t_s, speed_hz), constant outside. The rotor angle is
    its exact integral. Build with :meth:`constant`, :meth:`ramp` or :meth:`table`."""

    t_s: np.ndarray
    speed_hz: np.ndarray

    @classmethod
    def constant(cls, speed_hz: float) -> "SpeedProfile":
        return cls(np.zeros(1), np.array([v.speed("speed_hz", speed_hz)]))

    @classmethod
    def ramp(cls, start_hz: float, stop_hz: float, rate_hz_per_s: float,
             t_start_s: float = 0.0) -> "SpeedProfile":
        """Run-up (stop > start) or coast-down at |rate| Hz/s from ``t_start_s``; constant
        before and after."""
        start_hz, stop_hz = v.speed("start_hz", start_hz), v.speed("stop_hz", stop_hz)
        rate_hz_per_s = v.positive("rate_hz_per_s", rate_hz_per_s)
        t_start_s = v.non_negative("t_start_s", t_start_s)
        if stop_hz == start_hz:
            raise InputError("stop_hz: expected a speed different from start_hz")
        t1 = t_start_s + abs(stop_hz - start_hz) / rate_hz_per_s
        if not math.isfinite(t1) or t1 <= t_start_s:
            raise InputError(f"rate_hz_per_s: the ramp from {start_hz:g} to {stop_hz:g} Hz at "
                             f"{rate_hz_per_s!r} Hz/s has no finite, resolvable duration")
        return cls(np.array([t_start_s, t1]), np.array([float(start_hz), float(stop_hz)]))

    @classmethod
    def table(cls, t_s, speed_hz) -> "SpeedProfile":
        t, s = _table("speed_profile", t_s, speed_hz, x_positive=True)
        if np.any(np.abs(s) > v.MAX_SPEED_HZ):
            raise InputError(f"speed_profile values: expected speeds in [-{v.MAX_SPEED_HZ:g}, "
                             f"{v.MAX_SPEED_HZ:g}] Hz")
        return cls(t, s)

    def speed_at(self, t_s) -> np.ndarray:
        return np.interp(t_s, self.t_s, self.speed_hz)

    @property
    def is_constant(self) -> bool:
        return self.t_s.size == 1 or bool(np.all(self.speed_hz == self.speed_hz[0]))

    def to_core(self):
        sp = _core.SpeedProfile()
        if self.t_s.size > 1:
            sp.t = self.t_s
            sp.omega = hz_to_rad_s(self.speed_hz)
        return sp


@dataclass(frozen=True)
class PressureSchedule:
    """Chamber-pressure command without feedback, Pa: a base (constant, a table p(t) or a
    schedule p(Ω) — piecewise linear, constant outside) plus an optional harmonic
    ``amplitude_pa · sin(2π f t + phase)``, or with ``order`` > 0 locked to the rotor angle:
    ``amplitude_pa · sin(order θ(t) + phase)`` (order 1: once per revolution). With
    :meth:`with_harmonic_schedule` the amplitude and phase are tables over the speed,
    interpolated piecewise linearly at Ω(t) (constant outside): a speed-scheduled 1×
    command locked to the rotor angle."""

    kind: str = "constant"  # constant | time_table | speed_table
    value_pa: float = 0.0
    x: np.ndarray = field(default_factory=lambda: np.zeros(0))
    p_pa: np.ndarray = field(default_factory=lambda: np.zeros(0))
    amplitude_pa: float = 0.0
    frequency_hz: float = 0.0
    phase_deg: float = 0.0
    order: float = 0.0
    harmonic_speed_hz: np.ndarray = field(default_factory=lambda: np.zeros(0))
    harmonic_amplitudes_pa: np.ndarray = field(default_factory=lambda: np.zeros(0))
    harmonic_phases_deg: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @classmethod
    def constant(cls, chamber_pressure_pa: float) -> "PressureSchedule":
        return cls("constant", v.finite("chamber_pressure_pa", chamber_pressure_pa))

    @classmethod
    def time_table(cls, t_s, chamber_pressure_pa) -> "PressureSchedule":
        t, p = _table("chamber_pressure table", t_s, chamber_pressure_pa, x_positive=True)
        return cls("time_table", float(p[0]), t, p)

    @classmethod
    def speed_table(cls, speed_hz, chamber_pressure_pa) -> "PressureSchedule":
        """An open-loop schedule p_c(Ω) (e.g. from :func:`rotordyn.control.pressure_schedule`)."""
        s, p = _table("chamber_pressure schedule", speed_hz, chamber_pressure_pa)
        return cls("speed_table", float(p[0]), s, p)

    def with_harmonic(self, amplitude_pa: float, *, frequency_hz: float = 0.0,
                      phase_deg: float = 0.0, order: float = 0.0) -> "PressureSchedule":
        v.finite("amplitude_pa", amplitude_pa)
        v.non_negative("frequency_hz", frequency_hz)
        v.finite("phase_deg", phase_deg)
        v.non_negative("order", order)
        if amplitude_pa and not (frequency_hz or order):
            raise InputError("frequency_hz/order: a harmonic needs a frequency or an order > 0")
        return PressureSchedule(self.kind, self.value_pa, self.x, self.p_pa,
                                float(amplitude_pa), float(frequency_hz), float(phase_deg),
                                float(order))

    def with_harmonic_schedule(self, speed_hz, amplitude_pa, phase_deg, *, order: float = 1.0,
                               frequency_hz: float = 0.0) -> "PressureSchedule":
        """Add ``A(Ω) · sin(order θ(t) + φ(Ω))`` (or ``sin(2π f t + φ(Ω))`` with ``order`` 0):
        amplitude (Pa) and phase (degrees, unwrapped — interpolated as given) tables over the
        speed (Hz, increasing), e.g. from :func:`rotordyn.control.synchronous.synchronous_bound`.
        One-point tables are a constant harmonic (bit for bit :meth:`with_harmonic`)."""
        sp, amp = _table("harmonic schedule", speed_hz, amplitude_pa)
        sp2, ph = _table("harmonic schedule", speed_hz, phase_deg)
        v.non_negative("order", order)
        v.non_negative("frequency_hz", frequency_hz)
        if not (order or frequency_hz):
            raise InputError("frequency_hz/order: a harmonic needs a frequency or an order > 0")
        return PressureSchedule(self.kind, self.value_pa, self.x, self.p_pa, 0.0,
                                float(frequency_hz), 0.0, float(order), sp, amp, ph)

    def to_core(self):
        pc = _core.PressureCommand()
        pc.source = getattr(_core.PressureSource, self.kind)
        if self.kind != "constant":
            pc.table_x = self.x if self.kind == "time_table" else hz_to_rad_s(self.x)
            pc.table_p = self.p_pa
        pc.harmonic_amplitude = self.amplitude_pa
        pc.harmonic_frequency = hz_to_rad_s(self.frequency_hz)
        pc.harmonic_phase = math.radians(self.phase_deg)
        pc.harmonic_order = self.order
        if self.harmonic_speed_hz.size:
            pc.harmonic_table_omega = hz_to_rad_s(self.harmonic_speed_hz)
            pc.harmonic_table_amplitude = self.harmonic_amplitudes_pa
            pc.harmonic_table_phase = np.radians(self.harmonic_phases_deg)
        return pc
