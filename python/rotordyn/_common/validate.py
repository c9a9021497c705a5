"""Field checks shared by the model dataclasses and every analysis: one rule everywhere
(issue 13). Each error is an :class:`InputError` that names the field and the allowed range.

Numbers are Python or numpy ints/floats (never bool, str or None); integers must also fit the
C++ core's 32-bit ``int`` (< 2**31); arrays are float64 of a stated shape with finite entries.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn.errors import InputError

INT_MAX = 2**31 - 1  # the C++ core's int


def _num(field: str, value) -> float:
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        raise InputError(f"{field}: expected a number, got {_show(value)}")
    try:
        v = float(value)
    except OverflowError:  # an int beyond the float range
        raise InputError(f"{field}: expected a finite number, got an integer of "
                         f"{len(str(abs(value)))} digits") from None
    if not math.isfinite(v):
        raise InputError(f"{field}: expected a finite number, got {value!r}")
    return v


def _show(value) -> str:
    """A short repr for messages (a huge array or string is cut)."""
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def number(field: str, value) -> float:
    """Any finite number (alias of :func:`finite`)."""
    return _num(field, value)


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
    """An int (Python or numpy, not bool) within optional bounds and below 2**31."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise InputError(f"{field}: expected an integer, got {_show(value)}")
    value = int(value)
    hi = INT_MAX if hi is None else min(hi, INT_MAX)
    if lo is not None and value < lo:
        raise InputError(f"{field}: expected an integer >= {lo}, got {value}")
    if value > hi:
        shown = value if value < 10**30 else f"an integer of {len(str(value))} digits"
        raise InputError(f"{field}: expected an integer <= {hi}, got {shown}")
    return value


def choice(field: str, value, allowed) -> str:
    """One of a fixed set of strings."""
    if not isinstance(value, str) or value not in allowed:
        opts = ", ".join(repr(a) for a in allowed)
        raise InputError(f"{field}: expected one of {opts}, got {_show(value)}")
    return value


def text(field: str, value) -> str:
    """A string (possibly empty)."""
    if not isinstance(value, str):
        raise InputError(f"{field}: expected a string, got {_show(value)}")
    return value


def boolean(field: str, value) -> bool:
    """True or False (Python or numpy bool)."""
    if not isinstance(value, (bool, np.bool_)):
        raise InputError(f"{field}: expected true or false, got {_show(value)}")
    return bool(value)


def vector(field: str, value, n: int | None = None) -> np.ndarray:
    """A 1-D float64 array of finite numbers (of length ``n`` when given); a copy."""
    if value is None or isinstance(value, (str, bytes, dict, set, frozenset)):
        raise InputError(f"{field}: expected a sequence of numbers, got {_show(value)}")
    arr = _float_array(field, value, "a sequence of numbers")
    if arr.ndim != 1 or (n is not None and arr.shape[0] != n):
        want = f"({n},)" if n is not None else "a 1-D array"
        raise InputError(f"{field}: expected shape {want}, got {arr.shape}")
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.argmax(bad))
        raise InputError(f"{field}[{i}]: expected a finite number, got {arr[i]!r}")
    return arr


def _float_array(field: str, value, what: str) -> np.ndarray:
    """float64 copy of ``value``; strings and bools (numpy converts "1e6" and True silently)
    are refused."""
    try:
        kind = np.asarray(value).dtype.kind
        arr = np.array(value, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"{field}: expected {what}, got {_show(value)}") from None
    if kind in "USOb" and not (kind == "O" and _all_numbers(value)):
        raise InputError(f"{field}: expected {what}, got {_show(value)}")
    return arr


def _all_numbers(value) -> bool:
    flat = np.asarray(value, dtype=object).ravel()
    return all(isinstance(x, (int, float, np.integer, np.floating))
               and not isinstance(x, (bool, np.bool_)) for x in flat)


def matrix(field: str, value, shape: tuple | None = None) -> np.ndarray:
    """A 2-D float64 array of finite numbers (of ``shape`` when given; a scalar is 1 x 1);
    a copy."""
    if value is None or isinstance(value, (str, bytes, dict)):
        raise InputError(f"{field}: expected a matrix of numbers, got {_show(value)}")
    arr = _float_array(field, value, "a matrix of numbers")
    if arr.ndim < 2:
        arr = np.atleast_2d(arr)
    want = f"({shape[0]}, {shape[1]})" if shape is not None else "a 2-D matrix"
    if arr.ndim != 2 or (shape is not None and arr.shape != tuple(shape)):
        raise InputError(f"{field}: expected {want}, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        i, j = np.argwhere(~np.isfinite(arr))[0]
        raise InputError(f"{field}: expected a finite {want} matrix, got {float(arr[i, j])!r} at "
                         f"[{i}, {j}]")
    return arr


def psd_matrix(field: str, value, n: int, *, definite: bool = False) -> np.ndarray:
    """A finite symmetric positive semi-definite (``definite``: positive definite) (n, n)
    matrix; symmetry and the eigenvalues are checked to 1e-10 of the largest entry."""
    what = "positive definite" if definite else "positive semi-definite"
    msg = f"{field}: expected a finite symmetric {what} ({n}, {n}) matrix, got "
    if value is None or isinstance(value, (str, bytes, dict)):
        raise InputError(msg + _show(value))
    try:
        M = np.atleast_2d(_float_array(field, value, "a matrix of numbers"))
    except InputError:
        raise InputError(msg + _show(value)) from None
    if M.shape != (n, n):
        raise InputError(msg + f"shape {M.shape}")
    if not np.all(np.isfinite(M)):
        i, j = np.argwhere(~np.isfinite(M))[0]
        raise InputError(msg + f"{float(M[i, j])!r} at [{i}, {j}]")
    scale = float(np.abs(M).max()) if M.size else 0.0
    if scale > 1e300:
        raise InputError(msg + f"entries up to {scale:.3g} (at most 1e300)")
    if np.abs(M - M.T).max(initial=0.0) > 1e-10 * scale:
        raise InputError(msg + "a non-symmetric matrix")
    M = 0.5 * (M + M.T)
    lam = np.linalg.eigvalsh(M) if M.size else np.zeros(0)
    low = lam.min(initial=np.inf)
    if (definite and not low > 1e-10 * scale) or (not definite and low < -1e-10 * scale):
        raise InputError(msg + f"a matrix with eigenvalue {low:.3g}")
    return M


def bounds(field: str, value) -> tuple[float, float]:
    """A pair (low, high) of finite numbers with low < high."""
    if value is None or isinstance(value, (str, bytes, dict)):
        raise InputError(f"{field}: expected (low, high), got {_show(value)}")
    try:
        items = list(value)
    except TypeError:
        raise InputError(f"{field}: expected (low, high), got {_show(value)}") from None
    if len(items) != 2:
        raise InputError(f"{field}: expected (low, high), got {_show(value)}")
    lo, hi = _num(f"{field}[0]", items[0]), _num(f"{field}[1]", items[1])
    if not hi > lo:
        raise InputError(f"{field}: expected low < high, got {_show(value)}")
    return lo, hi


def sequence(field: str, value) -> list:
    """A list or tuple (not a string, mapping or scalar); a list copy."""
    if not isinstance(value, (list, tuple)):
        raise InputError(f"{field}: expected a list, got {_show(value)}")
    return list(value)


def memory(field: str, n_bytes: float, *, limit: float | None = None) -> None:
    """Refuse an allocation estimated at ``n_bytes`` above ``limit`` (default
    :func:`memory_limit`), naming the field and the estimate."""
    if limit is None:
        limit = memory_limit()
    if n_bytes > limit:
        raise InputError(f"{field}: needs about {_bytes(n_bytes)} of memory, above the limit "
                         f"of {_bytes(limit)}; reduce it")


def memory_limit() -> float:
    """The largest single allocation an analysis may plan: a quarter of the physical memory,
    at most 2 GiB (a result larger than that is not meaningful on a laptop, and the dense
    solvers need several copies of their arrays)."""
    try:
        import os

        phys = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        phys = 8 * 2**30
    return float(min(phys / 4, 2 * 2**30))


def _bytes(n: float) -> str:
    for unit, k in (("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if n >= k:
            return f"{n / k:.3g} {unit}"
    return f"{n:.0f} B"


MAX_SPEED_HZ = 1e5  # 6·10⁶ rpm: beyond it ω overflows nothing yet, but no rotor turns


def speed(field: str, value) -> float:
    """A finite spin speed, Hz, |speed| ≤ MAX_SPEED_HZ (the film solver's range too)."""
    f = finite(field, value)
    if abs(f) > MAX_SPEED_HZ:
        raise InputError(f"{field}: expected a speed in [-{MAX_SPEED_HZ:g}, {MAX_SPEED_HZ:g}] Hz, "
                         f"got {_show(value)}")
    return f


def speeds(field: str, value, *, positive_only: bool = False, max_count: int = 100_000
           ) -> np.ndarray:
    """A non-empty, strictly increasing 1-D array of finite speeds (Hz), at most
    ``max_count`` of them (a longer list is not a meaningful diagram)."""
    arr = vector(field, value)
    if arr.size == 0:
        raise InputError(f"{field}: expected at least one speed, got none")
    if arr.size > max_count:
        raise InputError(f"{field}: expected at most {max_count} speeds, got {arr.size}")
    if positive_only and np.any(arr <= 0):
        raise InputError(f"{field}: expected speeds > 0, got {arr.min()!r}")
    if np.any(np.abs(arr) > MAX_SPEED_HZ):
        raise InputError(f"{field}: expected speeds in [-{MAX_SPEED_HZ:g}, {MAX_SPEED_HZ:g}] Hz, "
                         f"got {float(arr[np.argmax(np.abs(arr))])!r}")
    if arr.size > 1 and np.any(np.diff(arr) <= 0):
        raise InputError(f"{field}: expected strictly increasing speeds")
    return arr


def unbalances(field: str, value, n_stations: int) -> list[tuple[int, float, float]]:
    """``[(station, mass_kg_m, phase_deg), ...]``: station an integer in [0, n_stations),
    the other two finite numbers."""
    items = sequence(field, value) if not isinstance(value, np.ndarray) else list(value)
    out = []
    for i, u in enumerate(items):
        if isinstance(u, (str, bytes, dict)) or not hasattr(u, "__len__") or len(u) != 3:
            raise InputError(f"{field}[{i}]: expected (station, mass_kg_m, phase_deg), "
                             f"got {_show(u)}")
        st, me, ph = u
        out.append((integer(f"{field}[{i}].station", st, lo=0, hi=n_stations - 1),
                    finite(f"{field}[{i}].mass_kg_m", me),
                    finite(f"{field}[{i}].phase_deg", ph)))
    return out


def arclength_steps(ds, ds_min, ds_max, max_points, direction) -> tuple:
    """The step controls of a pseudo-arclength continuation: (ds, ds_min, ds_max,
    max_points, direction) checked (0 < ds_min ≤ ds ≤ ds_max, 1 ≤ max_points ≤ 100 000,
    direction ±1)."""
    ds, ds_min, ds_max = positive("ds", ds), positive("ds_min", ds_min), positive("ds_max", ds_max)
    if not ds_min <= ds <= ds_max:
        raise InputError(f"ds: expected ds_min ≤ ds ≤ ds_max, got {ds_min:g} ≤ {ds:g} ≤ "
                         f"{ds_max:g}")
    max_points = integer("max_points", max_points, lo=1, hi=100_000)
    direction = integer("direction", direction, lo=-1, hi=1)
    if direction == 0:
        raise InputError("direction: expected +1 or -1, got 0")
    return ds, ds_min, ds_max, max_points, direction
