"""Vessel files: mass properties, damping, stiffness, wind/current coefficients and database.

A vessel file ``vessels/<name>/vessel.yaml`` (all SI; angles only in keys ending ``_deg``)::

    name: oc3_hywind
    database: database.nc            # path relative to this file (netCDF, floatmoor form)
    reference_point: [0, 0, 0]       # m, body frame: the point of the database matrices and of
                                     # every matrix in this file (usually on the waterline)
    mass: 7466330                    # kg, rigid body
    centre_of_gravity: [0, 0, -89.9] # m, body frame
    inertia_cg: [Ixx, Iyy, Izz]      # kg m^2 about the CoG, or a full 3x3 list
    point_masses:                    # optional: added to the body (e.g. a wind turbine)
      - {name: tower, mass: 2.5e5, position: [0, 0, 43.4], inertia_cg: [1.2e8, 1.2e8, 0]}
    linear_damping: 6x6              # N s/m, N s, N m s/rad (optional, default 0)
    quadratic_damping: 6x6           # N s^2/m^2 .. N m s^2/rad^2 (optional, default 0)
    additional_stiffness: 6x6        # N/m, N, N m/rad (optional, default 0)
    wind_coefficients:               # optional; F_i = C_i(theta) U^2
      heading_deg: [0, 45, 90, ...]  # relative heading: direction the wind travels towards,
                                     # measured in the body frame from +x towards +y
      surge: [...]                   # N s^2/m^2 for forces, N s^2/m for moments (per DOF name)
      reference_height: 10.0         # m above the water line where U is taken (wind only)
    current_coefficients: {heading_deg: [...], surge: [...], ...}   # same, U = current speed
    fairleads: {FL1: [x, y, z], ...} # m, body frame (optional)
    mass_budget: ...                 # optional, written by `floatmoor import openfast`: the
                                     # masses as imported (items, total_mass, centre_of_gravity,
                                     # inertia_cg) against buoyancy, weight and mooring pull at
                                     # zero pose; refused when the masses above no longer sum to
                                     # total_mass (a stale budget)
    slender_elements: ...            # reserved for a later issue: kept as raw data

DOFs missing from a coefficient table are zero.  Headings must be increasing; the table is
periodic over 360 deg (it is interpolated with wrap-around by the force models).

Derived quantities
------------------
* ``mass_matrix`` (6x6 about the reference point): with r = CoG - reference point and S(r)
  the skew matrix (S(r) v = r x v),
  M = [[m I, -m S(r)], [m S(r), I_cg - m S(r) S(r)]]  (parallel-axis theorem).
* ``gravity_stiffness``: the -m g z_G terms missing from WAMIT/Capytaine hydrostatics about the
  reference point: C44 = C55 = -m g z_G, C46 = m g x_G, C56 = m g y_G (z_G etc. relative to
  the reference point; WAMIT manual, hydrostatic coefficients).
* ``total_restoring`` = database hydrostatic_stiffness + gravity_stiffness + additional_stiffness.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from ..core.config import Node
from ..core.constants import GRAVITY
from ..core.dofs import DOF_NAMES
from ..core.errors import SceneError
from .database import load_database

__all__ = ["Vessel", "CoefficientTable", "MassBudgetRecord", "load_vessel",
           "rigid_body_mass_matrix", "gravity_stiffness"]


def _skew(r):
    x, y, z = r
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def rigid_body_mass_matrix(mass: float, cog_rel, inertia_cg) -> np.ndarray:
    """6x6 rigid-body mass matrix about a point, given the CoG relative to it (m) and the 3x3
    inertia about the CoG (kg m^2)."""
    S = _skew(np.asarray(cog_rel, float))
    M = np.zeros((6, 6))
    M[:3, :3] = mass * np.eye(3)
    M[:3, 3:] = -mass * S
    M[3:, :3] = mass * S
    M[3:, 3:] = np.asarray(inertia_cg, float) - mass * S @ S
    return M


def gravity_stiffness(mass: float, cog_rel, g: float = GRAVITY) -> np.ndarray:
    """Restoring from the weight about the reference point: C44 = C55 = -m g z_G,
    C46 = m g x_G, C56 = m g y_G (N m/rad)."""
    xg, yg, zg = np.asarray(cog_rel, float)
    C = np.zeros((6, 6))
    C[3, 3] = C[4, 4] = -mass * g * zg
    C[3, 5] = mass * g * xg
    C[4, 5] = mass * g * yg
    return C


@dataclass(frozen=True, kw_only=True)
class CoefficientTable:
    """Wind or current force coefficients F_i = C_i(theta) U^2 against relative heading.

    heading : (n,) rad, increasing, direction of travel relative to the body x axis.
    coefficients : (n, 6) N s^2/m^2 (forces), N s^2/m (moments).
    reference_height : m (wind only; None for current).
    """
    heading: np.ndarray
    coefficients: np.ndarray
    reference_height: float | None = None

    def at(self, heading: float) -> np.ndarray:
        """Coefficients (6,) at a relative heading (rad), periodic linear interpolation."""
        h = np.concatenate([self.heading, self.heading[:1] + 2 * np.pi])
        c = np.concatenate([self.coefficients, self.coefficients[:1]], axis=0)
        x = (heading - h[0]) % (2 * np.pi) + h[0]
        return np.array([np.interp(x, h, c[:, k]) for k in range(6)])


@dataclass(frozen=True, kw_only=True)
class Vessel:
    """A floating body: mass properties, matrices about ``reference_point``, database.

    All arrays in SI units, 6x6 in DOF order surge..yaw.  See the module docstring.
    """
    name: str
    file: Path
    reference_point: np.ndarray
    mass: float
    centre_of_gravity: np.ndarray
    inertia_cg: np.ndarray
    mass_matrix: np.ndarray
    linear_damping: np.ndarray
    quadratic_damping: np.ndarray
    additional_stiffness: np.ndarray
    hydrostatic_stiffness: np.ndarray
    gravity_stiffness: np.ndarray
    total_restoring: np.ndarray
    database: xr.Dataset = field(repr=False)
    database_path: Path
    wind_coefficients: CoefficientTable | None = None
    current_coefficients: CoefficientTable | None = None
    fairleads: dict = field(default_factory=dict)
    slender_elements: Any = None
    description: str = ""
    mass_budget: Any = None


_MATRIX_KEYS = ("linear_damping", "quadratic_damping", "additional_stiffness")
_ALLOWED = {"name", "description", "database", "reference_point", "mass", "centre_of_gravity",
            "inertia_cg", "point_masses", *_MATRIX_KEYS, "wind_coefficients",
            "current_coefficients", "fairleads", "slender_elements", "notes", "mass_budget"}
_BUDGET_KEYS = {"items", "total_mass", "centre_of_gravity", "inertia_cg", "displaced_volume",
                "water_density", "gravity", "buoyancy", "weight", "mooring_vertical",
                "preload_vertical", "imbalance", "imbalance_fraction", "closes", "notes"}


@dataclass(frozen=True, kw_only=True)
class MassBudgetRecord:
    """The ``mass_budget`` section of a vessel file (written by ``floatmoor import openfast``):
    the masses as imported and their hydrostatic balance at zero pose (SI units)."""

    items: tuple            # (name, mass kg, position (3,) m)
    total_mass: float
    centre_of_gravity: np.ndarray
    displaced_volume: float
    water_density: float
    gravity: float
    mooring_vertical: float
    preload_vertical: float
    imbalance: float
    imbalance_fraction: float
    closes: bool


def _mass_budget(node: Node, m_tot: float, cog_tot: np.ndarray) -> MassBudgetRecord:
    """Read ``mass_budget`` and check it against the vessel's masses: a budget whose total
    mass or centre of gravity no longer matches them is stale and refused."""
    b = node.child("mass_budget")
    b.reject_unknown(_BUDGET_KEYS)
    items = []
    for it in b.item_nodes("items", []):
        it.reject_unknown({"name", "mass", "position"})
        items.append((it.str("name"), it.float("mass", gt=0.0, unit="kg"),
                      it.array("position", shape=(3,), unit="m")))
    total = b.float("total_mass", gt=0.0, unit="kg")
    cog = b.array("centre_of_gravity", shape=(3,), unit="m")
    if items and not math.isclose(sum(m for _n, m, _p in items), total, rel_tol=1e-9):
        raise b.error("total_mass", f"the sum of the budget's items "
                      f"({sum(m for _n, m, _p in items):.10g} kg)", total)
    if not (math.isclose(total, m_tot, rel_tol=1e-9)
            and np.allclose(cog, cog_tot, rtol=0.0, atol=1e-6)):
        raise b.error("total_mass", f"the mass of the vessel's masses ({m_tot:.10g} kg, centre "
                      f"of gravity {[round(float(c), 6) for c in cog_tot]} m): the budget is "
                      f"stale", f"{total:.10g} kg at {[round(float(c), 6) for c in cog]} m",
                      "the masses were edited after the import: update or delete the "
                      "mass_budget section with them")
    return MassBudgetRecord(
        items=tuple(items), total_mass=total, centre_of_gravity=cog,
        displaced_volume=b.float("displaced_volume", gt=0.0, unit="m^3"),
        water_density=b.float("water_density", gt=0.0, unit="kg/m^3"),
        gravity=b.float("gravity", gt=0.0, unit="m/s^2"),
        mooring_vertical=b.float("mooring_vertical", 0.0, unit="N"),
        preload_vertical=b.float("preload_vertical", 0.0, unit="N"),
        imbalance=b.float("imbalance", unit="N"),
        imbalance_fraction=b.float("imbalance_fraction"),
        closes=b.bool("closes"))


def _inertia(node: Node, key: str) -> np.ndarray:
    raw = node.raw(key, expected="3 principal inertias or a 3x3 list (kg m^2)")
    arr = np.asarray(raw, dtype=object)
    if arr.shape == (3,):
        v = node.array(key, shape=(3,), ge=0.0, unit="kg m^2")
        return np.diag(v)
    I3 = node.array(key, shape=(3, 3), unit="kg m^2")
    if not np.allclose(I3, I3.T, rtol=1e-9, atol=1e-9 * np.max(np.abs(I3))):
        raise node.error(key, "a symmetric 3x3 inertia matrix (kg m^2)", raw)
    return I3


def _coefficients(node: Node, key: str, wind: bool) -> CoefficientTable:
    t = node.child(key)
    allowed = {"heading_deg", *DOF_NAMES, "notes"} | ({"reference_height"} if wind else set())
    if "heading" in t:
        raise t.error("heading", "the relative headings in degrees under 'heading_deg'",
                      t.data["heading"], "angles are given in degrees in keys ending _deg")
    t.reject_unknown(allowed)
    h = t.array("heading_deg", shape=(None,), unit="deg")
    if h.size < 2 or np.any(np.diff(h) <= 0) or h[-1] - h[0] >= 360.0:
        raise t.error("heading_deg", "at least 2 strictly increasing headings spanning < 360 deg",
                      t.data["heading_deg"])
    C = np.zeros((h.size, 6))
    present = [d for d in DOF_NAMES if d in t]
    if not present:
        raise t.error("surge", "coefficients for at least one DOF (surge, sway, ..., yaw)")
    for k, d in enumerate(DOF_NAMES):
        if d in t:
            C[:, k] = t.array(d, shape=(h.size,),
                              unit="N s^2/m^2" if k < 3 else "N s^2/m")
    ref = t.float("reference_height", 10.0, gt=0.0, unit="m") if wind else None
    return CoefficientTable(heading=np.radians(h), coefficients=C, reference_height=ref)


def read_mass_properties(path):
    """Rigid-body mass properties of a vessel file (with its point masses), without loading
    the database: returns (mass kg, CoG (3,) m, 3x3 inertia about the CoG kg m^2)."""
    node = Node.load(path)
    return _mass_properties(node)


def _mass_properties(node: Node):
    mass = node.float("mass", gt=0.0, unit="kg")
    cog = node.array("centre_of_gravity", shape=(3,), unit="m")
    Icg = _inertia(node, "inertia_cg")
    parts = [(mass, cog, Icg)]
    for pm in node.item_nodes("point_masses", []):
        pm.reject_unknown({"name", "mass", "position", "inertia_cg", "notes"})
        m = pm.float("mass", gt=0.0, unit="kg")
        p = pm.array("position", shape=(3,), unit="m")
        I = _inertia(pm, "inertia_cg") if "inertia_cg" in pm else np.zeros((3, 3))
        parts.append((m, p, I))
    m_tot = sum(p[0] for p in parts)
    cog_tot = sum(p[0] * p[1] for p in parts) / m_tot
    I_tot = np.zeros((3, 3))
    for m, p, I in parts:
        S = _skew(p - cog_tot)
        I_tot += I - m * S @ S
    return m_tot, cog_tot, I_tot


def load_vessel(path) -> Vessel:
    """Read a vessel file and its database.

    Parameters
    ----------
    path : ``vessel.yaml`` (or the folder holding it).

    Returns
    -------
    Vessel (frozen) with matrices about the reference point.

    Raises
    ------
    SceneError naming the file and the key for any mistake.
    """
    path = Path(path)
    if path.is_dir():
        path = path / "vessel.yaml"
    node = Node.load(path)
    node.reject_unknown(_ALLOWED)
    name = node.str("name", path.parent.name)
    ref = node.array("reference_point", np.zeros(3), shape=(3,), unit="m")
    m_tot, cog_tot, I_tot = _mass_properties(node)
    budget = _mass_budget(node, m_tot, cog_tot) if "mass_budget" in node else None
    mats = {}
    for key in _MATRIX_KEYS:
        M = node.array(key, np.zeros((6, 6)), shape=(6, 6))
        if key != "additional_stiffness":
            if np.any(np.diag(M) < 0):
                raise node.error(key, "a 6x6 matrix with a non-negative diagonal", node.data[key])
        mats[key] = M
    db_path = node.path_value("database")
    try:
        db = load_database(db_path)
    except SceneError as exc:
        raise SceneError(path, "database", "a loadable hydrodynamic database",
                         str(db_path), str(exc)) from None
    db_ref = np.asarray(db.attrs.get("reference_point", np.zeros(3)), float).reshape(-1)
    if db_ref.size == 3 and not np.allclose(db_ref, ref, atol=1e-6):
        raise node.error("reference_point", f"the reference point of the database {list(db_ref)}",
                         list(ref), "the vessel matrices must be about the database's point")
    C_hyd = db["hydrostatic_stiffness"].values if "hydrostatic_stiffness" in db else np.zeros((6, 6))
    g = float(db.attrs.get("g", GRAVITY))
    C_grav = gravity_stiffness(m_tot, cog_tot - ref, g)
    wind = _coefficients(node, "wind_coefficients", True) if "wind_coefficients" in node else None
    cur = (_coefficients(node, "current_coefficients", False)
           if "current_coefficients" in node else None)
    fair = {}
    if "fairleads" in node:
        fn = node.child("fairleads")
        for k in fn.keys():
            fair[str(k)] = fn.array(k, shape=(3,), unit="m")
    return Vessel(
        name=name, file=path, reference_point=ref, mass=m_tot, centre_of_gravity=cog_tot,
        inertia_cg=I_tot, mass_matrix=rigid_body_mass_matrix(m_tot, cog_tot - ref, I_tot),
        linear_damping=mats["linear_damping"], quadratic_damping=mats["quadratic_damping"],
        additional_stiffness=mats["additional_stiffness"], hydrostatic_stiffness=C_hyd,
        gravity_stiffness=C_grav, total_restoring=C_hyd + C_grav + mats["additional_stiffness"],
        database=db, database_path=db_path, wind_coefficients=wind, current_coefficients=cur,
        fairleads=fair, slender_elements=node.raw("slender_elements", None),
        description=node.str("description", ""), mass_budget=budget)
