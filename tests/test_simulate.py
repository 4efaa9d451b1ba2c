"""simulate(): the result Dataset contract; the multi-seed runner; the run/convergence commands."""

from __future__ import annotations

import argparse
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from floatmoor.analyses.simulate import simulate
from floatmoor.core.errors import SceneError

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

ROOT = Path(__file__).resolve().parents[1]
OC3 = ROOT / "vessels" / "oc3_hywind"


def _scene(tmp_path, extra="") -> Path:
    p = tmp_path / "oc3_waves.yaml"
    p.write_text(f"name: oc3-waves\nsite: {{water_depth: 320.0}}\n"
                 f"vessel: {OC3 / 'vessel.yaml'}\nmooring: {OC3 / 'mooring.yaml'}\n"
                 "environment:\n  waves: {spectrum: jonswap, hs: 6.0, tp: 12.0}\n"
                 "analysis: {duration: 150.0, dt: 0.1, transient: 50.0, ramp: 20.0, seeds: 1}\n"
                 + extra)
    return p


@pytest.fixture
def scene_file(tmp_path):
    return _scene(tmp_path)


def test_result_dataset_contract(scene_file, tmp_path):
    """The variables, units and attributes the post-processing and the report rely on."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(scene_file, seed=7, record_forces=True)
    assert ds["motion"].dims == ("time", "dof")
    assert list(ds["dof"].values) == ["surge", "sway", "heave", "roll", "pitch", "yaw"]
    assert ds["line_tension"].dims == ("time", "line")
    assert ds["line_tension"].attrs["units"] == "N"
    assert ds["anchor_tension"].attrs["units"] == "N"
    assert ds["wave_elevation"].dims == ("time",)
    assert ds["force"].dims == ("time", "model", "dof")
    assert list(ds["model"].values) == list(ds.attrs["models"])
    for name, var in ds.data_vars.items():
        assert var.attrs.get("units") is not None and var.attrs.get("long_name"), name
    assert ds.attrs["seed"] == 7 and ds.attrs["dt"] == 0.1 and ds.attrs["transient"] == 50.0
    assert "jonswap" in ds.attrs["scene"] and ds.attrs["version_floatmoor"]
    assert ds.attrs["run_time_s"] > 0.0
    assert ds["time"].values[-1] == pytest.approx(150.0)
    # mooring tension at the fairlead exceeds the anchor tension (line weight) for OC3
    assert np.all(ds["line_tension"].values > ds["anchor_tension"].values)
    # force balance: M' x'' = sum of the model forces (finite differences of the velocity)
    # is checked in the solver tests; here the sum of forces is finite
    assert np.all(np.isfinite(ds["force"].values))
    # netCDF round trip and the post-processing's per-seed statistics
    path = tmp_path / "r.nc"
    ds.to_netcdf(path)
    with xr.open_dataset(path) as back:
        assert np.array_equal(back["motion"].values, ds["motion"].values)
        assert int(back.attrs["seed"]) == 7
    from floatmoor.post.timeseries import per_seed_statistics
    stats = per_seed_statistics([ds], start=50.0)
    assert "line_tension_max" in stats or len(stats.data_vars) > 0


def test_bad_seed_and_dt_are_scene_errors(scene_file):
    with pytest.raises(SceneError, match="seed"):
        simulate(scene_file, seed=-1)
    with pytest.raises(SceneError, match="dt"):
        simulate(scene_file, dt=500.0)


def test_runner_parallel_resumable_and_failure_tolerant(scene_file, tmp_path, capsys):
    """Three seeds on two workers; seed 2 cannot be written (its file's path is a folder: the
    finished temporary file cannot be renamed onto it): it is recorded as failed with its error
    and the others finish; a second run skips the finished seeds and retries seed 2 only."""
    from floatmoor.analyses.runner import run_seeds, seed_file

    out = tmp_path / "out"
    out.mkdir()
    blocker = seed_file(out, "oc3-waves", 2)
    blocker.mkdir()
    lines = []
    batch = run_seeds(scene_file, [1, 2, 3], out, workers=2, echo=lines.append, progress=False)
    assert batch.failed == [2]
    assert [o.status for o in batch.outcomes] == ["done", "failed", "done"]
    assert seed_file(out, "oc3-waves", 1).is_file() and seed_file(out, "oc3-waves", 3).is_file()
    assert (out / "oc3-waves_seed0002.error.txt").is_file()
    assert any("seed 2: FAILED" in s for s in lines)
    with xr.open_dataset(seed_file(out, "oc3-waves", 3)) as ds:
        assert int(ds.attrs["seed"]) == 3
    blocker.rmdir()
    lines = []
    batch = run_seeds(scene_file, [1, 2, 3], out, workers=1, echo=lines.append, progress=False)
    assert [o.status for o in batch.outcomes] == ["skipped", "done", "skipped"]
    assert not batch.failed and not (out / "oc3-waves_seed0002.error.txt").exists()
    # identical to a direct simulation of the same seed
    direct = simulate(scene_file, seed=2)
    with xr.open_dataset(seed_file(out, "oc3-waves", 2)) as ds:
        assert np.array_equal(ds["motion"].values, direct["motion"].values)


def test_run_command_table_and_exit_status(scene_file, tmp_path, capsys):
    from floatmoor.commands import run as run_cmd

    p = argparse.ArgumentParser()
    run_cmd.add_arguments(p)
    args = p.parse_args([str(scene_file), "--seeds", "1-2", "--out", str(tmp_path / "o"),
                         "--workers", "1"])
    assert run_cmd.run(args) == 0
    text = capsys.readouterr().out
    assert "offset (m)" in text and "tension (kN)" in text and "statistics over 2 seeds" in text


def test_convergence_study_errors_shrink(scene_file):
    """Halving dt: the error of max offset / max tension against the finest run falls."""
    from floatmoor.analyses.convergence import convergence_study, format_table

    rows = convergence_study(scene_file, duration=150.0, dt0=0.4, levels=3)
    assert [r["dt"] for r in rows] == [0.4, 0.2, 0.1]
    assert rows[-1]["error_offset"] == 0.0
    assert rows[0]["error_tension"] >= rows[1]["error_tension"] - 1e-12
    assert "max tension" in format_table(rows)


def test_package_level_api(scene_file):
    """``floatmoor.load_scene`` and ``floatmoor.simulate`` are plain functions (the package
    re-exports them from :mod:`floatmoor.analyses`, even after the analysis modules have been
    imported) and give the same result as the module's function."""
    import types

    import floatmoor
    import floatmoor.analyses.simulate as mod

    assert isinstance(floatmoor.simulate, types.FunctionType) and floatmoor.simulate is simulate
    assert mod.simulate is simulate
    for name in ("load_scene", "equilibrium", "restoring_curves", "frequency_domain",
                 "run_seeds"):
        assert isinstance(getattr(floatmoor, name), types.FunctionType), name
    scene = floatmoor.load_scene(scene_file)
    a = floatmoor.simulate(scene, seed=2, duration=30.0)
    b = simulate(scene, seed=2, duration=30.0)
    assert np.array_equal(a["motion"].values, b["motion"].values)


def test_forces_section_of_the_scene_is_used(tmp_path):
    """``forces:`` in the scene file: excluded models are not built, a line failure happens."""
    p = _scene(tmp_path, extra="forces: {exclude: [radiation], line_failure: {line2: 10.0}, "
                               "record_forces: true}\n")
    ds = simulate(p, seed=1, duration=30.0)
    assert "radiation" not in ds.attrs["models"] and "mooring" in ds.attrs["models"]
    assert "force" in ds
    t = ds["time"].values
    assert np.all(ds["line_tension"].sel(line="line2").values[t > 10.05] == 0.0)
    p2 = _scene(tmp_path, extra="forces: {exclude: [windd]}\n")
    with pytest.raises(SceneError, match="forces.exclude"):
        simulate(p2, seed=1, duration=30.0)


def test_run_command_failed_seed_exit_status(scene_file, tmp_path, capsys):
    """A seed that fails: the others are written, the exit status is 3 and the failed seed is
    named on stderr."""
    from floatmoor.analyses.runner import seed_file
    from floatmoor.commands import run as run_cmd

    out = tmp_path / "o"
    out.mkdir()
    block = seed_file(out, "oc3-waves", 2)
    block.mkdir()   # the finished seed cannot be renamed onto its path: seed 2 fails
    p = argparse.ArgumentParser()
    run_cmd.add_arguments(p)
    args = p.parse_args([str(scene_file), "--seeds", "1-2", "--out", str(out), "--workers", "1"])
    assert run_cmd.run(args) == 3
    cap = capsys.readouterr()
    assert "1 seed(s) failed: 2" in cap.err
    assert seed_file(out, "oc3-waves", 1).is_file()
    assert "statistics over 1 seed" in cap.out


def test_duration_not_longer_than_transient(scene_file, tmp_path, capsys):
    """``floatmoor run --duration`` at or below the transient (50 s here) is a SceneError naming
    the duration and the transient, before any seed runs (exit status 2 through the CLI), not a
    zero-size-array crash in the statistics table; ``run_seeds`` refuses it too; ``simulate``
    allows such a short check with a FloatmoorWarning."""
    from floatmoor.analyses.runner import run_seeds
    from floatmoor.cli import main
    from floatmoor.commands import run as run_cmd
    from floatmoor.core.errors import FloatmoorWarning

    p = argparse.ArgumentParser()
    run_cmd.add_arguments(p)
    out = tmp_path / "o"
    for dur in ("50", "30"):
        args = p.parse_args([str(scene_file), "--seeds", "1", "--out", str(out),
                             "--duration", dur])
        with pytest.raises(SceneError, match="--duration") as err:
            run_cmd.run(args)
        assert "transient" in str(err.value) and "50 s" in str(err.value)
    assert not out.exists()
    assert main(["run", str(scene_file), "--seeds", "1", "--out", str(out),
                 "--duration", "30"]) == 2
    assert "transient" in capsys.readouterr().err
    with pytest.raises(SceneError, match="duration.*transient"):
        run_seeds(scene_file, [1], out, overrides={"duration": 40.0}, echo=None)
    with pytest.warns(FloatmoorWarning, match="transient"):
        ds = simulate(scene_file, seed=1, duration=30.0)
    assert ds["time"].values[-1] == pytest.approx(30.0)


def test_attributes_name_the_wave_force_frame_and_relative_velocity(scene_file):
    ds = simulate(scene_file, seed=1, duration=60.0)
    assert "start heading" in ds.attrs["wave_force_frame"]
    assert ds.attrs["relative_velocity"] == "low_frequency"
    assert ds.attrs["relative_velocity_note"] == "no wind or current force"
    assert 0.0 <= ds.attrs["max_yaw_excursion_deg"] < 15.0


def test_large_yaw_excursion_warns_about_the_wave_heading(scene_file):
    """A run whose yaw leaves the start heading by more than 15 deg (here a free yaw decay from
    25 deg in waves) warns that the wave forces stay at the start heading."""
    from floatmoor.core.errors import FloatmoorWarning
    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.solvers.time_domain import assemble

    b = build(load_scene(scene_file))
    a = assemble(b, seed=1, dt=0.1, duration=10.0)
    x0 = a.x0.copy()
    x0[5] += math.radians(25.0)
    with pytest.warns(FloatmoorWarning, match="start heading"):
        ds = simulate(b, seed=1, duration=10.0, dt=0.1, transient=0.0, start_pose=x0)
    assert ds.attrs["max_yaw_excursion_deg"] > 15.0
    with warnings.catch_warnings():
        warnings.simplefilter("error", FloatmoorWarning)
        simulate(b, seed=1, duration=60.0, dt=0.1)   # small yaw: no warning


def test_runner_reports_the_warnings_of_a_seed(scene_file, tmp_path):
    """The workers' FloatmoorWarnings (here the yaw far from the wave heading) are kept in the
    outcome and echoed, not lost in the worker process."""
    from floatmoor.analyses.runner import run_seeds
    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.solvers.time_domain import assemble

    a = assemble(build(load_scene(scene_file)), seed=1, dt=0.1, duration=10.0)
    x0 = a.x0.copy()
    x0[5] += math.radians(25.0)
    lines = []
    batch = run_seeds(scene_file, [1], tmp_path / "o", workers=1, echo=lines.append,
                      progress=False, overrides={"duration": 60.0, "start_pose": x0})
    assert len(batch.outcomes[0].warnings) == 1       # the scene's own warnings not repeated
    assert "start heading" in batch.outcomes[0].warnings[0]
    assert any(s.startswith("    warning (seed 1):") for s in lines)


def test_relative_velocity_option_from_the_scene_file(tmp_path):
    p = _scene(tmp_path, extra="forces: {relative_velocity: total}\n")
    ds = simulate(p, seed=1, duration=60.0)
    assert ds.attrs["relative_velocity"] == "total"
    p2 = _scene(tmp_path, extra="forces: {relative_velocity: lowfrequency}\n")
    with pytest.raises(SceneError, match="forces.relative_velocity"):
        simulate(p2, seed=1, duration=60.0)


# -- finite-element lines coupled: floatmoor run and report on their results -----------------
def _fe_scene(tmp_path) -> Path:
    """The FE flagship scene (scenes/floatel_100yr_fe.yaml) with 8 elements per line, a
    moderate sea and short runs."""
    import yaml

    d = yaml.safe_load((ROOT / "scenes" / "floatel_100yr_fe.yaml").read_text())
    d["name"] = "fe-small"
    d["vessel"] = str(ROOT / "vessels" / "floatel_like" / "vessel.yaml")
    d["environment"] = {"name": "sea", "waves": {"spectrum": "jonswap", "hs": 8.0, "tp": 13.0}}
    d["mooring"] = yaml.safe_load((ROOT / "vessels" / "floatel_like" / "mooring_fe.yaml")
                                  .read_text())
    d["mooring"]["finite_element"] = {"n_elements": 8}
    d["analysis"] = {"duration": 80.0, "dt": 0.2, "transient": 20.0, "ramp": 20.0,
                     "seeds": "1-4"}
    p = tmp_path / "fe_small.yaml"
    p.write_text(yaml.safe_dump(d))
    return p


def test_run_and_report_with_fe_lines(tmp_path, monkeypatch):
    """``floatmoor run`` of a scene with FE lines on two workers writes the FE channels per
    seed; a seed whose FE line fails is recorded with the line's NumericalError (time, line,
    remedy) while the others finish; ``floatmoor report`` reads the results."""
    from floatmoor.analyses.runner import run_seeds, seed_file
    from floatmoor.solvers import fe_coupling

    scene = _fe_scene(tmp_path)
    out = tmp_path / "out"
    lines = []
    batch = run_seeds(scene, [1, 2, 3], out, workers=2, echo=lines.append, progress=False)
    assert not batch.failed, lines
    with xr.open_dataset(seed_file(out, "fe-small", 2)) as ds:
        assert list(ds.attrs["fe_lines"]) == [f"line{i}" for i in range(1, 13)]
        assert "max_tension_along_line" in ds and "grounded_length" in ds
        assert (ds["line_model"].values == "finite-element").all()
        assert ds["line_tension"].values.max() > 5e5
    # seed 4 in-process with every Newton iteration refused: a real FE failure
    orig = fe_coupling.FEMooring.start

    def failing_start(self, **kw):
        orig(self, **kw)
        for ln in self.lines:
            ln.maxit = 0
    monkeypatch.setattr(fe_coupling.FEMooring, "start", failing_start)
    batch = run_seeds(scene, [1, 2, 3, 4], out, workers=1, echo=lines.append, progress=False)
    assert [o.status for o in batch.outcomes] == ["skipped", "skipped", "skipped", "failed"]
    err = batch.outcomes[3].error
    assert err.startswith("NumericalError") and "line 'line1'" in err and "reduce dt" in err
    assert (out / "fe-small_seed0004.error.txt").is_file()
    monkeypatch.undo()
    # the report of the three good seeds (the failed one is listed, not used)
    from floatmoor.cli import main

    code = main(["report", str(out), "--out", str(tmp_path / "rep")])
    assert code == 0
    rep = list((tmp_path / "rep").iterdir())
    assert rep
