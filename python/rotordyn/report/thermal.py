"""The report's thermal section (issue 20; docs/film-physics.md): for a model with an oil system
(the model file's ``[thermal]``), the thermal equilibrium of its fluid-film bearings
(:func:`rotordyn.system_thermal_equilibrium`, the model's own thermal model: effective
temperature or THD; one row per plain/active bearing, per pad or per lobe) at a few speeds of
the analysed range — maximum, mean (effective) and inlet temperatures, power loss, film and
supply flows, the journal position, the minimum film of the hot film (the other sections'
films are isothermal) — and each bearing's K, C at that thermal equilibrium with
its temperature field frozen (the coefficients the report's other sections give at the model's
isothermal viscosity). Text and HTML share these tables; ``bearing_thermal.csv`` and
``bearing_thermal_coefficients.csv`` are written beside the figures, ``bearing_thermal.png``
plots, per bearing, the hottest film temperature and the total power loss against speed."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rotordyn._common.status import CONVERGED
from rotordyn.analysis.bearing_coefficients import bearing_coefficients
from rotordyn.analysis.thermal import system_thermal_equilibrium
from rotordyn.errors import InputError, RotordynError
from rotordyn.report.tables import cell

if TYPE_CHECKING:
    import pandas as pd

N_SPEEDS = 5  # speeds of the thermal table, spread over the analysed range
THERMAL_HEADER = ("film", "speed (Hz)", "T_max (°C)", "T_mean (°C)", "T_in (°C)",
                  "power loss (W)", "film flow (L/min)", "supply flow (L/min)", "y (µm)",
                  "h_min (µm)", "status")
L_PER_MIN = 6e4  # m³/s -> L/min


def thermal_speeds(speeds_hz, n: int = N_SPEEDS) -> np.ndarray:
    """``n`` speeds spread over the positive part of the analysed range (Hz): a thermal
    equilibrium needs a turning journal."""
    sp = np.asarray(speeds_hz, dtype=float)
    sp = sp[sp > 0]
    if sp.size == 0:
        return sp
    return np.unique(np.linspace(float(sp.min()), float(sp.max()), min(n, sp.size)))


def thermal_frames(system, speeds_hz, chamber_pressure_pa: float, config_ay_m,
                   ) -> tuple[pd.DataFrame | None, pd.DataFrame | None, str]:
    """(thermal table, coefficients at the thermal equilibria, note) of ``system`` at
    :func:`thermal_speeds`; (None, None, "") without an oil system, (None, None, why) when the
    model's thermal model does not apply to its bearings (the InputError's text). The table is
    :meth:`rotordyn.results.thermal.SystemThermalResult.to_frame` per speed (one row per
    thermal film); the coefficients are :func:`rotordyn.analysis.bearing_coefficients.
    bearing_coefficients` of the returned system (frozen fields) at its own speed (NaN where
    the thermal equilibrium failed: nothing is linearised from a failed one)."""
    import pandas as pd
    if getattr(system, "thermal", None) is None:
        return None, None, ""
    tables, coeffs = [], []
    for f in thermal_speeds(speeds_hz):
        try:
            r = system_thermal_equilibrium(system, speed_hz=float(f),
                                           chamber_pressure_pa=chamber_pressure_pa,
                                           config_ay_m=config_ay_m)
        except InputError as exc:
            return None, None, f"not evaluated: {exc}"
        except RotordynError as exc:  # e.g. a film hotter than the oil law's range: the
            tables.append((float(f), exc))  # speed's rows say so, never a number
            continue
        fr = r.to_frame()
        if r.status not in CONVERGED:
            num = fr.select_dtypes("number").columns.difference(["speed_hz",
                                                                 "supply_temperature_c"])
            fr[num] = np.nan
        tables.append(fr)
        if r.status in CONVERGED:
            coeffs.append(bearing_coefficients(r.system, [float(f)], chamber_pressure_pa,
                                               config_ay_m))
    if not tables:
        return None, None, "not evaluated: no positive speed in the analysed range"
    tables = _failed_rows(system, tables)
    model = tables[0]["thermal_model"].iloc[0]
    note = (f"thermal model {model} ([thermal] of the model file), oil supplied at "
            f"{tables[0]['supply_temperature_c'].iloc[0]:g} °C")
    return (pd.concat(tables, ignore_index=True),
            pd.concat(coeffs, ignore_index=True) if coeffs else None, note)


def _failed_rows(system, tables) -> list:
    """``tables`` with each (speed, error) of a thermal equilibrium that raised replaced by its
    rows: the films of the speeds that converged (else the bearings), NaN numbers, status
    "error" and the error's text."""
    import pandas as pd

    ok = [t for t in tables if not isinstance(t, tuple)]
    names = list(ok[0]["bearing"]) if ok else [b.name or str(i)
                                                 for i, b in enumerate(system.bearings)]
    cols = list(ok[0].columns) if ok else ["speed_hz", "supply_temperature_c", "bearing",
                                           "thermal_model", "effective_temperature_c",
                                           "max_temperature_c", "inlet_temperature_c",
                                           "power_loss_w", "film_flow_m3_s",
                                           "supply_flow_m3_s", "journal_y_m", "h_min_m",
                                           "status", "message"]
    out = []
    for t in tables:
        if not isinstance(t, tuple):
            out.append(t)
            continue
        f, exc = t
        fr = pd.DataFrame({c: np.full(len(names), np.nan) for c in cols})
        fr["speed_hz"] = f
        fr["supply_temperature_c"] = system.thermal.supply_temperature_c
        fr["bearing"] = names
        fr["thermal_model"] = system.thermal.model
        fr["status"] = "error"
        fr["message"] = str(exc)
        out.append(fr)
    return out


def thermal_rows(frame) -> list[tuple]:
    """Table rows (:data:`THERMAL_HEADER`) of a thermal table."""
    return [(d.bearing, f"{d.speed_hz:.4g}", cell(d.max_temperature_c, ".2f"),
             cell(d.effective_temperature_c, ".2f"), cell(d.inlet_temperature_c, ".2f"),
             cell(d.power_loss_w, ".4g"), cell(d.film_flow_m3_s * L_PER_MIN, ".4g"),
             cell(d.supply_flow_m3_s * L_PER_MIN, ".4g"), cell(d.journal_y_m * 1e6, ".4g"),
             cell(d.h_min_m * 1e6, ".4g"), d.status) for d in frame.itertuples(index=False)]


TOTAL_HEADER = ("bearing", "speed (Hz)", "T_max (°C)", "power loss (W)")


def total_rows(frame) -> list[tuple]:
    """Table rows (:data:`TOTAL_HEADER`) of :func:`bearing_totals`."""
    return [(d.bearing, f"{d.speed_hz:.4g}", cell(d.max_temperature_c, ".2f"),
             cell(d.power_loss_w, ".4g"))
            for d in bearing_totals(frame).itertuples(index=False)]


def bearing_totals(frame) -> pd.DataFrame:
    """Per bearing (the part of a film name before ``.pad<k>``/``.lobe<k>``) and speed: the
    hottest film temperature (°C) and the total power loss (W)."""
    bearing = frame["bearing"].str.replace(r"\.(pad|lobe)\d+$", "", regex=True)
    g = frame.assign(bearing=bearing).groupby(["bearing", "speed_hz"], sort=False)
    return g.agg(max_temperature_c=("max_temperature_c", "max"),
                 power_loss_w=("power_loss_w", lambda x: x.sum(min_count=1))  # NaN: failed
                 ).reset_index()


def thermal_text_lines(frame, coeffs, note: str) -> list[str]:
    """The text report's thermal section (nothing without an oil system)."""
    from rotordyn.report.tables import COEFFICIENT_HEADER, _text_table, coefficient_rows

    if frame is None:
        return ["", f"bearing temperatures: {note}"] if note else []
    lines = ["", f"bearing temperatures and power loss at the thermal equilibrium ({note}; "
             "bearing_thermal.csv/.png)"]
    lines += _text_table(THERMAL_HEADER, thermal_rows(frame))
    lines += ["", "per bearing (its films together: the hottest, the total power loss)"]
    lines += _text_table(TOTAL_HEADER, total_rows(frame))
    if coeffs is not None and not coeffs.empty:
        lines += ["", "bearing coefficients at the thermal equilibrium (temperature field "
                  "frozen; bearing_thermal_coefficients.csv)"]
        lines += _text_table(COEFFICIENT_HEADER, coefficient_rows(coeffs))
    return lines


def thermal_html(frame, coeffs, note: str, svg, table) -> str:
    """The HTML report's section 2c ("" without an oil system): the figure, the per-bearing
    totals, the per-film table and K, C at the thermal equilibrium. ``svg(fig)``: a figure as
    inline SVG; ``table(header, rows)``: an HTML table (rotordyn.report.html's helpers)."""
    import html

    from rotordyn.report.tables import COEFFICIENT_HEADER, coefficient_rows

    def tab(header, rows):
        return table(header, [tuple(html.escape(str(c)) for c in r) for r in rows])
    head = "<h2>2c. Bearing temperatures and power loss</h2>"
    if frame is None:
        return head + f"<p class=\"nr\">{html.escape(note)}</p>" if note else ""
    sec = [head, f"<p>At the thermal equilibrium ({html.escape(note)}): one row per thermal "
           "film (pad, lobe). The other sections analyse the model's isothermal films.</p>",
           "<figure>" + svg(thermal_figure(frame)) + "<figcaption>Per bearing: the hottest "
           "film temperature and the total power loss of its films against speed."
           "</figcaption></figure>", tab(TOTAL_HEADER, total_rows(frame)),
           tab(THERMAL_HEADER, thermal_rows(frame))]
    if coeffs is not None and not coeffs.empty:
        sec += ["<p>Bearing coefficients at the thermal equilibrium (temperature field frozen "
                "there; section 2b: the model's isothermal films).</p>",
                tab(COEFFICIENT_HEADER, coefficient_rows(coeffs))]
    return "".join(sec)


def thermal_figure(frame):
    """Per bearing: the hottest film temperature (°C) and the total power loss (W) against
    speed (Hz) (:func:`rotordyn.plot.thermal.bearing_temperatures`); a matplotlib Figure."""
    from rotordyn.plot.thermal import bearing_temperatures

    return bearing_temperatures(bearing_totals(frame))


def write_thermal(frame, coeffs, outdir) -> None:
    """``bearing_thermal.csv``, ``bearing_thermal_coefficients.csv`` and
    ``bearing_thermal.png`` under ``outdir`` (nothing without a table)."""
    from pathlib import Path

    import matplotlib.pyplot as plt

    if frame is None:
        return
    outdir = Path(outdir)
    frame.to_csv(outdir / "bearing_thermal.csv", index=False)
    if coeffs is not None:
        coeffs.to_csv(outdir / "bearing_thermal_coefficients.csv", index=False)
    fig = thermal_figure(frame)
    fig.savefig(outdir / "bearing_thermal.png", dpi=200, bbox_inches="tight")
    plt.close(fig)


__all__ = ["N_SPEEDS", "THERMAL_HEADER", "TOTAL_HEADER", "bearing_totals", "thermal_figure",
           "thermal_frames", "thermal_html", "thermal_rows", "thermal_speeds",
           "thermal_text_lines", "total_rows", "write_thermal"]
