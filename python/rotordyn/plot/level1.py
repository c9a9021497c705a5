"""API 617 Level I figure: the judged forward mode's log decrement against the applied
cross-coupled stiffness Q, with the anticipated Q_A, the Q_0 of zero log decrement and the
δ = 0.1 criterion marked."""

from __future__ import annotations

import numpy as np

from rotordyn.plot._style import COLUMN_IN, new_axes, paper_style


@paper_style
def level1_curve(result, ax=None):
    """Axes of a :class:`rotordyn.results.Level1Result` (Q in MN/m); returns them."""
    ax = new_axes(ax, width=COLUMN_IN * 1.3)
    q = np.asarray(result.q_n_per_m) / 1e6
    ax.plot(q, result.log_dec, color="tab:blue", marker=".", ms=3,
            label=f"δ of the {result.mode_text}")
    ax.axhline(0.0, color="0.4", lw=0.6)
    ax.axhline(0.1, color="tab:red", lw=0.7, ls=":", label="δ = 0.1 (API 617)")
    if np.isfinite(result.q0_n_per_m):
        ax.plot([result.q0_n_per_m / 1e6], [0.0], "o", color="tab:red", mfc="none",
                label=f"Q_0 = {result.q0_n_per_m / 1e6:.4g} MN/m")
    if result.has_stage_data:
        ax.axvline(result.q_a_n_per_m / 1e6, color="tab:green", lw=0.8, ls="--")
        ax.plot([result.q_a_n_per_m / 1e6], [result.log_dec_a], "s", color="tab:green",
                label=f"Q_A = {result.q_a_n_per_m / 1e6:.4g} MN/m, δ_A = "
                      f"{result.log_dec_a:.3g}")
    ax.set_xlabel("applied cross-coupled stiffness Q (MN/m)")
    ax.set_ylabel("log decrement δ (–)")
    ax.set_xlim(0, q.max() if q.size and q.max() > 0 else 1)
    ax.set_title(f"API 617 Level I at {result.speed_hz:.4g} Hz ({60 * result.speed_hz:.0f} rpm)")
    ax.legend(loc="upper right", fontsize=6)
    return ax
