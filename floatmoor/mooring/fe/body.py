"""Several FE lines on one rigid body: the entry point for a coupled floater time step.

:class:`FEMooring` turns the body's pose and velocity at the end of a body step into fairlead
positions and velocities, advances every line (:meth:`FELine.advance`) and returns the
generalised force on the body: force (N, earth axes) and moment about the displaced reference
point (N m, earth axes), the convention of :meth:`floatmoor.mooring.MooringSystem.force`.
"""

from __future__ import annotations

import numpy as np

from ...core.frames import rotation_matrix_into
from .line import FELine

__all__ = ["FEMooring", "scene_line_inputs"]


def _current_kw(env, water_depth: float) -> dict | None:
    cur = getattr(env, "current", None)
    if cur is None:
        return None
    from ...metocean.current import current_speed

    z = np.linspace(-water_depth, 0.0, 61)
    if cur.profile == "piecewise_linear":
        z = np.union1d(z, np.clip(np.asarray(cur.z, float), -water_depth, 0.0))
    u = current_speed(cur, z, water_depth)
    return {"current_z": tuple(float(v) for v in z), "current_speed": tuple(float(v) for v in u),
            "current_heading": float(cur.heading)}


def scene_line_inputs(scene, system) -> dict:
    """What the FE lines take from a scene beyond the quasi-static ``system``: the keywords
    ``current`` and ``line_types`` of :meth:`FEMooring.from_system` (and of
    :func:`floatmoor.mooring.fe.decoupled.run_decoupled`), so that coupled runs and the
    decoupled ``floatmoor lines`` model the same lines.

    Parameters
    ----------
    scene : floatmoor.io.scene.Scene
        Its ``environment.current`` (profile sampled at 61 levels from the seabed to the
        surface, plus the levels of a piecewise-linear profile; speed m/s, heading rad).
    system : MooringSystem
        The lines, water depth and the line types its mooring section resolved
        (``system.line_types``: the default library extended with ``line_type_library`` and
        ``line_types``).

    Returns
    -------
    dict
        ``{"current": dict or None, "line_types": {name: LineType}}``.
    """
    return {"current": _current_kw(getattr(scene, "environment", None), system.water_depth),
            "line_types": dict(system.line_types)}


class FEMooring:
    """FE lines attached to one body.

    Parameters
    ----------
    specs : sequence of FELineSpec
        The lines; their ``fairlead`` is the earth position at ``pose0``.
    fairleads_body : (n, 3)
        Fairleads in body axes relative to the body reference point, m.
    pose0 : (6,), optional
        Pose at which the specs' fairleads are given (default zero).
    fast : bool
        Advance all lines in one numba call per body step (:mod:`.multi`; same kernels, same
        numbers) when every line uses the generalised-alpha integrator without wave
        kinematics; otherwise (or ``fast=False``) line by line through :meth:`FELine.advance`.
    **line_kw
        Passed to :class:`FELine` (``dynamic_ea``, ``axial_stiffness_limit``).
    """

    def __init__(self, specs, fairleads_body, pose0=None, *, fast: bool = True, **line_kw):
        self.lines = [FELine(s, **line_kw) for s in specs]
        self.fast = bool(fast)
        self._packed = None
        self.fairleads_body = np.asarray(fairleads_body, float).reshape(len(self.lines), 3)
        self._R = np.zeros((3, 3))
        self._pose0 = np.zeros(6) if pose0 is None else np.asarray(pose0, float)
        self._Q = np.zeros(6)
        self._line_forces = np.zeros((len(self.lines), 3))
        self.on = np.ones(len(self.lines), dtype=np.bool_)
        """(n,) bool: False for a released (failed) line (:meth:`release`)."""

    @classmethod
    def from_system(cls, system, line_models=None, *, pose=None, fast: bool = True,
                    current=None, line_types=None):
        """The FE lines of a :class:`~floatmoor.mooring.MooringSystem` as chosen by the scene.

        Parameters
        ----------
        system : MooringSystem
            As built by :func:`floatmoor.io.mooring_section.parse_mooring`.
        line_models : LineModels, optional
            Model choice and FE options (default ``system.line_models``; without it, every
            active line with default options).
        pose : (6,), optional
            Body pose of the initial fairlead positions (default zero), m and rad.
        current : dict, optional
            ``current_z``, ``current_speed``, ``current_heading`` of every line
            (:class:`FELineSpec`; default no current).
        line_types : mapping name -> LineType, optional
            The scene's line types, for the hydrodynamic coefficients (``cdn, cdt, can, cat``)
            of the segments (default ``LineType`` defaults, see
            :func:`~floatmoor.mooring.fe.from_system.spec_from_linedef`).

        Returns
        -------
        (FEMooring or None, list of str)
            The FE lines (``None`` when the scene has none) and their names; the remaining
            active lines stay quasi-static.  Statics are not solved yet
            (:meth:`solve_static`), :meth:`start` takes ``options.start_kw()``.
        """
        from .from_system import spec_from_linedef
        from .options import LineModels

        lm = line_models if line_models is not None else getattr(system, "line_models", None)
        if lm is None:
            lm = LineModels(models={n: "finite-element" for n in system.names})
        opts = lm.options
        names = [n for n, a in zip(system.names, system.active)
                 if a and lm.model_of(n) == "finite-element"]
        if not names:
            return None, []
        lines = [system.lines[system.names.index(n)] for n in names]
        specs = [spec_from_linedef(ld, water_depth=system.water_depth, pose=pose,
                                   water_density=system.water_density, gravity=system.gravity,
                                   line_types=line_types, **opts.spec_kw(system.water_depth),
                                   **(current or {}))
                 for ld in lines]
        fm = cls(specs, [ld.fairlead for ld in lines], pose0=pose, fast=fast, **opts.line_kw())
        fm.options = opts
        return fm, names

    def fairlead_kinematics(self, pose, velocity=None):
        """Earth positions (n, 3) and velocities (n, 3) of the fairleads; ``velocity`` is
        ``[u, v, w, omega_x, omega_y, omega_z]`` with the angular velocity in earth axes (rad/s;
        equal to the Euler-angle rates for small angles)."""
        pose = np.asarray(pose, float)
        rotation_matrix_into(pose[3], pose[4], pose[5], self._R)
        arm = self.fairleads_body @ self._R.T
        pos = pose[:3] + arm
        if velocity is None:
            return pos, np.zeros_like(pos)
        vel = np.asarray(velocity, float)
        return pos, vel[:3] + np.cross(vel[3:6], arm)

    def _sum(self, pose, forces):
        rotation_matrix_into(pose[3], pose[4], pose[5], self._R)
        arm = self.fairleads_body @ self._R.T
        self._Q[:3] = forces.sum(axis=0)
        self._Q[3:] = np.cross(arm, forces).sum(axis=0)
        return self._Q.copy()

    def solve_static(self, pose=None) -> np.ndarray:
        """Static equilibrium of every line with the body at ``pose``; returns the generalised
        force (6,)."""
        pose = self._pose0 if pose is None else np.asarray(pose, float)
        pos, _ = self.fairlead_kinematics(pose)
        for i, ln in enumerate(self.lines):
            if self.on[i]:
                self._line_forces[i] = ln.solve_static(fairlead=pos[i]).fairlead_force
            else:
                self._line_forces[i] = 0.0
        return self._sum(pose, self._line_forces)

    def release(self, line) -> None:
        """Release the fairlead end of ``line`` (index or name; line failure, ALS): from now on
        the line is not advanced any more, exerts no force on the body (zero in
        :attr:`line_forces` and the generalised force) and keeps its last state.  The coupled
        kernel (:mod:`floatmoor.solvers.fe_coupling`) does the same inside numba."""
        if isinstance(line, str):
            names = [ln.spec.name for ln in self.lines]
            if line not in names:
                raise KeyError(f"unknown FE line {line!r}; lines: {', '.join(names)}")
            line = names.index(line)
        self.on[int(line)] = False
        self._line_forces[int(line)] = 0.0

    def start(self, **kw):
        """Start the dynamics of every line (see :meth:`FELine.start`)."""
        for ln in self.lines:
            ln.start(**kw)
        self._packed = None
        if self.fast and all(ln.integrator == "generalized_alpha" and ln.waves is None
                             for ln in self.lines):
            from .multi import FEBody, line_list

            n = len(self.lines)
            self.counters = np.zeros((n, 2))
            body = FEBody(fair_b=np.ascontiguousarray(self.fairleads_body), R=np.zeros((3, 3)),
                          rf=np.zeros((n, 3)), vf=np.zeros((n, 3)), arm=np.zeros((n, 3)),
                          Q=self._Q, forces=self._line_forces, on=self.on,
                          fail=np.zeros(1, dtype=np.int64), counters=self.counters)
            self._packed = (body, line_list(self.lines))
            self._vel = np.zeros(6)

    def advance(self, t1, dt, pose1, velocity1, *, substeps: int = 1) -> np.ndarray:
        """Trial step of every line to ``t1`` with the body at ``pose1`` moving with
        ``velocity1``; returns the generalised force on the body (6,).  Repeatable until
        :meth:`accept`."""
        pose1 = np.asarray(pose1, float)
        if self._packed is not None:
            return self._advance_packed(float(t1), float(dt), pose1, velocity1, int(substeps))
        pos, vel = self.fairlead_kinematics(pose1, velocity1)
        for i, ln in enumerate(self.lines):
            if self.on[i]:
                self._line_forces[i] = ln.advance(t1, dt, pos[i], vel[i], substeps=substeps)
            else:
                self._line_forces[i] = 0.0
        return self._sum(pose1, self._line_forces)

    def _advance_packed(self, t1, dt, pose1, velocity1, substeps):
        from .multi import body_advance

        body, lines = self._packed
        vel = self._vel
        if velocity1 is None:
            vel[:] = 0.0
        else:
            vel[:] = velocity1
        st = body_advance(t1, dt, substeps, FELine.MAX_SPLIT, pose1, vel, body, lines)
        if st < 0:
            raise self.lines[int(body.fail[0])].step_error(st)
        for ln in self.lines:
            ln.trial(t1)
        return self._Q.copy()

    def accept(self):
        """Commit the trial state of every line."""
        if self._packed is None:
            for ln, on in zip(self.lines, self.on):
                if on:
                    ln.accept()
            return
        from .multi import body_accept

        if not self.lines[0].has_trial:
            raise RuntimeError("accept() without a preceding advance()")
        body_accept(self.on, self._packed[1])
        for ln, on in zip(self.lines, self.on):
            if on:
                ln.accept(copied=True)
            else:
                ln.reject()

    @property
    def newton_iterations(self) -> np.ndarray:
        """Newton iterations of every line since :meth:`start` (n,)."""
        if self._packed is None:
            return np.array([ln.newton_iterations for ln in self.lines])
        return self.counters[:, 0].astype(int)

    @property
    def line_forces(self) -> np.ndarray:
        """Force of every line on its fairlead at the last evaluation, (n, 3) N."""
        return self._line_forces.copy()
