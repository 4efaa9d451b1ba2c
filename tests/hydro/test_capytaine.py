"""Capytaine reader: convention conversion (no capytaine needed) and a real round trip."""

import numpy as np
import pytest
import xarray as xr

from floatmoor.hydro import DatabaseError, load_database, read_capytaine, save_database

CPT_DOFS = ["Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"]


def _fake_capytaine(tmp_path, drop_excitation=False):
    """A dataset laid out as Capytaine writes it (exp(-i w t), capitalised DOFs, re/im split)."""
    rng = np.random.default_rng(1)
    w = np.array([0.5, 1.0, 1.5])
    beta = np.array([0.0, np.pi / 2])
    A = rng.normal(size=(3, 6, 6))
    B = np.abs(rng.normal(size=(3, 6, 6)))
    FK = rng.normal(size=(3, 2, 6)) + 1j * rng.normal(size=(3, 2, 6))
    DF = rng.normal(size=(3, 2, 6)) + 1j * rng.normal(size=(3, 2, 6))
    ds = xr.Dataset(
        {"added_mass": (("omega", "radiating_dof", "influenced_dof"), np.swapaxes(A, 1, 2)),
         "radiation_damping": (("omega", "radiating_dof", "influenced_dof"), np.swapaxes(B, 1, 2)),
         "Froude_Krylov_force": (("omega", "wave_direction", "influenced_dof"), FK),
         "diffraction_force": (("omega", "wave_direction", "influenced_dof"), DF)},
        coords={"omega": w, "wave_direction": beta, "radiating_dof": CPT_DOFS,
                "influenced_dof": CPT_DOFS, "rho": 1000.0, "g": 9.81, "water_depth": np.inf,
                "period": ("omega", 2 * np.pi / w)})
    if not drop_excitation:
        ds["excitation_force"] = ds.Froude_Krylov_force + ds.diffraction_force
    split = xr.concat([ds.map(np.real), ds.map(np.imag)], dim="complex")
    split = split.assign_coords(complex=["re", "im"])
    for v in ("added_mass", "radiation_damping"):
        split[v] = ds[v]
    path = tmp_path / "cpt.nc"
    split.to_netcdf(path)
    return path, A, B, FK + DF


@pytest.mark.parametrize("drop_excitation", [False, True])
def test_reader_conjugates_and_reorders(tmp_path, drop_excitation):
    path, A, B, X = _fake_capytaine(tmp_path, drop_excitation)
    db = read_capytaine(path)
    assert db.attrs["phase_convention"] == "exp(+i omega t)"
    assert list(db.influenced_dof.values) == ["surge", "sway", "heave", "roll", "pitch", "yaw"]
    # matrices are [influenced (force i), radiating (motion j)] whatever the file's dim order
    np.testing.assert_allclose(db.added_mass.values, A)
    np.testing.assert_allclose(db.radiation_damping.values, B)
    # exp(-i w t) -> exp(+i w t): complex conjugate; FK + diffraction = excitation
    np.testing.assert_allclose(db.excitation_force.values, np.conj(X))
    assert db.attrs["rho"] == 1000.0 and db.attrs["g"] == 9.81


def test_reader_errors_name_the_file(tmp_path):
    with pytest.raises(DatabaseError, match="missing.nc"):
        read_capytaine(tmp_path / "missing.nc")
    path, *_ = _fake_capytaine(tmp_path)
    ds = xr.open_dataset(path).load()
    ds = ds.isel(radiating_dof=[0, 1, 2], influenced_dof=[0, 1, 2])
    p2 = tmp_path / "three_dofs.nc"
    ds.to_netcdf(p2)
    with pytest.raises(DatabaseError, match="three_dofs.nc: (influenced|radiating)_dof"):
        read_capytaine(p2)


@pytest.fixture(scope="module")
def cylinder(tmp_path_factory):
    cpt = pytest.importorskip("capytaine")
    # radius 5 m, draft 10 m, extending 4 m above the water line (clipped by immersed_part)
    mesh = cpt.mesh_vertical_cylinder(length=14.0, radius=5.0, center=(0, 0, -3.0),
                                      resolution=(3, 16, 7))
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, 0)),
                            center_of_mass=(0, 0, 0)).immersed_part()
    test = xr.Dataset(coords={"omega": [0.05, 0.5, 1.0], "wave_direction": [0.0, np.pi / 2],
                              "radiating_dof": list(body.dofs), "water_depth": [np.inf],
                              "rho": [1025.0], "g": [9.80665]})
    ds = cpt.BEMSolver().fill_dataset(test, body, hydrostatics=True)
    path = tmp_path_factory.mktemp("cpt") / "cylinder.nc"
    cpt.io.xarray.export_dataset(path, ds, format="netcdf")
    return ds, path


@pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")  # coarse mesh
def test_capytaine_round_trip(cylinder, tmp_path):
    raw, path = cylinder
    db = read_capytaine(path)
    r = raw.squeeze()
    A = r.added_mass.transpose("omega", "influenced_dof", "radiating_dof").values
    np.testing.assert_allclose(db.added_mass.values, A, rtol=1e-12)
    X = r.excitation_force.transpose("omega", "wave_direction", "influenced_dof").values
    np.testing.assert_allclose(db.excitation_force.values, np.conj(X), rtol=1e-12)
    np.testing.assert_allclose(db.hydrostatic_stiffness.values,
                               r.hydrostatic_stiffness.transpose("influenced_dof",
                                                                 "radiating_dof").values)
    # and through floatmoor's own netCDF
    back = load_database(save_database(db, tmp_path / "db.nc"))
    for v in db.data_vars:
        np.testing.assert_array_equal(back[v].values, db[v].values)


def test_capytaine_phase_convention_long_wave_limits(cylinder):
    _, path = cylinder
    db = read_capytaine(path)
    # Hand: C33 = rho g pi R^2 = 1025 * 9.80665 * pi * 25 = 789,456 N/m; the panelled waterplane
    # (16-gon) is 2.6 % smaller.  Long wave (omega = 0.05 rad/s, lambda = 24.7 km): the heave
    # excitation tends to C33 * A in phase with the elevation at the origin (exp(+i w t)).
    c33 = db.hydrostatic_stiffness.values[2, 2]
    assert c33 == pytest.approx(1025 * 9.80665 * np.pi * 25, rel=0.03)
    x3 = complex(db.excitation_force.isel(omega=0, wave_direction=0).sel(influenced_dof="heave"))
    assert abs(x3 / c33 - 1) < 0.01
    # Surge, waves towards +x: the force follows the horizontal fluid acceleration
    # d/dt [w A e^{kz} e^{i w t}] = i w^2 (...) -> phase +90 deg in exp(+i w t) (it would be
    # -90 deg in Capytaine's own exp(-i w t) numbers).
    x1 = complex(db.excitation_force.isel(omega=0, wave_direction=0).sel(influenced_dof="surge"))
    assert np.degrees(np.angle(x1)) == pytest.approx(90.0, abs=2.0)
    # the response sign test: heave RAO at the long-wave limit is +1 (body follows the wave)
    A = db.added_mass.values[0]
    B = db.radiation_damping.values[0]
    w = float(db.omega[0])
    m = 1025 * float(np.pi * 25 * 10)  # freely floating: mass = displaced mass
    z = (-w ** 2 * (m + A[2, 2]) + 1j * w * B[2, 2] + c33)
    rao = x3 / z
    assert abs(rao - 1) < 0.02
