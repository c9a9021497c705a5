"""Plain-text tables shared by the report's sections (:mod:`rotordyn.report.sections`,
:mod:`rotordyn.report.thermal`): the column layout and the bearings' coefficient rows."""

from __future__ import annotations

import numpy as np

# the one marker of a missing value (a failed point, a column a row does not have) in every
# table of the report, text and HTML
MISSING = "n/a"


def cell(x, fmt: str) -> str:
    """``x`` formatted by ``fmt``, :data:`MISSING` when it is not finite (NaN, inf)."""
    return format(x, fmt) if np.isfinite(x) else MISSING


def _text_table(header, rows) -> list[str]:
    """The text report's table layout: columns left-aligned to their widest cell, two spaces
    apart, indented by two."""
    w = [max(len(str(h)), *(len(str(r[i])) for r in rows)) for i, h in enumerate(header)]
    return ["  " + "  ".join(f"{str(c):<{w[i]}}" for i, c in enumerate(r))
            for r in [tuple(header), *rows]]


def coefficient_rows(frame) -> list[tuple]:
    """Table rows: bearing, speed (Hz), kxx … kyy (MN/m), cxx … cyy (kN·s/m), status."""
    rows = []
    for r in frame.itertuples(index=False):
        d = r._asdict()
        ks = [d[f"k{p}_n_per_m"] / 1e6 for p in ("xx", "xy", "yx", "yy")]
        cs = [d[f"c{p}_n_s_per_m"] / 1e3 for p in ("xx", "xy", "yx", "yy")]
        rows.append((d["bearing"], f"{d['speed_hz']:.4g}",
                     *(cell(x, ".4g") for x in ks + cs), d["status"]))
    return rows


COEFFICIENT_HEADER = ("bearing", "speed (Hz)", "kxx (MN/m)", "kxy (MN/m)", "kyx (MN/m)",
                      "kyy (MN/m)", "cxx (kN·s/m)", "cxy (kN·s/m)", "cyx (kN·s/m)",
                      "cyy (kN·s/m)", "status")


__all__ = ["COEFFICIENT_HEADER", "MISSING", "cell", "coefficient_rows"]
