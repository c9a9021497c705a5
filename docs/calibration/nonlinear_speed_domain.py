"""The paper rig in the speed domain (issue 19, "what it must show" item 2; docs/nonlinear.md):
a_y = 0, p_c of the docs' Fig. 13-14 waterfall (0.4 MPa), unbalance 2e-5 kg m at disk B.

(a) the Hopf speed and its type from ``rotordyn.hopf`` varying the speed;
(b) the nonlinear unbalance response as a continued branch of forced periodic orbits over the
    speed (``rotordyn.continuation``, vary="speed_hz"), against the linear unbalance response
    (``rotordyn.unbalance_response``, semi-major axis at the active bearing) at the branch's
    speeds, and against a slow run-up transient (``rotordyn.transient`` with a speed ramp)
    and a constant-speed transient settled at one branch speed.

The limit cycles born at the Hopf speed on the model's 72 x 16 film, their branch through
its fold and the transients that land on them: docs/calibration/rig_speed_hopf.py.

Run:  .venv/bin/python docs/calibration/nonlinear_speed_domain.py [--fine] [--no-runup]
      .venv/bin/python docs/calibration/nonlinear_speed_domain.py --cycles-only  # (a) + (a')
      .venv/bin/python docs/calibration/nonlinear_speed_domain.py --probe 100 110 112 # (e)
(a') with (a): the equilibrium branch over the speed (``rotordyn.continuation``, start
    "equilibrium") and its Hopf point, smooth or not;
(e) transients from the equilibrium disturbed upwards, no unbalance: does the whirl settle
    or grow to a rub. Default tolerances rtol 1e-8, atol 1e-12 m (``--probe-rtol``,
    ``--probe-atol``): at the transient's defaults (1e-6, 1e-9 m) a whirl of a few µm near
    the Hopf speed, whose amplitude moves by 4e-4 per period, is set by the integration
    error — on 72 x 16 at 99.4 Hz it "settled" at 1.7 µm where the cycle has 2.90 µm
    (docs/nonlinear.md).
Default: the active bearing's film on a 36 x 6 grid (as the continuation tests) so that it
runs in minutes; --fine keeps the model's 72 x 16 grid.
"""

from __future__ import annotations

import argparse
import dataclasses
import time

import numpy as np

import rotordyn as rd
from rotordyn.operation.profiles import SpeedProfile

PC = 0.4e6
UB = [(6, 2.0e-5, 0.0)]  # disk B, the docs' Fig. 13 waterfall
BEARING_STATION = 4


def rig_model(fine: bool):
    rig = rd.models.paper_rig()
    if fine:
        return rig
    b = rig.bearings[0]
    return dataclasses.replace(rig, bearings=(dataclasses.replace(b, n_circ=36, n_axial=6),)
                               + tuple(rig.bearings[1:]))


def hopf_speed(rig, hi):
    t = time.process_time()
    h = rd.hopf(rig, "speed_hz", bounds=(20.0, hi), chamber_pressure_pa=PC, config_ay_m=0.0)
    print(f"(a) Hopf in speed (p_c = {PC / 1e6:g} MPa, a_y = 0, bounds 20-{hi:g} Hz): {h!r} "
          f"[{time.process_time() - t:.1f} s CPU]")
    return h


def branch(rig, lo, hi, start_hz, ds, max_points):
    t = time.process_time()
    o = rd.periodic_orbit(rig, start_hz, PC, 0.0, kind="forced", unbalances=UB, rtol=1e-7,
                          tol=1e-5)
    print(f"(b) start: {o!r}")
    br = rd.continuation(rig, "speed_hz", (lo, hi), o, unbalances=UB, rtol=1e-7, tol=1e-5,
                         ds=ds, ds_max=max(ds, 0.3), max_points=max_points,
                         param_scale=hi - lo)
    print(f"    branch: {br!r} [{time.process_time() - t:.1f} s CPU]")
    return br


def linear(rig, speeds):
    u = rd.unbalance_response(rig, UB, np.asarray(speeds), stations=[BEARING_STATION],
                              chamber_pressure_pa=PC, config_ay_m=0.0, refine=False)
    return np.asarray(u.major_m)[:, 0]


def linear_peaks(rig):
    u = rd.unbalance_response(rig, UB, np.linspace(10.0, 120.0, 45),
                              stations=[BEARING_STATION], chamber_pressure_pa=PC,
                              config_ay_m=0.0)
    return u.peaks()


def runup(rig, lo, hi, rate):
    t = time.process_time()
    prof = SpeedProfile.ramp(lo, hi, rate)
    t_end = (hi - lo) / rate
    tr = rd.transient(rig, t_end, chamber_pressure_pa=PC, config_ay_m=0.0, unbalances=UB,
                      speed=prof, n_out=int(t_end * 32 * hi) + 1)
    print(f"(c) run-up {lo:g}->{hi:g} Hz at {rate:g} Hz/s: {tr.status}, "
          f"{time.process_time() - t:.1f} s CPU")
    return tr, prof


def runup_envelope(tr, prof, speeds):
    """Peak distance from the local mean over one revolution around each speed."""
    t = np.asarray(tr.t)
    x, y = tr.journal_x_m[:, 0], tr.journal_y_m[:, 0]
    out = []
    for s in speeds:
        k = np.abs(t - np.interp(s, prof.speed_hz, prof.t_s)) < 0.5 / s
        if k.sum() < 4:
            out.append(np.nan)
            continue
        out.append(float(np.max(np.hypot(x[k] - x[k].mean(), y[k] - y[k].mean()))))
    return np.array(out)


def _amp(x, y):
    """Largest distance from the mean over one closed period sampled without its endpoint."""
    return float(np.max(np.hypot(x - x.mean(), y - y.mean())))


def settled(rig, speed, revs):
    """Constant-speed transient from the static equilibrium against the shooting at the same
    speed; both sampled 100 times per revolution, the mean over one period without the
    repeated endpoint (PeriodicOrbitResult.amplitude counts it twice: an O(A/n_out) bias)."""
    t = time.process_time()
    tr = rd.transient(rig, revs / speed, speed, PC, 0.0, unbalances=UB,
                      n_out=int(revs * 100) + 1, rtol=1e-8, atol_m=1e-12)
    o = rd.periodic_orbit(rig, speed, PC, 0.0, kind="forced", unbalances=UB, rtol=1e-8,
                          tol=1e-6, n_out=101)
    last = slice((revs - 1) * 100, revs * 100)
    a_tr = _amp(tr.journal_x_m[last, 0], tr.journal_y_m[last, 0])
    a_o = _amp(o.journal_x_m[:-1, 0], o.journal_y_m[:-1, 0])
    shape = np.max(np.abs(tr.r[last] - o.r[:-1])) / np.max(np.abs(o.r - o.r.mean(axis=0)))
    print(f"(d) {speed:.4g} Hz: transient {revs} revolutions ({tr.status}) last-revolution "
          f"amplitude {a_tr * 1e6:.4f} um; shooting {a_o * 1e6:.4f} um; difference "
          f"{abs(a_tr / a_o - 1) * 100:.4f} %, largest sample difference {shape * 100:.4f} % "
          f"of the amplitude [{time.process_time() - t:.1f} s CPU]")
    return a_tr, o


def equilibrium_branch(rig, lo, hi):
    """(a') the equilibrium branch over the speed with its Hopf points
    (``rotordyn.continuation(..., start="equilibrium")``)."""
    t = time.process_time()
    br = rd.continuation(rig, "speed_hz", (lo, hi), start="equilibrium", chamber_pressure_pa=PC,
                         config_ay_m=0.0)
    print(f"(a') equilibrium branch: {br!r} [{time.process_time() - t:.2f} s CPU]")
    print(br.bifurcations_frame().to_string())
    return br


def probe(rig, speed, disturbance_m, t_end, rtol=1e-8, atol_m=1e-12):
    """(e) a transient from the equilibrium with the journal displaced by ``disturbance_m``
    upwards (no unbalance): the largest distance from the mean over each 4 s window, and the
    status (rub: the journal reached the bush)."""
    t = time.process_time()
    tr = rd.transient(rig, t_end, speed, PC, 0.0, disturbance_m=(0.0, disturbance_m),
                      n_out=int(t_end * 400) + 1, rtol=rtol, atol_m=atol_m)
    x, y = tr.journal_x_m[:, 0], tr.journal_y_m[:, 0]
    ts = np.asarray(tr.t)
    env = []
    for a in np.arange(0.0, t_end, 4.0):
        m = (ts >= a) & (ts < a + 4.0) & np.isfinite(x)
        env.append(f"{_amp(x[m], y[m]) * 1e6:.3g}" if m.sum() > 10 else "-")
    print(f"(e) {speed:g} Hz, disturbance {disturbance_m * 1e6:g} µm, {t_end:g} s (rtol "
          f"{rtol:g}, atol {atol_m:g} m): {tr.status}; "
          f"amplitude (µm) per 4 s: {' '.join(env)} [{time.process_time() - t:.1f} s CPU]"
          + (f"; {tr.message}" if tr.status != "ok" else ""))
    return tr


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--fine", action="store_true")
    ap.add_argument("--lo", type=float, default=20.0)
    ap.add_argument("--hi", type=float, default=110.0)
    ap.add_argument("--ds", type=float, default=0.03)
    ap.add_argument("--max-points", type=int, default=150)
    ap.add_argument("--rate", type=float, default=1.0, help="run-up rate, Hz/s")
    ap.add_argument("--no-runup", action="store_true")
    ap.add_argument("--no-hopf", action="store_true")
    ap.add_argument("--cycles-only", action="store_true",
                    help="only (a) the Hopf speed and (a') the equilibrium branch")
    ap.add_argument("--probe", type=float, nargs="*", default=None,
                    help="(e) transients at these speeds (Hz), disturbances 30 and 100 µm")
    ap.add_argument("--probe-s", type=float, default=40.0)
    ap.add_argument("--probe-disturbance", type=float, nargs="*", default=[3e-5, 1e-4],
                    help="(e) the journal's upward displacements, m")
    ap.add_argument("--probe-rtol", type=float, default=1e-8)
    ap.add_argument("--probe-atol", type=float, default=1e-12, help="(e) atol_m, m")
    a = ap.parse_args()
    rig = rig_model(a.fine)
    print(f"paper rig, film grid {rig.bearings[0].n_circ} x {rig.bearings[0].n_axial}, "
          f"p_c = {PC / 1e6:g} MPa, a_y = 0, unbalance {UB}")
    if a.probe is not None:
        for spd in a.probe:
            for d in a.probe_disturbance:
                probe(rig, spd, d, a.probe_s, a.probe_rtol, a.probe_atol)
        return
    if a.cycles_only or not a.no_hopf:
        h = hopf_speed(rig, 300.0)
        equilibrium_branch(rig, 20.0, 150.0)
    if a.cycles_only:
        return
    print("linear critical speeds (semi-major axis at the active bearing):")
    print(linear_peaks(rig).to_string())
    br = branch(rig, a.lo, a.hi, a.lo, a.ds, a.max_points)
    sp = br.parameter
    lin = linear(rig, sp)
    amp = np.array([_amp(o.journal_x_m[:-1, 0], o.journal_y_m[:-1, 0]) for o in br.orbits])
    env = None
    if not a.no_runup:
        tr, prof = runup(rig, a.lo, a.hi, a.rate)
        env = runup_envelope(tr, prof, sp)
    print(" speed_hz  nonlinear_um  linear_um  nl/lin-1_%  stable  max|mu|"
          + ("  runup_um" if env is not None else ""))
    for i, s in enumerate(sp):
        row = (f"{s:9.3f} {amp[i] * 1e6:12.4f} {lin[i] * 1e6:10.4f} "
               f"{(amp[i] / lin[i] - 1) * 100:10.3f}  {str(br.stable[i]):6s} "
               f"{br.max_multiplier[i]:7.4f}")
        if env is not None:
            row += f" {env[i] * 1e6:9.4f}"
        print(row)
    print("bifurcations:", br.bifurcations_frame().to_string() if br.bifurcations else "none")
    print("folds (dp/ds sign changes):", int(np.sum(br.tangent_p[1:] * br.tangent_p[:-1] < 0)))
    k = int(np.argmax(amp))
    print(f"branch peak: {amp[k] * 1e6:.4f} um at {sp[k]:.3f} Hz")
    settled(rig, float(sp[k]), 600)


if __name__ == "__main__":
    main()
