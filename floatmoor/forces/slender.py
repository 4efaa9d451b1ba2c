"""Slender elements: Morison drag strips on the hull (viscous drift, seed 002 chapter 6).

The physics and the kernel are in :mod:`floatmoor.forces.slender_kernels`; the vessel-file
section in :mod:`floatmoor.forces.slender_config`.  This module builds

* :class:`SlenderGeometry`: the elements as plain arrays (end points, local axes, drag per
  length, strips, stations);
* :class:`KinematicsTable`: the wave elevation and particle velocity at the stations, on a time
  grid of step ``H`` and at levels of the stretched vertical coordinate, by FFT of the same wave
  realisation as the first-order wave force (all its components: no reduced set);
* :func:`slender_force`: the force of the elements at one time, pose and velocity (the Python
  entry to the kernel, used by the tests and by the model's ``force``);
* :func:`covered_current_dofs`, :func:`current_table_without`: the double-counting rule of seed
  002 section 6.1.2 (the hull's current coefficients are set to zero in the DOFs the elements
  carry, because the strips already see the current).

Why a table: direct Airy sums cost ~42 ns per component and point; 2383 components at ~60 strip
points and 4 RK4 stages per step would be ~20 ms per step, 300x the whole storm step.  The table
is exact at its nodes (FFT of the full realisation); in between, linear interpolation in time
(step H, default 0.4 s: amplitude error (w H)^2/8, 0.2 % at the 18 s peak, 3 % at 5 s), in
stretched depth (default 2 m: relative error (k dz)^2/8, 0.5 % at 5 s period) and along pontoons
(stations every ``station_spacing`` m, default 10 m).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ..core.errors import FloatmoorWarning, SceneError
from .series import FrequencyGrid
from .slender_config import SlenderElementSpec
from .slender_kernels import local_axes, slender_force_into

__all__ = ["SlenderGeometry", "KinematicsTable", "slender_geometry", "build_kinematics_table",
           "slender_force", "covered_current_dofs", "current_table_without",
           "angular_velocity_earth", "DOF_NAMES"]

DOF_NAMES = ("surge", "sway", "heave", "roll", "pitch", "yaw")


@dataclass(frozen=True, eq=False)
class SlenderGeometry:
    """Plain arrays of the elements (see :func:`slender_force_into`); ``stations`` (ns, 2)
    the (x, y) of the kinematics stations at the reference pose (earth, m)."""

    names: tuple
    p1: np.ndarray
    p2: np.ndarray
    ex: np.ndarray
    ey: np.ndarray
    ez: np.ndarray
    c2: np.ndarray
    n_strips: np.ndarray
    st_first: np.ndarray
    st_count: np.ndarray
    stations: np.ndarray

    @property
    def z_min(self) -> float:
        return float(min(self.p1[:, 2].min(), self.p2[:, 2].min()))


def slender_geometry(elements: list, *, station_spacing: float = 10.0,
                     yaw0: float = 0.0, origin=(0.0, 0.0)) -> SlenderGeometry:
    """Arrays of ``elements`` (:class:`SlenderElementSpec` list).

    Each element gets ``max(1, ceil(l_h / station_spacing))`` stations at s = (i + 0.5)/n along
    it, l_h its horizontal length (a vertical column: one station).  Station positions are the
    element points at the reference pose: body heading ``yaw0`` (rad) and horizontal position
    ``origin`` (m).
    """
    if not elements:
        raise SceneError(None, "slender_elements.elements", "at least one element")
    ne = len(elements)
    p1 = np.array([e.p1 for e in elements], float).reshape(ne, 3)
    p2 = np.array([e.p2 for e in elements], float).reshape(ne, 3)
    axes = [local_axes(a, b) for a, b in zip(p1, p2)]
    ex = np.array([a[0] for a in axes])
    ey = np.array([a[1] for a in axes])
    ez = np.array([a[2] for a in axes])
    c2 = np.array([e.c2 for e in elements], float).reshape(ne, 3)
    n_strips = np.array([e.n_strips for e in elements], np.int64)
    st_first = np.zeros(ne, np.int64)
    st_count = np.zeros(ne, np.int64)
    c, s = math.cos(yaw0), math.sin(yaw0)
    st = []
    for i in range(ne):
        lh = float(np.hypot(*(p2[i, :2] - p1[i, :2])))
        n = max(1, int(math.ceil(lh / station_spacing - 1e-9)))
        st_first[i] = len(st)
        st_count[i] = n
        for j in range(n):
            q = p1[i] + (j + 0.5) / n * (p2[i] - p1[i])
            st.append((origin[0] + c * q[0] - s * q[1], origin[1] + s * q[0] + c * q[1]))
    return SlenderGeometry(names=tuple(e.name for e in elements), p1=p1, p2=p2, ex=ex, ey=ey,
                           ez=ez, c2=c2, n_strips=n_strips, st_first=st_first,
                           st_count=st_count, stations=np.array(st, float).reshape(-1, 2))


@dataclass(frozen=True, eq=False)
class KinematicsTable:
    """Elevation ``eta`` (nt, ns) (m) and wave velocity ``u`` (nt, ns, nl, 3) (m/s, earth axes)
    at the stations, times ``i H`` (s), stretched levels ``lev0 + l dlev`` (m, top level 0).
    ``wheeler``: Wheeler stretching (else constant above the MWL); ``depth`` (m, inf = deep)."""

    eta: np.ndarray
    u: np.ndarray
    H: float
    lev0: float
    dlev: float
    depth: float
    wheeler: bool

    @property
    def nbytes(self) -> int:
        return int(self.eta.nbytes + self.u.nbytes)


def _factors(k, z, depth):
    """cosh k(z+d)/sinh kd and sinh k(z+d)/sinh kd (overflow-free; deep water e^{kz})."""
    e1 = np.exp(k * z)
    if math.isinf(depth):
        return e1, e1
    q = np.exp(-2.0 * k * depth)
    e2 = q / e1
    return (e1 + e2) / (1.0 - q), (e1 - e2) / (1.0 - q)


def _sample(omega, coeffs, n_t: int, H: float, grid: FrequencyGrid | None) -> np.ndarray:
    """Re sum_k coeffs[k, :] exp(i w_k t_j), t_j = j H, (n_t, M): an FFT of length N/m when
    the frequencies lie on ``grid`` and H = m grid.h with m dividing N; else a direct sum."""
    if grid is not None:
        m = H / grid.h
        mi = int(round(m))
        pos = (omega - grid.w0) / grid.dw
        idx = np.rint(pos).astype(np.int64)
        if abs(m - mi) < 1e-9 and mi >= 1 and grid.N % mi == 0 and np.all(np.abs(pos - idx) < 1e-6):
            Np = grid.N // mi
            C = np.zeros((Np, coeffs.shape[1]), complex)
            np.add.at(C, idx % Np, coeffs)
            s = np.fft.ifft(C, axis=0) * Np
            j = np.arange(n_t)
            carrier = np.exp(1j * ((grid.w0 * H * j) % (2.0 * math.pi)))
            return (s[j % Np] * carrier[:, None]).real
    t = np.arange(n_t) * H
    out = np.zeros((n_t, coeffs.shape[1]))
    for k in range(omega.size):
        ph = np.exp(1j * omega[k] * t)
        out += (ph[:, None] * coeffs[k][None, :]).real
    return out


def build_kinematics_table(omega, amplitude, phase, k, direction, stations, *, duration: float,
                           H: float, depth: float, lev0: float, dlev: float = 2.0,
                           wheeler: bool = True, grid: FrequencyGrid | None = None
                           ) -> KinematicsTable:
    """Precompute elevation and linear wave velocity at ``stations`` (ns, 2) (m).

    Parameters
    ----------
    omega, amplitude, phase, k, direction : (n,) the wave components (rad/s, m, rad, rad/m,
        rad), ``eta = sum a cos(w t - k (x cos b + y sin b) + phi)``.
    duration : s, the table covers [0, duration + H].
    H : table time step (s); with a ``grid`` (FFT realisation) it should be a multiple m of
        grid.h with m dividing grid.N (else the direct sum is used: slow for many components).
    depth : water depth (m), inf for deep water.
    lev0, dlev : deepest level (m, < 0) and the level step (m); levels lev0 .. 0.
    wheeler : Wheeler stretching (True) or constant above the MWL (False).
    """
    omega = np.asarray(omega, float)
    amp = np.asarray(amplitude, float)
    ph = np.asarray(phase, float)
    kk = np.asarray(k, float)
    beta = np.broadcast_to(np.asarray(direction, float), omega.shape)
    stations = np.asarray(stations, float).reshape(-1, 2)
    if not (H > 0 and dlev > 0 and lev0 < 0):
        raise ValueError("H > 0, dlev > 0 and lev0 < 0 needed")
    nl = int(math.ceil(-lev0 / dlev - 1e-9)) + 1
    lev0 = -(nl - 1) * dlev
    levels = lev0 + dlev * np.arange(nl)
    n_t = int(math.ceil(duration / H - 1e-9)) + 2
    ns = stations.shape[0]
    eta = np.zeros((n_t, ns))
    u = np.zeros((n_t, ns, nl, 3))
    cb, sb = np.cos(beta), np.sin(beta)
    Cs = np.empty((omega.size, nl))
    Ss = np.empty((omega.size, nl))
    for l, z in enumerate(levels):
        Cs[:, l], Ss[:, l] = _factors(kk, z, depth)
    for s in range(ns):
        x, y = stations[s]
        base = amp * np.exp(1j * (ph - kk * (x * cb + y * sb)))
        coeffs = np.empty((omega.size, 1 + 3 * nl), complex)
        coeffs[:, 0] = base
        uh = (base * omega)[:, None] * Cs
        coeffs[:, 1::3] = uh * cb[:, None]
        coeffs[:, 2::3] = uh * sb[:, None]
        coeffs[:, 3::3] = (1j * base * omega)[:, None] * Ss
        vals = _sample(omega, coeffs, n_t, H, grid)
        eta[:, s] = vals[:, 0]
        u[:, s, :, :] = vals[:, 1:].reshape(n_t, nl, 3)
    return KinematicsTable(eta=eta, u=np.ascontiguousarray(u), H=float(H), lev0=float(lev0),
                           dlev=float(dlev), depth=float(depth), wheeler=bool(wheeler))


def angular_velocity_earth(yaw: float, rates) -> np.ndarray:
    """Angular velocity (rad/s, earth axes) from the roll, pitch and yaw rates (3,) of the
    time-domain solver (roll and pitch rates about the yaw-following axes; small roll and
    pitch): the roll/pitch rate vector turned by ``yaw``."""
    p, q, r = (float(x) for x in rates)
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([c * p - s * q, s * p + c * q, r])


def slender_force(geom: SlenderGeometry, table: KinematicsTable, t: float, pose, velocity,
                  omega=None, *, current_z=None, current_speed=None, current_heading=0.0,
                  wave_factor: float = 1.0) -> np.ndarray:
    """Force and moment (6,) (N, N m; earth axes, moments about the displaced reference point).

    Parameters
    ----------
    geom, table : from :func:`slender_geometry` and :func:`build_kinematics_table`.
    t : time (s).
    pose : (6,) x, y, z (m), roll, pitch, yaw (rad).
    velocity : (3,) or (6,) earth velocity of the reference point (m/s) (first three used).
    omega : (3,) angular velocity (rad/s, earth axes); default the rates velocity[3:6] (small
        angles) or zero.
    current_z, current_speed : current profile (m, increasing; m/s); None: no current.
    current_heading : rad, direction of travel.
    wave_factor : factor on the wave kinematics (ramp).
    """
    pose = np.ascontiguousarray(pose, float)
    vel = np.asarray(velocity, float).reshape(-1)
    if omega is None:
        omega = vel[3:6] if vel.size >= 6 else np.zeros(3)
    omega = np.ascontiguousarray(omega, float)
    cz = np.zeros(0) if current_z is None else np.ascontiguousarray(current_z, float)
    cs = np.zeros(0) if current_speed is None else np.ascontiguousarray(current_speed, float)
    out = np.zeros(6)
    R = np.zeros((3, 3))
    slender_force_into(float(t) / table.H, pose, np.ascontiguousarray(vel[:3]), omega, geom.p1,
                       geom.p2, geom.ex, geom.ey, geom.ez, geom.c2, geom.n_strips,
                       geom.st_first, geom.st_count, table.eta, table.u, table.lev0, table.dlev,
                       table.depth, table.wheeler, float(wave_factor), cz, cs,
                       math.cos(current_heading), math.sin(current_heading), R, out)
    return out


def covered_current_dofs(geom: SlenderGeometry, *, rel_tol: float = 0.01) -> tuple:
    """DOF indices in which the elements carry a current force: the force of a unit current
    (no waves, body at rest) over headings 0, 15, ..., 345 deg, where its largest magnitude
    exceeds ``rel_tol`` times the largest of the DOF's kind (forces vs moments / 100 m)."""
    nl = 2
    tab = KinematicsTable(eta=np.zeros((2, geom.stations.shape[0])),
                          u=np.zeros((2, geom.stations.shape[0], nl, 3)), H=1.0, lev0=-1.0e4,
                          dlev=1.0e4, depth=math.inf, wheeler=False)
    peak = np.zeros(6)
    for hd in np.radians(np.arange(0.0, 360.0, 15.0)):
        f = slender_force(geom, tab, 0.0, np.zeros(6), np.zeros(3), np.zeros(3),
                          current_z=np.array([0.0]), current_speed=np.array([1.0]),
                          current_heading=hd)
        peak = np.maximum(peak, np.abs(f))
    scale = max(peak[:3].max(), peak[3:].max() / 100.0, 1e-300)
    ref = np.array([scale] * 3 + [100.0 * scale] * 3)
    return tuple(int(d) for d in range(6) if peak[d] > rel_tol * ref[d])


def current_table_without(table: np.ndarray, dofs, *, vessel_file=None, warn: bool = True
                          ) -> np.ndarray:
    """The hull current coefficient table (n_heading, 6) with the columns ``dofs`` zeroed (all
    headings), seed 002 section 6.1.2; a :class:`FloatmoorWarning` names the DOFs."""
    out = np.array(table, float, copy=True)
    dofs = tuple(dofs)
    for d in dofs:
        out[:, d] = 0.0
    if warn and dofs:
        warnings.warn(f"slender elements carry the current: the current coefficients of "
                      f"{vessel_file or 'the vessel'} are set to zero in "
                      f"{', '.join(DOF_NAMES[d] for d in dofs)} (double counting, seed 002 "
                      f"section 6.1.2; forces: viscous_drift: double_counting: false keeps them)",
                      FloatmoorWarning, stacklevel=2)
    return out
