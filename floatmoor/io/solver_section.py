"""The ``solver:`` section of a scene: faster approximations of the time loop (opt-in).

```yaml
solver:
  catenary: predictor      # exact (default) | predictor
  memory: state_space      # convolution (default) | state_space
  memory_fit_tol: 0.01     # relative L2 error of the state-space fits (default 0.01)
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

Every key is optional; the defaults are the exact path (bit-identical results).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.config import Node

__all__ = ["SolverSpec", "parse_solver", "describe_solver", "SOLVER_KEYS", "CATENARY_MODES",
           "MEMORY_MODES", "catenary_tol"]

SOLVER_KEYS = ("catenary", "memory", "memory_fit_tol")
CATENARY_MODES = ("exact", "predictor")
MEMORY_MODES = ("convolution", "state_space")


@dataclass(frozen=True, kw_only=True)
class SolverSpec:
    """Options of the time loop (module docstring); ``file`` for messages."""

    catenary: str = "exact"
    memory: str = "convolution"
    memory_fit_tol: float = 0.01
    file: object = field(default=None, compare=False)

    @property
    def exact(self) -> bool:
        """True when every option is the exact path."""
        return self.catenary == "exact" and self.memory == "convolution"

    def describe(self) -> str:
        fit = (f" (fit {self.memory_fit_tol:g})" if self.memory == "state_space" else "")
        return f"catenary {self.catenary}, memory {self.memory}{fit}"


def parse_solver(node: Node) -> SolverSpec:
    """Read a ``solver:`` mapping (SceneError naming file and key for every mistake)."""
    node.reject_unknown(SOLVER_KEYS)
    d = SolverSpec()
    return SolverSpec(catenary=node.str("catenary", d.catenary, choices=CATENARY_MODES),
                      memory=node.str("memory", d.memory, choices=MEMORY_MODES),
                      memory_fit_tol=node.float("memory_fit_tol", d.memory_fit_tol, gt=0.0,
                                                lt=1.0),
                      file=node.file)


def catenary_tol(spec: SolverSpec | None) -> float:
    """The accepted Newton correction of the predictor-corrector catenary solves (0: exact)."""
    from ..mooring.catenary_step import STEP_TOL
    return STEP_TOL if spec is not None and spec.catenary == "predictor" else 0.0


def describe_solver(spec: SolverSpec | None, scene=None) -> list[str]:
    """Lines for ``Scene.describe()``."""
    if spec is None or spec.exact:
        return []
    return [f"solver: {spec.describe()}"]
