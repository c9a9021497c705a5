"""Ctrl-C where it cannot corrupt the interpreter.

Python raises KeyboardInterrupt at the next bytecode of the main thread, and that can be
inside the import machinery (``<frozen importlib._bootstrap>``: a module lock being taken,
released, or dropped by its weakref callback). The exception is then swallowed there
("Exception ignored in ... _get_module_lock.<locals>.cb") and the lock's state is left
broken, so a later import fails with a bare AssertionError: a sweep stopped by Ctrl-C
then exited 1 as an "internal error" instead of 130 with its resume line.

:func:`safe_interrupts` installs a SIGINT handler that raises as Python's own does, except
when the interrupted frame is the import machinery's: then the signal is sent again
:data:`RETRY_S` later, when the import is (normally) over.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading

RETRY_S = 0.02
"""Delay before a SIGINT that arrived inside the import machinery is delivered again (s)."""

_MACHINERY = "<frozen importlib"


def in_import_machinery(frame) -> bool:
    """True when ``frame`` (the one a signal interrupted) is the import machinery's code."""
    return frame is not None and frame.f_code.co_filename.startswith(_MACHINERY)


def handler(signum, frame) -> None:
    """SIGINT handler: KeyboardInterrupt, deferred out of the import machinery."""
    if in_import_machinery(frame):
        t = threading.Timer(RETRY_S, os.kill, (os.getpid(), signum))
        t.daemon = True
        t.start()
        return
    raise KeyboardInterrupt


@contextlib.contextmanager
def safe_interrupts():
    """:func:`handler` as the SIGINT handler inside the block (main thread only, and only
    over Python's default handler: a handler the caller installed is left alone)."""
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
        yield
        return
    old = signal.signal(signal.SIGINT, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)
