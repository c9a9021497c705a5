"""Unbalance run-up of the paper's rig through both critical speeds (issue 8, docs/control.md
§2): passive at the best constant chamber pressure, with the open-loop schedule p_c(Ω), and
with feedback (LQG on journal + disk B displacement, designed at the first critical speed),
each as a nonlinear CVODE run-up with the 100 Hz valve and its limits, beside the linear
steady prediction.

Run:  .venv/bin/python docs/calibration/control_runup.py [--rate-hz-s 10]
Prints every number quoted in docs/control.md; writes docs/figures/control_runup.png and
docs/figures/control_waterfalls.png.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.analysis.assembly import assembled  # noqa: E402
from rotordyn.control import Actuator, Controller, SpeedProfile  # noqa: E402
from rotordyn.control.closedloop import closed_loop, closed_loop_unbalance  # noqa: E402
from rotordyn.control.lqr import default_weights, lqg  # noqa: E402
from rotordyn.control.plant import plant  # noqa: E402
from rotordyn.control.reduction import modal_truncation  # noqa: E402
from rotordyn.control.schedule import pressure_schedule  # noqa: E402

FIG = Path(__file__).resolve().parents[1] / "figures"
UB = [(6, 2e-5, 0.0)]  # disk B, 2e-5 kg m (the waterfall of docs/transient-and-sweeps.md)
JOURNAL, DISK = 4, 6
AY = 0.0
F0, F1 = 10.0, 120.0
MIN_ZETA = 2e-4
SPLIT = 65.0  # between the two critical speeds


def peaks(sp, amp):
    lo, hi = sp < SPLIT, sp >= SPLIT
    i, j = np.nanargmax(np.where(lo, amp, -1)), np.nanargmax(np.where(hi, amp, -1))
    return (sp[i], amp[i]), (sp[j], amp[j])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rate-hz-s", type=float, default=10.0)
    args = ap.parse_args()
    rig = rd.models.paper_rig()
    asm = assembled(rig)
    act = Actuator()
    t0 = time.perf_counter()
    grid_sp = np.arange(F0, F1 + 0.01, 1.0)
    grid_p = np.arange(0.0, act.p_max_pa + 1, 0.05e6)
    sch = pressure_schedule(rig, UB, grid_sp, grid_p, stations=[JOURNAL, DISK], config_ay_m=AY,
                            min_damping=MIN_ZETA, p_min_pa=act.p_min_pa, p_max_pa=act.p_max_pa,
                            smooth_pa_per_hz=0.1e6)
    print(f"schedule grid: {grid_sp.size} speeds x {grid_p.size} pressures "
          f"({time.perf_counter() - t0:.1f} s); constraint: every mode ζ >= {MIN_ZETA}, "
          f"p_c in [{act.p_min_pa / 1e6}, {act.p_max_pa / 1e6}] MPa, slope <= 0.1 MPa/Hz")
    feas = sch.grid.groupby("chamber_pressure_pa")["feasible"].all()
    print("constant pressures feasible at every speed:",
          ", ".join(f"{p / 1e6:.2f}" for p in feas.index[feas.values]), "MPa")
    pc_best = sch.best_constant_pa
    print(f"best constant p_c = {pc_best / 1e6:.2f} MPa")
    sched = sch.schedule()
    print("schedule p_c(Ω) [Hz: MPa]:", ", ".join(
        f"{s:.0f}: {p / 1e6:.2f}" for s, p in zip(sch.speeds_hz[::5], sch.pressures_pa[::5])))

    # Feedback: LQG on journal + disk displacement at the first critical speed, base p_c
    meas = [("journal", 0), ("displacement", DISK)]
    pd_ = plant(rig, 38.0, pc_best, AY, measurements=meas, actuator=act,
                disturbance_stations=[DISK])
    pr, info = modal_truncation(pd_, 300.0)
    Q, _ = default_weights(pr)
    Q = Q + pr.C[2:4].T @ pr.C[2:4] / 3e-4**2
    k = lqg(pr, Q, np.array([[1 / 3e5**2]]), measurement_noise_m=1e-7).with_washout(2.0)
    cl = closed_loop(pd_, k)
    print(f"LQG: plant order {info['full_order']} -> {info['order']} (relative H∞ error "
          f"{info['relative_error']:.1e}), weights: journal and disk B displacement / c, "
          f"R = 1/(0.3 MPa)²; washout 2 Hz; n_k = {k.n_states}; at 38 Hz: {cl!r}")

    fine = np.unique(np.concatenate([np.arange(F0, F1 + 0.01, 1.0), np.arange(35, 42, 0.05),
                                     np.arange(84, 94, 0.05)]))
    zero = Controller.static(np.zeros((1, 4)), meas)
    lin = {"passive": closed_loop_unbalance(rig, zero, UB, fine, chamber_pressure_pa=pc_best,
                                            config_ay_m=AY, stations=[JOURNAL, DISK],
                                            actuator=act),
           "schedule": closed_loop_unbalance(rig, zero, UB, fine, chamber_pressure_pa=sched,
                                             config_ay_m=AY, stations=[JOURNAL, DISK],
                                             actuator=act),
           "feedback": closed_loop_unbalance(rig, k, UB, fine, chamber_pressure_pa=pc_best,
                                             config_ay_m=AY, stations=[JOURNAL, DISK],
                                             actuator=act)}
    print("linear steady response, peaks (speed Hz, µm) [first | second critical]:")
    for name, df in lin.items():
        s = df.speed_hz.to_numpy()
        out = []
        for st in (JOURNAL, DISK):
            (a, pa), (b, pb) = peaks(s, df[f"amplitude_m[{st}]"].to_numpy())
            out.append(f"station {st}: {a:.2f} Hz {pa * 1e6:.1f} | {b:.2f} Hz {pb * 1e6:.1f}")
        print(f"  {name:9s} max Re λ over speeds = {df.max_real_1_per_s.max():+.3f} 1/s; "
              + "; ".join(out))

    # Nonlinear run-ups
    rate = args.rate_hz_s
    T = (F1 - F0) / rate
    n_out = int(T * F1 * 32) + 1
    prof = SpeedProfile.ramp(F0, F1, rate)
    runs = {}
    common = dict(unbalances=UB, speed=prof, n_out=n_out, actuator=act)
    for name, kw in (("passive", dict(chamber_pressure_pa=pc_best)),
                     ("schedule", dict(pressure=sched)),
                     ("feedback", dict(chamber_pressure_pa=pc_best, controller=k))):
        t0 = time.perf_counter()
        tr = rd.transient(rig, T, F0, config_ay_m=AY, **common, **kw)
        runs[name] = tr
        print(f"run-up {name}: {F0:g} -> {F1:g} Hz at {rate:g} Hz/s ({T:g} s): {tr.status} "
              f"{tr.message} ({tr.stats['steps']} steps, {time.perf_counter() - t0:.1f} s wall); "
              f"p_c in [{np.nanmin(tr.chamber_pressure_actual_pa) / 1e6:.3f}, "
              f"{np.nanmax(tr.chamber_pressure_actual_pa) / 1e6:.3f}] MPa")
    sp = np.arange(F0 + 1, F1 - 0.5, 0.1)
    amps = {}
    print("nonlinear run-up, 1× amplitude peaks (speed Hz, µm) [first | second critical]:")
    for name, tr in runs.items():
        amps[name] = {}
        out = []
        for st in (JOURNAL, DISK):
            _, a = tr.order_amplitude(asm.station_output_matrix(st), sp, revolutions=8)
            amps[name][st] = a
            (x1, p1), (x2, p2) = peaks(sp, a)
            out.append(f"station {st}: {x1:.1f} Hz {p1 * 1e6:.1f} | {x2:.1f} Hz {p2 * 1e6:.1f}")
        print(f"  {name:9s} " + "; ".join(out))
    print("reduction against the best constant p_c (nonlinear run-up peaks) [first | second]:")
    for name in ("schedule", "feedback"):
        out = []
        for st in (JOURNAL, DISK):
            (_, a1), (_, a2) = peaks(sp, amps["passive"][st])
            (_, b1), (_, b2) = peaks(sp, amps[name][st])
            out.append(f"station {st}: {a1 / b1:.2f}x | {a2 / b2:.2f}x")
        print(f"  {name:9s} " + "; ".join(out))

    suffix = "" if rate == 10.0 else f"_{rate:g}hz_s"
    colours = {"passive": "C0", "schedule": "C1", "feedback": "C2"}
    fig, ax = plt.subplots(2, 2, figsize=(12, 7), sharex="col")
    for name in runs:
        for c, st in enumerate((JOURNAL, DISK)):
            ax[0, c].semilogy(sp, amps[name][st] * 1e6, lw=0.8, color=colours[name],
                              label=f"{name} (run-up {rate:g} Hz/s)")
            df = lin[name]
            ax[0, c].semilogy(df.speed_hz, df[f"amplitude_m[{st}]"] * 1e6, lw=0.5, ls=":",
                              color=colours[name], label=f"{name} (linear steady)")
            ax[0, c].set_title(f"station {st} ({'journal' if st == JOURNAL else 'disk B'})")
            ax[0, c].set_ylabel("1× amplitude (µm)")
        ax[1, 0].plot(runs[name].speed_hz_t, runs[name].chamber_pressure_actual_pa / 1e6,
                      lw=0.6, color=colours[name], label=name)
    ax[0, 0].legend(fontsize=7)
    ax[1, 0].set_ylabel("p_c (MPa)")
    ax[1, 0].set_xlabel("speed (Hz)")
    ax[1, 0].legend(fontsize=7)
    ax[1, 1].plot(sch.speeds_hz, sch.pressures_pa / 1e6, "o-", ms=2, label="schedule")
    ax[1, 1].axhline(pc_best / 1e6, color="k", lw=0.6, label="best constant")
    ax[1, 1].set_xlabel("speed (Hz)")
    ax[1, 1].set_ylabel("p_c (MPa)")
    ax[1, 1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(FIG / f"control_runup{suffix}.png", dpi=120)

    fig, ax = plt.subplots(1, 3, figsize=(14, 4.5), sharey=True)
    for a, (name, tr) in zip(ax, runs.items()):
        s, f, A = tr.waterfall(asm.station_output_matrix(DISK), window_s=0.25)
        m = f <= 250
        im = a.pcolormesh(f[m], s, 20 * np.log10(A[:, m] / 1e-6 + 1e-6), shading="auto",
                          vmin=-40, vmax=60, cmap="viridis")
        a.set_title(f"disk B, x: {name}")
        a.set_xlabel("frequency (Hz)")
    ax[0].set_ylabel("speed (Hz)")
    fig.colorbar(im, ax=ax, label="dB re 1 µm")
    fig.savefig(FIG / f"control_waterfalls{suffix}.png", dpi=120)
    print(f"wrote {FIG}/control_runup{suffix}.png and control_waterfalls{suffix}.png")


if __name__ == "__main__":
    main()
