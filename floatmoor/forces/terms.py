"""Kinds of force term and the numba bundles of their arrays (what the time loop reads).

The time-domain kernel does not know the force models: it sums *terms*, each of one *kind*,
kind by kind in the order of :data:`KINDS`, each kind over its terms in the order the models
contributed them.  A model writes its terms into the :class:`~floatmoor.forces.base.
KernelAssembly` in ``contribute`` (``asm.add_restoring(...)``, ``asm.add_series(...)``, ...);
the assembly stacks each kind's arrays into the bundles below, built once per run.

Kinds (the generalized force of a term, earth axes, moments about the displaced reference
point; ``T`` turns the yaw-following frame into earth axes):

``restoring``          ``T (F_0 - C x)``: constant ``F_0`` (6,) and matrix ``C`` (6, 6) on the
                       pose, in the yaw-following frame (hydrostatics; a body-fixed thrust)
``mooring``            quasi-static catenary lines at the instantaneous fairleads (one term)
``damping``            ``-T B nu``, matrix on the yaw-frame velocity ``nu``
``quadratic_damping``  ``-T (B nu|nu|)``, ``F_i = -sum_j B_ij nu_j |nu_j|``
``memory``             radiation memory: convolution of retardation functions with the
                       yaw-frame velocity history (one term)
``relative_flow``      ``C(theta_rel) |U - v|^2``: a flow speed (series or constant), heading and
                       body-axis coefficient table (wind, current)
``lf_damping``         ``-B (x' - x'_WF)``: matrix in earth axes on the low-frequency pose rate,
                       the pose rate less the linear wave-frequency velocity (wave drift damping)
``strips``             drag strips on the hull (slender elements; one strip set)
``series``             a force precomputed at the half-step samples (waves, drift)

The rows of the per-term force array ``parts`` follow the same order, and the total force is
their sum in that order.  A new model of an existing kind is one new file in ``forces/`` and
its import line in :mod:`floatmoor.forces` (the registry); the kernel does not change.

All bundles are :class:`typing.NamedTuple` of C-contiguous writeable arrays and scalars, so that
numba types them once (``cache=True``) and they also run with ``NUMBA_DISABLE_JIT=1``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["KINDS", "FlowTerms", "ForceTerms", "LFDampingTerms", "MatrixTerms", "MemoryTerm",
           "RestoringTerms", "StripTerm", "NoStrips", "as_kernel_array"]

KINDS = ("restoring", "mooring", "damping", "quadratic_damping", "memory", "relative_flow",
         "lf_damping", "strips", "series")
"""The kinds of force term, in the order the kernel evaluates and sums them."""

SINGLE_TERM_KINDS = ("mooring", "memory", "strips")
"""Kinds with at most one term (they carry their own states or large tables)."""


def as_kernel_array(a, dtype=None) -> np.ndarray:
    """``a`` as a C-contiguous writeable array (one compiled signature: the frozen arrays of
    the models are read-only and would type differently); a copy only when needed."""
    return np.require(np.asarray(a, dtype=dtype), requirements=("C", "W"))


class RestoringTerms(NamedTuple):
    """``restoring`` kind: ``const`` (n, 6) and ``matrix`` (n, 6, 6)."""

    const: np.ndarray
    matrix: np.ndarray


class MatrixTerms(NamedTuple):
    """``damping`` or ``quadratic_damping`` kind: ``matrix`` (n, 6, 6)."""

    matrix: np.ndarray


class MemoryTerm(NamedTuple):
    """``memory`` kind: ``on``; ``kernel`` (n_pairs, n_k) retardation functions K_ij(k dt) of
    the DOF pairs ``i``, ``j`` (n_pairs,) int64.  ``ss``: the history sum by the recursion of
    :mod:`floatmoor.hydro.memory_fit` (scene ``solver: {memory: state_space}``) with roots
    ``ss_z`` and residues ``ss_c`` (n_pairs, n_roots) complex (zero-padded) and its state
    ``ss_y`` (n_pairs, n_roots) complex, instead of the convolution sum."""

    on: bool
    kernel: np.ndarray
    i: np.ndarray
    j: np.ndarray
    ss: bool
    ss_z: np.ndarray
    ss_c: np.ndarray
    ss_y: np.ndarray


class FlowTerms(NamedTuple):
    """``relative_flow`` kind, n terms: ``speed`` (n, m) the flow speed (m/s) at the half-step
    samples (m = n_samples) or constant (m = 1, ``varies`` False); ``heading`` (n,) rad;
    coefficient tables ``table_heading`` (n, n_max) and ``table`` (n, n_max, 6) of which the
    first ``n_heading`` (n,) rows are used.  ``has_wf`` / ``wf_velocity`` (n_samples, 6): the
    linear wave-frequency body velocity (earth axes) removed from the body velocity."""

    speed: np.ndarray
    varies: np.ndarray
    heading: np.ndarray
    table_heading: np.ndarray
    table: np.ndarray
    n_heading: np.ndarray
    has_wf: bool
    wf_velocity: np.ndarray


class LFDampingTerms(NamedTuple):
    """``lf_damping`` kind, n terms: ``matrix`` (n, 6, 6) in earth axes on the pose rate less,
    when ``has_wf``, the linear wave-frequency velocity ``wf_velocity`` (n_samples, 6) (earth
    axes; the array the relative-flow terms use)."""

    matrix: np.ndarray
    has_wf: bool
    wf_velocity: np.ndarray


class StripTerm(NamedTuple):
    """``strips`` kind: ``on`` and the packed arrays of
    :func:`floatmoor.forces.slender_kernels.slender_packed_into`."""

    on: bool
    fel: np.ndarray
    iel: np.ndarray
    eta: np.ndarray
    u: np.ndarray
    a: np.ndarray
    par: np.ndarray
    cur: np.ndarray
    ramp: np.ndarray


class NoStrips(NamedTuple):
    """``strips`` kind of a run without strips (``on`` False).  A type of its own: the time loop
    compiled for it leaves the strip code out (:func:`floatmoor.forces.slender_kernels.
    strips_into` chooses on the bundle's type), so a scene without slender elements does not
    compile it."""

    on: bool


class ForceTerms(NamedTuple):
    """All force terms but the mooring's (its bundle,
    :class:`floatmoor.solvers.td_bundles.Lines`, also carries the line states):
    ``series`` (n, n_samples, 6)."""

    restoring: RestoringTerms
    damping: MatrixTerms
    quadratic_damping: MatrixTerms
    memory: MemoryTerm
    flow: FlowTerms
    lf_damping: LFDampingTerms
    strips: StripTerm | NoStrips
    series: np.ndarray


def empty_strips() -> NoStrips:
    return NoStrips(False)
