"""``rotordyn report MODEL --out DIR`` (the main job of ``make run``): the model's rotor and
sleeve frequencies, and for a system with an active bearing the paper's checks — Table 1
equilibria, the threshold of instability and the critical speeds — each beside the paper's
value when the model is the paper's rig. Text, CSV/JSON tables and PNG figures under DIR."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.model.bearings import ActiveJournalBearing

PAPER_ROTOR_HZ = (10.43, 43.04, 106.38)
PAPER_SLEEVE_HZ = (490.2, 1754.2, 6175.8)
PAPER_TABLE1 = {0.10e6: (0.1583, 0.0554), 0.15e6: (0.2915, 0.1234), 0.20e6: (0.4096, 0.2122),
                0.25e6: (0.4988, 0.3023)}
PAPER_THRESHOLD_PA = 0.098e6
PAPER_CRITICAL_HZ = (39.0, 90.0)


def _fmt_row(cells, widths):
    return " ".join(f"{c:>{w}}" for c, w in zip(cells, widths))


def run(model: str, out: str) -> int:
    import matplotlib

    matplotlib.use("Agg")
    s = rotordyn.models.load(model)
    paper = s.name == "paper-rig"
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    lines: list[str] = []

    def say(text=""):
        print(text)
        lines.append(text)

    # 1. rotor modes, full vs condensed
    method = s.reduction.method if s.reduction.method != "none" else "guyan"
    r = rotordyn.modes(s, 0.0, reduction=method)
    say(f"{s.name or model}: rotor {s.rotor.length_m:.3f} m, {s.mass_kg:.3f} kg, "
        f"{s.rotor.n_elements} elements, masters at stations "
        f"{list(s.reduction.master_stations)} ({r.model})")
    w = (4, 11, 15, 8, 11)
    say(_fmt_row(["mode", "full (Hz)", "condensed (Hz)", "error", "paper (Hz)" if paper else ""], w))
    for i, (a, b) in enumerate(zip(r.full.frequencies_hz[::2], r.frequencies_hz[::2])):
        say(_fmt_row([i + 1, f"{a:.3f}", f"{b:.3f}", f"{100 * (b - a) / a:.2f}%",
                      f"{PAPER_ROTOR_HZ[i]:.2f}" if paper and i < 3 else ""], w))
    r.to_frame().to_csv(outdir / "rotor_modes.csv", index=False)
    (outdir / "rotor_modes.json").write_text(json.dumps({
        "frequencies_hz": r.frequencies_hz.tolist(),
        "full_frequencies_hz": r.full.frequencies_hz.tolist()}, indent=2) + "\n")
    ax = r.full.plot(modes=range(0, 6, 2))
    ax.figure.savefig(outdir / "rotor_mode_shapes.png", dpi=120, bbox_inches="tight")

    active = [b for b in s.bearings if isinstance(b, ActiveJournalBearing)]
    if active:
        # 2. sleeve
        sr = active[0].sleeve.condense()
        say()
        say("flexible sleeve (three-step Guyan condensation)")
        say(_fmt_row(["mode", "full (Hz)", "condensed (Hz)", "", "paper (Hz)" if paper else ""], w))
        for i, c in enumerate(sr.freq_condensed_hz):
            say(_fmt_row([i + 1, f"{sr.freq_full_hz[i]:.1f}", f"{c:.1f}", "",
                          f"{PAPER_SLEEVE_HZ[i]:.1f}" if paper and i < 3 else ""], w))
        sr.to_frame().to_csv(outdir / "sleeve_modes.csv", index=False)

        # 3. Table 1 (a_y = -1.85 mm, 50 Hz)
        say()
        say("equilibrium at a_y = -1.85 mm, 50 Hz (paper Table 1; the paper's x axis is mirrored)")
        w3 = (8, 9, 9, 10, 10, 6)
        say(_fmt_row(["p_c MPa", "x/c", "y/c", "paper |x|", "paper y", "iter"], w3))
        rows = []
        for pc in sorted(PAPER_TABLE1):
            e = rotordyn.equilibrium(s, 50.0, pc, -1.85e-3)
            px, py = PAPER_TABLE1[pc] if paper else (np.nan, np.nan)
            say(_fmt_row([f"{pc / 1e6:.2f}", f"{e.x_over_c[0]:.4f}", f"{e.y_over_c[0]:.4f}",
                          f"{px:.4f}", f"{py:.4f}", e.iterations], w3))
            rows.append(e.to_frame())
        import pandas as pd

        pd.concat(rows, ignore_index=True).to_csv(outdir / "table1_equilibrium.csv", index=False)

        # 4. threshold
        t = rotordyn.threshold(s, "chamber_pressure_pa", bounds=(0.02e6, 0.3e6),
                               speed_hz=50.0, config_ay_m=-1.85e-3, n_scan=8)
        say()
        say(f"threshold of instability at a_y = -1.85 mm, 50 Hz: p_c = "
            f"{t.value / 1e6:.4f} MPa (stable {t.stable_side}; whirl {t.whirl_frequency_hz:.2f}"
            f" Hz){'; paper 0.098 MPa' if paper else ''} [{t.status}]")
        t.to_frame().to_csv(outdir / "threshold.csv", index=False)

        # 5. Campbell and critical speeds at p_c = 0.4 MPa, a_y = 0
        c = rotordyn.campbell(s, np.arange(5.0, 121.0, 1.0), 0.4e6, 0.0)
        crit = c.critical_speeds()
        say(f"critical speeds at p_c = 0.4 MPa: "
            + ", ".join(f"{x:.1f} Hz" for x in crit["speed_hz"])
            + ("; paper 39 and 90 Hz" if paper else ""))
        c.to_frame().to_csv(outdir / "campbell.csv", index=False)
        ax = c.plot()
        ax.set_title("natural frequencies at p_c = 0.4 MPa (paper Fig. 12)")
        ax.figure.savefig(outdir / "campbell.png", dpi=120, bbox_inches="tight")

    (outdir / "report.txt").write_text("\n".join(lines) + "\n")
    print(f"wrote {outdir}/report.txt and tables/figures", file=sys.stderr)
    return 0
