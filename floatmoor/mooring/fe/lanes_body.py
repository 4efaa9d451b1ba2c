"""The FE lines of a body advanced as SIMD lanes (:mod:`.lanes`) in the coupled run: the mode
bundle :class:`LaneLines` of :func:`.multi.advance_lines` and its kernel
:func:`lanes_body_step`, which does what :func:`.multi.body_advance`,
:func:`.multi.body_accept` and :func:`.multi.record_lines` do for lines one by one, with the
same numbers (every lane is bit for bit its line alone: tests/mooring/fe/test_lanes.py).

The lanes hold their own copy of the lines' states (a :class:`~.lanes.LaneGroup`); the line
bundles keep the started state until :func:`store_lines` copies the lanes' accepted states,
audits, element tensions and failure information back after the run
(``fe_coupling.run``), so every :class:`~.line.FELine` method sees the state the run ended in.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ...core.frames import rotation_matrix_into
from .lanes import LW, LaneGroup, build_group, store_states, trial
from .lanes_advance import accept, block_advance, record
from .layout import KERNEL_JIT
from .multi import add_line_wrench, fairlead_into

__all__ = ["LaneLines", "lane_order", "lanes_mode", "lanes_body_step", "store_lines", "lanes_fit"]


class LaneLines(NamedTuple):
    """Mode bundle of :func:`.multi.advance_lines`: the lines as lanes of one group."""

    status: np.ndarray
    """(n,) int64 (unused: the field of the other modes)."""
    threads: int
    """1."""
    recs: np.ndarray
    """(n, REC_STRIDE) the output channels of each line's accepted state (out)."""
    group: LaneGroup
    """The lanes (their own copy of the lines' states)."""
    on: np.ndarray
    """(nb LW,) bool: lanes advanced (the intact lines; dummy lanes off)."""
    slot: np.ndarray
    """(n,) int64: the lane row of each line (:func:`lane_order`)."""
    line_of: np.ndarray
    """(nb LW,) int64: the line in each lane row (a dummy lane: the first line of its
    block)."""


def lane_order(lines) -> list[int]:
    """The lines (started :class:`~.line.FELine`) in the order they fill the lanes: by
    friction code, Newton iteration and iteration limit (what a block must share), then by the
    fairlead tension of the started state.  A block advances in lock step until its slowest
    lane has converged, so lines that iterate alike should share it: lines of equal tension
    (the mirror images of a symmetric mooring in a storm along its axis) iterate the same
    numbers of times step by step.  On the flagship's storm track the blocks then iterate 1.085
    times the mean of their lines, against 1.194 in line order (1.083 for the best of the 5775
    partitions into three blocks; benchmarks/RESULTS.md).  Each lane's numbers do not depend on
    its block (every lane is its line alone, bit for bit), and the lines' forces are still
    summed in line order."""
    def key(k):
        ln = lines[k]
        par = ln.bundle.par
        t = float(np.linalg.norm(ln.bundle.now.f[-1]))
        return (int(par.fric), int(par.newton), int(par.maxit), t if np.isfinite(t) else 0.0, k)
    return sorted(range(len(lines)), key=key)


def lanes_fit(lines) -> bool:
    """True when the lines can be lanes of one group: the same node count, and in every block
    of the :func:`lane_order` the same friction code, Newton iteration and iteration limit
    (:func:`~.lanes.build_group`), and the generalised-alpha integrator."""
    if not lines:
        return False
    n = lines[0].n_nodes
    if any(ln.n_nodes != n or ln.integrator != "generalized_alpha" for ln in lines):
        return False
    pars = [lines[k].bundle.par for k in lane_order(lines)]
    for b in range(0, len(pars), LW):
        blk = pars[b:b + LW]
        for name in ("fric", "newton", "maxit"):
            if len({int(getattr(p, name)) for p in blk}) != 1:
                return False
    return True


def lanes_mode(lines, recs: np.ndarray) -> LaneLines:
    """The :class:`LaneLines` of started lines ``lines`` (:class:`~.line.FELine`, accepted
    states copied into the lanes, in the :func:`lane_order`)."""
    order = lane_order(lines)
    bl = [lines[k].bundle for k in order]
    g = build_group([b.par for b in bl], [b.now for b in bl])
    nrows = g.state0.r.shape[0] * LW
    on = np.zeros(nrows, np.bool_)
    on[:len(lines)] = True
    slot = np.zeros(max(len(lines), 1), np.int64)
    line_of = np.zeros(nrows, np.int64)
    for p, k in enumerate(order):
        slot[k] = p
    for p in range(nrows):
        line_of[p] = order[p] if p < len(order) else order[(p // LW) * LW]
    return LaneLines(status=np.zeros(max(len(lines), 1), np.int64), threads=1, recs=recs,
                     group=g, on=on, slot=slot, line_of=line_of)


@njit(**KERNEL_JIT)
def lanes_body_step(mode, t1, dt, nsub, max_split, pose, vel, body):
    """Advance the lanes of ``mode`` (:class:`LaneLines`) to ``t1`` with the body at ``pose``
    moving with ``vel``, and on success accept them and record their channels into
    ``mode.recs``: :func:`.multi.body_advance` (``body`` the :class:`~.multi.FEBody`: fairleads,
    end forces, wrench ``Q``, counters), :func:`.multi.body_accept` and
    :func:`.multi.record_lines` with the lines as lanes.  Returns the status (0, or a failing
    lane's, with ``body.fail[0]`` its line; the lane's ``work.info`` reaches the line through
    :func:`store_lines`).  No typed list, so no reference counting (numba's atomic counts on
    every field of the group it reads were 3 % of the coupled flagship, perf 2026-11-28)."""
    g = mode.group
    on_l = mode.on
    slot = mode.slot
    line_of = mode.line_of
    w = g.work
    fair_b, R, rf_all, vf_all, arm, Q, forces, on, fail, counters = body
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    for k in range(6):
        Q[k] = 0.0
    nl = fair_b.shape[0]
    nb = g.state0.r.shape[0]
    n = g.state0.r.shape[1] // (3 * LW)
    for i in range(nl):
        fairlead_into(i, pose, vel, R, fair_b, arm, rf_all, vf_all)
        on_l[slot[i]] = on[i]
    for p in range(nb * LW):
        i = line_of[p]
        b = p // LW
        lane = p % LW
        for c in range(3):
            w.fair[b, (9 + c) * LW + lane] = rf_all[i, c]
            w.fair[b, (12 + c) * LW + lane] = vf_all[i, c]
        w.stats[p, 0] = 0.0
        w.stats[p, 1] = 0.0
    for b in range(nb):
        block_advance(b, n, t1, dt, nsub, max_split, g, on_l)
    # the lines in line order (their wrenches summed as line by line)
    for i in range(nl):
        if not on[i]:
            for c in range(3):
                forces[i, c] = 0.0
            continue
        p = slot[i]
        counters[i, 0] += w.stats[p, 0]
        counters[i, 1] += w.stats[p, 1]
        st = w.status[p]
        if st < 0:
            fail[0] = i
            return st
        b = p // LW
        lane = p % LW
        for c in range(3):
            forces[i, c] = trial(g, b).f[b, ((n - 1) * 3 + c) * LW + lane]
        add_line_wrench(i, arm, forces, Q)
    for b in range(nb):
        accept(b, n, g, on_l)
    for i in range(nl):
        if on[i]:
            record(g, slot[i], n, mode.recs[i])
    return 0


def store_lines(mode: LaneLines, lines) -> None:
    """Copy the lanes' accepted states, energy audits and element tensions into the lines
    (:class:`~.line.FELine`), after a run."""
    g = mode.group
    order = [int(mode.line_of[p]) for p in range(len(lines))]
    store_states(g, [lines[k].bundle.now for k in order])
    n = lines[0].n_nodes
    tens = g.work.tens.reshape(g.state0.r.shape[0], n - 1, LW)
    for k, ln in enumerate(lines):
        p = int(mode.slot[k])
        ln.work.audit[:] = g.work.audit[p]
        ln.work.info[:] = g.work.info[p]
        ln.work.tens[:] = tens[p // LW, :, p % LW]
        # the energy stored for the line's own kernel is not the lanes' state's
        ln.work.energy[:] = 0.0
