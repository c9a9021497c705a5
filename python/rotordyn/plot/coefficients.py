"""Bearing stiffness and damping coefficients against speed (the frame of
:func:`rotordyn.analysis.bearing_coefficients.bearing_coefficients` or of a
``CoefficientTable.to_frame()``): direct and cross-coupled kxx … cyy, one colour per
coefficient, one line style per bearing, in MN/m and kN·s/m."""

from __future__ import annotations

import numpy as np

from rotordyn.plot._style import COLUMN_IN, paper_style, require

COEFF_COLOR = {"xx": "C0", "yy": "C1", "xy": "C2", "yx": "C3"}
BEARING_STYLE = ("-", "--", ":", "-.")


@paper_style
def bearing_coefficients(frame, *, title: str | None = None):
    """Two panels over ``speed_hz``: stiffness (MN/m) above, damping (kN·s/m) below; returns
    the figure. ``frame``: columns ``speed_hz``, ``k??_n_per_m``, ``c??_n_s_per_m`` and
    optionally ``bearing`` (one line style per bearing; bearings with identical coefficients
    are drawn once and named together)."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    need = {"speed_hz"} | {f"k{p}_n_per_m" for p in COEFF_COLOR} | \
        {f"c{p}_n_s_per_m" for p in COEFF_COLOR}
    require(need <= set(frame.columns), "bearing_coefficients: expected columns speed_hz, "
            "kxx_n_per_m … kyy_n_per_m, cxx_n_s_per_m … cyy_n_s_per_m")
    require(len(frame) > 0, "bearing_coefficients: the frame has no rows")
    groups = (list(frame.groupby("bearing", sort=False)) if "bearing" in frame.columns
              else [("bearing", frame)])
    # bearings with the same coefficients at every speed (a symmetric rotor) share a line
    drawn: list[tuple[list[str], object]] = []
    for name, g in groups:
        vals = g.sort_values("speed_hz")[sorted(need)].to_numpy(dtype=float)
        for names, other in drawn:
            if other.shape == vals.shape and np.allclose(other, vals, rtol=1e-9,
                                                         equal_nan=True):
                names.append(str(name))
                break
        else:
            drawn.append(([str(name)], vals))
    fig, (ak, ac) = plt.subplots(2, 1, figsize=(COLUMN_IN * 1.6, COLUMN_IN * 1.15),
                                 sharex=True, layout="constrained")
    for b, (name, g) in enumerate(groups):
        owner = next(i for i, (names, _) in enumerate(drawn) if str(name) in names)
        if drawn[owner][0][0] != str(name):
            continue
        g = g.sort_values("speed_hz")
        ls = BEARING_STYLE[owner % len(BEARING_STYLE)]
        for p, col in COEFF_COLOR.items():
            ak.plot(g["speed_hz"], g[f"k{p}_n_per_m"] / 1e6, color=col, ls=ls, marker=".",
                    ms=3)
            ac.plot(g["speed_hz"], g[f"c{p}_n_s_per_m"] / 1e3, color=col, ls=ls, marker=".",
                    ms=3)
    for a in (ak, ac):
        a.axhline(0, color="0.5", lw=0.5)
    ak.set_ylabel("stiffness (MN/m)")
    ac.set_ylabel("damping (kN·s/m)")
    ac.set_xlabel("rotor speed (Hz)")
    handles = [Line2D([], [], color=c, label=f"k{p}, c{p}") for p, c in COEFF_COLOR.items()]
    if len(groups) > 1:
        handles += [Line2D([], [], color="k", ls=BEARING_STYLE[i % len(BEARING_STYLE)],
                           label=" = ".join(names)) for i, (names, _) in enumerate(drawn)]
    fig.legend(handles=handles, loc="outside right upper", fontsize=6)
    ak.set_title(title or "bearing coefficients (dF = −K dq − C dq̇)")
    return fig


__all__ = ["bearing_coefficients"]
