"""Stability maps over two inputs (paper Fig. 9/10): colour = largest real part of the
eigenvalues with a colour bar in 1/s, the boundary Re λ = 0 drawn, the unstable side hatched,
failed points marked; equilibrium loci in units of the clearance with the clearance circle
(paper Fig. 7/8)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rotordyn.plot._style import COLUMN_IN, new_axes, paper_style, require
from rotordyn.units import split_unit, unit_of

if TYPE_CHECKING:
    import pandas as pd

AXIS_LABEL = {"speed_hz": "rotor speed W (Hz)", "chamber_pressure_pa": "chamber pressure p_c (MPa)",
              "config_ay_m": "housing offset a_y (mm)", "config_ax_m": "housing offset a_x (mm)"}
AXIS_SCALE = {"speed_hz": 1.0, "chamber_pressure_pa": 1e-6, "config_ay_m": 1e3,
              "config_ax_m": 1e3}
AXIS_SHORT = {"speed_hz": ("W", "Hz"), "chamber_pressure_pa": ("p_c", "MPa"),
              "config_ay_m": ("a_y", "mm"), "config_ax_m": ("a_x", "mm")}
OPERATING = ("config_ay_m", "config_ax_m", "speed_hz", "chamber_pressure_pa")
# Other axes (model fields such as ``bearing[0].clearance_m``) are drawn in the unit of their
# suffix, lengths in mm and pressures in MPa as above.
_DISPLAY = {"m": ("mm", 1e3), "Pa": ("MPa", 1e-6)}


def axis_short(name: str) -> tuple[str, str]:
    """(symbol, unit) of an axis as the figures write it."""
    if name in AXIS_SHORT:
        return AXIS_SHORT[name]
    stem, unit = split_unit(name)
    return stem, _DISPLAY.get(unit, (unit, 1.0))[0]


def axis_scale(name: str) -> float:
    """Factor from the column's SI value to the figure's unit."""
    if name in AXIS_SCALE:
        return AXIS_SCALE[name]
    return _DISPLAY.get(unit_of(name), (None, 1.0))[1]


def axis_label(name: str) -> str:
    """Axis label: the operating variables by name, any other axis by its path and unit."""
    if name in AXIS_LABEL:
        return AXIS_LABEL[name]
    sym, unit = axis_short(name)
    return f"{sym} ({unit})" if unit != "1" else sym


def sweep_axes(df: pd.DataFrame) -> list[str]:
    """The grid axes of a sweep dataset, outermost first: every ``i_<axis>`` index column (a
    frame without them: the operating variables present)."""
    axes = [c[2:] for c in df.columns if c.startswith("i_") and c[2:] in df.columns]
    return axes or [c for c in OPERATING if c in df]


def varying(df: pd.DataFrame) -> list[str]:
    """The grid axes that take more than one value."""
    return [c for c in sweep_axes(df) if df[c].nunique() > 1]


def select(df: pd.DataFrame, where: dict | None, what: str) -> pd.DataFrame:
    """The rows at ``where`` = {axis: value} (the grid value nearest each given value); an
    InputError names an axis that is not in the dataset."""
    if not where:
        return df
    axes = sweep_axes(df)
    for a, val in where.items():
        require(a in axes, f"{what}: --where {a}: not an axis of the dataset (axes: {axes})")
        vals = np.sort(df[a].unique())
        near = vals[int(np.argmin(np.abs(vals - float(val))))]
        df = df[df[a] == near]
    return df


@paper_style
def stability_map_grid(x, y, max_real, *, xname, yname, ax=None, failed=None, title=None,
                       limits=None, colorbar=True, legend=True, boundary_field=None):
    """Map of max Re λ (1/s) on the grid ``x`` (n_x,) × ``y`` (n_y,), ``max_real`` (n_x, n_y),
    in the inputs' own units (``xname``/``yname`` are column names such as
    ``chamber_pressure_pa``). ``failed``: (k, 2) points without a result (marked ×).
    ``boundary_field`` (n_x, n_y), 1/s: the field whose zero contour is drawn as the boundary
    (default ``max_real``; :func:`critical_field`: the same sign at every node, interpolated
    on the modes that go unstable).
    ``limits`` (lo, hi) 1/s: the colour scale (default: this map's range), so that small
    multiples share one; ``colorbar``/``legend`` False leave them to the caller (who gets the
    mappable as ``ax._rotordyn_mesh`` and the legend entries as ``ax._rotordyn_handles``)."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import TwoSlopeNorm
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    Z = np.asarray(max_real, dtype=float)
    require(Z.ndim == 2 and min(Z.shape) >= 2,
            f"stability-map: needs at least 2 values of each varying input, got grid {Z.shape}")
    ax = new_axes(ax, width=COLUMN_IN * 1.25, aspect=0.8)
    X, Y = np.meshgrid(np.asarray(x) * axis_scale(xname), np.asarray(y) * axis_scale(yname),
                       indexing="ij")
    require(np.isfinite(Z).any() or limits is not None,
            "stability-map: no converged point to draw")
    lo, hi = (np.nanmin(Z), np.nanmax(Z)) if limits is None else limits
    lo = min(lo, -1e-9)
    hi = max(hi, 1e-9)
    norm = TwoSlopeNorm(vcenter=0.0, vmin=lo, vmax=hi)
    m = ax.pcolormesh(X, Y, Z, cmap="RdBu_r", norm=norm, shading="nearest")
    if colorbar:
        cb = ax.figure.colorbar(m, ax=ax, pad=0.02)
        cb.set_label(COLOR_LABEL)
        two_slope_ticks(cb, lo, hi)
    # this map's own range decides its boundary
    lo, hi = (np.nanmin(Z), np.nanmax(Z)) if np.isfinite(Z).any() else (0.0, 0.0)
    handles = []
    if lo < 0 < hi and np.isfinite(Z).sum() > 3:
        B = Z if boundary_field is None else np.asarray(boundary_field, dtype=float)
        require(B.shape == Z.shape, f"stability-map: boundary_field: expected shape {Z.shape}, "
                                    f"got {B.shape}")
        ax.contourf(X, Y, np.nan_to_num(B, nan=-np.inf), levels=[0.0, np.inf], colors="none",
                    hatches=["////"])
        ax.contour(X, Y, B, levels=[0.0], colors="k", linewidths=1.8)
        handles.append(Line2D([], [], color="k", lw=1.8, label="stability boundary, Re λ = 0"))
        handles.append(Patch(facecolor="none", edgecolor="k", hatch="////",
                             label="unstable side (Re λ > 0)"))
    elif np.isfinite(Z).any():
        handles.append(Patch(facecolor="none", edgecolor="none",
                             label="stable everywhere" if hi <= 1e-9 else "unstable everywhere"))
    if failed is not None and len(failed):
        fp = np.asarray(failed, dtype=float)
        ax.plot(fp[:, 0] * axis_scale(xname), fp[:, 1] * axis_scale(yname), "x", color="0.2",
                ms=4)
        handles.append(Line2D([], [], ls="", marker="x", color="0.2",
                              label="no equilibrium / contact"))
    ax.set_xlabel(axis_label(xname))
    ax.set_ylabel(axis_label(yname))
    if legend:
        ax.legend(handles=handles, loc="best")
    ax._rotordyn_mesh, ax._rotordyn_handles = m, handles
    ax.grid(False)
    if title:
        ax.set_title(title)
    return ax


COLOR_LABEL = "largest real part of the eigenvalues, max Re λ (1/s)"


def two_slope_ticks(cb, lo: float, hi: float) -> None:
    """Ticks on both halves of a colour bar centred on 0 (a TwoSlopeNorm squeezes the smaller
    half, where the default locator left no tick: -0.02 against +17 1/s showed only 0)."""
    from matplotlib.ticker import MaxNLocator

    loc = MaxNLocator(nbins=3)
    # a half no wider than the ±1e-9 padding of a one-signed map gets no ticks
    neg = [t for t in loc.tick_values(lo, 0.0) if lo <= t < 0] if lo < -1e-9 else []
    pos = [t for t in loc.tick_values(0.0, hi) if 0 < t <= hi] if hi > 1e-9 else []
    if not neg and lo < -1e-9:
        neg = [lo]
    if not pos and hi > 1e-9:
        pos = [hi]
    cb.set_ticks(neg + [0.0] + pos)
    cb.ax.yaxis.set_major_formatter("{x:.3g}")


def critical_field(d: pd.DataFrame, axes: list[str], xs, ys) -> np.ndarray | None:
    """The field whose zero contour is the boundary (n_x, n_y), 1/s, by the rule of
    :func:`rotordyn._common.crossing.critical_values` (the boundary sweep's too): at each point
    the largest Re λ among the tracked modes (``mode_id``) that are unstable somewhere in ``d``
    (the rows with a result), else max Re λ; the sign of max Re λ at every point, but between
    points it follows the modes that cross (a turbine on a 10 Hz grid: 60.01 Hz drawn for a
    threshold at 61.58 Hz by max Re λ, 61.30 by this). None without ids or unstable modes."""
    from rotordyn._common.crossing import banded, critical_values

    if "mode_id" not in d or d["mode_id"].isna().any() or d.empty:
        return None
    re = d["eig_real_1_per_s"].to_numpy(dtype=float)
    mag = np.hypot(re, 2 * np.pi * d["freq_hz"].to_numpy(dtype=float))
    if not (banded(re, mag) > 0).any():  # no unstable mode (round-off of 0 is not one)
        return None
    xs, ys = np.asarray(xs), np.asarray(ys)
    key = (np.searchsorted(xs, d[axes[0]].to_numpy()) * len(ys)
           + np.searchsorted(ys, d[axes[1]].to_numpy()))
    pts, val = critical_values(key, d["mode_id"].to_numpy(), re, mag)
    out = np.full(len(xs) * len(ys), np.nan)
    out[pts] = val
    return out.reshape(len(xs), len(ys))


def _map_arrays(df: pd.DataFrame, axes: list[str], rotor_only: bool):
    """(x, y, max Re λ (n_x, n_y), failed points (k, 2), boundary field (n_x, n_y) or None) of
    a stability dataset over two axes."""
    d = df[df["status"] == "ok"]
    if rotor_only and "kind" in d:
        d = d[d["kind"] == "rotor"]
    xs, ys = np.sort(df[axes[0]].unique()), np.sort(df[axes[1]].unique())
    g = d.groupby(axes)["eig_real_1_per_s"].max().unstack().reindex(index=xs, columns=ys)
    pts = df.groupby(axes)["status"].apply(lambda s: (s != "ok").all())
    failed = np.array([k for k, bad in pts.items() if bad], dtype=float).reshape(-1, 2)
    return xs, ys, g.to_numpy(dtype=float), failed, critical_field(d, axes, xs, ys)


def stability_map(df: pd.DataFrame, ax=None, rotor_only: bool = True, where=None,
                  facet: str | None = None):
    """Stability map from a stability sweep dataset over any two of its axes (operating
    variables or model fields); a third varying axis is either fixed with ``where`` = {axis:
    value} (the nearest grid value) or drawn as small multiples with ``facet`` = that axis
    (:func:`stability_map_facets`), never averaged over."""
    if facet is not None:
        require(ax is None, "stability-map: facet draws a figure of its own (no ax)")
        return stability_map_facets(df, facet, rotor_only=rotor_only, where=where)
    df = select(df, where, "stability-map")
    axes = varying(df)
    require(len(axes) == 2, f"stability-map: expected exactly two varying axes, got "
                            f"{axes or 'none'}" + ("; fix the others with where={axis: value} "
                                                   "(CLI: --where AXIS=VALUE) or draw one map "
                                                   "per value of one with facet=AXIS (CLI: "
                                                   "--facet AXIS)" if len(axes) > 2 else ""))
    require("eig_real_1_per_s" in df, "stability-map: the dataset has no eigenvalues "
                                      "(eig_real_1_per_s); run a stability sweep")
    x, y, z, failed, b = _map_arrays(df, axes, rotor_only)
    return stability_map_grid(x, y, z, xname=axes[0], yname=axes[1], ax=ax, failed=failed,
                              boundary_field=b)


@paper_style
def stability_map_facets(df: pd.DataFrame, facet: str, rotor_only: bool = True, where=None):
    """Small multiples: one stability map over the two other varying axes per value of
    ``facet`` (a third axis of the sweep), panels titled with that value, one colour scale
    (max Re λ, 1/s) shared by all, one legend. Returns the first panel's Axes."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import TwoSlopeNorm
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    require("eig_real_1_per_s" in df, "stability-map: the dataset has no eigenvalues "
                                      "(eig_real_1_per_s); run a stability sweep")
    df = select(df, where, "stability-map")
    axes = varying(df)
    require(facet in axes, f"stability-map: --facet {facet}: not a varying axis of the dataset "
                           f"(varying: {axes or 'none'})")
    rest = [a for a in axes if a != facet]
    require(len(rest) == 2, f"stability-map: --facet {facet} needs exactly two other varying "
                            f"axes, got {rest or 'none'}" + ("; fix the others with --where "
                                                             "AXIS=VALUE" if len(rest) > 2
                                                             else ""))
    values = np.sort(df[facet].unique())
    panels = [(v, *_map_arrays(df[df[facet] == v], rest, rotor_only)) for v in values]
    allz = np.concatenate([p[3].ravel() for p in panels])
    require(np.isfinite(allz).any(), "stability-map: no converged point in the dataset")
    lo, hi = float(np.nanmin(allz)), float(np.nanmax(allz))
    n = len(panels)
    ncols = min(n, 3)
    nrows = -(-n // ncols)
    fig, grid = plt.subplots(nrows, ncols, squeeze=False, layout="constrained",
                             figsize=(COLUMN_IN * 0.95 * ncols + 0.9,
                                      COLUMN_IN * 0.8 * nrows + 0.6))
    sym, unit = axis_short(facet)
    k = axis_scale(facet)
    kinds = set()
    for a, (v, x, y, z, failed, b) in zip(grid.flat, panels):
        stability_map_grid(x, y, z, xname=rest[0], yname=rest[1], ax=a, failed=failed,
                           boundary_field=b,
                           limits=(lo, hi), colorbar=False, legend=False,
                           title=f"{sym} = {v * k:.4g}" + (f" {unit}" if unit != "1" else ""))
        kinds |= {h.get_label() for h in a._rotordyn_handles}
    for a in grid.flat[n:]:
        a.set_visible(False)
    norm = TwoSlopeNorm(vcenter=0.0, vmin=min(lo, -1e-9), vmax=max(hi, 1e-9))
    sm = plt.cm.ScalarMappable(norm=norm, cmap="RdBu_r")
    cb = fig.colorbar(sm, ax=[a for a in grid.flat[:n]], pad=0.02, shrink=0.9)
    cb.set_label(COLOR_LABEL)
    two_slope_ticks(cb, min(lo, -1e-9), max(hi, 1e-9))
    handles = [Line2D([], [], color="k", lw=1.8, label="stability boundary, Re λ = 0"),
               Patch(facecolor="none", edgecolor="k", hatch="////",
                     label="unstable side (Re λ > 0)")]
    handles = [h for h in handles if h.get_label() in kinds]
    if "no equilibrium / contact" in kinds:
        handles.append(Line2D([], [], ls="", marker="x", color="0.2",
                              label="no equilibrium / contact"))
    for label in ("stable everywhere", "unstable everywhere"):
        if label in kinds:
            handles.append(Patch(facecolor="none", edgecolor="none",
                                 label=f"some panels {label}"))
    fig.legend(handles=handles, loc="outside lower center", ncols=min(len(handles), 3),
               fontsize=6)
    fig.suptitle(f"stability maps, one per {axis_label(facet)} (shared colour scale)")
    return grid.flat[0]


@paper_style
def equilibrium_loci(df: pd.DataFrame, ax=None, bearing: str | None = None, where=None):
    """Journal centre x/c against y/c (one curve per value of the outer varying input), with
    the clearance circle; arrows show the direction of the inner input."""
    from matplotlib.lines import Line2D

    require("x_over_c" in df, "equilibrium: the dataset has no journal positions (x_over_c); "
                              "run an equilibrium sweep")
    df = select(df, where, "equilibrium")
    axes = varying(df)
    require(bool(axes), "equilibrium: expected at least one varying input")
    require(len(axes) <= 2, f"equilibrium: expected one or two varying axes, got {axes}; fix "
                            "the others with where={axis: value} (CLI: --where AXIS=VALUE)")
    if bearing is None and "bearing" in df:
        bearing = df["bearing"].iloc[0]
    if bearing is not None and "bearing" in df:
        df = df[df["bearing"] == bearing]
    ax = new_axes(ax, width=COLUMN_IN * 1.6, aspect=0.68)
    th = np.linspace(0, 2 * np.pi, 721)
    ax.plot(np.cos(th), np.sin(th), color="0.4", lw=0.8)
    handles = [Line2D([], [], color="0.4", lw=0.8, label="clearance circle (e = c)")]
    import matplotlib.pyplot as plt

    outer = axes[0] if len(axes) > 1 else None
    inner = axes[-1]
    groups = list(df.groupby(outer)) if outer else [(None, df)]
    cmap = plt.get_cmap("viridis")
    for i, (key, g) in enumerate(groups):
        col = cmap(i / max(1, len(groups) - 1) * 0.92)
        ok = g[g["status"] == "ok"].sort_values(inner)
        if outer:
            sym, unit = axis_short(outer)
            lab = f"{sym} = {key * axis_scale(outer):g} {unit}"
        else:
            lab = "equilibrium locus"
        ln, = ax.plot(ok["x_over_c"], ok["y_over_c"], "-", marker=".", ms=3, color=col,
                      label=lab)
        handles.append(ln)
        if len(ok):
            ax.plot(ok["x_over_c"].iloc[:1], ok["y_over_c"].iloc[:1], "o", mfc="white", mec=col,
                    ms=4)
        if len(ok) >= 2:
            a, b = ok.iloc[-2], ok.iloc[-1]
            ax.annotate("", (b["x_over_c"], b["y_over_c"]), (a["x_over_c"], a["y_over_c"]),
                        arrowprops=dict(arrowstyle="->", color=col, lw=1.0))
        bad = g[g["status"] != "ok"]
        if len(bad):
            ax.plot(bad["x_over_c"], bad["y_over_c"], "x", color=col, ms=4)
    sym, unit = axis_short(inner)
    lo_in = df[inner].min() * axis_scale(inner)
    handles.append(Line2D([], [], ls="", marker="o", mfc="white", mec="k", ms=4,
                          label=f"{sym} = {lo_in:g} {unit} (start)"))
    handles.append(Line2D([], [], ls="", marker=r"$\rightarrow$", color="k", ms=8,
                          label=f"increasing {sym} ({unit})"))
    if (df["status"] != "ok").any():
        handles.append(Line2D([], [], ls="", marker="x", color="k", ms=4,
                              label="no equilibrium / contact"))
    ax.set_aspect("equal")
    ax.set_xlim(-1.05, 1.05)   # the whole clearance circle: where the journal may go
    ax.set_ylim(-1.05, 1.05)
    ax.set_xlabel("journal x / c (–), horizontal")
    ax.set_ylabel("journal y / c (–), vertical up")
    if bearing:
        ax.set_title(f"equilibrium loci: {bearing}")
    ax.figure.legend(handles=handles, loc="outside right upper", fontsize=6)
    return ax


@paper_style
def boundary_curve(result, ax=None):
    """A :class:`rotordyn.results.BoundaryResult`: the threshold of ``vary`` along ``along``,
    the unstable side hatched."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    ax = new_axes(ax, width=COLUMN_IN * 1.2)
    t = result.table[result.table["status"] == "ok"].sort_values(result.along)
    xs = axis_scale(result.along)
    ys = axis_scale(result.vary)
    x, y = t[result.along].to_numpy() * xs, t[result.vary].to_numpy() * ys
    ax.plot(x, y, "ko-", ms=3)
    handles = [Line2D([], [], color="k", marker="o", ms=3, label="threshold of instability")]
    if len(t):
        side = t["stable_side"].iloc[0]
        y0, y1 = ax.get_ylim()
        lim = y0 if side == "above" else y1
        ax.fill_between(x, y, lim, facecolor="none", edgecolor="k", hatch="////", lw=0)
        ax.set_ylim(y0, y1)
        handles.append(Patch(facecolor="none", edgecolor="k", hatch="////",
                             label=f"unstable (stable {side})"))
    ax.set_xlabel(axis_label(result.along))
    ax.set_ylabel(axis_label(result.vary))
    ax.legend(handles=handles, loc="best")
    return ax
