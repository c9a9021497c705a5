"""Common figure settings: sizes for a paper's column (3.5 in) or page width (7.2 in), fonts
readable at that size, units in every label, and helpers shared by the figure modules."""

from __future__ import annotations

import functools

import numpy as np

from rotordyn.errors import InputError

COLUMN_IN = 3.5   # one column of a two-column paper, inches
PAGE_IN = 7.2     # full page width, inches

RC = {
    "font.size": 8, "axes.titlesize": 8, "axes.labelsize": 8, "xtick.labelsize": 7,
    "ytick.labelsize": 7, "legend.fontsize": 6.5, "legend.framealpha": 0.85,
    "lines.linewidth": 1.1, "lines.markersize": 4, "axes.grid": True, "grid.alpha": 0.3,
    "grid.linewidth": 0.5, "figure.dpi": 100, "savefig.dpi": 200, "savefig.bbox": "tight",
    "svg.fonttype": "none",
}

WHIRL_STYLE = {1: "-", -1: "--", 0: ":"}  # forward, backward, planar
WHIRL_TEXT = {1: "forward whirl", -1: "backward whirl", 0: "planar (no whirl)"}
ORDER_STYLE = {0.5: (0, (1, 1.5)), 1.0: "-", 2.0: (0, (4, 1.5, 1, 1.5)), 3.0: (0, (6, 2))}


def paper_style(fn):
    """Draw inside matplotlib's rc context :data:`RC` (fonts sized for print)."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        import matplotlib.pyplot as plt

        with plt.rc_context(RC):
            return fn(*args, **kwargs)

    return wrapper


def new_axes(ax=None, width: float = COLUMN_IN, aspect: float = 0.78, projection=None):
    """``ax`` if given, else a new figure of ``width`` inches and height ``aspect`` × width."""
    import matplotlib.pyplot as plt

    if ax is not None:
        return ax
    fig = plt.figure(figsize=(width, width * aspect), layout="constrained")
    return fig.add_subplot(projection=projection)


def hz_rpm_axis(ax, which: str = "x"):
    """A secondary axis in rev/min beside an axis in Hz (engineers read both)."""
    conv = (lambda hz: hz * 60.0, lambda rpm: rpm / 60.0)
    sec = ax.secondary_xaxis("top", functions=conv) if which == "x" else \
        ax.secondary_yaxis("right", functions=conv)
    (sec.set_xlabel if which == "x" else sec.set_ylabel)("speed (rpm)")
    return sec


def order_label(h: float) -> str:
    return f"{h:g}× running speed"


def require(cond: bool, message: str) -> None:
    """InputError (one line, exit 2 in the CLI) unless ``cond``."""
    if not cond:
        raise InputError(message)


def finite_range(*arrays) -> tuple[float, float]:
    vals = np.concatenate([np.ravel(a)[np.isfinite(np.ravel(a))] for a in arrays])
    return (float(vals.min()), float(vals.max())) if vals.size else (0.0, 1.0)


def declutter(texts, fig=None) -> int:
    """Hide each text (annotation) whose box overlaps one kept before it (``texts`` in order of
    priority), so that labels never pile up; returns how many were hidden."""
    texts = [t for t in texts if t.get_visible()]
    if not texts:
        return 0
    fig = fig or texts[0].figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    kept, hidden = [], 0
    for t in texts:
        box = t.get_window_extent(r).padded(1.0)
        if any(box.overlaps(k) for k in kept):
            t.set_visible(False)
            hidden += 1
        else:
            kept.append(box)
    return hidden


def legend_below(ax, handles, ncol: int = 3, **kw):
    """The legend under the figure's axes, outside them (a constrained-layout figure makes
    room for it, so it never covers the x label); inside the axes otherwise."""
    fig = ax.figure
    if fig.get_layout_engine() is not None and type(fig.get_layout_engine()).__name__ == \
            "ConstrainedLayoutEngine":
        return fig.legend(handles=handles, loc="outside lower center", ncol=ncol,
                          fontsize=kw.pop("fontsize", 6), **kw)
    return ax.legend(handles=handles, loc="best", fontsize=kw.pop("fontsize", 6), **kw)


def stability_segments(ax, x, y, stable, what: str) -> list:
    """A branch of a bifurcation diagram: segments between consecutive points solid where both
    ends are stable, dashed elsewhere (tab:blue). Returns the two legend handles
    ("stable <what>", "unstable <what>")."""
    from matplotlib.lines import Line2D

    # one polyline per run of segments with the same style: a dashed line drawn segment by
    # segment restarts its pattern at every point, and closely spaced points (a branch near
    # a fold) looked solid
    seg = [bool(stable[i] and stable[i + 1]) for i in range(len(x) - 1)]
    i = 0
    while i < len(seg):
        j = i
        while j + 1 < len(seg) and seg[j + 1] == seg[i]:
            j += 1
        ax.plot(x[i:j + 2], y[i:j + 2], "-" if seg[i] else "--", color="tab:blue", lw=1.2)
        i = j + 1
    return [Line2D([], [], color="tab:blue", ls="-", label=f"stable {what}"),
            Line2D([], [], color="tab:blue", ls="--", label=f"unstable {what}")]

