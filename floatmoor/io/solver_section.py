"""The ``solver:`` section of a scene: faster approximations of the time loop (opt-in, apart from
``fe_stages``, whose default is ``linear``: see below).

```yaml
solver:
  catenary: predictor      # exact (default) | predictor
  memory: state_space      # convolution (default) | state_space
  memory_fit_tol: 0.01     # relative L2 error of the state-space fits (default 0.01)
  threads: 2               # threads for the finite-element lines: 1 (default) | N | auto
  fe_stages: catenary      # coupled FE lines in the RK4 stages: linear (default) | catenary
  fe_stiffness_interval: 1.0  # s between the FE lines' catenary stiffness solves (linear
                              #   stages; default 1.0, 0: every body step)
```

``catenary``: ``exact`` solves every quasi-static line at every RK4 stage by Newton's method to
the catenary tolerance (1e-9, warm-started from the previous solution); ``predictor`` steps from
the previous solution with its stiffness and one Newton correction, falling back to the exact
solve when the correction exceeds 1e-4 of the tension (:mod:`floatmoor.mooring.catenary_step`;
the flagship storm's tensions agree with the exact path to about 1e-11, the loop is about
twice as fast).  ``memory``: ``convolution`` sums the sampled retardation functions over the
whole memory once per step; ``state_space`` replaces that sum by the recursion of a sum of
decaying exponentials fitted to each retardation function (``memory_fit_tol``, relative L2
error, :mod:`floatmoor.hydro.memory_fit`; the fit errors are the attribute
``memory_fit_error``).  On the flagship storm the history part of the memory force is within
0.3-1.1 % (RMS) of the convolution in surge, heave, roll and pitch at the default 1 %, 0.1-0.4 %
with ``memory_fit_tol: 0.001`` (0.6 s more setup); the storm's peaks move by 0.03-0.1 %, the
order of the time-step error at dt 0.1 s (benchmarks/RESULTS.md).
``floatmoor convergence --solver`` reports the differences against run time.

``fe_stages`` (runs with finite-element lines coupled to the body,
:mod:`floatmoor.solvers.fe_coupling`): over a body step the FE lines' force is their accepted
force at the step start plus the change of their elastic catenary from the step start to each
RK4 stage, a model of the lines' variation within the step (neither choice is the FE lines'
own variation, which the scheme holds over the step).  ``catenary`` solves those catenaries at
every stage (4 solves per line and step); ``linear`` (the default since 2026-11-28) takes the
change from the catenaries' 6x6 stiffness at the step start (one solve with stiffness per line
and step; the change over a stage is a fraction of a metre, so the dropped term is of second
order in it).  On the 3-hour flagship FE storm (12 lines x 50 elements, dt 0.1 s, two threads)
the loop went from 23.3 to 20.2 s (20.9 to 18.0 s with ``finite_element: {newton: fast}``); the
maximum fairlead tension moved by 0.0003 % and each line's maximum by at most 0.004 %, against
the time step's own 0.018 % (benchmarks/RESULTS.md); 3600 s of it on one core with the FE lines
as lanes: 7.6 / 7.9 s against 9.0 / 9.9 s, each line's maximum within 0.0006 % (section
"``fe_stages: linear`` the default").  In 240 s test storms the tensions stay within 1 % of
the time step's own error (``tests/solvers/test_fe_stages.py``).  Without FE lines the option changes nothing.

``fe_stiffness_interval`` (s, with ``fe_stages: linear``): the FE lines' catenary stiffness of
the linear stages is solved every ``round(interval / dt)`` body steps (at least every step;
``0``: every step, as before 2026-11-28) and at any step where a line is released (a line
failure leaves the stiffness at once); in between the last one is kept, turned into pose
coordinates at each step's pose.  The stiffness only scales the stage-to-stage change of the
force (a fraction of a metre of motion), so a stiffness up to a second old moves that change by
a few percent of itself.  On the 3-hour flagship FE storm (3 seeds, 12 x 50 elements, dt 0.1 s)
the default 1.0 s moved each line's mean maximum by at most 0.004 % and its std by 0.003 %
(the time step's own error 0.04 %) and took 0.8-0.9 of the CPU (benchmarks/RESULTS.md, "A mesh
by segment").  Ignored with ``fe_stages: catenary``, which solves the catenaries at every stage.

``threads``: the finite-element lines of the body are advanced in that many threads
(:func:`floatmoor.mooring.fe.multi.body_advance_parallel`); the results are bit for bit those of
one thread (the lines are independent within a body step; their sum stays in the line order),
so this is not an approximation and changes nothing without FE lines.  ``auto``: numba's
thread pool (``NUMBA_NUM_THREADS``, the CPUs by default), except for FE lines that fit one
group of SIMD lanes (the same node count), which then advance on one thread as lanes
(``fe_coupling.auto_threads``: faster than the lines in threads on the flagship since the lanes
vectorise, benchmarks/RESULTS.md); a number above the pool is reduced to it.
Processes that run several storms at once never oversubscribe the cores
(:func:`with_thread_cap`): ``floatmoor run`` with ``--workers W`` runs each worker with at most
``cores // W`` threads (at least 1), and campaign tasks (one storm per single-threaded worker)
with 1.  One thread (the default) runs the serial kernel, which neither contains nor compiles
the parallel one.

Every key is optional; the defaults are the exact catenaries and memory, one thread and the
linearised FE stages with their stiffness solved every 1.0 s (:attr:`SolverSpec.is_default`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

from ..core.config import Node
from ..core.errors import SceneError

__all__ = ["SolverSpec", "parse_solver", "describe_solver", "SOLVER_KEYS", "CATENARY_MODES", "FE_STIFFNESS_INTERVAL_MAX",
           "MEMORY_MODES", "FE_STAGE_MODES", "fe_stages", "fe_stiffness_interval",
           "FE_STIFFNESS_INTERVAL", "catenary_tol", "THREADS_AUTO",
           "parse_threads", "available_threads", "run_threads", "with_thread_cap", "is_auto",
           "worker_thread_cap"]

SOLVER_KEYS = ("catenary", "memory", "memory_fit_tol", "threads", "fe_stages",
               "fe_stiffness_interval")
FE_STIFFNESS_INTERVAL = 1.0
"""Default ``fe_stiffness_interval``, s (module docstring)."""
FE_STIFFNESS_INTERVAL_MAX = 10.0
"""Largest ``fe_stiffness_interval``, s: a stiffness older than that is no longer the
lines' at the pose (the flagship's surge moves metres in 10 s)."""
THREADS_AUTO = "auto"
THREADS_EXPECTED = "a positive integer or auto"
CATENARY_MODES = ("exact", "predictor")
MEMORY_MODES = ("convolution", "state_space")
FE_STAGE_MODES = ("catenary", "linear")


@dataclass(frozen=True, kw_only=True)
class SolverSpec:
    """Options of the time loop (module docstring); ``file`` for messages."""

    catenary: str = "exact"
    memory: str = "convolution"
    memory_fit_tol: float = 0.01
    threads: int | str = 1
    """Threads for the FE lines: a positive integer or ``"auto"`` (:func:`run_threads`)."""
    fe_stages: str = "linear"
    """The coupled FE lines' force over the RK4 stages: ``linear`` (default) or ``catenary``."""
    fe_stiffness_interval: float = FE_STIFFNESS_INTERVAL
    """s between the FE lines' catenary stiffness solves of the linear stages (0: every
    step)."""
    file: object = field(default=None, compare=False)
    threads_auto: bool = field(default=False, compare=False)
    """``threads`` is ``auto`` resolved to a number by :func:`with_thread_cap`: the FE run
    still takes one thread when its lines fit the SIMD lanes (:func:`is_auto`)."""

    @property
    def is_default(self) -> bool:
        """True when every option is its default (the reference path of ``floatmoor
        convergence --solver``; the thread count changes no number and is not looked at)."""
        return (self.catenary == "exact" and self.memory == "convolution"
                and self.fe_stages == "linear"
                and self.fe_stiffness_interval == FE_STIFFNESS_INTERVAL)

    def describe(self) -> str:
        fit = (f" (fit {self.memory_fit_tol:g})" if self.memory == "state_space" else "")
        fe = ", FE stages catenary" if self.fe_stages == "catenary" else ""
        if self.fe_stages == "linear" and self.fe_stiffness_interval != FE_STIFFNESS_INTERVAL:
            fe += f", FE stiffness every {self.fe_stiffness_interval:g} s"
        return f"catenary {self.catenary}, memory {self.memory}{fit}{fe}"

    def describe_threads(self) -> str:
        """``""`` for one thread, else e.g. ``"threads 2"``."""
        return "" if self.threads == 1 else f"threads {self.threads}"


def parse_solver(node: Node) -> SolverSpec:
    """Read a ``solver:`` mapping (SceneError naming file and key for every mistake)."""
    node.reject_unknown(SOLVER_KEYS)
    d = SolverSpec()
    return SolverSpec(catenary=node.str("catenary", d.catenary, choices=CATENARY_MODES),
                      memory=node.str("memory", d.memory, choices=MEMORY_MODES),
                      memory_fit_tol=node.float("memory_fit_tol", d.memory_fit_tol, gt=0.0,
                                                lt=1.0),
                      threads=parse_threads(node.raw("threads", d.threads), file=node.file,
                                            key=node.key("threads")),
                      fe_stages=node.str("fe_stages", d.fe_stages, choices=FE_STAGE_MODES),
                      fe_stiffness_interval=node.float(
                          "fe_stiffness_interval", d.fe_stiffness_interval, ge=0.0,
                          le=FE_STIFFNESS_INTERVAL_MAX, unit="s"),
                      file=node.file)


def parse_threads(value, *, file=None, key: str = "solver.threads") -> int | str:
    """A thread count: a positive integer or ``"auto"`` (SceneError naming ``file`` and
    ``key`` otherwise); digits in a string (a command-line value) are read as the integer."""
    if isinstance(value, str) and value.strip().isdigit():
        value = int(value.strip())
    if value == THREADS_AUTO:
        return THREADS_AUTO
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise SceneError(file, key, THREADS_EXPECTED, value)
    return int(value)


def available_threads() -> int:
    """numba's thread pool: ``NUMBA_NUM_THREADS`` (the CPUs of the machine by default)."""
    import numba
    return max(1, int(numba.config.NUMBA_NUM_THREADS))


def run_threads(spec: SolverSpec | None) -> int:
    """The threads a run of ``spec`` uses: 1 without a spec, ``auto`` the whole pool
    (:func:`available_threads`), a number at most the pool."""
    if spec is None:
        return 1
    pool = available_threads()
    if spec.threads == THREADS_AUTO:
        return pool
    return max(1, min(int(spec.threads), pool))


def worker_thread_cap(workers: int) -> int:
    """Threads per process when ``workers`` processes run at once: the CPUs available to this
    process divided among them (at least 1)."""
    import os
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        cores = os.cpu_count() or 1
    return max(1, cores // max(1, int(workers)))


def with_thread_cap(spec: SolverSpec | None, cap: int, threads=None) -> SolverSpec | None:
    """``spec`` with ``threads`` (when given: a command-line choice replacing the scene's) and
    at most ``cap`` threads (a process among several running storms at once); ``None`` stays
    ``None`` unless ``threads`` asks for more than one."""
    if threads is not None:
        spec = dataclasses.replace(spec if spec is not None else SolverSpec(), threads=threads)
    if spec is None:
        return None
    n = min(run_threads(spec), max(1, int(cap)))
    return (spec if n == spec.threads
            else dataclasses.replace(spec, threads=n, threads_auto=is_auto(spec)))


def is_auto(spec: SolverSpec | None) -> bool:
    """True when ``spec`` asks for ``threads: auto`` (as written or resolved against a cap by
    :func:`with_thread_cap`)."""
    return spec is not None and (spec.threads == THREADS_AUTO or spec.threads_auto)


def fe_stages(spec: SolverSpec | None) -> str:
    """The coupled FE lines' stage model of ``spec`` (``linear`` without a spec)."""
    return spec.fe_stages if spec is not None else "linear"


def fe_stiffness_interval(spec: SolverSpec | None) -> float:
    """s between the FE lines' stiffness solves of ``spec`` (the default without a spec)."""
    return spec.fe_stiffness_interval if spec is not None else FE_STIFFNESS_INTERVAL


def catenary_tol(spec: SolverSpec | None) -> float:
    """The accepted Newton correction of the predictor-corrector catenary solves (0: exact)."""
    from ..mooring.catenary_step import STEP_TOL
    return STEP_TOL if spec is not None and spec.catenary == "predictor" else 0.0


def describe_solver(spec: SolverSpec | None, scene=None) -> list[str]:
    """Lines for ``Scene.describe()``."""
    if spec is None:
        return []
    words = [] if spec.is_default else [spec.describe()]
    if spec.describe_threads():
        words.append(spec.describe_threads())
    return [f"solver: {', '.join(words)}"] if words else []
