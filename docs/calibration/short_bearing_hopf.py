"""A rigid rotor on two short (Ocvirk) bearings: the Hopf type over the static eccentricity /
Sommerfeld number (issue 19, "what it must show" item 3; docs/nonlinear.md).

Model (tests/short_bearing_hopf_reference.py): a 20.0 kg rigid symmetric rotor (E = 1000 ×
steel) on two identical plain bearings D = 50 mm, L/D = 0.25, c = 50 µm with the core's
short-bearing film (``FixedGeometryBearing(kind="partial_arc", arc_deg=360,
film_model="short")``), π film (``cavitation="gumbel"``); the viscosity μ is varied so that
the Hopf speed (``rotordyn.hopf`` over the speed) sits at different static eccentricities.

Against an independent computation (no rotordyn code): the closed-form short-bearing π-film
force of the journal, its exact Taylor coefficients (Cauchy integrals of the analytic
continuation) and Kuznetsov's l1 for the cylindrical whirl of the rigid rotor. Compared:
the Hopf speed, the whirl frequency, the type, and the normalisation-free amplitude
coefficient κ (journal semi-major² per Hz from the Hopf speed); then cycles shot from the
leading order (``hopf_cycle``) at a few points, the viscosity / eccentricity / Sommerfeld
number where the type changes, and the fit-span and film-grid dependence of rotordyn's l1.

Run:  .venv/bin/python docs/calibration/short_bearing_hopf.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests"))
import rotordyn as rd  # noqa: E402
from rotordyn.analysis.hopf import hopf_cycle  # noqa: E402
from short_bearing_hopf_reference import reference, rotor_mass_kg, rotordyn_model  # noqa: E402

BOUNDS = (150.0, 260.0)
N_AXIAL = 8


def shoot(mu, h, distances, args):
    """Cycles shot from the leading order at ``distances`` (Hz) from the Hopf point ``h``:
    amplitude, A²/d against κ, critical Floquet multiplier."""
    sys_ = rotordyn_model(mu, n_circ=args.n_circ, n_axial=N_AXIAL)
    sgn = 1 if h.cycle_side == "above" else -1
    for d in distances:
        t = time.process_time()
        o = hopf_cycle(sys_, h, h.value + sgn * d)
        if not o.ok:
            print(f"  mu {mu}: {d} Hz to the {h.cycle_side}: {o.status} {o.message}")
            continue
        A = o.amplitude(0)
        crit = abs(o.multipliers[o.critical_index])
        print(f"  mu {mu}: {d:4.2f} Hz {h.cycle_side}: amplitude {A * 1e6:.4f} µm, "
              f"A²/d = {A * A / d:.4e} m²/Hz against kappa {h.amplitude_coefficient[0]:.4e} "
              f"({A * A / d / h.amplitude_coefficient[0]:.4f}); critical |multiplier| "
              f"{crit:.6f}, {'stable' if o.stable else 'unstable'} "
              f"(CPU {time.process_time() - t:.1f} s)", flush=True)


def grid_study():
    """l1 of rotordyn at the reference's Hopf point (μ = 0.02) against the fit half-width
    and the film grid, the exact value in rotordyn's normalisation, and grid_check."""
    ref = reference(0.02, N_AXIAL)
    s_h = ref.hopf_speed(*BOUNDS)
    L = ref.lyapunov(s_h)
    print(f"\nl1 of rotordyn at mu = 0.02, {s_h:.4f} Hz, against the fit half-width "
          f"(scaled) and the film grid:")
    exact = None
    for nc in (90, 360, 1440):
        s_ = rotordyn_model(0.02, n_circ=nc, n_axial=N_AXIAL)
        line = []
        for fd in (0.0025, 0.005, 0.01, 0.02, 0.04, 0.08, 0.16):
            hh = rd.hopf(s_, "speed_hz", at=s_h, fd_step=fd)
            line.append(f"{fd}: {hh.l1:+.4f}")
            if exact is None:
                exact = hh.l1 * hh.amplitude_coefficient[0] / L["kappa"]
        print(f"  n_circ {nc:4d}: " + ", ".join(line), flush=True)
    print(f"  exact (reference, in rotordyn's normalisation l1·kappa_rd/kappa_ref): "
          f"{exact:+.4f}")
    print("grid_check (l1 again on every film grid refined twice):")
    for nc, fd in ((90, 0.005), (360, 0.05), (720, 0.05), (1440, 0.1)):
        s_ = rotordyn_model(0.02, n_circ=nc, n_axial=N_AXIAL)
        t = time.process_time()
        h0 = rd.hopf(s_, "speed_hz", at=s_h, fd_step=fd)
        t1 = time.process_time()
        h = rd.hopf(s_, "speed_hz", at=s_h, fd_step=fd, grid_check=True)
        t2 = time.process_time()
        print(f"  {nc:4d} nodes, ±{fd:g}: old l1 {h0.l1:+.4f} ± {h0.l1_error:.4f} {h0.type}; "
              f"refined {h.l1_refined:+.4f}, error {h.l1_error:.4f} -> {h.type} "
              f"(CPU {t1 - t:.1f} s without, {t2 - t1:.1f} s with)", flush=True)
    s_ = rotordyn_model(0.02, n_circ=90, n_axial=32, cavitation="none")
    h0 = rd.hopf(s_, "speed_hz", at=s_h)
    h = rd.hopf(s_, "speed_hz", at=s_h, grid_check=True)
    print(f"  smooth film (cavitation none, 90 x 32): l1 {h0.l1:+.8f}, with grid_check "
          f"{h.l1:+.8f}, refined {h.l1_refined:+.8f}, {h.type}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer viscosities, no grid study")
    ap.add_argument("--n-circ", type=int, default=1440)
    ap.add_argument("--fd-step", type=float, default=0.1)
    ap.add_argument("--grid-only", action="store_true", help="only the span / grid study")
    ap.add_argument("--cycles-only", action="store_true",
                    help="only the shot cycles at mu = 0.02 and 0.05, 0.2 Hz from the point")
    args = ap.parse_args()
    t0 = time.process_time()
    if args.cycles_only:
        for mu in (0.02, 0.05):
            h = rd.hopf(rotordyn_model(mu, n_circ=args.n_circ, n_axial=N_AXIAL), "speed_hz",
                        bounds=BOUNDS, fd_step=args.fd_step)
            shoot(mu, h, (0.2,), args)
        print(f"\nCPU {time.process_time() - t0:.1f} s")
        return
    if args.grid_only:
        grid_study()
        print(f"\nCPU {time.process_time() - t0:.1f} s")
        return
    mus = [0.01, 0.035, 0.06] if args.quick else [0.005, 0.01, 0.02, 0.03, 0.035, 0.04,
                                                     0.05, 0.08]
    print(f"rigid rotor {rotor_mass_kg():.3f} kg on two short bearings; film grid "
          f"{args.n_circ} x {N_AXIAL} (short model), fd_step {args.fd_step}")
    print("   mu     eps0   Sommerfeld | Hopf speed Hz: ref     rotordyn   | whirl/speed "
          "| l1 ref      l1 rotordyn (± err)   | kappa ref   kappa rd   ratio | type ref / rd")
    rows = {}
    for mu in mus:
        ref = reference(mu, N_AXIAL)
        sH = ref.hopf_speed(*BOUNDS)
        L = ref.lyapunov(sH)
        sys_ = rotordyn_model(mu, n_circ=args.n_circ, n_axial=N_AXIAL)
        h = rd.hopf(sys_, "speed_hz", bounds=BOUNDS, fd_step=args.fd_step)
        rows[mu] = (ref, sH, L, sys_, h)
        tref = "supercritical" if L["l1"] < 0 else "subcritical"
        print(f"  {mu:6.3f}  {L['eps0']:.4f}  {L['sommerfeld']:8.4f} | {sH:12.6f} "
              f"{h.value:12.6f} | {L['omega'] / 2 / math.pi / sH:.5f} "
              f"{h.whirl_frequency_hz / h.value:.5f} | {L['l1']:+.5f}  {h.l1:+.5f} ± "
              f"{h.l1_error:.5f} | {L['kappa']:.4e} {h.amplitude_coefficient[0]:.4e} "
              f"{h.amplitude_coefficient[0] / L['kappa']:.4f} | {tref} / {h.type}")

    # where the type changes: l1(μ) = 0 of the reference
    def l1_of(mu):
        r = reference(mu, N_AXIAL)
        return r.lyapunov(r.hopf_speed(*BOUNDS))["l1"]
    lo, hi = (0.03, 0.045)
    mu_c = brentq(l1_of, lo, hi, xtol=1e-7)
    r = reference(mu_c, N_AXIAL)
    sc = r.hopf_speed(*BOUNDS)
    Lc = r.lyapunov(sc)
    print(f"\ntype change (reference, l1 = 0): mu = {mu_c:.6f} Pa s, Hopf speed {sc:.4f} Hz, "
          f"eps0 = {Lc['eps0']:.4f}, Sommerfeld S = {Lc['sommerfeld']:.4f}; supercritical "
          f"for eps0 above, subcritical below")
    for mu in (0.03, 0.04):
        h = rd.hopf(rotordyn_model(mu, n_circ=args.n_circ, n_axial=N_AXIAL), "speed_hz",
                    bounds=BOUNDS, fd_step=args.fd_step)
        print(f"  rotordyn at mu = {mu}: l1 = {h.l1:+.5f} ± {h.l1_error:.5f}, {h.type}")

    # cycles shot from the leading order: A² / distance against κ
    print("\ncycles shot from the leading order (hopf_cycle, rtol 1e-8):")
    for mu in ([0.01, 0.05] if args.quick else [0.01, 0.02, 0.05, 0.08]):
        ref, sH, L, sys_, h = rows.get(mu) or (None, None, None, rotordyn_model(
            mu, n_circ=args.n_circ, n_axial=N_AXIAL), None)
        if h is None:
            h = rd.hopf(sys_, "speed_hz", bounds=BOUNDS, fd_step=args.fd_step)
        shoot(mu, h, (0.05, 0.2), args)

    if not args.quick:
        grid_study()
    print(f"\nCPU {time.process_time() - t0:.1f} s")


if __name__ == "__main__":
    main()
