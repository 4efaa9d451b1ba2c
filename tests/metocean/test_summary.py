"""Environment summary, zero-upcrossing analysis and the metocean data files."""

import importlib
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.metocean import (
    CurrentSpec,
    Environment,
    WaveSpec,
    WindSpec,
    environment_summary,
    format_summary,
    zero_upcrossing_waves,
)

ROOT = Path(__file__).resolve().parents[2]
HEIDRUN = Environment(name="heidrun-100yr", waves=WaveSpec(hs=16.0, tp=18.2),
                      wind=WindSpec(u10=36.0),
                      current=CurrentSpec(z=(0.0, -25.0, -50.0), speed=(0.94, 0.94, 0.94)))


def test_zero_upcrossing_of_a_sine():
    # eta = 2 sin(2 pi t / 12.5): every wave has H = 4 m and T = 12.5 s
    dt = 0.05
    t = np.arange(0.0, 500.0, dt) + 0.013
    h, T = zero_upcrossing_waves(2.0 * np.sin(2 * np.pi * t / 12.5), dt)
    assert h.size == 38  # upcrossings at 12.5, 25, ..., 487.5 s: 39 crossings, 38 waves
    np.testing.assert_allclose(h, 4.0, rtol=1e-3)
    np.testing.assert_allclose(T, 12.5, rtol=1e-6)


@pytest.fixture(scope="module")
def heidrun_summary():
    return environment_summary(HEIDRUN, water_depth=320.0)


def test_summary_statistics(heidrun_summary):
    s = heidrun_summary
    w = s["waves"]
    assert w["gamma"] == pytest.approx(math.exp(5.75 - 1.15 * 18.2 / 4.0), rel=1e-12)
    assert w["hs_realised"] == pytest.approx(16.0, rel=0.05)
    assert w["tz_realised"] == pytest.approx(w["tz_target"], rel=0.05)
    # Rayleigh: most probable max of N waves ~ Hs sqrt(ln N / 2) = 1.82 Hs for N ~ 780
    assert 1.5 * 16.0 < w["hmax"] < 2.2 * 16.0
    assert w["n_waves"] == pytest.approx(10800 / w["tz_realised"], rel=0.01)
    wi = s["wind"]
    assert wi["mean_target"] == pytest.approx(36.0)
    assert wi["mean"] == pytest.approx(36.0, abs=2.0)
    assert wi["std"] == pytest.approx(wi["std_target"], rel=0.15)
    assert wi["ti_target"] == pytest.approx(0.06 * (1 + 0.043 * 36.0), rel=1e-12)  # NPD I_U(10 m)
    assert wi["max"] > wi["mean"] + 3 * wi["std"]
    c = s["current"]
    assert (c["surface"], c["at_minus_50"], c["seabed"]) == (0.94, 0.94, 0.94)


def test_format_summary(heidrun_summary):
    text = format_summary(heidrun_summary)
    for needle in ("heidrun-100yr", "Waves: jonswap", "significant wave height", "16.00", "18.20",
                   "1.678", "Wind: npd", "36.00", "turbulence intensity", "Current:",
                   "at z = -50 m", "0.94"):
        assert needle in text, needle
    assert max(len(line) for line in text.splitlines()) <= 80


def test_summary_of_partial_environment():
    env = Environment(current=CurrentSpec(profile="power_law", speed=(1.0,)))
    s = environment_summary(env, water_depth=None, duration=600.0)
    assert s["waves"] is None and s["wind"] is None
    assert s["current"]["seabed"] is None and s["current"]["surface"] == 1.0
    assert "Waves" not in format_summary(s)


# --------------------------------------------------------------------------- data files

def test_heidrun_100yr_file_matches_wang_2016():
    # Wang (2016) sec. 5.2, tables 5.3-5.5
    d = yaml.safe_load((ROOT / "metocean" / "heidrun_100yr.yaml").read_text())
    assert d["name"] == "heidrun-100yr" and "Wang (2016)" in d["description"]
    assert d["waves"] == {"spectrum": "jonswap", "hs": 16.0, "tp": 18.2, "gamma": None,
                          "heading_deg": 0.0}
    assert d["wind"] == {"spectrum": "npd", "u10": 36.0, "heading_deg": 0.0}
    assert d["current"]["profile"] == "piecewise_linear"
    assert d["current"]["heading_deg"] == 0.0
    levels = np.array(d["current"]["levels"])
    assert levels[0, 0] == 0.0 and levels[-1, 0] == -50.0 and np.all(levels[:, 1] == 0.94)


def test_contour_file():
    d = yaml.safe_load((ROOT / "metocean" / "heidrun_contour.yaml").read_text())
    assert set(d) == {"name", "description", "sea_states"}
    pts = {(s["hs"], s["tp"]) for s in d["sea_states"]}
    assert {(16.0, 18.2), (15.5, 15.5), (15.5, 19.8)} <= pts  # Wang (2016) sec. 5.3
    names = [s["name"] for s in d["sea_states"]]
    assert len(set(names)) == len(names)
    for s in d["sea_states"]:
        assert set(s) <= {"name", "hs", "tp", "gamma"}
        assert s["hs"] > 0 and s["tp"] > 0
        assert 2 * np.pi * s["hs"] / (9.80665 * s["tp"] ** 2) < 1.0 / 15.0  # not breaking-steep
        assert s["hs"] <= 16.0  # Wang's (2016) peak point is the contour's maximum Hs


def test_heidrun_file_reads_through_scene_parser():
    env_mod = importlib.import_module("floatmoor.io.environment")
    env = env_mod.load_environment(ROOT / "metocean" / "heidrun_100yr.yaml", water_depth=320.0)
    assert env.waves.hs == 16.0 and env.wind.u10 == 36.0
    s = environment_summary(env, water_depth=320.0, duration=1800.0)
    assert s["current"]["at_minus_50"] == 0.94


@pytest.mark.parametrize("kwargs", [{"dt": 0.0}, {"dt": -0.1}, {"duration": 0.05},
                                    {"duration": float("inf")}])
def test_summary_bad_input(kwargs):
    from floatmoor.core.errors import SceneError
    with pytest.raises(SceneError):
        environment_summary(HEIDRUN, water_depth=320.0, **kwargs)
