"""The time-domain result as an xarray Dataset, driven by one table of variables.

Each row of :data:`VARIABLES` gives a Dataset variable's name, dims, units and long name and
the getter that takes it from the :class:`~floatmoor.solvers.time_domain.TimeDomainResult`
(None: the variable is absent, e.g. ``wave_elevation`` without waves); :data:`COORDINATES`
and :data:`ATTRIBUTES` do the same for the coordinates and the global attributes (the layout
of :mod:`floatmoor.analyses.fd_dataset`).  :func:`to_dataset` is
:func:`floatmoor.simulate`'s last step; the run's own attributes (run time, warnings' values)
are added by the caller.
"""

from __future__ import annotations

import datetime as _dt
import os
import platform
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from ..core.dofs import DOF_NAMES, DOF_UNITS, FORCE_UNITS

__all__ = ["TDRun", "Variable", "VARIABLES", "COORDINATES", "ATTRIBUTES", "to_dataset",
           "scene_text"]

POSE_UNITS = "m (surge, sway, heave), rad (roll, pitch, yaw)"


@dataclass(frozen=True, kw_only=True)
class TDRun:
    """What the Dataset is made of: the raw result ``r``
    (:class:`~floatmoor.solvers.time_domain.TimeDomainResult`), the built scene and the run's
    settings (seed, dt, duration, ramp, transient in s)."""

    r: object
    built: object
    seed: int
    dt: float
    duration: float
    ramp: float
    transient: float

    @property
    def fe(self) -> bool:
        return bool(getattr(self.r, "fe_lines", None))

    @property
    def lines(self) -> bool:
        return bool(self.r.line_names)


@dataclass(frozen=True)
class Variable:
    """One Dataset variable: ``get(run)`` its values or None (absent); ``attrs(run)`` its
    attributes beyond ``units`` and ``long_name`` (or instead of them, when it gives them)."""

    name: str
    dims: tuple
    units: str
    long_name: str | Callable
    get: Callable[[TDRun], object]
    attrs: Callable[[TDRun], dict] | None = None

    def entry(self, run: TDRun):
        v = self.get(run)
        if v is None:
            return None
        if self.attrs is not None:
            a = self.attrs(run)
        else:
            ln = self.long_name(run) if callable(self.long_name) else self.long_name
            a = {"units": self.units, "long_name": ln}
        return self.dims, v, a


def _lines(get):
    """``get`` on runs with mooring lines, else absent."""
    return lambda run: get(run) if run.lines else None


def _fe(key):
    return lambda run: run.r.fe_records[key] if run.lines and run.fe else None


def _tension_long_name(run: TDRun) -> str:
    if run.fe:
        return ("effective tension at the fairlead (finite-element lines: FE end force; "
                "others: quasi-static catenary)")
    return "effective tension at the fairlead (quasi-static catenary)"


def _mbs_attrs(run: TDRun) -> dict:
    m = run.built.mooring
    return m.mbs_attrs() if hasattr(m, "mbs_attrs") else \
        {"units": "N", "long_name": "minimum breaking strength (weakest segment)"}


VARIABLES: tuple[Variable, ...] = (
    Variable("motion", ("time", "dof"), POSE_UNITS,
             "pose of the body reference point (earth axes)", lambda run: run.r.motion),
    Variable("velocity", ("time", "dof"), "m/s (surge, sway, heave), rad/s (roll, pitch, yaw)",
             "pose rate of the body reference point", lambda run: run.r.velocity),
    Variable("line_tension", ("time", "line"), "N", _tension_long_name,
             _lines(lambda run: run.r.line_tension)),
    Variable("anchor_tension", ("time", "line"), "N", "tension at the anchor",
             _lines(lambda run: run.r.anchor_tension)),
    Variable("mbs", ("line",), "N", "", _lines(lambda run: np.asarray(run.built.mooring.mbs,
                                                                      float)),
             attrs=_mbs_attrs),
    Variable("line_model", ("line",), "", "line model",
             lambda run: np.array(["finite-element" if n in run.r.fe_lines else "quasi-static"
                                   for n in run.r.line_names]) if run.lines and run.fe else None,
             attrs=lambda run: {"long_name": "line model"}),
    Variable("max_tension_along_line", ("time", "line"), "N",
             "largest element tension along the line (finite-element lines; NaN: "
             "quasi-static)", _fe("max_tension_along_line")),
    Variable("grounded_length", ("time", "line"), "m",
             "unstretched length from the anchor to the last node in seabed contact "
             "(finite-element lines)", _fe("grounded_length")),
    Variable("touchdown_tension", ("time", "line"), "N",
             "tension of the element above the touchdown node (finite-element lines)",
             _fe("touchdown_tension")),
    Variable("wave_elevation", ("time",), "m", "undisturbed wave elevation at the origin",
             lambda run: run.r.wave_elevation),
    Variable("force", ("time", "model", "dof"), ", ".join(FORCE_UNITS),
             "generalized force of each model on the body (moments about the displaced "
             "reference point, earth axes)", lambda run: run.r.forces),
    Variable("start_pose", ("dof",), ", ".join(DOF_UNITS), "start pose (static equilibrium)",
             lambda run: run.r.x0),
)
"""The variables of :func:`floatmoor.simulate`'s Dataset, in their order."""

COORDINATES: tuple[tuple[str, Callable[[TDRun], object]], ...] = (
    ("time", lambda run: ("time", run.r.time, {"units": "s", "long_name": "simulated time"})),
    ("dof", lambda run: ("dof", list(DOF_NAMES), {"long_name": "degree of freedom",
                                                  "units": ", ".join(DOF_UNITS)})),
    ("line", lambda run: ("line", list(run.r.line_names), {"long_name": "mooring line"})
     if run.lines else None),
    ("model", lambda run: ("model", list(run.r.force_models), {"long_name": "force model"})
     if run.r.forces is not None else None),
)


def scene_text(scene) -> str:
    """The scene file's text (YAML) when it has a file, else its ``describe()``."""
    if scene.file is not None and Path(scene.file).is_file():
        return Path(scene.file).read_text()
    return scene.describe()


def _relative_velocity_note(r) -> str:
    mode = r.info.get("relative_velocity", "low_frequency")
    flows = [m for m in ("wind", "current") if m in r.models]
    if not flows:
        return "no wind or current force"
    what = " and ".join(flows)
    if mode == "total":
        return f"{what} relative to the total body velocity (Wang (2016) eq. 6.7 form)"
    if r.info.get("wf_velocity_removed", False):
        return (f"{what} relative to the low-frequency body velocity: the linear first-order "
                "wave-frequency velocity (motion RAOs x the run's wave realisation) is removed "
                "from the body velocity (Wang (2016) eq. 2.24, 2.26)")
    return (f"{what} relative to the body velocity (no first-order waves: it is the "
            "low-frequency velocity, Wang (2016) eq. 2.24, 2.26)")


def _versions() -> dict:
    import numba
    import scipy

    from .. import __version__
    return {"floatmoor": __version__, "numpy": np.__version__, "scipy": scipy.__version__,
            "xarray": xr.__version__, "numba": numba.__version__,
            "python": platform.python_version()}


FE_COUPLING = ("finite-element lines coupled to the body: one generalised-alpha advance of "
               "every FE line per body step (staggered); within the RK4 step the FE force is "
               "the value at the step start plus the change of the lines' quasi-static "
               "catenary force (floatmoor/solvers/fe_coupling.py)")

def _fe_count(key: str):
    """Getter of the FE count ``key`` of the run's info (absent without FE lines)."""
    return lambda run: int(run.r.info[key]) if run.fe and key in run.r.info else None


ATTRIBUTES: tuple[tuple[str, Callable[[TDRun], object]], ...] = (
    ("title", lambda run: f"floatmoor time-domain simulation of {run.built.scene.name}"),
    ("scene", lambda run: scene_text(run.built.scene)),
    ("scene_name", lambda run: run.built.scene.name),
    ("scene_file", lambda run: "" if run.built.scene.file is None
     else os.fspath(run.built.scene.file)),
    ("seed", lambda run: int(run.seed)),
    ("models", lambda run: list(run.r.models)),
    ("dt", lambda run: float(run.dt)),
    ("duration", lambda run: float(run.duration)),
    ("ramp", lambda run: float(run.ramp)),
    ("transient", lambda run: float(run.transient)),
    ("integrator", lambda run: "classical Runge-Kutta 4, fixed step; trapezoidal radiation "
                               "memory"),
    ("relative_velocity", lambda run: str(run.r.info.get("relative_velocity",
                                                         "low_frequency"))),
    ("relative_velocity_note", lambda run: _relative_velocity_note(run.r)),
    ("wave_force_frame", lambda run: "first-order wave and drift forces are evaluated at the "
                                     "mean position (the origin) and the start heading (body "
                                     "yaw 0): they do not follow the body's yaw or offset"),
    ("created", lambda run: _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds")),
    # finite-element lines only (None: absent)
    ("fe_lines", lambda run: list(run.r.fe_lines) if run.fe else None),
    ("fe_coupling", lambda run: FE_COUPLING if run.fe else None),
    *((k, _fe_count(k)) for k in ("fe_substeps", "fe_newton_iterations", "fe_step_halvings",
                                  "fe_threads")),
    ("fe_elements", lambda run: list(run.r.info["fe_elements"])
     if run.fe and "fe_elements" in run.r.info else None),
)
"""Global attributes of the Dataset (None: absent), then ``version_*`` of every package."""


def _fe_selfcheck(run: TDRun) -> dict:
    """Self-check variables (``selfcheck_*`` over ``line``, NaN / "-" for quasi-static lines;
    :mod:`floatmoor.mooring.fe.selfcheck`) of the coupled FE lines over the statistics window,
    with a FloatmoorWarning for a line that breaks a warning-level bound."""
    from ..core.frames import rotation_matrix_into
    from ..mooring.fe.selfcheck import line_selfcheck, selfcheck_variables, warn_broken

    r = run.r
    sel = r.time >= run.transient
    if not np.any(sel):
        sel = np.ones(r.time.size, bool)
    R = np.zeros((3, 3))
    rot = np.empty((r.time.size, 3, 3))
    for k, p in enumerate(r.motion):
        rotation_matrix_into(p[3], p[4], p[5], R)
        rot[k] = R
    dt = float(r.time[1] - r.time[0]) if r.time.size > 1 else 1.0
    fe = dict(zip(r.fe_lines, r.fe_objects))
    names = list(r.line_names)
    checks = []
    for j, name in enumerate(names):
        ln = fe.get(name)
        if ln is None:
            checks.append(None)
            continue
        rb = np.asarray(run.built.mooring.lines[j].fairlead, float)
        rf = r.motion[:, :3] + rot @ rb
        speed = np.linalg.norm(np.diff(rf, axis=0), axis=1) / dt
        checks.append(line_selfcheck(
            ln, fairlead_tension=r.line_tension[sel, j],
            max_tension=r.fe_records["max_tension_along_line"][sel, j],
            fairlead_height=float(rf[sel, 2].max() - ln.r[0, 2]),
            fairlead_speed=float(speed.max())))
    warn_broken(names, checks, stacklevel=5)
    return selfcheck_variables(checks)


def to_dataset(run: TDRun) -> xr.Dataset:
    """The Dataset of a time-domain run: the variables of :data:`VARIABLES` that the run has,
    each with ``units`` and ``long_name``, the self-check of its finite-element lines
    (``selfcheck_*``), the coordinates of :data:`COORDINATES` and the attributes of
    :data:`ATTRIBUTES` (and the package versions)."""
    data = {}
    for v in VARIABLES:
        e = v.entry(run)
        if e is not None:
            data[v.name] = e
    if run.lines and run.fe and getattr(run.r, "fe_objects", None):
        data.update(_fe_selfcheck(run))
    coords = {}
    for name, get in COORDINATES:
        c = get(run)
        if c is not None:
            coords[name] = c
    ds = xr.Dataset(data, coords=coords)
    for name, get in ATTRIBUTES:
        value = get(run)
        if value is not None:
            ds.attrs[name] = value
    for k, v in _versions().items():
        ds.attrs[f"version_{k}"] = v
    return ds
