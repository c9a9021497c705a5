"""Progress lines on stderr for work that takes more than a few seconds: which step, how far
(step k of n, item i of m), and the time so far. Two forms:

* :class:`Steps` — a known sequence of steps (the report): one line per step and, inside a
  step, at most one line per :data:`ITEM_INTERVAL_S` for its items;
* :func:`long_work` — one piece of work of unknown length (a Campbell diagram, an unbalance
  response, a transient): a line only if it is still running after :data:`DELAY_S`, and then
  a closing line with its time. Short work prints nothing.

Lines go to stderr (the CLI's stdout stays machine-readable)."""

from __future__ import annotations

import contextlib
import sys
import threading
import time

DELAY_S = 3.0          # long_work: silent unless the work runs longer than this
ITEM_INTERVAL_S = 2.0  # Steps.item: at most one line per this interval within a step


class Steps:
    """``Steps("report", 8)``; ``.step("Campbell diagram, 121 speeds")`` prints
    ``rotordyn report: [3/8] Campbell diagram, 121 speeds (12 s)``; ``.item(i, m)`` inside a
    step prints ``… item i/m`` at most every :data:`ITEM_INTERVAL_S`; ``enabled=False``
    silences all."""

    def __init__(self, what: str, n_steps: int, *, enabled: bool = True, stream=None):
        self.what, self.n, self.k = what, int(n_steps), 0
        self.enabled = enabled
        self.stream = stream
        self.t0 = time.monotonic()
        self.text = ""
        self.last_item = 0.0

    def _write(self, line: str) -> None:
        if self.enabled:
            s = self.stream or sys.stderr
            s.write(f"rotordyn {self.what}: {line} ({time.monotonic() - self.t0:.0f} s)\n")
            s.flush()

    def step(self, text: str) -> None:
        """Start the next step (the count grows past ``n_steps`` rather than lying)."""
        self.k += 1
        self.n = max(self.n, self.k)
        self.text = text
        self.last_item = time.monotonic()
        self._write(f"[{self.k}/{self.n}] {text}")

    def item(self, i: int, m: int) -> None:
        """Item ``i`` of ``m`` of the current step done (a line now and then, and at the end
        of a step that has already taken :data:`ITEM_INTERVAL_S`)."""
        now = time.monotonic()
        if now - self.last_item >= ITEM_INTERVAL_S:
            self.last_item = now
            self._write(f"[{self.k}/{self.n}] {self.text}: {i}/{m}")

    def done(self) -> None:
        self._write(f"done, {self.k} steps")


@contextlib.contextmanager
def long_work(what: str, *, delay_s: float | None = None, stream=None, enabled: bool = True):
    """Around one long call: ``rotordyn <what>: running…`` on stderr if it is still running
    after ``delay_s`` (default :data:`DELAY_S`), then ``… done after 12.3 s`` (``stopped
    after`` when it raised: the error follows)."""
    delay = DELAY_S if delay_s is None else delay_s
    t0 = time.monotonic()
    said = threading.Event()
    lock = threading.Lock()
    finished = False

    def _say():
        with lock:
            if finished:
                return
            s = stream or sys.stderr
            s.write(f"rotordyn {what}: running ({delay:g} s so far)…\n")
            s.flush()
            said.set()

    timer = threading.Timer(delay, _say) if enabled else None
    if timer is not None:
        timer.daemon = True
        timer.start()
    ok = False
    try:
        yield
        ok = True
    finally:
        with lock:
            finished = True
        if timer is not None:
            timer.cancel()
        if said.is_set():
            s = stream or sys.stderr
            s.write(f"rotordyn {what}: {'done' if ok else 'stopped'} after "
                    f"{time.monotonic() - t0:.1f} s\n")
            s.flush()


__all__ = ["DELAY_S", "ITEM_INTERVAL_S", "Steps", "long_work"]
