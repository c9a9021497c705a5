"""Figures from sweep datasets: stability maps (paper Fig. 9/10), equilibrium loci (Fig. 7/8),
Campbell diagrams from stability sweeps (Fig. 12) and waterfalls (Fig. 13)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from rotordyn.errors import InputError

KINDS = ("stability-map", "equilibrium", "campbell", "waterfall")
AXIS_LABEL = {"speed_hz": "speed (Hz)", "chamber_pressure_pa": "chamber pressure p_c (MPa)",
              "config_ay_m": "a_y (mm)"}
AXIS_SCALE = {"speed_hz": 1.0, "chamber_pressure_pa": 1e-6, "config_ay_m": 1e3}


def _varying(df: pd.DataFrame) -> list[str]:
    return [c for c in ("config_ay_m", "speed_hz", "chamber_pressure_pa")
            if c in df and df[c].nunique() > 1]


def stability_map(df: pd.DataFrame, ax=None, rotor_only: bool = True):
    """Largest real part of the eigenvalues over two varying inputs, with the boundary
    (Re λ = 0) drawn as a contour; unstable region shaded."""
    import matplotlib.pyplot as plt

    axes = _varying(df)
    if len(axes) != 2:
        raise InputError(f"stability-map: expected exactly two varying inputs, got {axes}")
    d = df[df["status"] == "ok"]
    if rotor_only and "kind" in d:
        d = d[d["kind"] == "rotor"]
    g = d.groupby(axes)["eig_real_1_per_s"].max().unstack()
    X, Y = np.meshgrid(g.index.to_numpy() * AXIS_SCALE[axes[0]],
                       g.columns.to_numpy() * AXIS_SCALE[axes[1]], indexing="ij")
    Z = g.to_numpy()
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 5))
    lim = np.nanmax(np.abs(Z)) or 1.0
    m = ax.pcolormesh(X, Y, Z, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="nearest")
    if np.nanmin(Z) < 0 < np.nanmax(Z):
        ax.contour(X, Y, Z, levels=[0.0], colors="k", linewidths=2)
    ax.figure.colorbar(m, ax=ax, label="max Re λ (1/s); > 0 unstable")
    ax.set_xlabel(AXIS_LABEL[axes[0]])
    ax.set_ylabel(AXIS_LABEL[axes[1]])
    ax.set_title("stability boundary (black): Re λ = 0")
    return ax


def equilibrium_loci(df: pd.DataFrame, ax=None):
    """x/c against y/c, one curve per value of the outer varying input."""
    import matplotlib.pyplot as plt

    axes = _varying(df)
    if not axes:
        raise InputError("equilibrium: expected at least one varying input")
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    outer = axes[0] if len(axes) > 1 else None
    groups = df.groupby(outer) if outer else [(None, df)]
    for key, g in groups:
        g = g[g["status"] == "ok"]
        lab = None if key is None else f"{AXIS_LABEL[outer].split(' (')[0]} = {key * AXIS_SCALE[outer]:g}"
        ax.plot(g["x_over_c"], g["y_over_c"], "o-", ms=3, label=lab)
    ax.set_xlabel("x / c")
    ax.set_ylabel("y / c")
    ax.grid(True, alpha=0.3)
    if outer:
        ax.legend(fontsize="small")
    return ax


def campbell(df: pd.DataFrame, ax=None):
    """Damped natural frequencies (rotor modes) against speed from a stability sweep."""
    import matplotlib.pyplot as plt

    d = df[(df["status"] == "ok")]
    if "kind" in d:
        d = d[d["kind"] == "rotor"]
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 5))
    for w, mk in (("forward", "o"), ("backward", "x")):
        s = d[d["whirl"] == w]
        ax.plot(s["speed_hz"], s["freq_hz"], mk, ms=3, label=w)
    sp = np.sort(d["speed_hz"].unique())
    ax.plot(sp, sp, "k:", label="1× speed")
    ax.set_xlabel("speed (Hz)")
    ax.set_ylabel("damped natural frequency (Hz)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return ax


def waterfall(df: pd.DataFrame, ax=None, axis: str = "x"):
    """Spectra of the journal motion stacked by speed (paper Fig. 13)."""
    import matplotlib.pyplot as plt

    d = df[df["status"] == "ok"]
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 6))
    col = f"amplitude_{axis}_m"
    speeds = np.sort(d["speed_hz"].unique())
    scale = 0.8 * (speeds[1] - speeds[0] if len(speeds) > 1 else 1.0) / (d[col].max() or 1.0)
    for s in speeds:
        g = d[d["speed_hz"] == s].sort_values("freq_hz")
        ax.plot(g["freq_hz"], s + scale * g[col], "k-", lw=0.7)
    ax.plot(speeds, speeds, "r:", lw=1, label="1×")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("speed (Hz)  [+ amplitude]")
    ax.set_title(f"waterfall of journal {axis}")
    ax.legend(fontsize="small")
    return ax


def plot_dataset(df: pd.DataFrame, kind: str, out: str) -> str:
    """Draw ``kind`` from a sweep dataset and save it to ``out`` (PNG or SVG)."""
    import matplotlib

    matplotlib.use("Agg")
    if kind not in KINDS:
        raise InputError(f"--kind: expected one of {KINDS}, got {kind!r}")
    fn = {"stability-map": stability_map, "equilibrium": equilibrium_loci,
          "campbell": campbell, "waterfall": waterfall}[kind]
    ax = fn(df)
    ax.figure.savefig(out, dpi=130, bbox_inches="tight")
    return out
