"""Sweep specifications (``sweeps/<name>.toml``): model, grid axes, analysis, options, chunk
size. Everything is checked when the spec loads (axes against the model, options against the
analysis), so a bad spec is one InputError naming the field before any worker starts.

Axes are the operating variables (``speed_hz``, ``chamber_pressure_pa``, ``config_ay_m``,
``config_ax_m``), any numeric model field by dotted path (:mod:`rotordyn.sweep.paths`) or an
analysis option by ``options.<name>[.<index>...]`` (e.g. ``options.unbalances.0.1``, the first
unbalance's magnitude). An axis is a number, a list, ``{start, stop, num}`` (values exact:
``start + i*step`` computed in decimal, so ``-2.5e-3 + 1*0.25e-3`` is ``-0.00225``) or
``{start, stop, num, scale = "log"}``. The grid expands in a fixed order (first axis
outermost), so ``point_id`` is stable across reruns.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import tomllib
from dataclasses import dataclass, field
from decimal import Decimal, localcontext
from pathlib import Path

from rotordyn.analysis.continuation import METHODS as CONTINUATION_METHODS
from rotordyn.analysis.continuation import NEWTON_MODES
from rotordyn.errors import InputError
from rotordyn.sweep import axis_values
from rotordyn.sweep.model_axes import check_model_axis
from rotordyn._common import validate as v
from rotordyn.model import builtin as models
from rotordyn.sweep import robust_rows as rr

SCHEMA = "rotordyn/sweep/1"
OPERATING = ("speed_hz", "chamber_pressure_pa", "config_ay_m", "config_ax_m")
DEFAULTS = {"speed_hz": 50.0, "chamber_pressure_pa": 0.0}
ANALYSES = ("equilibrium", "thermal", "stability", "campbell", "threshold", "boundary",
            "unbalance", "waterfall", "run-up", "robust")
ANALYSES += ("hopf",)
ANALYSES += ("limit_cycle",)
MAX_POINTS = 10_000_000


def _opt_int(lo, hi):
    return lambda f, x: v.integer(f, x, lo=lo, hi=hi)


def _opt_choice(*allowed):
    return lambda f, x: v.choice(f, x, allowed)


def _opt_range(lo, hi, lo_open=True):
    return lambda f, x: v.in_range(f, x, lo, hi, lo_open=lo_open)


def _opt_bearing(f, x):
    if not isinstance(x, str) or not x:
        raise InputError(f"{f}: expected a bearing's name (a string), got {x!r}")
    return x


def _opt_bool(f, x):
    if not isinstance(x, bool):
        raise InputError(f"{f}: expected true or false, got {x!r}")
    return x


def _opt_axis(f, x):
    if not isinstance(x, str):
        raise InputError(f"{f}: expected an axis name, got {x!r}")
    return x


def _opt_unbalances(f, x):
    if not isinstance(x, list) or not x:
        raise InputError(f"{f}: expected a list of [station, mass_kg_m, phase_deg], got {x!r}")
    out = []
    for i, u in enumerate(x):
        if not isinstance(u, list) or len(u) != 3:
            raise InputError(f"{f}[{i}]: expected [station, mass_kg_m, phase_deg], got {u!r}")
        out.append([v.integer(f"{f}[{i}].station", u[0], lo=0),
                    v.finite(f"{f}[{i}].mass_kg_m", u[1]), v.finite(f"{f}[{i}].phase_deg", u[2])])
    return out


def _opt_stations(f, x):
    if not isinstance(x, list) or not x:
        raise InputError(f"{f}: expected a non-empty list of station indices, got {x!r}")
    return [v.integer(f"{f}[{i}]", s, lo=0) for i, s in enumerate(x)]


def _opt_operating(f, x):
    if not isinstance(x, list) or len(x) != 2:
        raise InputError(f"{f}: expected [min, max] in Hz, got {x!r}")
    lo, hi = v.positive(f"{f}[0]", x[0]), v.positive(f"{f}[1]", x[1])
    if hi < lo:
        raise InputError(f"{f}: expected min <= max, got {x!r}")
    return [lo, hi]


# options.thermal: each point at its own thermal equilibrium (the model's [thermal]; these
# scalar keywords of rotordyn.system_thermal_equilibrium override it for every film)
_THERMAL_KEYS = {"model": _opt_choice("effective", "thd"), "tol_k": _opt_range(0.0, 1.0),
                 "supply_temperature_c": lambda f, x: v.finite(f, x),
                 "carry_over": lambda f, x: v.in_range(f, x, 0.0, 1.0, lo_open=False),
                 "effective_factor": lambda f, x: v.in_range(f, x, 0.0, 1.0, lo_open=False),
                 "supply_flow_m3_s": lambda f, x: v.non_negative(f, x),
                 "journal_htc_w_m2k": lambda f, x: v.non_negative(f, x),
                 "bush_htc_w_m2k": lambda f, x: v.non_negative(f, x),
                 "journal_temperature_c": lambda f, x: v.finite(f, x),
                 "bush_temperature_c": lambda f, x: v.finite(f, x),
                 "wall_htc": _opt_choice("given", "film"),
                 "journal_wall": _opt_choice("fixed", "balance"),
                 "bush_wall": _opt_choice("fixed", "conduction"),
                 "bush_thickness_m": lambda f, x: v.non_negative(f, x),
                 "bush_conductivity_w_per_m_k": lambda f, x: v.non_negative(f, x),
                 "back_htc_w_m2k": lambda f, x: v.non_negative(f, x),
                 "back_temperature_c": lambda f, x: v.finite(f, x)}


def _opt_thermal(f, x):
    if x is True:
        return {}
    if not isinstance(x, dict):
        raise InputError(f"{f}: expected true or a table of thermal keywords "
                         f"({', '.join(_THERMAL_KEYS)}), got {x!r}")
    out = {}
    for k, val in x.items():
        if k not in _THERMAL_KEYS:
            raise InputError(f"{f}.{k}: unknown thermal keyword (allowed: "
                             f"{', '.join(_THERMAL_KEYS)}; the oil and per-film values come "
                             "from the model's [thermal], axes thermal.<field>)")
        out[k] = _THERMAL_KEYS[k](f"{f}.{k}", val)
    return out


_EQ = {"method": _opt_choice("newton", "successive"), "tol": _opt_range(0.0, 1e-2),
       "max_iter": _opt_int(1, 10000)}
_LIN = {"linearization": _opt_choice("perturbation", "finite_difference")}
OPTIONS = {
    "equilibrium": dict(_EQ),
    "thermal": {"tol_k": _opt_range(0.0, 1.0)},
    "stability": {**_EQ, **_LIN, "n_modes": _opt_int(1, 1000), "track": _opt_bool,
                  "line": _opt_axis, "thermal": _opt_thermal, "bearing": _opt_bearing},
    "campbell": {**_EQ, **_LIN, "n_modes": _opt_int(1, 1000), "thermal": _opt_thermal,
                 "bearing": _opt_bearing},
    "threshold": {"vary": _opt_axis, "exclude_sleeve_modes": _opt_bool,
                  "xtol": _opt_range(0.0, math.inf)},
    "boundary": {"x": _opt_axis, "y": _opt_axis, "z": _opt_axis,
                 "resolution": _opt_int(3, 100001), "refine": _opt_choice("columns", "cells"),
                 "exclude_sleeve_modes": _opt_bool},
    "unbalance": {**_LIN, "unbalances": _opt_unbalances, "stations": _opt_stations,
                  "operating_speed_hz": _opt_operating, "thermal": _opt_thermal},
    "waterfall": {"unbalances": _opt_unbalances, "revolutions": _opt_int(4, 10000),
                  "samples_per_revolution": _opt_int(8, 4096),
                  "max_harmonic": _opt_range(0.0, 100.0),
                  "max_frequency_hz": _opt_range(0.0, 1e6), "rtol": _opt_range(0.0, 1e-2),
                  "rub_fraction": _opt_range(0.0, 0.999, lo_open=False),
                  "bdf_max_order": _opt_int(1, 5), "bearing": _opt_bearing},
    "run-up": {"unbalances": _opt_unbalances, "start_hz": _opt_range(0.0, 1e5),
               "stop_hz": _opt_range(0.0, 1e5), "rate_hz_per_s": _opt_range(0.0, 1e6),
               "samples_per_revolution": _opt_int(8, 4096), "rtol": _opt_range(0.0, 1e-2),
               "rub_fraction": _opt_range(0.0, 0.999, lo_open=False),
               "bdf_max_order": _opt_int(1, 5), "bearing": _opt_bearing},
}
OPTIONS["hopf"] = {**OPTIONS["threshold"], "fd_step": _opt_range(0.0, 0.5),
                   # l1 again on every film grid refined twice (rotordyn.hopf's grid_check)
                   "grid_check": _opt_bool}
REQUIRED = {"threshold": ("vary",), "hopf": ("vary",), "boundary": ("x", "y", "resolution"),
            "unbalance": ("unbalances",), "waterfall": ("unbalances",),
            "run-up": ("unbalances", "start_hz", "stop_hz", "rate_hz_per_s")}
# a fixed law closed around the plant re-linearised at each point (rotordyn.control.robust)
OPTIONS["robust"] = {**_EQ, "controller": rr.controller_option,
                     "actuator": rr.actuator_option, "margins": _opt_bool,
                     "pade_order": _opt_int(1, 20), "continuation": _opt_bool}
REQUIRED["robust"] = ("controller",)
# cycle branches born at each line's Hopf points, continued along the line
# (rotordyn.sweep.limit_cycle_rows; docs/nonlinear.md)
OPTIONS["limit_cycle"] = {**OPTIONS["hopf"], "station": _opt_int(0, 100000),
                          "rtol": _opt_range(1e-14, 1e-3), "tol": _opt_range(0.0, 1e-2),
                          "sensitivity_rtol": _opt_range(1e-14, 0.1),
                          "ds": _opt_range(0.0, 10.0), "ds_max": _opt_range(0.0, 10.0),
                          "max_points": _opt_int(2, 10000), "n_out": _opt_int(8, 100000),
                          "distance": _opt_range(0.0, 0.5),
                          "start_amplitude": _opt_range(0.0, 0.9),
                          "newton": _opt_choice(*NEWTON_MODES),
                          "method": _opt_choice(*CONTINUATION_METHODS),
                          "harmonics": _opt_int(1, 1000), "time_points": _opt_int(3, 100000)}
REQUIRED["limit_cycle"] = ("vary",)


def _dec(x) -> Decimal:
    return Decimal(repr(float(x)))


def _axis(name: str, val) -> list[float]:
    """The values of one axis (exact decimal arithmetic for ranges)."""
    where = f"grid.{name}"
    if isinstance(val, dict):
        extra = set(val) - {"start", "stop", "num", "scale"}
        if extra:
            raise InputError(f"{where}.{sorted(extra)[0]}: unknown key "
                             "(allowed: start, stop, num, scale)")
        try:
            start, stop, num = val["start"], val["stop"], val["num"]
        except KeyError as exc:
            raise InputError(f"{where}: missing {exc.args[0]!r} (start, stop, num)") from None
        start = v.finite(f"{where}.start", start)
        stop = v.finite(f"{where}.stop", stop)
        num = v.integer(f"{where}.num", num, lo=1, hi=MAX_POINTS)
        scale = v.choice(f"{where}.scale", val.get("scale", "linear"), ("linear", "log"))
        if num == 1:
            return [start]
        if scale == "log":
            if start <= 0 or stop <= 0:
                raise InputError(f"{where}: a log-spaced axis needs start > 0 and stop > 0")
            a, b = math.log10(start), math.log10(stop)
            vals = [float(f"{10 ** (a + (b - a) * i / (num - 1)):.15g}") for i in range(num)]
            vals[0], vals[-1] = start, stop
            return vals
        with localcontext() as ctx:
            ctx.prec = 40
            s0, s1 = _dec(start), _dec(stop)
            step = (s1 - s0) / (num - 1)
            return [float(s0 + i * step) for i in range(num)]
    if isinstance(val, (int, float)) and not isinstance(val, bool):
        return [v.finite(where, val)]
    if isinstance(val, list) and val:
        return [v.finite(f"{where}[{i}]", x) for i, x in enumerate(val)]
    raise InputError(f"{where}: expected a number, a non-empty list or {{start, stop, num}}")


def boundary_axes(spec) -> tuple[str, ...]:
    """The refined axes of a boundary sweep: (x, y), or (x, y, z) for a boundary surface."""
    o = spec.options
    return (o["x"], o["y"]) + ((o["z"],) if o.get("z") else ())


def fine_axes(spec) -> tuple[dict, dict]:
    """(ordered fine axes: fixed axes first, then x, y (and z); per-axis coarse nodes as sorted
    fine indices, both ends included).

    The fine axis has ``resolution`` evenly spaced values from the coarse axis' first to its
    last value; each coarse value is placed on the nearest fine node (index
    ``k (resolution - 1) / (n0 - 1)`` rounded), so any resolution >= the coarse count fits:
    the coarse cells are then ``(resolution - 1) / (n0 - 1)`` fine steps wide, rounded."""
    res = spec.options["resolution"]
    refined = boundary_axes(spec)
    fixed = {k: val for k, val in spec.axes.items() if k not in refined}
    for k, val in fixed.items():
        if len(val) != 1:
            raise InputError(f"grid.{k}: a boundary sweep takes one value for every axis but "
                             f"{', '.join(refined)}, got {len(val)}")
    ax = dict(fixed)
    nodes = {}
    for a in refined:
        c = spec.axes[a]
        n0 = len(c)
        if res < n0:
            raise InputError(f"options.resolution: expected >= {n0} (the number of values "
                             f"of grid.{a}, the coarse grid), got {res}")
        even = _axis(a, {"start": c[0], "stop": c[-1], "num": n0})
        if any(abs(e - v) > 1e-12 * max(1.0, abs(v)) for e, v in zip(even, c)):
            raise InputError(f"grid.{a}: the boundary's coarse grid must be a "
                             "{start, stop, num} range (evenly spaced)")
        ax[a] = _axis(a, {"start": c[0], "stop": c[-1], "num": res})
        # nearest fine node, in integers (halves round up): exact for any sizes
        nodes[a] = sorted({(2 * k * (res - 1) + n0 - 1) // (2 * (n0 - 1)) for k in range(n0)})
    return ax, nodes


def _flatten(grid: dict, prefix: str = "") -> dict:
    """``[grid]`` with TOML sub-tables (``bearings.active.clearance_m = ...`` unquoted) turned
    back into dotted names; a table of only start/stop/num/scale keys is a range."""
    out = {}
    for k, val in grid.items():
        name = f"{prefix}{k}"
        if isinstance(val, dict) and val and not set(val) <= {"start", "stop", "num", "scale"} \
                and not ({"start", "stop", "num"} & set(val)):
            out.update(_flatten(val, name + "."))
        else:
            out[name] = val
    return out


def _spec_dirs() -> list[Path]:
    """Where built-in specs are: installed beside this module (CMake installs the
    repository's ``sweeps/`` there), else the source tree's ``sweeps/``."""
    here = Path(__file__).resolve().parent
    return [d for d in (here / "specs", here.parents[2] / "sweeps") if d.is_dir()]


def builtin_specs() -> list[str]:
    """Names of the built-in sweep specs (file stems, e.g. ``fig9_stability_map``)."""
    return sorted({f.stem for d in _spec_dirs() for f in d.glob("*.toml")})


def builtin_spec_path(name: str) -> Path:
    """The file of built-in spec ``name`` (``fig9_stability_map``, ``fig9-stability-map``, or
    the repository path ``sweeps/fig9_stability_map.toml`` given from another directory);
    InputError naming the spec and the built-in names otherwise."""
    q = Path(name)
    if str(q.parent) in (".", "sweeps"):
        stem = q.name.removesuffix(".toml").replace("-", "_")
        for d in _spec_dirs():
            if (d / f"{stem}.toml").is_file():
                return d / f"{stem}.toml"
    raise InputError(f"spec: no such file {name!r}, nor a built-in spec (built-in: "
                     f"{', '.join(builtin_specs()) or 'none installed'})")


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep: ``axes`` maps each axis name to its values (first axis outermost)."""

    name: str
    model: str
    analysis: str
    axes: dict
    chunk_size: int = 20
    options: dict = field(default_factory=dict)
    source: str = ""
    max_files: int = 128  # chunks are compacted so the dataset has at most this many files

    # -- loading -----------------------------------------------------------------------
    @classmethod
    def from_toml(cls, path, *, check_model: bool = True) -> "SweepSpec":
        """A spec file, or a built-in spec by name (:func:`builtin_specs`: the repository's
        ``sweeps/*.toml``, shipped with the package, so ``rotordyn sweep fig9_stability_map``
        runs from any directory)."""
        p = Path(path)
        if not p.is_file():
            p = builtin_spec_path(str(path))
        try:
            text = p.read_text(encoding="utf-8")
            doc = tomllib.loads(text)
        except UnicodeDecodeError:
            raise InputError(f"spec: {p} is not UTF-8 text") from None
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"spec: {p} is not valid TOML: {exc}") from None
        allowed = {"schema", "name", "model", "analysis", "chunk_size", "max_files", "grid",
                   "options"}
        for k in doc:
            if k not in allowed:
                raise InputError(f"spec.{k}: unknown key (allowed: {', '.join(sorted(allowed))})")
        if doc.get("schema") != SCHEMA:
            raise InputError(f"schema: expected {SCHEMA!r}, got {doc.get('schema')!r}")
        analysis = v.choice("analysis", doc.get("analysis"), ANALYSES)
        grid = doc.get("grid")
        if not isinstance(grid, dict) or not grid:
            raise InputError("grid: expected a [grid] table with at least one axis")
        axes = {k: _axis(k, val) for k, val in _flatten(grid).items()}
        opts = doc.get("options", {})
        if not isinstance(opts, dict):
            raise InputError("options: expected a table")
        checked = {}
        for k, val in opts.items():
            if k not in OPTIONS[analysis]:
                raise InputError(f"options.{k}: unknown option for analysis {analysis!r} "
                                 f"(allowed: {', '.join(sorted(OPTIONS[analysis]))})")
            checked[k] = OPTIONS[analysis][k](f"options.{k}", val)
        for k in REQUIRED.get(analysis, ()):
            if k not in checked:
                raise InputError(f"options.{k}: required for analysis {analysis!r}")
        model = doc.get("model")
        if not isinstance(model, str) or not model:
            raise InputError("model: expected a built-in model name or a TOML path")
        if model.endswith(".toml") and not Path(model).is_absolute():
            model = str((p.parent / model).resolve())
        chunk = v.integer("chunk_size", doc.get("chunk_size", 20), lo=1, hi=100000)
        max_files = v.integer("max_files", doc.get("max_files", 128), lo=1, hi=100000)
        name = doc.get("name", p.stem)
        if not isinstance(name, str) or not name or "/" in name:
            raise InputError(f"name: expected a non-empty string without '/', got {name!r}")
        spec = cls(name=name, model=model, analysis=analysis, axes=axes, chunk_size=chunk,
                   options=checked, source=text, max_files=max_files)
        spec._check_shape()
        if check_model:
            spec.check_against(spec.load_model())
        return spec

    def load_model(self):
        return models.load(self.model)

    def _check_shape(self) -> None:
        n = math.prod(len(x) for x in self.axes.values())
        if n > MAX_POINTS:
            raise InputError(f"grid: {n} points, more than the limit of {MAX_POINTS}")
        for name, vals in self.axes.items():
            axis_values.check_unique(name, vals)
        a = self.analysis
        if a in ("threshold", "hopf", "limit_cycle"):
            ax = self.options["vary"]
            if ax not in self.axes or len(self.axes[ax]) < 2:
                raise InputError(f"options.vary: {ax!r} must be a grid axis with >= 2 values "
                                 "(its range is scanned; its first and last values are the "
                                 "bounds)")
            if ax not in OPERATING[:3]:
                raise InputError(f"options.vary: expected one of speed_hz, "
                                 f"chamber_pressure_pa, config_ay_m, got {ax!r}")
        if a == "boundary":
            x, y = self.options["x"], self.options["y"]
            z = self.options.get("z")
            for k, ax in (("x", x), ("y", y)) + ((("z", z),) if z else ()):
                if ax not in self.axes or len(self.axes[ax]) < 2:
                    raise InputError(f"options.{k}: {ax!r} must be a grid axis with >= 2 "
                                     "values (the coarse grid)")
            if x == y:
                raise InputError("options.y: must differ from options.x")
            if z and z in (x, y):
                raise InputError("options.z: must differ from options.x and options.y")
            fine_axes(self)
        if a == "limit_cycle":
            o = self.options
            hb = o.get("method", "shooting") == "harmonic_balance"
            if hb and "newton" in o:
                raise InputError("options.newton: applies only to options.method = "
                                 "'shooting' (harmonic balance corrects by Newton on the "
                                 "orbit's coefficients)")
            for k in ("harmonics", "time_points"):
                if k in o and not hb:
                    raise InputError(f"options.{k}: applies only to options.method = "
                                     "'harmonic_balance'")
            if "time_points" in o and o["time_points"] < 2 * o.get("harmonics", 8) + 1:
                raise InputError(f"options.time_points: expected M >= 2H + 1 = "
                                 f"{2 * o.get('harmonics', 8) + 1}, got {o['time_points']}")
        if a == "run-up":
            if "speed_hz" in self.axes:
                raise InputError("grid.speed_hz: a run-up takes its speeds from options "
                                 "start_hz, stop_hz, rate_hz_per_s")
            if self.options["stop_hz"] == self.options["start_hz"]:
                raise InputError("options.stop_hz: expected a speed different from start_hz")
            revs = (self.options["start_hz"] + self.options["stop_hz"]) / 2 * abs(
                self.options["stop_hz"] - self.options["start_hz"]) / self.options["rate_hz_per_s"]
            if revs * self.options.get("samples_per_revolution", 32) > 2e6:
                raise InputError(f"options.rate_hz_per_s: the run-up lasts {revs:.3g} "
                                 "revolutions; at most 2e6 samples per run (raise the rate "
                                 "or lower samples_per_revolution)")
        if a == "thermal":
            for ax in ("config_ay_m", "config_ax_m"):
                if ax in self.axes:
                    raise InputError(f"grid.{ax}: not available with the thermal model (sweep "
                                     "the bearings' own config_ay_m/config_ax_m fields)")
        if a == "robust" and "config_ax_m" in self.axes:
            raise InputError("grid.config_ax_m: the control plant takes a_y only (sweep the "
                             "bearing's own field bearings.<name>.config_ax_m)")
        if "line" in self.options and self.options["line"] not in self.axes:
            raise InputError(f"options.line: {self.options['line']!r} is not a grid axis")
        if a in ("campbell", "unbalance") and len(self.axes.get("speed_hz", ())) < 2:
            raise InputError(f"grid.speed_hz: analysis {a!r} needs a speed axis with >= 2 "
                             "values")
        if a in ("campbell", "unbalance"):
            sp = self.axes["speed_hz"]
            if any(b <= a_ for a_, b in zip(sp, sp[1:])) or sp[0] <= 0:
                raise InputError("grid.speed_hz: expected positive, strictly increasing "
                                 "speeds")
        la = self.line_axis
        if a in ("threshold", "hopf", "limit_cycle", "stability") and la in self.axes:
            axis_values.check_monotonic(la, self.axes[la], "modes are tracked" if a ==
                                        "stability" else "sign changes are bracketed")
        self._check_operating()

    def _check_operating(self) -> None:
        """Every value of an operating axis within the range the analyses accept (the same
        checks as ``rotordyn.equilibrium`` & co.), so that a bad value is one InputError
        naming ``grid.<axis>[i]`` at load, not a sweep of error rows."""
        checks = {"speed_hz": v.positive if self.analysis == "waterfall" else v.speed,
                  "chamber_pressure_pa": v.non_negative, "config_ay_m": v.finite,
                  "config_ax_m": v.finite}
        for name, check in checks.items():
            for i, val in enumerate(self.axes.get(name, ())):
                check(f"grid.{name}[{i}]", val)
        if self.analysis == "waterfall":
            for i, val in enumerate(self.axes.get("speed_hz", ())):
                v.speed(f"grid.speed_hz[{i}]", val)

    def check_against(self, system) -> None:
        """Every axis exists (model fields by dotted path) and every value builds a valid
        model; option stations exist. InputError names the axis."""
        if self.analysis == "thermal" and getattr(system, "thermal", None) is None:
            raise InputError("analysis: 'thermal' needs the model's oil system (a [thermal] "
                             "table in the model file, docs/model-file.md)")
        if "thermal" in self.options and getattr(system, "thermal", None) is None:
            raise InputError("options.thermal: needs the model's oil system (a [thermal] "
                             "table in the model file, docs/model-file.md)")
        if isinstance(self.options.get("thermal"), dict):
            # the other model's option refused up front, as rotordyn.system_thermal_equilibrium
            # refuses it (else every row failed with the same InputError)
            from rotordyn.analysis.thermal import refuse_other_model_options

            th = self.options["thermal"]
            refuse_other_model_options(th.get("model", system.thermal.model), th,
                                       prefix="options.thermal.")
        for name, vals in self.axes.items():
            if name in OPERATING:
                if name in ("config_ay_m", "config_ax_m"):
                    from rotordyn.bearings import ActiveJournalBearing

                    act = [b for b in system.bearings if isinstance(b, ActiveJournalBearing)]
                    if len(act) != 1 and len(system.bearings) != 1:
                        raise InputError(f"grid.{name}: addresses the active bearing, but the "
                                         f"model has {len(act)}; use bearings.<name>.{name}")
                if name == "chamber_pressure_pa" and any(isinstance(x, (int, float)) and x != 0
                                                          for x in vals):
                    from rotordyn.bearings import ActiveJournalBearing

                    if not any(isinstance(b, ActiveJournalBearing) for b in system.bearings):
                        raise InputError("grid.chamber_pressure_pa: acts on an active journal "
                                         "bearing's chamber and the model has none (allowed: "
                                         "0; other values would repeat the same point)")
                continue
            if name.startswith("options."):
                self._option_axis(name)
                continue
            if "." not in name and name not in ("gravity_m_s2",):
                raise InputError(f"grid.{name}: unknown axis (allowed: "
                                 f"{', '.join(OPERATING)}, a dotted model field such as "
                                 "bearings.active.clearance_m, or options.<name>)")
            check_model_axis(system, name, vals)
        if self.analysis == "robust":
            rr.check_model(system, self.options)
        if "bearing" in self.options:
            names = [getattr(b, "name", "") for b in system.bearings]
            if self.options["bearing"] not in names:
                raise InputError(f"options.bearing: {self.options['bearing']!r} is not a "
                                 f"bearing of the model (allowed: {', '.join(map(repr, names))})")
        n_st = system.rotor.n_stations
        if "station" in self.options and self.options["station"] >= n_st:
            raise InputError(f"options.station: station {self.options['station']} out of "
                             f"range (0..{n_st - 1})")
        for key in ("unbalances", "stations"):
            for i, u in enumerate(self.options.get(key, ())):
                st = u[0] if key == "unbalances" else u
                if st >= n_st:
                    raise InputError(f"options.{key}[{i}]: station {st} out of range "
                                     f"(0..{n_st - 1})")

    def _option_axis(self, name: str) -> None:
        parts = name.split(".")[1:]
        if not parts or parts[0] not in self.options:
            raise InputError(f"grid.{name}: no option {parts[0] if parts else ''!r} in "
                             f"[options] to sweep")
        cur = self.options[parts[0]]
        for p in parts[1:]:
            if not isinstance(cur, list) or not p.isdigit() or int(p) >= len(cur):
                raise InputError(f"grid.{name}: {p!r} does not index options.{parts[0]}")
            cur = cur[int(p)]
        if isinstance(cur, (list, bool)) or not isinstance(cur, (int, float)):
            raise InputError(f"grid.{name}: not a number in options")

    # -- expansion ---------------------------------------------------------------------
    @property
    def line_axis(self) -> str | None:
        """The axis a task keeps whole (continuation and tracking along it): speed for
        campbell/unbalance/tracked stability, the varied axis for threshold."""
        if self.analysis in ("threshold", "hopf", "limit_cycle"):
            return self.options["vary"]
        if self.analysis in ("campbell", "unbalance"):
            return "speed_hz"
        if self.analysis == "robust" and self.options.get("continuation", True):
            varying = [a for a, vals in self.axes.items() if len(vals) > 1]
            return varying[-1] if varying else None  # equilibria continued along the last
        if self.analysis == "stability" and "line" in self.options:
            return self.options["line"]
        if self.analysis == "stability" and self.options.get("track", True):
            if len(self.axes.get("speed_hz", ())) > 1:
                return "speed_hz"
            varying = [a for a, vals in self.axes.items() if len(vals) > 1]
            return varying[-1] if varying else None  # modes tracked along the last one
        return None

    @property
    def ordered_axes(self) -> dict:
        """Axes in expansion order: as written, with the line axis moved innermost."""
        la = self.line_axis
        if la is None or la not in self.axes:
            return dict(self.axes)
        d = {k: val for k, val in self.axes.items() if k != la}
        d[la] = self.axes[la]
        return d

    @property
    def n_points(self) -> int:
        return math.prod(len(x) for x in self.axes.values())

    def points(self):
        """Every grid point as (index tuple, value tuple) in the fixed expansion order."""
        ax = self.ordered_axes
        idx = itertools.product(*(range(len(x)) for x in ax.values()))
        for ii in idx:
            yield ii, tuple(vals[i] for vals, i in zip(ax.values(), ii))

    def chunk_bounds(self) -> list[tuple[int, int]]:
        """Contiguous point-id ranges [lo, hi) of each chunk; with a line axis, chunks hold
        whole lines (the chunk size is rounded up to a multiple of the line length)."""
        n = self.n_points
        if self.analysis in ("threshold", "hopf", "limit_cycle"):
            # one task unit = one line; chunk_size counts lines
            line = len(self.axes[self.options["vary"]])
            size = self.chunk_size * line
        else:
            line = len(self.axes[self.line_axis]) if self.line_axis else 1
            size = max(line, -(-self.chunk_size // line) * line)
        return [(lo, min(lo + size, n)) for lo in range(0, n, size)]

    def hash(self) -> str:
        """16 hex digits of the analysis, axes, options and chunking. The model is not in
        it: it enters by its content (the manifest's ``model_hash``), so a sweep whose model
        file moved, or that runs from another directory or machine, still resumes."""
        return self._hash({})

    def legacy_hash(self) -> str:
        """The hash before 2026-12-06, which also held the model reference as resolved
        (a TOML's absolute path): a directory written then still resumes where the model
        resolves to the same path as then (a moved one does not match it)."""
        return self._hash({"model": self.model})

    def _hash(self, extra: dict) -> str:
        payload = json.dumps({**extra, "analysis": self.analysis,
                              "axes": self.axes, "options": self.options,
                              "chunk_size": self.chunk_size, "max_files": self.max_files},
                             sort_keys=True)
        return hashlib.sha256(payload.encode()).hexdigest()[:16]
