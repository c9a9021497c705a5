"""The actuator (servo valve + chamber) between the chamber-pressure command and the chamber
pressure p_c.

The actuator models follow W. J. Thayer, *Transfer functions for Moog servovalves*, Moog
Technical Bulletin 103 (1958, rev. 1965): a servo valve is represented over the band that
matters by a first-order lag or a second-order lag whose natural frequency is the frequency of
90° phase lag and whose damping ratio fits the phase curve; H. E. Merritt, *Hydraulic Control
Systems* (Wiley, 1967, ch. 5–6) gives the same forms and adds the chamber's compressibility,
which for a small chamber is lumped into the same lag. The defaults (second order, f_n = 100 Hz,
ζ = 0.7; first order τ = 1/(2π·50 Hz)) are our choice of a two-stage valve with a
small chamber — two to ten times the rig's rotor critical speeds (39 and 90 Hz) — not numbers
read from a data sheet; docs/control.md shows how the results depend on them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.units import hz_to_rad_s

DEFAULT_P_MIN_PA = 0.0
DEFAULT_P_MAX_PA = 1.0e6


def _show(val) -> str:
    text = repr(val)
    return text if len(text) <= 40 else text[:20] + "…" + text[-8:]


@dataclass(frozen=True)
class Actuator:
    """Servo valve + chamber from the pressure command to p_c (module docstring for the
    sources of the forms and defaults).

    order 0: p_c = clip(p_cmd) (ideal); 1: τ ṗ = clip(p_cmd) − p; 2: p̈ + 2ζω_n ṗ + ω_n² p =
    ω_n² clip(p_cmd); clip to [p_min_pa, p_max_pa] (gauge; the chamber cannot pull), the rate
    |ṗ| ≤ rate_limit_pa_s (order ≥ 1), p_c = clip(p). States start at rest at the command.
    """

    order: int = 2
    time_constant_s: float = 1.0 / (2 * math.pi * 50.0)
    natural_frequency_hz: float = 100.0
    damping: float = 0.7
    p_min_pa: float = DEFAULT_P_MIN_PA
    p_max_pa: float = DEFAULT_P_MAX_PA
    rate_limit_pa_s: float = math.inf

    def __post_init__(self):
        v.integer("actuator.order", self.order, lo=0, hi=2)
        # Every field by its range, whatever the order (an unused one is still a number):
        # 0.1 µs .. 1000 s lag, (0, 1 MHz] valve, damping (0, 100] — beyond these ω² or 1/τ
        # leave the range where the closed loop's matrices stay finite.
        v.in_range("actuator.time_constant_s", self.time_constant_s, 1e-7, 1e3)
        v.in_range("actuator.natural_frequency_hz", self.natural_frequency_hz, 0.0, 1e6,
                   lo_open=True)
        v.in_range("actuator.damping", self.damping, 0.0, 100.0, lo_open=True)
        for name in ("p_min_pa", "p_max_pa", "rate_limit_pa_s"):
            # as float64 (issue 21, fuzzing: an integer beyond float64, 10**400, was accepted
            # and became an OverflowError in the transient)
            val = getattr(self, name)
            try:
                ok = not isinstance(val, (bool, np.bool_)) and isinstance(
                    val, (int, float, np.floating, np.integer)) and not math.isnan(float(val))
            except OverflowError:
                ok = False
            if not ok:
                unit = "Pa/s; inf: none" if name == "rate_limit_pa_s" else "Pa; ±inf: no limit"
                raise InputError(f"actuator.{name}: expected a float64 number ({unit}), "
                                 f"got {_show(val)}")
            object.__setattr__(self, name, float(val))
        if not self.p_min_pa < self.p_max_pa:
            raise InputError(f"actuator.p_min_pa/p_max_pa: expected p_min_pa < p_max_pa, got "
                             f"{self.p_min_pa!r} and {self.p_max_pa!r}")
        r = self.rate_limit_pa_s
        if not r > 0:
            raise InputError(f"actuator.rate_limit_pa_s: expected > 0 Pa/s (inf: none), got {r!r}")
        if self.order == 0 and math.isfinite(r):
            raise InputError("actuator.rate_limit_pa_s: a rate limit needs actuator dynamics "
                             "(order 1 or 2)")

    @classmethod
    def ideal(cls, p_min_pa: float = DEFAULT_P_MIN_PA, p_max_pa: float = DEFAULT_P_MAX_PA):
        """No lag: p_c = clip(p_cmd)."""
        return cls(order=0, p_min_pa=p_min_pa, p_max_pa=p_max_pa)

    @classmethod
    def unlimited(cls):
        """No lag and no limits (the bare system of eq. 12)."""
        return cls(order=0, p_min_pa=-math.inf, p_max_pa=math.inf)

    def transfer_function(self):
        """(num, den) of p_c/p_cmd in s (rad/s), unsaturated."""
        if self.order == 0:
            return np.array([1.0]), np.array([1.0])
        if self.order == 1:
            return np.array([1.0]), np.array([self.time_constant_s, 1.0])
        w = hz_to_rad_s(self.natural_frequency_hz)
        return np.array([w * w]), np.array([1.0, 2 * self.damping * w, w * w])

    def statespace(self):
        """(A, B, C) of the unsaturated lag, states [p] or [p, ṗ] (as integrated)."""
        if self.order == 0:
            return np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0))
        if self.order == 1:
            tau = self.time_constant_s
            return np.array([[-1 / tau]]), np.array([[1 / tau]]), np.array([[1.0]])
        w = hz_to_rad_s(self.natural_frequency_hz)
        return (np.array([[0.0, 1.0], [-w * w, -2 * self.damping * w]]),
                np.array([[0.0], [w * w]]), np.array([[1.0, 0.0]]))

    def to_core(self):
        a = _core.Actuator()
        a.order = int(self.order)
        a.time_constant = float(self.time_constant_s)
        a.natural_frequency = hz_to_rad_s(float(self.natural_frequency_hz))
        a.damping = float(self.damping)
        a.p_min, a.p_max = float(self.p_min_pa), float(self.p_max_pa)
        a.rate_limit = float(self.rate_limit_pa_s)
        return a
