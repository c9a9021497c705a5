"""Shared helpers for the benchmark scripts.

Every benchmark follows the same protocol (docs/performance.md, "Protocol"):

* one BLAS/OpenMP thread per side unless a row says otherwise (:func:`pin_threads`; call it
  before timing, it also limits libraries loaded later through the environment variables);
* the two sides of a ratio are timed in interleaved repeats (:func:`interleaved`), so that a
  change of machine load hits both, and the median of the repeats is reported;
* wall and CPU time of the process side by side (:class:`Timing`): a CPU time well below the
  wall time means the machine was busy with other work;
* the machine load (1-minute load average and the number of cores) printed before and after
  (:func:`print_load`).
"""

from __future__ import annotations

import contextlib
import io
import os
import statistics
import sys
import time
from dataclasses import dataclass

_THREAD_VARS = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                "BLIS_NUM_THREADS", "VECLIB_MAXIMUM_THREADS", "NUMEXPR_NUM_THREADS")


def pin_threads(n: int = 1) -> str:
    """Limit BLAS and OpenMP to ``n`` threads for the rest of the process: the environment
    variables (libraries loaded later) and threadpoolctl (libraries already loaded). Returns a
    one-line description of what was pinned."""
    for k in _THREAD_VARS:
        os.environ[k] = str(n)
    try:
        from threadpoolctl import threadpool_info, threadpool_limits
    except ImportError:
        return f"threads: env vars set to {n} (threadpoolctl not installed)"
    import numpy  # noqa: F401  - load numpy's BLAS so threadpoolctl sees it
    import rotordyn._core  # noqa: F401  - and the core's OpenMP runtime
    threadpool_limits(limits=n)
    libs = sorted({f"{d['internal_api']}={d['num_threads']}" for d in threadpool_info()})
    return f"threads pinned to {n}: " + ", ".join(libs)


def load_line(tag: str) -> str:
    """``tag: load 1.23 0.98 0.80 (1/5/15 min) on N cores``."""
    try:
        l1, l5, l15 = os.getloadavg()
        load = f"{l1:.2f} {l5:.2f} {l15:.2f}"
    except OSError:
        load = "n/a"
    return f"{tag}: load {load} (1/5/15 min) on {os.cpu_count()} cores"


def print_load(tag: str) -> None:
    print(load_line(tag), flush=True)


def header(title: str, threads: int = 1) -> None:
    """Title, Python and platform, thread pinning and the load before the run."""
    print(f"== {title}")
    print(f"python {sys.version.split()[0]} on {sys.platform}; {pin_threads(threads)}")
    print_load("machine before")


def footer() -> None:
    print_load("machine after")


@dataclass
class Timing:
    """Median wall and CPU seconds per call over the repeats (and every repeat's values)."""

    wall: float
    cpu: float
    walls: list
    cpus: list

    def __str__(self) -> str:
        return f"{fmt(self.wall)} wall, {fmt(self.cpu)} CPU"


def _once(fn, number: int):
    w0, c0 = time.perf_counter(), time.process_time()
    for _ in range(number):
        fn()
    return (time.perf_counter() - w0) / number, (time.process_time() - c0) / number


def measure(fn, repeat: int = 5, warmup: int = 1, number: int = 1) -> Timing:
    """Median wall and CPU time per call of ``fn`` (``number`` calls per repeat)."""
    for _ in range(warmup):
        fn()
    w, c = zip(*(_once(fn, number) for _ in range(repeat)))
    return Timing(statistics.median(w), statistics.median(c), list(w), list(c))


def interleaved(fns: dict, repeat: int = 5, warmup: int = 1, number: int = 1) -> dict:
    """Time several callables in interleaved repeats (a, b, a, b, ...): {name: Timing}."""
    for fn in fns.values():
        for _ in range(warmup):
            fn()
    w = {k: [] for k in fns}
    c = {k: [] for k in fns}
    for _ in range(repeat):
        for k, fn in fns.items():
            a, b = _once(fn, number)
            w[k].append(a)
            c[k].append(b)
    return {k: Timing(statistics.median(w[k]), statistics.median(c[k]), w[k], c[k]) for k in fns}


def median_time(fn, repeat: int = 7, warmup: int = 1, number: int = 1) -> float:
    """Median wall time of ``number`` calls of ``fn``, in seconds per call."""
    return measure(fn, repeat, warmup, number).wall


@contextlib.contextmanager
def quiet_fds():
    """Silence C-level stdout/stderr (ROSS's REFPROP loader prints from a shared library)."""
    saved = [os.dup(1), os.dup(2)]
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(null, 1)
        os.dup2(null, 2)
        yield
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in saved + [null]:
            os.close(fd)


def import_ross():
    """ross-rotordynamics if installed (optional extra ``rotordyn[ross]``), else None.
    Its import prints REFPROP/CoolProp notices (also from C); they are swallowed here."""
    try:
        with quiet_fds(), contextlib.redirect_stdout(io.StringIO()), \
                contextlib.redirect_stderr(io.StringIO()):
            import warnings

            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                import ross  # noqa: F401
        return ross
    except Exception:  # noqa: BLE001 - any import failure means "not available"
        return None


def clear_ross_caches(*rotors) -> int:
    """Clear every cache ROSS keeps: its ``Rotor.run_modal`` and ``_run_freq_response`` are
    memoised per rotor instance (methodtools ``lru_cache``), so run_campbell, a repeated
    run_modal or a repeated response on the same rotor and arguments is a dictionary look-up.
    Clears those of the given rotors and any module-level functools caches in ``ross``;
    returns how many caches were cleared."""
    import functools

    n = 0
    for r in rotors:
        for name in dir(type(r)):
            attr = type(r).__dict__.get(name)
            if attr is None or type(attr).__name__ != "_MethodRope":
                continue
            getattr(r, name).cache_clear()
            n += 1
    for modname, mod in list(sys.modules.items()):
        if not (modname == "ross" or modname.startswith("ross.")):
            continue
        for obj in list(vars(mod).values()):
            if isinstance(obj, functools._lru_cache_wrapper):
                obj.cache_clear()
                n += 1
    return n


def fmt(seconds: float) -> str:
    if seconds < 1e-3:
        return f"{seconds * 1e6:8.1f} µs"
    if seconds < 1:
        return f"{seconds * 1e3:8.2f} ms"
    return f"{seconds:8.3f} s "
