"""Nonlinear transient of the paper rig (CVODE BDF, one Reynolds solve per right-hand side).

    python benchmarks/bench_transient.py [--repeat 3] [--seconds 0.5]

Rig (``rd.models.paper_rig()``) at 50 Hz, a_y = −1.85 mm, disturbed by 0.1 c upwards, outputs
at 64 per revolution. Two runs: a decaying one (p_c = 0.15 MPa, paper §6.2 "fast decay") and a
limit cycle (p_c = 0.05 MPa). For each: median wall and CPU time, simulated seconds per wall
(and CPU) second, CVODE steps / right-hand sides / Jacobians per revolution, the cost of one
right-hand side (a film-force evaluation) and of one Jacobian (a perturbation linearisation)
timed on their own over the run's states, and wall ÷ (calls × cost per call): near 1 when the
integration is nothing but its film solves.

Baseline in the same run: the same integration plus one Reynolds solve per output time, which
is what recording the minimum film thickness cost before it came from the geometry (the
solve is replayed at each output state after the run, so both rows integrate identically).
Accuracy: the largest error over all output times against a reference run at rtol 1e-10,
atol 1e-14 m (``--no-reference`` skips it), so a speed-up that changes the integrator's path
is seen to keep the accuracy. CVODE's statistics (linear setups, Newton iterations,
stability-limit order reductions) and the Reynolds solves / active-set iterations of the run
are printed when the installed rotordyn reports them.
Goals (issue 11): decaying ≥ 10 simulated s per wall s, limit cycle ≥ 2, ratio ≤ 1.5.
Before/after a change: run this script alternately with the old and the new build (e.g.
``PYTHONPATH=<old site-packages copy>``) and compare the medians.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from _common import fmt, footer, header, interleaved  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.analysis.assembly import assembled  # noqa: E402

SPEED_HZ, AY_M, C_M = 50.0, -1.85e-3, 3e-4
CASES = {"decaying (p_c 0.15 MPa)": 0.15e6, "limit cycle (p_c 0.05 MPa)": 0.05e6}


def run(rig, pc, t_end, n_out):
    return rd.transient(rig, t_end, SPEED_HZ, pc, AY_M, disturbance_m=(0.0, 0.1 * C_M),
                        n_out=n_out)


def per_call_costs(rig, tr, repeat=3):
    """CPU seconds of one film-force evaluation and of one linearisation, timed on the run's
    output states in order (consecutive states as close as CVODE's are, or farther)."""
    s = assembled(rig).solver
    w = 2 * np.pi * SPEED_HZ
    R, V = tr.r, tr.v
    best_f = best_j = np.inf
    for _ in range(repeat):
        c0 = time.process_time()
        for i in range(len(R)):
            s.film_forces(R[i], V[i], w)
        best_f = min(best_f, (time.process_time() - c0) / len(R))
        idx = range(0, len(R), 8)
        c0 = time.process_time()
        for i in idx:
            s.linearize(R[i], V[i], w)
        best_j = min(best_j, (time.process_time() - c0) / len(idx))
    return best_f, best_j


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--seconds", type=float, default=0.5, help="simulated time per run, s")
    ap.add_argument("--no-reference", action="store_true",
                    help="skip the rtol-1e-10 reference runs (accuracy)")
    args = ap.parse_args(argv)
    header("bench_transient: paper rig, 50 Hz, a_y = -1.85 mm, 64 outputs per revolution")
    rig = rd.models.paper_rig()
    revs = SPEED_HZ * args.seconds
    n_out = int(round(64 * revs)) + 1
    print(f"{args.seconds} s simulated = {revs:g} revolutions, {n_out} output times; "
          f"median of {args.repeat} interleaved repeats")
    for name, pc in CASES.items():
        solver = assembled(rig).solver
        w = 2 * np.pi * SPEED_HZ
        last = {}

        def new():
            last["tr"] = run(rig, pc, args.seconds, n_out)

        def old():  # + one Reynolds solve per output time (the former h_min recording)
            tr = run(rig, pc, args.seconds, n_out)
            for i in range(len(tr.t)):
                solver.film_forces(tr.r[i], tr.v[i], w)

        t = interleaved({"new": new, "old": old}, repeat=args.repeat)
        tr = last["tr"]
        st = tr.stats
        f_cost, j_cost = per_call_costs(rig, tr)
        pred = st["rhs_evals"] * f_cost + st["jac_evals"] * j_cost
        print(f"\n{name}: status {tr.status}, amplitude {tr.amplitude() / C_M:.3f} c")
        print(f"  geometric h_min      {t['new']}   -> {args.seconds / t['new'].wall:6.2f} "
              f"simulated s per wall s ({args.seconds / t['new'].cpu:6.2f} per CPU s)")
        print(f"  + solve per output   {t['old']}   -> {args.seconds / t['old'].wall:6.2f} "
              f"simulated s per wall s ({args.seconds / t['old'].cpu:6.2f} per CPU s)  "
              f"[baseline: former behaviour]")
        print(f"  per revolution: {st['steps'] / revs:.1f} steps, {st['rhs_evals'] / revs:.1f} "
              f"right-hand sides, {st['jac_evals'] / revs:.2f} Jacobians "
              f"({st['newton_fails']} Newton and {st['error_test_fails']} error-test failures)")
        print(f"  cost per call (CPU): right-hand side {fmt(f_cost)}, Jacobian {fmt(j_cost)}; "
              f"calls x cost = {fmt(pred)}")
        print(f"  wall / (calls x cost) = {t['new'].wall / pred:.2f}, "
              f"CPU / (calls x cost) = {t['new'].cpu / pred:.2f}")
        if "linear_setups" in st:
            print(f"  CVODE: {st['linear_setups']} linear setups, {st['newton_iters']} Newton "
                  f"iterations, {st['stab_lim_order_reductions']} stability-limit order "
                  f"reductions; {st['reynolds_solves']} Reynolds solves, "
                  f"{st['reynolds_iterations'] / max(st['reynolds_solves'], 1):.2f} active-set "
                  f"iterations (factorisations) per solve; CPU per RHS "
                  f"{fmt(t['new'].cpu / st['rhs_evals'])} (all-in)")
        if not args.no_reference:
            ref = rd.transient(rig, args.seconds, SPEED_HZ, pc, AY_M,
                               disturbance_m=(0.0, 0.1 * C_M), n_out=n_out, rtol=1e-10,
                               atol_m=1e-14, max_steps=5_000_000)
            err = np.abs(tr.r - ref.r).max()
            print(f"  accuracy: max |r - r_ref| over the {n_out} outputs = {err:.2e} m "
                  f"({err / C_M:.1e} c; reference rtol 1e-10, {ref.stats['steps']} steps)")
    footer()


if __name__ == "__main__":
    main()
