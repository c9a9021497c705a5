"""The stability boundary of a ``hopf`` sweep with each point coloured by its Hopf type
(paper Fig. 9/10 with the criticality of the boundary: issue 19)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from rotordyn.plot.maps import axis_label, axis_scale, select, sweep_axes

COLOURS = {"supercritical": "tab:blue", "subcritical": "tab:red", "degenerate": "tab:gray"}
LABELS = {"supercritical": "supercritical (soft onset)",
          "subcritical": "subcritical (hard onset, hysteresis)",
          "degenerate": "type not resolved (|l1| < 3 × its error)"}


def hopf_map(df: pd.DataFrame, ax=None, where=None):
    """Rows of a ``hopf`` sweep: the threshold value of the varied axis against the other
    varying axis, a marker per crossing coloured by ``hopf_type``; crossings whose l1
    failed are black crosses. ``where``: values of further varying axes to fix."""
    import matplotlib.pyplot as plt

    if "hopf_type" not in df:
        from rotordyn.errors import InputError

        raise InputError("--kind hopf-map: expected the rows of a 'hopf' sweep (no hopf_type "
                         "column)")
    df = select(df, where, "hopf-map") if where else df
    vary = next(c for c in ("chamber_pressure_pa", "speed_hz", "config_ay_m")
                if c in df and df[c].notna().any() and "i_" + c in df
                and df["i_" + c].isna().all())
    along = [a for a in sweep_axes(df) if a != vary and df[a].nunique() > 1]
    along = along[0] if along else vary
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 4.6))
    sx, sy = axis_scale(along), axis_scale(vary)
    ok = df[df["status"] == "ok"]
    # one polyline per side of the boundary (stable above / below: the upper and lower
    # boundaries of an unstable band), not per crossing number
    for side, g in ok.groupby("stable_side"):
        g = g.sort_values(along)
        ax.plot(g[along] * sx, g["value"] * sy, "-", color="0.75", lw=0.8, zorder=1)
    for kind, colour in COLOURS.items():
        g = ok[ok["hopf_type"] == kind]
        if len(g):
            ax.scatter(g[along] * sx, g["value"] * sy, s=14, color=colour, zorder=2,
                       label=f"{LABELS[kind]}: {len(g)}")
    bad = df[(df["status"] == "error") & np.isfinite(df["value"].astype(float))]
    if len(bad):
        ax.scatter(bad[along] * sx, bad["value"] * sy, marker="x", color="k", s=16,
                   label=f"l1 failed: {len(bad)}")
    ax.set_xlabel(axis_label(along))
    ax.set_ylabel(axis_label(vary))
    ax.set_title("stability boundary and Hopf type")
    ax.legend(fontsize=7)
    return ax
