"""The fingerprint of a result's inputs, stored in every result file (``floatmoor run``,
``floatmoor fd --out``, every case and storm of a campaign).

A results folder is reused by a rerun (finished seeds and cases are skipped), so a file must say
what it was computed from.  :func:`scene_fingerprint` hashes, section by section:

* the values the scene gives: ``site``, ``environment`` (sea state, wind, current and their
  headings), ``analysis`` (without the seeds: one file per seed), ``forces``, ``solver`` (the
  approximations of the time loop; not the thread count, which changes no result), ``frequency_domain``,
  the ``models`` it builds and the run's ``overrides`` (``--duration``, ``--dt``);
* the files it reads, by content: ``vessel`` and ``vessel.database`` (the hydrodynamic
  database), ``mooring`` (or the inline mapping) and ``mooring.line_type_library``;
* ``code``: the code that computes the numbers (:func:`code_version`: floatmoor's version, a
  hash of the numerical source files and of the shipped line-type library, numpy, scipy and
  numba versions).  An update of floatmoor that touches the physics therefore makes earlier
  results stale: a campaign recomputes them on resume, ``floatmoor run`` refuses to mix them
  (``--force`` recomputes).

A campaign adds per case (:func:`case_fingerprint`) the ``condition`` (failed or breaking
lines, fibre stiffness bound) and, for the storms, the ``storage`` settings (precision,
sampling, whether series are kept), for the FD files the compression.  The case's sea state and
headings, which come from the campaign file and its contour or list, are in its
``environment``; its time settings (campaign ``analysis`` and ``--duration``) in its
``analysis``.  So an edited contour point makes exactly the cases of that sea state stale, and
a heading added to the campaign file leaves the existing cases as they are.

:func:`differing_keys` names the sections in which two fingerprints differ, for the messages
that recompute or refuse.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import json
from pathlib import Path

__all__ = ["FINGERPRINT_ATTR", "NUMERICAL_SOURCES", "case_fingerprint", "code_version",
           "differing_keys", "file_sections", "fingerprint_digest", "fingerprint_json",
           "scene_fingerprint"]

FINGERPRINT_ATTR = "input_fingerprint"
"""Result-file attribute holding the JSON of :func:`scene_fingerprint`."""

NUMERICAL_SOURCES = ("core", "metocean", "hydro", "mooring", "forces", "solvers",
                     "analyses/simulate.py", "analyses/frequency_domain.py",
                     "analyses/fd_*.py", "analyses/statics.py", "io/build.py",
                     "io/mooring_section.py", "io/solver_section.py",
                     "post/extremes.py", "campaign/matrix.py",
                     "campaign/tasks.py", "data/line_types.yaml")
"""The files of the package (relative to ``floatmoor/``, folders taken whole) whose content
decides the numbers of a result: the physics, the solvers, model building, the statistics a
campaign storm stores, and the shipped line-type library.  Readers and checks of input files
(their values are hashed instead), commands, reports and the campaign machinery are left out,
so that a new refusal or a reworded message does not make every stored result stale."""


def _h(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:16]


def _file_hash(path) -> str:
    p = Path(path)
    try:
        return _h(p.read_bytes())
    except OSError:
        return "unreadable"


def _value_hash(value) -> str:
    return _h(repr(_plain(value)).encode())


def _plain(v):
    """``v`` as plain Python values; a dataclass by its compared fields (a field with
    ``compare=False``, such as the file a section was read from, is not part of its value)."""
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in sorted(v.items(), key=lambda kv: str(kv[0]))}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {f.name: _plain(getattr(v, f.name)) for f in dataclasses.fields(v) if f.compare}
    if hasattr(v, "tolist"):
        return v.tolist()
    if isinstance(v, Path):
        return str(v)
    return v


def _source_files(package: Path) -> list[Path]:
    out = []
    for pattern in NUMERICAL_SOURCES:
        p = package / pattern
        if p.is_dir():
            out += sorted(p.rglob("*.py"))
        else:
            out += sorted(package.glob(pattern))
    return sorted(set(out))


@functools.lru_cache(maxsize=1)
def code_version() -> dict[str, str]:
    """floatmoor's version, a hash of its numerical sources (:data:`NUMERICAL_SOURCES`, by
    content) and the versions of the libraries that compute with them.  Computed once per
    process (about 10 ms)."""
    import numba
    import numpy
    import scipy

    from .. import __version__
    package = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for p in _source_files(package):
        h.update(p.relative_to(package).as_posix().encode())
        h.update(b"\0")
        h.update(p.read_bytes())
    return {"floatmoor": __version__, "sources": h.hexdigest()[:16], "numpy": numpy.__version__,
            "scipy": scipy.__version__, "numba": numba.__version__}


def _mooring_library(mooring) -> Path | None:
    """The ``line_type_library`` file a mooring file (or inline mapping) extends the shipped
    library with, or None."""
    from ..core.config import Node
    try:
        node = Node.load(mooring) if isinstance(mooring, Path) else Node(mooring, None, "")
        if "line_type_library" not in node:
            return None
        if not isinstance(mooring, Path):
            return Path(str(node.raw("line_type_library")))
        return node.path_value("line_type_library", must_exist=False)
    except Exception:  # noqa: BLE001 - a bad mooring file is reported by the run itself
        return None


def file_sections(scene) -> dict[str, str]:
    """The sections of :func:`scene_fingerprint` that hash files (vessel, its database, the
    mooring and its line-type library) and the code: the part a campaign computes once for its
    base scene and shares between its cases."""
    fp: dict[str, str] = {"code": _value_hash(code_version())}
    if scene.vessel is not None:
        fp["vessel"] = _file_hash(scene.vessel)
        try:
            from ..core.config import Node
            node = Node.load(scene.vessel)
            if "database" in node:
                fp["vessel.database"] = _file_hash(node.path_value("database"))
        except Exception:  # noqa: BLE001 - a bad vessel file is reported by the run itself
            pass
    if scene.mooring is not None:
        fp["mooring"] = (_file_hash(scene.mooring) if isinstance(scene.mooring, Path)
                         else _value_hash(scene.mooring))
        lib = _mooring_library(scene.mooring)
        if lib is not None:
            fp["mooring.line_type_library"] = _file_hash(lib)
    return fp


def _solver_value(solver):
    """The scene's ``solver`` options without the thread count (threads are bit-identical);
    None for the default path (the same numbers as a scene without the section)."""
    if solver is None or getattr(solver, "is_default", False):
        return None
    if dataclasses.is_dataclass(solver) and hasattr(solver, "threads"):
        return dataclasses.replace(solver, threads=1)
    return solver


def scene_fingerprint(scene, overrides: dict | None = None, *,
                      files: dict[str, str] | None = None) -> dict[str, str]:
    """Section name -> short hash of what a run of ``scene`` (a loaded Scene) depends on (see
    the module docstring).  ``files``: the :func:`file_sections` of the scene, when already
    computed (a campaign's cases share their base scene's)."""
    an = scene.analysis
    env = scene.environment
    fp = {
        "site": _value_hash(scene.site),
        "environment": _value_hash(env),
        "analysis": _value_hash({"duration": an.duration, "dt": an.dt, "ramp": an.ramp,
                                 "transient": an.transient,
                                 **({"fibre_stiffness": an.fibre_stiffness}
                                    if an.fibre_stiffness != "upper" else {})}),
        "forces": _value_hash(scene.forces),
        "models": ",".join(scene.active_models()),
        "overrides": _value_hash(dict(overrides or {})),
    }
    solver = _solver_value(getattr(scene, "solver", None))
    if solver is not None:
        fp["solver"] = _value_hash(solver)
    if getattr(scene, "frequency_domain", None) is not None:
        fp["frequency_domain"] = _value_hash(scene.frequency_domain)
    fp.update(file_sections(scene) if files is None else files)
    return fp


def case_fingerprint(case_scene, condition, files: dict[str, str], *, kind: str,
                     storage=None, compression: int | None = None,
                     scene_fp: dict[str, str] | None = None) -> dict[str, str]:
    """The fingerprint of one campaign result (:mod:`floatmoor.campaign`): the case's scene
    (the base scene with the case's sea state, headings, analysis and line failure), its
    ``condition`` and, by ``kind``, what decides the stored file: ``fd`` the compression,
    ``td``/``series`` the storage settings (``series``: full series kept).  ``scene_fp``: the
    case scene's :func:`scene_fingerprint` when already computed."""
    fp = dict(scene_fp) if scene_fp is not None else scene_fingerprint(case_scene, files=files)
    fp["condition"] = _value_hash(condition)
    if kind == "fd":
        fp["storage"] = _value_hash({"compression": compression})
    else:
        st = storage
        keep = kind == "series" or st.mode == "full"
        fp["storage"] = _value_hash({"precision": st.precision, "compression": st.compression,
                                     "sampling": dict(st.sampling) if keep else None,
                                     "series": keep})
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
