"""Campaign files: validation (every mistake a SceneError naming file and key) and the matrix."""

import math
from pathlib import Path

import pytest

from floatmoor.campaign.matrix import build_matrix, case_scene
from floatmoor.campaign.spec import load_campaign
from floatmoor.core.errors import SceneError

HERE = Path(__file__).parent
ROOT = HERE.parent.parent


def _write(tmp_path, text):
    p = tmp_path / "c.yaml"
    base = (ROOT / "scenes" / "floatel_100yr.yaml").as_posix()
    p.write_text(text.replace("BASE", base))
    return p


GOOD = """
name: t
base_scene: BASE
sea_states: {list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: 16.0, tp: 18.2}]}
headings: {waves_deg: {start: 0, stop: 90, step: 45}, current_offset_deg: [0, 30]}
conditions: {intact: true, failed_lines: [[line6]], line_failure: {lines: [line7], time: 200.0}}
seeds: "1-3"
analysis: {duration: 600.0, dt: 0.2, transient: 100.0}
"""


def test_example_campaign_matrix():
    """The example: 7 contour sea states x 24 headings x (intact + 12 single-line ALS)."""
    spec = load_campaign(ROOT / "campaigns" / "floatel_uls_als.yaml")
    cases = build_matrix(spec)
    assert len(spec.sea_states) == 7 and len(spec.wave_headings_deg) == 24
    assert spec.wave_headings_deg[-1] == 345.0
    assert len(spec.conditions) == 13 and len(cases) == 7 * 24 * 13
    assert len({c.id for c in cases}) == len(cases)
    assert spec.seeds == tuple(range(1, 21))


def test_matrix_and_case_scene(tmp_path):
    spec = load_campaign(_write(tmp_path, GOOD))
    cases = build_matrix(spec)
    # 2 sea states x 3 wave headings x 2 current offsets x 3 conditions
    assert len(cases) == 2 * 3 * 2 * 3
    from floatmoor import load_scene
    base = load_scene(spec.base_scene)
    c = next(c for c in cases if c.wave_heading_deg == 45.0 and c.current_heading_deg == 75.0
             and c.condition.kind == "transient" and c.sea_state.name == "b")
    scene, failed = case_scene(base, c, dict(spec.analysis))
    env = scene.environment
    assert failed is None
    assert env.waves.hs == 16.0 and env.waves.tp == 18.2
    assert math.isclose(env.waves.heading, math.radians(45.0))
    assert math.isclose(env.wind.heading, math.radians(45.0))
    assert math.isclose(env.current.heading, math.radians(75.0))
    assert scene.forces.line_failure == {"line7": 200.0}
    assert scene.analysis.duration == 600.0 and scene.analysis.dt == 0.2
    f = next(c for c in cases if c.condition.kind == "failed")
    assert case_scene(base, f)[1] == ["line6"]
    assert base.environment.waves.hs == 16.0 and base.forces is None  # base untouched


@pytest.mark.parametrize("old, new, key", [
    ("name: t", "name: t\nbogus: 1", "bogus"),
    ("step: 45", "step: -45", "headings.waves_deg.step"),
    ("[[line6]]", "[[line66]]", "conditions.failed_lines[0]"),
    ('seeds: "1-3"', 'seeds: "1-2"', "seeds"),
    ("hs: 10.0", "hs: -1.0", "sea_states.list[0].hs"),
    ("time: 200.0", "time: 900.0", "conditions.line_failure.time"),
    ("time: 200.0", "time: 50.0", "conditions.line_failure.time"),   # before the statistics
    ("transient: 100.0}", "transient: 100.0}\nstorage: {sampling: {motion: 0.3}}",
     "storage.sampling.motion"),
    ("current_offset_deg: [0, 30]", "current_offset_deg: [0, 0]",
     "headings.current_offset_deg"),
])
def test_mistakes_name_file_and_key(tmp_path, old, new, key):
    p = _write(tmp_path, GOOD.replace(old, new))
    with pytest.raises(SceneError) as e:
        load_campaign(p)
    assert e.value.key == key
    assert Path(e.value.file) == p
    assert "expected" in str(e.value)


@pytest.mark.slow  # the dry run calibrates and screens 12 FD cases: 20-80 s on the loaded machine
def test_cli_dry_run_and_input_error(tmp_path, capsys):
    from floatmoor.cli import main
    assert main(["campaign", str(HERE / "tiny.yaml"), "--dry-run", "--workers", "2",
                 "--fd-budget", "600"]) == 0
    out = capsys.readouterr().out
    assert "= 12 case(s); 3 seed(s)" in out and "FD cases: 12" in out
    n_td = int(out.split("TD cases after screening: ")[1].split()[0])
    assert 2 <= n_td <= 12  # the FD was run (cheap): the exact count, at least one per state
    assert f"storms: {3 * n_td}" in out and "storage (full mode)" in out
    assert "on 512 core(s)" in out
    bad = _write(tmp_path, GOOD.replace("seeds:", "seed:"))
    assert main(["campaign", str(bad), "--dry-run"]) == 2
    err = capsys.readouterr().err
    assert f"{bad}: seed: expected one of the keys" in err and "Traceback" not in err


@pytest.mark.parametrize("old, new, key", [
    ("sea_states: {list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: 16.0, tp: 18.2}]}",
     "sea_states: {scatter: SCATTER}", "sea_states.scatter"),
    ("{name: a, hs: 10.0, tp: 12.5}", "{name: a, hs: 10.0, tp: 12.5, probability: 0.01}",
     "sea_states.list[0].probability"),
])
def test_scatter_and_probabilities_refused(tmp_path, old, new, key):
    """A ULS/ALS campaign checks extreme sea states (a contour or a list); a scatter diagram or
    a sea state probability would be silently meaningless there: refused, pointing to the
    fatigue command that uses them."""
    text = GOOD.replace(old, new).replace(
        "SCATTER", (ROOT / "metocean" / "floatel_like_scatter.yaml").as_posix())
    p = _write(tmp_path, text)
    with pytest.raises(SceneError) as e:
        load_campaign(p)
    assert e.value.key == key and Path(e.value.file) == p
    assert "contour" in str(e.value) and "floatmoor fatigue" in str(e.value)


def test_design_code_from_the_campaign_file(tmp_path):
    """``design: standard`` names a code of floatmoor/data/codes (alias or key) or a code file;
    the analysis is auto (the line model) unless the file says otherwise."""
    spec = load_campaign(_write(tmp_path, GOOD))
    assert spec.design.standard == "dnv-os-e301-2008" and spec.design.analysis == "auto"
    spec = load_campaign(_write(tmp_path, GOOD + "design: {standard: api-rp-2sk}\n"))
    assert spec.design.standard == "api-rp-2sk-2005"
    p = _write(tmp_path, GOOD + "design: {standard: dnv-os-e301-2018}\n")
    with pytest.raises(SceneError) as e:
        load_campaign(p)
    assert e.value.key == "design.standard" and "dnv-os-e301-2008" in str(e.value)
