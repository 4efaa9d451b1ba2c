"""Decoupled FE line runs: fairlead motion prescribed as a harmonic or a time series (for
example the fairlead track of a previous floater run, Wang (2016) chapter 8 workflow), results as
an xarray Dataset with units, and the dynamic amplification factor

    DAF = (T_max - T_mean)_FE / (T_max - T_mean)_QS            (Wang 2016, eq. 8.1)

with the quasi-static tension from the elastic catenary for the same fairlead track.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import xarray as xr
from numba import njit

from ...core.frames import rotation_matrix_into
from ..catenary import solve_line
from . import kernels as K
from .layout import KERNEL_JIT
from .line import FELine

__all__ = ["HarmonicMotion", "TimeSeriesMotion", "fairlead_track_from_body", "run_prescribed",
           "quasi_static_tension", "daf", "decoupled_analysis", "forced_oscillation_impedance"]


@dataclass(frozen=True, kw_only=True)
class HarmonicMotion:
    """Fairlead displacement ``amplitude * sin(2 pi t / period + phase)`` (m, earth axes) about
    its static position, ramped in over ``ramp`` s with ``(1 - cos)`` / 2."""

    amplitude: tuple
    period: float
    phase: float = 0.0
    ramp: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "_A", np.asarray(self.amplitude, float))

    def __call__(self, t):
        A = self._A
        w = 2.0 * math.pi / self.period
        s = math.sin(w * t + self.phase)
        c = math.cos(w * t + self.phase)
        if self.ramp > 0.0 and t < self.ramp:
            g = 0.5 * (1.0 - math.cos(math.pi * t / self.ramp))
            gd = 0.5 * math.pi / self.ramp * math.sin(math.pi * t / self.ramp)
        else:
            g, gd = 1.0, 0.0
        return A * s * g, A * (w * c * g + s * gd)


@dataclass(frozen=True, kw_only=True)
class TimeSeriesMotion:
    """Fairlead displacement from a time series ``t`` (s), ``xyz`` (nt, 3) m about the static
    position, linear in between; the velocity is the slope of the interval."""

    t: np.ndarray
    xyz: np.ndarray

    def __call__(self, t):
        tt = np.asarray(self.t, float)
        X = np.asarray(self.xyz, float)
        j = int(np.clip(np.searchsorted(tt, t) - 1, 0, tt.size - 2))
        w = (t - tt[j]) / (tt[j + 1] - tt[j])
        w = min(max(w, 0.0), 1.0)
        pos = (1.0 - w) * X[j] + w * X[j + 1]
        vel = (X[j + 1] - X[j]) / (tt[j + 1] - tt[j])
        return pos, vel

    def track(self, times):
        """:meth:`__call__` at every time of the array ``times`` in one go: displacements and
        velocities (len(times), 3), element by element the same arithmetic (the same numbers
        as one call per time; :func:`run_prescribed` takes this instead of a Python call per
        step)."""
        tt = np.asarray(self.t, float)
        X = np.asarray(self.xyz, float)
        t = np.asarray(times, float)
        j = np.clip(np.searchsorted(tt, t) - 1, 0, tt.size - 2)
        h = tt[j + 1] - tt[j]
        w = np.minimum(np.maximum((t - tt[j]) / h, 0.0), 1.0)[:, None]
        pos = (1.0 - w) * X[j] + w * X[j + 1]
        vel = (X[j + 1] - X[j]) / h[:, None]
        return pos, vel


def fairlead_track_from_body(t, poses, fairlead_body, reference_pose=None) -> TimeSeriesMotion:
    """Fairlead displacement history from body poses of a floater run.

    Parameters
    ----------
    t : (nt,) s
    poses : (nt, 6) body poses ``[x, y, z, roll, pitch, yaw]`` (m, rad)
    fairlead_body : (3,) fairlead in body axes, m
    reference_pose : (6,), optional
        Pose at which the line's static fairlead position was given (default the first pose).
    """
    poses = np.asarray(poses, float)
    rb = np.asarray(fairlead_body, float)
    R = np.empty((3, 3))
    pos = np.empty((poses.shape[0], 3))
    for k, p in enumerate(poses):
        rotation_matrix_into(p[3], p[4], p[5], R)
        pos[k] = p[:3] + R @ rb
    p0 = poses[0] if reference_pose is None else np.asarray(reference_pose, float)
    rotation_matrix_into(p0[3], p0[4], p0[5], R)
    ref = p0[:3] + R @ rb
    return TimeSeriesMotion(t=np.asarray(t, float), xyz=pos - ref)


def run_prescribed(line: FELine, motion, t_end: float, dt: float, *, substeps: int = 1,
                   snapshot_times=(), record_every: int = 1, track_nodes=(),
                   progress=None, stats: dict | None = None) -> xr.Dataset:
    """Run a FE line with the fairlead following ``motion`` (a callable ``t -> (disp, vel)``,
    displacement about the static fairlead position, m and m/s).

    The line must be in static equilibrium and started (:meth:`FELine.solve_static`,
    :meth:`FELine.start`).  Returns a Dataset over ``time`` with ``fairlead_tension``,
    ``anchor_tension``, ``fairlead_force`` (time, axis), ``max_tension``,
    ``max_tension_element``, ``touchdown_tension``, ``touchdown_x``, ``touchdown_y``,
    ``grounded_length`` and profile snapshots ``profile_position`` (snapshot, node, axis),
    ``profile_tension`` (snapshot, element) at the steps nearest to ``snapshot_times``, and
    ``node_position`` (time, tracked_node, axis) of the nodes in ``track_nodes``.
    ``progress``: called with the simulated time and ``t_end`` (s, from the start) every 5 %
    of the run (the steps then run in 20 pieces: the same numbers as one).
    ``stats``: a dict that receives ``cpu_steps``, the CPU time (s, ``time.process_time``) of
    the time steps alone (the fairlead track evaluated before, the Dataset built after: what a
    benchmark against another line code times), and ``steps``.
    """
    n = int(round(t_end / dt))
    r0 = line.r[-1].copy()
    nrec = n // record_every + 1
    times = np.zeros(nrec)
    recs = np.zeros((nrec, 13))     # kernels.record_into channels of every recorded step
    snap_steps = np.array(sorted({int(round(ts / dt)) for ts in snapshot_times}), np.int64)
    snaps_r = np.zeros((len(snap_steps), line.n_nodes, 3))
    snaps_t = np.zeros((len(snap_steps), line.n_nodes - 1))
    zc = line.S[K.S_ZC]
    t0 = line.time
    tracked = np.asarray(track_nodes, dtype=np.int64)
    pos_tr = np.zeros((nrec, tracked.size, 3))
    b = line.bundle
    tens = b.work.tens      # element tensions of the last force evaluation (read only here)
    K.line_forces(line.r, line.v, line.fs, b.par, False, 0.0, 0.0, b.step.f, b.work)
    times[0] = t0
    K.record_into(line.r, b.step.f, tens, zc, line.s_nodes, recs[0])
    pos_tr[0] = line.r[tracked]
    si = 0
    if snap_steps.size and snap_steps[0] == 0:
        snaps_r[0] = line.r
        snaps_t[0] = tens
        si = 1
    if line.integrator == "generalized_alpha" and line.waves is None:
        # the fairlead track first, then every step in one numba call
        rf = np.zeros((n + 1, 3))
        vf = np.zeros((n + 1, 3))
        track = getattr(motion, "track", None)
        if track is not None:
            # the motion's own vectorised evaluation (the same numbers as a call per step;
            # the per-step Python calls cost a third of an OC3 line's run)
            d, v = track((t0 + np.arange(1, n + 1) * dt) - t0)
            rf[1:] = r0 + d
            vf[1:] = v
        else:
            for k in range(1, n + 1):
                d, v = motion(t0 + k * dt - t0)
                rf[k] = r0 + d
                vf[k] = v
        counts = np.zeros(2)
        pieces = PROGRESS_PIECES if progress is not None else 1
        k, st = 0, 0
        cpu0 = time.process_time()
        for p in range(pieces):
            k0 = n * p // pieces + 1
            k1 = n * (p + 1) // pieces
            if k1 >= k0:
                k, st, si = _run_steps(t0, dt, k0, k1, int(substeps), line.MAX_SPLIT, rf, vf,
                                       record_every, snap_steps, si, tracked, b, times, recs,
                                       snaps_r, snaps_t, pos_tr, counts)
            if st < 0:
                break
            if progress is not None:
                progress(k1 * dt, n * dt)
        cpu = time.process_time() - cpu0
        line.newton_iterations += int(counts[0])
        line.substeps_taken += int(counts[1])
        line.set_time(t0 + (k if st == 0 else k - 1) * dt)
        if st < 0:
            raise line.step_error(st)
    else:
        cpu0 = time.process_time()
        for k in range(1, n + 1):
            t = t0 + k * dt
            d, v = motion(t - t0)
            line.step(t, dt, r0 + d, v, substeps=substeps)
            if k % record_every == 0:
                kr = k // record_every
                times[kr] = t
                K.record_into(line.r, line.fn, tens, zc, line.s_nodes, recs[kr])
                pos_tr[kr] = line.r[tracked]
            if si < len(snap_steps) and snap_steps[si] == k:
                snaps_r[si] = line.r
                snaps_t[si] = tens
                si += 1
        cpu = time.process_time() - cpu0
    if stats is not None:
        stats["cpu_steps"] = cpu
        stats["steps"] = n
    Ff = recs[:, 0:3]
    Fa = recs[:, 3:6]
    tmax = recs[:, 6]
    imax = recs[:, 7].astype(np.int64)
    ttd = recs[:, 8]
    xtd = recs[:, 9]
    ytd = recs[:, 10]
    lg = recs[:, 11]
    name = line.spec.name
    ds = xr.Dataset(
        {
            "fairlead_tension": ("time", np.linalg.norm(Ff, axis=1),
                                 {"units": "N", "long_name": f"tension at the fairlead, {name}"}),
            "anchor_tension": ("time", np.linalg.norm(Fa, axis=1),
                               {"units": "N", "long_name": "tension at the anchor"}),
            "fairlead_force": (("time", "axis"), Ff,
                               {"units": "N", "long_name": "force of the line on the fairlead, "
                                                           "earth axes"}),
            "max_tension": ("time", tmax, {"units": "N",
                                           "long_name": "largest element tension along the line"}),
            "max_tension_element": ("time", imax, {"units": "1", "long_name":
                                                   "element of the largest tension (0 at anchor)"}),
            "touchdown_tension": ("time", ttd, {"units": "N", "long_name":
                                                "tension of the element above the touchdown node"}),
            "touchdown_x": ("time", xtd, {"units": "m", "long_name": "touchdown node x"}),
            "touchdown_y": ("time", ytd, {"units": "m", "long_name": "touchdown node y"}),
            "grounded_length": ("time", lg, {"units": "m", "long_name":
                                             "unstretched length from the anchor to the last node "
                                             "in seabed contact"}),
            "profile_position": (("snapshot", "node", "axis"), snaps_r,
                                 {"units": "m", "long_name": "node positions"}),
            "profile_tension": (("snapshot", "element"), snaps_t,
                                {"units": "N", "long_name": "element tensions"}),
            "node_position": (("time", "tracked_node", "axis"), pos_tr,
                              {"units": "m", "long_name": "positions of the tracked nodes"}),
        },
        coords={"time": ("time", times, {"units": "s"}),
                "axis": ["x", "y", "z"],
                "snapshot": ("snapshot", np.array(snap_steps, float) * dt + t0, {"units": "s"}),
                "node": np.arange(line.n_nodes), "element": np.arange(line.n_nodes - 1),
                "tracked_node": tracked},
        attrs={"line": name, "dt": dt, "substeps": substeps,
               "integrator": getattr(line, "integrator", ""),
               "newton_iterations": int(getattr(line, "newton_iterations", 0))})
    return ds


PROGRESS_PIECES = 20
"""Pieces a prescribed-motion run is split into when progress is reported (a line per 5 %)."""


@njit(**KERNEL_JIT)
def _run_steps(t0, dt, k0, k1, nsub, max_split, rf, vf, record_every, snap_steps, si, tracked,
               ln, times, recs, snaps_r, snaps_t, pos_tr, counts):
    """Steps ``k0 .. k1`` of :func:`run_prescribed` for a line without wave kinematics: advance
    (:func:`kernels.ga_advance`) to ``t0 + k dt`` with the fairlead at ``rf[k]`` moving with
    ``vf[k]``, accept, record every ``record_every`` steps (``times``, ``recs`` rows of
    :func:`kernels.record_into`, ``pos_tr`` of the ``tracked`` nodes) and the snapshots at
    ``snap_steps[si:]``.  ``counts`` += Newton iterations and halvings.  Returns ``(k, 0, si)``
    after the last step or ``(k, status, si)`` of the step ``k`` that failed (not accepted),
    ``si`` the next snapshot."""
    now = ln.now
    tr = ln.trial
    w = ln.work
    zc = ln.par.S[K.S_ZC]
    s_nodes = ln.par.s_nodes
    for k in range(k0, k1 + 1):
        t = t0 + k * dt
        w.stats[0] = 0.0
        w.stats[1] = 0.0
        st = K.ga_advance(t, dt, nsub, max_split, rf[k], vf[k], now, tr, ln.step, ln.par, w)
        counts[0] += w.stats[0]
        counts[1] += w.stats[1]
        if st < 0:
            return k, st, si
        K.accept_trial(ln)
        if k % record_every == 0:
            kr = k // record_every
            times[kr] = t
            K.record_into(now.r, now.f, w.tens, zc, s_nodes, recs[kr])
            for j in range(tracked.shape[0]):
                for c in range(3):
                    pos_tr[kr, j, c] = now.r[tracked[j], c]
        if si < snap_steps.shape[0] and snap_steps[si] == k:
            for i in range(now.r.shape[0]):
                for c in range(3):
                    snaps_r[si, i, c] = now.r[i, c]
            for j in range(w.tens.shape[0]):
                snaps_t[si, j] = w.tens[j]
            si += 1
    return k1, 0, si


def forced_oscillation_impedance(line: FELine, lf, duration: float, settle: float, dt: float,
                                 wf=None) -> tuple[float, float]:
    """Time-domain dynamic stiffness and damping of a line along x (N/m, N s/m) under the
    prescribed periodic motion ``lf`` (a function of time returning displacement and velocity,
    (2, 3) or equivalent; plus ``wf`` of the same form, e.g. a wave-frequency motion):
    ``K = -<F x> / <x^2>``, ``B = -<F v> / <v^2>`` over ``duration`` after ``settle`` (x, v the
    motion ``lf`` along x; F the fairlead force along x minus its mean).  The line is started
    from its present state and its node positions are put back afterwards."""
    line.start()
    r0 = line.r.copy()

    def motion(t):
        d, v = lf(t)
        if wf is not None:
            d2, v2 = wf(t)
            return d + d2, v + v2
        return d, v

    ds = run_prescribed(line, motion, settle + duration, dt)
    line.r[:] = r0
    t = ds.time.values
    keep = t > settle + 1e-9
    F = ds.fairlead_force.values[keep, 0]
    F = F - F.mean()
    xv = np.array([lf(tt) for tt in t[keep]])
    x, v = xv[:, 0, 0], xv[:, 1, 0]
    return -np.mean(F * x) / np.mean(x * x), -np.mean(F * v) / np.mean(v * v)


def quasi_static_tension(line: FELine, motion, times) -> np.ndarray:
    """Quasi-static fairlead tension (N) along the fairlead track (elastic catenary of
    :func:`floatmoor.mooring.solve_line`, no friction, static EA) at ``times`` (s)."""
    sp = line.spec
    A = np.asarray(sp.anchor, float)
    F0 = np.asarray(sp.fairlead, float)
    rho, g = sp.water_density, sp.gravity
    L = np.array([s.length for s in sp.segments])
    EA = np.array([s.line_type.ea for s in sp.segments])
    w = np.array([s.line_type.submerged_weight(rho, g) for s in sp.segments])
    out = np.empty(len(times))
    hf = vf = 0.0
    for k, t in enumerate(times):
        d, _ = motion(t)
        F = F0 + d
        xf = float(np.hypot(*(F[:2] - A[:2])))
        sol = solve_line(xf, float(F[2] - A[2]), L, EA, w, None, 0.0, hf0=hf, vf0=vf)
        hf, vf = sol.HF, sol.VF
        out[k] = sol.fairlead_tension
    return out


def daf(t_fe, t_qs) -> float:
    """Dynamic amplification factor ``(T_max - T_mean)_FE / (T_max - T_mean)_QS`` (Wang
    2016, eq. 8.1) from two tension histories over the same (steady) interval."""
    t_fe = np.asarray(t_fe, float)
    t_qs = np.asarray(t_qs, float)
    den = t_qs.max() - t_qs.mean()
    if not den > 0:
        raise ValueError("the quasi-static tension does not vary: DAF undefined")
    return float((t_fe.max() - t_fe.mean()) / den)


def decoupled_analysis(system, t, poses, *, dt: float | None = None, discard: float = 0.0,
                       lines=None, element_length: float = 20.0, line_kw=None,
                       **spec_kw) -> xr.Dataset:
    """Decoupled FE analysis of mooring lines driven by the body motion of a previous floater
    run (Wang (2016) chapter 8: SIMO motions into RIFLEX), with the DAF per line.

    Parameters
    ----------
    system : floatmoor.mooring.MooringSystem
        The quasi-static mooring (its lines become FE lines, :func:`specs_from_system`).
    t : (nt,) s, increasing
    poses : (nt, 6) body poses, m and rad
    dt : float, optional
        FE time step (default the spacing of ``t``).
    discard : float
        Start-up time left out of the statistics and the DAF, s (the FE lines start from static
        equilibrium at ``poses[0]`` with zero velocity).
    lines : sequence of str, optional
        Line names (default all active lines).
    element_length : float
        Target element length, m.
    line_kw : dict, optional
        Passed to :class:`FELine`.
    **spec_kw
        Passed to :func:`spec_from_linedef` (``line_types``, ``friction``, ``seabed``,
        ``internal_damping``, current).

    Returns
    -------
    xarray.Dataset
        ``fe_tension`` and ``qs_tension`` (line, time) in N and ``daf`` (line), with units.
    """
    from .from_system import spec_from_linedef

    t = np.asarray(t, float)
    poses = np.asarray(poses, float)
    if dt is None:
        dt = float(t[1] - t[0])
    names = [n for n, a in zip(system.names, system.active) if a] if lines is None else list(lines)
    fe_out, qs_out, dafs = [], [], []
    times = None
    for name in names:
        ld = system.lines[system.names.index(name)]
        spec = spec_from_linedef(ld, water_depth=system.water_depth, pose=poses[0],
                                 element_length=element_length,
                                 water_density=system.water_density, gravity=system.gravity,
                                 **spec_kw)
        line = FELine(spec, **(line_kw or {}))
        line.solve_static()
        line.start(t0=0.0)
        track = fairlead_track_from_body(t - t[0], poses, ld.fairlead)
        ds = run_prescribed(line, track, t[-1] - t[0], dt)
        times = ds.time.values + t[0]
        T_fe = ds.fairlead_tension.values
        T_qs = quasi_static_tension(line, track, ds.time.values)
        sel = ds.time.values >= discard
        fe_out.append(T_fe)
        qs_out.append(T_qs)
        dafs.append(daf(T_fe[sel], T_qs[sel]))
    return xr.Dataset(
        {"fe_tension": (("line", "time"), np.array(fe_out),
                        {"units": "N", "long_name": "fairlead tension, FE line"}),
         "qs_tension": (("line", "time"), np.array(qs_out),
                        {"units": "N", "long_name": "fairlead tension, quasi-static catenary"}),
         "daf": ("line", np.array(dafs), {"units": "1", "long_name":
                                          "(T_max - T_mean)_FE / (T_max - T_mean)_QS"})},
        coords={"line": names, "time": ("time", times, {"units": "s"})},
        attrs={"dt": dt, "discard": discard, "element_length": element_length})
