"""Frequency-domain numerics against closed forms and independent quadrature.

Expected values come from:
* linear oscillator m x'' + c x' + k x = f under one-sided white noise S0 (rad/s):
  sigma_x^2 = pi S0 / (2 c k), sigma_v^2 = pi S0 / (2 c m), Tz = 2 pi sqrt(m/k)
  (e.g. Newland, "Random Vibrations", ch. 7; the integral int_0^inf |H|^2 dw = pi / (2 c k));
* JONSWAP-driven oscillator: scipy.integrate.quad of |H|^2 S (adaptive, independent of our grid);
* Newman's drift spectrum (eq. 2.38) of a Gaussian-shaped wave spectrum S = a exp(-(w-w0)^2/2s^2)
  with a constant drift coefficient C: S_F(mu) = 8 C^2 a^2 sqrt(pi) s exp(-mu^2 / 4 s^2);
* stochastic linearisation of B_q v|v| under white noise: B_eq = sqrt(8/pi) sigma_v B_q with
  sigma_v^2 = pi S0 / (2 B_eq m), i.e. sigma_v^3 = pi S0 / (2 m sqrt(8/pi) B_q).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from floatmoor.core.errors import ConvergenceError
from floatmoor.metocean.spectra import jonswap
from floatmoor.solvers.frequency_domain import (
    SQRT_8_OVER_PI,
    FDModel,
    equivalent_quadratic_damping,
    gust_force_spectrum,
    lf_transfer,
    mean_drift_force,
    newman_drift_spectrum,
    qtf_drift_spectrum,
    response_cross_spectrum,
    response_std_tz,
    solve_frequency_domain,
    wave_frequency_rao,
)


def _sdof_matrices(m, c, k):
    """6x6 system: surge is the oscillator, the other DOFs unit mass/stiffness, unexcited."""
    M = np.eye(6)
    B = np.eye(6) * 0.1
    K = np.eye(6)
    M[0, 0], B[0, 0], K[0, 0] = m, c, k
    return M, B, K


def _wide_grid():
    # fine near the resonance, geometric tail to 1e4 rad/s (the white-noise tail beyond is
    # S0 / (3 m^2 W^3) for the displacement: negligible)
    return np.unique(np.concatenate([np.linspace(0.0, 5.0, 20001), np.geomspace(5.0, 1e4, 3000)]))


def test_white_noise_oscillator_std_and_tz():
    m, c, k, S0 = 2.0e6, 3.0e5, 8.0e5, 1.7
    w = _wide_grid()
    M, B, K = _sdof_matrices(m, c, k)
    X = np.zeros((w.size, 6), complex)
    X[:, 0] = 1.0  # unit force per unit "amplitude": the force spectrum is S0
    H = wave_frequency_rao(w, M, np.zeros((6, 6)), B, K, X)
    std, tz = response_std_tz(w, np.abs(H[:, 0]) ** 2 * S0)
    assert std == pytest.approx(math.sqrt(math.pi * S0 / (2 * c * k)), rel=5e-3)
    assert tz == pytest.approx(2 * math.pi * math.sqrt(m / k), rel=5e-3)


@pytest.mark.parametrize("wn, zeta", [(0.4, 0.05), (0.7, 0.02), (1.2, 0.3)])
def test_jonswap_oscillator_std_against_quad(wn, zeta):
    hs, tp, gamma = 8.0, 11.0, 3.3
    m = 1.0e7
    k = m * wn ** 2
    c = 2 * zeta * math.sqrt(k * m)
    # excitation k per metre of wave amplitude: a static RAO of 1
    w = np.linspace(0.1, 3.0, 581)  # the API's default step 0.005 rad/s
    M, B, K = _sdof_matrices(m, c, k)
    X = np.zeros((w.size, 6), complex)
    X[:, 0] = k
    H = wave_frequency_rao(w, M, np.zeros((6, 6)), B, K, X)
    std, _ = response_std_tz(w, np.abs(H[:, 0]) ** 2 * jonswap(w, hs, tp, gamma))

    def f(x):
        h2 = k ** 2 / ((k - m * x * x) ** 2 + (c * x) ** 2)
        return h2 * float(jonswap(np.array([x]), hs, tp, gamma)[0])
    ref, _ = integrate.quad(f, 0.1, 3.0, points=[wn, 2 * math.pi / tp], limit=400,
                            epsabs=0, epsrel=1e-10)
    assert std == pytest.approx(math.sqrt(ref), rel=5e-3)


def test_rao_phase_convention_quasi_static_limit():
    # far below resonance x = F / k in phase with the force (exp(+i w t)): H -> X / k
    M, B, K = _sdof_matrices(1.0, 0.1, 4.0)
    w = np.array([1e-4])
    X = np.zeros((1, 6), complex)
    X[0, 0] = 2.0 + 1.0j
    H = wave_frequency_rao(w, M, np.zeros((6, 6)), B, K, X)
    assert H[0, 0] == pytest.approx((2.0 + 1.0j) / 4.0, rel=1e-4)
    # at resonance the response lags the force by 90 deg: H = X / (i w c)
    w = np.array([2.0])
    H = wave_frequency_rao(w, M, np.zeros((6, 6)), B, K, X)
    assert H[0, 0] == pytest.approx((2.0 + 1.0j) / (1j * 2.0 * 0.1), rel=1e-9)


def _gauss(w, a, w0, s):
    return a * np.exp(-((w - w0) ** 2) / (2 * s * s))


def test_newman_drift_spectrum_closed_form_and_mean():
    a, w0, s, C = 3.0, 0.6, 0.05, 2.0e4
    w = np.linspace(0.2, 1.0, 3201)
    S = _gauss(w, a, w0, s)
    coeff = np.zeros((w.size, 6))
    coeff[:, 0] = C
    coeff[:, 1] = -0.5 * C  # a second DOF: cross-spectrum = -0.5 x the auto-spectrum
    mu = np.linspace(0.0, 0.2, 41)
    SF = newman_drift_spectrum(w, S, coeff, mu)
    ref = 8 * C ** 2 * a ** 2 * math.sqrt(math.pi) * s * np.exp(-mu ** 2 / (4 * s * s))
    # the closed form holds while C is constant over w + mu/2 (inside the grid)
    inside = mu < 0.15
    np.testing.assert_allclose(SF[inside, 0, 0], ref[inside], rtol=1e-3)
    np.testing.assert_allclose(SF[inside, 0, 1], -0.5 * ref[inside], rtol=1e-3)
    np.testing.assert_allclose(SF[inside, 1, 1], 0.25 * ref[inside], rtol=1e-3)
    # mean drift 2 C m0, m0 = a s sqrt(2 pi)
    F = mean_drift_force(w, S, coeff)
    assert F[0] == pytest.approx(2 * C * a * s * math.sqrt(2 * math.pi), rel=1e-6)


def test_qtf_with_newman_qtf_equals_newman():
    w = np.linspace(0.2, 1.2, 401)
    S = jonswap(w, 6.0, 9.0, 2.0)
    coeff = np.zeros((w.size, 6))
    coeff[:, 0] = 1e4 * (w / 0.7) ** 2
    coeff[:, 4] = -3e5 * w
    mu = np.linspace(0.0, 0.3, 31)

    def qtf(w1, w2):
        mid = 0.5 * (w1 + w2)
        return np.column_stack([np.interp(mid, w, coeff[:, j], right=0.0) for j in range(6)])
    np.testing.assert_allclose(qtf_drift_spectrum(w, S, qtf, mu),
                               newman_drift_spectrum(w, S, coeff, mu), rtol=1e-10, atol=1e-6)


def test_lf_surge_only_against_direct_integration():
    """Surge-only LF system driven by a known drift-force spectrum (Newman, Gaussian sea):
    our chain newman -> lf_transfer -> cross-spectrum -> std against scipy quad of the closed
    form |H|^2 S_F."""
    a, w0, s, C = 4.0, 0.45, 0.04, 3.0e4
    m, c, k = 5.0e7, 1.5e6, 3.0e5
    cutoff = 2 * math.pi / 30.0
    w = np.linspace(0.1, 0.8, 2801)
    S = _gauss(w, a, w0, s)
    coeff = np.zeros((w.size, 6))
    coeff[:, 0] = C
    mu = np.linspace(0.0, cutoff, 1200)
    SF = newman_drift_spectrum(w, S, coeff, mu)
    M = np.zeros((6, 6))
    M[0, 0] = m
    B = np.zeros((6, 6))
    B[0, 0] = c
    K = np.diag([k, 1e6, 1e6, 1e9, 1e9, 1e9])
    Sx = response_cross_spectrum(lf_transfer(mu, M, B, K), SF)
    std, tz = response_std_tz(mu, np.real(Sx[:, 0, 0]))

    def integrand(x, n):
        sf = 8 * C ** 2 * a ** 2 * math.sqrt(math.pi) * s * math.exp(-x * x / (4 * s * s))
        return x ** n * sf / ((k - m * x * x) ** 2 + (c * x) ** 2)
    m0 = integrate.quad(integrand, 0.0, cutoff, args=(0,), limit=200, epsrel=1e-10)[0]
    m2 = integrate.quad(integrand, 0.0, cutoff, args=(2,), limit=200, epsrel=1e-10)[0]
    assert std == pytest.approx(math.sqrt(m0), rel=2e-3)
    assert tz == pytest.approx(2 * math.pi * math.sqrt(m0 / m2), rel=2e-3)


def test_gust_force_spectrum_is_rank_one():
    b = np.array([2.0, 0.0, 0.0, 0.0, 50.0, 0.0])
    su = np.array([1.0, 2.0])
    SF = gust_force_spectrum(b, su)
    assert SF[1, 0, 0] == pytest.approx(8.0)
    assert SF[1, 0, 4] == pytest.approx(200.0)
    assert np.linalg.matrix_rank(SF[0]) == 1


def test_equivalent_quadratic_damping_formula():
    Bq = np.diag([4.0e5, 0, 0, 0, 0, 2.0e9])
    sv = np.array([0.3, 1, 1, 1, 1, 0.01])
    Beq = equivalent_quadratic_damping(Bq, sv)
    assert Beq[0, 0] == pytest.approx(math.sqrt(8 / math.pi) * 0.3 * 4.0e5)
    assert Beq[5, 5] == pytest.approx(math.sqrt(8 / math.pi) * 0.01 * 2.0e9)
    assert Beq[1, 1] == 0.0 and Beq[0, 5] == 0.0


def _white_noise_model(m, k, bq, S0, b_lin=0.0):
    w = _wide_grid()
    M, B, K = _sdof_matrices(m, b_lin, k)
    Bq = np.zeros((6, 6))
    Bq[0, 0] = bq
    X = np.zeros((w.size, 6), complex)
    X[:, 0] = 1.0
    mu = np.linspace(0.0, 0.2, 60)
    return FDModel(omega=w, wave_spectrum=np.full(w.size, S0), mass=M,
                   added_mass=np.zeros((w.size, 6, 6)), radiation_damping=np.zeros((w.size, 6, 6)),
                   excitation=X, stiffness=K, linear_damping=B, quadratic_damping=Bq,
                   lf_added_mass=np.zeros((6, 6)), mu=mu, lf_force_spectrum=np.zeros((60, 6, 6)),
                   tol=1e-7)


def test_stochastic_linearisation_closed_form():
    m, k, bq, S0 = 1.0, 1.0, 0.6, 0.05
    sol = solve_frequency_domain(_white_noise_model(m, k, bq, S0))
    sigma_v = (math.pi * S0 / (2 * m * SQRT_8_OVER_PI * bq)) ** (1.0 / 3.0)
    beq = SQRT_8_OVER_PI * sigma_v * bq
    assert sol.iterations > 3
    assert sol.equivalent_damping[0, 0] == pytest.approx(beq, rel=5e-3)
    assert math.sqrt(sol.wf_velocity_covariance[0, 0]) == pytest.approx(sigma_v, rel=5e-3)
    assert math.sqrt(sol.wf_covariance[0, 0]) == pytest.approx(
        math.sqrt(math.pi * S0 / (2 * beq * k)), rel=5e-3)


def test_stochastic_linearisation_reports_non_convergence():
    model = _white_noise_model(1.0, 1.0, 0.6, 0.05)
    from dataclasses import replace
    with pytest.raises(ConvergenceError, match="stochastic linearisation"):
        solve_frequency_domain(replace(model, max_iter=2, tol=1e-12))


def test_no_quadratic_damping_single_pass_and_lf_mass_only_horizontal():
    model = _white_noise_model(1.0, 1.0, 0.0, 0.05, b_lin=0.2)
    from dataclasses import replace
    model = replace(model, lf_added_mass=np.full((6, 6), 0.5))
    sol = solve_frequency_domain(model)
    assert sol.iterations == 1
    hz = [0, 1, 5]
    vert = [2, 3, 4]
    assert np.all(sol.lf_mass[np.ix_(vert, vert)] == 0.0)
    assert sol.lf_mass[0, 0] == pytest.approx(1.5)
    assert sol.lf_mass[np.ix_(hz, hz)][0, 2] == pytest.approx(0.5)


def test_aranha_drift_damping_constant_coefficient():
    """Constant C: b = 2 int S (w/g) 4 C dw = 8 C m1 / g, m1 = a s sqrt(2 pi) w0 for the
    Gaussian-shaped spectrum (its tails are negligible on the grid)."""
    from floatmoor.solvers.frequency_domain import aranha_drift_damping
    a, w0, s, C, g = 2.0, 0.6, 0.05, 1.0e4, 9.80665
    w = np.linspace(0.2, 1.0, 4001)
    B = aranha_drift_damping(w, _gauss(w, a, w0, s), np.full(w.size, C), g, math.pi / 2)
    b = 8 * C * a * s * math.sqrt(2 * math.pi) * w0 / g
    assert B[1, 1] == pytest.approx(b, rel=1e-6)  # waves along +y: sway only
    assert abs(B[0, 0]) < 1e-9 * b and abs(B[0, 1]) < 1e-9 * b
