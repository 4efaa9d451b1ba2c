"""numba's compile events, outermost only: what a command or a worker needs to know of them.

numba reports a compilation (``numba:compile``) and the holding of its compiler lock
(``numba:compiler_lock``) as nested start/end events: compiling a kernel compiles the kernels it
calls inside its own event.  :func:`outermost_listener` calls back at the end of the outermost
one only (the kernels compiled and, for the lock, saved to the cache).
"""

from __future__ import annotations

from collections.abc import Callable

__all__ = ["outermost_listener"]


def outermost_listener(on_end: Callable) -> object:
    """A numba event listener (register it with ``numba.core.event.register(kind, ...)``) that
    calls ``on_end(event)`` when an outermost event of its kind ends."""
    from numba.core import event

    class Outermost(event.Listener):
        def __init__(self):
            self.depth = 0

        def on_start(self, ev):
            self.depth += 1

        def on_end(self, ev):
            self.depth -= 1
            if self.depth == 0:
                on_end(ev)

    return Outermost()
