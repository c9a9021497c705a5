"""Cost of the ``limit_cycle`` sweep analysis on one line (issue 19; docs/nonlinear.md,
"Fig. 9 with Hopf type and the bistable region").

The compressor on plain bearings (tests/data/models/compressor_plain.toml) over the speed,
121, 124, 127 Hz (its whip branch: Hopf point, two folds, the stable whip), film grid
36 × 6 (``--grid 36x4`` for the tests' grid), rtol 1e-6, tol 1e-4, ds 0.1, 1 thread:
the baseline (``ds_max`` 0.2, the other options at their defaults) against the tuned options
of the tests and the Fig. 9 spec (``ds_max`` 0.3, ``sensitivity_rtol`` 1e-4,
``newton = "broyden"``). One run each (a line costs tens of seconds), wall and CPU, the
machine load before and after, and the rows of each (the flags must agree).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header  # noqa: E402

MODEL = Path(__file__).resolve().parents[1] / "tests" / "data" / "models" / \
    "compressor_plain.toml"
SPEC = """schema = "rotordyn/sweep/1"
name = "bench-limit-cycle"
model = "{model}"
analysis = "limit_cycle"
chunk_size = 1

[grid]
"bearings.*.n_circ" = {nc}
"bearings.*.n_axial" = {na}
speed_hz = [121.0, 124.0, 127.0]

[options]
vary = "speed_hz"
rtol = 1e-6
tol = 1e-4
ds = 0.1
max_points = 40
{extra}
"""
RUNS = {"baseline": "ds_max = 0.2",
        "tuned": 'ds_max = 0.3\nsensitivity_rtol = 1e-4\nnewton = "broyden"'}


def run(name, extra, nc, na, tmp):
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    spec = tmp / f"{name}.toml"
    spec.write_text(SPEC.format(model=MODEL, nc=nc, na=na, extra=extra))
    w0, c0 = time.perf_counter(), time.process_time()
    assert run_sweep(spec, tmp / name, threads=1, progress=False).complete
    w, c = time.perf_counter() - w0, time.process_time() - c0
    print(f"{name}: {w:.1f} s wall, {c:.1f} s CPU")
    f = sw.open(tmp / name).frame
    cyc = f[f["record"] == "cycle"]
    for _, r in cyc.iterrows():
        print(f"  {r['speed_hz']:6.1f} Hz {r['status']:>9} cycle {r['cycle']} "
              f"A/c {r['amplitude_c']:.4f} |mu| {r['max_multiplier']:.4f} "
              f"stable {r['stable']} eq_stable {r['equilibrium_stable']} "
              f"bistable {r['bistable']}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--grid", default="36x6", help="film grid n_circ x n_axial")
    ap.add_argument("--only", choices=sorted(RUNS), help="one of the runs")
    a = ap.parse_args(argv)
    nc, na = (int(x) for x in a.grid.split("x"))
    header(f"limit_cycle line on the compressor, film {nc} x {na}")
    with tempfile.TemporaryDirectory() as d:
        for name, extra in RUNS.items():
            if a.only in (None, name):
                run(name, extra, nc, na, Path(d))
    footer()
    return 0


if __name__ == "__main__":
    sys.exit(main())
