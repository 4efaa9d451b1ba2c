"""The example scenes in scenes/ load and validate (the README and `floatmoor check` use them)."""

import warnings
from pathlib import Path

import pytest
import yaml

from floatmoor.cli import main
from floatmoor.io import load_scene

from .helpers import ENVIRONMENT

REPO = Path(__file__).resolve().parents[2]
SCENES = sorted((REPO / "scenes").glob("*.yaml"))
HEIDRUN = REPO / "metocean" / "heidrun_100yr.yaml"


def test_the_examples_are_there():
    names = {p.name for p in SCENES}
    assert {"floatel_100yr.yaml", "metocean_demo.yaml", "oc3_hywind.yaml"} <= names


def _load_without_warnings(path):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return load_scene(path)


@pytest.mark.parametrize("path", SCENES, ids=[p.name for p in SCENES])
def test_example_scene_checks(path, capsys):
    text = path.read_text()
    if "heidrun_100yr.yaml" in text and not HEIDRUN.exists():
        pytest.skip("metocean/heidrun_100yr.yaml not in this tree")
    scene = _load_without_warnings(path)
    for ref in (scene.vessel, scene.mooring):
        assert ref is None or ref.exists()
    assert main(["check", str(path)]) == 0          # reads the vessel and mooring files too
    out = capsys.readouterr().out
    assert out.rstrip().endswith(": OK")
    if scene.vessel is not None:
        assert "vessel file read:" in out
    if scene.mooring is not None:
        assert "mooring read:" in out


@pytest.mark.parametrize("name", ["floatel_100yr.yaml", "metocean_demo.yaml"])
def test_heidrun_scenes_hold_the_design_environment(name):
    if not HEIDRUN.exists():
        pytest.skip("metocean/heidrun_100yr.yaml not in this tree")
    scene = _load_without_warnings(REPO / "scenes" / name)
    assert scene.environment.name == "heidrun-100yr"
    w = scene.environment.waves
    # Wang (2016) section 5.2: Hs 16 m, Tp 18.2 s JONSWAP; wind 36 m/s; current 0.94 m/s; head seas
    assert (w.spectrum, w.hs, w.tp, w.heading) == ("jonswap", 16.0, 18.2, 0.0)
    assert scene.environment.wind.u10 == 36.0
    assert scene.environment.current.speed[0] == 0.94
    assert scene.site.water_depth == 150.0


def test_oc3_scene_is_the_openfast_sea_state():
    # OpenFAST r-test 5MW_OC3Spar_DLL_WTurb_WavesIrr/SeaState.dat: WaveHs 6, WaveTp 10,
    # WaveDir 0, depth 320 m
    scene = _load_without_warnings(REPO / "scenes" / "oc3_hywind.yaml")
    w = scene.environment.waves
    assert (w.hs, w.tp, w.heading, w.random_amplitudes) == (6.0, 10.0, 0.0, True)
    assert scene.site.water_depth == 320.0
    assert scene.environment.wind is None and scene.environment.current is None


def test_floatel_scene_with_a_local_environment_copy(tmp_path):
    # The example scene's relative reference works from any folder holding the same layout.
    (tmp_path / "scenes").mkdir()
    (tmp_path / "metocean").mkdir()
    scene_file = tmp_path / "scenes" / "floatel_100yr.yaml"
    data = yaml.safe_load((REPO / "scenes" / "floatel_100yr.yaml").read_text())
    for key in ("vessel", "mooring"):   # tested in the repo test above when present
        data.pop(key, None)
    scene_file.write_text(yaml.safe_dump(data))
    (tmp_path / "metocean" / "heidrun_100yr.yaml").write_text(yaml.safe_dump(ENVIRONMENT))
    scene = load_scene(scene_file)
    a = scene.analysis
    # 12000 s with a 1200 s transient leaves the 3-hour window of Wang (2016) (SIMO runs of 12000 s)
    assert (a.duration, a.transient, a.duration - a.transient) == (12000.0, 1200.0, 10800.0)
    assert a.seeds == tuple(range(1, 21))
