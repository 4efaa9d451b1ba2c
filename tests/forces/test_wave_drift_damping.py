"""Wave drift damping (Aranha) in both domains: one model, one matrix.

Expected values: Aranha's integral b = 2 int S(w) (w/g) (4 C(w) + w dC/dw) dw written out here
on the database's surge mean drift coefficients at 0 deg and the scene's JONSWAP spectrum
(Aranha (1994); the FD's function is tested on a constant coefficient in
tests/solvers/test_frequency_domain.py); the time loop's term against the model's own Python
force; its effect on the LF motion against the frequency domain's prediction.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import floatmoor
from floatmoor.core.config import Node
from floatmoor.core.errors import FloatmoorWarning
from floatmoor.io.forces_section import ForcesSpec, parse_forces
from floatmoor.metocean.spectra import wave_spectrum
from floatmoor.post.timeseries import lowpass
from floatmoor.solvers.time_domain import assemble, integrate

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"


@pytest.fixture(scope="module")
def scenes():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        sc = floatmoor.load_scene(SCENE)
    on = replace(sc, forces=ForcesSpec(wave_drift_damping=True, file=sc.file))
    return sc, on


def test_scene_key_and_default():
    spec = parse_forces(Node({"wave_drift_damping": True}, "s.yaml", "forces"))
    assert spec.wave_drift_damping is True
    assert ForcesSpec().wave_drift_damping is False  # off unless the scene asks
    from floatmoor.core.errors import SceneError
    with pytest.raises(SceneError, match="forces.wave_drift_damping"):
        parse_forces(Node({"wave_drift_damping": "yes"}, "s.yaml", "forces"))


def test_time_and_frequency_domain_carry_the_same_matrix(scenes):
    """The TD term (start heading 0) and the FD's LF damping (mean heading: 0 in head seas)
    are the same matrix, and its surge entry is Aranha's integral written out here."""
    _, on = scenes
    built = floatmoor.build(on)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        a = assemble(built, seed=1, dt=0.1, duration=20.0, options=on.forces)
        fd = floatmoor.frequency_domain_result(built)
    assert "wave_drift_damping" in a.models and "wave_drift_damping" in fd.models
    assert abs(fd.mean[5]) < 1e-12  # head seas: the mean heading is the TD's start heading
    B_td = a.asm.damping_lf
    np.testing.assert_allclose(fd.lf_damping_wave_drift, B_td, rtol=1e-12,
                               atol=1e-12 * B_td[0, 0])
    assert np.count_nonzero(B_td) == 1  # surge only in head seas
    # Aranha by hand: the database's surge coefficient at 0 deg on the FD grid
    db = built.vessel.database
    w = np.asarray(fd.model.omega)
    C = np.interp(w, db["omega"].values,
                  db["mean_drift_force"].sel(wave_direction=0.0,
                                             influenced_dof="surge").values)
    S = wave_spectrum(built.scene.environment.waves, w)
    g = built.scene.site.gravity
    b = 2.0 * np.trapezoid(S * (w / g) * (4.0 * C + w * np.gradient(C, w)), w)
    assert B_td[0, 0] == pytest.approx(b, rel=1e-9)
    assert b > 0.0  # a damping (drift grows with the encounter frequency)
    # the FD's LF system has it, its WF system not
    assert fd.solution.lf_damping[0, 0] == pytest.approx(
        fd.model.linear_damping[0, 0] + fd.lf_damping_current[0, 0] + fd.lf_damping_wind[0, 0]
        + b, rel=1e-12)


def test_kernel_term_is_the_model_force_on_the_low_frequency_velocity(scenes):
    """The time loop's term equals the model's Python force -B (x' - x'_WF) at recorded steps,
    with the run's linear WF velocity: it acts on the low-frequency motion."""
    _, on = scenes
    built = floatmoor.build(on)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        a = assemble(built, seed=2, dt=0.1, duration=300.0, options=on.forces)
        r = integrate(a, record_forces=True, built=built)
    assert a.asm.lf_wf_velocity  # the WF velocity removed
    m = a.models["wave_drift_damping"]
    q = r.force_models.index("wave_drift_damping")
    wf = a.asm.wf_velocity
    for n in (0, 700, 1500, 2999):
        out = np.zeros(6)
        m.force(r.time[n], r.motion[n], r.velocity[n], out, wf_velocity=wf[2 * n])
        np.testing.assert_allclose(r.forces[n, q], out, rtol=1e-12, atol=1e-9)
    # on the LF velocity: the force is much smaller than B times the total velocity
    late = slice(2000, 3000)
    f_lf = np.std(r.forces[late, q, 0])
    f_total = np.std(m.matrix[0, 0] * r.velocity[late, 0])
    assert f_lf < 0.5 * f_total


def test_effect_on_the_lf_motion_as_the_frequency_domain_predicts(scenes):
    """With the same realisation, the TD LF surge std falls by the ratio the FD predicts
    (within 2 %), and the WF surge motion barely changes (within 1 %): a LF damping."""
    sc, on = scenes
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        fd_off = floatmoor.frequency_domain_result(sc)
        fd_on = floatmoor.frequency_domain_result(on)
        runs = [floatmoor.simulate(s, seed=4, duration=4200.0, transient=600.0)
                for s in (sc, on)]
    stats = []
    for ds in runs:
        t = ds["time"].values
        keep = t >= 600.0
        x = ds["motion"].values[:, 0]
        lf = lowpass(x, float(t[1] - t[0]))
        stats.append((np.std(lf[keep]), np.std((x - lf)[keep])))
    (lf0, wf0), (lf1, wf1) = stats
    fd_ratio = fd_on.lf_std[0] / fd_off.lf_std[0]
    assert fd_ratio < 0.97  # the damping matters here (285 kN s/m against 2.2 MN s/m)
    assert lf1 / lf0 == pytest.approx(fd_ratio, abs=0.02)
    assert wf1 / wf0 == pytest.approx(1.0, abs=0.01)
    assert math.isclose(fd_on.mean[0], fd_off.mean[0], rel_tol=1e-12)  # no mean force
