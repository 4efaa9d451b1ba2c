"""The ``solver:`` section of a scene: faster approximations of the time loop (opt-in).

```yaml
solver:
  catenary: predictor      # exact (default) | predictor
  memory: state_space      # convolution (default) | state_space
```

``catenary``: ``exact`` solves every quasi-static line at every RK4 stage by Newton's method to
the catenary tolerance (1e-9, warm-started from the previous solution); ``predictor`` steps from
the previous solution with its stiffness and one Newton correction, falling back to the exact
solve when the correction exceeds 1e-4 of the tension (:mod:`floatmoor.mooring.catenary_step`;
the flagship storm's tensions agree with the exact path to about 1e-11, the loop is about
twice as fast).  ``memory``: ``convolution`` sums the sampled retardation functions over the
whole memory once per step; ``state_space`` replaces that sum by the recursion of a sum of
decaying exponentials fitted to each retardation function (1 % relative L2 error,
:mod:`floatmoor.hydro.memory_fit`; the fit errors are the attribute ``memory_fit_error``).
``floatmoor convergence --solver`` reports the differences against run time.

Every key is optional; the defaults are the exact path (bit-identical results).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.config import Node

__all__ = ["SolverSpec", "parse_solver", "describe_solver", "SOLVER_KEYS", "CATENARY_MODES",
           "MEMORY_MODES", "catenary_tol"]

SOLVER_KEYS = ("catenary", "memory")
CATENARY_MODES = ("exact", "predictor")
MEMORY_MODES = ("convolution", "state_space")


@dataclass(frozen=True, kw_only=True)
class SolverSpec:
    """Options of the time loop (module docstring); ``file`` for messages."""

    catenary: str = "exact"
    memory: str = "convolution"
    file: object = field(default=None, compare=False)

    @property
    def exact(self) -> bool:
        """True when every option is the exact path."""
        return self.catenary == "exact" and self.memory == "convolution"

    def describe(self) -> str:
        return f"catenary {self.catenary}, memory {self.memory}"


def parse_solver(node: Node) -> SolverSpec:
    """Read a ``solver:`` mapping (SceneError naming file and key for every mistake)."""
    node.reject_unknown(SOLVER_KEYS)
    d = SolverSpec()
    return SolverSpec(catenary=node.str("catenary", d.catenary, choices=CATENARY_MODES),
                      memory=node.str("memory", d.memory, choices=MEMORY_MODES),
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
