"""Statics: equilibrium (linear limit, balance, line failure) and restoring curves."""

import math
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import ConvergenceError
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.solvers.statics import restoring_curve, solve_equilibrium

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def oc3():
    return parse_mooring(Node.load(ROOT / "vessels/oc3_hywind/mooring.yaml"), water_depth=320.0)


@pytest.fixture(scope="module")
def floatel():
    return parse_mooring(Node.load(ROOT / "vessels/floatel_like/mooring.yaml"), water_depth=150.0)


# OC3 hydrostatics (docs/PUBLISHED_VALUES.md): C33 = 332,941 N/m; C44 = C55 = -4.99918e9 N m/rad
# from the water plane and buoyancy, plus -m g zG = 7,466,330 * 9.80665 * 89.9155 for the platform
# alone (the tower and RNA are left out here: a test input, not the full OC3 model); yaw spring
# 98,340,000 N m/rad (HydroDyn AddCLin).
KH_OC3 = np.diag([0.0, 0.0, 332941.0, -4.99918e9 + 7466330 * 9.80665 * 89.9155,
                  -4.99918e9 + 7466330 * 9.80665 * 89.9155, 98.34e6])


def test_small_force_gives_linear_offset(oc3):
    """Linear limit: for a small external force the offset is K^-1 F (K = mooring + hydro)."""
    f0 = oc3.force(np.zeros(6))
    F = np.array([2.0e4, -1.0e4, 0.0, 0.0, 0.0, 5.0e4])
    ext = F - f0  # the net buoyancy balances the lines' vertical pull at zero pose
    res = solve_equilibrium(oc3, hydrostatic_stiffness=KH_OC3, external_force=ext)
    K = oc3.stiffness(np.zeros(6)) + KH_OC3
    lin = np.linalg.solve(K, F)
    # heave: a second-order set-down of about 0.2 mm is not in the linear model
    tol = 0.02 * np.abs(lin) + np.array([1e-6, 1e-6, 1e-3, 1e-8, 1e-8, 1e-8])
    assert np.all(np.abs(res.pose - lin) <= tol), (res.pose, lin)
    assert np.abs(res.residual).max() < 1e-3


def test_balance_at_large_offset(oc3):
    """A large surge force: the equilibrium balances exactly (residual ~ 0), the mooring surge
    force equals the applied force."""
    f0 = oc3.force(np.zeros(6))
    F = np.array([1.5e6, 0, 0, 0, 0, 0])
    res = solve_equilibrium(oc3, hydrostatic_stiffness=KH_OC3, external_force=F - f0)
    total = res.mooring_force - KH_OC3 @ res.pose + F - f0
    assert np.abs(total[:3]).max() < 1e-2 and np.abs(total[3:]).max() < 1.0
    assert res.pose[0] > 10.0
    assert res.mooring_force[0] - f0[0] == pytest.approx(-F[0], rel=1e-6)
    ds = res.to_dataset()
    assert ds["pose"].sel(dof="surge") == pytest.approx(res.pose[0])


def test_restricted_dofs(floatel):
    res = solve_equilibrium(floatel, external_force=[3.0e6, 1.0e6, 0, 0, 0, 0],
                      dofs=("surge", "sway", "yaw"))
    assert res.pose[2] == 0 and res.pose[3] == 0 and res.pose[4] == 0
    f = res.mooring_force
    assert f[0] == pytest.approx(-3.0e6, rel=1e-8) and f[1] == pytest.approx(-1.0e6, rel=1e-8)
    assert abs(f[5]) < 1e-2


def test_line_failure_raises_neighbour_tension(floatel):
    """Same environment (5,000 kN towards +x), line 7 removed: the body drifts further and the
    neighbouring lines 8 and 9 of the same corner, and line 6, carry more tension."""
    ext = [5.0e6, 0, 0, 0, 0, 0]
    intact = solve_equilibrium(floatel, external_force=ext, dofs=("surge", "sway", "yaw"))
    broken = solve_equilibrium(floatel.without_lines(["line7"]), external_force=ext,
                         dofs=("surge", "sway", "yaw"))
    ti = intact.tensions["fairlead_tension"]
    tb = broken.tensions["fairlead_tension"]
    for nb in ("line6", "line8", "line9"):
        assert float(tb.sel(line=nb)) > float(ti.sel(line=nb)) * 1.02
    assert broken.pose[0] > intact.pose[0]
    assert np.isnan(float(tb.sel(line="line7")))


def test_restoring_curve_level_slope_and_symmetry(floatel):
    """Floatel-like restoring curve along heading 0: 9,500 kN at 30 m (the calibration target of
    the mooring file); the analytic stiffness along the curve equals the slope of the curve
    (central differences), the curve is monotonic and stiffening, and it is odd in the offset
    (the system is symmetric about the y-z plane)."""
    off = np.linspace(-40.0, 40.0, 81)
    ds = restoring_curve(floatel, 0.0, off)
    F = ds["restoring_force"].values
    assert float(ds["restoring_force"].sel(offset=30.0)) == pytest.approx(9.5e6, rel=0.01)
    np.testing.assert_allclose(F, -F[::-1], rtol=1e-9, atol=1e-3)
    assert np.all(np.diff(F) > 0)
    slope = np.gradient(F, off)
    k = ds["stiffness_along_heading"].values
    np.testing.assert_allclose(k[5:-5], slope[5:-5], rtol=2e-3)
    assert k[70] > k[40]  # stiffer at 30 m than at 0
    # tensions symmetric about the heading: line k and 13-k
    t = ds["fairlead_tension"].sel(offset=25.0).values
    np.testing.assert_allclose(t, t[::-1], rtol=1e-9)


def test_restoring_curve_any_heading(floatel):
    ds = restoring_curve(floatel, math.radians(45.0), [0.0, 20.0])
    f = ds["force"].sel(offset=20.0).values
    assert f[0] == pytest.approx(f[1], rel=1e-9) and f[0] < 0


def test_non_convergence_names_the_dof(oc3):
    with pytest.raises(ConvergenceError, match="surge|sway|heave|roll|pitch|yaw"):
        solve_equilibrium(oc3, hydrostatic_stiffness=KH_OC3, external_force=[3e6, 0, 0, 0, 0, 0],
                    max_iter=1)


def test_summary_and_dataset(floatel):
    res = solve_equilibrium(floatel.without_lines(["line7"]), external_force=[5.0e6, 0, 0, 0, 0, 0],
                      dofs=("surge", "sway", "yaw"))
    text = res.summary()
    assert "line7       failed" in text and "surge" in text and "mooring stiffness" in text
    ds = res.to_dataset()
    assert ds["mooring_stiffness"].sel(dof="surge", dof_j="surge") == pytest.approx(
        res.mooring_stiffness[0, 0])
    assert ds["fairlead_tension"].attrs["units"] == "N"
