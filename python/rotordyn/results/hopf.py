"""A Hopf point of the stability boundary: the crossing, the whirl frequency, the first
Lyapunov coefficient, the type and the leading-order amplitude of the bifurcating cycle."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display
from rotordyn.results.continuation import parameter_units

if TYPE_CHECKING:
    import pandas as pd

HOPF_TYPES = ("supercritical", "subcritical", "degenerate")


@dataclass(frozen=True)
class HopfResult(Display):
    """``value``: the Hopf point in ``vary`` (Pa, Hz or m); ``whirl_frequency_hz``: ω/2π of
    the crossing pair ±iω; ``l1``: the first Lyapunov coefficient (1/s, in the scaled
    coordinates x̃ = (r/L, ṙ/(L·velocity_scale)) with ⟨q, q⟩ = 1; its sign is coordinate-
    free), ``l1_error`` its finite-difference error estimate; ``type``: supercritical
    (l1 < 0), subcritical (l1 > 0) or degenerate (sign not resolved); ``alpha_prime``:
    dRe λ/d(vary) (1/s per unit); ``stable_side``: where the equilibrium is stable;
    ``cycle_side``: where the bifurcating cycles are (the unstable side for supercritical,
    the stable side for subcritical); ``amplitude_coefficient`` (n_bearings,): m² per unit
    of vary, A_j² = coefficient·|p − p_H| to leading order (A_j the largest distance of
    journal j from its mean); ``q`` (2n,) the critical eigenvector in SI state coordinates
    (r, ṙ) with ``z2_per_unit``: |z|² per unit |p − p_H|; ``x_equilibrium`` (2n,);
    ``l1_refined``: l1 on the films' grids refined twice (``grid_check``; then ``l1_error``
    includes |l1_refined − l1|)."""

    vary: str
    fixed: dict
    fd_step: float
    bearing_names: tuple
    clearance_m: np.ndarray
    value: float = math.nan
    whirl_frequency_hz: float = math.nan
    speed_hz: float = math.nan
    l1: float = math.nan
    l1_error: float = math.nan
    type: str = ""
    alpha_prime: float = math.nan
    real_part: float = math.nan
    stable_side: str = ""
    cycle_side: str = ""
    amplitude_coefficient: np.ndarray = field(default_factory=lambda: np.zeros(0))
    z2_per_unit: float = math.nan
    q: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=complex))
    x_equilibrium: np.ndarray = field(default_factory=lambda: np.zeros(0))
    length_scale_m: float = math.nan
    velocity_scale: float = math.nan
    status: str = "ok"
    message: str = ""
    # grid_check: l1 on every film grid refined twice in both directions (NaN: not checked)
    l1_refined: float = math.nan

    @classmethod
    def failed(cls, status: str, message: str, **kw) -> "HopfResult":
        return cls(status=status, message=message, **kw)

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    @property
    def supercritical(self) -> bool:
        return self.type == "supercritical"

    def amplitude(self, value: float, bearing: int = 0) -> float:
        """Leading-order cycle amplitude at journal ``bearing`` (m) at ``value`` of vary;
        NaN on the side without cycles."""
        dp = float(value) - self.value
        if not self.ok or (dp > 0) != (self.cycle_side == "above"):
            return math.nan
        return float(math.sqrt(self.amplitude_coefficient[bearing] * abs(dp)))

    def cycle_state(self, value: float, phase_rad: float = 0.0) -> tuple[np.ndarray, float]:
        """The leading-order cycle at ``value``: the state x = x_e + 2 Re(z q e^{iφ}) (2n,)
        in SI and the period 2π/ω (s) — a start for :func:`rotordyn.periodic_orbit`."""
        dp = float(value) - self.value
        if not self.ok or dp == 0 or (dp > 0) != (self.cycle_side == "above"):
            from rotordyn.errors import InputError

            raise InputError(f"value: the cycles are on the {self.cycle_side or '?'} side of "
                             f"the Hopf point {self.value:.6g}, got {value!r}")
        z = math.sqrt(self.z2_per_unit * abs(dp))
        x = self.x_equilibrium + 2 * np.real(z * self.q * np.exp(1j * phase_rad))
        return x, 1.0 / self.whirl_frequency_hz

    def __repr__(self) -> str:
        if not self.ok:
            return f"<HopfResult {self.status}: {self.vary}; {self.message}>"
        unit, sym, f, u2 = parameter_units(self.vary)
        amp = ", ".join(f"{math.sqrt(c * abs(self.value) * 0.01) * 1e6:.3g} µm"
                        for c in self.amplitude_coefficient) if self.value else ""
        return (f"<HopfResult ok: {self.type} Hopf point at {sym} = {self.value * f:.6g} {u2}, "
                f"whirl {self.whirl_frequency_hz:.5g} Hz, l1 = {self.l1:.4g} ± "
                f"{self.l1_error:.2g} 1/s, dReλ/d{sym} = {self.alpha_prime:.4g}; "
                + (f"cycles {self.cycle_side} ({'stable' if self.supercritical else 'unstable'})"
                   if self.type != "degenerate" else
                   f"cycles {self.cycle_side} by l1's sign, their side and stability not "
                   "resolved")
                + (f", amplitude at 1 % from the point: {amp}" if amp else "")
                + (f"; grid check: l1 = {self.l1_refined:.4g} on the refined films"
                   if math.isfinite(self.l1_refined) else "")
                + (f"; {self.message}" if self.message else "") + ">")

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd
        rows = []
        for i, name in enumerate(self.bearing_names):
            row = {self.vary: self.value, **{k: val for k, val in self.fixed.items()
                                             if val is not None},
                   "bearing": name, "whirl_frequency_hz": self.whirl_frequency_hz,
                   "l1": self.l1, "l1_error": self.l1_error, "l1_refined": self.l1_refined,
                   "type": self.type, "alpha_prime": self.alpha_prime,
                   "stable_side": self.stable_side,
                   "cycle_side": self.cycle_side,
                   "amplitude_coefficient_m2": (float(self.amplitude_coefficient[i])
                                                if self.ok else math.nan),
                   "clearance_m": float(self.clearance_m[i]), "status": self.status,
                   "message": self.message}
            rows.append(row)
        return pd.DataFrame(rows)

    def plot(self, ax=None, span: float | None = None, bearing: int = 0, branch=None):
        """Leading-order bifurcation diagram: journal amplitude against vary (the
        equilibrium solid where stable, dashed where unstable; the cycle solid if stable
        (supercritical), dashed if not), with an optional :class:`BranchResult` ``branch``
        drawn as points for comparison. ``span``: the width shown (default 5 % of |value|)."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 4))
        unit, sym, f, u2 = parameter_units(self.vary)
        if not self.ok:
            ax.set_title(f"Hopf: {self.status}")
            return ax
        span = span or 0.05 * abs(self.value) or 1.0
        sgn = 1 if self.cycle_side == "above" else -1
        p = self.value + sgn * np.linspace(0, span, 100)
        amp = np.sqrt(self.amplitude_coefficient[bearing] * np.abs(p - self.value))
        c = self.clearance_m[bearing]
        st = "-" if self.supercritical else "--"
        ax.plot(p * f, amp / c, "C0" + st, label=f"cycle, leading order ({self.type})")
        eq_st = self.value + np.array([0, -sgn * span]) if self.supercritical else \
            self.value + np.array([0, sgn * span])
        ax.plot(np.sort(eq_st) * f, [0, 0], "k-", label="equilibrium (stable)")
        other = self.value + np.array([0, sgn * span]) if self.supercritical else \
            self.value + np.array([0, -sgn * span])
        ax.plot(np.sort(other) * f, [0, 0], "k--", label="equilibrium (unstable)")
        ax.plot([self.value * f], [0], "ro", label="Hopf point")
        if branch is not None:
            ax.plot(np.asarray(branch.parameter) * f,
                    np.asarray(branch.amplitude_m)[:, bearing] / c, "C1o", ms=4,
                    label="continued branch")
        ax.set_xlabel(f"{sym} ({u2})")
        ax.set_ylabel(f"amplitude / c ({self.bearing_names[bearing]})")
        ax.legend(fontsize=8)
        return ax
