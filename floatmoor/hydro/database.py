"""The hydrodynamic database: one documented xarray form, netCDF save/load and a validator.

Form (Capytaine's names and dimensions, plus floatmoor's own variables)
-----------------------------------------------------------------------
Dimensions and coordinates

* ``omega`` (rad/s): finite wave frequencies, strictly increasing, > 0.
* ``wave_direction`` (rad): wave heading, the direction the waves travel towards, measured from
  +x towards +y (WAMIT's BETA and Capytaine's ``wave_direction`` are both this).
* ``influenced_dof``, ``radiating_dof``: the DOF names ``surge .. yaw``.  Matrices are indexed
  ``[influenced_dof, radiating_dof]`` = ``[force i, motion j]`` exactly as Capytaine stores them,
  so ``ds.added_mass.values[k]`` is the usual 6x6 matrix A_ij(omega_k).
* ``qtf_omega``, ``qtf_omega_2``, ``qtf_wave_direction``: the grid of a difference-frequency
  QTF (optional; its own grid, usually coarser than ``omega``).

Variables (SI units; ``units`` and ``long_name`` on each)

* ``added_mass(omega, influenced_dof, radiating_dof)`` kg, kg m, kg m^2
* ``radiation_damping(omega, influenced_dof, radiating_dof)`` N s/m, N s, N m s
* ``excitation_force(omega, wave_direction, influenced_dof)`` complex, per unit wave amplitude,
  N/m and N m/m, with the phase convention below.
* ``infinite_frequency_added_mass(influenced_dof, radiating_dof)`` (when known)
* ``zero_frequency_added_mass(influenced_dof, radiating_dof)`` (when known)
* ``hydrostatic_stiffness(influenced_dof, radiating_dof)``: waterplane and buoyancy terms only,
  about the reference point, WITHOUT the gravity term -m g z_G (the vessel adds it,
  see :mod:`floatmoor.hydro.vessel`).
* ``mean_drift_force(omega, wave_direction, influenced_dof)`` N/m^2 (N m/m^2 for moments):
  mean second-order force per squared wave amplitude.  NaN marks frequencies or headings where
  it is not available (e.g. outside the range of a QTF file): never extrapolate silently.
* ``difference_frequency_qtf(qtf_omega, qtf_omega_2, qtf_wave_direction, influenced_dof)``
  complex, N/m^2: WAMIT's difference-frequency QTF, F(t) = Re sum A_1 A_2 Q exp(i (w1 - w2) t)
  (unidirectional); its diagonal is the mean drift.

Phase convention (attribute ``phase_convention``): ``exp(+i omega t)``, as WAMIT.  The wave
elevation at the origin is Re[A exp(i omega t)] and the excitation force is
Re[A X exp(i omega t)].  Capytaine's exp(-i omega t) data are complex-conjugated on read.

Attributes: ``phase_convention``, ``rho`` (kg/m^3), ``g`` (m/s^2), ``water_depth`` (m, inf for
deep water), ``reference_point`` (x, y, z in m, body frame, about which matrices are given),
``source`` (file(s) read), ``floatmoor_database_version``.

netCDF: complex variables are split along a ``complex`` dimension with coordinates ``re``/``im``
as Capytaine does (``separate_complex_values``).
"""

from __future__ import annotations

import os
import warnings
from pathlib import Path

import numpy as np
import xarray as xr

from ..core.dofs import DOF_NAMES
from ..core.errors import FloatmoorWarning, SceneError

__all__ = [
    "DOF_NAMES", "PHASE_CONVENTION", "make_database", "save_database", "load_database",
    "validate_database", "matrix_units", "DatabaseError",
]

PHASE_CONVENTION = "exp(+i omega t)"
DATABASE_VERSION = "1"

_TRANS = {"surge", "sway", "heave"}


class DatabaseError(SceneError):
    """A hydrodynamic database (file or Dataset) that is unusable.  A SceneError: the 'key' is
    the quantity concerned (``added_mass``, ``omega``, ...)."""

    def __init__(self, file, quantity: str, expected: str, found=SceneError.MISSING,
                 hint: str | None = None):
        super().__init__(file, quantity, expected, found, hint)


def _unit_pair(i: str, j: str, kind: str) -> str:
    ti, tj = i in _TRANS, j in _TRANS
    if kind == "added_mass":
        return {(True, True): "kg", (False, False): "kg m^2"}.get((ti, tj), "kg m")
    if kind == "radiation_damping":
        return {(True, True): "N s/m", (False, False): "N m s/rad"}.get((ti, tj), "N s")
    if kind == "hydrostatic_stiffness":
        return {(True, True): "N/m", (False, False): "N m/rad"}.get((ti, tj), "N")
    raise ValueError(kind)


def matrix_units(kind: str) -> str:
    """The ``units`` attribute text of a 6x6 matrix variable (mixed units spelled out)."""
    return {"added_mass": "kg (translation), kg m (coupling), kg m^2 (rotation)",
            "radiation_damping": "N s/m (translation), N s (coupling), N m s/rad (rotation)",
            "hydrostatic_stiffness": "N/m (translation), N (coupling), N m/rad (rotation)",
            }[kind]


_ATTRS = {
    "omega": ("rad/s", "wave angular frequency"),
    "wave_direction": ("rad", "wave heading: direction of travel, from +x towards +y"),
    "added_mass": (matrix_units("added_mass"), "added mass A_ij (force i, motion j)"),
    "radiation_damping": (matrix_units("radiation_damping"),
                          "radiation damping B_ij (force i, motion j)"),
    "infinite_frequency_added_mass": (matrix_units("added_mass"),
                                      "infinite-frequency added mass A_ij(inf)"),
    "zero_frequency_added_mass": (matrix_units("added_mass"), "zero-frequency added mass A_ij(0)"),
    "hydrostatic_stiffness": (matrix_units("hydrostatic_stiffness"),
                              "hydrostatic restoring (waterplane and buoyancy; no -m g z_G term)"),
    "excitation_force": ("N/m (force), N m/m (moment), per unit wave amplitude",
                         "first-order wave excitation (Froude-Krylov + diffraction), "
                         "convention exp(+i omega t)"),
    "mean_drift_force": ("N/m^2 (force), N m/m^2 (moment), per squared wave amplitude",
                         "mean second-order wave drift force"),
}


def _set_attrs(ds: xr.Dataset) -> xr.Dataset:
    for name, (units, long_name) in _ATTRS.items():
        if name in ds.variables:
            ds[name].attrs.setdefault("units", units)
            ds[name].attrs.setdefault("long_name", long_name)
    for name in ("influenced_dof", "radiating_dof"):
        if name in ds.coords:
            ds[name].attrs.setdefault("long_name", "degree of freedom (" +
                                      ("force" if name == "influenced_dof" else "motion") + ")")
            ds[name].attrs.setdefault("units", "1")
    return ds


def make_database(omega, wave_direction=None, *, added_mass, radiation_damping,
                  excitation_force=None, infinite_frequency_added_mass=None,
                  zero_frequency_added_mass=None, hydrostatic_stiffness=None,
                  mean_drift_force=None,
                  rho: float = 1025.0, g: float = 9.80665, water_depth: float = np.inf,
                  reference_point=(0.0, 0.0, 0.0), source: str = "") -> xr.Dataset:
    """Build a database Dataset from plain arrays (SI units, convention exp(+i omega t)).

    Parameters
    ----------
    omega : (n_w,) rad/s, strictly increasing.
    wave_direction : (n_b,) rad, direction of travel; required with excitation or drift.
    added_mass, radiation_damping : (n_w, 6, 6) indexed [omega, force i, motion j].
    excitation_force : (n_w, n_b, 6) complex, per unit amplitude.
    infinite_frequency_added_mass, zero_frequency_added_mass, hydrostatic_stiffness : (6, 6).
    mean_drift_force : (n_w, n_b, 6), N/m^2 and N m/m^2.
    (a difference-frequency QTF is attached with :func:`floatmoor.hydro.wamit.add_qtf`)
    rho, g, water_depth, reference_point : metadata stored as attributes.
    """
    omega = np.asarray(omega, float)
    coords = {"omega": omega, "influenced_dof": list(DOF_NAMES), "radiating_dof": list(DOF_NAMES)}
    if wave_direction is not None:
        coords["wave_direction"] = np.asarray(wave_direction, float)
    mat = ("influenced_dof", "radiating_dof")
    data = {
        "added_mass": (("omega",) + mat, np.asarray(added_mass, float)),
        "radiation_damping": (("omega",) + mat, np.asarray(radiation_damping, float)),
    }
    if excitation_force is not None:
        data["excitation_force"] = (("omega", "wave_direction", "influenced_dof"),
                                    np.asarray(excitation_force, complex))
    for name, val in (("infinite_frequency_added_mass", infinite_frequency_added_mass),
                      ("zero_frequency_added_mass", zero_frequency_added_mass),
                      ("hydrostatic_stiffness", hydrostatic_stiffness)):
        if val is not None:
            data[name] = (mat, np.asarray(val, float))
    if mean_drift_force is not None:
        data["mean_drift_force"] = (("omega", "wave_direction", "influenced_dof"),
                                    np.asarray(mean_drift_force, float))
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({
        "phase_convention": PHASE_CONVENTION,
        "rho": float(rho), "g": float(g), "water_depth": float(water_depth),
        "reference_point": np.asarray(reference_point, float),
        "source": str(source),
        "floatmoor_database_version": DATABASE_VERSION,
    })
    return _set_attrs(ds)


# ------------------------------------------------------------------------------------------
# netCDF
# ------------------------------------------------------------------------------------------
def _separate_complex(ds: xr.Dataset) -> xr.Dataset:
    out = ds.copy()
    for name in list(ds.data_vars):
        da = ds[name]
        if np.iscomplexobj(da.values):
            split = xr.concat([da.real, da.imag], dim="complex").assign_coords(complex=["re", "im"])
            split = split.transpose(*da.dims, "complex")
            split.attrs = dict(da.attrs)
            out[name] = split
    return out


def _merge_complex(ds: xr.Dataset) -> xr.Dataset:
    if "complex" not in ds.dims:
        return ds
    out = ds.copy()
    for name in list(ds.data_vars):
        da = ds[name]
        if "complex" in da.dims:
            merged = da.sel(complex="re") + 1j * da.sel(complex="im")
            merged.attrs = dict(da.attrs)
            out[name] = merged
    return out.drop_dims("complex")


def save_database(ds: xr.Dataset, path) -> Path:
    """Write a database to netCDF (complex values split along ``complex`` = re/im).

    Parameters
    ----------
    ds : database Dataset (see module docstring); validated before writing.
    path : output file (``.nc``).

    Returns
    -------
    The path written.
    """
    path = Path(path)
    validate_database(ds, name=str(path))
    out = _separate_complex(ds)
    attrs = {}
    for k, v in out.attrs.items():
        if isinstance(v, (bool, np.bool_)):
            v = int(v)
        attrs[k] = v
    out.attrs = attrs
    encoding = {name: {"zlib": True, "complevel": 4} for name in out.data_vars}
    out.to_netcdf(path, encoding=encoding)
    return path


def load_database(path, *, validate: bool = True) -> xr.Dataset:
    """Read a database written by :func:`save_database` (no capytaine needed).

    Raises
    ------
    DatabaseError (a SceneError) naming the file when it is missing or not a database.
    """
    path = Path(path)
    if not path.exists():
        raise DatabaseError(path, "", "an existing hydrodynamic database file (.nc)",
                            "no such file")
    try:
        with xr.open_dataset(path) as raw:
            ds = raw.load()
    except Exception as exc:  # netCDF/HDF errors have many types
        raise DatabaseError(path, "", "a netCDF hydrodynamic database",
                            f"an unreadable file ({exc})") from None
    ds = _merge_complex(ds)
    for k in ("influenced_dof", "radiating_dof"):
        if k in ds.coords:
            ds = ds.assign_coords({k: [str(v) for v in ds[k].values]})
    if "reference_point" in ds.attrs:
        ds.attrs["reference_point"] = np.atleast_1d(np.asarray(ds.attrs["reference_point"], float))
    if validate:
        validate_database(ds, name=str(path))
    return ds


# ------------------------------------------------------------------------------------------
# validation
# ------------------------------------------------------------------------------------------
def validate_database(ds: xr.Dataset, name: str | os.PathLike | None = None, *,
                      sym_rtol: float = 1e-2, neg_damping_rtol: float = 1e-3) -> xr.Dataset:
    """Check a database Dataset; raise :class:`DatabaseError` or warn, naming file and quantity.

    Errors: missing variables or dims, wrong DOF names, non-finite values, frequencies not
    strictly increasing or not positive, wrong phase convention, excitation/drift on a
    different grid.  Warnings (:class:`FloatmoorWarning`): added mass, damping or stiffness
    not symmetric within ``sym_rtol`` (relative to sqrt(|X_ii X_jj|)), negative diagonal
    damping beyond ``neg_damping_rtol`` of the largest diagonal value.

    Returns the Dataset unchanged.
    """
    where = name if name is not None else ds.attrs.get("source", None) or "<database>"
    for v in ("added_mass", "radiation_damping"):
        if v not in ds.data_vars:
            raise DatabaseError(where, v, f"a variable {v}(omega, influenced_dof, radiating_dof)")
        if tuple(ds[v].dims) != ("omega", "influenced_dof", "radiating_dof"):
            raise DatabaseError(where, v, "dims (omega, influenced_dof, radiating_dof)",
                                tuple(ds[v].dims))
    for d in ("influenced_dof", "radiating_dof"):
        names = tuple(str(x) for x in ds[d].values)
        if names != DOF_NAMES:
            raise DatabaseError(where, d, "the DOF names " + ", ".join(DOF_NAMES), names)
    conv = ds.attrs.get("phase_convention", None)
    if conv != PHASE_CONVENTION:
        raise DatabaseError(where, "phase_convention", f"the attribute {PHASE_CONVENTION!r}", conv,
                            "convert the data on read (Capytaine: use read_capytaine)")
    omega = np.asarray(ds["omega"].values, float)
    if omega.size < 1 or not np.all(np.isfinite(omega)) or np.any(omega <= 0):
        raise DatabaseError(where, "omega", "finite frequencies > 0 rad/s", omega[:5])
    if np.any(np.diff(omega) <= 0):
        raise DatabaseError(where, "omega", "strictly increasing frequencies",
                            "a grid that is not increasing or has repeated values")
    if "wave_direction" in ds.coords:
        beta = np.asarray(ds["wave_direction"].values, float)
        if not np.all(np.isfinite(beta)) or np.any(np.abs(beta) > 2 * np.pi + 1e-9):
            raise DatabaseError(where, "wave_direction", "headings in rad within [-2 pi, 2 pi]",
                                beta[:5], "headings are stored in rad in the database")
    for v in ds.data_vars:
        vals = np.asarray(ds[v].values)
        if str(v).endswith("mean_drift_force"):  # NaN = not available there; inf never
            if np.any(np.isinf(vals)) or np.all(np.isnan(vals)):
                raise DatabaseError(where, v, "finite values (NaN only where not available)",
                                    "inf or no value at all")
            continue
        if vals.dtype.kind in "fc" and not np.all(np.isfinite(vals)):
            bad = np.argwhere(~np.isfinite(vals))[0]
            raise DatabaseError(where, v, "finite values", f"NaN/inf at index {tuple(bad)}")
    for v in ("excitation_force", "mean_drift_force"):
        if v in ds.data_vars:
            want = ("omega", "wave_direction", "influenced_dof")
            if tuple(ds[v].dims) != want:
                raise DatabaseError(where, v, "dims " + str(want), tuple(ds[v].dims))
    for v in ("infinite_frequency_added_mass", "zero_frequency_added_mass", "hydrostatic_stiffness"):
        if v in ds.data_vars and tuple(ds[v].dims) != ("influenced_dof", "radiating_dof"):
            raise DatabaseError(where, v, "dims (influenced_dof, radiating_dof)", tuple(ds[v].dims))
    # symmetry
    for v in ("added_mass", "radiation_damping", "infinite_frequency_added_mass",
              "zero_frequency_added_mass"):
        if v not in ds.data_vars:
            continue
        m = np.asarray(ds[v].values, float)
        m3 = m.reshape((-1, 6, 6))
        err = _asymmetry(m3)
        if err > sym_rtol:
            warnings.warn(f"{where}: {v} is not symmetric (largest |X_ij - X_ji| / "
                          f"sqrt|X_ii X_jj| = {err:.3g} > {sym_rtol:g})", FloatmoorWarning,
                          stacklevel=2)
    # negative diagonal damping
    b = np.asarray(ds["radiation_damping"].values, float)
    diag = np.diagonal(b, axis1=1, axis2=2)
    scale = np.max(np.abs(diag), axis=0)
    for k, dof in enumerate(DOF_NAMES):
        if scale[k] > 0:
            worst = np.min(diag[:, k])
            if worst < -neg_damping_rtol * scale[k]:
                iw = int(np.argmin(diag[:, k]))
                warnings.warn(f"{where}: radiation_damping[{dof},{dof}] is negative "
                              f"({worst:.4g} at omega = {omega[iw]:.4g} rad/s); "
                              "check the panel model (irregular frequencies?)", FloatmoorWarning,
                              stacklevel=2)
    return ds


def _asymmetry(m3: np.ndarray) -> float:
    d = np.abs(np.diagonal(m3, axis1=1, axis2=2))
    dmax = np.max(d, axis=0)
    scale = np.sqrt(np.outer(dmax, dmax))
    scale[scale == 0] = np.inf
    diff = np.max(np.abs(m3 - np.swapaxes(m3, 1, 2)), axis=0)
    return float(np.max(diff / scale))


def interpolate_heading(ds: xr.Dataset, variable: str, heading: float, *,
                        dim: str = "wave_direction") -> np.ndarray:
    """``ds[variable]`` at a wave heading (rad, direction of travel), linear in heading.

    A database whose headings cover the full circle (the largest gap, counted across the
    wrap-around, equals the step) is treated as periodic; otherwise a heading outside
    [min, max] is a DatabaseError naming the database and the quantity.

    A heading equal to a database heading (within 1e-9 rad) returns the stored values
    unchanged, NaN only where that heading holds NaN; between headings NaN propagates from
    either neighbour (the interpolation needs both).

    Returns the array with the heading dimension removed (same order of the other dims).
    """
    where = ds.attrs.get("source", "<database>")
    if variable not in ds:
        raise DatabaseError(where, variable, f"a variable {variable} in the database")
    da = ds[variable]
    beta = np.asarray(ds[dim].values, float)
    axis = da.dims.index(dim)
    vals = np.moveaxis(np.asarray(da.values), axis, 0)
    order = np.argsort(beta)
    beta, vals = beta[order], vals[order]
    if beta.size == 1:
        if abs(np.angle(np.exp(1j * (heading - beta[0])))) < 1e-6:
            return vals[0]
        raise DatabaseError(where, f"{variable} at heading {np.degrees(heading):.1f} deg",
                            f"the only heading of the database, {np.degrees(beta[0]):.1f} deg",
                            f"{np.degrees(heading):.1f} deg")
    steps = np.diff(beta)
    wrap_gap = beta[0] + 2 * np.pi - beta[-1]
    periodic = wrap_gap <= np.max(steps) + 1e-6 and wrap_gap > 1e-9
    if periodic:
        x = (heading - beta[0]) % (2 * np.pi) + beta[0]
        b = np.concatenate([beta, [beta[0] + 2 * np.pi]])
        v = np.concatenate([vals, vals[:1]], axis=0)
    else:
        x = heading
        # allow the same direction written as heading +- 2 pi
        for cand in (heading, heading - 2 * np.pi, heading + 2 * np.pi):
            if beta[0] - 1e-9 <= cand <= beta[-1] + 1e-9:
                x = cand
                break
        else:
            raise DatabaseError(where, f"{variable} at heading {np.degrees(heading):.1f} deg",
                                f"a heading within the database range "
                                f"{np.degrees(beta[0]):.1f} .. {np.degrees(beta[-1]):.1f} deg",
                                f"{np.degrees(heading):.1f} deg",
                                "extend the diffraction run or mirror a symmetric hull")
        b, v = beta, vals
    # an exact database heading (within 1e-9 rad) is returned as stored: the linear weights
    # would otherwise give 0 x NaN = NaN where only the neighbouring heading holds NaN
    hit = np.flatnonzero(np.abs(b - x) < 1e-9)
    if hit.size:
        return np.array(v[hit[0]], copy=True)
    k = int(np.clip(np.searchsorted(b, x) - 1, 0, b.size - 2))
    f = (x - b[k]) / (b[k + 1] - b[k])
    return (1 - f) * v[k] + f * v[k + 1]
