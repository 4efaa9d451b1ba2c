"""Fibre segments in the mooring system: the working curve in statics (hand computation for a
taut segment; direct integration of the extensible catenary with the nonlinear law), the
linearisation about the mean tension (a small harmonic stretch gives EA_dyn(T_mean)), the
default path unchanged."""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import fsolve

from floatmoor.mooring import LineDef, MooringSystem, Segment
from floatmoor.mooring.fibre import POLYESTER_DEFAULT, FibreModel

MBS = 8.5e6
SIMPLE = FibreModel(working_strain=(0.0, 0.01, 0.03), working_tension_mbs=(0.0, 0.10, 0.40),
                    alpha=10.0, beta=0.5)


def taut_system(model=SIMPLE, length=1000.0, dist=1020.0, w=0.0, ea=15 * MBS):
    """One segment between a mid-water anchor at the origin and a fairlead at 45 deg."""
    c = dist / math.sqrt(2.0)
    line = LineDef(name="p", anchor=(0.0, 0.0, -c - 10.0), fairlead=(c, 0.0, -10.0),
                   segments=(Segment(length=length, ea=ea, w=w, mbs=MBS, fibre=model),),
                   anchor_on_seabed=False)
    return MooringSystem([line], water_depth=2000.0)


def test_taut_weightless_segment_against_hand_computation():
    """Straight segment: strain 1020/1000 - 1 = 2 %, on the working curve T = 25 % MBS
    (halfway between (1 %, 10 %) and (3 %, 40 %))."""
    ms = taut_system()
    t = ms.tensions(np.zeros(6))
    assert float(t["fairlead_tension"][0]) == pytest.approx(0.25 * MBS, rel=1e-9)
    assert float(t["anchor_tension"][0]) == pytest.approx(0.25 * MBS, rel=1e-9)
    # the stiffness along the line is the tangent 15 MBS / L (working curve slope)
    K = ms.stiffness(np.zeros(6))
    e = np.array([1.0, 0.0, 1.0]) / math.sqrt(2.0)
    k_axial = e @ K[:3, :3] @ e
    assert k_axial == pytest.approx(15.0 * MBS / 1000.0, rel=1e-6)


def _nonlinear_catenary(H, V, L, w, model):
    """Fairlead position of a fully suspended segment with the nonlinear law, integrating
    dx/ds = (1 + eps(T)) H / T, dz/ds = (1 + eps(T)) V(s) / T, V(s) = V - w (L - s)."""
    def eps(T):
        return float(model.static_strain(T, MBS))

    def fx(s):
        v = V - w * (L - s)
        T = math.hypot(H, v)
        return (1.0 + eps(T)) * H / T

    def fz(s):
        v = V - w * (L - s)
        T = math.hypot(H, v)
        return (1.0 + eps(T)) * v / T
    opts = dict(limit=200, epsabs=1e-10, epsrel=1e-12, points=None)
    return quad(fx, 0.0, L, **opts)[0], quad(fz, 0.0, L, **opts)[0]


@pytest.mark.parametrize("model", [SIMPLE, POLYESTER_DEFAULT])
def test_heavy_catenary_against_direct_integration(model):
    """A suspended segment with a (deliberately large) weight of 300 N/m, tension varying by
    about 300 kN along it: the secant EA at the length-mean tension against the exact nonlinear
    extensible catenary solved by shooting on (H, V). Tolerance 5e-5 relative on the fairlead
    tension (the secant rule is exact for uniform tension; the residual is the variation of the
    working-curve slope along the segment; measured about 5e-6 in H)."""
    L, w = 1000.0, 300.0
    ms = taut_system(model, length=L, dist=1015.0, w=w)
    t = ms.tensions(np.zeros(6))
    hf, vf = float(t["horizontal_fairlead"][0]), float(t["vertical_fairlead"][0])
    c = 1015.0 / math.sqrt(2.0)

    def res(hv):
        x, z = _nonlinear_catenary(hv[0], hv[1], L, w, model)
        return [x - c, z - c]
    H, V = fsolve(res, [hf, vf], xtol=1e-13)
    assert np.allclose(res([H, V]), 0.0, atol=1e-6)
    assert math.hypot(hf, vf) == pytest.approx(math.hypot(H, V), rel=5e-5)
    assert hf == pytest.approx(H, rel=5e-5)


def test_harmonic_stretch_gives_dynamic_ea_at_mean_tension():
    """Linearised about the mean (2 % strain, T_m = 25 % MBS): a small stretch dl changes the
    tension by EA_dyn dl / L with EA_dyn = MBS (10 + 0.5 * 25) = 22.5 MBS (upper bound), or by
    the working-curve tangent 15 MBS (lower bound); the mean tension itself is unchanged."""
    ms = taut_system()
    e = np.array([1.0, 0.0, 1.0, 0, 0, 0]) / math.sqrt(2.0)
    amp = 1e-3
    for sys_, k_expected in ((ms.linearised_fibre(np.zeros(6)), 22.5 * MBS),
                             (ms.with_fibre_bound("lower").linearised_fibre(np.zeros(6)), 15 * MBS)):
        t0 = float(sys_.tensions(np.zeros(6))["fairlead_tension"][0])
        assert t0 == pytest.approx(0.25 * MBS, rel=1e-9)
        phases = np.linspace(0.0, 2 * np.pi, 17)[:-1]
        dt = np.array([float(sys_.tensions(amp * math.sin(p) * e)["fairlead_tension"][0]) - t0
                       for p in phases])
        # first harmonic of the tension over the stretch amplitude
        k = 2.0 * np.mean(dt * np.sin(phases)) / amp * 1000.0
        assert k == pytest.approx(k_expected, rel=1e-4)


def test_slack_and_chain_fibre_chain_line_converges():
    """Chain-polyester-chain line with a seabed touchdown (the Floatel-like arrangement in
    miniature): the secant iteration converges, the force is continuous with the pose and the
    analytic stiffness matches finite differences of the working-curve force (tangent)."""
    from floatmoor.mooring.line_types import chain, polyester
    ch, po = chain(0.084), polyester(0.16)
    segs = (Segment(length=600.0, ea=ch.ea, w=ch.submerged_weight(), mbs=ch.mbs),
            Segment(length=900.0, ea=po.ea, w=po.submerged_weight(), mbs=po.mbs,
                    fibre=POLYESTER_DEFAULT),
            Segment(length=150.0, ea=ch.ea, w=ch.submerged_weight(), mbs=ch.mbs))
    line = LineDef(name="l", anchor=(-1625.0, 0.0, -300.0), fairlead=(0.0, 0.0, -15.0),
                   segments=segs)
    ms = MooringSystem([line], water_depth=300.0)
    K = ms.stiffness(np.zeros(6))
    h = 0.005
    fp = ms.force(np.array([h, 0, 0, 0, 0, 0]))
    fm = ms.force(np.array([-h, 0, 0, 0, 0, 0]))
    k_fd = -(fp[0] - fm[0]) / (2 * h)
    # the tangent linearisation about the mean tension against the finite difference of the
    # secant (working-curve) solution; measured 1e-7 relative
    assert K[0, 0] == pytest.approx(k_fd, rel=1e-5)
    t = float(ms.tensions(np.zeros(6))["fairlead_tension"][0])
    assert 0.12 * po.mbs < t < 0.2 * po.mbs  # on the curved part of the working curve
    # the polyester segment's equivalent EA is the secant there, between 12 and 14 MBS
    assert 12.0 * po.mbs < ms.seg_EA[1] < 14.0 * po.mbs


def test_no_fibre_system_is_unchanged():
    ms = taut_system(model=None)
    assert not ms.has_fibre
    assert ms.linearised_fibre(np.zeros(6)) is ms
    assert ms.with_fibre_bound("lower") is ms
    # constant EA 15 MBS: T = 15 MBS * 0.02
    assert float(ms.tensions(np.zeros(6))["fairlead_tension"][0]) == pytest.approx(
        0.3 * MBS, rel=1e-9)


def test_secant_iteration_cap_raises(monkeypatch):
    """An iteration that has not converged at the cap is a ConvergenceError naming the fibre
    segments (cap forced to 1 on a weighted segment, which needs several iterations)."""
    import floatmoor.mooring.fibre_system as fsys
    from floatmoor.core.errors import ConvergenceError
    monkeypatch.setattr(fsys, "SECANT_MAX_ITER", 1)
    ms = taut_system(POLYESTER_DEFAULT, dist=1015.0, w=300.0)
    with pytest.raises(ConvergenceError, match="fibre"):
        ms.tensions(np.zeros(6))


def test_bedding_in_after_the_largest_tension():
    """``max_tension_mbs`` 0.4 with the original curve of SIMPLE_OC: permanent strain
    5 % - 3 % = 2 % (hand computation), so the new 1000 m rope is 1020 m long in statics; at a
    chord of 1040.4 m its strain is 2 % on the working curve, T = 25 % MBS."""
    from dataclasses import replace
    oc = replace(SIMPLE, original_strain=(0.0, 0.02, 0.05), original_tension_mbs=(0.0, 0.1, 0.4))
    assert oc.length_factor(MBS) == 1.0  # no largest tension given: the length as given
    bedded = replace(oc, max_tension_mbs=0.4)
    assert bedded.length_factor(MBS) == pytest.approx(1.02)
    ms = taut_system(bedded, length=1000.0, dist=1040.4)
    assert ms.seg_L[0] == pytest.approx(1020.0)
    assert float(ms.tensions(np.zeros(6))["fairlead_tension"][0]) == pytest.approx(
        0.25 * MBS, rel=1e-9)
    # linearised about there: tension unchanged, the segment weight kept
    lin = ms.linearised_fibre(np.zeros(6))
    assert float(lin.tensions(np.zeros(6))["fairlead_tension"][0]) == pytest.approx(
        0.25 * MBS, rel=1e-9)
    with pytest.raises(ValueError, match="original curve"):
        replace(SIMPLE, max_tension_mbs=0.3)
