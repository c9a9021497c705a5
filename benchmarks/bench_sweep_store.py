"""The sweep store's own costs on a map that is not the paper rig (the compressor of
tests/data/models on plain bearings, clearance × speed, stability): bytes on disk per point
and per row, and what a resume costs, each beside its baseline measured in the same run:

* fresh: the whole map from the command line (start included) — the baseline;
* resume half: the directory of a run stopped after half its chunks (the log and the files
  of the second half removed, as a `kill -9` leaves them), resumed: its CPU against half the
  fresh run's (the verification of the first half's files and the start are the overhead);
* resume done: the finished directory run again (nothing to compute: start-up, verifying
  every file against the log's size, SHA-256 and rows) against the fresh run.

Repeats are interleaved (fresh, half, done, fresh, ...); medians; CPU of the command and every
process it started; the load average before and after. `--threads 1` unless given.

    python benchmarks/bench_sweep_store.py [--n 100 --m 100] [--repeats 3] [--threads 1]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

MODEL = Path(__file__).resolve().parents[1] / "tests" / "data" / "models" / \
    "compressor_plain.toml"
SPEC = """schema = "rotordyn/sweep/1"
name = "store-bench"
model = "{model}"
analysis = "stability"
chunk_size = {chunk}

[grid]
"bearings.*.clearance_m" = {{start = 0.8e-4, stop = 1.6e-4, num = {n}}}
speed_hz = {{start = 40.0, stop = 200.0, num = {m}}}

[options]
n_modes = 6
"""


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def run(cmd: list[str]) -> tuple[float, float, dict]:
    """Wall and CPU (the command and its reaped descendants) of one run, its JSON summary."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, check=True,
                       env={**os.environ, "OMP_NUM_THREADS": "1"})
    w = time.perf_counter() - w0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return w, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime), \
        json.loads(p.stdout.strip().splitlines()[-1])


def stop_half(src: Path, dst: Path) -> int:
    """``dst``: ``src`` as a driver killed after its first half of the chunks leaves it."""
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(src, dst)
    entries = [json.loads(x) for x in (dst / "_chunks.jsonl").read_text().splitlines()]
    n = max(e["hi"] for e in entries if e["op"] == "file") + 1
    keep = [e for e in entries if e["op"] == "file" and e["hi"] < n // 2]
    for e in entries:
        if e["op"] == "file" and e["hi"] >= n // 2:
            (dst / e["file"]).unlink(missing_ok=True)
    (dst / "_chunks.jsonl").write_text("".join(json.dumps(e, sort_keys=True) + "\n"
                                               for e in keep))
    return n - n // 2


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100, help="clearance values")
    ap.add_argument("--m", type=int, default=100, help="speeds (one line per chunk unit)")
    ap.add_argument("--chunk", type=int, default=250)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    args = ap.parse_args()
    exe = str(Path(sys.executable).with_name("rotordyn"))
    flags = ["--threads", str(args.threads), "--json"]
    print(f"load average before: {load()} (2-core machine: CPU times are the figure)")
    t: dict[str, list] = {"fresh": [], "half": [], "done": []}
    with tempfile.TemporaryDirectory() as d:
        sp = Path(d) / "s.toml"
        sp.write_text(SPEC.format(model=MODEL, n=args.n, m=args.m, chunk=args.chunk))
        out, half = Path(d) / "out", Path(d) / "half"
        for _ in range(args.repeats):
            shutil.rmtree(out, ignore_errors=True)
            t["fresh"].append(run([exe, "sweep", str(sp), "--out", str(out), *flags]))
            left = stop_half(out, half)
            t["half"].append(run([exe, "sweep", str(sp), "--out", str(half), *flags]))
            same = all((half / f.name).read_bytes() == f.read_bytes()
                       for f in out.glob("part-*.parquet"))
            t["done"].append(run([exe, "sweep", str(sp), "--out", str(out), *flags]))
        parts = sorted(out.glob("part-*.parquet"))
        nbytes = sum(f.stat().st_size for f in parts)
        res = t["fresh"][-1][2]
        n_pts = res["ok"] + res["failed"]
        import pyarrow.parquet as pq

        rows = sum(pq.ParquetFile(f).metadata.num_rows for f in parts)
        meta = sum(f.stat().st_size for f in out.iterdir() if f.name.startswith("_"))
    med = {k: (statistics.median(w for w, _, _ in v), statistics.median(c for _, c, _ in v))
           for k, v in t.items()}
    fw, fc = med["fresh"]
    print(f"compressor map {args.n} x {args.m} = {n_pts} points, {rows} rows, chunk "
          f"{args.chunk} ({res['n_chunks']} chunks), {' '.join(flags[:2])}, median of "
          f"{args.repeats}:")
    print(f"  fresh (baseline):  {fw:6.2f} s wall, {fc:6.2f} s CPU, "
          f"{fc / n_pts * 1e3:.3f} ms CPU/point, {n_pts / fw:.0f} points/s wall")
    hw, hc = med["half"]
    print(f"  resume half ({left} of {res['n_chunks']} chunks to do): {hw:6.2f} s wall, "
          f"{hc:6.2f} s CPU = {hc / fc:.2f}x the fresh run (half of it: 0.50x + start); "
          f"files equal to the fresh run's: {same}")
    dw, dc = med["done"]
    print(f"  resume done (verify only): {dw:6.2f} s wall, {dc:6.2f} s CPU = "
          f"{dc / fc:.2f}x the fresh run")
    print(f"  on disk: {len(parts)} part files, {nbytes} bytes = {nbytes / n_pts:.1f} B/point, "
          f"{nbytes / rows:.1f} B/row (zstd); bookkeeping {meta} bytes")
    print(f"load average after: {load()}")


if __name__ == "__main__":
    main()
