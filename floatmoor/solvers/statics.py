"""Static equilibrium of a moored body and restoring curves (the numerics, on a mooring system).

The scene-level function is :func:`floatmoor.equilibrium` (:mod:`floatmoor.analyses.statics`):
it builds the scene and calls :func:`solve_equilibrium` with the vessel's restoring and the net
buoyancy.

The static balance on the body, with moments about the body reference point, is

    R(p) = F_mooring(p) - K_h p + F_ext = 0

``F_mooring`` is the quasi-static mooring force (:class:`floatmoor.mooring.MooringSystem`), ``K_h``
the linear hydrostatic restoring matrix (6x6, about the same reference point, including any
additional springs such as the OC3 yaw spring) and ``F_ext`` a constant external force: wind,
current and mean wave drift, plus the net buoyancy at the zero pose (``rho g V - m g`` in heave)
when the body's weight and buoyancy do not balance there.  Newton's method on the free DOFs uses
the analytic Jacobian ``-(K_mooring(p) + K_h)`` with a backtracking line search and a step limit;
it raises :class:`~floatmoor.core.errors.ConvergenceError` naming the DOF with the largest
residual when it does not converge.

Note: the mooring stiffness is the derivative with respect to a small rotation vector about the
displaced reference point; for the Euler angles of the pose it is exact at zero roll and pitch
and an excellent Newton Jacobian otherwise (convergence is checked on the residual itself).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from ..core.dofs import DOF_NAMES, DOF_UNITS, FORCE_UNITS, dof_index
from ..core.errors import ConvergenceError, NumericalError
from ..mooring.system import MooringSystem

__all__ = ["solve_equilibrium", "EquilibriumResult", "restoring_curve"]


@dataclass(frozen=True, kw_only=True)
class EquilibriumResult:
    """Result of :func:`solve_equilibrium` (SI units, moments about the body reference point).

    Attributes
    ----------
    pose : (6,) equilibrium pose [m, m, m, rad, rad, rad].
    mooring_force : (6,) mooring force at the equilibrium.
    residual : (6,) remaining out-of-balance force on the free DOFs (zero on fixed DOFs).
    mooring_stiffness : (6, 6) analytic mooring stiffness at the equilibrium.
    total_stiffness : (6, 6) mooring plus hydrostatic stiffness.
    iterations : int
    tensions : xarray.Dataset of per-line results at the equilibrium.
    free_dofs : tuple of DOF names solved for.
    """

    pose: np.ndarray
    mooring_force: np.ndarray
    residual: np.ndarray
    mooring_stiffness: np.ndarray
    total_stiffness: np.ndarray
    iterations: int
    tensions: xr.Dataset = field(repr=False)
    free_dofs: tuple = DOF_NAMES

    def summary(self) -> str:
        """Plain-text report: equilibrium pose, per-line tensions, 6x6 mooring stiffness."""
        lines = [f"Static equilibrium ({self.iterations} Newton iterations; free DOFs: "
                 f"{', '.join(self.free_dofs)})"]
        for i, name in enumerate(DOF_NAMES):
            v = self.pose[i]
            txt = f"{v:12.4f} m" if i < 3 else f"{v:12.6f} rad ({math.degrees(v):9.4f} deg)"
            lines.append(f"  {name:6s} {txt}")
        t = self.tensions
        lines.append("")
        lines.append("  line        T fairlead   T anchor    angle  grounded   MBS       T/MBS")
        lines.append("                  kN          kN        deg      m        kN")
        for i, name in enumerate(t["line"].values):
            if bool(t["failed"].values[i]):
                lines.append(f"  {str(name):10s}  failed (removed)")
                continue
            lines.append(
                f"  {str(name):10s} {t['fairlead_tension'].values[i] / 1e3:10.1f} "
                f"{t['anchor_tension'].values[i] / 1e3:10.1f} {t['fairlead_angle'].values[i]:8.2f} "
                f"{t['grounded_length'].values[i]:8.1f} {t['mbs'].values[i] / 1e3:9.0f} "
                f"{t['utilisation'].values[i]:8.3f}")
        lines.append("")
        lines.append("  mooring stiffness at the equilibrium (N/m, N/rad, N m/rad; moments about "
                     "the displaced reference point):")
        lines.append("          " + "".join(f"{n:>12s}" for n in DOF_NAMES))
        for i, name in enumerate(DOF_NAMES):
            lines.append(f"  {name:6s}  " + "".join(f"{v:12.4g}" for v in self.mooring_stiffness[i]))
        return "\n".join(lines)

    def to_dataset(self) -> xr.Dataset:
        """The result as an xarray Dataset (pose, forces, stiffness and line tensions)."""
        ds = self.tensions.copy()
        ds["pose"] = ("dof", self.pose, {"long_name": "equilibrium pose",
                                         "units": ", ".join(DOF_UNITS)})
        ds["mooring_force"] = ("dof", self.mooring_force,
                               {"long_name": "mooring force on the body (moments about the "
                                             "displaced reference point)",
                                "units": ", ".join(FORCE_UNITS)})
        ds["mooring_stiffness"] = (("dof", "dof_j"), self.mooring_stiffness,
                                   {"long_name": "analytic mooring stiffness -dQ/d(dt, theta)"})
        ds["total_stiffness"] = (("dof", "dof_j"), self.total_stiffness,
                                 {"long_name": "mooring plus hydrostatic stiffness"})
        ds = ds.assign_coords(dof=list(DOF_NAMES), dof_j=list(DOF_NAMES))
        ds.attrs["iterations"] = self.iterations
        ds.attrs["free_dofs"] = list(self.free_dofs)
        return ds


def _free_indices(dofs) -> np.ndarray:
    if dofs is None:
        return np.arange(6)
    idx = []
    for d in dofs:
        idx.append(dof_index(d) if isinstance(d, str) else int(d))
    idx = sorted(set(idx))
    if not idx or any(i < 0 or i > 5 for i in idx):
        raise ValueError(f"dofs must name DOFs among {DOF_NAMES}: {dofs}")
    return np.array(idx)


def solve_equilibrium(mooring: MooringSystem, *, hydrostatic_stiffness=None, external_force=None,
                x0=None, dofs: Sequence[str] | None = None, tol_translation: float = 1e-6,
                tol_rotation: float = 1e-8, max_iter: int = 60, max_step_translation: float = 20.0,
                max_step_rotation: float = 0.1) -> EquilibriumResult:
    """Static equilibrium pose of a moored body.

    Parameters
    ----------
    mooring : MooringSystem
    hydrostatic_stiffness : (6, 6) array, optional
        Linear hydrostatic (plus additional) restoring matrix about the body reference point,
        N/m, N/rad, N m/rad.  Default zero (then heave, roll and pitch are held by the lines only,
        so give ``dofs`` to fix them).
    external_force : (6,) array, optional
        Constant external force and moment on the body, N and N m (moments about the reference
        point), including the net buoyancy at the zero pose if it does not balance the weight.
    x0 : (6,) array, optional
        Start pose (default zero); DOFs not in ``dofs`` stay at their ``x0`` value.
    dofs : sequence of DOF names, optional
        Free DOFs (default all six), e.g. ``("surge", "sway", "yaw")``.
    tol_translation, tol_rotation : float
        Convergence on the Newton step, m and rad.
    max_iter : int
    max_step_translation, max_step_rotation : float
        Step limits, m and rad.

    Returns
    -------
    EquilibriumResult

    Raises
    ------
    ConvergenceError
        No equilibrium within ``max_iter`` iterations (names the DOF with the largest residual).
    """
    Kh = np.zeros((6, 6)) if hydrostatic_stiffness is None else np.asarray(hydrostatic_stiffness, float)
    if Kh.shape != (6, 6):
        raise ValueError(f"hydrostatic_stiffness must be 6x6, got shape {Kh.shape}")
    Fe = np.zeros(6) if external_force is None else np.asarray(external_force, float).reshape(6)
    p = np.zeros(6) if x0 is None else np.array(x0, float).reshape(6)
    free = _free_indices(dofs)
    is_rot = free >= 3

    def residual(pose):
        fm, km = mooring.force_and_stiffness(pose)
        return fm - Kh @ pose + Fe, fm, km

    r, fm, km = residual(p)
    it = 0
    converged = False
    while it < max_iter:
        it += 1
        J = (km + Kh)[np.ix_(free, free)]
        try:
            step = np.linalg.solve(J, r[free])
        except np.linalg.LinAlgError:
            raise ConvergenceError("singular stiffness in the equilibrium iteration",
                                   where="statics",
                                   remedy="a free DOF has no restoring stiffness: give the "
                                          "hydrostatic stiffness or fix that DOF (dofs=...)") from None
        # step limits
        scale = 1.0
        tmax = np.abs(step[~is_rot]).max() if np.any(~is_rot) else 0.0
        rmax = np.abs(step[is_rot]).max() if np.any(is_rot) else 0.0
        if tmax > max_step_translation:
            scale = min(scale, max_step_translation / tmax)
        if rmax > max_step_rotation:
            scale = min(scale, max_step_rotation / rmax)
        step *= scale
        diag = np.maximum(np.abs(np.diag(J)), 1e-30)
        merit0 = np.sum((r[free] / diag) ** 2)
        alpha = 1.0
        for _ in range(20):
            trial = p.copy()
            trial[free] += alpha * step
            try:
                r_t, fm_t, km_t = residual(trial)
            except NumericalError:
                alpha *= 0.5
                continue
            if np.sum((r_t[free] / diag) ** 2) <= merit0 or alpha < 1e-3:
                break
            alpha *= 0.5
        else:
            raise ConvergenceError("the line search found no admissible step", where="statics",
                                   remedy="start closer to the equilibrium (x0)")
        p, r, fm, km = trial, r_t, fm_t, km_t
        done_t = np.all(np.abs(alpha * step[~is_rot]) <= tol_translation)
        done_r = np.all(np.abs(alpha * step[is_rot]) <= tol_rotation)
        if done_t and done_r and scale == 1.0:
            converged = True
            break
    if not converged:
        j = free[np.argmax(np.abs(r[free]) / np.maximum(np.abs(np.diag(km + Kh))[free], 1e-30))]
        raise ConvergenceError(
            f"no static equilibrium after {max_iter} iterations (largest residual "
            f"{r[j]:.4g} {FORCE_UNITS[j]} in {DOF_NAMES[j]})", where=f"statics, DOF {DOF_NAMES[j]}",
            remedy="check the external force against the mooring capacity, give the hydrostatic "
                   "stiffness of every free DOF, or start closer (x0)")
    res = np.zeros(6)
    res[free] = r[free]
    return EquilibriumResult(pose=p, mooring_force=fm, residual=res, mooring_stiffness=km,
                             total_stiffness=km + Kh, iterations=it,
                             tensions=mooring.tensions(p),
                             free_dofs=tuple(DOF_NAMES[i] for i in free))


def restoring_curve(mooring: MooringSystem, heading: float, offsets, *, pose0=None) -> xr.Dataset:
    """Mooring restoring force against horizontal offset along a heading.

    Parameters
    ----------
    mooring : MooringSystem
    heading : float
        Direction of the offset, rad, from +x towards +y.
    offsets : array of float
        Offsets along the heading, m (may be negative).
    pose0 : (6,) array, optional
        Pose from which the offsets are taken (default zero); the other DOFs stay fixed.

    Returns
    -------
    xarray.Dataset
        Dims ``offset`` and ``line`` (and ``dof``): ``restoring_force`` (N, the mooring force
        component opposing the offset, i.e. ``-F . e_heading``), ``force`` (offset, dof),
        ``fairlead_tension``, ``anchor_tension`` (offset, line, N), ``grounded_length``
        (offset, line, m), and ``stiffness_along_heading`` (N/m, ``e^T K e`` from the analytic
        stiffness).
    """
    offsets = np.atleast_1d(np.asarray(offsets, float))
    p0 = np.zeros(6) if pose0 is None else np.asarray(pose0, float).reshape(6)
    e = np.array([math.cos(heading), math.sin(heading), 0.0, 0.0, 0.0, 0.0])
    n = mooring.n_lines
    F = np.zeros((offsets.size, 6))
    k_along = np.zeros(offsets.size)
    tf = np.zeros((offsets.size, n))
    ta = np.zeros((offsets.size, n))
    lg = np.zeros((offsets.size, n))
    for i, s in enumerate(offsets):
        pose = p0 + s * e
        f, K = mooring.force_and_stiffness(pose)
        F[i] = f
        k_along[i] = e @ K @ e
        t = mooring.tensions(pose)
        tf[i] = t["fairlead_tension"].values
        ta[i] = t["anchor_tension"].values
        lg[i] = t["grounded_length"].values
    return xr.Dataset(
        {"restoring_force": ("offset", -F @ e, {"units": "N", "long_name":
                             "mooring force opposing the offset (-F . e_heading)"}),
         "force": (("offset", "dof"), F, {"units": "N, N m", "long_name":
                   "mooring force and moment about the displaced reference point"}),
         "stiffness_along_heading": ("offset", k_along, {"units": "N/m", "long_name":
                                     "analytic stiffness along the heading"}),
         "fairlead_tension": (("offset", "line"), tf, {"units": "N", "long_name": "fairlead tension"}),
         "anchor_tension": (("offset", "line"), ta, {"units": "N", "long_name": "anchor tension"}),
         "grounded_length": (("offset", "line"), lg, {"units": "m", "long_name":
                             "unstretched length on the seabed"})},
        coords={"offset": ("offset", offsets, {"units": "m"}), "line": list(mooring.names),
                "dof": list(DOF_NAMES)},
        attrs={"heading_deg": math.degrees(heading), "pose0": list(map(float, p0))})
