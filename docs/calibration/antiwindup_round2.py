"""Anti-windup, round 2 (issue 24, docs/control.md §2.4): back-calculation against
conditioning, continuous and sample-and-hold laws, on the law's own saturation (a speed dip)
and on the schedule's (a pressure pulse beyond the valve's range), on the paper rig and on the
compressor with an active bearing.

Run:  .venv/bin/python docs/calibration/antiwindup_round2.py [--part dip|pulse|rate|compressor|all]
      [--sample-time 5e-4]
Prints every number quoted in docs/control.md §2.4 (round 2), with the wall time of each run
and the machine load.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.control import Actuator, PressureSchedule, SpeedProfile
from rotordyn.control.antiwindup import with_anti_windup
from rotordyn.control.export import discretise
from rotordyn.control.pid import pid

C_RIG = 3e-4
AY, F, PC = -1.85e-3, 50.0, 0.15e6
MODELS = Path(__file__).resolve().parents[2] / "tests" / "data" / "models"


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def variants(k):
    out = {"none": k, "back-calculation": with_anti_windup(k),
           "conditioning": with_anti_windup(k, mode="conditioning"),
           "conditioning, Hanus gain": with_anti_windup(k, gain="hanus", mode="conditioning")}
    return out


def measure(tr, act, jx, jy, t_after):
    m = tr.t >= t_after
    e = np.hypot(tr.r[m, jx] - tr.equilibrium_r[jx], tr.r[m, jy] - tr.equilibrium_r[jy])
    ise = float(np.sum(0.5 * (e[1:] ** 2 + e[:-1] ** 2) * np.diff(tr.t[m])))
    cmd = tr.chamber_pressure_command_pa
    sat = (cmd <= act.p_min_pa) | (cmd >= act.p_max_pa)
    return ise, (float(tr.t[sat].max()) if sat.any() else None), float(e.max())


def show(tag, lab, law, tr, act, jx, jy, t_after, wall, clearance):
    ise, sat, emax = measure(tr, act, jx, jy, t_after)
    rate = law.info.get("tracking_rate_hz")
    print(f"[{tag}] {lab:26s} {tr.status}: command saturated until "
          f"{'never' if sat is None else f'{sat:.4f} s'}, largest error after "
          f"{emax / clearance:.4f} c, ∫e² dt after {ise:.3e} m² s"
          f"{'' if rate is None else f' (tracking {rate:.2f} Hz)'} ({wall:.1f} s wall, load "
          f"{load()})")


def laws(sample_time):
    k = pid(1.0e9, 2.5e6, 1.0e9 / 0.02)
    # Tustin: the ZOH law of this PID closes an unstable loop at T ≥ 0.5 ms (max Re λ +27.6
    # 1/s at 0.5 ms, +215 at 1 ms; Tustin −1.53 and −1.49, the continuous loop −1.56)
    return {"continuous": k,
            f"discrete (Tustin) T = {sample_time:g} s": discretise(k, sample_time, "tustin")}


def part_dip(sample_time):
    """The law saturates: the speed dips 50 → 30 Hz for 0.1 s (§2.4 round 1)."""
    rig = rd.models.paper_rig()
    bc = [b for b in assembled(rig).bearings if b.active][0]
    prof = SpeedProfile.table([0, 0.02, 0.03, 0.12, 0.13], [50, 50, 30, 30, 50])
    for half, rate in ((1e3, np.inf), (1e3, 1e5)):
        act = Actuator(p_min_pa=PC - half, p_max_pa=PC + half, rate_limit_pa_s=rate)
        for kind, k in laws(sample_time).items():
            for lab, law in variants(k).items():
                t0 = time.perf_counter()
                tr = rd.transient(rig, 0.5, chamber_pressure_pa=PC, config_ay_m=AY, speed=prof,
                                  controller=law, actuator=act, n_out=1001, max_step_s=5e-4)
                show(f"dip ±{half:g} Pa, rate {rate:g} Pa/s, {kind}", lab, law, tr, act, bc.jx,
                     bc.jy, 0.13, time.perf_counter() - t0, C_RIG)


def part_pulse(sample_time):
    """The schedule saturates: p_c(t) pulses to 0.6 MPa (0.02–0.13 s) on a valve stopping at
    p_max (0.2 or 0.3 MPa), the PID holding the journal."""
    rig = rd.models.paper_rig()
    bc = [b for b in assembled(rig).bearings if b.active][0]
    sched = PressureSchedule.time_table([0, 0.02, 0.025, 0.125, 0.13], [PC, PC, 0.6e6, 0.6e6, PC])
    for pmax in (0.2e6, 0.3e6):
        act = Actuator(p_min_pa=0.0, p_max_pa=pmax)
        for kind, k in laws(sample_time).items():
            for lab, law in variants(k).items():
                t0 = time.perf_counter()
                tr = rd.transient(rig, 0.5, F, config_ay_m=AY, pressure=sched, controller=law,
                                  actuator=act, n_out=1001, max_step_s=5e-4)
                show(f"pulse 0.6 MPa on p_max {pmax / 1e6:g} MPa, {kind}", lab, law, tr, act,
                     bc.jx, bc.jy, 0.13, time.perf_counter() - t0, C_RIG)


def part_rate():
    """The schedule beyond the valve's rate: p_c(t) steps 0.15 → 0.25 MPa in 1 ms (and back at
    0.12 s) on a first-order valve limited to 2 MPa/s (range [0, 1] MPa: the magnitude never
    saturates, so conditioning is back-calculation here)."""
    rig = rd.models.paper_rig()
    bc = [b for b in assembled(rig).bearings if b.active][0]
    sched = PressureSchedule.time_table([0, 0.02, 0.021, 0.12, 0.121],
                                        [PC, PC, 0.25e6, 0.25e6, PC])
    act = Actuator(order=1, p_min_pa=0.0, p_max_pa=1e6, rate_limit_pa_s=2e6)
    for lab, law in variants(pid(1.0e9, 2.5e6, 1.0e9 / 0.02)).items():
        t0 = time.perf_counter()
        tr = rd.transient(rig, 0.4, F, config_ay_m=AY, pressure=sched, controller=law,
                          actuator=act, n_out=801, max_step_s=5e-4)
        wall = time.perf_counter() - t0
        e = np.hypot(tr.r[:, bc.jx] - tr.equilibrium_r[bc.jx],
                     tr.r[:, bc.jy] - tr.equilibrium_r[bc.jy])
        m = tr.t >= 0.121
        ise = float(np.sum(0.5 * (e[m][1:] ** 2 + e[m][:-1] ** 2) * np.diff(tr.t[m])))
        whole = float(np.sum(0.5 * (e[1:] ** 2 + e[:-1] ** 2) * np.diff(tr.t)))
        print(f"[rate step 2 MPa/s] {lab:26s} {tr.status}: ∫e² dt after the step down "
              f"{ise:.3e}, over the run {whole:.3e} m² s, largest error {e.max() / C_RIG:.3f} c "
              f"({wall:.1f} s wall, load {load()})")


def part_compressor(sample_time):
    """The compressor with an active DE bearing: a 0.6 MPa pulse (5–30 ms) on a valve
    stopping at 0.25 MPa, PID 2e9 Pa/m, 2e5 Pa s/m, T_i 0.02 s at 60 Hz."""
    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    bc = [b for b in assembled(s).bearings if b.active][0]
    cl = 1e-4
    sched = PressureSchedule.time_table([0, 0.005, 0.01, 0.03, 0.035],
                                        [0.2e6, 0.2e6, 0.6e6, 0.6e6, 0.2e6])
    act = Actuator(p_min_pa=0.0, p_max_pa=0.25e6)
    k = pid(2e9, 2e5, 2e9 / 0.02)
    for kind, kk in (("continuous", k), (f"discrete T = {sample_time:g} s",
                                         discretise(k, sample_time))):
        for lab, law in variants(kk).items():
            t0 = time.perf_counter()
            tr = rd.transient(s, 0.1, 60.0, pressure=sched, controller=law, actuator=act,
                              n_out=401)
            wall = time.perf_counter() - t0
            show(f"compressor pulse, {kind}", lab, law, tr, act, bc.jx, bc.jy, 0.035, wall, cl)
            e = np.hypot(tr.r[:, bc.jx] - tr.equilibrium_r[bc.jx],
                         tr.r[:, bc.jy] - tr.equilibrium_r[bc.jy])
            print(f"[compressor pulse, {kind}] {lab:26s} ∫e² dt over the whole run "
                  f"{float(np.sum(0.5 * (e[1:] ** 2 + e[:-1] ** 2) * np.diff(tr.t))):.3e} m² s, "
                  f"largest |u| after the pulse "
                  f"{np.abs(tr.controller_output_pa[tr.t >= 0.035]).max():.4g} Pa")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", default="all",
                    choices=["dip", "pulse", "rate", "compressor", "all"])
    ap.add_argument("--sample-time", type=float, default=5e-4)
    a = ap.parse_args()
    print(f"load at start: {load()}")
    if a.part in ("dip", "all"):
        part_dip(a.sample_time)
    if a.part in ("pulse", "all"):
        part_pulse(a.sample_time)
    if a.part in ("rate", "all"):
        part_rate()
    if a.part in ("compressor", "all"):
        part_compressor(a.sample_time)


if __name__ == "__main__":
    main()
