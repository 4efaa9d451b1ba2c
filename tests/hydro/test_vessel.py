"""Vessel files: loading, derived matrices, and SceneErrors naming file and key."""


import numpy as np
import pytest
import yaml

from floatmoor.core.errors import SceneError
from floatmoor.hydro import load_vessel, make_database, save_database
from floatmoor.hydro.vessel import gravity_stiffness, rigid_body_mass_matrix

from .conftest import VESSELS

G = 9.80665


def test_mass_matrix_parallel_axis_and_symmetry():
    m, r = 1000.0, np.array([1.0, -2.0, 3.0])
    Icg = np.diag([10.0, 20.0, 30.0])
    M = rigid_body_mass_matrix(m, r, Icg)
    np.testing.assert_allclose(M, M.T)
    # I_ref = I_cg + m (|r|^2 I - r r^T): e.g. Ixx = 10 + 1000 (4 + 9) = 13010
    assert M[3, 3] == pytest.approx(10 + m * (r[1] ** 2 + r[2] ** 2))
    assert M[3, 4] == pytest.approx(-m * r[0] * r[1])
    # kinetic energy check: a rotation about the reference point moves the CoG by theta x r
    theta = np.array([0.0, 0.0, 0.1])
    v_cog = np.cross(theta, r)
    u = np.concatenate([np.zeros(3), theta])
    ke = 0.5 * u @ M @ u
    assert ke == pytest.approx(0.5 * m * v_cog @ v_cog + 0.5 * theta @ Icg @ theta)


def test_gravity_stiffness_terms():
    C = gravity_stiffness(2.0e6, [1.0, 2.0, -10.0], G)
    assert C[3, 3] == pytest.approx(2.0e6 * G * 10) and C[4, 4] == pytest.approx(2.0e6 * G * 10)
    assert C[3, 5] == pytest.approx(2.0e6 * G * 1.0) and C[4, 5] == pytest.approx(2.0e6 * G * 2.0)


def test_oc3_vessel():
    v = load_vessel(VESSELS / "oc3_hywind" / "vessel.yaml")
    # total mass: platform 7,466,330 + tower 249,718 + nacelle 240,000 + rotor 110,000 kg
    assert v.mass == pytest.approx(8066048.0)
    # Independent check (MAP++ solution, docs/PUBLISHED_VALUES.md): buoyancy - weight equals the
    # vertical mooring load 3 x 535,728 N (MAP run with g = 9.81)
    buoyancy = 1025 * G * 8029.21
    assert buoyancy - v.mass * G == pytest.approx(3 * 535728.0, rel=0.005)
    np.testing.assert_allclose(v.mass_matrix, v.mass_matrix.T)
    # additional yaw spring and damping of HydroDyn
    assert v.additional_stiffness[5, 5] == 9.834e7
    assert v.linear_damping[5, 5] == 1.3e7 and v.linear_damping[2, 2] == 1.3e5
    # total roll restoring = WAMIT C44 (-4.99918e9) - m g z_G
    assert v.total_restoring[3, 3] == pytest.approx(-4.99918e9 - v.mass * G *
                                                    v.centre_of_gravity[2], rel=1e-5)
    assert v.total_restoring[3, 3] > 0
    assert v.fairleads["FL1"][2] == -70.0
    assert "excitation_force" in v.database


@pytest.mark.parametrize("name", ["floatel_like", "oc4_semi"])
def test_shipped_capytaine_vessels_load(name):
    path = VESSELS / name / "vessel.yaml"
    if not (VESSELS / name / "database.nc").exists():
        pytest.skip(f"{name}/database.nc not built yet")
    v = load_vessel(path)
    np.testing.assert_allclose(v.mass_matrix, v.mass_matrix.T)
    assert "excitation_force" in v.database
    assert "mean_drift_force" in v.database


# ---- bad input -------------------------------------------------------------------------------
@pytest.fixture
def vessel_dir(tmp_path):
    w = np.linspace(0.2, 1.0, 4)
    A = np.tile(np.eye(6), (4, 1, 1))
    save_database(make_database(w, added_mass=A, radiation_damping=0.1 * A,
                                hydrostatic_stiffness=np.diag([0, 0, 1e6, 1e8, 1e8, 0.0])),
                  tmp_path / "db.nc")
    return tmp_path


def _write(d, data):
    p = d / "vessel.yaml"
    p.write_text(yaml.safe_dump(data))
    return p


def _base():
    return {"name": "box", "database": "db.nc", "mass": 1.0e6, "centre_of_gravity": [0, 0, -1.0],
            "inertia_cg": [1.0e8, 1.0e8, 2.0e8]}


def test_minimal_vessel(vessel_dir):
    v = load_vessel(_write(vessel_dir, _base()))
    assert v.mass == 1.0e6
    assert v.total_restoring[3, 3] == pytest.approx(1e8 + 1.0e6 * G * 1.0)
    assert v.wind_coefficients is None and v.slender_elements is None


@pytest.mark.parametrize("change, key, words", [
    ({"mass": None}, "mass", "a number"),
    ({"mass": -5.0}, "mass", "> 0"),
    ({"mass": "heavy"}, "mass", "a number"),
    ({"centre_of_gravity": [0, 0]}, "centre_of_gravity", "shape (3)"),
    ({"inertia_cg": [[1, 2, 3], [0, 1, 0], [0, 0, 1]]}, "inertia_cg", "symmetric"),
    ({"linear_damping": [[1, 0], [0, 1]]}, "linear_damping", "shape (6, 6)"),
    ({"quadratic_damping": (-np.eye(6)).tolist()}, "quadratic_damping", "non-negative"),
    ({"databse": "db.nc"}, "databse", "unknown key"),
    ({"database": "nothere.nc"}, "database", "existing file"),
    ({"reference_point": [0, 0, 1.0]}, "reference_point", "reference point of the database"),
    ({"fairleads": {"FL1": [1, 2]}}, "fairleads.FL1", "shape (3)"),
    ({"wind_coefficients": {"heading": [0, 90], "surge": [1, 0]}}, "wind_coefficients.heading",
     "_deg"),
    ({"wind_coefficients": {"heading_deg": [0, 90, 45], "surge": [1, 0, 1]}},
     "wind_coefficients.heading_deg", "increasing"),
    ({"current_coefficients": {"heading_deg": [0, 90], "surge": [1, 0, 3]}},
     "current_coefficients.surge", "shape (2)"),
    ({"current_coefficients": {"heading_deg": [0, 90], "surge": [1, 0], "reference_height": 10}},
     "current_coefficients.reference_height", "unknown key"),
    ({"point_masses": [{"mass": 1.0}]}, "point_masses[0].position", "a list of numbers"),
])
def test_scene_errors_name_file_and_key(vessel_dir, change, key, words):
    data = _base()
    for k, v in change.items():
        if v is None:
            data.pop(k)
        else:
            data[k] = v
    p = _write(vessel_dir, data)
    with pytest.raises(SceneError) as err:
        load_vessel(p)
    msg = str(err.value)
    assert str(p) in msg and key in msg and words in msg, msg


def test_bad_database_file_is_a_scene_error_naming_the_vessel_file(vessel_dir):
    (vessel_dir / "junk.nc").write_text("junk")
    data = _base()
    data["database"] = "junk.nc"
    p = _write(vessel_dir, data)
    with pytest.raises(SceneError, match=r"vessel.yaml: database.*junk.nc"):
        load_vessel(p)


def test_coefficient_table_interpolation_is_periodic(vessel_dir):
    data = _base()
    data["current_coefficients"] = {"heading_deg": [0, 90, 180, 270],
                                    "surge": [4.0, 0.0, -4.0, 0.0], "sway": [0, 2.0, 0, -2.0]}
    v = load_vessel(_write(vessel_dir, data))
    c = v.current_coefficients
    np.testing.assert_allclose(c.at(np.radians(45)), [2.0, 1.0, 0, 0, 0, 0])
    np.testing.assert_allclose(c.at(np.radians(315)), [2.0, -1.0, 0, 0, 0, 0])
    np.testing.assert_allclose(c.at(np.radians(-45)), [2.0, -1.0, 0, 0, 0, 0])


# ---- the shipped Floatel-like semi -------------------------------------------------------------
@pytest.fixture(scope="module")
def floatel():
    if not (VESSELS / "floatel_like" / "database.nc").exists():
        pytest.skip("floatel_like/database.nc not built")
    return load_vessel(VESSELS / "floatel_like" / "vessel.yaml")


def test_floatel_hydrostatics_against_the_waterplane_by_hand(floatel):
    rho_g = 1025 * G
    # waterplane: four 14 m (x) x 12.5 m (y) columns centred at (+-25.25, +-25.5)
    awp = 4 * 14.0 * 12.5
    ixx = 4 * 14.0 * (31.75 ** 3 - 19.25 ** 3) / 3  # int y^2 dA over y in [19.25, 31.75]
    iyy = 4 * 12.5 * (32.25 ** 3 - 18.25 ** 3) / 3  # int x^2 dA over x in [18.25, 32.25]
    # displaced volume and centre of buoyancy: pontoons 2 x 90 x 14 x 8.625 at z = -8.6875,
    # wetted columns 4 x 14 x 12.5 x 4.375 at z = -2.1875
    vp, vc = 2 * 90 * 14 * 8.625, 4 * 14 * 12.5 * 4.375
    v = vp + vc
    zb = (vp * -8.6875 + vc * -2.1875) / v
    C = floatel.hydrostatic_stiffness
    assert C[2, 2] == pytest.approx(rho_g * awp, rel=1e-6)
    # C44 = rho g (I_xx + V z_B); Capytaine's one-point panel quadrature of y^2 costs < 1 %
    assert C[3, 3] == pytest.approx(rho_g * (ixx + v * zb), rel=0.01)
    assert C[4, 4] == pytest.approx(rho_g * (iyy + v * zb), rel=0.01)
    assert floatel.database.attrs["displaced_volume"] == pytest.approx(v, rel=1e-6)
    # about 25,500 t (Wang (2016) table 5.1: 25,472 t)
    assert 1.025 * v == pytest.approx(25472, rel=0.01)
    # statics: GM > 0 in roll and pitch with the assumed KG
    assert floatel.total_restoring[3, 3] > 0 and floatel.total_restoring[4, 4] > 0


def test_floatel_panel_model_symmetry_and_damping(floatel):
    db = floatel.database
    # the BEM asymmetry removed by make_database.symmetrize was small
    assert db.attrs["max_asymmetry_removed"] < 0.05
    B = db.radiation_damping.values
    diag = np.diagonal(B, axis1=1, axis2=2)
    assert np.all(diag >= -1e-3 * np.abs(diag).max(axis=0))


def test_floatel_wind_current_and_damping_match_wang_2016(floatel):
    # wind-only mean surge force about 2 MN at U10 = 36 m/s (Wang (2016) section 7)
    assert floatel.wind_coefficients.at(0.0)[0] * 36.0 ** 2 == pytest.approx(2.0e6, rel=0.01)
    # current coefficient in surge 3.129e5 N s^2/m^2 (section 6.1.3)
    assert floatel.current_coefficients.at(0.0)[0] == pytest.approx(3.129e5)
    # linear damping 1.5e6 N s/m in surge and sway (section 5.4.3)
    assert floatel.linear_damping[0, 0] == 1.5e6 and floatel.linear_damping[1, 1] == 1.5e6
    # Wang's (2016) mass in surge 2.5603e7 kg (section 5.4.3) within 1 %
    assert floatel.mass == pytest.approx(2.5603e7, rel=0.01)
    assert floatel.slender_elements["elements"][0]["name"] == "column_1"


def test_floatel_mean_drift_direction_and_symmetry(floatel):
    db = floatel.database
    md = db.mean_drift_force.sel(influenced_dof="surge")
    band = (db.omega >= 0.4) & (db.omega <= 2.0)
    head = md.sel(wave_direction=0.0, method="nearest").values[band.values]
    back = md.sel(wave_direction=np.pi, method="nearest").values[band.values]
    # waves push the hull the way they travel
    assert np.all(head > 0)
    # doubly symmetric hull: F_x(180 deg) = -F_x(0 deg) (both computed, not mirrored)
    np.testing.assert_allclose(back, -head, rtol=0.05, atol=0.01 * np.abs(head).max())


def test_oc4_vessel_mass_balances_buoyancy_and_mooring():
    if not (VESSELS / "oc4_semi" / "database.nc").exists():
        pytest.skip("oc4_semi/database.nc not built")
    v = load_vessel(VESSELS / "oc4_semi")
    # platform incl. ballast 1.3473e7 kg (published) + tower, nacelle, rotor as for OC3
    assert v.mass == pytest.approx(1.3473e7 + 249718 + 240000 + 110000)
    # buoyancy (PtfmVol0 = 13,917 m^3) - weight = vertical mooring load: 3 x 631.1 kN from the
    # static catenary of the MoorDyn data (docs/PUBLISHED_VALUES.md; the published 613 kN
    # per line is marked uncertain there)
    assert 1025 * G * 13917 - v.mass * G == pytest.approx(3 * 631.1e3, rel=0.01)
    assert v.fairleads["FL2"][0] == pytest.approx(-40.868)
