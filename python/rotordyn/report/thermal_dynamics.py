"""The HTML report's unbalance response (section 4) and stability (section 5) on thermal films
(a model with an oil system, ``[thermal]``; docs/film-physics.md, "Dynamics at each point's own
thermal equilibrium"): every speed at its own thermal equilibrium, the temperature field
frozen. Nothing is computed twice: the results are section 3c's
(:func:`rotordyn.report.sections.thermal_dynamics`): its Campbell diagram gives the log
decrements, its API unbalance response the Bode data. Shown beside the isothermal results, the
API checks evaluated on both (the checks table's "films" column); a speed whose thermal
equilibrium failed is marked (× on the speed axis, listed), never plotted as a number.

The figure helpers of :mod:`rotordyn.report.html` (``svg``, ``table``, ``verdict``, the log
decrement figure) are passed in: this module sits below it."""

from __future__ import annotations

import html

import numpy as np

from rotordyn._common.status import CONVERGED
from rotordyn.report.criteria import (NOT_RESOLVED, amplitude_checks, separation_checks,
                                      stability_screen)

THERMAL = "thermal films"
ISOTHERMAL = "isothermal films"
PEAK_HEADER = ["N_c (Hz)", "peak (µm)", "AF", "SM (%)", "required (%)", "result"]


def no_thermal_equilibrium(result) -> np.ndarray:
    """Speeds (Hz) of ``result`` (a thermal Campbell or unbalance result: its ``thermal`` per
    speed) whose thermal equilibrium failed or raised (never linearised: NaN rows)."""
    th = getattr(result, "thermal", ())
    if not th:
        return np.empty(0)
    bad = [t is None or t.status not in CONVERGED for t in th]
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


def station_html(u, checks, station: int, n_mc_hz: float, clearance_m, svg, table, verdict,
                 films: str = "") -> list[str]:
    """One output station of section 4: the Bode plot of ``u`` (UnbalanceResult), its peaks
    with the API 684 separation margins and the API 617 amplitude checks (added to
    ``checks`` under ``films``: "" without an oil system, else :data:`THERMAL` or
    :data:`ISOTHERMAL`, the Bode title and the checks table say which)."""
    from rotordyn.plot import bode

    checks.films = films
    a1, _ = bode(u, station=station)
    failed = no_thermal_equilibrium(u)
    if films:
        a1.set_title(f"unbalance response at station {station}, {films}", fontsize=8)
    mark_failed(a1, failed)
    out = [f"<figure>{svg(a1.figure)}<figcaption>Station {station}"
           + (f", {films}" if films else "") + "." + failed_text(failed)
           + "</figcaption></figure>"]
    rows = separation_checks(checks, u, station)
    if rows:
        out.append(table(PEAK_HEADER, [
            (f"{nc:.4g}", f"{pk * 1e6:.3g}", html.escape(aft),
             f"{sm:.1f}" if np.isfinite(sm) else "n/a",
             ("none" if req == 0 else f"{req:.1f}") if np.isfinite(req) else "n/a",
             verdict(v)) for nc, pk, aft, sm, req, v in rows]))
    else:
        out.append(f"<p>Station {station}" + (f" ({films})" if films else "")
                   + ": no resonance peak in the speed range.</p>")
    amplitude_checks(checks, u, station, n_mc_hz, clearance_m)
    return out


def unstable_html(u, checks) -> str:
    """The warning and check of the speeds where ``u``'s equilibrium is linearly unstable
    (speeds without a thermal equilibrium are not counted: nothing was linearised there)."""
    ok = np.isin(u.point_status, CONVERGED)
    bad = u.speeds_hz[~u.stable & ok]
    if not bad.size:
        return ""
    checks.add("linear stability over the speed range", "every speed below the threshold "
               "of instability", f"unstable from {bad[0]:.4g} Hz", False)
    return (f"<p class=\"fail\">The equilibrium is linearly unstable at {bad.size} of the "
            f"speeds ({bad[0]:.4g}–{bad[-1]:.4g} Hz): there the response is not a steady "
            "orbit and is left out of the amplitude checks.</p>")


def equilibrium_check(checks, result, what: str) -> None:
    """The check "thermal equilibrium at every speed of ``what``": not resolved when any speed
    of ``result`` failed (its dynamics are missing there), else no criterion (n/a)."""
    failed = no_thermal_equilibrium(result)
    n = len(result.speeds_hz)
    checks.add(f"thermal equilibrium at every speed of {what}", "each speed's thermal "
               "equilibrium converged (else its dynamics are missing)",
               (f"{len(failed)} of {n} speeds failed: " + ", ".join(f"{f:.4g}" for f in failed)
                + " Hz") if len(failed) else f"all {n} speeds converged",
               NOT_RESOLVED if len(failed) else None)


def response_html(u, checks, outs, n_mc_hz: float, clear: dict, svg, table, verdict) -> str:
    """Section 4 on thermal films: ``u`` the thermal API unbalance response of section 3c."""
    checks.films = THERMAL
    parts = ["<h2>4b. Unbalance response on thermal films</h2><p>The same API unbalance with "
             "every speed at its own thermal equilibrium, the temperature field frozen (the "
             "response of section 3c); the API checks below are evaluated on these films too "
             "(checks table: column \"films\").</p>", unstable_html(u, checks)]
    equilibrium_check(checks, u, "the unbalance response")
    for st in outs:
        parts += station_html(u, checks, st, n_mc_hz, clear.get(st), svg, table, verdict,
                              THERMAL)
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


def log_dec_rows(iso, iso_ld, c, ld, n: int = 11) -> list[tuple[str, ...]]:
    """Rows of :data:`LOG_DEC_HEADER` at ``n`` speeds spread over the thermal Campbell diagram
    ``c``: the least damped screened forward mode on isothermal (``iso``, ``iso_ld``) and on
    thermal films; a speed without a thermal equilibrium says so, never a number."""
    failed = set(no_thermal_equilibrium(c).tolist())
    sp = c.speeds_hz[np.unique(np.linspace(0, c.speeds_hz.size - 1, min(n, c.speeds_hz.size))
                               .round().astype(int))]
    rows = []
    for f in sp:
        a, b = least_damped(iso, iso_ld, f), least_damped(c, ld, f)
        rows.append((f"{f:.4g}",) + ((f"{a[0]:.4g}", f"{a[1] + 0.0:.4g}") if a else ("–",) * 2)
                    + (("no thermal equilibrium",) * 2 if float(f) in failed else
                       (f"{b[0]:.4g}", f"{b[1] + 0.0:.4g}") if b else ("–",) * 2))
    return rows


def stability_html(c, checks, window_hz: float, op_range, svg, log_dec_figure, table,
                   iso, iso_ld) -> str:
    """Section 5 on thermal films: ``c`` the thermal Campbell diagram of section 3c, screened
    as the isothermal one (:func:`rotordyn.report.criteria.stability_screen`, rows under
    :data:`THERMAL`); ``log_dec_figure(c, ld, op_range, title, failed)``; a table of the least
    damped mode beside the isothermal Campbell ``iso`` (its screened δ ``iso_ld``)."""
    checks.films = THERMAL
    equilibrium_check(checks, c, "the Campbell diagram")
    ld = stability_screen(checks, c, window_hz, op_range)
    failed = no_thermal_equilibrium(c)
    fig = log_dec_figure(c, ld, op_range, "log decrement of the forward rotor modes, "
                         + THERMAL, failed)
    return ("<h2>5a. Stability on thermal films</h2><figure>" + svg(fig)
            + f"<figcaption>Forward rotor modes below {window_hz:.4g} Hz with every speed at "
            "its own thermal equilibrium, the temperature field frozen (the Campbell diagram "
            "of section 3c); the screening checks evaluated on these films (checks table: "
            "column \"films\")." + failed_text(failed) + "</figcaption></figure>"
            + "<p>The least damped screened forward rotor mode at a few speeds, on both films "
            "(δ of the figures above):</p>"
            + table(LOG_DEC_HEADER, log_dec_rows(iso, iso_ld, c, ld)))


__all__ = ["ISOTHERMAL", "LOG_DEC_HEADER", "THERMAL", "equilibrium_check", "failed_text",
           "least_damped", "log_dec_rows", "mark_failed",
           "no_thermal_equilibrium", "response_html", "stability_html", "station_html",
           "unstable_html"]
