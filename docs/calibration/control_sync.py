"""The synchronous bound and the speed-scheduled 1× chamber-pressure command (issue 8,
docs/control.md §3.2): what any law driving the one chamber pressure can do to the steady
unbalance response at each critical speed (linear model), and what a 1×-locked command whose
amplitude and phase are scheduled over the speed does in the nonlinear run-up.

Rig at a_y = 0, 2e-5 kg m at disk B (station 6), 10 → 120 Hz, 100 Hz valve with p_c in
[0, 1] MPa; stations 4 (active journal) and 6 (disk B); amplitudes are orbit semi-major axes.

Run:  .venv/bin/python docs/calibration/control_sync.py [--rate-hz-s 10] [--no-runs]
Prints every number quoted in docs/control.md §3.2 (bound and run-ups); writes
docs/figures/control_sync.png.
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
from rotordyn.control import Actuator, PressureSchedule, SpeedProfile  # noqa: E402
from rotordyn.control.closedloop import closed_loop  # noqa: E402
from rotordyn.control.lqr import default_weights, lqg  # noqa: E402
from rotordyn.control.plant import plant  # noqa: E402
from rotordyn.control.reduction import modal_truncation  # noqa: E402
from rotordyn.control.schedule import pressure_schedule  # noqa: E402
from rotordyn.control.synchronous import semi_major, synchronous_bound  # noqa: E402

FIG = Path(__file__).resolve().parents[1] / "figures"
UB = [(6, 2e-5, 0.0)]
ST = (4, 6)
NAMES = {4: "journal", 6: "disk B"}
AY, F0, F1, SPLIT = 0.0, 10.0, 120.0, 65.0
WINDOWS = ((28.0, 50.0), (75.0, 105.0))  # "at each critical speed" (39 and 90 Hz)
MIN_ZETA = 2e-4
SLOPE = 0.1e6  # Pa/Hz, the static schedule's slope limit


def region_peaks(sp, amp):
    """(speed, value) of the largest amplitude in each critical-speed window."""
    out = []
    for m in ((sp >= WINDOWS[0][0]) & (sp <= WINDOWS[0][1]),
              (sp >= WINDOWS[1][0]) & (sp <= WINDOWS[1][1])):
        x = np.where(m & np.isfinite(amp), amp, -np.inf)
        i = int(np.argmax(x))
        out.append((sp[i], amp[i]))
    return out


def smooth_path(cost, pp, sp, slope, q=4.0):
    """Dynamic programme over the grid under |Δp| ≤ slope Δf minimising Σ cost^q along the
    path (q = 4: close to the min–max path at the peaks, but every speed still counts)."""
    move = np.abs(pp[:, None] - pp[None, :])
    c = cost ** q
    acc = c[0].copy()
    back = np.zeros(cost.shape, dtype=int)
    for i in range(1, sp.size):
        cand = np.where(move <= slope * (sp[i] - sp[i - 1]) + 1e-9, acc[:, None], np.inf)
        back[i] = np.argmin(cand, axis=0)
        acc = cand[back[i], np.arange(pp.size)] + c[i]
    j = np.zeros(sp.size, dtype=int)
    j[-1] = int(np.argmin(acc))
    for i in range(sp.size - 1, 0, -1):
        j[i - 1] = back[i, j[i]]
    return j


def order_semi_major(tr, Co, speeds, revolutions=8.0):
    """Semi-major axis of the 1× orbit at each speed of a run-up: least squares of x and y
    on [1, t, cos θ, sin θ] over ±revolutions/2 (as TransientResult.order_amplitude)."""
    z = tr.r @ Co.T
    out = np.full(speeds.size, np.nan)
    for i, f in enumerate(speeds):
        tc = np.interp(f, tr.speed_hz_t, tr.t)
        win = np.abs(tr.t - tc) <= 0.5 * revolutions / f
        th, tt = tr.angle_rad[win], tr.t[win] - tc
        A = np.column_stack([np.ones_like(tt), tt, np.cos(th), np.sin(th)])
        c = np.linalg.lstsq(A, z[win], rcond=None)[0]
        X, Y = c[2] - 1j * c[3]
        out[i] = semi_major(X, Y)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rate-hz-s", type=float, default=10.0)
    ap.add_argument("--no-runs", action="store_true", help="the linear bound only")
    args = ap.parse_args()
    rig = rd.models.paper_rig()
    asm = assembled(rig)
    act = Actuator()
    sp = np.unique(np.round(np.concatenate([np.arange(F0, F1 + 0.01, 1.0),
                                            np.arange(35, 42, 0.1), np.arange(84, 94, 0.1)]), 6))
    pp = np.arange(0.0, act.p_max_pa + 1, 0.05e6)
    t0 = time.perf_counter()
    sb = synchronous_bound(rig, UB, sp, pp, stations=list(ST), config_ay_m=AY, actuator=act)
    print(f"grid {sp.size} speeds x {pp.size} mean pressures ({time.perf_counter() - t0:.1f} s)")

    # Best constant pressure and the static schedule exactly as control_runup.py
    grid_sp = np.arange(F0, F1 + 0.01, 1.0)
    sch = pressure_schedule(rig, UB, grid_sp, pp, stations=list(ST), config_ay_m=AY,
                            min_damping=MIN_ZETA, p_min_pa=act.p_min_pa, p_max_pa=act.p_max_pa,
                            smooth_pa_per_hz=SLOPE)
    pc_best = sch.best_constant_pa
    jb = sb.column(pc_best)
    print(f"best constant p_c = {pc_best / 1e6:.2f} MPa (control_runup.py)")

    # 1. The bound per station (each minimised alone), steady linear semi-major axes.
    lo = sp < SPLIT
    stable = sb.min_damping_ratio >= MIN_ZETA
    print("\nSYNCHRONOUS BOUND (linear, steady, orbit semi-major axis, µm) — peak over each "
          "critical-speed region (< / >= 65 Hz):")
    print("station   crit | passive 0.5 MPa | static p_c(Ω) only (stable) | 1× at 0.5 MPa | "
          "any p0(Ω) + 1× (any law) | best reduction")
    alone = {}
    for k, st in enumerate(ST):
        ref = np.full(len(ST), 1.0)
        ref[k] = 1e-6
        sk = sb.with_references(ref)
        alone[st] = sk
        static = np.nanmin(np.where(stable, sb.passive_m[:, :, k], np.inf), axis=1)
        anyp = np.nanmin(np.where(sk.status == "ok", sk.optimal_m[:, :, k], np.inf), axis=1)
        for name, m in (("1st", lo), ("2nd", ~lo)):
            pas = sb.passive_m[m, jb, k]
            vals = (pas.max(), static[m].max(), sk.optimal_m[m, jb, k].max(), anyp[m].max())
            print(f"{NAMES[st]:8s} {name}  | {vals[0] * 1e6:8.2f} ({sp[m][np.argmax(pas)]:.1f} Hz)"
                  f" | {vals[1] * 1e6:8.2f} | {vals[2] * 1e6:8.2f} | {vals[3] * 1e6:8.2f} | "
                  f"{vals[0] / vals[3]:.2f}x {'(3x reachable)' if vals[0] / vals[3] >= 3 else '(3x NOT reachable)'}")

    # 2. Designs: references = each station's passive peak in its critical-speed window
    #    (geometric interpolation between the windows, so the schedule has no jump), min–max
    #    over the stations at every speed. "disk/3": the disk's reference divided by 3
    #    (target disk 3× with the journal not above its passive peak; disk/30 pushes the
    #    disk further, the journal allowed up to its passive peak); "disk only": the
    #    journal ignored (reference 1 km). "journal-capped" (below): the least disk orbit
    #    whose journal orbit stays at or below the passive one at that speed.
    w1 = (sp <= WINDOWS[0][1])
    w2 = (sp >= WINDOWS[1][0])
    pk1 = np.array([sb.passive_m[(sp >= WINDOWS[0][0]) & w1, jb, k].max() for k in range(2)])
    pk2 = np.array([sb.passive_m[(sp <= WINDOWS[1][1]) & w2, jb, k].max() for k in range(2)])
    s_ = np.clip((sp - WINDOWS[0][1]) / (WINDOWS[1][0] - WINDOWS[0][1]), 0, 1)[:, None]
    base_ref = np.exp((1 - s_) * np.log(pk1)[None] + s_ * np.log(pk2)[None])
    variants = {"disk/3": base_ref * np.array([1.0, 1 / 3.0]),
                "disk/30": base_ref * np.array([1.0, 1 / 30.0]),
                "disk only": np.column_stack([np.full(sp.size, 1e3), base_ref[:, 1]])}
    sched1x, lin = {}, {"passive": sb.passive_m[:, jb]}
    for vname, refs in variants.items():
        sw = sb.with_references(refs)
        lin[f"1x {vname} at {pc_best / 1e6:.1f} MPa"] = sw.optimal_m[:, jb]  # linear only
        # (b) joint: mean pressure p0(Ω) among the stable grid pressures (slope-limited path,
        #     Σ objective⁴) with the optimal 1× command at that p0
        cost = np.where(stable & (sw.status == "ok"), sw.objective, np.inf)
        jpath = smooth_path(cost, pp, sp, SLOPE)
        p0_path = pp[jpath]
        sp_b, amp_b, ph_b = sw.harmonic_schedule(p0_path)
        sched1x[f"p0(Ω) + 1x {vname}"] = PressureSchedule.speed_table(
            sp, p0_path).with_harmonic_schedule(sp_b, amp_b, ph_b)
        lin[f"p0(Ω) + 1x {vname}"] = sw.optimal_m[np.arange(sp.size), jpath]
        print(f"\n1× design '{vname}': at {pc_best / 1e6:.2f} MPa |p̂| up to "
              f"{np.abs(sw.p_hat_pa[:, jb]).max() / 1e6:.3f} MPa; joint p0(Ω) in "
              f"[{p0_path.min() / 1e6:.2f}, {p0_path.max() / 1e6:.2f}] MPa with |p̂| up to "
              f"{amp_b.max() / 1e6:.3f} MPa")
        print("  p0(Ω) [Hz: MPa]:", ", ".join(f"{s:.0f}: {p / 1e6:.2f}" for s, p in
                                             zip(sp[::10], p0_path[::10])))
    # Journal-capped: over disk weights K (disk reference D/K, journal reference = its
    # passive orbit at that speed and 0.5 MPa), keep per grid point the least disk orbit
    # whose journal orbit is ≤ the cap (p̂ = 0 included when it qualifies) — the
    # ε-constraint solution on a ladder of K.
    cap = sb.passive_m[:, jb, 0]
    best_d = np.where(sb.passive_m[:, :, 0] <= cap[:, None] * (1 + 1e-9),
                      sb.passive_m[:, :, 1], np.inf)
    best_j = np.where(np.isfinite(best_d), sb.passive_m[:, :, 0], np.nan)
    best_p = np.where(np.isfinite(best_d), 0.0, np.nan + 0j)
    for K in (0.3, 1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 50.0, 100.0, 300.0, 1000.0):
        sk = sb.with_references(np.column_stack([cap, base_ref[:, 1] / K]))
        good = (sk.optimal_m[:, :, 0] <= cap[:, None] * (1 + 1e-6)) \
            & (sk.optimal_m[:, :, 1] < best_d)
        best_d = np.where(good, sk.optimal_m[:, :, 1], best_d)
        best_j = np.where(good, sk.optimal_m[:, :, 0], best_j)
        best_p = np.where(good, sk.p_hat_pa, best_p)
    cost = np.where(stable & np.isfinite(best_d), best_d / base_ref[:, 1:2], np.inf)
    for tag, jsel in ((f"at {pc_best / 1e6:.1f} MPa", np.full(sp.size, jb)),
                      ("p0(Ω) +", smooth_path(cost, pp, sp, SLOPE))):
        ph = best_p[np.arange(sp.size), jsel]
        phase = np.degrees(np.unwrap(np.angle(ph))) + 90.0
        base = (PressureSchedule.constant(pc_best) if tag.startswith("at")
                else PressureSchedule.speed_table(sp, pp[jsel]))
        name = (f"1x journal-capped {tag}" if tag.startswith("at")
                else "p0(Ω) + 1x journal-capped")
        if not tag.startswith("at"):  # (linear only at the constant pressure)
            sched1x[name] = base.with_harmonic_schedule(sp, np.abs(ph), phase)
        lin[name] = np.column_stack([best_j[np.arange(sp.size), jsel],
                                     best_d[np.arange(sp.size), jsel]])
        print(f"\n1× design '{name}': |p̂| up to {np.abs(ph).max() / 1e6:.3f} MPa; p0 in "
              f"[{pp[jsel].min() / 1e6:.2f}, {pp[jsel].max() / 1e6:.2f}] MPa")
    print("linear steady peaks (µm) [journal 1st | 2nd ; disk 1st | 2nd]:")
    for name, A in lin.items():
        pk = [region_peaks(sp, A[:, k]) for k in range(len(ST))]
        print(f"  {name:26s} " + " ; ".join(" | ".join(f"{v * 1e6:.2f} ({s:.1f})" for s, v in p)
                                            for p in pk))
    if args.no_runs:
        return

    # 3. Nonlinear run-ups
    meas = [("journal", 0), ("displacement", 6)]
    pd_ = plant(rig, 38.0, pc_best, AY, measurements=meas, actuator=act,
                disturbance_stations=[6])
    pr, _ = modal_truncation(pd_, 300.0)
    Q, _ = default_weights(pr)
    Q = Q + pr.C[2:4].T @ pr.C[2:4] / 3e-4**2
    k_fb = lqg(pr, Q, np.array([[1 / 3e5**2]]), measurement_noise_m=1e-7).with_washout(2.0)
    print(f"feedback (LQG as control_runup.py): {closed_loop(pd_, k_fb)!r}")
    rate = args.rate_hz_s
    T = (F1 - F0) / rate
    prof = SpeedProfile.ramp(F0, F1, rate)
    common = dict(unbalances=UB, speed=prof, n_out=int(T * F1 * 32) + 1, actuator=act)
    designs = {"passive": dict(chamber_pressure_pa=pc_best),
               "static schedule": dict(pressure=sch.schedule())}
    designs.update({name: dict(pressure=ps) for name, ps in sched1x.items()})
    designs["feedback (LQG)"] = dict(chamber_pressure_pa=pc_best, controller=k_fb)
    track = np.arange(F0 + 1, F1 - 0.5, 0.1)
    amps, rng = {}, {}
    for name, kw in designs.items():
        t0 = time.perf_counter()
        tr = rd.transient(rig, T, F0, config_ay_m=AY, **common, **kw)
        pc = tr.chamber_pressure_actual_pa
        rng[name] = (np.nanmin(pc), np.nanmax(pc))
        print(f"run-up {name}: {tr.status} {tr.message} ({tr.stats['steps']} steps, "
              f"{time.perf_counter() - t0:.1f} s wall); p_c in [{rng[name][0] / 1e6:.3f}, "
              f"{rng[name][1] / 1e6:.3f}] MPa; command in "
              f"[{np.nanmin(tr.chamber_pressure_command_pa) / 1e6:.3f}, "
              f"{np.nanmax(tr.chamber_pressure_command_pa) / 1e6:.3f}] MPa")
        amps[name] = {st: order_semi_major(tr, asm.station_output_matrix(st), track) for st in ST}
    print(f"\nNONLINEAR RUN-UP {rate:g} Hz/s, 1× orbit semi-major axis peaks, µm (speed Hz) and "
          "reduction vs passive:")
    print(f"windows {WINDOWS} Hz; design | journal 1st | journal 2nd | disk B 1st | disk B 2nd "
          "| p_c MPa | largest outside the windows (journal, disk)")
    base = {st: region_peaks(track, amps["passive"][st]) for st in ST}
    for name in designs:
        cells = []
        for st in ST:
            for r, (s_, v_) in enumerate(region_peaks(track, amps[name][st])):
                red = base[st][r][1] / v_
                cells.append(f"{v_ * 1e6:7.2f} ({s_:.1f}) {red:.2f}x")
        outside = ~(((track >= WINDOWS[0][0]) & (track <= WINDOWS[0][1]))
                    | ((track >= WINDOWS[1][0]) & (track <= WINDOWS[1][1])))
        print(f"{name:26s} | " + " | ".join(cells)
              + f" | {rng[name][0] / 1e6:.3f}-{rng[name][1] / 1e6:.3f} | "
              + ", ".join(f"{np.nanmax(amps[name][st][outside]) * 1e6:.2f}" for st in ST))

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    for c, st in enumerate(ST):
        for name in designs:
            ax[c].semilogy(track, amps[name][st] * 1e6, lw=0.8, label=name)
        k = ST.index(st)
        anyp = np.nanmin(np.where(alone[st].status == "ok", alone[st].optimal_m[:, :, k],
                                  np.inf), axis=1)
        ax[c].semilogy(sp, anyp * 1e6, "k:", lw=0.8, label="bound: any law (linear, steady)")
        ax[c].set_title(f"station {st} ({NAMES[st]}), run-up {rate:g} Hz/s")
        ax[c].set_xlabel("speed (Hz)")
        ax[c].set_ylabel("1× semi-major axis (µm)")
    ax[0].legend(fontsize=7)
    for name, ps in sched1x.items():
        ax[2].plot(ps.harmonic_speed_hz, ps.harmonic_amplitudes_pa / 1e6, lw=0.8,
                   label=f"|p̂| {name}")
        if ps.kind == "speed_table":
            ax[2].plot(ps.x, ps.p_pa / 1e6, lw=0.8, ls="--", label=f"p0 {name}")
    ax[2].set_xlabel("speed (Hz)")
    ax[2].set_ylabel("MPa")
    ax[2].set_title("1× schedules")
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    out = FIG / ("control_sync.png" if rate == 10.0 else f"control_sync_{rate:g}hz_s.png")
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
