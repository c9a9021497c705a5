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


# A tilting film's coupling blocks (rotordyn.analysis.bearing_coefficients.TILT_COLUMNS):
# per block its column stem, its SI unit in the column name, the printed unit and scale
_BLOCKS = (("k", "xy", "t", "n_per_rad", "kN/rad", 1e3),
           ("k", "t", "xy", "n_m_per_m", "kN·m/m", 1e3),
           ("k", "t", "t", "n_m_per_rad", "kN·m/rad", 1e3),
           ("c", "xy", "t", "n_s_per_rad", "N·s/rad", 1.0),
           ("c", "t", "xy", "n_m_s_per_m", "N·m·s/m", 1.0),
           ("c", "t", "t", "n_m_s_per_rad", "N·m·s/rad", 1.0))
_AX = {"xy": ("x", "y"), "t": ("tx", "ty")}
_SHOW = {"x": "x", "y": "y", "tx": "θx", "ty": "θy"}


def _tilt_cells():
    """[(frame column, header, scale)] of the coupling blocks in the order printed."""
    out = []
    for kc, rows, cols, unit, shown, scale in _BLOCKS:
        for i in _AX[rows]:
            for j in _AX[cols]:
                out.append((f"{kc}{i}{j}_{unit}", f"{kc}{_SHOW[i]}{_SHOW[j]} ({shown})", scale))
    return out


def tilt_coefficient_tables(frame) -> list[tuple[tuple, list[tuple]]]:
    """The tilting films' coupling blocks of the 4×4 K, C over (x, y, θx, θy) (force–tilt,
    moment–translation, tilt–tilt; the translational block is the main table's) as two
    tables, K then C: [(header, rows)], rows only for the bearings with a tilting film;
    [] when the frame has none (an untilted model's report is unchanged)."""
    cells = _tilt_cells()
    if frame.empty or cells[0][0] not in frame:
        return []
    names = frame.loc[frame[[c for c, _, _ in cells]].notna().any(axis=1), "bearing"]
    tilted = frame[frame["bearing"].isin(set(names))]  # every speed of those bearings
    if tilted.empty:
        return []
    out = []
    for kc in ("k", "c"):
        part = [c for c in cells if c[0].startswith(kc)]
        rows = []
        for r in tilted.itertuples(index=False):
            d = r._asdict()
            rows.append((d["bearing"], f"{d['speed_hz']:.4g}",
                         *(cell(d[c] / sc, ".4g")
                           for c, _, sc in part), d["status"]))
        out.append((("bearing", "speed (Hz)", *(h for _, h, _ in part), "status"), rows))
    return out


__all__ = ["COEFFICIENT_HEADER", "MISSING", "cell", "coefficient_rows", "tilt_coefficient_tables"]
