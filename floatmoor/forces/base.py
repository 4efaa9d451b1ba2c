"""The force-model interface, the registry and the kernel assembly.

Every force on the floater (hydrostatics, mooring, radiation memory, damping, waves, wind,
current) is a :class:`ForceModel`, one file in ``floatmoor/forces/`` serving both domains:

* ``wanted(built, options)`` (class method) whether a scene asks for the model: the time and
  the frequency domain choose their models with it (:func:`select_models`, in the registry's
  order, which is the order of the time loop's terms).
* ``setup(ctx)`` (time domain) turns the built scene (:class:`SetupContext`) into frozen
  parameters and plain arrays, once.  After setup the model does not change (``_frozen``).
* ``force(t, pose, velocity, out)`` adds the model's generalized force (N, N m; moments about the
  displaced body reference point, earth axes) into ``out``.  It is the readable Python reference
  of what the time-domain kernel computes for that model; tests compare the two.
* ``contribute(asm)`` adds the model's force terms to the :class:`KernelAssembly`, each of one
  kind (:mod:`floatmoor.forces.terms`: restoring, mooring, damping, quadratic damping, memory,
  relative flow, low-frequency damping, strips, series) with ``asm.add_<kind>(name, ...)``.  A
  model that the scene does not name is never constructed, so it adds no term and the kernel
  does no work for it.
* ``frequency_domain(fd)`` (frequency domain) the model's :class:`FDTerms` about the mean
  position (:class:`FDContext`): its mean force, its linearised stiffness and damping (WF and
  LF, or LF only), a quadratic damping matrix for the stochastic linearisation, its WF
  excitation and its LF force spectrum.  The default reads the model's own time-domain terms
  of the linear kinds (restoring, damping, quadratic damping) as they are, so a model of those
  kinds needs no frequency-domain code; a model with terms of another kind and no
  ``frequency_domain`` is refused by the frequency domain (SceneError naming it).
* ``stiffness(pose)`` (optional) the analytic Jacobian ``-dF/dpose`` (6x6);
  ``damping_linearized(...)`` (optional) ``-dF/dv``, which the model's ``frequency_domain``
  uses.
* ``mean_force()`` the force at rest averaged over time (wind and current at their mean speed,
  mean wave drift), used for the static start.  The constants and matrices of ``restoring``
  terms already enter the static start (:attr:`KernelAssembly.const_force`,
  :attr:`KernelAssembly.restoring`): such a model keeps ``mean_force`` zero.
* ``channels()`` the output channels the model can report (``force`` by default).

Models are registered by name in :data:`REGISTRY` with :func:`register`; :func:`model_class`
turns a name into its class and raises :class:`~floatmoor.core.errors.SceneError` listing the
names available.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ..core.errors import SceneError
from ..core.frames import yaw_rotation6
from .terms import (
    KINDS,
    SINGLE_TERM_KINDS,
    FlowTerms,
    ForceTerms,
    LFDampingTerms,
    MatrixTerms,
    MemoryTerm,
    RestoringTerms,
    StripTerm,
    as_kernel_array,
    empty_strips,
)

__all__ = ["REGISTRY", "GROUPS", "ForceModel", "KernelAssembly", "SetupContext", "FDContext",
           "FDTerms", "model_class", "register", "select_models"]


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
    inputs : :class:`floatmoor.io.build.ModelInputs`, the vessel data after the scene's rules
        that combine models (viscous drift: extra linear damping, hull current coefficients
        without double counting, corrected mean drift), applied once where the scene's models
        are chosen; None: the vessel's data as they are (a model set up on its own).
    solver : the ``solver:`` options (:class:`floatmoor.io.solver_section.SolverSpec`) or
        None (the exact path).
    """

    built: Any
    seed: int
    dt: float
    n_steps: int
    ramp: float = 0.0
    yaw0: float = 0.0
    options: Any = None
    waves: Any = None
    inputs: Any = None
    solver: Any = None

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


@dataclass(frozen=True, kw_only=True)
class FDContext:
    """What a force model may read in the frequency domain (plain data, nothing changes later).

    built, options, inputs : as in :class:`SetupContext` (``inputs`` at the body heading
        ``yaw``: the scene's rules that combine models, e.g. the drift coefficients of the
        correction formula at that heading).
    omega : (n,) the wave-frequency grid (rad/s) over the hydrodynamic database's range.
    mu : (m,) the low-frequency grid (rad/s), 0 to the LF cut-off.
    directions : (n_dir,) directions of travel (rad, earth) of the sea's energy: every wave
        system and, with spreading, each of its directions (equal directions merged);
        spectra : (n_dir, n) the one-sided elevation spectrum of each direction on ``omega``
        (m^2 s/rad); their sum is the sea's spectrum.  n_dir = 0 without waves.
    yaw : the mean body heading (rad).  pose : (6,) the mean pose, or None while the mean
        position is iterated.
    linear : False while the mean position is iterated (only ``const_force``, ``restoring``
        and ``mean_force`` of the terms are read: a model may leave out the rest), True at the
        mean position.
    notes : the run's remarks (``append(text)``, ``warn(text)`` also shows a warning) or None.
    fd_options : the :class:`floatmoor.solvers.frequency_domain.FDOptions` of the run.
    """

    built: Any
    options: Any = None
    inputs: Any = None
    omega: np.ndarray
    mu: np.ndarray
    directions: np.ndarray
    spectra: np.ndarray
    yaw: float = 0.0
    pose: Any = None
    linear: bool = False
    notes: Any = None
    fd_options: Any = None

    @property
    def has_waves(self) -> bool:
        return self.directions.size > 0

    @property
    def rotation(self) -> np.ndarray:
        """(6, 6) yaw-following frame -> earth axes at the mean heading."""
        return yaw_rotation6(self.yaw)

    @property
    def gravity(self) -> float:
        return float(self.built.scene.site.gravity)

    def note(self, text: str) -> None:
        if self.notes is not None:
            self.notes.append(text)

    def warn(self, text: str) -> None:
        if self.notes is not None:
            self.notes.warn(text)

    def setup_context(self) -> SetupContext:
        """A one-step :class:`SetupContext` without waves at the mean heading, for the
        time-domain setup of a model whose terms are read as they are (default
        :meth:`ForceModel.frequency_domain`)."""
        return SetupContext(built=self.built, seed=0, dt=1.0, n_steps=1, yaw0=float(self.yaw),
                            options=self.options, inputs=self.inputs)


@dataclass(frozen=True, kw_only=True)
class FDTerms:
    """A force model's contribution to the frequency domain (:meth:`ForceModel.
    frequency_domain`), about the mean position, SI units, earth axes unless said; None: none.

    const_force (6,), restoring (6, 6) : a ``restoring`` term (``F_0 - C x``): ``F_0`` joins
        the static balance and ``C`` the hydrostatic restoring of the statics (as the time
        domain's static start) and the linear stiffness.
    mean_force (6,) : the time-mean force at rest at the mean heading (wind and current at
        their mean speed, mean wave drift).
    stiffness (6, 6) : linearised ``-dF/dx`` at the mean beyond ``restoring``.
    damping (6, 6) : linear damping ``-dF/dv`` on the wave- and low-frequency motion.
    lf_damping (6, 6) : damping on the low-frequency motion only (wind, current, wave drift
        damping).
    quadratic_damping (6, 6) : ``B`` of ``F_i = -sum_j B_ij nu_j |nu_j|`` on the yaw-frame
        velocity; the solver linearises it stochastically on the total velocity (every entry).
    wf_excitation (n_dir, n, 6) complex : first-order force per unit wave amplitude of each
        direction of :class:`FDContext` (exp(+i w t)).
    lf_force_spectrum (m, 6, 6) : slowly varying force cross-spectra (N^2 s/rad ...).
    added_mass, radiation_damping (n, 6, 6) : the frequency-dependent radiation on the WF grid
        and lf_added_mass (6, 6) in the LF system (radiation model; without it A_inf is used).
    info : named values for the result (e.g. the drift method, the mean wind speed).
    """

    const_force: np.ndarray | None = None
    restoring: np.ndarray | None = None
    mean_force: np.ndarray | None = None
    stiffness: np.ndarray | None = None
    damping: np.ndarray | None = None
    lf_damping: np.ndarray | None = None
    quadratic_damping: np.ndarray | None = None
    wf_excitation: np.ndarray | None = None
    lf_force_spectrum: np.ndarray | None = None
    added_mass: np.ndarray | None = None
    radiation_damping: np.ndarray | None = None
    lf_added_mass: np.ndarray | None = None
    info: dict = field(default_factory=dict)

    @classmethod
    def from_assembly(cls, name: str, asm: KernelAssembly, yaw: float) -> FDTerms:
        """The terms of the linear kinds that ``name`` added to ``asm``, as they are: a
        restoring term's constant and matrix, a damping matrix turned to earth axes at ``yaw``
        (``T B T^T``), a quadratic damping matrix (yaw frame).  SceneError for a term of
        another kind (no frequency-domain form without the model's own ``frequency_domain``)."""
        const = restoring = damping = quadratic = None
        T = yaw_rotation6(yaw)
        for kind in KINDS:
            for owner, payload in asm.terms[kind]:
                if owner != name:
                    continue
                if kind == "restoring":
                    const, restoring = payload
                elif kind == "damping":
                    damping = T @ payload @ T.T
                elif kind == "quadratic_damping":
                    quadratic = payload
                else:
                    raise SceneError(None, "forces", "force models with a frequency-domain "
                                     "form (terms of the kinds restoring, damping, quadratic "
                                     "damping, or a frequency_domain of their own)",
                                     f"model {name!r} with a {kind} term",
                                     hint="exclude it (forces: exclude) to run the frequency "
                                          "domain without it")
        return cls(const_force=const, restoring=restoring, damping=damping,
                   quadratic_damping=quadratic)


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

    def contribute(self, asm: KernelAssembly) -> None:  # pragma: no cover
        raise NotImplementedError

    @classmethod
    def wanted(cls, built, options) -> bool:
        """Whether the built scene (:class:`floatmoor.io.build.BuiltScene`) with its ``forces``
        settings ``options`` (or None) asks for this model; False unless the model says."""
        return False

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """The model's :class:`FDTerms` about the mean position (:class:`FDContext`).  Default:
        a fresh instance set up for one step at the mean heading (:meth:`FDContext.
        setup_context`) and its terms of the linear kinds as they are
        (:meth:`FDTerms.from_assembly`)."""
        ctx = fd.setup_context()
        m = type(self)()
        m.setup(ctx)
        asm = KernelAssembly(n_samples=ctx.n_samples, sample_dt=ctx.sample_dt)
        m.contribute(asm)
        return FDTerms.from_assembly(self.name, asm, fd.yaw)

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
"""Force-model classes by name, in the order of registration: the order in which both domains
assemble a scene's models (:func:`select_models`) and the time loop sums their terms within a
kind (the import order of :mod:`floatmoor.forces`; the bit-identity digests pin it)."""

GROUPS = {"drift": ("drift_newman", "drift_qtf"),
          "damping": ("damping_linear", "damping_quadratic"),
          "waves": ("wave1", "drift_newman", "drift_qtf", "wave_drift_damping")}
"""Names that exclude several models at once (``forces: {exclude: [drift]}``)."""


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


def select_models(built, options=None) -> list[str]:
    """Names of the models a built scene asks for (each class's :meth:`ForceModel.wanted`), in
    the registry's order, less those named in ``forces: exclude`` (model or group names;
    SceneError for an unknown name).  Both domains assemble these models."""
    exclude = set(getattr(options, "exclude", ()) or ())
    drop = set()
    for name in exclude:
        if name in GROUPS:
            drop.update(GROUPS[name])
        elif name in REGISTRY:
            drop.add(name)
        else:
            raise SceneError(getattr(options, "file", None), "forces.exclude",
                             "force model names: " + ", ".join(sorted(set(REGISTRY) | set(GROUPS))),
                             name)
    return [name for name, cls in REGISTRY.items()
            if name not in drop and cls.wanted(built, options)]


def _sum(arrays, shape):
    """Sum of ``arrays`` in their order (the array itself for one: no arithmetic)."""
    if not arrays:
        return np.zeros(shape)
    out = arrays[0]
    for a in arrays[1:]:
        out = out + a
    return out


@dataclass(kw_only=True)
class KernelAssembly:
    """The force terms of a run, by kind (:mod:`floatmoor.forces.terms`), filled by the models'
    ``contribute``; :meth:`force_terms` stacks them into the kernel's bundle.

    ``inertia`` M + A_inf (6, 6); ``wf_velocity`` (n_samples, 6) the linear wave-frequency body
    velocity removed from the body velocity in the relative-flow terms when
    ``has_wf_velocity`` and in the low-frequency damping terms when ``lf_wf_velocity``.  Units
    SI; matrices 6x6 about the body reference point.
    """

    n_samples: int
    sample_dt: float
    inertia: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))
    wf_velocity: np.ndarray = field(default_factory=lambda: np.zeros((0, 6)))
    has_wf_velocity: bool = False
    lf_wf_velocity: bool = False
    """The ``lf_damping`` terms act on the pose rate less ``wf_velocity`` (set with the
    series); independent of ``has_wf_velocity``, which is the relative-flow terms' choice
    (``forces: relative_velocity``)."""
    terms: dict = field(default_factory=lambda: {k: [] for k in KINDS})
    """kind -> list of (model name, arrays) in the order of contribution."""

    # -- adding terms (called by the models' contribute) ----------------------------------------
    def _add(self, kind: str, name: str, payload) -> None:
        if kind in SINGLE_TERM_KINDS and self.terms[kind]:
            raise ValueError(f"{name}: a second {kind} term ({self.terms[kind][0][0]} has one); "
                             f"the kernel takes one {kind} term")
        if name in self.part_names:
            raise ValueError(f"{name}: a model adds one force term")
        self.terms[kind].append((name, payload))

    def add_restoring(self, name: str, const, matrix) -> None:
        """``T (const - matrix x)`` (N, N m; yaw-following frame, turned to earth axes)."""
        self._add("restoring", name, (np.asarray(const, float).reshape(6),
                                      np.asarray(matrix, float).reshape(6, 6)))

    def add_mooring(self, name: str, system, fail_time) -> None:
        """Quasi-static lines of a :class:`floatmoor.mooring.MooringSystem`, each inactive from
        its ``fail_time`` (s; inf: intact) on."""
        self._add("mooring", name, (system, np.asarray(fail_time, float)))

    def replace_mooring_system(self, system) -> None:
        """Swap the :class:`~floatmoor.mooring.MooringSystem` of the mooring term (same lines,
        same failure times), e.g. for fibre ropes linearised about the mean position."""
        name, (_, fail_time) = self.terms["mooring"][0]
        self.terms["mooring"][0] = (name, (system, fail_time))

    def add_damping(self, name: str, matrix) -> None:
        """``-T matrix nu`` (N s/m ...), on the yaw-frame velocity."""
        self._add("damping", name, np.asarray(matrix, float).reshape(6, 6))

    def add_quadratic_damping(self, name: str, matrix) -> None:
        """``F_i = -T sum_j matrix_ij nu_j |nu_j|`` on the yaw-frame velocity."""
        self._add("quadratic_damping", name, np.asarray(matrix, float).reshape(6, 6))

    def add_memory(self, name: str, kernel, i, j, state_space=None) -> None:
        """Radiation memory: ``kernel`` (n_pairs, n_k) K_ij at 0, dt, 2 dt, ... for the DOF
        pairs ``i``, ``j``; ``state_space``: None (the convolution) or the roots and residues
        (n_pairs, n_roots) complex of the recursive history sum
        (:mod:`floatmoor.hydro.memory_fit`)."""
        self._add("memory", name, (np.asarray(kernel, float), np.asarray(i, np.int64),
                                   np.asarray(j, np.int64), state_space))

    def add_relative_flow(self, name: str, *, speed, heading: float, table_heading,
                          table) -> None:
        """``C(theta_rel) |U - v|^2``: ``speed`` (m/s) a constant or (n_samples,) at the
        half-step samples, ``heading`` (rad, earth), body-axis table (n, 6) at
        ``table_heading`` (n,) rad."""
        speed = np.asarray(speed, float)
        if speed.ndim and speed.shape != (self.n_samples,):
            raise ValueError(f"{name}: speed shape {speed.shape}, expected ({self.n_samples},)")
        self._add("relative_flow", name, (speed, float(heading),
                                          np.asarray(table_heading, float),
                                          np.asarray(table, float)))

    def add_lf_damping(self, name: str, matrix) -> None:
        """``-matrix (x' - x'_WF)`` (N s/m ...): earth axes, on the low-frequency pose rate
        (the pose rate less the linear wave-frequency velocity, when the run has one)."""
        self._add("lf_damping", name, np.asarray(matrix, float).reshape(6, 6))

    def add_strips(self, name: str, arrays: tuple) -> None:
        """A strip set: the packed arrays (fel, iel, eta, u, a, par, cur, ramp) of
        :func:`floatmoor.forces.slender_kernels.slender_packed_into`."""
        self._add("strips", name, tuple(arrays))

    def add_series(self, name: str, values: np.ndarray) -> None:
        """Add a precomputed force series (n_samples, 6) (N, N m), ramp already applied."""
        values = np.asarray(values, float)
        if values.shape != (self.n_samples, 6):
            raise ValueError(f"series {name}: shape {values.shape}, expected ({self.n_samples}, 6)")
        self._add("series", name, values)

    # -- what the solver reads ------------------------------------------------------------------
    @property
    def part_names(self) -> list:
        """Model name of each row of the kernel's per-term force array (kind order)."""
        return [name for k in KINDS for name, _ in self.terms[k]]

    @property
    def part_kinds(self) -> list:
        return [k for k in KINDS for _ in self.terms[k]]

    @property
    def restoring(self) -> np.ndarray:
        """Total restoring matrix (6, 6) of the restoring terms (statics, stability)."""
        return _sum([m for _, (_, m) in self.terms["restoring"]], (6, 6))

    @property
    def const_force(self) -> np.ndarray:
        """Total constant force (6,) of the restoring terms (yaw-following frame)."""
        return _sum([c for _, (c, _) in self.terms["restoring"]], (6,))

    @property
    def damping_linear(self) -> np.ndarray:
        return _sum([m for _, m in self.terms["damping"]], (6, 6))

    @property
    def damping_quadratic(self) -> np.ndarray:
        return _sum([m for _, m in self.terms["quadratic_damping"]], (6, 6))

    @property
    def damping_lf(self) -> np.ndarray:
        """Total low-frequency damping (6, 6) of the ``lf_damping`` terms (earth axes)."""
        return _sum([m for _, m in self.terms["lf_damping"]], (6, 6))

    @property
    def has_damping_quadratic(self) -> bool:
        return bool(self.terms["quadratic_damping"])

    @property
    def mooring(self):
        """The :class:`floatmoor.mooring.MooringSystem` of the mooring term, or None."""
        t = self.terms["mooring"]
        return t[0][1][0] if t else None

    @property
    def fail_time(self) -> np.ndarray:
        t = self.terms["mooring"]
        return t[0][1][1] if t else np.zeros(0)

    def force_terms(self) -> ForceTerms:
        """The numba bundle of every term but the mooring's (built once per run)."""
        c = as_kernel_array
        t = self.terms
        rest = RestoringTerms(c(np.array([a for _, (a, _) in t["restoring"]]).reshape(-1, 6)),
                              c(np.array([m for _, (_, m) in t["restoring"]]).reshape(-1, 6, 6)))
        damp = MatrixTerms(c(np.array([m for _, m in t["damping"]]).reshape(-1, 6, 6)))
        quad = MatrixTerms(c(np.array([m for _, m in t["quadratic_damping"]]).reshape(-1, 6, 6)))
        no_ss = np.zeros((0, 1), complex)
        if t["memory"]:
            kernel, i, j, ss = t["memory"][0][1]
            if ss is None:
                ss_on, z, cz = False, no_ss, no_ss
            else:
                ss_on, (z, cz) = True, ss
            mem = MemoryTerm(True, c(kernel if kernel.size else np.zeros((0, 1))), c(i), c(j),
                             ss_on, c(z, complex), c(cz, complex), np.zeros_like(c(z, complex)))
        else:
            mem = MemoryTerm(False, np.zeros((0, 1)), np.zeros(0, np.int64),
                             np.zeros(0, np.int64), False, no_ss, no_ss, no_ss.copy())
        flows = [p for _, p in t["relative_flow"]]
        n = len(flows)
        varies = np.array([p[0].ndim == 1 for p in flows], np.bool_)
        m = self.n_samples if varies.any() else 1
        nh = np.array([p[2].shape[0] for p in flows], np.int64)
        n_max = int(nh.max()) if n else 1
        speed = np.zeros((n, m))
        th = np.zeros((n, n_max))
        tab = np.zeros((n, n_max, 6))
        for q, (sp, _, h, tb) in enumerate(flows):
            speed[q] = sp
            th[q, :h.shape[0]] = h
            tab[q, :h.shape[0]] = tb
        wf = self.wf_velocity if self.has_wf_velocity else np.zeros((1, 6))
        flow = FlowTerms(speed, varies, np.array([p[1] for p in flows], float).reshape(n), th,
                         tab, nh, bool(self.has_wf_velocity), c(wf, float))
        lf_wf = self.wf_velocity if self.lf_wf_velocity else np.zeros((1, 6))
        lf = LFDampingTerms(c(np.array([m for _, m in t["lf_damping"]]).reshape(-1, 6, 6)),
                            bool(self.lf_wf_velocity), c(lf_wf, float))
        strips = (StripTerm(True, *(c(a) for a in t["strips"][0][1])) if t["strips"]
                  else empty_strips())
        series = (c(np.array([s for _, s in t["series"]])) if t["series"]
                  else np.zeros((0, 1, 6)))
        return ForceTerms(rest, damp, quad, mem, flow, lf, strips, series)
