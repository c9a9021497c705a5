"""Save a result to one file and load it back as an equal object (issue 18).

The file is a NumPy ``.npz`` archive (read without pickle) holding every array of the result
under a numbered key, and one entry ``__rotordyn__``: UTF-8 JSON with

* ``schema``: ``"rotordyn/result/<n>"`` (:data:`SCHEMA_VERSION`; a file from a newer schema is
  refused, an older one is read);
* ``kind``: the result's class (``StabilityResult``, ``CampbellResult`` …);
* ``rotordyn``: the package version that wrote it;
* ``value``: the result's fields as a tree: plain JSON for numbers and text, ``{"$array":
  key}`` for an array, ``{"$frame": key}`` for a table (parquet bytes, dtypes and categories
  kept), ``{"$tuple"|"$list"|"$dict": …}``, and ``{"$dataclass": "module:Class", "fields":
  …}`` for nested results (a stability result's linear model and equilibrium), and
  ``{"$system": text}`` for a model held by a result (a thermal equilibrium's frozen
  ``system``): its TOML model file, read back with ``System.from_toml`` (lossless).

Only classes of ``rotordyn.results`` are rebuilt from a file, so a file cannot name arbitrary
code. Any family can be saved: equilibrium, stability (with its linear model), modes,
Campbell, unbalance, static, threshold, boundary, state space, transient, the system thermal
equilibrium, and the thermal stability, Campbell and unbalance results that carry one per
point."""

from __future__ import annotations

import dataclasses
import importlib
import io
import json
import math
import os
from pathlib import Path

import numpy as np

from rotordyn._common.info import __version__
from rotordyn.errors import InputError, OutputError
from rotordyn.model.system import System

SCHEMA = "rotordyn/result"
SCHEMA_VERSION = 1
META_KEY = "__rotordyn__"
ALLOWED_MODULES = ("rotordyn.results.",)


class _Encoder:
    def __init__(self):
        self.arrays: dict[str, np.ndarray] = {}

    def _put(self, a: np.ndarray) -> str:
        key = f"a{len(self.arrays)}"
        self.arrays[key] = a
        return key

    def enc(self, x, where: str):
        import pandas as pd

        if x is None or isinstance(x, (bool, str)):
            return x
        if isinstance(x, (int, np.integer)) and not isinstance(x, np.bool_):
            return {"$int": int(x)} if isinstance(x, np.integer) else x
        if isinstance(x, (float, np.floating)):
            f = float(x)
            return f if math.isfinite(f) else {"$float": repr(f)}
        if isinstance(x, np.bool_):
            return {"$bool_": bool(x)}
        if isinstance(x, (complex, np.complexfloating)):
            return {"$complex": [self.enc(x.real, where), self.enc(x.imag, where)]}
        if isinstance(x, np.ndarray):
            if x.dtype == object:
                # text, with None entries allowed (e.g. point_message: None where a point
                # converged), kept as a mask beside the text
                none = np.array([v is None for v in x.ravel()], dtype=bool).reshape(x.shape)
                if not all(isinstance(v, str) or v is None for v in x.ravel()):
                    raise InputError(f"save: {where}: an object array that is not text")
                a = np.where(none, "", x).astype(str)
                out = {"$array": self._put(a), "object": True}
                if none.any():
                    out["none"] = self._put(none)
                return out
            if x.dtype.kind not in "biufcUS":
                raise InputError(f"save: {where}: arrays of dtype {x.dtype} cannot be saved")
            return {"$array": self._put(x)}
        if isinstance(x, pd.DataFrame):
            buf = io.BytesIO()
            x.to_parquet(buf, index=True)
            return {"$frame": self._put(np.frombuffer(buf.getvalue(), dtype=np.uint8))}
        if isinstance(x, tuple):
            return {"$tuple": [self.enc(v, f"{where}[{i}]") for i, v in enumerate(x)]}
        if isinstance(x, list):
            return {"$list": [self.enc(v, f"{where}[{i}]") for i, v in enumerate(x)]}
        if isinstance(x, dict):
            return {"$dict": [[self.enc(k, f"{where} key"), self.enc(v, f"{where}[{k!r}]")]
                              for k, v in x.items()]}
        if isinstance(x, System):  # a thermal equilibrium's frozen model: its model file
            return {"$system": x.to_toml()}
        if dataclasses.is_dataclass(x) and not isinstance(x, type):
            cls = type(x)
            if not cls.__module__.startswith(ALLOWED_MODULES):
                raise InputError(f"save: {where}: a {cls.__name__} is not a result object")
            return {"$dataclass": f"{cls.__module__}:{cls.__qualname__}",
                    "fields": {f.name: self.enc(getattr(x, f.name), f"{where}.{f.name}")
                               for f in dataclasses.fields(x)}}
        raise InputError(f"save: {where}: values of type {type(x).__name__} cannot be saved")


def _class(name: str, where: str):
    mod, _, qual = name.partition(":")
    if not mod.startswith(ALLOWED_MODULES) or not qual.isidentifier():
        raise InputError(f"load_result: {where}: {name!r} is not a rotordyn result class")
    try:
        cls = getattr(importlib.import_module(mod), qual)
    except (ImportError, AttributeError):
        raise InputError(f"load_result: {where}: unknown result class {name!r} (written by a "
                         "different rotordyn?)") from None
    if not dataclasses.is_dataclass(cls):
        raise InputError(f"load_result: {where}: {name!r} is not a result class")
    return cls


def _dec(x, arrays, where: str):
    import pandas as pd

    if x is None or isinstance(x, (bool, int, float, str)):
        return x
    if isinstance(x, dict):
        if "$array" in x:
            a = arrays[x["$array"]]
            if not x.get("object"):
                return a
            a = a.astype(object)
            if "none" in x:
                a[np.asarray(arrays[x["none"]], dtype=bool)] = None
            return a
        if "$frame" in x:
            return pd.read_parquet(io.BytesIO(arrays[x["$frame"]].tobytes()), use_threads=False)
        if "$int" in x:
            return np.int64(x["$int"])
        if "$float" in x:
            return float(x["$float"])
        if "$bool_" in x:
            return np.bool_(x["$bool_"])
        if "$complex" in x:
            re, im = (_dec(v, arrays, where) for v in x["$complex"])
            return complex(re, im)
        if "$tuple" in x:
            return tuple(_dec(v, arrays, f"{where}[{i}]") for i, v in enumerate(x["$tuple"]))
        if "$list" in x:
            return [_dec(v, arrays, f"{where}[{i}]") for i, v in enumerate(x["$list"])]
        if "$dict" in x:
            return {_dec(k, arrays, where): _dec(v, arrays, where) for k, v in x["$dict"]}
        if "$system" in x:  # read as a model file is (no code named by the file)
            return System.from_toml(str(x["$system"]), is_text=True)
        if "$dataclass" in x:
            cls = _class(x["$dataclass"], where)
            vals = {k: _dec(v, arrays, f"{where}.{k}") for k, v in x["fields"].items()}
            fields = {f.name: f for f in dataclasses.fields(cls)}
            if set(vals) - set(fields):
                raise InputError(f"load_result: {where}: fields {sorted(set(vals) - set(fields))}"
                                 f" are not fields of {cls.__name__}")
            obj = cls(**{k: v for k, v in vals.items() if fields[k].init})
            for k, v in vals.items():
                if not fields[k].init:
                    object.__setattr__(obj, k, v)
            return obj
    raise InputError(f"load_result: {where}: unreadable value {str(x)[:60]!r}")


def save_result(result, path) -> Path:
    """Write ``result`` (any rotordyn result object) to ``path`` (conventionally ``.npz``);
    returns the path. Written to a temporary name and renamed, so a failed write leaves no
    half file."""
    if not (dataclasses.is_dataclass(result) and
            type(result).__module__.startswith(ALLOWED_MODULES)):
        raise InputError(f"save: expected a rotordyn result object, got "
                         f"{type(result).__name__}")
    e = _Encoder()
    value = e.enc(result, type(result).__name__)
    meta = {"schema": f"{SCHEMA}/{SCHEMA_VERSION}", "kind": type(result).__name__,
            "rotordyn": __version__, "value": value}
    blob = np.frombuffer(json.dumps(meta).encode("utf-8"), dtype=np.uint8)
    out = Path(path)
    tmp = out.with_name(f".{out.name}.tmp{os.getpid()}")
    try:
        with open(tmp, "wb") as fh:
            np.savez_compressed(fh, **{META_KEY: blob}, **e.arrays)
        os.replace(tmp, out)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise OutputError(f"out: cannot write {out}: {exc.strerror or exc}") from None
    return out


def load_result(path, kind: str | type | None = None):
    """The result saved in ``path`` by :func:`save_result` (``result.save(path)``), equal to
    the one saved. ``kind`` (a class or its name): refuse a file holding another kind of
    result. A file that is not a saved result, or from a newer schema, is refused with an
    :class:`~rotordyn.InputError`."""
    p = Path(path)
    try:
        with np.load(p, allow_pickle=False) as z:
            if META_KEY not in z.files:
                raise InputError(f"load_result: {p} is not a saved rotordyn result (no "
                                 f"{META_KEY} entry)")
            arrays = {k: z[k] for k in z.files}
    except FileNotFoundError:
        raise InputError(f"load_result: {p}: no such file") from None
    except (OSError, ValueError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError(f"load_result: {p} is not a saved rotordyn result ({exc})") from None
    try:
        meta = json.loads(arrays.pop(META_KEY).tobytes().decode("utf-8"))
        schema = str(meta["schema"])
    except (ValueError, KeyError, TypeError):
        raise InputError(f"load_result: {p}: unreadable {META_KEY} metadata") from None
    name, _, ver = schema.rpartition("/")
    if name != SCHEMA or not ver.isdigit():
        raise InputError(f"load_result: {p}: schema {schema!r} is not {SCHEMA}/<n>")
    if int(ver) > SCHEMA_VERSION:
        raise InputError(f"load_result: {p}: schema version {ver} is newer than this rotordyn "
                         f"({__version__}) reads (≤ {SCHEMA_VERSION}); update rotordyn "
                         f"(written by rotordyn {meta.get('rotordyn', '?')})")
    want = kind if kind is None or isinstance(kind, str) else kind.__name__
    if want is not None and meta.get("kind") != want:
        raise InputError(f"load_result: {p} holds a {meta.get('kind')}, expected a {want}")
    return _dec(meta["value"], arrays, str(meta.get("kind")))


__all__ = ["SCHEMA", "SCHEMA_VERSION", "load_result", "save_result"]
