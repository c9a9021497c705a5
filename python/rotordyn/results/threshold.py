"""Stability thresholds (where the least-damped eigenvalue crosses the imaginary axis) and
stability boundaries traced across a second parameter (paper Fig. 9, Fig. 10)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class ThresholdResult(Display):
    """``value`` of ``vary`` at which max Re λ = 0 (to ``xtol``), with the whirl frequency
    of the crossing mode. ``stable_side``: "above" or "below" the threshold. ``status``:
    "ok", "no_crossing" (no sign change in ``bounds``: ``value`` is NaN) or "error".
    ``crossings``: every sign change found by the scan, refined (``value`` is the first).
    ``scan``: the bracketing scan (vary value, ``max_real_1_per_s`` the raw max Re λ,
    ``verdict_real_1_per_s`` the function bracketed (its sign the verdict,
    :func:`rotordyn.results.modes.verdict_real`), ``stable`` the point's verdict (NA at a
    failed point), ``freq_hz``, ``status``)."""

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
        if self.status != "ok" and self.message:  # no crossing: say which side the scan saw
            return (f"<ThresholdResult {self.status}: {self.message}; "
                    f"{self.evaluations} evaluations>")
        return (f"<ThresholdResult {self.status}: {self.vary} = {self.value:.6g} (stable "
                f"{self.stable_side or '?'}), whirl {self.whirl_frequency_hz:.4g} Hz "
                f"(ratio {self.whirl_ratio:.3g}); {len(self.crossings)} crossings in "
                f"{tuple(self.bounds)}, {self.evaluations} evaluations>")

    def to_frame(self) -> pd.DataFrame:
        # fixed inputs that apply: config_ay_m is None (and p_c moot) without an active bearing
        import pandas as pd
        row = {k: val for k, val in self.fixed.items() if val is not None}
        if self.fixed.get("config_ay_m", 0.0) is None:
            row.pop("chamber_pressure_pa", None)
        row.update({"vary": self.vary, self.vary: self.value,
                    "whirl_frequency_hz": self.whirl_frequency_hz,
                    "whirl_ratio": self.whirl_ratio, "stable_side": self.stable_side,
                    "evaluations": self.evaluations, "status": self.status,
                    "message": self.message})
        return pd.DataFrame([row])

    def plot(self, ax=None):
        """The scan: largest real part (1/s) against the varied input, the threshold and
        every crossing marked, the unstable side hatched."""
        from matplotlib.lines import Line2D
        from matplotlib.patches import Patch

        from rotordyn.plot._style import COLUMN_IN, new_axes, paper_style
        from rotordyn.plot.maps import axis_label, axis_scale

        @paper_style
        def draw(ax):
            ax = new_axes(ax, width=COLUMN_IN * 1.2)
            k = axis_scale(self.vary)
            col = "max_real_1_per_s"
            sc = self.scan[np.isfinite(self.scan[col])]
            x, y = sc[self.vary].to_numpy() * k, sc[col].to_numpy()
            ax.plot(x, y, "o-", color="tab:blue", ms=3)
            ax.axhline(0, color="k", lw=0.6)
            # hatched where the point's verdict is unstable (not Re λ's round-off sign)
            bad = (sc["verdict_real_1_per_s"].to_numpy() > 0 if "verdict_real_1_per_s" in sc
                   else y > 0)
            ax.fill_between(x, 0, np.where(bad, np.maximum(y, 0), 0), facecolor="none",
                            edgecolor="tab:red", hatch="////", lw=0)
            for c in self.crossings:
                ax.axvline(c * k, color="k", ls="--", lw=0.8)
            h = [Line2D([], [], color="tab:blue", marker="o", ms=3,
                        label="largest real part of the eigenvalues"),
                 Patch(facecolor="none", edgecolor="tab:red", hatch="////",
                       label="unstable (Re λ > 0)")]
            if self.crossings:
                h.append(Line2D([], [], color="k", ls="--", lw=0.8,
                                label=f"threshold {self.value * k:.4g}"))
            ax.set_xlabel(axis_label(self.vary))
            ax.set_ylabel("max Re λ (1/s)")
            ax.legend(handles=h, loc="best")
            return ax

        return draw(ax)


@dataclass(frozen=True)
class BoundaryResult(Display):
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
        """The boundary curve with the unstable side hatched (:func:`rotordyn.plot.boundary_curve`)."""
        from rotordyn.plot.maps import boundary_curve

        return boundary_curve(self, ax=ax)
