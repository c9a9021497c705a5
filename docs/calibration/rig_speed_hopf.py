"""The paper rig's Hopf point in the speed domain on its own 72 x 16 film (a_y = 0,
p_c = 0.4 MPa; issue 19; docs/nonlinear.md, "The rig in the speed domain"): which answer is
right at 99.4 Hz — the continued limit cycle (≈ 3 µm) or the transient that "settled near
1.7 µm" — and why.

(a) the Hopf point and its first Lyapunov coefficient over the fit half-width ``fd_step``:
    a plateau (the same l1 at h and h/2 and over a decade of h) is the film's kink-free piece
    around the equilibrium, where the discrete film force is smooth;
(b) the bifurcating cycles by harmonic balance a few 1e-4 Hz from the Hopf point: A²/d
    against the leading-order κ of the plateau's l1 (d the distance to the Hopf speed);
(c) the cycles at fixed speeds (harmonic balance from two start amplitudes, then shooting at
    rtol 1e-10, tol 1e-9): two cycles below the Hopf speed, one above;
(d) the branch by pseudo-arclength continuation from the stable cycle at 99.4 Hz down through
    the fold and back up the unstable cycles to the Hopf point (``param_scale`` 50 Hz: a
    speed step of 0.01 Hz counts in the scaled arclength as much as a 0.06 µm step of a
    coordinate, so the fold, 0.12 Hz wide and 1.4 µm high, is round; a constant step 4e-3;
    ``fd_step`` 2e-4, a 0.01 Hz central difference for ∂R/∂p, whose amplitude component is
    ~1e-6 per Hz and drowns in the flows' noise at the default 1e-4 of the bounds' span);
    ``--branch-up``: the same upwards from 99.4 Hz (80 points);
(e) transients at 99.4 Hz from the equilibrium displaced 30 µm, and from the shot cycle, at
    the transient's default tolerances (rtol 1e-6, atol 1e-9 m) and tighter ones.

Run:  .venv/bin/python docs/calibration/rig_speed_hopf.py              # (a)-(c), ~1 min CPU
      .venv/bin/python docs/calibration/rig_speed_hopf.py --branch [--branch-up]  # + (d)
      .venv/bin/python docs/calibration/rig_speed_hopf.py --transients [--long 400]  # + (e)
      .venv/bin/python docs/calibration/rig_speed_hopf.py --pc   # the p_c Hopf point only
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import rotordyn as rd

PC = 0.4e6
RIG = rd.models.paper_rig()


def amp(o) -> float:
    """The active journal's largest distance from its mean over one period (the repeated
    endpoint left out)."""
    x, y = o.journal_x_m[:-1, 0], o.journal_y_m[:-1, 0]
    return float(np.max(np.hypot(x - x.mean(), y - y.mean())))


def window_amplitudes(tr, window_s):
    t = np.asarray(tr.t)
    x, y = tr.journal_x_m[:, 0], tr.journal_y_m[:, 0]
    out = []
    for a in np.arange(0.0, t[-1], window_s):
        m = (t >= a) & (t < a + window_s) & np.isfinite(x)
        out.append(float(np.max(np.hypot(x[m] - x[m].mean(), y[m] - y[m].mean())))
                   if m.sum() > 10 else np.nan)
    return np.array(out)


def hopf_point():
    t = time.process_time()
    br = rd.continuation(RIG, "speed_hz", (90.0, 110.0), chamber_pressure_pa=PC, config_ay_m=0.0)
    (p_h,) = br.hopf_points()
    print(f"(a) equilibrium branch 90-110 Hz: Hopf at {p_h:.7f} Hz "
          f"[{time.process_time() - t:.1f} s CPU]")
    rows = []
    for fd in (1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 2e-2, 5e-2, 1e-1):
        h = rd.hopf(RIG, "speed_hz", at=p_h, chamber_pressure_pa=PC, config_ay_m=0.0,
                    fd_step=fd)
        rows.append(h)
        print(f"    fd_step {fd:6g}: l1 = {h.l1:+.4e} ± {h.l1_error:.1e} ({h.type}), "
              f"κ = {h.amplitude_coefficient[0] * 1e12:9.4g} µm²/Hz, cycles {h.cycle_side}")
    return p_h, rows[2]  # fd_step 1e-3: inside the plateau


def near_cycles(h, distances):
    """(b) harmonic balance at p_H ± d (the cycle side), started at the leading order."""
    sg = 1 if h.cycle_side == "above" else -1
    kap = float(h.amplitude_coefficient[0])
    print(f"(b) cycles {h.cycle_side} the Hopf point by harmonic balance (H = 8, tol 1e-10) "
          f"against κ = {kap * 1e12:.5g} µm²/Hz (fd_step {h.fd_step:g}):")
    for d in distances:
        t = time.process_time()
        o = rd.periodic_orbit(RIG, h.value + sg * d, PC, 0.0, method="harmonic_balance",
                              harmonics=8, start_amplitude_c=np.sqrt(kap * d) / 3e-4,
                              tol=1e-10, floquet="flow", rtol=1e-10, n_out=1001)
        if not o.ok:
            print(f"    d = {d:g} Hz: {o.status} {o.message}")
            continue
        a = amp(o)
        print(f"    d = {d:g} Hz: A = {a * 1e6:.5f} µm (leading order "
              f"{np.sqrt(kap * d) * 1e6:.5f}), A²/(κ d) = {a * a / (kap * d):.4f}, "
              f"|μ_c| = {abs(o.critical_multiplier):.9f} ({'stable' if o.stable else 'unstable'}),"
              f" period {o.period_s * 1e3:.6f} ms [{time.process_time() - t:.1f} s CPU]")


def cycles_at(speeds):
    """(c) every cycle harmonic balance finds from two start amplitudes, polished by
    shooting at rtol 1e-10, tol 1e-9."""
    print("(c) cycles at fixed speeds (HB from 0.001 c and 0.01 c, then shooting):")
    for s in speeds:
        t = time.process_time()
        found = {}
        for a0 in (0.001, 0.01):
            hb = rd.periodic_orbit(RIG, s, PC, 0.0, method="harmonic_balance", harmonics=8,
                                   start_amplitude_c=a0, tol=1e-9, floquet="none", n_out=1001)
            if not hb.ok:
                continue
            o = rd.periodic_orbit(RIG, s, PC, 0.0, start=(hb.r[0], hb.v[0]),
                                  period_s=hb.period_s, rtol=1e-10, tol=1e-9, n_out=2001)
            if o.ok:
                found[round(amp(o) * 1e9)] = o
        eq = rd.stability(RIG, s, PC, 0.0)
        txt = "; ".join(f"{amp(o) * 1e6:.4f} µm |μ_c| {abs(o.critical_multiplier):.6f} "
                        f"{'stable' if o.stable else 'unstable'}"
                        for _, o in sorted(found.items()))
        re_max = float(np.max(np.real(eq.eigenvalues)))
        print(f"    {s:8.3f} Hz: equilibrium max Re λ {re_max:+.6f} 1/s; cycles: "
              f"{txt or 'none'} [{time.process_time() - t:.1f} s CPU]")


def branch(direction):
    """(d) the branch from the stable cycle at 99.4 Hz: down (direction −1) through the fold
    to the Hopf point, or up (+1)."""
    t = time.process_time()
    hb = rd.periodic_orbit(RIG, 99.4, PC, 0.0, method="harmonic_balance", harmonics=8,
                           start_amplitude_c=0.01, tol=1e-9, floquet="none", n_out=1001)
    o = rd.periodic_orbit(RIG, 99.4, PC, 0.0, start=(hb.r[0], hb.v[0]), period_s=hb.period_s,
                          rtol=1e-9, tol=1e-8, n_out=1001)
    bounds = (98.5, 99.5) if direction < 0 else (98.5, 102.0)
    br = rd.continuation(RIG, "speed_hz", bounds, o, direction=direction, rtol=1e-9, tol=1e-8,
                         ds=4e-3, ds_max=4e-3, ds_min=4e-5, max_points=80, param_scale=50.0,
                         fd_step=2e-4, max_iter=12, n_out=1001)
    print(f"(d) {'down' if direction < 0 else 'up'}: {br!r} "
          f"[{time.process_time() - t:.1f} s CPU]")
    print("    speed_hz  amplitude_um  whirl_hz  |mu_c|     stable")
    for i, s in enumerate(br.parameter):
        print(f"    {s:9.5f} {amp(br.orbits[i]) * 1e6:12.5f} {1 / br.period_s[i]:9.5f} "
              f"{br.max_multiplier[i]:.7f}  {bool(br.stable[i])}")
    print("    bifurcations:\n" + br.bifurcations_frame().to_string())
    return br


def transients(long_s):
    """(e) 99.4 Hz: from the equilibrium displaced 30 µm up, and from the shot cycle."""
    s = 99.4
    hb = rd.periodic_orbit(RIG, s, PC, 0.0, method="harmonic_balance", harmonics=8,
                           start_amplitude_c=0.01, tol=1e-9, floquet="none", n_out=1001)
    o = rd.periodic_orbit(RIG, s, PC, 0.0, start=(hb.r[0], hb.v[0]), period_s=hb.period_s,
                          rtol=1e-10, tol=1e-9, n_out=1001)
    print(f"(e) the cycle at {s} Hz by shooting: {amp(o) * 1e6:.4f} µm, "
          f"|μ_c| = {abs(o.critical_multiplier):.6f}, period {o.period_s * 1e3:.5f} ms")
    for rtol, atol in ((1e-6, 1e-9), (1e-6, 1e-12), (1e-7, 1e-11), (1e-8, 1e-12)):
        for start in ("displaced", "cycle"):
            if (rtol, atol) == (1e-6, 1e-12) and start == "displaced":
                continue  # only from the cycle: which tolerance matters
            t_end = long_s if start == "displaced" else 60.0
            t = time.process_time()
            kw = (dict(disturbance_m=(0.0, 3e-5)) if start == "displaced"
                  else dict(r0=o.r[0], v0=o.v[0]))
            tr = rd.transient(RIG, t_end, s, PC, 0.0, n_out=int(t_end * 400) + 1, rtol=rtol,
                              atol_m=atol, **kw)
            w = 20.0 if start == "displaced" else 5.0
            env = " ".join(f"{a * 1e6:.3f}" for a in window_amplitudes(tr, w))
            print(f"    rtol {rtol:g}, atol_m {atol:g}, from the {start} start, {t_end:g} s: "
                  f"{tr.status}; amplitude (µm) per {w:g} s: {env} "
                  f"[{time.process_time() - t:.1f} s CPU]", flush=True)


def pc_point():
    """The supercritical Hopf point over p_c at a_y = −1.85 mm, 50 Hz (docs/nonlinear.md,
    "l1 inside the kink-free piece"): l1 over fd_step, and harmonic-balance cycles d below."""
    fixed = dict(speed_hz=50.0, config_ay_m=-1.85e-3)
    br = rd.continuation(RIG, "chamber_pressure_pa", (0.04e6, 0.08e6), **fixed)
    (p_h,) = br.hopf_points()
    th = rd.threshold(RIG, "chamber_pressure_pa", bounds=(0.04e6, 0.08e6), **fixed)
    print(f"(p) a_y = -1.85 mm, 50 Hz: Hopf at {p_h:.6f} Pa (equilibrium branch; "
          f"rd.threshold {th.value:.6f} Pa)")
    for fd in (1e-4, 3e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2, 5e-2, 1e-1):
        h = rd.hopf(RIG, at=p_h, fd_step=fd, **fixed)
        print(f"    fd_step {fd:6g}: l1 = {h.l1:+.5f} ± {h.l1_error:.1e} ({h.type}), "
              f"κ = {h.amplitude_coefficient[0] * 1e12:.4g} µm²/Pa, cycles {h.cycle_side}")
    h = rd.hopf(RIG, at=p_h, fd_step=1e-3, **fixed)
    kap = float(h.amplitude_coefficient[0])
    prev = None
    for d in (0.003, 0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 12.0, 25.0, 100.0):
        o = rd.periodic_orbit(RIG, 50.0, p_h - d, -1.85e-3, method="harmonic_balance",
                              harmonics=8, start_amplitude_c=np.sqrt(kap * d) / 3e-4,
                              tol=1e-10, floquet="flow", rtol=1e-9, n_out=1001)
        if not o.ok:
            print(f"    d = {d:g} Pa: {o.status} {o.message}")
            continue
        a = amp(o)
        sl = (f", slope from the previous / κ {(a * a - prev[1] ** 2) / (d - prev[0]) / kap:.4f}"
              if prev else "")
        print(f"    d = {d:g} Pa: A = {a * 1e6:.5f} µm, A²/(κ d) = {a * a / (kap * d):.4f}{sl}, "
              f"|μ_c| = {abs(o.critical_multiplier):.7f} ({'stable' if o.stable else 'unstable'})")
        prev = (d, a)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--branch", action="store_true", help="(d) the branch down to the Hopf point")
    ap.add_argument("--branch-up", action="store_true", help="(d) the branch up from 99.4 Hz")
    ap.add_argument("--transients", action="store_true", help="(e) the transients")
    ap.add_argument("--pc", action="store_true",
                    help="only the Hopf point over p_c at a_y = -1.85 mm, 50 Hz")
    ap.add_argument("--long", type=float, default=400.0,
                    help="(e) seconds of the transient from the displaced equilibrium")
    a = ap.parse_args()
    b = RIG.bearings[0]
    if a.pc:
        print(f"paper rig, film {b.n_circ} x {b.n_axial}")
        pc_point()
        return
    print(f"paper rig, film {b.n_circ} x {b.n_axial}, p_c = {PC / 1e6:g} MPa, a_y = 0")
    p_h, h = hopf_point()
    near_cycles(h, (5e-5, 1e-4, 2e-4, 3e-4))
    cycles_at((98.85, 98.88, 98.95, 98.98, 99.1, 99.4, 99.7, 100.5))
    if a.branch:
        branch(-1)
    if a.branch_up:
        branch(+1)
    if a.transients:
        transients(a.long)


if __name__ == "__main__":
    main()
