"""BLAS threads for the analyses' small dense problems.

The linear algebra of one operating point is small (tens to hundreds of unknowns): a threaded
BLAS gains nothing there and, on a loaded machine, loses a lot (50 unbalance frequencies of a
100-element rotor took 8.1 s with the default OpenBLAS threads against 0.4 s on one thread,
issue 11). The public analyses therefore run with BLAS limited to one thread (threadpoolctl)
unless the user asks otherwise with :func:`set_blas_threads` or the environment variable
``ROTORDYN_BLAS_THREADS`` (an integer, or ``default`` to leave the BLAS alone). OpenMP (the C++
batches) is not affected.

The limit is process-wide (BLAS thread pools are): it is taken by the first analysis that
starts and given back when the last running one ends, so analyses in several Python threads at
once neither undo each other's limit nor leave it behind.
"""

from __future__ import annotations

import functools
import os
import sys
import threading

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


_lock = threading.Lock()
_threads: int | None = _from_env()
_controller = None
_controller_modules = -1  # len(sys.modules) when the controller was made
_active = 0
_saved = None


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


def _enter():
    global _controller, _controller_modules, _active, _saved
    with _lock:
        if _threads is None:
            return False
        if _active == 0:
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
        return True


def _exit():
    global _active, _saved
    with _lock:
        _active -= 1
        if _active == 0 and _saved is not None:
            _saved.restore_original_limits()
            _saved = None


def limited_blas(fn):
    """Decorator: run ``fn`` with the BLAS limited to :func:`get_blas_threads` threads."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        entered = _enter()
        try:
            return fn(*args, **kwargs)
        finally:
            if entered:
                _exit()

    return wrapper
