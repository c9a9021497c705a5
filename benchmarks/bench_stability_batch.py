"""The bare stability chunk (``_core.stability_batch``: equilibrium, K_H/D_H, eigen-analysis
per point) on Fig. 9 lines of the paper rig at 50 Hz, per-point CPU (issue 22): this tree
with the films' cavitation sets carried along the line (the default), this tree without
that carry (``carry_cavitation=False``: each equilibrium from the coarse-grid prediction),
and optionally a baseline package (``--baseline PYTHONPATH``, e.g. the main checkout's
installed core: the code before the change). Each side runs in its own process (one BLAS
thread), the sides alternate ``--repeat`` times, medians are printed with the load; the
outputs of every side are compared with the first side's (statuses, equilibria, eigenvalues:
bit for bit or the largest difference). A side ``jacobian="exact"`` forms the Newton Jacobian
at every step (the former equilibrium, before the default modified Newton). Also printed: Reynolds solves and active-set
iterations per solve (sides whose core exposes ``reynolds_iterations``).

    python benchmarks/bench_stability_batch.py [--lines 10] [--points 100] [--repeat 3]
        [--baseline /work/main/.venv/lib/python3.11/site-packages]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

CHILD = r'''
import json, os, sys, time
import numpy as np
import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import Assembled
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.sweep.points import equilibrium_options
from rotordyn.units import hz_to_rad_s
nl, npl, calls, carry, out = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
asm = Assembled(rd.models.paper_rig())
ays, pcs = np.linspace(-2.5e-3, 2.5e-3, nl), np.linspace(0.0, 0.3e6, npl)
om = np.full(nl * npl, hz_to_rad_s(50.0))
pr = np.tile(pcs, nl)
A = np.array([asm.config_vector(ay) for ay in ays for _ in pcs])
rs = [1 if k == 0 else 0 for _ in ays for k in range(npl)]
extra = ({} if carry == "default" else {"jacobian": carry[4:]} if carry.startswith("jac=")
         else {"carry_cavitation": carry == "on"})
def run():
    sol = _core.SystemSolver(asm.model)
    res = _core.stability_batch(sol, om, pr, A, rs, equilibrium_options({}), 0, False,
        FD_REL_STEP, asm.rotor.xy_pairs(), asm.rotor.rot_pairs(),
        [i for bc in asm.bearings for i in bc.sleeve], **extra)
    return sol, res
run()  # warm-up
cpu = []
for _ in range(calls):
    c0 = time.process_time()
    sol, res = run()
    cpu.append(time.process_time() - c0)
n = nl * npl
np.savez(out, status=np.array(res.status), ev=np.asarray(res.eigenvalues), r=np.asarray(res.r))
print(json.dumps({"cpu_ms": 1e3 * min(cpu) / n, "solves": sol.reynolds_solves / n,
                  "as_iters": (sol.reynolds_iterations / sol.reynolds_solves
                               if hasattr(sol, "reynolds_iterations") else None),
                  "lin": (sol.linearizations / n if hasattr(sol, "linearizations") else None)}))
'''


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def compare(a, b) -> str:
    import numpy as np

    if not (a["status"] == b["status"]).all():
        return "statuses DIFFER"
    out = []
    for k in ("r", "ev"):
        x, y = a[k], b[k]
        if np.array_equal(x, y, equal_nan=True):
            out.append(f"{k} bit for bit")
        else:
            m = np.isfinite(x) & np.isfinite(y)
            out.append(f"{k} max diff {np.max(np.abs(x - y)[m]) / np.max(np.abs(x[m])):.1e} "
                       "of the largest")
    return "statuses equal, " + ", ".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=10)
    ap.add_argument("--points", type=int, default=100, help="points per line (p_c)")
    ap.add_argument("--repeat", type=int, default=3, help="alternations of the sides")
    ap.add_argument("--calls", type=int, default=2, help="timed calls per process (best)")
    ap.add_argument("--baseline", default=None, help="PYTHONPATH of the baseline package")
    a = ap.parse_args()
    here = os.environ.get("PYTHONPATH", "")
    sides = [("this tree (default)", here, "on"),
             ("this tree, exact Newton Jacobian", here, "jac=exact"),
             ("this tree, no line carry", here, "off")]
    if a.baseline:
        sides.insert(0, ("baseline", a.baseline, "default"))
    print(f"== bare stability_batch, {a.lines} lines x {a.points} points over p_c, 50 Hz; "
          f"load before {load()} on {os.cpu_count()} cores (shared machine)")
    got: dict = {s[0]: [] for s in sides}
    with tempfile.TemporaryDirectory() as d:
        for _ in range(a.repeat):
            for name, pp, carry in sides:
                out = str(Path(d) / f"{len(got[name])}-{abs(hash(name))}.npz")
                env = {**os.environ, "PYTHONPATH": pp, "OMP_NUM_THREADS": "1",
                       "OPENBLAS_NUM_THREADS": "1"}
                p = subprocess.run([sys.executable, "-c", CHILD, str(a.lines), str(a.points),
                                    str(a.calls), carry, out], env=env, capture_output=True,
                                   text=True, check=True)
                got[name].append((json.loads(p.stdout.strip().splitlines()[-1]), out))
        import numpy as np

        ref = np.load(got[sides[0][0]][0][1])
        med0 = None
        for name, _, _ in sides:
            runs = got[name]
            med = statistics.median(r[0]["cpu_ms"] for r in runs)
            med0 = med0 or med
            r0 = runs[0][0]
            it = f"{r0['as_iters']:.3f}" if r0["as_iters"] is not None else "n/a"
            lin = f"{r0['lin']:.3f}" if r0.get("lin") is not None else "n/a"
            print(f"{name:34s} {med:.4f} ms CPU/point (median of {len(runs)}; each the best of "
                  f"{a.calls}), {med / med0:.3f}x the first; Reynolds solves/point "
                  f"{r0['solves']:.3f}, linearisations/point {lin}, active-set iterations/solve {it}; "
                  f"{compare(ref, np.load(runs[-1][1]))}")
    print(f"load after {load()}")


if __name__ == "__main__":
    main()
