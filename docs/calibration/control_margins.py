"""Margins of the tuned PD, LQG and H∞ laws at the rig's unstable point (a_y = −1.85 mm, 50 Hz,
p_c = 0.05 MPa, 100 Hz valve; the laws of docs/control.md §3.1), each beside an independent
computation, and the accuracy of the exported systems in python-control with and without
slycot (issue 24, docs/control.md §2.1).

Independent computations:
* gain margins: the loop gain α at which the closed loop u = α K y has an eigenvalue on the
  imaginary axis (Brent on the closed-loop matrix's largest Re λ);
* delay margin: the delay at which the closed loop with a 6th-order Padé delay before the
  valve turns unstable (Brent on its largest Re λ);
* phase margin: from that delay, ω_c τ (ω_c the crossover of the least delay margin);
* peak |S| and disk margin 1/‖S − ½‖∞: numpy solves on the unscaled matrices on a grid of
  1200 log points + the closed-loop poles' frequencies, refined by a bounded scalar search;
  and python-control's L∞ norm (SLICOT AB13DD).

Run:  .venv/bin/python docs/calibration/control_margins.py   (H∞ rows need slycot)
"""

from __future__ import annotations

import math
import time

import control
import numpy as np
from scipy.optimize import brentq, minimize_scalar

import rotordyn as rd
from rotordyn.control import Controller
from rotordyn.control.closedloop import closed_loop, closed_loop_matrix
from rotordyn.control.lqr import lqg
from rotordyn.control.pid import tune_pd
from rotordyn.control.plant import plant
from rotordyn.control.reduction import balanced_truncation, modal_truncation

AY, PC, F = -1.85e-3, 0.05e6, 50.0


def max_real(p, k):
    return float(np.linalg.eigvals(closed_loop_matrix(p, k)).real.max())


def k_dense(k, s):
    if k.n_states == 0:
        return k.D
    return k.C @ np.linalg.solve(s * np.eye(k.n_states) - k.A, k.B) + k.D


def independent(p, k, m):
    """The independent numbers of the module docstring."""
    out = {}
    out["gm_lo"] = brentq(lambda a: max_real(p, k.scaled(a)), 0.9 * m.gain_margin_lower,
                          1.1 * m.gain_margin_lower, xtol=1e-15)
    out["gm_hi"] = brentq(lambda a: max_real(p, k.scaled(a)), 0.9 * m.gain_margin_upper,
                          1.1 * m.gain_margin_upper, xtol=1e-15)

    def with_delay(tau):
        num, den = control.pade(tau, 6)
        kd = control.ss(control.tf(num, den)) * k.to_control()
        return max_real(p, Controller.from_lti(kd, k.measurements))

    tau = m.delay_margin_s
    out["dm"] = brentq(with_delay, 0.9 * tau, 1.1 * tau, xtol=1e-15)
    out["pm_from_dm"] = math.degrees(2 * math.pi * m.delay_margin_hz * out["dm"])

    def L(f):
        s = 2j * np.pi * f
        return -(k_dense(k, s) @ (p.C @ np.linalg.solve(s * np.eye(p.A.shape[0]) - p.A,
                                                          p.B)))[0, 0]

    lam = np.linalg.eigvals(closed_loop_matrix(p, k))
    fd = np.abs(lam.imag[lam.imag > 0]) / (2 * np.pi)
    grid = np.unique(np.concatenate([np.geomspace(0.1, 5000.0, 1200),
                                     (fd[:, None] * (1 + np.linspace(-2e-3, 2e-3, 9))).ravel()]))
    for key, fun in (("S", lambda x: abs(1 / (1 + x))),
                     ("disk", lambda x: abs(1 / (1 + x) - 0.5))):
        vals = np.array([fun(L(f)) for f in grid])
        i = int(np.argmax(vals))
        r = minimize_scalar(lambda lf: -fun(L(np.exp(lf))), method="bounded",
                            bounds=(np.log(grid[max(i - 1, 0)]), np.log(grid[i + 1])),
                            options={"xatol": 1e-13})
        out[key] = (-r.fun, float(np.exp(r.x)))
    n = p.n_mech
    sc = np.concatenate([np.full(n, 3e-4), np.full(n, 2 * np.pi * 50 * 3e-4),
                         np.full(p.A.shape[0] - 2 * n, 1e5)])
    G = control.ss(p.A / sc[:, None] * sc[None, :], p.B / sc[:, None], p.C * sc[None, :],
                   np.zeros((p.C.shape[0], 1)))
    S = control.feedback(control.ss([], [], [], [[1.0]]), -(k.to_control() * G))
    out["S_ab13dd"] = float(control.linfnorm(S)[0])
    return out


def export_errors(p, k):
    """Largest relative error of python-control's evaluation (slycot TB05AD or its fallback)
    of the LQG law and of the plant, unscaled and balanced, against rotordyn's response."""
    from rotordyn.control import lti

    f = np.geomspace(1.0, 2000.0, 200)
    w = 2 * np.pi * f
    ref_k = lti.freqresp(lti.balanced(lti.SS(k.A, k.B, k.C, k.D)), w)
    ref_p = p.frequency_response(f)
    rows = []
    for what, ref, make in (("LQG law", ref_k, k.to_control), ("plant", ref_p, p.to_control)):
        for bal in (False, True):
            sys_ = make(balanced=bal)
            for slycot in (True, False):
                with pytest_like_patch(not slycot):
                    G = np.moveaxis(sys_(1j * w), 2, 0)
                err = max(np.linalg.norm(G[i] - ref[i]) / np.linalg.norm(ref[i])
                          for i in range(len(f)))
                rows.append((what, "balanced" if bal else "unscaled",
                             "slycot TB05AD" if slycot else "dense solve", err))
    return rows


class pytest_like_patch:
    """Make python-control's slycot evaluation fail so that it takes its own path."""

    def __init__(self, active):
        self.active = active

    def __enter__(self):
        if self.active:
            self.saved = control.StateSpace.slycot_laub

            def no(self_, x):
                raise ImportError("disabled")
            control.StateSpace.slycot_laub = no

    def __exit__(self, *exc):
        if self.active:
            control.StateSpace.slycot_laub = self.saved


def main():
    rig = rd.models.paper_rig()
    p = plant(rig, F, PC, AY, measurements=[("journal", 0)])
    laws = {"PD (tuned)": tune_pd(p)[0], "LQG (17-state modal truncation)":
            lqg(modal_truncation(p, 500.0)[0])}
    try:
        from rotordyn.control.hinf import hinf
        pd_ = plant(rig, F, PC, AY, measurements=[("journal", 0)], disturbance_stations=[4])
        laws["H∞ (8-state balanced truncation)"] = hinf(balanced_truncation(pd_, 8)[0])
    except ImportError as exc:
        print(f"H∞ skipped: {exc}")
    print("| law | quantity | rotordyn (frequency) | independent | relative difference |")
    print("|---|---|---|---|---|")
    for name, k in laws.items():
        t0 = time.perf_counter()
        cl = closed_loop(p, k)
        dt = time.perf_counter() - t0
        m = cl.margins.input
        ind = independent(p, k, m)

        def row(q, mine, at, other):
            d = abs(mine / other - 1) if other else float("nan")
            print(f"| {name} | {q} | {mine:.6g}{at} | {other:.6g} | {d:.1e} |")

        row("gain margin, lower", m.gain_margin_lower, f" ({m.gain_margin_lower_hz:.2f} Hz)",
            ind["gm_lo"])
        row("gain margin, upper", m.gain_margin_upper, f" ({m.gain_margin_upper_hz:.2f} Hz)",
            ind["gm_hi"])
        for pm, fc, dm in zip(m.phase_margins_deg, m.crossover_hz, m.delay_margins_s):
            print(f"| {name} | phase margin at a crossover | {pm:.3f}° ({fc:.2f} Hz); delay "
                  f"{dm * 1e3:.4g} ms | | |")
        row("delay margin (ms)", m.delay_margin_s * 1e3, f" ({m.delay_margin_hz:.2f} Hz)",
            ind["dm"] * 1e3)
        row("phase margin at that crossover (deg)",
            float(m.phase_margins_deg[np.argmin(m.delay_margins_s)]), "", ind["pm_from_dm"])
        row("peak \\|S\\|", m.peak_sensitivity, f" ({m.peak_sensitivity_hz:.3f} Hz)",
            ind["S"][0])
        row("peak \\|S\\|, python-control AB13DD", m.peak_sensitivity, "", ind["S_ab13dd"])
        lo, hi = m.disk.gain_db
        row("disk margin α (σ = 0)", m.disk.alpha,
            f" ({m.disk.frequency_hz:.3f} Hz; gain [{lo:.2f}, {hi:.2f}] dB, ±{m.disk.phase_deg:.2f}°)",
            1 / ind["disk"][0])
        for sg in (-1.0, 1.0):
            d = m.disk_margin(sg)
            print(f"| {name} | disk margin σ = {sg:+.0f} | {d.alpha:.5g} (gain "
                  f"[{d.gain_db[0]:.2f}, {d.gain_db[1]:.2f}] dB, ±{d.phase_deg:.2f}°) | | |")
        ml = cl.margins.multiloop
        print(f"| {name} | multivariable disk margin (journal x, y at once) | "
              f"{ml.disk.alpha:.5g} ({ml.disk.frequency_hz:.2f} Hz; ±{ml.disk.gain_db[1]:.2f} dB, "
              f"±{ml.disk.phase_deg:.2f}°) | | |")
        print(f"| {name} | time of closed_loop() with every margin | {dt:.2f} s | | |")
    print()
    print("| export | states | python-control path | largest relative error, 1 Hz–2 kHz |")
    print("|---|---|---|---|")
    kq = laws["LQG (17-state modal truncation)"]
    pd2 = plant(rig, F, PC, AY, measurements=[("journal", 0)], disturbance_stations=[4, 6])
    for what, st, path, err in export_errors(pd2, kq):
        print(f"| {what} | {st} | {path} | {err:.2e} |")


if __name__ == "__main__":
    main()
