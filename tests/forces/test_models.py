"""Force models: registry, closed forms, FFT series, and the kernel against the models' force."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.errors import SceneError
from floatmoor.forces import REGISTRY, model_class
from floatmoor.forces.kernels import relative_flow_force_into, table_at_into
from floatmoor.forces.series import complex_envelope, grid_for
from floatmoor.io.build import build
from floatmoor.io.scene import load_scene
from floatmoor.solvers.time_domain import assemble, integrate

ROOT = Path(__file__).resolve().parents[2]
FL = ROOT / "vessels" / "floatel_like"


def test_unknown_model_name_lists_the_registry():
    with pytest.raises(SceneError, match="mooring") as err:
        model_class("windd")
    for name in ("wave1", "drift_newman", "wind", "current", "radiation"):
        assert name in REGISTRY and name in str(err.value)


def test_fft_sum_equals_direct_sum():
    """A sum on an FFT grid equals the direct cosine sum (round-off)."""
    h = 0.05
    grid = grid_for(0.3, 2 * math.pi / 100.0, h, 100.0)
    rng = np.random.default_rng(0)
    m = np.arange(0, 40)
    w = grid.w0 + m * grid.dw
    c = rng.normal(size=40) + 1j * rng.normal(size=40)
    n = 2500  # longer than the repeat period: wraps around
    fast = complex_envelope(w, c[:, None], n, h, grid)[:, 0]
    t = np.arange(n) * h
    direct = (c[None, :] * np.exp(1j * w[None, :] * t[:, None])).sum(1)
    assert np.max(np.abs(fast - direct)) < 1e-9 * np.abs(c).sum()


def test_table_interpolation_periodic():
    th = np.radians(np.arange(0, 360, 30.0))
    tab = np.stack([np.cos(th)] * 6, 1)
    out = np.zeros(6)
    table_at_into(math.radians(345.0), th, tab, out)  # between 330 and 360 = 0
    assert out[0] == pytest.approx(0.5 * (math.cos(math.radians(330)) + 1.0))
    table_at_into(math.radians(-15.0), th, tab, out)
    assert out[0] == pytest.approx(0.5 * (math.cos(math.radians(330)) + 1.0))


def test_relative_flow_force_closed_form():
    """Wang (2016) eq. 2.24/2.26: F = C (U - x')^2 along the flow; its derivative in x' is the
    flow damping -2 C (U - x'); turning the body by yaw turns the relative heading."""
    th = np.radians(np.arange(0, 360, 30.0))
    C0 = 1500.0
    tab = np.zeros((12, 6))
    tab[:, 0] = C0 * np.cos(th) * np.abs(np.cos(th))
    tab[:, 1] = C0 * np.sin(th) * np.abs(np.sin(th))
    coef = np.zeros(6)
    out = np.zeros(6)
    U, vx = 30.0, 0.7
    relative_flow_force_into(U, 0.0, vx, 0.0, 0.0, 1.0, th, tab, coef, out)
    assert out[0] == pytest.approx(C0 * (U - vx) ** 2)
    # damping: -dF/dx' = 2 C (U - x')
    eps = 1e-4
    fp = np.zeros(6)
    fm = np.zeros(6)
    relative_flow_force_into(U, 0.0, vx + eps, 0.0, 0.0, 1.0, th, tab, coef, fp)
    relative_flow_force_into(U, 0.0, vx - eps, 0.0, 0.0, 1.0, th, tab, coef, fm)
    assert -(fp[0] - fm[0]) / (2 * eps) == pytest.approx(2 * C0 * (U - vx), rel=1e-8)
    # body yawed by 90 deg, flow along +x: relative heading -90 deg (body -y), force along
    # earth +x with the sway coefficient
    out = np.zeros(6)
    relative_flow_force_into(U, 0.0, 0.0, 0.0, math.pi / 2, 1.0, th, tab, coef, out)
    assert out[0] == pytest.approx(C0 * U ** 2) and abs(out[1]) < 1e-6 * C0 * U ** 2


@pytest.fixture(scope="module")
def floatel(tmp_path_factory):
    assert (FL / "database.nc").is_file(), "the shipped floatel_like database is missing"
    p = tmp_path_factory.mktemp("fl") / "s.yaml"
    p.write_text(f"name: fl\nsite: {{water_depth: 150.0}}\nvessel: {FL / 'vessel.yaml'}\n"
                 f"mooring: {FL / 'mooring.yaml'}\nenvironment: {ROOT / 'metocean' / 'heidrun_100yr.yaml'}\n")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return build(load_scene(p))


def test_kernel_forces_equal_model_forces(floatel):
    """The numba loop's per-model forces at recorded steps equal each model's Python
    ``force`` at the same (t, pose, velocity) (radiation: with the same velocity history), also
    with the body turned 0.6 rad in yaw (the damping, radiation and hydrostatic terms act in the
    yaw-following frame, the wind and current at the relative heading)."""
    from floatmoor.forces.kernels import to_yaw_frame

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a0 = assemble(floatel, seed=2, dt=0.2, duration=120.0, ramp=30.0)
        for yaw in (0.0, 0.6):
            start = a0.x0.copy()
            start[5] += yaw
            a = assemble(floatel, seed=2, dt=0.2, duration=120.0, ramp=30.0,
                         start_pose=start if yaw else None)
            r = integrate(a, built=floatel, record_forces=True)
            assert a.wf_velocity is not None and a.wf_velocity.shape == (2 * r.time.size - 1, 6)
            assert r.force_models == ["hydrostatics", "mooring", "radiation", "damping_linear",
                                      "wind", "current", "wave1", "drift_newman"]
            nu = np.array([to_yaw_frame(r.velocity[n], r.motion[n, 5])
                           for n in range(r.time.size)])
            for n in (0, 37, 412, 600):
                t = r.time[n]
                for q, name in enumerate(r.force_models):
                    m = a.models[name]
                    out = np.zeros(6)
                    if name == "radiation":
                        m.force(t, r.motion[n], r.velocity[n], out,
                                history=nu[n - 1::-1] if n > 0 else None)
                    elif name in ("wind", "current"):
                        # relative to the low-frequency velocity: the solver's linear WF
                        # velocity at this step (sample 2 n of the half-step series) removed
                        m.force(t, r.motion[n], r.velocity[n], out,
                                wf_velocity=a.wf_velocity[2 * n])
                    else:
                        m.force(t, r.motion[n], r.velocity[n], out)
                    scale = max(np.abs(out).max(), 1.0)
                    assert np.allclose(r.forces[n, q], out, rtol=1e-9, atol=1e-9 * scale), \
                        (name, n, yaw)
            if yaw:  # the body is turned at the compared steps (step 37, t = 7.4 s; the yaw
                #        damping of the vessel, 27 % of critical, brings it back by t = 120 s)
                assert abs(r.motion[37, 5]) > 0.1


def test_newman_mean_and_ramp(floatel):
    """Newman drift: its time mean over the repeat period is sum a_k^2 D_k (the mean drift of
    the realised spectrum); the first-order force starts from zero under the ramp."""
    a = assemble(floatel, seed=5, dt=0.5, duration=2000.0, ramp=0.0)
    drift = a.models["drift_newman"]
    n_per = a.waves.grid.N  # samples in one repeat period
    s = drift.series
    assert s.shape[0] >= n_per
    assert s[:n_per, 0].mean() == pytest.approx(drift.mean_force()[0], rel=1e-9)
    assert drift.mean_force()[0] > 0.0  # drift pushes the semi along the waves (+x)
    a2 = assemble(floatel, seed=5, dt=0.5, duration=2000.0, ramp=100.0)
    assert np.all(a2.models["wave1"].series[0] == 0.0)
    assert np.array_equal(a2.models["wave1"].series[400:], a.models["wave1"].series[400:])
    assert np.allclose(a2.models["drift_newman"].series[0], drift.mean_force())


OC4 = ROOT / "vessels" / "oc4_semi"


@pytest.fixture(scope="module")
def oc4(tmp_path_factory):
    assert (OC4 / "database.nc").is_file(), "the shipped oc4_semi database is missing"
    p = tmp_path_factory.mktemp("oc4") / "s.yaml"
    p.write_text(f"name: oc4\nsite: {{water_depth: 200.0}}\nvessel: {OC4 / 'vessel.yaml'}\n"
                 "environment:\n  waves: {spectrum: jonswap, hs: 4.0, tp: 8.0, "
                 "discretisation: {omega_min: 0.4, omega_max: 2.8}}\n")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return build(load_scene(p))


def test_qtf_drift_with_newman_qtf_equals_newman(oc4):
    """The full-QTF model fed with Newman's QTF Q(w1, w2) = (D(w1) + D(w2))/2 (D the database's
    mean drift) reproduces the Newman model's series (all wave components inside the QTF's
    frequency range, where both definitions agree); with the database's own QTF its mean is
    sum a^2 Q(w, w) and it is the default drift model of a database with a QTF."""
    from dataclasses import replace

    from floatmoor.forces import select_models

    assert "drift_qtf" in select_models(oc4) and "drift_newman" not in select_models(oc4)
    db = oc4.vessel.database
    qw = db["qtf_omega"].values
    D = db["mean_drift_force"].sel(wave_direction=0.0).values  # (omega, dof)
    D = np.nan_to_num(D)
    Dq = np.stack([np.interp(qw, db["omega"].values, D[:, d]) for d in range(6)], 1)
    Qn = 0.5 * (Dq[:, None, :] + Dq[None, :, :])
    q = db["difference_frequency_qtf"].copy(data=Qn[:, :, None, :].astype(complex))
    db2 = db.assign(difference_frequency_qtf=q)
    # Newman on the same D restricted to the QTF grid (zero below it, as the QTF model)
    md = db["mean_drift_force"].copy(data=np.where(
        (db["omega"].values >= qw[0] - 1e-9)[:, None, None], np.nan_to_num(db["mean_drift_force"].values), 0.0))
    db2 = db2.assign(mean_drift_force=md)
    b2 = replace(oc4, vessel=replace(oc4.vessel, database=db2))
    kw = dict(seed=4, dt=0.2, duration=1500.0)
    aq = assemble(b2, models=["hydrostatics", "drift_qtf"], **kw)
    an = assemble(b2, models=["hydrostatics", "drift_newman"], **kw)
    sq = aq.models["drift_qtf"].series
    sn = an.models["drift_newman"].series
    for d in (0, 2, 4):
        scale = np.abs(sn[:, d]).max()
        assert np.max(np.abs(sq[:, d] - sn[:, d])) < 2e-3 * scale, d
    # database QTF: mean drift = sum a^2 Q(w, w)
    a = assemble(oc4, models=["hydrostatics", "drift_qtf"], **kw)
    m = a.models["drift_qtf"]
    r = a.waves.realisation
    Qdiag = np.array([np.interp(r.omega, qw, np.real(np.diagonal(
        db["difference_frequency_qtf"].isel(qtf_wave_direction=0).values[:, :, d])),
        left=0.0, right=0.0) for d in range(6)]).T
    # the model interpolates Q bilinearly in (w1, w2); between the nodes that differs from the
    # linear interpolation along the diagonal used here by a fraction of a percent
    assert m.mean_force()[0] == pytest.approx(np.sum(r.amplitude ** 2 * Qdiag[:, 0]), rel=0.01)


def test_wind_speed_series_mean_and_gust_variance(floatel):
    """The wind speed the kernel reads: its mean model value is the NPD 1-hour mean at the
    coefficients' reference height (10 m: u10 = 36 m/s); one 3-hour series has a mean within
    5 % of it and a sample variance within 40 % of the NPD spectral variance up to 0.741 Hz
    (trapezoid on a fine grid; one 3-hour sample of a process with gusts of minutes scatters
    that much; seed 3 gives 0.997)."""
    from floatmoor.metocean.wind import npd_wind_spectrum

    a = assemble(floatel, seed=3, dt=0.5, duration=10800.0, ramp=0.0,
                 models=["hydrostatics", "wind"])
    w = a.models["wind"]
    assert w.mean_speed == pytest.approx(36.0, rel=1e-12)
    u = w.speed[:a.asm.n_samples - 1]  # one repeat period or less
    # the sample variance of one 3-hour series scatters around the spectral variance
    f_hi = 0.741  # Hz, metocean docstring: NPD at 36 m/s cut at 1e-3 of the peak
    f = np.linspace(1e-6, f_hi, 200001)
    var = np.trapezoid(npd_wind_spectrum(f, 36.0, 10.0), f)
    assert abs(u.mean() / 36.0 - 1.0) < 0.05
    assert 0.6 < u.var() / var < 1.4
