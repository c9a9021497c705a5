"""The scope of one public call, per thread: what a warm start may survive.

Rule: the same inputs give the same answer whatever ran before. The analyses keep solver
state between the operating points of one call (a Campbell diagram continues its equilibrium
from speed to speed, a threshold scan from point to point); none of it may survive into the
next public call. Every public analysis is wrapped by :func:`rotordyn._common.threads.limited_blas`,
which enters :func:`outermost_call`: the outermost such call on a thread opens a new
*epoch* (nested public calls, e.g. the equilibrium inside a stability analysis, share their
caller's). A cached per-system state (``rotordyn.analysis.assembly.Assembled``: the last
equilibrium and the C++ solver's film state) records the epoch it was used in and is reset
when it is next used in another: each public call starts from the concentric, undeformed state
with forgotten cavitation sets, and continues only along its own path.

Per thread: the analyses in other threads (sweep chunks, dask workers, a user's thread pool)
have their own caches and their own epochs.
"""

from __future__ import annotations

import contextlib
import itertools
import threading

_local = threading.local()
_counter = itertools.count(1)  # epochs unique across threads (next() is atomic under the GIL)


def current_epoch() -> int:
    """The epoch of this thread's running outermost public call (0 outside any)."""
    return getattr(_local, "epoch", 0)


@contextlib.contextmanager
def outermost_call():
    """Enter a public call: the outermost one on this thread opens a new epoch."""
    depth = getattr(_local, "depth", 0)
    if depth == 0:
        _local.epoch = next(_counter)
    _local.depth = depth + 1
    try:
        yield
    finally:
        _local.depth = depth
