"""Run a sweep: expand the grid into fixed chunks, skip the chunks the directory already holds
(verified), compute the rest on threads in this process (``threads=N``), on a LocalCluster
of worker processes (default) or on a running dask cluster (``scheduler="tcp://..."``), and
write each chunk as it arrives (:mod:`rotordyn.sweep.store`).

Before the first task every dask worker is checked (same rotordyn version, build and core
library, else an InputError naming the worker, within ``worker_timeout`` s). A chunk's rows do
not depend on where or when it ran (see :mod:`rotordyn.sweep.work`), so 1, 2 or N workers,
processes or threads, and any resume give the same dataset bit for bit.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

from rotordyn._common import validate as v
from rotordyn._common.info import __version__, build_info
from rotordyn.sweep.spec import SweepSpec
from rotordyn.sweep.store import Store, part_metadata, read_manifest, task_key
from rotordyn.sweep.boundary import run_boundary
from rotordyn.sweep.dataset import open_dataset
from rotordyn.sweep.execution import (Progress, SweepInterrupted, SweepResult, check_scheduler,
                                      executor, group_size)
from rotordyn.sweep.work import Job, job_schema
from rotordyn.units import unit_of

UNITS = {
    "speed_hz": ("Hz", "spin speed"), "chamber_pressure_pa": ("Pa", "chamber pressure p_c"),
    "config_ay_m": ("m", "housing offset a_y of the active bearing"),
    "config_ax_m": ("m", "housing offset a_x of the active bearing"),
    "journal_bearing": ("", "the bearing whose journal journal_x_m, journal_y_m, config_ay_m "
                            "(when not an axis) and the motion columns describe"),
    "journal_x_m": ("m", "journal x relative to the housing"),
    "journal_y_m": ("m", "journal y relative to the housing"),
    "h_min_m": ("m", "minimum film thickness"), "freq_hz": ("Hz", "damped natural frequency"),
    "eig_real_1_per_s": ("1/s", "eigenvalue real part"),
    "max_real_1_per_s": ("1/s", "largest eigenvalue real part of the point"),
    "amplitude_x_m": ("m", "amplitude of x"), "amplitude_y_m": ("m", "amplitude of y"),
    "value": ("axis units", "threshold value of the varied axis"),
    "whirl_frequency_hz": ("Hz", "whirl frequency at the threshold"),
    "l1": ("1/s", "first Lyapunov coefficient at the crossing (scaled coordinates)"),
    "l1_refined": ("1/s", "l1 on every film grid refined twice (options.grid_check)"),
    "alpha_prime": ("1/s per axis unit", "dRe λ/d(vary) at the crossing"),
    "amplitude_coefficient_m2": ("m² per axis unit",
                                 "leading-order cycle amplitude² per distance from the crossing"),
    "journal_theta_x_rad": ("rad", "journal rotation about x relative to the housing"),
    "journal_theta_y_rad": ("rad", "journal rotation about y relative to the housing"),
    "h_min_z_m": ("m", "axial position of the minimum film (0: mid-plane)"),
    "film_moment_x_n_m": ("N m", "the films' moment on the journal about x (tilt = true)"),
    "film_moment_y_n_m": ("N m", "the films' moment on the journal about y (tilt = true)"),
}
UNITS.update({  # the limit_cycle analysis
    "amplitude_m": ("m", "limit cycle's semi-major axis (largest distance from its mean)"),
    "amplitude_c": ("1", "limit cycle's semi-major axis / clearance"),
    "period_s": ("s", "limit cycle's period"),
    "max_multiplier": ("1", "modulus of the largest non-trivial Floquet multiplier"),
})


def read_dataset(out):
    """The dataset of a sweep directory as one DataFrame (rows in point order)."""
    return open_dataset(out).frame


# -- the sweep ----------------------------------------------------------------------------
def _header(spec: SweepSpec, model_toml: str) -> dict:
    bounds = spec.chunk_bounds()
    return {"sweep_id": spec.name, "analysis": spec.analysis, "spec_hash": spec.hash(),
            "model_hash": hashlib.sha256(model_toml.encode()).hexdigest()[:16],
            "rotordyn": __version__, "build_info": build_info(),
            "axes": spec.ordered_axes, "options": spec.options, "n_points": spec.n_points,
            "n_chunks": len(bounds), "chunk_size": spec.chunk_size,
            "group": group_size(len(bounds), spec.max_files), "spec": spec.source,
            "model": model_toml,
            "units": {**{a: {"units": unit_of(a), "long_name": f"sweep axis {a}"}
                         for a in spec.ordered_axes},
                      **{k: {"units": u, "long_name": n} for k, (u, n) in UNITS.items()}}}


def run_sweep(spec_path, out, *, scheduler: str | None = None, workers: int | None = None,
              threads: int | None = None, resume: bool = True, progress=None,
              worker_timeout: float = 30.0, tls_ca_file=None, tls_cert=None,
              tls_key=None) -> SweepResult:
    """Run (or resume) the sweep of ``spec_path`` into directory ``out``.

    threads : compute on this many threads in this process (no dask); else ``workers`` dask
        worker processes on this machine, or the cluster at ``scheduler``
        (``tcp://HOST:PORT``, or ``tls://HOST:PORT`` with ``tls_ca_file``, ``tls_cert`` and
        ``tls_key``: the CA that signed the cluster's certificates, and this client's
        certificate and key). The cluster is trusted completely: dask deserialises (runs)
        what it receives; see docs/reliability.md.
    progress : True for a progress line on stderr, None for one only on a terminal, False
        for none.
    KeyboardInterrupt becomes :class:`SweepInterrupted` after the directory is left
    consistent (running again resumes).
    """
    # a spec file or built-in name; or a checked SweepSpec (rotordyn.control.robust)
    spec = spec_path if isinstance(spec_path, SweepSpec) else SweepSpec.from_toml(spec_path)
    scheduler = check_scheduler(scheduler, tls_ca_file, tls_cert, tls_key)
    if threads is not None:
        v.integer("threads", threads, lo=1, hi=1024)
    if workers is not None:
        v.integer("workers", workers, lo=1, hi=1024)
    system = spec.load_model()
    model_toml = system.to_toml()
    header = _header(spec, model_toml)
    n_chunks = header["n_chunks"]
    if spec.analysis == "boundary":
        return run_boundary(spec, header, model_toml, out, scheduler=scheduler,
                            workers=workers, threads=threads, resume=resume,
                            progress=progress, worker_timeout=worker_timeout)
    job = Job(spec.name, model_toml, spec.analysis, spec.options, spec.ordered_axes)
    store = Store(out, header, resume=resume, group=header["group"],
                  schema=job_schema(job, system), spec_aliases=(spec.legacy_hash(),))
    try:
        bounds = spec.chunk_bounds()
        store.compact_complete(n_chunks)
        done = store.done_chunks()
        prev = store.chunk_entries()
        counts0 = {k: sum(c[k] for c in prev.values()) for k in ("ok", "failed", "unstable")}
        todo = [(cid, lo, hi) for cid, (lo, hi) in enumerate(bounds) if cid not in done]
        bar = Progress(n_chunks, len(done), counts0,
                       enabled=None if progress is None else bool(progress))
        if todo:
            job.key = task_key(header)
            job.meta = part_metadata(header)
            ex = None
            try:
                n = workers or min(len(todo), os.cpu_count() or 1)
                ex = executor(scheduler, n, threads, worker_timeout, bar)
                for cid, (table, cnt) in ex.map(job, todo):
                    store.add(cid, table, cnt, n_chunks)
                    bar.update(cnt)
            except KeyboardInterrupt:
                bar.close()
                raise SweepInterrupted(
                    f"interrupted: {len(store.done_chunks())}/{n_chunks} chunks saved in "
                    f"{str(out)!r}; run the same command again to resume") from None
            finally:
                if ex is not None:
                    ex.close()
        bar.close()
        final = store.chunk_entries()
        counts = {k: sum(c[k] for c in final.values()) for k in ("ok", "failed", "unstable")}
        return SweepResult(Path(out), {"format": "", **header}, len(final), n_chunks, counts,
                           tuple(store.dropped))
    finally:
        store.close()


def result_of(out) -> SweepResult:
    """The state of an existing sweep directory."""
    m, entries = read_manifest(out)
    done = {}
    for e in entries:
        for c, cnt in zip(range(e["lo"], e["hi"] + 1), e["counts"]):
            done[c] = cnt
    counts = {k: sum(c[k] for c in done.values()) for k in ("ok", "failed", "unstable")}
    return SweepResult(Path(out), m, len(done), m["n_chunks"], counts)


def manifest_json(res: SweepResult) -> str:
    return json.dumps({"sweep_id": res.manifest.get("sweep_id"), "out": str(res.out),
                       "chunks_done": res.done, "n_chunks": res.n_chunks, **res.counts,
                       "dropped": [list(d) for d in res.dropped]})
