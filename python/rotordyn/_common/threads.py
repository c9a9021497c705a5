"""BLAS threads for the analyses' small dense problems.

The linear algebra of one operating point is small (tens to hundreds of unknowns): a threaded
BLAS gains nothing there and, on a loaded machine, loses a lot (50 unbalance frequencies of a
100-element rotor took 8.1 s with the default OpenBLAS threads against 0.4 s on one thread,
issue 11). The public analyses therefore run with BLAS limited to one thread (threadpoolctl)
unless the user asks otherwise with :func:`set_blas_threads` or the environment variable
``ROTORDYN_BLAS_THREADS`` (an integer, or ``default`` to leave the BLAS alone). OpenMP (the C++
batches) is not affected.

Eigen's own products in the C++ core run on one thread likewise (:func:`set_eigen_threads`,
``ROTORDYN_EIGEN_THREADS``), set once at import for every core call: the core links OpenMP
for its batches, and Eigen would otherwise split every product above ~50³ over OpenMP threads
that spin-wait on a loaded machine.

The limit is process-wide (BLAS thread pools are): it is taken by the first analysis that
starts and given back when the last running one ends, so analyses in several Python threads at
once neither undo each other's limit nor leave it behind.
"""

from __future__ import annotations

import functools
import os
import sys
import threading

from rotordyn import _core
from rotordyn._common.calls import outermost_call
from rotordyn.errors import InputError


def _from_env() -> int | None:
    text = os.environ.get("ROTORDYN_BLAS_THREADS", "1").strip().lower()
    if text in ("default", "none", ""):
        return None
    try:
        n = int(text)
    except ValueError:
        raise InputError("ROTORDYN_BLAS_THREADS: expected a positive integer or 'default', "
                         f"got {text!r}") from None
    if n < 1:
        raise InputError(f"ROTORDYN_BLAS_THREADS: expected a positive integer or 'default', got {n}")
    return n


def _eigen_from_env() -> int:
    text = os.environ.get("ROTORDYN_EIGEN_THREADS", "1").strip().lower()
    if text in ("default", "none", ""):
        return 0
    try:
        n = int(text)
    except ValueError:
        n = -1
    if n < 1:
        raise InputError("ROTORDYN_EIGEN_THREADS: expected a positive integer or 'default', "
                         f"got {text!r}")
    return n


_lock = threading.Lock()
_threads: int | None = _from_env()
_controller = None
_controller_modules = -1  # len(sys.modules) when the controller was made
_active = 0
_saved = None
_eigen_pending: int | None = None  # a set_eigen_threads value waiting for the running calls


def set_blas_threads(n: int | None) -> None:
    """BLAS threads used inside rotordyn's analyses: a positive integer (default 1), or None
    to leave the BLAS libraries' own setting alone."""
    global _threads
    if n is not None and (isinstance(n, bool) or not isinstance(n, int) or n < 1):
        raise InputError(f"n: expected a positive integer or None, got {n!r}")
    with _lock:
        _threads = n


def get_blas_threads() -> int | None:
    """The current setting of :func:`set_blas_threads`."""
    return _threads


def set_eigen_threads(n: int | None) -> None:
    """Threads of Eigen's own matrix products inside the C++ core, process-wide: a positive
    integer (default 1), or None for OpenMP's count (``OMP_NUM_THREADS``, Eigen's default).

    One thread is the default in every core call: the products of one operating point are too
    small to gain from threads, and on a loaded machine Eigen's OpenMP threads spin-wait
    (docs/performance.md, "Threads"). Parallelism is across points instead: the C++ batches'
    OpenMP loops (``OMP_NUM_THREADS``), ``threads=`` of the analyses that take it, sweep
    threads and workers. Environment: ``ROTORDYN_EIGEN_THREADS=n|default``. A change made while
    analyses run takes effect when the last of them has returned (no core call sees the value
    change under it)."""
    global _eigen_pending
    if n is not None and (isinstance(n, bool) or not isinstance(n, int) or n < 1):
        raise InputError(f"n: expected a positive integer or None, got {n!r}")
    with _lock:
        if _active == 0:
            _core.set_eigen_threads(0 if n is None else n)
            _eigen_pending = None
        else:
            _eigen_pending = 0 if n is None else n


def get_eigen_threads() -> int | None:
    """The current setting of :func:`set_eigen_threads` (None: OpenMP's count)."""
    with _lock:
        n = _core.eigen_threads() if _eigen_pending is None else _eigen_pending
    return None if n == 0 else n


_core.set_eigen_threads(_eigen_from_env())


def _enter():
    global _controller, _controller_modules, _active, _saved
    with _lock:
        if _active == 0 and _threads is not None:
            try:
                # A BLAS loaded since the controller was made (a new extension module) would
                # escape it: look again whenever modules were imported (~10 ms; rare once the
                # program runs).
                if _controller is None or len(sys.modules) != _controller_modules:
                    from threadpoolctl import ThreadpoolController

                    _controller = ThreadpoolController()
                    _controller_modules = len(sys.modules)
                _saved = _controller.limit(limits=_threads, user_api="blas")
            except ImportError:  # threadpoolctl is a dependency; tolerate its absence
                _saved = None
        _active += 1


def _exit():
    global _active, _saved, _eigen_pending
    with _lock:
        _active -= 1
        if _active == 0:
            if _saved is not None:
                _saved.restore_original_limits()
                _saved = None
            if _eigen_pending is not None:
                _core.set_eigen_threads(_eigen_pending)
                _eigen_pending = None


class core_calls:
    """Context of core calls made outside a public analysis (a sweep chunk's C++ batches on
    a pool thread): counted as running, so a set_eigen_threads waits for them too, with the
    BLAS limited as in :func:`limited_blas`."""

    def __enter__(self):
        _enter()
        return self

    def __exit__(self, *exc):
        _exit()
        return False


def limited_blas(fn):
    """Decorator of every public analysis: run ``fn`` with the BLAS limited to
    :func:`get_blas_threads` threads, as one public call (:mod:`rotordyn._common.calls`: the
    outermost on a thread starts from no warm state of an earlier call)."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        _enter()
        try:
            with outermost_call():
                return fn(*args, **kwargs)
        finally:
            _exit()

    return wrapper
