"""Mooring system: quasi-static lines between fixed anchors and fairleads on one floating body.

Frames and conventions
----------------------
* Anchors are fixed in the earth frame (x, y horizontal, z up, origin at the mean water line).
* Fairleads are given in body axes relative to the body reference point.  For a pose
  ``p = [x, y, z, roll, pitch, yaw]`` a fairlead ``r_b`` is at ``p[:3] + R r_b`` with
  ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (:mod:`floatmoor.core.frames`).
* :meth:`MooringSystem.force` returns the force (earth axes) and the moment about the
  **displaced body reference point** ``p[:3]`` (earth axes) exerted by all lines on the body.
* :meth:`MooringSystem.stiffness` is ``K = -dQ/d(delta)`` with ``delta = [dt, theta]``: a small
  translation ``dt`` of the body and a small rotation ``theta`` (rotation vector, earth axes) about
  the displaced reference point, applied to the current pose.  At zero roll and pitch and zero
  yaw it equals minus the derivative with respect to the pose vector itself.  With moments about
  the displaced reference point the coupling ``K51`` equals ``K15`` (OC3: both about -2.82e6 N);
  moments about the fixed earth origin would add ``-V_total`` to ``K51`` (see
  ``docs/PUBLISHED_VALUES.md``).  ``K`` is analytic: per line the 2x2 catenary stiffness is turned
  into the 3x3 fairlead stiffness ``Kf`` and

      K_tt = Kf,  K_tr = -Kf [r]x,  K_rt = [r]x Kf,  K_rr = -[r]x Kf [r]x - [f]x [r]x

  with ``r = R r_b`` the fairlead arm, ``f`` the line force on the body and ``[a]x`` the cross-
  product matrix.  The last term (load stiffness) makes ``K_rr`` non-symmetric in general.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import xarray as xr
from numba import njit

from ..core.errors import ConvergenceError, FloatmoorWarning, SceneError
from ..core.frames import rotation_matrix_into
from .catenary import (
    OUT_HA,
    OUT_HF,
    OUT_ITER,
    OUT_K11,
    OUT_K12,
    OUT_K21,
    OUT_K22,
    OUT_LB,
    OUT_SIZE,
    OUT_VA,
    OUT_VF,
    STATUS_MESSAGES,
    line_kernel,
    line_profile,
)
from .fibre import FibreModel
from .fibre_system import (
    DEFAULT_TIME_CONSTANT,
    FibreSegments,
    iterate_secant,
    linearised_lines,
    linearised_segments,
)
from .line_geometry import add_line_force, fairlead_geometry

__all__ = ["Segment", "LineDef", "MooringSystem", "system_force_kernel", "CatenaryArrays"]


@dataclass(frozen=True, kw_only=True)
class Segment:
    """One homogeneous segment of a line (SI units).

    ``point_load`` acts at the segment's upper joint (towards the fairlead): N, positive down
    (clump weight), negative for a buoy.  It is ignored on the last (fairlead) segment.
    """

    length: float
    ea: float
    w: float
    mbs: float = math.inf
    line_type: str = ""
    point_load: float = 0.0
    ea_dynamic: float | None = None
    mass_per_length: float = 0.0
    diameter: float = 0.0
    fibre: FibreModel | None = None


@dataclass(frozen=True, kw_only=True)
class LineDef:
    """A line from a fixed anchor (earth coordinates, m) to a fairlead (body coordinates, m);
    segments are listed from the anchor to the fairlead."""

    name: str
    anchor: tuple
    fairlead: tuple
    segments: tuple
    cb: float = 0.0
    anchor_on_seabed: bool = True

    @property
    def mbs(self) -> float:
        """MBS of the weakest segment (N); nan when a segment's MBS is unknown (the weakest
        could be that one)."""
        vals = [s.mbs for s in self.segments]
        return math.nan if any(math.isnan(v) for v in vals) else min(vals)


# --------------------------------------------------------------------------------------------
# numba kernel for the whole system
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _cross_matrix(a, out):
    out[0, 0] = 0.0
    out[0, 1] = -a[2]
    out[0, 2] = a[1]
    out[1, 0] = a[2]
    out[1, 1] = 0.0
    out[1, 2] = -a[0]
    out[2, 0] = -a[1]
    out[2, 1] = a[0]
    out[2, 2] = 0.0


@njit(cache=True)
def system_force_kernel(pose, anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start, cb,
                        seabed, active, warm, want_k, work, rot, line_out, force, stiff):
    """Force (and optionally stiffness) of all lines on the body at ``pose``.  No allocation.

    Parameters
    ----------
    pose : (6,) body pose.
    anchors : (n, 3) earth coordinates; fairleads : (n, 3) body coordinates.
    seg_L, seg_EA, seg_w, seg_P : (m,) segment data, lines stored consecutively from the anchor.
    line_start : (n+1,) int, segments of line i are ``line_start[i]:line_start[i+1]``.
    cb : (n,) friction coefficients; seabed : (n,) bool, anchor on the seabed.
    active : (n,) bool, False for a failed (removed) line.
    warm : (n, 2) HF, VF of the previous solution (read as warm start, then overwritten).
    want_k : bool, also fill ``stiff``.
    work : (>= 60,) scratch; rot : (3, 3) scratch.
    line_out : (n, OUT_SIZE) per-line catenary output.
    force : (6,) output, overwritten: force (N) and moment about the displaced reference point
        (N m), earth axes.
    stiff : (6, 6) output, overwritten when ``want_k``.

    Returns
    -------
    int
        -1 when all lines converged, else the index of the first line that failed (its status
        code is in ``line_out[i, OUT_ITER]``).
    """
    rotation_matrix_into(pose[3], pose[4], pose[5], rot)
    for k in range(6):
        force[k] = 0.0
    if want_k:
        for a in range(6):
            for b in range(6):
                stiff[a, b] = 0.0
    cw = work[24:48]
    out = work[48:48 + OUT_SIZE]
    n = anchors.shape[0]
    for i in range(n):
        if not active[i]:
            for k in range(OUT_SIZE):
                line_out[i, k] = 0.0
            continue
        r0, r1, r2, h, dz, ux, uy = fairlead_geometry(pose, rot, fairleads, anchors, i)
        st = line_kernel(h, dz, seg_L, seg_EA, seg_w, seg_P, line_start[i], line_start[i + 1],
                         cb[i], seabed[i], warm[i, 0], warm[i, 1], cw, out)
        if st != 0 and warm[i, 0] > 0.0:
            st = line_kernel(h, dz, seg_L, seg_EA, seg_w, seg_P, line_start[i],
                             line_start[i + 1], cb[i], seabed[i], 0.0, 0.0, cw, out)
        if st != 0:
            line_out[i, OUT_ITER] = st
            return i
        for k in range(OUT_SIZE):
            line_out[i, k] = out[k]
        HF = out[OUT_HF]
        VF = out[OUT_VF]
        warm[i, 0] = HF
        warm[i, 1] = VF
        add_line_force(force, HF, VF, ux, uy, r0, r1, r2)
        if want_k:
            K11 = out[OUT_K11]
            K12 = out[OUT_K12]
            K21 = out[OUT_K21]
            K22 = out[OUT_K22]
            hh = max(h, 1e-12)
            kf = work[0:9]
            # Kf = [[K11 uu^T + HF/h (I - uu^T), K12 u], [K21 u^T, K22]]
            g = HF / hh
            kf[0] = K11 * ux * ux + g * (1.0 - ux * ux)
            kf[1] = K11 * ux * uy - g * ux * uy
            kf[2] = K12 * ux
            kf[3] = kf[1]
            kf[4] = K11 * uy * uy + g * (1.0 - uy * uy)
            kf[5] = K12 * uy
            kf[6] = K21 * ux
            kf[7] = K21 * uy
            kf[8] = K22
            # assemble with cross-product matrices
            rv = work[9:12]
            fv = work[12:15]
            rv[0] = r0
            rv[1] = r1
            rv[2] = r2
            fv[0] = -HF * ux   # the line force added above (add_line_force)
            fv[1] = -HF * uy
            fv[2] = -VF
            for a in range(3):
                for b in range(3):
                    kab = kf[3 * a + b]
                    stiff[a, b] += kab
            # Kf [r]x  and [r]x Kf  and [r]x Kf [r]x, [f]x [r]x
            for a in range(3):
                for b in range(3):
                    # (Kf [r]x)[a, b] = sum_c Kf[a, c] rx[c, b]
                    s1 = 0.0
                    s2 = 0.0
                    for c in range(3):
                        rx_cb = _cx(rv, c, b)
                        rx_ac = _cx(rv, a, c)
                        s1 += kf[3 * a + c] * rx_cb
                        s2 += rx_ac * kf[3 * c + b]
                    stiff[a, 3 + b] -= s1
                    stiff[3 + a, b] += s2
            for a in range(3):
                for b in range(3):
                    s3 = 0.0
                    s4 = 0.0
                    for c in range(3):
                        # ([r]x Kf [r]x)[a, b] = sum_c ([r]x Kf)[a, c] rx[c, b]
                        t = 0.0
                        for e in range(3):
                            t += _cx(rv, a, e) * kf[3 * e + c]
                        s3 += t * _cx(rv, c, b)
                        s4 += _cx(fv, a, c) * _cx(rv, c, b)
                    stiff[3 + a, 3 + b] += -s3 - s4
    return -1


class CatenaryArrays(NamedTuple):
    """The lines of a :class:`MooringSystem` as the numba bundle of the time loop (the
    arguments of :func:`system_force_kernel` from ``anchors`` to ``seabed``)."""

    anchors: np.ndarray
    fairleads: np.ndarray
    seg_L: np.ndarray
    seg_EA: np.ndarray
    seg_w: np.ndarray
    seg_P: np.ndarray
    line_start: np.ndarray
    cb: np.ndarray
    seabed: np.ndarray


@njit(cache=True)
def _cx(v, a, b):
    """Entry (a, b) of the cross-product matrix of v."""
    if a == b:
        return 0.0
    if a == 0:
        return -v[2] if b == 1 else v[1]
    if a == 1:
        return v[2] if b == 0 else -v[0]
    return -v[1] if b == 0 else v[0]


# --------------------------------------------------------------------------------------------
# Python API
# --------------------------------------------------------------------------------------------
class MooringSystem:
    """Quasi-static mooring system of one floating body.

    Parameters
    ----------
    lines : sequence of LineDef
    water_depth : float
        Water depth, m (seabed at ``z = -water_depth``).
    water_density, gravity : float
        Used only to report; submerged weights are already in the segments.
    source : str
        Where the definition came from (file path), for messages.
    failed : names of failed (removed) lines.
    line_models : the line model chosen per line (quasi-static or finite-element, with the FE
        options), :class:`floatmoor.mooring.fe.options.LineModels`; None means quasi-static.
        Carried over by :meth:`without_lines` and :meth:`with_dynamic_ea`.
    line_types : mapping name -> :class:`~floatmoor.mooring.line_types.LineType`, optional
        The line types the segments name, as the mooring section resolved them (their
        hydrodynamic coefficients are used by finite-element lines); carried over like
        ``line_models``.
    fibre_time_constant : float
        s, time constant of the slowly varying tension about which the quasi-static time
        domain linearises the fibre segments (:func:`floatmoor.mooring.fibre_system.
        fibre_track`; ``inf``: about the static mean for the whole run); carried over like
        ``line_models``.

    Notes
    -----
    See the module docstring for frames, the reference point of moments and of the stiffness.
    """

    def __init__(self, lines: Sequence[LineDef], *, water_depth: float, water_density: float = 1025.0,
                 gravity: float = 9.80665, source: str = "", failed: Iterable[str] = (),
                 line_models=None, line_types=None,
                 fibre_time_constant: float = DEFAULT_TIME_CONSTANT):
        if not lines:
            raise ValueError("a mooring system needs at least one line")
        self.lines = tuple(lines)
        self.line_models = line_models
        self.line_types = dict(line_types or {})
        self.fibre_time_constant = float(fibre_time_constant)
        names = [l.name for l in self.lines]
        if len(set(names)) != len(names):
            raise ValueError(f"line names must be unique: {names}")
        self.water_depth = float(water_depth)
        self.water_density = float(water_density)
        self.gravity = float(gravity)
        self.source = source
        failed = tuple(failed)
        for nme in failed:
            if nme not in names:
                raise KeyError(f"unknown line {nme!r}; lines: {', '.join(names)}")
        self.failed = failed
        n = len(self.lines)
        self.names = tuple(names)
        self.anchors = np.array([l.anchor for l in self.lines], float).reshape(n, 3)
        self.fairleads = np.array([l.fairlead for l in self.lines], float).reshape(n, 3)
        segs = [s for l in self.lines for s in l.segments]
        self.seg_L = np.array([s.length for s in segs], float)
        self.seg_EA = np.array([s.ea for s in segs], float)
        self.seg_w = np.array([s.w for s in segs], float)
        self.seg_P = np.array([s.point_load for s in segs], float)
        self.line_start = np.zeros(n + 1, np.int64)
        self.line_start[1:] = np.cumsum([len(l.segments) for l in self.lines])
        self.cb = np.array([l.cb for l in self.lines], float)
        self.seabed = np.array([l.anchor_on_seabed for l in self.lines], np.bool_)
        self.active = np.array([l.name not in failed for l in self.lines], np.bool_)
        self.mbs = np.array([l.mbs for l in self.lines], float)
        self.warm = np.zeros((n, 2))
        self._work = np.zeros(64)
        self._rot = np.zeros((3, 3))
        self._line_out = np.zeros((n, OUT_SIZE))
        self._force = np.zeros(6)
        self._stiff = np.zeros((6, 6))
        self.fibre_segments = FibreSegments.of(segs)
        if self.fibre_segments is not None:
            self.fibre_segments.bed_in(self.seg_L, self.seg_w)

    # -- line failure -------------------------------------------------------------------------
    def without_lines(self, names: Iterable[str]) -> MooringSystem:
        """A copy with the named lines removed (failed), e.g. for an ALS check."""
        names = [names] if isinstance(names, str) else list(names)
        for nme in names:
            if nme not in self.names:
                raise KeyError(f"unknown line {nme!r}; lines: {', '.join(self.names)}")
        return MooringSystem(self.lines, water_depth=self.water_depth,
                             water_density=self.water_density, gravity=self.gravity,
                             source=self.source, failed=tuple(self.failed) + tuple(names),
                             line_models=self.line_models, line_types=self.line_types,
                             fibre_time_constant=self.fibre_time_constant)

    remove_lines = without_lines

    def only_lines(self, names: Iterable[str]) -> MooringSystem:
        """A copy with only the named lines (in this system's order), e.g. to run or export one
        line on its own."""
        names = [names] if isinstance(names, str) else list(names)
        for nme in names:
            if nme not in self.names:
                raise KeyError(f"unknown line {nme!r}; lines: {', '.join(self.names)}")
        return MooringSystem([ln for ln in self.lines if ln.name in names],
                             water_depth=self.water_depth, water_density=self.water_density,
                             gravity=self.gravity, source=self.source,
                             failed=tuple(f for f in self.failed if f in names),
                             line_models=self.line_models, line_types=self.line_types,
                             fibre_time_constant=self.fibre_time_constant)

    def with_dynamic_ea(self) -> MooringSystem:
        """A copy whose segments use their dynamic axial stiffness (``ea_dynamic``, e.g. for
        polyester) instead of the static one; segments without one keep ``ea``."""
        from dataclasses import replace
        lines = [replace(l, segments=tuple(replace(s, ea=s.ea_dynamic or s.ea) for s in l.segments))
                 for l in self.lines]
        return MooringSystem(lines, water_depth=self.water_depth, water_density=self.water_density,
                             gravity=self.gravity, source=self.source, failed=self.failed,
                             line_models=self.line_models, line_types=self.line_types,
                             fibre_time_constant=self.fibre_time_constant)

    def unknown_mbs(self) -> str:
        """Empty when every line has a known MBS; else which line types have none, where they
        came from and what to set (the text of the design-check errors)."""
        types = {}
        for ln in self.lines:
            for sg in ln.segments:
                if math.isnan(sg.mbs):
                    types.setdefault(sg.line_type, []).append(ln.name)
        if not types:
            return ""
        parts = []
        for name, lines in types.items():
            lt = self.line_types.get(name)
            src = getattr(lt, "source", "") or "unknown origin"
            where = (str(self.source) if str(self.source).endswith((".yaml", ".yml")) else
                     f"the floatmoor mooring file imported from {self.source} (its "
                     f"'mbs: unknown')")
            parts.append(f"line type {name!r} (from {src}; lines {', '.join(dict.fromkeys(lines))})"
                         f" has no MBS: set line_types.{name}.mbs (N) in {where}")
        return "; ".join(parts)

    def mbs_attrs(self) -> dict:
        """netCDF attributes of an ``mbs(line)`` variable (``unknown``: the
        :meth:`unknown_mbs` text, read back by the design checks)."""
        out = {"units": "N", "long_name": "minimum breaking strength (weakest segment; nan: "
               "unknown)"}
        text = self.unknown_mbs()
        if text:
            out["unknown"] = text
        return out

    def require_mbs(self, purpose: str) -> None:
        """SceneError when a line's MBS is unknown (``mbs: unknown``, e.g. an imported MoorDyn
        or MAP++ file): ``purpose`` names the design check that needs it."""
        text = self.unknown_mbs()
        if text:
            name = next(sg.line_type for ln in self.lines for sg in ln.segments
                        if math.isnan(sg.mbs))
            raise SceneError(self.source, f"line_types.{name}.mbs",
                             f"the minimum breaking strength (N) of every line type, needed by "
                             f"{purpose}", "unknown", text)

    @property
    def has_fibre(self) -> bool:
        """True when a segment has a fibre-rope model (load-dependent stiffness)."""
        return self.fibre_segments is not None

    def with_fibre_bound(self, bound: str) -> MooringSystem:
        """A copy whose fibre models carry the stiffness bound ``lower`` or ``upper``
        (:meth:`floatmoor.mooring.fibre.FibreModel.lower`); itself without fibre segments."""
        if not self.has_fibre:
            return self
        from dataclasses import replace
        pick = {"lower": lambda m: m.lower(), "upper": lambda m: m.upper(),
                "nominal": lambda m: replace(m, bound="nominal")}[bound]
        lines = [replace(l, segments=tuple(replace(s, fibre=pick(s.fibre)) if s.fibre is not None
                                           else s for s in l.segments)) for l in self.lines]
        return self._copy_with(lines)

    def linearised_fibre(self, pose, rule: str = "dynamic") -> MooringSystem:
        """A constant-EA copy for the dynamics about ``pose`` (the mean position): every fibre
        segment gets its dynamic stiffness at its mean tension there (``rule="tangent"``: the
        working curve's tangent) with its length adjusted so that the tensions at ``pose``
        are unchanged (:mod:`floatmoor.mooring.fibre_system`). Itself without fibre segments."""
        if not self.has_fibre:
            return self
        self._evaluate(pose, False)
        out = self._copy_with(linearised_lines(self, rule))
        out.warm[:] = self.warm
        return out

    def _copy_with(self, lines) -> MooringSystem:
        return MooringSystem(lines, water_depth=self.water_depth, water_density=self.water_density,
                             gravity=self.gravity, source=self.source, failed=self.failed,
                             line_models=self.line_models, line_types=self.line_types,
                             fibre_time_constant=self.fibre_time_constant)

    @property
    def n_lines(self) -> int:
        return len(self.lines)

    # -- evaluation -----------------------------------------------------------------------------
    def _evaluate(self, pose, want_k):
        pose = np.ascontiguousarray(pose, dtype=float).reshape(6)
        if self.fibre_segments is not None:
            self._evaluate_fibre(pose, want_k)
            return
        bad = system_force_kernel(pose, self.anchors, self.fairleads, self.seg_L, self.seg_EA,
                                  self.seg_w, self.seg_P, self.line_start, self.cb, self.seabed,
                                  self.active, self.warm, want_k, self._work, self._rot,
                                  self._line_out, self._force, self._stiff)
        self._raise_failed(bad, pose)

    def _evaluate_fibre(self, pose, want_k):
        """Fibre segments: the working curve through the secant EA iterated to the segments'
        mean tensions (:func:`floatmoor.mooring.fibre_system.iterate_secant`); the stiffness
        is that of the working curve's tangent about those tensions."""
        def run(L, EA, w, want, line_out, force, warm):
            bad = system_force_kernel(pose, self.anchors, self.fairleads, L, EA, w, self.seg_P,
                                      self.line_start, self.cb, self.seabed, self.active, warm,
                                      want, self._work, self._rot, line_out, force, self._stiff)
            self._raise_failed(bad, pose, line_out)

        def secant_step():
            run(self.seg_L, self.seg_EA, self.seg_w, False, self._line_out, self._force, self.warm)

        secant_step()
        iterate_secant(self, secant_step)
        if want_k:
            L, EA, w = linearised_segments(self, "tangent")
            run(L, EA, w, True, np.zeros_like(self._line_out), np.zeros(6), self.warm.copy())

    def _raise_failed(self, bad, pose, line_out=None):
        line_out = self._line_out if line_out is None else line_out
        if bad >= 0:
            self._line_out[bad, OUT_ITER] = line_out[bad, OUT_ITER]
            status = int(self._line_out[bad, OUT_ITER])
            raise ConvergenceError(f"catenary: {STATUS_MESSAGES.get(status, status)}",
                                   where=f"line {self.names[bad]!r} at pose {pose.tolist()}",
                                   remedy="check anchor position, line length and the pose; "
                                          "a pose far from equilibrium may overstretch the line")

    def force(self, pose) -> np.ndarray:
        """Force (N, earth axes) and moment about the displaced reference point (N m) of all
        lines on the body at ``pose`` = [x, y, z, roll, pitch, yaw] (m, rad)."""
        self._evaluate(pose, False)
        return self._force.copy()

    def stiffness(self, pose=None) -> np.ndarray:
        """Analytic 6x6 stiffness ``-dQ/d[dt, theta]`` (N/m, N, N m/rad) about the displaced
        reference point (see the module docstring)."""
        self._evaluate(np.zeros(6) if pose is None else pose, True)
        return self._stiff.copy()

    def force_and_stiffness(self, pose):
        """Both at once (one catenary solve per line)."""
        self._evaluate(pose, True)
        return self._force.copy(), self._stiff.copy()

    def catenary_arrays(self) -> CatenaryArrays:
        """The lines as a :class:`CatenaryArrays` bundle (C-contiguous writeable copies)."""
        c = np.ascontiguousarray
        return CatenaryArrays(c(self.anchors, float).copy(), c(self.fairleads, float).copy(),
                              self.seg_L.copy(), self.seg_EA.copy(), self.seg_w.copy(),
                              self.seg_P.copy(), c(self.line_start, np.int64).copy(),
                              self.cb.copy(), c(self.seabed, np.bool_).copy())

    def fairlead_positions(self, pose) -> np.ndarray:
        """Earth coordinates of the fairleads at ``pose``, (n, 3)."""
        rot = np.zeros((3, 3))
        rotation_matrix_into(float(pose[3]), float(pose[4]), float(pose[5]), rot)
        return np.asarray(pose[:3], float) + self.fairleads @ rot.T

    def tensions(self, pose=None, *, warn: bool = False) -> xr.Dataset:
        """Per-line results at ``pose`` as an xarray Dataset (dimension ``line``).

        Variables: ``fairlead_tension``, ``anchor_tension``, ``horizontal_fairlead``,
        ``vertical_fairlead``, ``horizontal_anchor``, ``vertical_anchor`` (N),
        ``fairlead_angle`` (deg from horizontal), ``grounded_length`` (m), ``mbs`` (N),
        ``utilisation`` (fairlead tension / MBS), ``failed`` (bool).
        With ``warn=True`` a :class:`FloatmoorWarning` names every line above its MBS.
        """
        pose = np.zeros(6) if pose is None else np.asarray(pose, float)
        self._evaluate(pose, False)
        o = self._line_out
        hf, vf, ha, va = o[:, OUT_HF], o[:, OUT_VF], o[:, OUT_HA], o[:, OUT_VA]
        tf = np.hypot(hf, vf)
        ta = np.hypot(ha, va)
        ang = np.degrees(np.arctan2(vf, hf))
        util = tf / self.mbs
        failed = ~self.active
        def var(x, units, long_name):
            x = np.where(failed, np.nan, x) if x.dtype.kind == "f" else x
            return ("line", x, {"units": units, "long_name": long_name})
        ds = xr.Dataset(
            {"fairlead_tension": var(tf, "N", "tension at the fairlead"),
             "anchor_tension": var(ta, "N", "tension at the anchor"),
             "horizontal_fairlead": var(hf, "N", "horizontal tension component at the fairlead"),
             "vertical_fairlead": var(vf, "N", "vertical tension component at the fairlead"),
             "horizontal_anchor": var(ha, "N", "horizontal tension component at the anchor"),
             "vertical_anchor": var(va, "N", "vertical tension component at the anchor (up)"),
             "fairlead_angle": var(ang, "deg", "line angle at the fairlead from horizontal"),
             "grounded_length": var(o[:, OUT_LB], "m", "unstretched length on the seabed"),
             "mbs": ("line", self.mbs, self.mbs_attrs()),
             "utilisation": var(util, "1", "fairlead tension / MBS"),
             "failed": ("line", failed, {"long_name": "line removed (failed)"})},
            coords={"line": list(self.names)},
            attrs={"pose": list(map(float, pose)), "source": self.source})
        if warn:
            for i in np.nonzero(~failed & (util > 1.0))[0]:
                warnings.warn(f"line {self.names[i]!r}: fairlead tension {tf[i] / 1e3:.1f} kN "
                              f"exceeds its MBS {self.mbs[i] / 1e3:.1f} kN", FloatmoorWarning,
                              stacklevel=2)
        return ds

    def line_profile(self, name: str, pose=None, n_per_segment: int = 51) -> dict:
        """Shape of one line in earth coordinates at ``pose``: dict of arrays ``s`` (m along the
        unstretched line from the anchor), ``x, y, z`` (m), ``tension`` (N)."""
        i = self.names.index(name)
        pose = np.zeros(6) if pose is None else np.asarray(pose, float)
        self._evaluate(pose, False)
        o = self._line_out[i]
        a, b = self.line_start[i], self.line_start[i + 1]
        p = line_profile(o[OUT_HF], o[OUT_VF], self.seg_L[a:b], self.seg_EA[a:b],
                         self.seg_w[a:b], self.seg_P[a:b], self.cb[i], bool(self.seabed[i]),
                         n=n_per_segment)
        fl = self.fairlead_positions(pose)[i]
        d = fl[:2] - self.anchors[i, :2]
        h = np.hypot(*d)
        u = d / h if h > 0 else np.array([1.0, 0.0])
        return dict(s=p["s"], x=self.anchors[i, 0] + u[0] * p["x"],
                    y=self.anchors[i, 1] + u[1] * p["x"], z=self.anchors[i, 2] + p["z"],
                    tension=p["tension"])

    def __repr__(self):
        return (f"MooringSystem({self.n_lines} lines, depth {self.water_depth:g} m, "
                f"failed={list(self.failed)})")
