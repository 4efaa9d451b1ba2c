"""The FE lines of a body advanced as SIMD lanes (:mod:`.lanes`) in the coupled run: the mode
bundle :class:`LaneLines` of :func:`.multi.advance_lines` and its kernel
:func:`lanes_advance_lines`, which does what :func:`.multi.body_advance`,
:func:`.multi.body_accept` and :func:`.multi.record_lines` do for lines one by one, with the
same numbers (every lane is bit for bit its line alone: tests/mooring/fe/test_lanes.py).

The lanes hold their own copy of the lines' states (a :class:`~.lanes.LaneGroup`); the line
bundles keep the started state until :func:`store_lines` copies the lanes' accepted states,
audits and element tensions back after the run (``fe_coupling.run``), so every
:class:`~.line.FELine` method sees the state the run ended in.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ...core.frames import rotation_matrix_into
from .lanes import LW, LaneGroup, build_group, store_states
from .lanes_advance import accept, block_advance, record
from .multi import add_line_wrench, fairlead_into

__all__ = ["LaneLines", "lanes_mode", "lanes_advance_lines", "store_lines", "lanes_fit"]


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


def lanes_fit(lines) -> bool:
    """True when the lines can be lanes of one group: the same node count, and in every block
    the same friction code, Newton iteration and iteration limit (:func:`~.lanes.build_group`),
    and the generalised-alpha integrator."""
    if not lines:
        return False
    n = lines[0].n_nodes
    if any(ln.n_nodes != n or ln.integrator != "generalized_alpha" for ln in lines):
        return False
    pars = [ln.bundle.par for ln in lines]
    for b in range(0, len(pars), LW):
        blk = pars[b:b + LW]
        for name in ("fric", "newton", "maxit"):
            if len({int(getattr(p, name)) for p in blk}) != 1:
                return False
    return True


def lanes_mode(lines, recs: np.ndarray) -> LaneLines:
    """The :class:`LaneLines` of started lines ``lines`` (:class:`~.line.FELine`, accepted
    states copied into the lanes)."""
    bl = [ln.bundle for ln in lines]
    g = build_group([b.par for b in bl], [b.now for b in bl])
    on = np.zeros(g.now.r.shape[0] * LW, np.bool_)
    on[:len(lines)] = True
    return LaneLines(status=np.zeros(max(len(lines), 1), np.int64), threads=1, recs=recs,
                     group=g, on=on)


@njit(cache=True)  # with reference counting: it reads the typed list of the line bundles
def lanes_advance_lines(mode, t1, dt, nsub, max_split, pose, vel, body, lines):
    """Advance the lanes of ``mode`` (:class:`LaneLines`) to ``t1`` with the body at ``pose``
    moving with ``vel``, and on success accept them and record their channels into
    ``mode.recs``: :func:`.multi.body_advance` (``body`` the :class:`~.multi.FEBody`: fairleads,
    end forces, wrench ``Q``, counters), :func:`.multi.body_accept` and
    :func:`.multi.record_lines` with the lines as lanes.  A failing lane returns its status
    with ``body.fail[0]`` the line and its ``work.info`` (time, node, code) copied into the
    line's bundle (``lines``, the typed list of the lines' bundles)."""
    g = mode.group
    on_l = mode.on
    w = g.work
    fair_b, R, rf_all, vf_all, arm, Q, forces, on, fail, counters = body
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    for k in range(6):
        Q[k] = 0.0
    nl = fair_b.shape[0]
    nb = g.now.r.shape[0]
    n = g.now.r.shape[1] // (3 * LW)
    for i in range(nl):
        fairlead_into(i, pose, vel, R, fair_b, arm, rf_all, vf_all)
        on_l[i] = on[i]
    for p in range(nb * LW):
        i = p if p < nl else (p // LW) * LW
        b = p // LW
        lane = p % LW
        for c in range(3):
            w.fair[b, (9 + c) * LW + lane] = rf_all[i, c]
            w.fair[b, (12 + c) * LW + lane] = vf_all[i, c]
        w.stats[p, 0] = 0.0
        w.stats[p, 1] = 0.0
    for b in range(nb):
        block_advance(b, n, t1, dt, nsub, max_split, g, on_l)
    for i in range(nl):
        if not on[i]:
            for c in range(3):
                forces[i, c] = 0.0
            continue
        counters[i, 0] += w.stats[i, 0]
        counters[i, 1] += w.stats[i, 1]
        st = w.status[i]
        if st < 0:
            fail[0] = i
            info = lines[i].work.info
            for k in range(3):
                info[k] = w.info[i, k]
            return st
        b = i // LW
        lane = i % LW
        for c in range(3):
            forces[i, c] = g.trial.f[b, ((n - 1) * 3 + c) * LW + lane]
        add_line_wrench(i, arm, forces, Q)
    for b in range(nb):
        accept(b, n, g, on_l)
    for i in range(nl):
        if on[i]:
            record(g, i, n, mode.recs[i])
    return 0


def store_lines(mode: LaneLines, lines) -> None:
    """Copy the lanes' accepted states, energy audits and element tensions into the lines
    (:class:`~.line.FELine`), after a run."""
    g = mode.group
    store_states(g, [ln.bundle.now for ln in lines])
    n = lines[0].n_nodes
    tens = g.work.tens.reshape(g.now.r.shape[0], n - 1, LW)
    for p, ln in enumerate(lines):
        ln.work.audit[:] = g.work.audit[p]
        ln.work.info[:] = g.work.info[p]
        ln.work.tens[:] = tens[p // LW, :, p % LW]
        # the energy stored for the line's own kernel is not the lanes' state's
        ln.work.energy[:] = 0.0
