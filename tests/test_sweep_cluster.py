"""A real dask cluster, started as docs/transient-and-sweeps.md tells a user: `dask scheduler`
and `dask worker` processes on 127.0.0.1. A worker without rotordyn is refused within 30 s with
a message naming it; with three workers, one killed mid-sweep, the sweep completes with every
point exactly once and the same dataset as a single-threaded run."""

import hashlib
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.sweep import run_sweep
from rotordyn.sweep import store as store_mod

DASK = str(Path(sys.executable).with_name("dask"))
SPEC = """
schema = "rotordyn/sweep/1"
name = "t-cluster"
model = "paper-rig"
analysis = "stability"
chunk_size = 3
max_files = 4

[grid]
config_ay_m = [-1.85e-3, -1.0e-3, 0.0]
chamber_pressure_pa = {start = 0.0, stop = 0.29e6, num = 30}
speed_hz = 50.0

[options]
track = false  # chunks of chunk_size points (not whole p_c lines), to test the bookkeeping
"""


def _digest(out) -> dict:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(Path(out).glob("*.parquet"))}


class Cluster:
    def __init__(self, tmp: Path):
        self.tmp = tmp
        self.file = tmp / "scheduler.json"
        self.procs = []
        env = dict(os.environ, OMP_NUM_THREADS="1")
        self.sched = self._start([DASK, "scheduler", "--host", "127.0.0.1", "--port", "0",
                                  "--no-dashboard", "--scheduler-file", str(self.file)], env)
        t0 = time.monotonic()
        while not self.file.exists() and time.monotonic() - t0 < 60:
            time.sleep(0.1)
        time.sleep(0.2)
        self.address = json.loads(self.file.read_text())["address"]

    def _start(self, cmd, env):
        p = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                             cwd=self.tmp)
        self.procs.append(p)
        return p

    def worker(self, env_extra=None):
        env = dict(os.environ, OMP_NUM_THREADS="1", **(env_extra or {}))
        return self._start([DASK, "worker", self.address, "--nthreads", "1", "--no-nanny",
                            "--host", "127.0.0.1", "--no-dashboard"], env)

    def close(self):
        for p in reversed(self.procs):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
        for p in self.procs:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=30)


def test_worker_without_rotordyn_is_refused(tmp_path):
    fake = tmp_path / "fake" / "rotordyn"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ModuleNotFoundError(\"No module named 'rotordyn'\")\n")
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC)
    c = Cluster(tmp_path)
    try:
        c.worker({"PYTHONPATH": str(fake.parent)})
        t0 = time.monotonic()
        with pytest.raises(rd.InputError, match=r"worker tcp://127\.0\.0\.1:\d+: cannot run "
                                                r"rotordyn \(ModuleNotFoundError"):
            run_sweep(spec, tmp_path / "o", scheduler=c.address, worker_timeout=30)
        assert time.monotonic() - t0 < 30
        assert not (tmp_path / "o" / store_mod.LOCK).exists()
    finally:
        c.close()


def test_three_workers_one_killed(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC)
    ref = tmp_path / "ref"
    run_sweep(spec, ref, threads=1)
    c = Cluster(tmp_path)
    try:
        workers = [c.worker() for _ in range(3)]
        out = tmp_path / "o"
        drv = subprocess.Popen([sys.executable, "-m", "rotordyn.cli", "sweep", str(spec),
                                "--out", str(out), "--scheduler", c.address, "--json"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        log = out / store_mod.LOG
        t0 = time.monotonic()
        while time.monotonic() - t0 < 60:
            if log.exists() and log.read_text().count('"op": "file"') >= 2:
                break
            time.sleep(0.02)
        workers[0].send_signal(signal.SIGKILL)
        so, se = drv.communicate(timeout=120)
        assert drv.returncode == 0, se
        j = json.loads(so)
        assert j["chunks_done"] == j["n_chunks"]
        df = sw.open(out).frame
        assert df["point_id"].nunique() == 90
        assert not df.duplicated(["point_id", "mode"]).any()
        assert _digest(out) == _digest(ref)
    finally:
        c.close()
