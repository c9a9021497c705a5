"""Text layout checks of a rendered matplotlib figure (used by tests/test_figure_layout.py):
the boxes of titles, axis labels, legends, annotations and free texts must not overlap each
other, and every axis of data carries a label with a unit."""

from __future__ import annotations


def text_boxes(fig) -> list[tuple[str, object]]:
    """(name, display-space Bbox) of every visible text element that a reader must read."""
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    out = []
    if fig._suptitle is not None and fig._suptitle.get_text():
        out.append(("suptitle", fig._suptitle.get_window_extent(r)))
    for legend in fig.legends:
        out.append(("figure legend", legend.get_window_extent(r)))
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        for what in ("title", "_left_title", "_right_title"):
            t = getattr(ax, what if what != "title" else "title")
            if t.get_text() and t.get_visible():
                out.append((f"ax{k} {what}", t.get_window_extent(r)))
        for axis, name in ((ax.xaxis, "xlabel"), (ax.yaxis, "ylabel")):
            lab = axis.get_label()
            if lab.get_text() and lab.get_visible():
                out.append((f"ax{k} {name} {lab.get_text()[:30]!r}", lab.get_window_extent(r)))
        leg = ax.get_legend()
        if leg is not None and leg.get_visible():
            out.append((f"ax{k} legend", leg.get_window_extent(r)))
        for t in ax.texts:
            if t.get_visible() and t.get_text().strip():
                box = t.get_bbox_patch()
                ext = (box.get_window_extent(r) if box is not None else
                       t.get_window_extent(r))
                out.append((f"ax{k} text {t.get_text()[:30]!r}", ext))
    return out


def overlaps(fig, pad: float = 0.0) -> list[str]:
    """Pairs of text boxes that overlap (more than ``pad`` display pixels)."""
    boxes = text_boxes(fig)
    bad = []
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i][1], boxes[j][1]
            w = min(a.x1, b.x1) - max(a.x0, b.x0)
            h = min(a.y1, b.y1) - max(a.y0, b.y0)
            if w > pad and h > pad:
                bad.append(f"{boxes[i][0]} overlaps {boxes[j][0]}")
    return bad


def unlabelled_axes(fig) -> list[str]:
    """Data axes (2-D, with ticks) whose x or y label is empty or has no unit in brackets."""
    fig.canvas.draw()
    bad = []
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible() or ax.name != "rectilinear" or not ax.has_data() \
                or hasattr(ax, "_colorbar"):
            continue
        pairs = [("y", ax.get_ylabel())]
        # an x axis shared with a panel below it shows no tick labels and needs no label
        if any(t.get_visible() and t.get_text() for t in ax.get_xticklabels()):
            pairs.insert(0, ("x", ax.get_xlabel()))
        for name, lab in pairs:
            if not lab.strip():
                bad.append(f"ax{k} {name}: no label")
            elif "(" not in lab and "[" not in lab:
                bad.append(f"ax{k} {name}: no unit in {lab!r}")
    return bad
