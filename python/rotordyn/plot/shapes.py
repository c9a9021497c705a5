"""Mode shapes and deflected shapes in 3-D: the whirl orbit of every node along the rotor
(both planes: x horizontal, y vertical), the instantaneous shape, the rotor outline, disks and
bearings; forward / backward / planar orbits told apart by colour (same rule as the tables,
:data:`rotordyn._common.whirl.WHIRL_PLANAR_TOL`), the start of each orbit marked so the sense
of rotation can be read."""

from __future__ import annotations

import numpy as np

from rotordyn.plot._style import COLUMN_IN, PAGE_IN, new_axes, paper_style, require

ORBIT_COLOR = {"forward": "tab:blue", "backward": "tab:red", "planar": "0.35"}


def _outline(ax, system, scale):
    """Rotor outline (radius × ``scale``), disks as circles, bearings as markers."""
    from rotordyn.plot.drawing import SUPPORT_STYLE, disk_radius_m, support_items

    zs = system.rotor.station_positions_m()
    th = np.linspace(0, 2 * np.pi, 60)
    for i, s in enumerate(system.rotor.sections):
        r = s.outer_diameter_m / 2 * scale
        for sgn in (1, -1):
            ax.plot([zs[i], zs[i + 1]], [0, 0], [sgn * r, sgn * r], color="0.6", lw=0.6)
        ax.plot([zs[i], zs[i]], [0, 0], [-r, r], color="0.6", lw=0.4)
    for d in system.rotor.disks:
        r = disk_radius_m(d) * scale
        ax.plot(np.full(th.size, zs[d.station]), r * np.cos(th), r * np.sin(th), color="0.3",
                lw=1.0)
    for st, _, kind in support_items(system):
        mk, col = SUPPORT_STYLE[kind]
        ax.plot([zs[st]], [0], [-0.18], marker=mk, color=col, ms=6, ls="")


@paper_style
def orbits_3d(z_m, X, Y, *, ax=None, system=None, title=None, normalise=True,
              unit="normalised", label_points=None):
    """Orbits x = Re(X e^{iθ}), y = Re(Y e^{iθ}) at axial positions ``z_m`` (n,), complex
    ``X``, ``Y`` (n,). ``normalise``: largest semi-major axis = 1 (mode shapes); otherwise
    displacements are drawn in µm (``unit="µm"``)."""
    from matplotlib.lines import Line2D

    from rotordyn._common.whirl import whirl_index, whirl_label

    z = np.asarray(z_m, dtype=float)
    X = np.asarray(X, dtype=complex)
    Y = np.asarray(Y, dtype=complex)
    require(z.size >= 2 and X.shape == Y.shape == z.shape,
            "orbits: expected axial positions and complex X, Y of the same length (≥ 2)")
    major = (np.abs(X + 1j * Y) + np.abs(np.conj(X) + 1j * np.conj(Y))) / 2
    if normalise:
        s = float(np.nanmax(major)) or 1.0
        # phase so that the largest motion is at θ = 0 in x or y
        k = int(np.nanargmax(major))
        ph = np.exp(-1j * np.angle(X[k] if abs(X[k]) >= abs(Y[k]) else Y[k]))
        X, Y = X * ph / s, Y * ph / s
    else:
        X, Y = X * 1e6, Y * 1e6
    ax = new_axes(ax, width=PAGE_IN * 0.75, aspect=0.62, projection="3d")
    ax.set_box_aspect((2.6, 1, 1), zoom=0.92)
    th = np.linspace(0, 2 * np.pi, 73)
    lab = whirl_label(whirl_index(X, Y, axis=()))
    seen = set()
    for i in range(z.size):
        xo = np.real(X[i] * np.exp(1j * th))
        yo = np.real(Y[i] * np.exp(1j * th))
        ax.plot(np.full(th.size, z[i]), xo, yo, color=ORBIT_COLOR[lab[i]], lw=0.8)
        ax.plot([z[i]], [xo[0]], [yo[0]], "o", color=ORBIT_COLOR[lab[i]], ms=2.2)
        seen.add(lab[i])
    ax.plot(z, np.real(X), np.real(Y), color="k", lw=1.4)
    ax.plot(z, np.zeros_like(z), np.zeros_like(z), color="0.5", lw=0.5, ls="-.")
    if system is not None and normalise:
        rmax = max(s.outer_diameter_m for s in system.rotor.sections) / 2
        _outline(ax, system, 0.15 / rmax)
    handles = [Line2D([], [], color=ORBIT_COLOR[w], lw=0.8,
                      label=f"{w} orbit" if w != "planar" else "planar orbit (no whirl)")
               for w in ("forward", "backward", "planar") if w in seen]
    handles += [Line2D([], [], color="0.2", marker="o", ls="", ms=2.5,
                       label="orbit at θ = 0 (motion starts here)"),
                Line2D([], [], color="k", lw=1.4, label="shape at θ = 0")]
    if system is not None and normalise:
        handles.append(Line2D([], [], color="0.6", lw=0.6, label="rotor outline, disks, "
                                                                  "bearings (not to scale)"))
    ax.legend(handles=handles, loc="upper left", fontsize=6)
    u = "(–, normalised)" if normalise else f"({unit})"
    from matplotlib.ticker import MaxNLocator

    ax.yaxis.set_major_locator(MaxNLocator(3))
    ax.zaxis.set_major_locator(MaxNLocator(3))
    ax.set_xlabel("axial position (m)", labelpad=2)
    ax.set_ylabel(f"x, horizontal\n{u}", labelpad=4)
    ax.set_zlabel(f"y, vertical\n{u}", labelpad=4)
    ax.view_init(elev=22, azim=-58)
    if title:
        ax.set_title(title)
    return ax


def mode_shape(result, mode: int = 0, *, ax=None, system=None):
    """3-D mode shape ``mode`` (0-based) of a ModesResult or StabilityResult."""
    shapes = getattr(result, "shapes", None)
    if shapes is None:
        shapes = result.rotor_shapes
    require(0 <= mode < shapes.shape[2], f"mode: expected 0..{shapes.shape[2] - 1}, got {mode}")
    z = result.node_positions_m if hasattr(result, "node_positions_m") else \
        (system.rotor.node_positions_m() if system is not None else np.arange(shapes.shape[0]))
    f = result.frequencies_hz[mode]
    ld = result.log_dec[mode]
    ld = 0.0 if abs(ld) < 1e-6 else ld  # round-off of an undamped rotor
    wh = result.whirl[mode]
    # the table's mode number (1-based, as to_frame()["mode"] and the CLI's --mode) and the
    # 0-based index the plot was asked for, so neither reading is wrong
    title = (f"mode {mode + 1} (index {mode}): {f:.2f} Hz, {wh} whirl, log dec {ld:.3g}, at "
             f"{result.speed_hz:g} Hz")
    return orbits_3d(z, shapes[:, 0, mode], shapes[:, 1, mode], ax=ax, system=system,
                     title=title)


@paper_style
def mode_shapes_2d(result, modes=None, ax=None, plane: str = "x"):
    """Mode shapes along the shaft in one plane (real part, normalised), legend with the
    frequency and whirl of each mode."""
    ax = new_axes(ax, width=COLUMN_IN * 1.4, aspect=0.6)
    k = {"x": 0, "y": 1}[plane]
    idx = range(len(result.eigenvalues)) if modes is None else modes
    for j in idx:
        s = result.shapes[:, k, j]
        i = int(np.argmax(np.abs(s)))
        v = np.real(s * np.exp(-1j * np.angle(s[i]))) / (np.abs(s[i]) or 1.0)
        ax.plot(result.node_positions_m, v,
                label=f"mode {j + 1}: {result.frequencies_hz[j]:.2f} Hz ({result.whirl[j]})")
    ax.axhline(0, color="0.5", lw=0.5)
    ax.set_xlabel("axial position (m)")
    ax.set_ylabel(f"{plane} displacement (–, normalised)")
    ax.set_title(f"{result.model} model at {result.speed_hz:g} Hz")
    ax.legend(loc="best")
    return ax


def deflected_shape(result, speed_hz: float, *, ax=None, system=None):
    """Deflected shape of an unbalance response (:class:`UnbalanceResult`) at the computed
    speed nearest ``speed_hz``: orbits in µm at the output stations."""
    require(len(result.stations) >= 2, "deflected_shape: needs responses at 2 or more stations "
                                       "(unbalance_response(..., stations=[...]))")
    i = int(np.argmin(np.abs(result.speeds_hz - speed_hz)))
    zst = (system.rotor.station_positions_m()[list(result.stations)] if system is not None
           else np.asarray(result.stations, dtype=float))
    ax = orbits_3d(zst, result.x[i], result.y[i], ax=ax, system=None, normalise=False,
                   unit="µm",
                   title=f"unbalance response at {result.speeds_hz[i]:.4g} Hz "
                         f"({60 * result.speeds_hz[i]:.0f} rpm)")
    if system is None:
        ax.set_xlabel("station")
    return ax
