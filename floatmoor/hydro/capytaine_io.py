"""Reading Capytaine datasets (netCDF files or in-memory xarray) into floatmoor's database form.

Capytaine (capytaine.github.io) writes its results with ``cpt.assemble_dataset`` and saves them
with complex values split along a ``complex`` dimension (``re``/``im``).  Its conventions and
what this reader does with them:

* time dependence exp(-i omega t): complex amplitudes are complex-conjugated to floatmoor's
  exp(+i omega t) (same physical signal Re[X e^{-iwt}] = Re[conj(X) e^{+iwt}]);
* ``wave_direction`` in rad, direction of propagation from +x towards +y: kept as is;
* DOF names ``Surge`` .. ``Yaw``: mapped case-insensitively to ``surge`` .. ``yaw``; all six
  rigid-body DOFs are required;
* excitation = ``Froude_Krylov_force`` + ``diffraction_force`` when ``excitation_force`` is
  absent;
* ``omega`` = 0 and ``omega`` = inf rows (Capytaine >= 2 can compute them) become
  ``zero_frequency_added_mass`` and ``infinite_frequency_added_mass``;
* ``rho``, ``g``, ``water_depth`` and ``rotation_center`` (the reference point) are taken from
  its coordinates.

Capytaine itself is NOT needed to read a file.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from ..core.dofs import DOF_NAMES
from .database import DatabaseError, _merge_complex, make_database

__all__ = ["read_capytaine", "from_capytaine_dataset"]


def _scalar(ds, name, default):
    if name in ds.coords or name in ds.data_vars:
        v = np.asarray(ds[name].values)
        if v.size == 1:
            return float(v.reshape(-1)[0])
        raise DatabaseError(ds.attrs.get("_path", "<capytaine dataset>"), name,
                            "a single value (one body, one condition per dataset)",
                            f"{v.size} values", "select one value with ds.sel(...) first")
    return default


def from_capytaine_dataset(cds: xr.Dataset, where="<capytaine dataset>") -> xr.Dataset:
    """Convert a Capytaine result Dataset (in memory) to a floatmoor database."""
    cds = _merge_complex(cds)
    if "omega" not in cds.dims:
        for d in ("period", "freq", "wavenumber", "wavelength"):
            if d in cds.dims and "omega" in cds.coords:
                cds = cds.swap_dims({d: "omega"})
                break
        else:
            raise DatabaseError(where, "omega", "a Capytaine dataset with an omega dimension",
                                list(cds.dims))
    for v in ("added_mass", "radiation_damping"):
        if v not in cds:
            raise DatabaseError(where, v, f"the Capytaine variable {v}")
    # DOF names
    rename = {}
    for d in ("influenced_dof", "radiating_dof"):
        names = [str(x) for x in cds[d].values]
        low = [n.lower() for n in names]
        missing = [n for n in DOF_NAMES if n not in low]
        if missing:
            raise DatabaseError(where, d, "the six rigid-body DOFs Surge..Yaw",
                                names, "compute with cpt.rigid_body_dofs()")
        rename[d] = low
    cds = cds.assign_coords({d: rename[d] for d in rename})
    cds = cds.sel(influenced_dof=list(DOF_NAMES), radiating_dof=list(DOF_NAMES))
    if "wave_direction" in cds.dims:
        cds = cds.sortby("wave_direction")
    cds = cds.sortby("omega")
    omega_all = np.asarray(cds["omega"].values, float)
    finite = np.isfinite(omega_all) & (omega_all > 0)
    A_all = cds["added_mass"].transpose("omega", "influenced_dof", "radiating_dof").values
    B_all = cds["radiation_damping"].transpose("omega", "influenced_dof", "radiating_dof").values
    A0 = A_all[np.nonzero(omega_all == 0)[0][0]] if np.any(omega_all == 0) else None
    Ainf = A_all[np.nonzero(np.isinf(omega_all))[0][0]] if np.any(np.isinf(omega_all)) else None
    omega = omega_all[finite]
    X = beta = None
    if "excitation_force" in cds:
        Xc = cds["excitation_force"]
    elif "diffraction_force" in cds and "Froude_Krylov_force" in cds:
        Xc = cds["diffraction_force"] + cds["Froude_Krylov_force"]
    else:
        Xc = None
    if Xc is not None:
        Xc = Xc.transpose("omega", "wave_direction", "influenced_dof")
        X = np.conj(np.asarray(Xc.values)[finite])  # exp(-iwt) -> exp(+iwt)
        beta = np.asarray(cds["wave_direction"].values, float)
    C = None
    if "hydrostatic_stiffness" in cds:
        C = cds["hydrostatic_stiffness"].transpose("influenced_dof", "radiating_dof").values
    ref = (0.0, 0.0, 0.0)
    if "rotation_center" in cds.coords or "rotation_center" in cds:
        ref = tuple(np.asarray(cds["rotation_center"].values, float).reshape(3))
    drift = None
    if "mean_drift_force" in cds:  # floatmoor's own addition when written by our scripts
        drift = cds["mean_drift_force"].transpose("omega", "wave_direction",
                                                  "influenced_dof").values[finite]
    ds = make_database(omega, beta, added_mass=A_all[finite], radiation_damping=B_all[finite],
                       excitation_force=X, infinite_frequency_added_mass=Ainf,
                       zero_frequency_added_mass=A0, hydrostatic_stiffness=C,
                       mean_drift_force=drift,
                       rho=_scalar(cds, "rho", 1025.0), g=_scalar(cds, "g", 9.81),
                       water_depth=_scalar(cds, "water_depth", np.inf), reference_point=ref,
                       source=f"Capytaine {cds.attrs.get('capytaine_version', '')} {where}".strip())
    return ds


def read_capytaine(path) -> xr.Dataset:
    """Read a Capytaine netCDF result file into a floatmoor database (exp(+i omega t)).

    Parameters
    ----------
    path : netCDF file written by Capytaine (``cpt.io.xarray.export_dataset`` or
        ``separate_complex_values(ds).to_netcdf(path)``).

    Returns
    -------
    xarray.Dataset in floatmoor's database form.

    Raises
    ------
    DatabaseError naming the file when it is missing, unreadable or lacks a quantity.
    """
    path = Path(path)
    if not path.exists():
        raise DatabaseError(path, "", "an existing Capytaine netCDF file", "no such file")
    try:
        with xr.open_dataset(path) as raw:
            cds = raw.load()
    except Exception as exc:
        raise DatabaseError(path, "", "a netCDF file written by Capytaine",
                            f"an unreadable file ({exc})") from None
    for d in ("influenced_dof", "radiating_dof"):
        if d in cds.coords:
            cds = cds.assign_coords({d: [str(x) for x in cds[d].values]})
    return from_capytaine_dataset(cds, where=str(path))
