"""Double-quadratic velocity-ramp friction (ANSYS 2013, Aqwa eq. 9-62 to 9-65, figure 9.10;
reconstructed form, see floatmoor.mooring.fe.config): the transition function against its
defining properties and hand values, a grounded line dragged on the seabed against the Coulomb
closed form ``mu N x grounded length`` with the unloading branch on a speed decrease, the energy
dissipated per cycle of a harmonic sliding velocity against quadrature of the transition
functions, the full FE line under harmonic sway, the scene option and the no-JIT run."""

import math
import os
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import quad

from floatmoor.core.config import Node
from floatmoor.mooring.fe import FRICTION_MODELS, FELine, FELineSpec, FESegment, Friction, Seabed
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.options import parse_fe_options
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import oc3_spec, oc3_type

DQ = "velocity_ramp_double_quadratic"
MU_A, MU_L = 0.7, 1.0


# ---------------------------------------------------------------------------------------------
# the transition function
# ---------------------------------------------------------------------------------------------
def _f(x, xp=0.0, fp=0.0):
    return K.dq_transition(x, xp, fp)


def test_transition_defining_properties():
    xs = np.linspace(0.0, 1.0, 101)
    # from rest the loading branch is eq. 9-64, 2x - x^2: f(0) = 0, f(1) = 1, f'(1) = 0
    for x in xs:
        f, df = _f(x)
        assert f == pytest.approx(2 * x - x * x, abs=1e-15)
        assert df == pytest.approx(2 - 2 * x, abs=1e-15)
    assert _f(0.0) == (0.0, 2.0)
    assert _f(1.0) == (1.0, 0.0)
    assert _f(3.0, 0.2, 0.36) == (1.0, 0.0)          # full Coulomb beyond the ramp velocity
    # from full sliding (previous speed >= v_R) the unloading branch is x^2: f'(0) = 0
    for x in xs[:-1]:
        f, df = _f(x, 2.5, 1.0)
        assert f == pytest.approx(x * x, abs=1e-15)
        assert df == pytest.approx(2 * x, abs=1e-15)
    # hand values: loading from rest, unloading from 1, unloading from a loading state,
    # loading from an unloading state
    assert _f(0.5)[0] == pytest.approx(0.75, abs=1e-15)
    assert _f(0.5, 1.0, 1.0)[0] == pytest.approx(0.25, abs=1e-15)
    assert _f(0.25, 0.5, 0.75)[0] == pytest.approx(0.75 * 0.25, abs=1e-15)    # 0.75 (1/2)^2
    assert _f(0.75, 0.5, 0.25)[0] == pytest.approx(1 - 0.75 * 0.25, abs=1e-15)  # 1 - 3 (1/4)^2
    # continuity at the anchor, monotone in x, inside the envelope x^2 <= f <= 2x - x^2,
    # slope bounded by 4 (mu N / v_R units)
    rng = np.random.default_rng(7)
    for _ in range(200):
        xp = rng.uniform(0.0, 1.0)
        fp = rng.uniform(xp * xp, xp * (2 - xp))
        assert _f(xp, xp, fp)[0] == pytest.approx(fp, abs=1e-14)
        assert _f(xp * (1 - 1e-12), xp, fp)[0] == pytest.approx(fp, abs=1e-10)
        vals = np.array([_f(x, xp, fp) for x in xs])
        assert np.all(np.diff(vals[:, 0]) >= -1e-15)
        assert np.all(vals[:, 0] >= xs ** 2 - 1e-14)
        assert np.all(vals[:, 0] <= xs * (2 - xs) + 1e-14)
        assert np.all(vals[:, 1] <= 4.0 + 1e-12) and np.all(vals[:, 1] >= 0.0)


# ---------------------------------------------------------------------------------------------
# a grounded line dragged on the seabed (nodal forces of the line kernel)
# ---------------------------------------------------------------------------------------------
L_G = 200.0
N_EL = 20


@pytest.fixture(scope="module")
def grounded():
    """A 200 m OC3 chain lying straight on the seabed (both ends on the seabed at 50 m), in
    static equilibrium: every interior node carries its net weight on the seabed springs."""
    spec = FELineSpec(name="grounded", anchor=(0.0, 0.0, -50.0), fairlead=(L_G, 0.0, -50.0),
                      segments=(FESegment(line_type=oc3_type(), length=L_G, n_elements=N_EL),),
                      seabed=Seabed(depth=50.0),
                      friction=Friction(model=DQ, mu_axial=MU_A, mu_lateral=MU_L))
    line = FELine(spec)
    line.solve_static(friction=False)
    return line


def _friction_force(line, v, fric, fs):
    """Total friction force (N, (3,)) on the nodes at velocity ``v``: nodal forces with the
    friction model minus the same without friction (drag cancels)."""
    out = []
    for code in (fric, K.FR_NONE):
        f = np.zeros((line.n_nodes, 3))
        K.line_forces(line.r, v, fs, line.params(fric=code), False, 0.0, 0.0, f, line.work)
        out.append(f.sum(axis=0))
    return out[0] - out[1]


def _commit(line, v, fric, fs):
    K.friction_commit(line.r, v, line.work.q, fric, fs, line.P, line.S, line.S[K.S_ZC])


def test_grounded_line_dragged_axially_and_lateral_closed_form(grounded):
    """Sliding faster than the ramp velocity: total friction ``mu N`` times the grounded length
    carried by the seabed, ``L - l_e`` (the outer half elements hang on the fixed end nodes),
    opposite to the motion; ``mu_a`` axially, ``mu_l`` laterally."""
    line = grounded
    w = oc3_type().submerged_weight()
    vR = line.S[K.S_VR]
    assert vR == pytest.approx(0.09 / 10.0)      # D / T_z default
    le = L_G / N_EL
    for code in (K.FR_VEL, K.FR_VDQ):
        for k, mu in ((0, MU_A), (1, MU_L)):
            v = np.zeros_like(line.r)
            v[:, k] = 5.0 * vR
            fs = np.zeros((line.n_nodes, K.N_FS))
            F = _friction_force(line, v, code, fs)
            assert F[k] == pytest.approx(-mu * w * (L_G - le), rel=1e-3)
            assert abs(F[1 - k]) < 1e-9 * mu * w * L_G and abs(F[2]) < 1e-9 * w * L_G


def test_speed_reduction_follows_the_unloading_branch(grounded):
    """Axial drag at 2 v_R, then 0.5, 0.25 and 0.75 v_R (each state committed as an accepted
    time step): the double-quadratic ramp gives f = 1, 0.5^2, 0.25 (0.25/0.5)^2 and the
    loading quadratic through the last state; the memoryless ramp gives 2x - x^2 each time."""
    line = grounded
    w = oc3_type().submerged_weight()
    vR = line.S[K.S_VR]
    full = MU_A * w * (L_G - L_G / N_EL)
    x3 = 0.0625
    expect = [(2.0, 1.0, 1.0), (0.5, 0.25, 0.75), (0.25, x3, 0.4375),
              (0.75, 1 - (1 - x3) * ((1 - 0.75) / (1 - 0.25)) ** 2, 0.9375)]
    fs_dq = np.zeros((line.n_nodes, K.N_FS))
    fs_vr = np.zeros((line.n_nodes, K.N_FS))
    for x, f_dq, f_vr in expect:
        v = np.zeros_like(line.r)
        v[:, 0] = x * vR
        assert -_friction_force(line, v, K.FR_VDQ, fs_dq)[0] == pytest.approx(f_dq * full,
                                                                              rel=1e-3)
        assert -_friction_force(line, v, K.FR_VEL, fs_vr)[0] == pytest.approx(f_vr * full,
                                                                              rel=1e-3)
        _commit(line, v, K.FR_VDQ, fs_dq)
        inner = slice(1, line.n_nodes - 1)
        assert np.allclose(fs_dq[inner, K.FS_UPREV], x * vR)
        assert np.allclose(fs_dq[inner, K.FS_FPREV], f_dq)
    # the end nodes are not in contact: their memory stays at rest
    assert fs_dq[0, K.FS_UPREV] == 0.0 and fs_dq[-1, K.FS_FPREV] == 0.0


def test_friction_damping_block_matches_finite_differences(grounded):
    """C = -df/dv of the double-quadratic friction (plus drag) by central differences, on the
    loading and the unloading branch, with unequal axial and lateral coefficients."""
    line = grounded
    vR = line.S[K.S_VR]
    rng = np.random.default_rng(5)
    for scale_prev, scale_now in ((0.3, 0.6), (0.8, 0.4), (0.0, 0.5), (2.0, 0.7)):
        fs = np.zeros((line.n_nodes, K.N_FS))
        d = rng.normal(size=(line.n_nodes, 2))
        d /= np.linalg.norm(d, axis=1)[:, None]
        vp = np.zeros_like(line.r)
        vp[:, 0:2] = scale_prev * vR * d
        _commit(line, vp, K.FR_VDQ, fs)
        v = np.zeros_like(line.r)
        v[:, 0:2] = scale_now * vR * d
        par = line.params(fric=K.FR_VDQ)
        f = np.zeros((line.n_nodes, 3))
        K.line_forces(line.r, v, fs, par, True, 0.0, 1.0, f, line.work)
        Dg = line.work.Dg.copy()
        for i in (3, 10):
            for a in range(2):
                h = 1e-7 * vR
                fpm = []
                for sgn in (1.0, -1.0):
                    vv = v.copy()
                    vv[i, a] += sgn * h
                    K.line_forces(line.r, vv, fs, par, False, 0.0, 0.0, f, line.work)
                    fpm.append(f[i].copy())
                col = -(fpm[0] - fpm[1]) / (2 * h)
                assert np.allclose(col, Dg[i][:, a], rtol=1e-5,
                                   atol=1e-6 * np.abs(Dg[i]).max()), (scale_prev, i, a)


# ---------------------------------------------------------------------------------------------
# energy per cycle of a harmonic sliding velocity
# ---------------------------------------------------------------------------------------------
def _cycle_work_exact(a, model):
    """Work per cycle / (mu N U / omega) for u = U sin(theta), U = a v_R, a >= 1: four quarter
    cycles, each int f(|u| / v_R) |sin theta| dtheta with f = 2x - x^2 below the ramp (and
    for the double quadratic x^2 while the speed falls from full sliding)."""
    th1 = math.asin(1.0 / a)                       # |u| = v_R
    load = quad(lambda t: (2 * a * math.sin(t) - (a * math.sin(t)) ** 2) * math.sin(t),
                0.0, th1)[0]
    unload_vr = load
    unload_dq = quad(lambda t: (a * math.sin(t)) ** 2 * math.sin(t), 0.0, th1)[0]
    sat = 2.0 * math.cos(th1)                      # f = 1 between th1 and pi - th1
    return 2.0 * (load + sat + (unload_dq if model == DQ else unload_vr))


def test_energy_per_cycle_of_harmonic_lateral_sliding(grounded):
    """Lateral sliding velocity U sin(omega t) with U = 2 v_R imposed on the grounded line,
    one accepted step after the other: the dissipated work per cycle is positive, matches the
    quadrature of the transition functions (0.5 % at 2000 steps per cycle), is below the
    Coulomb value 4 mu N U / omega, and the double quadratic dissipates less than the
    memoryless ramp (it unloads along x^2 <= 2x - x^2)."""
    line = grounded
    w = oc3_type().submerged_weight()
    vR = line.S[K.S_VR]
    U, omega = 2.0 * vR, 2 * math.pi / 10.0
    N_tot = w * (L_G - L_G / N_EL)
    works = {}
    for name, code in (("velocity_ramp", K.FR_VEL), (DQ, K.FR_VDQ)):
        fs = np.zeros((line.n_nodes, K.N_FS))
        nstep = 2000
        dt = 2 * math.pi / omega / nstep
        W = 0.0
        for k in range(1, 2 * nstep + 1):
            v = np.zeros_like(line.r)
            v[:, 1] = U * math.sin(omega * k * dt)
            F = _friction_force(line, v, code, fs)
            if k > nstep:                         # second cycle: memory established
                W += -F[1] * v[1, 1] * dt
            _commit(line, v, code, fs)
        works[name] = W
        ref = _cycle_work_exact(2.0, name) * MU_L * N_tot * U / omega
        assert W > 0.0
        assert W == pytest.approx(ref, rel=5e-3)
        assert W < 4 * MU_L * N_tot * U / omega
    assert works[DQ] < works["velocity_ramp"]


# ---------------------------------------------------------------------------------------------
# the full FE line in the time domain
# ---------------------------------------------------------------------------------------------
def test_oc3_line_harmonic_sway_with_the_three_regularisations():
    """Sway 3 m at 15 s (Lu 2012, excitation 2), OC3 line, generalised-alpha at 0.1 s: with each
    regularisation the work per cycle exceeds the frictionless one, the first grounded node
    slides much less, and the three agree within 1 % (the ramp velocity D / T_z = 9 mm/s is far
    below the sliding speeds, so all tend to the same Coulomb limit).  Measured 2026-11-21:
    W = 133141 J without friction, 135895 J velocity_ramp, 135896 J double quadratic, 135707 J
    displacement-velocity ramp."""
    res = {}
    for name in ("none", "velocity_ramp", DQ, "displacement_velocity_ramp"):
        fr = Friction() if name == "none" else Friction(model=name, mu_axial=MU_A,
                                                           mu_lateral=MU_L)
        line = FELine(oc3_spec(n=45, friction=fr))
        s = line.solve_static(friction=False)
        i_td = int(np.nonzero(s.positions[:, 2] < -320.0)[0].max())
        line.start()
        m = HarmonicMotion(amplitude=(0.0, 3.0, 0.0), period=15.0, ramp=15.0)
        ds = run_prescribed(line, m, 60.0, 0.1, track_nodes=(i_td - 1,))
        assert np.all(np.isfinite(ds.fairlead_tension.values))
        sel = ds.time.values > 45.0
        t = ds.time.values[sel]
        v = np.array([m(tt)[1] for tt in t])
        p = -np.sum(ds.fairlead_force.values[sel] * v, axis=1)
        res[name] = (float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(t))),
                     float(np.ptp(ds.node_position.values[sel, 0, 1])))
    for name in ("velocity_ramp", DQ, "displacement_velocity_ramp"):
        assert res[name][0] > res["none"][0] > 0.0
        assert res[name][1] < 0.1 * res["none"][1]
        assert res[name][0] == pytest.approx(res[DQ][0], rel=0.01)


# ---------------------------------------------------------------------------------------------
# scene option and no-JIT
# ---------------------------------------------------------------------------------------------
def test_selectable_from_the_scene():
    assert DQ in FRICTION_MODELS
    o = parse_fe_options(Node({"friction": {"model": DQ, "mu_axial": 0.7, "mu_lateral": 1.0,
                                            "zero_crossing_period": 8.0}},
                              "scene.yaml", "mooring.finite_element"))
    assert o.friction.model == DQ and o.friction.zero_crossing_period == 8.0
    line = FELine(oc3_spec(n=10, friction=o.friction))
    assert line.fric_code == K.FR_VDQ
    assert line.S[K.S_VR] == pytest.approx(0.09 / 8.0)


_NOJIT_CODE = """
from tests.mooring.fe.conftest import oc3_spec
from floatmoor.mooring.fe import FELine, Friction
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed
line = FELine(oc3_spec(n=8, friction=Friction(model="velocity_ramp_double_quadratic",
                                              mu_axial=0.7, mu_lateral=1.0)))
line.solve_static(friction=False)
line.start()
ds = run_prescribed(line, HarmonicMotion(amplitude=(1.0, 2.0, 0.5), period=8.0, ramp=4.0),
                    2.0, 0.2)
print(repr(float(ds.fairlead_tension.values[-1])), repr(float(line.fs[3, 1])))
"""


def test_double_quadratic_runs_without_jit():
    """Plain Python (NUMBA_DISABLE_JIT=1) gives the numbers of the compiled kernels."""
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(__file__))))
    vals = []
    for flag in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=flag)
        out = subprocess.run([sys.executable, "-c", _NOJIT_CODE], env=env, cwd=root,
                             capture_output=True, text=True, check=True)
        vals.append([float(x) for x in out.stdout.strip().splitlines()[-1].split()])
    assert vals[0] == pytest.approx(vals[1], rel=1e-9)

