"""Shared helpers for the benchmark scripts: timing with warm-up and medians of repeats."""

from __future__ import annotations

import contextlib
import io
import statistics
import time


def median_time(fn, repeat: int = 7, warmup: int = 1, number: int = 1) -> float:
    """Median wall time of ``number`` calls of ``fn``, in seconds per call."""
    for _ in range(warmup):
        fn()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number)
    return statistics.median(times)


def import_ross():
    """ross-rotordynamics if installed (optional extra ``rotordyn[ross]``), else None.
    Its import prints REFPROP/CoolProp notices; they are swallowed here."""
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            import warnings

            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                import ross  # noqa: F401
        return ross
    except Exception:  # noqa: BLE001 - any import failure means "not available"
        return None


def fmt(seconds: float) -> str:
    if seconds < 1e-3:
        return f"{seconds * 1e6:8.1f} µs"
    if seconds < 1:
        return f"{seconds * 1e3:8.2f} ms"
    return f"{seconds:8.3f} s "
