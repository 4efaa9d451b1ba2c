"""FE lines as SIMD lanes: the state of several lines in a structure-of-arrays layout, so that
the kernels of their generalised-alpha advance (:mod:`.lanes_forces`, :mod:`.lanes_step`,
:mod:`.lanes_advance`) run the same arithmetic on :data:`LW` lines at once.

Layout.  The lines of a group (the same node count ``n``) sit in blocks of :data:`LW` lanes;
a block's array of a node quantity with ``K`` components is one row of a 2-D array,
``X[b, (i * K + k) * LW + l]`` for node (or element) ``i``, component ``k`` and lane ``l``:
node index outer, component, lane inner.  The lane width is a constant of the code, so every
offset between two entries of a row is a constant: with the lane kernels compiled with
``noalias`` array arguments (:class:`NoAliasCompiler`), non-negative indices (:func:`ix`), a
lane loop whose trip count is read at run time (:func:`lanes_in`) and no run-time flag tested
inside it (the passes take such flags as constants, or as selects after loads made for every
lane), LLVM vectorises the loops over the lanes of a node (AVX2: 4 doubles per instruction;
``benchmarks/check_lanes_asm.py`` counts the packed instructions of every pass).  Before
2026-11-27 the lane loops were written over the constant :data:`LW` and tested run-time flags,
and the assembly showed them scalar or two nodes per 128-bit register: the lanes then took
0.82-0.90 of the line-by-line time, now 0.44-0.57 (benchmarks/RESULTS.md, "FE lanes
vectorised").  A
block not filled by lines is filled with copies of its first line (dummy lanes: the same
arithmetic as that line, never written back).

Each lane does the arithmetic of the line-by-line kernels, operation for operation, so a
line's results are bit for bit those it would have alone; the control of the iteration (Newton
convergence, step halving, energy audit) is per lane, the lanes of a block advancing in lock
step (a converged lane waits, its state frozen, while the others iterate).

Every array of the bundles is its own allocation (the ``noalias`` contract of the lane
kernels: no two array arguments share memory).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit
from numba.core.compiler import Compiler

from .elements import _slack_strain, _stiff
from .energy import AUDIT_FLOOR
from .fibre_law import EL_LAW
from .layout import (
    EL_C1,
    EL_C2,
    EL_C3,
    KERNEL_JIT,
    N_EL,
    N_FS,
    N_NP,
    N_S,
    NP_KC,
    NP_MASS,
    NP_W,
    S_BEND,
)

__all__ = ["LW", "NoAliasCompiler", "LANE_JIT", "ix", "LaneParams", "LaneState", "LaneWork",
           "LaneGroup", "accepted", "trial", "accepted_rows", "build_group", "N_EC", "EC_E0",
           "EC_A", "EC_B", "EC_STIFF"]

LW = 4
"""Lanes per block: doubles per AVX2 register."""


class NoAliasCompiler(Compiler):
    """numba's compiler with every pointer argument of the compiled function marked
    ``noalias`` (numba's own ``Flags.noalias``, used by its parallel gufuncs): the caller
    promises that no two array arguments share memory, and LLVM may then vectorise loops that
    read some arrays and write others without run-time overlap checks (it gives up beyond a
    handful of them)."""

    def __init__(self, typingctx, targetctx, library, args, return_type, flags, locals):
        flags.noalias = True
        super().__init__(typingctx, targetctx, library, args, return_type, flags, locals)


LANE_JIT = {**KERNEL_JIT, "error_model": "numpy", "pipeline_class": NoAliasCompiler}
"""numba options of the vectorised lane kernels: :data:`~.layout.KERNEL_JIT`, ``noalias`` arguments, and
numpy's error model (a float division by zero gives inf or NaN instead of raising: with
Python's model every division carries a branch to the exception, and the loop does not
vectorise; the lanes compute both sides of a branch and select, so a division by zero on the
side not taken must not raise)."""


@njit(inline="always")
def lanes_in(X, width):
    """:data:`LW`, read at run time from the shape of the block array ``X`` (``X.shape[1] ==
    width * LW``).  The lane passes loop ``for l in range(lanes_in(...))``, not over the
    constant ``LW``: LLVM unrolls a loop of four known trips before its loop vectoriser runs,
    then vectorises the loop over the nodes instead (two nodes per SSE register, with
    shuffles), and numba leaves LLVM's SLP vectoriser, which would pack the unrolled lanes, off
    (``NUMBA_SLP_VECTORIZE``).  With a trip count known only at run time the lane loop stays
    the innermost loop and is vectorised as four lanes per AVX2 register (checked in the
    assembly: ``benchmarks/check_lanes_asm.py``).  The arithmetic of each lane is the same
    either way."""
    return X.shape[1] // width


@njit(inline="always")
def ix(i, k, K, l):
    """Index of component ``k`` (of ``K``) of node or element ``i`` in lane ``l`` of a block
    row, unsigned (numba adds no negative-index wrap-around to an unsigned index: the offsets
    stay affine and the loop vectorises)."""
    return np.uintp((i * K + k) * LW + l)


# element constants (EC columns): slack strain e0, the cubic A eps^2 + B eps^3 below it (the
# values elements._tension computes at every call), 1.0 for a stiff element
EC_E0, EC_A, EC_B, EC_STIFF = range(4)
N_EC = 4
# block flags (LaneParams.flags columns)
BF_FRIC, BF_BEND, BF_MODE, BF_DAMP, BF_STIFF, BF_FIBRE, BF_CLUMP, BF_MAXIT, BF_NLINES, \
    BF_WAVES = range(10)
N_BF = 10
# per-lane floats (LaneWork.lf columns, one row per block): step size, cK, cC, time of the
# sub-step; Newton control (residual norm of the last iterate, backtracking factor, last
# correction, force scales); energy audit (energy, power, budget at the step start, floor)
(LF_DT, LF_CK, LF_CC, LF_T, LF_RES, LF_RESP, LF_ALPHA, LF_DMAX, LF_DPREV, LF_FTOL, LF_FCAP,
 LF_TTOL, LF_FBAR, LF_IMB, LF_EN0, LF_PW0, LF_BUD0, LF_EFLOOR, LF_RMAX) = range(19)
N_LF = 19
# per-lane integers (LaneWork.li columns): Newton status (0 running, 1 converged, 2 converged
# on the residual, < 0 failed, 3 idle), iterations, modified-Newton flags, stiff elements,
# sub-step position and size (units of the smallest sub-step), the step's result; 1 when the
# force stop holds for the current iterate (newton: force, all elements taut)
(LI_ST, LI_IT, LI_FRESH, LI_NSTIFF, LI_POS, LI_SZ, LI_RET, LI_SOLVE, LI_IMAX, LI_SRC,
 LI_FSTOP) = range(11)
N_LI = 11


class LaneParams(NamedTuple):
    """Read-only parameters of a group's lanes (``nb`` blocks of :data:`LW` lanes, ``n``
    nodes; per-lane rows ``nb * LW``)."""

    P: np.ndarray
    """(nb, n N_NP LW) node parameters."""
    E: np.ndarray
    """(nb, (n-1) N_EL LW) element parameters (dynamic law)."""
    EC: np.ndarray
    """(nb, (n-1) N_EC LW) element constants of the axial law (``EC_*``)."""
    SC: np.ndarray
    """(nb, N_S LW) line scalars."""
    S: np.ndarray
    """(nb LW, m) each lane's whole ``S`` (fibre records after the scalars; zero padded)."""
    cur_z: np.ndarray
    """(nb LW, mz) current levels of each lane (zero padded; ``cur_n`` levels)."""
    cur_u: np.ndarray
    """(nb LW, mz) current speeds."""
    cur_n: np.ndarray
    """(nb LW,) int64 current levels of each lane."""
    cur_c: np.ndarray
    """(nb, 4 LW) each lane's current profile ends: lowest and highest level, speed at them
    (``+inf`` levels for a profile of fewer than two levels: then ``cur_u[0]``, or 0 without
    levels)."""
    wk: np.ndarray
    """(nb, n 6 LW) wave particle velocity and acceleration at the nodes."""
    coef: np.ndarray
    """(nb, 4 LW) generalised-alpha coefficients of each lane."""
    tol: np.ndarray
    """(nb, LW) Newton position tolerance of each lane (m)."""
    flags: np.ndarray
    """(nb, N_BF) int64 block flags: friction code, bending, Newton code, internal damping,
    stiff elements, fibre elements, clump drag (any lane), iteration limit, real lines, wave
    kinematics (``wk`` may be non-zero)."""
    weight: np.ndarray
    """(nb, 2 LW) per lane: largest node weight scale (``force_tolerances``' ``ftol`` before
    its round-off floor) and the free nodes' weight in air (N)."""
    wsum: np.ndarray
    """(nb, LW) summed absolute submerged weight of the free nodes (N, the audit floor)."""
    s_nodes: np.ndarray
    """(nb LW, n) unstretched arc length of the nodes."""


class LaneState(NamedTuple):
    """Node states of a group's lanes (``(nb, n K LW)`` rows)."""

    r: np.ndarray
    v: np.ndarray
    a: np.ndarray
    f: np.ndarray
    fs: np.ndarray


class LaneWork(NamedTuple):
    """Scratch and per-call outputs of the lane kernels."""

    q: np.ndarray
    el: np.ndarray
    tens: np.ndarray
    act: np.ndarray
    Tl: np.ndarray
    Dl: np.ndarray
    Mb: np.ndarray
    Dg: np.ndarray
    Of: np.ndarray
    OfK: np.ndarray
    BX: np.ndarray
    R: np.ndarray
    W: np.ndarray
    Y: np.ndarray
    dx: np.ndarray
    xr: np.ndarray
    uc: np.ndarray
    cmemo: np.ndarray
    """(nb, n 4 LW) each node's last current interval (``cur_z[j]``, ``cur_z[j + 1]``,
    ``cur_u[j]``, ``cur_u[j + 1]``; NaN until the first look-up)."""
    cmiss: np.ndarray
    """(nb, LW) nodes of each lane whose current interval changed in the last look-up."""
    carry: np.ndarray
    lf: np.ndarray
    li: np.ndarray
    fair: np.ndarray
    mask: np.ndarray
    bad: np.ndarray
    eo: np.ndarray
    status: np.ndarray
    audit: np.ndarray
    info: np.ndarray
    stats: np.ndarray
    T1: np.ndarray
    tacc: np.ndarray
    etr: np.ndarray
    """(nb, 5 LW) the energy audit's figures of each lane's trial end state: known (1.0),
    energy, power, budget, floor (``LineWork.energy`` of the line kernel)."""
    geo: np.ndarray
    """(nb,) int64: what ``el`` and ``q`` hold for every lane of block ``b`` that is ``on``: 0
    unknown, 1 the trial state's (the last sub-step of an advance in which every such lane
    stepped and accepted), 2 the accepted state's (after :func:`~.lanes_advance.accept` of 1).
    """
    eacc: np.ndarray
    """(nb, 5 LW) the same of the accepted state (copied from ``etr`` on accept): the next
    advance starts from them when every lane of the block has them."""
    """(nb, (n-1) LW) element tensions of each lane's last accepted sub-step (put back into
    ``tens`` at the end of an advance: a lane done early has its ``tens`` overwritten by the
    passes of the lanes still stepping)."""


class LaneGroup(NamedTuple):
    """A group of lines as lanes: parameters, two state buffers, the sub-step state and the
    work arrays.

    The two buffers hold each block's accepted and trial states, and swap roles when the trial
    is accepted (``cur``; :func:`accepted`, :func:`trial`): accepting a block's trial flips its
    ``cur`` instead of copying four arrays (the copies of the accept and of the sub-step result
    into the trial were 7.7 % of the flagship's lanes replay, perf 2026-11-28)."""

    par: LaneParams
    state0: LaneState
    state1: LaneState
    step: LaneState
    work: LaneWork
    cur: np.ndarray
    """(nb,) int64: the buffer (0: ``state0``, 1: ``state1``) that holds block ``b``'s
    accepted state; the other holds its trial state."""


@njit(inline="always")
def accepted(g, b):
    """The state buffer holding the accepted state of block ``b`` of the group ``g``."""
    return g.state1 if g.cur[b] != 0 else g.state0


@njit(inline="always")
def trial(g, b):
    """The state buffer holding the trial state of block ``b`` of the group ``g``."""
    return g.state0 if g.cur[b] != 0 else g.state1


def accepted_rows(grp: LaneGroup, name: str) -> np.ndarray:
    """The field ``name`` (``r``, ``v``, ``a``, ``f``, ``fs``) of every block's accepted state,
    as one (nb, ...) array (a copy; Python side)."""
    a0 = getattr(grp.state0, name)
    a1 = getattr(grp.state1, name)
    return np.where((grp.cur != 0)[:, None], a1, a0)


def _rows(nb, count, k):
    return np.zeros((nb, count * k * LW))


class _BlockView:
    """Lane row ``p`` of a group array ``X`` (nb, count k LW) as a (count, k) view:
    ``_BlockView(X, count, k)[p]``; assignable."""

    def __init__(self, X, count, k):
        self.v = X.reshape(X.shape[0], count, k, LW)

    def __getitem__(self, p):
        return self.v[p // LW, :, :, p % LW]

    def __setitem__(self, p, value):
        self.v[p // LW, :, :, p % LW] = value


def _block_view(X, nb, count, k):
    """``X`` (nb, count k LW) as lane rows (count, k): line arrays to pack / unpack (views,
    no copies)."""
    return _BlockView(X, count, k)


def lane_lines(nl: int) -> list:
    """The line of every lane row of a group of ``nl`` lines (row ``p``: block ``p // LW``,
    lane ``p % LW``): line ``p``, or in the last block's dummy lanes the block's first line."""
    nb = (nl + LW - 1) // LW
    return [p if p < nl else (p // LW) * LW for p in range(nb * LW)]


def build_group(params, states, *, waves: bool = False) -> LaneGroup:
    """A :class:`LaneGroup` of lines (the same node count) with their ``LineParams``
    ``params`` and accepted ``LineState`` s ``states`` (copied in; see :func:`load_states`).
    Lanes beyond the lines repeat the block's first line; ``waves``: the lines' wave kinematics
    ``wk`` are updated between steps (else they stay zero)."""
    nl = len(params)
    if nl == 0:
        raise ValueError("a lane group needs at least one line")
    n = params[0].P.shape[0]
    if any(p.P.shape[0] != n for p in params):
        raise ValueError("the lines of a lane group must have the same node count")
    nb = (nl + LW - 1) // LW
    src = lane_lines(nl)

    def put(rows, arrs, count, k):
        v = _block_view(rows, nb, count, k)
        for p, s in enumerate(src):
            v[p] = np.asarray(arrs[s]).reshape(count, k)
        return rows

    P = put(_rows(nb, n, N_NP), [p.P for p in params], n, N_NP)
    E = put(_rows(nb, n - 1, N_EL), [p.E for p in params], n - 1, N_EL)
    ec = []
    for p in params:
        e = np.zeros((n - 1, N_EC))
        for j in range(n - 1):
            c1, c2, c3 = p.E[j, EL_C1], p.E[j, EL_C2], p.E[j, EL_C3]
            e0 = _slack_strain(p.P, p.E, j)
            # the cubic of elements._tension, the same arithmetic
            T0 = c1 * e0 + c2 * e0 * e0 + c3 * e0 * e0 * e0
            D0 = c1 + 2.0 * c2 * e0 + 3.0 * c3 * e0 * e0
            B = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
            A = (T0 - B * e0 * e0 * e0) / (e0 * e0)
            e[j] = (e0, A, B, 1.0 if _stiff(p.P, p.E, j) else 0.0)
        ec.append(e)
    EC = put(_rows(nb, n - 1, N_EC), ec, n - 1, N_EC)
    SC = put(_rows(nb, 1, N_S), [p.S[:N_S] for p in params], 1, N_S)
    ms = max(p.S.shape[0] for p in params)
    S = np.zeros((nb * LW, ms))
    mz = max(max(p.cur_z.shape[0] for p in params), 1)
    cz = np.zeros((nb * LW, mz))
    cu = np.zeros((nb * LW, mz))
    cn = np.zeros(nb * LW, np.int64)
    s_nodes = np.zeros((nb * LW, n))
    for q, s in enumerate(src):
        p = params[s]
        S[q, :p.S.shape[0]] = p.S
        cn[q] = p.cur_z.shape[0]
        cz[q, :cn[q]] = p.cur_z
        cu[q, :cn[q]] = p.cur_u
        s_nodes[q] = p.s_nodes
    cc = np.zeros((nb, 4 * LW))
    for q, s in enumerate(src):
        p = params[s]
        m = p.cur_z.shape[0]
        ends = ((p.cur_z[0], p.cur_z[m - 1], p.cur_u[0], p.cur_u[m - 1]) if m >= 2 else
                (np.inf, np.inf, p.cur_u[0] if m == 1 else 0.0, 0.0))
        for k in range(4):
            cc[q // LW, k * LW + q % LW] = ends[k]
    wk = put(_rows(nb, n, 6), [p.wk for p in params], n, 6)
    coef = put(_rows(nb, 1, 4), [p.coef for p in params], 1, 4)
    tol = np.array([params[s].tol for s in src]).reshape(nb, LW)
    flags = np.zeros((nb, N_BF), np.int64)
    weight = np.zeros((nb, 2 * LW))
    wsum = np.zeros((nb, LW))
    for b in range(nb):
        ps = [params[s] for s in src[b * LW:(b + 1) * LW]]
        for name, col in (("fric", BF_FRIC), ("newton", BF_MODE), ("maxit", BF_MAXIT)):
            vals = {int(getattr(p, name)) for p in ps}
            if len(vals) != 1:
                raise ValueError(f"the lines of a lane block must share {name}")
            flags[b, col] = vals.pop()
        flags[b, BF_BEND] = int(any(p.S[S_BEND] > 0.0 for p in ps))
        flags[b, BF_DAMP] = int(any(np.any(p.E[:, 4] != 0.0) for p in ps))
        flags[b, BF_STIFF] = int(any(np.any(e[:, EC_STIFF] > 0.0) for e in
                                     [ec[s] for s in src[b * LW:(b + 1) * LW]]))
        flags[b, BF_FIBRE] = int(any(np.any(p.E[:, EL_LAW] != 0.0) for p in ps))
        flags[b, BF_CLUMP] = int(any(np.any(p.P[:, NP_KC] > 0.0) for p in ps))
        flags[b, BF_NLINES] = min(LW, nl - b * LW)
        flags[b, BF_WAVES] = int(waves)
        for l, p in enumerate(ps):
            # force_tolerances: the weight scale before its round-off floor, the weight in air
            ftol = 0.0
            for i in range(n):
                ftol = max(ftol, 1e-5 * abs(p.P[i, NP_W]), 1e-5 * 9.80665 * p.P[i, NP_MASS])
            w_air = 0.0
            for i in range(1, n - 1):
                w_air += 9.80665 * p.P[i, NP_MASS]
            weight[b, l] = ftol
            weight[b, LW + l] = w_air
            ws = 0.0
            for i in range(1, n - 1):
                ws += abs(p.P[i, NP_W])
            wsum[b, l] = ws
    par = LaneParams(P=P, E=E, EC=EC, SC=SC, S=S, cur_z=cz, cur_u=cu, cur_n=cn, cur_c=cc, wk=wk,
                     coef=coef, tol=tol, flags=flags, weight=weight, wsum=wsum,
                     s_nodes=s_nodes)

    def state():
        return LaneState(r=_rows(nb, n, 3), v=_rows(nb, n, 3), a=_rows(nb, n, 3),
                         f=_rows(nb, n, 3), fs=_rows(nb, n, N_FS))

    state0, state1, step = state(), state(), state()
    bend = bool(flags[:, BF_BEND].any())
    work = LaneWork(
        q=_rows(nb, n, 3), el=_rows(nb, n - 1, 4), tens=_rows(nb, n - 1, 1),
        act=_rows(nb, n - 1, 1), Tl=_rows(nb, n - 1, 1), Dl=_rows(nb, n - 1, 1),
        Mb=_rows(nb, n, 9), Dg=_rows(nb, n, 9), Of=_rows(nb, n - 1, 9),
        OfK=_rows(nb, n - 1, 9),
        BX=np.zeros((nb * LW, 7, n, 3, 3)) if bend else np.zeros((1, 7, 1, 3, 3)),
        R=_rows(nb, n, 3), W=_rows(nb, n, 9), Y=_rows(nb, n, 3), dx=_rows(nb, n, 3),
        xr=_rows(nb, n, 3), uc=_rows(nb, n, 1),
        cmemo=np.full((nb, n * 4 * LW), np.nan), cmiss=np.zeros((nb, LW)),
        carry=np.zeros((nb, 16 * LW)),
        lf=np.zeros((nb, N_LF * LW)), li=np.zeros((nb, N_LI * LW), np.int64),
        fair=np.zeros((nb, 16 * LW)), mask=np.zeros((nb, LW), np.int64),
        bad=np.zeros((nb, LW), np.int64), eo=np.zeros((nb, 8 * LW)),
        status=np.zeros(nb * LW, np.int64), audit=np.zeros((nb * LW, 12)),
        info=np.zeros((nb * LW, 3)), stats=np.zeros((nb * LW, 2)),
        T1=np.zeros((nb * LW, 3, 3)), tacc=_rows(nb, n - 1, 1),
        etr=np.zeros((nb, 5 * LW)), geo=np.zeros(nb, np.int64), eacc=np.zeros((nb, 5 * LW)))
    grp = LaneGroup(par=par, state0=state0, state1=state1, step=step, work=work,
                    cur=np.zeros(nb, np.int64))
    load_states(grp, states, src)
    return grp


def load_states(grp: LaneGroup, states, src=None) -> None:
    """Copy the accepted line states ``states`` (``LineState`` s of the group's lines, in its
    line order) into the group's accepted state (``src``: the line of each lane row; default
    the group's own map, dummy lanes repeating their block's first line)."""
    nb = grp.state0.r.shape[0]
    n = grp.state0.r.shape[1] // (3 * LW)
    if src is None:
        src = lane_lines(len(states))
    grp.work.geo[:] = 0
    for name, k in (("r", 3), ("v", 3), ("a", 3), ("f", 3), ("fs", N_FS)):
        views = [_block_view(getattr(s, name), nb, n, k) for s in (grp.state0, grp.state1)]
        for p, s in enumerate(src):
            views[int(grp.cur[p // LW] != 0)][p] = getattr(states[s], name)


def store_states(grp: LaneGroup, states) -> None:
    """Copy the group's accepted state back into the line states ``states`` (the group's line
    order; dummy lanes are not written)."""
    nb = grp.state0.r.shape[0]
    n = grp.state0.r.shape[1] // (3 * LW)
    for name, k in (("r", 3), ("v", 3), ("a", 3), ("f", 3), ("fs", N_FS)):
        views = [_block_view(getattr(s, name), nb, n, k) for s in (grp.state0, grp.state1)]
        for p in range(len(states)):
            getattr(states[p], name)[:] = views[int(grp.cur[p // LW] != 0)][p]


def audit_floor(wsum: float) -> float:
    """The energy audit's floor for a line of summed submerged weight ``wsum`` (N)."""
    return AUDIT_FLOOR * wsum
