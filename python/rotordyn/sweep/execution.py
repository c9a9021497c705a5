"""How a sweep's chunks are executed and reported, shared by the grid runner
(:mod:`.runner`) and the adaptive boundary (:mod:`.boundary`): the executors (threads of this
process, or dask — a LocalCluster or an existing cluster, whose workers are checked to run this
very build), the progress line, the interruption and the finished-sweep result."""

from __future__ import annotations

import math
import os
import re
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from rotordyn.errors import InputError
from rotordyn.sweep.dataset import open_dataset
from rotordyn.sweep.work import Job, run_chunk


# The wall time below which `--workers N` keeps a map on N threads of the driver instead of
# starting a LocalCluster: the start and worker check (1.0-1.4 s on the 2-core machine, idle
# or loaded), the workers' first imports and model builds (~1.5 CPU-s each, competing with
# the driver on the same cores) and the close (0.3 s); docs/performance.md.
CLUSTER_START_S = 3.0


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
    # files a resume found damaged, unlogged or unfinished and removed, (name, why): their
    # chunks were computed again
    dropped: tuple = ()

    @property
    def complete(self) -> bool:
        return self.done == self.n_chunks

    def to_frame(self):
        """The whole dataset (as :func:`rotordyn.sweep.open`)."""
        return open_dataset(self.out).frame


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


# -- the scheduler's address -----------------------------------------------------------
CONNECT_TIMEOUT = 5.0   # s for the TCP connection to a scheduler (a refused port fails at once)
HANDSHAKE_TIMEOUT = 10.0  # s for dask's own connection once the port answers
_ADDR = re.compile(r"(?:(?P<proto>[a-z]+)://)?(?P<host>\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+)"
                   r":(?P<port>[0-9]{1,5})\Z")


@dataclass(frozen=True)
class Scheduler:
    """A checked scheduler address, with dask's TLS security for ``tls://``."""

    address: str
    host: str
    port: int
    security: object = None


def check_scheduler(address, tls_ca_file=None, tls_cert=None, tls_key=None):
    """The ``--scheduler`` address checked before anything starts: ``tcp://HOST:PORT``,
    ``tls://HOST:PORT`` or ``HOST:PORT`` (tcp); ``tls://`` needs the CA file, the client
    certificate and its key (dask's mutual TLS, :class:`distributed.security.Security`).
    Returns a :class:`Scheduler`, or None for no address (a LocalCluster)."""
    tls = {"tls_ca_file": tls_ca_file, "tls_cert": tls_cert, "tls_key": tls_key}
    if address is None:
        given = [k for k, val in tls.items() if val is not None]
        if given:
            raise InputError(f"{given[0]}: TLS options need a tls:// scheduler address")
        return None
    m = _ADDR.match(address) if isinstance(address, str) else None
    if m is None or not 0 < int(m["port"]) < 65536 or (m["proto"] or "tcp") not in ("tcp",
                                                                                    "tls"):
        raise InputError(f"scheduler: expected tcp://HOST:PORT or tls://HOST:PORT (port "
                         f"1..65535), got {address!r}")
    proto, host, port = m["proto"] or "tcp", m["host"].strip("[]"), int(m["port"])
    security = None
    if proto == "tls":
        for k, val in tls.items():
            if val is None:
                raise InputError(f"{k}: a tls:// scheduler needs tls_ca_file, tls_cert and "
                                 "tls_key (CLI: --tls-ca-file, --tls-cert, --tls-key)")
            if not Path(val).is_file():
                raise InputError(f"{k}: no such file {str(val)!r}")
        from distributed.security import Security

        security = Security(tls_ca_file=str(tls_ca_file), tls_client_cert=str(tls_cert),
                            tls_client_key=str(tls_key), require_encryption=True)
    else:
        given = [k for k, val in tls.items() if val is not None]
        if given:
            raise InputError(f"{given[0]}: TLS options need a tls:// scheduler address, got "
                             f"{address!r}")
    return Scheduler(f"{proto}://{m['host']}:{port}", host, port, security)


def _reachable(s: Scheduler) -> None:
    """A plain TCP connection first: a closed port fails at once, a silent one within
    CONNECT_TIMEOUT, instead of dask retrying for its whole timeout."""
    import socket

    try:
        socket.create_connection((s.host, s.port), timeout=CONNECT_TIMEOUT).close()
    except socket.gaierror as exc:
        raise InputError(f"scheduler: cannot connect to {s.address!r} (unknown host: "
                         f"{exc.strerror or exc})") from None
    except TimeoutError:
        raise InputError(f"scheduler: cannot connect to {s.address!r} (no answer within "
                         f"{CONNECT_TIMEOUT:g} s)") from None
    except OSError as exc:
        raise InputError(f"scheduler: cannot connect to {s.address!r} "
                         f"({exc.strerror or exc})") from None


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
    from rotordyn._common.threads import core_calls

    with core_calls():  # Eigen's thread count is not changed under the chunk's batches
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


class Threads:
    """Chunks on a thread pool of this process (the C++ core releases the GIL)."""

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


class Dask:
    """Chunks on dask: a LocalCluster of worker processes, or the cluster at ``scheduler``."""

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
            if not isinstance(scheduler, Scheduler):
                scheduler = check_scheduler(scheduler)
            progress.status(f"connecting to {scheduler.address}")
            _reachable(scheduler)
            try:
                self.client = Client(scheduler.address, timeout=f"{HANDSHAKE_TIMEOUT}s",
                                     security=scheduler.security)
            except (OSError, TimeoutError) as exc:
                raise InputError(f"scheduler: cannot connect to {scheduler.address!r} "
                                 f"({exc})") from None
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
                # No dashboard, and the scheduler's HTTP endpoints on a free loopback port:
                # with dashboard_address=None dask still binds them to port 8787, so a
                # second sweep running at the same time on the machine met "port 8787 is
                # already in use" (a warning, then a retry on another port).
                self.cluster = LocalCluster(n_workers=workers, threads_per_worker=1,
                                            processes=True, dashboard_address=None,
                                            scheduler_kwargs={"dashboard_address":
                                                              "127.0.0.1:0"},
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


class StartingCluster:
    """A LocalCluster started only when the map is worth it, its start overlapping the
    driver's own work. At the first ``map``, ``workers`` threads of this process compute
    chunks (the C++ core releases the GIL). The time the rest would take on those threads is
    estimated as chunks left × a chunk's time / threads, from a thread's second chunk (its
    first also builds the model: 0.3 s against 0.03 s on the Fig. 9 map), or from the first
    chunk done when even that bound is short: if it is below :data:`CLUSTER_START_S`, the
    driver finishes the map itself and says so (on a
    map of seconds the processes' start, imports, transfers and close cost more than they
    give: measured in docs/performance.md); otherwise the main thread starts the cluster
    (SIGINT ignored while the worker processes are spawned, as in :class:`Dask`: Ctrl-C
    reaches only the driver, which stops the workers itself) while the threads go on, and once
    the workers are up and checked the threads finish the chunks they hold and the chunks not
    yet begun go to the workers. A chunk's rows do not depend on where it ran: the dataset is
    the same as on the workers alone. ``local`` counts the chunks the driver computed;
    ``cluster`` tells whether the workers were started."""

    def __init__(self, workers: int, timeout: float, progress):
        self.workers, self.timeout, self.progress = workers, timeout, progress
        self.dask = None
        self.local = 0
        self.cluster = False

    def _started(self) -> bool:
        """The workers are up and checked (the driver's threads stop taking chunks)."""
        return self.dask is not None

    def _worth_a_cluster(self, seconds_left: float) -> bool:
        """Start the workers when the driver's threads would need longer than their start."""
        return seconds_left > CLUSTER_START_S

    def _overlap(self, job, tasks):
        """Compute tasks on the driver's threads, starting the cluster if worth it: a
        generator of (chunk id, result) whose return value is the index of the first task
        not begun (the workers' share)."""
        import queue
        import threading

        lock = threading.Lock()
        state = {"next": 0, "stop": False}
        done: queue.Queue = queue.Queue()

        def work():
            first = True
            while True:
                with lock:
                    if state["stop"] or self._started() or state["next"] >= len(tasks):
                        done.put(None)
                        return
                    t = tasks[state["next"]]
                    state["next"] += 1
                t0 = time.perf_counter()
                try:
                    r = _task(job, *t)
                except BaseException as exc:  # noqa: BLE001 - re-raised in the driver
                    with lock:
                        state["stop"] = True
                    done.put(("error", exc))
                    done.put(None)
                    return
                dt = time.perf_counter() - t0
                with lock:
                    self.local += 1
                done.put((t[0], r, dt, first))
                first = False

        n = max(1, min(self.workers, len(tasks)))
        threads = [threading.Thread(target=work, name=f"rotordyn-sweep-driver-{i}",
                                    daemon=True) for i in range(n)]
        self.progress.status(f"computing here on {n} threads")
        for th in threads:
            th.start()
        live, decided = n, False
        try:
            while live:
                item = done.get()
                if item is None:
                    live -= 1
                    continue
                if item[0] == "error":
                    raise item[1]
                yield item[0], item[1]
                if decided:
                    continue
                with lock:
                    rest = len(tasks) - state["next"]
                left = rest * item[2] / n
                if item[3] and self._worth_a_cluster(left):
                    continue  # a first chunk (model build included): wait for a warm one
                decided = True
                if self._worth_a_cluster(left):
                    self.progress.status(f"computing here while {self.workers} worker "
                                         f"processes start")
                    self.cluster = True
                    dask = Dask(None, self.workers, self.timeout, self.progress)
                    with lock:
                        self.dask = dask
                else:
                    self.progress.status(
                        f"{n} threads of this process: the map's remaining ~{left:.1f} s is "
                        f"less than a LocalCluster's start (~{CLUSTER_START_S:g} s)")
            return state["next"]
        finally:
            with lock:
                state["stop"] = True
            for th in threads:
                th.join()

    def map(self, job, tasks):
        tasks = list(tasks)
        i = 0
        if not self._started() and tasks:
            i = yield from self._overlap(job, tasks)
        if i < len(tasks):
            if self.dask is None:  # the threads stopped before the decision (tests force it)
                self.cluster = True
                self.dask = Dask(None, self.workers, self.timeout, self.progress)
            yield from self.dask.map(job, tasks[i:])

    def close(self):
        if self.dask is not None:
            self.dask.close()


def executor(scheduler, workers: int, threads: int | None, timeout: float, progress):
    """The executor of a sweep: threads of this process (``threads``), the cluster at
    ``scheduler``, else a LocalCluster of ``workers`` processes whose start overlaps the
    driver's own work (:class:`StartingCluster`)."""
    if threads is not None:
        return Threads(threads)
    if scheduler:
        return Dask(scheduler, workers, timeout, progress)
    return StartingCluster(workers, timeout, progress)


def group_size(n_chunks: int, max_files: int = 128) -> int:
    """Chunks per compacted file: at most ``max_files`` files whatever the size."""
    return max(1, math.ceil(n_chunks / max_files))
