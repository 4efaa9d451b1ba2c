"""The floatmoor command: check, environment, --help, --version, exit codes, no tracebacks."""

import importlib
import subprocess
import sys

import pytest

import floatmoor
from floatmoor import NumericalError
from floatmoor.cli import commands, main

from .io.helpers import DELETE, write_case


def test_version(capsys):
    assert main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"floatmoor {floatmoor.__version__}"


def test_help_lists_every_subcommand(capsys):
    assert main(["--help"]) == 0
    out = capsys.readouterr().out
    assert "usage: floatmoor" in out
    for cmd in commands():
        assert cmd.name in out


def test_no_subcommand_is_a_usage_error(capsys):
    assert main([]) == 2
    assert "usage: floatmoor" in capsys.readouterr().err


def test_check_prints_what_the_scene_builds(tmp_path, capsys):
    scene_path, env_path = write_case(tmp_path)
    assert main(["check", str(scene_path)]) == 0
    out = capsys.readouterr().out
    assert "scene: floatel-like-100yr-head-seas" in out
    assert f"[file {env_path}]" in out
    assert "waves: jonswap  Hs 16 m  Tp 18.2 s" in out
    assert "models: waves:jonswap, wind:npd, current:piecewise_linear" in out
    assert out.rstrip().endswith(f"{scene_path}: OK")


@pytest.mark.parametrize("scene_changes, env_changes, text", [
    ({"site.water_depth": -150.0}, {}, "site.water_depth: expected a number > 0"),
    ({}, {"waves.hs": 0.0}, "waves.hs: expected a number > 0"),
    ({}, {"waves.spectrum": "jonswop"}, "one of: jonswap, pierson_moskowitz, torsethaugen"),
    ({"environment": "../metocean/missing.yaml"}, {}, "environment: expected a path to an "
                                                      "existing file"),
    ({"analysis.durration": 1.0}, {}, "unknown key 'durration'"),
])
def test_scene_error_prints_one_line_without_traceback_and_exits_2(tmp_path, capsys,
                                                                   scene_changes, env_changes,
                                                                   text):
    scene_path, _ = write_case(tmp_path, scene_changes, env_changes)
    assert main(["check", str(scene_path)]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.startswith("floatmoor: error: ")
    assert text in captured.err
    assert "Traceback" not in captured.err
    assert captured.err.count("\n") == 1


def test_missing_scene_file_exits_2(tmp_path, capsys):
    assert main(["check", str(tmp_path / "nope.yaml")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("floatmoor: error: ") and "nope.yaml" in err


def test_warnings_are_printed_plainly(tmp_path, capsys):
    scene_path, _ = write_case(tmp_path, {}, {"wind.u10": 70.0})
    assert main(["check", str(scene_path)]) == 0
    err = capsys.readouterr().err
    assert err.startswith("floatmoor: warning: ") and "wind.u10" in err
    assert "warnings.warn" not in err


def _install_failing_command(monkeypatch, exc):
    """Make `check` raise ``exc`` (to test the exit codes of failures other than SceneError)."""
    import floatmoor.cli as cli

    def run(args):
        raise exc

    new = [cli.Command(c.name, c.help, c.add_arguments, run)
           if isinstance(c, cli.Command) and c.name == "check" else c
           for c in cli.COMMANDS]
    monkeypatch.setattr(cli, "COMMANDS", new)


def test_numerical_error_exits_3(tmp_path, capsys, monkeypatch):
    _install_failing_command(monkeypatch, NumericalError("NaN in the state", time=12.5,
                                                         where="surge", remedy="reduce dt"))
    assert main(["check", "x.yaml"]) == 3
    err = capsys.readouterr().err
    assert "NaN in the state at t = 12.500 s in surge. Likely remedy: reduce dt" in err
    assert "Traceback" not in err


def test_keyboard_interrupt_exits_130_quietly(capsys, monkeypatch):
    _install_failing_command(monkeypatch, KeyboardInterrupt())
    assert main(["check", "x.yaml"]) == 130
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == "floatmoor: interrupted\n"


def test_python_dash_m_entry_point(tmp_path):
    done = subprocess.run([sys.executable, "-m", "floatmoor", "--version"], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 0
    assert done.stdout.strip() == f"floatmoor {floatmoor.__version__}"
    # a scene error through the real process: status 2, no traceback
    scene_path, _ = write_case(tmp_path, {"site.water_depth": 0.0})
    done = subprocess.run([sys.executable, "-m", "floatmoor", "check", str(scene_path)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 2
    assert done.stderr.startswith("floatmoor: error: ") and "Traceback" not in done.stderr


def test_cli_import_does_not_import_numba():
    # `floatmoor --help` and the parser must start fast: subcommands import heavy modules
    # (numba-compiled kernels) only when they run.
    code = ("import sys, floatmoor.cli; floatmoor.cli.build_parser(); "
            "print('NUMBA' if 'numba' in sys.modules else 'CLEAN')")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "CLEAN"


# -- environment ---------------------------------------------------------------------------------
def test_environment_prints_the_realised_statistics(tmp_path, capsys):
    importlib.import_module("floatmoor.metocean.summary")
    scene_path, _ = write_case(tmp_path)
    args = ["environment", str(scene_path), "--seed", "3", "--duration", "600", "--dt", "0.5"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert out.startswith("scene: floatel-like-100yr-head-seas")
    assert "seed 3, 600 s at dt = 0.5 s" in out and "water depth 150 m" in out
    for model in ("Waves: jonswap", "Wind: npd", "Current: piecewise_linear"):
        assert model in out
    assert main(args) == 0
    assert capsys.readouterr().out == out           # same seed: identical output
    assert main(["environment", str(scene_path), "--seed", "4", "--duration", "600",
                 "--dt", "0.5"]) == 0
    assert capsys.readouterr().out != out           # another seed: another realisation


def test_environment_defaults_come_from_the_scene(tmp_path, capsys):
    importlib.import_module("floatmoor.metocean.summary")
    scene_path, _ = write_case(tmp_path, {"analysis": {"duration": 300.0, "dt": 0.25,
                                                       "seeds": [7, 9]}},
                               {"wind": DELETE, "current": DELETE})
    assert main(["environment", str(scene_path)]) == 0
    captured = capsys.readouterr()
    out = captured.out
    # a 300 s statistics window is warned about, and the command still runs
    assert captured.err.startswith("floatmoor: warning: ") and "shorter than one hour" in captured.err
    assert "seed 7, 300 s at dt = 0.25 s" in out
    assert "Waves: jonswap" in out and "Wind:" not in out and "Current:" not in out


@pytest.mark.parametrize("extra, text", [(["--dt", "0"], "expected a number > 0"),
                                         (["--duration", "-5"], "expected a number > 0"),
                                         (["--seed", "-1"], "seed between 0 and 4294967295"),
                                         (["--seed", "x"], "integer seed"),
                                         (["--dt", "700", "--duration", "600"],
                                          "must be shorter than the duration")])
def test_environment_refuses_bad_options(tmp_path, capsys, extra, text):
    scene_path, _ = write_case(tmp_path)
    assert main(["environment", str(scene_path), *extra]) == 2
    err = capsys.readouterr().err
    assert text in err and "Traceback" not in err


def test_environment_scene_error_exits_2(tmp_path, capsys):
    scene_path, env_path = write_case(tmp_path, {}, {"waves.tp": -1.0})
    assert main(["environment", str(scene_path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"floatmoor: error: {env_path}: waves.tp")


# -- check reads the referenced vessel file --------------------------------------------------------
def test_check_reads_the_vessel_file_and_names_its_mistakes(tmp_path, capsys):
    importlib.import_module("floatmoor.hydro.vessel")
    (tmp_path / "vessels").mkdir()
    vessel = tmp_path / "vessels" / "vessel.yaml"
    vessel.write_text("name: broken\nmass: -1.0\ncentre_of_gravity: [0, 0, 0]\n"
                      "inertia_cg: [1, 1, 1]\ndatabase: db.nc\n")
    scene_path, _ = write_case(tmp_path, {"vessel": "../vessels/vessel.yaml"})
    assert main(["check", str(scene_path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"floatmoor: error: {vessel}: mass: expected a number > 0")
    # --quick validates the scene only
    assert main(["check", "--quick", str(scene_path)]) == 0
    assert f"vessel: {vessel}" in capsys.readouterr().out


def test_check_reads_a_real_vessel(tmp_path, capsys):
    importlib.import_module("floatmoor.hydro.vessel")
    from .io.test_example_scenes import REPO
    vessel = REPO / "vessels" / "oc3_hywind" / "vessel.yaml"
    assert vessel.exists(), "the shipped OC3-Hywind vessel file is missing"
    # the OC3 vessel file has no wind or current coefficients: the scene excludes those forces
    scene_path, _ = write_case(tmp_path, {"vessel": str(vessel.parent), "site.water_depth": 320.0,
                                          "forces": {"exclude": ["wind", "current"]}})
    assert main(["check", str(scene_path)]) == 0
    out = capsys.readouterr().out
    assert f"vessel: {vessel}" in out and "vessel file read: oc3_hywind" in out


def _one_line_mooring(length):
    # one studless R4 chain line of 84 mm from the shipped library, anchor 800 m out in 150 m
    return {"lines": [{"name": "L1", "anchor": {"x": 800.0, "y": 0.0},
                       "fairlead": [10.0, 0.0, -10.0],
                       "segments": [{"type": "chain_studless_R4", "diameter": 0.084,
                                     "length": length}]}]}


def test_check_reads_an_inline_mooring(tmp_path, capsys):
    importlib.import_module("floatmoor.io.mooring_section")
    scene_path, _ = write_case(tmp_path, {"mooring": _one_line_mooring(900.0)})
    assert main(["check", str(scene_path)]) == 0
    out = capsys.readouterr().out
    assert "mooring: inline mapping with keys lines" in out
    assert "mooring read: 1 lines; at zero offset fairlead tension" in out


def test_check_names_a_mooring_mistake_in_the_scene_file(tmp_path, capsys):
    importlib.import_module("floatmoor.io.mooring_section")
    scene_path, _ = write_case(tmp_path, {"mooring": _one_line_mooring(-900.0)})
    assert main(["check", str(scene_path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"floatmoor: error: {scene_path}: mooring.lines[0].segments[0].length")
    assert "Traceback" not in err


@pytest.mark.parametrize("name", [c.name for c in commands()])
def test_every_subcommand_has_help(name, capsys):
    assert main([name, "--help"]) == 0
    assert f"usage: floatmoor {name}" in capsys.readouterr().out
