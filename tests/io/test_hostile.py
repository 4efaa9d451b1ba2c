"""Hostile and careless input: every class of bad input ends in exit status 2 with a message
naming the file (or the option) and the key, without a traceback, in bounded time and memory.

The YAML bombs run in a child process with a memory limit (``RLIMIT_AS``) and a time limit;
the other cases run ``floatmoor.cli.main`` in-process (an unexpected exception would fail the
test with its traceback)."""

from __future__ import annotations

import re
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from floatmoor.cli import main

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

ROOT = Path(__file__).resolve().parents[2]
MEM_LIMIT = 1500 * 2**20


@pytest.fixture(scope="module")
def tree(tmp_path_factory):
    """A copy of the example scenes, metocean files and two vessels (mutated per test)."""
    root = tmp_path_factory.mktemp("hostile")
    for d in ("scenes", "metocean", "vessels/floatel_like", "vessels/oc3_hywind"):
        shutil.copytree(ROOT / d, root / d, ignore=shutil.ignore_patterns("source", "*.py",
                                                                            "results"))
    return root


def _mutate(tree: Path, rel: str, old: str, new: str, name: str) -> Path:
    text = (tree / rel).read_text()
    assert old in text, old
    p = (tree / rel).parent / name
    p.write_text(text.replace(old, new, 1))
    return p


def _scene_with(tree: Path, name: str, **refs) -> Path:
    """The Floatel scene with its vessel/mooring/environment replaced by mutated files."""
    text = (tree / "scenes/floatel_100yr.yaml").read_text()
    for key, path in refs.items():
        text = re.sub(rf"^{key}: .*$", f"{key}: {path}", text, count=1, flags=re.M)
    p = tree / "scenes" / name
    p.write_text(text)
    return p


def _cli(argv, capsys):
    code = main([str(a) for a in argv])
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err + cap.out
    return code, cap.err


def _limited():
    resource.setrlimit(resource.RLIMIT_AS, (MEM_LIMIT, MEM_LIMIT))


def _cli_bounded(argv, timeout=120.0):
    """``python -m floatmoor`` in a child process with a memory limit; (status, stderr, s)."""
    t0 = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "floatmoor", *map(str, argv)],
                          capture_output=True, text=True, timeout=timeout, preexec_fn=_limited)
    assert "Traceback" not in done.stderr + done.stdout
    return done.returncode, done.stderr, time.monotonic() - t0


# -- 1. YAML bombs and oversized numbers: refused before expansion or conversion --------------
LAUGHS = "".join(f"{a}: &{a} [{', '.join(['*' + b] * 9) if b else ', '.join(['1'] * 9)}]\n"
                 for a, b in zip("abcdefgh", ["", "a", "b", "c", "d", "e", "f", "g"]))

YAML_CASES = {
    "recursive alias": ("name: x\nsite: {water_depth: 150.0}\nlevels: &r [*r]\n",
                        "recursive alias"),
    "billion laughs as a number": (LAUGHS + "name: x\nsite: {water_depth: *h}\n",
                                   "expanding to at most"),
    "deep nesting": ("name: x\nsite: {water_depth: 150.0}\nanalysis: " + "[" * 3000
                     + "]" * 3000 + "\n", "nested at most"),
    "400-digit integer": ("name: x\nsite: {water_depth: " + "9" * 400 + "}\n",
                          "a number of at most"),
    "5000-digit integer": ("name: x\nsite: {water_depth: " + "9" * 5000 + "}\n",
                           "a number of at most"),
}


@pytest.mark.parametrize("case", sorted(YAML_CASES))
def test_yaml_bombs_are_refused_in_bounded_time_and_memory(case, tmp_path):
    text, expected = YAML_CASES[case]
    p = tmp_path / "bomb.yaml"
    p.write_text(text)
    code, err, secs = _cli_bounded(["check", "--quick", p])
    assert code == 2, err
    assert str(p) in err and expected in err
    assert secs < 60.0
    assert len(err) < 2000  # the message shortens the value without building it whole


def test_error_message_shortens_a_huge_value_without_building_it():
    from floatmoor.core.errors import SceneError

    x = [1] * 9
    for _ in range(9):  # 9**10 leaves, shared: the full repr would be gigabytes
        x = [x] * 9
    t0 = time.monotonic()
    msg = str(SceneError("f.yaml", "k", "a number", x))
    assert time.monotonic() - t0 < 1.0 and len(msg) < 200
    import numpy as np
    msg = str(SceneError("f.yaml", "k", "a number", [np.float64(0.5), np.float64(1.0)]))
    assert "np.float64" not in msg and "[0.5, 1.0]" in msg


# -- 2. size bounds at check time, before anything is allocated -----------------------------
SIZE_CASES = [
    ("dt: 0.1 ", "dt: 1.0e-9 ", "analysis.dt", "would need at least"),
    ("duration: 12000.0", "duration: 1.0e+12", "analysis.dt", "would need at least"),
    ("seeds: [1, 20]", "seeds: [0, 4294967295]", "analysis.seeds", "at most 100000 seeds"),
    ("seeds: [1, 20]", "seeds: [0, 5000000000]", "analysis.seeds", "between 0 and"),
    ("seeds: [1, 20]", "seeds: '1-4294967295'", "analysis.seeds", "at most 100000 seeds"),
    ("seeds: [1, 20]", "seeds: '1-99999999999999999999'", "analysis.seeds", "between 0 and"),
]


@pytest.mark.parametrize("old,new,key,words", SIZE_CASES)
def test_sizes_bounded_at_check(tree, capsys, old, new, key, words):
    p = _mutate(tree, "scenes/floatel_100yr.yaml", old, new, "size.yaml")
    t0 = time.monotonic()
    code, err = _cli(["check", "--quick", p], capsys)
    assert code == 2 and str(p) in err and key in err and words in err, err
    assert time.monotonic() - t0 < 10.0


@pytest.mark.parametrize("waves_extra,key", [
    ("  discretisation: {n_frequencies: 100000000}\n", "n_frequencies"),
    ("  spreading: cos2s\n  spreading_s: 10\n  n_directions: 1000000\n", "n_directions"),
])
def test_wave_component_counts_bounded(tree, capsys, waves_extra, key):
    env = _mutate(tree, "metocean/heidrun_100yr.yaml", "  heading_deg: 0.0\nwind",
                  "  heading_deg: 0.0\n" + waves_extra + "wind", "big_env.yaml")
    p = _scene_with(tree, "big_env_scene.yaml", environment=f"../metocean/{env.name}")
    code, err = _cli(["check", "--quick", p], capsys)
    assert code == 2 and str(env) in err and key in err, err


def test_long_duration_bounded_through_the_implied_wave_components(tree, capsys):
    """Without n_frequencies the wave components grow with the duration: 9e6 s at dt 0.5 s is
    within the time-step bound but would need millions of components."""
    p = _mutate(tree, "scenes/floatel_100yr.yaml", "dt: 0.1 ", "dt: 0.5 ", "long0.yaml")
    p = _mutate(tree, "scenes/" + p.name, "duration: 12000.0", "duration: 9.0e+6", "long.yaml")
    code, err = _cli(["check", "--quick", p], capsys)
    assert code == 2 and str(p) in err and "analysis.duration" in err and "components" in err


@pytest.mark.parametrize("argv,words", [
    (["--seeds", "1-4294967295"], "at most 100000 seeds"),
    (["--seeds", "5000000000"], "between 0 and 4294967295"),
    (["--seeds", "1-99999999999999999999"], "between 0 and"),
    (["--dt", "1e-9"], "--dt"),
    (["--workers", "0"], "integer >= 1"),
])
def test_run_command_line_bounds(tree, capsys, tmp_path, argv, words):
    code, err = _cli(["run", tree / "scenes/oc3_hywind.yaml", "--out", tmp_path / "o", *argv],
                     capsys)
    assert code == 2 and words in err, err
    assert not list((tmp_path).glob("o/*.nc"))


# -- 3. --out problems are usage errors naming the path --------------------------------------
def test_out_problems_are_usage_errors(tree, capsys, tmp_path):
    f = tmp_path / "a_file"
    f.write_text("x")
    d = tmp_path / "a_dir"
    d.mkdir()
    scene = tree / "scenes/oc3_hywind.yaml"
    for argv, words in [(["run", scene, "--out", f], "expected a folder"),
                        (["run", scene, "--out", f / "sub"], "is a file"),
                        (["fd", scene, "--out", d], "existing folder"),
                        (["fd", scene, "--out", f / "x.nc"], "is a file")]:
        code, err = _cli(argv, capsys)
        assert code == 2 and str(argv[3]) in err and words in err, (argv, err)


# -- 5. physical plausibility at check ------------------------------------------------------
V = "vessels/floatel_like/vessel.yaml"
M = "vessels/floatel_like/mooring.yaml"
PLAUSIBILITY = [
    (V, "mass: 2.5472e+7", "mass: 2.5472e+4", "mass", "tonnes"),
    (V, "centre_of_gravity: [0.0, 0.0, 7.0]", "centre_of_gravity: [0.0, 0.0, 60.0]",
     "centre_of_gravity", "metacentre"),
    (V, "heading_deg: [0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330]\n  surge: [1543.0",
     "heading_deg: [0, 0.5236, 1.0472, 1.5708, 2.0944, 2.618, 3.1416, 3.6652, 4.1888, 4.7124, "
     "5.236, 5.7596]\n  surge: [1543.0", "wind_coefficients.heading_deg", "radians"),
    (V, "wind_coefficients:", "wind_coefficientz:", "wind_coefficientz", "one of the keys"),
    (V, "quadratic_drag_per_length:", "quadratic_drag_per_lenght:", "slender_elements", ""),
    (M, "material: chain", "material: chian", "material", "one of: chain"),
    (M, "length: 1200.0", "length: 10.0", "segments", "MBS"),
]


@pytest.mark.parametrize("rel,old,new,key,words", PLAUSIBILITY)
def test_plausibility_refused_at_check(tree, capsys, rel, old, new, key, words):
    m = _mutate(tree, rel, old, new, "implausible_" + Path(rel).name)
    kw = {"vessel" if rel == V else "mooring": f"../{rel.rsplit('/', 1)[0]}/{m.name}"}
    p = _scene_with(tree, "implausible.yaml", **kw)
    code, err = _cli(["check", p], capsys)
    assert code == 2 and str(m) in err and key in err and words in err, err


def test_wind_without_coefficients_refused_at_check(tree, capsys):
    text = (tree / V).read_text()
    start = text.index("wind_coefficients:")
    end = text.index("current_coefficients:")
    m = tree / "vessels/floatel_like/no_wind.yaml"
    m.write_text(text[:start] + text[end:])
    p = _scene_with(tree, "no_wind_scene.yaml", vessel="../vessels/floatel_like/no_wind.yaml")
    code, err = _cli(["check", p], capsys)
    assert code == 2 and str(m) in err and "wind_coefficients" in err, err


def test_anchor_above_seabed_must_be_declared(tree, capsys):
    text = (tree / M).read_text()
    anchor = re.search(r"anchor: \{[^}]*\}", text).group(0)
    m = _mutate(tree, M, anchor, anchor.replace("}", ", z: -30.0}"), "floating_anchor.yaml")
    p = _scene_with(tree, "floating_anchor_scene.yaml",
                    mooring="../vessels/floatel_like/floating_anchor.yaml")
    code, err = _cli(["check", p], capsys)
    assert code == 2 and str(m) in err and "anchor" in err and "above_seabed" in err, err


def test_depth_against_database_and_draft():
    """The Floatel database is computed at 150 m: 400 m is beyond the factor 2; 8 m is above
    its fairleads (8.7 m below the water line)."""
    import dataclasses

    from floatmoor.core.errors import SceneError
    from floatmoor.io.build import build
    from floatmoor.io.plausibility import check_depth

    built = build(ROOT / "scenes/floatel_100yr.yaml")
    for depth, words in ((400.0, "within a factor 2"), (8.0, "deepest point of the floater")):
        site = dataclasses.replace(built.scene.site, water_depth=depth)
        b = dataclasses.replace(built, scene=dataclasses.replace(built.scene, site=site))
        with pytest.raises(SceneError) as exc:
            check_depth(b)
        assert "site.water_depth" in str(exc.value) and words in str(exc.value)
        assert "floatel_100yr.yaml" in str(exc.value)


def test_every_line_failed_is_refused(tree, capsys):
    text = (tree / M).read_text()
    names = re.findall(r"name: (line\d+)", text)
    m = tree / "vessels/floatel_like/all_failed.yaml"
    m.write_text(text + "failed_lines: [" + ", ".join(names) + "]\n")
    p = _scene_with(tree, "all_failed_scene.yaml", mooring="../vessels/floatel_like/all_failed.yaml")
    code, err = _cli(["check", p], capsys)
    assert code == 2 and str(m) in err and "failed_lines" in err, err


def test_harmonic_amplitude_sanity(tree, capsys, tmp_path):
    code, err = _cli(["lines", tree / "scenes/oc3_hywind.yaml", "--harmonic", "surge:5000:15",
                      "--duration", "20", "--out", tmp_path / "x.nc"], capsys)
    assert code == 2 and "--harmonic" in err and "water depth" in err, err


def test_shipped_scenes_still_pass(capsys):
    for name in ("floatel_100yr.yaml", "oc3_hywind.yaml"):
        code, err = _cli(["check", ROOT / "scenes" / name], capsys)
        assert code == 0, err


# -- 6. messages: every error names its file; no RuntimeWarning noise ------------------------
def test_error_without_file_names_the_command_input(monkeypatch, capsys, tmp_path):
    """A SceneError raised by a model without a file (e.g. a realisation checking its
    arguments) is printed with the scene file the command was given."""
    from floatmoor import cli
    from floatmoor.core.errors import SceneError

    def failing(args):
        import numpy as np
        np.log(np.zeros(3))  # a RuntimeWarning that must not reach the user
        raise SceneError(None, "analysis.duration", "a number > 0 (s)", -1.0)

    monkeypatch.setattr(cli, "COMMANDS", [cli.Command("check", "x", cli._check_arguments,
                                                      failing)])
    code = cli.main(["check", str(tmp_path / "my_scene.yaml")])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith(f"floatmoor: error: {tmp_path / 'my_scene.yaml'}: "
                                        "analysis.duration")
    assert "RuntimeWarning" not in err and "(given in Python)" not in err


def test_line_diameter_in_mm_and_light_chain_refused(tree, capsys):
    for old, new, key in (("diameter: 0.084", "diameter: 84", "diameter"),
                          ("density: 7850.0", "density: 785.0", "density")):
        m = _mutate(tree, M, old, new, "bad_line_type.yaml")
        p = _scene_with(tree, "bad_line_type_scene.yaml",
                        mooring="../vessels/floatel_like/bad_line_type.yaml")
        code, err = _cli(["check", p], capsys)
        assert code == 2 and str(m) in err and key in err, err


def test_line_far_longer_than_its_span_refused(tree, capsys):
    text = (tree / M).read_text()
    first = re.search(r"\blength: ([0-9.]+)", text).group(0)
    m = _mutate(tree, M, first, "length: 1.0e+9", "endless_line.yaml")
    p = _scene_with(tree, "endless_line_scene.yaml",
                    mooring="../vessels/floatel_like/endless_line.yaml")
    code, err = _cli(["check", p], capsys)
    assert code == 2 and str(m) in err and "length" in err and "anchor-fairlead" in err, err
