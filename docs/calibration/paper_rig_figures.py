"""Equilibrium loci of the paper's rig (reference paper §6.1, Fig. 7 and Fig. 8).

Fig. 7: journal equilibrium at W = 50 Hz for a_y = −1.0, −0.5, …, 2.5 mm, p_c = 0 … 0.25 MPa.
Fig. 8: a_y = 0 for W = 10, 20, 30, 40, 50 Hz, p_c = 0 … 0.25 MPa.
Each curve is traced by continuation in p_c (Newton, warm start from the previous point; the
first point from the concentric, undeformed state). Writes docs/figures/paper_rig_fig7.png
and docs/figures/paper_rig_fig8.png and prints the loci's numbers (docs/paper-rig.md).

Plotted in rotordyn's frame (x right, y up, rotation counter-clockwise); the paper's x is −x
(docs/paper-rig.md, "Sign convention").

Run:  .venv/bin/python docs/calibration/paper_rig_figures.py [--out docs/figures]
"""

from __future__ import annotations

import argparse
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rotordyn as rd  # noqa: E402

AY_MM = (-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5)
SPEEDS_HZ = (10.0, 20.0, 30.0, 40.0, 50.0)
PC_PA = np.linspace(0.0, 0.25e6, 26)  # 0.01 MPa steps


def locus(system, speed_hz, ay_m, pcs=PC_PA):
    """Continuation in p_c: arrays x/c, y/c, h_min/c, iterations, statuses."""
    out = {"x": [], "y": [], "hmin": [], "it": [], "solves": [], "status": []}
    for i, pc in enumerate(pcs):
        r = rd.equilibrium(system, speed_hz, float(pc), ay_m, warm_start=i > 0)
        out["x"].append(r.x_over_c[0])
        out["y"].append(r.y_over_c[0])
        out["hmin"].append(r.h_min_m[0] / r.clearance_m[0])
        out["it"].append(r.iterations)
        out["solves"].append(r.reynolds_solves)
        out["status"].append(r.status)
    return {k: (np.asarray(v) if k != "status" else v) for k, v in out.items()}


def fig7_loci(system=None, pcs=PC_PA):
    system = system or rd.models.paper_rig()
    return {ay: locus(system, 50.0, ay * 1e-3, pcs) for ay in AY_MM}


def fig8_loci(system=None, pcs=PC_PA):
    system = system or rd.models.paper_rig()
    return {w: locus(system, w, 0.0, pcs) for w in SPEEDS_HZ}


def plot(loci, label, title, path, pcs=PC_PA):
    fig, ax = plt.subplots(figsize=(6.4, 5.6))
    cmap = plt.get_cmap("viridis")
    keys = list(loci)
    for i, k in enumerate(keys):
        d = loci[k]
        col = cmap(i / max(len(keys) - 1, 1))
        ax.plot(d["x"], d["y"], "-", color=col, lw=1.4, label=label.format(k))
        ax.plot(d["x"][0], d["y"][0], "o", color=col, ms=4)           # p_c = 0
        for j in range(5, len(pcs), 5):                               # every 0.05 MPa
            ax.plot(d["x"][j], d["y"][j], ".", color=col, ms=5)
    ax.set_aspect("equal")
    xs = np.concatenate([loci[k]["x"] for k in keys])
    ys = np.concatenate([loci[k]["y"] for k in keys])
    pad = 0.08
    ax.set_xlim(min(xs.min(), -0.1) - pad, max(xs.max(), 0.1) + pad)
    ax.set_ylim(min(ys.min(), -0.1) - pad, max(ys.max(), 0.1) + pad)
    ax.axhline(0, color="0.85", lw=0.5)
    ax.axvline(0, color="0.85", lw=0.5)
    ax.set_xlabel("x/c  (rotordyn frame: x right, rotation counter-clockwise; paper's x = −x)")
    ax.set_ylabel("y/c  (up)")
    d0 = loci[keys[0]]
    ax.annotate(f"p_c = {pcs[-1] / 1e6:.2f} MPa", (d0["x"][-1], d0["y"][-1]), fontsize=7,
                xytext=(4, 6), textcoords="offset points")
    ax.annotate("p_c = 0", (d0["x"][0], d0["y"][0]), fontsize=7, xytext=(-36, -4),
                textcoords="offset points")
    ax.set_title(title + "\n(o: p_c = 0; dots every 0.05 MPa)", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def report(loci, name, unit):
    sel = [0, 5, 10, 15, 20, 25]
    print(f"\n{name}: x/c, y/c at p_c = " + ", ".join(f"{PC_PA[j] / 1e6:.2f}" for j in sel)
          + " MPa; h_min/c at 0 and 0.25 MPa; Newton iterations per point (max)")
    for k, d in loci.items():
        bad = [s for s in d["status"] if s != "ok"]
        step = np.hypot(np.diff(d["x"]), np.diff(d["y"]))
        print(f"  {k:5.1f} {unit}: " + "  ".join(f"({d['x'][j]:+.3f},{d['y'][j]:+.3f})" for j in sel)
              + f"  hmin {d['hmin'][0]:.3f}/{d['hmin'][-1]:.3f}  it<= {d['it'].max()}"
              + f"  max step {step.max():.4f} (median {np.median(step):.4f})"
              + (f"  statuses {sorted(set(bad))}" if bad else ""))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "figures"))
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    t0 = time.perf_counter()
    s = rd.models.paper_rig()
    l7 = fig7_loci(s)
    l8 = fig8_loci(s)
    t1 = time.perf_counter()
    report(l7, "Fig. 7 (W = 50 Hz)", "mm")
    report(l8, "Fig. 8 (a_y = 0)", "Hz")
    plot(l7, "a_y = {:+.1f} mm", "Fig. 7: journal equilibrium, W = 50 Hz, p_c = 0-0.25 MPa",
         os.path.join(args.out, "paper_rig_fig7.png"))
    plot(l8, "W = {:.0f} Hz", "Fig. 8: journal equilibrium, a_y = 0, p_c = 0-0.25 MPa",
         os.path.join(args.out, "paper_rig_fig8.png"))
    n = sum(len(d["x"]) for d in (*l7.values(), *l8.values()))
    print(f"\n{n} equilibria in {t1 - t0:.2f} s; figures in {os.path.normpath(args.out)}")


if __name__ == "__main__":
    main()
