"""Benchmark: the tilting films' moments in a transient (issue 20) — the cost of recording
them (one more film solve per output after the run) against the same run without.

Run ``python benchmarks/bench_tilt_transient.py [--repeat 5]``. Protocol
(benchmarks/_common.py): one thread, the two sides in interleaved repeats, medians, wall and
CPU time side by side, the machine load before and after.

Model: the compressor of tests/data/models on its plain journal bearings (72 × 16) with
``tilt = true`` and both housings misaligned by θy = 0.3 mrad; 150 Hz, an unbalance of
2e-4 kg·m at station 3; ``revolutions`` revolutions from the equilibrium with
``samples_per_revolution`` outputs each. Sides: ``record_film_moments=True`` (default) and
``False``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import sys
from pathlib import Path

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import footer, header, interleaved  # noqa: E402

import rotordyn  # noqa: E402

MODELS = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--revolutions", type=int, default=10)
    ap.add_argument("--samples-per-revolution", type=int, default=64)
    args = ap.parse_args(argv)
    header("tilting films' moments in a transient (issue 20)")
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=True, config_theta_y_rad=3e-4) for b in s.bearings))
    f = 150.0
    n_out = args.revolutions * args.samples_per_revolution + 1
    runs = {}

    def side(record):
        def fn():
            runs[record] = rotordyn.transient(s, args.revolutions / f, f, n_out=n_out,
                                              unbalances=[(3, 2e-4, 0.0)],
                                              record_film_moments=record)
        return fn

    t = interleaved({"moments recorded": side(True), "not recorded": side(False)},
                    repeat=args.repeat)
    base = t["not recorded"]
    print(f"{args.revolutions} revolutions, {n_out} outputs; rhs evaluations "
          f"{runs[False].stats['rhs_evals']}, Reynolds solves of the run "
          f"{runs[False].stats['reynolds_solves']} (both sides: "
          f"{runs[True].stats['reynolds_solves']})")
    for k, v in t.items():
        print(f"  {k:18s} CPU {v.cpu:8.3f} s  wall {v.wall:8.3f} s  ratio (CPU) "
              f"{v.cpu / base.cpu:.3f}")
    footer()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
