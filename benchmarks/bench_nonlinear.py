"""Limit cycle of the paper rig by shooting beside the same orbit reached by transient
integration (issue 19; docs/nonlinear.md prints these numbers).

Rig (``rd.models.paper_rig()``) at 50 Hz, a_y = −1.85 mm, p_c = 0.05 MPa (paper Fig. 11: a
stable limit cycle). Both routes start from the static equilibrium with the journal disturbed
by 0.1 c upwards:

* transient: CVODE (rtol 1e-6, the transient's default) for ``--t-end`` s; the settled orbit
  is the last period (period from the crossings of the journal's mean position);
* shooting: the same transient for ``--t-start`` s only, then :func:`rotordyn.periodic_orbit`
  (kind ``"autonomous"``, rtol 1e-6, tol 1e-4 of the clearance), Floquet multipliers included
  (monodromy to ``--sensitivity-rtol``, default 1e-3).

Accuracy of each against a reference cycle (shooting at rtol 1e-9, tol 1e-7): amplitude
(largest distance of the journal from the orbit's mean), period, and shape (largest distance
of the orbit's points from the reference curve, relative to the amplitude). Timing: median
of ``--repeat`` interleaved repeats, wall and CPU, one thread, load printed.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header, interleaved, pin_threads  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.analysis.periodic import period_from_transient  # noqa: E402

SPEED_HZ, PC_PA, AY_M, C_M = 50.0, 0.05e6, -1.85e-3, 3e-4
OUT_PER_S = 10_000  # transient output rate (200 per revolution, 400 per whirl period)


def start_transient(rig, t_end):
    return rd.transient(rig, t_end, SPEED_HZ, PC_PA, AY_M, disturbance_m=(0.0, 0.1 * C_M),
                        n_out=int(round(t_end * OUT_PER_S)) + 1)


def last_period(tr):
    """(x, y) of the journal over the transient's last period, and that period."""
    T = period_from_transient(tr)
    sel = tr.t >= tr.t[-1] - T
    return tr.journal_x_m[sel, 0], tr.journal_y_m[sel, 0], T


def amplitude(x, y):
    return float(np.max(np.hypot(x - x.mean(), y - y.mean())))


def shape_error(x, y, xr, yr):
    """Largest distance of the points (x, y) from the closed polyline (xr, yr), m."""
    P = np.column_stack([x, y])
    A = np.column_stack([xr, yr])
    B = np.roll(A, -1, axis=0)
    AB = B - A
    L2 = np.maximum((AB ** 2).sum(1), 1e-300)
    d = np.empty(len(P))
    for i, p in enumerate(P):
        s = np.clip(((p - A) * AB).sum(1) / L2, 0.0, 1.0)
        d[i] = np.sqrt((((A + s[:, None] * AB) - p) ** 2).sum(1).min())
    return float(d.max())


def compare(name, x, y, T, ref):
    xr, yr = ref.journal_x_m[:, 0], ref.journal_y_m[:, 0]
    a, ar = amplitude(x, y), amplitude(xr, yr)
    e_a = abs(a - ar) / ar
    e_T = abs(T - ref.period_s) / ref.period_s
    e_s = shape_error(x, y, xr, yr) / ar
    print(f"  {name:<34s} amplitude {a * 1e6:9.4f} µm ({e_a:8.1e}), period {T * 1e3:8.5f} ms "
          f"({e_T:8.1e}), shape {e_s:8.1e}")
    return max(e_a, e_T, e_s)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--t-end", type=float, default=2.0, help="transient route: simulated s")
    ap.add_argument("--t-start", type=float, default=0.6,
                    help="shooting route: simulated s of transient before shooting")
    ap.add_argument("--sensitivity-rtol", type=float, default=1e-3,
                    help="shooting route: relative tolerance of the monodromy (sensitivities)")
    ap.add_argument("--hopf", action="store_true",
                    help="instead: the first Lyapunov coefficient at one boundary point and "
                         "the projection for every vertex of the 401² Fig. 9 boundary")
    ap.add_argument("--sample", type=int, default=40,
                    help="--hopf: boundary vertices timed for the projection")
    ap.add_argument("--procs", type=int, default=0,
                    help="--hopf: also every vertex on this many processes (the measurement)")
    ap.add_argument("--hb", action="store_true",
                    help="instead: harmonic balance from the equilibrium start (H = --harmonics) "
                         "against the transient route")
    ap.add_argument("--harmonics", type=int, default=8)
    args = ap.parse_args(argv)
    if args.hb:
        return hb_bench(args)
    if args.hopf:
        return hopf_bench(args)
    print(pin_threads(1))
    header("bench_nonlinear: paper rig limit cycle, 50 Hz, a_y = -1.85 mm, p_c = 0.05 MPa")
    rig = rd.models.paper_rig()

    ref_start = start_transient(rig, args.t_end)
    ref = rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=ref_start, rtol=1e-9,
                            atol_m=1e-12, tol=1e-7, n_out=4001)
    assert ref.status == "ok", ref.message
    print(f"reference: {ref!r}")
    print(f"  residuals {np.array2string(ref.residuals, precision=2)}, trivial multiplier "
          f"{ref.trivial_multiplier:.9f}")
    print("  multipliers (largest 6): " + ", ".join(
        f"{m.real:+.5f}{m.imag:+.5f}j" for m in ref.multipliers[:6]))

    last = {}

    def transient_route():
        last["tr"] = start_transient(rig, args.t_end)

    def shooting_route():
        tr = start_transient(rig, args.t_start)
        last["po"] = rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=tr, rtol=1e-6,
                                       atol_m=1e-9, tol=1e-4, n_out=2001,
                                       sensitivity_rtol=args.sensitivity_rtol)

    def shooting_only():
        rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=last["start"], rtol=1e-6,
                          atol_m=1e-9, tol=1e-4, n_out=2001,
                          sensitivity_rtol=args.sensitivity_rtol)

    last["start"] = start_transient(rig, args.t_start)
    t = interleaved({"transient": transient_route, "shooting": shooting_route,
                     "shooting_only": shooting_only}, repeat=args.repeat)
    po = last["po"]
    assert po.status == "ok", po.message
    x, y, T = last_period(last["tr"])
    print(f"\naccuracy against the reference (relative):")
    e_tr = compare(f"transient {args.t_end:g} s, last period", x, y, T, ref)
    e_po = compare(f"transient {args.t_start:g} s + shooting", po.journal_x_m[:, 0],
                   po.journal_y_m[:, 0], po.period_s, ref)
    print(f"  shooting: {po.stats['iterations']} flows ({po.stats['steps']} steps), residuals "
          f"{np.array2string(po.residuals, precision=2)}; critical multiplier "
          f"{abs(po.critical_multiplier):.5f} (reference {abs(ref.critical_multiplier):.5f}), "
          f"trivial {po.trivial_multiplier.real:.6f}")
    st = last["tr"].stats
    print(f"  transient: {st['steps']} steps")
    print(f"\ntiming (median of {args.repeat}):")
    print(f"  transient route  {t['transient']}  [baseline]")
    print(f"  shooting route   {t['shooting']}")
    print(f"    of which shooting (from the {args.t_start:g} s transient) {t['shooting_only']}")
    print(f"  speed-up: {t['transient'].wall / t['shooting'].wall:.2f}x wall, "
          f"{t['transient'].cpu / t['shooting'].cpu:.2f}x CPU; worst relative error "
          f"transient {e_tr:.1e}, shooting {e_po:.1e}")
    footer()


def hb_bench(args):
    """Harmonic balance (from the equilibrium plus its whirl mode at 0.3 c: no transient)
    beside the 2 s transient, both against the shooting reference; interleaved repeats."""
    print(pin_threads(1))
    header("bench_nonlinear --hb: paper rig limit cycle by harmonic balance vs transient")
    rig = rd.models.paper_rig()
    ref = rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, start=start_transient(rig, args.t_end),
                            rtol=1e-9, atol_m=1e-12, tol=1e-7, n_out=4001)
    assert ref.status == "ok", ref.message
    print(f"reference: {ref!r}")
    last = {}

    def hb(h):
        return rd.periodic_orbit(rig, SPEED_HZ, PC_PA, AY_M, method="harmonic_balance",
                                 harmonics=h, tol=1e-6, n_out=2001)

    for h in (4, 8, 12, 16):
        o = hb(h)
        print(f"H = {h:2d}: {o.status}, {o.stats['evaluations']} evaluations, "
              f"|mu_c| {abs(o.critical_multiplier) if o.ok else float('nan'):.5f}, trivial "
              f"{abs(o.trivial_multiplier) if o.ok else float('nan'):.6f}")
        compare(f"harmonic balance H = {h}", o.journal_x_m[:, 0], o.journal_y_m[:, 0],
                o.period_s, ref)

    def transient_route():
        last["tr"] = start_transient(rig, args.t_end)

    def hb_route():
        last["hb"] = hb(args.harmonics)

    t = interleaved({"transient": transient_route, "hb": hb_route}, repeat=args.repeat)
    x, y, T = last_period(last["tr"])
    e_tr = compare(f"transient {args.t_end:g} s, last period", x, y, T, ref)
    o = last["hb"]
    e_hb = compare(f"harmonic balance H = {args.harmonics}", o.journal_x_m[:, 0],
                   o.journal_y_m[:, 0], o.period_s, ref)
    print(f"\ntiming (median of {args.repeat}):")
    print(f"  transient route  {t['transient']}  [baseline]")
    print(f"  harmonic balance {t['hb']}")
    print(f"  speed-up: {t['transient'].wall / t['hb'].wall:.2f}x wall, "
          f"{t['transient'].cpu / t['hb'].cpu:.2f}x CPU; worst relative error transient "
          f"{e_tr:.1e}, harmonic balance {e_hb:.1e}")
    footer()


def hopf_bench(args):
    """l1 at one Fig. 9 boundary point (rd.hopf at the threshold) beside the threshold
    search itself (baseline, same run), and the Hopf type at a sample of the vertices of the
    adaptive 401² Fig. 9 boundary (sweeps/fig9_boundary.toml), projected to every vertex on
    2 cores."""
    import tempfile
    import time

    from rotordyn.sweep.dataset import open_dataset
    from rotordyn.sweep.runner import run_sweep

    header("bench_nonlinear --hopf: first Lyapunov coefficient on the Fig. 9 boundary")
    rig = rd.models.paper_rig()
    bounds = (0.04e6, 0.08e6)
    th = rd.threshold(rig, bounds=bounds, speed_hz=SPEED_HZ, config_ay_m=AY_M)
    h = rd.hopf(rig, at=th.value, speed_hz=SPEED_HZ, config_ay_m=AY_M)
    print(f"threshold: {th!r}\nhopf: {h!r}")
    t = interleaved({
        "threshold": lambda: rd.threshold(rig, bounds=bounds, speed_hz=SPEED_HZ,
                                          config_ay_m=AY_M),
        "hopf_at": lambda: rd.hopf(rig, at=th.value, speed_hz=SPEED_HZ, config_ay_m=AY_M),
    }, repeat=args.repeat)
    print(f"  threshold search (25-point scan + Brent) {t['threshold']}  [baseline]")
    print(f"  hopf at the threshold (l1, dRe λ/dp)     {t['hopf_at']}")
    root = Path(__file__).resolve().parents[1]
    with tempfile.TemporaryDirectory() as tmp:
        w0, c0 = time.perf_counter(), time.process_time()
        run_sweep(root / "sweeps" / "fig9_boundary.toml", Path(tmp) / "fig9b", workers=1,
                  threads=1)
        w1, c1 = time.perf_counter(), time.process_time()
        bnd = open_dataset(Path(tmp) / "fig9b").boundary()
    nv = len(bnd)
    print(f"Fig. 9 boundary sweep (401², 1 worker): {w1 - w0:.2f} s wall, {c1 - c0:.2f} s "
          f"CPU (this process); {nv} vertices on {bnd['line'].nunique()} polylines")
    idx = np.unique(np.linspace(0, nv - 1, min(args.sample, nv)).astype(int))
    cpu, types = [], {}
    for i in idx:
        ay, pc = float(bnd["config_ay_m"].iloc[i]), float(bnd["chamber_pressure_pa"].iloc[i])
        c0 = time.process_time()
        r = rd.hopf(rig, at=pc, speed_hz=SPEED_HZ, config_ay_m=ay)
        cpu.append(time.process_time() - c0)
        key = r.type if r.ok else r.status
        types[key] = types.get(key, 0) + 1
    med = float(np.median(cpu))
    print(f"hopf at {len(idx)} sampled vertices: CPU per vertex median {med * 1e3:.1f} ms "
          f"(max {max(cpu) * 1e3:.1f} ms, sum {sum(cpu):.1f} s); types {types}")
    print(f"projection for all {nv} vertices: {med * nv:.1f} s CPU, {med * nv / 2:.1f} s on "
          "2 cores (goal <= 120 s)")
    if args.procs:
        _hopf_all(bnd, args.procs)
    footer()


def _hopf_vertex(v):
    import time
    c0 = time.process_time()
    r = _RIG.hopf_at(v)
    return r, time.process_time() - c0


class _Rig:
    def __init__(self):
        self.rig = rd.models.paper_rig()

    def hopf_at(self, v):
        r = rd.hopf(self.rig, at=v[1], speed_hz=SPEED_HZ, config_ay_m=v[0])
        return r.type if r.ok else r.status


_RIG = None


def _init():
    global _RIG
    pin_threads(1)  # the environment is inherited from the parent's pin_threads(1) too
    _RIG = _Rig()


def _hopf_all(bnd, procs):
    """Every vertex of the boundary on ``procs`` processes (spawned, one BLAS thread each):
    the measurement, start of the processes included."""
    import multiprocessing as mp
    import resource
    import time

    verts = [(float(a), float(p)) for a, p in zip(bnd["config_ay_m"], bnd["chamber_pressure_pa"])]
    w0 = time.perf_counter()
    ch0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    with mp.get_context("spawn").Pool(procs, initializer=_init) as pool:
        out = pool.map(_hopf_vertex, verts, chunksize=4)
    wall = time.perf_counter() - w0
    ch1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    child = (ch1.ru_utime + ch1.ru_stime) - (ch0.ru_utime + ch0.ru_stime)
    types = {}
    for t, _ in out:
        types[t] = types.get(t, 0) + 1
    print(f"hopf at all {len(verts)} vertices on {procs} processes (start included): "
          f"{wall:.1f} s wall, {child:.1f} s CPU of the processes (hopf calls "
          f"{sum(c for _, c in out):.1f} s); types {types} (goal <= 120 s on 2 cores)")


if __name__ == "__main__":
    main()
