"""Static current drag on the mooring lines, as an increment on the quasi-static mooring force.

The quasi-static catenary lines of :class:`~floatmoor.mooring.MooringSystem` carry no current.
:class:`LineCurrentStatics` gives, at a body pose, what the current changes in the static force
of every line: each active line is built twice as a FE line
(:func:`~floatmoor.mooring.fe.from_system.spec_from_linedef`, the scene's FE options and line
types), once in still water and once in the scene's current profile (Morison normal and
tangential drag on the nodes, ``cdn`` and ``cdt`` of the line types, the profile at each node's
depth, the same drag law as the time-domain FE lines), both solved statically for the fairlead
at that pose (:meth:`~floatmoor.mooring.fe.line.FELine.solve_static`).  The increment is the
difference of the two fairlead forces,

    dF_i(p) = F_FE,current,i(p) - F_FE,still,i(p),

summed into the generalised force on the body (moments about the displaced reference point,
earth axes: the convention of :meth:`~floatmoor.mooring.MooringSystem.force`).  Added to the
catenary force it gives the static line force in current; the FE discretisation (element
length, seabed springs) cancels to first order in the difference, and without current the
increment is exactly zero, so the catenary statics are recovered to round-off.

Seabed friction: the still line is solved without friction; the line in current with the
line's static friction (the displacement ramp of Lu (2012), when the line has a friction model)
measured from the still line's shape, i.e. the current is applied to a line laid in still
water.  Lines without seabed friction (``cb`` 0) slide freely, as in the time domain.

Used by the frequency domain's option ``line_current_drag``
(:mod:`floatmoor.analyses.frequency_domain`), which also takes the increment's change with the
pose (:meth:`LineCurrentStatics.linearise`, central differences) into its stiffness.  Each call
continues every line from its last solution (continuation), so successive poses of an
equilibrium iteration cost a few Newton iterations per line.  The lines in current are solved
with a trust radius on the nodal move of a Newton step (:data:`MAX_STEP`): the first solve from
the still-water shape moves a grounded chain tens of metres sideways along its softest modes,
where the damped Newton alone crawls.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.frames import rotation_matrix_into
from .body import scene_line_inputs
from .from_system import spec_from_linedef
from .line import FELine

__all__ = ["CurrentDragIncrement", "LineCurrentStatics", "MAX_STEP", "STIFFNESS_STEPS"]

MAX_STEP = 5.0
"""Trust radius (m) on the nodal move of a Newton step of the lines' statics
(:func:`~floatmoor.mooring.fe.kernels.static_newton`; in still water as well, so that without
current both solves take the same steps and the increment is exactly zero): the first solve
from the still-water shape moves a grounded chain tens of metres sideways along modes of 15-24
N/m, which the damped Newton alone crawls along (Floatel-like chains: 209-525 iterations; with
it 18-45)."""

STIFFNESS_STEPS = (0.5, 0.5, 0.5, 2e-3, 2e-3, 2e-3)
"""Central-difference steps (m, rad) of :meth:`LineCurrentStatics.linearise`: large against the
FE statics' tolerance (a few N of force over 1 m: ~1 N/m against drag stiffnesses of kN/m),
small against the scale of the drag's change (the line's sideways shape: tens of metres)."""


@dataclass(frozen=True, kw_only=True)
class CurrentDragIncrement:
    """The static current drag of the lines at one pose (SI units, earth axes).

    force : (6,) increment of the mooring's generalised force on the body (N, N m about the
        displaced reference point).
    line_force : (n_lines, 3) increment of each line's force on its fairlead (zero for failed
        lines).
    tension : (n_lines,) increment of the fairlead tension, ``|F_current| - |F_still|`` (N; NaN
        for failed lines).
    tension_current : (n_lines,) FE fairlead tension in current (N; NaN for failed lines).
    iterations : (n_lines,) Newton iterations of the line in current at this pose.
    """

    force: np.ndarray
    line_force: np.ndarray
    tension: np.ndarray
    tension_current: np.ndarray
    iterations: np.ndarray


class LineCurrentStatics:
    """Static current drag on the lines of a mooring system (module docstring).

    Parameters
    ----------
    system : MooringSystem
        The lines (only the active ones are modelled), water depth, density and gravity.
    current : dict
        ``current_z``, ``current_speed``, ``current_heading`` (:class:`~.config.FELineSpec`), as
        :func:`~floatmoor.mooring.fe.body.scene_line_inputs` samples the scene's profile.
    line_types : mapping name -> LineType, optional
        For the drag coefficients and diameters of the segments (default: the ``LineType``
        defaults, see :func:`~floatmoor.mooring.fe.from_system.spec_from_linedef`).
    spec_kw : dict, optional
        FE options of the lines (:meth:`~floatmoor.mooring.fe.options.FEOptions.spec_kw`:
        element length or count, seabed, friction); default 20 m elements.
    line_kw : dict, optional
        Keywords of :class:`~floatmoor.mooring.fe.line.FELine` (``fibre_law``: the axial law
        of fibre segments in statics).
    pose : (6,), optional
        Body pose at which the lines are first built (default zero).
    """

    def __init__(self, system, *, current: dict, line_types=None, spec_kw=None, line_kw=None,
                 pose=None, max_step: float = MAX_STEP):
        self.system = system
        self.index = [i for i, a in enumerate(system.active) if a]
        self.fairleads_body = np.array([system.lines[i].fairlead for i in self.index],
                                       float).reshape(len(self.index), 3)
        kw = dict(water_depth=system.water_depth, pose=pose, water_density=system.water_density,
                  gravity=system.gravity, line_types=line_types, **(spec_kw or {}))
        self.still = [FELine(spec_from_linedef(system.lines[i], **kw), **(line_kw or {}))
                      for i in self.index]
        self.in_current = [FELine(spec_from_linedef(system.lines[i], **kw, **current),
                                  **(line_kw or {}))
                           for i in self.index]
        self.max_step = float(max_step)
        self._R = np.zeros((3, 3))

    @classmethod
    def from_scene(cls, scene, system, *, pose=None, **kw) -> LineCurrentStatics | None:
        """The lines of ``system`` with the current, FE options and line types of ``scene``
        (``None`` when the scene has no current)."""
        inputs = scene_line_inputs(scene, system)
        if inputs["current"] is None:
            return None
        lm = getattr(system, "line_models", None)
        spec_kw = lm.options.spec_kw(system.water_depth) if lm is not None else {}
        # the keywords that matter in statics (the fibre law); the axial stiffness limit acts
        # in dynamics only
        line_kw = ({k: v for k, v in lm.options.line_kw().items()
                    if k in ("fibre_law", "fibre_time_constant")} if lm is not None else {})
        return cls(system, current=inputs["current"], line_types=inputs["line_types"],
                   spec_kw=spec_kw, line_kw=line_kw, pose=pose, **kw)

    def fairleads(self, pose) -> tuple[np.ndarray, np.ndarray]:
        """Earth positions of the modelled lines' fairleads (n, 3) and their arms from the
        body reference point (n, 3) at ``pose``."""
        pose = np.asarray(pose, float)
        rotation_matrix_into(pose[3], pose[4], pose[5], self._R)
        arm = self.fairleads_body @ self._R.T
        return pose[:3] + arm, arm

    def __call__(self, pose) -> CurrentDragIncrement:
        """The increment at ``pose`` (6,).

        Raises
        ------
        ConvergenceError
            FE statics that fail (naming the line and a remedy).
        """
        pos, arm = self.fairleads(pose)
        n = len(self.system.names)
        d_line = np.zeros((n, 3))
        d_t = np.full(n, np.nan)
        t_cur = np.full(n, np.nan)
        iters = np.zeros(n, np.int64)
        for k, i in enumerate(self.index):
            still = self.still[k].solve_static(fairlead=pos[k], friction=False,
                                               max_step=self.max_step)
            cur = self.in_current[k].solve_static(fairlead=pos[k], reference=still.positions,
                                                  max_step=self.max_step)
            d_line[i] = cur.fairlead_force - still.fairlead_force
            d_t[i] = cur.fairlead_tension - still.fairlead_tension
            t_cur[i] = cur.fairlead_tension
            iters[i] = cur.iterations
        force = np.zeros(6)
        force[:3] = d_line.sum(axis=0)
        force[3:] = np.cross(arm, d_line[self.index]).sum(axis=0)
        return CurrentDragIncrement(force=force, line_force=d_line, tension=d_t,
                                    tension_current=t_cur, iterations=iters)

    def linearise(self, pose, steps=STIFFNESS_STEPS) -> tuple[np.ndarray, np.ndarray]:
        """The drag increment's change with the pose by central differences about ``pose``:
        its stiffness ``K[i, j] = -d force_i / d pose_j`` (6, 6; not symmetric: the drag is
        not conservative) and the gradient of the fairlead tension increment
        ``d tension / d pose`` (n_lines, 6; NaN for failed lines).  Leaves the lines at
        ``pose``."""
        pose = np.asarray(pose, float)
        K = np.zeros((6, 6))
        g = np.zeros((len(self.system.names), 6))
        for j in range(6):
            dp = np.zeros(6)
            dp[j] = steps[j]
            ip, im = self(pose + dp), self(pose - dp)
            K[:, j] = -(ip.force - im.force) / (2.0 * steps[j])
            g[:, j] = (ip.tension - im.tension) / (2.0 * steps[j])
        self(pose)
        return K, g
