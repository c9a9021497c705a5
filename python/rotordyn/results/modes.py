"""Modal results: eigenvalues, damped natural frequencies, damping, whirl, mode shapes."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn import _core
from rotordyn.results._display import Display

from rotordyn._common.whirl import (  # noqa: F401 - the modal results' vocabulary
    WHIRL_NAMES, WHIRL_PLANAR_TOL, whirl_index, whirl_label)

if TYPE_CHECKING:
    import pandas as pd


def _freq_list(f, whirl=None, n: int = 6) -> str:
    items = [f"{x:.4g}" + (f" {str(w)[0]}" if whirl is not None else "")
             for x, w in zip(f[:n], whirl[:n] if whirl is not None else [None] * n)]
    return ", ".join(items) + (", …" if len(f) > n else "")


ROUND_OFF_REL = float(_core.ROUND_OFF_REL)
"""Real parts within ±1e-9 max(|λ|, 1) of zero are round-off of an undamped mode: they count as
zero damping (log dec 0, ζ 0) and as stable, never as a sign (issue 18: δ = −4e-12 read as
unstable by a filter on the sign). The constant is the C++ core's (``kRoundOffRel`` in
modal.hpp), so the C++ verdicts (the stability batch's least stable root, the root picker,
the unbalance sweep's max Re λ) and the Python ones (:func:`mode_stable`,
:func:`point_stable`: ``StabilityResult.stable``, every sweep row's ``mode_stable`` and
``point_stable``) share one band."""


def settled_real(eigenvalues: np.ndarray) -> np.ndarray:
    """Re λ with the round-off band (:data:`ROUND_OFF_REL`) set to exactly 0."""
    lam = np.asarray(eigenvalues)
    re = lam.real
    return np.where(np.abs(re) < ROUND_OFF_REL * np.maximum(np.abs(lam), 1.0), 0.0, re)


def mode_stable(eigenvalues: np.ndarray) -> np.ndarray:
    """Per mode: Re λ below the round-off band (an undamped mode is marginally stable)."""
    return settled_real(eigenvalues) <= 0.0


def point_stable(eigenvalues: np.ndarray) -> bool:
    """The point's verdict: every root :func:`mode_stable` (no root: True). The one rule of
    ``StabilityResult.stable`` and of every sweep row's ``point_stable``."""
    return bool(np.all(mode_stable(np.asarray(eigenvalues))))


def verdict_real(eigenvalues: np.ndarray) -> float:
    """The threshold's function of a point's roots: max Re λ where the point is unstable
    (:func:`point_stable` False) or max Re λ < 0, else −ROUND_OFF_REL·max(|λ|, 1) of the
    deciding root (a stable max Re λ in the round-off band is 0, never a sign). Its sign is
    the verdict's and it is never 0, so a bracket and Brent's method on it find where the
    verdict flips; away from the band it is max Re λ itself. The C++ threshold line's rule
    (cpp/src/threshold.cpp)."""
    lam = np.asarray(eigenvalues)
    i = int(np.argmax(lam.real))
    y = float(lam[i].real)
    if not point_stable(lam) or y < 0:
        return y
    return -ROUND_OFF_REL * max(float(abs(lam[i])), 1.0)


def damping_ratio(eigenvalues: np.ndarray) -> np.ndarray:
    """ζ = −Re λ / |λ| (0 for λ = 0 and within the round-off band of Re λ = 0; NaN for a NaN
    eigenvalue: a failed point's slot has no damping)."""
    mag = np.abs(eigenvalues)
    z = np.where(mag > 0, -settled_real(eigenvalues) / np.where(mag > 0, mag, 1.0), 0.0)
    return np.where(np.isnan(mag), np.nan, z)


def log_dec(eigenvalues: np.ndarray) -> np.ndarray:
    """Logarithmic decrement δ = −2π Re λ / Im λ (for a non-oscillating root +inf when it
    decays, −inf when it grows: a divergence; 0 within the round-off band of Re λ = 0, +0 never
    −0: tables printed "-0"; NaN for a NaN eigenvalue)."""
    lam = np.asarray(eigenvalues)
    im = lam.imag
    re = settled_real(lam)
    d = np.where(im > 0, -2 * np.pi * re / np.where(im > 0, im, 1.0),
                 np.where(re > 0, -np.inf, np.where(re < 0, np.inf, 0.0)))  # neutral real: 0
    return np.where(np.isnan(lam), np.nan, d) + 0.0


@dataclass(frozen=True)
class ModesResult(Display):
    """Eigen-analysis of the rotor at one speed (paper eq. 19 without excitation).

    eigenvalues: (n_modes,) complex, 1/s, λ = σ + iω_d with ω_d ≥ 0, ascending in ω_d.
    whirl: (n_modes,) ``"forward"``/``"backward"``/``"planar"``.
    shapes: (n_nodes, 4, n_modes) complex mode shapes at every FE node, DOF (x, y, θx, θy).
    node_positions_m: (n_nodes,) axial node positions.
    full: the full model's result when this one is reduced, else None.
    """

    speed_hz: float
    model: str  # "full" or the reduction method
    eigenvalues: np.ndarray
    whirl: np.ndarray
    shapes: np.ndarray
    node_positions_m: np.ndarray
    full: "ModesResult | None" = None
    status: str = "ok"
    message: str = ""
    extra: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        return (f"<ModesResult {self.model} model at {self.speed_hz:g} Hz, "
                f"{len(self.eigenvalues)} modes (Hz; f/b/p = forward/backward/planar): "
                f"{_freq_list(self.frequencies_hz, self.whirl)}"
                + (f"; status {self.status}" if self.status != "ok" else "") + ">")

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Damped natural frequencies ω_d/2π, Hz, ascending."""
        return self.eigenvalues.imag / (2 * np.pi)

    @property
    def natural_frequencies_hz(self) -> np.ndarray:
        """Undamped-equivalent natural frequencies |λ|/2π, Hz."""
        return np.abs(self.eigenvalues) / (2 * np.pi)

    @property
    def damping_ratio(self) -> np.ndarray:
        """ζ = −Re λ / |λ|."""
        return damping_ratio(self.eigenvalues)

    @property
    def log_dec(self) -> np.ndarray:
        """Logarithmic decrement δ = −2π Re λ / Im λ."""
        return log_dec(self.eigenvalues)

    def frequency_errors(self) -> np.ndarray:
        """Relative error of each reduced frequency against the full model's same mode number,
        as a fraction (0.004 = 0.4 %; the CLI's JSON ``frequency_errors`` are the same)."""
        if self.full is None:
            from rotordyn.errors import InputError

            raise InputError("frequency_errors: this result is of the full model (reduction "
                             "'none'); ask modes() for a reduced one to compare")
        n = min(len(self.eigenvalues), len(self.full.eigenvalues))
        f, g = self.frequencies_hz[:n], self.full.frequencies_hz[:n]
        return (f - g) / g

    def to_frame(self) -> pd.DataFrame:
        """One row per mode (and per model when reduced): tidy, unit-suffixed columns."""
        import pandas as pd
        frames = [self._frame()]
        if self.full is not None:
            frames.append(self.full._frame())
        return pd.concat(frames, ignore_index=True)

    def _frame(self) -> pd.DataFrame:
        import pandas as pd
        n = len(self.eigenvalues)
        df = pd.DataFrame({
            "model": pd.Categorical([self.model] * n),
            "speed_hz": np.full(n, float(self.speed_hz)),
            "mode": np.arange(1, n + 1, dtype=np.int64),
            "freq_hz": self.frequencies_hz,
            "natural_freq_hz": self.natural_frequencies_hz,
            "eig_real_1_per_s": self.eigenvalues.real,
            "eig_imag_rad_s": self.eigenvalues.imag,
            "damping_ratio": self.damping_ratio,
            "log_dec": self.log_dec,
            "whirl": pd.Categorical(self.whirl, categories=["forward", "backward", "planar"]),
            "status": pd.Categorical([self.status] * n),
            "message": [self.message] * n,
        })
        return df

    def plot(self, modes=None, ax=None, plane: str = "x", *, system=None):
        """Mode shapes. ``modes`` an int: the 3-D whirl orbits of that mode (0-based) along the
        rotor (:func:`rotordyn.plot.mode_shape`; ``system`` adds the rotor outline, disks and
        bearings); a list or None: the real part of the ``plane`` translation of those modes
        along the shaft (:func:`rotordyn.plot.mode_shapes_2d`). Returns the Axes."""
        from rotordyn.plot.shapes import mode_shape, mode_shapes_2d

        if isinstance(modes, (int, np.integer)):
            return mode_shape(self, int(modes), ax=ax, system=system)
        return mode_shapes_2d(self, modes=modes, ax=ax, plane=plane)
