"""Ctrl-C where it cannot corrupt the interpreter.

Python raises KeyboardInterrupt at the next bytecode of the main thread, and that can be
inside the import machinery (``<frozen importlib._bootstrap>``: a module lock being taken,
released, or dropped by its weakref callback). The exception is then swallowed there
("Exception ignored in ... _get_module_lock.<locals>.cb") and the lock's state is left
broken, so a later import fails with a bare AssertionError: a sweep stopped by Ctrl-C
then exited 1 as an "internal error" instead of 130 with its resume line.

:func:`safe_interrupts` installs a SIGINT handler that raises as Python's own does, except
when the interrupted frame is the import machinery's: then the signal is sent again
:data:`RETRY_S` later, when the import is (normally) over — for at most :data:`MAX_DEFER_S`
(an import blocked on another thread's lock is then interrupted as before, not waited for).
A deferral still pending when the block ends is reported by the guard (``pending``).
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import time

RETRY_S = 0.02
"""Delay before a SIGINT that arrived inside the import machinery is delivered again (s)."""
MAX_DEFER_S = 0.5
"""Longest a SIGINT is deferred out of the import machinery (s); then it is raised there."""

_MACHINERY = "<frozen importlib"


class Guard:
    """The state of :func:`safe_interrupts`: ``since`` the time of the first deferral of the
    interrupt not yet delivered (None: none pending), ``timer`` its re-send."""

    def __init__(self):
        self.since: float | None = None
        self.timer: threading.Timer | None = None
        self.active = False

    @property
    def pending(self) -> bool:
        """A Ctrl-C was deferred and not delivered before the block ended."""
        return self.since is not None

    def resend(self, signum) -> None:
        if not self.active:
            return
        if signal.getsignal(signum) != self.handler:  # ignored for a moment (a cluster
            self._later(signum)                        # starting): not lost, sent after it
            return
        os.kill(os.getpid(), signum)

    def _later(self, signum) -> None:
        self.timer = threading.Timer(RETRY_S, self.resend, (signum,))
        self.timer.daemon = True
        self.timer.start()

    def handler(self, signum, frame) -> None:
        """SIGINT handler: KeyboardInterrupt, deferred out of the import machinery."""
        now = time.monotonic()
        if in_import_machinery(frame):
            if self.since is None:
                self.since = now
            if now - self.since < MAX_DEFER_S:
                self._later(signum)
                return
        self.since = self.timer = None
        raise KeyboardInterrupt


def in_import_machinery(frame) -> bool:
    """True when ``frame`` (the one a signal interrupted) is the import machinery's code."""
    return frame is not None and frame.f_code.co_filename.startswith(_MACHINERY)


@contextlib.contextmanager
def safe_interrupts():
    """A :class:`Guard`'s handler as the SIGINT handler inside the block (main thread only,
    and only over Python's default handler: a handler the caller installed is left alone).
    Yields the guard; its ``pending`` after the block: a Ctrl-C deferred at the block's end
    and not delivered (the caller decides: the CLI reports "interrupted", exit 130)."""
    guard = Guard()
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
        yield guard
        return
    guard.active = True
    old = signal.signal(signal.SIGINT, guard.handler)
    try:
        yield guard
    finally:
        guard.active = False
        if guard.timer is not None:
            guard.timer.cancel()
        signal.signal(signal.SIGINT, old)
