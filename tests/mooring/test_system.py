"""MooringSystem: OC3-Hywind published stiffness, MAP++ fairlead forces, finite differences at
general poses, large yaw, line failure and the no-JIT path."""

import math

import numpy as np
import pytest

from floatmoor.core.frames import rotation_matrix
from floatmoor.mooring import LineDef, MooringSystem, Segment

G = 9.80665


def oc3_system(g=G, cb=0.0):
    """OC3-Hywind mooring from the MAP++/MoorDyn input files (reference/OC3_Hywind): 3 lines of
    902.2 m, D = 0.09 m, 77.7066 kg/m, EA = 384.243e6 N; anchors at r = 853.87 m, 320 m deep;
    fairleads at r = 5.2 m, z = -70 m; lines at 0, 120, 240 deg."""
    w = (77.7066 - 1025 * math.pi * 0.09 ** 2 / 4) * g
    lines = []
    for i, az in enumerate((0.0, 120.0, 240.0)):
        a = math.radians(az)
        lines.append(LineDef(name=f"line{i + 1}",
                             anchor=(853.87 * math.cos(a), 853.87 * math.sin(a), -320.0),
                             fairlead=(5.2 * math.cos(a), 5.2 * math.sin(a), -70.0),
                             segments=(Segment(length=902.2, ea=384.243e6, w=w),), cb=cb))
    return MooringSystem(lines, water_depth=320.0)


def euler_from_matrix(R):
    roll = math.atan2(R[2, 1], R[2, 2])
    pitch = -math.asin(max(-1.0, min(1.0, R[2, 0])))
    yaw = math.atan2(R[1, 0], R[0, 0])
    return roll, pitch, yaw


def rotvec_matrix(theta):
    th = np.linalg.norm(theta)
    if th == 0:
        return np.eye(3)
    k = theta / th
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(th) * K + (1 - math.cos(th)) * K @ K


def perturbed(pose, delta):
    """Pose after a small translation delta[:3] and rotation vector delta[3:] (earth axes)
    about the displaced reference point."""
    R = rotvec_matrix(np.asarray(delta[3:])) @ rotation_matrix(*pose[3:])
    return np.concatenate([np.asarray(pose[:3]) + delta[:3], euler_from_matrix(R)])


def fd_stiffness(ms, pose, h_t=1e-3, h_r=1e-6):
    K = np.zeros((6, 6))
    for j in range(6):
        h = h_t if j < 3 else h_r
        d = np.zeros(6)
        d[j] = h
        fp = ms.force(perturbed(pose, d))
        fm = ms.force(perturbed(pose, -d))
        K[:, j] = -(fp - fm) / (2 * h)
    return K


def test_oc3_stiffness_against_published_values():
    """Jonkman (2010) NREL/TP-500-47535 eq. 5-3 (also BModes mooring_K): K11 = K22 = 41,180 N/m,
    K33 = 11,940 N/m, K15 = -2.821e6 N/rad (K24 = +2.821e6), K44 = K55 = 3.111e8 N m/rad,
    K66 = 1.156e7 N m/rad; moments about the displaced reference point.  Within 1 %."""
    K = oc3_system().stiffness(np.zeros(6))
    assert K[0, 0] == pytest.approx(41180, rel=0.01)
    assert K[1, 1] == pytest.approx(41180, rel=0.01)
    assert K[2, 2] == pytest.approx(11940, rel=0.01)
    assert K[0, 4] == pytest.approx(-2.821e6, rel=0.01)
    assert K[4, 0] == pytest.approx(-2.816e6, rel=0.01)
    assert K[1, 3] == pytest.approx(2.821e6, rel=0.01)
    assert K[3, 3] == pytest.approx(3.111e8, rel=0.01)
    assert K[4, 4] == pytest.approx(3.111e8, rel=0.01)
    assert K[5, 5] == pytest.approx(1.156e7, rel=0.01)
    off = np.ones((6, 6), bool)
    for i, j in [(0, 0), (1, 1), (2, 2), (3, 3), (4, 4), (5, 5), (0, 4), (4, 0), (1, 3), (3, 1)]:
        off[i, j] = False
    assert np.abs(K[off]).max() < 1e-6 * np.abs(K).max()


def test_oc3_fairlead_forces_against_map_sum():
    """MAP++ .sum (reference/OC3_Hywind): H = 736,939 N, V = 535,728 N per line (its omega
    698.09 N/m corresponds to g = 9.80665 in the weight, CB = 0.001); total vertical 3 V."""
    ms = oc3_system(cb=0.001)
    t = ms.tensions(np.zeros(6))
    np.testing.assert_allclose(t["horizontal_fairlead"], 736939.29, rtol=2e-6)
    np.testing.assert_allclose(t["vertical_fairlead"], 535728.0, rtol=2e-6)
    f = ms.force(np.zeros(6))
    assert f[2] == pytest.approx(-3 * 535728.0, rel=2e-6)
    np.testing.assert_allclose(f[[0, 1, 3, 4, 5]], 0.0, atol=1e-3)


@pytest.mark.parametrize("pose", [
    np.zeros(6),
    np.array([12.0, -7.0, 1.5, 0.05, -0.08, 0.3]),
    np.array([-20.0, 15.0, -2.0, -0.1, 0.06, 2.4]),   # large yaw
])
def test_analytic_stiffness_matches_finite_differences(pose):
    ms = oc3_system(cb=0.3)
    K = ms.stiffness(pose)
    Kfd = fd_stiffness(ms, pose)
    # relative 1e-4, with an absolute floor of 1e-6 of the largest entry for entries near zero
    excess = np.abs(K - Kfd) - 1e-4 * np.abs(Kfd)
    assert excess.max() < 1e-6 * np.abs(K).max(), (K, Kfd)


def test_force_is_invariant_under_symmetric_yaw():
    """OC3 is symmetric under a 120 deg rotation: the system at the rotated offset (same yaw)
    gives the rotated force and moment (line k takes the place of line k+1)."""
    ms = oc3_system()
    p = np.array([15.0, 4.0, 0.0, 0.0, 0.0, 0.2])
    c, s = math.cos(2 * math.pi / 3), math.sin(2 * math.pi / 3)
    q = np.array([c * 15.0 - s * 4.0, s * 15.0 + c * 4.0, 0.0, 0.0, 0.0, 0.2])
    f1, f2 = ms.force(p), ms.force(q)
    Rz = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    np.testing.assert_allclose(f2[:3], Rz @ f1[:3], rtol=1e-9, atol=1e-3)
    np.testing.assert_allclose(f2[3:], Rz @ f1[3:], rtol=1e-9, atol=1e-2)


def test_line_failure():
    ms = oc3_system()
    ms2 = ms.without_lines(["line1"])
    f = ms2.force(np.zeros(6))
    # with line 1 (towards +x) gone the other two pull the body towards -x
    assert f[0] < -1e5
    t = ms2.tensions(np.zeros(6))
    assert bool(t["failed"].sel(line="line1"))
    assert np.isnan(float(t["fairlead_tension"].sel(line="line1")))
    with pytest.raises(KeyError, match="line1, line2, line3"):
        ms.without_lines(["line9"])


def test_tension_above_mbs_warns_naming_the_line():
    ms = oc3_system()
    lines = [LineDef(name=l.name, anchor=l.anchor, fairlead=l.fairlead,
                     segments=(Segment(length=902.2, ea=384.243e6, w=l.segments[0].w, mbs=2.0e6),))
             for l in ms.lines]
    ms = MooringSystem(lines, water_depth=320.0)
    from floatmoor.core.errors import FloatmoorWarning
    with pytest.warns(FloatmoorWarning, match="line 'line1'.*exceeds its MBS 2000.0 kN"):
        t = ms.tensions(np.array([-60.0, 0, 0, 0, 0, 0]), warn=True)
    assert float(t["utilisation"].sel(line="line1")) > 1.0


def test_profile_in_earth_coordinates():
    ms = oc3_system()
    p = ms.line_profile("line2", np.zeros(6))
    a = ms.anchors[1]
    assert p["x"][0] == pytest.approx(a[0]) and p["z"][0] == pytest.approx(-320.0)
    fl = ms.fairlead_positions(np.zeros(6))[1]
    assert p["x"][-1] == pytest.approx(fl[0], abs=1e-6)
    assert p["y"][-1] == pytest.approx(fl[1], abs=1e-6)
    assert p["z"][-1] == pytest.approx(-70.0, abs=1e-6)


def test_system_kernel_direct_call_with_warm_starts():
    """The time-loop kernel called directly with preallocated arrays gives the same force as the
    Python API, with and without warm starts, and reports per-line results."""
    from floatmoor.mooring.catenary import OUT_SIZE
    from floatmoor.mooring.system import system_force_kernel
    ms = oc3_system(cb=0.2)
    pose = np.array([5.0, -3.0, 0.5, 0.02, -0.01, 0.1])
    n = ms.n_lines
    warm = np.zeros((n, 2))
    work = np.zeros(64)
    rot = np.zeros((3, 3))
    line_out = np.zeros((n, OUT_SIZE))
    force = np.zeros(6)
    stiff = np.zeros((6, 6))
    args = (ms.anchors, ms.fairleads, ms.seg_L, ms.seg_EA, ms.seg_w, ms.seg_P, ms.line_start,
            ms.cb, ms.seabed, ms.active)
    ref = oc3_system(cb=0.2).force(pose)
    for step in range(3):  # cold, then warm starts
        p = pose + step * np.array([0.01, 0, 0, 0, 0, 0])
        assert system_force_kernel(p, *args, warm, False, work, rot, line_out, force, stiff) == -1
        if step == 0:
            np.testing.assert_allclose(force, ref, rtol=1e-10, atol=1e-6)
    assert np.all(warm[:, 0] > 0) and np.all(line_out[:, -1] <= 3)  # warm: few iterations


def test_system_force_without_jit():
    import os
    import subprocess
    import sys
    code = ("import sys, numpy as np; sys.path.insert(0, 'tests/mooring'); "
            "from test_system import oc3_system; "
            "print(repr(oc3_system(cb=0.2).force(np.array([5.0, -3.0, 0.5, 0.02, -0.01, 0.1])).tolist()))")
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    out = subprocess.run([sys.executable, "-c", code], env=dict(os.environ, NUMBA_DISABLE_JIT="1"),
                         capture_output=True, text=True, check=True, cwd=root)
    f = np.array(eval(out.stdout.strip()))
    np.testing.assert_allclose(f, oc3_system(cb=0.2).force(
        np.array([5.0, -3.0, 0.5, 0.02, -0.01, 0.1])), rtol=1e-10, atol=1e-6)


def test_dynamic_ea_stiffens_a_polyester_system():
    """Polyester with dynamic EA (25 MBS) > static (15 MBS): the taut system gets stiffer."""
    from floatmoor.mooring.line_types import polyester
    p = polyester(0.15)
    seg = Segment(length=400.0, ea=p.ea, w=p.submerged_weight(), ea_dynamic=p.ea_dynamic)
    lines = [LineDef(name=f"p{i}", anchor=(380 * math.cos(a), 380 * math.sin(a), -150.0),
                     fairlead=(0.0, 0.0, 0.0), segments=(seg,))
             for i, a in enumerate((0.0, 2 * math.pi / 3, 4 * math.pi / 3))]
    ms = MooringSystem(lines, water_depth=150.0)
    k_static = ms.stiffness()[0, 0]
    k_dyn = ms.with_dynamic_ea().stiffness()[0, 0]
    assert k_dyn > 1.2 * k_static
