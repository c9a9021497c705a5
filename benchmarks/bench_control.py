"""Benchmark: the nonlinear rig with the active bearing under feedback (issue 8).

Run ``python benchmarks/bench_control.py [--repeat 3] [--t-sim 0.2] [--no-scipy] [--no-runup]
[--laws-only | --no-laws]``.

* **laws** (issue 24) — cost per right-hand side of the gain-scheduled PD and of the adaptive
  1× command against the fixed PD, and of the PID with anti-windup (back-calculation,
  conditioning) against the same PID, on one run-up segment (goal: ≤ 20 % extra);

* **closed loop** — paper rig, a_y = −1.85 mm, 50 Hz, p_c = 0.05 MPa (linearly unstable
  without control), 0.1 c disturbance, the tuned PD law + 100 Hz second-order valve, one CVODE
  run (BDF, analytic Jacobian over rotor + valve + controller states);
* **open loop** — the same point without controller or valve (eq. 12 as before issue 8):
  the baseline for the controller's cost (goal: < 20 % extra). Its trajectory grows into the
  whirl while the closed loop decays, so beside simulated-seconds per wall-second the cost
  per right-hand side (each one a Reynolds solve) is printed, which isolates the overhead;
* **SciPy** — ``scipy.integrate.solve_ivp(method="BDF")`` on the same closed-loop right-hand
  side written in Python around the same C++ film forces (``SystemSolver.film_forces``), a
  shorter run, two rows: (a) with its default finite-difference Jacobian — what a user who
  writes the right-hand side would run (the issue's baseline), and (b) given rotordyn's
  analytic Jacobian (``SystemSolver.linearize``), the stronger baseline, and (c) with the film
  forces in NumPy/SciPy too (``python_film.py``: the same discrete Reynolds problem, SuperLU,
  checked against the core to round-off) and SciPy's finite-difference Jacobian — the whole
  right-hand side in Python, what a SciPy user without rotordyn has; each compared at
  equal tolerance and at equal accuracy (largest error over 11 output times against a tight
  CVODE reference; SciPy's CPU time interpolated log-log between the two tolerances whose
  errors bracket rotordyn's) (goal: rotordyn ≥ 20× faster in simulated seconds per CPU
  second);
* **run-up** — 10 → 120 Hz in 10 s with a 2e-5 kg m unbalance at disk B, p_c = 0.5 MPa and
  the valve (goal: < 60 s wall on one core).
* **robust sweep** (``--robust-points``, default 1000) — ``rotordyn.sweep.robust.robust`` of
  the tuned PD over speed × p_c × a_y (10 × 10 × 10 around the design point), stability only
  (plant re-linearised at each point, equilibria continued along the innermost axis,
  closed-loop eigenvalues), beside the same points one by one in a Python loop (``plant``
  with its default warm start + ``closed_loop(with_margins=False)``); then with the margins at
  every stable point on 10 × 10 (speed × p_c) points, beside the loop doing the same
  (``closed_loop`` + ``margins.loop_margins`` of the input loop) (goal: 10³ points ≤ 30 s
  on 2 cores); medians of ``--repeat`` interleaved repeats (sweep on 2 threads, sweep on
  ``--robust-workers`` processes, loop).

Medians of interleaved repeats; wall and CPU (process) time; the machine load before and
after (the machine is shared: figures are noisy). One BLAS/OpenMP thread.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import statistics
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
import rotordyn as rd  # noqa: E402
from rotordyn.analysis.assembly import assembled  # noqa: E402
from rotordyn.control import Actuator, SpeedProfile  # noqa: E402
from rotordyn.analysis.measurement import measurement_matrix  # noqa: E402
from rotordyn.control.pid import tune_pd  # noqa: E402
from rotordyn.control.plant import plant  # noqa: E402
from python_film import PythonFilmForces, check_against_core  # noqa: E402
from _common import load_line  # noqa: E402

C, AY, F, PC = 3e-4, -1.85e-3, 50.0, 0.05e6
RTOL, ATOL = 1e-6, 1e-9


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def timed(fn):
    w0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - w0, time.process_time() - c0


N_ERR = 11  # output times at which both sides' errors are measured (0 .. t_sim)


def scipy_closed_loop(rig, k, act, t_sim, rtol=RTOL, atol_scale=1.0, analytic_jacobian=True,
                      python_film=False):
    """solve_ivp(BDF) on [r, v, p, ṗ, x_k] with the C++ film forces (or, ``python_film``, the
    NumPy/SciPy ones of python_film.py), Python elsewhere; the Jacobian analytic (rotordyn's
    film K_H, D_H) or SciPy's finite differences."""
    from scipy.integrate import solve_ivp

    asm = assembled(rig)
    m, s = asm.model, asm.solver
    n = asm.n
    M, K, Cg = np.asarray(m.M), np.asarray(m.K), np.asarray(m.C) + 2 * np.pi * F * np.asarray(m.G)
    Minv = np.linalg.inv(M)
    ch = np.asarray(m.chamber)
    a = asm.config_vector(AY)
    F0 = np.asarray(m.Q) - K @ a
    e = rd.equilibrium(rig, F, PC, AY)
    Cm, _ = measurement_matrix(rig, k.measurements)
    off = Cm @ np.concatenate([e.r, np.zeros(n)])
    w = 2 * np.pi * act.natural_frequency_hz
    z = act.damping
    om = 2 * np.pi * F
    nk = k.n_states
    film = PythonFilmForces(m) if python_film else s.film_forces

    def rhs(t, y):
        r, v = y[:n], y[n:2 * n]
        p, pd, xk = y[2 * n], y[2 * n + 1], y[2 * n + 2:]
        ym = Cm @ y[:2 * n] - off
        u = (k.C @ xk + k.D @ ym)[0]
        cmd = min(max(PC + u, act.p_min_pa), act.p_max_pa)
        pc = min(max(p, act.p_min_pa), act.p_max_pa)
        H = np.asarray(film(r, v, om))
        acc = Minv @ (H + F0 + pc * ch - K @ r - Cg @ v)
        return np.concatenate([v, acc, [pd, w * w * (cmd - p) - 2 * z * w * pd],
                               k.A @ xk + k.B @ ym])

    def jac(t, y):
        r, v = y[:n], y[n:2 * n]
        lin = s.linearize(r, v, om)
        N = y.size
        J = np.zeros((N, N))
        J[:n, n:2 * n] = np.eye(n)
        J[n:2 * n, :n] = -Minv @ (K + np.asarray(lin.KH))
        J[n:2 * n, n:2 * n] = -Minv @ (Cg + np.asarray(lin.DH))
        J[n:2 * n, 2 * n] = Minv @ ch
        dcmd = np.zeros(N)
        dcmd[:2 * n] = (k.D @ Cm)[0]
        dcmd[2 * n + 2:] = k.C[0]
        J[2 * n, 2 * n + 1] = 1.0
        J[2 * n + 1] = w * w * dcmd
        J[2 * n + 1, 2 * n] -= w * w
        J[2 * n + 1, 2 * n + 1] -= 2 * z * w
        J[2 * n + 2:, :2 * n] = k.B @ Cm
        J[2 * n + 2:, 2 * n + 2:] = k.A
        return J

    r0 = e.r.copy()
    r0[asm.bearings[0].jy] += 0.1 * C
    # the valve starts at rest at the initial command (as in rotordyn's transient)
    u0 = (k.D @ (Cm @ np.concatenate([r0, np.zeros(n)]) - off))[0]
    p0 = min(max(PC + u0, act.p_min_pa), act.p_max_pa)
    y0 = np.concatenate([r0, np.zeros(n), [p0, 0.0], np.zeros(nk)])
    atol = atol_scale * np.concatenate([np.full(n, ATOL), np.full(n, ATOL * om), [1.0, om],
                                        np.full(nk, ATOL)])
    # t_eval only samples SciPy's dense output: its steps do not depend on it
    return solve_ivp(rhs, (0, t_sim), y0, method="BDF", jac=jac if analytic_jacobian else None,
                     rtol=rtol, atol=atol, t_eval=np.linspace(0.0, t_sim, N_ERR))


def equal_accuracy_cost(points, err_target):
    """CPU time SciPy needs for the error ``err_target``: log-log interpolation between the two
    tolerances whose errors bracket it (``points``: (error, cpu) pairs). None if none does."""
    pts = sorted(points)
    for (e0, c0), (e1, c1) in zip(pts, pts[1:]):
        if e0 <= err_target <= e1 and e0 > 0 and e1 > e0:
            f = np.log(err_target / e0) / np.log(e1 / e0)
            return float(np.exp(np.log(c0) + f * (np.log(c1) - np.log(c0))))
    return None


def laws(rig, act, repeat):
    """Issue 24: cost per right-hand side of the gain-scheduled PD and of the adaptive 1×
    command against the fixed PD, on one run-up segment (30 → 60 Hz in 0.3 s, a_y = 0,
    0.5 MPa, the valve, 2e-5 kg m at disk B). Interleaved repeats, medians of CPU time."""
    from rotordyn.control.adaptive import adaptive_rejection
    from rotordyn.control.antiwindup import with_anti_windup
    from rotordyn.control.gain_schedule import gain_schedule
    from rotordyn.control.pid import pid

    fixed = pid(1.0e9, 2.5e6)
    sched = gain_schedule([pid(0.8e9, 2.0e6), pid(1.0e9, 2.5e6), pid(1.2e9, 3.0e6),
                           pid(1.0e9, 2.0e6)], [25.0, 40.0, 50.0, 65.0])
    ad = adaptive_rejection(rig, [25.0, 40.0, 50.0, 65.0], [("displacement", 6)], 20.0,
                            chamber_pressure_pa=0.5e6, config_ay_m=0.0, actuator=act)
    # γ(Ω) scheduled on its own grid, a leak and freezing at the valve's limits (§2.6)
    ad2 = ad.with_gain(([25.0, 40.0, 50.0, 65.0], [20.0, 2.0, 10.0, 20.0]))
    ad2 = type(ad2)(ad2.measurements, ad2.speeds_hz, ad2.influence, ad2.gain_1_per_s,
                    leak_1_per_s=0.5, freeze_at_limits=True)
    prof = SpeedProfile.ramp(30.0, 60.0, 100.0)
    kw = dict(chamber_pressure_pa=0.5e6, config_ay_m=0.0, speed=prof, actuator=act,
              unbalances=[(6, 2e-5, 0.0)], n_out=301, rtol=RTOL, atol_m=ATOL)
    # anti-windup (§2.4): the PID with back-calculation / conditioning against the same PID
    fpid = pid(1.0e9, 2.5e6, 1.0e9 / 0.02)
    cases = {"fixed PD": dict(controller=fixed), "scheduled PD": dict(controller=sched),
             "adaptive 1x": dict(adaptive=ad), "fixed PD + adaptive 1x":
             dict(controller=fixed, adaptive=ad),
             "adaptive 1x γ(Ω)+σ+freeze": dict(adaptive=ad2),
             "fixed PID": dict(controller=fpid),
             "PID + back-calculation": dict(controller=with_anti_windup(fpid)),
             "PID + conditioning": dict(controller=with_anti_windup(fpid, mode="conditioning"))}
    # the same with a ±2 kPa valve: saturated for most of the segment (the correction active)
    narrow = dict(actuator=dataclasses.replace(act, p_min_pa=0.5e6 - 2e3, p_max_pa=0.5e6 + 2e3))
    cases.update({"PID, ±2 kPa": dict(narrow, controller=fpid),
                  "PID + back-calc., ±2 kPa": dict(narrow, controller=with_anti_windup(fpid)),
                  "PID + cond., ±2 kPa": dict(narrow, controller=with_anti_windup(
                      fpid, mode="conditioning"))})
    ref = {"PID + back-calculation": "fixed PID", "PID + conditioning": "fixed PID",
           "PID + back-calc., ±2 kPa": "PID, ±2 kPa", "PID + cond., ±2 kPa": "PID, ±2 kPa"}
    res = {name: [] for name in cases}
    kw0 = dict(kw, n_out=2)
    for _ in range(repeat):
        for name, extra in cases.items():
            tr, wall, cpu = timed(lambda: rd.transient(rig, 0.3, **dict(kw, **extra)))
            assert tr.status == "ok", tr.message
            # the call's fixed costs (equilibrium, set-up): the same call over 1 ms
            tr0, _, cpu0 = timed(lambda: rd.transient(rig, 1e-3, **dict(kw0, **extra)))
            res[name].append((wall, cpu, tr.stats["rhs_evals"], cpu0, tr0.stats["rhs_evals"]))
    per_rhs = {}
    for name, rows in res.items():
        wall = statistics.median(r[0] for r in rows)
        cpu = statistics.median(r[1] for r in rows)
        per = statistics.median(r[1] / r[2] for r in rows)
        per2 = statistics.median((r[1] - r[3]) / (r[2] - r[4]) for r in rows)
        per_rhs[name] = (per, per2)
        b = ref.get(name, "fixed PD")
        base, base2 = per_rhs[b]
        print(f"[laws] {name:24s}: wall {wall:.3f} s, CPU {cpu:.3f} s, {rows[0][2]} RHS, "
              f"{1e6 * per:.1f} µs CPU per RHS ({100 * (per / base - 1):+.1f} % vs the {b}); "
              f"without the call's fixed costs {1e6 * per2:.1f} µs "
              f"({100 * (per2 / base2 - 1):+.1f} %; goal <= +20 %)")
    print(f"[laws] load: {load()}")
def robust_rows(rig, k, n_side: int, workers: int, repeat: int, cube_margins: bool = False,
                threads_only: bool = False) -> None:
    """The robust sweep against a Python loop over the same points (module docstring)."""
    import tempfile

    from rotordyn.control import margins as mg
    from rotordyn.control.closedloop import closed_loop
    from rotordyn.sweep.robust import robust

    speeds = np.linspace(30.0, 70.0, n_side)
    pcs = np.linspace(0.02e6, 0.2e6, n_side)
    ays = np.linspace(-2.2e-3, -1.5e-3, n_side)

    def loop(points, with_margins):
        out = []
        for f, pc, ay in points:
            try:
                # the default warm start: from this thread's previous equilibrium
                p = plant(rig, f, pc, ay, measurements=k.measurements)
            except rd.ConvergenceError:
                out.append(None)
                continue
            cl = closed_loop(p, k, freqs_hz=[1.0, 2.0], with_margins=False)
            m = None
            if with_margins and cl.stable:
                m = mg.loop_margins(mg.lti.loop_at_input(mg.plant_ss(p), mg.controller_ss(k)))
            out.append((cl.max_real, m))
        return out

    cases = [("stability only", {"speed_hz": speeds.tolist(), "chamber_pressure_pa": pcs.tolist(),
                                 "config_ay_m": ays.tolist()}, False),
             ("with margins", {"speed_hz": speeds.tolist(), "chamber_pressure_pa": pcs.tolist(),
                               "config_ay_m": ays.tolist() if cube_margins else AY}, True)]
    for label, grid, with_m in cases:
        pts = [(f, pc, ay) for f in grid["speed_hz"] for pc in grid["chamber_pressure_pa"]
               for ay in np.atleast_1d(grid["config_ay_m"])]
        print(f"robust sweep, {label}: {len(pts)} points, medians of {repeat} interleaved "
              f"repeats; {load_line('load')}")
        runs = {"threads=2": []} if threads_only else \
            {"threads=2": [], f"workers={workers}": [], "loop": []}
        for _ in range(repeat):
            for kw in ({"threads": 2},) if threads_only else ({"threads": 2},
                                                              {"workers": workers}):
                with tempfile.TemporaryDirectory() as d:
                    r, wall, cpu = timed(lambda: robust(rig, k, grid, margins=with_m,
                                                        out=os.path.join(d, "r"), **kw))
                runs[", ".join(f"{a}={b}" for a, b in kw.items())].append((wall, cpu))
            if threads_only:
                continue
            res, wall, cpu = timed(lambda: loop(pts, with_m))
            runs["loop"].append((wall, cpu))
        s = r.summary()
        print(f"  {s['stable']} stable, {s['unstable']} unstable, {s['failed']} without verdict; "
              f"worst max Re λ {s['worst']['max_real_1_per_s']['value']:.3f} 1/s")
        for name, v in runs.items():
            wall = statistics.median(x[0] for x in v)
            cpu = statistics.median(x[1] for x in v)
            what = ("the same points in a Python loop (1 thread)" if name == "loop"
                    else f"robust({name})")
            note = (" (the workers' CPU not counted)" if name.startswith("workers") else
                    f" ({1e3 * cpu / len(pts):.1f} ms CPU per point)")
            print(f"  {what}: wall {wall:.1f} s, CPU of this process {cpu:.1f} s{note}; "
                  f"walls {', '.join(f'{x[0]:.1f}' for x in v)}")
        if threads_only:
            print(f"  {load_line('load')}")
            continue
        got = r.frame.max_real_1_per_s.to_numpy()
        ref = np.array([np.nan if x is None else x[0] for x in res])
        print(f"  rows vs loop: largest |Δ max Re λ| {np.nanmax(np.abs(got - ref)):.1e} 1/s, "
              f"same failures: {bool(np.array_equal(np.isnan(got), np.isnan(ref)))}; "
              f"{load_line('load')}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--t-sim", type=float, default=0.2)
    ap.add_argument("--t-scipy", type=float, default=0.05)
    ap.add_argument("--no-scipy", action="store_true")
    ap.add_argument("--no-runup", action="store_true")
    ap.add_argument("--no-python-film", action="store_true",
                    help="skip the SciPy row whose film is NumPy/SciPy too (~1 min)")
    ap.add_argument("--laws-only", action="store_true",
                    help="only the fixed / scheduled / adaptive law comparison (issue 24)")
    ap.add_argument("--no-laws", action="store_true")
    ap.add_argument("--no-robust", action="store_true")
    ap.add_argument("--robust-only", action="store_true",
                    help="only the robust-sweep rows")
    ap.add_argument("--robust-points", type=int, default=1000,
                    help="points of the stability-only robust sweep (a cube: 10 per axis)")
    ap.add_argument("--robust-workers", type=int, default=2)
    ap.add_argument("--robust-cube-margins", action="store_true",
                    help="the margins case on the same 10x10x10 cube as stability only")
    ap.add_argument("--robust-threads-only", action="store_true",
                    help="only robust(threads=2) (no worker processes, no Python loop)")
    args = ap.parse_args()
    print(f"load before: {load()}  (2 shared cores: figures are noisy)")
    rig = rd.models.paper_rig()
    act = Actuator()
    if not (args.no_laws or args.robust_only):
        laws(rig, act, args.repeat)
        if args.laws_only:
            print(f"load after: {load()}")
            return
    k, cl = tune_pd(plant(rig, F, PC, AY, measurements=[("journal", 0)], actuator=act))
    print(f"PD: closed-loop max Re λ = {cl.max_real:.2f} 1/s; t_sim = {args.t_sim} s")
    if args.robust_only:
        robust_rows(rig, k, round(args.robust_points ** (1 / 3)), args.robust_workers,
                    args.repeat, args.robust_cube_margins, args.robust_threads_only)
        print(f"load after: {load()}")
        return
    kw = dict(disturbance_m=(0.0, 0.1 * C), n_out=201, rtol=RTOL, atol_m=ATOL)

    def ol():
        return rd.transient(rig, args.t_sim, F, PC, AY, **kw)

    def olv():
        return rd.transient(rig, args.t_sim, F, PC, AY, actuator=act, **kw)

    def clo():
        return rd.transient(rig, args.t_sim, F, PC, AY, controller=k, actuator=act, **kw)

    res = {"open": [], "open+valve": [], "closed": []}
    for _ in range(args.repeat):  # interleaved
        for name, fn in (("open", ol), ("open+valve", olv), ("closed", clo)):
            tr, wall, cpu = timed(fn)
            assert tr.status == "ok", tr.message
            res[name].append((wall, cpu, tr.stats["rhs_evals"], tr.stats["steps"]))
            last_stats = dict(tr.stats)
    med = {}
    for name, rows in res.items():
        wall = statistics.median(r[0] for r in rows)
        cpu = statistics.median(r[1] for r in rows)
        rhs, steps = rows[0][2], rows[0][3]
        med[name] = (wall, cpu, rhs)
        print(f"{name:10s}: {args.t_sim / wall:7.3f} sim-s/wall-s ({args.t_sim / cpu:.3f} "
              f"per CPU-s), wall {wall:.3f} s, CPU {cpu:.3f} s, {steps} steps, {rhs} RHS, "
              f"{1e6 * cpu / rhs:.1f} µs CPU per RHS")
    if "reynolds_solves" in last_stats:  # the closed loop (the last case run)
        st = last_stats
        print(f"closed-loop CVODE statistics: {st['jac_evals']} Jacobians, "
              f"{st['linear_setups']} linear setups, {st['newton_iters']} Newton iterations, "
              f"{st['error_test_fails']} error-test failures, "
              f"{st['stab_lim_order_reductions']} stability-limit order reductions; "
              f"{st['reynolds_solves']} Reynolds solves, "
              f"{st['reynolds_iterations'] / max(st['reynolds_solves'], 1):.2f} "
              "active-set iterations (sparse factorisations) per solve")
    extra = med["closed"][1] / med["closed"][2] / (med["open"][1] / med["open"][2]) - 1
    print(f"controller + valve cost per right-hand side: {100 * extra:+.1f} % (goal < 20 %); "
          f"per simulated second: {100 * (med['closed'][1] / med['open'][1] - 1):+.1f} % "
          "(different trajectories: decaying vs growing whirl)")
    if not args.no_scipy:
        # Accuracy of both against a tight CVODE reference (rtol 1e-10), the largest error over
        # N_ERR output times. Equal accuracy: SciPy's CPU time interpolated (log-log) between
        # the two tolerances whose errors bracket rotordyn's — not the first tolerance that
        # beats it, which would credit rotordyn with SciPy's extra accuracy.
        T = args.t_scipy
        ref = rd.transient(rig, T, F, PC, AY, controller=k, actuator=act, n_out=N_ERR, rtol=1e-10,
                           atol_m=1e-14, disturbance_m=(0.0, 0.1 * C))
        n = ref.r.shape[1]
        kw_err = dict(kw, n_out=N_ERR)  # the path does not depend on the output times

        def run_rd():
            return rd.transient(rig, T, F, PC, AY, controller=k, actuator=act, **kw_err)

        def paired(fn):
            """``repeat`` interleaved pairs (rotordyn, fn): medians of both sides' CPU time."""
            a, b = [], []
            for _ in range(args.repeat):
                a.append(timed(run_rd)[2])
                out, _, cpu = timed(fn)
                b.append(cpu)
            return statistics.median(a), out, statistics.median(b)

        first = run_rd()
        err_rd = np.abs(first.r - ref.r).max()
        print(f"rotordyn closed loop, {T} s at rtol {RTOL:g}: {first.stats['rhs_evals']} RHS, "
              f"largest error over {N_ERR} times: {err_rd:.2e} m; each SciPy row below: medians "
              f"of {args.repeat} interleaved (rotordyn, SciPy) pairs, CPU time both")
        asm = assembled(rig)
        e = rd.equilibrium(rig, F, PC, AY)
        states = [(e.r + 0.1 * C * q * np.eye(n)[asm.bearings[0].jy], 1e-3 * q * np.ones(n))
                  for q in (0.0, 0.5, 1.0)]
        print("python_film.py vs the core's film forces (3 states): largest relative "
              f"difference {check_against_core(asm.solver, PythonFilmForces(asm.model), states, 2 * np.pi * F):.1e}")
        rows = [("default finite-difference Jacobian", False, False),
                ("rotordyn's analytic Jacobian", True, False)]
        if not args.no_python_film:
            rows.append(("film in NumPy/SciPy (python_film.py), finite-difference Jacobian",
                         False, True))
        for label, analytic, pyfilm in rows:
            ratio_eq, points, cpu_rds = None, [], []
            # from rotordyn's rtol toward the tolerance whose error crosses rotordyn's: tighter
            # while SciPy is less accurate, looser while it is more accurate
            rt, step = RTOL, None
            while len(points) < 6:
                cpu_rd, sol, cpu = paired(lambda: scipy_closed_loop(
                    rig, k, act, T, rtol=rt, atol_scale=rt / RTOL, analytic_jacobian=analytic,
                    python_film=pyfilm))
                if sol.status != 0 or sol.t.size != N_ERR:
                    print(f"SciPy solve_ivp(BDF), {label}, rtol {rt:.1e}: failed "
                          f"(status {sol.status}: {sol.message}); no equal-accuracy point")
                    break
                err = np.abs(sol.y[:n].T - ref.r).max()
                cpu_rds.append(cpu_rd)
                points.append((err, cpu))
                print(f"SciPy solve_ivp(BDF), same RHS from Python, {label}, rtol {rt:.1e}: "
                      f"{sol.nfev} RHS, {sol.njev} Jacobians, {sol.nlu} LU, "
                      f"CPU {cpu:.2f} s -> {T / cpu:.4f} sim-s per CPU-s, error {err:.2e} m "
                      f"(rotordyn in the same pairs: CPU {cpu_rd:.3f} s)")
                if rt == RTOL:
                    ratio_eq = cpu / cpu_rd
                    step = 1 / np.sqrt(10) if err > err_rd else np.sqrt(10)
                elif (err > err_rd) != (step < 1):
                    break  # the error crossed rotordyn's
                rt *= step
            if ratio_eq is None:
                continue  # SciPy failed at rotordyn's tolerance: no ratio
            cpu_eq = equal_accuracy_cost(points, err_rd)
            cpu_rd = statistics.median(cpu_rds)
            print(f"  => rotordyn vs SciPy BDF with {label}: at equal tolerances "
                  f"{ratio_eq:.1f}x faster; "
                  + (f"at equal accuracy ({err_rd:.2e} m, SciPy's time interpolated): "
                     f"{cpu_eq / cpu_rd:.1f}x faster" if cpu_eq else
                     "SciPy's errors did not bracket rotordyn's in 6 tolerances")
                  + " (goal >= 20x)")
    if not args.no_runup:
        prof = SpeedProfile.ramp(10.0, 120.0, 11.0)
        tr, wall, cpu = timed(lambda: rd.transient(
            rig, 10.0, 10.0, 0.5e6, 0.0, unbalances=[(6, 2e-5, 0.0)], speed=prof,
            actuator=act, n_out=10 * 120 * 32 + 1))
        print(f"run-up 10 -> 120 Hz in 10 s (valve, unbalance): {tr.status}, "
              f"{tr.stats['steps']} steps, wall {wall:.1f} s, CPU {cpu:.1f} s (goal < 60 s)")
    if not args.no_robust:
        robust_rows(rig, k, round(args.robust_points ** (1 / 3)), args.robust_workers,
                    args.repeat)
    print(f"load after: {load()}")


if __name__ == "__main__":
    main()
