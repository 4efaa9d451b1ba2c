"""Slender elements: Morison drag strips on the hull (viscous drift, Wang (2016) chapter 6).

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
stretched depth (default 3 m: relative error (k dz)^2/8, 0.5 % at 8 s period) and along pontoons
(stations every ``station_spacing`` m, default 10 m).  The elevation, which sets the wetted
length of the columns, is tabulated at every half step (exact in the time loop): with it at
0.4 s too, the surge force peaks were 17 % off a fine table (0.1 s) in the 100-year sea.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ..core.errors import FloatmoorWarning, SceneError
from .base import FDContext, FDTerms, ForceModel, KernelAssembly, SetupContext, register
from .series import FrequencyGrid
from .slender_kernels import local_axes, slender_force_into

__all__ = ["SlenderGeometry", "KinematicsTable", "slender_geometry", "build_kinematics_table",
           "slender_force", "covered_current_dofs", "current_table_without",
           "angular_velocity_earth", "DOF_NAMES", "SlenderElements", "hull_current_table",
           "drift_database", "linear_damping_matrix", "viscous_spec",
           "corrected_drift_database", "viscous_linear_damping", "hull_current_coefficients"]

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
    cm: np.ndarray
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
    cm = np.array([getattr(e, "cm", (0.0, 0.0, 0.0)) for e in elements], float).reshape(ne, 3)
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
                           ez=ez, c2=c2, cm=cm, n_strips=n_strips, st_first=st_first,
                           st_count=st_count, stations=np.array(st, float).reshape(-1, 2))


@dataclass(frozen=True, eq=False)
class KinematicsTable:
    """Elevation ``eta`` (nt, ns) (m) and wave velocity ``u`` (nt, ns, nl, 3) (m/s, earth axes)
    at the stations, times ``i H`` (s), stretched levels ``lev0 + l dlev`` (m, top level 0).
    ``wheeler``: Wheeler stretching (else constant above the MWL); ``depth`` (m, inf = deep);
    ``a`` the wave acceleration (m/s^2) like ``u``, or None (no inertia terms)."""

    eta: np.ndarray
    u: np.ndarray
    H: float
    lev0: float
    dlev: float
    depth: float
    wheeler: bool
    a: np.ndarray | None = None
    H_eta: float | None = None

    @property
    def eta_step(self) -> float:
        """Time step (s) of the elevation table (default the velocity table's)."""
        return self.H if self.H_eta is None else self.H_eta

    @property
    def nbytes(self) -> int:
        return int(self.eta.nbytes + self.u.nbytes + (0 if self.a is None else self.a.nbytes))


def _factors(k, z, depth):
    """cosh k(z+d)/sinh kd and sinh k(z+d)/sinh kd (overflow-free; deep water e^{kz})."""
    e1 = np.exp(k * z)
    if math.isinf(depth):
        return e1, e1
    q = np.exp(-2.0 * k * depth)
    e2 = q / e1
    return (e1 + e2) / (1.0 - q), (e1 - e2) / (1.0 - q)


def _sample(omega, coeffs, n_t: int, H: float, grid: FrequencyGrid | None) -> np.ndarray:
    """Re sum_k coeffs[k, :] exp(i w_k t_j), t_j = j H, as (M, n_t): an FFT of length N/m when
    the frequencies lie on ``grid`` and H = m grid.h with m dividing N; else a direct sum."""
    M = coeffs.shape[1]
    if grid is not None:
        m = H / grid.h
        mi = int(round(m))
        pos = (omega - grid.w0) / grid.dw
        idx = np.rint(pos).astype(np.int64)
        if abs(m - mi) < 1e-9 and mi >= 1 and grid.N % mi == 0 and np.all(np.abs(pos - idx) < 1e-6):
            Np = grid.N // mi
            C = np.zeros((M, Np), complex)
            col = idx % Np
            if np.unique(col).size == col.size:
                C[:, col] = coeffs.T
            else:  # several directions per frequency (spreading)
                np.add.at(C, (slice(None), col), coeffs.T)
            s = np.fft.ifft(C, axis=1)
            n0 = min(n_t, Np)
            carrier = Np * np.exp(1j * ((grid.w0 * H * np.arange(n_t)) % (2.0 * math.pi)))
            out = np.empty((M, n_t))
            out[:, :n0] = (s[:, :n0] * carrier[None, :n0]).real
            j = n0
            while j < n_t:  # the sum repeats after N h
                n1 = min(n_t - j, Np)
                out[:, j:j + n1] = (s[:, :n1] * carrier[None, j:j + n1]).real
                j += n1
            return out
    t = np.arange(n_t) * H
    out = np.zeros((M, n_t))
    for k in range(omega.size):
        out += (coeffs[k][:, None] * np.exp(1j * omega[k] * t)[None, :]).real
    return out


def build_kinematics_table(omega, amplitude, phase, k, direction, stations, *, duration: float,
                           H: float, depth: float, lev0: float, dlev: float = 3.0,
                           wheeler: bool = True, grid: FrequencyGrid | None = None,
                           acceleration: bool = False, H_eta: float | None = None
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
    acceleration : also tabulate the particle acceleration (for the inertia terms).
    H_eta : time step (s) of the elevation table (default H).  The wetted length of a
        surface-piercing element follows the elevation: a finer elevation table removes most
        of the interpolation error at steep crests for little memory (one series per station).
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
    He = H if H_eta is None else float(H_eta)
    n_te = int(math.ceil(duration / He - 1e-9)) + 2
    eta = np.zeros((n_te, ns), np.float32)
    u = np.zeros((n_t, ns, nl, 3), np.float32)   # float32: half the memory, 1e-7 relative
    acc = np.zeros((n_t, ns, nl, 3), np.float32) if acceleration else None
    cb, sb = np.cos(beta), np.sin(beta)
    Cs = np.empty((omega.size, nl))
    Ss = np.empty((omega.size, nl))
    for l, z in enumerate(levels):
        Cs[:, l], Ss[:, l] = _factors(kk, z, depth)
    for s in range(ns):
        x, y = stations[s]
        base = amp * np.exp(1j * (ph - kk * (x * cb + y * sb)))
        nv = 1 + 3 * nl
        coeffs = np.empty((omega.size, nv * 2 - 1 if acceleration else nv), complex)
        coeffs[:, 0] = base
        uh = (base * omega)[:, None] * Cs
        coeffs[:, 1:nv:3] = uh * cb[:, None]
        coeffs[:, 2:nv:3] = uh * sb[:, None]
        coeffs[:, 3:nv:3] = (1j * base * omega)[:, None] * Ss
        if acceleration:  # d/dt of exp(i w t): i w
            coeffs[:, nv:] = coeffs[:, 1:nv] * (1j * omega)[:, None]
        vals = _sample(omega, coeffs, n_t, H, grid)
        eta[:, s] = vals[0] if He == H else _sample(omega, coeffs[:, :1], n_te, He, grid)[0]
        u[:, s, :, :] = vals[1:nv].T.reshape(n_t, nl, 3)
        if acceleration:
            acc[:, s, :, :] = vals[nv:].T.reshape(n_t, nl, 3)
    return KinematicsTable(eta=eta, u=u, a=acc, H=float(H), H_eta=float(He), lev0=float(lev0),
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
    inertia = table.a is not None and bool(np.any(geom.cm != 0.0))
    a_tab = table.a if inertia else np.zeros((2, 1, 2, 3), np.float32)
    slender_force_into(float(t) / table.H, float(t) / table.eta_step, pose,
                       np.ascontiguousarray(vel[:3]), omega, geom.p1, geom.p2, geom.ex,
                       geom.ey, geom.ez, geom.c2, geom.cm, geom.n_strips, geom.st_first,
                       geom.st_count, table.eta, table.u, a_tab, inertia, table.lev0,
                       table.dlev, table.depth, table.wheeler, float(wave_factor), cz, cs,
                       math.cos(current_heading), math.sin(current_heading), R, out)
    return out


def covered_current_dofs(geom: SlenderGeometry, *, rel_tol: float = 0.01) -> tuple:
    """DOF indices in which the elements carry a current force: the force of a unit current
    (no waves, body at rest) over headings 0, 15, ..., 345 deg, where its largest magnitude
    exceeds ``rel_tol`` times the largest of the DOF's kind (forces vs moments / 100 m)."""
    nl = 2
    tab = KinematicsTable(eta=np.zeros((2, geom.stations.shape[0]), np.float32),
                          u=np.zeros((2, geom.stations.shape[0], nl, 3), np.float32), H=1.0,
                          lev0=-1.0e4, dlev=1.0e4, depth=math.inf, wheeler=False)
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
    headings), Wang (2016) section 6.1.2; a :class:`FloatmoorWarning` names the DOFs."""
    out = np.array(table, float, copy=True)
    dofs = tuple(dofs)
    for d in dofs:
        out[:, d] = 0.0
    if warn and dofs:
        warnings.warn(f"slender elements carry the current: the current coefficients of "
                      f"{vessel_file or 'the vessel'} are set to zero in "
                      f"{', '.join(DOF_NAMES[d] for d in dofs)} (double counting, Wang (2016) "
                      f"section 6.1.2; forces: viscous_drift: double_counting: false keeps them)",
                      FloatmoorWarning, stacklevel=2)
    return out


# -- the force model -------------------------------------------------------------------------

def viscous_spec(ctx):
    """The scene's ``forces: viscous_drift`` options (None when absent)."""
    return getattr(getattr(ctx, "options", None), "viscous_drift", None)


def _table_ratio(grid: FrequencyGrid | None, h: float, table_step: float) -> int:
    """Samples (of step h) per table step: the largest m <= table_step / h dividing grid.N."""
    m = max(1, int(math.floor(table_step / h + 1e-9)))
    if grid is None:
        return m
    while m > 1 and grid.N % m != 0:
        m -= 1
    return m


def _current_profile(scene, lev0: float):
    """Current (z (nc,), speed (nc,), heading) at heights lev0..0 from the scene, or empty."""
    spec = scene.environment.current
    if spec is None:
        return np.zeros(0), np.zeros(0), 0.0
    from ..metocean.current import current_speed
    z = np.linspace(min(lev0, -1.0), 0.0, 41)
    return z, np.asarray(current_speed(spec, z, scene.site.water_depth), float).reshape(-1), \
        float(spec.heading)


@register
class SlenderElements(ForceModel):
    """Morison drag strips on the hull (:mod:`floatmoor.forces.slender_kernels`), from the
    vessel file's ``slender_elements`` section; options in ``forces: viscous_drift``."""

    name = "slender_elements"
    description = "slender elements: Morison drag strips, current + waves - body velocity"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return getattr(getattr(options, "viscous_drift", None), "model",
                       "none") == "slender_elements"

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """The strips in the current alone, body at rest at the mean heading: their mean force
        (the time domain's :meth:`mean_force`) and, at the mean position, the damping of the LF
        motion ``-dF/dv`` (surge, sway, yaw rate; central differences).  Their viscous wave
        drift (drag on the wave kinematics and the WF body motion) is a time-domain effect:
        the frequency domain says so with a warning."""
        spec = getattr(fd.options, "viscous_drift", None)
        v = fd.built.vessel
        from .slender_config import parse_slender_elements
        drag = dict(getattr(spec, "drag", {}) or {})
        elements = parse_slender_elements(v.slender_elements, file=v.file,
                                          key="slender_elements", scale=drag or None)
        geom = slender_geometry(elements, station_spacing=getattr(spec, "station_spacing", 10.0))
        dlev = float(getattr(spec, "level_step", 3.0))
        nl = int(math.ceil(-(geom.z_min - 5.0) / dlev)) + 1
        table = KinematicsTable(eta=np.zeros((2, geom.stations.shape[0]), np.float32),
                                u=np.zeros((2, geom.stations.shape[0], nl, 3), np.float32),
                                H=1.0, lev0=-(nl - 1) * dlev, dlev=dlev,
                                depth=float(fd.built.scene.site.water_depth), wheeler=False)
        cz, cs, chead = _current_profile(fd.built.scene, table.lev0)
        pose = np.zeros(6)
        pose[5] = fd.yaw

        def force(vel):
            return slender_force(geom, table, 0.0, pose, vel[:3], np.array([0.0, 0.0, vel[5]]),
                                 current_z=cz, current_speed=cs, current_heading=chead,
                                 wave_factor=0.0)

        mean = force(np.zeros(6))
        if not fd.linear:
            return FDTerms(mean_force=mean)
        fd.warn("forces: viscous_drift: {model: slender_elements}: the frequency domain carries "
                "the slender elements' current load and its damping, not their viscous wave "
                "drift (drag on the wave kinematics and the WF motion: a time-domain effect); "
                "model: correction_formula gives an FD viscous drift")
        dv = 1e-4 * max(1.0, float(np.max(cs, initial=0.0)))
        radius = max(1.0, float(np.max(np.abs(np.vstack([geom.p1[:, :2], geom.p2[:, :2]])))))
        D = np.zeros((6, 6))
        for k, h in ((0, dv), (1, dv), (5, dv / radius)):
            e = np.zeros(6)
            e[k] = h
            D[:, k] = -(force(e) - force(-e)) / (2.0 * h)
        return FDTerms(mean_force=mean, lf_damping=D)

    def setup(self, ctx: SetupContext):
        from .slender_config import parse_slender_elements
        spec = viscous_spec(ctx)
        v = ctx.built.vessel
        scene = ctx.built.scene
        drag = dict(getattr(spec, "drag", {}) or {})
        elements = parse_slender_elements(v.slender_elements, file=v.file,
                                          key="slender_elements", scale=drag or None)
        geom = slender_geometry(elements, station_spacing=getattr(spec, "station_spacing", 10.0),
                                yaw0=ctx.yaw0)
        wheeler = bool(getattr(spec, "wheeler", True))
        inertia = bool(getattr(spec, "inertia", False))
        if inertia and not np.any(geom.cm != 0.0):
            raise SceneError(v.file, "slender_elements.inertia_per_length",
                             "inertia coefficients (kg/m) for forces: viscous_drift: inertia: "
                             "true")
        h = ctx.sample_dt
        duration = ctx.n_samples * h
        depth = float(scene.site.water_depth)
        comp = ctx.waves
        hs = float(getattr(scene.environment.waves, "hs", 0.0) or 0.0) if comp is not None else 0.0
        # deepest stretched level: the lowest element end, less heave/pitch motion and crests
        lev0 = geom.z_min - 5.0 - (1.2 * hs if wheeler else 0.0)
        dlev = float(getattr(spec, "level_step", 3.0))
        if comp is not None:
            r = comp.realisation
            m = _table_ratio(comp.grid, h, float(getattr(spec, "table_step", 0.4)))
            table = build_kinematics_table(r.omega, r.amplitude, r.phase, r.k, r.direction,
                                           geom.stations, duration=duration, H=m * h, H_eta=h,
                                           depth=depth, lev0=lev0, dlev=dlev, wheeler=wheeler,
                                           grid=comp.grid, acceleration=inertia)
        else:
            m = max(1, ctx.n_samples)
            nl = int(math.ceil(-lev0 / dlev)) + 1
            table = KinematicsTable(eta=np.zeros((2, geom.stations.shape[0]), np.float32),
                                    u=np.zeros((2, geom.stations.shape[0], nl, 3), np.float32),
                                    a=None, H=m * h,
                                    lev0=-(nl - 1) * dlev, dlev=dlev, depth=depth,
                                    wheeler=wheeler)
        cz, cs, chead = _current_profile(scene, table.lev0)
        self.geom = geom
        self.table = table
        self.h = h
        self.m = m
        self.ramp = np.ascontiguousarray(ctx.ramp_series(), float)
        self.current_z, self.current_speed, self.current_heading = cz, cs, chead
        self.fel = np.ascontiguousarray(np.hstack([geom.p1, geom.p2, geom.ex, geom.ey, geom.ez,
                                                   geom.c2, geom.cm]))
        self.iel = np.ascontiguousarray(np.stack([geom.n_strips, geom.st_first, geom.st_count],
                                                 axis=1).astype(np.int64))
        has_inertia = table.a is not None
        self.a_tab = table.a if has_inertia else np.zeros((2, 1, 2, 3), np.float32)
        self.par = np.array([float(m), table.lev0, table.dlev, table.depth, float(wheeler),
                             math.cos(chead), math.sin(chead), float(has_inertia),
                             float(round(table.eta_step / h))])
        self.cur = np.ascontiguousarray(np.stack([cz, cs], axis=1)) if cz.size else \
            np.zeros((0, 2))
        self._freeze()

    def force(self, t, pose, velocity, out):
        """Adds the strip forces at time t (s), pose (6,) and pose rate ``velocity`` (6,)
        (earth translation rate; roll/pitch rates about the yaw-following axes, yaw rate)."""
        vel = np.asarray(velocity, float)
        j = int(round(t / self.h))
        wf = float(self.ramp[min(max(j, 0), self.ramp.size - 1)])
        out += slender_force(self.geom, self.table, t, pose, vel[:3],
                             angular_velocity_earth(float(pose[5]), vel[3:6]),
                             current_z=self.current_z, current_speed=self.current_speed,
                             current_heading=self.current_heading, wave_factor=wf)

    def mean_force(self):
        """Current only (waves not yet ramped in), body at rest at the reference pose."""
        return slender_force(self.geom, self.table, 0.0, np.zeros(6), np.zeros(3), np.zeros(3),
                             current_z=self.current_z, current_speed=self.current_speed,
                             current_heading=self.current_heading, wave_factor=0.0)

    def covered_dofs(self) -> tuple:
        return covered_current_dofs(self.geom)

    def kernel_arrays(self) -> tuple:
        """(fel, iel, eta, u, a, par, cur, ramp) for :func:`slender_packed_into`."""
        return (self.fel, self.iel, self.table.eta, self.table.u, self.a_tab, self.par, self.cur,
                self.ramp)

    def contribute(self, asm: KernelAssembly):
        asm.add_strips(self.name, self.kernel_arrays())


def hull_current_table(ctx, table: np.ndarray, vessel) -> np.ndarray:
    """:func:`hull_current_coefficients` with the options of a :class:`SetupContext`."""
    return hull_current_coefficients(viscous_spec(ctx), table, vessel)


def hull_current_coefficients(spec, table: np.ndarray, vessel) -> np.ndarray:
    """The hull current coefficients to use: zeroed in the DOFs the slender elements cover when
    ``spec`` (the scene's ``viscous_drift`` options or None) selects them with
    ``double_counting: true`` (Wang (2016) section 6.1.2); else ``table`` itself."""
    if spec is None or getattr(spec, "model", "none") != "slender_elements" \
            or not getattr(spec, "double_counting", True):
        return table
    from .slender_config import parse_slender_elements
    els = parse_slender_elements(vessel.slender_elements, file=vessel.file,
                                 scale=dict(spec.drag) or None)
    dofs = covered_current_dofs(slender_geometry(els))
    return current_table_without(table, dofs, vessel_file=vessel.file)


def drift_database(ctx, db):
    """The database whose mean drift coefficients the drift model uses: corrected by eq. 6.6
    when the scene asks for ``viscous_drift: {model: correction_formula}``."""
    return corrected_drift_database(ctx.built, viscous_spec(ctx), db, yaw=ctx.yaw0)


def corrected_drift_database(built, spec, db=None, *, yaw: float = 0.0):
    """``db`` (default the vessel's database) with its mean drift coefficients corrected by
    eq. 6.6 when ``spec`` (a ``ViscousDriftSpec`` or None) selects the correction formula, for
    the scene's sea state (Hs), current (speed at z = 0 unless the spec gives one, heading) and
    the body heading ``yaw`` (rad); else ``db`` itself.  For the time domain (Newman drift) and
    the frequency domain (mean drift and slow-drift spectrum) alike."""
    if db is None:
        db = built.vessel.database
    if spec is None or getattr(spec, "model", "none") != "correction_formula":
        return db
    from ..hydro.viscous_drift import corrected_mean_drift
    from ..metocean.current import current_speed
    scene = built.scene
    env = scene.environment
    if env.waves is None:
        return db
    from ..metocean.config import WaveSpec
    if not isinstance(env.waves, WaveSpec):
        raise SceneError(scene.file, "forces.viscous_drift.model", "one sea state for the "
                         "correction formula (eq. 6.6 is written with the Hs of one sea)",
                         f"{len(env.waves.systems)} wave systems",
                         hint="use model: slender_elements, or none")
    U = spec.current_speed
    head = 0.0
    if env.current is not None:
        head = float(env.current.heading)
        if U is None:
            U = float(np.asarray(current_speed(env.current, np.array([0.0]),
                                               scene.site.water_depth)).reshape(-1)[0])
    return corrected_mean_drift(db, current_speed=float(U or 0.0), current_heading=head,
                                hs=float(env.waves.hs), formula=spec.correction_formula(),
                                yaw=yaw)


def uses_correction_formula(spec) -> bool:
    """True when ``spec`` (a ``ViscousDriftSpec`` or None) selects the correction formula."""
    return getattr(spec, "model", "none") == "correction_formula"


def refuse_qtf_with_correction(spec, drift, *, file, key: str) -> bool:
    """The drift rule of the correction formula, shared by the time and frequency domains:
    eq. 6.6 corrects the mean drift coefficients, which only Newman's approximation uses, so
    an explicit ``drift`` of ``"qtf"`` is a SceneError (``file``, ``key``) and a default must
    pick Newman.  Returns whether ``spec`` selects the correction formula."""
    correction = uses_correction_formula(spec)
    if correction and drift == "qtf":
        raise SceneError(file, key, "newman (or the default) with forces: viscous_drift: "
                         "{model: correction_formula} (eq. 6.6 corrects the mean drift "
                         "coefficients, which Newman's approximation uses)", "qtf")
    return correction


def linear_damping_matrix(ctx, D: np.ndarray) -> np.ndarray:
    """The vessel's linear damping, raised in surge and sway by ``extra_damping`` (fraction)
    for the correction-formula case (Wang (2016) section 6.6)."""
    return viscous_linear_damping(viscous_spec(ctx), D)


def viscous_linear_damping(spec, D: np.ndarray) -> np.ndarray:
    """``D`` raised in surge and sway by ``spec.extra_damping`` when ``spec`` selects the
    correction formula (Wang (2016) section 6.6, table 6.10); else ``D`` itself."""
    if spec is None or getattr(spec, "model", "none") != "correction_formula" \
            or not getattr(spec, "extra_damping", 0.0):
        return D
    from ..hydro.viscous_drift import extra_linear_damping
    return extra_linear_damping(D, increase=float(spec.extra_damping))
