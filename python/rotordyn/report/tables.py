"""Plain-text tables shared by the report's sections (:mod:`rotordyn.report.sections`,
:mod:`rotordyn.report.thermal`): the column layout and the bearings' coefficient rows."""

from __future__ import annotations

import numpy as np

from rotordyn.units import tilt_unit_stem, unit_of

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
# per block (row block, column block: 0 translations, 1 rotations; the units are
# rotordyn.units.tilt_unit_stem's) the printed prefix and its scale
_BLOCKS = (("k", 0, 1, "k", 1e3), ("k", 1, 0, "k", 1e3), ("k", 1, 1, "k", 1e3),
           ("c", 0, 1, "", 1.0), ("c", 1, 0, "", 1.0), ("c", 1, 1, "", 1.0))
_AX = (("x", "y"), ("tx", "ty"))
_SHOW = {"x": "x", "y": "y", "tx": "θx", "ty": "θy"}


def _tilt_cells():
    """[(frame column, header, scale)] of the coupling blocks in the order printed."""
    out = []
    for kc, rb, cb, prefix, scale in _BLOCKS:
        stem = tilt_unit_stem(kc, 2 * rb, 2 * cb)
        shown = prefix + unit_of("_" + stem)
        for i in _AX[rb]:
            for j in _AX[cb]:
                out.append((f"{kc}{i}{j}_{stem}", f"{kc}{_SHOW[i]}{_SHOW[j]} ({shown})", scale))
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
