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
import math
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import rotordyn
from rotordyn.errors import InputError
from rotordyn.sweep.spec import SweepSpec
from rotordyn.sweep.store import Store, read_manifest
from rotordyn.sweep.work import Job, run_chunk

UNITS = {
    "speed_hz": ("Hz", "spin speed"), "chamber_pressure_pa": ("Pa", "chamber pressure p_c"),
    "config_ay_m": ("m", "housing offset a_y of the active bearing"),
    "config_ax_m": ("m", "housing offset a_x of the active bearing"),
    "journal_x_m": ("m", "journal x relative to the housing"),
    "journal_y_m": ("m", "journal y relative to the housing"),
    "h_min_m": ("m", "minimum film thickness"), "freq_hz": ("Hz", "damped natural frequency"),
    "eig_real_1_per_s": ("1/s", "eigenvalue real part"),
    "max_real_1_per_s": ("1/s", "largest eigenvalue real part of the point"),
    "amplitude_x_m": ("m", "amplitude of x"), "amplitude_y_m": ("m", "amplitude of y"),
    "value": ("axis units", "threshold value of the varied axis"),
    "whirl_frequency_hz": ("Hz", "whirl frequency at the threshold"),
}


class SweepInterrupted(Exception):
    """Ctrl-C: the chunks written so far are kept; running again resumes."""


@dataclass(frozen=True)
class SweepResult:
    """A finished (or partly finished) sweep directory."""

    out: Path
    manifest: dict
    done: int
    n_chunks: int
    counts: dict

    @property
    def complete(self) -> bool:
        return self.done == self.n_chunks

    def to_frame(self):
        """The whole dataset (as :func:`rotordyn.sweep.open`)."""
        from rotordyn.sweep.dataset import open_dataset

        return open_dataset(self.out).frame


def read_dataset(out):
    """The dataset of a sweep directory as one DataFrame (rows in point order)."""
    from rotordyn.sweep.dataset import open_dataset

    return open_dataset(out).frame


# -- worker check -------------------------------------------------------------------------
_PROBE_SRC = '''
def probe():
    try:
        import hashlib, rotordyn
        from rotordyn import _core
        with open(_core.__file__, "rb") as fh:
            core = hashlib.sha256(fh.read()).hexdigest()[:16]
        return {"version": rotordyn.__version__, "build": _core.build_info(), "core": core}
    except BaseException as exc:
        return {"error": type(exc).__name__ + ": " + str(exc)}
'''


def _probe_function():
    """A probe defined outside any importable module, so that cloudpickle ships it by value
    and a worker without rotordyn can still run it (and say so)."""
    ns: dict = {"__name__": "__rotordyn_probe__"}
    exec(compile(_PROBE_SRC, "<rotordyn-probe>", "exec"), ns)
    return ns["probe"]


def local_identity() -> dict:
    """This process's identity, by the same probe the workers run."""
    return _probe_function()()


def check_workers(client, timeout: float = 30.0) -> int:
    """Every worker of ``client`` has this rotordyn (version, build, core library); returns
    the number of workers. InputError naming the worker otherwise, within ``timeout`` s."""
    t0 = time.monotonic()
    try:
        client.wait_for_workers(1, timeout=timeout)
    except Exception:  # noqa: BLE001 - dask raises TimeoutError subclasses
        raise InputError(f"scheduler: no dask worker joined within {timeout:g} s") from None
    me = local_identity()
    import concurrent.futures as cf

    with cf.ThreadPoolExecutor(1) as ex:
        fut = ex.submit(client.run, _probe_function(), on_error="return")
        try:
            info = fut.result(timeout=max(1.0, timeout - (time.monotonic() - t0)))
        except cf.TimeoutError:
            raise InputError(f"scheduler: the workers did not answer the rotordyn check "
                             f"within {timeout:g} s") from None
    for addr, got in sorted(info.items()):
        if isinstance(got, BaseException):
            got = {"error": f"{type(got).__name__}: {got}"}
        if "error" in got:
            raise InputError(f"worker {addr}: cannot run rotordyn ({got['error']}); install "
                             f"rotordyn {me['version']} in the worker's environment")
        for k in ("version", "build", "core"):
            if got.get(k) != me[k]:
                raise InputError(f"worker {addr}: rotordyn {k} differs from this driver's "
                                 f"({got.get(k)!r} != {me[k]!r}); install the same build")
    return len(info)


# -- progress -----------------------------------------------------------------------------
class Progress:
    """One status line on a terminal: bar, chunks, points ok/failed/unstable, ETA."""

    def __init__(self, n_chunks: int, n_done: int, counts: dict, stream=None, enabled=None):
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.n, self.done0, self.done = n_chunks, n_done, n_done
        self.counts = dict(counts)
        self.t0 = time.monotonic()
        self.last = 0.0
        self.msg = ""

    def status(self, msg: str) -> None:
        self.msg = msg
        self._draw(force=True)

    def update(self, counts: dict) -> None:
        self.done += 1
        for k, val in counts.items():
            self.counts[k] = self.counts.get(k, 0) + val
        self._draw()

    def _draw(self, force=False) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if not force and now - self.last < 0.2 and self.done < self.n:
            return
        self.last = now
        frac = self.done / self.n if self.n else 1.0
        bar = "#" * int(24 * frac) + "." * (24 - int(24 * frac))
        new = self.done - self.done0
        eta = ""
        if new > 0 and self.done < self.n:
            s = (now - self.t0) / new * (self.n - self.done)
            eta = f" ETA {int(s // 60)}m{int(s % 60):02d}s"
        c = self.counts
        line = (f"[{bar}] {self.done}/{self.n} chunks  ok {c.get('ok', 0)} failed "
                f"{c.get('failed', 0)} unstable {c.get('unstable', 0)}{eta}")
        if self.msg and self.done == self.done0:
            line = f"{self.msg} ... {line}"
        self.stream.write("\r" + line[:150].ljust(100))
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self._draw(force=True)
            self.stream.write("\n")
            self.stream.flush()


# -- executors ----------------------------------------------------------------------------
def _task(job: Job, chunk_id: int, lo: int, hi: int, pids=None):
    t = run_chunk(job, chunk_id, lo, hi, pids)
    return t, counts_of(t)


def counts_of(table) -> dict:
    """Points ok / failed / unstable in one chunk's table."""
    import numpy as np
    import pyarrow.compute as pc

    pid = table.column("point_id").to_numpy()
    status = table.column("status").cast("string").to_numpy(zero_copy_only=False)
    bad = status != "ok"
    bad &= status != "contact"
    bad &= status != "no_crossing"
    pts = np.unique(pid)
    failed = np.unique(pid[bad])
    unstable = 0
    if "point_stable" in table.column_names:
        ps = pc.fill_null(table.column("point_stable"), True).to_numpy(zero_copy_only=False)
        unstable = len(np.unique(pid[(~ps) & ~bad]))
    return {"ok": int(len(pts) - len(failed)), "failed": int(len(failed)),
            "unstable": int(unstable)}


class _Threads:
    def __init__(self, n: int):
        import concurrent.futures as cf

        self.ex = cf.ThreadPoolExecutor(max_workers=n, thread_name_prefix="rotordyn-sweep")

    def map(self, job, tasks):
        import concurrent.futures as cf

        futs = {self.ex.submit(_task, job, *t): t[0] for t in tasks}
        try:
            for f in cf.as_completed(futs):
                yield futs[f], f.result()
        finally:
            for f in futs:
                f.cancel()

    def close(self):
        self.ex.shutdown(wait=True, cancel_futures=True)


class _Dask:
    def __init__(self, scheduler, workers, timeout, progress):
        import logging

        from dask.distributed import Client

        # The driver reports failures itself; dask's own logging (tracebacks of closed
        # connections when the sweep is interrupted) is silenced while the sweep runs.
        self._log = logging.getLogger("distributed")
        self._level = self._log.level
        self._log.setLevel(logging.CRITICAL + 10)
        self.cluster = None
        if scheduler:
            progress.status(f"connecting to {scheduler}")
            try:
                self.client = Client(scheduler, timeout=f"{timeout}s")
            except (OSError, TimeoutError) as exc:
                raise InputError(f"scheduler: cannot connect to {scheduler!r} ({exc})") from None
        else:
            from dask.distributed import LocalCluster

            import signal
            import threading

            progress.status(f"starting {workers} worker processes")
            os.environ.setdefault("OMP_NUM_THREADS", "1")
            # Worker processes inherit an ignored SIGINT: Ctrl-C on the terminal reaches the
            # whole process group, and only the driver should act on it (it stops the
            # workers itself); otherwise each worker dies printing its own tracebacks.
            main = threading.current_thread() is threading.main_thread()
            old = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
            try:
                self.cluster = LocalCluster(n_workers=workers, threads_per_worker=1,
                                            processes=True, dashboard_address=None,
                                            silence_logs=logging.CRITICAL)
            finally:
                if main:
                    signal.signal(signal.SIGINT, old)
            self.client = Client(self.cluster)
        try:
            progress.status("checking workers")
            check_workers(self.client, timeout)
        except BaseException:
            self.close()
            raise

    def map(self, job, tasks):
        from dask.distributed import as_completed

        jf = self.client.scatter(job, broadcast=True, hash=False)
        futs = {self.client.submit(_task, jf, *t, key=f"rotordyn-chunk-{job.key}-{t[0]}",
                                   pure=False): t[0] for t in tasks}
        try:
            for f in as_completed(futs):
                yield futs[f], f.result()
        finally:
            self.client.cancel(list(futs))

    def close(self):
        import contextlib

        with contextlib.suppress(Exception):
            self.client.close(timeout=5)
        if self.cluster is not None:
            with contextlib.suppress(Exception):
                self.cluster.close(timeout=5)
        self._log.setLevel(self._level)


# -- the sweep ----------------------------------------------------------------------------
def _header(spec: SweepSpec, model_toml: str) -> dict:
    bounds = spec.chunk_bounds()
    return {"sweep_id": spec.name, "analysis": spec.analysis, "spec_hash": spec.hash(),
            "model_hash": hashlib.sha256(model_toml.encode()).hexdigest()[:16],
            "rotordyn": rotordyn.__version__, "build_info": rotordyn.build_info(),
            "axes": spec.ordered_axes, "options": spec.options, "n_points": spec.n_points,
            "n_chunks": len(bounds), "chunk_size": spec.chunk_size,
            "group": group_size(len(bounds), spec.max_files), "spec": spec.source,
            "model": model_toml,
            "units": {k: {"units": u, "long_name": n} for k, (u, n) in UNITS.items()}}


def group_size(n_chunks: int, max_files: int = 128) -> int:
    """Chunks per compacted file: at most ``max_files`` files whatever the size."""
    return max(1, math.ceil(n_chunks / max_files))


def run_sweep(spec_path, out, *, scheduler: str | None = None, workers: int | None = None,
              threads: int | None = None, resume: bool = True, progress=None,
              worker_timeout: float = 30.0) -> SweepResult:
    """Run (or resume) the sweep of ``spec_path`` into directory ``out``.

    threads : compute on this many threads in this process (no dask); else ``workers`` dask
        worker processes on this machine, or the cluster at ``scheduler``.
    progress : True for a progress line on stderr, None for one only on a terminal, False
        for none.
    KeyboardInterrupt becomes :class:`SweepInterrupted` after the directory is left
    consistent (running again resumes).
    """
    spec = SweepSpec.from_toml(spec_path)
    if threads is not None:
        from rotordyn import _validate as v

        v.integer("threads", threads, lo=1, hi=1024)
    if workers is not None:
        from rotordyn import _validate as v

        v.integer("workers", workers, lo=1, hi=1024)
    system = spec.load_model()
    model_toml = system.to_toml()
    header = _header(spec, model_toml)
    n_chunks = header["n_chunks"]
    if spec.analysis == "boundary":
        from rotordyn.sweep.boundary import run_boundary

        return run_boundary(spec, header, model_toml, out, scheduler=scheduler,
                            workers=workers, threads=threads, resume=resume,
                            progress=progress, worker_timeout=worker_timeout)
    store = Store(out, header, resume=resume, group=header["group"])
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
            job = Job(spec.name, model_toml, spec.analysis, spec.options, spec.ordered_axes)
            job.key = header["spec_hash"]
            job.meta = {"sweep_id": spec.name, "spec_hash": header["spec_hash"],
                        "model_hash": header["model_hash"], "rotordyn": rotordyn.__version__,
                        "units": header["units"]}
            ex = None
            try:
                if threads is not None:
                    ex = _Threads(threads)
                else:
                    n = workers or min(len(todo), os.cpu_count() or 1)
                    ex = _Dask(scheduler, n, worker_timeout, bar)
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
        return SweepResult(Path(out), {"format": "", **header}, len(final), n_chunks, counts)
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
                       "chunks_done": res.done, "n_chunks": res.n_chunks, **res.counts})
