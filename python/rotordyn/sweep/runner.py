"""Run a sweep on dask: expand the grid, skip the chunks the manifest marks done, map the rest
to workers (a LocalCluster of processes by default, or ``scheduler="tcp://..."``), write one
parquet file per chunk (temporary name, then rename) and keep ``manifest.json`` current."""

from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

import rotordyn
from rotordyn.errors import InputError
from rotordyn.sweep.spec import SweepSpec
from rotordyn.sweep.work import STATUS, run_chunk

UNITS = {
    "speed_hz": ("Hz", "spin speed"), "chamber_pressure_pa": ("Pa", "chamber pressure p_c"),
    "config_ay_m": ("m", "housing offset a_y of the active bearing"),
    "journal_x_m": ("m", "journal x relative to the housing"),
    "journal_y_m": ("m", "journal y relative to the housing"), "h_min_m": ("m", "minimum film"),
    "freq_hz": ("Hz", "frequency"), "eig_real_1_per_s": ("1/s", "eigenvalue real part"),
    "amplitude_x_m": ("m", "spectral amplitude of x"),
    "amplitude_y_m": ("m", "spectral amplitude of y"),
}
ID_COLS = ["sweep_id", "point_id", "chunk_id"]
INPUT_COLS = ["speed_hz", "chamber_pressure_pa", "config_ay_m"]


@dataclass(frozen=True)
class SweepResult:
    """A finished (or partly finished) sweep directory."""

    out: Path
    manifest: dict

    @property
    def complete(self) -> bool:
        return len(self.manifest["chunks_done"]) == self.manifest["n_chunks"]

    def to_frame(self) -> pd.DataFrame:
        """The whole dataset, one row per observation, sorted by point."""
        return read_dataset(self.out)


def read_dataset(out) -> pd.DataFrame:
    files = sorted(Path(out).glob("part-*.parquet"))
    if not files:
        raise InputError(f"sweep: no parquet chunks in {str(out)!r}")
    df = pd.concat([pd.read_parquet(f) for f in files], ignore_index=True)
    return df.sort_values(["point_id"], kind="stable", ignore_index=True)


def _atomic_write_text(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def _tidy(df: pd.DataFrame, sweep_id: str) -> pd.DataFrame:
    df = df.copy()
    df.insert(0, "sweep_id", sweep_id)
    for c in ("point_id", "chunk_id", "mode", "iterations"):
        if c in df:
            df[c] = df[c].astype("int64")
    outputs = [c for c in df.columns if c not in ID_COLS + INPUT_COLS + ["status", "message"]]
    if "message" not in df:
        df["message"] = ""
    df["message"] = df["message"].fillna("").astype(str)
    df["status"] = pd.Categorical(df["status"].fillna("error"), categories=STATUS)
    for c in ("whirl", "kind", "bearing"):
        if c in df:
            df[c] = df[c].astype("category")
    for c in outputs:
        if df[c].dtype.kind in "fiu" and c not in ("mode", "iterations"):
            df[c] = df[c].astype("float64")
    return df[ID_COLS + INPUT_COLS + outputs + ["status", "message"]]


def _write_chunk(out: Path, df: pd.DataFrame, meta: dict, chunk_id: int) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    table = pa.Table.from_pandas(df, preserve_index=False)
    md = dict(table.schema.metadata or {})
    md[b"rotordyn"] = json.dumps(meta).encode()
    table = table.replace_schema_metadata(md)
    final = out / f"part-{chunk_id:05d}.parquet"
    tmp = out / f".part-{chunk_id:05d}.parquet.tmp"
    pq.write_table(table, tmp)
    os.replace(tmp, final)


def _local_cluster(n: int):
    """A LocalCluster of ``n`` single-threaded worker processes. Worker start-up can be slow
    on a loaded machine: the start is retried once with generous timeouts, then falls back
    to worker threads in this process (the C++ core releases the GIL) rather than failing
    the sweep."""
    import dask
    from dask.distributed import LocalCluster

    last = None
    for attempt in range(2):
        timeout = "30s" if attempt == 0 else "120s"
        try:
            with dask.config.set({"distributed.comm.timeouts.connect": timeout,
                                  "distributed.deploy.lost-worker-timeout": timeout}):
                return LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                    dashboard_address=None)
        except Exception as exc:  # noqa: BLE001 - start-up failure, retried
            last = exc
    import logging

    logging.getLogger("rotordyn.sweep").warning(
        "dask worker processes failed to start (%s); using worker threads", last)
    return LocalCluster(n_workers=n, threads_per_worker=1, processes=False,
                        dashboard_address=None)


def run_sweep(spec_path, out, *, scheduler: str | None = None, workers: int | None = None,
              resume: bool = True, progress=None) -> SweepResult:
    """Run (or resume) the sweep described by ``spec_path`` into directory ``out``."""
    spec = SweepSpec.from_toml(spec_path)
    system = rotordyn.models.load(spec.model)
    model_toml = system.to_toml()
    model_hash = hashlib.sha256(model_toml.encode()).hexdigest()[:16]
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    chunks = spec.chunks()
    mpath = out / "manifest.json"
    done: set[int] = set()
    if mpath.exists() and resume:
        old = json.loads(mpath.read_text())
        if old.get("spec_hash") != spec.hash() or old.get("model_hash") != model_hash:
            raise InputError(f"out: {str(out)!r} holds a different sweep (spec or model "
                             "changed); use another directory, or --no-resume to overwrite it "
                             "(resume=False in Python)")
        done = {c for c in old.get("chunks_done", [])
                if (out / f"part-{c:05d}.parquet").exists()}
    elif not resume:
        for f in out.glob("part-*.parquet"):
            f.unlink()
    manifest = {
        "sweep_id": spec.name, "analysis": spec.analysis, "spec_hash": spec.hash(),
        "model_hash": model_hash, "rotordyn": rotordyn.__version__,
        "build_info": rotordyn.build_info(), "axes": spec.axes, "options": spec.options,
        "n_points": sum(len(c) for c in chunks), "n_chunks": len(chunks),
        "chunks_done": sorted(done), "chunks_failed": {}, "spec": spec.source,
        "model": model_toml,
    }
    _atomic_write_text(mpath, json.dumps(manifest, indent=2))
    meta = {"rotordyn": rotordyn.__version__, "build_info": rotordyn.build_info(),
            "model_hash": model_hash, "spec_hash": spec.hash(),
            "units": {k: {"units": u, "long_name": n} for k, (u, n) in UNITS.items()}}
    todo = [(i, c) for i, c in enumerate(chunks) if i not in done]
    if not todo:
        return SweepResult(out, manifest)

    from dask.distributed import Client, as_completed

    cluster = None
    if scheduler:
        client = Client(scheduler)
    else:
        n = workers or min(len(todo), os.cpu_count() or 1)
        # One thread per worker process; the C++ core's own OpenMP is kept to one thread.
        os.environ.setdefault("OMP_NUM_THREADS", "1")
        cluster = _local_cluster(n)
        client = Client(cluster)
    try:
        futs = {client.submit(run_chunk, model_toml, spec.analysis, spec.options, cid, pts,
                              key=f"{spec.name}-{spec.hash()}-chunk-{cid}", pure=False): cid
                for cid, pts in todo}
        for fut in as_completed(futs):
            cid = futs[fut]
            try:
                df = fut.result()
            except Exception as exc:  # noqa: BLE001 - infrastructure failure of one chunk
                manifest["chunks_failed"][str(cid)] = f"{type(exc).__name__}: {exc}"
                _atomic_write_text(mpath, json.dumps(manifest, indent=2))
                continue
            _write_chunk(out, _tidy(df, spec.name), meta, cid)
            manifest["chunks_done"] = sorted(set(manifest["chunks_done"]) | {cid})
            manifest["chunks_failed"].pop(str(cid), None)
            _atomic_write_text(mpath, json.dumps(manifest, indent=2))
            if progress:
                progress(len(manifest["chunks_done"]), manifest["n_chunks"])
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return SweepResult(out, manifest)
