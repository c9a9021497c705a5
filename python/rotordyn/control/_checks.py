"""Argument checks shared by the design functions of :mod:`rotordyn.control` (issue 21): each
is the rule of :mod:`rotordyn._common.validate` applied to one kind of argument (a system, a
controller, an actuator, an operating point, a station list, a grid), so every function
refuses bad input with an :class:`~rotordyn.errors.InputError` naming the field and the
allowed range before any solve starts."""

from __future__ import annotations

import numpy as np

from rotordyn._common import validate as v
from rotordyn.analysis.assembly import assembled
from rotordyn.errors import InputError
from rotordyn.model.system import System
from rotordyn.operation.actuator import Actuator
from rotordyn.operation.controller import Controller

MAX_GRID = 100_000  # points of one speed or pressure axis (more is not a design grid)
MAX_FREQS = 1_000_000  # frequencies of one loop-response grid


def system(value, field: str = "system") -> System:
    if not isinstance(value, System):
        raise InputError(f"{field}: expected a rotordyn System (e.g. rotordyn.models."
                         f"paper_rig()), got {type(value).__name__}")
    return value


def controller(value, field: str = "controller", *, continuous: bool = False) -> Controller:
    if not isinstance(value, Controller):
        raise InputError(f"{field}: expected a rotordyn.control.Controller, got "
                         f"{type(value).__name__}")
    if continuous and value.discrete:
        raise InputError(f"{field}.sample_time_s: expected a continuous controller (None), got "
                         f"{value.sample_time_s!r} s")
    return value


def actuator(value, field: str = "actuator") -> Actuator:
    """None: the default :class:`Actuator` (100 Hz second-order valve)."""
    if value is None:
        return Actuator()
    if not isinstance(value, Actuator):
        raise InputError(f"{field}: expected a rotordyn.control.Actuator or None, got "
                         f"{type(value).__name__}")
    return value


def config_ay(sys_, config_ay_m):
    """None (the model's own) or a finite offset the system can take: one active bearing
    (the error of :meth:`Assembled.config_vector` raised here, not swallowed in a grid)."""
    if config_ay_m is None:
        return None
    val = v.finite("config_ay_m", config_ay_m)
    assembled(sys_).config_vector(val)
    return val


def operating_point(sys_, speed_hz, chamber_pressure_pa, config_ay_m):
    """(speed_hz, chamber_pressure_pa, config_ay_m) by the ranges of
    :func:`rotordyn.equilibrium`."""
    system(sys_)
    return (v.speed("speed_hz", speed_hz),
            v.non_negative("chamber_pressure_pa", chamber_pressure_pa),
            config_ay(sys_, config_ay_m))


def stations(sys_, value, field: str = "stations") -> tuple:
    """A non-empty list of rotor stations, each an integer in [0, n_stations − 1]."""
    n = sys_.rotor.n_stations
    if isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_)):
        value = [value]
    items = v.sequence(field, list(value) if isinstance(value, np.ndarray) else value)
    if not items:
        raise InputError(f"{field}: expected at least one station in [0, {n - 1}]")
    return tuple(v.integer(f"{field}[{i}]", s, lo=0, hi=n - 1) for i, s in enumerate(items))


def unbalances(sys_, value, field: str = "unbalances") -> list:
    """A non-empty ``[(station, mass_kg_m, phase_deg), ...]``."""
    ub = v.unbalances(field, value, sys_.rotor.n_stations)
    if not ub:
        raise InputError(f"{field}: expected at least one (station, mass_kg_m, phase_deg)")
    return ub


def speeds(field: str, value) -> np.ndarray:
    """A non-empty, strictly increasing array of speeds > 0 Hz."""
    return v.speeds(field, value, positive_only=True, max_count=MAX_GRID)


def pressures(field: str, value) -> np.ndarray:
    """A non-empty array of distinct chamber pressures >= 0 Pa, finite."""
    arr = v.vector(field, value)
    if arr.size == 0:
        raise InputError(f"{field}: expected at least one pressure (Pa, >= 0), got none")
    if arr.size > MAX_GRID:
        raise InputError(f"{field}: expected at most {MAX_GRID} pressures, got {arr.size}")
    if np.any(arr < 0):
        raise InputError(f"{field}: expected pressures >= 0 Pa, got {float(arr.min())!r}")
    if np.unique(arr).size != arr.size:
        raise InputError(f"{field}: expected distinct pressures")
    return arr


def frequencies(field: str, value) -> np.ndarray:
    """A strictly increasing array of at least 2 frequencies > 0 Hz (finite)."""
    arr = v.vector(field, value)
    if arr.size < 2 or arr.size > MAX_FREQS:
        raise InputError(f"{field}: expected between 2 and {MAX_FREQS} frequencies (Hz), "
                         f"got {arr.size}")
    if np.any(arr <= 0):
        raise InputError(f"{field}: expected frequencies > 0 Hz, got {float(arr.min())!r}")
    if np.any(np.diff(arr) <= 0):
        raise InputError(f"{field}: expected strictly increasing frequencies")
    return arr


def frequencies_any(field: str, value) -> np.ndarray:
    """A non-empty array of at most MAX_FREQS finite frequencies >= 0 Hz (any order)."""
    arr = np.atleast_1d(v.vector(field, np.atleast_1d(value)) if np.ndim(value) else
                        np.array([v.finite(field, value)]))
    if arr.size == 0 or arr.size > MAX_FREQS:
        raise InputError(f"{field}: expected between 1 and {MAX_FREQS} frequencies (Hz), "
                         f"got {arr.size}")
    if np.any(arr < 0):
        raise InputError(f"{field}: expected frequencies >= 0 Hz, got {float(arr.min())!r}")
    return arr


def measured_by(sys_, k: Controller, field: str = "controller") -> None:
    """The controller's measurements exist on the system and give its number of inputs."""
    from rotordyn.analysis.measurement import measurement_matrix

    Cm, _ = measurement_matrix(sys_, k.measurements)
    if Cm.shape[0] != k.n_inputs:
        raise InputError(f"{field}: expected {Cm.shape[0]} inputs (the measurements "
                         f"{k.measurements} give {Cm.shape[0]} signals), got {k.n_inputs}")


def keywords(field: str, kw: dict, allowed) -> None:
    """Refuse unknown keyword arguments (a TypeError deep inside otherwise)."""
    bad = sorted(set(kw) - set(allowed))
    if bad:
        raise InputError(f"{field}: unknown option(s) {', '.join(bad)}; expected any of "
                         f"{', '.join(sorted(allowed))}")
