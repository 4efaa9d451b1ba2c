"""Frequency domain against time domain: one model, two methods.

Both domains assemble the same force models (:func:`floatmoor.forces.select_models`); where the
frequency domain (FD) is exact the time domain (TD) must reproduce it within the sampling error
of its finite records, and where the FD linearises it must agree within the error of the
linearisation.

Sampling error (derived here, used by both tests).  A zero-mean stationary Gaussian process
x(t) with one-sided spectrum S(w) (rad/s) and autocovariance R(tau) = int_0^inf S(w) cos(w tau)
dw, sampled over a window T much longer than its correlation time, has the sample variance
s^2 = (1/T) int_0^T x^2 dt with E[s^2] = R(0) and

    Var[s^2] = (1/T^2) int int 2 R(t - t')^2 dt dt' ~= (2/T) int_-inf^inf R(tau)^2 dtau
             = (2 pi / T) int_0^inf S(w)^2 dw

(the fourth moment of a Gaussian process, E[x1^2 x2^2] = R(0)^2 + 2 R^2, and Parseval's
theorem for the two-sided spectrum S/2); in terms of the statistical bandwidth B_e in Hz the
relative error of the mean-square estimate is 1/sqrt(B_e T) (Bendat & Piersol (2010), ch. 8).
The scenes below have random Rayleigh amplitudes (``random_amplitudes: true``), so the TD
realisation is a Gaussian process of the FD's spectrum (the amplitude scatter gives exactly
the term d_omega int S^2 dw of this variance).  The mean of s^2 over n seeds then has the
standard error sqrt(Var[s^2] / n), with S the FD's own response spectrum: the tests allow
4 standard errors.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.core.errors import FloatmoorWarning

ROOT = Path(__file__).resolve().parents[1]
OC3 = ROOT / "vessels" / "oc3_hywind"
N_SEEDS = 10
TRANSIENT = 600.0


def _scene(tmp_path, name, waves, *, quadratic=None, duration, dt=0.2):
    """The OC3 spar scene (its vessel, with ``quadratic`` as its quadratic damping when
    given) in the sea state ``waves``."""
    vessel = OC3 / "vessel.yaml"
    if quadratic is not None:
        v = yaml.safe_load(vessel.read_text())
        v["database"] = str(OC3 / "database.nc")
        v["quadratic_damping"] = np.asarray(quadratic, float).tolist()
        vessel = tmp_path / f"{name}_vessel.yaml"
        vessel.write_text(yaml.safe_dump(v, sort_keys=False))
    sc = {"name": name, "site": {"water_depth": 320.0, "water_density": 1025.0},
          "vessel": str(vessel), "mooring": str(OC3 / "mooring.yaml"),
          "environment": {"waves": {**waves, "random_amplitudes": True}
                          if "systems" not in waves else waves},
          "analysis": {"duration": TRANSIENT + duration, "dt": dt, "transient": TRANSIENT,
                       "ramp": 100.0}}
    p = tmp_path / f"{name}.yaml"
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    return p


def _td_variances(path, n_seeds):
    """Sample variances (n_seeds, 6) of the motion and (n_seeds, n_lines) of the fairlead
    tensions over the window after the transient, and the window length T (s)."""
    built = floatmoor.build(path)
    motions, ten = [], []
    for seed in range(1, n_seeds + 1):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FloatmoorWarning)
            ds = floatmoor.simulate(built, seed=seed)
        keep = ds["time"].values >= TRANSIENT
        motions.append(np.var(ds["motion"].values[keep], axis=0))
        ten.append(np.var(ds["line_tension"].values[keep], axis=0))
        T = float(ds["time"].values[-1] - TRANSIENT)
    return np.array(motions), np.array(ten), T


def _fd_spectra(res):
    """The FD's WF response spectra (n_w, 6) of the motions and (n_w, n_lines) of the
    fairlead tensions (g . H over the directions, g the tension gradient)."""
    from floatmoor.solvers.frequency_domain import wf_directions
    g = np.nan_to_num(res.tension_gradient)
    st = sum(np.abs(rao @ g.T) ** 2 * S[:, None] for rao, S in wf_directions(res.model,
                                                                           res.solution))
    return res.solution.wf_spectrum, st


def _standard_error(omega, spectra, T, n):
    """Standard error (per column) of the mean over n seeds of the sample variance of a
    Gaussian process of spectrum ``spectra`` (n_w, k) over a window T (module docstring)."""
    var_s2 = 2.0 * math.pi / T * np.trapezoid(spectra ** 2, omega, axis=0)
    return np.sqrt(var_s2 / n)


LINEAR_SEAS = {
    "one_system": {"spectrum": "jonswap", "hs": 2.0, "tp": 10.0, "heading_deg": 30.0},
    "wind_sea_and_swell": {"systems": [
        {"name": "wind_sea", "spectrum": "jonswap", "hs": 1.8, "tp": 9.0, "heading_deg": 0.0},
        {"name": "swell", "spectrum": "jonswap", "hs": 1.0, "tp": 14.0, "gamma": 5.0,
         "heading_deg": 100.0, "spreading": "cos2s", "spreading_s": 8.0, "n_directions": 5}]},
}


@pytest.mark.parametrize("sea", list(LINEAR_SEAS))
def test_linear_scene_td_std_equals_fd_std_within_the_sampling_error(tmp_path, sea):
    """OC3 spar, first-order waves only (JONSWAP Hs 2 m, Tp 10 s, 30 deg; or a wind sea and
    a spread swell from 100 deg: surge, sway, heave, roll and pitch all respond), linear
    damping, radiation memory, catenary lines at small motions: the FD is exact (its linear
    RAOs and tension gradients, the directions' responses added).  The mean over 10 seeds of
    the TD sample variance of every motion and fairlead tension equals the FD variance within
    4 standard errors of the sampling (module docstring)."""
    waves = LINEAR_SEAS[sea]
    if "systems" in waves:
        waves = {**waves, "random_amplitudes": True}
    p = _scene(tmp_path, "linear", waves, duration=3000.0)
    res = floatmoor.frequency_domain_result(p)
    assert set(res.models) == {"hydrostatics", "mooring", "radiation", "damping_linear",
                               "wave1"}  # linear forces only, first-order waves
    assert np.all(res.lf_std < 1e-9 * res.wf_std.max())  # no LF excitation
    motions, ten, T = _td_variances(p, N_SEEDS)
    s_mot, s_ten = _fd_spectra(res)
    for name, td, fd_var, spectra in (("motion", motions, res.wf_std ** 2, s_mot),
                                      ("tension", ten, res.tension_std_wf ** 2, s_ten)):
        se = _standard_error(res.model.omega, spectra, T, N_SEEDS)
        dofs = range(5) if name == "motion" else range(td.shape[1])  # yaw: ~1e-4 deg
        for k in dofs:
            err = abs(td[:, k].mean() - fd_var[k])
            assert err <= 4.0 * se[k], (name, k, td[:, k].mean(), fd_var[k], se[k])
            assert se[k] < 0.05 * fd_var[k]  # the check resolves 5 % of the variance
        # the seeds scatter as the derivation says (its standard deviation within 2x)
        spread = np.std(td[:, list(dofs)], axis=0, ddof=1) / (se[list(dofs)] * math.sqrt(N_SEEDS))
        assert np.all((spread > 0.4) & (spread < 2.5)), (name, spread)


def _linearisation_error() -> float:
    """The relative error of the stochastic linearisation of a quadratic damping in the
    standard deviation, closed form for its worst case: a lightly damped oscillator
    x'' + q x'|x'| + w^2 x = W(t) under white noise of two-sided density S0.

    Linearised (Caughey (1963)): c = sqrt(8/pi) q sigma_v and sigma_v^2 = pi S0 / c, so
    sigma_v,lin^3 = pi S0 / (sqrt(8/pi) q).  Stochastic averaging of the energy
    H = (x'^2 + w^2 x^2)/2 (Roberts & Spanos (1990)): drift pi S0 - q <|x'|^3>_H with
    <|x'|^3>_H = (2H)^(3/2) 4/(3 pi), diffusion 2 pi S0 H, so the stationary density is
    p(H) ~ exp(-k H^(3/2)), k = 16 sqrt(2) q / (9 pi^2 S0), and sigma_v^2 = <H> =
    k^(-2/3) Gamma(4/3)/Gamma(2/3).  The ratio sigma_v,exact / sigma_v,lin is
    sqrt((9 sqrt(pi)/8)^(2/3) Gamma(4/3)/Gamma(2/3)) = 1.0221 for any q, S0, w (x alike): the
    linearisation underestimates by 2.2 %.  With part of the damping linear (radiation) or a
    narrow-band excitation the error is smaller."""
    ratio2 = (9.0 * math.sqrt(math.pi) / 8.0) ** (2.0 / 3.0) * math.gamma(4.0 / 3.0) \
        / math.gamma(2.0 / 3.0)
    return math.sqrt(ratio2) - 1.0


def test_linearisation_error_closed_form():
    """The closed form of :func:`_linearisation_error` (2.21 %) against its terms computed by
    quadrature: <H> of p(H) ~ exp(-k H^1.5) and sigma_v,lin from the linearised balance, for
    q = 2, S0 = 0.3."""
    from scipy.integrate import quad
    q, S0 = 2.0, 0.3
    k = 16.0 * math.sqrt(2.0) * q / (9.0 * math.pi ** 2 * S0)
    num = quad(lambda h: h * math.exp(-k * h ** 1.5), 0, np.inf)[0]
    den = quad(lambda h: math.exp(-k * h ** 1.5), 0, np.inf)[0]
    s_lin = (math.pi * S0 / (math.sqrt(8.0 / math.pi) * q)) ** (1.0 / 3.0)
    assert math.sqrt(num / den) / s_lin - 1.0 == pytest.approx(_linearisation_error(),
                                                                rel=1e-8)
    assert _linearisation_error() == pytest.approx(0.02212, abs=5e-6)


def test_full_quadratic_damping_fd_and_td_agree_within_the_linearisation_error(tmp_path):
    """OC3 spar in swell at its pitch and roll resonance (JONSWAP Hs 3 m, Tp 28 s, 45 deg),
    whose damping there is a full quadratic matrix on roll and pitch, B = b [[1, c], [c, 1]],
    b = 1.5e11 N m s^2, c = 0.9 (dissipative: the power b (|p|^3 + |q|^3) + c b (p q|q| +
    q p|p|) >= 2 (1 - c) b |q|^3 > 0 at the worst ratio p = -q, which the 45 deg waves drive).
    The FD linearises every entry (B_eq = sqrt(8/pi) B diag(sigma)); the TD integrates
    B nu|nu| itself.  Over 10 seeds the TD standard deviations of surge, sway, roll, pitch and
    the tensions equal the FD's within the linearisation's error (closed form, 2.2 %) plus 4
    sampling standard errors, while the FD with the diagonal of B alone (what the FD did
    before) is outside that band: the coupling changes the pitch response by about 40 %."""
    from dataclasses import replace

    from floatmoor.solvers.frequency_domain import response_std_tz, solve_frequency_domain
    b, c = 1.5e11, 0.9
    B = np.zeros((6, 6))
    B[3, 3] = B[4, 4] = b
    B[3, 4] = B[4, 3] = c * b
    p = _scene(tmp_path, "quadratic", {"spectrum": "jonswap", "hs": 3.0, "tp": 28.0,
                                       "heading_deg": 45.0}, quadratic=B, duration=10000.0)
    res = floatmoor.frequency_domain_result(p)
    assert "damping_quadratic" in res.models
    np.testing.assert_array_equal(res.model.quadratic_damping, B)  # the whole matrix
    eq = res.solution.equivalent_damping
    assert eq[3, 4] != 0.0 and eq[4, 3] != 0.0  # the coupling linearised
    diag = solve_frequency_domain(replace(res.model, quadratic_damping=np.diag(np.diag(B))))
    std_diag, _ = response_std_tz(res.model.omega, diag.wf_spectrum)
    motions, ten, T = _td_variances(p, N_SEEDS)
    s_mot, s_ten = _fd_spectra(res)
    e_lin = _linearisation_error()
    for name, td, fd_var, spectra, dofs in (
            ("motion", motions, res.wf_std ** 2, s_mot, (0, 1, 3, 4)),
            ("tension", ten, res.tension_std_wf ** 2, s_ten, range(ten.shape[1]))):
        se = _standard_error(res.model.omega, spectra, T, N_SEEDS)
        for k in dofs:
            ratio = math.sqrt(td[:, k].mean() / fd_var[k])
            tol = e_lin + 4.0 * 0.5 * se[k] / fd_var[k]  # in std: half the relative variance
            assert abs(ratio - 1.0) <= tol, (name, k, ratio, tol)
            if name == "motion" and k in (3, 4):
                ratio_diag = math.sqrt(td[:, k].mean()) / std_diag[k]
                assert abs(ratio_diag - 1.0) > 3.0 * tol, (k, ratio_diag, tol)


def test_iea15_quadratic_damping_is_the_same_in_both_domains(tmp_path):
    """The IEA-15 VolturnUS-S public model (OpenFAST files as published, imported): its full
    AddBQuad, with the -8.92e6 / 8.92e6 N s^2 surge-pitch and sway-roll terms, is the
    quadratic damping of the time domain's term and of the frequency domain's model, and the
    FD linearises every entry on the velocity it multiplies: B_eq = sqrt(8/pi) B diag(sigma_v)
    with sigma_v from the FD's own WF and LF velocity covariances (the off-diagonal entries
    included)."""
    from floatmoor.io.openfast import import_openfast
    from floatmoor.solvers.time_domain import assemble

    from .io.public_models import lay_out
    fst = lay_out("iea15-volturnus-v4", tmp_path / "model")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        res = import_openfast(fst, tmp_path / "out")
        built = floatmoor.build(res.files["scene"])
        a = assemble(built, seed=1, dt=0.1, duration=20.0)
        fd = floatmoor.frequency_domain_result(built)
    Bq = np.asarray(built.vessel.quadratic_damping, float)
    assert Bq[0, 4] == -8.92e6 and Bq[1, 3] == 8.92e6
    np.testing.assert_array_equal(a.asm.damping_quadratic, Bq)
    np.testing.assert_array_equal(fd.model.quadratic_damping, Bq)
    sol = fd.solution
    sigma = np.sqrt(np.diag(sol.wf_velocity_covariance + sol.lf_velocity_covariance))
    expected = math.sqrt(8.0 / math.pi) * Bq * sigma[None, :]
    np.testing.assert_allclose(sol.equivalent_damping, expected, rtol=2e-4,
                               atol=1e-9 * np.abs(expected).max())
    assert sol.equivalent_damping[0, 4] < 0.0 < sol.equivalent_damping[1, 3]
