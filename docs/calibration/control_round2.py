"""Control round 2 (issue 24, docs/control.md §2.4–2.6): anti-windup, a gain-scheduled PD
through both critical speeds, and the adaptive 1× unbalance rejection in the nonlinear
run-up, each beside its reference.

Run:  .venv/bin/python docs/calibration/control_round2.py [--part aw|schedule|adaptive|all]
      [--rate-hz-s 10] [--gamma 20] [--washout-hz 0] [--refine-rounds 0] [--no-runup]
      [--unbalance ST ME PH] [--passive] [--measure both|disk|journal] [--schedule]
      [--fraction 0.5] [--leak 0] [--freeze] [--check] [--max-steps 2000000]
Prints every number quoted in docs/control.md §2.4–2.6.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.control import Actuator, PressureSchedule, SpeedProfile
from rotordyn.control.adaptive import adaptive_rejection
from rotordyn.control.antiwindup import with_anti_windup
from rotordyn.control.closedloop import closed_loop
from rotordyn.control.gain_schedule import gain_schedule, schedule_stability
from rotordyn.control.pid import pid, tune_pd
from rotordyn.control.plant import plant

C = 3e-4
JOURNAL, DISK = 4, 6
UB = [(6, 2e-5, 0.0)]  # disk B, as docs/control.md §3.2
SPLIT = 65.0
MAX_STEPS = 2_000_000  # CVODE steps per output interval (--max-steps)


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def part_aw():
    rig = rd.models.paper_rig()
    AY, F, PC = -1.85e-3, 50.0, 0.15e6
    bc = [b for b in assembled(rig).bearings if b.active][0]
    k = pid(1.0e9, 2.5e6, 1.0e9 / 0.02)
    aw = with_anti_windup(k)
    cl = closed_loop(plant(rig, F, PC, AY, actuator=Actuator()), k, with_margins=False)
    print(f"[aw] PID k_p 1e9 Pa/m, k_d 2.5e6 Pa s/m, T_i 0.02 s at a_y {AY} m, {F} Hz, "
          f"{PC / 1e6} MPa: linear max Re λ {cl.max_real:.3f} 1/s; tracking rate "
          f"{aw.info['tracking_rate_hz']:.2f} Hz (√(k_i/k_d)/2π = "
          f"{np.sqrt(5e10 / 2.5e6) / (2 * np.pi):.2f} Hz), L = {aw.anti_windup_gain}, "
          f"max Re λ(A − L C) {aw.info['tracking_max_real_1_per_s']:.1f} 1/s")
    prof = SpeedProfile.table([0, 0.02, 0.03, 0.12, 0.13], [50, 50, 30, 30, 50])
    for half, rate in ((1e3, np.inf), (1e3, 1e5), (0.5e3, np.inf)):
        act = Actuator(p_min_pa=PC - half, p_max_pa=PC + half, rate_limit_pa_s=rate)
        for lab, law in (("without", k), ("with", aw)):
            t0 = time.perf_counter()
            tr = rd.transient(rig, 0.5, chamber_pressure_pa=PC, config_ay_m=AY, speed=prof,
                              controller=law, actuator=act, n_out=1001, max_step_s=5e-4)
            m = tr.t >= 0.13
            e = np.hypot(tr.r[m, bc.jx] - tr.equilibrium_r[bc.jx],
                         tr.r[m, bc.jy] - tr.equilibrium_r[bc.jy])
            ise = float(np.sum(0.5 * (e[1:] ** 2 + e[:-1] ** 2) * np.diff(tr.t[m])))
            cmd = tr.chamber_pressure_command_pa
            sat = (cmd <= act.p_min_pa) | (cmd >= act.p_max_pa)
            print(f"[aw] valve ±{half:g} Pa, rate limit {rate:g} Pa/s, {lab} anti-windup: "
                  f"{tr.status}, command saturated until {tr.t[sat].max():.4f} s "
                  f"({100 * sat.mean():.0f} % of the run), largest error after the dip "
                  f"{e.max() / C:.4f} c, ∫e² dt after it {ise:.3e} m² s "
                  f"({time.perf_counter() - t0:.1f} s wall, load {load()})")


def peaks(tr, bcs):
    """1× semi-major axes (µm) at the journal and disk B, peaks below and above SPLIT."""
    from rotordyn.control.synchronous import semi_major

    out = {}
    asm = assembled(tr_sys)
    for name, st in (("journal", JOURNAL), ("disk", DISK)):
        L = asm.station_output_matrix(st)
        xy = (tr.r - tr.equilibrium_r) @ L.T
        sp, X, Y = one_x_track(tr, xy[:, 0], xy[:, 1])
        a = semi_major(X, Y) * 1e6
        lo, hi = sp < SPLIT, sp >= SPLIT
        i = np.nanargmax(np.where(lo, a, -1))
        j = np.nanargmax(np.where(hi, a, -1))
        out[name] = ((sp[i], a[i]), (sp[j], a[j]))
    return out


def one_x_track(tr, x, y, revs=4):
    """Least squares on [1, t, cos θ, sin θ] over ±revs revolutions at every 50th sample."""
    sp, X, Y = [], [], []
    th = tr.angle_rad
    for i in range(0, tr.t.size, 50):
        m = np.abs(th - th[i]) <= 2 * np.pi * revs
        if m.sum() < 16:
            continue
        A = np.column_stack([np.ones(m.sum()), tr.t[m] - tr.t[i], np.cos(th[m]), np.sin(th[m])])
        cx = np.linalg.lstsq(A, x[m], rcond=None)[0]
        cy = np.linalg.lstsq(A, y[m], rcond=None)[0]
        sp.append(tr.speed_hz_t[i])
        X.append(cx[2] - 1j * cx[3])
        Y.append(cy[2] - 1j * cy[3])
    return np.array(sp), np.array(X), np.array(Y)


tr_sys = None


def runup(rig, rate, **kw):
    prof = SpeedProfile.ramp(10.0, 120.0, rate)
    t_end = 110.0 / rate
    t0 = time.perf_counter()
    tr = rd.transient(rig, t_end, chamber_pressure_pa=0.5e6, config_ay_m=0.0, speed=prof,
                      unbalances=UB, actuator=Actuator(), n_out=int(t_end * 2000) + 1,
                      max_steps=MAX_STEPS, **kw)
    return tr, time.perf_counter() - t0


def show(lab, tr, wall):
    pk = peaks(tr, None)
    (fj1, j1), (fj2, j2) = pk["journal"]
    (fd1, d1), (fd2, d2) = pk["disk"]
    print(f"[run-up] {lab}: {tr.status}; journal {j1:.2f} µm ({fj1:.1f} Hz) | {j2:.2f} "
          f"({fj2:.1f}); disk B {d1:.2f} ({fd1:.1f}) | {d2:.2f} ({fd2:.1f}); p_c "
          f"[{np.nanmin(tr.chamber_pressure_actual_pa) / 1e6:.3f}, "
          f"{np.nanmax(tr.chamber_pressure_actual_pa) / 1e6:.3f}] MPa; "
          f"{tr.stats['rhs_evals']} RHS, "
          f"{wall:.1f} s wall, load {load()}")
    return pk


def design(rig, f, act, kw, washout_hz):
    k, cl = tune_pd(plant(rig, f, 0.5e6, 0.0, actuator=act), **kw)
    print(f"[schedule] PD at {f:6.2f} Hz: k_p {k.info['kp']:.4g} Pa/m, k_d "
          f"{k.info['kd']:.4g} Pa s/m, min ζ {cl.min_damping:.4f}")
    return k.with_washout(washout_hz) if washout_hz else k


KP_SET = (-3e9, -1e9, -3e8, 0.0, 3e8, 1e9, 3e9)  # Pa/m
KD_SET = (-3e6, -1e6, -3e5, 0.0, 3e5, 1e6, 3e6)  # Pa s/m


def grid_design(rig, f, act, washout_hz):
    """The PD (gains from KP_SET × KD_SET: bounded) with the largest least damping ratio of
    the closed loop at ``f`` — a design that cannot run away to the huge gains of tune_pd."""
    from rotordyn.control.closedloop import closed_loop_matrix
    from rotordyn.results.modes import damping_ratio

    p = plant(rig, f, 0.5e6, 0.0, actuator=act)
    best = None
    for kp in KP_SET:
        for kd in KD_SET:
            k = pid(kp, kd)
            k = k.with_washout(washout_hz) if washout_hz else k
            z = damping_ratio(np.linalg.eigvals(closed_loop_matrix(p, k))).min()
            if best is None or z > best[0]:
                best = (z, kp, kd, k)
    print(f"[schedule] grid PD at {f:6.2f} Hz: k_p {best[1]:.3g} Pa/m, k_d {best[2]:.3g} "
          f"Pa s/m, min ζ {best[0]:.4f}")
    return best[3]


def part_schedule_grid(rate, washout_hz=2.0):
    """Bounded grid-search PD designs at 12 speeds, scheduled; the dense check; run-ups."""
    global tr_sys
    rig = rd.models.paper_rig()
    tr_sys = rig
    act = Actuator()
    sp = np.array([10.0, 20.0, 30.0, 38.0, 45.0, 55.0, 65.0, 80.0, 88.0, 95.0, 105.0, 120.0])
    designs = [grid_design(rig, f, act, washout_hz) for f in sp]
    law = gain_schedule(designs, sp)
    st = schedule_stability(rig, law, chamber_pressure_pa=0.5e6, config_ay_m=0.0,
                            actuator=act, n_between=4)
    f, w = st.worst
    print(f"[schedule] grid designs (washout {washout_hz} Hz): dense check over "
          f"{st.speed_hz.size} speeds: stable {st.stable}; worst max Re λ {w:.4f} 1/s at "
          f"{f:.2f} Hz; least ζ {np.nanmin(st.min_damping):.5f}")
    fixed = designs[3]
    mr = np.array([closed_loop(plant(rig, f, 0.5e6, 0.0, actuator=act), fixed,
                               with_margins=False).max_real for f in st.speed_hz])
    print(f"[schedule] fixed grid PD (38 Hz design) over the same speeds: worst max Re λ "
          f"{mr.max():.4f} 1/s at {st.speed_hz[int(np.argmax(mr))]:.2f} Hz")
    for lab, kk in (("fixed grid PD (38 Hz)", fixed), ("scheduled grid PD", law)):
        tr, wall = runup(rig, rate, controller=kk)
        show(lab, tr, wall)


def part_schedule(rate, washout_hz=0.0, rounds=0, runups=True):
    """PD designs by tune_pd on a speed grid, scheduled; the dense stability check; designs
    added where it fails (``rounds`` times); run-ups passive / fixed (38 Hz) / scheduled.
    ``washout_hz`` > 0: each design behind a washout (as the feedback of §3.2)."""
    global tr_sys
    rig = rd.models.paper_rig()
    tr_sys = rig
    act = Actuator()
    grid = [10.0, 20.0, 30.0, 35.0, 38.0, 42.0, 50.0, 65.0, 80.0, 88.0, 95.0, 105.0, 120.0]
    t0 = time.perf_counter()
    designs, kw = {}, {}
    for f in grid:
        designs[f] = design(rig, f, act, kw, washout_hz)
        kw = dict(kp0=designs[f].info["kp"], kd0=designs[f].info["kd"])
    # the dense check between the designs; a design added where it fails (twice at most)
    for rnd in range(rounds + 1):
        sp = np.array(sorted(designs))
        law = gain_schedule([designs[f] for f in sp], sp)
        st = schedule_stability(rig, law, chamber_pressure_pa=0.5e6, config_ay_m=0.0,
                                actuator=act, n_between=4)
        f, w = st.worst
        print(f"[schedule] round {rnd}: {sp.size} designs (washout {washout_hz} Hz); dense "
              f"check over {st.speed_hz.size} speeds: stable {st.stable}; worst max Re λ "
              f"{w:.3f} 1/s at {f:.2f} Hz; least ζ {np.nanmin(st.min_damping):.4f} "
              f"({time.perf_counter() - t0:.0f} s so far)")
        if st.stable or rnd == rounds:
            break
        bad = st.speed_hz[(st.max_real_1_per_s >= 0) & ~st.design]
        for f in bad:
            designs[float(f)] = design(rig, float(f), act, {}, washout_hz)
    fixed = designs[38.0]
    mr = np.array([closed_loop(plant(rig, f, 0.5e6, 0.0, actuator=act), fixed,
                               with_margins=False).max_real for f in st.speed_hz])
    print(f"[schedule] fixed PD (38 Hz design, washout) over the same speeds: worst max Re λ "
          f"{mr.max():.3f} 1/s at {st.speed_hz[int(np.argmax(mr))]:.2f} Hz; unstable at "
          f"{int(np.sum(mr >= 0))} of {mr.size} speeds")
    res = {}
    if not runups:
        return res
    for lab, kk in (("passive 0.5 MPa", None), ("fixed PD (38 Hz)", fixed),
                    ("scheduled PD", law)):
        tr, wall = runup(rig, rate, controller=kk)
        res[lab] = show(lab, tr, wall)
    return res


def adaptive_grid():
    grid = np.arange(10.0, 120.01, 1.0)
    return np.unique(np.concatenate([grid, np.arange(35.0, 42.0, 0.1),
                                     np.arange(84.0, 94.0, 0.1)]))


def dc_command(ss, omega_rad_s, update, gain_1_per_s, drift, leak_1_per_s=0.0,
               washout_rad_s=0.0, drift_rate=None):
    """Quasi-static DC command (Pa) the adaptive law makes from a constant drift ``drift``
    (n_y,) of its measurements (their offset is the starting equilibrium; the equilibrium
    moves with the speed). In the stationary frame Q = P e^{iθ} the law is exactly
    Q' = (iΩ − σ) Q − 2γ T̂⁺ y, command Re Q; with y = drift + T(0) Re Q (the plant ``ss``
    quasi-static) the steady Q solves a real 2 × 2 system; returns Re Q. The averaged loop
    (rotordyn.control.adaptive_design) drops this channel: it is a 2Ω term there.
    With the law's washout ω_w (rad/s) a drift ramping at ``drift_rate`` (n_y,) per s leaves
    drift_rate/ω_w at the demodulation, the quasi-static plant response is washed out (a = 0)
    and the update is T̂⁺(1 − iω_w/Ω)."""
    A, B, C, D = ss.A, ss.B[:, 0], ss.C, ss.D[:, 0]
    W = 2 * gain_1_per_s * np.asarray(update, dtype=complex)
    if washout_rad_s > 0:
        W = W * (1 - 1j * washout_rad_s / omega_rad_s)
        a = 0j
        b = complex(W @ (np.asarray(drift_rate, dtype=float) / washout_rad_s))
    else:
        a = complex(W @ (C @ np.linalg.solve(-A, B) + D))
        b = complex(W @ np.asarray(drift, dtype=float))
    M = np.array([[-leak_1_per_s - a.real, -omega_rad_s],
                  [omega_rad_s - a.imag, -leak_1_per_s]])
    return float(np.linalg.solve(M, [b.real, b.imag])[0])


DC_SPEEDS = (20.0, 40.0, 60.0, 80.0, 88.0, 90.0, 90.2, 90.4, 91.0, 92.0, 95.0, 110.0)


def command_mean(tr, speeds_hz, revs=4):
    """Mean (Pa) of the run's command over ±``revs`` whole revolutions about the sample where
    the speed reaches each of ``speeds_hz`` (NaN where the run never did): its DC part, the 1×
    part cancelling over whole revolutions."""
    ok = np.isfinite(tr.t)
    f, c, th = tr.speed_hz_t[ok], tr.chamber_pressure_command_pa[ok], tr.angle_rad[ok]
    out = []
    for s in speeds_hz:
        i = int(np.searchsorted(f, s))
        if i >= f.size:
            out.append(np.nan)
            continue
        m = np.abs(th - th[i]) <= 2 * np.pi * revs
        out.append(c[m].mean())
    return np.array(out)


def exact_loop_matrix(ss, omega_rad_s, update, gain_1_per_s, leak_1_per_s=0.0):
    """The frozen-speed loop of the linear plant ``ss`` (command → measurements) and the
    adaptive law without averaging: in the stationary frame Q = P e^{iθ}, z = [x, Re Q, Im Q],
    x' = A x + B Re Q, Q' = (iΩ − σ) Q − 2γ T̂⁺ (C x + D Re Q) — time invariant at constant Ω.
    Returns its (n + 2, n + 2) real matrix (the averaged loop drops the conjugate coupling)."""
    A, B, C, D = ss.A, ss.B[:, 0], ss.C, ss.D[:, 0]
    W = 2 * gain_1_per_s * np.asarray(update, dtype=complex)
    n = A.shape[0]
    M = np.zeros((n + 2, n + 2))
    M[:n, :n], M[:n, n] = A, B
    M[n, :n], M[n + 1, :n] = -(W.real @ C), -(W.imag @ C)
    M[n, n] = -(W.real @ D) - leak_1_per_s
    M[n + 1, n] = -(W.imag @ D) + omega_rad_s
    M[n, n + 1], M[n + 1, n + 1] = -omega_rad_s, -leak_1_per_s
    return M


def dc_check(rig, des, meas, leak, act, rate=10.0, washout_hz=0.0):
    """dc_command over the design grid with the equilibrium drift from 10 Hz (0.5 MPa); with
    the washout, the drift's rate at the run-up ``rate`` (Hz/s) instead."""
    from rotordyn.analysis.measurement import measurement_matrix
    from rotordyn.control.adaptive_design import _linear_plants

    Cm, _ = measurement_matrix(rig, meas)
    grid = des.speeds_hz

    def yeq(f):
        e = rd.equilibrium(rig, float(f), 0.5e6, 0.0, warm_start=False)
        return Cm @ np.concatenate([e.r, np.zeros(e.r.size)])

    ys = np.array([yeq(f) for f in grid])
    rates = np.gradient(ys, grid, axis=0) * rate  # drift per second in the run-up
    ww = 2 * np.pi * washout_hz
    out, ex = [], []
    for f, g, T, (ss, _), y, yr in zip(grid, des.gain_1_per_s, des.influence,
                                       _linear_plants(rig, grid, meas, 0.5e6, 0.0, act), ys,
                                       rates):
        T = np.asarray(T, dtype=complex)
        G = T.conj() / np.vdot(T, T).real
        dy = y - ys[0]
        out.append((np.linalg.norm(dy), dc_command(ss, 2 * np.pi * f, G, g, dy, leak, ww, yr)))
        ex.append(np.linalg.eigvals(exact_loop_matrix(ss, 2 * np.pi * f, G, g, leak)).real.max())
    out, ex = np.array(out), np.array(ex)
    j = int(np.argmax(ex))
    print(f"[adaptive]   exact frozen-speed loop (no averaging) at γ(Ω): unstable at "
          f"{int(np.sum(ex >= 0))} of {grid.size} speeds; worst max Re {ex[j]:+.4f} 1/s at "
          f"{grid[j]:.1f} Hz")
    i = int(np.argmax(np.abs(out[:, 1])))
    print(f"[adaptive]   DC command from the equilibrium drift (quasi-static, γ(Ω) of the "
          f"design" + (f", washout {washout_hz:g} Hz" if washout_hz else "")
          + f"): largest {out[i, 1] / 1e6:+.4f} MPa at {grid[i]:.1f} Hz (drift "
          f"{out[i, 0] * 1e6:.2f} µm); " + ", ".join(
              f"{grid[k]:.1f} Hz {out[k, 1] / 1e6:+.4f}"
              for k in np.unique(np.round(grid, 1), return_index=True)[1]
              if round(grid[k], 1) in DC_SPEEDS))


def part_adaptive(rate, gamma, passive=False, measure="both", schedule=False, fraction=0.5,
                  gamma_max=20.0, leak=0.0, freeze=False, check=False, washout_hz=0.0):
    """The adaptive 1× law in the run-up: a constant γ, or (``schedule``) γ(Ω) of the share
    rule (rotordyn.control.adaptive_design) with γ ≤ gamma_max; optional leak σ and freezing
    at the valve's limits; ``check``: the averaged loop's max Re of a constant-γ law too;
    ``washout_hz``: the law's measurement washout corner (0: none)."""
    from rotordyn.control.adaptive_design import adaptive_design, averaged_stability

    global tr_sys
    rig = rd.models.paper_rig()
    tr_sys = rig
    act = Actuator()
    if passive:
        tr, wall = runup(rig, rate)
        show("passive 0.5 MPa", tr, wall)
    grid = adaptive_grid()
    for lab, meas in (("disk B", [("displacement", DISK)]), ("journal", [("journal", 0)])):
        if measure not in ("both", lab.split()[0]):
            continue
        t0 = time.perf_counter()
        des = adaptive_design(rig, grid, meas, fraction=fraction, gain_max_1_per_s=gamma_max,
                              leak_1_per_s=leak, freeze_at_limits=freeze,
                              chamber_pressure_pa=0.5e6, config_ay_m=0.0, actuator=act,
                              washout_hz=washout_hz)
        g = des.gain_1_per_s
        print(f"[adaptive] {lab}: influence coefficients and share-rule design at {grid.size} "
              f"speeds in {time.perf_counter() - t0:.1f} s; |Σw + T̂⁺D − 1| ≤ "
              f"{np.abs(des.share_sum - 1).max():.1e}")
        for lo, hi in ((10, 30), (30, 36), (36, 42), (42, 60), (60, 84), (84, 95), (95, 120.1)):
            m = (grid >= lo) & (grid < hi)
            i = np.flatnonzero(m)[np.argmin(g[m])]
            print(f"[adaptive]   {lo}–{hi:g} Hz: γ(Ω) {g[m].min():.3g}–{g[m].max():.3g} 1/s "
                  f"(least at {grid[i]:.1f} Hz, set by the {des.limit_hz[i]:.2f} Hz mode); "
                  f"averaged loop max Re {des.averaged_max_real_1_per_s[m].max():+.3f} 1/s "
                  f"(plant {des.passive_max_real_1_per_s[m].max():+.3f})")
        if check:
            dc_check(rig, des, meas, leak, act, rate, washout_hz)
            for gc in (gamma, 2.0):
                am = averaged_stability(rig, des.law.with_gain(gc), chamber_pressure_pa=0.5e6,
                                        config_ay_m=0.0, actuator=act)
                bad = grid[am > 0]
                print(f"[adaptive]   constant γ = {gc} 1/s, σ = {leak}: averaged loop max Re "
                      f"{am.max():+.3f} 1/s at {grid[np.argmax(am)]:.1f} Hz; unstable at "
                      f"{bad.size} of {grid.size} speeds"
                      + (f" ({bad.min():.1f}–{bad.max():.1f} Hz)" if bad.size else ""))
        law = des.law if schedule else des.law.with_gain(gamma)
        tag = (f"γ(Ω) share rule κ = {fraction}, ≤ {gamma_max}" if schedule else f"γ = {gamma}")
        tag += f", σ = {leak}" + (", frozen at the limits" if freeze else "")
        tag += f", washout {washout_hz} Hz" if washout_hz else ""
        tr, wall = runup(rig, rate, adaptive=law)
        show(f"adaptive 1× on {lab} ({tag})", tr, wall)
        cm = command_mean(tr, DC_SPEEDS)
        print("[adaptive]   command mean over ±4 revolutions: " + ", ".join(
            f"{f:g} Hz {c / 1e6:.3f}" for f, c in zip(DC_SPEEDS, cm)) + " MPa")
        ok = np.isfinite(tr.t)  # a run that stopped early has NaN rows after its end
        P = tr.adaptive_states[ok]
        cmd = tr.chamber_pressure_command_pa[ok]
        print(f"[adaptive]   |P| max {np.abs(P[:, 0] + 1j * P[:, 1]).max() / 1e6:.3f} MPa; "
              f"command outside [0, 1] MPa in {100 * np.mean((cmd <= 0) | (cmd >= 1e6)):.1f} % "
              f"of the samples; ended at {tr.speed_hz_t[ok].max():.2f} Hz ({tr.status}"
              + (f": {tr.message}" if tr.status != "ok" else "") + ")")


def part_bound():
    """The synchronous bound (§3.2) for the unbalance UB with the mean pressure held at
    0.5 MPa (each station alone): the steady 1× orbit any 1× command on 0.5 MPa can reach."""
    from rotordyn.control.synchronous import synchronous_bound

    rig = rd.models.paper_rig()
    sp = np.unique(np.concatenate([np.arange(10.0, 120.01, 1.0), np.arange(35.0, 42.0, 0.1),
                                   np.arange(84.0, 94.0, 0.1)]))
    for name, st in (("journal", JOURNAL), ("disk B", DISK)):
        t0 = time.perf_counter()
        sb = synchronous_bound(rig, UB, sp, [0.5e6], stations=[st], config_ay_m=0.0,
                               actuator=Actuator())
        pas, opt = sb.passive_m[:, 0, 0] * 1e6, sb.optimal_m[:, 0, 0] * 1e6
        lo, hi = sp < SPLIT, sp >= SPLIT
        out = []
        for m in (lo, hi):
            i = int(np.nanargmax(np.where(m, pas, -1)))
            j = int(np.nanargmax(np.where(m, opt, -1)))
            out.append(f"passive {pas[i]:.2f} µm ({sp[i]:.1f} Hz), 1× on 0.5 MPa "
                       f"{opt[j]:.2f} µm ({sp[j]:.1f} Hz)")
        print(f"[bound] {UB} {name}: < 65 Hz: {out[0]}; >= 65 Hz: {out[1]} "
              f"({time.perf_counter() - t0:.1f} s)")


def main():
    global UB, MAX_STEPS
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", default="all",
                    choices=["aw", "schedule", "schedule-grid", "adaptive", "bound", "all"])
    ap.add_argument("--rate-hz-s", type=float, default=10.0)
    ap.add_argument("--gamma", type=float, default=20.0)
    ap.add_argument("--washout-hz", type=float, default=0.0)
    ap.add_argument("--refine-rounds", type=int, default=0)
    ap.add_argument("--no-runup", action="store_true")
    ap.add_argument("--unbalance", nargs=3, type=float, metavar=("ST", "ME", "PH"),
                    help="station, kg m, deg (default: 2e-5 kg m at disk B, 0 deg)")
    ap.add_argument("--measure", default="both", choices=["both", "disk", "journal"])
    ap.add_argument("--passive", action="store_true",
                    help="with --part adaptive: also the passive run-up at 0.5 MPa")
    ap.add_argument("--schedule", action="store_true",
                    help="with --part adaptive: γ(Ω) by the share rule (≤ --gamma)")
    ap.add_argument("--fraction", type=float, default=0.5, help="κ of the share rule")
    ap.add_argument("--leak", type=float, default=0.0, help="σ, 1/s")
    ap.add_argument("--freeze", action="store_true", help="freeze at the valve's limits")
    ap.add_argument("--check", action="store_true",
                    help="averaged-loop check of constant γ (--gamma and 2); the design's "
                    "exact frozen-speed loop and DC command from the equilibrium drift")
    ap.add_argument("--adaptive-washout-hz", type=float, default=0.0,
                    help="with --part adaptive: the law's measurement washout corner, Hz")
    ap.add_argument("--max-steps", type=int, default=MAX_STEPS,
                    help="CVODE steps per output interval (a stalled run returns not_converged)")
    a = ap.parse_args()
    MAX_STEPS = a.max_steps
    if a.unbalance:
        UB = [(int(a.unbalance[0]), a.unbalance[1], a.unbalance[2])]
    print(f"unbalance {UB}")
    print(f"load at start: {load()}")
    if a.part in ("aw", "all"):
        part_aw()
    if a.part in ("schedule", "all"):
        part_schedule(a.rate_hz_s, a.washout_hz, a.refine_rounds, not a.no_runup)
    if a.part in ("schedule-grid", "all"):
        part_schedule_grid(a.rate_hz_s, a.washout_hz or 2.0)
    if a.part in ("bound", "all"):
        part_bound()
    if a.part in ("adaptive", "all"):
        part_adaptive(a.rate_hz_s, a.gamma, a.passive, a.measure, a.schedule, a.fraction,
                      a.gamma, a.leak, a.freeze, a.check, a.adaptive_washout_hz)


if __name__ == "__main__":
    main()
