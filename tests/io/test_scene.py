"""Valid scenes: what load_scene builds, describe() and active_models(), defaults, warnings."""

import copy
import dataclasses
import importlib
import math
import warnings

import pytest

from floatmoor import FloatmoorWarning, SceneError
from floatmoor.core.constants import GRAVITY, RHO_AIR
from floatmoor.io import AnalysisSpec, Scene, load_environment, load_scene, seeds_from_text
from floatmoor.io.environment import peak_wavelength
from floatmoor.io.scene import SECTIONS, scene_keys
from floatmoor.metocean.config import CurrentSpec, Environment, WaveSpec, WindSpec

from .helpers import DELETE, ENVIRONMENT, write_case


def load_quietly(path):
    """Load a scene, failing the test on any warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return load_scene(path)


def test_design_scene_is_read_into_frozen_objects(tmp_path):
    scene_path, env_path = write_case(tmp_path)
    scene = load_quietly(scene_path)
    assert isinstance(scene, Scene)
    assert scene.name == "floatel-like-100yr-head-seas"
    assert scene.file == scene_path
    assert scene.site.water_depth == 150.0 and scene.site.water_density == 1025.0
    assert scene.site.gravity == GRAVITY and scene.site.air_density == RHO_AIR
    env = scene.environment
    assert env.name == "heidrun-100yr" and env.source == str(env_path)
    assert env.waves == WaveSpec(spectrum="jonswap", hs=16.0, tp=18.2, gamma=None, heading=0.0)
    assert env.wind == WindSpec(spectrum="npd", u10=36.0, heading=0.0, reference_height=10.0)
    assert env.current == CurrentSpec(profile="piecewise_linear", z=(0.0, -50.0),
                                      speed=(0.94, 0.94), heading=0.0)
    assert scene.analysis == AnalysisSpec(duration=10800.0, dt=0.1, transient=1200.0, ramp=100.0,
                                          seeds=tuple(range(1, 21)))
    assert scene.vessel is None and scene.mooring is None
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.name = "other"
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.environment.waves.hs = 1.0
    with pytest.raises(TypeError):  # keyword-only
        AnalysisSpec(10800.0)


def test_headings_are_converted_to_radians(tmp_path):
    scene_path, _ = write_case(tmp_path, {}, {"waves.heading_deg": 90.0, "wind.heading_deg": -30,
                                              "current.heading_deg": 180.0})
    env = load_quietly(scene_path).environment
    assert env.waves.heading == pytest.approx(math.pi / 2, rel=1e-15)
    assert env.wind.heading == pytest.approx(-math.pi / 6, rel=1e-15)
    assert env.current.heading == pytest.approx(math.pi, rel=1e-15)


def test_inline_environment_equals_the_file(tmp_path):
    file_scene, _ = write_case(tmp_path)
    inline_dir = tmp_path / "inline"
    inline_dir.mkdir()
    inline_scene, _ = write_case(inline_dir, {"environment": copy.deepcopy(ENVIRONMENT)})
    a = load_quietly(file_scene).environment
    b = load_quietly(inline_scene).environment
    assert a == b              # source differs but is not compared
    assert b.source is None and a.source is not None


def test_optional_wave_settings(tmp_path):
    scene_path, _ = write_case(tmp_path, {}, {
        "waves.gamma": 3.3, "waves.spreading": "cos2s", "waves.spreading_s": 6.0,
        "waves.n_directions": 11, "waves.random_amplitudes": True,
        "waves.discretisation": {"omega_min": 0.2, "omega_max": 2.5, "n_frequencies": 4000}})
    w = load_quietly(scene_path).environment.waves
    assert (w.gamma, w.spreading, w.spreading_s, w.n_directions) == (3.3, "cos2s", 6.0, 11)
    assert (w.omega_min, w.omega_max, w.n_frequencies) == (0.2, 2.5, 4000)
    assert w.random_amplitudes is True


def test_other_spectra_and_profiles(tmp_path):
    scene_path, _ = write_case(tmp_path, {}, {
        "waves.spectrum": "torsethaugen", "waves.gamma": DELETE,
        "wind.spectrum": "constant", "wind.reference_height": 25.0,
        "current": {"profile": "power_law", "surface_speed": 1.2, "heading_deg": 45.0}})
    env = load_quietly(scene_path).environment
    assert env.waves.spectrum == "torsethaugen" and env.waves.gamma is None
    assert env.wind.spectrum == "constant" and env.wind.reference_height == 25.0
    assert env.current == CurrentSpec(profile="power_law", z=(0.0,), speed=(1.2,),
                                      heading=math.radians(45.0), exponent=1.0 / 7.0)


def test_absent_components_are_none_and_not_listed(tmp_path):
    scene_path, _ = write_case(tmp_path, {}, {"wind": DELETE, "current": DELETE})
    scene = load_quietly(scene_path)
    assert scene.environment.wind is None and scene.environment.current is None
    assert scene.active_models() == ["waves:jonswap"]
    text = scene.describe()
    assert "wind: none" in text and "current: none" in text


def test_calm_scene_without_environment_and_analysis(tmp_path):
    scene_path, _ = write_case(tmp_path, {"environment": DELETE, "analysis": DELETE,
                                          "name": DELETE})
    scene = load_quietly(scene_path)
    assert scene.name == "scene"                      # the file name without extension
    assert scene.environment == Environment(name="calm")
    assert scene.analysis == AnalysisSpec()
    assert scene.analysis.duration == 10800.0 and scene.analysis.seeds == (1,)
    assert scene.active_models() == []


def test_active_models_and_describe_list_everything(tmp_path):
    (tmp_path / "vessels").mkdir()
    vessel = tmp_path / "vessels" / "vessel.yaml"
    vessel.write_text("name: v\n")
    mooring = tmp_path / "vessels" / "mooring.yaml"
    mooring.write_text("lines: []\n")
    scene_path, _ = write_case(tmp_path, {"vessel": "../vessels/vessel.yaml",
                                          "mooring": "../vessels/mooring.yaml",
                                          "description": "100-year storm, head seas"},
                               {"waves.heading_deg": 30.0})
    scene = load_quietly(scene_path)
    assert scene.vessel == vessel and scene.mooring == mooring
    assert scene.active_models() == ["waves:jonswap", "wind:npd", "current:piecewise_linear",
                                     "mooring"]
    text = scene.describe()
    for piece in ["floatel-like-100yr-head-seas", "100-year storm, head seas",
                  "water depth 150 m", f"vessel: {vessel}", f"mooring: {mooring}",
                  "jonswap  Hs 16 m  Tp 18.2 s", "heading 30 deg",
                  # DNV-RP-C205 rule by hand: exp(5.75 - 1.15 * 18.2 / sqrt(16)) = 1.678
                  "gamma 1.68 from the DNV-RP-C205 rule",
                  "U10 36 m/s", "0.94 m/s at z = -50 m", "duration 10800 s", "dt 0.1 s",
                  "transient 1200 s", "ramp 100 s", "20 seeds 1-20",
                  "models: waves:jonswap, wind:npd, current:piecewise_linear, mooring"]:
        assert piece in text, piece


def test_mooring_node_names_the_right_file_and_key(tmp_path):
    scene_path, _ = write_case(tmp_path, {"mooring": {"lines": [{"length": -1.0}]}})
    scene = load_quietly(scene_path)
    assert scene.mooring == {"lines": [{"length": -1.0}]}
    line = scene.mooring_node().item_nodes("lines")[0]
    with pytest.raises(SceneError) as info:
        line.float("length", gt=0.0)
    assert info.value.file == str(scene_path) and info.value.key == "mooring.lines[0].length"
    assert scene.describe().count("mooring: inline mapping with keys lines") == 1


def test_seed_forms():
    assert seeds_from_text("1-20") == tuple(range(1, 21))
    assert seeds_from_text("3,7,11") == (3, 7, 11)
    assert seeds_from_text(" 1-3, 9 ") == (1, 2, 3, 9)
    for bad in ["", "1-", "a", "5-1", "1,1", "1-3,2"]:
        with pytest.raises(ValueError):
            seeds_from_text(bad)


@pytest.mark.parametrize("value, seeds", [(7, (7,)), ([1, 20], tuple(range(1, 21))),
                                          ([5, 5], (5,)), ("1-5,9", (1, 2, 3, 4, 5, 9)),
                                          ("3,7,11", (3, 7, 11))])
def test_seeds_in_the_scene(tmp_path, value, seeds):
    scene_path, _ = write_case(tmp_path, {"analysis.seeds": value})
    assert load_quietly(scene_path).analysis.seeds == seeds


def test_load_environment_alone(tmp_path):
    _, env_path = write_case(tmp_path, {}, {"current.levels": [[0.0, 1.0], [-500.0, 0.2]]})
    env = load_environment(env_path)                  # no depth: no seabed check
    assert env.current.z == (0.0, -500.0)
    with pytest.raises(SceneError, match="below the seabed"):
        load_environment(env_path, water_depth=150.0)


def test_scene_keys_follow_the_section_registry():
    assert set(scene_keys()) == {"name", "description"} | {s.key for s in SECTIONS}
    fields = {f.name for f in dataclasses.fields(Scene)}
    assert {s.field for s in SECTIONS} <= fields


# -- plausibility warnings -------------------------------------------------------------------------
WARNING_CASES = [
    # Hs 12 m, Tp 10 s in 150 m (deep for 10 s: k d = 6.0): Lp = g T^2/(2 pi) = 156.1 m,
    # Hs/Lp = 1/13.0, steeper than 1/15 but below the breaking refusal at 1/10.
    ("steep sea", {}, {"waves.hs": 12.0, "waves.tp": 10.0}, "very steep"),
    ("gamma above 7", {}, {"waves.gamma": 9.0}, "outside the range 1-7"),
    ("wind in knots", {}, {"wind.u10": 70.0}, "not knots"),
    ("current in knots", {}, {"current.levels": [[0.0, 4.0]]}, "not knots"),
    ("density in g/cm3", {"site.water_density": 1.025}, {}, "water_density"),
    ("ramp longer than transient", {"analysis.ramp": 2000.0}, {}, "include the ramp-up"),
    ("short statistics window", {"analysis.duration": 1800.0, "analysis.transient": 100.0},
     {}, "shorter than one hour"),
    # dt 1 s with Tp 18.2 s: 18.2 steps per peak period < 20
    ("coarse dt", {"analysis.dt": 1.0}, {}, "steps per peak period"),
    # 400 bins over 0.2-2.5 rad/s: domega = 0.00575, 2 pi/domega = 1093 s < 10800 s
    ("discretisation repeats", {}, {"waves.discretisation": {"omega_min": 0.2, "omega_max": 2.5,
                                                             "n_frequencies": 400}},
     "repeat every 2 pi/domega = 1093 s"),
    # 20 m depth, Hs 10 m: 1.86 Hs = 18.6 m > 0.78 d = 15.6 m (depth-limited breaking)
    ("depth-limited breaking", {"site.water_depth": 20.0},
     {"waves.hs": 10.0, "waves.tp": 16.0, "current": DELETE}, "depth-limited"),
]


@pytest.mark.parametrize("scene_changes, env_changes, text", [c[1:] for c in WARNING_CASES],
                         ids=[c[0] for c in WARNING_CASES])
def test_plausibility_warnings(tmp_path, scene_changes, env_changes, text):
    scene_path, _ = write_case(tmp_path, scene_changes, env_changes)
    with pytest.warns(FloatmoorWarning, match=text):
        load_scene(scene_path)


@pytest.mark.parametrize("dt,env,limit", [
    # omega_max 4 rad/s needs dt <= pi/4 = 0.785 s; dt 0.8 s (22.75 steps per Tp) is above it
    (0.8, {"waves.discretisation": {"omega_max": 4.0}}, "0.785"),
    # milliseconds typed for seconds: 100 s steps in an 18.2 s sea (default components up to
    # 1.59 rad/s: dt <= 1.98 s)
    (100.0, {}, "1.98"),
])
def test_dt_above_nyquist_is_refused(tmp_path, dt, env, limit):
    """A time step above the Nyquist limit pi/omega_max of the highest wave component cannot
    represent the sea state (the realisation cannot be put on the time grid: a run failed with
    a ValueError after check had passed): refused at load, naming analysis.dt and the limit."""
    from floatmoor.core.errors import SceneError
    scene_path, _ = write_case(tmp_path, {"analysis.dt": dt}, env)
    with pytest.raises(SceneError) as e:
        load_scene(scene_path)
    assert e.value.key == "analysis.dt" and f"pi/omega_max = {limit} s" in str(e.value)


def test_steepness_limits_at_the_boundaries(tmp_path):
    # deep water (d = 11000 m): Lp = g Tp^2 / (2 pi); Hs just below Lp/10 loads with a warning,
    # just above is refused.
    tp = 10.0
    lp = GRAVITY * tp**2 / (2 * math.pi)
    below, _ = write_case(tmp_path, {"site.water_depth": 11000.0},
                          {"waves.hs": 0.0999 * lp, "waves.tp": tp})
    with pytest.warns(FloatmoorWarning):
        load_scene(below)
    above, _ = write_case(tmp_path, {"site.water_depth": 11000.0},
                          {"waves.hs": 0.1001 * lp, "waves.tp": tp})
    with pytest.raises(SceneError, match="does not break"):
        load_scene(above)


def test_peak_wavelength_limits():
    g = GRAVITY
    # deep water: L = g T^2 / (2 pi)
    assert peak_wavelength(10.0, None) == pytest.approx(g * 100.0 / (2 * math.pi), rel=1e-14)
    assert peak_wavelength(10.0, 5000.0) == pytest.approx(g * 100.0 / (2 * math.pi), rel=1e-12)
    # shallow water: L -> T sqrt(g d) as k d -> 0 (here k d = 0.013: tanh error ~ (kd)^2/6)
    assert peak_wavelength(100.0, 1.0) == pytest.approx(100.0 * math.sqrt(g * 1.0), rel=1e-4)
    # intermediate depth: the dispersion relation w^2 = g k tanh(k d) holds
    for tp, d in [(18.2, 150.0), (10.0, 20.0), (25.0, 50.0)]:
        k = 2 * math.pi / peak_wavelength(tp, d)
        assert g * k * math.tanh(k * d) == pytest.approx((2 * math.pi / tp) ** 2, rel=1e-12)


@pytest.mark.parametrize("hs, tp", [(16.0, 12.0), (16.0, 18.2), (4.0, 25.0)])
def test_described_gamma_agrees_with_the_metocean_rule(tmp_path, hs, tp):
    # describe() evaluates the DNV rule itself (to keep numba out of `floatmoor check`); it must
    # print the value floatmoor.metocean.spectra.dnv_gamma uses.
    spectra = importlib.import_module("floatmoor.metocean.spectra")
    from floatmoor.io.environment import _rule_gamma_text
    assert _rule_gamma_text(hs, tp).startswith(f"{spectra.dnv_gamma(hs, tp):.3g} ")


def test_load_scene_is_exported_at_the_top_level():
    import floatmoor
    assert floatmoor.load_scene is load_scene


def test_scene_pickles_for_worker_processes(tmp_path):
    # `floatmoor run` sends scenes to worker processes: a round trip keeps it equal.
    import pickle
    scene_path, _ = write_case(tmp_path, {"mooring": {"lines": []}})
    scene = load_quietly(scene_path)
    again = pickle.loads(pickle.dumps(scene))
    assert again == scene and again.file == scene.file


def test_vessel_may_be_given_as_its_folder(tmp_path):
    (tmp_path / "vessels" / "semi").mkdir(parents=True)
    (tmp_path / "vessels" / "semi" / "vessel.yaml").write_text("name: semi\n")
    scene_path, _ = write_case(tmp_path, {"vessel": "../vessels/semi"})
    assert load_quietly(scene_path).vessel == tmp_path / "vessels" / "semi" / "vessel.yaml"


def test_forces_section_is_read_through_the_registry(tmp_path):
    importlib.import_module("floatmoor.forces")
    scene_path, _ = write_case(tmp_path, {"forces": {"exclude": ["wind"],
                                                     "line_failure": {"line6": 1500.0}}})
    scene = load_quietly(scene_path)
    assert scene.forces.exclude == ("wind",) and scene.forces.line_failure == {"line6": 1500.0}
    assert "forces: excluded wind; line line6 fails at 1500 s" in scene.describe()
    scene_path, _ = write_case(tmp_path, {"forces": {"exclud": ["wind"]}})
    with pytest.raises(SceneError) as info:
        load_scene(scene_path)
    assert (info.value.file, info.value.key) == (str(scene_path), "forces.exclud")
    scene_path, _ = write_case(tmp_path)                  # no forces: section
    assert load_quietly(scene_path).forces is None


def test_frequency_domain_section_is_read_through_the_registry(tmp_path):
    importlib.import_module("floatmoor.io.fd_section")
    scene_path, _ = write_case(tmp_path, {"frequency_domain": {"duration": 3600.0,
                                                               "drift": "newman"}})
    scene = load_quietly(scene_path)
    assert scene.frequency_domain.duration == 3600.0 and scene.frequency_domain.drift == "newman"
    assert "frequency domain: duration 3600 s" in scene.describe()
    scene_path, _ = write_case(tmp_path, {"frequency_domain": {"duration": -1.0}})
    with pytest.raises(SceneError) as info:
        load_scene(scene_path)
    assert (info.value.file, info.value.key) == (str(scene_path), "frequency_domain.duration")
    scene_path, _ = write_case(tmp_path)
    assert load_quietly(scene_path).frequency_domain is None
