"""Feedback stabilisation of the paper's rig with the active bearing (issue 8, docs/control.md
§1, §3, §4): the passive rig at a_y = −1.85 mm, 50 Hz, p_c = 0.05 MPa whirls (limit cycle);
a PD law on the journal's vertical displacement, tuned on the linear closed loop with a
100 Hz servo valve, stabilises it; the nonlinear closed loop from a 0.1 c disturbance decays;
the thresholds move; linear vs nonlinear decay rates; the valve bandwidth at which the same
law fails.

Run:  .venv/bin/python docs/calibration/control_stabilisation.py
Prints every number quoted in docs/control.md and writes docs/figures/control_stabilisation.png.
"""

from __future__ import annotations

import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.control import Actuator  # noqa: E402
from rotordyn.control.closedloop import closed_loop, closed_loop_matrix  # noqa: E402
from rotordyn.control.lqr import lqg  # noqa: E402
from rotordyn.control.pid import tune_pd  # noqa: E402
from rotordyn.control.plant import plant  # noqa: E402
from rotordyn.control.reduction import modal_truncation  # noqa: E402
from rotordyn.control.threshold import closed_loop_threshold  # noqa: E402

FIG = Path(__file__).resolve().parents[1] / "figures"
C, AY, F, PC = 3e-4, -1.85e-3, 50.0, 0.05e6


def amplitude(tr, t0):
    m = tr.t >= t0
    return float(np.hypot(tr.journal_x_m[m, 0] - tr.equilibrium_r[2],
                          tr.journal_y_m[m, 0] - tr.equilibrium_r[3]).max())


def thresholds(rig, k, act, label):
    """Print the controlled p_c crossings at 50 Hz and the threshold speed at p_c = 0.1 MPa,
    passive and with the fixed law ``k`` (labelled ``label``)."""
    roots, scan = closed_loop_threshold(rig, k, "chamber_pressure_pa", bounds=(0, 0.3e6),
                                        speed_hz=F, config_ay_m=AY, actuator=act, n_scan=31)
    print(f"controlled p_c at 50 Hz: crossings {roots}; max Re λ over 0–0.3 MPa in "
          f"[{scan.max_real_1_per_s.min():.2f}, {scan.max_real_1_per_s.max():.2f}] 1/s")
    ths = rd.threshold(rig, "speed_hz", bounds=(20, 150), chamber_pressure_pa=0.1e6,
                       config_ay_m=AY, n_scan=27)
    rs, _ = closed_loop_threshold(rig, k, "speed_hz", bounds=(20, 150), chamber_pressure_pa=0.1e6,
                                  config_ay_m=AY, actuator=act, n_scan=27)
    th = ths.crossings[0]
    print(f"threshold speed at p_c = 0.1 MPa: passive {th:.2f} Hz, {label} "
          + (f"{rs[0]:.2f} Hz (+{rs[0] - th:.2f} Hz)" if len(rs) else "none in 20–150 Hz"))


def main():
    rig = rd.models.paper_rig()
    st = rd.stability(rig, F, PC, AY)
    i = int(np.argmax(st.eigenvalues.real))
    print(f"passive at a_y = {AY * 1e3} mm, {F} Hz, p_c = {PC / 1e6} MPa: max Re λ = "
          f"{st.eigenvalues[i].real:.3f} 1/s at {st.frequencies_hz[i]:.2f} Hz (unstable)")
    th = rd.threshold(rig, "chamber_pressure_pa", bounds=(0, 0.3e6), speed_hz=F,
                      config_ay_m=AY, n_scan=31)
    print("passive p_c crossings at 50 Hz:", ", ".join(f"{x / 1e6:.4f} MPa" for x in th.crossings))

    act = Actuator()
    p = plant(rig, F, PC, AY, measurements=[("journal", 0)], actuator=act)
    k, cl = tune_pd(p)
    print(f"valve: 2nd order f_n = {act.natural_frequency_hz} Hz, ζ = {act.damping}, "
          f"p_c in [{act.p_min_pa / 1e6}, {act.p_max_pa / 1e6}] MPa")
    print(f"PD (vertical journal displacement, derivative filter τ = {k.info['tau_d_s']} s): "
          f"k_p = {k.info['kp']:.4g} Pa/m, k_d = {k.info['kd']:.4g} Pa s/m")
    print(f"  linear closed loop: max Re λ = {cl.max_real:.3f} 1/s, min ζ (all modes) = "
          f"{cl.min_damping:.4f}; margins {cl.margins.input!r}")
    pr, info = modal_truncation(p, 500.0)
    kq = lqg(pr)
    clq = closed_loop(p, kq)
    print(f"LQG on the modal truncation (order {info['order']} of {info['full_order']}, "
          f"relative H∞ error {info['relative_error']:.2e} over 1 Hz–2 kHz): n_k = "
          f"{kq.n_states}, on the full plant max Re λ = {clq.max_real:.3f} 1/s, "
          f"min ζ = {clq.min_damping:.4f}; margins {clq.margins.input!r}")

    # Nonlinear: 0.1 c disturbance, 2 s
    kw = dict(disturbance_m=(0.0, 0.1 * C), n_out=8001, rtol=1e-7, atol_m=1e-11)
    t0 = time.perf_counter()
    ol = rd.transient(rig, 2.0, F, PC, AY, **kw)
    t1 = time.perf_counter()
    cln = rd.transient(rig, 2.0, F, PC, AY, controller=k, actuator=act, **kw)
    t2 = time.perf_counter()
    print(f"nonlinear open loop: {ol.status}, largest distance from the equilibrium over "
          f"0.8–1.0 s = {amplitude(ol, 0.8) / C:.3f} c, over 1.8–2.0 s = "
          f"{amplitude(ol, 1.8) / C:.3f} c ({ol.stats['steps']} steps, {t1 - t0:.1f} s wall)")
    print(f"nonlinear closed loop (PD): {cln.status}, amplitude over the last 0.2 s = "
          f"{amplitude(cln, 1.8) / C:.2e} c ({cln.stats['steps']} steps, {t2 - t1:.1f} s wall); "
          f"p_c within [{cln.chamber_pressure_actual_pa.min() / 1e6:.4f}, "
          f"{cln.chamber_pressure_actual_pa.max() / 1e6:.4f}] MPa")
    clq_nl = rd.transient(rig, 2.0, F, PC, AY, controller=kq, actuator=act, **kw)
    print(f"nonlinear closed loop (LQG): {clq_nl.status}, amplitude over the last 0.2 s = "
          f"{amplitude(clq_nl, 1.8) / C:.2e} c; p_c within "
          f"[{clq_nl.chamber_pressure_actual_pa.min() / 1e6:.4f}, "
          f"{clq_nl.chamber_pressure_actual_pa.max() / 1e6:.4f}] MPa")

    # Thresholds with the fixed PD law
    thresholds(rig, k, act, "controlled")

    # Linear vs nonlinear decay: 0.01 c, projection on the closed-loop left eigenvectors
    d = 0.01 * C
    tr = rd.transient(rig, 0.4, F, PC, AY, controller=k, actuator=act, n_out=4001,
                      disturbance_m=(0.0, d), rtol=1e-9, atol_m=1e-14, atol_pa=1e-4)
    Acl = closed_loop_matrix(p, k)
    lam, V = np.linalg.eig(Acl)
    W = np.linalg.inv(V)
    n = p.n_mech
    X = np.hstack([tr.r - tr.equilibrium_r, tr.v, tr.actuator_states - [PC, 0.0],
                   tr.controller_states])
    print("linear vs nonlinear decay rates (least-damped closed-loop modes below 500 Hz):")
    order = np.argsort(-lam.real)
    shown = 0
    for j in order:
        if lam[j].imag < 0 or abs(lam[j]) > 2 * np.pi * 500:
            continue
        q = X @ W[j]
        mag = np.abs(q)
        m = (tr.t > 0.05) & (tr.t < 0.35)
        slope = np.polyfit(tr.t[m], np.log(mag[m]), 1)[0]
        print(f"  λ = {lam[j].real:.3f} ± {abs(lam[j].imag) / (2 * np.pi):.2f} Hz·2πi: "
              f"nonlinear decay {slope:.3f} 1/s ({100 * (slope / lam[j].real - 1):+.2f} %)")
        shown += 1
        if shown == 3:
            break

    # Valve bandwidth: the same PD law with slower valves
    def maxre(fn):
        a = Actuator(natural_frequency_hz=fn)
        return closed_loop(plant(rig, F, PC, AY, measurements=[("journal", 0)], actuator=a),
                           k, with_margins=False).max_real
    fns = [100, 70, 50, 40, 30, 25, 20, 15, 10, 5]
    vals = [maxre(f) for f in fns]
    print("valve f_n (Hz) -> closed-loop max Re λ (1/s):",
          ", ".join(f"{f}: {v_:.2f}" for f, v_ in zip(fns, vals)))
    fail = None
    for a, b, va, vb in zip(fns, fns[1:], vals, vals[1:]):
        if va < 0 <= vb:
            fail = brentq(maxre, b, a, xtol=1e-3)
            break
    if fail:
        print(f"the PD law fails below a valve natural frequency of {fail:.2f} Hz")
        slow = Actuator(natural_frequency_hz=0.8 * fail)
        trs = rd.transient(rig, 2.0, F, PC, AY, controller=k, actuator=slow, **kw)
        print(f"nonlinear check at f_n = {0.8 * fail:.1f} Hz: {trs.status}, amplitude over the "
              f"last 0.2 s = {amplitude(trs, 1.8) / C:.3f} c")

    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    for tr_, lab in ((ol, "open loop"), (cln, "PD + 100 Hz valve")):
        ax[0].plot(tr_.journal_x_m[:, 0] / C, tr_.journal_y_m[:, 0] / C, lw=0.6, label=lab)
        ax[1].plot(tr_.t, np.hypot(tr_.journal_x_m[:, 0] - tr_.equilibrium_r[2],
                                   tr_.journal_y_m[:, 0] - tr_.equilibrium_r[3]) / C, lw=0.6,
                   label=lab)
    ax[0].set_aspect("equal")
    ax[0].set_xlabel("x / c")
    ax[0].set_ylabel("y / c")
    ax[0].legend()
    ax[1].set_yscale("log")
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("|journal − equilibrium| / c")
    ax[2].plot(cln.t, cln.chamber_pressure_actual_pa / 1e6, lw=0.8, label="p_c (actual)")
    ax[2].plot(cln.t, cln.chamber_pressure_command_pa / 1e6, lw=0.5, ls="--", label="command")
    ax[2].set_xlabel("t (s)")
    ax[2].set_ylabel("MPa")
    ax[2].legend()
    fig.tight_layout()
    fig.savefig(FIG / "control_stabilisation.png", dpi=120)
    print(f"wrote {FIG / 'control_stabilisation.png'}")


if __name__ == "__main__":
    main()
