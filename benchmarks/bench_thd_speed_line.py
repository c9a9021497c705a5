"""THD system equilibrium of the compressor (tests/data/models/compressor_plain_thermal.toml,
36 x 8 films) over 40-160 Hz: status, outer iterations and CPU per speed, for this checkout and
a baseline checkout measured in the same run (each in its own subprocess, so each imports its
own rotordyn and _core). docs/film-physics.md, "Inlet of an ungrooved film".

Run:  python benchmarks/bench_thd_speed_line.py [--baseline /work/main/python] [--repeat 3]
(--baseline: the python/ directory of the checkout to compare with; its _core is the one
importable from there or the installed one)
"""

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CHILD = r"""
import dataclasses, json, sys, time
import rotordyn as rd
s = rd.System.from_toml(sys.argv[1])
s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=8)
                                          for b in s.bearings))
rd.system_thermal_equilibrium(s, speed_hz=100.0, model="thd")  # warm-up
rows = []
for f in range(40, 161, 10):
    best = None
    for _ in range(int(sys.argv[2])):
        c0 = time.process_time()
        r = rd.system_thermal_equilibrium(s, speed_hz=float(f), model="thd")
        c = time.process_time() - c0
        best = c if best is None else min(best, c)
    rows.append([f, r.status, int(r.iterations), best, float(r.max_temperature_c[0])])
print(json.dumps({"file": rd.__file__, "rows": rows}))
"""


def run(pythonpath, repeat):
    env = dict(os.environ, PYTHONPATH=str(pythonpath))
    model = ROOT / "tests" / "data" / "models" / "compressor_plain_thermal.toml"
    out = subprocess.run([sys.executable, "-c", CHILD, str(model), str(repeat)], env=env,
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", default="/work/main/python")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    print(f"load average {os.getloadavg()}")
    new, base = run(ROOT / "python", a.repeat), run(a.baseline, a.repeat)
    print(f"this checkout: {new['file']}\nbaseline:      {base['file']}")
    print("speed_hz | base status  iters  CPU s  T_max NDE | new status  iters  CPU s  T_max NDE")
    tot = [0.0, 0.0, 0, 0]
    for (f, bs, bi, bc, bt), (_, ns, ni, nc, nt) in zip(base["rows"], new["rows"]):
        print(f"{f:8d} | {bs:13s} {bi:5d} {bc:6.3f} {bt:9.3f} | {ns:10s} {ni:5d} {nc:6.3f} "
              f"{nt:9.3f}")
        tot = [tot[0] + bc, tot[1] + nc, tot[2] + bi, tot[3] + ni]
    print(f"total: baseline {tot[2]} iterations {tot[0]:.3f} s CPU; new {tot[3]} iterations "
          f"{tot[1]:.3f} s CPU (min of {a.repeat} per speed); load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
