"""Unbalance response figures: Bode (amplitude in µm and phase against speed) and polar plots,
with the API 684 amplification factor (half-power method) of each peak, the half-power band,
the operating speed range and each separation margin against its API requirement."""

from __future__ import annotations

import numpy as np

from rotordyn._common.api import af_text
from rotordyn.plot._style import (COLUMN_IN, PAGE_IN, declutter, hz_rpm_axis, legend_below,
                                  paper_style, require)


def _station_index(result, station):
    if station is None:
        return 0
    require(station in result.stations,
            f"station: expected one of {list(result.stations)}, got {station!r}")
    return list(result.stations).index(station)


@paper_style
def phase_lag_deg(z) -> np.ndarray:
    """Phase lag of the response behind the unbalance force, deg: −arg(z), unwrapped along speed
    (a lag grows by ~180° through each critical, never jumps by 360°), each finite run on its
    own and started in (−180°, 180°]."""
    z = np.asarray(z)
    out = np.full(z.shape, np.nan)
    ok = np.isfinite(z)
    idx = np.flatnonzero(ok)
    if idx.size:
        runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
        for r in runs:
            out[r] = -np.degrees(np.unwrap(np.angle(z[r])))
    return out


def bode(result, station=None, axes=None, annotate: bool = True):
    """Bode plot at ``station``: amplitude of x, y and the orbit's semi-major axis (µm), phase
    lag of x and y behind the unbalance (deg, unwrapped: :func:`phase_lag_deg`), peaks
    annotated with N_c and AF, operating range and margins."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    k = _station_index(result, station)
    require(len(result.speeds_hz) >= 3, "bode: needs 3 or more speeds")
    if axes is None:
        fig, axes = plt.subplots(2, 1, sharex=True, figsize=(PAGE_IN * 0.62, PAGE_IN * 0.68),
                                 height_ratios=(2, 1), layout="constrained")
    a1, a2 = axes
    sp = result.speeds_hz
    x, y = result.x[:, k], result.y[:, k]
    a1.plot(sp, np.abs(x) * 1e6, color="tab:blue", label="x amplitude (horizontal)")
    a1.plot(sp, np.abs(y) * 1e6, color="tab:orange", label="y amplitude (vertical)")
    a1.plot(sp, result.major_m[:, k] * 1e6, color="k", lw=0.8, ls="--",
            label="orbit semi-major axis")
    a2.plot(sp, phase_lag_deg(x), color="tab:blue")
    a2.plot(sp, phase_lag_deg(y), color="tab:orange")
    handles, _ = a1.get_legend_handles_labels()
    if annotate:
        pk = result.peaks(result.stations[k])
        top = float(np.nanmax(result.major_m[:, k])) * 1e6 if np.isfinite(result.major_m[:, k]).any() else 1.0
        xr = float(sp[-1] - sp[0])
        boxes, bands = [], False
        for n, (_, row) in enumerate(pk.sort_values("critical_speed_hz").iterrows()):
            nc, af = row["critical_speed_hz"], row["amplification_factor"]
            a1.axvline(nc, color="0.3", lw=0.6, ls=":")
            if np.isfinite(row["n1_hz"]) and np.isfinite(row["n2_hz"]):
                a1.axvspan(row["n1_hz"], row["n2_hz"], color="tab:purple", alpha=0.15, lw=0)
                bands = True
            txt = f"N_c = {nc:.1f} Hz, " + af_text(af, row["af_kind"])
            if "separation_margin_pct" in row and np.isfinite(row.get("required_margin_pct",
                                                                      np.nan)):
                sm, req = row["separation_margin_pct"], row["required_margin_pct"]
                txt += (f"\nSM = {sm:.0f} % (API ≥ {req:.0f} %: "
                        f"{'pass' if sm >= req else 'FAIL'})" if req > 0 else
                        "\nno margin required (AF < 2.5)")
            # boxes stacked in the free band above the curves, arrows to the peaks
            ty = top * (1.55 - 0.2 * (n % 3))
            tx = min(max(nc + 0.02 * xr, sp[0]), sp[-1] - 0.3 * xr)
            boxes.append((row["peak_m"], a1.annotate(
                txt, (nc, row["peak_m"] * 1e6), xytext=(tx, ty), fontsize=5.8, va="top",
                ha="left", arrowprops=dict(arrowstyle="-", color="0.4", lw=0.5),
                bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="0.6", alpha=0.9))))
        if len(pk):
            a1.set_ylim(0, top * 1.62)
            # the largest peaks keep their boxes; one that would overlap them is hidden
            hidden = declutter([b for _, b in sorted(boxes, key=lambda pb: -pb[0])])
            more = f" ({hidden} smaller not labelled: peaks())" if hidden else ""
            handles.append(Line2D([], [], color="0.3", lw=0.6, ls=":",
                                  label="critical speed N_c (peak)" + more))
        if bands:
            handles.append(Patch(color="tab:purple", alpha=0.15,
                                 label="half-power band N₁…N₂ (AF = N_c/(N₂−N₁))"))
    if result.operating_speed_hz is not None:
        lo, hi = result.operating_speed_hz
        for a in axes:
            a.axvspan(lo, hi, color="tab:green", alpha=0.12, lw=0)
        handles.append(Patch(color="tab:green", alpha=0.12, label="operating speed range"))
    a1.set_ylabel("amplitude (µm, 0-peak)")
    a2.set_ylabel("phase lag (deg)")
    lags = np.concatenate([phase_lag_deg(x), phase_lag_deg(y)])
    if np.isfinite(lags).any():  # ticks every 90° over the unwrapped range
        lo = 90 * np.floor(np.nanmin(lags) / 90)
        hi = 90 * np.ceil(np.nanmax(lags) / 90)
        a2.set_yticks(np.arange(lo, hi + 1, 90 if hi - lo <= 540 else 180))
    a2.set_xlabel("rotor speed (Hz)")
    hz_rpm_axis(a1)
    a2.figure.legend(handles=handles, loc="outside lower center", ncol=2, fontsize=6)
    a1.set_title(f"unbalance response at station {result.stations[k]}", fontsize=8)
    return a1, a2


@paper_style
def polar(result, station=None, ax=None, component: str = "y", n_labels: int = 6):
    """Polar plot of the response vector of ``component`` (x or y) at ``station``: amplitude
    (µm) and phase (deg) traced over speed, speeds labelled along the curve."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    require(component in ("x", "y"), f"component: expected 'x' or 'y', got {component!r}")
    k = _station_index(result, station)
    z = (result.x if component == "x" else result.y)[:, k] * 1e6
    if ax is None:
        fig = plt.figure(figsize=(COLUMN_IN * 1.15, COLUMN_IN * 1.15), layout="constrained")
        ax = fig.add_subplot(projection="polar")
    ok = np.isfinite(z)
    ax.plot(np.angle(z[ok]), np.abs(z[ok]), color="tab:blue", lw=1.1)
    ax.plot([np.angle(z[ok][0])], [np.abs(z[ok][0])], "o", color="tab:green", ms=4)
    idx = np.linspace(0, ok.sum() - 1, n_labels).astype(int)
    sp = result.speeds_hz[ok]
    labels = [ax.annotate(f"{sp[i]:.0f} Hz", (np.angle(z[ok][i]), np.abs(z[ok][i])),
                          fontsize=6, xytext=(3, 3), textcoords="offset points") for i in idx]
    j = int(np.nanargmax(np.abs(z)))
    ax.plot([np.angle(z[j])], [np.abs(z[j])], "s", color="tab:red", ms=4)
    ax.set_rlabel_position(100)
    ax.set_xlabel("phase (deg, counter-clockwise from +x); radius: amplitude (µm)")
    legend_below(ax, [Line2D([], [], color="tab:blue", label=f"{component} response vector"),
                      Line2D([], [], marker="o", ls="", color="tab:green",
                             label=f"lowest speed ({sp[0]:.0f} Hz)"),
                      Line2D([], [], marker="s", ls="", color="tab:red",
                             label=f"largest amplitude ({np.abs(z[j]):.3g} µm at "
                                   f"{result.speeds_hz[j]:.1f} Hz)")], ncol=1)
    ax.set_title(f"polar plot, station {result.stations[k]} ({component})", fontsize=8)
    declutter(labels)  # speeds where the curve doubles back would pile up
    return ax
