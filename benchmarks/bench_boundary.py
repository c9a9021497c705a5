"""The adaptive Fig. 9 boundary at any resolution (issue 22): points evaluated and time for
the boundary of the rig at 50 Hz over (a_y, p_c) from a 26 x 26 coarse grid, against the full
grid of the same resolution, and its crossings on sampled columns against the same columns
evaluated densely (every fine node, through the same chunk function).

    .venv/bin/python benchmarks/bench_boundary.py [--resolution 1001] [--coarse 26]
        [--columns 3] [--threads 2]
    .venv/bin/python benchmarks/bench_boundary.py --surface --coarse 17 --coarse-z 9
        --resolution 65 [--refine both|columns|cells] [--columns 3]

The surface (a_y x p_c x speed 30-70 Hz) runs the cell refinement first (the baseline) and
then the columns (the surface default), each with the C++ share of its CPU time and its
crossings on sampled (a_y, speed) columns against the dense column.

Wall and CPU time of the process side by side (the sweep runs in threads of this process, so
the CPU time counts both), the load average before and after. One BLAS/OpenMP thread per
thread.
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import sys  # noqa: E402
import tempfile  # noqa: E402
import threading  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
from _common import footer, header  # noqa: E402

import rotordyn.sweep as sw  # noqa: E402
from rotordyn.sweep import run_sweep  # noqa: E402
from rotordyn.sweep.spec import SweepSpec, fine_axes  # noqa: E402
from rotordyn.sweep.work import Job, run_chunk  # noqa: E402

SPEC = """
schema = "rotordyn/sweep/1"
name = "fig9-boundary-bench"
model = "paper-rig"
analysis = "boundary"
chunk_size = 50

[grid]
config_ay_m = {{start = -2.5e-3, stop = 2.5e-3, num = {n0}}}
chamber_pressure_pa = {{start = 0.0, stop = 0.3e6, num = {n0}}}
speed_hz = {speed}

[options]
x = "config_ay_m"
y = "chamber_pressure_pa"
resolution = {res}
{zopt}"""



def point_values(t, name="max_real_1_per_s"):
    """A boundary chunk's per-point value (its first row: the point's mode rows share it)."""
    pid = t.column("point_id").to_numpy()
    first = np.r_[0, np.flatnonzero(np.diff(pid)) + 1] if len(pid) else np.zeros(0, int)
    return np.asarray(t.column(name).to_pylist(), dtype=float)[first]

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--resolution", type=int, default=1001)
    ap.add_argument("--coarse", type=int, default=26)
    ap.add_argument("--columns", type=int, default=3, help="dense columns checked")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--surface", action="store_true",
                    help="the 3-D boundary over a_y x p_c x speed (30-70 Hz, --coarse-z values)")
    ap.add_argument("--coarse-z", type=int, default=9)
    ap.add_argument("--dense-grid", action="store_true",
                    help="surface: also every fine node, and every column compared (small R)")
    ap.add_argument("--refine", choices=["both", "columns", "cells"], default="both",
                    help="surface: the refinement(s) run (both: cells first, the baseline)")
    args = ap.parse_args(argv)
    dim = 3 if args.surface else 2
    header(f"bench_boundary: Fig. 9 boundary at {args.resolution}^{dim}", threads=1)
    res, n0 = args.resolution, args.coarse
    if args.surface:
        return surface(args)
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "s.toml"
        p.write_text(SPEC.format(n0=n0, res=res, speed="50.0", zopt=""))
        w0, c0 = time.perf_counter(), time.process_time()
        r = run_sweep(p, Path(d) / "o", threads=args.threads, progress=False)
        w, c = time.perf_counter() - w0, time.process_time() - c0
        n = r.manifest["n_points"]
        print(f"boundary at {res}x{res} from {n0}x{n0}: {n} points evaluated (goal <= 4,000 "
              f"at 1001^2) vs {res * res:,} for the full grid: {res * res / n:.0f}x fewer; "
              f"{w:.1f} s wall, {c:.1f} s CPU on {args.threads} threads; counts {r.counts}")
        ds = sw.open(Path(d) / "o")
        levels = ds.frame.groupby("level")["point_id"].nunique().to_dict()
        print(f"points per refinement level: {levels}")
        b = ds.boundary()
        spec = SweepSpec.from_toml(p)
        ax, _ = fine_axes(spec)
        job = Job(spec.name, spec.load_model().to_toml(), spec.analysis, spec.options, ax)
        xs, ys = np.asarray(ax["config_ay_m"]), np.asarray(ax["chamber_pressure_pa"])
        ny = len(ys)
        fr = ds.frame.drop_duplicates("point_id")  # a point's mode rows share it
        # columns the boundary crosses (both states among its evaluated nodes), evenly spread
        mixed = fr.groupby("config_ay_m")["point_stable"].nunique()
        cand = np.searchsorted(xs, mixed[mixed > 1].index.to_numpy())
        cols = cand[np.linspace(0, len(cand) - 1, args.columns).round().astype(int)]
        w0, c0 = time.perf_counter(), time.process_time()
        worst = 0.0
        for i in cols:
            t = run_chunk(job, 0, 0, 0, [i * ny + j for j in range(ny)])
            z = point_values(t)
            st = np.where(np.isfinite(z), (z >= 0).astype(int), 2)
            k = np.flatnonzero(st[1:] != st[:-1])
            # the boundary's evaluated nodes on this column and their states
            sub = fr[np.abs(fr["config_ay_m"] - xs[i]) <= 1e-15]
            jj = np.searchsorted(ys, sub["chamber_pressure_pa"].to_numpy())
            seen = np.zeros(ny, bool)
            seen[jj] = True
            zz = np.full(ny, np.nan)
            zz[jj] = sub["max_real_1_per_s"].to_numpy()
            stb = np.where(np.isfinite(zz), (zz >= 0).astype(int), 2)
            kb = np.flatnonzero((stb[1:] != stb[:-1]) & seen[1:] & seen[:-1])
            zc = [k_ for k_ in k if st[k_] != 2 and st[k_ + 1] != 2]
            want = np.array([ys[k_] + (ys[k_ + 1] - ys[k_]) * z[k_] / (z[k_] - z[k_ + 1])
                             for k_ in zc])
            got = np.unique(b[np.abs(b["config_ay_m"] - xs[i]) <= 1e-15]["chamber_pressure_pa"])
            if len(want) and len(got) == len(want):
                worst = max(worst, float(np.max(np.abs(np.sort(got) - np.sort(want)))))
            print(f"column a_y = {xs[i] * 1e3:+.4f} mm: dense crossings between nodes "
                  f"{k.tolist()}, boundary's {kb.tolist()} -> "
                  f"{'identical' if list(k) == list(kb) else 'DIFFERENT'}; contour p_c "
                  f"{np.round(np.sort(got) / 1e3, 3).tolist()} kPa vs dense "
                  f"{np.round(np.sort(want) / 1e3, 3).tolist()} kPa")
        print(f"dense columns: {len(cols)} x {ny} points, {time.perf_counter() - w0:.1f} s wall, "
              f"{time.process_time() - c0:.1f} s CPU; largest contour difference "
              f"{worst:.3g} Pa")
    footer()


class _Timed:
    """rotordyn._core with max_real_batch timed (CPU seconds of the calling thread, summed
    over threads): the C++ share of a run."""

    def __init__(self, core):
        self.core, self.cpu, self.calls, self.points = core, 0.0, 0, 0
        self.lock = threading.Lock()

    def __getattr__(self, k):
        return getattr(self.core, k)

    def max_real_batch(self, solver, inp):
        t = time.thread_time()
        r = self.core.max_real_batch(solver, inp)
        with self.lock:
            self.cpu += time.thread_time() - t
            self.calls += 1
            self.points += len(inp.omega)
        return r


def _timed_advance(cls, acc):
    """``cls.advance`` timed (CPU of the driver thread) into ``acc``; returns the original."""
    orig = cls.advance

    def advance(self, *a):
        t = time.thread_time()
        try:
            return orig(self, *a)
        finally:
            acc[0] += time.thread_time() - t

    cls.advance = advance
    return orig


def surface(args):
    """The boundary surface over a_y x p_c x speed: points, time (C++ share), dense columns;
    the cell refinement (the former default) first as the baseline of the same run."""
    import rotordyn.sweep.blocks as blocks
    from rotordyn.sweep.boundary import Refinement
    from rotordyn.sweep.surface import ColumnPlan

    res, n0 = args.resolution, args.coarse
    methods = ["cells", "columns"] if args.refine == "both" else [args.refine]
    dense = dense_grid(args) if args.dense_grid else None
    for method in methods:
        with tempfile.TemporaryDirectory() as d:
            p = Path(d) / "s.toml"
            p.write_text(SPEC.format(n0=n0, res=res,
                                     speed=f"{{start = 30.0, stop = 70.0, num = {args.coarse_z}}}",
                                     zopt=f'z = "speed_hz"\nrefine = "{method}"\n'))
            timed = blocks._core = _Timed(blocks._core)
            plan_cpu = [0.0]
            o1, o2 = (_timed_advance(k, plan_cpu) for k in (Refinement, ColumnPlan))
            load0 = os.getloadavg()[0]
            w0, c0 = time.perf_counter(), time.process_time()
            r = run_sweep(p, Path(d) / "o", threads=args.threads, progress=False)
            w, c = time.perf_counter() - w0, time.process_time() - c0
            blocks._core = timed.core
            Refinement.advance, ColumnPlan.advance = o1, o2
            n = r.manifest["n_points"]
            ds = sw.open(Path(d) / "o")
            b = ds.boundary()
            levels = ds.frame.groupby("level")["point_id"].nunique().to_dict()
            if method == "columns":  # rounds, not levels: the points by reason instead
                levels = r.manifest.get("points_by_reason", levels)
            print(f"[{method}] boundary surface at {res}^3 from {n0}x{n0}x{args.coarse_z}: "
                  f"{n:,} points evaluated vs {res**3:,} for the full grid ({res**3 / n:.0f}x "
                  f"fewer); {w:.1f} s wall, {c:.1f} s CPU on {args.threads} threads (load "
                  f"{load0:.1f} -> {os.getloadavg()[0]:.1f}; goal at 257^3: <= 60 s on 2 "
                  f"cores); C++ max_real_batch {timed.cpu:.1f} s CPU in {timed.calls} calls "
                  f"({1e3 * timed.cpu / max(timed.points, 1):.2f} ms/point), the rest "
                  f"{c - timed.cpu:.1f} s (Python: the plan {plan_cpu[0]:.1f} s, tables, "
                  f"store); "
                  f"{b['speed_hz'].nunique()} speed slices with a contour; counts {r.counts}; "
                  f"points per level {levels}")
            if args.columns:
                dense_columns(args, p, ds, b)
            if dense is not None:
                compare_grid(ds, dense)
    footer()


def dense_grid(args):
    """max Re λ at every fine node of the surface's grid (lines along speed, one chunk per
    a_y slab, on --threads threads)."""
    from concurrent.futures import ThreadPoolExecutor

    res = args.resolution
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "s.toml"
        p.write_text(SPEC.format(n0=args.coarse, res=res,
                                 speed=f"{{start = 30.0, stop = 70.0, num = {args.coarse_z}}}",
                                 zopt='z = "speed_hz"\n'))
        spec = SweepSpec.from_toml(p)
    ax, _ = fine_axes(spec)
    job = Job(spec.name, spec.load_model().to_toml(), spec.analysis, spec.options, ax)
    V = np.full((res, res, res), np.nan)

    def slab(i):
        t = run_chunk(job, 0, 0, 0, list(range(i * res * res, (i + 1) * res * res)))
        return i, point_values(t)

    w0, c0 = time.perf_counter(), time.process_time()
    with ThreadPoolExecutor(args.threads) as ex:
        for i, v in ex.map(slab, range(res)):
            V[i] = v.reshape(res, res)
    print(f"dense grid {res}^3: {res**3:,} points, {time.perf_counter() - w0:.1f} s wall, "
          f"{time.process_time() - c0:.1f} s CPU, {int(np.isnan(V).sum())} failed")
    return V


def compare_grid(ds, V):
    """Every (a_y, speed) column's crossings (neighbouring p_c nodes in different states, both
    evaluated) against the dense grid's."""
    st = np.where(np.isfinite(V), (V >= 0).astype(int), 2)
    fr = ds.frame.drop_duplicates("point_id")  # a point's mode rows share it
    i, j, k = (fr[f"i_{a}"].to_numpy() for a in ("config_ay_m", "chamber_pressure_pa",
                                                  "speed_hz"))
    seen = np.zeros(st.shape, bool)
    seen[i, j, k] = True
    got = np.full(st.shape, -1)
    ok = fr["status"].isin(["ok", "contact"]).to_numpy()
    got[i, j, k] = np.where(ok, (fr["max_real_1_per_s"].to_numpy() >= 0).astype(int), 2)
    dense = st[:, 1:, :] != st[:, :-1, :]
    found = (got[:, 1:, :] != got[:, :-1, :]) & seen[:, 1:, :] & seen[:, :-1, :]
    same = (dense == found).all(axis=1)
    print(f"  every column against the dense grid: {int(same.sum()):,} of {same.size:,} "
          f"identical ({int(dense.sum()):,} crossings, {int((dense & ~found).sum())} missed, "
          f"{int((found & ~dense).sum())} extra; evaluated values equal the dense ones to "
          f"{np.nanmax(np.abs(fr['max_real_1_per_s'].to_numpy() - V[i, j, k])):.2g} 1/s)")


def dense_columns(args, p, ds, b):
    """Crossings on sampled (a_y, speed) columns of the surface vs the dense column (every
    fine p_c node through the same chunk function)."""
    spec = SweepSpec.from_toml(p)
    ax, _ = fine_axes(spec)
    job = Job(spec.name, spec.load_model().to_toml(), spec.analysis, spec.options, ax)
    xs, ys, zs = (np.asarray(ax[a]) for a in ("config_ay_m", "chamber_pressure_pa", "speed_hz"))
    ny, nz = len(ys), len(zs)
    fr = ds.frame.drop_duplicates("point_id")  # a point's mode rows share it
    mixed = fr.groupby(["i_config_ay_m", "i_speed_hz"])["point_stable"].nunique()
    cand = mixed[mixed > 1].index.to_list()
    pick = [cand[q] for q in np.linspace(0, len(cand) - 1, args.columns).round().astype(int)]
    w0, c0 = time.perf_counter(), time.process_time()
    same, worst = 0, 0.0
    for i, k in pick:
        t = run_chunk(job, 0, 0, 0, [(i * ny + j) * nz + k for j in range(ny)])
        zc = point_values(t)
        st = np.where(np.isfinite(zc), (zc >= 0).astype(int), 2)
        kd = np.flatnonzero(st[1:] != st[:-1])
        sub = fr[(fr["i_config_ay_m"] == i) & (fr["i_speed_hz"] == k)]
        jj = sub["i_chamber_pressure_pa"].to_numpy()
        seen = np.zeros(ny, bool)
        seen[jj] = True
        zz = np.full(ny, np.nan)
        zz[jj] = sub["max_real_1_per_s"].to_numpy()
        sb = np.where(np.isfinite(zz), (zz >= 0).astype(int), 2)
        kb = np.flatnonzero((sb[1:] != sb[:-1]) & seen[1:] & seen[:-1])
        ok = list(kd) == list(kb)
        same += ok
        zk = [q for q in kd if st[q] != 2 and st[q + 1] != 2]
        want = np.sort([ys[q] + (ys[q + 1] - ys[q]) * zc[q] / (zc[q] - zc[q + 1]) for q in zk])
        got = np.unique(b[(np.abs(b["config_ay_m"] - xs[i]) <= 1e-15)
                          & (b["speed_hz"] == zs[k])]["chamber_pressure_pa"])
        if len(want) and len(got) == len(want):
            worst = max(worst, float(np.max(np.abs(got - want))))
        print(f"  column a_y = {xs[i] * 1e3:+.4f} mm, {zs[k]:.3f} Hz: dense crossings between "
              f"nodes {kd.tolist()}, the surface's {kb.tolist()} -> "
              f"{'identical' if ok else 'DIFFERENT'}; contour p_c "
              f"{np.round(got / 1e3, 3).tolist()} kPa vs dense "
              f"{np.round(want / 1e3, 3).tolist()} kPa")
    print(f"  dense columns: {same} of {len(pick)} identical; {len(pick)} x {ny} points, "
          f"{time.perf_counter() - w0:.1f} s wall, {time.process_time() - c0:.1f} s CPU; "
          f"largest contour difference {worst:.3g} Pa")


if __name__ == "__main__":
    main()
