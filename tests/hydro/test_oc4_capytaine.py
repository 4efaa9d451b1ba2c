"""OC4-DeepCwind: the Capytaine first-order model of vessels/oc4_semi/make_database.py against
WAMIT's marin_semi.1.

The stored results checked here are all produced by make_database.py (Capytaine itself is not
needed to run these tests):

* ``capytaine_mesh_convergence.nc`` (``--convergence``): radiation A, B (6x6) of the columns +
  pontoons + cross braces panel model for column panel sizes 2.0 / 1.5 / 1.0 m at 0.3 .. 2.0
  rad/s, the Richardson extrapolation and WAMIT's values on the same frequencies;
* ``capytaine_mesh_convergence_graded.nc`` (``--convergence --graded``): the same with the
  column panels graded towards the edges and the water line (build_mesh ``grade_edges``);
* ``capytaine_tube_study.nc`` and the Haskind records (diagnostics of the heave damping);
* ``database.nc`` (``--slender --symmetric``, 2 m column panels): WAMIT A, B plus the
  Capytaine excitation, A and B of the 2 m model.
"""

import math

import numpy as np
import pytest
import xarray as xr

from floatmoor.hydro import load_database
from floatmoor.hydro.wamit import read_wamit_1

from .conftest import VESSELS

DOFS = ["surge", "sway", "heave", "roll", "pitch", "yaw"]
BAND = (0.3, 2.0)  # rad/s: periods 3 .. 21 s, where the OC4 sea states carry their energy
RHO, G, DEPTH = 1025.0, 9.80665, 200.0


@pytest.fixture(scope="module")
def db():
    path = VESSELS / "oc4_semi" / "database.nc"
    if not path.exists():
        pytest.skip("oc4_semi/database.nc not built")
    return load_database(path)


@pytest.fixture(scope="module")
def conv():
    path = VESSELS / "oc4_semi" / "capytaine_mesh_convergence.nc"
    if not path.exists():
        pytest.skip("oc4_semi/capytaine_mesh_convergence.nc not built")
    return xr.load_dataset(path)


def _err(cap, wam, k):
    """max |Capytaine - WAMIT| / max |WAMIT| of the diagonal term k over the frequencies."""
    return np.max(np.abs(cap[:, k, k] - wam[:, k, k])) / np.max(np.abs(wam[:, k, k]))


def test_stored_wamit_values_are_marin_semi_1(conv, oc4_root):
    # The reference columns of the convergence record are WAMIT's .1 file itself (ULEN 1 m,
    # rho 1025), read again here with floatmoor's reader on the same grid points.
    omega, A, B, _, _ = read_wamit_1(str(oc4_root) + ".1", ulen=1.0, rho=RHO)
    idx = [int(np.argmin(np.abs(omega - w))) for w in conv.omega.values]
    assert np.allclose(omega[idx], conv.omega.values, atol=1e-9)
    assert np.allclose(conv.wamit_added_mass.values, A[idx], rtol=1e-12, atol=0)
    assert np.allclose(conv.wamit_radiation_damping.values, B[idx], rtol=1e-12, atol=0)


def test_shipped_database_is_the_2m_model_of_the_convergence_record(db, conv):
    # database.nc's Capytaine A and B come from the same 2 m D3-symmetric mesh as the 2 m row
    # of the convergence record (separate runs: radiation-only vs radiation + diffraction and
    # Kochin functions; measured difference 1.7e-5 of the largest term at 0.35 rad/s, < 4e-7
    # elsewhere; tolerance 1e-4).
    # (database.nc keeps WAMIT's frequencies 2 pi / PER, within 1e-6 rad/s of Capytaine's.)
    h2 = conv.sel(panel_size=2.0)
    idx = [int(np.argmin(np.abs(db.omega.values - w))) for w in conv.omega.values]
    assert np.allclose(db.omega.values[idx], conv.omega.values, atol=1e-5)
    for name in ("added_mass", "radiation_damping"):
        cap = db["capytaine_" + name].values[idx]
        ref = h2[name].values
        assert np.max(np.abs(cap - ref)) <= 1e-4 * np.max(np.abs(ref))


# Heave damping is the one diagonal term the uniform-column model does not bring within 5 %
# (6.2 % of max|WAMIT| at 1.25 rad/s, extrapolated); the graded-column record below does
# (test_graded_capytaine_matches_wamit_within_5_percent).  See make_database.py ("Mesh
# convergence") and benchmarks/RESULTS.md for the tables.


@pytest.mark.parametrize("dof", DOFS)
@pytest.mark.parametrize("name", ["added_mass", "radiation_damping"])
def test_converged_capytaine_matches_wamit_within_5_percent(conv, name, dof):
    # Acceptance: Capytaine from the public member geometry (RAFT_OC4semi.yaml) within 5 % of
    # WAMIT's .1 file over the wave band, per diagonal DOF, in % of the largest WAMIT value in
    # the band.  Compared: the Richardson extrapolation (order 2) of the two finest column
    # panel sizes (1.5 and 1.0 m) of capytaine_mesh_convergence.nc, 0.30 .. 2.00 rad/s step
    # 0.05.  Measured (% of max|WAMIT|): A surge 2.2, heave 0.6, pitch 0.6, yaw 1.5; B surge
    # 1.4, heave 6.2 (xfail), pitch 2.6, yaw 1.8 (sway, roll = surge, pitch by symmetry).
    # The 1.0 m values alone give 3.1, 0.3, 0.2, 2.5; 2.5, 6.1, 2.1, 2.9.
    # Heave B with uniform column panels is the documented miss (6.2 %, at 1.25 rad/s; column
    # refinement moves it < 0.5 %): asserted as such, the 5 % check of heave B is made on the
    # graded-column record (test_graded_capytaine_matches_wamit_within_5_percent).
    w = conv.omega.values
    sel = (w >= BAND[0] - 1e-9) & (w <= BAND[1] + 1e-9)
    k = DOFS.index(dof)
    err = _err(conv[name + "_extrapolated"].values[sel], conv["wamit_" + name].values[sel], k)
    if name == "radiation_damping" and dof == "heave":
        assert 0.05 < err < 0.07, f"uniform-column heave B: {100 * err:.2f} % (recorded 6.2 %)"
        return
    assert err < 0.05, f"{name}[{dof},{dof}]: {100 * err:.2f} % of max |WAMIT|"


def _wavenumber(w, h):
    k = w * w / G
    for _ in range(200):
        k = w * w / (G * math.tanh(k * h))
    return k


@pytest.fixture(scope="module")
def haskind():
    path = VESSELS / "oc4_semi" / "capytaine_haskind_check.nc"
    if not path.exists():
        pytest.skip("oc4_semi/capytaine_haskind_check.nc not built")
    return xr.load_dataset(path)


def haskind_damping(omega, headings, X):
    """Haskind-Newman relation (Newman 1962, J. Ship Res. 6), finite depth h:
    B_jj = k / (8 pi rho g C_g) * integral_0^2pi |X_j(beta)|^2 dbeta,
    C_g = (w / 2k) (1 + 2kh / sinh 2kh).  X: (n_omega, n_heading, 6) on equally spaced
    headings 0 .. 180 deg; the OC4 semi is symmetric about y = 0, so |X_j(-beta)| = |X_j(beta)|
    and the periodic trapezoid rule runs over the mirrored 0 .. 360 deg."""
    hd = np.asarray(headings)
    step = hd[1] - hd[0]
    assert abs(hd[0]) < 1e-9 and abs(hd[-1] - np.pi) < 1e-9 and np.allclose(np.diff(hd), step)
    X2 = np.abs(X) ** 2
    X2 = np.concatenate([X2, X2[:, -2:0:-1]], axis=1)
    out = []
    for i, om in enumerate(omega):
        k = _wavenumber(om, DEPTH)
        cg = om / (2 * k) * (1 + 2 * k * DEPTH / math.sinh(2 * k * DEPTH))
        out.append(k / (8 * math.pi * RHO * G * cg) * X2[i].sum(axis=0) * step)
    return np.array(out)


def test_haskind_formula_on_a_body_in_the_long_wave_limit():
    # Check of the helper itself: a body whose heave excitation is the same from every
    # heading, X3 = const, gives B33 = k |X3|^2 / (4 rho g C_g) (the integral is 2 pi |X3|^2);
    # in deep water (kh >> 1, C_g = g / 2w) that is w^3 |X3|^2 / (2 rho g^3).
    w = np.array([1.5])
    X = np.zeros((1, 37, 6), complex)
    X[0, :, 2] = 3.0e6 * np.exp(0.3j)
    b = haskind_damping(w, np.radians(np.arange(0.0, 180.001, 5.0)), X)[0, 2]
    assert _wavenumber(1.5, DEPTH) * DEPTH > 40
    assert b == pytest.approx(1.5 ** 3 * 9e12 / (2 * RHO * G ** 3), rel=1e-9)


@pytest.mark.parametrize("dof", ["surge", "heave", "pitch", "yaw"])
def test_haskind_damping_from_capytaine_excitation(haskind, dof):
    # Capytaine's excitation (diffraction solution, 37 headings 0 .. 180 deg step 5, 2 m
    # column panels) through the Haskind-Newman relation against Capytaine's damping from the
    # radiation solution of the same mesh, at 0.5 .. 1.3 rad/s (WAMIT's heave-B residual is
    # at 1.0 .. 1.2).  An independent check of the excitation stored for the simulations
    # (units, phase-free magnitude, Froude-Krylov + diffraction) and of the damping.  The
    # relation is exact for the continuous problem but not for a constant-panel solution:
    # for a Capytaine hemisphere (r = 5 m, deep water, 0.9 rad/s) the defect is 4.9 / 2.5 /
    # 1.3 % with 100 / 400 / 1600 panels (first order in the panel size).  Tolerance fixed
    # from that before this comparison: 10 % of max|B_jj| over the frequencies (2 m panels
    # on 6 m columns are about as coarse as the 100-panel hemisphere, and the tube ends on
    # the column walls are not a closed surface).
    k = DOFS.index(dof)
    X = haskind.excitation_force_re.values + 1j * haskind.excitation_force_im.values
    b_h = haskind_damping(haskind.omega.values, haskind.wave_direction.values, X)[:, k]
    b_c = haskind.radiation_damping.values[:, k, k]
    err = np.max(np.abs(b_h - b_c)) / np.max(np.abs(b_c))
    assert err < 0.10, f"Haskind {dof}: {100 * err:.2f} % of max |B|"


def test_haskind_defect_shrinks_with_the_column_panels(haskind):
    # The Haskind-vs-direct defect is a discretisation error (hemisphere: first order in the
    # panel size), so it must shrink when the column panels go from 2 m to 1 m
    # (capytaine_haskind_check_h1.0.nc, 1.1 and 1.2 rad/s).  Measured |Haskind/direct - 1|,
    # 2 m -> 1 m: surge 2.1 -> 1.0 %, heave 5.1 -> 3.5 %, yaw 2.5 -> 1.2 % at 1.1 rad/s.
    path = VESSELS / "oc4_semi" / "capytaine_haskind_check_h1.0.nc"
    if not path.exists():
        pytest.skip("oc4_semi/capytaine_haskind_check_h1.0.nc not built")
    fine = xr.load_dataset(path)
    coarse = haskind.sel(omega=fine.omega.values)
    defect = []
    for ds in (coarse, fine):
        X = ds.excitation_force_re.values + 1j * ds.excitation_force_im.values
        b_h = haskind_damping(ds.omega.values, ds.wave_direction.values, X)
        b_c = np.array([np.diag(b) for b in ds.radiation_damping.values])
        defect.append(np.abs(b_h / b_c - 1)[:, [0, 2, 5]])
    assert np.all(defect[1] < defect[0]), f"2 m: {defect[0]}, 1 m: {defect[1]}"


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


# --- Tube refinement and junction study -------------------------------------------------------
# capytaine_tube_study.nc (make_database.py --tube-study): 6 radiation problems + heave
# excitation on 0 .. 60 deg at 0.7 / 1.1 / 1.25 rad/s for pontoon/brace tubes of 8 / 12 / 16
# panels round (1.0 / 0.67 / 0.5 m long), column panels 1.5 and 1.0 m, with and without the
# junction trimming (build_mesh trim_inside: column-wall panels under the tube ends and the
# brace / Y-pontoon overlap at the main column removed).


@pytest.fixture(scope="module")
def tube_study():
    path = VESSELS / "oc4_semi" / "capytaine_tube_study.nc"
    if not path.exists():
        pytest.skip("oc4_semi/capytaine_tube_study.nc not built")
    return xr.load_dataset(path)


def _heave_haskind_d3(omega, headings, X3):
    """As make_database.haskind_heave_d3 (written again here: the tests do not import
    Capytaine): 6 x the trapezoid of |X3|^2 over 0 .. 60 deg."""
    k = _wavenumber(omega, DEPTH)
    cg = omega / (2 * k) * (1 + 2 * k * DEPTH / math.sinh(2 * k * DEPTH))
    return k / (8 * math.pi * RHO * G * cg) * 6 * np.trapezoid(np.abs(X3) ** 2, headings)


def test_heave_haskind_from_one_sixth_of_the_headings(haskind):
    # The study stores the heave excitation on 0 .. 60 deg only and uses the D3 symmetry of
    # the mesh (|X3| even in the heading and 120-deg periodic).  On the 37-heading record the
    # reduced integral must equal the full one.
    X = haskind.excitation_force_re.values + 1j * haskind.excitation_force_im.values
    hd = haskind.wave_direction.values
    full = haskind_damping(haskind.omega.values, hd, X)[:, 2]
    sub = hd <= math.pi / 3 + 1e-9
    red = [_heave_haskind_d3(w, hd[sub], X[i, sub, 2]) for i, w in enumerate(haskind.omega.values)]
    assert np.allclose(red, full, rtol=1e-9, atol=0)


def test_tube_study_baseline_is_the_1p5m_model_of_the_convergence_record(tube_study, conv):
    # The study's (1.5 m columns, 8 x 1.0 m tubes, untrimmed) mesh is the 1.5 m mesh of the
    # convergence record; separate runs (radiation + 13 diffraction problems here), so A and
    # B must agree to solver round-off (tolerance 1e-4 of the largest term per DOF).
    base = tube_study.where((tube_study.column_panel_size == 1.5)
                            & (tube_study.tube_panels_round == 8)
                            & (tube_study.trim_inside == 0)
                            & (tube_study.graded_column_edges == 0), drop=True).squeeze("config")
    ref = conv.sel(panel_size=1.5, omega=tube_study.omega.values, method="nearest")
    for name in ("added_mass", "radiation_damping"):
        r = np.array([np.diag(m) for m in ref[name].values])
        assert np.max(np.abs(base[name].values - r), axis=0).max() <= 1e-4 * np.abs(r).max()


def test_heave_damping_gap_is_not_the_tubes_or_their_junctions(tube_study):
    # Finding behind the heave-B xfail: neither finer tubes nor closing the junctions moves
    # heave B towards WAMIT or closes the Haskind-vs-direct gap.  Measured (N s/m, 1.1 rad/s,
    # WAMIT 6.043e5): 1.5 m columns, tubes 8 / 12 / 16 round 5.668 / 5.679 / 5.683e5, trimmed
    # 8 / 16 round 5.676 / 5.686e5; 1.0 m columns, 16 round 5.701e5, trimmed 5.698e5 (8 round,
    # convergence record: 5.687e5).  Largest change against the 8-round untrimmed mesh of the
    # same column size: 1.4 % of max|WAMIT| (0.7 rad/s, 3.565 -> 3.476e5, away from WAMIT's
    # 3.662e5).  Heave Haskind / direct - 1: +2.7 .. +7.7 % in every configuration (1.1 rad/s:
    # 4.1-4.3 % with 1.5 m columns, 3.4 % with 1.0 m, as with 8-round tubes).
    wmax = 6.463e5  # max|WAMIT B33| over 0.3-2.0 rad/s (1.25 rad/s), as in the band test
    tube_study = tube_study.isel(config=np.nonzero(tube_study.graded_column_edges.values == 0)[0])
    b = tube_study.radiation_damping.sel(dof="heave")
    for h in np.unique(tube_study.column_panel_size.values):
        cfg = tube_study.column_panel_size.values == h
        ref = b[np.nonzero(cfg & (tube_study.tube_panels_round.values == 8)
                           & (tube_study.trim_inside.values == 0))[0]]
        if ref.sizes["config"] == 0:
            continue
        change = np.abs(b[np.nonzero(cfg)[0]].values - ref.values).max()
        assert change < 0.025 * wmax, f"{h} m columns: heave B moved {change:.3g} N s/m"
    gap = tube_study.heave_damping_haskind / b - 1
    assert float(gap.min()) > 0.025 and float(gap.max()) < 0.08, gap.values
    # and heave B stays more than 5 % of max|WAMIT| below WAMIT at 1.1 rad/s in every mesh
    wam = float(tube_study.wamit_radiation_damping.sel(omega=1.1, dof="heave"))
    assert float((wam - b.sel(omega=1.1)).min()) > 0.05 * wmax


def test_graded_column_edges_move_heave_damping_towards_wamit(tube_study, conv):
    # Diagnostic of the same study: the same panel counts on the columns, clustered towards
    # the column edges and the water line (cosine spacing, build_mesh grade_edges), 8 x 1 m
    # tubes.  Unlike the tubes, this moves heave B towards WAMIT and narrows the Haskind gap,
    # at 1.5 and 1.0 m columns, 1.1 and 1.25 rad/s.  Measured (N s/m): 1.0 m uniform / graded
    # 5.687 / 5.788e5 at 1.1 rad/s (WAMIT 6.043e5), 6.068 / 6.202e5 at 1.25 (WAMIT 6.463e5);
    # Haskind / direct - 1 (1.1 rad/s) 3.5 % (uniform, capytaine_haskind_check_h1.0.nc) ->
    # 2.4 % (graded).  (Not a band test: only three frequencies were computed graded.)
    b = tube_study.radiation_damping.sel(dof="heave")
    wam = tube_study.wamit_radiation_damping.sel(dof="heave")
    for h in (1.5, 1.0):
        g = np.nonzero((tube_study.graded_column_edges.values == 1)
                       & (tube_study.column_panel_size.values == h))[0]
        assert g.size == 1
        bg = b.isel(config=g[0]).sel(omega=[1.1, 1.25])
        bu = conv.radiation_damping.sel(panel_size=h, omega=[1.1, 1.25],
                                        method="nearest").values[:, 2, 2]
        assert np.all(np.abs(wam.sel(omega=[1.1, 1.25]) - bg) < np.abs(wam.sel(omega=[1.1, 1.25]).values - bu))
        gap_g = tube_study.heave_damping_haskind.isel(config=g[0]).sel(omega=1.1) / bg.sel(omega=1.1) - 1
        ung = np.nonzero((tube_study.graded_column_edges.values == 0)
                         & (tube_study.column_panel_size.values == h))[0]
        gap_u = (tube_study.heave_damping_haskind.isel(config=ung).sel(omega=1.1)
                 / b.isel(config=ung).sel(omega=1.1) - 1)
        assert float(gap_g) < float(gap_u.min())


# capytaine_mesh_convergence_graded.nc (make_database.py 2.0,1.5,1.0 --convergence --graded):
# the convergence study again with the column panels graded towards the sharp edges (heave
# plates of the base columns, column bottoms) and the water line (build_mesh grade_edges:
# cosine spacing, the same panel counts as the uniform mesh of each size; a standard BEM
# practice for singular edges, no parameter chosen by comparison with WAMIT).


@pytest.fixture(scope="module")
def conv_graded():
    path = VESSELS / "oc4_semi" / "capytaine_mesh_convergence_graded.nc"
    if not path.exists():
        pytest.skip("oc4_semi/capytaine_mesh_convergence_graded.nc not built")
    return xr.load_dataset(path)


def test_graded_record_has_the_panels_and_wamit_values_of_the_uniform_record(conv_graded, conv):
    # Grading moves panels, it does not add any: same hull panel count per column panel size
    # as the uniform record (2.0 / 1.5 / 1.0 m: 3,672 / 5,310 / 9,468), same frequencies and
    # the same WAMIT reference values (marin_semi.1, checked above against the raw file).
    assert "grade_edges" in conv_graded.attrs["column_grading"]
    assert np.array_equal(conv_graded.omega.values, conv.omega.values)
    for h in conv_graded.panel_size.values:
        assert int(conv_graded.nb_panels.sel(panel_size=h)) == int(conv.nb_panels.sel(panel_size=h))
    for v in ("wamit_added_mass", "wamit_radiation_damping", "wamit_added_mass_inf"):
        assert np.array_equal(conv_graded[v].values, conv[v].values)


def test_graded_record_reproduces_the_graded_rows_of_the_tube_study(conv_graded, tube_study):
    # The graded 1.5 m and 1.0 m meshes (8 x 1 m tubes, untrimmed) were solved before in the
    # tube study at 0.7 / 1.1 / 1.25 rad/s (separate runs, there with 13 diffraction problems
    # as well): the diagonal A and B must agree per DOF.  Measured: < 4e-8 of the DOF's
    # largest value at the three frequencies except heave (A 1.3e-5, B 1.3e-4 at 1.0 m,
    # 1.25 rad/s: 83 N s/m of 6.20e5; 3.4e-5 at 1.5 m), so the tolerance is 5e-4, 50x below
    # the 2 % effect of the grading (the uniform 2 m runs of database.nc and of the
    # convergence record agree within 1.7e-5).
    for h in (1.5, 1.0):
        g = np.nonzero((tube_study.graded_column_edges.values == 1)
                       & (tube_study.column_panel_size.values == h)
                       & (tube_study.tube_panels_round.values == 8)
                       & (tube_study.trim_inside.values == 0))[0]
        assert g.size == 1
        ts = tube_study.isel(config=g[0])
        assert int(ts.nb_panels) == int(conv_graded.nb_panels.sel(panel_size=h))
        cg = conv_graded.sel(panel_size=h).sel(omega=ts.omega.values, method="nearest")
        for name in ("added_mass", "radiation_damping"):
            diag = np.diagonal(cg[name].values, axis1=1, axis2=2)
            ref = ts[name].values
            assert np.all(np.max(np.abs(diag - ref), axis=0)
                          <= 5e-4 * np.max(np.abs(ref), axis=0)), (name, h)


@pytest.mark.parametrize("dof", DOFS)
@pytest.mark.parametrize("name", ["added_mass", "radiation_damping"])
def test_graded_capytaine_matches_wamit_within_5_percent(conv_graded, name, dof):
    # Acceptance (replaces the heave-B strict xfail of the uniform record): Capytaine
    # from the public member geometry (RAFT_OC4semi.yaml), graded column panels, within 5 %
    # of WAMIT's marin_semi.1 over 0.30 .. 2.00 rad/s step 0.05, per diagonal DOF, in % of the
    # largest WAMIT value in the band.  Compared, as for the uniform record: the Richardson
    # extrapolation (order 2) from the two finest graded sizes (1.5, 1.0 m); and, because the
    # observed orders are erratic (median 0.7-2.8 over the frequencies, heave A not monotonic)
    # so the extrapolation is only an estimate, also the finest graded mesh (1.0 m) by itself.
    # Measured in capytaine_mesh_convergence_graded.nc (% of max|WAMIT|), extrapolated / 1.0 m:
    # A surge 2.3 / 3.1, heave 0.6 / 0.9, pitch 0.3 / 0.6, yaw 1.7 / 2.5; B surge 2.3 / 3.2,
    # heave 3.7 / 4.1 (at 1.15 rad/s: WAMIT 6.074e5, 1.0 m 5.807e5, extrapolated 5.837e5 N s/m),
    # pitch 1.4 / 1.4, yaw 2.4 / 3.3 (sway, roll = surge, pitch by symmetry).
    w = conv_graded.omega.values
    sel = (w >= BAND[0] - 1e-9) & (w <= BAND[1] + 1e-9)
    k = DOFS.index(dof)
    wam = conv_graded["wamit_" + name].values[sel]
    err_ext = _err(conv_graded[name + "_extrapolated"].values[sel], wam, k)
    err_fine = _err(conv_graded[name].sel(panel_size=1.0).values[sel], wam, k)
    assert err_ext < 0.05, f"extrapolated {name}[{dof},{dof}]: {100 * err_ext:.2f} % of max|WAMIT|"
    assert err_fine < 0.05, f"1.0 m graded {name}[{dof},{dof}]: {100 * err_fine:.2f} % of max|WAMIT|"


def test_graded_columns_raise_heave_damping_at_its_peak(conv_graded, conv):
    # The grading acts where the uniform study stalled: at 1.10-1.25 rad/s heave B of every
    # graded size lies above the uniform one of the same size (closer to WAMIT, which is
    # above both).  Measured at 1.25 rad/s (N s/m): uniform 6.044 / 6.072 / 6.068e5, graded
    # 6.114 / 6.166 / 6.201e5 (2.0 / 1.5 / 1.0 m), WAMIT 6.463e5.
    om = [1.1, 1.15, 1.2, 1.25]
    g = conv_graded.radiation_damping.sel(omega=om, method="nearest").values[:, :, 2, 2]
    u = conv.radiation_damping.sel(omega=om, method="nearest").values[:, :, 2, 2]
    wam = conv.wamit_radiation_damping.sel(omega=om, method="nearest").values[:, 2, 2]
    assert np.all(g > u) and np.all(g < wam)
