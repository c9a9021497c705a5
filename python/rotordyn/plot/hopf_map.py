"""The stability boundary of a ``hopf`` sweep with each point coloured by its Hopf type
(paper Fig. 9/10 with the criticality of the boundary: issue 19); from a ``limit_cycle``
sweep also the bistable region (a stable limit cycle beside the linearly stable
equilibrium) shaded, with contours of the largest stable cycle's amplitude, or, for a
single line, the bifurcation diagram of its cycles with the bistable interval shaded."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rotordyn.plot.maps import axis_label, axis_scale, select, sweep_axes

if TYPE_CHECKING:
    import pandas as pd

COLOURS = {"supercritical": "tab:blue", "subcritical": "tab:red", "degenerate": "tab:gray"}
LABELS = {"supercritical": "supercritical (soft onset)",
          "subcritical": "subcritical (hard onset, hysteresis)",
          "degenerate": "type not resolved (|l1| < 3 × its error)"}


def hopf_map(df: pd.DataFrame, ax=None, where=None, amplitude_contours: bool = True):
    """Rows of a ``hopf`` sweep: the threshold value of the varied axis against the other
    varying axis, a marker per crossing coloured by ``hopf_type``; crossings whose l1
    failed are black crosses. Rows of a ``limit_cycle`` sweep (``record`` hopf/cycle): the
    same boundary from its hopf rows, the grid cells of bistable points shaded and (with
    ``amplitude_contours``) contours of the largest stable cycle's amplitude / c; a sweep of
    one line: :func:`cycle_diagram`. ``where``: values of further varying axes to fix."""
    import matplotlib.pyplot as plt

    if "hopf_type" not in df:
        from rotordyn.errors import InputError

        raise InputError("--kind hopf-map: expected the rows of a 'hopf' or 'limit_cycle' "
                         "sweep (no hopf_type column)")
    df = select(df, where, "hopf-map") if where else df
    cycles = None
    if "record" in df:
        cycles = df[df["record"] == "cycle"]
        df = df[df["record"] == "hopf"]
        vary = next(c for c in ("chamber_pressure_pa", "speed_hz", "config_ay_m")
                    if c in df and "i_" + c in df and df["i_" + c].isna().all())
        if not [a for a in sweep_axes(cycles) if a != vary and cycles[a].nunique() > 1]:
            return cycle_diagram(cycles, vary, df, ax=ax)
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
    if cycles is not None:
        _bistable_cells(ax, cycles, along, vary, sx, sy, amplitude_contours)
    ax.set_xlabel(axis_label(along))
    ax.set_ylabel(axis_label(vary))
    ax.set_title("stability boundary, Hopf type" + (" and bistable region" if cycles
                                                    is not None else ""))
    ax.legend(fontsize=7)
    return ax


def _edges(v: np.ndarray) -> np.ndarray:
    """Cell edges around sorted grid values (midpoints; the ends half a step out)."""
    if v.size == 1:
        return np.array([v[0] - 0.5, v[0] + 0.5]) if v[0] == 0 else v[0] * np.array([0.99, 1.01])
    mid = 0.5 * (v[1:] + v[:-1])
    return np.concatenate([[2 * v[0] - mid[0]], mid, [2 * v[-1] - mid[-1]]])


def _bistable_cells(ax, cycles, along, vary, sx, sy, contours):
    """Shade the grid cells of bistable points; contours of the largest stable amplitude."""
    per = cycles.assign(_b=cycles["bistable"].fillna(False).astype(float),
                        _a=np.where(cycles["stable"].fillna(False).astype(bool)
                                    & (cycles["status"] == "ok"),
                                    cycles["amplitude_c"].astype(float), np.nan))
    B = per.pivot_table(index=vary, columns=along, values="_b", aggfunc="max", dropna=False)
    xs, ys = B.columns.to_numpy(float), B.index.to_numpy(float)
    Z = np.ma.masked_less(B.to_numpy(float), 0.5)
    n_bi = int(Z.count())
    if Z.count():
        ax.pcolormesh(_edges(xs) * sx, _edges(ys) * sy, Z, cmap="Oranges", vmin=0, vmax=1.6,
                      alpha=0.55, zorder=0, shading="flat")
    ax.scatter([], [], marker="s", color="tab:orange", alpha=0.55,
               label=f"bistable (stable equilibrium and stable cycle): {n_bi} points")
    if contours and xs.size >= 2 and ys.size >= 2:
        A = per.pivot_table(index=vary, columns=along, values="_a", aggfunc="max",
                            dropna=False).reindex(index=ys, columns=xs).to_numpy(float)
        if np.isfinite(A).sum() >= 4 and np.nanmax(A) > np.nanmin(A):
            cs = ax.contour(xs * sx, ys * sy, A, levels=6, colors="0.35", linewidths=0.7,
                            zorder=1)
            ax.clabel(cs, fmt="%.2g c", fontsize=6)


def cycle_diagram(cycles: pd.DataFrame, vary: str, hopf_rows=None, ax=None):
    """Cycles of a one-line ``limit_cycle`` sweep: the amplitude / c of each cycle against
    the varied axis (stable filled, unstable hollow), the Hopf points on the axis coloured by
    type, the equilibrium's unstable values as a bar, the bistable interval shaded."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 4.6))
    s = axis_scale(vary)
    ok = cycles[cycles["status"] == "ok"]
    st = ok["stable"].astype(bool)
    ax.scatter(ok.loc[st, vary] * s, ok.loc[st, "amplitude_c"], color="k", s=16,
               label="stable cycle", zorder=3)
    ax.scatter(ok.loc[~st, vary] * s, ok.loc[~st, "amplitude_c"], facecolors="none",
               edgecolors="k", s=16, label="unstable cycle", zorder=3)
    pts = cycles.drop_duplicates("point_id").sort_values(vary)
    x = pts[vary].to_numpy(float)
    bi = pts["bistable"].fillna(False).astype(bool).to_numpy()
    unst = (pts["equilibrium_stable"] == False).to_numpy()  # noqa: E712 (nullable)
    e = _edges(x)
    for k in np.flatnonzero(bi):
        ax.axvspan(e[k] * s, e[k + 1] * s, color="tab:orange", alpha=0.3, lw=0,
                   label="bistable" if k == np.flatnonzero(bi)[0] else None)
    if unst.any():
        ax.plot(x[unst] * s, np.zeros(unst.sum()), "s", color="tab:red", ms=3,
                label="equilibrium unstable")
    if hopf_rows is not None:
        for kind, colour in COLOURS.items():
            g = hopf_rows[(hopf_rows["status"] == "ok") & (hopf_rows["hopf_type"] == kind)]
            if len(g):
                ax.scatter(g["value"] * s, np.zeros(len(g)), marker="D", color=colour, s=30,
                           zorder=4, label=f"Hopf point, {LABELS[kind]}")
    ax.set_xlabel(axis_label(vary))
    ax.set_ylabel("cycle amplitude / clearance")
    ax.set_title("limit cycles along the line and the bistable interval")
    ax.legend(fontsize=7)
    return ax
