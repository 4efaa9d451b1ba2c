"""A line on the terminal when numba starts compiling: a command that would otherwise sit
silent for tens of seconds at its first use after an installation or an update (``floatmoor fd
--tension-model dynamic``: about 40 s of compilation of the finite-element line kernels) says
what it is doing.

:func:`compile_notice` listens to numba's ``numba:compile`` events, which fire only when a
kernel is compiled (not when it is loaded from numba's cache): at the first compilation it
prints one line, and at the end of the block how long the compilation took.  Nothing is
printed when every kernel comes from the cache.
"""

from __future__ import annotations

import contextlib
import sys
import time

__all__ = ["compile_notice"]


@contextlib.contextmanager
def compile_notice(what: str = "floatmoor's kernels", echo=None, report_end: bool = True):
    """Within the block, print ``compiling <what> (numba, once ...)`` at the first numba
    compilation (``echo``: default a line on stderr), and the compile time at the end (unless
    ``report_end`` is False)."""
    from numba.core import event

    if echo is None:
        def echo(text):
            print(text, file=sys.stderr, flush=True)

    class Notice(event.Listener):
        def __init__(self):
            self.depth = 0
            self.started = None
            self.total = 0.0

        def on_start(self, ev):
            if self.depth == 0:
                if self.started is None:
                    echo(f"compiling {what} (numba, once per installation or update of "
                         "floatmoor; `floatmoor compile` does it ahead) ...")
                self.t0 = time.perf_counter()
                self.started = True
            self.depth += 1

        def on_end(self, ev):
            self.depth -= 1
            if self.depth == 0:
                self.total += time.perf_counter() - self.t0

    notice = Notice()
    event.register("numba:compile", notice)
    try:
        yield notice
    finally:
        event.unregister("numba:compile", notice)
        if notice.started and report_end:
            echo(f"compiled in {notice.total:.0f} s")
