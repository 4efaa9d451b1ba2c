"""Build the physical models a scene names: vessel, mooring system and the static balance.

:func:`build` is the one place where a validated :class:`~floatmoor.io.scene.Scene` becomes
objects the solvers use (statics, time domain, frequency domain), so that every solver sees the
same vessel, the same mooring and the same constant loads.  It builds only what the scene asks
for: no ``mooring:`` key, no mooring system.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field, replace

import numpy as np

from ..core.constants import GRAVITY
from ..core.errors import SceneError
from ..hydro.vessel import Vessel, load_vessel
from ..mooring.system import MooringSystem
from .mooring_section import parse_mooring
from .scene import Scene, load_scene

__all__ = ["BuiltScene", "ModelInputs", "build", "model_inputs", "net_buoyancy_force"]


@dataclass(frozen=True, kw_only=True)
class BuiltScene:
    """A scene with its models built.

    scene: the validated scene; vessel: :class:`~floatmoor.hydro.vessel.Vessel` or None;
    mooring: :class:`~floatmoor.mooring.system.MooringSystem` or None (failed lines already
    removed); static_force: (6,) constant generalized force on the body at zero pose about the
    reference point from buoyancy minus weight (N, N m) -- what the mooring and hydrostatic
    restoring must balance; displaced_volume: m^3 at zero pose (None when unknown).
    """

    scene: Scene
    vessel: Vessel | None = None
    mooring: MooringSystem | None = None
    static_force: np.ndarray = field(default_factory=lambda: np.zeros(6))
    displaced_volume: float | None = None

    def model_inputs(self, options, names, *, yaw: float = 0.0) -> ModelInputs:
        """:func:`model_inputs` of this scene (the solvers call it without importing io)."""
        return model_inputs(self, options, names, yaw=yaw)


def with_fibre_bound(built: BuiltScene, bound: str | None) -> BuiltScene:
    """``built`` with its fibre ropes at the stiffness bound ``lower`` or ``upper``
    (:meth:`floatmoor.mooring.MooringSystem.with_fibre_bound`); None or a mooring without fibre
    ropes: ``built`` itself."""
    if bound is None:
        return built
    if bound not in ("lower", "upper"):
        raise SceneError(built.scene.file, "fibre_stiffness", "lower or upper", bound)
    if built.mooring is None or not built.mooring.has_fibre:
        return built
    return replace(built, mooring=built.mooring.with_fibre_bound(bound))


def net_buoyancy_force(vessel: Vessel, water_density: float, gravity: float = GRAVITY):
    """Buoyancy minus weight at zero pose, as a 6-vector about the reference point.

    Buoyancy rho g V acts at the centre of buoyancy; its moment about the reference point is
    already inside the database's hydrostatic stiffness (which is linear about zero pose), so
    only the vertical force and the moment of the weight-buoyancy imbalance about the reference
    point in roll/pitch from horizontal offsets of the CoG and CoB enter here.  The centre of
    buoyancy is taken from the database attribute ``centre_of_buoyancy`` when present, else on
    the vertical through the reference point (symmetric hulls).

    Returns (force (6,), displaced volume or None).  Without a ``displaced_volume`` attribute in
    the database the vessel is taken to float freely at zero pose (force 0).
    """
    db = vessel.database
    vol = db.attrs.get("displaced_volume")
    if vol is None:
        return np.zeros(6), None
    vol = float(np.asarray(vol).reshape(-1)[0])
    cob = np.asarray(db.attrs.get("centre_of_buoyancy", [0.0, 0.0, 0.0]), float).reshape(-1)
    ref = np.asarray(vessel.reference_point, float)
    buoy = water_density * gravity * vol
    weight = vessel.mass * gravity
    f = np.zeros(6)
    f[2] = buoy - weight
    rg = np.asarray(vessel.centre_of_gravity, float) - ref
    rb = (cob[:3] - ref) if cob.size >= 3 else np.zeros(3)
    # moments of the vertical forces about the reference point: M = r x F, F = (0, 0, Fz)
    f[3] = rb[1] * buoy - rg[1] * weight
    f[4] = -rb[0] * buoy + rg[0] * weight
    return f, vol


def build(scene: Scene | str | os.PathLike, *, failed_lines=None, need_vessel: bool = True) -> BuiltScene:
    """Build the vessel and mooring a scene names.

    Parameters
    ----------
    scene : a :class:`Scene` or a path to a scene file.
    failed_lines : names of lines to remove in addition to the scene's ``failed_lines`` (ALS).
    need_vessel : raise a SceneError when the scene names no vessel.
    """
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    vessel = None
    if scene.vessel is not None:
        vessel = load_vessel(scene.vessel)
    elif need_vessel:
        raise SceneError(scene.file, "vessel", "a path to a vessel file (vessel.yaml)")
    mooring = None
    node = scene.mooring_node()
    if node is not None:
        mooring = parse_mooring(node, water_depth=scene.site.water_depth,
                                water_density=scene.site.water_density,
                                gravity=scene.site.gravity)
        if failed_lines:
            known = {ln.name for ln in mooring.lines}
            unknown = [n for n in failed_lines if n not in known]
            if unknown:
                raise SceneError(scene.file, "failed_lines",
                                 "names of mooring lines: " + ", ".join(sorted(known)), unknown)
            mooring = mooring.without_lines(failed_lines)
    static_force, vol = (np.zeros(6), None)
    if vessel is not None:
        static_force, vol = net_buoyancy_force(vessel, scene.site.water_density, scene.site.gravity)
    if mooring is not None and mooring.has_fibre:
        mooring = mooring.with_fibre_bound(scene.analysis.fibre_bounds[-1])
    return BuiltScene(scene=scene, vessel=vessel, mooring=mooring, static_force=static_force,
                      displaced_volume=vol)


@dataclass(frozen=True, kw_only=True)
class ModelInputs:
    """Vessel data for the force models after the scene's rules that combine models.

    The viscous-drift rules (``forces: viscous_drift``, Wang (2016) chapter 6): with the
    correction formula, the mean drift coefficients corrected by eq. 6.6 (``drift_database``,
    used by Newman's drift) and the linear damping raised in surge and sway (section 6.6,
    ``linear_damping``); with slender elements and ``double_counting: true``, the hull current
    coefficients zeroed in the DOFs the elements carry (section 6.1.2, ``current_table``).
    A field is None when its model is not in the run (the model then reads the vessel).  The
    time and the frequency domain read the same fields (the latter at each body heading).
    """

    linear_damping: np.ndarray | None = None
    current_table: np.ndarray | None = None
    drift_database: object = None


def model_inputs(built: BuiltScene, options, names, *, yaw: float = 0.0) -> ModelInputs:
    """The :class:`ModelInputs` of a run with the force models ``names`` (the scene's
    ``forces`` settings ``options``, body heading ``yaw`` in rad): the one place where the
    rules combining models are applied."""
    from ..forces.slender import (
        corrected_drift_database,
        hull_current_coefficients,
        viscous_linear_damping,
    )

    v = built.vessel
    spec = getattr(options, "viscous_drift", None)
    names = set(names)
    damping = current = drift = None
    if "damping_linear" in names:
        damping = viscous_linear_damping(spec, np.array(v.linear_damping, float))
    if "current" in names and v.current_coefficients is not None:
        current = hull_current_coefficients(
            spec, np.ascontiguousarray(v.current_coefficients.coefficients, float), v)
    if "drift_newman" in names or "wave_drift_damping" in names:
        drift = corrected_drift_database(built, spec, v.database, yaw=yaw)
    return ModelInputs(linear_damping=damping, current_table=current, drift_database=drift)
