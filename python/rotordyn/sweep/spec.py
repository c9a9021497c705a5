"""Sweep specifications (``sweeps/<name>.toml``): model, grid axes with units, analysis,
options and chunk size. The grid expands deterministically, so ``point_id`` is stable across
reruns and an interrupted sweep resumes where it stopped."""

from __future__ import annotations

import hashlib
import itertools
import json
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from rotordyn.errors import InputError
from rotordyn import _validate as v

SCHEMA = "rotordyn/sweep/1"
AXES = ("speed_hz", "chamber_pressure_pa", "config_ay_m")
ANALYSES = ("equilibrium", "stability", "waterfall")
OPTIONS = {
    "equilibrium": {"method"},
    "stability": {"n_modes"},
    "waterfall": {"unbalances", "revolutions", "samples_per_revolution", "max_harmonic",
                  "rtol"},
}


def _axis(name: str, val) -> list[float]:
    where = f"grid.{name}"
    if isinstance(val, dict):
        extra = set(val) - {"start", "stop", "num"}
        if extra:
            raise InputError(f"{where}.{sorted(extra)[0]}: unknown key (allowed: start, stop, num)")
        try:
            start, stop, num = val["start"], val["stop"], val["num"]
        except KeyError as exc:
            raise InputError(f"{where}: missing {exc.args[0]!r} (start, stop, num)") from None
        v.finite(f"{where}.start", start)
        v.finite(f"{where}.stop", stop)
        v.integer(f"{where}.num", num, lo=1, hi=1_000_000)
        return [float(x) for x in np.linspace(start, stop, num)]
    if isinstance(val, (int, float)) and not isinstance(val, bool):
        return [v.finite(where, val)]
    if isinstance(val, list) and val:
        return [v.finite(f"{where}[{i}]", x) for i, x in enumerate(val)]
    raise InputError(f"{where}: expected a number, a non-empty list or {{start, stop, num}}")


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep: ``axes`` maps each grid axis to its values (outermost first)."""

    name: str
    model: str
    analysis: str
    axes: dict
    chunk_size: int = 20
    options: dict = field(default_factory=dict)
    source: str = ""

    @classmethod
    def from_toml(cls, path) -> "SweepSpec":
        p = Path(path)
        if not p.is_file():
            raise InputError(f"spec: no such file {str(p)!r}")
        try:
            doc = tomllib.loads(p.read_text(encoding="utf-8"))
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"spec: {p} is not valid TOML: {exc}") from None
        allowed = {"schema", "name", "model", "analysis", "chunk_size", "grid", "options"}
        for k in doc:
            if k not in allowed:
                raise InputError(f"spec.{k}: unknown key (allowed: {', '.join(sorted(allowed))})")
        if doc.get("schema") != SCHEMA:
            raise InputError(f"schema: expected {SCHEMA!r}, got {doc.get('schema')!r}")
        analysis = v.choice("analysis", doc.get("analysis"), ANALYSES)
        grid = doc.get("grid")
        if not isinstance(grid, dict) or not grid:
            raise InputError("grid: expected a [grid] table with at least one axis")
        for k in grid:
            if k not in AXES:
                raise InputError(f"grid.{k}: unknown axis (allowed: {', '.join(AXES)})")
        axes = {k: _axis(k, grid[k]) for k in grid}
        opts = doc.get("options", {})
        for k in opts:
            if k not in OPTIONS[analysis]:
                raise InputError(f"options.{k}: unknown option for analysis {analysis!r} "
                                 f"(allowed: {', '.join(sorted(OPTIONS[analysis]))})")
        model = doc.get("model")
        if not isinstance(model, str) or not model:
            raise InputError("model: expected a built-in model name or a TOML path")
        if model.endswith(".toml") and not Path(model).is_absolute():
            model = str((p.parent / model).resolve())
        chunk = v.integer("chunk_size", doc.get("chunk_size", 20), lo=1, hi=100000)
        return cls(name=str(doc.get("name", p.stem)), model=model, analysis=analysis,
                   axes=axes, chunk_size=chunk, options=dict(opts),
                   source=p.read_text(encoding="utf-8"))

    def points(self) -> list[dict]:
        """Every grid point as a dict of axis values, in a fixed order (outermost first);
        axes not in the grid take their defaults at run time."""
        names = list(self.axes)
        return [dict(zip(names, vals)) for vals in itertools.product(*self.axes.values())]

    def chunks(self) -> list[list[tuple[int, dict]]]:
        """Contiguous chunks of (point_id, point)."""
        pts = list(enumerate(self.points()))
        return [pts[i:i + self.chunk_size] for i in range(0, len(pts), self.chunk_size)]

    def hash(self) -> str:
        payload = json.dumps({"model": self.model, "analysis": self.analysis,
                              "axes": self.axes, "options": self.options,
                              "chunk_size": self.chunk_size}, sort_keys=True)
        return hashlib.sha256(payload.encode()).hexdigest()[:16]
