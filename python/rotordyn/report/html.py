"""``rotordyn report MODEL --html OUT.html``: one self-contained HTML file (figures inline as
SVG, no external resources) in the spirit of an API 684 lateral analysis:

1. model summary and rotor drawing;
2. undamped critical speed map (natural frequencies against bearing stiffness, with the
   bearings' own stiffness at the operating point);
3. Campbell diagram with the critical speeds;
4. unbalance response (API 684 unbalance U = 6350 W/N g·mm) with amplification factors,
   separation margins and the API 617 amplitude limit;
5. stability: the logarithmic decrement of every mode over the speed range, against the
   API 617 level-I criterion δ > 0.1;
6. for an active journal bearing, the stability map over (a_y, p_c);
7. the text report (the paper's checks with their stated tolerances).

Each check states its criterion and, where one exists, pass or fail.
"""

from __future__ import annotations

import dataclasses
import html
import io
import re
from pathlib import Path

import numpy as np

from rotordyn import analysis
from rotordyn._common.info import __version__
from rotordyn.model import builtin as models
from rotordyn.bearings import ActiveJournalBearing

API_LOG_DEC_MIN = 0.1          # API 617 level I screening: every mode's log dec > 0.1
API_UNBALANCE_G_MM = 6350.0    # API 684: U = 6350 W / N g·mm (W journal static load kg, N rpm)


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
    return f"<table><thead><tr>{h}</tr></thead><tbody>{body}</tbody></table>"


def _verdict(ok: bool | None) -> str:
    if ok is None:
        return '<span class="na">n/a</span>'
    return '<span class="pass">PASS</span>' if ok else '<span class="fail">FAIL</span>'


class Checks:
    """The list of checks: name, criterion, value, verdict."""

    def __init__(self):
        self.rows: list[tuple[str, str, str, bool | None]] = []

    def add(self, name: str, criterion: str, value: str, ok: bool | None) -> None:
        self.rows.append((name, criterion, value, ok))

    def html(self) -> str:
        return _table(["check", "criterion", "value", "result"],
                      [(html.escape(n), html.escape(c), html.escape(v), _verdict(ok))
                       for n, c, v, ok in self.rows])


def _film_stations(system):
    return [b.station for b in system.bearings]


def critical_speed_map(system, k_range=(1e5, 1e10), n_k=21, n_modes=4, op=None):
    """Undamped natural frequencies (Hz, at rest) against an isotropic stiffness k (N/m) put
    in place of each fluid-film bearing (or of each linear support when there are none).
    Returns (k (n_k,), f (n_k, n_modes)). ``op``: (kxx, kyy) of the bearing at the operating
    point, drawn for reference."""
    from rotordyn.model.rotor import Support
    from rotordyn.model.system import Reduction

    stations = _film_stations(system) or [s.station for s in system.supports
                                          if s.type == "linear"]
    base = tuple(s for s in system.supports if s.station not in stations)
    ks = np.geomspace(*k_range, n_k)
    f = np.full((n_k, n_modes), np.nan)
    for i, k in enumerate(ks):
        sup = base + tuple(Support(st, "linear", kxx_n_per_m=k, kyy_n_per_m=k)
                           for st in stations)
        s = dataclasses.replace(system, supports=sup, bearings=(),
                                reduction=Reduction(method="none"))
        m = analysis.modes(s, 0.0, reduction="none", n_modes=2 * n_modes)
        fr = np.unique(np.round(m.frequencies_hz, 6))[:n_modes]  # x/y pairs coincide at rest
        f[i, :fr.size] = fr
    return ks, f, stations


def _critical_map_figure(ks, f, stations, op):
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    from rotordyn.plot._style import COLUMN_IN, RC

    with plt.rc_context(RC):
        fig, ax = plt.subplots(figsize=(COLUMN_IN * 1.5, COLUMN_IN), layout="constrained")
        for j in range(f.shape[1]):
            ax.loglog(ks, f[:, j], "-", color=f"C{j}", label=f"mode {j + 1}")
        h, _ = ax.get_legend_handles_labels()
        for lab, k, ls in op:
            if np.isfinite(k) and k > 0:
                ax.axvline(k, color="k", ls=ls, lw=0.8)
                h.append(Line2D([], [], color="k", ls=ls, lw=0.8, label=lab))
        ax.set_xlabel(f"bearing stiffness k at station(s) {stations} (N/m)")
        ax.set_ylabel("undamped natural frequency (Hz)")
        ax.set_title("undamped critical speed map (at rest, isotropic k)")
        ax.legend(handles=h, loc="upper left", fontsize=6)
    return fig


def _log_dec_figure(c, op_range):
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from rotordyn.plot._style import COLUMN_IN, RC, WHIRL_STYLE

    ld = c.tracked(np.where(c.rotor_mask(), c.log_dec, np.nan))
    fr = c.tracked(np.where(c.rotor_mask(), c.frequencies_hz, np.nan))
    wh = c.tracked(c.whirl.astype(float))
    with plt.rc_context(RC):
        fig, ax = plt.subplots(figsize=(COLUMN_IN * 1.6, COLUMN_IN), layout="constrained")
        h = []
        for j in range(ld.shape[1]):
            if np.isfinite(ld[:, j]).sum() < 2 or np.nanmax(fr[:, j]) <= 0:
                continue
            w = int(np.nanmedian(wh[:, j])) if np.isfinite(wh[:, j]).any() else 0
            f0 = np.nanmedian(fr[:, j])
            ln, = ax.plot(c.speeds_hz, np.clip(ld[:, j], -1, 1.5), ls=WHIRL_STYLE.get(w, "-"),
                          color=["C0", "C1", "C2", "C4", "C5", "C6", "C8", "C9"][len(h) % 8],
                          label=f"mode ≈ {f0:.0f} Hz")
            h.append(ln)
        ax.axhline(API_LOG_DEC_MIN, color="tab:red", lw=1.6, ls=(0, (5, 2)))
        ax.axhline(0, color="k", lw=0.6)
        h.append(Line2D([], [], color="tab:red", lw=1.6, ls=(0, (5, 2)),
                        label=f"API 617 level I: δ > {API_LOG_DEC_MIN}"))
        h.append(Line2D([], [], color="0.3", ls="-", label="solid: forward, dashed: backward, "
                                                             "dotted: planar"))
        if op_range is not None:
            ax.axvspan(*op_range, color="tab:green", alpha=0.12, lw=0)
            h.append(Patch(color="tab:green", alpha=0.12, label="operating speed range"))
        ax.set_xlabel("rotor speed (Hz)")
        ax.set_ylabel("logarithmic decrement δ (–), clipped to [−1, 1.5]")
        ax.set_ylim(-0.1 + min(0.0, float(np.nanmin(np.clip(ld, -1, 1.5)))), 1.55)
        ax.set_title("stability of every rotor mode over the speed range")
        ax.legend(handles=h, loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=6)
    return fig


CSS = """body{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.4;color:#222}
h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:2em}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;padding:.2em .5em;
text-align:left;vertical-align:top}th{background:#eee}
.pass{color:#060;font-weight:bold}.fail{color:#b00;font-weight:bold}.na{color:#777}
figure{margin:1em 0}figcaption{font-size:.9em;color:#444}svg{max-width:100%;height:auto}
pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:.85em}"""


def write_html(model: str, path, *, text_lines=(), operating_speed_hz=None,
               speeds_hz=None, chamber_pressure_pa: float | None = None) -> Path:
    """Write the HTML report of ``model`` (a built-in name or TOML path) to ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    from rotordyn.plot import bode, rotor_drawing, stability_map_grid
    from rotordyn.plot.frequency import campbell_diagram

    s = models.load(model)
    paper = s.name == "paper-rig"
    active = [b for b in s.bearings if isinstance(b, ActiveJournalBearing)]
    pc = (0.4e6 if active else 0.0) if chamber_pressure_pa is None else chamber_pressure_pa
    ay = 0.0 if active else None
    if operating_speed_hz is None and paper:
        operating_speed_hz = (45.0, 55.0)
    sp = np.arange(5.0, 121.0, 1.0) if speeds_hz is None else np.asarray(speeds_hz, float)
    checks = Checks()
    parts: list[str] = []
    title = f"Lateral analysis of {html.escape(s.name or str(model))}"
    op_txt = (f"{operating_speed_hz[0]:g}–{operating_speed_hz[1]:g} Hz"
              if operating_speed_hz else "not given (margins not assessed)")

    # 1. model
    rows = [("length", f"{s.rotor.length_m * 1e3:.0f} mm"), ("mass", f"{s.mass_kg:.3f} kg"),
            ("shaft elements", s.rotor.n_elements), ("stations", s.rotor.n_stations),
            ("disks", len(s.rotor.disks)),
            ("supports", ", ".join(f"{x.type} at {x.station}" for x in s.supports) or "none"),
            ("fluid-film bearings", ", ".join(f"{b.name or type(b).__name__} at {b.station}"
                                              for b in s.bearings) or "none"),
            ("reduction", f"{s.reduction.method} {list(s.reduction.master_stations)}"),
            ("operating speed range", op_txt),
            ("chamber pressure p_c, a_y (active bearing)",
             f"{pc / 1e6:g} MPa, {ay:g} mm" if active else "n/a")]
    parts.append("<h2>1. Model</h2>" + (f"<p>{html.escape(s.description)}</p>"
                                        if s.description else "")
                 + _table(["item", "value"], [(html.escape(a), html.escape(str(b)))
                                               for a, b in rows]))
    ax = rotor_drawing(s)
    parts.append(f"<figure>{svg(ax.figure)}<figcaption>Rotor drawn from the model: sections "
                 "to scale (radial scale exaggerated), disks, bearings, stations."
                 "</figcaption></figure>")

    # campbell (used by 2, 3, 5)
    if s.bearings:
        c = analysis.campbell(s, sp, pc, ay)
    else:
        c = analysis.rotor_campbell(s, sp)
    crit = c.critical_speeds()

    # 2. undamped critical speed map
    op_k = []
    if s.bearings and operating_speed_hz:
        lm = analysis.linearize(s, float(np.mean(operating_speed_hz)), pc, ay)
        lab = list(lm.labels)
        b = s.bearings[0]
        ix = lab.index(f"station{b.station}.x") if f"station{b.station}.x" in lab else None
        if ix is not None and lm.status in ("ok", "contact"):
            op_k = [(f"bearing k_xx at {np.mean(operating_speed_hz):g} Hz",
                     lm.KH[ix, ix], "--"),
                    (f"bearing k_yy at {np.mean(operating_speed_hz):g} Hz",
                     lm.KH[ix + 1, ix + 1], ":")]
    ks, fmap, stations = critical_speed_map(s)
    parts.append("<h2>2. Undamped critical speed map</h2><figure>"
                 + svg(_critical_map_figure(ks, fmap, stations, op_k))
                 + "<figcaption>Natural frequencies at rest with an isotropic spring k in place "
                 "of the bearing(s); vertical lines: the film's direct stiffness at the "
                 "operating point.</figcaption></figure>")

    # 3. Campbell
    ax = campbell_diagram(c, title=(f"Campbell diagram, p_c = {pc / 1e6:g} MPa" if active
                                    else "Campbell diagram"))
    ctab = [(f"{r.speed_hz:.2f}", f"{60 * r.speed_hz:.0f}", r.whirl) for r in crit.itertuples()]
    parts.append("<h2>3. Campbell diagram and critical speeds</h2><figure>" + svg(ax.figure)
                 + "</figure>" + _table(["critical speed (Hz)", "(rpm)", "whirl"], ctab))

    # 4. unbalance response
    disk = max(s.rotor.disks, key=lambda d: d.mass_kg) if s.rotor.disks else None
    st_ub = disk.station if disk else s.rotor.n_stations // 2
    n_sup = max(1, len(s.supports) + len(s.bearings))
    w_kg = s.mass_kg / n_sup
    nmax_rpm = 60 * (operating_speed_hz[1] if operating_speed_hz else sp[-1])
    u_kgm = API_UNBALANCE_G_MM * w_kg / nmax_rpm * 1e-6
    probe = s.bearings[0].station if s.bearings else st_ub
    outs = sorted({st_ub, probe})
    u = analysis.unbalance_response(s, [(st_ub, u_kgm, 0.0)], sp, stations=outs,
                                    chamber_pressure_pa=pc, config_ay_m=ay,
                                    operating_speed_hz=operating_speed_hz)
    parts.append(f"<h2>4. Unbalance response</h2><p>API 684 unbalance U = 6350 W/N g·mm = "
                 f"{u_kgm * 1e6:.1f} g·mm at station {st_ub} (W = {w_kg:.2f} kg per support, "
                 f"N = {nmax_rpm:.0f} rpm); the speed grid is refined at every peak.</p>")
    for st in outs:
        a1, _ = bode(u, station=st)
        parts.append(f"<figure>{svg(a1.figure)}</figure>")
        pk = u.peaks(st)
        rows = []
        for r in pk.to_dict("records"):
            af = r["amplification_factor"]
            req = r.get("required_margin_pct", np.nan)
            sm = r.get("separation_margin_pct", np.nan)
            ok = None if not np.isfinite(req) else bool(sm >= req)
            aft = f"{af:.3g}" if np.isfinite(af) else "∞ (half-power points not found)"
            rows.append((f"{r['critical_speed_hz']:.2f}", f"{r['peak_m'] * 1e6:.3g}", aft, f"{sm:.1f}" if np.isfinite(sm) else "n/a",
                         f"{req:.1f}" if np.isfinite(req) else "n/a", _verdict(ok)))
            if operating_speed_hz:
                checks.add(f"separation margin, N_c = {r['critical_speed_hz']:.1f} Hz "
                           f"(station {st})",
                           "API 684: AF < 2.5 needs none; else SM ≥ 17(1 − 1/(AF − 1.5)) % "
                           "below / 10 + that above the operating range",
                           f"AF {aft}, SM {sm:.1f} %, required {req:.1f} %", ok)
        parts.append(_table(["N_c (Hz)", "peak (µm)", "AF", "SM (%)", "required (%)",
                             "result"], rows))
        if operating_speed_hz:
            lo, hi = operating_speed_hz
            inr = (u.speeds_hz >= lo) & (u.speeds_hz <= hi)
            if inr.any():
                pp = 2 * np.nanmax(u.major_m[inr, outs.index(st)]) * 1e6
                lim = 25.4 * np.sqrt(12000.0 / nmax_rpm)
                checks.add(f"vibration amplitude in the operating range (station {st})",
                           "API 617: peak-to-peak ≤ 25.4 √(12000/N_mc) µm", f"{pp:.3g} µm "
                           f"(limit {lim:.3g} µm)", bool(pp <= lim))
    parts.append("<p>AF: amplification factor N_c/(N₂ − N₁) by the half-power method; SM: "
                 "separation margin from the operating speed range.</p>")

    # 5. stability over speed
    fig = _log_dec_figure(c, operating_speed_hz)
    parts.append("<h2>5. Stability: logarithmic decrement of every mode</h2><figure>"
                 + svg(fig) + "</figure>")
    ld = np.where(c.rotor_mask(), c.log_dec, np.nan)
    if operating_speed_hz:
        inr = (c.speeds_hz >= operating_speed_hz[0]) & (c.speeds_hz <= operating_speed_hz[1])
        ldmin = np.nanmin(ld[inr]) if inr.any() and np.isfinite(ld[inr]).any() else np.nan
        checks.add("stability in the operating range", f"API 617 level I: every rotor mode "
                   f"δ > {API_LOG_DEC_MIN}", f"minimum δ = {ldmin:.3g}",
                   bool(ldmin > API_LOG_DEC_MIN) if np.isfinite(ldmin) else None)
    ldall = np.nanmin(ld) if np.isfinite(ld).any() else np.nan
    checks.add("stability over the whole speed range", "every rotor mode δ > 0 (no growing "
               "mode)", f"minimum δ = {ldall:.3g}",
               bool(ldall > 0) if np.isfinite(ldall) else None)

    # 6. active bearing: stability map in p_c
    if active:
        speed = float(np.mean(operating_speed_hz)) if operating_speed_hz else 50.0
        ays = np.linspace(-2.5e-3, 0.5e-3, 13)
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
        ax = stability_map_grid(ays, pcs, Z, xname="config_ay_m", yname="chamber_pressure_pa",
                                failed=failed,
                                title=f"active bearing: stability map at {speed:g} Hz")
        parts.append("<h2>6. Active bearing: stability map in p_c</h2><figure>" + svg(ax.figure)
                     + "</figure>")
        t = analysis.threshold(s, "chamber_pressure_pa", bounds=(0.02e6, 0.3e6),
                               speed_hz=speed, config_ay_m=-1.85e-3, n_scan=8)
        checks.add(f"threshold of instability at a_y = −1.85 mm, {speed:g} Hz",
                   "stable operation needs p_c on the stable side of the threshold",
                   f"p_c = {t.value / 1e6:.4f} MPa, stable {t.stable_side} ({t.status})", None)

    # 7. text report
    if text_lines:
        parts.append("<h2>7. Checks against the reference paper (text report)</h2><pre>"
                     + html.escape("\n".join(text_lines)) + "</pre>")
    doc = (f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}"
           f"</title><style>{CSS}</style></head><body><h1>{title}</h1>"
           f"<p>rotordyn {__version__}. Checks and criteria:</p>{checks.html()}"
           + "".join(parts) + "</body></html>\n")
    doc = re.sub(r"\n\s*\n", "\n", doc)
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(doc, encoding="utf-8")
    return out
