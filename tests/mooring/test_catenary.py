"""Single elastic catenary: closed forms, limits, symmetry, finite differences and MoorPy."""

import math
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

from floatmoor.core.errors import ConvergenceError
from floatmoor.mooring import catenary

G = 9.80665


def fd_stiffness(xf, zf, *args, h=1e-4, **kw):
    def f(x, z):
        r = catenary(x, z, *args, **kw)
        return np.array([r.HF, r.VF])
    kx = (f(xf + h, zf) - f(xf - h, zf)) / (2 * h)
    kz = (f(xf, zf + h) - f(xf, zf - h)) / (2 * h)
    return np.column_stack([kx, kz])


# ---------------------------------------------------------------------------------------------
# Closed forms and limits
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("a,zf,L", [(300.0, 250.0, 900.0), (50.0, 100.0, 400.0), (2000.0, 20.0, 1000.0)])
def test_inextensible_touchdown_closed_form(a, zf, L):
    """Inextensible catenary z = a (cosh(x/a) - 1) from the touchdown point (textbook form):
    suspended length Ls = sqrt(zf^2 + 2 a zf), its horizontal span a acosh(1 + zf/a), H = w a,
    V = w Ls.  A very stiff line (EA = 1e16 N) must reproduce it."""
    w = 700.0
    Ls = math.sqrt(zf * zf + 2 * a * zf)
    assert Ls < L
    xf = (L - Ls) + a * math.acosh(1 + zf / a)
    r = catenary(xf, zf, L, 1e19, w)
    assert r.HF == pytest.approx(w * a, rel=1e-7)
    assert r.VF == pytest.approx(w * Ls, rel=1e-7)
    assert r.grounded_length == pytest.approx(L - Ls, rel=1e-7)
    assert r.HA == pytest.approx(r.HF, rel=1e-12) and r.VA == 0.0


def test_inextensible_suspended_symmetric_closed_form():
    """Both ends at the same height, no seabed: the textbook symmetric catenary
    L = 2 a sinh(xf / (2 a)), VF = w L / 2 at each end, HF = w a."""
    w, a, xf = 500.0, 400.0, 600.0
    L = 2 * a * math.sinh(xf / (2 * a))
    r = catenary(xf, 0.0, L, 1e16, w, seabed=False)
    assert r.HF == pytest.approx(w * a, rel=1e-7)
    assert r.VF == pytest.approx(w * L / 2, rel=1e-7)
    assert r.VA == pytest.approx(-w * L / 2, rel=1e-7)  # the anchor end is pulled down too
    assert r.HA == pytest.approx(r.HF)


def test_mirrored_line_gives_the_other_end():
    """Swapping the ends of a free-hanging line (zf -> -zf) must swap end forces:
    HF stays, VF(-zf) = -VA(zf)."""
    args = (700.0, 1000.0, 5e8, 800.0)
    r1 = catenary(args[0], 150.0, *args[1:], seabed=False)
    r2 = catenary(args[0], -150.0, *args[1:], seabed=False)
    assert r2.HF == pytest.approx(r1.HF, rel=1e-9)
    assert r2.VF == pytest.approx(-r1.VA, rel=1e-9)
    assert r2.VA == pytest.approx(-r1.VF, rel=1e-9)


def test_vertical_taut_line_elastic():
    """xf = 0, no seabed, stretched vertically: zf = L + (VF L - w L^2 / 2) / EA."""
    L, EA, w = 100.0, 1e8, 500.0
    zf = 100.5
    r = catenary(0.0, zf, L, EA, w, seabed=False)
    assert r.HF < 1e-9 * r.VF
    assert r.VF == pytest.approx((zf - L) * EA / L + w * L / 2, rel=1e-9)
    assert r.stiffness[1, 1] == pytest.approx(EA / L, rel=1e-6)


def test_very_slack_line_hangs_vertically():
    """More line on the seabed than the horizontal distance: H = 0, the line hangs vertically
    over the fairlead height; elastic vertical hang: zf = Ls + w Ls^2 / (2 EA), VF = w Ls."""
    L, EA, w, zf = 900.0, 4e8, 700.0, 250.0
    r = catenary(100.0, zf, L, EA, w)
    Ls = (-1 + math.sqrt(1 + 2 * w * zf / EA)) / (w / EA)
    assert r.HF == 0.0 and r.HA == 0.0
    assert r.VF == pytest.approx(w * Ls, rel=1e-9)
    assert r.stiffness[0, 0] == 0.0


def test_nearly_vertical_and_taut_lines_match_fd():
    cases = [
        (1e-3, 250.0, 260.0, 4e8, 700.0, True),    # nearly vertical, fully suspended
        (900.0, 250.0, 902.2, 3.8e8, 698.0, True),  # taut, stretched beyond the chord
        (848.67, 250.0, 902.2, 384.243e6, 698.09, True),  # OC3, touching the seabed
        (500.0, 100.0, 700.0, 1e9, 1500.0, False),  # free hanging U-shape
    ]
    for xf, zf, L, EA, w, sb in cases:
        r = catenary(xf, zf, L, EA, w, seabed=sb)
        h = 1e-6 * max(xf, zf, 1.0)
        k = fd_stiffness(xf, zf, L, EA, w, seabed=sb, h=h)
        np.testing.assert_allclose(r.stiffness, k, rtol=2e-5, atol=1e-6 * np.abs(k).max())


def test_friction_stiffness_matches_fd():
    r = catenary(848.67, 250.0, 902.2, 384.243e6, 698.09, 0.5)
    k = fd_stiffness(848.67, 250.0, 902.2, 384.243e6, 698.09, 0.5)
    np.testing.assert_allclose(r.stiffness, k, rtol=1e-5)
    # friction: anchor tension = HF - cb w LB
    assert r.HA == pytest.approx(r.HF - 0.5 * 698.09 * r.grounded_length, rel=1e-9)


def test_oc3_line_against_map_sum():
    """MAP++ 1.20.10 .sum file of the OC3-Hywind r-test (reference/OC3_Hywind):
    H = 736,939.290 N, V = 535,727.992 N, HAnch = 736,845.198 N, Lb = 134.785 m.  The .sum prints
    omega = 698.09 N/m, which is (77.7066 - 1025 pi 0.09^2 / 4) * 9.80665."""
    w = (77.7066 - 1025 * math.pi * 0.09 ** 2 / 4) * G
    assert w == pytest.approx(698.09, abs=0.005)
    r = catenary(853.87 - 5.2, 320.0 - 70.0, 902.2, 384.243e6, w, 0.001)
    assert r.HF == pytest.approx(736939.290, rel=2e-6)
    assert r.VF == pytest.approx(535727.992, rel=2e-6)
    assert r.HA == pytest.approx(736845.198, rel=2e-6)
    assert r.grounded_length == pytest.approx(134.785, abs=2e-3)


def test_profile_closes_and_matches_end_forces():
    r = catenary(848.67, 250.0, 902.2, 384.243e6, 698.09, 0.3)
    p = r.profile(201)
    assert p["x"][0] == 0.0 and p["z"][0] == 0.0
    assert p["x"][-1] == pytest.approx(848.67, abs=1e-6)
    assert p["z"][-1] == pytest.approx(250.0, abs=1e-6)
    assert p["tension"][-1] == pytest.approx(r.fairlead_tension, rel=1e-9)
    assert p["tension"][0] == pytest.approx(r.anchor_tension, rel=1e-9)
    assert p["z"].min() >= 0.0
    assert np.all(np.diff(p["x"]) >= 0)


def test_warm_start_converges_faster():
    r = catenary(848.67, 250.0, 902.2, 384.243e6, 698.09)
    r2 = catenary(849.0, 250.0, 902.2, 384.243e6, 698.09, hf0=r.HF, vf0=r.VF)
    r3 = catenary(849.0, 250.0, 902.2, 384.243e6, 698.09)
    assert r2.HF == pytest.approx(r3.HF, rel=1e-10)
    assert r2.iterations <= r3.iterations


def test_bad_input_and_non_convergence_name_the_inputs():
    with pytest.raises(ValueError, match="length"):
        catenary(100.0, 50.0, -1.0, 1e8, 100.0)
    with pytest.raises(ValueError):
        catenary(100.0, 50.0, 200.0, 0.0, 100.0)
    # a failed iteration (here forced by a NaN warm start) is a ConvergenceError naming inputs
    with pytest.raises(ConvergenceError, match=r"catenary\(xf=300.0, zf=50.0, length=400.0"):
        catenary(300.0, 50.0, 400.0, 1e8, 100.0, hf0=1.0, vf0=float("nan"))


def test_buoyant_suspended_line_is_the_mirror_of_a_hanging_one():
    """A buoyant line (w < 0) that stays off the seabed is the vertical mirror image of a heavy
    line: HF equal, VF opposite."""
    r = catenary(300.0, 50.0, 400.0, 1e8, -100.0)
    m = catenary(300.0, -50.0, 400.0, 1e8, 100.0, seabed=False)
    assert r.HF == pytest.approx(m.HF, rel=1e-9)
    assert r.VF == pytest.approx(-m.VF, rel=1e-9)


def test_kernel_runs_without_jit():
    """The kernel must also run as plain Python (NUMBA_DISABLE_JIT=1)."""
    code = ("from floatmoor.mooring import catenary; "
            "r = catenary(848.67, 250.0, 902.2, 384.243e6, 698.09, 0.001); print(float(r.HF))")
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True)
    assert float(out.stdout.strip()) == pytest.approx(catenary(848.67, 250.0, 902.2, 384.243e6, 698.09, 0.001).HF, rel=1e-12)


# ---------------------------------------------------------------------------------------------
# MoorPy (optional reference program)
# ---------------------------------------------------------------------------------------------
def _random_cases(n, seed=1):
    rng = np.random.default_rng(seed)
    for i in range(n):
        L = rng.uniform(100, 1500)
        zf = rng.uniform(0.05, 0.95) * L
        xmax = math.sqrt(max(L * L - zf * zf, 1.0))
        regime = i % 4
        if regime == 0:      # ordinary catenary, part on the seabed or just lifting
            xf = rng.uniform(0.3, 0.99) * xmax
        elif regime == 1:    # taut: around and beyond the chord length
            xf = rng.uniform(0.99, 1.01) * xmax
        elif regime == 2:    # steep, nearly vertical
            xf = rng.uniform(0.0, 0.3) * xmax
        else:                # very slack, long grounded part
            xf = rng.uniform(0.7, 0.999) * (L - zf)
        w = rng.uniform(50, 5000)
        EA = 10 ** rng.uniform(7, 10)
        cb = [0.0, 0.5, 1.0, 0.0][rng.integers(4)]
        seabed = rng.uniform() >= 0.2
        yield xf, zf, L, EA, w, cb, seabed


def test_against_moorpy_random_cases():
    """MoorPy's catenary() (Hall et al., NREL; FAST v7 formulation): end forces within 0.1 %
    over 400 random cases in all regimes, with and without seabed friction.

    MoorPy conventions: CB > 0 is the seabed friction coefficient, CB < 0 means no seabed contact
    (the seabed is -CB below end A; -1e9 here); info['HF'], info['VF'] are the fairlead (end B)
    tension components; fAH, fAV are the forces on the anchor (end A), positive towards end B
    and up.  MoorPy 1.3.0 returns for a few strongly stretched lines a fully suspended shape whose
    anchor end is pulled *down* (the line runs below the seabed); those cases are checked for
    closure of our own profile instead and counted."""
    mp = pytest.importorskip("moorpy.Catenary")
    worst = 0.0
    compared = 0
    below = 0
    for xf, zf, L, EA, w, cb, seabed in _random_cases(400):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fAH, fAV, fBH, fBV, info = mp.catenary(xf, zf, L, EA, w, CB=cb if seabed else -1e9,
                                                   Tol=1e-10, MaxIter=200)
        r = catenary(xf, zf, L, EA, w, cb, seabed=seabed)
        T = math.hypot(r.HF, r.VF)
        if seabed and fAV < -1e-6 * math.hypot(fAH, fAV):
            below += 1
            p = r.profile(101)
            assert p["x"][-1] == pytest.approx(xf, abs=1e-6 * L)
            assert p["z"][-1] == pytest.approx(zf, abs=1e-6 * L)
            assert p["z"].min() >= -1e-9
            continue
        err = max(abs(r.HF - info["HF"]), abs(r.VF - info["VF"]), abs(r.HA - abs(fAH)),
                  abs(r.VA - fAV)) / T
        worst = max(worst, err)
        compared += 1
    assert compared >= 380 and below <= 20
    assert worst < 1e-3
    print(f"catenary vs MoorPy: {compared} cases, max rel. error {worst:.2e}; "
          f"{below} MoorPy shapes below the seabed skipped")
