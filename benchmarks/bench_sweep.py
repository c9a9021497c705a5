"""Sweep throughput (issue 9): per-point cost against the bare C++ calls, points/s at 1 and 2
workers and the parallel efficiency, time to first result on a running cluster, a 10⁴-point
Fig. 9 map, the adaptive Fig. 9 boundary against the full grid at equal resolution, the
bookkeeping cost per chunk at 10⁴ chunks, and a projection to 10⁶ points.

Wall time and CPU time are printed side by side (a loaded machine stretches the wall time, not
the CPU time), with the load average before and after. One BLAS/OpenMP thread per worker.
    python benchmarks/bench_sweep.py [--quick]
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import statistics  # noqa: E402
import tempfile  # noqa: E402
import threading  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn import _core  # noqa: E402
from rotordyn.analysis.assembly import Assembled  # noqa: E402
from rotordyn.sweep import run_sweep  # noqa: E402
from rotordyn.sweep.work import Job, run_chunk  # noqa: E402

FIG9 = """
schema = "rotordyn/sweep/1"
name = "{name}"
model = "paper-rig"
analysis = "{analysis}"
chunk_size = {chunk}

[grid]
config_ay_m = {{start = -2.5e-3, stop = 2.5e-3, num = {nx}}}
chamber_pressure_pa = {{start = 0.0, stop = 0.3e6, num = {ny}}}
speed_hz = 50.0
{extra}
"""


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def spec(d, name, nx, ny, chunk=50, analysis="stability", extra=""):
    p = Path(d) / f"{name}.toml"
    p.write_text(FIG9.format(name=name, nx=nx, ny=ny, chunk=chunk, analysis=analysis,
                             extra=extra))
    return p


def timed(fn):
    w0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - w0, time.process_time() - c0, out


def per_point(n_pts: int, repeats: int):
    """The sweep's chunk code against a bare loop of the same C++ calls (equilibrium
    continued along p_c, K_H/D_H, eigen-analysis) on one line of Fig. 9, interleaved."""
    s = rd.models.paper_rig()
    pcs = list(np.linspace(0.0, 0.3e6, n_pts))
    job = Job("b", s.to_toml(), "stability", {}, {"config_ay_m": [-1.85e-3],
                                                   "chamber_pressure_pa": pcs,
                                                   "speed_hz": [50.0]})
    asm = Assembled(s)
    M, C, G, K = (np.asarray(x) for x in (asm.model.M, asm.model.C, asm.model.G, asm.model.K))
    a = asm.config_vector(-1.85e-3)
    w = 2 * np.pi * 50.0
    xy, rot = asm.rotor.xy_pairs(), asm.rotor.rot_pairs()

    def bare():
        solver = _core.SystemSolver(asm.model)
        o = _core.EquilibriumOptions()
        r0 = np.zeros(0)
        for p in pcs:
            e = solver.equilibrium(w, p, a, r0, o)
            r0 = np.asarray(e.r) if e.status == "ok" else np.zeros(0)
            lin = solver.linearize(np.asarray(e.r), np.zeros(asm.n), w)
            _core.modal(M, C + w * G + np.asarray(lin.DH), K + np.asarray(lin.KH), xy, asm.n,
                        True, rot)

    from rotordyn.analysis.linear import FD_REL_STEP
    from rotordyn.sweep.points import equilibrium_options

    sleeve = [i for bc in asm.bearings for i in bc.sleeve]

    def batch():  # the one C++ call a chunk makes (issue 22: the honest baseline)
        solver = _core.SystemSolver(asm.model)
        return _core.stability_batch(
            solver, np.full(n_pts, w), np.array(pcs), np.tile(a, (n_pts, 1)),
            [1] + [0] * (n_pts - 1), equilibrium_options({}), 0, False, FD_REL_STEP, xy, rot,
            sleeve)

    run_chunk(job, 0, 0, 3)
    batch()
    sw, bw, cw = [], [], []
    for _ in range(repeats):
        sw.append(timed(lambda: run_chunk(job, 0, 0, n_pts))[:2])
        bw.append(timed(bare)[:2])
        cw.append(timed(batch)[:2])
    med = lambda xs, k: statistics.median(x[k] for x in xs) / n_pts * 1e3  # noqa: E731
    return med(sw, 0), med(sw, 1), med(bw, 0), med(bw, 1), med(cw, 0), med(cw, 1)


def first_result(d, client_addr):
    sp = spec(d, "first", 5, 5, chunk=5)
    out = Path(d) / "first"
    t0 = time.perf_counter()
    th = threading.Thread(target=run_sweep, args=(sp, out), kwargs={"scheduler": client_addr,
                                                                     "progress": False})
    th.start()
    log = out / "_chunks.jsonl"
    first = None
    while th.is_alive() or first is None:
        if first is None and log.exists() and '"op": "file"' in log.read_text():
            first = time.perf_counter() - t0
        if not th.is_alive() and first is None:
            first = time.perf_counter() - t0
        time.sleep(0.005)
    th.join()
    return first


def bookkeeping(d, n_chunks: int):
    """Store.add of n_chunks one-row chunks (the driver's work per chunk: write, fsync, log,
    compaction), timed per decile."""
    import pyarrow as pa

    from rotordyn.sweep.execution import group_size
    from rotordyn.sweep.store import Store

    hdr = {"sweep_id": "bk", "spec_hash": "x", "model_hash": "y"}
    st = Store(Path(d) / "bk", hdr, group=group_size(n_chunks))
    t = pa.table({"point_id": pa.array([0], pa.int64()), "v": pa.array([1.0])})
    times = []
    for c in range(n_chunks):
        t0 = time.perf_counter()
        st.add(c, t, {"ok": 1, "failed": 0, "unstable": 0}, n_chunks)
        times.append(time.perf_counter() - t0)
    st.close()
    dec = [1e3 * float(np.mean(times[i * n_chunks // 10:(i + 1) * n_chunks // 10]))
           for i in range(10)]
    return dec, len(list((Path(d) / "bk").glob("*.parquet")))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="smaller grids (a smoke run)")
    args = ap.parse_args()
    q = args.quick
    print(f"load average before: {load()} (2-core machine shared with other work: wall "
          "times are noisy, CPU times less so)")
    with tempfile.TemporaryDirectory() as d:
        sw_w, sw_c, b_w, b_c, c_w, c_c = per_point(60 if q else 200, 3)
        print(f"per point (Fig. 9 line, stability): sweep {sw_w:.3f} ms wall / {sw_c:.3f} ms "
              f"CPU; the chunk's one C++ call (stability_batch) {c_w:.3f} / {c_c:.3f} ms: "
              f"ratio {sw_c / c_c:.2f} (CPU), {sw_w / c_w:.2f} (wall), goal <= 1.1; a Python "
              f"loop of three C++ calls {b_w:.3f} / {b_c:.3f} ms: ratio {sw_c / b_c:.2f} (CPU)")

        n1 = (10, 10) if q else (20, 20)
        res = {}
        for name, kw in (("threads=1", {"threads": 1}), ("threads=2", {"threads": 2})):
            sp = spec(d, name.replace("=", ""), *n1, chunk=25)
            w, c, _ = timed(lambda: run_sweep(sp, Path(d) / name, progress=False, **kw))
            res[name] = (n1[0] * n1[1] / w, c)
            print(f"{name}: {n1[0] * n1[1]} points in {w:.2f} s wall, {c:.2f} s CPU "
                  f"(driver process) -> {n1[0] * n1[1] / w:.0f} points/s")
        eff = res["threads=2"][0] / (2 * res["threads=1"][0])
        print(f"parallel efficiency, 2 threads: {100 * eff:.0f} % (goal >= 85 % on 2 free "
              "cores)")

        from dask.distributed import Client, LocalCluster

        t0 = time.perf_counter()
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
        print(f"LocalCluster(2 processes) start: {time.perf_counter() - t0:.2f} s")
        try:
            sp = spec(d, "p1", *n1, chunk=25)
            w, c, _ = timed(lambda: run_sweep(sp, Path(d) / "p2", scheduler=cluster.scheduler_address,
                                              progress=False))
            eff_p = n1[0] * n1[1] / w / (2 * res["threads=1"][0])
            print(f"2 worker processes (running cluster): {n1[0] * n1[1] / w:.0f} points/s, "
                  f"efficiency vs 1 thread {100 * eff_p:.0f} %")
            print(f"time to first result, running cluster: "
                  f"{first_result(d, cluster.scheduler_address):.2f} s (goal <= 2 s)")
            nx = 30 if q else 100
            sp = spec(d, "fig9", nx, nx, chunk=100)
            w, c, r = timed(lambda: run_sweep(sp, Path(d) / "fig9",
                                              scheduler=cluster.scheduler_address,
                                              progress=False))
            print(f"Fig. 9 map {nx}x{nx} = {nx * nx} points on 2 processes: {w:.1f} s wall "
                  f"(goal <= 15 s for 10^4), {r.counts}, "
                  f"{len(list((Path(d) / 'fig9').glob('*.parquet')))} files")
        finally:
            client.close()
            cluster.close()

        res_b = 101 if q else 401
        coarse = 26 if not q else 26
        sp = spec(d, "bnd", coarse, coarse, chunk=50, analysis="boundary",
                  extra=f'[options]\nx = "config_ay_m"\ny = "chamber_pressure_pa"\n'
                        f"resolution = {res_b}\n")
        w, c, r = timed(lambda: run_sweep(sp, Path(d) / "bnd", threads=2, progress=False))
        n_eval = r.manifest["n_points"]
        print(f"adaptive boundary at {res_b}x{res_b}: {n_eval} points evaluated vs "
              f"{res_b * res_b} for the full grid: {res_b * res_b / n_eval:.1f}x fewer "
              f"(goal >= 20x), {w:.1f} s wall on 2 threads")

        nb = 1000 if q else 10000
        dec, nfiles = bookkeeping(d, nb)
        print(f"bookkeeping per chunk over {nb} chunks (ms, by decile): "
              + " ".join(f"{x:.2f}" for x in dec) + f"; {nfiles} files")
        # projection to 10^6 points on 2 workers from the measured per-point and per-chunk costs
        per_pt = sw_c / 1e3
        chunk = 250
        n_ch = 10**6 // chunk
        t_proj = 10**6 * per_pt / (2 * max(eff, 0.5)) + n_ch * np.mean(dec) / 1e3
        print(f"projection, 10^6 points, chunk {chunk} ({n_ch} chunks), 2 workers: "
              f"{t_proj / 60:.1f} min ({10**6 * per_pt / 60:.1f} CPU-min of points + "
              f"{n_ch * np.mean(dec) / 1e3:.0f} s of bookkeeping)")
    print(f"load average after: {load()}")


if __name__ == "__main__":
    main()
