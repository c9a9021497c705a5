"""The sweep directory: a parquet dataset that pandas, pyarrow, polars and duckdb read as a
directory, with the bookkeeping under names those readers skip.

Layout::

    OUT/part-000000-000031.parquet   rows of chunks 0..31 (one row group per chunk)
    OUT/part-000032-000032.parquet   rows of chunk 32 (not yet compacted)
    OUT/_rotordyn_sweep.json         manifest: spec, model, versions, schema (written once)
    OUT/_chunks.jsonl                append-only log: one line per file written, with its
                                     chunk range, row count, size and SHA-256
    OUT/_lock                        flock of the running driver (pid, host); refused to a
                                     second one
    OUT/_boundary.parquet            derived file of a boundary sweep (logged as "aux")

Every file is written to a fresh ``_tmp-`` name (O_EXCL|O_NOFOLLOW, :mod:`.safedir`), renamed,
then logged: the log is the truth, and nothing of the directory is trusted that the log does
not vouch for. Log entries must name the store's own part files (:func:`part_name`); on
resume every logged file is verified (regular file, size, row count, SHA-256); a file that
fails, and any ``part-*.parquet`` the log does not list (a crash between rename and log), is
removed and its chunks are recomputed. Readers (:mod:`.dataset`) verify the same way and
refuse instead. See docs/reliability.md, "The sweep store". Chunks are compacted in fixed groups (``group`` chunks per file) as
soon as a group is complete, so the final files do not depend on the order chunks finished
or on how often the sweep was resumed.
"""

from __future__ import annotations

import errno
import hashlib
import json
import os
import re
import socket
import time
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

from rotordyn.errors import InputError, OutputError
from rotordyn.sweep.safedir import TMP, NotRegular, SafeDir, write_all

MANIFEST = "_rotordyn_sweep.json"
LOG = "_chunks.jsonl"
LOCK = "_lock"
BOUNDARY = "_boundary.parquet"
AUX = (BOUNDARY,)  # derived files logged with their hash (op "aux"), outside the dataset
FORMAT = "rotordyn/sweep-dataset/2"
_PART = re.compile(r"part-(\d{6,})-(\d{6,})\.parquet\Z")
_SHA = re.compile(r"[0-9a-f]{64}\Z")
# the disk failed us (a runtime failure, CLI exit 1), as opposed to a directory the user
# cannot write to (bad input, exit 2)
_RUNTIME = {errno.ENOSPC, errno.EDQUOT, errno.EIO, errno.EFBIG}


def part_metadata(header: dict) -> dict:
    """What every part's schema metadata (key ``rotordyn``) holds: the sweep, the hashes of
    its spec and model, the analysis and its options, the rotordyn version and build, the
    units. With the model's TOML (the manifest's ``model``, identified by ``model_hash``) a
    point is reproduced from its row's axis values."""
    return {k: header[k] for k in ("sweep_id", "spec_hash", "model_hash", "rotordyn",
                                   "build_info", "analysis", "options", "units")}


def task_key(header: dict) -> str:
    """The sweep's part of its chunks' task names on a dask scheduler: the spec's and the
    model's hashes, so two sweeps that differ only in their model never share a task."""
    return f"{header['spec_hash']}-{header['model_hash']}"


def part_name(lo: int, hi: int) -> str:
    """File holding chunks lo..hi (inclusive)."""
    return f"part-{lo:06d}-{hi:06d}.parquet"


def _io(path, exc: OSError) -> InputError:
    cls = OutputError if exc.errno in _RUNTIME else InputError
    return cls(f"out: cannot write {str(path)!r}: {exc.strerror or exc}")


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


# -- the log -------------------------------------------------------------------------------
def log_corrupt(path, line: int, why: str) -> InputError:
    """The one message for a log that cannot be trusted (from a resume and from ``open``)."""
    return InputError(f"{LOG}: {str(path)!r} is corrupt at line {line} ({why}); the sweep "
                      "can neither be resumed nor read from it: run it again with "
                      "--no-resume (resume=False; every chunk is recomputed) or remove the "
                      "directory")


def _int(x) -> bool:
    return isinstance(x, int) and not isinstance(x, bool) and x >= 0


def _entry_problem(e) -> str | None:
    """Why a parsed log line is not a well-formed entry (None if it is)."""
    if not isinstance(e, dict) or e.get("op") not in ("file", "remove", "aux"):
        return "not a log entry"
    f = e.get("file")
    if e["op"] == "aux":
        if f not in AUX:
            return f"file {f!r} is not a file of this store"
        if not _int(e.get("bytes")) or not isinstance(e.get("sha256"), str) or \
                not _SHA.match(e["sha256"]):
            return f"{f}: bytes and sha256 must be a size and a SHA-256 digest"
        return None
    if not isinstance(f, str) or not _PART.match(f):
        return f"file {f!r} is not a part name of this store"
    if e["op"] == "remove":
        return None
    lo, hi = e.get("lo"), e.get("hi")
    if not (_int(lo) and _int(hi) and lo <= hi) or f != part_name(lo, hi):
        return f"file {f!r} does not match its chunk range"
    if not (_int(e.get("rows")) and _int(e.get("bytes"))):
        return f"{f}: rows and bytes must be non-negative integers"
    if not isinstance(e.get("sha256"), str) or not _SHA.match(e["sha256"]):
        return f"{f}: sha256 is not a SHA-256 digest"
    c = e.get("counts")
    if not isinstance(c, list) or len(c) != hi - lo + 1 or not all(
            isinstance(x, dict) and all(_int(x.get(k)) for k in ("ok", "failed", "unstable"))
            for x in c):
        return f"{f}: counts must be one {{ok, failed, unstable}} per chunk"
    return None


def parse_log(data: bytes, path) -> list[dict]:
    """The entries of a log; a torn last line (a driver killed mid-append) is dropped, any
    other bad line is :func:`log_corrupt`."""
    out = []
    lines = data.split(b"\n")
    for i, ln in enumerate(lines):
        if not ln.strip():
            continue
        try:
            e = json.loads(ln)
        except ValueError:
            if i >= len(lines) - 2 and not data.endswith(b"\n"):  # torn last line
                break
            raise log_corrupt(path, i + 1, "not JSON") from None
        why = _entry_problem(e)
        if why:
            raise log_corrupt(path, i + 1, why)
        out.append(e)
    return out


def live_entries(entries: list[dict]) -> dict[str, dict]:
    live: dict[str, dict] = {}
    for e in entries:
        if e["op"] == "file":
            live[e["file"]] = e
        elif e["op"] == "remove":
            live.pop(e["file"], None)
    return live


def read_aux(out, name: str) -> dict | None:
    """The last log entry of derived file ``name`` (AUX), or None if it is not logged."""
    d = SafeDir(out)
    try:
        entries = parse_log(_bookkeeping(d, LOG, "dir") or b"", Path(out) / LOG)
    finally:
        d.close()
    got = [e for e in entries if e["op"] == "aux" and e["file"] == name]
    return got[-1] if got else None


def _bookkeeping(d: SafeDir, name: str, field: str) -> bytes | None:
    """A bookkeeping file's bytes (None if missing); a symlink or a non-regular file is
    refused, never followed."""
    try:
        return d.read(name)
    except FileNotFoundError:
        return None
    except NotRegular as exc:
        raise InputError(f"{field}: {str(Path(d.path) / name)!r} is a symlink or not a "
                         f"regular file ({exc.strerror}); refusing to use it") from None
    except OSError as exc:
        raise InputError(f"{field}: cannot read {str(Path(d.path) / name)!r}: "
                         f"{exc.strerror or exc}") from None


class Store:
    """An open sweep directory, locked for this process."""

    def __init__(self, out, header: dict, *, resume: bool = True, group: int = 1,
                 schema: pa.Schema | None = None, spec_aliases: tuple[str, ...] = ()):
        self.out = Path(out)
        self.header = header
        # older spec hashes of this same sweep (SweepSpec.legacy_hash): a directory written
        # under one resumes, and its manifest is rewritten with today's hash
        self.spec_aliases = tuple(spec_aliases)
        # the rows' schema of this sweep (None: not checked): a resume refuses parts written
        # with another one (an older rotordyn's rows) rather than mixing two in one dataset
        self.schema = schema
        self.group = max(1, int(group))
        self.files: dict[str, dict] = {}   # file name -> log entry (live files only)
        # what a resume found and dropped (file name, why): its chunks are recomputed
        self.dropped: list[tuple[str, str]] = []
        self._lockfd = None
        self._log = None                   # descriptor of the log, open for appending
        self.dir = None
        # fsync after every file: only needed to survive a power loss (a killed process
        # loses nothing the OS has been given); off by default, a resume verifies anyway
        self.durable = os.environ.get("ROTORDYN_SWEEP_FSYNC", "") == "1"
        out = self.out
        if out.exists() and not out.is_dir():
            raise InputError(f"out: {str(out)!r} is a file, expected a directory")
        try:
            out.mkdir(parents=True, exist_ok=True)
            self.dir = SafeDir(out)
        except OSError as exc:
            raise InputError(f"out: cannot create {str(out)!r}: {exc.strerror or exc}") from None
        try:
            self._lock()
            self._open(resume)
        except BaseException:
            self.close()
            raise

    # -- lock ----------------------------------------------------------------------------
    def _lock(self) -> None:
        path = self.out / LOCK
        me = {"pid": os.getpid(), "host": socket.gethostname(), "started": time.time()}

        def stale(old: dict) -> bool:
            # a lock file of an older driver (link lock, no flock): its process may run
            try:
                pid, host = int(old["pid"]), str(old["host"])
            except (KeyError, TypeError, ValueError):
                return True
            return host == me["host"] and not _pid_alive(pid)

        try:
            fd, holder = self.dir.lock(LOCK, me, stale)
        except NotRegular as exc:
            raise InputError(f"out: {str(path)!r} is a symlink or not a regular file "
                             f"({exc.strerror}); refusing to use it") from None
        except OSError as exc:
            if exc.errno == errno.ELOOP:
                raise InputError(f"out: {str(path)!r} is a symlink; refusing to use it") \
                    from None
            cls = OutputError if exc.errno in _RUNTIME else InputError
            raise cls(f"out: {str(self.out)!r} is not writable: {exc.strerror or exc}") \
                from None
        if fd is None:
            who = (f"out: {str(self.out)!r} is in use by another sweep (pid "
                   f"{holder.get('pid', '?')} on {holder.get('host', '?')}); wait for it to "
                   "finish")
            if holder.get("flock") or not holder:
                # held by flock: its process is alive (the kernel drops the lock when it
                # exits); removing the file would let a second driver in
                raise InputError(f"{who} (the lock is released when that process exits)")
            raise InputError(f"{who}, or remove {str(path)!r} if that process is gone "
                             "(a lock of an older rotordyn)")
        self._lockfd = fd

    def close(self) -> None:
        """Release the directory; never raises (a failure here must not hide the error that
        made the sweep stop)."""
        if self._log is not None:
            try:
                os.close(self._log)
            except OSError:
                pass
            self._log = None
        if self._lockfd is not None:
            try:
                self.dir.unlock(LOCK, self._lockfd)
            except OSError:
                pass
            self._lockfd = None
        if self.dir is not None:
            try:
                self.dir.close()
            except OSError:
                pass

    # -- opening -------------------------------------------------------------------------
    def _ours(self, name: str) -> bool:
        return bool(_PART.match(name))

    def _open(self, resume: bool) -> None:
        out = self.out
        mpath = out / MANIFEST
        manifest = None
        raw = _bookkeeping(self.dir, MANIFEST, "out")
        if raw is not None:
            try:
                manifest = json.loads(raw.decode("utf-8"))
                if not isinstance(manifest, dict) or manifest.get("format") != FORMAT:
                    raise ValueError("not a rotordyn sweep manifest")
            except (ValueError, UnicodeDecodeError) as exc:
                raise InputError(f"out: {str(mpath)!r} is corrupt ({exc}); remove the "
                                 "directory or choose another --out") from None
        stray = sorted(n for n in self.dir.names() if n.endswith(".parquet")
                       and not n.startswith(("_", ".")))
        if manifest is None:
            if stray or self.dir.lstat(LOG) is not None:
                raise InputError(f"out: {str(out)!r} holds parquet files but no sweep manifest "
                                 f"({stray[0] if stray else LOG}); they may belong to another "
                                 "sweep: choose an empty directory")
            self._check_no_others()
            self._clean_tmp()
            self._write_manifest()
            self._rewrite_log([])
            return
        alias = (manifest.get("spec_hash") != self.header["spec_hash"]
                 and manifest.get("spec_hash") in self.spec_aliases)
        same = ((alias or manifest.get("spec_hash") == self.header["spec_hash"])
                and manifest.get("model_hash") == self.header["model_hash"])
        foreign = [n for n in stray if not self._ours(n)]
        if foreign:
            raise InputError(f"out: {str(out)!r} holds parquet files that are not this "
                             f"sweep's ({foreign[0]}); choose another directory")
        self._check_no_others()
        if not resume:
            if manifest.get("sweep_id") != self.header["sweep_id"]:
                raise InputError(
                    f"out: {str(out)!r} holds sweep {manifest.get('sweep_id')!r}, not "
                    f"{self.header['sweep_id']!r}; --no-resume only restarts the same sweep")
            for n in stray:
                self.dir.unlink(n)
            self._clean_tmp()
            self._write_manifest()
            self._rewrite_log([])
            return
        if not same:
            what = [f"{k} changed (hash {self.header[k + '_hash']}, the directory's "
                    f"{manifest.get(k + '_hash')})" for k in ("spec", "model")
                    if manifest.get(k + "_hash") != self.header[k + "_hash"]
                    and not (k == "spec" and alias)]
            raise InputError(f"out: {str(out)!r} holds a different sweep "
                             f"({manifest.get('sweep_id')!r}: {', '.join(what)}); use "
                             "another directory or --no-resume")
        self.dropped += [(n, "an unfinished write of a driver that stopped")
                         for n in self._clean_tmp()]
        raw = _bookkeeping(self.dir, LOG, "out")
        live = live_entries(parse_log(raw or b"", out / LOG))
        good = []
        for e in live.values():
            why = self._verify(e)
            if why:
                self.dropped.append((e["file"], why))
            else:
                good.append(e)
        self._check_schemas(good)
        # a crash between logging a compacted file and logging the removal of its parts
        # leaves both: keep the widest file covering each chunk
        good = [e for e in good if not any(o is not e and o["lo"] <= e["lo"] and
                                           e["hi"] <= o["hi"] and o["hi"] - o["lo"] >
                                           e["hi"] - e["lo"] for o in good)]
        keep = {e["file"] for e in good}
        for n in stray:
            if n not in keep:
                if n not in live:
                    self.dropped.append((n, "not in the log: written by a driver that "
                                            "stopped before logging it"))
                self.dir.unlink(n)  # a symlink of a part's name goes too (not its target)
        self._rewrite_log(good)
        if alias:  # every check passed: today's hash from now on
            self._write_manifest()

    def _check_no_others(self) -> None:
        """Refuse a directory holding entries the dataset's readers would take for data:
        pandas.read_parquet(OUT) and pyarrow.dataset read every file and sub-directory whose
        name does not begin with '_' or '.' (a notes.txt made them fail; a sub-directory of
        another sweep's parts would be read into this one's rows). Nothing is removed."""
        others = sorted(n for n in self.dir.names()
                        if not n.startswith(("_", ".")) and not _PART.match(n))
        if others:
            more = f" and {len(others) - 1} more" if len(others) > 1 else ""
            raise InputError(
                f"out: {str(self.out)!r} holds {others[0]!r}{more}, which "
                "pandas.read_parquet(OUT) and pyarrow.dataset would read as part of the "
                "dataset: choose an empty or new directory (names beginning with '_' or '.' "
                "are skipped by the readers and allowed)")

    def _clean_tmp(self) -> list[str]:
        """Remove the temporaries (the names removed): only the lock holder writes them, so
        every one here is a dead driver's."""
        gone = []
        for n in self.dir.names():
            if n.startswith(TMP):
                try:
                    self.dir.unlink(n)
                    gone.append(n)
                except OSError:
                    pass
        return gone

    def _write_manifest(self) -> None:
        self._atomic(MANIFEST, json.dumps({"format": FORMAT, **self.header}, indent=1).encode())

    def _read_part(self, e: dict) -> bytes:
        """The bytes of a logged file, checked against the log (size, SHA-256); NotRegular
        or OSError otherwise."""
        data = self.dir.read(e["file"], expect_size=e["bytes"])
        if len(data) != e["bytes"] or hashlib.sha256(data).hexdigest() != e["sha256"]:
            raise NotRegular(errno.EINVAL, f"{e['file']} does not match its SHA-256")
        return data

    def _verify(self, e: dict) -> str | None:
        """Why a logged file cannot be kept (None: it matches the log)."""
        try:
            data = self._read_part(e)
            f = pq.ParquetFile(pa.BufferReader(data))
            e["_schema"] = f.schema_arrow  # for _check_schemas (not logged)
        except FileNotFoundError:
            return "missing"
        except (OSError, pa.ArrowException) as exc:
            return getattr(exc, "strerror", None) or str(exc)
        n = f.metadata.num_rows
        return None if n == e["rows"] else f"{n} rows, the log says {e['rows']}"

    def _check_schemas(self, entries: list[dict]) -> None:
        """Refuse a resume whose logged parts hold rows of another schema than this sweep's
        (``self.schema``; e.g. parts of an older rotordyn, before a column was added): the
        new chunks would be written with the new schema beside them, a dataset no reader can
        concatenate. The message names the part and the columns that differ."""
        for e in sorted(entries, key=lambda e: e["lo"]):
            got = e.pop("_schema", None)
            if self.schema is None or got is None:
                continue
            why = schema_difference(self.schema, got)
            if why:
                raise InputError(
                    f"out: {str(self.out)!r} holds chunks written with another row schema "
                    f"({e['file']}: {why}; e.g. rows of an older rotordyn); resuming would mix "
                    "two schemas in one dataset: run the sweep again with --no-resume "
                    "(resume=False; every chunk is recomputed) or into another directory")

    def _rewrite_log(self, entries: list[dict]) -> None:
        if self._log is not None:
            os.close(self._log)
            self._log = None
        text = "".join(json.dumps(e, sort_keys=True) + "\n" for e in entries)
        # the descriptor that wrote the new log stays open for the appends: the log is
        # never reopened by name
        try:
            self._log = self.dir.write_atomic(LOG, text.encode(), durable=self.durable,
                                              keep_open=True)
        except OSError as exc:
            raise _io(self.out / LOG, exc) from None
        self.files = {e["file"]: e for e in entries}

    def _atomic(self, name: str, data: bytes) -> None:
        try:
            self.dir.write_atomic(name, data, durable=self.durable)
        except OSError as exc:
            raise _io(self.out / name, exc) from None

    def add_aux(self, name: str, data: bytes) -> None:
        """Write a derived file (AUX) and log its size and SHA-256."""
        self._atomic(name, data)
        self._append({"op": "aux", "file": name, "bytes": len(data),
                      "sha256": hashlib.sha256(data).hexdigest()})

    def _append(self, entry: dict) -> None:
        line = (json.dumps(entry, sort_keys=True) + "\n").encode()
        try:
            end = os.lseek(self._log, 0, os.SEEK_END)
        except OSError as exc:
            raise _io(self.out / LOG, exc) from None
        try:
            write_all(self._log, line)
            if self.durable:
                os.fsync(self._log)
        except OSError as exc:
            try:  # no torn line left behind (a resume would drop it anyway)
                os.ftruncate(self._log, end)
            except OSError:
                pass
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

    def _table(self, e: dict) -> pa.Table | pq.ParquetFile:
        """A logged file, re-checked against its SHA-256 (a part replaced since the resume
        verified it must not be laundered into a compacted file with a fresh hash)."""
        try:
            return pq.ParquetFile(pa.BufferReader(self._read_part(e)))
        except (OSError, pa.ArrowException) as exc:
            raise InputError(f"out: {str(self.out / e['file'])!r} changed while the sweep "
                             f"ran ({getattr(exc, 'strerror', None) or exc}); run the sweep "
                             "again to verify and recompute it") from None

    def _compact(self, lo: int, hi: int, names: list[str]) -> None:
        tables = [self._table(self.files[n]).read(use_threads=False) for n in names]
        counts = [self.files[n]["counts"][0] for n in names]
        self._write_file(part_name(lo, hi), tables, lo, hi, counts)
        for n in names:
            self._append({"op": "remove", "file": n})
            self.files.pop(n, None)
            self.dir.unlink(n)

    def table(self, chunk_id: int) -> pa.Table:
        """The rows of one done chunk (for driver-side analyses that build on results)."""
        for e in self.files.values():
            if e["lo"] <= chunk_id <= e["hi"]:
                return self._table(e).read_row_group(chunk_id - e["lo"], use_threads=False)
        raise KeyError(chunk_id)


def schema_difference(expected: pa.Schema, got: pa.Schema) -> str:
    """What differs between two row schemas (metadata aside): the columns missing from
    ``got``, those it has beyond ``expected``, those of another type or order; "" if none."""
    if got.remove_metadata().equals(expected.remove_metadata()):
        return ""
    names, have = list(expected.names), list(got.names)
    missing = [n for n in names if n not in have]
    extra = [n for n in have if n not in names]
    parts = []
    if missing:
        parts.append(f"without the columns {missing}")
    if extra:
        parts.append(f"with the columns {extra} this sweep does not write")
    for n in names:
        if n in have and got.field(n).type != expected.field(n).type:
            parts.append(f"column {n!r} of type {got.field(n).type}, expected "
                         f"{expected.field(n).type}")
    if not parts:
        parts.append("the columns in another order")
    return "; ".join(parts)


def open_dir(out) -> SafeDir:
    """The sweep directory ``out`` opened for reading (InputError if it is not one)."""
    try:
        return SafeDir(out)
    except OSError:
        raise InputError(f"dir: {str(out)!r} is not a sweep directory (no {MANIFEST})") \
            from None


def read_manifest(out, d: SafeDir | None = None) -> tuple[dict, list[dict]]:
    """(manifest, live log entries) of a sweep directory, without locking it (``d``: the
    directory already opened, to read everything through one descriptor). Names in the log
    are checked (the store's own part names, nothing outside the directory)."""
    out = Path(out)
    mine = d is None
    d = open_dir(out) if mine else d
    try:
        raw = _bookkeeping(d, MANIFEST, "dir")
        if raw is None:
            raise InputError(f"dir: {str(out)!r} is not a sweep directory (no {MANIFEST})")
        try:
            manifest = json.loads(raw.decode("utf-8"))
            if not isinstance(manifest, dict) or manifest.get("format") != FORMAT:
                raise ValueError("not a rotordyn sweep manifest")
        except (ValueError, UnicodeDecodeError) as exc:
            raise InputError(f"dir: {str(out / MANIFEST)!r} is corrupt ({exc})") from None
        live = live_entries(parse_log(_bookkeeping(d, LOG, "dir") or b"", out / LOG))
    finally:
        if mine:
            d.close()
    return manifest, [live[k] for k in sorted(live)]
