"""The frequency domain's option ``line_current_drag``: the mean position with the static current
drag on the lines (:mod:`floatmoor.mooring.fe.current_statics`).

Expected values come from: the still-water limit (the default result, to round-off); the coupled
time domain with FE lines, which is an independent model of the same physics: its start pose
(:func:`floatmoor.solvers.fe_coupling.start_equilibrium`, the FE lines' full static force in
current) and, in the slow test, the dynamic relaxation of the body and lines under current only
(the generalised-alpha FE lines with relative-velocity drag; no statics involved); and the 12
coupled FE storms of the Floatel-like 100-year case
(notebooks/data/fd_line_dynamics/coupled_storms.csv, written by
benchmarks/fd_vs_coupled_storms.py: mean surge 14.70 m, WF tension std per line).
"""

from __future__ import annotations

import dataclasses
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.analyses.frequency_domain import FDOptions, frequency_domain_result
from floatmoor.core.errors import SceneError
from floatmoor.io.build import build
from floatmoor.mooring.fe.current_statics import LineCurrentStatics
from tests.fe_flagship import flagship_fe_as_stored

ROOT = Path(__file__).resolve().parents[2]
FLAGSHIP = ROOT / "scenes" / "floatel_100yr.yaml"
FLAGSHIP_FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"
STORMS = ROOT / "notebooks" / "data" / "fd_line_dynamics" / "coupled_storms.csv"


def _fd(scene, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return frequency_domain_result(scene, **kw)


def _with_env(scene, **env):
    sc = floatmoor.load_scene(scene)
    return dataclasses.replace(sc, environment=dataclasses.replace(sc.environment, **env))


def test_scene_key_and_validation(tmp_path):
    """``frequency_domain: line_current_drag`` is read as a bool; anything else is a
    SceneError naming the file and key."""
    src = yaml.safe_load(FLAGSHIP.read_text())
    for k in ("vessel", "environment", "mooring"):
        src[k] = str((FLAGSHIP.parent / src[k]).resolve())
    p = tmp_path / "s.yaml"
    src["frequency_domain"] = {"line_current_drag": True}
    p.write_text(yaml.safe_dump(src))
    sc = floatmoor.load_scene(p)
    assert sc.frequency_domain.line_current_drag is True
    assert "current drag on the lines" in sc.describe()
    src["frequency_domain"] = {"line_current_drag": 3}
    p.write_text(yaml.safe_dump(src))
    with pytest.raises(SceneError) as e:
        floatmoor.load_scene(p)
    assert "line_current_drag" in str(e.value) and "s.yaml" in str(e.value)
    with pytest.raises(SceneError, match="line_current_drag"):
        FDOptions(line_current_drag="yes")
    assert FDOptions().line_current_drag is False


def test_still_water_limit():
    """Current of zero speed: the option gives the default result to round-off, and no
    current in the scene at all changes nothing (same code path, a note)."""
    sc = floatmoor.load_scene(FLAGSHIP)
    cur = sc.environment.current
    still = _with_env(FLAGSHIP, current=dataclasses.replace(cur, speed=(0.0,) * len(cur.speed)))
    a, b = _fd(still), _fd(still, line_current_drag=True)
    assert np.array_equal(b.mean_force_line_current, np.zeros(6))
    np.testing.assert_allclose(b.mean, a.mean, rtol=0, atol=1e-9)
    for k in ("tension_static", "wf_std", "lf_std"):
        ref = getattr(a, k)
        np.testing.assert_allclose(getattr(b, k), ref, rtol=1e-9,
                                   atol=1e-9 * np.abs(ref).max(), err_msg=k)
    # the tension gradients are central differences of the catenary (1 cm steps): the
    # round-off of the mean pose and of the catenary solves comes out amplified (3.5e-9 seen)
    for k in ("tension_std_wf", "tension_std_lf", "tension_max_total"):
        ref = getattr(a, k)
        np.testing.assert_allclose(getattr(b, k), ref, rtol=1e-7,
                                   atol=1e-7 * np.abs(ref).max(), err_msg=k)
    none = _with_env(FLAGSHIP, current=None)
    c, d = _fd(none), _fd(none, line_current_drag=True)
    assert np.array_equal(c.mean, d.mean) and d.mean_force_line_current is None
    assert any("no current" in n for n in d.notes)


def _current_only_fe(n_elements):
    """The FE flagship under its current alone (no waves, no wind), lines of n elements."""
    sc = _with_env(FLAGSHIP_FE, waves=None, wind=None)
    b = build(sc)
    lm = b.mooring.line_models
    b.mooring.line_models = dataclasses.replace(
        lm, options=dataclasses.replace(lm.options, n_elements=n_elements))
    return b


def test_current_only_against_the_coupled_fe_start_pose():
    """Current only, lines of 100 elements: the FD mean with the lines' current drag against
    the static start pose of the coupled FE time domain (the FE lines' whole static force,
    fixed point on F_FE - F_catenary).  Measured: surge 3.8777 against 3.8803 m (the line drag
    moves the body 2.88 m from 0.997 m); 50 / 100 / 200 elements: 3.9145 / 3.8777 / 3.8805 m
    against 3.8890 / 3.8803 / 3.8817 m (both converge)."""
    from floatmoor.solvers.time_domain import assemble
    td = assemble(_current_only_fe(100), seed=1, dt=0.1, duration=10.0, ramp=0.0).x0
    fd0 = _fd(_current_only_fe(100))
    fd = _fd(_current_only_fe(100), line_current_drag=True)
    assert fd.mean[0] - fd0.mean[0] > 2.5                    # the effect is large
    assert abs(fd.mean[0] - td[0]) < 0.01                    # m
    assert abs(fd.mean[2] - td[2]) < 1e-3                    # m
    assert abs(fd.mean[4] - td[4]) < 2e-5                    # rad
    assert np.all(fd.tension_static_line_current[:3] > 0)    # every line tighter in current



@pytest.mark.parametrize("dof, load", [(0, 3e5), (1, 3e5), (5, 3e7)])
def test_stiffness_against_the_coupled_fe_start_pose_under_an_extra_load(dof, load):
    """The drag's change with the pose in the linearisation: current only, 50-element lines;
    an extra constant load +-F in surge, sway (300 kN) or yaw (30 MN m) moves the coupled FE
    time domain's static start pose (the FE lines' whole static force in current, its own
    equilibrium iteration) by dx; the FD's linear prediction K^-1 F with the drag's stiffness
    (central differences of the increment, LineCurrentStatics.linearise) against it, and
    without it.  Measured: surge 1.1303 / 1.1334 m (without 1.0723), sway 1.1361 / 1.1376 m
    (1.0738), yaw 0.05295 / 0.05288 rad (0.06205): the drag softens surge and sway by 6 % and
    stiffens yaw (the yaw response 15 % smaller).  The FE start pose is converged to 1 mm (hence the large loads)."""
    from floatmoor.solvers.time_domain import assemble
    fd = _fd(_current_only_fe(50), line_current_drag=True)
    b0 = _current_only_fe(50)
    drag = LineCurrentStatics.from_scene(b0.scene, b0.mooring, pose=fd.mean)
    K_drag, _ = drag.linearise(fd.mean)
    f = np.zeros(6)
    f[dof] = load
    x = []
    for sign in (1.0, -1.0):
        b = _current_only_fe(50)
        b = dataclasses.replace(b, static_force=b.static_force + sign * f)
        x.append(assemble(b, seed=1, dt=0.1, duration=10.0, ramp=0.0).x0)
    dx_fe = 0.5 * (x[0] - x[1])[dof]
    dx_fd = np.linalg.solve(fd.model.stiffness, f)[dof]
    dx_without = np.linalg.solve(fd.model.stiffness - K_drag, f)[dof]
    assert abs(dx_fd / dx_fe - 1.0) < 0.005
    assert abs(dx_without / dx_fe - 1.0) > 0.04          # the term matters
    assert any("its stiffness in the linearisation" in n for n in fd.notes)


@pytest.mark.slow  # about 70 s of CPU: 1000 s of the coupled FE run with 12 lines
def test_current_only_against_fe_dynamic_relaxation():
    """Current only: the coupled FE time domain started at the FD mean *without* line drag
    (0.997 m) drifts and settles under the lines' current drag; its rest position and fairlead
    tensions (mean of the last 100 s of 1000 s) against the FD mean with the option.  Measured
    (50 elements, 2400 s): rest 3.8890 m, tension line 1 930.2 kN, line 6 1187.15 kN; the FD
    3.9145 m, 931.0 and 1188.2 kN; with 100 elements the two differ by 3 mm."""
    b = _current_only_fe(100)
    fd0 = _fd(_current_only_fe(100))
    fd = _fd(_current_only_fe(100), line_current_drag=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = floatmoor.simulate(b, seed=1, duration=1000.0, ramp=0.0, transient=0.0,
                                start_pose=fd0.mean)
    t = ds.time.values
    last = t >= 900.0
    m = ds["motion"].values[last]
    T = ds["line_tension"].values[last].mean(axis=0)
    assert m[:, 0].std() < 5e-3                                # at rest
    assert abs(m[:, 0].mean() - fd.mean[0]) < 0.01             # m, of a 2.88 m drift
    assert abs(m[:, 4].mean() - fd.mean[4]) < 2e-5             # rad
    np.testing.assert_allclose(T, fd.tension_static, rtol=2e-3)


def test_floatel_100yr_against_coupled_fe_storms():
    """Floatel-like 100-year case, dynamic WF tension, the storms' 50-element lines: the FD mean
    surge with the lines' current drag against the 12 coupled FE storms (14.70 m; without the
    option the FD gives 10.47 m), and the WF tension std of every line (storms: RMS over the
    seeds).  Measured: 13.60 m; WF std FD / storms - 1 from +1.1 to +2.5 % (without the option
    -1.0 to +6.4 %; with the option but without the drag's stiffness +1.4 to +2.9 %).  The 1.1 m left is not static: the storms' lines move in the waves, and
    the mean of a quadratic drag on a line oscillating in a current exceeds the drag of the
    current alone."""
    import pandas as pd
    df = pd.read_csv(STORMS)
    fe = df[df["model"] == "fe"]
    surge_storms = float(fe["surge_mean"].mean())
    std_storms = np.array([np.sqrt((fe[f"line{i}_wf_std"] ** 2).mean()) for i in range(1, 13)])
    scene = flagship_fe_as_stored()                 # the storms' 50 elements per line
    r0 = _fd(scene, tension_model="dynamic")
    r = _fd(scene, tension_model="dynamic", line_current_drag=True)
    assert abs(surge_storms - 14.70) < 0.01
    err0, err = surge_storms - r0.mean[0], surge_storms - r.mean[0]
    assert err0 > 4.0 and 0.0 < err < 1.3
    dev0 = r0.tension_std_wf / 1e3 / std_storms - 1.0
    dev = r.tension_std_wf / 1e3 / std_storms - 1.0
    assert np.abs(dev0).max() > 0.06
    assert np.abs(dev).max() < 0.035


def test_cli_flag_and_dataset(capsys, tmp_path):
    """``floatmoor fd --line-current-drag``: the table says so and the Dataset has the line
    drag variables with units (the increment of the static tension is the difference of the
    two runs' static tensions)."""
    from floatmoor.cli import main
    out = tmp_path / "fd.nc"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["fd", str(FLAGSHIP), "--line-current-drag", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "static current drag of the lines" in text
    import xarray as xr
    with xr.open_dataset(out) as ds:
        assert ds.attrs["line_current_drag"] == 1
        assert ds["tension_static_line_current"].attrs["units"] == "N"
        assert ds["mean_force_line_current"].values[0] > 5e5     # N, downstream
        r0 = _fd(FLAGSHIP)
        # the static tension is the catenary's at the new mean plus the increment
        assert not np.allclose(ds["tension_static"].values, r0.tension_static, rtol=1e-2)
