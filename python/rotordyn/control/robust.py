"""Robust stability and performance of a fixed feedback law over a grid of operating points
and model uncertainties, in one call: :func:`robust`.

The law K (a :class:`~rotordyn.control.Controller`) stays fixed; at every grid point — any
combination of ``speed_hz``, ``chamber_pressure_pa``, ``config_ay_m`` and numeric model fields
by dotted path (``bearings.active.clearance_m``, ``bearings.active.viscosity_pa_s``,
``rotor.disks.1.mass_kg``, ...) — the plant is re-linearised about that point's own equilibrium
(solved cold, so a row does not depend on the order the points ran in) and the loop closed:

* stability: the closed-loop eigenvalues λ of [A + B D_k C, B C_k; B_k C, A_k] (a discrete law:
  the exact sampled-data loop, λ = ln z / T), their spectral abscissa max Re λ and the least
  damping ratio min ζ, ζ = −Re λ / |λ|;
* performance: the margins of the loop broken at the valve command, L = −K G
  (:func:`rotordyn.control.margins.loop_margins`, located exactly): gain margins below and
  above 1, phase and delay margins, balanced disk margin, peak sensitivity max |1/(1 + L)|
  with its zone after ISO 14839-3 (A ≤ 3, B ≤ 4, C ≤ 5, D above;
  :mod:`rotordyn.sweep.robust_rows` for the source);
* the worst case over the grid of each quantity, with its point.

It runs as the ``robust`` analysis of the sweep machinery (:mod:`rotordyn.sweep`): parquet
rows, deterministic, resumable when ``out`` is given (the same call again computes only the
missing chunks), on threads or worker processes. A point whose equilibrium fails is a row
with that status (``no_equilibrium``, ``not_converged``, ``error``) and no verdict:
``point_stable`` and every margin are null. An unstable point has a verdict and no margins.

Not built: the structured singular value μ over the physical parameters. SLICOT's AB13MD
(slycot, the optional ``hinf`` extra) bounds μ of a given M(iω) for a block structure, but
rotordyn has no linear fractional representation of the film coefficients in speed,
clearance or viscosity (the plant is re-linearised numerically at each point), so there is no
M to give it; python-control has no μ. The multivariable disk margin at the measurements
(:func:`rotordyn.control.margins.multiloop_disk_margin`) is the μ of a diagonal complex
perturbation of the measurement channels.
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
from rotordyn.errors import InputError
from rotordyn.sweep import robust_rows as rr
from rotordyn.sweep.spec import SweepSpec, _axis

# worst case of each column: "max" or "min" over the points that have it
WORST = {"max_real_1_per_s": "max", "min_damping_ratio": "min",
         "gain_margin_lower": "max", "gain_margin_upper": "min", "phase_margin_deg": "min",
         "delay_margin_s": "min", "disk_margin": "min", "peak_sensitivity": "max"}
VERDICT = ["point_stable"] + list(WORST)


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
               equilibrium: dict | None = None) -> SweepSpec:
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
    opts = {"controller": rr.controller_table(controller)}
    if actuator is not None:
        opts["actuator"] = rr.actuator_table(chk.actuator(actuator))
    opts["margins"] = v.boolean("margins", margins)
    opts["pade_order"] = v.integer("pade_order", pade_order, lo=1, hi=20)
    if equilibrium is not None:
        if not isinstance(equilibrium, dict):
            raise InputError(f"equilibrium: expected a dict (method, tol, max_iter), got "
                             f"{type(equilibrium).__name__}")
        from rotordyn.sweep.spec import OPTIONS

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
           equilibrium: dict | None = None) -> "RobustResult":
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
    """
    spec = build_spec(system, controller, grid, actuator=actuator, margins=margins,
                      pade_order=pade_order, chunk_size=chunk_size, name=name,
                      equilibrium=equilibrium)
    from rotordyn.sweep import open_dataset, run_sweep

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


@dataclass(frozen=True)
class RobustResult:
    """Rows of a robust sweep (one per grid point, in ``point_id`` order): the axes, status,
    ``point_stable`` (null without a verdict), max Re λ (1/s), min ζ, the margins and the ISO
    14839-3 zone of the peak sensitivity. :meth:`worst` gives each quantity's worst case with
    its point."""

    frame: object
    axes: dict
    controller_name: str = "controller"
    out: Path | None = None

    def to_frame(self):
        return self.frame.copy()

    @property
    def verdicts(self):
        """The rows that have a closed-loop verdict (equilibrium converged)."""
        return self.frame[self.frame["point_stable"].notna()]

    @property
    def failed(self):
        """The rows without a verdict (status other than ok), with their messages."""
        return self.frame[self.frame["point_stable"].isna()]

    @property
    def all_stable(self) -> bool:
        """Every point has a verdict and it is stable."""
        return bool(len(self.failed) == 0 and self.frame["point_stable"].astype(bool).all())

    def worst(self) -> dict:
        """{quantity: {"value", "point_id", axis values...}} — max Re λ and peak |S| at their
        largest, gain_margin_lower at its largest, the others at their smallest, over the
        points that have the quantity (margins: the stable points)."""
        out = {}
        for col, how in WORST.items():
            s = self.frame[col].astype(float)
            ok = s.notna()
            if not ok.any():
                continue
            i = s[ok].idxmax() if how == "max" else s[ok].idxmin()
            row = self.frame.loc[i]
            out[col] = {"value": float(row[col]), "point_id": int(row["point_id"]),
                        **{a: float(row[a]) for a in self.axes}}
        return out

    def summary(self) -> dict:
        """Counts (points, with a verdict, stable, unstable, failed), the worst zone and
        :meth:`worst`."""
        f = self.frame
        have = f["point_stable"].notna()
        st = f.loc[have, "point_stable"].astype(bool)
        zones = f["iso_zone"].dropna().astype(str)
        return {"controller": self.controller_name, "points": int(len(f)),
                "with_verdict": int(have.sum()), "stable": int(st.sum()),
                "unstable": int((~st).sum()), "failed": int((~have).sum()),
                "all_stable": self.all_stable,
                "worst_iso_zone": max(zones) if len(zones) else None,
                "zones": {z: int((zones == z).sum()) for z in rr.ZONES},
                "worst": self.worst()}

    def __repr__(self):
        s = self.summary()
        w = s["worst"].get("max_real_1_per_s", {})
        return (f"RobustResult({self.controller_name}: {s['points']} points, {s['stable']} "
                f"stable, {s['unstable']} unstable, {s['failed']} without verdict; worst max "
                f"Re λ {w.get('value', math.nan):.4g} 1/s at point {w.get('point_id')}; worst "
                f"zone {s['worst_iso_zone']})")

    def plot(self, value: str = "max_real_1_per_s", x: str | None = None,
             y: str | None = None, ax=None, **fixed):
        """``value`` over one axis (a line per value of a second varying axis) or a map over
        two (``x``, ``y``; ``fixed`` axis=value picks the slice of the others); failed points
        are gaps, the worst point is marked. Returns the matplotlib Figure."""
        import matplotlib.pyplot as plt

        if value not in self.frame.columns or value in ("status", "message", "iso_zone"):
            raise InputError(f"value: expected a numeric column of the rows, got {value!r}")
        varying = [a for a, vals in self.axes.items() if len(vals) > 1]
        x = x or (varying[-1] if varying else next(iter(self.axes)))
        for a in [x] + ([y] if y else []) + list(fixed):
            if a not in self.axes:
                raise InputError(f"x/y/fixed: {a!r} is not an axis of this sweep "
                                 f"(axes: {', '.join(self.axes)})")
        f = self.frame
        for a, val in fixed.items():
            f = f[np.isclose(f[a].astype(float), float(val), rtol=1e-12, atol=0)]
        vals = f[value].astype(float)
        fig = ax.figure if ax is not None else plt.figure(figsize=(7, 4.5))
        ax = ax or fig.add_subplot(111)
        if y:
            piv = f.assign(_v=vals).pivot_table(index=y, columns=x, values="_v",
                                                aggfunc="first", dropna=False)
            m = ax.pcolormesh(piv.columns.values, piv.index.values, piv.values,
                              shading="nearest")
            fig.colorbar(m, ax=ax, label=value)
            ax.set_ylabel(y)
        else:
            others = [a for a in varying if a != x]
            groups = f.groupby(others) if others else [((), f)]
            for key, g in groups:
                lab = ", ".join(f"{a}={k:g}" for a, k in zip(others, np.atleast_1d(key))) \
                    if others else None
                ax.plot(g[x].astype(float), g[value].astype(float), ".-", label=lab)
            if others and len(groups) <= 12:
                ax.legend(fontsize=7)
            ax.set_ylabel(value)
            if value == "max_real_1_per_s":
                ax.axhline(0.0, color="k", lw=0.6)
            if value == "peak_sensitivity":
                for z, hi in rr.ISO_ZONES:
                    ax.axhline(hi, color="0.6", lw=0.6, ls="--")
                    ax.text(ax.get_xlim()[1], hi, f" {z}/{chr(ord(z) + 1)}", fontsize=7,
                            va="center")
        ax.set_xlabel(x)
        ax.set_title(f"{self.controller_name}: {value}")
        return fig
