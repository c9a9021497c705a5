"""H∞ output feedback at the passive rig's unstable point (issue 8, docs/control.md §3.1):
a_y = −1.85 mm, 50 Hz, p_c = 0.05 MPa, 100 Hz valve; the law is designed on an 8-state
balanced truncation of the plant (journal disturbance force, journal measurement) and
closed on the full plant, linear and nonlinear (0.1 c vertical disturbance, 2 s), beside the
closed-loop H∞ norm measured by a frequency sweep, the controlled p_c threshold at 50 Hz, and
the valve bandwidth at which the law fails.

Run:  .venv/bin/python docs/calibration/control_hinf.py   (needs slycot: rotordyn[hinf])
"""

from __future__ import annotations

import time

import numpy as np
from scipy.optimize import brentq

import rotordyn as rd
from rotordyn.control import Actuator
from rotordyn.control.closedloop import closed_loop
from rotordyn.control.hinf import hinf, lower_lft_response
from rotordyn.control.plant import plant
from rotordyn.control.reduction import balanced_truncation, modal_truncation

# the same operating point and measure as the PD/LQG script beside this one
from control_stabilisation import AY, PC, C, F, amplitude, thresholds  # noqa: E402


def main():
    rig = rd.models.paper_rig()
    act = Actuator()
    p = plant(rig, F, PC, AY, measurements=[("journal", 0)], actuator=act,
              disturbance_stations=[4])
    print(f"plant: {p.A.shape[0]} states, max Re λ = {p.poles.real.max():.3f} 1/s (unstable)")
    for name, (r, info) in (("balanced truncation, 8 states", balanced_truncation(p, 8)),
                            ("modal truncation < 500 Hz", modal_truncation(p, 500.0)),
                            ("full plant", (p, {"relative_error": 0.0}))):
        t0 = time.perf_counter()
        k = hinf(r)
        dt = time.perf_counter() - t0
        A, B, Cg, D, sizes = k.info["generalized_plant"]
        f = np.logspace(-1, 4, 4000)
        s = lower_lft_response(A, B, Cg, D, sizes, k.info["controller_scaled"], f)
        cl = closed_loop(p, k)
        print(f"H∞ on the {name} (relative error {info['relative_error']:.1e}): "
              f"γ = {k.info['gamma']:.5f}, swept ‖T_zw‖∞ = {s.max():.5f} at "
              f"{f[np.argmax(s)]:.2f} Hz, n_k = {k.n_states}, synthesis {dt:.2f} s; on the full "
              f"plant: {cl!r}")
        if name.startswith("balanced"):
            kb, clb = k, cl
    k, cl = kb, clb
    kw = dict(disturbance_m=(0.0, 0.1 * C), n_out=8001, rtol=1e-7, atol_m=1e-11)
    tr = rd.transient(rig, 2.0, F, PC, AY, controller=k, actuator=act, **kw)
    print(f"nonlinear closed loop (H∞, 8 states): {tr.status}, largest distance from the "
          f"equilibrium over 0.8–1.0 s {amplitude(tr, 0.8) / C:.2e} c, over 1.8–2.0 s "
          f"{amplitude(tr, 1.8) / C:.2e} c; p_c within "
          f"[{tr.chamber_pressure_actual_pa.min() / 1e6:.4f}, "
          f"{tr.chamber_pressure_actual_pa.max() / 1e6:.4f}] MPa")
    thresholds(rig, k, act, "H∞")

    def maxre(fn):
        a = Actuator(natural_frequency_hz=fn)
        return closed_loop(plant(rig, F, PC, AY, measurements=[("journal", 0)], actuator=a),
                           k, with_margins=False).max_real
    fns = [100, 70, 50, 40, 30, 25, 20, 15, 10]
    vals = [maxre(f) for f in fns]
    print("valve f_n (Hz) -> closed-loop max Re λ (1/s), same H∞ law:",
          ", ".join(f"{f}: {v:.2f}" for f, v in zip(fns, vals)))
    for a, b, va, vb in zip(fns, fns[1:], vals, vals[1:]):
        if va < 0 <= vb:
            print(f"the H∞ law fails below a valve natural frequency of "
                  f"{brentq(maxre, b, a, xtol=1e-3):.2f} Hz")
            break


if __name__ == "__main__":
    main()
