"""Sweep runner determinism and robustness (issue 9 and issue 13): the same sweep with 1 or 2
threads, 2 worker processes, after a resume and after 20+ kill -9 of the driver gives the same
dataset bit for bit (same part files, same SHA-256); a full disk or an unwritable directory is
an InputError naming ``out`` and leaves a resumable directory; Ctrl-C stops with one line."""

import errno
import hashlib
import multiprocessing as mp
import os
import random
import signal
import subprocess
import sys
import time

import pandas as pd
import pytest

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.sweep import run_sweep
from rotordyn.sweep import store as store_mod

SPEC = """
schema = "rotordyn/sweep/1"
name = "t-determinism"
model = "paper-rig"
analysis = "stability"
chunk_size = 2
max_files = 3

[grid]
config_ay_m = [-1.85e-3, -1.0e-3, 0.0]
chamber_pressure_pa = {start = 0.0, stop = 0.25e6, num = 6}
speed_hz = 50.0

[options]
track = false  # chunks of chunk_size points (not whole p_c lines), to test the bookkeeping
"""


def _digest(out) -> dict:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(out.glob("*.parquet"))}


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    d = tmp_path_factory.mktemp("det")
    spec = d / "spec.toml"
    spec.write_text(SPEC)
    res = run_sweep(spec, d / "ref", threads=1)
    assert res.complete
    return spec, d / "ref"


def test_compacted_into_few_files(reference):
    spec, ref = reference
    names = sorted(p.name for p in ref.glob("*.parquet"))
    # 18 points in 9 chunks, at most 3 files: groups of 3 chunks, one row group per chunk
    assert names == ["part-000000-000002.parquet", "part-000003-000005.parquet",
                     "part-000006-000008.parquet"]
    import pyarrow.parquet as pq

    assert pq.ParquetFile(ref / names[0]).num_row_groups == 3


def test_threads_processes_identical(reference, tmp_path, monkeypatch):
    """2 threads, then 2 worker processes (started whatever the map's size), against the
    one-thread reference."""
    _workers_only(monkeypatch)
    spec, ref = reference
    want = _digest(ref)
    assert run_sweep(spec, tmp_path / "t2", threads=2).complete
    assert _digest(tmp_path / "t2") == want
    assert run_sweep(spec, tmp_path / "p2", workers=2).complete
    assert _digest(tmp_path / "p2") == want
    pd.testing.assert_frame_equal(sw.open(tmp_path / "p2").frame, sw.open(ref).frame,
                                  check_exact=True)


def test_workers_while_port_8787_is_taken(reference, tmp_path, monkeypatch):
    """A --workers sweep while another program (e.g. a second sweep, or a dask dashboard)
    holds port 8787: the LocalCluster's HTTP endpoints go to a free port, with no warning
    (warnings are errors in this suite) and the same rows. Before: dask bound them to 8787
    even without a dashboard, warned 'port 8787 is already in use' and retried."""
    import socket

    _workers_only(monkeypatch)  # a cluster, small map or not
    spec, ref = reference
    holder = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    try:
        holder.bind(("0.0.0.0", 8787))
    except OSError:
        holder.close()
        pytest.skip("port 8787 is in use by another program")
    try:
        holder.listen(1)
        assert run_sweep(spec, tmp_path / "p", workers=1, progress=False).complete
    finally:
        holder.close()
    assert _digest(tmp_path / "p") == _digest(ref)


def test_driver_then_workers_identical(reference, tmp_path, monkeypatch):
    """--workers: the driver's threads compute chunks while the LocalCluster starts, then
    hand the chunks not yet begun to the workers. Forced here to start the cluster (the map
    is small) and to stop the driver's 2 threads after 2 chunks (3 if both held one): the rest
    run on the workers, and the dataset equals the one-thread reference bit for bit."""
    from rotordyn.sweep import execution

    seen = []

    class TwoFirst(execution.StartingCluster):
        def _worth_a_cluster(self, seconds_left):
            return True

        def _started(self):  # the driver's threads stop after 2 chunks, whatever the start
            return self.local >= 2

        def close(self):
            seen.append((self.local, self.cluster))
            super().close()

    monkeypatch.setattr(execution, "StartingCluster", TwoFirst)
    spec, ref = reference
    assert run_sweep(spec, tmp_path / "h", workers=2, progress=False).complete
    assert len(seen) == 1 and seen[0][0] in (2, 3) and seen[0][1]
    assert _digest(tmp_path / "h") == _digest(ref)


def _workers_only(monkeypatch):
    """--workers with every chunk on the worker processes (the cluster started first)."""
    from rotordyn.sweep import execution

    class WorkersOnly(execution.StartingCluster):
        def _overlap(self, job, tasks):
            self.dask = execution.Dask(None, self.workers, self.timeout, self.progress)
            self.cluster = True
            return 0
            yield  # a generator, as the method it replaces

    monkeypatch.setattr(execution, "StartingCluster", WorkersOnly)


def test_small_map_stays_on_the_driver(reference, tmp_path, monkeypatch):
    """--workers 2 on a map whose remaining time on the driver's threads is below a
    LocalCluster's start: no worker process is started, every chunk runs on the driver's 2
    threads, the dataset is the reference's."""
    from rotordyn.sweep import execution

    seen = []

    class Watch(execution.StartingCluster):
        def close(self):
            seen.append((self.local, self.cluster))
            super().close()

    monkeypatch.setattr(execution, "StartingCluster", Watch)
    spec, ref = reference
    assert run_sweep(spec, tmp_path / "s", workers=2, progress=False).complete
    assert seen == [(9, False)]
    assert _digest(tmp_path / "s") == _digest(ref)


@pytest.mark.parametrize("start_s, cluster", [(0.5, True), (20.0, False)])
def test_cluster_decision_from_the_warm_chunks(monkeypatch, start_s, cluster):
    """The decision on timed fake chunks: 100 tasks on 2 threads, a first chunk per thread of
    0.3 s (the model build) then 0.02 s each, i.e. ~1 s left on the threads after the first
    warm chunk (~15 s if judged from a first chunk): a start cost of 0.5 s starts the cluster
    (which takes the chunks not yet begun), one of 20 s keeps the map on the driver. Every
    chunk is yielded exactly once either way."""
    import threading

    from rotordyn.sweep import execution

    warm = threading.local()

    def task(job, cid, lo, hi):
        time.sleep(0.02 if getattr(warm, "done", False) else 0.3)
        warm.done = True
        return cid, {}

    class FakeDask:
        def __init__(self, *a):
            self.closed = False

        def map(self, job, tasks):
            for t in tasks:
                yield t[0], (t[0], {})

        def close(self):
            self.closed = True

    class Progress:
        def status(self, text):
            pass

    monkeypatch.setattr(execution, "_task", task)
    monkeypatch.setattr(execution, "Dask", FakeDask)
    monkeypatch.setattr(execution, "CLUSTER_START_S", start_s)
    ex = execution.StartingCluster(2, 30.0, Progress())
    tasks = [(i, i, i + 1) for i in range(100)]
    got = [cid for cid, _ in ex.map(None, tasks)]
    ex.close()
    assert sorted(got) == list(range(100))
    assert ex.cluster is cluster
    if cluster:
        assert 2 < ex.local < 60  # a warm chunk was awaited, then the rest went to the cluster
    else:
        assert ex.local == 100


def test_resume_identical(reference, tmp_path):
    """Same dataset after a resume from any subset of chunks (parts removed, a compacted
    file damaged, a torn last log line)."""
    spec, ref = reference
    out = tmp_path / "r"
    run_sweep(spec, out, threads=2)
    files = sorted(out.glob("part-*.parquet"))
    files[1].write_bytes(files[1].read_bytes()[:-10])
    files[2].unlink()
    with open(out / store_mod.LOG, "ab") as fh:
        fh.write(b'{"op": "file", "fi')
    assert run_sweep(spec, out, threads=1).complete
    assert _digest(out) == _digest(ref)


def _child(spec, out):
    try:
        run_sweep(spec, out, threads=1, progress=False)
    except BaseException:  # noqa: BLE001 - killed or interrupted: nothing to report
        os._exit(1)
    os._exit(0)


def test_kill_loop_then_resume_identical(reference, tmp_path):
    """kill -9 of the driver at random moments, 24 times, then a resume: the dataset equals
    the uninterrupted run's, file for file."""
    spec = tmp_path / "kill.toml"
    spec.write_text(SPEC.replace("num = 6", "num = 20").replace("max_files = 3",
                                                                 "max_files = 4"))
    ref = tmp_path / "ref"
    t0 = time.perf_counter()
    run_sweep(spec, ref, threads=2)
    # kill moments scaled to this machine's speed: 24 kills at a mean of 1/30 of an
    # uninterrupted run each cannot finish the sweep, whatever the load
    t_run = time.perf_counter() - t0
    out = tmp_path / "k"
    rng = random.Random(1234)
    ctx = mp.get_context("fork")
    kills = 0
    for _ in range(40):
        p = ctx.Process(target=_child, args=(spec, out))
        p.start()
        time.sleep(rng.uniform(0.0, t_run / 15))
        alive = p.is_alive()
        if alive:
            os.kill(p.pid, signal.SIGKILL)
            kills += 1
        p.join()
        if not alive or kills >= 24:
            break
    assert kills >= 20
    res = run_sweep(spec, out, threads=1)
    assert res.complete
    assert _digest(out) == _digest(ref)
    pd.testing.assert_frame_equal(sw.open(out).frame, sw.open(ref).frame, check_exact=True)


def test_full_disk_and_unwritable(reference, tmp_path, monkeypatch):
    spec, ref = reference
    out = tmp_path / "full"
    real = store_mod.Store._atomic
    calls = {"n": 0}

    def atomic(self, name, data):
        if name.startswith("part-"):
            calls["n"] += 1
            if calls["n"] == 3:
                raise store_mod._io(self.out / name, OSError(errno.ENOSPC,
                                                             os.strerror(errno.ENOSPC)))
        return real(self, name, data)

    monkeypatch.setattr(store_mod.Store, "_atomic", atomic)
    with pytest.raises(rd.InputError, match="out: cannot write .*No space left on device"):
        run_sweep(spec, out, threads=1)
    monkeypatch.setattr(store_mod.Store, "_atomic", real)
    assert not (out / store_mod.LOCK).exists()
    assert run_sweep(spec, out, threads=1).complete
    assert _digest(out) == _digest(ref)

    # (root ignores permissions, so the refusal is injected where the lock file is created)
    real_open = os.open

    def deny(path, flags, *a, **k):
        if path == store_mod.LOCK and flags & os.O_CREAT:
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES))
        return real_open(path, flags, *a, **k)

    monkeypatch.setattr(os, "open", deny)
    with pytest.raises(rd.InputError, match="out: .* is not writable: Permission denied"):
        run_sweep(spec, tmp_path / "ro", threads=1)


@pytest.mark.parametrize("mode", [["--threads", "1"], ["--workers", "2"]])
def test_ctrl_c_one_line_and_resumable(reference, tmp_path, mode):
    """SIGINT to the whole process group (what Ctrl-C on a terminal does, worker processes
    included): exit 130, one line on stderr, the lock released, the chunks kept."""
    spec, ref = reference
    out = tmp_path / "int"
    big = tmp_path / "big.toml"
    # long enough that the SIGINT lands mid-sweep on a fast core under any load (60 p_c values
    # finished before the signal under load once the chunks got faster); never run to its end
    big.write_text(SPEC.replace("num = 6", "num = 2000"))
    p = subprocess.Popen([sys.executable, "-m", "rotordyn.cli", "sweep", str(big), "--out",
                          str(out), *mode], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    log = out / store_mod.LOG
    t0 = time.monotonic()
    while time.monotonic() - t0 < 60:
        if log.exists() and log.read_text().count("\n") >= 2:
            break
        time.sleep(0.05)
    os.killpg(p.pid, signal.SIGINT)
    _, err = p.communicate(timeout=60)
    assert p.returncode == 130, err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and "interrupted" in lines[0] and "resume" in lines[0]
    assert not (out / store_mod.LOCK).exists()
    m, entries = store_mod.read_manifest(out)
    assert entries and m["sweep_id"] == "t-determinism"
