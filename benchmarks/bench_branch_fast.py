"""Limit-cycle branches by the corrector modes against the first (``exact``) in one run: the
paper rig's 50-point branch (issue 19's goal: ≤ 30 s CPU on one core) and, ``--model
compressor``, the oil-whip branch of the compressor on plain bearings through its folds
(docs/nonlinear.md prints these numbers).

Rig (``rd.models.paper_rig()``) at 50 Hz, a_y = −1.85 mm. Start: the stable cycle at
p_c = 0.05 MPa (paper Fig. 11) from a 0.6 s transient (journal disturbed by 0.1 c upwards)
and :func:`rotordyn.periodic_orbit` (rtol 1e-6, tol 1e-4). Branch: p_c upwards towards the
Hopf point (bounds 0–0.12 MPa) at rtol 1e-6, tol 1e-4 with a **constant** arclength step
(ds = ds_max, default 0.0125: ≈ 50 points from 0.05 MPa to the Hopf point at 0.05706 MPa —
the resolution at which the amplitude's √(p_H − p) shape near the Hopf point is drawn; the
step control of the 6-point branch of bench_continuation.py would reach the Hopf point in
6 points). A constant step gives every mode the same predictor sequence, so the points
correspond one to one.

Compressor (``--model compressor``: tests/data/models/compressor_plain.toml on a 36 × 6 film
grid, as bench_continuation.py --whip): the stable whip cycle at 130 Hz from a 0.4 s transient
(journal disturbed by 0.6 c), continued **down in speed** (bounds 100–140 Hz) at rtol 1e-6,
tol 1e-4 with a constant step (default ds 0.1, 30 points): past the fold near 121.8 Hz onto
the unstable cycles and back past the fold near 126.6 Hz. The speed has no parameter
sensitivity: ``fast`` keeps the central-difference ∂R/∂p there (Broyden and the screening
remain).

Harmonic balance (mode ``hb`` or ``hb:H``: ``rd.continuation(..., method="harmonic_balance",
harmonics=H)``, default H = 8, residual tol ``--hb-tol`` 1e-6, its own constant step
``--hb-ds``): its arclength measures the Fourier coefficients (not the start state), so its
points are not the shooting's; it is compared with the baseline **at its own parameter
values** by interpolating the baseline (cubic splines of A², T and |μ_c| in the parameter,
possible where the baseline does not fold), with the interpolation's own error estimated by
interpolating the baseline's odd points from its even ones. Each point's Floquet route
(samples, or the sensitivity flow within ``floquet_margin`` of the unit circle) is printed.

``--repeat N`` runs the modes N times interleaved (exact, fast, exact, fast, …) and prints the
median CPU and wall of each and the median CPU ratio of every mode to the first.

Printed per mode: CPU and wall of the branch (one thread), the corrector statistics, and
against the baseline (the first mode, ``exact`` = the default, in the same run):
the largest point distance (state in the length scale, period relative, p_c in Pa), the
largest difference of |μ_c|, equal stability flags and critical types, the same
bifurcations (kinds, parameters). Load printed before and after each mode.

    python benchmarks/bench_branch_fast.py                       # exact, broyden, fast
    python benchmarks/bench_branch_fast.py --model compressor --modes exact fast --repeat 3
    python benchmarks/bench_branch_fast.py --modes sensitivities fast --ds 0.05
    python benchmarks/bench_branch_fast.py --modes sensitivities fast:1e-4:0   # never re-run
    python benchmarks/bench_branch_fast.py --modes exact fast hb --quiet   # HB beside fast
    python benchmarks/bench_branch_fast.py --model compressor --quiet --repeat 3 \
        --modes hb:8:flow hb:8:samples hb:8:hill   # the Floquet routes of one HB branch

Mode ``hb:H:ROUTE`` sets the branch's ``floquet`` (samples, hill or flow). HB modes of equal H
have the same points (the route does not steer the corrector): against an ``hb:H:flow`` mode
every point's screening |mu_c| (the samples' or Hill's) and its trivial error are printed
beside the flow's, with the route taken and the stability flags.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, print_load  # noqa: E402

import rotordyn as rd  # noqa: E402

SPEED_HZ, PC_PA, AY_M, C_M = 50.0, 0.05e6, -1.85e-3, 3e-4
KW = {"rtol": 1e-6, "tol": 1e-4}
MODELS = Path(__file__).parent.parent / "tests" / "data" / "models"


def rig_case():
    """(system, start cycle, continuation arguments, unit name, unit) of the rig's branch."""
    rig = rd.models.paper_rig()
    tr = rd.transient(rig, 0.6, SPEED_HZ, PC_PA, AY_M, disturbance_m=(0.0, 0.1 * C_M),
                      n_out=6001)
    cyc = rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=tr, **KW)
    return rig, cyc, dict(vary="chamber_pressure_pa", bounds=(0.0, 0.12e6)), "Pa", 1.0


def compressor_case():
    """The compressor's whip cycle at 130 Hz and its branch down in speed."""
    import dataclasses

    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                              for b in s.bearings))
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    cyc = rd.periodic_orbit(s, 130.0, start=tr, **KW)
    return s, cyc, dict(vary="speed_hz", bounds=(100.0, 140.0), direction=-1), "Hz", 1.0


def compare(base, br, unit: str) -> str:
    """Point-by-point comparison of two branches with the same predictor sequence."""
    n = min(len(base), len(br))
    lines = [f"points {len(br)} (baseline {len(base)})"]
    if n == 0:
        return lines[0]
    dx = 0.0
    for a, b in zip(base.orbits[:n], br.orbits[:n]):
        L = a.length_scale_m
        dx = max(dx, float(np.max(np.abs(a.r[0] - b.r[0]))) / L)
    c = base.clearance_m[0]
    dT = float(np.max(np.abs(base.period_s[:n] - br.period_s[:n]) / base.period_s[:n]))
    dp = float(np.max(np.abs(base.parameter[:n] - br.parameter[:n])))
    dA = float(np.max(np.abs(base.amplitude_m[:n, 0] - br.amplitude_m[:n, 0])) / c)
    dmu = float(np.max(np.abs(base.max_multiplier[:n] - br.max_multiplier[:n])))
    same_stab = bool(np.array_equal(base.stable[:n], br.stable[:n]))
    same_type = base.critical_type[:n] == br.critical_type[:n]
    bk = [(b["kind"], float(f"{b['parameter']:.6g}")) for b in base.bifurcations]
    fk = [(b["kind"], float(f"{b['parameter']:.6g}")) for b in br.bifurcations]
    lines.append(f"max |dr0|/L {dx:.2e}, |dA|/c {dA:.2e}, |dT|/T {dT:.2e}, |dp| {dp:.3g} "
                 f"{unit}, max ||mu_c| diff| {dmu:.2e}")
    lines.append(f"stability flags equal: {same_stab}; critical types equal: {same_type}")
    lines.append(f"bifurcations: {fk} (baseline {bk})")
    if [k for k, _ in bk] == [k for k, _ in fk]:
        d = [abs(a[1] - b[1]) for a, b in zip(bk, fk)]
        lines.append("bifurcation shifts: " + ", ".join(f"{x:.3g} {unit}" for x in d))
    return "\n  ".join(lines)


def compare_interp(base, br, unit: str) -> str:
    """The branch ``br`` against the baseline at br's own parameter values: the baseline
    interpolated by cubic splines of A², T and |μ_c| in the parameter over its monotonic
    part, and (near a Hopf point A(p) is steep, so a small shift along the branch is a large
    change of A at fixed p) the parameter at br's amplitude (a spline of p in A). The
    interpolation's own error is estimated from the baseline's odd points interpolated from
    its even ones. Differences are split at the baseline's |μ_c| = 0.99: nearer the unit
    circle a shooting point at tol is uncertain by up to tol/(1 − |μ_c|) along the branch."""
    from scipy.interpolate import CubicSpline

    p = np.asarray(base.parameter, float)
    d = np.sign(p[-1] - p[0])
    k = 1
    while k < len(p) and (p[k] - p[k - 1]) * d > 0:
        k += 1
    if k < 4:
        return "not compared by interpolation: the baseline is not monotonic in p"
    c = base.clearance_m[0]
    idx = np.arange(k) if d > 0 else np.arange(k)[::-1]
    ps, A, T, mu = (p[idx], base.amplitude_m[idx, 0], base.period_s[idx],
                    base.max_multiplier[idx])

    def splines(j):
        return (CubicSpline(ps[j], A[j] ** 2), CubicSpline(ps[j], T[j]),
                CubicSpline(ps[j], mu[j]))

    fA, fT, fm = splines(np.arange(len(ps)))
    q = np.asarray(br.parameter, float)
    inside = (q >= ps[0]) & (q <= ps[-1])
    if not inside.any():
        return "no point inside the baseline's parameter range"
    qi, Ai = q[inside], br.amplitude_m[inside, 0]
    dA = np.abs(np.sqrt(np.maximum(fA(qi), 0)) - Ai) / c
    dT = np.abs(fT(qi) - br.period_s[inside]) / br.period_s[inside]
    dm = np.abs(fm(qi) - br.max_multiplier[inside])
    far = fm(qi) < 0.99
    ev, od = np.arange(0, len(ps), 2), np.arange(1, len(ps) - 1, 2)
    gA, gT, gm = splines(ev)
    eA = np.abs(np.sqrt(np.maximum(gA(ps[od]), 0)) - A[od]) / c
    eT = np.abs(gT(ps[od]) - T[od]) / T[od]
    em = np.abs(gm(ps[od]) - mu[od])
    o = np.argsort(A)  # p as a function of the amplitude (monotonic on this branch)
    fp = CubicSpline(A[o], ps[o])
    inA = (br.amplitude_m[:, 0] >= A.min()) & (br.amplitude_m[:, 0] <= A.max())
    dpA = np.abs(fp(br.amplitude_m[inA, 0]) - q[inA])
    big = br.amplitude_m[inA, 0] > 0.1 * c
    nearest = np.abs(ps[None, :] - qi[:, None]).argmin(1)
    same_stab = bool(np.array_equal(base.stable[idx][nearest], br.stable[inside]))

    def mx(x, m):
        return f"{x[m].max():.2e}" if m.any() else "-"

    lines = [f"points {len(br)} ({int(inside.sum())} inside the baseline's monotonic range "
             f"{ps[0]:.6g}..{ps[-1]:.6g} {unit}; baseline {len(base)}, {k} monotonic)",
             f"at equal parameter values, where the baseline's |mu_c| < 0.99 ({int(far.sum())} "
             f"points): max |dA|/c {mx(dA, far)}, |dT|/T {mx(dT, far)}, ||mu_c| diff| "
             f"{mx(dm, far)}",
             f"  and nearer 1 ({int((~far).sum())} points): |dA|/c {mx(dA, ~far)}, |dT|/T "
             f"{mx(dT, ~far)}, ||mu_c| diff| {mx(dm, ~far)}",
             f"at equal amplitude: max |dp| {dpA.max():.3g} {unit} ({int(inA.sum())} points; "
             f"{mx(dpA, big)} {unit} where A > 0.1 c)",
             f"interpolation error of the baseline (odd points from the even ones): "
             f"|dA|/c {eA.max():.2e}, |dT|/T {eT.max():.2e}, |mu_c| {em.max():.2e}",
             f"stability flags equal to the nearest baseline point's: {same_stab}",
             "bifurcations: " + str([(b["kind"], float(f"{b['parameter']:.6g}"))
                                     for b in br.bifurcations]) + " (baseline " +
             str([(b["kind"], float(f"{b['parameter']:.6g}")) for b in base.bifurcations])
             + ")"]
    if k < len(p):
        lines.append(f"baseline parameter after its monotonic part: "
                     f"{', '.join(f'{x:.7g}' for x in p[k - 2:])}")
    return "\n  ".join(lines)


def reshoot(system, base, br, count: int, vary: str, rig: bool) -> None:
    """``count`` points of the branch ``br`` (spread over it) re-shot at their own parameter
    by ``rd.periodic_orbit`` at tight tolerances (rtol 1e-8, tol 1e-7, monodromy 1e-6) from
    their state: the error of br's point and of the baseline interpolated there (its spline
    of A² in p, as in :func:`compare_interp`) against that reference."""
    from scipy.interpolate import CubicSpline

    p = np.asarray(base.parameter, float)
    k = 1
    while k < len(p) and p[k] > p[k - 1]:
        k += 1
    fA = CubicSpline(p[:k], base.amplitude_m[:k, 0] ** 2)
    fT = CubicSpline(p[:k], base.period_s[:k])
    c = base.clearance_m[0]
    print(f"\nreshoot: {count} points re-shot at rtol 1e-8, tol 1e-7 (the reference); errors "
          "of the branch point and of the baseline interpolated at its parameter")
    for i in np.unique(np.linspace(0, len(br) - 1, count).astype(int)):
        o = br.orbits[i]
        q = float(br.parameter[i])
        op = {"speed_hz": o.speed_hz, "chamber_pressure_pa": o.chamber_pressure_pa,
              "config_ay_m": AY_M if rig else None} | {vary: q}
        r = rd.periodic_orbit(system, op["speed_hz"], op["chamber_pressure_pa"],
                              op["config_ay_m"], start=(o.r[0], o.v[0]), period_s=o.period_s,
                              rtol=1e-8, tol=1e-7, sensitivity_rtol=1e-6)
        if not r.ok:
            print(f"  point {i} ({vary} {q:.6g}): reference failed: {r.message}")
            continue
        a = r.amplitude()
        line = (f"  point {i} ({vary} {q:.6g}, A/c {a / c:.4f}, |mu_c| "
                f"{abs(r.critical_multiplier):.5f}): branch |dA|/c {abs(o.amplitude() - a) / c:.1e}"
                f", |dT|/T {abs(o.period_s - r.period_s) / r.period_s:.1e}, ||mu_c| diff| "
                f"{abs(abs(o.critical_multiplier) - abs(r.critical_multiplier)):.1e}")
        if p[0] <= q <= p[k - 1]:
            line += (f"; baseline |dA|/c {abs(np.sqrt(fA(q)) - a) / c:.1e}, |dT|/T "
                     f"{abs(fT(q) - r.period_s) / r.period_s:.1e}")
        print(line)


def run_mode(mode: str, system, cyc, ckw: dict, ds: float, npts: int, args):
    """One branch by ``mode``: a shooting corrector (exact, broyden, fast[:SCREEN:MARGIN]) or
    harmonic balance (hb[:H])."""
    name, *extra = mode.split(":")
    if name == "hb":
        h = int(extra[0]) if extra else 8
        fl = {"floquet": extra[1]} if len(extra) > 1 else {}
        return rd.continuation(system, start=cyc, ds=args.hb_ds, ds_max=args.hb_ds,
                               max_points=npts, method="harmonic_balance", harmonics=h,
                               **ckw, **fl, rtol=KW["rtol"], tol=args.hb_tol)
    sk = dict(zip(("screen_rtol", "screen_margin"), map(float, extra)))
    return rd.continuation(system, start=cyc, ds=ds, ds_max=ds, max_points=npts,
                           newton=name, **ckw, **sk, **KW)


def screen(o) -> float:
    """|mu_c| of a harmonic-balance point's screening route (Hill's or the samples')."""
    s = o.stats
    return s.get("floquet_hill_modulus", s.get("floquet_samples_modulus", float("nan")))


def compare_routes(runs: dict) -> None:
    """HB modes hb:H:ROUTE of equal H have the same points (the Floquet route does not steer
    the corrector): each point's |mu_c| of every route against hb:H:flow's, with the screen's
    trivial-multiplier error and the flows each route took."""
    for mode, ref in runs.items():
        name, *extra = mode.split(":")
        if len(extra) < 2 or extra[1] != "flow":
            continue
        for other, br in runs.items():
            if other == mode or other.split(":")[1:2] != extra[:1] or len(br) != len(ref):
                continue
            print(f"\n[{other}] against [{mode}] point by point (same points):")
            worst = 0.0
            for i, (o, r) in enumerate(zip(br.orbits, ref.orbits)):
                s = o.stats
                key = "hill" if "floquet_hill_modulus" in s else "samples"
                mu, et = s[f"floquet_{key}_modulus"], s[f"floquet_{key}_trivial_error"]
                d = mu - abs(r.critical_multiplier)
                worst = max(worst, abs(d))
                print(f"  {i:3d} p {br.parameter[i]:.6g}: flow |mu_c| "
                      f"{abs(r.critical_multiplier):.5f}, {key} {mu:.5f} ({d:+.1e}), trivial "
                      f"error {et:.1e}, route {s['floquet']}, stable {bool(br.stable[i])} "
                      f"(flow: {bool(ref.stable[i])})")
            print(f"  largest |d|mu_c|| {worst:.2e}; flows {br.stats['flow_rechecks']} of "
                  f"{len(br)}; same stability flags {bool(np.array_equal(br.stable, ref.stable))}")


def recheck(system, br, vary: str, band: float, rig: bool) -> None:
    """|mu_c| of screened points near the unit circle at both tolerances, same state."""
    print(f"\nrecheck: screened points with ||mu_c| - 1| < {band:g}, re-shot from their state")
    for i, o in enumerate(br.orbits):
        if o.stats["monodromy_rtol"] == KW["rtol"] or abs(br.max_multiplier[i] - 1) >= band:
            continue
        p = float(br.parameter[i])
        op = {"speed_hz": o.speed_hz, "chamber_pressure_pa": o.chamber_pressure_pa,
              "config_ay_m": AY_M if rig else None} | {vary: p}
        mu = {}
        for sr in (1e-4, KW["rtol"]):
            r = rd.periodic_orbit(system, op["speed_hz"], op["chamber_pressure_pa"],
                                  op["config_ay_m"], start=(o.r[0], o.v[0]),
                                  period_s=o.period_s, sensitivity_rtol=sr, **KW)
            mu[sr] = (abs(r.critical_multiplier) if r.ok else float("nan"), r.residuals[0])
        print(f"  point {i} ({vary} {p:.6g}): branch |mu_c| {br.max_multiplier[i]:.5f} "
              f"(screened); re-shot |mu_c| {mu[1e-4][0]:.5f} at 1e-4, {mu[KW['rtol']][0]:.5f} "
              f"at {KW['rtol']:g} (first residual {mu[KW['rtol']][1]:.2e})")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", choices=("rig", "compressor"), default="rig",
                    help="rig: p_c branch at 50 Hz; compressor: the whip branch over the speed")
    ap.add_argument("--ds", type=float, default=None,
                    help="constant step ds = ds_max (default 0.0125 rig, 0.1 compressor)")
    ap.add_argument("--max-points", type=int, default=None,
                    help="points (default 50 rig, 30 compressor)")
    ap.add_argument("--modes", nargs="+", default=["exact", "broyden", "fast"],
                    help="newton modes; fast:SCREEN_RTOL:SCREEN_MARGIN sets the screening")
    ap.add_argument("--repeat", type=int, default=1, help="interleaved repeats of the modes")
    ap.add_argument("--hb-ds", type=float, default=None,
                    help="mode hb: its constant step (default 0.0155 rig: 50 points end at the same 12 µm as the shooting modes' 50; 0.1 compressor)")
    ap.add_argument("--hb-tol", type=float, default=1e-6,
                    help="mode hb: the scaled residual tolerance (default 1e-6)")
    ap.add_argument("--reshoot", type=int, default=0, metavar="K",
                    help="after the runs: K points of the last hb branch re-shot at tight "
                         "tolerances, the error of the hb points and of the baseline there")
    ap.add_argument("--quiet", action="store_true", help="no per-point table")
    ap.add_argument("--recheck", type=float, default=None, metavar="BAND",
                    help="after the runs: every point of the last branch with a screened "
                         "monodromy and ||mu_c| - 1| < BAND re-shot from its own state by "
                         "rd.periodic_orbit at sensitivity_rtol 1e-4 and at rtol (the "
                         "screening's error at the same point)")
    args = ap.parse_args()
    rig = args.model == "rig"
    ds = args.ds if args.ds is not None else (0.0125 if rig else 0.1)
    npts = args.max_points if args.max_points is not None else (50 if rig else 30)
    if args.hb_ds is None:
        args.hb_ds = 0.0155 if rig else 0.1
    what = ("rig limit-cycle branch over p_c, 50 Hz, a_y = -1.85 mm" if rig else
            "compressor on plain bearings (36 x 6), whip branch down in speed from 130 Hz")
    header(f"bench_branch_fast: {what}, ds = ds_max = {ds}, max_points {npts}, "
           f"repeat {args.repeat}")
    w0, c0 = time.perf_counter(), time.process_time()
    system, cyc, ckw, unit, to_unit = rig_case() if rig else compressor_case()
    print(f"start: {cyc} ({time.perf_counter() - w0:.1f} s wall, "
          f"{time.process_time() - c0:.1f} s CPU)")
    base = last_hb = None
    hb_runs = {}
    times = {m: ([], []) for m in args.modes}
    for rep in range(args.repeat):
        for mode in args.modes:
            print_load(f"before {mode} (repeat {rep + 1})")
            w0, c0 = time.perf_counter(), time.process_time()
            br = run_mode(mode, system, cyc, ckw, ds, npts, args)
            hb = mode.split(":")[0] == "hb"
            if hb:
                last_hb = br
            wall, cpu = time.perf_counter() - w0, time.process_time() - c0
            times[mode][0].append(cpu)
            times[mode][1].append(wall)
            print(f"\n[{mode}] {br}")
            if not args.quiet and rep == 0:
                print(f"{ckw['vary']:>20} {'amplitude µm':>13} {'period ms':>10} "
                      f"{'|mu_c|':>8} {'dp/ds':>8} {'type':>15} stable "
                      + ("floquet (|mu_c| screen)" if hb else "monodromy_rtol"))
                for i in range(len(br)):
                    print(f"{br.parameter[i] / to_unit:20.6f} "
                          f"{br.amplitude_m[i, 0] * 1e6:13.3f} "
                          f"{br.period_s[i] * 1e3:10.5f} {br.max_multiplier[i]:8.5f} "
                          f"{br.tangent_p[i]:+8.4f} {br.critical_type[i]:>15} "
                          f"{str(bool(br.stable[i])):>6} " + (
                              f"{br.orbits[i].stats['floquet']} ({screen(br.orbits[i]):.5f})"
                              if hb
                              else f"{br.orbits[i].stats['monodromy_rtol']:g}"))
            for b in br.bifurcations:
                print(f"bifurcation: {b['kind']} at {ckw['vary']} = {b['parameter']:.6g}")
            print(f"stop: {br.stop} {br.message}; {br.stats}")
            print(f"[{mode}] {len(br)} points: {wall:.2f} s wall, {cpu:.2f} s CPU "
                  f"({cpu / max(len(br), 1):.3f} s CPU per point)")
            if hb and rep == 0:
                hb_runs[mode] = br
            if base is None:
                base = br
            elif hb and args.modes[0].split(":")[:2] == mode.split(":")[:2]:
                pass  # an HB baseline of the same H: the same points, compare_routes below
            elif hb:
                print(f"[{mode}] against [{args.modes[0]}]:\n  "
                      f"{compare_interp(base, br, unit)}")
            else:
                print(f"[{mode}] against [{args.modes[0]}]:\n  {compare(base, br, unit)}")
            if base is not br and not hb:
                n = min(len(base), len(br))
                d = np.abs(base.max_multiplier[:n] - br.max_multiplier[:n])
                print("  ||mu_c| diff| per point (|mu_c| of the baseline): " + ", ".join(
                    f"{m:.4f}:{x:.1e}" for m, x in zip(base.max_multiplier[:n], d)))
            print_load(f"after {mode} (repeat {rep + 1})")
    compare_routes(hb_runs)
    if args.recheck is not None:
        recheck(system, br, ckw["vary"], args.recheck, rig)
    if args.reshoot:
        reshoot(system, base, last_hb, args.reshoot, ckw["vary"], rig)
    print("\nsummary (median over the repeats, one thread):")
    ref = times[args.modes[0]][0]
    for mode, (cpus, walls) in times.items():
        ratios = [c / r for c, r in zip(cpus, ref)]
        print(f"  [{mode}] CPU {statistics.median(cpus):.2f} s {[round(c, 2) for c in cpus]}, "
              f"wall {statistics.median(walls):.2f} s {[round(w, 2) for w in walls]}; CPU / "
              f"[{args.modes[0]}] in the same repeat: median {statistics.median(ratios):.3f} "
              f"{[round(x, 3) for x in ratios]}")
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
