"""``floatmoor report`` refuses seeds computed from different inputs.

The scenario: seeds 1-2 of a scene are run, the mooring file is edited (the scene file itself is
unchanged, so the stored scene text is the same), seed 3 is run into the same folder (``floatmoor
run`` checks only the seeds it is asked for).  The input fingerprints stored by ``floatmoor run``
(floatmoor.analyses.fingerprint) then differ in the ``mooring`` section and the report must not
combine the seeds: exit 2, naming the seeds of each fingerprint and the differing section.
Before this check the report combined the three seeds (exit 0).
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
import xarray as xr

from floatmoor.analyses.fingerprint import FINGERPRINT_ATTR, fingerprint_digest
from floatmoor.analyses.runner import run_seeds
from floatmoor.cli import main

ROOT = Path(__file__).resolve().parents[1]
RUN = {"duration": 60.0, "transient": 20.0, "ramp": 10.0, "dt": 0.2}


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    base = tmp_path_factory.mktemp("fp")
    moor = base / "mooring.yaml"
    moor.write_text((ROOT / "vessels/oc3_hywind/mooring.yaml").read_text())
    text = (ROOT / "scenes" / "oc3_hywind.yaml").read_text()
    text = text.replace("../vessels/oc3_hywind/vessel.yaml",
                        (ROOT / "vessels/oc3_hywind/vessel.yaml").as_posix())
    text = text.replace("../vessels/oc3_hywind/mooring.yaml", "mooring.yaml")
    scene = base / "scene.yaml"
    scene.write_text(text)
    same = base / "same"
    run_seeds(scene, [1, 2, 3], same, workers=1, overrides=RUN, echo=None, progress=False)
    mixed = base / "mixed"
    mixed.mkdir()
    for f in sorted(same.glob("*_seed000[12].nc")):
        shutil.copy(f, mixed / f.name)
    moor.write_text(moor.read_text() + "\n# edited after seeds 1-2 were run\n")
    run_seeds(scene, [3], mixed, workers=1, overrides=RUN, echo=None, progress=False)
    return same, mixed


def _fp(path):
    with xr.open_dataset(path) as ds:
        return json.loads(ds.attrs[FINGERPRINT_ATTR])


def test_one_fingerprint_reports(folders, tmp_path, capsys):
    code = main(["report", str(folders[0]), "--out", str(tmp_path / "r")])
    assert code in (0, 1) and "Traceback" not in capsys.readouterr().err


def test_mixed_fingerprints_are_refused(folders, tmp_path, capsys):
    mixed = folders[1]
    fp12 = _fp(next(mixed.glob("*_seed0001.nc")))
    fp3 = _fp(next(mixed.glob("*_seed0003.nc")))
    assert fp12["mooring"] != fp3["mooring"]          # the edit is in the fingerprint
    code = main(["report", str(mixed), "--out", str(tmp_path / "r")])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("floatmoor: error:") and "Traceback" not in err
    assert f"seed(s) 1, 2 from inputs {fingerprint_digest(fp12)}" in err
    assert f"seed(s) 3 from inputs {fingerprint_digest(fp3)}" in err
    assert "they differ in: mooring" in err
    assert not (tmp_path / "r" / "report.html").exists()


def test_a_file_without_fingerprint_beside_others_is_refused(folders, tmp_path, capsys):
    d = tmp_path / "res"
    shutil.copytree(folders[0], d)
    f = next(d.glob("*_seed0002.nc"))
    with xr.open_dataset(f) as ds:
        ds = ds.load()
    del ds.attrs[FINGERPRINT_ATTR]
    ds.to_netcdf(f)
    code = main(["report", str(d), "--out", str(tmp_path / "r")])
    err = capsys.readouterr().err
    assert code == 2 and "seed(s) 2 from inputs (no fingerprint)" in err
