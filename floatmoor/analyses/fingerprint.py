"""The fingerprint of a run's inputs, stored in every result file of ``floatmoor run``.

A results folder is reused by a rerun (finished seeds are skipped), so a file must say what it
was computed from: :func:`scene_fingerprint` hashes, section by section, the scene's site,
environment, analysis settings (without the seeds: one file per seed), force options, the
models it builds, the vessel file and its hydrodynamic database, the mooring, and the run's
overrides (``--duration``, ``--dt``).  :func:`differing_keys` names the sections in which two
fingerprints differ, for the message refusing to mix results of two scenes in one folder.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from pathlib import Path

__all__ = ["scene_fingerprint", "fingerprint_json", "fingerprint_digest", "differing_keys", "FINGERPRINT_ATTR"]

FINGERPRINT_ATTR = "input_fingerprint"
"""Result-file attribute holding the JSON of :func:`scene_fingerprint`."""


def _h(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:16]


def _file_hash(path) -> str:
    p = Path(path)
    try:
        return _h(p.read_bytes())
    except OSError:
        return "unreadable"


def _value_hash(value) -> str:
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        value = {f.name: getattr(value, f.name) for f in dataclasses.fields(value)}
    return _h(repr(_plain(value)).encode())


def _plain(v):
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in sorted(v.items(), key=lambda kv: str(kv[0]))}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {f.name: _plain(getattr(v, f.name)) for f in dataclasses.fields(v)}
    if hasattr(v, "tolist"):
        return v.tolist()
    if isinstance(v, Path):
        return str(v)
    return v


def scene_fingerprint(scene, overrides: dict | None = None) -> dict[str, str]:
    """Section name -> short hash of what a run of ``scene`` (a loaded Scene) depends on."""
    an = scene.analysis
    fp = {
        "site": _value_hash(scene.site),
        "environment": _value_hash(dataclasses.replace(scene.environment, source=None)
                                   if hasattr(scene.environment, "source") else
                                   scene.environment),
        "analysis": _value_hash({"duration": an.duration, "dt": an.dt, "ramp": an.ramp,
                                 "transient": an.transient,
                                 **({"fibre_stiffness": an.fibre_stiffness}
                                    if an.fibre_stiffness != "upper" else {})}),
        "forces": _value_hash(scene.forces),
        "models": ",".join(scene.active_models()),
        "overrides": _value_hash(dict(overrides or {})),
    }
    if scene.vessel is not None:
        fp["vessel"] = _file_hash(scene.vessel)
        try:
            from ..core.config import Node
            node = Node.load(scene.vessel)
            if "database" in node:
                fp["vessel.database"] = _file_hash(node.path_value("database"))
        except Exception:  # a bad vessel file is reported by the run itself
            pass
    if scene.mooring is not None:
        fp["mooring"] = (_file_hash(scene.mooring) if isinstance(scene.mooring, Path)
                         else _value_hash(scene.mooring))
    return fp


def fingerprint_json(scene, overrides: dict | None = None) -> str:
    """:func:`scene_fingerprint` as the JSON text stored in a result file (``scene``: a Scene
    or the path of a scene file)."""
    if not hasattr(scene, "analysis"):
        from ..io.scene import load_scene
        scene = load_scene(scene)
    return json.dumps(scene_fingerprint(scene, overrides), sort_keys=True)


def fingerprint_digest(fp: dict[str, str]) -> str:
    """One hash of a whole fingerprint."""
    return _h(json.dumps(fp, sort_keys=True).encode())


def differing_keys(a: dict[str, str], b: dict[str, str]) -> list[str]:
    """The sections whose hashes differ (or are present in one only)."""
    return sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
