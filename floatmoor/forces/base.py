"""The force-model interface, the registry and the kernel assembly.

Every force on the floater (hydrostatics, mooring, radiation memory, damping, waves, wind,
current) is a :class:`ForceModel`:

* ``setup(ctx)`` turns the built scene (:class:`SetupContext`) into frozen parameters and plain
  arrays, once.  After setup the model does not change (``_frozen``).
* ``force(t, pose, velocity, out)`` adds the model's generalized force (N, N m; moments about the
  displaced body reference point, earth axes) into ``out``.  It is the readable Python reference
  of what the time-domain kernel computes for that model; tests compare the two.
* ``stiffness(pose)`` (optional) the analytic Jacobian ``-dF/dpose`` (6x6).
* ``damping_linearized(...)`` (optional) for the frequency domain.
* ``mean_force()`` the force at rest averaged over time (wind and current at their mean speed,
  mean wave drift), used for the static start.
* ``channels()`` the output channels the model can report (``force`` by default).
* ``contribute(asm)`` writes the model's arrays into the :class:`KernelAssembly`, the one bag of
  plain arrays the numba time loop reads.  A model that the scene does not name is never
  constructed, so its arrays stay empty and the kernel skips it.

Models are registered by name in :data:`REGISTRY` with :func:`register`; :func:`model_class`
turns a name into its class and raises :class:`~floatmoor.core.errors.SceneError` listing the
names available.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ..core.errors import SceneError

__all__ = ["ForceModel", "SetupContext", "KernelAssembly", "REGISTRY", "register", "model_class",
           "PART_NAMES", "N_PARTS"]

# Slots of the per-model force array the kernel fills at every evaluation.  Time-series models
# (first-order waves, drift) occupy the slots from PART_SERIES on, in their order of assembly.
PART_HYDROSTATICS = 0
PART_MOORING = 1
PART_DAMPING_LINEAR = 2
PART_DAMPING_QUADRATIC = 3
PART_RADIATION = 4
PART_WIND = 5
PART_CURRENT = 6
PART_SLENDER = 7
PART_SERIES = 8
MAX_SERIES = 4
N_PARTS = PART_SERIES + MAX_SERIES
PART_NAMES = ("hydrostatics", "mooring", "damping_linear", "damping_quadratic", "radiation",
              "wind", "current", "slender_elements")


@dataclass(frozen=True, kw_only=True)
class SetupContext:
    """What a force model may read at setup (plain data; nothing here changes later).

    built : :class:`floatmoor.io.build.BuiltScene` (vessel, mooring, static force, scene).
    seed : int, the realisation seed (each model derives its own stream from it).
    dt : float, time step (s); n_steps : int, number of steps (the run covers n_steps * dt).
    ramp : float, ramp length (s) of the fluctuating environmental loads.
    yaw0 : float, the body heading (rad) at which the wave loads are evaluated.
    options : the ``forces:`` settings (:class:`floatmoor.io.forces_section.ForcesSpec` or None).
    waves : :class:`floatmoor.forces.waves.WaveComponents` shared by the wave models, or None.
    """

    built: Any
    seed: int
    dt: float
    n_steps: int
    ramp: float = 0.0
    yaw0: float = 0.0
    options: Any = None
    waves: Any = None

    @property
    def n_samples(self) -> int:
        """Samples of the precomputed series: every half step (RK4 evaluates at t + dt/2)."""
        return 2 * self.n_steps + 1

    @property
    def sample_dt(self) -> float:
        return 0.5 * self.dt

    def ramp_series(self) -> np.ndarray:
        """Ramp factor 0.5 (1 - cos(pi t / T_ramp)) at the half-step samples (1 after T_ramp)."""
        t = np.arange(self.n_samples) * self.sample_dt
        if self.ramp <= 0.0:
            return np.ones_like(t)
        r = 0.5 * (1.0 - np.cos(np.pi * np.minimum(t / self.ramp, 1.0)))
        return r


class ForceModel:
    """Base class of all force models (see the module docstring for the contract)."""

    name: ClassVar[str] = ""
    description: ClassVar[str] = ""

    def __init__(self):
        self._frozen = False

    # -- contract -----------------------------------------------------------------------------
    def setup(self, ctx: SetupContext) -> None:  # pragma: no cover - each model overrides
        raise NotImplementedError

    def force(self, t: float, pose, velocity, out) -> None:  # pragma: no cover
        raise NotImplementedError

    def contribute(self, asm: "KernelAssembly") -> None:  # pragma: no cover
        raise NotImplementedError

    def mean_force(self) -> np.ndarray:
        """Time-mean force at rest (N, N m); zero unless the model says otherwise."""
        return np.zeros(6)

    def channels(self) -> list[str]:
        return ["force"]

    # -- helpers --------------------------------------------------------------------------------
    def _freeze(self) -> None:
        for value in vars(self).values():
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
        self._frozen = True

    def __setattr__(self, key, value):
        if getattr(self, "_frozen", False):
            raise AttributeError(f"force model {self.name!r} is frozen after setup")
        object.__setattr__(self, key, value)

    def __repr__(self):
        return f"<{type(self).__name__} {self.name!r}>"


REGISTRY: dict[str, type[ForceModel]] = {}
"""Force-model classes by name."""


def register(cls: type[ForceModel]) -> type[ForceModel]:
    """Class decorator adding a model to :data:`REGISTRY` under ``cls.name``."""
    if not cls.name:
        raise ValueError(f"{cls.__name__} has no name")
    if cls.name in REGISTRY and REGISTRY[cls.name] is not cls:
        raise ValueError(f"a force model named {cls.name!r} is already registered")
    REGISTRY[cls.name] = cls
    return cls


def model_class(name: str, *, file=None, key: str = "forces") -> type[ForceModel]:
    """The registered class of ``name``; SceneError listing the names otherwise."""
    try:
        return REGISTRY[name]
    except KeyError:
        raise SceneError(file, key, "one of the force models: " + ", ".join(sorted(REGISTRY)),
                         name) from None


def _empty(*shape, dtype=float):
    return np.zeros(shape, dtype=dtype)


@dataclass(kw_only=True)
class KernelAssembly:
    """The plain arrays the time-domain kernel reads, filled by the models' ``contribute``.

    Everything absent stays empty (size 0) and the kernel skips it.  Units SI; matrices 6x6
    about the body reference point.
    """

    n_samples: int
    sample_dt: float
    inertia: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))      # M + A_inf
    const_force: np.ndarray = field(default_factory=lambda: np.zeros(6))       # buoyancy - weight
    restoring: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))    # C (force -C x)
    damping_linear: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))
    damping_quadratic: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))
    has_damping_linear: bool = False
    has_damping_quadratic: bool = False
    # radiation memory: K[p, j] = K_{i(p) j(p)}(j dt), j = 0..n_k-1
    ret_kernel: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    ret_i: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    ret_j: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    # time series (n_series, n_samples, 6), ramp included
    series: np.ndarray | None = None
    series_names: list = field(default_factory=list)
    # wind and current: speed series / constant, heading (rad, earth), coefficient table
    wind_speed: np.ndarray = field(default_factory=lambda: np.zeros(0))
    wind_heading: float = 0.0
    wind_table_heading: np.ndarray = field(default_factory=lambda: np.zeros(0))
    wind_table: np.ndarray = field(default_factory=lambda: np.zeros((0, 6)))
    current_speed: float = 0.0
    current_heading: float = 0.0
    current_table_heading: np.ndarray = field(default_factory=lambda: np.zeros(0))
    current_table: np.ndarray = field(default_factory=lambda: np.zeros((0, 6)))
    has_wind: bool = False
    has_current: bool = False
    # linear wave-frequency body velocity (n_samples, 6), earth axes: removed from the body
    # velocity in the wind and current relative velocity (seed 002 eq. 2.24, 2.26); empty: none
    wf_velocity: np.ndarray = field(default_factory=lambda: np.zeros((0, 6)))
    has_wf_velocity: bool = False
    # mooring (quasi-static)
    mooring: Any = None
    fail_time: np.ndarray = field(default_factory=lambda: np.zeros(0))
    # slender elements: (fel, iel, eta, u, a, par, cur, ramp), see floatmoor.forces.slender
    slender: Any = None

    def add_series(self, name: str, values: np.ndarray) -> None:
        """Add a precomputed force series (n_samples, 6) (N, N m), ramp already applied."""
        values = np.asarray(values, float)
        if values.shape != (self.n_samples, 6):
            raise ValueError(f"series {name}: shape {values.shape}, expected ({self.n_samples}, 6)")
        if len(self.series_names) >= MAX_SERIES:
            raise ValueError(f"at most {MAX_SERIES} time-series force models")
        s = values[None]
        self.series = s if self.series is None else np.concatenate([self.series, s])
        self.series_names.append(name)
