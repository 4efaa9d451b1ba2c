"""The FE flagship scene with the mesh of the stored coupled storms.

notebooks/data/fd_line_dynamics/coupled_storms.csv (benchmarks/fd_vs_coupled_storms.py) holds
storms of scenes/floatel_100yr_fe.yaml run on 2026-11-24 with 50 elements per line shared by
length (23 / 22 / 5).  Since 2026-11-28 the scene gives the elements per segment ([12, 26, 12],
a mesh study, benchmarks/RESULTS.md "A mesh by segment"), so a frequency-domain result
compared with those storms is computed on the storms' mesh: the comparison is one of methods,
not of meshes.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FLAGSHIP_FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"
STORMS_N_ELEMENTS = 50
"""Elements per line of the stored storms (shared among the segments by length)."""


def with_fe_options(scene, **options):
    """``scene`` with ``options`` added to its mooring's ``finite_element:`` mapping (the
    mooring file read and passed inline; it names no other file)."""
    import dataclasses

    import yaml
    mooring = scene.mooring
    if not isinstance(mooring, dict):
        mooring = yaml.safe_load(Path(mooring).read_text())
    mooring = dict(mooring)
    mooring["finite_element"] = {**mooring.get("finite_element", {}), **options}
    return dataclasses.replace(scene, mooring=mooring)


def flagship_fe_as_stored():
    """The FE flagship scene (a :class:`floatmoor.io.scene.Scene`) with the stored storms'
    50 elements per line."""
    import floatmoor
    return with_fe_options(floatmoor.load_scene(FLAGSHIP_FE), n_elements=STORMS_N_ELEMENTS)
