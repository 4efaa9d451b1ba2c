"""Every mistake a user can make in a scene is a SceneError naming file, key, expected, found.

Each case changes one key of a valid scene (the 100-year Floatel-like scene of Wang (2016)) or of
its referenced environment file and checks the four parts of the error.
"""

import math

import pytest

from floatmoor import SceneError
from floatmoor.io import load_scene

from .helpers import DELETE, write_case

MISSING = SceneError.MISSING

# (id, scene changes, environment changes, file ("scene"|"env"), key, text in expected, found)
CASES = [
    # missing keys
    ("missing site", {"site": DELETE}, {}, "scene", "site", "site", MISSING),
    ("missing water depth", {"site.water_depth": DELETE}, {}, "scene", "site.water_depth",
     "> 0", MISSING),
    ("missing hs", {}, {"waves.hs": DELETE}, "env", "waves.hs", "> 0", MISSING),
    ("missing tp", {}, {"waves.tp": DELETE}, "env", "waves.tp", "> 0", MISSING),
    ("missing wave spectrum", {}, {"waves.spectrum": DELETE}, "env", "waves.spectrum",
     "jonswap", MISSING),
    ("missing u10", {}, {"wind.u10": DELETE}, "env", "wind.u10", ">= 0", MISSING),
    ("missing current levels", {}, {"current.levels": DELETE}, "env", "current.levels",
     "list of numbers", MISSING),
    # wrong types
    ("depth with unit", {"site.water_depth": "150 m"}, {}, "scene", "site.water_depth",
     "a number", "150 m"),
    ("hs quoted", {}, {"waves.hs": "16"}, "env", "waves.hs", "a number", "16"),
    ("hs boolean", {}, {"waves.hs": True}, "env", "waves.hs", "a number", True),
    ("site not a mapping", {"site": 150.0}, {}, "scene", "site", "mapping", 150.0),
    ("waves a list", {}, {"waves": [16.0, 18.2]}, "env", "waves", "mapping", [16.0, 18.2]),
    ("random amplitudes not boolean", {}, {"waves.random_amplitudes": 1}, "env",
     "waves.random_amplitudes", "true or false", 1),
    ("environment a number", {"environment": 3}, {}, "scene", "environment",
     "environment file or a mapping", 3),
    ("mooring a number", {"mooring": 12}, {}, "scene", "mooring", "mooring file or a mapping",
     12),
    ("n_frequencies a float", {}, {"waves.discretisation": {"n_frequencies": 400.5}}, "env",
     "waves.discretisation.n_frequencies", "an integer", 400.5),
    ("levels not pairs", {}, {"current.levels": [0.0, 0.94]}, "env", "current.levels",
     "shape (n, 2)", [0.0, 0.94]),
    ("seeds a float", {"analysis.seeds": 1.5}, {}, "scene", "analysis.seeds", "integer seed",
     1.5),
    # unknown model names (the message lists the names available)
    ("unknown wave spectrum", {}, {"waves.spectrum": "jonswop"}, "env", "waves.spectrum",
     "jonswap, pierson_moskowitz, torsethaugen", "jonswop"),
    ("unknown wind spectrum", {}, {"wind.spectrum": "kaimal"}, "env", "wind.spectrum",
     "api, constant, npd", "kaimal"),
    ("unknown current profile", {}, {"current.profile": "linear"}, "env", "current.profile",
     "piecewise_linear, power_law", "linear"),
    ("unknown spreading", {}, {"waves.spreading": "cos4"}, "env", "waves.spreading",
     "none, cos2s", "cos4"),
    # site
    ("negative depth", {"site.water_depth": -150.0}, {}, "scene", "site.water_depth", "> 0",
     -150.0),
    ("zero depth", {"site.water_depth": 0}, {}, "scene", "site.water_depth", "> 0", 0),
    ("depth beyond the oceans", {"site.water_depth": 15000.0}, {}, "scene", "site.water_depth",
     "<= 11000", 15000.0),
    ("zero density", {"site.water_density": 0.0}, {}, "scene", "site.water_density", "> 0", 0.0),
    # waves
    ("zero hs", {}, {"waves.hs": 0.0}, "env", "waves.hs", "> 0", 0.0),
    ("negative hs", {}, {"waves.hs": -16.0}, "env", "waves.hs", "> 0", -16.0),
    ("zero tp", {}, {"waves.tp": 0}, "env", "waves.tp", "> 0", 0),
    ("negative tp", {}, {"waves.tp": -18.2}, "env", "waves.tp", "> 0", -18.2),
    ("gamma below one", {}, {"waves.gamma": 0.9}, "env", "waves.gamma", ">= 1", 0.9),
    ("gamma for pierson-moskowitz", {}, {"waves.spectrum": "pierson_moskowitz",
                                         "waves.gamma": 3.3}, "env", "waves.gamma",
     "no gamma", 3.3),
    ("gamma for torsethaugen", {}, {"waves.spectrum": "torsethaugen", "waves.gamma": 2.0},
     "env", "waves.gamma", "no gamma", 2.0),
    ("breaking sea (Hs and Tp swapped)", {}, {"waves.hs": 18.2, "waves.tp": 5.0}, "env",
     "waves.hs", "does not break", 18.2),
    ("spreading_s without spreading", {}, {"waves.spreading_s": 4.0}, "env",
     "waves.spreading_s", "long-crested", 4.0),
    ("cos2s without n_directions", {}, {"waves.spreading": "cos2s"}, "env",
     "waves.n_directions", "an integer", MISSING),
    ("omega_max below the peak", {}, {"waves.discretisation": {"omega_max": 0.3}}, "env",
     "waves.discretisation.omega_max", "> 0.345", 0.3),
    ("omega_min above the peak", {}, {"waves.discretisation": {"omega_min": 0.4}}, "env",
     "waves.discretisation.omega_min", "< 0.345", 0.4),
    ("discretisation typo", {}, {"waves.discretisation": {"omega_mx": 2.5}}, "env",
     "waves.discretisation.omega_mx", "omega_max", "unknown key 'omega_mx'"),
    # headings: radians where degrees are expected
    ("bare heading key", {}, {"waves.heading": 0.5}, "env", "waves.heading", "heading_deg",
     "unknown key 'heading'"),
    ("radians in heading_deg", {}, {"waves.heading_deg": 3.1416}, "env", "waves.heading_deg",
     "degrees", 3.1416),
    ("radians in wind heading_deg", {}, {"wind.heading_deg": 1.5708}, "env",
     "wind.heading_deg", "degrees", 1.5708),
    ("bare current heading", {}, {"current.heading": 1.0}, "env", "current.heading",
     "heading_deg", "unknown key 'heading'"),
    ("heading beyond a turn", {}, {"waves.heading_deg": 400.0}, "env", "waves.heading_deg",
     "<= 360", 400.0),
    # unknown keys (typos)
    ("top-level typo", {"enviroment": "x"}, {}, "scene", "enviroment", "environment",
     "unknown key 'enviroment'"),
    ("site typo", {"site.waterdepth": 150.0}, {}, "scene", "site.waterdepth", "water_depth",
     "unknown key 'waterdepth'"),
    ("waves typo", {}, {"waves.Hs": 16.0}, "env", "waves.Hs", "hs", "unknown key 'Hs'"),
    ("environment typo", {}, {"wave": {}}, "env", "wave", "waves", "unknown key 'wave'"),
    ("analysis typo", {"analysis.durration": 10800.0}, {}, "scene", "analysis.durration",
     "duration", "unknown key 'durration'"),
    ("wind typo", {}, {"wind.U10": 36.0}, "env", "wind.U10", "u10", "unknown key 'U10'"),
    # wind
    ("negative wind", {}, {"wind.u10": -1.0}, "env", "wind.u10", ">= 0", -1.0),
    ("gust discretisation on constant wind", {}, {"wind.spectrum": "constant",
                                                  "wind.discretisation": {"f_max": 0.5}},
     "env", "wind.discretisation", "constant wind", {"f_max": 0.5}),
    # current
    ("current level below the seabed", {}, {"current.levels": [[0.0, 0.9], [-200.0, 0.5]]},
     "env", "current.levels[1]", "above the seabed", [-200.0, 0.5]),
    ("current levels not from the surface", {}, {"current.levels": [[-10.0, 0.9]]}, "env",
     "current.levels[0]", "surface", [-10.0, 0.9]),
    ("current levels out of order", {}, {"current.levels": [[0.0, 0.9], [-50.0, 0.5],
                                                            [-20.0, 0.1]]},
     "env", "current.levels[2]", "decreasing", [-20.0, 0.1]),
    ("negative current speed", {}, {"current.levels": [[0.0, -0.9]]}, "env",
     "current.levels[0]", ">= 0", [0.0, -0.9]),
    ("levels on a power law", {}, {"current.profile": "power_law"}, "env", "current.levels",
     "no levels", [[0.0, 0.94], [-50.0, 0.94]]),
    # analysis
    ("zero dt", {"analysis.dt": 0.0}, {}, "scene", "analysis.dt", "> 0", 0.0),
    ("negative dt", {"analysis.dt": -0.1}, {}, "scene", "analysis.dt", "> 0", -0.1),
    ("dt longer than the run", {"analysis.dt": 20000.0}, {}, "scene", "analysis.dt",
     "< 10800", 20000.0),
    ("zero duration", {"analysis.duration": 0.0}, {}, "scene", "analysis.duration", "> 0", 0.0),
    ("transient equal to duration", {"analysis.transient": 10800.0}, {}, "scene",
     "analysis.transient", "< 10800", 10800.0),
    ("transient beyond duration", {"analysis.transient": 20000.0}, {}, "scene",
     "analysis.transient", "< 10800", 20000.0),
    ("negative transient", {"analysis.transient": -1.0}, {}, "scene", "analysis.transient",
     ">= 0", -1.0),
    ("seed range backwards", {"analysis.seeds": [20, 1]}, {}, "scene", "analysis.seeds",
     "last >= first", [20, 1]),
    ("three seeds as a list", {"analysis.seeds": [3, 7, 11]}, {}, "scene", "analysis.seeds",
     "[first, last]", [3, 7, 11]),
    ("negative seed", {"analysis.seeds": -1}, {}, "scene", "analysis.seeds", "between 0", -1),
    ("bad seed text", {"analysis.seeds": "1..20"}, {}, "scene", "analysis.seeds", "1-20",
     "1..20"),
    # referenced paths that do not exist
    ("missing environment file", {"environment": "../metocean/nope.yaml"}, {}, "scene",
     "environment", "existing file", "../metocean/nope.yaml"),
    ("missing vessel file", {"vessel": "../vessels/nope/vessel.yaml"}, {}, "scene", "vessel",
     "existing file", "../vessels/nope/vessel.yaml"),
    ("missing mooring file", {"mooring": "../vessels/nope/mooring.yaml"}, {}, "scene",
     "mooring", "existing file", "../vessels/nope/mooring.yaml"),
    ("vessel folder without vessel.yaml", {"vessel": "../metocean"}, {}, "scene", "vessel",
     "folder holding vessel.yaml", "../metocean"),
    ("empty name", {"name": " "}, {}, "scene", "name", "non-empty", " "),
]


@pytest.mark.parametrize("scene_changes, env_changes, where, key, expected, found",
                         [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_each_mistake_names_file_key_expected_found(tmp_path, scene_changes, env_changes,
                                                    where, key, expected, found):
    scene_path, env_path = write_case(tmp_path, scene_changes, env_changes)
    with pytest.raises(SceneError) as info:
        load_scene(scene_path)
    err = info.value
    assert err.file == str(scene_path if where == "scene" else env_path)
    assert err.key == key
    assert expected in err.expected
    if found is MISSING:
        assert err.found is MISSING
        assert "missing" in str(err)
    elif isinstance(found, str) and found.startswith("unknown key"):
        assert err.found == found
    else:
        assert err.found == found
    # the printed message holds all four parts
    text = str(err)
    assert text.startswith(err.file) and key in text and "expected" in text and "found" in text


def test_error_in_referenced_environment_file_names_that_file(tmp_path):
    scene_path, env_path = write_case(tmp_path, {}, {"waves.hs": -3.0})
    with pytest.raises(SceneError) as info:
        load_scene(scene_path)
    assert info.value.file == str(env_path)
    assert str(info.value).startswith(str(env_path) + ": waves.hs: expected a number > 0")


def test_inline_environment_error_names_scene_file_and_full_key(tmp_path):
    import copy

    from .helpers import ENVIRONMENT
    env = copy.deepcopy(ENVIRONMENT)
    env["waves"]["tp"] = -1.0
    scene_path, _ = write_case(tmp_path, {"environment": env})
    with pytest.raises(SceneError) as info:
        load_scene(scene_path)
    assert info.value.file == str(scene_path)
    assert info.value.key == "environment.waves.tp"


def test_radians_hint_says_what_to_do(tmp_path):
    scene_path, _ = write_case(tmp_path, {}, {"waves.heading_deg": 3.1416})
    with pytest.raises(SceneError, match=r"looks like an angle in radians \(180"):
        load_scene(scene_path)
    scene_path, _ = write_case(tmp_path, {}, {"waves.heading": 0.5,
                                              "waves.heading_deg": DELETE})
    with pytest.raises(SceneError, match="use heading_deg"):
        load_scene(scene_path)


def test_breaking_sea_error_gives_the_limit_and_a_hint(tmp_path):
    # Hs 16 m with Tp 8 s: Lp = g Tp^2 / (2 pi) = 99.9 m in deep water (150 m is deep for 8 s:
    # k d = 9.4), Hs/Lp = 0.16 > 1/10 -> refused; the limit printed is Hs <= 9.99 m.
    scene_path, env_path = write_case(tmp_path, {}, {"waves.tp": 8.0})
    with pytest.raises(SceneError) as info:
        load_scene(scene_path)
    assert "Hs <= 9.99 m" in info.value.expected
    assert "swapped" in info.value.hint


def test_missing_scene_file(tmp_path):
    with pytest.raises(SceneError) as info:
        load_scene(tmp_path / "nope.yaml")
    assert "nope.yaml" in str(info.value)


def test_empty_and_non_mapping_scene_files(tmp_path):
    p = tmp_path / "empty.yaml"
    p.write_text("")
    with pytest.raises(SceneError, match="empty file"):
        load_scene(p)
    p.write_text("- 1\n- 2\n")
    with pytest.raises(SceneError, match="mapping"):
        load_scene(p)


def test_heading_within_limits_is_not_taken_for_radians(tmp_path):
    # 3.0 deg is not a multiple of pi/4 and 45 deg is an integer: both accepted as degrees
    scene_path, _ = write_case(tmp_path, {}, {"waves.heading_deg": 3.0, "wind.heading_deg": 45})
    env = load_scene(scene_path).environment
    assert env.waves.heading == pytest.approx(math.radians(3.0))
    assert env.wind.heading == pytest.approx(math.pi / 4)
