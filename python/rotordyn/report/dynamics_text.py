"""The text report's unbalance response and stability screen (report.txt), the text form of
the HTML report's sections 4, 4b, 5 and 5a: per output station the resonance peaks of the API
unbalance response with their separation margins and the API 617 amplitude checks, and the
least damped screened forward rotor mode at a few speeds, each block labelled with the films
it is on (isothermal, or thermal films: every speed at its own thermal equilibrium, the
temperature field frozen). A speed without a thermal equilibrium is listed and written "no
thermal equilibrium", never a number.

Only rendering: the rows come from :mod:`rotordyn.report.thermal_dynamics`, which computes
them once for both reports (the checks go into the report's one
:class:`~rotordyn.report.criteria.Checks`)."""

from __future__ import annotations

import numpy as np

from rotordyn.report.tables import _text_table

PEAK_HEADER = ("N_c (Hz)", "peak (µm)", "AF", "SM (%)", "required (%)", "result")


def verdict_text(ok) -> str:
    """PASS / FAIL / n/a / the verdict's own words ("not resolved", "not evaluated ...")."""
    return "n/a" if ok is None else ok if isinstance(ok, str) else "PASS" if ok else "FAIL"


def check_line(row, indent: str = "    ", films: str = "") -> str:
    """One check row (name, criterion, value, verdict) as ``RESULT  name [films]: value``."""
    name, _, value, ok = row
    return f"{indent}{verdict_text(ok):<12} {name}" + (f" [{films}]" if films else "") \
        + f": {value}"


def response_head(films: str, u_kgm: float, where: str, n_mc_hz: float) -> list[str]:
    """The heading of an unbalance response block (``films``: "" without an oil system)."""
    on = f" on {films}" if films else ""
    return ["", f"unbalance response{on}: API 684 unbalance U = {u_kgm * 1e6:.4g} g·mm {where}"
            f" (N = N_mc = {60 * n_mc_hz:.0f} rpm); per output station its resonance peaks "
            "with the separation margins (AF < 1: no resonance, no margin) and the API 617 "
            "amplitude checks"]


def unstable_line(bad) -> list[str]:
    """The warning for the linearly unstable speeds ``bad`` (Hz) of a response ([] if none)."""
    if not len(bad):
        return []
    where = f"{bad[0]:.4g} Hz" if len(bad) == 1 else f"{bad[0]:.4g}–{bad[-1]:.4g} Hz"
    return [f"  linearly unstable at {len(bad)} of the speeds ({where}): the response there is "
            "not a steady orbit and is left out of the amplitude checks"]


def failed_line(failed, n: int) -> list[str]:
    """The speeds (Hz) without a thermal equilibrium among ``n`` ([] if none)."""
    if not len(failed):
        return []
    return [f"  no thermal equilibrium at {len(failed)} of {n} speeds (not linearised: no "
            "response, no eigenvalues there): " + ", ".join(f"{f:.4g}" for f in failed) + " Hz"]


def station_lines(station: int, rows, amplitude) -> list[str]:
    """One output station: its peaks ``rows`` (N_c Hz, peak m, AF text, SM %, required %,
    verdict) as a table, then the ``amplitude`` check rows."""
    if rows:
        out = [f"  station {station}: {len(rows)} resonance peak(s)"]
        out += ["  " + x for x in _text_table(PEAK_HEADER, [
            (f"{nc:.4g}", f"{pk * 1e6:.3g}", aft, f"{sm:.1f}" if np.isfinite(sm) else "n/a",
             ("none" if req == 0 else f"{req:.1f}") if np.isfinite(req) else "n/a",
             verdict_text(v)) for nc, pk, aft, sm, req, v in rows])]
    else:
        out = [f"  station {station}: no resonance peak in the speed range"]
    return out + [check_line(r) for r in amplitude]


def stability_head(films: str, window_hz: float, thermal: bool) -> list[str]:
    """The heading of the stability block (``thermal``: both films side by side)."""
    on = (" on isothermal and thermal films" if thermal else f" on {films}" if films else "")
    return ["", f"stability{on}: the least damped forward rotor mode below {window_hz:.4g} Hz "
            "(screened: backward modes, roots damped beyond δ = 2π (no resonance) and round-off "
            "|δ| < 1e-6 left out) at up to 11 speeds; "
            "screening δ > 0.1 in the operating range, δ ≥ 0 over the range"]


def log_dec_lines(header, rows, checks_added) -> list[str]:
    """The least damped mode table and the screening checks added for it (``checks_added``:
    (check row, films) pairs)."""
    return _text_table(header, rows) + [check_line(r, "  ", f) for r, f in checks_added]


__all__ = ["PEAK_HEADER", "check_line", "failed_line", "log_dec_lines", "response_head",
           "stability_head", "station_lines", "unstable_line", "verdict_text"]
