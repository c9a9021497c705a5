"""Robust stability and performance of a fixed law over a grid, in one call: :func:`robust`
runs the ``robust`` analysis (:mod:`rotordyn.sweep.robust_rows`) through the sweep machinery
and returns a :class:`rotordyn.control.robust.RobustResult` (rows, worst cases, zones, plots;
the physics and its sources are in :mod:`rotordyn.control.robust`, docs/control.md §2.7).

Parquet rows, deterministic (equilibria continued only along whole lines inside a chunk),
resumable when ``out`` is given (the same call again computes only the missing chunks), on
threads or worker processes; a point whose equilibrium fails is a row with that status and no
verdict.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control.robust import RobustResult, actuator_table, controller_table
from rotordyn.errors import InputError
from rotordyn.sweep import robust_rows as rr
from rotordyn.sweep.spec import OPTIONS, SweepSpec, _axis


@dataclass(frozen=True)
class _SystemSpec(SweepSpec):
    """A sweep spec whose model is an in-memory :class:`~rotordyn.System` (its hash names it
    by the SHA-256 of its TOML, so a rerun with the same model resumes)."""

    system: object = field(default=None, compare=False, repr=False)

    def load_model(self):
        return self.system


def _toml_value(x) -> str:
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, (float, np.floating)):
        x = float(x)
        return repr(x) if math.isfinite(x) else ("nan" if math.isnan(x) else
                                                  ("inf" if x > 0 else "-inf"))
    if isinstance(x, str):
        return json.dumps(x)
    if isinstance(x, dict):
        return "{ " + ", ".join(f"{json.dumps(k)} = {_toml_value(val)}"
                                for k, val in x.items()) + " }"
    return "[" + ", ".join(_toml_value(e) for e in x) + "]"


def spec_toml(name: str, axes: dict, options: dict, chunk_size: int, model: str) -> str:
    """The spec as TOML text (stored in the dataset's manifest; ``rotordyn sweep`` runs it
    with the model file saved as ``model``)."""
    lines = ['schema = "rotordyn/sweep/1"', f"name = {json.dumps(name)}",
             f"model = {json.dumps(model)}", 'analysis = "robust"',
             f"chunk_size = {chunk_size}", "", "[grid]"]
    lines += [f"{json.dumps(k)} = {_toml_value(val)}" for k, val in axes.items()]
    lines += ["", "[options]"]
    lines += [f"{k} = {_toml_value(val)}" for k, val in options.items()]
    return "\n".join(lines) + "\n"


def _grid(grid) -> dict:
    if not isinstance(grid, dict):
        raise InputError(f"grid: expected a dict {{axis: values}}, got {type(grid).__name__}")
    if not grid:
        raise InputError("grid: expected at least one axis (e.g. {'speed_hz': [40, 50, 60]})")
    axes = {}
    for k, val in grid.items():
        if not isinstance(k, str) or not k:
            raise InputError(f"grid: expected axis names as strings, got {k!r}")
        if isinstance(val, np.ndarray):
            val = val.tolist()
        elif isinstance(val, tuple):
            val = list(val)
        elif isinstance(val, (np.floating, np.integer)):
            val = float(val)
        if isinstance(val, list) and any(isinstance(e, (np.floating, np.integer)) for e in val):
            val = [float(e) for e in val]
        axes[k] = _axis(k, val)
    return axes


def build_spec(system, controller, grid, *, actuator=None, margins: bool = True,
               pade_order: int = 6, chunk_size: int | None = None, name: str = "robust",
               equilibrium: dict | None = None, continuation: bool = True) -> SweepSpec:
    """The ``robust`` sweep spec of :func:`robust` (checked: axes against the model, the
    law's measurements, the options), without running it."""
    from rotordyn.control import _checks as chk
    from rotordyn.model.system import System
    from rotordyn.operation.controller import Controller

    if not isinstance(system, System):
        raise InputError(f"system: expected a rotordyn.System, got {type(system).__name__}")
    if not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller, got "
                         f"{type(controller).__name__}")
    axes = _grid(grid)
    opts = {"controller": controller_table(controller)}
    if actuator is not None:
        opts["actuator"] = actuator_table(chk.actuator(actuator))
    opts["margins"] = v.boolean("margins", margins)
    opts["pade_order"] = v.integer("pade_order", pade_order, lo=1, hi=20)
    opts["continuation"] = v.boolean("continuation", continuation)
    if equilibrium is not None:
        if not isinstance(equilibrium, dict):
            raise InputError(f"equilibrium: expected a dict (method, tol, max_iter), got "
                             f"{type(equilibrium).__name__}")
        for k, val in equilibrium.items():
            if k not in ("method", "tol", "max_iter"):
                raise InputError(f"equilibrium.{k}: unknown key (allowed: method, tol, "
                                 f"max_iter)")
            opts[k] = OPTIONS["robust"][k](f"equilibrium.{k}", val)
    for k in ("controller", "actuator"):
        if k in opts:
            opts[k] = OPTIONS_CHECK[k](f"options.{k}", opts[k])
    n = math.prod(len(x) for x in axes.values())
    chunk = v.integer("chunk_size", chunk_size, lo=1, hi=100000) if chunk_size is not None \
        else max(1, min(50, -(-n // 8)))
    v.text("name", name)
    text = system.to_toml()
    model = "model-sha256:" + hashlib.sha256(text.encode()).hexdigest()[:16]
    spec = _SystemSpec(name=name, model=model, analysis="robust", axes=axes,
                       chunk_size=chunk, options=opts,
                       source=spec_toml(name, axes, opts, chunk, "model.toml"),
                       system=system)
    spec._check_shape()
    spec.check_against(system)
    return spec


OPTIONS_CHECK = {"controller": rr.controller_option, "actuator": rr.actuator_option}


def robust(system, controller, grid, *, actuator=None, margins: bool = True,
           pade_order: int = 6, out=None, threads: int | None = None,
           workers: int | None = None, chunk_size: int | None = None, resume: bool = True,
           progress: bool = False, name: str = "robust",
           equilibrium: dict | None = None, continuation: bool = True) -> "RobustResult":
    """The fixed law ``controller`` closed around ``system`` re-linearised at every point of
    ``grid`` (module docstring).

    grid : {axis: values}; axes ``speed_hz``, ``chamber_pressure_pa``, ``config_ay_m`` and
        dotted model fields (the sweep spec's axes, docs/sweeps.md); values a number, a list
        or array, or ``{"start", "stop", "num"}``. The first axis is outermost.
    actuator : the valve (default ``Actuator()``, the 100 Hz second-order valve).
    margins : compute the loop margins at every stable point (0.2–1 s each on the rig);
        False: stability only (a few ms per point).
    out : a directory for the parquet rows (kept; the same call resumes). None: a temporary
        one, removed after reading.
    threads / workers : as :func:`rotordyn.sweep.run_sweep` (default: one thread per core).
    equilibrium : {method, tol, max_iter} of the equilibrium at each point.
    continuation : start each point's equilibrium from the previous point's along the last
        varying axis (chunks hold whole lines, so the rows stay deterministic; a failed
        continued solve is retried cold); False: every point cold, as a direct call with
        ``warm_start=False`` (about 2× the cost).
    """
    spec = build_spec(system, controller, grid, actuator=actuator, margins=margins,
                      pade_order=pade_order, chunk_size=chunk_size, name=name,
                      equilibrium=equilibrium, continuation=continuation)
    from rotordyn.sweep.dataset import open_dataset
    from rotordyn.sweep.runner import run_sweep

    if threads is None and workers is None:
        threads = os.cpu_count() or 1
    tmp = None
    if out is None:
        tmp = tempfile.mkdtemp(prefix="rotordyn-robust-")
        target = Path(tmp) / "sweep"
    else:
        target = Path(out)
    try:
        run_sweep(spec, target, threads=threads, workers=workers, resume=resume,
                  progress=progress)
        frame = open_dataset(target).frame
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
    return RobustResult(frame, dict(spec.ordered_axes), controller.name,
                        None if out is None else Path(out))
