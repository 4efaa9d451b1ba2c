"""Hostile and careless campaign input: each case ends in exit status 2 before anything runs,
with a message naming the file and the key (or option) and no traceback; results read back
are checked (a corrupted, truncated, sign-flipped, mislabelled or stale result file is refused
naming it, never silently dropped from a fit); a folder of another campaign is refused.

The campaign cases run ``floatmoor campaign FILE --dry-run`` in-process: every refusal comes
from reading the campaign (and building its base scene), before the dry run's calibration.
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import numpy as np
import pytest

from floatmoor.cli import main
from floatmoor.core.errors import SceneError

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

HERE = Path(__file__).parent
ROOT = HERE.parents[1]

GOOD = """
name: hostile
base_scene: BASE
sea_states: {list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: 16.0, tp: 18.2}]}
headings: {waves_deg: [0, 45, 90], wind_offset_deg: [0], current_offset_deg: [0, 30]}
conditions: {intact: true, failed_lines: [[line6], [line7]]}
seeds: "1-3"
analysis: {duration: 600.0, dt: 0.2, transient: 100.0}
"""


def _write(tmp_path, text, name="c.yaml"):
    p = tmp_path / name
    p.write_text(text.replace("BASE", (ROOT / "scenes" / "floatel_100yr.yaml").as_posix()))
    return p


def _cli(argv, capsys):
    code = main([str(a) for a in argv])
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err + cap.out
    return code, cap.err


def test_the_good_file_passes(tmp_path):
    from floatmoor.campaign.matrix import build_matrix
    from floatmoor.campaign.spec import load_campaign
    spec = load_campaign(_write(tmp_path, GOOD))
    assert len(build_matrix(spec)) == 2 * 3 * 2 * 3


# -- refused when the campaign file is read: (old, new, key, words) --------------------------
CASES = {
    "headings in radians": ("[0, 45, 90]", "[0, 0.7854, 1.5708, 3.1416]",
                            "headings.waves_deg", "radians"),
    "heading range to 2 pi": ("[0, 45, 90]", "{start: 0, stop: 6.2832, step: 0.7854}",
                              "headings.waves_deg", "radians"),
    "wind offset pi": ("wind_offset_deg: [0]", "wind_offset_deg: [3.1416]",
                       "headings.wind_offset_deg", "radians"),
    "the same direction twice": ("[0, 45, 90]", "[0, 360]", "headings.waves_deg",
                                 "same direction"),
    "directions 0.04 apart and 360": ("[0, 45, 90]", "[0, 0.04, 360]", "headings.waves_deg",
                                      "same direction"),
    "a condition twice": ("[[line6], [line7]]", "[[line6], [line6]]",
                          "conditions.failed_lines[1]", "listed before"),
    "a condition twice in another order": ("[[line6], [line7]]",
                                           "[[line6, line7], [line7, line6]]",
                                           "conditions.failed_lines[1]", "listed before"),
    "a line twice in a condition": ("[[line6], [line7]]", "[[line6, line6]]",
                                    "conditions.failed_lines[0]", "distinct"),
    "a sea state twice": ("{name: b, hs: 16.0, tp: 18.2}", "{name: b, hs: 10.0, tp: 12.5}",
                          "sea_states.list", "distinct sea states"),
    "contour sea state steeper than a scene accepts": (
        "{name: b, hs: 16.0, tp: 18.2}", "{name: b, hs: 16.0, tp: 8.0}", "sea_states.list[1].hs",
        "does not break"),
    "gamma below 1": ("{name: a, hs: 10.0, tp: 12.5}", "{name: a, hs: 10.0, tp: 12.5, gamma: 0.5}",
                      "sea_states.list[0].gamma", ">= 1"),
    "a heading range of a million values": ("[0, 45, 90]", "{start: 0, stop: 345, step: 0.0001}",
                                            "headings.waves_deg.step", "at most 3600"),
    "dt of 100 (milliseconds)": ("dt: 0.2", "dt: 100", "analysis.dt", "resolves the sea state"),
    "duration shorter than the transient": ("duration: 600.0", "duration: 60.0",
                                            "analysis.duration", "longer than the transient"),
    "break after the end of the storm": ("failed_lines: [[line6], [line7]]",
                                         "line_failure: {lines: [line6], time: 1500.0}",
                                         "conditions.line_failure.time", "never break"),
    "base scene a folder": ("base_scene: BASE", "base_scene: " + (ROOT / "scenes").as_posix(),
                            "base_scene", "not a folder"),
    "a scatter diagram": ("sea_states: {list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: "
                          "16.0, tp: 18.2}]}", "sea_states: {scatter: x.yaml}",
                          "sea_states.scatter", "fatigue"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_campaign_file_mistakes_are_refused_before_anything_runs(case, tmp_path, capsys):
    old, new, key, words = CASES[case]
    assert old in GOOD or old == "base_scene: BASE"
    p = _write(tmp_path, GOOD.replace(old, new, 1))
    t0 = time.monotonic()
    code, err = _cli(["campaign", p, "--dry-run"], capsys)
    assert code == 2, err
    assert err.startswith(f"floatmoor: error: {p}: {key}") and words in err, err
    assert time.monotonic() - t0 < 30.0
    assert not (tmp_path / "results").exists()


def test_a_matrix_of_a_million_cases_is_refused_before_allocation(tmp_path, capsys):
    """7 sea states x 3600 headings x 40 offsets = 1,008,000 cases: refused with the size and
    the limit, without building the matrix."""
    import resource
    text = GOOD.replace("[0, 45, 90]", "{start: 0, stop: 359.9, step: 0.1}").replace(
        "current_offset_deg: [0, 30]", "current_offset_deg: {start: -39, stop: 39, step: 2}")
    text = text.replace("{list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: 16.0, tp: 18.2}]}",
                        "{contour: " + (ROOT / "metocean/heidrun_contour.yaml").as_posix() + "}")
    text = text.replace("failed_lines: [[line6], [line7]]", "failed_lines: [[line6]]")
    text = text.replace("intact: true, ", "intact: false, ")
    p = _write(tmp_path, text)
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    code, err = _cli(["campaign", p, "--dry-run"], capsys)
    assert code == 2 and f"{p}: headings" in err and "at most 50,000 cases" in err, err
    assert "7 x 3600 x 1 x 40 x 1 = 1,008,000 cases" in err
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 200_000  # kB


def test_binary_garbage_and_control_characters_are_refused(tmp_path, capsys):
    p = tmp_path / "garbage.yaml"
    p.write_bytes(bytes(range(1, 32)) * 40)
    code, err = _cli(["campaign", p, "--dry-run"], capsys)
    assert code == 2 and f"{p}: line 1, column 1" in err and "control character" in err, err
    p.write_bytes(os.urandom(4000))
    code, err = _cli(["campaign", p, "--dry-run"], capsys)
    assert code == 2 and str(p) in err, err


@pytest.mark.parametrize("argv,key,words", [
    (["--duration", "600"], "--duration", "longer than the transient (1200 s"),
    (["--duration", "1e15"], "--duration", "at most"),
])
def test_command_line_times_checked_against_the_campaign(argv, key, words, capsys, tmp_path):
    camp = ROOT / "campaigns" / "floatel_uls_als.yaml"
    code, err = _cli(["campaign", camp, "--out", tmp_path / "out", *argv], capsys)
    assert code == 2 and f"{camp}: {key}" in err and words in err, err
    assert not (tmp_path / "out").exists()   # nothing created


def test_a_break_outside_the_storm_given_on_the_command_line(capsys, tmp_path):
    camp = HERE / "transient.yaml"
    code, err = _cli(["campaign", camp, "--duration", "100", "--out", tmp_path / "o"], capsys)
    assert code == 2 and f"{camp}: conditions.line_failure.time" in err, err
    assert "(100 s, --duration)" in err and "never break" in err
    assert not (tmp_path / "o").exists()


def test_worker_found_errors_are_scene_errors_before_any_case(tmp_path, capsys):
    """A vessel of mass 0 in the base scene: refused when the campaign is read (exit 2 naming
    the vessel file), not a failed case per worker."""
    vdir = tmp_path / "v"
    vdir.mkdir()
    src = ROOT / "vessels" / "floatel_like"
    text = (src / "vessel.yaml").read_text()
    import re
    (vdir / "vessel.yaml").write_text(re.sub(r"^mass: .*$", "mass: 1.0", text, flags=re.M)
                                      .replace("database: database.nc",
                                               f"database: {(src / 'database.nc').as_posix()}"))
    scene = (ROOT / "scenes" / "floatel_100yr.yaml").read_text()
    scene = scene.replace("../vessels/floatel_like/vessel.yaml", (vdir / "vessel.yaml").as_posix())
    scene = scene.replace("../metocean/", (ROOT / "metocean").as_posix() + "/")
    scene = scene.replace("../vessels/floatel_like/mooring.yaml",
                          (src / "mooring.yaml").as_posix())
    (tmp_path / "base.yaml").write_text(scene)
    p = tmp_path / "c.yaml"
    p.write_text(GOOD.replace("BASE", (tmp_path / "base.yaml").as_posix()))
    code, err = _cli(["campaign", p, "--out", tmp_path / "out"], capsys)
    assert code == 2 and f"{vdir / 'vessel.yaml'}: mass" in err, err
    assert not (tmp_path / "out").exists()


# -- the campaign folder ----------------------------------------------------------------------
def _record(folder, name="other", **extra):
    from floatmoor.campaign import store
    folder.mkdir(parents=True, exist_ok=True)
    rec = {"name": name, "seeds": [1, 2, 3], "design": {}, "cases": [], "lines": [],
           "campaign_file": "/somewhere/other.yaml", **extra}
    (folder / store.RECORD).write_text(json.dumps(rec))
    store.Manifest(folder)


def test_a_folder_of_another_campaign_is_refused_unless_forced(tmp_path, capsys):
    from floatmoor.campaign.engine import _check_folder
    from floatmoor.campaign.spec import load_campaign
    out = tmp_path / "out"
    _record(out, "other")
    p = _write(tmp_path, GOOD)
    code, err = _cli(["campaign", p, "--out", out], capsys)
    assert code == 2 and f"{p}: name" in err and "'other'" in err and "--force" in err, err
    spec = load_campaign(p)
    said = []
    _check_folder(spec, out, True, said.append)          # --force: reused, and said so
    assert "reusing the folder of the campaign 'other'" in said[0]
    run = tmp_path / "run"
    run.mkdir()
    (run / "scene_seed0001.nc").write_bytes(b"x")
    code, err = _cli(["campaign", p, "--out", run], capsys)
    assert code == 2 and "a folder of other results (scene_seed0001.nc" in err, err


@pytest.mark.parametrize("content,words", [(b"", "an empty file"),
                                           (b'{"name": "x", "seeds": [1, 2', "truncated JSON"),
                                           (b'{"name": "x"}', "missing: seeds")])
def test_a_damaged_campaign_record_names_the_file(tmp_path, capsys, content, words):
    from floatmoor.campaign import store
    _record(tmp_path / "c")
    rec = tmp_path / "c" / store.RECORD
    rec.write_bytes(content)
    with pytest.raises(SceneError) as e:
        store.read_record(tmp_path / "c")
    assert str(rec) in str(e.value) and words in str(e.value)
    code, err = _cli(["report", tmp_path / "c", "--out", tmp_path / "r"], capsys)
    assert code == 2 and str(rec) in err and words in err, err
    p = _write(tmp_path, GOOD)
    code, err = _cli(["campaign", p, "--out", tmp_path / "c"], capsys)
    assert code == 2 and str(rec) in err, err


def test_a_folder_in_use_is_refused(tmp_path, capsys):
    import fcntl

    from floatmoor.analyses.folder_lock import LOCK_NAME
    out = tmp_path / "busy"
    out.mkdir()
    fd = os.open(out / LOCK_NAME, os.O_RDWR | os.O_CREAT)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        os.write(fd, b"pid 4242 (floatmoor campaign x, since 2026-01-01 00:00:00)\n")
        code, err = _cli(["campaign", _write(tmp_path, GOOD), "--out", out], capsys)
    finally:
        os.close(fd)
    assert code == 2 and f"{out}: expected an output folder that no other floatmoor" in err
    assert "pid 4242" in err, err


# -- results read back ----------------------------------------------------------------------
def _storm_file(path, case="c1", seed=1, **change):
    import xarray as xr

    from floatmoor.analyses.fingerprint import FINGERPRINT_ATTR
    n = 3
    v = {"line_tension_max": np.array([2.0e6, 2.2e6, 1.9e6]),
         "line_tension_mean": np.array([1.0e6, 1.1e6, 0.9e6]),
         "line_tension_min": np.array([0.5e6, 0.6e6, 0.4e6]),
         "line_tension_std": np.array([1e5, 1e5, 1e5]),
         "anchor_tension_max": np.array([1.8e6, 2.0e6, 1.7e6]),
         "mbs": np.full(n, 8.5e6)}
    v.update({k: np.asarray(x, float) for k, x in change.items() if k in v})
    ds = xr.Dataset({k: ("line", x) for k, x in v.items()})
    ds["offset_max"] = change.get("offset_max", 20.0)
    ds["offset_mean"] = 10.0
    for k in ("motion_max", "motion_min", "motion_mean", "motion_std"):
        ds[k] = ("dof", np.zeros(6))
    ds.attrs = {"case": case, "seed": seed, FINGERPRINT_ATTR: json.dumps({"a": "1"})}
    path.parent.mkdir(parents=True, exist_ok=True)
    ds.to_netcdf(path)
    return path


@pytest.mark.parametrize("change,key", [
    ({"line_tension_max": [2.0e6, np.nan, 1.9e6]}, "line_tension_max"),
    ({"line_tension_max": [-2.0e6, -2.2e6, -1.9e6], "line_tension_mean": [-1e6, -1.1e6, -0.9e6],
      "line_tension_min": [-3e6, -3e6, -3e6]}, "line_tension_max"),
    ({"line_tension_max": [2.0e6, 1e9, 1.9e6]}, "line_tension_max"),
    ({"line_tension_mean": [3.0e6, 1.1e6, 0.9e6]}, "line_tension_mean"),
    ({"offset_max": np.inf}, "offset_max"),
])
def test_corrupted_storm_statistics_are_refused_naming_the_file(tmp_path, change, key):
    """A storm with a NaN maximum, sign-flipped tensions, a tension beyond 10 x MBS, a mean above
    its maximum or an infinite offset is never fitted (nor silently left out of a fit)."""
    from floatmoor.campaign import store
    p = _storm_file(store.storm_path(tmp_path, "c1", 1), **change)
    with pytest.raises(SceneError) as e:
        store.load_td_statistics(tmp_path, ["c1"], [1], expected={})
    assert e.value.file == str(p) and e.value.key == key, str(e.value)


def test_truncated_mislabelled_and_stale_storm_files_are_refused(tmp_path):
    from floatmoor.analyses.fingerprint import fingerprint_digest
    from floatmoor.campaign import store
    p = _storm_file(store.storm_path(tmp_path, "c1", 1))
    good = store.load_td_statistics(tmp_path, ["c1"], [1],
                                    expected={"c1": fingerprint_digest({"a": "1"})})
    assert good["line_tension_max"].shape == (1, 1, 3)
    with pytest.raises(SceneError) as e:          # computed from other inputs
        store.load_td_statistics(tmp_path, ["c1"], [1], expected={"c1": "0123456789abcdef"})
    assert e.value.file == str(p) and "rerun the campaign" in str(e.value)
    q = _storm_file(store.storm_path(tmp_path, "c1", 2), case="c9")   # another case's file
    with pytest.raises(SceneError) as e:
        store.load_td_statistics(tmp_path, ["c1"], [2], expected={})
    assert e.value.file == str(q) and e.value.key == "case"
    data = p.read_bytes()
    p.write_bytes(data[: len(data) // 2])                            # truncated
    with pytest.raises(SceneError) as e:
        store.load_td_statistics(tmp_path, ["c1"], [1], expected={})
    assert e.value.file == str(p) and "truncated" in str(e.value)
    # an absent file is a storm not run yet: NaN, not an error
    out = store.load_td_statistics(tmp_path, ["c1"], [3], expected={})
    assert out == {}


def test_manifest_of_an_older_version_is_upgraded(tmp_path):
    """A manifest written without the fingerprint column is rewritten with today's columns,
    so that rows appended now are read back by name (else every resume recomputes)."""
    from floatmoor.campaign import store
    old = ("kind,case,seed,status,wall_time_s,path,bytes,sha256\n"
           "fd,c1,-1,done,1.0,fd/c1.nc,10,abc\n")
    (tmp_path / store.MANIFEST).write_text(old)
    m = store.Manifest(tmp_path)
    m.append({"kind": "td", "case": "c1", "seed": 1, "status": "done", "fingerprint": "f1"}, {})
    rows = m.latest()
    assert rows[("fd", "c1", -1)]["bytes"] == "10"
    assert rows[("td", "c1", 1)]["fingerprint"] == "f1"
