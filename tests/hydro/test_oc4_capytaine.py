"""OC4-DeepCwind: the Capytaine first-order model (vessels/oc4_semi/make_database.py) against
WAMIT's marin_semi.1, both stored in the shipped database."""

import numpy as np
import pytest

from floatmoor.hydro import load_database

from .conftest import VESSELS

DOFS = ["surge", "sway", "heave", "roll", "pitch", "yaw"]
BAND = (0.3, 2.0)  # rad/s: periods 3 .. 21 s, where the OC4 sea states carry their energy


@pytest.fixture(scope="module")
def db():
    path = VESSELS / "oc4_semi" / "database.nc"
    if not path.exists():
        pytest.skip("oc4_semi/database.nc not built")
    return load_database(path)


DAMPING_GAP = (
    "not met by the shipped columns-only 2 m model: max |Capytaine - WAMIT| / max|WAMIT| over "
    "0.3-2 rad/s = 9.2 % surge/sway, 13.9 % heave, 7.3 % roll/pitch, 5.9 % yaw (3 m panels: "
    "13.7, 16.9, 11.8, 10.1 %; 1.5 m panels barely move B).  Main cause found 2026-11-21: the WAMIT "
    "model includes the pontoons and cross braces (HydroDyn PropPot = TRUE for all 25 members; "
    "marin_semi.hst waterplane 380.06 m^2 = columns 372.47 + 3 braces 2.54 at the water line). "
    "With them (make_database.py --slender, 2,919 panels) at 0.7 rad/s heave B 2.76e5 -> 3.49e5 "
    "(WAMIT 3.66e5), pitch B 6.12e8 -> 6.55e8 (6.53e8); at 1.6 rad/s surge B 4.75e6 -> 4.22e6 "
    "(4.11e6); over 0.3-1.5 rad/s (2 m columns) B errors become surge 5.2, heave 6.3, pitch 2.9, "
    "yaw 7.5 % (A: surge 6.6, heave 0.9, yaw 6.0 %); 1.5 m column panels + Richardson bring surge "
    "and yaw A, B within 4.2 % at 0.7 and 1.0 rad/s, but heave B stays 5-7 % low at 1.0-1.2 rad/s "
    "(mesh- and lid-independent, unexplained).  Ruled out: water depth (WAMIT is at finite "
    "depth), B units, irregular frequencies, column geometry.  database.nc not regenerated "
    "(BEM cost, see make_database.py)")


@pytest.mark.parametrize("name", [
    "added_mass",
    pytest.param("radiation_damping", marks=pytest.mark.xfail(strict=True, reason=DAMPING_GAP)),
])
def test_capytaine_matches_wamit_within_5_percent(db, name):
    w = db.omega.values
    sel = (w >= BAND[0]) & (w <= BAND[1])
    wam = db[name].values[sel]
    cap = db["capytaine_" + name].values[sel]
    for k, dof in enumerate(DOFS):
        ref = np.max(np.abs(wam[:, k, k]))
        err = np.max(np.abs(cap[:, k, k] - wam[:, k, k])) / ref
        assert err < 0.05, f"{name}[{dof},{dof}]: {100 * err:.1f} % of max |WAMIT|"


def test_excitation_long_wave_heave_limit(db):
    # Lowest frequency 0.1 rad/s in 200 m water: k = 0.00234 1/m (w^2 = g k tanh kh, kh = 0.468).
    # Long-wave limit (Froude-Krylov + G.I. Taylor inertia):
    #   X3 = C33 - s (rho V + A33) w^2,  s = sinh(k (z + h)) / sinh(kh) = 0.909 at the heave
    # plates (z = -17 m), V = 13,917 m^3 (HydroDyn PtfmVol0), A33 from WAMIT at 0.1 rad/s,
    # in phase with the elevation under exp(+i w t) (sign test of the conversion).
    w = float(db.omega[0])
    assert w == pytest.approx(0.1)
    k = 0.00234
    assert w ** 2 == pytest.approx(9.80665 * k * np.tanh(k * 200), rel=0.01)
    s = np.sinh(k * (200 - 17)) / np.sinh(k * 200)
    a33 = float(db.added_mass.isel(omega=0).sel(influenced_dof="heave", radiating_dof="heave"))
    c33 = db.hydrostatic_stiffness.values[2, 2]
    expected = c33 - s * (1025 * 13917 + a33) * w ** 2
    x3 = complex(db.excitation_force.isel(omega=0).sel(wave_direction=0.0)
                 .sel(influenced_dof="heave"))
    assert abs(x3 - expected) < 0.03 * c33
    assert abs(np.angle(x3)) < 0.01


def test_far_field_drift_against_wamit_qtf_diagonal(db):
    # Validates the mean-drift method used for floatel_like: Capytaine's far-field (Kochin)
    # surge drift with free-floating RAOs against WAMIT's difference-frequency QTF diagonal
    # (marin_semi.12d), head seas, over 0.5 .. 2.0 rad/s (away from the heave resonance near
    # 0.36 rad/s, where the undamped RAOs of both models are unreliable).  Tolerance fixed
    # before the comparison: 15 % of the largest WAMIT value in the band (far field vs near
    # field, 2 m panels).
    w = db.omega.values
    sel = (w >= 0.5) & (w <= 2.0)
    wam = db.mean_drift_force.sel(wave_direction=0.0, influenced_dof="surge").values[sel]
    cap = db.capytaine_mean_drift_force.sel(wave_direction=0.0,
                                            influenced_dof="surge").values[sel]
    assert np.all(np.isfinite(wam)) and np.all(np.isfinite(cap))
    err = np.max(np.abs(cap - wam)) / np.max(np.abs(wam))
    assert err < 0.15, f"max |Capytaine - WAMIT| = {100 * err:.1f} % of max |WAMIT|"
