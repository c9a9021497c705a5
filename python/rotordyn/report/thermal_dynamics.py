"""The HTML report's unbalance response (section 4) and stability (section 5) on thermal films
(a model with an oil system, ``[thermal]``; docs/film-physics.md, "Dynamics at each point's own
thermal equilibrium"): every speed at its own thermal equilibrium, the temperature field
frozen. Nothing is computed twice: the results are section 3c's
(:func:`rotordyn.report.sections.thermal_dynamics`): its Campbell diagram gives the log
decrements, its API unbalance response the Bode data. Shown beside the isothermal results, the
API checks evaluated on both (the checks table's "films" column); a speed whose thermal
equilibrium failed is marked (× on the speed axis, listed), never plotted as a number.

The figure helpers of :mod:`rotordyn.report.html` (``svg``, ``table``, ``verdict``, the log
decrement figure) are passed in: this module sits below it. The same rows as text (report.txt:
:mod:`rotordyn.report.dynamics_text`): the HTML functions fill a ``text`` list beside their
HTML from the rows they computed, and :func:`text_sections` gives the text alone (the text
report without ``--html``), adding the same checks in the same order."""

from __future__ import annotations

import html

import numpy as np

from rotordyn._common.status import CONVERGED
from rotordyn.report import dynamics_text as txt
from rotordyn.report.criteria import (NOT_RESOLVED, amplitude_checks, separation_checks,
                                      stability_screen)

THERMAL = "thermal films"
ISOTHERMAL = "isothermal films"
PEAK_HEADER = ["N_c (Hz)", "peak (µm)", "AF", "SM (%)", "required (%)", "result"]


def no_thermal_equilibrium(result) -> np.ndarray:
    """Speeds (Hz) of ``result`` (a thermal Campbell or unbalance result: its ``thermal`` per
    speed) whose thermal equilibrium failed or raised, or whose system equilibrium on the
    frozen field did (never linearised: NaN rows)."""
    th = getattr(result, "thermal", ())
    if not th:
        return np.empty(0)
    bad = [t is None or t.status not in CONVERGED for t in th]
    ps = getattr(result, "point_status", None)
    if ps is not None:  # the dynamics need the frozen field's equilibrium too
        bad = [b or str(p) not in CONVERGED for b, p in zip(bad, ps)]
    return np.asarray(result.speeds_hz, dtype=float)[np.asarray(bad, dtype=bool)]


def mark_failed(ax, failed_hz) -> None:
    """× on the speed axis of ``ax`` at each speed without a thermal equilibrium (in the axes'
    own legend), no number drawn there."""
    if len(failed_hz) == 0:
        return
    ln, = ax.plot(failed_hz, np.zeros(len(failed_hz)), "x", color="tab:red", ms=5, mew=1.2,
                  clip_on=False, transform=ax.get_xaxis_transform(),
                  label="no thermal equilibrium (not computed)")
    ax.legend(handles=[ln], loc="lower right", fontsize=6)


def failed_text(failed_hz) -> str:
    """The caption's sentence on the speeds without a thermal equilibrium ("" when none)."""
    if len(failed_hz) == 0:
        return ""
    return (f" × on the speed axis: {len(failed_hz)} speed(s) without a thermal equilibrium "
            "(not linearised, not plotted): " + ", ".join(f"{f:.4g}" for f in failed_hz)
            + " Hz.")


def station_checks(u, checks, station: int, n_mc_hz: float, clearance_m,
                   films: str = "") -> tuple[list, list]:
    """The peaks of ``u`` (UnbalanceResult) at ``station`` with the API 684 separation margins
    and the API 617 amplitude checks, added to ``checks`` under ``films`` ("" without an oil
    system, else :data:`THERMAL` or :data:`ISOTHERMAL`). Returns (the peaks table's rows, the
    amplitude check rows added) — what the HTML and the text report both show."""
    checks.films = films
    rows = separation_checks(checks, u, station)
    n0 = len(checks.rows)
    amplitude_checks(checks, u, station, n_mc_hz, clearance_m)
    return rows, checks.rows[n0:]


def station_html(u, checks, station: int, n_mc_hz: float, clearance_m, svg, table, verdict,
                 films: str = "", text: list | None = None) -> list[str]:
    """One output station of section 4: the Bode plot of ``u`` (UnbalanceResult), its peaks
    with the API 684 separation margins and the API 617 amplitude checks
    (:func:`station_checks`; the Bode title and the checks table say which films). ``text``:
    a list that also gets the station's text lines (:func:`rotordyn.report.dynamics_text.
    station_lines`) from the same rows."""
    from rotordyn.plot import bode

    rows, added = station_checks(u, checks, station, n_mc_hz, clearance_m, films)
    a1, _ = bode(u, station=station)
    failed = no_thermal_equilibrium(u)
    if films:
        a1.set_title(f"unbalance response at station {station}, {films}", fontsize=8)
    mark_failed(a1, failed)
    out = [f"<figure>{svg(a1.figure)}<figcaption>Station {station}"
           + (f", {films}" if films else "") + "." + failed_text(failed)
           + "</figcaption></figure>"]
    if rows:
        out.append(table(PEAK_HEADER, [
            (f"{nc:.4g}", f"{pk * 1e6:.3g}", html.escape(aft),
             f"{sm:.1f}" if np.isfinite(sm) else "n/a",
             ("none" if req == 0 else f"{req:.1f}") if np.isfinite(req) else "n/a",
             verdict(v)) for nc, pk, aft, sm, req, v in rows]))
    else:
        out.append(f"<p>Station {station}" + (f" ({films})" if films else "")
                   + ": no resonance peak in the speed range.</p>")
    if text is not None:
        text += txt.station_lines(station, rows, added)
    return out


def unstable_speeds(u, checks) -> np.ndarray:
    """The speeds (Hz) where ``u``'s equilibrium is linearly unstable, with their check (speeds
    without a thermal equilibrium are not counted: nothing was linearised there)."""
    ok = np.isin(u.point_status, CONVERGED)
    bad = u.speeds_hz[~u.stable & ok]
    if bad.size:
        checks.add("linear stability over the speed range", "every speed below the threshold "
                   "of instability", f"unstable from {bad[0]:.4g} Hz", False)
    return bad


def unstable_html(u, checks, text: list | None = None) -> str:
    """The warning and check of the speeds where ``u``'s equilibrium is linearly unstable
    (:func:`unstable_speeds`); ``text`` also gets the warning as text."""
    bad = unstable_speeds(u, checks)
    if text is not None:
        text += txt.unstable_line(bad)
    if not bad.size:
        return ""
    return (f"<p class=\"fail\">The equilibrium is linearly unstable at {bad.size} of the "
            f"speeds ({bad[0]:.4g}–{bad[-1]:.4g} Hz): there the response is not a steady "
            "orbit and is left out of the amplitude checks.</p>")


def equilibrium_check(checks, result, what: str) -> None:
    """The check "thermal equilibrium at every speed of ``what``": not resolved when any speed
    of ``result`` failed (its dynamics are missing there), else passed (every speed's
    dynamics are there)."""
    failed = no_thermal_equilibrium(result)
    n = len(result.speeds_hz)
    checks.add(f"thermal equilibrium at every speed of {what}", "each speed's thermal "
               "equilibrium converged (else its dynamics are missing)",
               (f"{len(failed)} of {n} speeds failed: " + ", ".join(f"{f:.4g}" for f in failed)
                + " Hz") if len(failed) else f"all {n} speeds converged",
               NOT_RESOLVED if len(failed) else True)


def response_html(u, checks, outs, n_mc_hz: float, clear: dict, svg, table, verdict,
                  text: list | None = None) -> str:
    """Section 4 on thermal films: ``u`` the thermal API unbalance response of section 3c;
    ``text`` also gets its text lines (after a heading the caller wrote)."""
    checks.films = THERMAL
    parts = ["<h2>4b. Unbalance response on thermal films</h2><p>The same API unbalance with "
             "every speed at its own thermal equilibrium, the temperature field frozen (the "
             "response of section 3c); the API checks below are evaluated on these films too "
             "(checks table: column \"films\").</p>", unstable_html(u, checks, text)]
    equilibrium_check(checks, u, "the unbalance response")
    if text is not None:
        text += txt.failed_line(no_thermal_equilibrium(u), len(u.speeds_hz))
    for st in outs:
        parts += station_html(u, checks, st, n_mc_hz, clear.get(st), svg, table, verdict,
                              THERMAL, text)
    return "".join(parts)


def least_damped(c, ld, speed_hz: float) -> tuple[float, float] | None:
    """(damped frequency Hz, δ) of the least damped screened forward rotor mode of ``c`` at
    ``speed_hz`` (``ld``: :func:`~rotordyn.report.criteria.stability_screen`'s δ); None when
    the speed is not in ``c`` or has no screened mode there."""
    i = np.flatnonzero(np.isclose(c.speeds_hz, speed_hz, rtol=1e-12, atol=0.0))
    if not i.size or not np.isfinite(ld[i[0]]).any():
        return None
    j = int(np.nanargmin(ld[i[0]]))
    return float(c.frequencies_hz[i[0], j]), float(ld[i[0], j])


LOG_DEC_HEADER = ("speed (Hz)", "isothermal films: mode (Hz)", "isothermal films: δ",
                  "thermal films: mode (Hz)", "thermal films: δ")
LOG_DEC_HEADER_ONE = ("speed (Hz)", "mode (Hz)", "δ")  # one film (no oil system)


def log_dec_rows(iso, iso_ld, c, ld, n: int = 11) -> list[tuple[str, ...]]:
    """Rows of :data:`LOG_DEC_HEADER` at ``n`` speeds spread over the thermal Campbell diagram
    ``c``: the least damped screened forward mode on isothermal (``iso``, ``iso_ld``) and on
    thermal films; a speed without a thermal equilibrium says so, never a number. ``c`` None:
    rows of :data:`LOG_DEC_HEADER_ONE` over ``iso``'s speeds alone."""
    ref = iso if c is None else c
    failed = set(no_thermal_equilibrium(c).tolist()) if c is not None else set()
    sp = ref.speeds_hz[np.unique(np.linspace(0, ref.speeds_hz.size - 1,
                                             min(n, ref.speeds_hz.size)).round().astype(int))]
    rows = []
    for f in sp:
        a = least_damped(iso, iso_ld, f)
        row = (f"{f:.4g}",) + ((f"{a[0]:.4g}", f"{a[1] + 0.0:.4g}") if a else ("–",) * 2)
        if c is not None:
            b = least_damped(c, ld, f)
            row += (("no thermal equilibrium",) * 2 if float(f) in failed else
                    (f"{b[0]:.4g}", f"{b[1] + 0.0:.4g}") if b else ("–",) * 2)
        rows.append(row)
    return rows


def stability_checks(c, checks, window_hz: float, op_range) -> tuple[np.ndarray, list]:
    """The thermal Campbell diagram ``c``'s checks under :data:`THERMAL`: every speed's thermal
    equilibrium and the screening (:func:`rotordyn.report.criteria.stability_screen`). Returns
    (its screened δ, the check rows added with their films)."""
    checks.films = THERMAL
    n0 = len(checks.rows)
    equilibrium_check(checks, c, "the Campbell diagram")
    ld = stability_screen(checks, c, window_hz, op_range)
    return ld, list(zip(checks.rows[n0:], checks.films_of[n0:]))


def stability_html(c, checks, window_hz: float, op_range, svg, log_dec_figure, table,
                   iso, iso_ld, text: list | None = None, iso_checks=()) -> str:
    """Section 5 on thermal films: ``c`` the thermal Campbell diagram of section 3c, screened
    as the isothermal one (:func:`stability_checks`); ``log_dec_figure(c, ld, op_range, title,
    failed)``; a table of the least damped mode beside the isothermal Campbell ``iso`` (its
    screened δ ``iso_ld``). ``text`` also gets the table and the screening checks (the
    isothermal ones ``iso_checks`` first: (row, films) pairs)."""
    ld, added = stability_checks(c, checks, window_hz, op_range)
    failed = no_thermal_equilibrium(c)
    rows = log_dec_rows(iso, iso_ld, c, ld)
    if text is not None:
        text += (txt.stability_head(THERMAL, window_hz, True)
                 + txt.failed_line(failed, len(c.speeds_hz))
                 + txt.log_dec_lines(LOG_DEC_HEADER, rows, list(iso_checks) + added))
    fig = log_dec_figure(c, ld, op_range, "log decrement of the forward rotor modes, "
                         + THERMAL, failed)
    return ("<h2>5a. Stability on thermal films</h2><figure>" + svg(fig)
            + f"<figcaption>Forward rotor modes below {window_hz:.4g} Hz with every speed at "
            "its own thermal equilibrium, the temperature field frozen (the Campbell diagram "
            "of section 3c); the screening checks evaluated on these films (checks table: "
            "column \"films\")." + failed_text(failed) + "</figcaption></figure>"
            + "<p>The least damped screened forward rotor mode at a few speeds, on both films "
            "(δ of the figures above):</p>"
            + table(LOG_DEC_HEADER, rows))


def isothermal_screen(checks, c, window_hz: float, op_range, films: str):
    """The isothermal Campbell diagram ``c``'s screening under ``films`` ("" without an oil
    system): (its screened δ, the check rows added with their films)."""
    checks.films = films
    n0 = len(checks.rows)
    ld = stability_screen(checks, c, window_hz, op_range)
    return ld, list(zip(checks.rows[n0:], checks.films_of[n0:]))


def text_sections(checks, *, response, thermal_response, campbell, thermal_campbell, outs,
                  n_mc_hz: float, clear: dict, window_hz: float, op_range, films: str
                  ) -> list[str]:
    """The text report's unbalance response and stability screen without the HTML report
    (report.txt of ``rotordyn report --out DIR``): the same rows and the same checks, added
    to ``checks`` in the HTML report's order. ``response``: (UnbalanceResult, U kg·m, where)
    of the isothermal films; ``thermal_response``: the thermal API response of section 3c
    (None without an oil system, as ``thermal_campbell``); ``films``: the isothermal films'
    label ("" without an oil system)."""
    u, u_kgm, where = response
    tu, tc = thermal_response, thermal_campbell
    out = txt.response_head(films, u_kgm, where, n_mc_hz)
    checks.films = films
    out += txt.unstable_line(unstable_speeds(u, checks))
    for st in outs:
        rows, amp = station_checks(u, checks, st, n_mc_hz, clear.get(st), films)
        out += txt.station_lines(st, rows, amp)
    if tu is not None:
        out += txt.response_head(THERMAL, u_kgm, where, n_mc_hz)
        checks.films = THERMAL
        out += txt.unstable_line(unstable_speeds(tu, checks))
        equilibrium_check(checks, tu, "the unbalance response")
        out += txt.failed_line(no_thermal_equilibrium(tu), len(tu.speeds_hz))
        for st in outs:
            rows, amp = station_checks(tu, checks, st, n_mc_hz, clear.get(st), THERMAL)
            out += txt.station_lines(st, rows, amp)
    if campbell is None or not campbell.speeds_hz.size:
        return out
    ld, iso_added = isothermal_screen(checks, campbell, window_hz, op_range, films)
    if tc is None:
        return out + txt.stability_head(films, window_hz, False) + txt.log_dec_lines(
            LOG_DEC_HEADER_ONE, log_dec_rows(campbell, ld, None, None), iso_added)
    tld, added = stability_checks(tc, checks, window_hz, op_range)
    return (out + txt.stability_head(THERMAL, window_hz, True)
            + txt.failed_line(no_thermal_equilibrium(tc), len(tc.speeds_hz))
            + txt.log_dec_lines(LOG_DEC_HEADER, log_dec_rows(campbell, ld, tc, tld),
                                iso_added + added))


__all__ = ["ISOTHERMAL", "LOG_DEC_HEADER", "LOG_DEC_HEADER_ONE", "THERMAL", "equilibrium_check",
           "failed_text", "isothermal_screen", "least_damped", "log_dec_rows", "mark_failed",
           "no_thermal_equilibrium", "response_html", "stability_checks", "stability_html",
           "station_checks", "station_html", "text_sections", "unstable_html",
           "unstable_speeds"]
