"""Cost of verifying a sweep directory on open (issue 21): ``rotordyn.sweep.open(OUT)`` (every
part read once, size and SHA-256 checked against the log, parsed from the same bytes) against
``open(OUT, verify=False)`` (no hash) and ``pandas.read_parquet(OUT)`` (the baseline: no
check at all), median of ``--repeat`` runs after a warm-up (the files in the page cache).

    python benchmarks/bench_sweep_open.py [--dir OUT] [--rows 100000] [--repeat 7]

Without ``--dir`` a synthetic dataset is written through the store: ``--rows`` rows of a
stability-like table (20 float64 columns, ids, status) in chunks of 250 rows, compacted into
at most 128 files.
"""

from __future__ import annotations

import argparse
import hashlib
import statistics
import tempfile
import time
from pathlib import Path


def synthetic(d: Path, rows: int) -> Path:
    import numpy as np
    import pyarrow as pa
    from rotordyn.sweep.execution import group_size
    from rotordyn.sweep.store import Store

    per = 250
    n_chunks = -(-rows // per)
    out = d / "synthetic"
    st = Store(out, {"sweep_id": "bench-open", "spec_hash": "x", "model_hash": "y",
                     "n_chunks": n_chunks}, group=group_size(n_chunks))
    rng = np.random.default_rng(21)
    cat = pa.array(["ok"] * per).dictionary_encode()
    for c in range(n_chunks):
        cols = {"point_id": pa.array(np.arange(c * per, (c + 1) * per), pa.int64()),
                "chunk_id": pa.array(np.full(per, c), pa.int64())}
        for k in range(20):
            cols[f"v{k}"] = pa.array(rng.standard_normal(per))
        cols["status"] = cat
        st.add(c, pa.table(cols), {"ok": per, "failed": 0, "unstable": 0}, n_chunks)
    st.close()
    return out


def timed(fns: dict, repeat: int) -> dict:
    """{name: (median, min)} in seconds, the functions interleaved run by run (a load that
    changes during the benchmark then stretches all of them alike)."""
    for fn in fns.values():
        fn()  # warm-up (page cache, imports)
    ts: dict = {k: [] for k in fns}
    for _ in range(repeat):
        for k, fn in fns.items():
            t0 = time.perf_counter()
            fn()
            ts[k].append(time.perf_counter() - t0)
    return {k: (statistics.median(x), min(x)) for k, x in ts.items()}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--dir", default=None, help="an existing sweep directory")
    ap.add_argument("--rows", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args()
    import os

    import pandas as pd
    import rotordyn.sweep as sw

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(args.dir) if args.dir else synthetic(Path(tmp), args.rows)
        files = sorted(out.glob("part-*.parquet"))
        size = sum(f.stat().st_size for f in files)
        n = len(sw.open(out).frame)
        print(f"{out}: {n} rows, {len(files)} files, {size / 2**20:.2f} MiB; load "
              f"{os.getloadavg()[0]:.2f}")
        r = timed({"open(verify=True)": lambda: sw.open(out),
                   "open(verify=False)": lambda: sw.open(out, verify=False),
                   "pandas.read_parquet": lambda: pd.read_parquet(out),
                   "SHA-256 of the files": lambda: [hashlib.sha256(f.read_bytes()).digest()
                                                    for f in files]}, args.repeat)
        for k, (med, lo) in r.items():
            print(f"{k:22s} median {1e3 * med:7.1f} ms  min {1e3 * lo:7.1f} ms")
        (v, v0), (f, f0) = r["open(verify=True)"], r["open(verify=False)"]
        h = r["SHA-256 of the files"][1]
        print(f"verification: {1e3 * (v - f):+.1f} ms median, {1e3 * (v0 - f0):+.1f} ms min "
              f"(hashing alone {1e3 * h:.1f} ms, {size / 2**20 / h:.0f} MiB/s); load "
              f"{os.getloadavg()[0]:.2f}")

if __name__ == "__main__":
    main()
