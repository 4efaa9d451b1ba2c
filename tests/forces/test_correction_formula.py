"""EXWAVE correction formula (Wang (2016) eq. 6.6) against hand-computed values.

Hand computation (g = 9.80665 m/s^2, C_p = 0.25 s/m, G = 10 s, B0 = 1 kN/m^3):

case A: w = 0.5 rad/s, D0 = 12.5 m, sum d_i = 4 x 12.5 = 50 m, U = 0.94 m/s, Hs = 16 m,
        f_pot = 20 kN/m^2 (surge, beta = 0)
    k = 0.25 / 9.80665 = 0.0254929 rad/m
    k D0 = 0.318661; 1.25 (k D0)^2 = 0.126934; p = exp(-0.126934) = 0.880794
    B = 1000 x 0.0254929 x 0.880794 x 50 = 1122.70 N/m^3
    potential part 20000 (1 + 0.25 x 0.94) = 24700 N/m^2
    viscous part 1122.70 x (10 x 0.94 + 16) = 1122.70 x 25.4 = 28516.6 N/m^2
    f_d = 53216.6 N/m^2
case B: w = 0.3 rad/s, same hull, U = 0, Hs = 10 m, f_pot = 5 kN/m^2
    k = 0.09 / 9.80665 = 0.00917745; 1.25 (k D0)^2 = 0.0164481; p = 0.983684
    B = 1000 x 0.00917745 x 0.983684 x 50 = 451.385 N/m^3
    f_d = 5000 + 451.385 x 10 = 9513.85 N/m^2
case C: w = 1.0 rad/s, D0 = 14 m, sum d_i = 56 m, U = 1.5 m/s, Hs = 5 m, f_pot = -1 kN/m^2
    k = 1 / 9.80665 = 0.101972; 1.25 (k D0)^2 = 2.54757; p = 0.0782723
    B = 1000 x 0.101972 x 0.0782723 x 56 = 446.967 N/m^3
    f_d = -1000 x 1.375 + 446.967 x (15 + 5) = -1375 + 8939.34 = 7564.34 N/m^2
"""

import math

import numpy as np
import pytest
import xarray as xr

from floatmoor.core.errors import SceneError
from floatmoor.hydro.viscous_drift import (
    CorrectionFormula,
    corrected_coefficients,
    corrected_mean_drift,
    extra_linear_damping,
    viscous_drift_b,
)

CASES = [
    # w, D0, d_i, U, Hs, f_pot, B (hand), f_d (hand)
    (0.5, 12.5, [12.5] * 4, 0.94, 16.0, 2.0e4, 1122.70, 53216.6),
    (0.3, 12.5, [12.5] * 4, 0.0, 10.0, 5.0e3, 451.385, 9513.85),
    (1.0, 14.0, [14.0] * 4, 1.5, 5.0, -1.0e3, 446.967, 7564.34),
]


@pytest.mark.parametrize("w, D0, d, U, hs, fpot, B_hand, fd_hand", CASES)
def test_hand_computed_values(w, D0, d, U, hs, fpot, B_hand, fd_hand):
    cf = CorrectionFormula(column_diameters=d, main_column_diameter=D0)
    B = viscous_drift_b(np.array([w]), cf)[0]
    assert B == pytest.approx(B_hand, rel=2e-6)
    f = np.zeros((1, 1, 6))
    f[0, 0, 0] = fpot
    out = corrected_coefficients([w], [0.0], f, current_along=U, hs=hs, formula=cf)
    assert out[0, 0, 0] == pytest.approx(fd_hand, rel=2e-6)
    assert np.all(out[0, 0, 1:] == 0.0)


def test_limits():
    cf = CorrectionFormula(column_diameters=[12.5] * 4, main_column_diameter=12.5)
    w = np.array([0.3, 0.6, 2.5])
    f = np.random.default_rng(1).normal(size=(3, 1, 6)) * 1e4
    # no current, no waves: the potential coefficients unchanged
    assert np.allclose(corrected_coefficients(w, [0.0], f, current_along=0.0, hs=0.0,
                                              formula=cf), f)
    # short waves: p -> 0 removes the viscous part (k D0 = 8.0 at 2.5 rad/s: p = e^-80)
    out = corrected_coefficients(w, [0.0], f, current_along=0.0, hs=16.0, formula=cf)
    assert out[2, 0, 0] == pytest.approx(f[2, 0, 0], abs=1e-20)
    # linear in Hs and in U (viscous part)
    a = corrected_coefficients(w, [0.0], f, current_along=0.5, hs=8.0, formula=cf)
    b = corrected_coefficients(w, [0.0], f, current_along=0.5, hs=16.0, formula=cf)
    assert np.allclose(b[:, 0, 0] - a[:, 0, 0], viscous_drift_b(w, cf) * 8.0)


def _db():
    w = np.array([0.3, 0.5, 0.8])
    beta = np.array([0.0, math.pi / 2, math.pi])
    f = np.zeros((3, 3, 6))
    f[:, 0, 0] = [1e4, 2e4, 3e4]
    f[:, 1, 1] = [1e4, 2e4, 3e4]
    f[:, 2, 0] = [-1e4, -2e4, -3e4]
    f[:, :, 5] = 7.0e5
    da = xr.DataArray(f, dims=("omega", "wave_direction", "influenced_dof"),
                      coords={"omega": w, "wave_direction": beta,
                              "influenced_dof": ["surge", "sway", "heave", "roll", "pitch", "yaw"]},
                      attrs={"units": "N/m^2"})
    return xr.Dataset({"mean_drift_force": da})


def test_database_correction_directions():
    db = _db()
    cf = CorrectionFormula(column_diameters=[12.5] * 4, main_column_diameter=12.5)
    U, hs = 0.94, 16.0
    out = corrected_mean_drift(db, current_speed=U, current_heading=0.0, hs=hs, formula=cf)
    B = viscous_drift_b(db.omega.values, cf)
    md = out["mean_drift_force"].values
    # waves along +x, current along +x: U_along = +0.94
    assert np.allclose(md[:, 0, 0], db.mean_drift_force.values[:, 0, 0] * (1 + 0.25 * U)
                       + B * (10 * U + hs))
    # waves along +y, current along +x: U_along = 0, viscous force along +y only
    assert np.allclose(md[:, 1, 1], db.mean_drift_force.values[:, 1, 1] + B * hs)
    assert np.allclose(md[:, 1, 0], 0.0, atol=1e-9)
    # waves along -x, current along +x: U_along = -0.94, force along -x
    assert np.allclose(md[:, 2, 0], db.mean_drift_force.values[:, 2, 0] * (1 - 0.25 * U)
                       - B * (-10 * U + hs))
    # yaw moment: only the potential factor
    assert np.allclose(md[:, 0, 5], 7e5 * (1 + 0.25 * U))
    # input untouched, potential kept
    assert np.all(db.mean_drift_force.values[:, 0, 0] == [1e4, 2e4, 3e4])
    assert np.all(out["mean_drift_force_potential"].values == db.mean_drift_force.values)
    # body and current both turned by 90 deg: the same relative current, the same result
    out2 = corrected_mean_drift(db, current_speed=U, current_heading=math.pi / 2, hs=hs,
                                formula=cf, yaw=math.pi / 2)
    assert np.allclose(out2["mean_drift_force"].values, md)


def test_bad_input():
    with pytest.raises(SceneError, match="column_diameters"):
        CorrectionFormula(column_diameters=[], main_column_diameter=12.0)
    with pytest.raises(SceneError, match="main_column_diameter"):
        CorrectionFormula(column_diameters=[12.0], main_column_diameter=-1.0)
    cf = CorrectionFormula(column_diameters=[12.0], main_column_diameter=12.0)
    with pytest.raises(SceneError, match="hs"):
        corrected_coefficients([0.5], [0.0], np.zeros((1, 1, 6)), current_along=0.0,
                               hs=-1.0, formula=cf)


def test_extra_damping_table_6_10():
    # Wang (2016) table 6.10: 1.5e6 N s/m raised by 50 %, 100 %, 200 %, 300 %
    B0 = np.diag([1.5e6, 1.5e6, 1.9e6, 1.2e9, 1.2e9, 0.0])
    for inc, new in ((0.5, 2.25e6), (1.0, 3.0e6), (2.0, 4.5e6), (3.0, 6.0e6)):
        B = extra_linear_damping(B0, increase=inc)
        assert B[0, 0] == pytest.approx(new) and B[1, 1] == pytest.approx(new)
        assert np.all(np.diag(B)[2:] == np.diag(B0)[2:])
