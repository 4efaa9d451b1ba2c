"""All FE lines of one body in one numba call per body step (:class:`FEMooring` fast path).

The fairlead kinematics, the generalised-alpha advance of every line (:func:`kernels.ga_advance`,
unchanged), the end forces and their generalised force on the body are one call
(:func:`body_advance`), and :func:`body_accept` commits every line.  The lines are a numba
typed list of their :class:`~.bundles.LineBundle` (the bundles hold the lines' own arrays: no
copies), so every :class:`FELine` stays valid for its other methods; the body side is one
:class:`FEBody`.

Threads (``solver: {threads: N}``): :func:`body_advance_parallel` advances the lines of a
body in ``numba.prange`` (a ``parallel=True`` kernel), each line on one thread with its own
bundles (every array a line's advance writes is its own: state, work arrays, counters of the
advance in ``work.stats``; the typed list is only read), and then sums the wrench, the counters
and the failure report in the serial line order: its results are bit for bit those of
:func:`body_advance` for any thread count.  :func:`advance_lines` chooses the kernel on the
type of its ``mode`` bundle (:class:`SerialLines` or :class:`ParallelLines`), so a serial run
neither contains nor compiles the parallel kernel.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit, prange
from numba.extending import overload
from numba.typed import List

from ...core.frames import rotation_matrix_into
from .kernels import S_ZC, accept_trial, ga_advance, record_into

__all__ = ["FEBody", "new_body", "line_list", "body_advance", "body_accept", "add_line_wrench",
           "SerialLines", "ParallelLines", "lines_mode", "advance_lines",
           "body_advance_parallel", "record_lines", "REC_STRIDE"]

REC_STRIDE = 16
"""Columns of a row of the mode bundles' ``recs``: the 13 channels of
:func:`~.kernels.record_into`, padded to two 64-byte cache lines so that two threads writing
neighbouring rows do not share a cache line."""


class FEBody(NamedTuple):
    """The body side of the FE lines of one body (``n`` lines; arrays written by
    :func:`body_advance` marked "out")."""

    fair_b: np.ndarray
    """(n, 3) fairleads in body axes relative to the reference point (m)."""
    R: np.ndarray
    """(3, 3) rotation matrix of the pose (out)."""
    rf: np.ndarray
    """(n, 3) fairlead positions, earth axes (m, out)."""
    vf: np.ndarray
    """(n, 3) fairlead velocities (m/s, out)."""
    arm: np.ndarray
    """(n, 3) lever arms of the fairleads about the displaced reference point (m, out)."""
    Q: np.ndarray
    """(6,) generalised force of the lines on the body (N, N m, earth axes, out)."""
    forces: np.ndarray
    """(n, 3) force of each line on its fairlead (N, out)."""
    on: np.ndarray
    """(n,) bool: False for a released (failed, ALS) line."""
    fail: np.ndarray
    """(1,) int64: the failing line (out)."""
    counters: np.ndarray
    """(n, 2) Newton iterations and step halvings since the start."""


def new_body(fairleads_body) -> FEBody:
    """An :class:`FEBody` for the fairleads ``fairleads_body`` (n, 3): all lines on, zero
    outputs and counters."""
    fb = np.ascontiguousarray(fairleads_body, dtype=np.float64)
    n = fb.shape[0]
    return FEBody(fair_b=fb, R=np.zeros((3, 3)), rf=np.zeros((n, 3)), vf=np.zeros((n, 3)),
                  arm=np.zeros((n, 3)), Q=np.zeros(6), forces=np.zeros((n, 3)),
                  on=np.ones(n, dtype=np.bool_), fail=np.zeros(1, dtype=np.int64),
                  counters=np.zeros((n, 2)))


@njit(cache=True)
def _list_of(item):
    """A typed list holding ``item`` (built in compiled code, so cached: see line_list)."""
    lst = List()
    lst.append(item)
    return lst


@njit(cache=True)
def _list_append(lst, item):
    lst.append(item)


def line_list(lines):
    """Numba typed list of the :attr:`FELine.bundle` of started ``lines`` (references).

    Built by two cached kernels: ``List()`` and ``append`` called from Python compile numba's
    own list helpers, which numba does not cache, again in every process (0.5-1.2 s before
    each process's first coupled FE storm, benchmarks/RESULTS.md)."""
    lines = list(lines)
    if not lines:
        return List()
    lst = _list_of(lines[0].bundle)
    for ln in lines[1:]:
        _list_append(lst, ln.bundle)
    return lst


@njit(cache=True)
def body_advance(t1, dt, nsub, max_split, pose, vel, body, lines):
    """Trial advance of every line of a body to ``t1`` with the body at ``pose`` moving with
    ``vel`` (angular velocity in earth axes, rad/s); ``lines`` the typed list of the lines'
    :class:`~.bundles.LineBundle`, ``body`` their :class:`FEBody`.

    Writes the fairlead positions / velocities ``body.rf, body.vf``, the lever arms
    ``body.arm``, the force of each line on its fairlead ``body.forces`` and the generalised
    force ``body.Q`` (N, N m about the displaced reference point, earth axes);
    ``body.counters`` += Newton iterations and step halvings.  Lines with ``body.on[i]`` False
    are released (failed, ALS): not advanced (their state stays as it was), zero force, no
    contribution to ``Q``.  Returns 0, or the failing status of :func:`kernels.ga_advance`
    with ``body.fail[0]`` the line index (its ``work.info`` holds the time and the node).
    """
    fair_b, R, rf_all, vf_all, arm, Q, forces, on, fail, counters = body
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    for k in range(6):
        Q[k] = 0.0
    nl = fair_b.shape[0]
    for i in range(nl):
        fairlead_into(i, pose, vel, R, fair_b, arm, rf_all, vf_all)
        if not on[i]:
            for c in range(3):
                forces[i, c] = 0.0
            continue
        ln = lines[i]
        st_i = ln.work.stats
        st_i[0] = 0.0
        st_i[1] = 0.0
        st = ga_advance(t1, dt, nsub, max_split, rf_all[i], vf_all[i], ln.now, ln.trial,
                        ln.step, ln.par, ln.work)
        counters[i, 0] += st_i[0]
        counters[i, 1] += st_i[1]
        if st < 0:
            fail[0] = i
            return st
        f = ln.trial.f
        n = f.shape[0]
        for c in range(3):
            forces[i, c] = f[n - 1, c]
        add_line_wrench(i, arm, forces, Q)
    return 0


@njit(cache=True)
def fairlead_into(i, pose, vel, R, fair_b, arm, rf, vf):
    """Lever arm ``arm[i]`` (rotation ``R`` of the body-axes fairlead ``fair_b[i]``), position
    ``rf[i]`` and velocity ``vf[i]`` of fairlead ``i`` for the body at ``pose`` moving with
    ``vel`` (angular velocity in earth axes)."""
    for c in range(3):
        arm[i, c] = R[c, 0] * fair_b[i, 0] + R[c, 1] * fair_b[i, 1] + R[c, 2] * fair_b[i, 2]
    rf[i, 0] = pose[0] + arm[i, 0]
    rf[i, 1] = pose[1] + arm[i, 1]
    rf[i, 2] = pose[2] + arm[i, 2]
    vf[i, 0] = vel[0] + vel[4] * arm[i, 2] - vel[5] * arm[i, 1]
    vf[i, 1] = vel[1] + vel[5] * arm[i, 0] - vel[3] * arm[i, 2]
    vf[i, 2] = vel[2] + vel[3] * arm[i, 1] - vel[4] * arm[i, 0]


@njit(cache=True)
def add_line_wrench(i, arm, forces, Q):
    """``Q`` (6,) += the force of line ``i`` on its fairlead ``forces[i]`` (N, earth axes) and
    its moment ``arm[i] x forces[i]`` about the displaced reference point (N m)."""
    for c in range(3):
        Q[c] += forces[i, c]
    Q[3] += arm[i, 1] * forces[i, 2] - arm[i, 2] * forces[i, 1]
    Q[4] += arm[i, 2] * forces[i, 0] - arm[i, 0] * forces[i, 2]
    Q[5] += arm[i, 0] * forces[i, 1] - arm[i, 1] * forces[i, 0]


@njit(cache=True)
def body_accept(on, lines):
    """Commit the trial state of every line with ``on[i]`` (the copies of
    :meth:`FELine.accept`); released lines keep their state."""
    for i in range(len(lines)):
        if on[i]:
            accept_trial(lines[i])


@njit(cache=True, inline="always")
def _record_line(ln, out):
    """The output channels of a line's accepted state into ``out`` (13 or more,
    :func:`~.kernels.record_into`; the element tensions are those of the last force
    evaluation, the accepted state's)."""
    record_into(ln.now.r, ln.now.f, ln.work.tens, ln.par.S[S_ZC], ln.par.s_nodes, out)


@njit(cache=True)
def record_lines(on, lines, recs):
    """``recs[i]`` the output channels of the accepted state of every line with ``on[i]``
    (:func:`~.kernels.record_into`): the record of the start state, before the first
    :func:`advance_lines`, which then writes them for every step."""
    for i in range(len(lines)):
        if on[i]:
            _record_line(lines[i], recs[i])


# -- threads ----------------------------------------------------------------------------------
class SerialLines(NamedTuple):
    """Mode bundle of :func:`advance_lines`: the lines one after the other
    (:func:`body_advance`)."""

    status: np.ndarray
    """(n,) int64 (unused here: the fields of :class:`ParallelLines`)."""
    threads: int
    """1."""
    recs: np.ndarray
    """(n, :data:`REC_STRIDE`) the output channels of each line's accepted state
    (:func:`~.kernels.record_into`, first 13 columns; out, written at every accept)."""


class ParallelLines(NamedTuple):
    """Mode bundle of :func:`advance_lines`: the lines in threads
    (:func:`body_advance_parallel`)."""

    status: np.ndarray
    """(n,) int64 status of each line's last advance (out)."""
    threads: int
    """Threads (numba's thread count must be set to it around the kernel call)."""
    recs: np.ndarray
    """(n, :data:`REC_STRIDE`) the output channels of each line's accepted state, written by
    the thread that accepted it (out; as :class:`SerialLines`)."""


def lines_mode(n_lines: int, threads: int):
    """The mode bundle for ``n_lines`` lines advanced with ``threads`` threads: serial for one
    thread (or one line), parallel otherwise."""
    status = np.zeros(max(int(n_lines), 1), np.int64)
    recs = np.zeros((max(int(n_lines), 1), REC_STRIDE))
    nt = min(int(threads), int(n_lines))
    if nt > 1:
        return ParallelLines(status=status, threads=nt, recs=recs)
    return SerialLines(status=status, threads=1, recs=recs)


@njit(cache=True)
def _advance_accept_line(t1, dt, nsub, max_split, rf_all, vf_all, lines, i, recs):
    """Line ``i``'s part of :func:`body_advance_parallel`: its trial advance
    (:func:`~.kernels.ga_advance` with the fairlead ``rf_all[i]``, ``vf_all[i]``, counters in
    the line's ``work.stats``), and when it succeeds its accept and the output channels of the
    accepted state into ``recs[i]``.  Returns the advance's status.  (The line goes by its
    index: the line's bundle of ~50 arrays as an argument cost more than the call.)

    A separate (not inlined) function on purpose: with the advance and the accept inlined into
    the ``prange`` body, the parallel kernel compiled in a process that had not compiled the
    serial one first lost the accepts (the lines never moved: a 60 s coupled run with two
    threads gave a maximum tension of 1666 kN against 2809 kN; reproduced from an empty cache,
    and ``tests/solvers/test_fe_threads.py`` checks it in a new process).  numba's parfor
    passes now see only this call."""
    ln = lines[i]
    st_i = ln.work.stats
    st_i[0] = 0.0
    st_i[1] = 0.0
    st = ga_advance(t1, dt, nsub, max_split, rf_all[i], vf_all[i], ln.now, ln.trial, ln.step,
                    ln.par, ln.work)
    if st >= 0:
        accept_trial(ln)
        _record_line(ln, recs[i])
    return st


@njit(cache=True, parallel=True)
def body_advance_parallel(t1, dt, nsub, max_split, pose, vel, body, lines, status, threads,
                          recs):
    """:func:`body_advance` with the lines advanced in threads: ``numba.prange`` over
    ``threads`` slots, slot ``k`` advancing lines ``k, k + threads, ...`` (run it with numba's
    thread count ``threads``); ``status`` (n,) int64 scratch, each line's advance status.

    Bit for bit the results of :func:`body_advance` for any number of threads: each line's
    advance touches only that line's bundles (the typed list is only read), and the end
    forces, the wrench ``body.Q``, the counters and the failure report are done after the
    threads, in the line order.  When several lines fail, the lowest index is reported (the
    serial loop stops there); the lines after it were advanced too (their trial states, scratch
    until accepted, differ from a serial run's; the counters, forces and ``Q`` do not).  Each
    thread accepts every line it advanced without failure (the trial state copied into the
    accepted one, as :func:`body_accept`), so after a failure other lines may have been
    accepted: the coupled run stops there anyway.  The same thread writes the output channels
    of the accepted state into ``recs[i]`` (:func:`record_lines`): the main thread then reads
    13 numbers of a line instead of its node arrays (reading those moved half of every line's
    state between the cores at every step)."""
    fair_b, R, rf_all, vf_all, arm, Q, forces, on, fail, counters = body
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    for k in range(6):
        Q[k] = 0.0
    nl = fair_b.shape[0]
    for i in range(nl):
        fairlead_into(i, pose, vel, R, fair_b, arm, rf_all, vf_all)
    # one prange iteration per thread, lines interleaved (thread k: lines k, k + nt, ...): the
    # lines of a mooring come in clusters (corners, windward and leeward), each thread gets
    # some of every cluster
    nt = max(1, min(threads, nl))
    for k in prange(nt):
        for i in range(np.int64(k), nl, nt):
            status[i] = 0
            if on[i]:
                status[i] = _advance_accept_line(t1, dt, nsub, max_split, rf_all, vf_all, lines,
                                                 i, recs)
    for i in range(nl):
        if not on[i]:
            for c in range(3):
                forces[i, c] = 0.0
            continue
        ln = lines[i]
        st_i = ln.work.stats
        counters[i, 0] += st_i[0]
        counters[i, 1] += st_i[1]
        if status[i] < 0:
            fail[0] = i
            return status[i]
        f = ln.trial.f
        n = f.shape[0]
        for c in range(3):
            forces[i, c] = f[n - 1, c]
        add_line_wrench(i, arm, forces, Q)
    return 0


def advance_lines(mode, t1, dt, nsub, max_split, pose, vel, body, lines):
    """Advance and accept the lines of a body and record their accepted states into
    ``mode.recs``: :func:`body_advance`, :func:`body_accept` and :func:`record_lines`
    (``mode`` a :class:`SerialLines`), or :func:`body_advance_parallel`, whose threads accept
    the lines they advance (a :class:`ParallelLines`: a line's state stays in the cache of the
    core that advances it; accepting all lines on the main thread made two threads slower than
    one).  A failing advance returns its status with the lines not (all) accepted.  Compiled, the choice is made on
    the type of ``mode`` (:func:`_advance_lines_typed`): a kernel compiled for serial lines
    neither contains nor compiles the parallel one."""
    from .lanes_body import LaneLines, lanes_body_step
    if isinstance(mode, LaneLines):
        # the lanes hold the lines' states: ``lines`` is not read (a failing lane's
        # information reaches its line through store_lines after the run)
        return lanes_body_step(mode, t1, dt, nsub, max_split, pose, vel, body)
    if isinstance(mode, ParallelLines):
        return body_advance_parallel(t1, dt, nsub, max_split, pose, vel, body, lines,
                                     mode.status, mode.threads, mode.recs)
    st = body_advance(t1, dt, nsub, max_split, pose, vel, body, lines)
    if st >= 0:
        body_accept(body.on, lines)
        record_lines(body.on, lines, mode.recs)
    return st


@overload(advance_lines)
def _advance_lines_typed(mode, t1, dt, nsub, max_split, pose, vel, body, lines):
    from .lanes_body import LaneLines, lanes_body_step
    if getattr(mode, "instance_class", None) is LaneLines:
        def lanes(mode, t1, dt, nsub, max_split, pose, vel, body, lines):
            return lanes_body_step(mode, t1, dt, nsub, max_split, pose, vel, body)
        return lanes
    if getattr(mode, "instance_class", None) is ParallelLines:
        def parallel(mode, t1, dt, nsub, max_split, pose, vel, body, lines):
            return body_advance_parallel(t1, dt, nsub, max_split, pose, vel, body, lines,
                                         mode.status, mode.threads, mode.recs)
        return parallel

    def serial(mode, t1, dt, nsub, max_split, pose, vel, body, lines):
        st = body_advance(t1, dt, nsub, max_split, pose, vel, body, lines)
        if st >= 0:
            body_accept(body.on, lines)
            record_lines(body.on, lines, mode.recs)
        return st
    return serial
