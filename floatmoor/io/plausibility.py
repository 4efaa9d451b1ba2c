"""Physical plausibility of a built scene, checked before any analysis (``floatmoor check``,
``statics``, ``fd``, ``run``).

Each check raises a :class:`~floatmoor.core.errors.SceneError` naming the file and key to fix:

* the water depth against the hydrodynamic database's depth (:data:`DEPTH_RATIO_LIMIT`) and
  against the deepest point of the hull (fairleads, slender elements);
* the mass against the displacement: weight, buoyancy and the mooring's vertical pull at zero
  pose must balance within :data:`MASS_DISPLACEMENT_TOLERANCE` of the buoyancy (a mass in
  tonnes, or a database of another vessel, is off by orders of magnitude);
* stability: positive restoring in heave, roll and pitch (hydrostatics, gravity, additional
  stiffness and the mooring's stiffness at zero pose): a centre of gravity above the
  metacentre would otherwise give a "small" pitch at equilibrium that is not an equilibrium;
* the inputs of every model the scene builds: wind (current) coefficients in the vessel file
  when the scene has wind (current), a valid ``slender_elements`` section when present.

A :class:`~floatmoor.core.errors.FloatmoorWarning` marks a water depth more than 10 % from the
database's.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..core.errors import FloatmoorWarning, SceneError

__all__ = ["check_built", "MASS_DISPLACEMENT_TOLERANCE", "DEPTH_RATIO_LIMIT"]

MASS_DISPLACEMENT_TOLERANCE = 0.10
"""Largest vertical imbalance at zero pose (weight - buoyancy - mooring pull), as a fraction
of the buoyancy rho g V.  Free-floating vessels balance to a percent or two; ballast or
mooring pretension changes of more than 10 % would also move the draft away from the one the
hydrodynamic database was computed at."""

DEPTH_RATIO_LIMIT = 2.0
"""The scene's water depth may differ from the database's finite depth by at most this factor
(refused beyond; warned beyond 10 %): the added mass, damping and excitation depend on it."""


def check_built(built, *, time_domain: bool = True) -> None:
    """Run every plausibility check on a :class:`~floatmoor.io.build.BuiltScene`.

    ``time_domain=False`` (the frequency-domain analysis, which runs without wind or current
    coefficients and says so in its notes) skips the check of the time-domain models' inputs.
    """
    if built.vessel is None:
        return
    check_depth(built)
    if time_domain:
        check_model_inputs(built)
    check_mass_and_stability(built)


def check_depth(built) -> None:
    """Water depth against the database's depth and against the hull's deepest point."""
    scene, v = built.scene, built.vessel
    depth = float(scene.site.water_depth)
    db_depth = float(v.database.attrs.get("water_depth", math.inf))
    lowest, what = _lowest_hull_point(built)
    if lowest is not None and not depth > -lowest:
        raise SceneError(scene.file, "site.water_depth", f"a water depth greater than the "
                         f"deepest point of the floater ({-lowest:g} m below the water line, "
                         f"{what})", depth)
    if math.isfinite(db_depth) and db_depth > 0.0:
        ratio = depth / db_depth
        if ratio > DEPTH_RATIO_LIMIT or ratio < 1.0 / DEPTH_RATIO_LIMIT:
            raise SceneError(scene.file, "site.water_depth", f"a water depth within a factor "
                             f"{DEPTH_RATIO_LIMIT:g} of the depth of the vessel's hydrodynamic "
                             f"database ({db_depth:g} m, {v.database_path})", depth,
                             "the hydrodynamic coefficients depend on the depth; compute a "
                             "database at this depth")
        if abs(ratio - 1.0) > 0.10:
            warnings.warn(f"{scene.file}: site.water_depth: {depth:g} m differs by "
                          f"{100 * abs(ratio - 1):.0f} % from the depth of the hydrodynamic "
                          f"database ({db_depth:g} m, {v.database_path})", FloatmoorWarning,
                          stacklevel=3)


def _lowest_hull_point(built):
    """(z, description) of the deepest known point of the floater at zero pose."""
    pts = []
    ms = built.mooring
    if ms is not None:
        for ln in ms.lines:
            pts.append((float(ln.fairlead[2]), f"the fairlead of line {ln.name!r}"))
    raw = built.vessel.slender_elements
    if isinstance(raw, dict):
        for el in raw.get("elements", []) or []:
            if isinstance(el, dict):
                for k in ("p1", "p2"):
                    p = el.get(k)
                    if (isinstance(p, list) and len(p) == 3
                            and all(isinstance(c, (int, float)) for c in p)):
                        pts.append((float(p[2]), f"slender element {el.get('name', '?')!r}"))
    if not pts:
        return None, ""
    return min(pts)


def check_model_inputs(built) -> None:
    """The inputs of the models the scene builds, so that a missing table is exit status 2 at
    ``check`` rather than a failed seed at run time."""
    from ..forces import select_models

    scene, v = built.scene, built.vessel
    models = select_models(built, getattr(scene, "forces", None))
    for model, attr in (("wind", "wind_coefficients"), ("current", "current_coefficients")):
        if model in models and getattr(v, attr) is None:
            raise SceneError(v.file, attr, f"{model} coefficients in the vessel file (the scene "
                             f"{scene.file} has {model})",
                             hint=f"add {attr}, or exclude {model} in the scene's forces section")
    if v.slender_elements is not None:
        from ..forces.slender_config import parse_slender_elements
        parse_slender_elements(v.slender_elements, file=v.file, key="slender_elements",
                               rho=float(scene.site.water_density))


def check_mass_and_stability(built) -> None:
    """Weight, buoyancy and mooring pull balanced; positive restoring in heave, roll, pitch."""
    scene, v = built.scene, built.vessel
    rho = float(scene.site.water_density)
    g = float(scene.site.gravity)
    zero = np.zeros(6)
    f_moor = np.zeros(6)
    k_moor = np.zeros((6, 6))
    if built.mooring is not None:
        try:
            f_moor = np.asarray(built.mooring.force(zero), float)
            k_moor = np.asarray(built.mooring.stiffness(zero), float)
        except Exception:  # a mooring that cannot be solved is reported by its own check
            pass
    volume = built.displaced_volume
    if volume is not None and volume > 0.0:
        buoyancy = rho * g * volume
        imbalance = float(built.static_force[2] + f_moor[2])  # up positive
        if abs(imbalance) > MASS_DISPLACEMENT_TOLERANCE * buoyancy:
            expected_mass = (buoyancy + f_moor[2]) / g
            c33 = float(v.total_restoring[2, 2] + k_moor[2, 2])
            heave = f" (a heave of {imbalance / c33:.3g} m to balance it)" if c33 > 0 else ""
            raise SceneError(v.file, "mass", f"a mass balancing buoyancy and mooring pull within "
                             f"{100 * MASS_DISPLACEMENT_TOLERANCE:g} %: about {expected_mass:.4g} "
                             f"kg (displaced volume {volume:.6g} m^3 x {rho:g} kg/m^3, mooring "
                             f"vertical force {f_moor[2] / 1e3:.4g} kN)", v.mass,
                             f"the imbalance is {imbalance / 1e3:.4g} kN{heave}; a mass in "
                             "tonnes instead of kg?")
    c = np.asarray(v.total_restoring, float) + k_moor
    names = {2: "heave", 3: "roll", 4: "pitch"}
    for i, name in names.items():
        if not c[i, i] > 0.0:
            detail = f"C_{name} = {c[i, i]:.4g}" + (" N/m" if i == 2 else " N m/rad")
            if i > 2 and v.mass > 0:
                detail += (f" (metacentric height about {c[i, i] / (v.mass * g):.3g} m: the "
                           "centre of gravity is above the metacentre)")
            raise SceneError(v.file, "centre_of_gravity", f"a stable floater: positive "
                             f"restoring in heave, roll and pitch at zero pose (hydrostatics, "
                             f"gravity and mooring; {name} is not)", list(v.centre_of_gravity),
                             detail)
