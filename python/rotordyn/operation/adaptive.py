"""The adaptive 1× unbalance-rejection law as it runs in the transient's CVODE loop
(:class:`AdaptiveRejection`): its influence-coefficient table over speed, gain and the C++
description. The law, its sources and its design: :mod:`rotordyn.control.adaptive`."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.operation.measurement import parse_measurements

MAX_GAIN_1_PER_S = 1e4
MAX_LEAK_1_PER_S = 1e4
#: the washout corner's largest ratio to the lowest 1× frequency of a run (k Ω_min / 2π)
MAX_WASHOUT_RATIO = 0.25


def _rate(name: str, value, hi: float, meaning: str) -> float:
    """An adaptation rate ``adaptive.<name>``: finite, in [0, hi] 1/s."""
    try:
        return v.in_range(f"adaptive.{name}", value, 0.0, hi)
    except InputError as exc:
        raise InputError(f"{exc} ({meaning})") from None


def _gain(value) -> float:
    """The adaptation gain γ: finite, in [0, 1e4] 1/s."""
    return _rate("gain_1_per_s", value, MAX_GAIN_1_PER_S,
                 "the adaptation rate γ of the 1× coefficients, 1/s; 0: frozen")


def _leak(value) -> float:
    """The leak σ: finite, in [0, 1e4] 1/s."""
    return _rate("leak_1_per_s", value, MAX_LEAK_1_PER_S,
                 "the leak rate σ of Ṗ = −γ T̂⁺ 2y e^{−iθ} − σ P, 1/s; 0: no leak")


def _washout(value) -> float:
    """The washout corner f_w = ω_w/2π: finite, >= 0 Hz (0: no washout)."""
    f = "adaptive.washout_hz"
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{f}: expected a finite corner frequency >= 0 Hz (0: no washout), "
                         f"got {value!r}") from None
    if not (math.isfinite(x) and x >= 0.0):
        raise InputError(f"{f}: expected a finite corner frequency >= 0 Hz (0: no washout), "
                         f"got {value!r}")
    return x


def _is_scalar(value) -> bool:
    return value is None or isinstance(value, (str, bytes, int, float, np.number)) \
        or np.ndim(value) == 0


def _gain_schedule(value, grid_hz: np.ndarray):
    """γ as a number (float) or a schedule over the speed ((speeds_hz, gains) arrays): a
    sequence on the T̂ grid ``grid_hz``, a pair (speeds_hz, gains) on its own grid, or a
    callable of the speed in Hz evaluated on the T̂ grid."""
    f = "adaptive.gain_1_per_s"
    if _is_scalar(value):
        return _gain(value)
    if callable(value):
        try:
            value = [value(float(x)) for x in grid_hz]
        except InputError:
            raise
        except Exception as exc:  # a user's function failing is bad input
            raise InputError(f"{f}: the gain function failed on the T̂ grid: {exc}") from None
    if (isinstance(value, (tuple, list)) and len(value) == 2
            and all(not _is_scalar(x) for x in value)):
        sp = v.vector(f + " (speeds_hz)", value[0])
        g = v.vector(f + " (gains)", value[1], sp.size)
        if sp.size < 1 or np.any(np.diff(sp) <= 0) or np.any(sp < 0):
            raise InputError(f"{f}: expected strictly increasing schedule speeds >= 0 Hz, "
                             f"got {sp!r}")
    else:
        try:
            g = v.vector(f, value, grid_hz.size)
        except InputError as exc:
            raise InputError(f"{exc} (a schedule given as a sequence lies on the T̂ grid "
                             f"adaptive.speeds_hz, {grid_hz.size} speeds)") from None
        sp = grid_hz.copy()
    if np.any(g < 0) or np.any(g > MAX_GAIN_1_PER_S):
        raise InputError(f"{f}: expected gains in [0, {MAX_GAIN_1_PER_S:g}] 1/s, got "
                         f"{g.min():g}–{g.max():g}")
    return sp, g


@dataclass(frozen=True)
class AdaptiveRejection:
    """The adaptive 1× command (module docstring). ``speeds_hz`` (n_g,) strictly increasing;
    ``influence`` (n_g, n_y) complex T(Ω) (m/Pa or m/s/Pa per measurement); ``gain_1_per_s``
    γ (1/s): a number, or a schedule γ(Ω) — a sequence on the T̂ grid, a pair
    (speeds_hz, gains) on its own grid, or a callable of the speed in Hz (kept as the pair);
    interpolated piecewise linearly at Ω(t) in the right-hand side; ``p0_pa`` the complex
    coefficient at t = 0; ``order`` the harmonic (1: 1×); ``leak_1_per_s`` σ of the leak −σ P;
    ``freeze_at_limits``: the gradient term off while the command is outside the valve's
    limits (the leak stays); ``washout_hz`` f_w (Hz, >= 0; 0: none): a first-order washout
    H(s) = s/(s + ω_w), ω_w = 2π f_w, on each measurement before the demodulation, the
    update compensated by 1/H(ikΩ) (:mod:`rotordyn.control.adaptive`); a run needs
    f_w <= ``MAX_WASHOUT_RATIO`` · k · f_min (the corner well below the 1×)."""

    measurements: tuple
    speeds_hz: np.ndarray
    influence: np.ndarray
    gain_1_per_s: object
    p0_pa: complex = 0j
    order: float = 1.0
    leak_1_per_s: float = 0.0
    freeze_at_limits: bool = False
    washout_hz: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "measurements", parse_measurements(self.measurements))
        sp = v.vector("adaptive.speeds_hz", self.speeds_hz)
        if sp.size < 1 or np.any(np.diff(sp) <= 0) or np.any(sp < 0):
            raise InputError(f"adaptive.speeds_hz: expected strictly increasing speeds >= 0 "
                             f"Hz, got {sp!r}")
        T = np.asarray(self.influence, dtype=complex)
        if T.ndim == 1:
            T = T[:, None] if sp.size > 1 or T.size == 1 else T[None, :]
        if T.shape[0] != sp.size or T.ndim != 2:
            raise InputError(f"adaptive.influence: expected shape ({sp.size}, n_y), got "
                             f"{np.shape(self.influence)}")
        if not np.all(np.isfinite(T)) or np.any(np.sum(np.abs(T) ** 2, axis=1) == 0):
            raise InputError("adaptive.influence: expected finite coefficients, not all 0 at "
                             "any speed")
        object.__setattr__(self, "speeds_hz", sp)
        object.__setattr__(self, "influence", T)
        object.__setattr__(self, "gain_1_per_s", _gain_schedule(self.gain_1_per_s, sp))
        object.__setattr__(self, "leak_1_per_s", _leak(self.leak_1_per_s))
        object.__setattr__(self, "freeze_at_limits",
                           v.boolean("adaptive.freeze_at_limits", self.freeze_at_limits))
        object.__setattr__(self, "washout_hz", _washout(self.washout_hz))
        p0 = complex(self.p0_pa)
        if not (math.isfinite(p0.real) and math.isfinite(p0.imag)):
            raise InputError(f"adaptive.p0_pa: expected a finite complex Pa, got {p0!r}")
        object.__setattr__(self, "p0_pa", p0)
        object.__setattr__(self, "order", v.in_range("adaptive.order", self.order, 0.0, 100.0,
                                                     lo_open=True))

    @property
    def scheduled(self) -> bool:
        """True when γ is a schedule over the speed."""
        return not isinstance(self.gain_1_per_s, float)

    def gain_at(self, speed_hz) -> np.ndarray:
        """γ(Ω) (1/s) at the speeds, as the right-hand side interpolates it."""
        f = np.asarray(speed_hz, dtype=float)
        if not self.scheduled:
            return np.full(f.shape, self.gain_1_per_s)
        sp, g = self.gain_1_per_s
        return np.interp(f, sp, g)

    @property
    def update(self) -> np.ndarray:
        """T⁺ = Tᴴ/(Tᴴ T) per speed, (n_g, n_y) complex."""
        T = self.influence
        return T.conj() / np.sum(np.abs(T) ** 2, axis=1, keepdims=True)

    def optimum(self, response_m) -> complex:
        """P* = −T⁺ Y_u at one grid speed: ``response_m`` (n_y,) complex 1× response without
        the command (single grid speed only)."""
        if self.speeds_hz.size != 1:
            raise InputError("adaptive: optimum() needs a single-speed law")
        Y = np.asarray(response_m, dtype=complex).ravel()
        return complex(-(self.update[0] @ Y))

    def check_covers(self, lo_hz: float, hi_hz: float) -> None:
        x = self.speeds_hz
        tol = 1e-9 * max(abs(x[-1]), 1.0)
        if x.size > 1 and (lo_hz < x[0] - tol or hi_hz > x[-1] + tol):
            raise InputError(f"adaptive.speeds_hz: the grid {x[0]:g}–{x[-1]:g} Hz does not "
                             f"cover the run's speeds {lo_hz:g}–{hi_hz:g} Hz")
        if x.size == 1 and (abs(lo_hz - x[0]) > tol or abs(hi_hz - x[0]) > tol):
            raise InputError(f"adaptive.speeds_hz: a single-speed law ({x[0]:g} Hz) runs at "
                             f"that speed only, got {lo_hz:g}–{hi_hz:g} Hz")
        kf = self.order * max(lo_hz, 0.0)
        if self.washout_hz > MAX_WASHOUT_RATIO * kf:
            raise InputError(f"adaptive.washout_hz: expected a corner <= {MAX_WASHOUT_RATIO:g} "
                             f"x the lowest {self.order:g}x frequency of the run "
                             f"({kf:g} Hz), got {self.washout_hz:g} Hz")
        if self.scheduled:
            g = self.gain_1_per_s[0]
            tol = 1e-9 * max(abs(g[-1]), 1.0)
            if lo_hz < g[0] - tol or hi_hz > g[-1] + tol:
                raise InputError(f"adaptive.gain_1_per_s: the gain schedule's speeds "
                                 f"{g[0]:g}–{g[-1]:g} Hz do not cover the run's speeds "
                                 f"{lo_hz:g}–{hi_hz:g} Hz")

    def with_gain(self, gain_1_per_s) -> "AdaptiveRejection":
        return AdaptiveRejection(self.measurements, self.speeds_hz, self.influence,
                                 gain_1_per_s, self.p0_pa, self.order, self.leak_1_per_s,
                                 self.freeze_at_limits, self.washout_hz)

    def to_core(self, Cm: np.ndarray, offset: np.ndarray):
        ny = Cm.shape[0]
        if ny != self.influence.shape[1]:
            raise InputError(f"adaptive.influence: expected {ny} columns (the measurements "
                             f"{list(self.measurements)}), got {self.influence.shape[1]}")
        h = _core.AdaptiveHarmonic()
        h.enabled = True
        h.order = float(self.order)
        if self.scheduled:
            sp, g = self.gain_1_per_s
            h.gain = float(g.max())
            h.gain_omega = 2 * np.pi * sp
            h.gain_table = np.asarray(g, dtype=float)
        else:
            h.gain = float(self.gain_1_per_s)
        if self.leak_1_per_s != 0.0:
            h.leak = float(self.leak_1_per_s)
        if self.freeze_at_limits:
            h.freeze_saturated = True
        if self.washout_hz != 0.0:
            h.washout = 2 * np.pi * self.washout_hz
        h.measurement = Cm
        h.offset = np.asarray(offset, dtype=float)
        h.table_omega = 2 * np.pi * self.speeds_hz
        G = self.update
        h.table_re, h.table_im = np.ascontiguousarray(G.real), np.ascontiguousarray(G.imag)
        h.p0_re, h.p0_im = self.p0_pa.real, self.p0_pa.imag
        return h


__all__ = ["AdaptiveRejection", "MAX_GAIN_1_PER_S", "MAX_LEAK_1_PER_S", "MAX_WASHOUT_RATIO"]
