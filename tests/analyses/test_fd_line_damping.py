"""The frequency domain's option ``line_damping: fe``: the mooring lines' LF impedance (drag
damping and dynamic stiffening) from their FE models (:mod:`floatmoor.analyses.fd_line_damping`).

Expected values come from: the catenary mooring's stiffness (the static limit of the lines'
impedance, summed into the body's 6x6 through the fairlead arms: an independent model of the
same lines); the 12 coupled FE storms of the Floatel-like 100-year case
(notebooks/data/fd_line_dynamics/coupled_storms.csv, written by
benchmarks/fd_vs_coupled_storms.py: body and FE lines integrated together in the time domain,
the lines' drag damping coming out of the line model); the line model itself is checked
against time-domain forced oscillations in tests/mooring/fe/test_frequency_damping.py.
"""

from __future__ import annotations

import dataclasses
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.analyses.fd_line_damping import MU_STATIC, MooringLineDamping
from floatmoor.analyses.frequency_domain import FDOptions, frequency_domain_result
from floatmoor.core.errors import SceneError
from floatmoor.io.build import build
from floatmoor.mooring.fe.frequency_damping import fairlead_impedance, harmonic_band
from tests.fe_flagship import flagship_fe_as_stored

ROOT = Path(__file__).resolve().parents[2]
FLAGSHIP = ROOT / "scenes" / "floatel_100yr.yaml"
FLAGSHIP_FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"
STORMS = ROOT / "notebooks" / "data" / "fd_line_dynamics" / "coupled_storms.csv"


def _skew(a):
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


def _fd(scene, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return frequency_domain_result(scene, **kw)


def test_scene_key_and_validation(tmp_path):
    """``frequency_domain: line_damping`` is ``none`` or ``fe``; anything else is a SceneError
    naming the file and key."""
    assert FDOptions().line_damping == "none"
    with pytest.raises(SceneError, match="line_damping"):
        FDOptions(line_damping="fem")
    src = yaml.safe_load(FLAGSHIP.read_text())
    for k in ("vessel", "environment", "mooring"):
        src[k] = str((FLAGSHIP.parent / src[k]).resolve())
    p = tmp_path / "s.yaml"
    src["frequency_domain"] = {"line_damping": "fe"}
    p.write_text(yaml.safe_dump(src))
    sc = floatmoor.load_scene(p)
    assert sc.frequency_domain.line_damping == "fe"
    assert "FE line damping" in sc.describe()
    src["frequency_domain"] = {"line_damping": "yes"}
    p.write_text(yaml.safe_dump(src))
    with pytest.raises(SceneError) as exc:
        floatmoor.load_scene(p)
    assert "line_damping" in str(exc.value) and "s.yaml" in str(exc.value)


def test_static_limit_is_the_catenary_stiffness():
    """Without current and drag, the lines' impedance at w -> 0 summed through the fairlead
    arms (``J^T Z J``, plus in yaw the static fairlead force turning with its arm,
    ``-[F]x [arm]x``, which no velocity term has) is the catenary mooring's stiffness at the mean
    pose (surge, sway, yaw within 1.5 %: 50-element FE lines against the elastic catenary)."""
    sc = flagship_fe_as_stored()                    # 50 elements per line
    sc = dataclasses.replace(sc, environment=dataclasses.replace(sc.environment, current=None))
    built = build(sc)
    r = _fd(built)
    lines = MooringLineDamping(built, r.mean)
    K = np.zeros((6, 6))
    for line, J in lines.lines:
        imp = fairlead_impedance(line, [harmonic_band(0.05, 1.0)], [MU_STATIC], drag=False)
        K += J.T @ imp.stiffness[0] @ J
        F = line.solve_static().fairlead_force              # the line's force on the body
        K[3:, 3:] += _skew(F) @ J[:, 3:]     # -[F]x [arm]x, with J[:, 3:] = -[arm]x
    K_cat = built.mooring.stiffness(r.mean)
    hz = [0, 1, 5]
    for i in hz:
        assert K[i, i] == pytest.approx(K_cat[i, i], rel=0.015), (i, K[i, i], K_cat[i, i])
    assert abs(K[0, 1]) < 1e-3 * K[0, 0] and abs(K[0, 5]) < 1e-3 * K[5, 5] / 30.0


def test_floatel_lf_surge_against_coupled_fe_storms():
    """Floatel-like 100-year case (FE scene, with the lines' static current drag): the LF surge
    std of the FD with the lines' impedance against the RMS over the 12 coupled FE storms
    (1.805 m; the seeds' standard error 0.030 m).  Without it the FD is 35 % above the storms
    (2.444 m: no line damping); with it within 8 % (measured 1.710 m, -5.3 %).  Head seas on a
    symmetric spread: no surge-sway or surge-yaw coupling in the line damping.  The LF tension
    std of lines 1-6 (the FE lines' dynamic tension increment on the quasi-static gradient)
    within 12 % of the storms' RMS (measured -5.3, -4.1, -2.8, -10.0, -9.2, -8.5 %; without
    the option -40 % on the slack lines 1-3 and +11 to +21 % on the taut lines 4-6)."""
    pd = pytest.importorskip("pandas")
    df = pd.read_csv(STORMS)
    fe = df[df["model"] == "fe"]
    storms = float(np.sqrt(np.mean(fe["surge_lf_std"] ** 2)))
    scene = flagship_fe_as_stored()                 # the storms' 50 elements per line
    r0 = _fd(scene, line_current_drag=True)
    r = _fd(scene, line_current_drag=True, line_damping="fe")
    assert r0.lf_damping_mooring is None and r0.model.lf_impedance is None
    assert r0.lf_std[0] / storms - 1.0 > 0.3
    assert abs(r.lf_std[0] / storms - 1.0) < 0.08
    assert np.allclose(r.mean, r0.mean)              # the mean position is not touched
    B = r.lf_damping_mooring
    assert B[0, 0] > 0 and B[1, 1] > 0 and B[5, 5] > 0
    assert abs(B[0, 1]) < 1e-3 * B[0, 0] and abs(B[0, 5]) < 1e-3 * B[0, 0] * 30.0
    t_storms = np.sqrt(np.mean(fe[[f"line{k}_lf_std" for k in range(1, 7)]].values ** 2,
                               axis=0)) * 1e3
    err = r.tension_std_lf[:6] / t_storms - 1.0
    assert np.all(np.abs(err) < 0.12), err
    assert np.all(np.abs(r0.tension_std_lf[:6] / t_storms - 1.0) > 0.10)
    assert np.allclose(r.tension_std_lf_quasi_static[:6] / r0.tension_std_lf[:6], 1.0, atol=0.5)
    ds = floatmoor.frequency_domain(FLAGSHIP_FE, line_current_drag=True, line_damping="fe")
    assert ds.attrs["line_damping"] == "fe" and "lf_damping_mooring" in ds
    assert "lf_damping_mooring" not in floatmoor.frequency_domain(FLAGSHIP_FE)
