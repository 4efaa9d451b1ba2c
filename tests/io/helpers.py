"""Build scene and environment files in a temporary folder for the io tests."""

from __future__ import annotations

import copy
from pathlib import Path

import yaml

DELETE = object()

# The 100-year design sea state of Wang (2016) (Hs 16 m, Tp 18.2 s JONSWAP, wind 36 m/s NPD,
# current 0.94 m/s to 50 m, all heading 0): a local copy in the format of metocean/*.yaml.
ENVIRONMENT = {
    "name": "heidrun-100yr",
    "description": "test copy of the 100-year sea state",
    "waves": {"spectrum": "jonswap", "hs": 16.0, "tp": 18.2, "gamma": None, "heading_deg": 0.0},
    "wind": {"spectrum": "npd", "u10": 36.0, "heading_deg": 0.0},
    "current": {"profile": "piecewise_linear", "levels": [[0.0, 0.94], [-50.0, 0.94]],
                "heading_deg": 0.0},
}

SCENE = {
    "name": "floatel-like-100yr-head-seas",
    "site": {"water_depth": 150.0, "water_density": 1025.0},
    "environment": "../metocean/heidrun_100yr.yaml",
    "analysis": {"duration": 10800.0, "dt": 0.1, "transient": 1200.0, "ramp": 100.0,
                 "seeds": [1, 20]},
}


def set_key(data: dict, dotted: str, value) -> dict:
    """Set (or with DELETE remove) ``a.b.c`` in a nested dict, in place."""
    *parents, last = dotted.split(".")
    d = data
    for p in parents:
        d = d[p]
    if value is DELETE:
        del d[last]
    else:
        d[last] = value
    return data


def write_case(tmp_path: Path, scene_changes: dict | None = None,
               env_changes: dict | None = None, *, scene: dict | None = None,
               environment: dict | None = None) -> tuple[Path, Path]:
    """Write ``metocean/heidrun_100yr.yaml`` and ``scenes/scene.yaml`` under tmp_path with the
    given dotted-key changes; return (scene path, environment path)."""
    env = copy.deepcopy(ENVIRONMENT if environment is None else environment)
    for k, v in (env_changes or {}).items():
        set_key(env, k, v)
    sc = copy.deepcopy(SCENE if scene is None else scene)
    for k, v in (scene_changes or {}).items():
        set_key(sc, k, v)
    (tmp_path / "metocean").mkdir(exist_ok=True)
    (tmp_path / "scenes").mkdir(exist_ok=True)
    env_path = tmp_path / "metocean" / "heidrun_100yr.yaml"
    env_path.write_text(yaml.safe_dump(env, sort_keys=False))
    scene_path = tmp_path / "scenes" / "scene.yaml"
    scene_path.write_text(yaml.safe_dump(sc, sort_keys=False))
    return scene_path, env_path
