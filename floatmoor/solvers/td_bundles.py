"""The bundles of the time-domain kernels besides the force terms
(:mod:`floatmoor.forces.terms`): the body and integrator settings, the mooring lines with
their states, the work arrays and the outputs.

Numba-friendly :class:`typing.NamedTuple` of C-contiguous writeable arrays and scalars (typed
once, cached with ``cache=True``; plain tuples under ``NUMBA_DISABLE_JIT=1``), built once per
run by :func:`floatmoor.solvers.time_domain.integrate`.  Arrays are mutable (states and outputs
are written in place); the tuples themselves are not.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..mooring.catenary import OUT_SIZE
from ..mooring.catenary_step import WARM_SIZE
from ..mooring.fibre_system import FibreTrack, NoFibre, no_fibre_track
from ..mooring.system import CatenaryArrays

__all__ = ["Body", "Lines", "PredictorLines", "Outputs", "State", "lines_bundle", "new_outputs",
           "new_state", "no_lines"]


class Body(NamedTuple):
    """The rigid body and the integrator: ``n_steps`` steps of ``dt`` (s); ``inertia``
    M + A_inf (6, 6) in the yaw-following frame and ``minv`` its inverse; start pose ``x0`` and
    pose rate ``v0`` (6,); ``guard`` (6,) largest |x - x0| per DOF; ``tension_guard`` largest
    line tension / MBS; ``record_parts``: record the force of every term at every step."""

    n_steps: int
    dt: float
    inertia: np.ndarray
    minv: np.ndarray
    x0: np.ndarray
    v0: np.ndarray
    guard: np.ndarray
    tension_guard: float
    record_parts: bool


class Lines(NamedTuple):
    """The ``mooring`` kind: quasi-static lines ``cat`` (:class:`CatenaryArrays`) when ``on``;
    their states ``active`` (n,) bool (False once failed) and ``warm`` (n, 8) catenary warm
    starts (H, V; the predictor-corrector path also x, z, K, :mod:`floatmoor.mooring.
    catenary_step`); ``fail_time`` (n,) s (inf: intact); ``mbs`` (n,) N; ``fibre`` the fibre
    segments linearised about their slowly varying tension (:class:`~floatmoor.mooring.
    fibre_system.FibreTrack`, or :class:`~floatmoor.mooring.fibre_system.NoFibre`: none, or
    the fixed-mean rule); the exact catenary solves (``step_tol`` 0; the predictor-corrector
    solves are the bundle :class:`PredictorLines`)."""

    on: bool
    cat: CatenaryArrays
    active: np.ndarray
    warm: np.ndarray
    fail_time: np.ndarray
    mbs: np.ndarray
    fibre: FibreTrack | NoFibre
    step_tol: float = 0.0


class PredictorLines(Lines):
    """:class:`Lines` with the predictor-corrector catenary solves (scene ``solver: {catenary:
    predictor}``, :mod:`floatmoor.mooring.catenary_step`), ``step_tol`` > 0 the accepted
    correction.  A type of its own: the time loop compiled for :class:`Lines` leaves the
    predictor-corrector code out (:func:`floatmoor.solvers.td_kernel.line_forces` chooses on
    the bundle's type), so an exact run does not compile it."""

    __slots__ = ()


def lines_bundle(on, cat, active, warm, fail_time, mbs, fibre, step_tol=0.0) -> Lines:
    """The :class:`Lines` bundle, :class:`PredictorLines` when ``step_tol`` > 0."""
    cls = PredictorLines if step_tol > 0.0 else Lines
    return cls(on, cat, active, warm, fail_time, mbs, fibre, float(step_tol))


class State(NamedTuple):
    """State and work arrays of :func:`floatmoor.solvers.td_kernel.td_steps`.

    State carried from step to step: pose ``x`` and yaw-frame velocity ``v`` (6,), ``hist``
    (6, 2 n_k) ring buffer of step velocities (stored twice), ``s0``, ``s1`` (n_pairs,)
    convolution sums S_n, S_{n+1}; ``mcorr`` (6,) added to the mooring force when
    ``has_mcorr`` (coupled FE lines), and with ``has_mlin`` also ``mlin @ (x - mref)``
    (``mlin`` (6, 6), ``mref`` (6,): the linearised stage variation of the FE lines' force,
    ``solver: {fe_stages: linear}``).  Work: ``parts`` (n_terms, 6) force of every term,
    ``f`` (6,) their sum; ``work``, ``rot``, ``line_out``, ``fm``, ``stiff`` (catenaries),
    ``coef``, ``sl_sc`` (flow and strip kernels), ``xs``, ``vs`` (stage state), ``mom``, ``g``
    (6,), ``q``, ``a`` (4, 6) the RK4 stage rates."""

    x: np.ndarray
    v: np.ndarray
    hist: np.ndarray
    s0: np.ndarray
    s1: np.ndarray
    mcorr: np.ndarray
    has_mcorr: bool
    mlin: np.ndarray
    mref: np.ndarray
    has_mlin: bool
    parts: np.ndarray
    work: np.ndarray
    rot: np.ndarray
    line_out: np.ndarray
    fm: np.ndarray
    stiff: np.ndarray
    coef: np.ndarray
    sl_sc: np.ndarray
    xs: np.ndarray
    vs: np.ndarray
    f: np.ndarray
    mom: np.ndarray
    g: np.ndarray
    q: np.ndarray
    a: np.ndarray


class Outputs(NamedTuple):
    """Recorded at every step n (row n): ``motion`` pose and ``velocity`` pose rate
    (n_steps+1, 6); ``t_fair``, ``t_anchor`` (n_steps+1, n_lines) N; ``parts`` (n_steps+1,
    n_terms, 6) the force of every term (earth axes) when ``record_parts``, else (1, n_terms,
    6) scratch; ``status`` int64 (3,) or more: code, step, DOF or line
    (:data:`floatmoor.solvers.td_kernel.STATUS_NAMES`)."""

    motion: np.ndarray
    velocity: np.ndarray
    t_fair: np.ndarray
    t_anchor: np.ndarray
    parts: np.ndarray
    status: np.ndarray


def no_lines() -> Lines:
    """A :class:`Lines` bundle without lines (``on`` False)."""
    cat = CatenaryArrays(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0), np.zeros(0),
                         np.zeros(0), np.zeros(0), np.zeros(1, np.int64), np.zeros(0),
                         np.zeros(0, np.bool_))
    return Lines(False, cat, np.zeros(0, np.bool_), np.zeros((0, WARM_SIZE)), np.zeros(0),
                 np.zeros(0), no_fibre_track(), 0.0)


def new_state(n_terms: int, n_lines: int, n_pairs: int, n_k: int, *,
              has_mcorr: bool = False, has_mlin: bool = False) -> State:
    """Zeroed :class:`State` (allocated once per run, outside the step loop)."""
    return State(np.zeros(6), np.zeros(6), np.zeros((6, 2 * n_k)), np.zeros(n_pairs),
                 np.zeros(n_pairs), np.zeros(6), bool(has_mcorr), np.zeros((6, 6)), np.zeros(6),
                 bool(has_mlin), np.zeros((n_terms, 6)),
                 np.zeros(64), np.zeros((3, 3)), np.zeros((n_lines, OUT_SIZE)), np.zeros(6),
                 np.zeros((6, 6)), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6),
                 np.zeros(6), np.zeros(6), np.zeros(6), np.zeros((4, 6)), np.zeros((4, 6)))


def new_outputs(n_steps: int, n_lines: int, n_terms: int, *, record_parts: bool,
                n_status: int = 3) -> Outputs:
    """Zeroed :class:`Outputs` of a run of ``n_steps`` steps."""
    n = n_steps + 1
    return Outputs(np.zeros((n, 6)), np.zeros((n, 6)), np.zeros((n, n_lines)),
                   np.zeros((n, n_lines)), np.zeros((n if record_parts else 1, n_terms, 6)),
                   np.zeros(n_status, np.int64))
