"""``rotordyn report MODEL --html OUT.html``: one self-contained HTML file (figures inline as
SVG, no external resources) in the spirit of an API 684 lateral analysis:

1. model summary and rotor drawing;
2. undamped critical speed map (natural frequencies against bearing stiffness, with the
   bearings' own stiffness at the operating point);
2b. each bearing's stiffness and damping kxx … cyy over the analysed speeds (table, figure;
   :mod:`rotordyn.report.sections`);
3. Campbell diagram with the critical speeds, and (3b) the mode shape at each critical speed;
4. unbalance response (API 684 unbalance U = 6350 W/N g·mm) with amplification factors,
   separation margins and the API 617 amplitude limit;
5. stability: the logarithmic decrement of the forward rotor modes in the frequency window,
   screened against δ > 0.1; with an oil system (``[thermal]``) 3c, 4b and 5a give the same on
   thermal films (:mod:`rotordyn.report.thermal_dynamics`, the checks on both); 5b. API 617
   Level I with the anticipated cross-coupling Q_A of the model's stages
   (:mod:`rotordyn.report.level1`; "not evaluated (no stage data)" without);
6. for an active journal bearing, the stability map over (a_y, p_c);
7. the text report (the paper's checks with their stated tolerances).

Each check states its criterion and, where one exists, pass or fail; a value that cannot be
computed is "not resolved", never a pass. The speed range, the API unbalance and the checks are
:mod:`rotordyn.report.criteria`.
"""

from __future__ import annotations

import html
import io
import re
from pathlib import Path

import numpy as np

from rotordyn import analysis
from rotordyn._common.info import __version__
from rotordyn.model import builtin as models
from rotordyn.bearings import ActiveJournalBearing
from rotordyn.report import level1 as level1_report
from rotordyn._common.progress import Steps
from rotordyn.plot.coefficients import bearing_coefficients as coefficient_figure
from rotordyn.report.tables import tilt_coefficient_tables
from rotordyn.report.sections import (COEFFICIENT_HEADER, CRITICAL_HEADER, MERGE_RTOL,
                                      api_response, bearing_coefficient_frame,
                                      coefficient_rows, coefficient_text_lines,
                                      SOURCE_LEAST_DAMPED, backward_note, critical_rows,
                                      critical_speed_table, critical_text_lines,
                                      not_resonance_note, shape_source, shapes_for,
                                      thermal_critical_text_lines, thermal_results)
from rotordyn.report import dynamics_text
from rotordyn.report.pad_onset import pad_onset_html
from rotordyn.report import thermal_dynamics as thermal_dyn
from rotordyn.report.criteria import (NOT_RESOLVED, SCREEN_LOG_DEC, Checks, critical_speed_map,
                                      speed_range)



def svg(fig) -> str:
    """The figure as an inline <svg> element (XML prolog and DOCTYPE removed); closes it."""
    import matplotlib.pyplot as plt

    buf = io.StringIO()
    fig.savefig(buf, format="svg")
    plt.close(fig)
    text = buf.getvalue()
    return text[text.index("<svg"):]


def _table(header, rows) -> str:
    h = "".join(f"<th>{html.escape(str(c))}</th>" for c in header)
    body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>" for r in rows)
    # in a box of its own that scrolls sideways on a narrow screen (the page never does)
    return (f"<div class=\"tbl\"><table><thead><tr>{h}</tr></thead><tbody>{body}</tbody>"
            "</table></div>")


def _verdict(ok) -> str:
    if ok is None:
        return '<span class="na">n/a</span>'
    if ok == NOT_RESOLVED:
        return '<span class="nr">not resolved</span>'
    if isinstance(ok, str):  # e.g. "not evaluated (no stage data)": no criterion was applied
        return f'<span class="na">{html.escape(ok)}</span>'
    return '<span class="pass">PASS</span>' if ok else '<span class="fail">FAIL</span>'


def _checks_html(checks: Checks) -> str:
    """The checks table; with an oil system a column "films" says which physics each row is
    computed on (isothermal or thermal films)."""
    films = any(checks.films_of)
    return _table(["check"] + ["films"] * films + ["criterion", "value", "result"],
                  [(html.escape(n),) + (html.escape(f or "–"),) * films
                   + (html.escape(c), html.escape(v), _verdict(ok))
                   for (n, c, v, ok), f in zip(checks.rows, checks.films_of)])


def _critical_map_figure(ks, f, stations, op):
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    from rotordyn.plot._style import COLUMN_IN, RC

    with plt.rc_context(RC):
        fig, ax = plt.subplots(figsize=(COLUMN_IN * 1.5, COLUMN_IN), layout="constrained")
        for j in range(f.shape[1]):
            ax.loglog(ks, f[:, j], "-", color=f"C{j}", label=f"mode {j + 1}")
        h, _ = ax.get_legend_handles_labels()
        for lab, k, spd, ls in op:
            good = np.isfinite(k) & (k > 0)
            if good.any():
                ax.loglog(k[good], spd[good], color="k", ls=ls, lw=0.9, marker=".", ms=3)
                h.append(Line2D([], [], color="k", ls=ls, lw=0.9, marker=".", ms=3, label=lab))
        ax.set_xlabel("bearing stiffness k at station" + ("s " if len(stations) > 1 else " ")
                      + ", ".join(str(x) for x in stations) + " (N/m)")
        ax.set_ylabel("undamped natural frequency; running speed (Hz)")
        ax.set_title("undamped critical speed map (at rest, isotropic k)")
        ax.legend(handles=h, loc="upper left", fontsize=6)
    return fig


def _log_dec_figure(c, ld, op_range, title="log decrement of the forward rotor modes",
                    failed=()):
    """δ of the screened forward rotor modes ``ld`` over speed; ``failed``: speeds (Hz) without
    a thermal equilibrium, marked × on the speed axis."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from rotordyn.plot._style import COLUMN_IN, RC, WHIRL_STYLE

    fr = c.tracked(np.where(np.isfinite(ld), c.frequencies_hz, np.nan))
    ld = c.tracked(ld)
    wh = c.tracked(c.whirl.astype(float))
    with plt.rc_context(RC):
        fig, ax = plt.subplots(figsize=(COLUMN_IN * 1.6, COLUMN_IN), layout="constrained")
        h = []
        for j in range(ld.shape[1]):
            if np.isfinite(ld[:, j]).sum() < 2 or np.nanmax(fr[:, j]) <= 0:
                continue
            w = int(np.nanmedian(wh[:, j])) if np.isfinite(wh[:, j]).any() else 0
            f0 = np.nanmedian(fr[:, j])
            ln, = ax.plot(c.speeds_hz, ld[:, j], ls=WHIRL_STYLE.get(w, "-"),
                          color=["C0", "C1", "C2", "C4", "C5", "C6", "C8", "C9"][len(h) % 8],
                          label=f"mode ≈ {f0:.0f} Hz")
            h.append(ln)
        ax.axhline(SCREEN_LOG_DEC, color="tab:red", lw=1.6, ls=(0, (5, 2)))
        ax.axhline(0, color="k", lw=0.6)
        h.append(Line2D([], [], color="tab:red", lw=1.6, ls=(0, (5, 2)),
                        label=f"screening: δ > {SCREEN_LOG_DEC}"))
        if op_range is not None:
            ax.axvspan(*op_range, color="tab:green", alpha=0.12, lw=0)
            h.append(Patch(color="tab:green", alpha=0.12, label="operating speed range"))
        ax.set_xlabel("rotor speed (Hz)")
        ax.set_ylabel("logarithmic decrement δ (–)")
        if np.isfinite(ld).any():
            ax.set_ylim(min(-0.05, 1.1 * float(np.nanmin(ld))),
                        max(0.3, 1.05 * float(np.nanmax(ld))))
        ax.set_title(title)
        if len(failed):
            h.append(ax.plot(failed, np.zeros(len(failed)), "x", color="tab:red", ms=5,
                             mew=1.2, clip_on=False, transform=ax.get_xaxis_transform(),
                             label="no thermal equilibrium (not computed)")[0])
        ax.legend(handles=h, loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=6)
    return fig


CSS = """body{font-family:sans-serif;max-width:60em;margin:2em auto;padding:0 .5em;
line-height:1.4;color:#222;overflow-wrap:break-word}
.tbl{overflow-x:auto;max-width:100%}
h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:2em}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;padding:.2em .5em;
text-align:left;vertical-align:top}th{background:#eee}
.pass{color:#060;font-weight:bold}.fail{color:#b00;font-weight:bold}.na{color:#777}
.nr{color:#a60;font-weight:bold}
figure{margin:1em 0}figcaption{font-size:.9em;color:#444}svg{max-width:100%;height:auto}
pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:.85em}"""




def _progress(steps, text: str) -> None:
    """Start the next step of the report's progress line (:class:`Steps`)."""
    steps.step(text)


def _bearing_stiffness_curves(s, coeffs):
    """[(label, k (n,), speed (n,), ls)]: the direct stiffness k_xx, k_yy of the first bearing
    element over speed (``coeffs``: :func:`rotordyn.report.sections.bearing_coefficient_frame`,
    pads condensed at synchronous whirl), for the critical speed map."""
    if not s.bearings or coeffs.empty:
        return []
    name = coeffs["bearing"].iloc[0]
    g = coeffs[coeffs["bearing"] == name]
    sp = g["speed_hz"].to_numpy()
    return [(f"{name}: k_xx(Ω)", g["kxx_n_per_m"].to_numpy(), sp, "--"),
            (f"{name}: k_yy(Ω)", g["kyy_n_per_m"].to_numpy(), sp, ":")]


def _save_png(fig, figure_dir, name: str) -> None:
    """``fig`` as ``figure_dir/name`` at the style's 200 dpi (no-op without a directory)."""
    if figure_dir is not None:
        fig.savefig(Path(figure_dir) / name, dpi=200, bbox_inches="tight")


def write_html(model: str, path, *, text_lines=(), operating_speed_hz=None,
               speeds_hz=None, chamber_pressure_pa: float | None = None,
               progress: bool = True, level1_options: dict | None = None,
               figure_dir=None, text_sink: list | None = None) -> Path:
    """Write the HTML report of ``model`` (a built-in name or TOML path) to ``path``.

    ``operating_speed_hz`` (min, max) Hz: the operating range of the separation margins and
    amplitude checks (none given: no margins are assessed). ``speeds_hz``: the analysed speeds
    (default :func:`rotordyn.report.criteria.speed_range`). ``progress``: a line on stderr per
    section, "which step, how far" (:class:`rotordyn._common.progress.Steps`).
    ``level1_options``: keywords of :func:`rotordyn.level1` for the Level I section
    (``gas_density_kg_m3``, ``csr_limit``). ``figure_dir``: also write the mode shape at each
    critical speed and the bearing coefficient figure there as PNG, and the coefficients and
    the critical speeds as ``bearing_coefficients.csv``, ``critical_speeds.csv``.
    ``text_sink``: a list that gets the text report's lines of the critical speeds, their mode
    shapes and the bearing coefficients (:mod:`rotordyn.report.sections`) and the checks
    table (:meth:`Checks.text_lines`)."""
    import datetime
    import hashlib

    import matplotlib

    matplotlib.use("Agg")
    from rotordyn.plot import rotor_drawing, stability_map_grid
    from rotordyn.plot.frequency import campbell_diagram

    s = models.load(model)
    paper = s.name in ("paper-rig", "paper-rig-hs")
    active = [b for b in s.bearings if isinstance(b, ActiveJournalBearing)]
    pc = (0.4e6 if active else 0.0) if chamber_pressure_pa is None else chamber_pressure_pa
    ay = active[0].config_ay_m if active else None  # the model's configuration (rig: 0)
    if operating_speed_hz is None and paper:
        operating_speed_hz = (45.0, 55.0)
    progress = Steps("report", 6 + bool(active) + 2 * (s.thermal is not None),
                     enabled=bool(progress))
    checks = Checks()
    parts: list[str] = []
    title = f"Lateral analysis of {html.escape(s.name or str(model))}"

    _progress(progress, "undamped critical speed map")
    ks, fmap, stations = critical_speed_map(s)
    rng = speed_range(s, operating_speed_hz, speeds_hz, (ks, fmap, stations), paper)
    sp = rng.speeds_hz
    window_hz = 1.5 * float(sp[-1])  # the frequency window of Campbell and stability
    op_txt = (f"{operating_speed_hz[0]:g}–{operating_speed_hz[1]:g} Hz"
              if operating_speed_hz else "not given (margins not assessed)")

    # 1. model
    toml = s.to_toml()
    rows = [("length", f"{s.rotor.length_m * 1e3:.0f} mm"), ("mass", f"{s.mass_kg:.3f} kg"),
            ("shaft elements", s.rotor.n_elements), ("stations", s.rotor.n_stations),
            ("disks", len(s.rotor.disks)),
            ("supports", ", ".join(f"{x.type} at {x.station}" for x in s.supports) or "none"),
            ("bearing elements", ", ".join(f"{b.name or type(b).__name__} at {b.station}"
                                           for b in s.bearings) or "none"),
            ("reduction", f"{s.reduction.method} {list(s.reduction.master_stations)}"),
            ("operating speed range", op_txt),
            ("analysed speeds", f"{sp[0]:.4g}–{sp[-1]:.4g} Hz ({rng.why})"),
            ("chamber pressure p_c, a_y (active bearing)",
             f"{pc / 1e6:g} MPa, {ay * 1e3:g} mm" if active else "n/a"),
            ("model hash (SHA-256 of the TOML, 16 hex)",
             hashlib.sha256(toml.encode()).hexdigest()[:16]),
            ("date (UTC)", datetime.datetime.now(datetime.timezone.utc).strftime(
                "%Y-%m-%d %H:%M"))]
    parts.append("<h2>1. Model</h2>" + (f"<p>{html.escape(s.description)}</p>"
                                        if s.description else "")
                 + _table(["item", "value"], [(html.escape(a), html.escape(str(b)))
                                               for a, b in rows])
                 + "<details><summary>input echo (the model as TOML)</summary><pre>"
                 + html.escape(toml) + "</pre></details>")
    ax = rotor_drawing(s)
    parts.append(f"<figure>{svg(ax.figure)}<figcaption>Rotor drawn from the model: sections "
                 "to scale (radial scale exaggerated), disks, bearings, stations."
                 "</figcaption></figure>")

    # static: how the weight is shared, deflection and bending at N_mc
    _progress(progress, "static analysis")
    stat = analysis.static(s, rng.n_mc_hz, pc, ay)
    if stat.converged:
        parts.append("<h2>1b. Static load sharing</h2><figure>"
                     + svg(stat.plot(system=s)[0].figure)
                     + f"<figcaption>At {rng.n_mc_hz:.4g} Hz: deflection, shear force and "
                     "bending moment along the rotor.</figcaption></figure>"
                     + _table(["support / bearing", "station", "kind", "F_x (N)", "F_y (N)"],
                              [(html.escape(str(r.name or "")), r.station, r.kind,
                                f"{r.force_x_n:.4g}", f"{r.force_y_n:.4g}")
                               for r in stat.reactions.itertuples()])
                     + f"<p>Weight {stat.weight_n:.4g} N; the reactions' vertical sum "
                     f"{stat.reactions['force_y_n'].sum():.4g} N.</p>")
    else:
        parts.append(f"<h2>1b. Static load sharing</h2><p class=\"nr\">No equilibrium at "
                     f"{rng.n_mc_hz:.4g} Hz ({html.escape(stat.status)}): "
                     f"{html.escape(stat.message)}</p>")

    # 2. undamped critical speed map with the bearings' K(Ω)
    _progress(progress, "bearing coefficients over speed")
    eqs: list = []
    coeffs = bearing_coefficient_frame(s, sp, pc, ay, progress=progress.item, equilibria=eqs)
    curves = _bearing_stiffness_curves(s, coeffs)
    parts.append("<h2>2. Undamped critical speed map</h2><figure>"
                 + svg(_critical_map_figure(ks, fmap, stations, curves))
                 + "<figcaption>Natural frequencies at rest with an isotropic spring k in place "
                 "of the bearing(s), each mode once; dashed/dotted: the first bearing's direct "
                 "stiffness against running speed (where a curve meets a mode: an undamped "
                 "critical speed).</figcaption></figure>")
    if not coeffs.empty:
        if figure_dir is not None:
            coeffs.to_csv(Path(figure_dir) / "bearing_coefficients.csv", index=False)
        fig = coefficient_figure(coeffs)
        _save_png(fig, figure_dir, "bearing_coefficients.png")
        parts.append("<h2>2b. Bearing coefficients over speed</h2><figure>" + svg(fig)
                     + "<figcaption>Each bearing's stiffness and damping at its equilibrium in "
                     "the system (dF = −K dq − C dq̇; x horizontal, y up)"
                     + (", pads/sleeve condensed at synchronous whirl" if any(
                         hasattr(b, "pad_films") or isinstance(b, ActiveJournalBearing)
                         for b in s.bearings) else "")
                     + ".</figcaption></figure>"
                     + _table(COEFFICIENT_HEADER, [tuple(html.escape(str(c)) for c in r)
                                                   for r in coefficient_rows(coeffs)]))
        for (head, rows), what in zip(tilt_coefficient_tables(coeffs),
                                      ("Stiffness", "Damping")):
            parts.append(f"<p>Tilting films: {what.lower()} coupling blocks of the 4×4 over "
                         "(x, y, θx, θy) (dH = −K dr − C dṙ, H = (Fx, Fy, Mx, My); the x, y "
                         "block is the table above).</p>"
                         + _table(head, [tuple(html.escape(str(c)) for c in r)
                                         for r in rows]))

    # 2d (placed after 2c). the minimum film, its place, and tilted films' edge and moments
    from rotordyn.report.films import film_html, film_text_lines, write_films

    film_tab, lengths = write_films(s, eqs, figure_dir)
    # 2c. the bearings' temperatures and K, C at the thermal equilibrium (an oil system)
    from rotordyn.report.thermal import (thermal_frames, thermal_html, thermal_text_lines,
                                         write_thermal)

    if s.thermal is not None:
        _progress(progress, "bearing temperatures at the thermal equilibrium")
    th, th_coeffs, th_note = thermal_frames(s, sp, pc, ay)
    if figure_dir is not None:
        write_thermal(th, th_coeffs, figure_dir)
    parts.append(thermal_html(th, th_coeffs, th_note, svg, _table))
    parts.append(film_html(film_tab, _table, lengths))

    # 3. Campbell; the unbalance response is computed here too, for its peaks are critical
    # speeds as well (the only ones of a heavily damped mode that never crosses 1×)
    _progress(progress, f"Campbell diagram, {sp.size} speeds")
    if s.bearings:
        c = analysis.campbell(s, sp, pc, ay)
    else:
        c = analysis.rotor_campbell(s, sp, n_modes=12)
    _progress(progress, "unbalance response")
    u, st_ub, u_kgm, where = api_response(s, sp, rng.n_mc_hz, pc, ay, operating_speed_hz)
    outs = list(u.stations)
    crit = critical_speed_table(c, u)
    if figure_dir is not None:
        crit.to_csv(Path(figure_dir) / "critical_speeds.csv", index=False)
    ax = campbell_diagram(c, title=(f"Campbell diagram, p_c = {pc / 1e6:g} MPa" if active
                                    else "Campbell diagram"))
    ax.set_ylim(0, window_hz)
    parts.append("<h2>3. Campbell diagram and critical speeds</h2><figure>" + svg(ax.figure)
                 + f"<figcaption>Modes up to {window_hz:.4g} Hz (1.5 × the top speed)."
                 "</figcaption></figure>"
                 + (_table(CRITICAL_HEADER, [tuple(html.escape(str(x)) for x in r)
                                             for r in critical_rows(crit)])
                    + "<p>Each critical speed with its source: a forward mode crossing the 1× "
                    "line of the damped Campbell diagram, a resonance peak of the unbalance "
                    "response (section 4; AF < 1 is none), or both (the crossing inside the "
                    f"peak's half-power band or within {100 * MERGE_RTOL:g} % of it). A heavily "
                    "damped mode may never cross 1× and still give a response peak "
                    "(docs/api-criteria.md).</p>" if len(crit) else
                    "<p>No critical speed in the speed range: no resonant forward 1× crossing in the "
                    "Campbell diagram and no resonance peak in the unbalance response.</p>")
                 + "".join(f"<p>{html.escape(n)}</p>"
                           for n in (not_resonance_note(crit), backward_note(crit)) if n))

    # 3b. the mode shape at each critical speed
    _progress(progress, f"mode shapes at the critical speeds ({len(crit)} in range)")
    shapes = shapes_for(s, crit, rng.n_mc_hz, window_hz, pc, ay, progress=progress.item)
    if shapes:
        sec = ["<h2>3b. Mode shapes at the critical speeds</h2>"]
        for k, m in enumerate(shapes, start=1):
            what = ("No critical speed" if m.source == SOURCE_LEAST_DAMPED
                    else f"Critical speed {k}")
            if m.figure is None:
                sec.append(f"<p class=\"nr\">{what} ({m.speed_hz:.4g} Hz): mode "
                           f"shape not resolved ({html.escape(m.why)}).</p>")
                continue
            _save_png(m.figure, figure_dir, f"critical_mode_{k}.png")
            sec.append(f"<figure>{svg(m.figure)}<figcaption>{what}: "
                       f"{m.speed_hz:.4g} Hz ({60 * m.speed_hz:.0f} rpm, "
                       f"{html.escape(m.source)}), {m.whirl} mode at {m.freq_hz:.4g} Hz, log "
                       f"dec {m.log_dec:.3g} "
                       f"({html.escape(shape_source(m.source, m.whirl))}): whirl orbits "
                       "along the rotor, normalised to the largest.</figcaption>"
                       "</figure>")
        if len(crit) > len(shapes):
            sec.append(f"<p>The first {len(shapes)} of {len(crit)} critical speeds shown.</p>")
        parts.append("".join(sec))
    # 3c. critical speeds with every speed at its own thermal equilibrium (an oil system)
    if s.thermal is not None:
        _progress(progress, "Campbell and unbalance response on thermal films")
    tcrit, tnote, tc, tu = thermal_results(s, rng, pc, ay, operating_speed_hz)
    if tcrit is not None and figure_dir is not None:
        tcrit.to_csv(Path(figure_dir) / "critical_speeds_thermal.csv", index=False)
    parts.append(_thermal_critical_html(tcrit, tnote, tc, window_hz))
    if text_sink is not None:
        text_sink += critical_text_lines(crit, shapes, rng, pc, bool(active),
                                         files=figure_dir is not None)
        text_sink += coefficient_text_lines(coeffs)
        text_sink += film_text_lines(film_tab, lengths)
        text_sink += thermal_text_lines(th, th_coeffs, th_note)
        text_sink += thermal_critical_text_lines(tcrit, tnote)

    # 4. unbalance response
    parts.append(f"<h2>4. Unbalance response</h2><p>API 684 unbalance U = 6350 W/N g·mm = "
                 f"{u_kgm * 1e6:.4g} g·mm {html.escape(where)} (W = {s.mass_kg:.4g} kg, the "
                 f"rotor's static load; N = N_mc = {60 * rng.n_mc_hz:.0f} rpm); the speed grid "
                 "is refined at every peak." + _isothermal_note(s, tu is not None) + "</p>")
    iso = thermal_dyn.ISOTHERMAL if s.thermal is not None else ""
    checks.films = iso
    # the text report's lines of sections 4, 4b, 5 and 5a, from the same rows (report.txt)
    dyn = dynamics_text.response_head(iso, u_kgm, where, rng.n_mc_hz)
    parts.append(thermal_dyn.unstable_html(u, checks, dyn))
    clear = {b.station: getattr(b, "clearance_m", None) for b in s.bearings}
    for st in outs:
        parts += thermal_dyn.station_html(u, checks, st, rng.n_mc_hz, clear.get(st), svg,
                                          _table, _verdict, iso, dyn)
    if tu is not None:  # the same on thermal films: section 3c's response
        dyn += dynamics_text.response_head(thermal_dyn.THERMAL, u_kgm, where, rng.n_mc_hz)
        parts.append(thermal_dyn.response_html(tu, checks, outs, rng.n_mc_hz, clear, svg,
                                               _table, _verdict, dyn))
    parts.append("<p>AF: amplification factor N_c/(N₂ − N₁) by the half-power method (≤: a "
                 "bound, one half-power speed outside the range); SM: separation margin from "
                 "the operating speed range.</p>")

    # 5. stability over speed
    ld, iso_added = thermal_dyn.isothermal_screen(checks, c, window_hz, operating_speed_hz, iso)
    parts.append("<h2>5. Stability: logarithmic decrement of the forward rotor modes</h2>"
                 "<figure>" + svg(_log_dec_figure(c, ld, operating_speed_hz, (
                     "log decrement of the forward rotor modes" + (f", {iso}" if iso else ""))))
                 + f"<figcaption>Forward rotor modes below {window_hz:.4g} Hz (backward modes "
                 "and the undamped shaft modes far above the speed range are left out; |δ| < "
                 "1e-6 is round-off)." + _isothermal_note(s, tc is not None)
                 + "</figcaption></figure>" + pad_onset_html(eqs))
    if tc is not None:  # the same on thermal films: section 3c's Campbell diagram
        parts.append(thermal_dyn.stability_html(tc, checks, window_hz, operating_speed_hz, svg,
                                                _log_dec_figure, _table, c, ld, dyn,
                                                iso_added))
    else:
        dyn += dynamics_text.stability_head(iso, window_hz, False) + dynamics_text.log_dec_lines(
            thermal_dyn.LOG_DEC_HEADER_ONE, thermal_dyn.log_dec_rows(c, ld, None, None),
            iso_added)
    if text_sink is not None:
        text_sink += dyn
    checks.films = iso  # Level I and the active bearing's map: isothermal films

    # 5b. API 617 Level I with the stages' anticipated cross-coupling
    _progress(progress, "API 617 Level I")
    l1, why = level1_report.evaluate(s, operating_speed_hz, pc, ay, **(level1_options or {}))
    parts.append(level1_report.html_section(l1, why, checks, svg, _table))

    # 6. active bearing: stability map in p_c
    if active:
        _progress(progress, "active bearing stability map")
        speed = float(np.mean(operating_speed_hz)) if operating_speed_hz else 50.0
        # the paper's a_y range on its rig (−8.3 c … +1.7 c); another model's ±8 c about its
        # own configuration (the rig's a_y of −1.85 mm is 18 clearances of a 0.1 mm bearing)
        ab = active[0]
        ays = (np.linspace(-2.5e-3, 0.5e-3, 13) if paper else
               ab.config_ay_m + ab.clearance_m * np.linspace(-8.0, 8.0, 13))
        pcs = np.linspace(0.0, 0.4e6, 21)
        Z = np.full((ays.size, pcs.size), np.nan)
        failed = []
        for i, a in enumerate(ays):
            for j, p in enumerate(pcs):
                st = analysis.stability(s, speed, p, a)
                if st.status in ("ok",) and len(st.eigenvalues):
                    Z[i, j] = np.max(st.eigenvalues.real[st.kind == "rotor"])
                else:
                    failed.append((a, p))
                progress.item(i * pcs.size + j + 1, ays.size * pcs.size)
        ax = stability_map_grid(ays, pcs, Z, xname="config_ay_m", yname="chamber_pressure_pa",
                                failed=failed,
                                title=f"active bearing: stability map at {speed:g} Hz")
        parts.append("<h2>6. Active bearing: stability map in p_c</h2><figure>" + svg(ax.figure)
                     + "</figure>")
        t_ay, bounds = (-1.85e-3, (0.02e6, 0.3e6)) if paper else (ab.config_ay_m,
                                                                   (0.0, float(pcs[-1])))
        t = analysis.threshold(s, "chamber_pressure_pa", bounds=bounds, speed_hz=speed,
                               config_ay_m=t_ay, n_scan=8)
        value = (f"p_c = {t.value / 1e6:.4f} MPa, stable {t.stable_side} ({t.status})"
                 if t.status == "ok" else
                 f"none in {bounds[0] / 1e6:g}–{bounds[1] / 1e6:g} MPa ({t.status}: "
                 f"{t.message})")
        checks.add(f"threshold of instability at a_y = {1e3 * t_ay:g} mm, {speed:g} Hz"
                   .replace("-", "−"),  # a minus sign, as the rest of the page
                   "stable operation needs p_c on the stable side of the threshold",
                   value, None)

    # 7. text report
    if text_lines:
        # the paper's checks only on its rig; another model's text report has no reference
        heading = ("Checks against the reference paper (text report)" if paper else
                   "Text report")
        parts.append(f"<h2>7. {heading}</h2><pre>"
                     + html.escape("\n".join(text_lines)) + "</pre>")
    if text_sink is not None:
        text_sink += checks.text_lines()
    verdict = checks.overall()
    cls = {"PASS": "pass", "FAIL": "fail"}.get(verdict, "nr")
    doc = (f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}"
           f"</title><style>{CSS}</style></head><body><h1>{title}</h1>"
           f"<p>rotordyn {__version__}. Overall: <span class=\"{cls}\">{verdict}</span> "
           f"(every check below with its criterion).</p>{_checks_html(checks)}"
           + "".join(parts) + "</body></html>\n")
    doc = re.sub(r"\n\s*\n", "\n", doc)
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(doc, encoding="utf-8")
    progress.done()
    return out


def _isothermal_note(system, thermal_shown: bool = True) -> str:
    """With an oil system (``[thermal]``), the label of a section computed on the isothermal
    films ("" without one); ``thermal_shown``: sections 4b and 5a give the thermal films' (else
    section 3c says why not)."""
    if getattr(system, "thermal", None) is None:
        return ""
    where = ("sections 4b and 5a (from section 3c's results)" if thermal_shown else
             "not evaluated in this report (section 3c says why)")
    return (" <b>Isothermal films</b> (each bearing's own viscosity, not the oil system's "
            "thermal equilibrium); the same on thermal films (each speed at its own thermal "
            f"equilibrium, field frozen): {where}, and "
            "<code>rotordyn stability/unbalance --thermal</code>.")


def _thermal_critical_html(crit, note: str, campbell, window_hz: float) -> str:
    """Section 3c: the Campbell diagram and the critical speeds with every speed at its own
    thermal equilibrium ("" without an oil system)."""
    from rotordyn.plot.frequency import campbell_diagram

    head = "<h2>3c. Campbell diagram and critical speeds on thermal films</h2>"
    if crit is None:
        return head + f"<p class=\"nr\">{html.escape(note)}</p>" if note else ""
    ax = campbell_diagram(campbell, title="Campbell diagram, thermal films")
    ax.set_ylim(0, window_hz)
    rows = [tuple(html.escape(str(x)) for x in r) for r in critical_rows(crit)]
    return (head + f"<p>{html.escape(note)} (docs/film-physics.md); sections 3, 4 and 5: the "
            "model's isothermal films; 4b and 5a: these thermal films.</p><figure>"
            + svg(ax.figure) + "</figure>"
            + (_table(CRITICAL_HEADER, rows) if rows else
               "<p>No critical speed in the speed range on thermal films.</p>"))
