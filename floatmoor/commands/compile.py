"""``floatmoor compile SCENE.yaml [...]``: compile the kernels of the scenes' storms ahead of
their first run.

numba compiles floatmoor's kernels at their first use and keeps them in floatmoor's cache
folder (:mod:`floatmoor.core.numba_cache`), so the first storm after an installation, or after
an update of the kernel sources, waits for 10-20 s of compilation (benchmarks/RESULTS.md,
"First run").  This command pays that once, where it suits: when a container image or a
cluster's software module is built, or before a campaign is started.  For each scene it runs a
short storm (300 s; statics, start state and time loop: the kernels, and the types, of a
full storm of that scene); for a scene with ``solver: {threads: N}`` also with one thread (the
kernel each worker uses when several seeds run at once).  Kernels already in the cache are
loaded, not compiled again, and kernels shared by several scenes are compiled once.

numba's cache entries are specific to the CPU, the numba and Python versions and the kernel
sources, so the compiled kernels serve the machine (type) that compiled them; elsewhere numba
compiles again, as without this command.
"""

from __future__ import annotations

import argparse

HELP = "compile the numba kernels of the scenes' storms ahead of their first run"

DURATION = 300.0
"""Length of each short storm (s): long enough for the scene's wave realisation (its frequency
step is 2 pi / duration), a second or two of time loop."""


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor compile``."""
    p.add_argument("scenes", nargs="+", metavar="SCENE.yaml",
                   help="scene files whose storms will be run (all are read before anything "
                        "is compiled)")


def _compile_counter():
    """The list of the outermost compilations of this process from now on (a kernel compiled
    for a caller is part of its caller's compilation), by function name."""
    from numba.core import event

    from ..core.compile_events import outermost_listener

    done: list[str] = []
    event.register("numba:compile", outermost_listener(
        lambda ev: done.append(ev.data["dispatcher"].py_func.__qualname__)))
    return done


def _variants(scene):
    """The solver settings whose kernels a storm of ``scene`` may use: the scene's (threads
    capped at this machine's cores, as ``floatmoor run`` with one worker), and one thread when
    that is more (several workers)."""
    import dataclasses

    from ..io.solver_section import run_threads, with_thread_cap, worker_thread_cap

    solver = with_thread_cap(scene.solver, worker_thread_cap(1))
    out = [("", solver)]
    if solver is not None and run_threads(solver) > 1:
        out.append((" (one thread)", dataclasses.replace(solver, threads=1)))
    return out


def run(args: argparse.Namespace) -> int:
    """Run ``floatmoor compile``; returns the exit status."""
    import os
    import time
    import warnings

    from ..analyses.simulate import simulate
    from ..cli import EXIT_OK
    from ..core.errors import FloatmoorWarning
    from ..io.scene import load_scene

    scenes = [(path, load_scene(path)) for path in args.scenes]
    compiled = _compile_counter()
    print(f"numba cache: {os.environ.get('NUMBA_CACHE_DIR', '(numba default)')}")
    total = time.perf_counter()
    for path, scene in scenes:
        for label, solver in _variants(scene):
            n0 = len(compiled)
            t0 = time.perf_counter()
            with warnings.catch_warnings():
                # a storm shorter than the transient and the ramp, on purpose
                warnings.simplefilter("ignore", FloatmoorWarning)
                simulate(scene, duration=min(DURATION, scene.analysis.duration),
                         transient=0.0, solver=solver)
            n = len(compiled) - n0
            what = (f"{n} kernel{'s' if n != 1 else ''} compiled" if n
                    else "nothing to compile (loaded from the cache)")
            print(f"{path}{label}: {what} in {time.perf_counter() - t0:.1f} s", flush=True)
    print(f"done in {time.perf_counter() - total:.1f} s")
    return EXIT_OK
