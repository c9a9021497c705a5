"""Nonlinear checks of the paper's rig (§6.2 Fig. 11, §6.3 Fig. 13-14) with the CVODE
transient: journal orbits after a disturbance at a_y = -1.85 mm, 50 Hz, p_c = 0.05, 0.10,
0.15 MPa, and a waterfall of the unbalance response at p_c = 0.4 MPa (dask sweep).

Run:  .venv/bin/python docs/calibration/paper_rig_transient.py [--no-waterfall]
Writes docs/figures/fig11_orbits.png, docs/figures/fig13_waterfall.png and prints the numbers
quoted in docs/transient-and-sweeps.md.
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.plot import waterfall  # noqa: E402
from rotordyn.sweep import run_sweep  # noqa: E402

FIG = Path(__file__).resolve().parents[1] / "figures"

WATERFALL = """
schema = "rotordyn/sweep/1"
name = "doc-waterfall"
model = "paper-rig"
analysis = "waterfall"
chunk_size = 3
[grid]
speed_hz = {start = 10.0, stop = 120.0, num = 23}
chamber_pressure_pa = 0.4e6
config_ay_m = 0.0
[options]
unbalances = [[6, 2.0e-5, 0.0]]
revolutions = 40
samples_per_revolution = 64
max_harmonic = 4.0
"""


def orbits():
    rig = rd.models.paper_rig()
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.2))
    for ax, pc in zip(axes, (0.05e6, 0.10e6, 0.15e6)):
        tr = rd.transient(rig, 2.0, 50.0, pc, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=4001)
        st = rd.stability(rig, 50.0, pc, -1.85e-3)
        tr.plot(ax=ax)
        print(f"p_c = {pc / 1e6:.2f} MPa: {tr.status}, steps {tr.stats['steps']}, "
              f"amplitude over the last 0.5 s = {tr.amplitude() / 3e-4:.3g} c, "
              f"linear max Re λ = {st.max_real_1_per_s:.2f} 1/s")
    fig.tight_layout()
    fig.savefig(FIG / "fig11_orbits.png", dpi=110)


def waterfall_fig():
    with tempfile.TemporaryDirectory() as d:
        spec = Path(d) / "w.toml"
        spec.write_text(WATERFALL)
        res = run_sweep(spec, Path(d) / "out", workers=2)
        df = res.to_frame()
    ax = waterfall(df)
    ax.figure.savefig(FIG / "fig13_waterfall.png", dpi=110, bbox_inches="tight")
    sync = df[np.isclose(df["order"], 1.0, atol=0.5 / 40)]
    g = sync.groupby("speed_hz")["amplitude_x_m"].max()
    peaks = [s for i, s in enumerate(g.index[1:-1], 1)
             if g.iloc[i] > g.iloc[i - 1] and g.iloc[i] >= g.iloc[i + 1]]
    print("synchronous peaks (Hz, on a 5 Hz grid):", peaks)


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--no-waterfall", action="store_true")
    a = ap.parse_args()
    FIG.mkdir(exist_ok=True)
    orbits()
    if not a.no_waterfall:
        waterfall_fig()
