"""WAMIT reader against the raw OC3-Hywind and OC4-DeepCwind files (vessels/*/source/; expected
values in docs/PUBLISHED_VALUES.md, "Values computed from the source files")."""

import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.errors import FloatmoorWarning
from floatmoor.hydro import DatabaseError, load_database, read_wamit, save_database

RHO, G = 1025.0, 9.80665


def _raw_rows(path, first):
    """Rows of a WAMIT file whose first column equals ``first`` (hand parsing for the tests)."""
    rows = []
    for line in Path(path).read_text().replace("\r", "").splitlines():
        p = line.split()
        if p and abs(float(p[0]) - first) < 1e-6:
            rows.append([float(x) for x in p])
    return rows


def test_oc3_heave_added_mass_at_low_frequency_by_hand(oc3_db, oc3_root):
    # Spar.1 row "0.125664E+03  3  3  2.449598E+02  8.155613E-01" (PER = 125.664 s, omega =
    # 2 pi / 125.664 = 0.05 rad/s): A33 = rho * L^3 * Abar = 1025 * 244.9598 = 251,083.8 kg
    # and B33 = rho * omega * L^3 * Bbar = 1025 * 0.05 * 0.8155613 = 41.80 N s/m.
    row = [r for r in _raw_rows(str(oc3_root) + ".1", 125.664) if r[1] == 3 and r[2] == 3][0]
    a33 = RHO * row[3]
    assert a33 == pytest.approx(251083.8, rel=1e-6)
    w = 2 * np.pi / 125.664
    got = oc3_db.added_mass.sel(omega=w, method="nearest").sel(influenced_dof="heave",
                                                                 radiating_dof="heave")
    assert float(got) == pytest.approx(a33, rel=1e-12)
    b = oc3_db.radiation_damping.sel(omega=w, method="nearest").sel(influenced_dof="heave",
                                                                     radiating_dof="heave")
    assert float(b) == pytest.approx(RHO * w * row[4], rel=1e-12)


def test_oc3_limits_and_hydrostatics_match_computed_values(oc3_db):
    # docs/PUBLISHED_VALUES.md: PER=0 (infinite frequency) A11=7.759E6 kg, A33=2.413E5 kg,
    # A55=3.7936E10 kg m^2, A15=-4.831E8 kg m; PER=-1: A11=7.983E6 kg, A55=3.8020E10 kg m^2;
    # C33 = 332,941 N/m; C44 = C55 = -4.99918E9 N m/rad.
    ainf = oc3_db.infinite_frequency_added_mass.values
    a0 = oc3_db.zero_frequency_added_mass.values
    assert ainf[0, 0] == pytest.approx(7.759e6, rel=1e-3)
    assert ainf[2, 2] == pytest.approx(2.413e5, rel=1e-3)
    assert ainf[4, 4] == pytest.approx(3.7936e10, rel=1e-4)
    assert ainf[0, 4] == pytest.approx(-4.831e8, rel=1e-3)
    assert a0[0, 0] == pytest.approx(7.983e6, rel=1e-3)
    assert a0[4, 4] == pytest.approx(3.8020e10, rel=1e-4)
    C = oc3_db.hydrostatic_stiffness.values
    assert C[2, 2] == pytest.approx(332941, rel=1e-5)
    assert C[3, 3] == pytest.approx(-4.99918e9, rel=1e-5)
    assert C[4, 4] == pytest.approx(-4.99918e9, rel=1e-5)


def test_oc3_grid_and_headings(oc3_db):
    w = oc3_db.omega.values
    assert w.size == 100 and np.all(np.diff(w) > 0)
    assert w[0] == pytest.approx(0.05, rel=1e-4) and w[-1] == pytest.approx(5.0, rel=1e-4)
    beta = oc3_db.wave_direction.values
    assert beta.size == 37
    assert beta[0] == pytest.approx(-np.pi) and beta[-1] == pytest.approx(np.pi)


def test_oc3_excitation_units_and_long_wave_heave_limit(oc3_db, oc3_root):
    # Hand: Spar.3 first rows, PER = 125.664 s, BETA = -180, I = 3: Re = 31.43565 ->
    # X3 = rho g A L^2 Xbar = 1025 * 9.80665 * 31.43565 N/m.
    row = [r for r in _raw_rows(str(oc3_root) + ".3", 125.664) if r[1] == -180 and r[2] == 3][0]
    x3 = oc3_db.excitation_force.isel(omega=0, wave_direction=0).sel(influenced_dof="heave")
    assert complex(x3) == pytest.approx(RHO * G * complex(row[5], row[6]), rel=1e-12)
    # Phase-convention sign test: in exp(+i w t) with eta = Re[A e^{iwt}] at the origin, a long
    # wave lifts the body with the elevation: X3 -> C33 A in phase (not in anti-phase).  At
    # w = 0.05 rad/s the first correction (Froude-Krylov + G.I. Taylor inertia) still matters:
    # X3 ~ C33 - w^2 (rho V + A33) = 0.936 C33 with V = 8029.21 m^3 (HydroDyn PtfmVol0).
    c33 = oc3_db.hydrostatic_stiffness.values[2, 2]
    w = float(oc3_db.omega[0])
    a33 = float(oc3_db.added_mass.values[0, 2, 2])
    expected = c33 - w ** 2 * (RHO * 8029.21 + a33)
    for k in range(oc3_db.wave_direction.size):
        x = complex(oc3_db.excitation_force.isel(omega=0, wave_direction=k)
                    .sel(influenced_dof="heave"))
        assert abs(x - expected) < 0.02 * c33
        assert abs(np.angle(x)) < 0.01
    # Surge, waves towards +x (BETA = 0): the force follows the horizontal fluid acceleration,
    # +90 deg ahead of the elevation in exp(+i w t) (the same check is made on Capytaine data
    # after conjugation in test_capytaine.py)
    x1 = complex(oc3_db.excitation_force.isel(omega=0).sel(wave_direction=0.0, method="nearest")
                 .sel(influenced_dof="surge"))
    assert np.degrees(np.angle(x1)) == pytest.approx(90.0, abs=1.0)


def test_oc3_symmetry_and_non_negative_damping(oc3_db):
    A = oc3_db.added_mass.values
    B = oc3_db.radiation_damping.values
    scale = np.sqrt(np.outer(np.diag(A[0]), np.diag(A[0])))
    assert np.max(np.abs(A - np.swapaxes(A, 1, 2)) / np.maximum(scale, 1e-300)) < 1e-3
    diagB = np.diagonal(B, axis1=1, axis2=2)
    assert np.all(diagB[:, :5] >= 0)
    # yaw of an axisymmetric spar: numerical noise only
    assert np.max(np.abs(diagB[:, 5])) < 1e-6


def test_oc4_qtf_hermitian_and_mean_drift_is_its_diagonal(oc4_db, oc4_root):
    Q = oc4_db.difference_frequency_qtf.values
    assert Q.shape == (56, 56, 1, 6)
    off = ~np.eye(56, dtype=bool)
    np.testing.assert_allclose(Q[off], np.conj(np.swapaxes(Q, 0, 1))[off], rtol=0, atol=1e-9)
    # the diagonal (mean drift) is real up to WAMIT's numerical noise
    d = np.stack([Q[k, k, 0] for k in range(56)])
    assert np.all(np.abs(d.imag) <= 0.01 * np.abs(d).max(axis=0))
    # Hand: marin_semi.12d first row PER1 = PER2 = 25.133 s, I = 1: Re = 0.427149 ->
    # F = rho g L A^2 Fbar = 1025 * 9.80665 * 0.427149 N/m^2 at omega = 0.25 rad/s.
    w = oc4_db.omega.values
    k = int(np.argmin(np.abs(w - 2 * np.pi / 25.133)))
    md = oc4_db.mean_drift_force.isel(omega=k, wave_direction=0).sel(influenced_dof="surge")
    assert float(md) == pytest.approx(RHO * G * 0.427149, rel=1e-4)
    assert np.isnan(oc4_db.mean_drift_force.values[0, 0, 0])  # omega = 0.01: outside the QTF
    # OC4 hydrostatics (docs/PUBLISHED_VALUES.md): C33 = 3.8203E6 N/m, C44 = -3.8072E8 N m/rad
    C = oc4_db.hydrostatic_stiffness.values
    assert C[2, 2] == pytest.approx(3.8203e6, rel=1e-4)
    assert C[3, 3] == pytest.approx(-3.8072e8, rel=1e-4)
    ainf = oc4_db.infinite_frequency_added_mass.values  # 6.487E6, 1.470E7, 7.211E9
    assert ainf[0, 0] == pytest.approx(6.487e6, rel=1e-3)
    assert ainf[2, 2] == pytest.approx(1.470e7, rel=1e-3)
    assert ainf[4, 4] == pytest.approx(7.211e9, rel=1e-3)


def test_missing_excitation_warns(oc4_root):
    with pytest.warns(FloatmoorWarning, match="marin_semi.3: no excitation file"):
        read_wamit(oc4_root)


def test_ulen_scaling(oc3_root, oc3_db):
    # ULEN = 2: A_ij scales with L^k (k = 3, 4, 5), X with L^2 / L^3, C with L^2 .. L^4
    ds2 = read_wamit(oc3_root, ulen=2.0)
    r = ds2.added_mass.values[10] / np.where(oc3_db.added_mass.values[10] == 0, 1,
                                             oc3_db.added_mass.values[10])
    assert r[0, 0] == pytest.approx(8) and r[0, 4] == pytest.approx(16)
    assert r[4, 4] == pytest.approx(32)
    rc = ds2.hydrostatic_stiffness.values / np.where(oc3_db.hydrostatic_stiffness.values == 0, 1,
                                                     oc3_db.hydrostatic_stiffness.values)
    assert rc[2, 2] == pytest.approx(4) and rc[3, 3] == pytest.approx(16)


def test_crlf_and_lf_files_read_the_same(oc3_root, tmp_path, oc3_db):
    for ext in (".1", ".hst"):
        text = Path(str(oc3_root) + ext).read_bytes()
        assert b"\r\n" in text
        (tmp_path / ("s" + ext)).write_bytes(text.replace(b"\r\n", b"\n"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = read_wamit(tmp_path / "s")
    np.testing.assert_array_equal(ds.added_mass.values, oc3_db.added_mass.values)


def test_truncated_file_is_an_error_naming_it(oc3_root, tmp_path):
    lines = Path(str(oc3_root) + ".1").read_text().splitlines(keepends=True)
    (tmp_path / "t.1").write_text("".join(lines[:-3]))  # the last period loses 3 pairs
    with pytest.raises(DatabaseError, match=r"t\.1.*truncated"):
        read_wamit(tmp_path / "t")
    (tmp_path / "u.1").write_text("".join(lines[:-1]) + lines[-1][:20] + "\n")  # cut mid-line
    with pytest.raises(DatabaseError, match=r"u\.1.*line"):
        read_wamit(tmp_path / "u")


def test_truncated_excitation_file(oc3_root, tmp_path):
    shutil.copy(str(oc3_root) + ".1", tmp_path / "s.1")
    lines = Path(str(oc3_root) + ".3").read_text().splitlines(keepends=True)
    (tmp_path / "s.3").write_text("".join(lines[:-40]))
    with pytest.raises(DatabaseError, match=r"s\.3.*truncated"):
        read_wamit(tmp_path / "s")


def test_mismatched_frequency_grids_name_both_files(oc3_root, tmp_path):
    shutil.copy(str(oc3_root) + ".1", tmp_path / "s.1")
    rows = Path(str(oc3_root) + ".3").read_text().replace("\r", "").splitlines()
    first_per = rows[0].split()[0]
    keep = [r for r in rows if r.split()[0] != first_per]  # drop one whole period
    (tmp_path / "s.3").write_text("\n".join(keep) + "\n")
    with pytest.raises(DatabaseError, match=r"s\.3.*frequencies of s\.1"):
        read_wamit(tmp_path / "s")


def test_missing_root_file(tmp_path):
    with pytest.raises(DatabaseError, match=r"nothing\.1"):
        read_wamit(tmp_path / "nothing")


def test_oc3_netcdf_round_trip(oc3_db, tmp_path):
    p = save_database(oc3_db, tmp_path / "oc3.nc")
    back = load_database(p)
    for name in oc3_db.data_vars:
        np.testing.assert_array_equal(back[name].values, oc3_db[name].values)


def test_mean_drift_file_8_is_read_and_redimensionalised(oc3_root, tmp_path):
    # A synthetic .8 file (WAMIT's format "PER BETA1 BETA2 I |F| phase Re Im") on three of the
    # Spar.1 periods, heading 0, plus a second heading pair that is not unidirectional (ignored).
    # F = rho g L^m A^2 Fbar, m = 1 for forces, 2 for moments (ULEN = 2 here: factor 2 and 4).
    shutil.copy(str(oc3_root) + ".1", tmp_path / "s.1")
    shutil.copy(str(oc3_root) + ".hst", tmp_path / "s.hst")
    pers = [12.5664, 6.28319, 4.18879]  # omega = 0.5, 1.0, 1.5 rad/s (Spar.1 grid)
    lines = []
    for p, fx in zip(pers, [0.1, 0.4, 0.9]):
        lines.append(f"{p} 0.0 0.0 1 {fx} 0.0 {fx} 0.0")
        lines.append(f"{p} 0.0 0.0 5 {3 * fx} 180.0 {-3 * fx} 0.0")
        lines.append(f"{p} 0.0 90.0 1 7.0 0.0 7.0 0.0")
    (tmp_path / "s.8").write_text("\r\n".join(lines) + "\r\n")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = read_wamit(tmp_path / "s", ulen=2.0)
    md = ds.mean_drift_force.sel(wave_direction=0.0)
    w = ds.omega.values
    k = int(np.argmin(np.abs(w - 1.0)))
    assert float(md.isel(omega=k).sel(influenced_dof="surge")) == pytest.approx(RHO * G * 2 * 0.4)
    assert float(md.isel(omega=k).sel(influenced_dof="pitch")) == pytest.approx(
        -RHO * G * 4 * 1.2)
    # between the file's frequencies: linear; outside them: NaN (not available)
    k2 = int(np.argmin(np.abs(w - 1.25)))
    assert float(md.isel(omega=k2).sel(influenced_dof="surge")) == pytest.approx(
        RHO * G * 2 * 0.65, rel=1e-3)
    assert np.isnan(float(md.isel(omega=0).sel(influenced_dof="surge")))
    assert "s.8" in ds.attrs["source"]
