"""Stability thresholds (where the least-damped eigenvalue crosses the imaginary axis) and
stability boundaries traced across a second parameter (paper Fig. 9, Fig. 10)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd


@dataclass(frozen=True)
class ThresholdResult:
    """``value`` of ``vary`` at which max Re λ = 0 (to ``xtol``), with the whirl frequency
    of the crossing mode. ``stable_side``: "above" or "below" the threshold. ``status``:
    "ok", "no_crossing" (no sign change in ``bounds``: ``value`` is NaN) or "error".
    ``crossings``: every sign change found by the scan, refined (``value`` is the first).
    ``scan``: the bracketing scan (vary value, max real part, status)."""

    vary: str
    value: float
    whirl_frequency_hz: float
    whirl_ratio: float
    stable_side: str
    fixed: dict
    bounds: tuple
    xtol: float
    evaluations: int
    scan: pd.DataFrame
    crossings: tuple = ()
    status: str = "ok"
    message: str = ""

    def __repr__(self) -> str:
        return (f"<ThresholdResult {self.status}: {self.vary} = {self.value:.6g} (stable "
                f"{self.stable_side or '?'}), whirl {self.whirl_frequency_hz:.4g} Hz "
                f"(ratio {self.whirl_ratio:.3g}); {len(self.crossings)} crossings in "
                f"{tuple(self.bounds)}, {self.evaluations} evaluations>")

    def to_frame(self) -> pd.DataFrame:
        row = dict(self.fixed)
        row.update({"vary": self.vary, self.vary: self.value,
                    "whirl_frequency_hz": self.whirl_frequency_hz,
                    "whirl_ratio": self.whirl_ratio, "stable_side": self.stable_side,
                    "evaluations": self.evaluations, "status": self.status,
                    "message": self.message})
        return pd.DataFrame([row])


@dataclass(frozen=True)
class BoundaryResult:
    """A stability boundary: the threshold of ``vary`` at each value of ``along``."""

    vary: str
    along: str
    table: pd.DataFrame  # columns: along, vary, whirl_frequency_hz, whirl_ratio, stable_side, status, message

    def __repr__(self) -> str:
        ok = int((self.table["status"] == "ok").sum()) if "status" in self.table else 0
        return (f"<BoundaryResult threshold of {self.vary} along {self.along}: "
                f"{len(self.table)} points, {ok} ok>")

    def to_frame(self) -> pd.DataFrame:
        return self.table.copy()

    def plot(self, ax=None):
        """The boundary curve (stable side shaded lightly)."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 4.5))
        t = self.table[self.table["status"] == "ok"]
        ax.plot(t[self.along], t[self.vary], "o-", label="stability boundary")
        ax.set_xlabel(self.along)
        ax.set_ylabel(self.vary)
        ax.grid(True, alpha=0.3)
        if len(t):
            side = t["stable_side"].iloc[0]
            ax.set_title(f"stable {side} the curve")
        ax.legend()
        return ax
