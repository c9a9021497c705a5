"""``rotordyn report MODEL --out DIR`` (the main job of ``make run``): the model's rotor and
sleeve frequencies, and for a system with an active bearing its journal's equilibria over
p_c, the threshold of instability and the critical speeds — on the paper's rig at the paper's
conditions (Table 1), each beside the paper's value; on another model at the active bearing's
own configuration and the report's speeds (docs/api-criteria.md). Text, CSV/JSON tables and
PNG figures under DIR."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

from rotordyn import analysis
from rotordyn._common.status import CONVERGED
from rotordyn.model import builtin as models
from rotordyn.bearings import ActiveJournalBearing

PAPER_ROTOR_HZ = (10.43, 43.04, 106.38)
PAPER_SLEEVE_HZ = (490.2, 1754.2, 6175.8)
PAPER_TABLE1 = {0.10e6: (0.1583, 0.0554), 0.15e6: (0.2915, 0.1234), 0.20e6: (0.4096, 0.2122),
                0.25e6: (0.4988, 0.3023)}
PAPER_THRESHOLD_PA = 0.098e6
PAPER_CRITICAL_HZ = (39.0, 90.0)
# The two calibrations of the paper's rig (docs/paper-rig.md, "Cavitation model").
CALIBRATIONS = {"paper-rig": "Swift-Stieber film, fitted to Table 1",
                "paper-rig-hs": "half-Sommerfeld film, fitted to Table 1 + threshold"}

# Stated tolerances of the comparisons with the paper (a mark says "ok" only within them).
TOL_ROTOR_REL = 0.01       # condensed rotor frequencies: calibrated to 10.43/43.04/106.38 Hz
TOL_SLEEVE_REL = 0.02      # condensed sleeve frequencies
TOL_TABLE1_ABS = 0.01      # x/c, y/c of Table 1 (0.01 c = 3 µm)
TOL_THRESHOLD_REL = 0.10   # threshold of instability p_c
TOL_CRITICAL_REL = 0.03    # critical speeds (1 Hz Campbell grid)


def mark(value: float, ref: float, *, rtol: float | None = None,
         atol: float | None = None) -> str:
    """Comparison mark from a stated tolerance: ``ok (±2 %)`` within it, else
    ``OFF by 42 %`` (relative) or ``OFF by 0.031`` (absolute), with the tolerance."""
    if not (np.isfinite(value) and np.isfinite(ref)):
        return "n/a"
    if rtol is not None:
        err = abs(value - ref) / abs(ref)
        return (f"ok (±{100 * rtol:g} %)" if err <= rtol
                else f"OFF by {100 * err:.2g} % (tolerance {100 * rtol:g} %)")
    err = abs(value - ref)
    return (f"ok (±{atol:g})" if err <= atol
            else f"OFF by {err:.3g} (tolerance {atol:g})")


def _fmt_row(cells, widths):
    return " ".join(f"{c:>{w}}" for c, w in zip(cells, widths))


def run(model: str, out: str, html: str | None = None, operating_speed_hz=None,
        speeds_hz=None, level1_options: dict | None = None) -> int:
    s = models.load(model)  # a bad model exits before matplotlib is imported
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    paper = s.name in CALIBRATIONS
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    lines: list[str] = []

    def say(text=""):
        print(text)
        lines.append(text)

    # 1. rotor modes, full vs condensed
    method = s.reduction.method
    r = analysis.modes(s, 0.0, reduction=method, n_modes=None if method != "none" else 6,
                       without_bearings=True)
    full = r.full if r.full is not None else r
    say(f"{s.name or model}: rotor {s.rotor.length_m:.3f} m, {s.mass_kg:.3f} kg, "
        f"{s.rotor.n_elements} elements, "
        + (f"masters at stations {list(s.reduction.master_stations)} ({r.model})"
           if method != "none" else "full model (no reduction)"))
    say("rotor modes at rest on its supports" + (", without the bearing elements (their films "
                                                  "depend on the operating point)"
                                                  if s.bearings else ""))
    w = (4, 11, 15, 8, 11, 18)
    say(_fmt_row(["mode", "full (Hz)", "condensed (Hz)", "error",
                  "paper (Hz)" if paper else "", "check" if paper else ""], w))
    for i, (a, b) in enumerate(zip(full.frequencies_hz[::2], r.frequencies_hz[::2])):
        ref = PAPER_ROTOR_HZ[i] if paper and i < 3 else np.nan
        say(_fmt_row([i + 1, f"{a:.3f}", f"{b:.3f}" if r.full is not None else "-",
                      f"{100 * (b - a) / a:.2f}%" if r.full is not None else "",
                      f"{ref:.2f}" if np.isfinite(ref) else "",
                      mark(b, ref, rtol=TOL_ROTOR_REL) if np.isfinite(ref) else ""], w))
    r.to_frame().to_csv(outdir / "rotor_modes.csv", index=False)
    (outdir / "rotor_modes.json").write_text(json.dumps({
        "frequencies_hz": r.frequencies_hz.tolist(),
        "full_frequencies_hz": full.frequencies_hz.tolist()}, indent=2) + "\n")
    ax = full.plot(modes=range(0, min(6, len(full.eigenvalues)), 2))
    ax.figure.savefig(outdir / "rotor_mode_shapes.png", dpi=200, bbox_inches="tight")
    plt.close(ax.figure)  # a long-lived process writing many reports keeps no figure

    active = [b for b in s.bearings if isinstance(b, ActiveJournalBearing)]
    campbell_04 = None  # the Campbell at p_c = 0.4 MPa of the paper's checks, reused below
    # API 617 Level I (with the model's stages, at the top of the operating range)
    from rotordyn.report import level1 as level1_report

    l1, why = level1_report.evaluate(s, operating_speed_hz, 0.4e6 if active else 0.0,
                                     0.0 if active else None, **(level1_options or {}))
    say()
    for line in level1_report.text_lines(l1, why):
        say(line)
    if l1 is not None:
        l1.to_frame().to_csv(outdir / "level1.csv", index=False)

    if active:
        # 2. sleeve
        sr = active[0].sleeve.condense()
        say()
        say("flexible sleeve (three-step Guyan condensation)")
        say(_fmt_row(["mode", "full (Hz)", "condensed (Hz)", "", "paper (Hz)" if paper else "",
                      "check" if paper else ""], w))
        for i, c in enumerate(sr.freq_condensed_hz):
            ref = PAPER_SLEEVE_HZ[i] if paper and i < 3 else np.nan
            say(_fmt_row([i + 1, f"{sr.freq_full_hz[i]:.1f}", f"{c:.1f}", "",
                          f"{ref:.1f}" if np.isfinite(ref) else "",
                          mark(c, ref, rtol=TOL_SLEEVE_REL) if np.isfinite(ref) else ""], w))
        sr.to_frame().to_csv(outdir / "sleeve_modes.csv", index=False)

        # 3.–5. on the paper's rig its conditions (Table 1 at a_y = -1.85 mm, 50 Hz, and the
        # paper's 5–120 Hz); on another model the active bearing's own configuration at the
        # HTML section 6's speed, p_c over its map's 0–0.4 MPa and the report's speeds
        ia = next(i for i, b in enumerate(s.bearings) if isinstance(b, ActiveJournalBearing))
        aname = s.bearings[ia].name or f"bearing[{ia}]"
        if paper:
            speed, ay, pcs = 50.0, -1.85e-3, sorted(PAPER_TABLE1)
            bounds, where = (0.02e6, 0.3e6), "a_y = -1.85 mm, 50 Hz"
        else:
            speed = float(np.mean(operating_speed_hz)) if operating_speed_hz else 50.0
            ay, pcs, bounds = s.bearings[ia].config_ay_m, [0.0, 0.1e6, 0.2e6, 0.3e6, 0.4e6], \
                (0.0, 0.4e6)
            where = f"its configuration a_y = {1e3 * ay:g} mm, {speed:g} Hz"
        say()
        if paper:
            say(f"equilibrium at {where} (paper Table 1; the paper's x axis is mirrored)")
        else:
            say(f"equilibrium of the active bearing {aname!r} at {where}")
        w3 = (8, 9, 9, 10, 10, 6, 30) if paper else (8, 9, 9, 6, 14)

        def row3(cells):  # the paper's columns on its rig only
            return _fmt_row(cells if paper else cells[:3] + cells[5:], w3)
        say(row3(["p_c MPa", "x/c", "y/c", "paper |x|", "paper y", "iter",
                  "check (|x|/c, y/c)" if paper else "status"]))
        rows = []
        for pc in pcs:
            e = analysis.equilibrium(s, speed, pc, ay)
            x, y = e.x_over_c[ia], e.y_over_c[ia]  # the active bearing's journal
            chk, px, py = e.status, "", ""
            if paper:
                rx, ry = PAPER_TABLE1[pc]
                px, py = f"{rx:.4f}", f"{ry:.4f}"
                chk = mark(max(abs(abs(x) - rx), abs(y - ry)), 0.0, atol=TOL_TABLE1_ABS)
            ok = e.status in CONVERGED
            say(row3([f"{pc / 1e6:.2f}", f"{x:.4f}" if ok else "-",
                      f"{y:.4f}" if ok else "-", px, py, e.iterations, chk]))
            rows.append(e.to_frame())
        import pandas as pd

        pd.concat(rows, ignore_index=True).to_csv(outdir / "table1_equilibrium.csv", index=False)

        # 4. threshold
        t = analysis.threshold(s, "chamber_pressure_pa", bounds=bounds, speed_hz=speed,
                               config_ay_m=ay, n_scan=8)
        say()
        head = f"threshold of instability {'' if paper else 'in p_c '}at {where}: "
        if t.status == "ok":
            say(head + f"p_c = {t.value / 1e6:.4f} MPa (stable {t.stable_side}; whirl "
                f"{t.whirl_frequency_hz:.2f} Hz; status {t.status})"
                + (f"; paper {PAPER_THRESHOLD_PA / 1e6:.3f} MPa: "
                   f"{mark(t.value, PAPER_THRESHOLD_PA, rtol=TOL_THRESHOLD_REL)}"
                   if paper else ""))
        else:  # no crossing in the bounds (or a failed scan): say what the scan saw
            say(head + f"none in {bounds[0] / 1e6:g}–{bounds[1] / 1e6:g} MPa ({t.status}: "
                f"{t.message})" + (f"; paper {PAPER_THRESHOLD_PA / 1e6:.3f} MPa: missing"
                                   if paper else ""))
        t.to_frame().to_csv(outdir / "threshold.csv", index=False)

        # 5. Campbell and critical speeds at p_c = 0.4 MPa, the configuration of the rest of
        # the report
        from rotordyn.report.criteria import speed_range

        op = operating_speed_hz or ((45.0, 55.0) if paper else None)  # as the HTML report
        sp = np.arange(5.0, 121.0, 1.0) if paper else speed_range(s, op, speeds_hz, None,
                                                                  paper).speeds_hz
        c = campbell_04 = analysis.campbell(s, sp, 0.4e6, s.bearings[ia].config_ay_m)
        crit = c.critical_speeds()
        cs = crit.loc[crit["resonant"], "speed_hz"].to_numpy()
        line = ("critical speeds at p_c = 0.4 MPa"
                + ("" if paper else f" ({sp[0]:.4g}–{sp[-1]:.4g} Hz)") + ": "
                + ", ".join(f"{x:.1f} Hz" for x in cs) + ("" if len(cs) or paper else "none"))
        if paper:
            line += "; paper " + ", ".join(
                f"{ref:g} Hz: " + (mark(cs[np.argmin(abs(cs - ref))], ref, rtol=TOL_CRITICAL_REL)
                                   if len(cs) else "missing")
                for ref in PAPER_CRITICAL_HZ)
        say(line)
        c.to_frame().to_csv(outdir / "campbell.csv", index=False)
        ax = c.plot()
        ax.set_title("natural frequencies at p_c = 0.4 MPa"
                     + (" (paper Fig. 12)" if paper else ""))
        ax.figure.savefig(outdir / "campbell.png", dpi=200, bbox_inches="tight")
        plt.close(ax.figure)

        if paper:
            say()
            _calibrations_side_by_side(say, outdir)

    if html:
        from rotordyn.report.html import write_html

        extra: list[str] = []
        write_html(model, html, text_lines=lines, operating_speed_hz=operating_speed_hz,
                   speeds_hz=speeds_hz, level1_options=level1_options,
                   figure_dir=outdir, text_sink=extra)
        for text in extra:
            say(text)
        print(f"wrote {html}", file=sys.stderr)
    else:
        # the critical speeds with their sources, their mode shapes and the bearings'
        # coefficients, as the HTML report has them (same speeds, p_c and a_y)
        from rotordyn.report import sections
        from rotordyn.report.criteria import speed_range

        op = operating_speed_hz or ((45.0, 55.0) if paper else None)  # as the HTML report
        rng = speed_range(s, op, speeds_hz, None, paper)
        same = campbell_04 is not None and np.array_equal(campbell_04.speeds_hz, rng.speeds_hz)
        for text in sections.write_text_sections(
                s, rng, 0.4e6 if active else 0.0, active[0].config_ay_m if active else None,
                outdir,
                op, campbell=campbell_04 if same else None, level1=(l1, why)):
            say(text)
    (outdir / "report.txt").write_text("\n".join(lines) + "\n")
    print(f"wrote {outdir}/report.txt and tables/figures", file=sys.stderr)
    return 0


def _calibrations_side_by_side(say, outdir: Path) -> None:
    """Table 1 and the threshold of both built-in calibrations of the paper's rig beside the
    paper's values, so a user can pick the calibration for the number to reproduce."""
    names = list(CALIBRATIONS)
    systems = {n: models.load(n) for n in names}
    say("the two calibrations of the paper's rig side by side (a_y = -1.85 mm, 50 Hz):")
    for n in names:
        say(f"  {n}: {CALIBRATIONS[n]}")
    w = (22, 15) + (15,) * len(names)
    say(_fmt_row(["quantity", "paper"] + names, w))
    rows = []
    for pc in sorted(PAPER_TABLE1):
        px, py = PAPER_TABLE1[pc]
        es = {n: analysis.equilibrium(systems[n], 50.0, pc, -1.85e-3) for n in names}
        for lab, ref, get in ((f"|x|/c at {pc / 1e6:.2f} MPa", px, lambda e: abs(e.x_over_c[0])),
                              (f"y/c at {pc / 1e6:.2f} MPa", py, lambda e: e.y_over_c[0])):
            vals = {n: float(get(es[n])) for n in names}
            say(_fmt_row([lab, f"{ref:.4f}"] + [f"{vals[n]:.4f}" for n in names], w))
            rows.append({"quantity": lab, "paper": ref, **vals})
    th = {}
    for n in names:
        t = analysis.threshold(systems[n], "chamber_pressure_pa", bounds=(0.02e6, 0.3e6),
                               speed_hz=50.0, config_ay_m=-1.85e-3, n_scan=8)
        th[n] = t.value / 1e6 if t.status == "ok" else float("nan")
    say(_fmt_row(["threshold p_c (MPa)", f"{PAPER_THRESHOLD_PA / 1e6:.4f}"]
                 + [f"{th[n]:.4f}" for n in names], w))
    rows.append({"quantity": "threshold p_c (MPa)", "paper": PAPER_THRESHOLD_PA / 1e6, **th})
    t1 = {n: max(abs(r[n] - r["paper"]) for r in rows[:-1]) for n in names}
    say(_fmt_row(["Table 1 max |error|", f"tol {TOL_TABLE1_ABS:g}"]
                 + [mark(t1[n], 0.0, atol=TOL_TABLE1_ABS) for n in names], w))
    say(_fmt_row(["threshold", f"tol {100 * TOL_THRESHOLD_REL:g} %"]
                 + [mark(th[n] * 1e6, PAPER_THRESHOLD_PA, rtol=TOL_THRESHOLD_REL)
                    for n in names], w))
    import pandas as pd

    pd.DataFrame(rows).to_csv(outdir / "calibrations.csv", index=False)
