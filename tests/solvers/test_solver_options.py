"""The ``solver:`` options of the time loop (opt-in approximations) against the exact path on the
flagship storm (scenes/floatel_100yr.yaml, seed 1).

Reference: the exact path of the same run (its own accuracy is the business of the model tests
and of the time-step convergence, 0.07 % on the max offset and tension at dt = 0.1 s,
benchmarks/RESULTS.md); an option must stay far below that.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.analyses.simulate import simulate
from floatmoor.core.errors import SceneError
from floatmoor.io.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def flagship(tmp_path, solver: dict | None) -> Path:
    """The flagship scene with absolute paths and a ``solver`` section."""
    d = yaml.safe_load((ROOT / "scenes" / "floatel_100yr.yaml").read_text())
    for key in ("vessel", "environment", "mooring"):
        d[key] = str((ROOT / "scenes" / d[key]).resolve())
    if solver is not None:
        d["solver"] = solver
    p = tmp_path / "flagship.yaml"
    p.write_text(yaml.safe_dump(d))
    return p


@pytest.fixture(scope="module")
def exact_storm(tmp_path_factory):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return simulate(flagship(tmp_path_factory.mktemp("exact"), None), seed=1,
                        duration=1500.0)


def test_bad_option_is_a_scene_error(tmp_path):
    with pytest.raises(SceneError, match="solver.catenary"):
        load_scene(flagship(tmp_path, {"catenary": "fast"}))
    with pytest.raises(SceneError, match="solver"):
        load_scene(flagship(tmp_path, {"catenery": "predictor"}))


def test_predictor_catenary_against_the_exact_path(tmp_path, exact_storm):
    """``solver: {catenary: predictor}``: 1500 s of the storm; fairlead and anchor tensions
    within 1e-7 of the largest tension and the motion within 1e-6 m / rad of the exact path
    (measured: 3e-10 over 3 hours), i.e. 1e4 times below the time-step error."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(flagship(tmp_path, {"catenary": "predictor"}), seed=1, duration=1500.0)
    assert ds.attrs["solver"] == "catenary predictor"
    assert "solver" not in exact_storm.attrs
    ref = exact_storm
    tmax = float(ref["line_tension"].max())
    for name in ("line_tension", "anchor_tension"):
        assert float(np.abs(ds[name] - ref[name]).max()) <= 1e-7 * tmax, name
    assert float(np.abs(ds["motion"] - ref["motion"]).max()) <= 1e-6
    assert not np.array_equal(ds["line_tension"].values, ref["line_tension"].values)
