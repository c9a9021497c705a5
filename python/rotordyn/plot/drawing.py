"""A drawing of the rotor from the model: shaft sections to scale (axial and radial axes in mm,
each to its own scale, stated on the axes), disks, bearings and supports at their stations,
station numbers."""

from __future__ import annotations

import numpy as np

from rotordyn.plot._style import PAGE_IN, declutter, new_axes, paper_style


def disk_radius_m(disk) -> float:
    """The disk's outer radius when its geometry is known, else the equivalent solid disk's
    from the polar inertia: r = sqrt(2 I_p / m)."""
    if getattr(disk, "outer_diameter_m", None):
        return 0.5 * float(disk.outer_diameter_m)
    return float(np.sqrt(2 * disk.ip_kg_m2 / disk.mass_kg)) if disk.mass_kg > 0 else 0.0


KIND_LABEL = {"rigid": "ball bearing (rigid in x, y)", "linear": "linear support (spring)",
              "journal": "journal bearing", "active_journal": "active journal bearing",
              "fixed_geometry": "fixed-geometry bearing", "tilting_pad": "tilting-pad bearing",
              "squeeze_film_damper": "squeeze-film damper", "table": "bearing coefficient table"}


def _bearing_label(kind: str, b) -> str:
    """What the drawing says of a bearing element: its kind and its main dimensions."""
    lab = KIND_LABEL[kind]
    if kind == "table":
        return f"{lab} ({len(b.speeds_hz)} speeds)"
    extra = f", {b.n_pads} pads" if kind == "tilting_pad" else (
        f", {b.kind.replace('_', ' ')}" if kind == "fixed_geometry" else "")
    return f"{lab} (D = {b.diameter_m * 1e3:g} mm, c = {b.clearance_m * 1e6:g} µm{extra})"


def support_items(system):
    """[(station, label, kind)] of the supports and bearings, kind a support type or a TOML
    ``[[bearing]] type``."""
    from rotordyn.bearings import BEARING_TYPES

    kinds = {cls: name for name, cls in BEARING_TYPES.items()}
    out = []
    for s in system.supports:
        lab = "ball bearing (rigid in x, y)" if s.type == "rigid" else \
            f"linear support (k = {max(s.kxx_n_per_m, s.kyy_n_per_m):.3g} N/m)"
        out.append((s.station, s.name or lab, s.type))
    for b in system.bearings:
        kind = kinds[type(b)]
        lab = _bearing_label(kind, b)
        out.append((b.station, f"{b.name}\n{lab}" if b.name else lab, kind))
    return out


SUPPORT_STYLE = {"rigid": ("^", "tab:blue"), "linear": ("^", "tab:green"),
                 "journal": ("s", "tab:orange"), "active_journal": ("D", "tab:red"),
                 "fixed_geometry": ("s", "tab:brown"), "tilting_pad": ("p", "tab:purple"),
                 "squeeze_film_damper": ("o", "tab:cyan"), "table": ("X", "tab:olive")}


def _stagger(labels, levels: int = 6) -> None:
    """Move each support label down a line until it clears the labels before it."""
    if not labels:
        return
    fig = labels[0].figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    kept = []
    for t in labels:
        for level in range(levels):
            t.xyann = (0, -7 - 9 * level)
            box = t.get_window_extent(r).padded(1.0)
            if not any(box.overlaps(k) for k in kept):
                break
        kept.append(t.get_window_extent(r))


@paper_style
def rotor_drawing(system, ax=None, title: str | None = None, stations: bool = True):
    """Draw ``system``'s rotor: sections (hollow ones with their bore), disks, bearings."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch, Rectangle

    ax = new_axes(ax, width=PAGE_IN, aspect=0.32)
    rotor = system.rotor
    zs = rotor.station_positions_m() * 1e3
    rmax = max(s.outer_diameter_m for s in rotor.sections) / 2 * 1e3
    for i, s in enumerate(rotor.sections):
        ro, ri = s.outer_diameter_m / 2 * 1e3, s.inner_diameter_m / 2 * 1e3
        ax.add_patch(Rectangle((zs[i], -ro), zs[i + 1] - zs[i], 2 * ro, fc="0.82", ec="0.25",
                               lw=0.6))
        if ri > 0:
            ax.add_patch(Rectangle((zs[i], -ri), zs[i + 1] - zs[i], 2 * ri, fc="white",
                                   ec="0.25", lw=0.4, hatch="...."))
    handles = [Patch(fc="0.82", ec="0.25", label="shaft section (to scale)")]
    if any(s.inner_diameter_m > 0 for s in rotor.sections):
        handles.append(Patch(fc="white", ec="0.25", hatch="....", label="bore"))
    width = 0.012 * zs[-1]
    top = rmax
    for d in rotor.disks:
        r = disk_radius_m(d) * 1e3
        top = max(top, r)
        ax.add_patch(Rectangle((zs[d.station] - width / 2, -r), width, 2 * r, fc="tab:gray",
                               ec="k", lw=0.6))
        ax.annotate(f"{d.mass_kg:.3g} kg", (zs[d.station] + width / 2, r * 0.8), xytext=(2, 0),
                    textcoords="offset points", ha="left", va="center", fontsize=6)
    if rotor.disks:
        handles.append(Patch(fc="tab:gray", ec="k", label="disk (equivalent solid radius)"))
    seen = set()
    labels = []
    for n, (st, lab, kind) in enumerate(support_items(system)):
        mk, col = SUPPORT_STYLE[kind]
        y = -top * 1.25
        ax.plot([zs[st]], [y], marker=mk, color=col, ms=7, ls="")
        ax.plot([zs[st], zs[st]], [y, -rmax], color=col, lw=0.8)
        labels.append(ax.annotate(lab, (zs[st], y), xytext=(0, -7), textcoords="offset points",
                                  ha="center", va="top", fontsize=5.5, color=col))
        if kind not in seen:
            handles.append(Line2D([], [], marker=mk, color=col, ls="", ms=6,
                                  label=KIND_LABEL[kind]))
            seen.add(kind)
    nums = []
    if stations:
        nums = [ax.annotate(str(k), (z, top * 1.12), ha="center", va="bottom", fontsize=6,
                            color="0.3") for k, z in enumerate(zs)]
        ax.plot(zs, np.full(zs.size, top * 1.08), "|", color="0.3", ms=4)
        handles.append(Line2D([], [], marker="|", color="0.3", ls="", label="station (number)"))
    ax.axhline(0.0, color="0.5", lw=0.5, ls="-.")
    ax.set_xlim(zs[0] - 0.03 * zs[-1], zs[-1] * 1.03)
    ax.set_ylim(-top * 1.85, top * 1.45)
    _stagger(labels)  # after the limits: the boxes are measured where they will be drawn
    if nums:  # close stations keep their ticks; numbers that would touch are left out
        declutter([nums[0], nums[-1]] + nums[1:-1])
    ax.set_xlabel("axial position (mm)")
    ax.set_ylabel("radius (mm)")
    ax.grid(False)
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=6,
              borderaxespad=0)
    ax.set_title(title or f"{system.name or 'rotor'}: {zs[-1]:.0f} mm, {system.mass_kg:.2f} kg, "
                          f"{rotor.n_elements} elements (radial scale exaggerated)")
    return ax
