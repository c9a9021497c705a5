"""Robust stability and performance of the rig's tuned PD and LQG laws (designed at a_y =
−1.85 mm, 50 Hz, p_c = 0.05 MPa; docs/control.md §3.1) over the operating range and the
bearing's uncertain clearance and viscosity (issue 24, docs/control.md §2.7).

Grids (the law fixed, the plant re-linearised at every point, margins at every stable point):
* PD: speed 30–70 Hz (5 Hz) × p_c 0–0.3 MPa (0.05 MPa) at a_y = −1.85 mm;
* LQG: speed 30–70 Hz (10 Hz) × p_c 0.05, 0.1 MPa;
* PD at the design point (50 Hz, 0.05 MPa): clearance 0.27, 0.30, 0.33 mm × viscosity
  0.036, 0.040, 0.044 Pa·s (±10 %).

Prints per grid the counts, the worst case of each quantity with its point, the ISO 14839-3
zones of the peak sensitivity; writes docs/figures/control_robust.png (max Re λ and peak |S|
of the PD over speed × p_c).

Run:  .venv/bin/python docs/calibration/control_robust.py
"""

from __future__ import annotations

import os
import time

import numpy as np

import rotordyn as rd
from rotordyn.control.lqr import lqg
from rotordyn.control.pid import tune_pd
from rotordyn.control.plant import plant
from rotordyn.control.reduction import modal_truncation
from rotordyn.sweep.robust import robust

AY, PC, F = -1.85e-3, 0.05e6, 50.0
FIG = os.path.join(os.path.dirname(__file__), "..", "figures", "control_robust.png")


def show(label, r, wall):
    s = r.summary()
    print(f"\n== {label}: {s['points']} points in {wall:.1f} s wall; {s['stable']} stable, "
          f"{s['unstable']} unstable, {s['failed']} without verdict; zones {s['zones']}")
    for q, w in s["worst"].items():
        at = ", ".join(f"{a} {w[a]:g}" for a in r.axes)
        print(f"   worst {q:18s} {w['value']:.5g}  at {at}")
    if s["failed"]:
        for _, row in r.failed.iterrows():
            print(f"   no verdict at {', '.join(f'{a} {row[a]:g}' for a in r.axes)}: "
                  f"{row.status}: {row.message[:90]}")


def main():
    rig = rd.models.paper_rig()
    p = plant(rig, F, PC, AY, measurements=[("journal", 0)])
    pd_law = tune_pd(p)[0]
    lqg_law = lqg(modal_truncation(p, 500.0)[0])
    print(f"load {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")

    t = time.perf_counter()
    r_pd = robust(rig, pd_law, {"speed_hz": {"start": 30.0, "stop": 70.0, "num": 9},
                                "chamber_pressure_pa": {"start": 0.0, "stop": 0.3e6, "num": 7},
                                "config_ay_m": AY})
    show("PD over speed x p_c", r_pd, time.perf_counter() - t)
    f = r_pd.frame
    print("   per speed: the stable pressures (MPa) and the range of peak |S| there")
    for sp, g in f.groupby("speed_hz"):
        st = g[g.point_stable == True]  # noqa: E712
        if not len(st):
            print(f"   {sp:5.1f} Hz: stable at none of {len(g)} pressures")
            continue
        pcs = " ".join(f"{x / 1e6:.2f}" for x in st.chamber_pressure_pa)
        print(f"   {sp:5.1f} Hz: stable at {len(st)}/{len(g)} ({pcs}); peak |S| "
              f"{st.peak_sensitivity.min():.3f}–{st.peak_sensitivity.max():.3f}")

    t = time.perf_counter()
    r_lqg = robust(rig, lqg_law, {"speed_hz": {"start": 30.0, "stop": 70.0, "num": 5},
                                  "chamber_pressure_pa": [0.05e6, 0.1e6], "config_ay_m": AY})
    show("LQG over speed x p_c", r_lqg, time.perf_counter() - t)

    t = time.perf_counter()
    r_unc = robust(rig, pd_law, {"bearings.active.clearance_m": [2.7e-4, 3.0e-4, 3.3e-4],
                                 "bearings.active.viscosity_pa_s": [0.036, 0.040, 0.044],
                                 "speed_hz": F, "chamber_pressure_pa": PC, "config_ay_m": AY})
    show("PD at the design point, clearance x viscosity (±10 %)", r_unc,
         time.perf_counter() - t)
    print(r_unc.frame[["bearings.active.clearance_m", "bearings.active.viscosity_pa_s",
                       "max_real_1_per_s", "gain_margin_lower", "gain_margin_upper",
                       "phase_margin_deg", "peak_sensitivity", "iso_zone"]].to_string(
                           index=False))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axs = plt.subplots(1, 2, figsize=(12, 4.5))
    r_pd.plot("max_real_1_per_s", x="speed_hz", ax=axs[0])
    r_pd.plot("peak_sensitivity", x="speed_hz", ax=axs[1])
    fig.tight_layout()
    fig.savefig(FIG, dpi=110)
    print(f"\nfigure: {os.path.normpath(FIG)}")


if __name__ == "__main__":
    main()
