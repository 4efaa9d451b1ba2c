"""Static equilibrium and restoring curves of a scene (user API).

>>> import floatmoor
>>> res = floatmoor.equilibrium("scenes/floatel_100yr.yaml")
>>> print(res.summary())

:func:`equilibrium` is the one public equilibrium of floatmoor (of a scene); the numerics on a
mooring system are :func:`floatmoor.solvers.statics.solve_equilibrium`.

The body is held by its hydrostatic restoring (database hydrostatics + gravity terms +
additional stiffness of the vessel file, linear about the zero pose), the quasi-static mooring
and a constant external force: the net buoyancy at the zero pose (buoyancy rho g V of the
database's displaced volume minus the weight, see :func:`floatmoor.io.build.net_buoyancy_force`)
plus any constant force the caller gives (mean wind, current and drift are added by the
frequency-domain module, which computes them from the environment).
"""

from __future__ import annotations

import math
import os

import numpy as np
import xarray as xr

from ..core.errors import SceneError
from ..io.build import BuiltScene, build
from ..io.scene import Scene
from ..solvers.statics import EquilibriumResult, restoring_curve, solve_equilibrium

__all__ = ["equilibrium", "restoring_curves"]


def _built(scene, failed_lines) -> BuiltScene:
    built = scene if isinstance(scene, BuiltScene) else build(scene, failed_lines=failed_lines)
    if built.mooring is None:
        raise SceneError(built.scene.file, "mooring", "a mooring section or mooring file "
                         "(statics needs a mooring system)")
    return built


def equilibrium(scene: Scene | BuiltScene | str | os.PathLike, *, external_force=None,
                failed_lines=None, dofs=None) -> EquilibriumResult:
    """Equilibrium pose of the scene's vessel on its mooring.

    Parameters
    ----------
    scene : a scene file path, a :class:`~floatmoor.io.scene.Scene` or a built scene.
    external_force : (6,) constant force and moment about the reference point (N, N m), added
        to the net buoyancy at the zero pose.
    failed_lines : line names to remove (ALS), in addition to the scene's ``failed_lines``.
    dofs : free DOFs (default all six).

    Returns
    -------
    :class:`~floatmoor.solvers.statics.EquilibriumResult` (pose, per-line tensions, analytic
    6x6 mooring stiffness about the displaced reference point; ``summary()`` prints them).
    """
    built = _built(scene, failed_lines)
    f = built.static_force.copy()
    if external_force is not None:
        f += np.asarray(external_force, float).reshape(6)
    return solve_equilibrium(built.mooring, hydrostatic_stiffness=built.vessel.total_restoring,
                             external_force=f, dofs=dofs)


def restoring_curves(scene: Scene | BuiltScene | str | os.PathLike, *,
                     headings_deg=(0.0, 45.0, 90.0), offsets=None,
                     failed_lines=None) -> xr.Dataset:
    """Mooring restoring force against horizontal offset for several headings.

    The offsets are taken from the still-water equilibrium pose (heave, roll, pitch held there).
    Returns a Dataset with dims ``heading``, ``offset``, ``line`` (see
    :func:`floatmoor.solvers.statics.restoring_curve` for the variables).
    """
    built = _built(scene, failed_lines)
    if offsets is None:
        offsets = np.linspace(0.0, 40.0, 21)
    eq = equilibrium(built)
    curves = [restoring_curve(built.mooring, math.radians(h), offsets, pose0=eq.pose)
              for h in headings_deg]
    ds = xr.concat(curves, dim="heading", combine_attrs="drop_conflicts")
    ds = ds.assign_coords(heading=("heading", np.asarray(headings_deg, float), {"units": "deg"}))
    ds.attrs["pose0"] = list(map(float, eq.pose))
    ds.attrs["scene"] = str(built.scene.file) if built.scene.file else built.scene.name
    return ds
