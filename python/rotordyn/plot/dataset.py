"""Figures from sweep datasets (``rotordyn plot DIR --kind ...``): each kind checks that the
dataset holds what it needs and says so in one line (InputError, exit 2) otherwise."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rotordyn.plot._style import require
from rotordyn.plot.cascade import waterfall
from rotordyn.plot.frequency import campbell_arrays
from rotordyn.plot.maps import equilibrium_loci, select, stability_map, varying

if TYPE_CHECKING:
    import pandas as pd

KINDS = ("stability-map", "equilibrium", "campbell", "waterfall")
KINDS += ("hopf-map",)
WHIRL_CODE = {"forward": 1, "backward": -1, "planar": 0}


def campbell(df: pd.DataFrame, ax=None, rotor_only: bool = True, where=None):
    """Campbell diagram from a stability sweep over speed (modes by their ``mode_id`` when
    tracked, else by their slot), coloured by log decrement. Any other varying axis must be
    fixed with ``where`` = {axis: value}: it is never averaged over."""
    require({"freq_hz", "log_dec", "whirl"} <= set(df.columns),
            "campbell: the dataset has no modes (freq_hz, log_dec, whirl); run a stability "
            "sweep over speed_hz")
    df = select(df, where, "campbell")
    others = [c for c in varying(df) if c != "speed_hz"]
    require(not others, f"campbell: expected speed_hz as the only varying axis, also varying: "
                        f"{others}; fix them with where={{axis: value}} (CLI: --where AXIS=VALUE)")
    d = df[df["status"] == "ok"]
    if rotor_only and "kind" in d:
        d = d[d["kind"] == "rotor"]
    speeds = np.sort(d["speed_hz"].unique())
    require(speeds.size >= 2, f"campbell: needs a sweep over 2 or more speeds, got "
                              f"{speeds.size} (a one-speed sweep has no Campbell diagram)")
    key = "mode_id" if "mode_id" in d else "mode"
    d = d.assign(_w=d["whirl"].astype(str).map(WHIRL_CODE).astype(float))
    piv = {c: d.pivot_table(index="speed_hz", columns=key, values=c).reindex(speeds)
           for c in ("freq_hz", "log_dec", "_w")}
    return campbell_arrays(speeds, piv["freq_hz"].to_numpy(), piv["log_dec"].to_numpy(),
                           piv["_w"].to_numpy(), ax=ax, critical=None)


def plot_dataset(df: pd.DataFrame, kind: str, out: str, dpi: int = 200, **kwargs) -> str:
    """Draw ``kind`` from a sweep dataset and save it to ``out`` (PNG or SVG, ``dpi``)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    require(kind in KINDS, f"--kind: expected one of {KINDS}, got {kind!r}")
    require(str(out).lower().endswith((".png", ".svg", ".pdf")),
            f"--out: expected a .png, .svg or .pdf file name, got {out!r}")
    from rotordyn.plot.hopf_map import hopf_map

    fn = {"stability-map": stability_map, "equilibrium": equilibrium_loci,
          "campbell": campbell, "waterfall": waterfall, "hopf-map": hopf_map}[kind]
    where = kwargs.pop("where", None)
    if kind == "waterfall":  # its speed axis is the only one drawn: the others fixed first
        df = select(df, where, "waterfall")
    else:
        kwargs["where"] = where
    ax = fn(df, **kwargs)
    # the paper style's tight bounding box (its rc applies while drawing, not here): a 3-D
    # cascade's frequency label hangs below the figure and was cut off in the file
    ax.figure.savefig(out, dpi=dpi, bbox_inches="tight")
    plt.close(ax.figure)
    return out
