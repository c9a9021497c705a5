"""Waterfall diagrams (paper Fig. 13): amplitude spectra of the journal motion against speed,
in µm, linear or logarithmic, as a 3-D cascade or as a colour map (speed × frequency), with
0.5×, 1×, 2× order lines; from steady-speed sets (a waterfall sweep) or a run-up
(:func:`runup_spectra`). Every trace is drawn over the same frequency span."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rotordyn.plot._style import ORDER_STYLE, PAGE_IN, new_axes, order_label, paper_style, require

if TYPE_CHECKING:
    import pandas as pd

STYLES = ("cascade", "map")
SCALES = ("linear", "log")


def runup_spectra(t_s, z_m, speed_hz, *, window_s: float, overlap: float = 0.5,
                  fmax_hz: float | None = None) -> pd.DataFrame:
    """Short-time spectra of a run-up: ``z_m`` (n_t,) sampled at uniform ``t_s`` (n_t,) while
    the speed ``speed_hz`` (n_t,) changes. Hann windows of ``window_s`` seconds, ``overlap``
    fraction. Returns a tidy table (speed_hz = mean speed in the window, freq_hz,
    amplitude_m, status) that :func:`waterfall` draws (``axis=None``)."""
    import pandas as pd
    t = np.asarray(t_s, dtype=float)
    z = np.asarray(z_m, dtype=float)
    sp = np.asarray(speed_hz, dtype=float)
    require(t.ndim == 1 and t.size == z.size == sp.size and t.size >= 16,
            "runup_spectra: expected equal-length 1-D arrays t_s, z_m, speed_hz (≥ 16 samples)")
    dt = np.diff(t)
    require(np.allclose(dt, dt[0], rtol=1e-6), "t_s: expected uniformly spaced samples")
    n = int(round(window_s / dt[0]))
    require(8 <= n <= t.size, f"window_s: expected between 8 samples and the record length "
                              f"({t.size * dt[0]:g} s), got {window_s!r}")
    step = max(1, int(n * (1 - overlap)))
    win = np.hanning(n)
    f = np.fft.rfftfreq(n, dt[0])
    rows = []
    for i0 in range(0, t.size - n + 1, step):
        seg = z[i0:i0 + n]
        amp = 2 * np.abs(np.fft.rfft((seg - seg.mean()) * win)) / win.sum()
        keep = f <= (fmax_hz if fmax_hz else f[-1])
        rows.append(pd.DataFrame({"speed_hz": sp[i0:i0 + n].mean(), "freq_hz": f[keep],
                                  "amplitude_m": amp[keep], "status": "ok"}))
    return pd.concat(rows, ignore_index=True)


def _table(df: pd.DataFrame, axis: str | None):
    col = "amplitude_m" if axis is None else f"amplitude_{axis}_m"
    require("freq_hz" in df and col in df,
            f"waterfall: the dataset has no spectra ({col}); use a waterfall sweep "
            "(analysis = \"waterfall\") or runup_spectra()")
    d = df[df["status"] == "ok"] if "status" in df else df
    speeds = np.sort(d["speed_hz"].unique())
    require(speeds.size >= 2, f"waterfall: needs spectra at 2 or more speeds, got {speeds.size}")
    fmax = min(d[d["speed_hz"] == s]["freq_hz"].max() for s in speeds)  # common span
    return d[d["freq_hz"] <= fmax + 1e-12], speeds, col, fmax


@paper_style
def waterfall(df: pd.DataFrame, ax=None, axis: str | None = "x", style: str = "cascade",
              scale: str = "linear", orders=(0.5, 1.0, 2.0), floor_um: float | None = None,
              title: str | None = None):
    """Waterfall of journal spectra against speed.

    df: tidy table with speed_hz, freq_hz, amplitude_{axis}_m (a waterfall sweep), or
    amplitude_m with ``axis=None`` (:func:`runup_spectra`). style: ``"cascade"`` (3-D) or
    ``"map"`` (colour = amplitude). scale: ``"linear"`` or ``"log"`` amplitude.
    floor_um: lower amplitude limit of the log scale (default 1e-4 of the peak)."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm, Normalize
    from matplotlib.lines import Line2D

    require(style in STYLES, f"style: expected one of {STYLES}, got {style!r}")
    require(scale in SCALES, f"scale: expected one of {SCALES}, got {scale!r}")
    d, speeds, col, fmax = _table(df, axis)
    amp_um = d[col].to_numpy() * 1e6
    peak = float(np.nanmax(amp_um)) if amp_um.size else 1.0
    floor = floor_um or peak * 1e-4
    where = "journal" if axis is None else f"journal {axis}"
    handles = []
    if style == "map":
        ax = new_axes(ax, width=PAGE_IN * 0.6, aspect=0.75)
        # traces have their own frequency resolution (Δf = 1/record length): put each on one
        # common grid, fine enough (≤ the finest Δf / 2) not to flatten a peak
        df_min = min(np.min(np.diff(np.sort(d[d["speed_hz"] == s]["freq_hz"].unique())))
                     for s in speeds)
        fg = np.linspace(0.0, fmax, int(min(4000, max(200, 2 * fmax / df_min))) + 1)
        Z = np.vstack([np.interp(fg, *d[d["speed_hz"] == s].sort_values("freq_hz")
                                 [["freq_hz", col]].to_numpy().T) for s in speeds]) * 1e6
        F, S = np.meshgrid(fg, speeds)
        norm = LogNorm(floor, peak) if scale == "log" else Normalize(0, peak)
        m = ax.pcolormesh(F, S, np.clip(Z, floor, None) if scale == "log" else Z, norm=norm,
                          cmap="magma_r", shading="nearest")
        cb = ax.figure.colorbar(m, ax=ax, pad=0.02)
        cb.set_label(f"{where} amplitude (µm{', log scale' if scale == 'log' else ''})")
        for h in orders:
            ax.plot(h * speeds, speeds, color="tab:cyan", lw=0.9, ls=ORDER_STYLE.get(h, "-."))
            handles.append(Line2D([], [], color="tab:cyan", lw=0.9, ls=ORDER_STYLE.get(h, "-."),
                                  label=order_label(h)))
        ax.set_xlim(0, fmax)
        ax.set_ylim(speeds[0], speeds[-1])
        ax.set_xlabel("frequency (Hz)")
        ax.set_ylabel("rotor speed (Hz)")
        ax.grid(False)
    else:
        ax = new_axes(ax, width=PAGE_IN * 0.6, aspect=0.8, projection="3d")
        zt = (lambda a: np.log10(np.clip(a, floor, None))) if scale == "log" else (lambda a: a)
        z0 = zt(np.array([floor if scale == "log" else 0.0]))[0]
        for s in speeds:
            g = d[d["speed_hz"] == s].sort_values("freq_hz")
            ax.plot(g["freq_hz"], np.full(len(g), s), zt(g[col].to_numpy() * 1e6), color="k",
                    lw=0.6)
        handles.append(Line2D([], [], color="k", lw=0.6, label="spectrum at one speed"))
        for h in orders:
            s = speeds[h * speeds <= fmax]
            ax.plot(h * s, s, np.full(s.size, z0), color="tab:red", lw=0.9,
                    ls=ORDER_STYLE.get(h, "-."))
            handles.append(Line2D([], [], color="tab:red", lw=0.9, ls=ORDER_STYLE.get(h, "-."),
                                  label=order_label(h)))
        ax.set_xlim(0, fmax)
        ax.set_xlabel("frequency (Hz)")
        ax.set_ylabel("rotor speed (Hz)")
        if scale == "log":
            ax.set_zlabel("amplitude (µm, log₁₀)")
            ticks = np.arange(np.floor(z0), np.ceil(np.log10(peak)) + 1)
            ax.set_zticks(ticks)
            ax.set_zticklabels([f"$10^{{{int(k)}}}$" for k in ticks])
        else:
            ax.set_zlabel("amplitude (µm)")
        ax.view_init(elev=28, azim=-62)
    ax.legend(handles=handles, loc="upper left", fontsize=6)
    ax.set_title(title or f"waterfall of the {where} motion")
    return ax
