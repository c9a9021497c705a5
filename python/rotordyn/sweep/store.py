"""The sweep directory: a parquet dataset that pandas, pyarrow, polars and duckdb read as a
directory, with the bookkeeping under names those readers skip.

Layout::

    OUT/part-000000-000031.parquet   rows of chunks 0..31 (one row group per chunk)
    OUT/part-000032-000032.parquet   rows of chunk 32 (not yet compacted)
    OUT/_rotordyn_sweep.json         manifest: spec, model, versions, schema (written once)
    OUT/_chunks.jsonl                append-only log: one line per file written, with its
                                     chunk range, row count, size and SHA-256
    OUT/_lock                        the running driver (pid, host); refused to a second one

Every file is written to a ``_tmp-`` name, flushed, renamed, then logged: the log is the truth.
On resume every logged file is verified (size, row count, SHA-256); a file that fails, and
any ``part-*.parquet`` the log does not list (a crash between rename and log), is removed and
its chunks are recomputed. Chunks are compacted in fixed groups (``group`` chunks per file) as
soon as a group is complete, so the final files do not depend on the order chunks finished
or on how often the sweep was resumed.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import socket
import time
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

from rotordyn.errors import InputError

MANIFEST = "_rotordyn_sweep.json"
LOG = "_chunks.jsonl"
LOCK = "_lock"
TMP = "_tmp-"
FORMAT = "rotordyn/sweep-dataset/2"


def part_name(lo: int, hi: int) -> str:
    """File holding chunks lo..hi (inclusive)."""
    return f"part-{lo:06d}-{hi:06d}.parquet"


def _io(path, exc: OSError) -> InputError:
    return InputError(f"out: cannot write {str(path)!r}: {exc.strerror or exc}")


def _pid_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


class Store:
    """An open sweep directory, locked for this process."""

    def __init__(self, out, header: dict, *, resume: bool = True, group: int = 1):
        self.out = Path(out)
        self.header = header
        self.group = max(1, int(group))
        self.files: dict[str, dict] = {}   # file name -> log entry (live files only)
        self._locked = False
        self._log = None
        # fsync after every file: only needed to survive a power loss (a killed process
        # loses nothing the OS has been given); off by default, a resume verifies anyway
        self.durable = os.environ.get("ROTORDYN_SWEEP_FSYNC", "") == "1"
        out = self.out
        if out.exists() and not out.is_dir():
            raise InputError(f"out: {str(out)!r} is a file, expected a directory")
        try:
            out.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise InputError(f"out: cannot create {str(out)!r}: {exc.strerror or exc}") from None
        self._lock()
        try:
            self._open(resume)
        except BaseException:
            self.close()
            raise

    # -- lock ----------------------------------------------------------------------------
    def _lock(self) -> None:
        path = self.out / LOCK
        me = {"pid": os.getpid(), "host": socket.gethostname(), "started": time.time()}
        # The lock is created with its content in one step (a hard link to a written
        # temporary file), so a driver killed at any moment never leaves an empty lock.
        tmp = self.out / f"{TMP}lock-{me['pid']}"
        try:
            tmp.write_text(json.dumps(me))
        except OSError as exc:
            raise InputError(f"out: {str(self.out)!r} is not writable: "
                             f"{exc.strerror or exc}") from None
        try:
            for _ in range(2):
                try:
                    os.link(tmp, path)
                except FileExistsError:
                    try:
                        other = json.loads(path.read_text())
                        pid, host = int(other["pid"]), str(other["host"])
                    except (OSError, ValueError, KeyError, TypeError):
                        pid, host = -1, "?"
                    if host == me["host"] and not _pid_alive(pid) or host == "?":
                        path.unlink(missing_ok=True)  # stale: its driver is gone
                        continue
                    raise InputError(
                        f"out: {str(self.out)!r} is in use by another sweep (pid {pid} on "
                        f"{host}); wait for it to finish, or remove {str(path)!r} if that "
                        "process is gone") from None
                except OSError as exc:
                    raise InputError(f"out: {str(self.out)!r} is not writable: "
                                     f"{exc.strerror or exc}") from None
                self._locked = True
                return
        finally:
            tmp.unlink(missing_ok=True)
        raise InputError(f"out: could not lock {str(self.out)!r}")

    def close(self) -> None:
        if self._log is not None:
            self._log.close()
            self._log = None
        if self._locked:
            (self.out / LOCK).unlink(missing_ok=True)
            self._locked = False

    # -- opening -------------------------------------------------------------------------
    def _ours(self, name: str) -> bool:
        return name.startswith("part-") and name.endswith(".parquet")

    def _open(self, resume: bool) -> None:
        out = self.out
        mpath = out / MANIFEST
        manifest = None
        if mpath.exists():
            try:
                manifest = json.loads(mpath.read_text(encoding="utf-8"))
                if not isinstance(manifest, dict) or manifest.get("format") != FORMAT:
                    raise ValueError("not a rotordyn sweep manifest")
            except (ValueError, UnicodeDecodeError) as exc:
                raise InputError(f"out: {str(mpath)!r} is corrupt ({exc}); remove the "
                                 "directory or choose another --out") from None
        stray = sorted(p.name for p in out.iterdir() if p.suffix == ".parquet"
                       and not p.name.startswith(("_", ".")))
        if manifest is None:
            if stray or (out / LOG).exists():
                raise InputError(f"out: {str(out)!r} holds parquet files but no sweep manifest "
                                 f"({stray[0] if stray else LOG}); they may belong to another "
                                 "sweep: choose an empty directory")
            self._write_manifest()
            self._rewrite_log([])
            return
        same = (manifest.get("spec_hash") == self.header["spec_hash"]
                and manifest.get("model_hash") == self.header["model_hash"])
        foreign = [n for n in stray if not self._ours(n)]
        if foreign:
            raise InputError(f"out: {str(out)!r} holds parquet files that are not this "
                             f"sweep's ({foreign[0]}); choose another directory")
        if not resume:
            if manifest.get("sweep_id") != self.header["sweep_id"]:
                raise InputError(
                    f"out: {str(out)!r} holds sweep {manifest.get('sweep_id')!r}, not "
                    f"{self.header['sweep_id']!r}; --no-resume only restarts the same sweep")
            for n in stray:
                (out / n).unlink()
            self._clean_tmp()
            self._write_manifest()
            self._rewrite_log([])
            return
        if not same:
            raise InputError(f"out: {str(out)!r} holds a different sweep "
                             f"({manifest.get('sweep_id')!r}: spec or model changed); use "
                             "another directory or --no-resume")
        self._clean_tmp()
        entries = self._read_log()
        live = {}
        for e in entries:
            if e.get("op") == "file":
                live[e["file"]] = e
            elif e.get("op") == "remove":
                live.pop(e["file"], None)
        good = [e for e in live.values() if self._verify(e)]
        # a crash between logging a compacted file and logging the removal of its parts
        # leaves both: keep the widest file covering each chunk
        good = [e for e in good if not any(o is not e and o["lo"] <= e["lo"] and
                                           e["hi"] <= o["hi"] and o["hi"] - o["lo"] >
                                           e["hi"] - e["lo"] for o in good)]
        keep = {e["file"] for e in good}
        for n in stray:
            if n not in keep:
                (out / n).unlink()
        self._rewrite_log(good)

    def _clean_tmp(self) -> None:
        for p in self.out.glob(TMP + "*"):
            p.unlink(missing_ok=True)

    def _write_manifest(self) -> None:
        self._atomic(MANIFEST, json.dumps({"format": FORMAT, **self.header}, indent=1).encode())

    def _read_log(self) -> list[dict]:
        path = self.out / LOG
        if not path.exists():
            return []
        out = []
        lines = path.read_bytes().split(b"\n")
        for i, ln in enumerate(lines):
            if not ln.strip():
                continue
            try:
                out.append(json.loads(ln))
            except ValueError:
                if i >= len(lines) - 2:  # a torn last line (killed mid-append)
                    break
                raise InputError(f"out: {str(path)!r} is corrupt at line {i + 1}; remove the "
                                 "directory or use --no-resume") from None
        return out

    def _verify(self, e: dict) -> bool:
        p = self.out / e["file"]
        try:
            if p.stat().st_size != e["bytes"]:
                return False
            data = p.read_bytes()
            if hashlib.sha256(data).hexdigest() != e["sha256"]:
                return False
            return pq.ParquetFile(io.BytesIO(data)).metadata.num_rows == e["rows"]
        except (OSError, KeyError, pa.ArrowException):
            return False

    def _rewrite_log(self, entries: list[dict]) -> None:
        if self._log is not None:
            self._log.close()
        text = "".join(json.dumps(e, sort_keys=True) + "\n" for e in entries)
        self._atomic(LOG, text.encode())
        self.files = {e["file"]: e for e in entries}
        self._log = open(self.out / LOG, "ab")

    def _atomic(self, name: str, data: bytes) -> None:
        tmp = self.out / (TMP + name)
        try:
            with open(tmp, "wb") as fh:
                fh.write(data)
                if self.durable:
                    fh.flush()
                    os.fsync(fh.fileno())
            os.replace(tmp, self.out / name)
        except OSError as exc:
            tmp.unlink(missing_ok=True)
            raise _io(self.out / name, exc) from None

    def _append(self, entry: dict) -> None:
        try:
            self._log.write((json.dumps(entry, sort_keys=True) + "\n").encode())
            self._log.flush()
            if self.durable:
                os.fsync(self._log.fileno())
        except OSError as exc:
            raise _io(self.out / LOG, exc) from None

    # -- chunks ------------------------------------------------------------------------
    def done_chunks(self) -> set[int]:
        s = set()
        for e in self.files.values():
            s.update(range(e["lo"], e["hi"] + 1))
        return s

    def chunk_entries(self) -> dict[int, dict]:
        """Per done chunk, its counts (ok/failed/unstable points)."""
        out = {}
        for e in self.files.values():
            for c, cnt in zip(range(e["lo"], e["hi"] + 1), e["counts"]):
                out[c] = cnt
        return out

    def _write_file(self, name: str, tables: list[pa.Table], lo: int, hi: int,
                    counts: list) -> None:
        buf = pa.BufferOutputStream()
        with pq.ParquetWriter(buf, tables[0].schema, compression="zstd") as w:
            for t in tables:
                w.write_table(t, row_group_size=max(1, t.num_rows))
        data = buf.getvalue().to_pybytes()
        self._atomic(name, data)
        self._append({"op": "file", "file": name, "lo": lo, "hi": hi, "counts": counts,
                      "rows": sum(t.num_rows for t in tables), "bytes": len(data),
                      "sha256": hashlib.sha256(data).hexdigest()})
        self.files[name] = {"file": name, "lo": lo, "hi": hi, "counts": counts,
                            "rows": sum(t.num_rows for t in tables), "bytes": len(data),
                            "sha256": hashlib.sha256(data).hexdigest()}

    def add(self, chunk_id: int, table: pa.Table, counts, n_chunks: int) -> None:
        """Write one chunk (then compact its group if the group is complete)."""
        self._write_file(part_name(chunk_id, chunk_id), [table], chunk_id, chunk_id,
                         [counts])
        if self.group > 1:
            g0 = (chunk_id // self.group) * self.group
            g1 = min(g0 + self.group, n_chunks) - 1
            names = [part_name(c, c) for c in range(g0, g1 + 1)]
            if g1 > g0 and all(n in self.files for n in names):
                self._compact(g0, g1, names)

    def compact_complete(self, n_chunks: int) -> None:
        """Compact every complete group still held as single-chunk parts (a driver stopped
        between the last part of a group and its compaction)."""
        if self.group <= 1:
            return
        for g0 in range(0, n_chunks, self.group):
            g1 = min(g0 + self.group, n_chunks) - 1
            names = [part_name(c, c) for c in range(g0, g1 + 1)]
            if g1 > g0 and all(n in self.files for n in names):
                self._compact(g0, g1, names)

    def _compact(self, lo: int, hi: int, names: list[str]) -> None:
        tables = [pq.read_table(self.out / n) for n in names]
        counts = [self.files[n]["counts"][0] for n in names]
        self._write_file(part_name(lo, hi), tables, lo, hi, counts)
        for n in names:
            self._append({"op": "remove", "file": n})
            self.files.pop(n, None)
            (self.out / n).unlink(missing_ok=True)

    def ordered_files(self) -> list[Path]:
        return [self.out / n for n in sorted(self.files)]

    def table(self, chunk_id: int) -> pa.Table:
        """The rows of one done chunk (for driver-side analyses that build on results)."""
        for e in self.files.values():
            if e["lo"] <= chunk_id <= e["hi"]:
                f = pq.ParquetFile(self.out / e["file"])
                return f.read_row_group(chunk_id - e["lo"])
        raise KeyError(chunk_id)


def read_manifest(out) -> tuple[dict, list[dict]]:
    """(manifest, live log entries) of a sweep directory, without locking it."""
    out = Path(out)
    mpath = out / MANIFEST
    if not mpath.is_file():
        raise InputError(f"dir: {str(out)!r} is not a sweep directory (no {MANIFEST})")
    try:
        manifest = json.loads(mpath.read_text(encoding="utf-8"))
    except (ValueError, UnicodeDecodeError) as exc:
        raise InputError(f"dir: {str(mpath)!r} is corrupt ({exc})") from None
    live: dict = {}
    path = out / LOG
    if path.exists():
        for ln in path.read_bytes().split(b"\n"):
            try:
                e = json.loads(ln) if ln.strip() else None
            except ValueError:
                break
            if e is None:
                continue
            if e.get("op") == "file":
                live[e["file"]] = e
            elif e.get("op") == "remove":
                live.pop(e["file"], None)
    return manifest, [live[k] for k in sorted(live)]
