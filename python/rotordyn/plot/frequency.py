"""Campbell diagrams: damped natural frequencies against speed, modes tracked through crossings
(ids from :mod:`rotordyn.analysis.tracking`), each curve coloured by its logarithmic
decrement (or damping ratio) with a colour bar, unstable stretches (δ < 0) in red, forward /
backward / planar whirl as solid / dashed / dotted lines, 0.5×, 1×, 2× order lines and the
critical speeds (forward crossings of 1×) marked and labelled."""

from __future__ import annotations

import numpy as np

from rotordyn.plot._style import (ORDER_STYLE, PAGE_IN, WHIRL_STYLE, WHIRL_TEXT, hz_rpm_axis,
                                  declutter, legend_below, new_axes, order_label, paper_style,
                                  require)

COLOR_BY = {"log_dec": "logarithmic decrement δ (–)", "damping_ratio": "damping ratio ζ (–)"}


def _segments(x, y):
    pts = np.column_stack([x, y])
    return np.stack([pts[:-1], pts[1:]], axis=1)


@paper_style
def campbell_arrays(speeds_hz, freq_hz, damping, whirl, *, ax=None, color_by="log_dec",
                    harmonics=(0.5, 1.0, 2.0), critical=None, title=None, damping_max=None):
    """Draw a Campbell diagram from arrays.

    speeds_hz: (n_s,); freq_hz, damping, whirl: (n_s, n_curves) — one column per tracked mode
    (NaN where absent), damping in the unit of ``color_by``, whirl codes +1/−1/0.
    critical: DataFrame with ``speed_hz``, ``freq_hz`` (and ``harmonic``, ``resonant``: a
    crossing whose mode has no resonance, δ ≥ 2π, is drawn grey and unlabelled) to mark, or None.
    Returns the Axes (its figure holds the colour bar).
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.colors import Normalize
    from matplotlib.lines import Line2D

    sp = np.asarray(speeds_hz, dtype=float)
    require(sp.size >= 2, f"campbell: needs at least 2 speeds to draw curves, got {sp.size} "
                          "(a one-speed sweep is a stability point: use `rotordyn stability`)")
    require(color_by in COLOR_BY, f"color_by: expected one of {sorted(COLOR_BY)}, got "
                                  f"{color_by!r}")
    ax = new_axes(ax, width=PAGE_IN * 0.62, aspect=0.72)
    f = np.asarray(freq_hz, dtype=float)
    d = np.asarray(damping, dtype=float)
    w = np.asarray(whirl, dtype=float)
    dpos = d[np.isfinite(d) & (d > 0)]
    # δ above ~1 is heavily damped either way: the scale resolves 0 … min(1, 95th percentile)
    cap = 1.0 if color_by == "log_dec" else 0.16
    vmax = damping_max or (min(cap, float(np.percentile(dpos, 95))) if dpos.size else cap)
    norm = Normalize(0.0, vmax)
    # viridis without its last, pale-yellow fifth: a well-damped mode stays visible on white
    from matplotlib.colors import ListedColormap

    cmap = ListedColormap(plt.get_cmap("viridis")(np.linspace(0.0, 0.8, 256)))
    any_unstable = False
    for j in range(f.shape[1]):
        ok = np.isfinite(f[:, j])
        if ok.sum() < 2:
            continue
        seg = _segments(sp, f[:, j])
        valid = ok[:-1] & ok[1:]
        dm = 0.5 * (d[:-1, j] + d[1:, j])
        ws = np.where(np.isfinite(w[:-1, j]), w[:-1, j], 0).astype(int)
        colors = cmap(norm(np.nan_to_num(dm, nan=0.0)))
        unstable = dm < 0
        any_unstable |= bool(np.any(unstable & valid))
        colors[unstable] = (0.85, 0.0, 0.0, 1.0)
        widths = np.where(unstable, 2.6, 1.4)
        styles = [WHIRL_STYLE[int(k)] for k in ws]
        m = valid
        lc = LineCollection(seg[m], colors=colors[m], linewidths=widths[m],
                            linestyles=[s for s, keep in zip(styles, m) if keep],
                            capstyle="butt")
        ax.add_collection(lc)
    fmax = np.nanmax(f) if np.isfinite(f).any() else sp.max()
    handles = []
    for h in harmonics:
        ax.plot(sp, h * sp, color="0.35", lw=0.8, ls=ORDER_STYLE.get(h, "-."), zorder=1)
        handles.append(Line2D([], [], color="0.35", lw=0.8, ls=ORDER_STYLE.get(h, "-."),
                              label=order_label(h)))
    for code in (1, -1, 0):
        if np.any(w == code):
            handles.append(Line2D([], [], color=cmap(0.6), ls=WHIRL_STYLE[code],
                                  label=WHIRL_TEXT[code]))
    if any_unstable:
        handles.append(Line2D([], [], color=(0.85, 0, 0), lw=2.6,
                              label="unstable (δ < 0, growing)"))
    flat = None
    if critical is not None and "resonant" in critical:  # crossings without a resonance
        flat = critical[~critical["resonant"].astype(bool)]
        critical = critical[critical["resonant"].astype(bool)]
    if flat is not None and len(flat):
        ax.plot(flat["speed_hz"], flat["freq_hz"], "o", mfc="0.8", mec="0.45", ms=4, zorder=5)
        handles.append(Line2D([], [], ls="", marker="o", mfc="0.8", mec="0.45", ms=4,
                              label="1× crossing, no resonance (δ ≥ 2π)"))
    if critical is not None and len(critical):
        ax.plot(critical["speed_hz"], critical["freq_hz"], "o", mfc="white", mec="k", ms=5,
                zorder=5)
        notes = []
        for _, row in critical.iterrows():
            notes.append(ax.annotate(
                f"{row['speed_hz']:.1f} Hz\n({60 * row['speed_hz']:.0f} rpm)",
                (row["speed_hz"], row["freq_hz"]), xytext=(4, -14), textcoords="offset points",
                fontsize=6.5, bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none",
                                        alpha=0.8)))
        handles.append(Line2D([], [], ls="", marker="o", mfc="white", mec="k",
                              label="critical speed (1×, forward or planar)"))
    ax.set_xlim(sp.min(), sp.max())
    ax.set_ylim(0, 1.05 * max(fmax, sp.max() * (min(max(harmonics), 1.0) if harmonics else 1)))
    if critical is not None and len(critical):
        declutter(notes)  # close critical speeds: the first keeps its label
    ax.set_xlabel("rotor speed (Hz)")
    ax.set_ylabel("damped natural frequency (Hz)")
    hz_rpm_axis(ax)
    sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
    cb = ax.figure.colorbar(sm, ax=ax, pad=0.02, extend="max")
    cb.set_label(COLOR_BY[color_by])
    legend_below(ax, handles, ncol=3)
    if title:
        ax.set_title(title)
    return ax


def campbell_diagram(result, *, ax=None, color_by="log_dec", harmonics=(0.5, 1.0, 2.0),
                     critical=True, rotor_only=True, title=None):
    """Campbell diagram of a :class:`rotordyn.results.CampbellResult` (tracked modes).
    ``rotor_only``: omit the sleeve modes of an active bearing (as the paper's Fig. 12)."""
    f = result.frequencies_hz
    if rotor_only and result.kind is not None:
        f = np.where(result.kind == "rotor", f, np.nan)
    damp = result.log_dec if color_by == "log_dec" else \
        -result.eigenvalues.real / np.abs(result.eigenvalues)
    ft = result.tracked(f)
    dt = result.tracked(np.asarray(damp, dtype=float))
    wt = result.tracked(result.whirl.astype(float))
    crit = result.critical_speeds() if critical else None
    return campbell_arrays(result.speeds_hz, ft, dt, wt, ax=ax, color_by=color_by,
                           harmonics=harmonics, critical=crit, title=title)
