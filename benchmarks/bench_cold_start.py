"""What history independence costs: every public call starts its first equilibrium cold
(python/rotordyn/_common/calls.py) and continues only along its own points.

On the compressor (plain bearings) and the paper rig, in the same run, interleaved repeats,
medians, wall and CPU, BLAS and Eigen on one thread, load printed:

* ``campbell, first speed cold`` — a Campbell diagram of 20 speeds as called now (the first
  equilibrium from the concentric state, each next one from the previous speed's);
* ``campbell, first speed warm`` — the behaviour before: the same call made inside one outer
  call after an identical one, so its first equilibrium starts from the last speed's
  equilibrium of the call before (what a repeated call used to do);
* ``per-speed cold`` — each speed its own call (no continuation at all), the cost the warm
  starts along a call still save;
* ``stability, cold`` / ``stability, warm`` — one operating point, as now and as a repeated
  call used to (warm from the same point's equilibrium).

    python benchmarks/bench_cold_start.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import dataclasses
from pathlib import Path

import numpy as np

from _common import footer, header, interleaved

import rotordyn as rd
from rotordyn._common.threads import limited_blas

MODELS = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"


@limited_blas
def _inside_one_call(fn):
    """``fn`` twice in one outer public call: the second shares the first's warm state (the
    behaviour of any repeated call before); the second's time is what is returned."""
    import time

    fn()
    w0, c0 = time.perf_counter(), time.process_time()
    fn()
    return time.perf_counter() - w0, time.process_time() - c0


def rows(label, s, speeds, speed, pc=0.0, repeat=5):
    print(f"-- {label}")
    camp = lambda: rd.campbell(s, speeds, pc)  # noqa: E731
    stab = lambda: rd.stability(s, speed, pc)  # noqa: E731
    warm = {"c": (0.0, 0.0), "s": (0.0, 0.0)}

    def camp_warm():
        warm["c"] = _inside_one_call(camp)

    def stab_warm():
        warm["s"] = _inside_one_call(stab)

    t = interleaved({"campbell, first speed cold": camp,
                     "per-speed cold": lambda: [rd.campbell(s, [f], pc) for f in speeds],
                     "stability, cold": stab}, repeat=repeat)
    # the warm sides: the timed second call of each pair (medians over the repeats)
    cw, sw = [], []
    for _ in range(repeat):
        camp_warm()
        cw.append(warm["c"])
        stab_warm()
        sw.append(warm["s"])
    med = lambda xs, k: float(np.median([x[k] for x in xs]))  # noqa: E731
    for k, v in t.items():
        print(f"  {k:30s} {v.wall * 1e3:8.1f} ms wall {v.cpu * 1e3:8.1f} ms CPU")
    print(f"  {'campbell, first speed warm':30s} {med(cw, 0) * 1e3:8.1f} ms wall "
          f"{med(cw, 1) * 1e3:8.1f} ms CPU")
    print(f"  {'stability, warm':30s} {med(sw, 0) * 1e3:8.1f} ms wall "
          f"{med(sw, 1) * 1e3:8.1f} ms CPU")
    c = t["campbell, first speed cold"].cpu
    print(f"  campbell cold/warm CPU {c / med(cw, 1):.3f}; per-speed cold / campbell CPU "
          f"{t['per-speed cold'].cpu / c:.2f}; stability cold/warm CPU "
          f"{t['stability, cold'].cpu / med(sw, 1):.3f}")
    e = [rd.equilibrium(s, f, pc) for f in (speeds[0],)]
    print(f"  (a cold first equilibrium: {e[0].iterations} Newton iterations, "
          f"{e[0].reynolds_solves} Reynolds solves)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    header("cold first equilibrium per public call vs the former warm start")
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    rows("compressor_plain.toml, 20 speeds 60-250 Hz", s, list(np.linspace(60.0, 250.0, 20)),
         150.0, repeat=a.repeat)
    rig = rd.models.paper_rig()
    rig = dataclasses.replace(rig, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) if isinstance(b, rd.ActiveJournalBearing)
        else b for b in rig.bearings))
    rows("paper rig (active bearing 36 x 8), 20 speeds 20-80 Hz, p_c 0.2 MPa", rig,
         list(np.linspace(20.0, 80.0, 20)), 50.0, 0.2e6, repeat=a.repeat)
    footer()


if __name__ == "__main__":
    main()
