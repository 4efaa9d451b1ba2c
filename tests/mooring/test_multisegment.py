"""Multi-segment lines: consistency with the single catenary, finite differences, equilibrium
of the profile, and MoorPy (free connection points) as an independent solver."""

import math
import warnings

import numpy as np
import pytest

from floatmoor.core.errors import ConvergenceError
from floatmoor.mooring import catenary, solve_line

# chain - polyester - chain in the style of Wang (2016) table 5.2 (submerged weights assumed)
CPC = dict(lengths=[1200.0, 1200.0, 250.0], ea=[332.7e6, 172.8e6, 332.7e6],
           w=[1350.0, 60.0, 1350.0])


def fd(fun, xf, zf, h):
    def f(x, z):
        r = fun(x, z)
        return np.array([r.HF, r.VF])
    return np.column_stack([(f(xf + h, zf) - f(xf - h, zf)) / (2 * h),
                            (f(xf, zf + h) - f(xf, zf - h)) / (2 * h)])


def test_split_segments_equal_single_line():
    """A line cut into three pieces of equal properties is the same line."""
    args = (848.67, 250.0)
    one = catenary(*args, 902.2, 384.243e6, 698.09, 0.4)
    three = solve_line(*args, [100.0, 500.0, 302.2], [384.243e6] * 3, [698.09] * 3, cb=0.4)
    for k in ("HF", "VF", "HA", "VA", "grounded_length"):
        assert getattr(three, k) == pytest.approx(getattr(one, k), rel=1e-9, abs=1e-9)
    np.testing.assert_allclose(three.stiffness, one.stiffness, rtol=1e-8)


@pytest.mark.parametrize("xf", [2000.0, 2450.0, 2560.0, 2620.0])
def test_chain_polyester_chain_stiffness_fd(xf):
    """Touchdown in the lower chain, at the joint, in the polyester, or none: analytic 2x2
    against central differences."""
    def fun(x, z):
        return solve_line(x, z, CPC["lengths"], CPC["ea"], CPC["w"], cb=0.6)
    r = fun(xf, 130.0)
    k = fd(fun, xf, 130.0, 1e-3)
    np.testing.assert_allclose(r.stiffness, k, rtol=2e-5, atol=1e-7 * np.abs(k).max())


@pytest.mark.parametrize("cb", [0.0, 0.5])
@pytest.mark.parametrize("xf,where", [(850.0, "polyester"), (870.0, "clump"), (880.0, "chain")])
def test_clump_and_buoy_profile_equilibrium_and_fd(xf, where, cb):
    """Clump weight at joint 1, buoy at joint 2; touchdown in the polyester, at the clump (which
    then rests on the seabed) or in the lower chain.  The profile closes on the fairlead, stays
    above the seabed, VF - VA equals the suspended weight, and the stiffness matches central
    differences."""
    L = [400.0, 300.0, 200.0]
    EA = [5e8, 2e8, 5e8]
    W = [1000.0, 200.0, 1000.0]
    P = [50e3, -30e3, 0.0]
    def fun(x, z):
        return solve_line(x, z, L, EA, W, P, cb)
    r = fun(xf, 150.0)
    p = r.profile(401)
    assert p["x"][-1] == pytest.approx(xf, abs=1e-6)
    assert p["z"][-1] == pytest.approx(150.0, abs=1e-6)
    assert p["z"].min() >= -1e-9
    lg = r.grounded_length
    if where == "chain":
        assert 0.0 < lg < 400.0
        suspended = 1000.0 * (400.0 - lg) + 200.0 * 300.0 + 1000.0 * 200.0 + 50e3 - 30e3
    elif where == "clump":
        # the clump rests on the seabed, the line above lifts part of its weight
        assert lg == 400.0
        above = 200.0 * 300.0 + 1000.0 * 200.0 - 30e3
        assert above < r.VF < above + 50e3
        suspended = r.VF  # VA = 0
        # friction: anchor tension = HF - cb (normal force on the clump + chain weight on seabed)
        normal = 50e3 - (r.VF - above)
        assert r.HA == pytest.approx(max(r.HF - cb * (normal + 1000.0 * 400.0), 0.0), rel=1e-9)
    else:
        assert 400.0 < lg < 700.0
        suspended = 200.0 * (700.0 - lg) + 1000.0 * 200.0 - 30e3
    assert r.VF - r.VA == pytest.approx(suspended, rel=1e-9)
    np.testing.assert_allclose(r.stiffness, fd(fun, xf, 150.0, 1e-4), rtol=5e-5)


def test_buoyant_segment_suspended_lazy_wave():
    """A lazy-wave: chain, buoyant section, chain.  Supported while the buoyant section is
    suspended; the profile closes and the stiffness matches finite differences."""
    L = [300.0, 150.0, 250.0]
    EA = [5e8, 5e8, 5e8]
    W = [1000.0, -800.0, 1000.0]
    def fun(x, z):
        return solve_line(x, z, L, EA, W)
    r = fun(450.0, 150.0)
    p = r.profile(301)
    assert p["x"][-1] == pytest.approx(450.0, abs=1e-6)
    assert p["z"][-1] == pytest.approx(150.0, abs=1e-6)
    assert 0.0 < r.grounded_length < 300.0
    np.testing.assert_allclose(r.stiffness, fun(450.0, 150.0).stiffness)
    np.testing.assert_allclose(r.stiffness, fd(fun, 450.0, 150.0, 1e-3), rtol=5e-5)


def test_buoyant_segment_on_seabed_is_refused():
    """A buoyant section that would have to lie on the seabed is refused, naming the line."""
    with pytest.raises(ConvergenceError, match="buoyant|line 7"):
        solve_line(500.0, 50.0, [100.0, 200.0, 300.0], [5e8] * 3, [1000.0, -50.0, 1000.0],
                   name="line 7")


def test_against_moorpy_free_connection_points():
    """MoorPy System with two free connection points (clump weight at the upper one, which stays
    suspended: MoorPy supports points near the seabed with a soft contact ramp that has no
    counterpart here) solved by its own equilibrium iteration.  Fairlead forces within 0.1 %."""
    mp = pytest.importorskip("moorpy")
    depth = 150.0
    g = 9.81
    clump_kg = 8000.0
    ms = mp.System(depth=depth, g=g)
    # line types by mass per length and volumetric diameter; w = (m - rho pi d^2 / 4) g
    ms.setLineType(dnommm=151.0, name="chain", mass=140.0, d_vol=0.151, EA=6.0e8)
    ms.setLineType(dnommm=160.0, name="poly", mass=25.0, d_vol=0.16, EA=1.5e8)
    ms.addPoint(1, [-2500.0, 0.0, -depth])
    ms.addPoint(0, [-1400.0, 0.0, -depth + 1.0])
    ms.addPoint(0, [-300.0, 0.0, -80.0], m=clump_kg)
    ms.addPoint(1, [0.0, 0.0, -15.0])
    ms.addLine(1150.0, "chain", pointA=1, pointB=2, nSegs=20)
    ms.addLine(1100.0, "poly", pointA=2, pointB=3, nSegs=20)
    ms.addLine(250.0, "chain", pointA=3, pointB=4, nSegs=20)
    ms.initialize()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ms.solveEquilibrium(tol=1e-6, maxIter=1000)
    f_mp = ms.pointList[3].getForces()
    lt = ms.lineTypes
    w = [lt["chain"]["w"], lt["poly"]["w"], lt["chain"]["w"]]
    r = solve_line(2500.0, depth - 15.0, [1150.0, 1100.0, 250.0], [6.0e8, 1.5e8, 6.0e8], w,
                   [0.0, clump_kg * g, 0.0])
    assert abs(ms.pointList[2].r[2] + depth) > 10.0  # the clump is well off the seabed
    assert r.HF == pytest.approx(abs(f_mp[0]), rel=1e-3)
    assert r.VF == pytest.approx(abs(f_mp[2]), rel=1e-3)


def test_random_lines_converge_and_profiles_close():
    """1,000 random 1-3 segment lines (EA 1e7-1e11 N, w 1-5000 N/m, clumps, friction 0-1, with
    and without seabed): every solve converges and the independently integrated profile ends on
    the fairlead (horizontally slack lines excepted in x: their grounded part lies in a heap)."""
    rng = np.random.default_rng(11)
    for _ in range(1000):
        ns = int(rng.integers(1, 4))
        L = rng.uniform(10, 1500, ns)
        EA = 10 ** rng.uniform(7, 11, ns)
        w = rng.uniform(1, 5000, ns)
        P = np.where(rng.uniform(size=ns) < 0.3, rng.uniform(0, 50e3, ns), 0.0)
        Lt = L.sum()
        zf = rng.uniform(0, 0.99) * Lt
        xf = rng.uniform(0, 1.05) * math.sqrt(max(Lt ** 2 - zf ** 2, 0.0))
        cb = float(rng.choice([0.0, 0.3, 1.0]))
        seabed = bool(rng.uniform() < 0.85)
        r = solve_line(xf, zf, L, EA, w, P, cb, seabed=seabed)
        p = r.profile(41)
        assert p["z"][-1] == pytest.approx(zf, abs=1e-6 * Lt)
        if r.HF > 0:
            assert p["x"][-1] == pytest.approx(xf, abs=1e-6 * Lt)
