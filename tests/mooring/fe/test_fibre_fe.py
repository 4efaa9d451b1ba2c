"""FE lines with the fibre-rope (polyester) law of :mod:`floatmoor.mooring.fe.fibre_law`.

The rope: the ``polyester_default`` preset of :mod:`floatmoor.mooring.fibre` (working curve
table, ``EA_d = MBS (11.6 + 0.40 L_m)``, ``L_m`` the mean load in % MBS) on an MBS of 8.5 MN.
Most tests use a neutrally buoyant, straight, taut line (no weight: every element carries the
same tension, the fairlead displacement over the length is the strain), so the expected numbers
are hand computations from the table and the formula.
"""

import math
import os
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Seabed
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.fibre_law import FS_EM
from floatmoor.mooring.fibre import POLYESTER_DEFAULT as PD
from floatmoor.mooring.line_types import LineType

ROOT = Path(__file__).resolve().parents[3]
MBS = 8.5e6
MASS = 22.59          # kg/m


def _type(fibre=PD, *, weight=0.0, ea=14 * MBS, ea_dynamic=20 * MBS):
    """Polyester type; ``weight`` the submerged weight (N/m), 0: neutrally buoyant."""
    vol = (MASS - weight / 9.80665) / 1025.0
    return LineType(name="poly", material="polyester", diameter=0.185, mass_per_length=MASS,
                    displaced_volume=vol, ea=ea, ea_dynamic=ea_dynamic, mbs=MBS, fibre=fibre)


def _taut(strain, *, length=100.0, n=5, fibre=PD, **kw):
    """A horizontal taut line of unstretched ``length`` stretched to ``strain``."""
    spec = FELineSpec(name="taut", anchor=(0.0, 0.0, -100.0),
                      fairlead=(length * (1.0 + strain), 0.0, -100.0),
                      segments=(FESegment(line_type=_type(fibre), length=length, n_elements=n),),
                      seabed=Seabed(depth=200.0))
    return FELine(spec, **kw)


def _hand_working(strain):
    """Working-curve tension (N) by hand from the preset table (linear between its points)."""
    xs = PD.working_strain
    ys = PD.working_tension_mbs
    for k in range(len(xs) - 1):
        if strain <= xs[k + 1]:
            return MBS * (ys[k] + (ys[k + 1] - ys[k]) * (strain - xs[k]) / (xs[k + 1] - xs[k]))
    raise ValueError


def _ea_dyn(mean_tension):
    """``EA_d = MBS (alpha + beta L_m)``, ``L_m = 100 T_m / MBS`` (the preset's formula)."""
    return MBS * (PD.alpha + PD.beta * 100.0 * mean_tension / MBS)


@pytest.mark.parametrize("strain, by_hand", [(0.007, 0.078 * MBS), (0.02, 0.28 * MBS),
                                             (0.045, 0.68 * MBS)])
def test_statics_reproduce_the_working_curve(strain, by_hand):
    """Static equilibrium of a taut weightless line: every element carries the working-curve
    tension at the strain of the fairlead displacement; the hand values from the table:
    0.05 + 0.07 * 2/5 = 0.078, 0.28, (0.60 + 0.76) / 2 = 0.68 MBS."""
    line = _taut(strain)
    sol = line.solve_static(restart=True)
    assert by_hand == pytest.approx(_hand_working(strain), rel=1e-12)
    np.testing.assert_allclose(sol.tensions, by_hand, rtol=1e-9)
    assert sol.fairlead_tension == pytest.approx(by_hand, rel=1e-9)


def test_statics_of_a_heavy_taut_line_match_the_extensible_catenary_with_the_working_curve():
    """A heavy polyester line (submerged weight 50 N/m, 1000 m) pulled taut (about 0.34 MBS)
    between anchor and fairlead: the FE equilibrium against the elastic catenary with the
    working curve's strain, integrated here independently: ``dx/ds = H / T (1 + e(T))``,
    ``dz/ds = V(s) / T (1 + e(T))``, ``V(s) = V_a + w s``, ``e`` the inverse of the working
    curve, solved for the anchor forces (scipy).  The lumped-mass line converges at second
    order in the element length: 40 and 80 elements, Richardson-extrapolated."""
    from scipy.integrate import quad
    from scipy.optimize import fsolve

    w = 50.0
    L = 1000.0
    A = np.array([0.0, 0.0, -300.0])
    F = np.array([985.0, 0.0, -20.0])
    sols = []
    for n in (40, 80):
        spec = FELineSpec(name="sag", anchor=tuple(A), fairlead=tuple(F),
                          segments=(FESegment(line_type=_type(weight=w), length=L,
                                              n_elements=n),),
                          seabed=Seabed(depth=400.0))
        sols.append(FELine(spec).solve_static(restart=True))

    def strain(T):
        return float(PD.static_strain(T, MBS))

    def ends(hv):
        H, V = hv

        def dx(s):
            T = math.hypot(H, V + w * s)
            return H / T * (1.0 + strain(T))

        def dz(s):
            T = math.hypot(H, V + w * s)
            return (V + w * s) / T * (1.0 + strain(T))

        return [quad(dx, 0, L, limit=200, epsabs=1e-11)[0] - (F[0] - A[0]),
                quad(dz, 0, L, limit=200, epsabs=1e-11)[0] - (F[2] - A[2])]

    H, V = fsolve(ends, [2.8e6, 7e5], xtol=1e-13)
    assert 0.3 * MBS < math.hypot(H, V + w * L) < 0.4 * MBS
    for k, ref in ((0, H), (2, V)):
        fe = [s.anchor_force[k] for s in sols]
        assert (4 * fe[1] - fe[0]) / 3 == pytest.approx(ref, rel=1e-7)
        assert fe[1] == pytest.approx(ref, rel=1e-5)


def test_fast_small_stretch_follows_the_dynamic_stiffness_at_the_mean_tension():
    """A harmonic fairlead stretch of 0.05 m at 10 s about a mean strain of 2 % (tau = 300 s:
    omega tau = 188, the mean strain hardly moves): the tension amplitude is
    ``EA_d(T_mean) / L * a`` (formula; inertia of the 100 m line (omega L / c)^2 / 3 ~ 1e-4),
    its mean the working-curve tension; a line with the constant law and ``ea = ea_dynamic =
    EA_d`` gives the same amplitude."""
    eps, L, a, T = 0.02, 100.0, 0.05, 10.0
    Tm = _hand_working(eps)
    amp = {}
    for law in ("two_component", "constant"):
        if law == "two_component":
            line = _taut(eps, length=L)
        else:
            lt = _type(None, ea=_ea_dyn(Tm), ea_dynamic=_ea_dyn(Tm))
            line = FELine(replace(_taut(eps, length=L).spec, segments=(
                FESegment(line_type=lt, length=L, n_elements=5),)))
        line.solve_static(restart=True)
        line.start()
        dt = 0.1
        F = []
        x0 = line.r[-1].copy()
        for k in range(1, 401):
            t = k * dt
            x = x0 + np.array([a * math.sin(2 * math.pi * t / T), 0.0, 0.0])
            v = np.array([a * 2 * math.pi / T * math.cos(2 * math.pi * t / T), 0.0, 0.0])
            F.append(np.linalg.norm(line.step(t, dt, x, v)))
        F = np.array(F[200:])
        amp[law] = 0.5 * (F.max() - F.min())
        if law == "two_component":
            assert F.mean() == pytest.approx(Tm, rel=2e-4)
    expected = _ea_dyn(Tm) / L * a
    assert amp["two_component"] == pytest.approx(expected, rel=3e-3)
    assert amp["two_component"] == pytest.approx(amp["constant"], rel=1e-3)
    # and not the working-curve slope (16 MBS here against 22.8 MBS): the test can fail
    assert abs(amp["two_component"] - 16 * MBS / L * a) > 0.2 * expected


def test_slow_cycle_follows_the_working_curve():
    """A stretch cycle from 1 % to 3 % strain and back over 600 s with tau = 2 s: the mean
    strain lags the strain by about ``tau deps/dt`` (<= 2e-4), so the tension stays on the
    working curve within ``|EA_d - k_w| tau max|deps/dt| + EA_d h max|deps/dt|`` (the lag of
    the filter and of its one-step update, h = 0.5 s); a fast law would leave it by far more."""
    L, tau, dt, P = 100.0, 2.0, 0.5, 600.0
    line = _taut(0.01, length=L, fibre_time_constant=tau)
    line.solve_static(restart=True)
    line.start()
    x0 = line.r[-1].copy()
    rate = 0.02 * math.pi / P             # max deps/dt of eps = 0.02 - 0.01 cos(2 pi t / P)
    worst = 0.0
    for k in range(1, int(P / dt) + 1):
        t = k * dt
        e = 0.02 - 0.01 * math.cos(2 * math.pi * t / P)
        de = 0.01 * 2 * math.pi / P * math.sin(2 * math.pi * t / P)
        F = line.step(t, dt, x0 + np.array([L * (e - 0.01), 0, 0]), np.array([L * de, 0, 0]))
        eps_el = (line.r[-1, 0] - line.r[-2, 0]) / (L / 5) - 1.0
        worst = max(worst, abs(np.linalg.norm(F) - _hand_working(eps_el)))
    kd = _ea_dyn(0.44 * MBS)
    kw = 0.08 / 0.005 * MBS
    bound = (abs(kd - kw) * tau + kd * dt) * rate
    assert worst < bound
    # a law without the filter (the dynamic stiffness from the start strain) would be off by
    # about |EA_d - k_w| times the strain amplitude 0.01 at the ends of the cycle
    assert bound < 0.05 * abs(kd - kw) * 0.01


def test_cycle_at_the_filter_frequency_gives_the_standard_linear_solid_modulus():
    """A small stretch (strain amplitude 2e-4) at omega tau = 1 about 2 % strain: the tension
    follows the complex modulus of the linearised law, ``EA_d - (EA_d - k_w) / (1 + i)`` =
    ``(EA_d + k_w) / 2 + i (EA_d - k_w) / 2`` (module docstring of ``fibre_law``; ``k_w`` = 16
    MBS the working-curve slope, EA_d = 22.8 MBS): 19.7 MBS in amplitude with a 9.9 deg phase
    lead, between the two stiffnesses.  Fitted over the last two of five cycles."""
    L, tau, dt = 100.0, 10.0, 0.1
    w = 1.0 / tau
    A = 2e-4 * L
    line = _taut(0.02, length=L, fibre_time_constant=tau)
    line.solve_static(restart=True)
    line.start()
    x0 = line.r[-1].copy()
    n = int(round(5 * 2 * math.pi / w / dt))
    t = dt * np.arange(1, n + 1)
    F = np.zeros(n)
    for k in range(n):
        s, c = math.sin(w * t[k]), math.cos(w * t[k])
        F[k] = np.linalg.norm(line.step(t[k], dt, x0 + [A * s, 0, 0], [A * w * c, 0, 0]))
    sel = t >= t[-1] - 2 * 2 * math.pi / w
    X = np.column_stack([np.ones(sel.sum()), np.sin(w * t[sel]), np.cos(w * t[sel])])
    _, a, b = np.linalg.lstsq(X, F[sel], rcond=None)[0]
    kd = _ea_dyn(0.28 * MBS)
    kw = 16.0 * MBS
    M = kd - (kd - kw) / (1.0 + 1.0j)
    assert (a + 1j * b) / (A / L) == pytest.approx(M, rel=5e-3)
    assert math.degrees(math.atan2(b, a)) == pytest.approx(9.9, abs=0.3)


def test_reject_restores_the_mean_strain_and_accept_commits_it():
    """The mean strain lives in the line state: a rejected trial leaves no trace (the next
    advance equals that of a line that never made the trial), an accepted one moves the mean
    strain by ``(1 - exp(-dt / tau)) (eps - eps_m)``."""
    a = _taut(0.02, fibre_time_constant=5.0)
    b = _taut(0.02, fibre_time_constant=5.0)
    for ln in (a, b):
        ln.solve_static(restart=True)
        ln.start()
    x0 = a.r[-1].copy()
    a.advance(0.2, 0.2, x0 + [1.0, 0, 0], [5.0, 0, 0])
    a.reject()
    Fa = a.advance(0.2, 0.2, x0 + [0.1, 0, 0], [0.5, 0, 0])
    Fb = b.advance(0.2, 0.2, x0 + [0.1, 0, 0], [0.5, 0, 0])
    np.testing.assert_array_equal(Fa, Fb)
    for x, y in zip(a.bundle.trial, b.bundle.trial):
        np.testing.assert_array_equal(x, y)
    em0 = a.fs[:5, FS_EM].copy()
    np.testing.assert_allclose(em0, 0.02, rtol=1e-9)
    a.accept()
    r = a.r
    eps = np.linalg.norm(np.diff(r, axis=0), axis=1) / 20.0 - 1.0
    np.testing.assert_allclose(a.fs[:5, FS_EM], em0 + (1 - math.exp(-0.2 / 5.0)) * (eps - em0),
                               rtol=1e-12)
    assert np.all(a.fs[:5, FS_EM] > em0)


def test_laws_and_scene_options():
    """``fibre_law`` selects the element laws (the constant law leaves the arrays of a line
    without fibre model: the exact old code path); the scene keys reach FELine."""
    from floatmoor.core.config import Node
    from floatmoor.core.errors import SceneError
    from floatmoor.mooring.fe.options import parse_fe_options

    two = _taut(0.02)
    work = _taut(0.02, fibre_law="working_curve")
    const = _taut(0.02, fibre_law="constant")
    plain = _taut(0.02, fibre=None)
    assert set(two.E_dynamic[:, 5]) == {2.0} and set(two.E_static[:, 5]) == {1.0}
    assert set(work.E_dynamic[:, 5]) == {1.0}
    assert set(_taut(0.02, fibre=PD.lower()).E_dynamic[:, 5]) == {1.0}
    for x, y in ((const.E_static, plain.E_static), (const.E_dynamic, plain.E_dynamic),
                 (const.S, plain.S)):
        np.testing.assert_array_equal(x, y)
    assert plain.S.size == K.N_S and two.S.size > K.N_S
    o = parse_fe_options(Node({"fibre_law": "working_curve", "fibre_time_constant": 120.0},
                              file="s.yaml", path="mooring.finite_element"))
    assert o.line_kw()["fibre_law"] == "working_curve"
    assert o.line_kw()["fibre_time_constant"] == 120.0
    with pytest.raises(SceneError):
        parse_fe_options(Node({"fibre_law": "syrope"}, file="s.yaml",
                              path="mooring.finite_element"))
    with pytest.raises(SceneError):
        parse_fe_options(Node({"fibre_time_constant": 0.0}, file="s.yaml",
                              path="mooring.finite_element"))


def test_frequency_domain_uses_the_dynamic_stiffness_at_the_static_tension():
    """The linearised FE line of a fibre segment: static tension from the working curve,
    axial slope EA_d at it (formula), or the working-curve tangent with dynamic_ea=False."""
    from floatmoor.mooring.fe.frequency import line_statics

    line = _taut(0.02)
    line.solve_static(restart=True)
    st = line_statics(line)
    Tm = 0.28 * MBS
    np.testing.assert_allclose(st.T, Tm, rtol=1e-9)
    np.testing.assert_allclose(st.kax_eps, _ea_dyn(Tm), rtol=1e-9)
    st = line_statics(line, dynamic_ea=False)
    np.testing.assert_allclose(st.kax_eps, 0.08 / 0.005 * MBS, rtol=1e-9)


def test_frequency_response_of_a_taut_fibre_line_has_the_dynamic_stiffness():
    """The FD line (no drag) under a narrow-band fairlead motion along the line at 0.6 rad/s:
    tension std = EA_d(T_mean) / L * motion std (quasi-static in the axial mode, inertia
    (omega L / c)^2 / 3 ~ 1e-4), not the working-curve tangent (16 MBS against 22.8 MBS)."""
    from floatmoor.mooring.fe import frequency_response

    line = _taut(0.02)
    line.solve_static(restart=True)
    w = np.linspace(0.3, 0.9, 61)
    S = np.zeros((w.size, 3))
    S[:, 0] = np.exp(-(((w - 0.6) / 0.05) ** 2))
    ds = frequency_response(line, w, S, seabed="fe", drag=False)
    sx = math.sqrt(np.trapezoid(S[:, 0], w))
    expected = _ea_dyn(0.28 * MBS) / 100.0 * sx
    assert float(ds.fairlead_tension_std) == pytest.approx(expected, rel=1e-3)


_NOJIT = """
import math
import numpy as np
from tests.mooring.fe.test_fibre_fe import _taut
line = _taut(0.02, fibre_time_constant=3.0)
line.solve_static(restart=True)
line.start()
x0 = line.r[-1].copy()
for k in range(1, 6):
    t = 0.2 * k
    F = line.step(t, 0.2, x0 + [0.3 * math.sin(t), 0.1 * t, 0], [0.3 * math.cos(t), 0.1, 0])
print(" ".join(repr(float(x)) for x in list(F) + list(line.fs[:5, 8])))
"""


def test_fibre_law_runs_without_jit():
    """The same steps as plain Python (NUMBA_DISABLE_JIT=1) give the compiled numbers."""
    vals = []
    for flag in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=flag)
        out = subprocess.run([sys.executable, "-c", _NOJIT], env=env, cwd=ROOT,
                             capture_output=True, text=True, check=True)
        vals.append(np.array([float(x) for x in out.stdout.strip().splitlines()[-1].split()]))
    np.testing.assert_allclose(vals[0], vals[1], rtol=1e-12)


def _taut_system(w=50.0, fibre=PD):
    """Two heavy taut polyester lines (1000 m, 50 N/m submerged) from mid-water anchors to
    fairleads on opposite sides of a body (mooring system with the fibre model; the catenary
    statics of :mod:`floatmoor.mooring.fibre_system`)."""
    from floatmoor.mooring import LineDef, MooringSystem, Segment

    c = 1020.0 / math.sqrt(2.0)
    lines = [LineDef(name=f"p{k}", anchor=(s * (c + 10.0), 0.0, -c - 10.0),
                     fairlead=(s * 10.0, 0.0, -10.0),
                     segments=(Segment(length=1000.0, ea=14 * MBS, ea_dynamic=20 * MBS, w=w,
                                       mbs=MBS, mass_per_length=MASS, diameter=0.185,
                                       fibre=fibre),),
                     anchor_on_seabed=False)
             for k, s in enumerate((1.0, -1.0))]
    return MooringSystem(lines, water_depth=2000.0)


def test_fe_statics_agree_with_the_catenary_statics_of_the_fibre_system():
    """The FE lines (50 elements each, working curve) and the quasi-static mooring system
    (elastic catenary with the working curve) give the same restoring force at several poses,
    hence the same mean offset under a given load (measured: 1e-6 apart; the lines are nearly
    straight, so the lumped-mass error is small)."""
    from floatmoor.mooring.fe.body import FEMooring

    ms = _taut_system()
    fm, _ = FEMooring.from_system(ms)
    for pose in ([0.0] * 6, [8.0, 0, 0, 0, 0, 0], [-5.0, 0, 3.0, 0, 0, 0]):
        q_fe = fm.solve_static(np.array(pose))
        q_qs = ms.force(np.array(pose))
        t_qs = ms.tensions(np.array(pose))["fairlead_tension"].values
        for i in range(len(fm.lines)):
            T_fe = np.linalg.norm(fm.line_forces[i])
            assert T_fe == pytest.approx(t_qs[i], rel=1e-5)
        np.testing.assert_allclose(q_fe[[0, 2]], q_qs[[0, 2]], rtol=0,
                                   atol=1e-5 * np.abs(t_qs).max())
    # the stiffness of the static curve: 8 m of surge moves the force by far more than the tol
    assert abs(ms.force(np.array([8.0, 0, 0, 0, 0, 0]))[0]) > 1e4 * 1e-5 * np.abs(t_qs).max()


def test_multi_line_kernel_carries_the_mean_strain_like_the_line_by_line_path():
    """All lines of a body in one numba call (the coupled runs' path, ``multi.body_advance`` /
    ``body_accept``) give bit for bit the forces and mean strains of line-by-line advances,
    with a rejected trial in between."""
    from floatmoor.mooring.fe.body import FEMooring

    ms = _taut_system()
    out = []
    for fast in (True, False):
        fm, _ = FEMooring.from_system(ms, fast=fast)
        fm.solve_static(np.zeros(6))
        fm.start()
        em0 = np.array([ln.fs[:, FS_EM] for ln in fm.lines])
        Q = []
        for k in range(1, 11):
            t = 0.2 * k
            pose = np.array([0.5 * math.sin(t), 0, 0.2 * math.sin(2 * t), 0, 0, 0])
            fm.advance(t, 0.2, pose + 1.0, np.zeros(6))
            for ln in fm.lines:
                ln.reject()
            Q.append(fm.advance(t, 0.2, pose, np.zeros(6)))
            fm.accept()
        out.append((np.array(Q), np.array([ln.fs[:, FS_EM] for ln in fm.lines])))
    np.testing.assert_array_equal(out[0][0], out[1][0])
    np.testing.assert_array_equal(out[0][1], out[1][1])
    assert np.abs(out[0][1] - em0).max() > 1e-8      # the mean strains moved


def test_the_stiffness_bound_of_the_system_reaches_the_fe_lines():
    """``MooringSystem.with_fibre_bound("lower")`` (the scene's ``analysis.fibre_stiffness``):
    the FE lines use the working curve also in dynamics; ``upper``: the two-component law."""
    from floatmoor.mooring.fe.body import FEMooring

    ms = _taut_system()
    for bound, law in (("lower", 1.0), ("upper", 2.0)):
        fm, _ = FEMooring.from_system(ms.with_fibre_bound(bound))
        for ln in fm.lines:
            assert set(ln.E_dynamic[:, 5]) == {law} and set(ln.E_static[:, 5]) == {1.0}


def test_fe_dynamic_stiffness_agrees_with_the_linearised_fibre_system():
    """A small surge oscillation of the body (0.05 m at 30 s) about the static pose: the FE
    lines' force amplitude equals the surge stiffness of the mooring system linearised with the
    dynamic stiffness at the mean tension (``MooringSystem.linearised_fibre``) times the
    amplitude, and differs clearly from the working-curve (static) stiffness.  Line inertia at
    30 s, (omega L / c)^2 / 3 ~ 2e-3, and the filter (omega tau = 63) stay below the 0.5 %
    tolerance (measured -0.19 %)."""
    from floatmoor.mooring.fe.body import FEMooring

    ms = _taut_system()
    fm, _ = FEMooring.from_system(ms)
    p0 = np.zeros(6)
    fm.solve_static(p0)
    fm.start()
    a, T, dt = 0.05, 30.0, 0.2
    Fx = []
    for k in range(1, int(2 * T / dt) + 1):
        t = k * dt
        pose = np.array([a * math.sin(2 * math.pi * t / T), 0, 0, 0, 0, 0])
        vel = np.array([a * 2 * math.pi / T * math.cos(2 * math.pi * t / T), 0, 0, 0, 0, 0])
        Fx.append(fm.advance(t, dt, pose, vel)[0])
        fm.accept()
    Fx = np.array(Fx[int(T / dt):])
    amp = 0.5 * (Fx.max() - Fx.min())
    k_dyn = ms.linearised_fibre(p0).stiffness(p0)[0, 0]
    k_static = ms.stiffness(p0)[0, 0]
    assert amp == pytest.approx(k_dyn * a, rel=5e-3)
    assert abs(k_dyn - k_static) > 0.1 * k_static


def test_bedded_in_fibre_segments_agree_with_the_catenary_statics():
    """A rope that has seen 10 % MBS (``max_tension_mbs``): the FE line lengthens its fibre
    segments by the permanent strain (``FibreModel.length_factor``: the gap between the
    original and the working curve at that tension) with the segment's mass and weight kept, as
    the catenary statics do; both give the same tensions (and lower ones than the new rope)."""
    from floatmoor.mooring.fe.body import FEMooring

    bedded = replace(PD, max_tension_mbs=0.1)
    f = bedded.length_factor(MBS)
    assert f > 1.005
    t = {}
    for name, model in (("new", PD), ("bedded", bedded)):
        ms = _taut_system(fibre=model)
        fm, _ = FEMooring.from_system(ms)
        fm.solve_static(np.zeros(6))
        t[name] = ms.tensions(np.zeros(6))["fairlead_tension"].values
        np.testing.assert_allclose(np.linalg.norm(fm.line_forces, axis=1), t[name], rtol=1e-5)
    ln = fm.lines[0]
    assert ln.s_nodes[-1] == pytest.approx(1000.0 * f, rel=1e-12)
    assert ln.P[:, K.NP_MASS].sum() == pytest.approx(MASS * 1000.0, rel=1e-12)
    assert t["bedded"].max() < 0.6 * t["new"].max()      # 1.22 against 2.40 MN


def _taut_damped(strain, zeta, **kw):
    line = _taut(strain)
    seg = replace(line.spec.segments[0], internal_damping=-zeta)
    return FELine(replace(line.spec, segments=(seg,)), **kw)


def test_fraction_of_critical_damping_uses_the_fibre_dynamic_stiffness():
    """``internal_damping: -zeta`` of a fibre element: zeta x the critical damping
    ``2 sqrt(k m) l`` (config.FESegment.damping_coefficient) of the stiffness the element has
    when the dynamics start: two-component law, EA_d at the static tension (2 % strain: 0.28
    MBS, EA_d = (11.6 + 0.40 x 28) MBS = 22.8 MBS by hand), not the type's ea_dynamic (20
    MBS); working-curve law, the working-curve tangent at 2 % (right derivative, 0.28 -> 0.36
    MBS over 0.5 % strain: 16 MBS)."""
    zeta, le = 0.3, 100.0 / 5
    for law, k_hand in (("two_component", 22.8 * MBS), ("working_curve", 16.0 * MBS)):
        line = _taut_damped(0.02, zeta, fibre_law=law)
        line.solve_static(restart=True)
        line.start()
        b = line.E_dynamic[:, K.EL_B]
        np.testing.assert_allclose(b, zeta * 2.0 * math.sqrt(k_hand * MASS) * le, rtol=1e-6)
    assert k_hand != 20 * MBS


def test_axial_stiffness_limit_caps_the_two_component_law():
    """A limit below EA_d (22.8 MBS at 2 %, see above) caps the dynamic stiffness: a harmonic
    stretch of 0.05 m at 10 s on the 100 m line gives the tension amplitude limit / L x a
    (the formula of test_fast_small_stretch with EA_d replaced by the limit); the statics keep
    the working curve."""
    eps, L, a, T = 0.02, 100.0, 0.05, 10.0
    limit = 15.0 * MBS
    with pytest.warns(Warning, match="axial stiffness limited"):
        line = _taut(eps, length=L, axial_stiffness_limit=limit)
    sol = line.solve_static(restart=True)
    assert sol.fairlead_tension == pytest.approx(_hand_working(eps), rel=1e-9)
    line.start()
    np.testing.assert_allclose(line.fs[:-1, 10], limit)             # FS_KD: EA_d capped
    x0 = line.r[-1].copy()
    F = []
    for k in range(1, 301):
        t = k * 0.1
        x = x0 + np.array([a * math.sin(2 * math.pi * t / T), 0.0, 0.0])
        v = np.array([a * 2 * math.pi / T * math.cos(2 * math.pi * t / T), 0.0, 0.0])
        F.append(np.linalg.norm(line.step(t, 0.1, x, v)))
    F = np.array(F[100:])
    assert 0.5 * (F.max() - F.min()) == pytest.approx(limit / L * a, rel=3e-3)


def test_axial_stiffness_limit_caps_the_working_curve_in_dynamics_only():
    """Working-curve law with a limit of 15 MBS: the dynamic elements use the curve with its
    slopes capped (the preset's slopes above 15 MBS -- 16 MBS from 2 % strain on -- become 15
    MBS), the static elements the curve itself."""
    from floatmoor.mooring.fe.fibre_law import EL_FIB, working_tension
    limit = 15.0 * MBS
    with pytest.warns(Warning, match="axial stiffness limited"):
        line = _taut(0.02, fibre_law="working_curve", axial_stiffness_limit=limit)
    xs, ys = np.array(PD.working_strain), np.array(PD.working_tension_mbs) * MBS
    o_st, o_dy = int(line.E_static[0, EL_FIB]), int(line.E_dynamic[0, EL_FIB])
    assert o_st != o_dy
    for e in (0.003, 0.007, 0.012, 0.027, 0.045):
        k = np.searchsorted(xs, e, side="right") - 1
        slope = (ys[k + 1] - ys[k]) / (xs[k + 1] - xs[k])
        assert working_tension(line.S, o_st, e)[1] == pytest.approx(slope, rel=1e-12)
        assert working_tension(line.S, o_dy, e)[1] == pytest.approx(min(slope, limit), rel=1e-12)
    assert working_tension(line.S, o_st, 0.025)[0] == pytest.approx(_hand_working(0.025))
    # no limit below the fibre stiffness: no warning, one record shared by statics and dynamics
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        line2 = _taut(0.02, fibre_law="working_curve", axial_stiffness_limit=1e12)
    assert int(line2.E_static[0, EL_FIB]) == int(line2.E_dynamic[0, EL_FIB])


def test_frequency_domain_damping_and_limit_follow_the_time_domain_rule():
    """The linearised line uses the same fibre stiffness and -zeta damping as the time domain:
    B = zeta 2 sqrt(k m) l with k = EA_d(0.28 MBS) = 22.8 MBS (see the damping test above), and
    with a limit of 15 MBS the capped stiffness (working-curve law: 16 -> 15 MBS at 2 %)."""
    from floatmoor.mooring.fe.frequency import line_statics
    zeta, le = 0.3, 100.0 / 5
    line = _taut_damped(0.02, zeta)
    line.solve_static(restart=True)
    st = line_statics(line)
    np.testing.assert_allclose(st.B, zeta * 2.0 * math.sqrt(22.8 * MBS * MASS) * le, rtol=1e-6)
    line.start()
    np.testing.assert_allclose(st.B, line.E_dynamic[:, K.EL_B], rtol=1e-12)
    with pytest.warns(Warning, match="axial stiffness limited"):
        capped = _taut(0.02, fibre_law="working_curve", axial_stiffness_limit=15.0 * MBS)
    capped.solve_static(restart=True)
    np.testing.assert_allclose(line_statics(capped).kax_eps, 15.0 * MBS, rtol=1e-12)
