"""Frequency-domain dynamic line tension (floatmoor.mooring.fe.frequency): drag linearisation,
touchdown springs, natural frequencies and transfer functions against independent results."""

import math

import numpy as np
import pytest

from floatmoor.mooring.catenary import solve_line
from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Seabed
from floatmoor.mooring.fe.drag_linearisation import (
    drag_damping_1d,
    drag_damping_2d,
    mean_abs_gaussian,
)
from floatmoor.mooring.fe.frequency import frequency_response
from floatmoor.mooring.fe.touchdown_springs import LowerPart, least_squares_springs
from floatmoor.mooring.line_types import LineType

from .conftest import oc3_spec


def _jonswap_surge(w, sigma, tp=10.0):
    from floatmoor.metocean.spectra import jonswap
    S = jonswap(w, 1.0, tp)
    S = S / np.trapezoid(S, w) * sigma ** 2
    psd = np.zeros((w.size, 3))
    psd[:, 0] = S
    return psd


# -- drag linearisation --------------------------------------------------------------------------
def test_drag_1d_closed_forms():
    # Borgman: zero mean, E[d(k|u|u)/du] = 2 k E|u| = sqrt(8/pi) k sigma
    assert drag_damping_1d(3.0, 0.0, 0.7) == pytest.approx(math.sqrt(8 / math.pi) * 3.0 * 0.7,
                                                           rel=1e-12)
    # a strong current dominates: 2 k U
    assert drag_damping_1d(3.0, 2.0, 1e-3) == pytest.approx(2 * 3.0 * 2.0, rel=1e-9)
    # E|u| of a Gaussian with mean, against Monte Carlo (1e6 samples: 0.1 % standard error)
    rng = np.random.default_rng(0)
    u = rng.normal(0.4, 0.5, 1_000_000)
    assert mean_abs_gaussian(0.4, 0.5) == pytest.approx(np.abs(u).mean(), rel=3e-3)


def test_drag_single_dof_equivalent_linearisation():
    """A single DOF with quadratic drag under Gaussian velocity: the equivalent damping
    c = E[df/dv] (the least-squares linearisation for Gaussian v) also minimises
    E[(k|v|v - c v)^2]: c = k E[|v| v^2] / E[v^2] = 2 k E|v| (Stein's lemma); checked by
    sampling the least-squares coefficient."""
    rng = np.random.default_rng(1)
    v = rng.normal(0.0, 0.8, 2_000_000)
    k = 5.0
    c_ls = np.mean(k * np.abs(v) * v * v) / np.mean(v * v)
    assert drag_damping_1d(k, 0.0, 0.8) == pytest.approx(c_ls, rel=3e-3)


@pytest.mark.parametrize("mean, cov", [
    ((0.3, -0.2), ((0.5, 0.2), (0.2, 0.1))),
    ((0.0, 0.0), ((1.0, 0.0), (0.0, 1.0))),
    ((1.0, 0.1), ((0.01, 0.0), (0.0, 1e-8))),
    ((0.05, 0.0), ((1.0, 0.99), (0.99, 1.0))),
])
def test_drag_2d_against_monte_carlo(mean, cov):
    rng = np.random.default_rng(2)
    m = np.array(mean)
    S = np.array(cov)
    u = rng.multivariate_normal(m, S, size=1_000_000)
    r = np.linalg.norm(u, axis=1)
    E = r.mean() * np.eye(2) + (u / r[:, None]).T @ u / len(u)
    C = drag_damping_2d(np.array([2.0]), m[None], S[None])[0]
    assert np.allclose(C, 2.0 * E, rtol=0.0, atol=0.01 * np.abs(2.0 * E).max())


def test_drag_2d_rank_one_exact():
    # in-line motion only, no current: E[|u| I + u u^T/|u|] = E|u1| (I + e1 e1^T)
    C = drag_damping_2d(np.array([1.0]), np.zeros((1, 2)), np.array([[[4.0, 0.0], [0.0, 0.0]]]))
    e = 2.0 * math.sqrt(2.0 / math.pi)
    assert np.allclose(C[0], [[2 * e, 0.0], [0.0, e]], rtol=1e-10)


# -- touchdown springs ---------------------------------------------------------------------------
def _oc3_lower_part():
    lt_w = 77.7066 * 9.80665 - 1025.0 * 9.80665 * math.pi * 0.09 ** 2 / 4
    return LowerPart(lengths=np.array([350.0]), ea=np.array([384.243e6]), w=np.array([lt_w]),
                     H0=7.0e5, V0=4.0e4)


def test_least_squares_springs_small_excursion_is_catenary_stiffness():
    """Small-excursion limit: the Ong & Pellegrino springs are the catenary stiffness of the
    lower part (solve_line's analytic inverse Jacobian at the same end point)."""
    part = _oc3_lower_part()
    x, z = part.position(part.H0, part.V0)
    sol = solve_line(x, z, part.lengths, part.ea, part.w)
    assert sol.HF == pytest.approx(part.H0, rel=1e-8)
    assert sol.VF == pytest.approx(part.V0, rel=1e-8)
    K0 = least_squares_springs(part, np.zeros((2, 2)))
    K1 = least_squares_springs(part, np.diag([1e-6 * part.H0, 1e-6 * part.V0]) ** 2)
    for K in (K0, K1):
        assert np.allclose(K, sol.stiffness, rtol=1e-5, atol=1e-5 * np.abs(sol.stiffness).max())


def test_least_squares_springs_beat_the_tangent_over_the_excursion():
    """Over a large excursion of the cut forces (lift-off: V1 of 40 % of V0) the least-squares
    compliance fits the exact catenary positions (sampled independently of the cubic expansion
    used for the fit) better than the tangent: the horizontal error falls by more than 5 %; the
    vertical error, dominated by the quadratic lift-off term that no linear law captures under
    a symmetric excursion, stays the same (within 0.5 %)."""
    part = _oc3_lower_part()
    cov = np.diag([0.05 * part.H0, 0.4 * part.V0]) ** 2
    K_ls = least_squares_springs(part, cov)
    K_t = least_squares_springs(part, np.zeros((2, 2)))
    assert not np.allclose(K_ls, K_t, rtol=1e-2)
    rng = np.random.default_rng(3)
    F = rng.multivariate_normal([0.0, 0.0], cov, size=1000)
    F = F[part.V0 + F[:, 1] > 0.05 * part.V0]
    x0 = part.position(part.H0, part.V0)
    Y = np.array([part.position(part.H0 + h, part.V0 + v) - x0 for h, v in F])
    err_ls = np.mean((Y - F @ np.linalg.inv(K_ls).T) ** 2, axis=0)
    err_t = np.mean((Y - F @ np.linalg.inv(K_t).T) ** 2, axis=0)
    assert err_ls[0] < 0.95 * err_t[0]
    assert err_ls[1] < 1.005 * err_t[1]


# -- taut line: closed-form modes ---------------------------------------------------------------
def _taut_line(n=20, L=100.0, stretch=1.001, ea=1e7, damping=0.0):
    rho = 1025.0
    d = 0.1
    vol = math.pi * d * d / 4
    # neutrally buoyant (no sag), no added mass and no drag
    lt = LineType(name="taut", material="user", diameter=d, mass_per_length=rho * vol,
                  displaced_volume=vol, ea=ea, ea_dynamic=ea, mbs=1e7, cdn=0.0, cdt=0.0,
                  can=0.0, cat=0.0)
    spec = FELineSpec(name="taut", anchor=(0.0, 0.0, -150.0),
                      fairlead=(L * stretch, 0.0, -150.0),
                      segments=(FESegment(line_type=lt, length=L, n_elements=n,
                                          internal_damping=damping),),
                      seabed=Seabed(depth=300.0), water_density=rho)
    line = FELine(spec)
    line.solve_static()
    return line, lt, L, stretch, ea


def test_taut_line_natural_frequencies_closed_form():
    """Lumped-mass string fixed at both ends: omega_k = 2 sqrt(k_e / m_e) sin(k pi / 2N) with
    k_e = T / l (transverse, two planes) and EA / l (axial), m_e = m l (the discrete string,
    e.g. Meirovitch, Elements of Vibration Analysis)."""
    n = 20
    line, lt, L, stretch, ea = _taut_line(n=n)
    w = np.linspace(0.1, 5.0, 50)
    ds = frequency_response(line, w, np.full((w.size, 3), 1e-6), seabed="fe", drag=False,
                            n_modes=12)
    T = ea * (stretch - 1.0)
    le = L * stretch / n
    me = lt.mass_per_length * L / n
    k = np.arange(1, 7)
    wt = 2.0 * np.sqrt(T / le / me) * np.sin(k * math.pi / (2 * n))
    wa = 2.0 * np.sqrt(ea / (L / n) / me) * np.sin(1 * math.pi / (2 * n))
    expected = np.sort(np.concatenate([wt, wt, [wa]]))[:12]
    got = ds.natural_frequency.values
    assert np.allclose(got, expected, rtol=1e-6)
    # and the continuous string within the discretisation error
    assert got[0] == pytest.approx(math.pi / (L * stretch) * math.sqrt(T / lt.mass_per_length
                                                                       * stretch), rel=5e-3)


def test_taut_line_axial_transfer_closed_form():
    """Axial fairlead motion of the taut lumped-mass line: the fairlead tension per unit
    displacement is that of the fixed-free discrete rod, k_e (1 - X_{N-1}) with the
    closed-form discrete wave solution X_i = sin(i theta) / sin(N theta),
    cos(theta) = 1 - omega^2 m_e / (2 k_e)."""
    n = 20
    line, lt, L, _, ea = _taut_line(n=n)
    w = np.linspace(5.0, 60.0, 37)
    ds = frequency_response(line, w, np.full((w.size, 3), 1e-6), seabed="fe", drag=False)
    ke = ea / (L / n)
    me = lt.mass_per_length * L / n
    theta = np.arccos(1.0 - w ** 2 * me / (2 * ke))
    x_last = np.sin((n - 1) * theta) / np.sin(n * theta)
    expected = ke * (1.0 - x_last)
    rao = ds.fairlead_tension_rao.sel(axis="x", complex="re").values
    assert np.allclose(rao, expected, rtol=1e-6)
    assert np.all(np.abs(ds.fairlead_tension_rao.sel(axis="x", complex="im")) < 1e-6 * ke)


def test_linear_limit_peaks_at_natural_frequencies():
    """OC3 line, drag off, light internal damping, tiny motion: every peak of the fairlead
    tension transfer function (surge) lies at a natural frequency of the eigen-analysis with
    the fairlead held (the tension is the dynamic stiffness of the line at its driven end):
    the resonance peaks, those standing out of the background by more than 5 times.
    Touchdown pinned: the ``fe`` seabed has the line's (heavy) seabed dampers."""
    line = FELine(oc3_spec(n=30, damping=-0.002))
    line.solve_static()
    w = np.linspace(0.1, 3.0, 2901)
    ds = frequency_response(line, w, _jonswap_surge(w, 1e-3), seabed="pinned", drag=False,
                            n_modes=30)
    h = np.hypot(ds.fairlead_tension_rao.sel(axis="x", complex="re"),
                 ds.fairlead_tension_rao.sel(axis="x", complex="im")).values
    peaks = np.nonzero((h[1:-1] > h[:-2]) & (h[1:-1] > h[2:]))[0] + 1
    # resonance peaks (the background has gentle local maxima of its own)
    peaks = peaks[h[peaks] > 5.0 * np.median(h)]
    assert peaks.size >= 5
    nat = ds.natural_frequency.values
    for p in peaks:
        assert np.min(np.abs(nat - w[p])) < 2e-3 * w[p] + 1e-3


# -- the OC3 line: behaviour of the models ------------------------------------------------------
@pytest.fixture(scope="module")
def oc3_static():
    line = FELine(oc3_spec(n=50))
    line.solve_static()
    return line


def test_cross_spectrum_input_equals_auto_spectra(oc3_static):
    w = np.linspace(0.2, 2.5, 80)
    psd = _jonswap_surge(w, 0.5)
    psd[:, 2] = 0.3 * psd[:, 0]
    a = frequency_response(oc3_static, w, psd, seabed="pinned")
    full = np.zeros((w.size, 3, 3))
    full[:, [0, 1, 2], [0, 1, 2]] = psd
    b = frequency_response(oc3_static, w, full, seabed="pinned")
    assert float(a.fairlead_tension_std) == pytest.approx(float(b.fairlead_tension_std),
                                                          rel=1e-12)
    assert a.attrs["converged"] == 1


def test_drag_iteration_converges_and_damps(oc3_static):
    w = np.linspace(0.2, 2.5, 120)
    psd = _jonswap_surge(w, 0.5)
    with_drag = frequency_response(oc3_static, w, psd, seabed="fe")
    no_drag = frequency_response(oc3_static, w, psd, seabed="fe", drag=False)
    hist = with_drag.iteration_tension_std.values
    assert with_drag.attrs["converged"] == 1
    assert abs(hist[-1] - hist[-2]) <= 1e-3 * hist[-1]
    assert float(with_drag.fairlead_tension_std) < float(no_drag.fairlead_tension_std)
    ts = with_drag.tension_std.values
    assert np.all(np.isfinite(ts)) and np.all(ts > 0)


def test_linear_scaling_without_drag(oc3_static):
    w = np.linspace(0.2, 2.5, 60)
    a = frequency_response(oc3_static, w, _jonswap_surge(w, 0.1), seabed="spring", drag=False)
    b = frequency_response(oc3_static, w, _jonswap_surge(w, 0.3), seabed="spring", drag=False)
    assert float(b.fairlead_tension_std) == pytest.approx(3 * float(a.fairlead_tension_std),
                                                          rel=1e-10)


def test_bad_input(oc3_static):
    w = np.linspace(0.2, 2.5, 10)
    with pytest.raises(ValueError, match="seabed"):
        frequency_response(oc3_static, w, np.zeros((10, 3)), seabed="sand")
    with pytest.raises(ValueError, match="motion_psd"):
        frequency_response(oc3_static, w, np.zeros((9, 3)))
