"""Reading a sweep directory: ``rotordyn.sweep.open(OUT)`` gives the rows (exactly what
``pandas.read_parquet(OUT)`` gives), the manifest, the axes and helpers that pivot a map onto
its axes."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.errors import InputError
from rotordyn.sweep.store import BOUNDARY, open_dir, read_aux, read_manifest

if TYPE_CHECKING:
    import pandas as pd


@dataclass
class SweepDataset:
    """A sweep directory opened for reading.

    frame : the rows, in point order (pandas.read_parquet of the directory).
    manifest : the ``_rotordyn_sweep.json`` contents (spec, model, versions, units).
    axes : {axis: values} in expansion order.
    """

    out: Path
    frame: pd.DataFrame
    manifest: dict
    verify: bool = True

    @property
    def axes(self) -> dict:
        return self.manifest.get("axes", {})

    @property
    def complete(self) -> bool:
        return self.frame["chunk_id"].nunique() == self.manifest.get("n_chunks")

    @property
    def units(self) -> dict:
        return {k: val["units"] for k, val in self.manifest.get("units", {}).items()}

    def per_point(self, value: str = "max_real_1_per_s", how: str = "first") -> pd.DataFrame:
        """One row per point: the axes and ``value`` (reduced over a point's rows by
        ``how``: first, max, min, mean)."""
        keys = ["point_id"] + [a for a in self.axes]
        g = self.frame.groupby(keys, observed=True, sort=True)[value]
        return getattr(g, how)().reset_index()

    def pivot(self, value: str = "max_real_1_per_s", x: str | None = None,
              y: str | None = None, how: str = "first", **fixed) -> pd.DataFrame:
        """A 2-D map of ``value`` on axes ``x`` (rows) and ``y`` (columns), the other axes
        fixed by keyword (``speed_hz=50.0``) or required to have one value. Missing or failed
        points are NaN."""
        axes = list(self.axes)
        varying = [a for a in axes if len(self.axes[a]) > 1 and a not in fixed]
        if x is None or y is None:
            if len(varying) < 2:
                raise InputError(f"pivot: expected two varying axes, got {varying}")
            x = x or [a for a in varying if a != y][0]
            y = y or [a for a in varying if a != x][0]
        for a in (x, y):
            if a not in axes:
                raise InputError(f"pivot: {a!r} is not an axis (axes: {axes})")
        rest = [a for a in varying if a not in (x, y)]
        if rest:
            raise InputError(f"pivot: fix the other varying axes by keyword: {rest}")
        df = self.frame
        for k, val in fixed.items():
            if k not in axes:
                raise InputError(f"pivot: {k!r} is not an axis (axes: {axes})")
            df = df[df[k] == val]
        df = df[df["status"].isin(["ok", "contact"])]
        g = df.groupby([x, y], observed=True)[value]
        m = getattr(g, how)().unstack(y)
        return m.reindex(index=self.axes[x], columns=self.axes[y])

    def boundary(self) -> pd.DataFrame:
        """Boundary polylines of a ``boundary`` sweep: (line, vertex, x, y), checked against
        the size and SHA-256 the log holds for ``_boundary.parquet`` (unless opened with
        ``verify=False``)."""
        import hashlib

        import pyarrow as pa
        import pyarrow.parquet as pq

        from rotordyn.sweep.safedir import SafeDir

        e = read_aux(self.out, BOUNDARY) if self.verify else None
        d = SafeDir(self.out)
        try:
            if d.lstat(BOUNDARY) is None or self.verify and e is None:
                raise InputError(f"boundary: {str(self.out)!r} holds no finished boundary "
                                 "(not a boundary sweep, or it stopped before the end: run it "
                                 "again)")
            try:
                data = d.read(BOUNDARY)
            except OSError as exc:
                raise InputError(f"boundary: {str(self.out / BOUNDARY)!r} is damaged "
                                 f"({exc.strerror or exc})") from None
        finally:
            d.close()
        if e is not None and (len(data) != e["bytes"]
                              or hashlib.sha256(data).hexdigest() != e["sha256"]):
            raise InputError(f"boundary: {str(self.out / BOUNDARY)!r} is damaged (its SHA-256 "
                             "differs from the log's); run the sweep again to rewrite it")
        # no Arrow thread pool: pyarrow 26 can abort the interpreter at exit ('terminate called
        # without an active exception') when its CPU pool was started (seen in 4-15 of 20 runs)
        t = pq.read_table(pa.BufferReader(data), use_threads=False)
        return t.to_pandas(use_threads=False)


def open_dataset(out, *, verify: bool = True) -> SweepDataset:
    """Open a sweep directory written by :func:`rotordyn.sweep.run_sweep`.

    Every file the log lists is read once, without following a symlink, and (``verify``,
    the default) checked against the size, SHA-256 and row count the log holds for it: a
    file that differs is an InputError naming it as damaged (a resume recomputes it).
    ``verify=False`` skips the size, hash and row checks (the fast path: a flipped bit is
    then read as data); the names are still checked and symlinks still refused.
    ``pandas.read_parquet(OUT)`` checks nothing of this.
    """
    import pyarrow as pa

    out = Path(out)
    for attempt in range(3):
        d = open_dir(out)  # one descriptor for the manifest, the log and every part
        try:
            manifest, entries = read_manifest(out, d)
            if not entries:
                raise InputError(f"dir: {str(out)!r} holds no finished chunk yet")
            tables = _read_parts(out, d, entries, verify)
            break
        except _Missing:
            # a running sweep compacted parts after we read its log: read the log again
            if attempt == 2:
                raise
        finally:
            d.close()
    try:
        table = pa.concat_tables(tables)
    except (OSError, pa.ArrowException) as exc:
        raise InputError(f"dir: {str(out)!r} has parts of different schemas ({exc}); run "
                         "the sweep again to verify and recompute them") from None
    return SweepDataset(out, table.to_pandas(use_threads=False), manifest, verify)


class _Missing(InputError):
    """A logged part is gone (deleted, or compacted by a running sweep)."""


def _read_parts(out, d, entries, verify):
    import hashlib

    import pyarrow as pa
    import pyarrow.parquet as pq

    from rotordyn.sweep.safedir import NotRegular

    def damaged(name, why, cls=InputError):
        return cls(f"dir: part {name!r} of {str(out)!r} is damaged ({why}); run the "
                   "sweep again to verify and recompute it")

    tables = []
    for e in entries:
        name = e["file"]
        try:
            data = d.read(name, expect_size=e["bytes"] if verify else None)
        except FileNotFoundError:
            raise damaged(name, "missing", _Missing) from None
        except NotRegular as exc:
            raise damaged(name, exc.strerror) from None
        except OSError as exc:
            raise damaged(name, exc.strerror or exc) from None
        if verify and (len(data) != e["bytes"]
                       or hashlib.sha256(data).hexdigest() != e["sha256"]):
            raise damaged(name, "its SHA-256 differs from the log's")
        try:
            t = pq.read_table(pa.BufferReader(data), use_threads=False)
        except (OSError, pa.ArrowException) as exc:
            raise damaged(name, exc) from None
        if verify and t.num_rows != e["rows"]:
            raise damaged(name, f"{t.num_rows} rows, the log says {e['rows']}")
        tables.append(t)
    return tables


def _np(x):
    return np.asarray(x)
