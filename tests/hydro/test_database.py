"""Database form, netCDF round trip and validator."""

import warnings

import numpy as np
import pytest
import xarray as xr

from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.hydro import (
    DatabaseError,
    load_database,
    make_database,
    save_database,
    validate_database,
)


def _toy(n=5, nb=3, seed=0):
    rng = np.random.default_rng(seed)
    w = np.linspace(0.2, 1.0, n)
    A = rng.normal(size=(n, 6, 6))
    A = A + np.swapaxes(A, 1, 2) + 10 * np.eye(6)
    B = np.abs(rng.normal(size=(n, 6, 6)))
    B = B + np.swapaxes(B, 1, 2)
    X = rng.normal(size=(n, nb, 6)) + 1j * rng.normal(size=(n, nb, 6))
    D = rng.normal(size=(n, nb, 6))
    return make_database(w, np.radians(np.linspace(0, 90, nb)), added_mass=A, radiation_damping=B,
                         excitation_force=X, infinite_frequency_added_mass=A[-1],
                         hydrostatic_stiffness=np.diag([0, 0, 1e6, 1e8, 1e8, 0.0]),
                         mean_drift_force=D, source="toy")


def test_every_variable_has_units_and_long_name():
    ds = _toy()
    for name in list(ds.data_vars) + ["omega", "wave_direction"]:
        assert ds[name].attrs.get("units"), name
        assert ds[name].attrs.get("long_name"), name
    assert ds.attrs["phase_convention"] == "exp(+i omega t)"
    assert ds.added_mass.dims == ("omega", "influenced_dof", "radiating_dof")


def test_netcdf_round_trip_splits_complex_values(tmp_path):
    ds = _toy()
    path = save_database(ds, tmp_path / "db.nc")
    with xr.open_dataset(path) as raw:  # on disk: Capytaine's re/im split
        assert "complex" in raw.dims
        assert list(raw["complex"].values) == ["re", "im"]
        assert raw.excitation_force.dims[-1] == "complex"
    back = load_database(path)
    for name in ds.data_vars:
        np.testing.assert_array_equal(back[name].values, ds[name].values)
        assert back[name].dims == ds[name].dims
    assert np.iscomplexobj(back.excitation_force.values)
    assert list(back.influenced_dof.values) == list(ds.influenced_dof.values)
    np.testing.assert_array_equal(back.attrs["reference_point"], [0, 0, 0])


def test_missing_file_names_the_file(tmp_path):
    with pytest.raises(SceneError, match="nothere.nc"):
        load_database(tmp_path / "nothere.nc")


def test_garbage_file_names_the_file(tmp_path):
    p = tmp_path / "bad.nc"
    p.write_text("not netcdf")
    with pytest.raises(DatabaseError, match="bad.nc"):
        load_database(p)


def test_validator_errors_name_the_quantity():
    ds = _toy()
    bad = ds.assign_coords(omega=ds.omega.values[::-1])
    with pytest.raises(DatabaseError, match="omega.*increasing"):
        validate_database(bad, name="x.nc")
    bad = ds.copy()
    bad.attrs["phase_convention"] = "exp(-i omega t)"
    with pytest.raises(DatabaseError, match="phase_convention"):
        validate_database(bad, name="x.nc")
    bad = ds.copy(deep=True)
    bad.added_mass.values[1, 2, 2] = np.nan
    with pytest.raises(DatabaseError, match="x.nc: added_mass"):
        validate_database(bad, name="x.nc")
    bad = ds.drop_vars("radiation_damping")
    with pytest.raises(DatabaseError, match="radiation_damping"):
        validate_database(bad, name="x.nc")
    bad = ds.assign_coords(influenced_dof=["x", "sway", "heave", "roll", "pitch", "yaw"])
    with pytest.raises(DatabaseError, match="influenced_dof"):
        validate_database(bad, name="x.nc")
    bad = ds.assign_coords(wave_direction=[0.0, 45.0, 90.0])  # degrees by mistake
    with pytest.raises(DatabaseError, match="wave_direction"):
        validate_database(bad, name="x.nc")


def test_validator_warns_on_asymmetry_and_negative_damping():
    ds = _toy()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        validate_database(ds, name="ok.nc")  # no warning for a clean database
    bad = ds.copy(deep=True)
    bad.added_mass.values[:, 0, 4] += 5.0
    with pytest.warns(FloatmoorWarning, match="bad.nc: added_mass is not symmetric"):
        validate_database(bad, name="bad.nc")
    bad = ds.copy(deep=True)
    bad.radiation_damping.values[2, 3, 3] = -1.0
    with pytest.warns(FloatmoorWarning, match=r"radiation_damping\[roll,roll\] is negative"):
        validate_database(bad, name="bad.nc")


def test_mean_drift_may_hold_nan_but_not_only_nan():
    ds = _toy()
    part = ds.copy(deep=True)
    part.mean_drift_force.values[0] = np.nan
    validate_database(part)
    allnan = ds.copy(deep=True)
    allnan.mean_drift_force.values[:] = np.nan
    with pytest.raises(DatabaseError, match="mean_drift_force"):
        validate_database(allnan)


def test_interpolate_heading_inside_periodic_and_outside():
    from floatmoor.hydro.database import interpolate_heading
    ds = _toy(nb=3)  # headings 0, 45, 90 deg: not periodic
    X = ds.excitation_force.values
    mid = interpolate_heading(ds, "excitation_force", np.radians(22.5))
    np.testing.assert_allclose(mid, 0.5 * (X[:, 0] + X[:, 1]))
    with pytest.raises(DatabaseError, match=r"excitation_force at heading 120.0 deg"):
        interpolate_heading(ds, "excitation_force", np.radians(120))
    full = _toy(nb=4).assign_coords(wave_direction=np.radians([0, 90, 180, 270]))
    Xf = full.excitation_force.values
    wrap = interpolate_heading(full, "excitation_force", np.radians(315))
    np.testing.assert_allclose(wrap, 0.5 * (Xf[:, 3] + Xf[:, 0]))
    np.testing.assert_allclose(interpolate_heading(full, "excitation_force", np.radians(-90)),
                               Xf[:, 3])


def test_interpolate_heading_exact_hit_ignores_nan_neighbour():
    # regression: OC4 mean drift known at heading 0 only (marin_semi.12d), NaN at the other
    # headings; the linear weights gave 0 x NaN = NaN at exactly 0 deg.
    from floatmoor.hydro.database import interpolate_heading
    ds = _toy(nb=3)  # headings 0, 45, 90 deg
    ds.mean_drift_force.values[:, 1:] = np.nan
    D = ds.mean_drift_force.values
    at0 = interpolate_heading(ds, "mean_drift_force", 0.0)
    np.testing.assert_array_equal(at0, D[:, 0])
    assert np.all(np.isfinite(at0))
    # the same direction written as 360 deg, and a periodic database hit at its wrap point
    np.testing.assert_array_equal(interpolate_heading(ds, "mean_drift_force", 2 * np.pi), D[:, 0])
    # NaN where the interpolation really needs the NaN neighbour
    assert np.all(np.isnan(interpolate_heading(ds, "mean_drift_force", np.radians(10))))
    # exact hits of finite headings are unchanged in the middle of the range
    np.testing.assert_array_equal(interpolate_heading(ds, "excitation_force", np.radians(45)),
                                  ds.excitation_force.values[:, 1])
    full = _toy(nb=4).assign_coords(wave_direction=np.radians([0, 90, 180, 270]))
    full.mean_drift_force.values[:, 1:] = np.nan
    np.testing.assert_array_equal(interpolate_heading(full, "mean_drift_force", 0.0),
                                  full.mean_drift_force.values[:, 0])
    np.testing.assert_array_equal(interpolate_heading(full, "mean_drift_force", -2 * np.pi),
                                  full.mean_drift_force.values[:, 0])
