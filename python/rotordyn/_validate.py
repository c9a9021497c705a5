"""Field checks shared by the model dataclasses; each error names the field and the range."""

from __future__ import annotations

import math

import numpy as np

from rotordyn.errors import InputError


def _num(field: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(f"{field}: expected a number, got {value!r}")
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"{field}: expected a finite number, got {value!r}")
    return v


def positive(field: str, value) -> float:
    """A finite number > 0."""
    v = _num(field, value)
    if v <= 0.0:
        raise InputError(f"{field}: expected a value > 0, got {value!r}")
    return v


def non_negative(field: str, value) -> float:
    """A finite number >= 0."""
    v = _num(field, value)
    if v < 0.0:
        raise InputError(f"{field}: expected a value >= 0, got {value!r}")
    return v


def finite(field: str, value) -> float:
    """Any finite number."""
    return _num(field, value)


def in_range(field: str, value, lo: float, hi: float, *, lo_open=False, hi_open=False) -> float:
    """A finite number in [lo, hi] (or open at either end)."""
    v = _num(field, value)
    bad = (v <= lo if lo_open else v < lo) or (v >= hi if hi_open else v > hi)
    if bad:
        lb = "(" if lo_open else "["
        rb = ")" if hi_open else "]"
        raise InputError(f"{field}: expected a value in {lb}{lo}, {hi}{rb}, got {value!r}")
    return v


def integer(field: str, value, lo: int | None = None, hi: int | None = None) -> int:
    """An int within optional bounds."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise InputError(f"{field}: expected an integer, got {value!r}")
    if lo is not None and value < lo:
        raise InputError(f"{field}: expected an integer >= {lo}, got {value}")
    if hi is not None and value > hi:
        raise InputError(f"{field}: expected an integer <= {hi}, got {value}")
    return value


def choice(field: str, value, allowed) -> str:
    """One of a fixed set of strings."""
    if value not in allowed:
        opts = ", ".join(repr(a) for a in allowed)
        raise InputError(f"{field}: expected one of {opts}, got {value!r}")
    return value
