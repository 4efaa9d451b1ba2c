"""Argument bundles of the FE line kernels (:mod:`.kernels`, :mod:`.multi`).

A kernel takes a few of these instead of dozens of positional arrays.  They are
:class:`typing.NamedTuple` s of numpy arrays and scalars, built once by :class:`.line.FELine`
(the arrays are the line's own: no copies), so they work in numba's nopython mode with
``cache=True`` (and in plain Python under ``NUMBA_DISABLE_JIT=1``), and several lines go into
one numba typed list of :class:`LineBundle` (:mod:`.multi`).  The shapes use ``n`` for the
number of nodes; column layouts are the constants of :mod:`.kernels`.

* :class:`LineParams`: read-only parameters of one analysis (statics or dynamics).
* :class:`LineState`: node positions, velocities, accelerations, forces and friction state
  (with the mean strains of fibre elements); a line has three (accepted, trial, sub-step
  result).
* :class:`LineWork`: scratch and per-call outputs of the Newton iterations.
* :class:`LineBundle`: all of a line's bundles, for the multi-line kernels.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

N_AU = 12
"""Length of :attr:`LineWork.audit` (the columns are ``kernels.AU_*``)."""
N_EN = 5
"""Columns of :attr:`LineWork.energy`: known (1.0) or not (0.0), then the energy, power,
energy budget and summed submerged weight of :func:`~.energy.line_energy`."""
N_EW = 10
"""Rows of :attr:`LineWork.ew` (``flat.EW_*``)."""

__all__ = ["LineParams", "LineState", "LineWork", "LineBundle", "new_state", "new_work"]


class LineParams(NamedTuple):
    """Parameters of a line for one analysis; read only in the kernels."""

    P: np.ndarray
    """(n, N_NP) node parameters (mass, weight, drag, added mass, seabed, friction, bending)."""
    E: np.ndarray
    """(n-1, N_EL) element parameters (static or dynamic axial law, internal damping)."""
    S: np.ndarray
    """(N_S,) line scalars (seabed level, friction ramps, current direction, ...)."""
    cur_z: np.ndarray
    """(m,) current profile levels, increasing (m)."""
    cur_u: np.ndarray
    """(m,) current speeds at ``cur_z`` (m/s)."""
    wk: np.ndarray
    """(n, 6) wave particle velocity and acceleration at the nodes (zeros without waves; the
    caller updates it in place before a step)."""
    fric: int
    """Friction code (``kernels.FR_*``)."""
    coef: np.ndarray
    """(4,) generalised-alpha ``alpha_m, alpha_f, beta, gamma``."""
    tol: float
    """Newton tolerance: position correction (m) in dynamics, nodal residual (N) in statics."""
    maxit: int
    """Newton iteration limit."""
    s_nodes: np.ndarray
    """(n,) unstretched arc length of the nodes from the anchor (m)."""
    newton: int
    """Generalised-alpha Newton iteration: 0 exact (the iteration matrix rebuilt at every
    iteration, the default); bits ``kernels.NW_KEEP`` (1, modified: the matrix of the first
    iteration of a step kept while the residual falls fast enough, stop on the estimated
    error), ``NW_PREDICT`` (2, predictor with the fairlead's acceleration) and ``NW_QSTOP`` (4,
    stop on the quadratic-convergence estimate); ``kernels.gen_alpha_step``."""


class LineState(NamedTuple):
    """State of the nodes at one time (m, m/s, m/s^2, N)."""

    r: np.ndarray
    """(n, 3) positions."""
    v: np.ndarray
    """(n, 3) velocities."""
    a: np.ndarray
    """(n, 3) accelerations."""
    f: np.ndarray
    """(n, 3) total nodal forces."""
    fs: np.ndarray
    """(n, N_FS) friction state; columns ``FS_EM, FS_TM, FS_KD`` of row ``j``: mean strain of
    the fibre element ``j``, the working-curve tension and dynamic stiffness at it
    (:mod:`.fibre_law`)."""


class LineWork(NamedTuple):
    """Scratch arrays and per-call outputs of the line kernels (overwritten by every call)."""

    q: np.ndarray
    """(n, 3) node tangents."""
    tens: np.ndarray
    """(n-1,) element tensions of the last force evaluation (N)."""
    act: np.ndarray
    """(n-1,) tension estimate of the stiff elements in a generalised-alpha step (N)."""
    Mb: np.ndarray
    """(n, 3, 3) nodal mass blocks."""
    Dg: np.ndarray
    """(n, 3, 3) diagonal blocks of the iteration matrix."""
    Of: np.ndarray
    """(n-1, 3, 3) first off-diagonal blocks."""
    BX: np.ndarray
    """(7, n, 3, 3) bending blocks and band-solver scratch."""
    R: np.ndarray
    """(n, 3) Newton residual."""
    W: np.ndarray
    """(n, 3, 3) solver scratch (inverse pivots)."""
    Y: np.ndarray
    """(n, 3) solver scratch."""
    T1: np.ndarray
    """(3, 3) solver scratch."""
    dx: np.ndarray
    """(n, 3) Newton correction."""
    rtry: np.ndarray
    """(n, 3) trial positions of the static Newton."""
    rf: np.ndarray
    """(3,) fairlead position of a sub-step."""
    vf: np.ndarray
    """(3,) fairlead velocity of a sub-step."""
    info: np.ndarray
    """(3,) failure or convergence information (see the kernels)."""
    stats: np.ndarray
    """(2,) Newton iterations and step halvings of the last advance."""
    el: np.ndarray
    """(n-1, 4) element unit directions and lengths (m) of the last force evaluation."""
    audit: np.ndarray
    """(``kernels.N_AU``,) energy audit and self-check of the run (cumulative since
    :meth:`FELine.start`, not reset per call; columns ``kernels.AU_*``)."""
    uc: np.ndarray
    """(n,) current speed at the nodes of the last force evaluation (m/s;
    :func:`~.flat.current_speeds`)."""
    ew: np.ndarray
    """(``flat.N_EW``, n) scratch of the energy audit: the terms of every element and node
    (:func:`~.flat.energy_terms`), summed in the audit's order (:func:`~.flat.energy_sums`)."""
    energy: np.ndarray
    """(2, :data:`N_EN`) the energy audit's figures of the trial state's end (row 0, written
    by a completed :func:`~.advance.ga_advance`) and of the accepted state (row 1, copied
    from row 0 by an accept): the next advance starts from them instead of evaluating the
    accepted state again (the same numbers: :func:`~.energy.line_energy` of the same state
    with the element geometry of its own force evaluation).  Column 0 is 1.0 when the row is
    known; :meth:`FELine.start` clears both rows."""


class LineBundle(NamedTuple):
    """Everything a multi-line kernel needs of one line in dynamics."""

    par: LineParams
    now: LineState
    """The accepted state (the line's ``r, v, a, fn, fs``)."""
    trial: LineState
    """The trial state of the last advance."""
    step: LineState
    """The result of one generalised-alpha sub-step (its ``fs`` is not used)."""
    work: LineWork


def new_state(n: int, n_fs: int) -> LineState:
    """A zero :class:`LineState` of ``n`` nodes with ``n_fs`` friction-state columns."""
    return LineState(np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3)),
                     np.zeros((n, n_fs)))


def new_work(n: int) -> LineWork:
    """A zero :class:`LineWork` of ``n`` nodes."""
    z3 = lambda: np.zeros((n, 3))  # noqa: E731
    return LineWork(q=z3(), tens=np.zeros(n - 1), act=np.zeros(n - 1),
                    Mb=np.zeros((n, 3, 3)), Dg=np.zeros((n, 3, 3)), Of=np.zeros((n - 1, 3, 3)),
                    BX=np.zeros((7, n, 3, 3)), R=z3(), W=np.zeros((n, 3, 3)), Y=z3(),
                    T1=np.zeros((3, 3)), dx=z3(), rtry=z3(), rf=np.zeros(3), vf=np.zeros(3),
                    info=np.zeros(3), stats=np.zeros(2),
                    el=np.zeros((n - 1, 4)), audit=np.zeros(N_AU), uc=np.zeros(n),
                    ew=np.zeros((N_EW, n)),
                    energy=np.zeros((2, N_EN)))
