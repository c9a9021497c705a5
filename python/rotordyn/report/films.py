"""The report's film table: each fluid-film bearing's minimum film at the equilibrium over
speed, where it sits, and with ``tilt = true`` the edge it moves to, the journal's tilt in
the housing and the films' moments (issue 20; docs/film-physics.md)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from rotordyn._common.status import CONVERGED
from rotordyn.report.tables import MISSING, _text_table, cell

TILT_COLUMNS = ("h_min_z_m", "journal_theta_x_rad", "journal_theta_y_rad",
                "config_theta_x_rad", "config_theta_y_rad", "film_moment_x_n_m",
                "film_moment_y_n_m")


def film_frame(system, equilibria) -> pd.DataFrame:
    """One row per fluid-film bearing (clearance > 0) and speed of ``equilibria`` (the
    ``(speed_hz, status, EquilibriumResult | None)`` that
    :func:`rotordyn.analysis.bearing_coefficients.bearing_coefficients` collects, so the table
    and the coefficients share their operating points): ``eccentricity_ratio``, ``h_min_m``,
    ``h_min_angle_deg`` and, when a bearing has ``tilt = true``, the :data:`TILT_COLUMNS`
    (NaN for its untilted neighbours); ``status`` of the equilibrium (not converged or raised:
    NaN outputs). Empty without fluid-film bearings."""
    films = [(i, getattr(b, "name", "") or f"bearing[{i}]")
             for i, b in enumerate(system.bearings) if getattr(b, "clearance_m", 0.0) > 0.0]
    tilted = any(getattr(b, "tilt", False) for b in system.bearings)
    rows = []
    for sp, status, e in equilibria if films else ():
        ok = e is not None and status in CONVERGED  # as the coefficients beside it
        for i, name in films:
            row = {"bearing": name, "speed_hz": float(sp), "eccentricity_ratio": math.nan,
                   "h_min_m": math.nan, "h_min_angle_deg": math.nan, "status": status}
            t = e.tilt.get(i, {}) if ok else {}
            if ok:
                row.update(eccentricity_ratio=float(e.eccentricity_ratio[i]),
                           h_min_m=float(e.h_min_m[i]),
                           h_min_angle_deg=float(e.h_min_angle_deg[i]))
            for k in TILT_COLUMNS if tilted else ():
                row[k] = float(t[k]) if k in t else math.nan
            rows.append(row)
    return pd.DataFrame(rows)


def _where(z, length):
    """The minimum film's axial place: "edge ±" at an end of a bearing of ``length`` (m; 0:
    unknown), else its z in mm."""
    if not np.isfinite(z):
        return MISSING
    if length and abs(abs(z) - 0.5 * length) <= 1e-9 * length:
        return "edge +" if z > 0 else "edge −"
    return f"{1e3 * z:.1f} mm"


def film_rows(frame: pd.DataFrame, lengths: dict | None = None):
    """(header, rows of strings) of the film table; ``lengths``: bearing name → length (m),
    to name an end as "edge"."""
    tilt = "film_moment_y_n_m" in frame
    head = ["bearing", "speed (Hz)", "ε", "h_min (µm)", "at φ (deg)"]
    if tilt:
        head += ["at z", "tilt θx, θy (mrad)", "M_x (N·m)", "M_y (N·m)"]
    head.append("status")
    body = []
    for r in frame.itertuples(index=False):
        cells = [r.bearing, f"{r.speed_hz:.4g}", cell(r.eccentricity_ratio, ".3f"),
                 cell(1e6 * r.h_min_m, ".2f"), cell(r.h_min_angle_deg, ".0f")]
        if tilt:
            cells += [_where(r.h_min_z_m, (lengths or {}).get(r.bearing, 0.0)),
                      MISSING if not np.isfinite(r.journal_theta_x_rad) else
                      f"{1e3 * r.journal_theta_x_rad:.3f}, {1e3 * r.journal_theta_y_rad:.3f}",
                      cell(r.film_moment_x_n_m, ".4g"), cell(r.film_moment_y_n_m, ".4g")]
        cells.append(str(r.status))
        body.append([str(c) for c in cells])
    return head, body


def _what(frame) -> str:
    return ("minimum film at the equilibrium and where it sits (φ from +x towards +y"
            + ("; with tilt = true: its axial place, the journal's tilt in the housing and "
               "the films' moments on the journal" if "film_moment_y_n_m" in frame else "")
            + "; bearing_films.csv)")


def film_text_lines(frame: pd.DataFrame, lengths: dict | None = None) -> list[str]:
    """The text report's film table (none for an empty frame)."""
    if frame.empty:
        return []
    head, body = film_rows(frame, lengths)
    return ["", "bearing films: " + _what(frame)] + _text_table(head, body)


def film_html(frame: pd.DataFrame, table, lengths: dict | None = None) -> str:
    """The HTML report's section 2d (``table(header, rows)``: the report's table writer)."""
    import html

    if frame.empty:
        return ""
    head, body = film_rows(frame, lengths)
    return ("<h2>2d. Bearing films at the equilibrium</h2><p>" + html.escape(_what(frame))
            + "</p>" + table(head, [tuple(html.escape(c) for c in b) for b in body]))


def write_films(system, equilibria, outdir):
    """The film frame of ``equilibria`` (:func:`film_frame`), written as ``bearing_films.csv``
    under ``outdir`` (None: not written); returns (frame, lengths by bearing name)."""
    from pathlib import Path

    fr = film_frame(system, equilibria)
    if outdir is not None and not fr.empty:
        fr.to_csv(Path(outdir) / "bearing_films.csv", index=False)
    return fr, {getattr(b, "name", ""): getattr(b, "length_m", 0.0) for b in system.bearings}


__all__ = ["TILT_COLUMNS", "film_frame", "film_html", "film_rows", "film_text_lines",
           "write_films"]
