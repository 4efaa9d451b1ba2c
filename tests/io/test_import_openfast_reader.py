"""The OpenFAST input reader (floatmoor.io.openfast.reader) and the import's refusals.

Expected behaviour: OpenFAST's own readers (ElastoDyn reads by position with ``ReadVar`` and
ignores the names; HydroDyn, SeaState and the driver check the names with ``ParseVar``, which
also accepts ``Name value``).  The files are written here, small, for one behaviour each; the
public models are in test_import_public_models.py.
"""

from __future__ import annotations

import shutil
import warnings

import numpy as np
import pytest

from floatmoor.cli import main
from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.hydro import load_vessel
from floatmoor.io.openfast import InputFile, import_openfast
from floatmoor.io.openfast.reader import Key

from .public_models import lay_out

HEAD = "------- TEST INPUT FILE --------\ntitle line of the test file\n"
SCHEMA = [Key(name="NumBl"), Key(name="TipRad"), Key(name="PreCone(1)"), Key(name="PreCone(2)"),
          Key(name="HubCM"), Key(name="NewKey", optional=True), Key(name="OverHang")]


def _file(tmp_path, body, name="f.dat"):
    p = tmp_path / name
    p.write_text(HEAD + body)
    return p


def test_names_aliases_and_case(tmp_path):
    p = _file(tmp_path, "3  numbl - blades\n63.0 TipRad - m\n-2.5 PreCone1 - deg\n"
                        "-2.5 PreCone(2) - deg\n0 HubCM\n-5.0 OverHang\n")
    f = InputFile(p, SCHEMA, "ElastoDyn")
    assert f.int("NumBl") == 3 and f.float("PreCone(1)") == -2.5
    assert f.values["PreCone(1)"].how == "name" and f.line("OverHang") == 8
    assert not f.has("NewKey") and f.notes == []


def test_unknown_name_read_by_position_as_elastodyn_does(tmp_path):
    """A misspelt name between two keys found by name is read by its position (ReadVar)."""
    p = _file(tmp_path, "3 NumBl\n63.0 TipRad\n-2.5 PreConeOne\n-2.5 PreCone(2)\n0 HubCM\n"
                        "-5.0 OverHang\n")
    f = InputFile(p, SCHEMA, "ElastoDyn")
    assert f.float("PreCone(1)") == -2.5 and f.values["PreCone(1)"].how == "position"
    assert "line 5: read as PreCone(1) by its position" in f.notes[0]


def test_name_first_and_optional_key_of_a_newer_version(tmp_path):
    p = _file(tmp_path, "NumBl 3\n63.0 TipRad\n-2.5 PreCone(1)\n-2.5 PreCone(2)\n0 HubCM\n"
                        "7 NewKey - added in a later version\n-5.0 OverHang\n")
    f = InputFile(p, SCHEMA, "ElastoDyn")
    assert f.int("NumBl") == 3 and f.int("NewKey") == 7 and f.float("OverHang") == -5.0


def test_missing_key_names_file_key_and_line(tmp_path):
    p = _file(tmp_path, "3 NumBl\n63.0 TipRad\n-2.5 PreCone(1)\n-2.5 PreCone(2)\n-5.0 OverHang\n")
    f = InputFile(p, SCHEMA, "ElastoDyn")
    with pytest.raises(SceneError) as ei:
        f.float("HubCM")
    msg = str(ei.value)
    assert str(p) in msg and "HubCM" in msg and "after PreCone(2) (line 6)" in msg
    assert "line 7: -5.0 OverHang" in msg
    with pytest.raises(SceneError) as ei:
        InputFile(tmp_path / "none.dat", SCHEMA, "ElastoDyn")
    assert ei.value.found == "no such file"


def test_addf0_one_row_of_openfast_2_0(tmp_path):
    """HydroDyn 2.0-2.5 wrote AddF0 as one row of six; later versions as six rows."""
    from floatmoor.io.openfast import schemas

    body = ("0 0 0 0 1.0E6 0 AddF0 - preload\n" + "\n".join(
        ["1 0 0 0 0 0 AddCLin"] + ["0 0 0 0 0 0"] * 5 + ["0 0 0 0 0 0 AddBLin"]
        + ["0 0 0 0 0 0"] * 5 + ["0 0 0 0 0 0 AddBQuad"] + ["0 0 0 0 0 0"] * 5) + "\n")
    f = InputFile(_file(tmp_path, body), schemas.HYDRODYN, "HydroDyn")
    assert f.leading_numbers("AddF0") == 6
    np.testing.assert_array_equal(f.numbers_after("AddF0", 1, 6).ravel(), [0, 0, 0, 0, 1e6, 0])
    assert f.numbers_after("AddCLin", 6, 6)[0, 0] == 1.0


def _edit(path, old, new):
    text = path.read_bytes().decode()
    assert old in text, old
    path.write_bytes(text.replace(old, new, 1).encode())


@pytest.mark.parametrize("key,old,new,expected", [
    ("WaveHs", "1.10  WaveHs", "-6  WaveHs", "a significant wave height > 0 m"),
    ("WaveTp", "8.52  WaveTp", "0  WaveTp", "a peak period > 0 s"),
])
def test_impossible_waves_refused_naming_hydrodyn_file_and_key(tmp_path, key, old, new, expected):
    """OpenFAST v3 files: the waves are in HydroDyn."""
    fst = lay_out("iea15-volturnus-v3", tmp_path / "m")
    hd = fst.parent / "IEA-15-240-RWT-UMaineSemi_HydroDyn.dat"
    _edit(hd, old, new)
    with pytest.raises(SceneError) as ei:
        import_openfast(fst, tmp_path / "out")
    assert ei.value.file == str(hd) and key in ei.value.key and expected in str(ei.value)


def test_impossible_waves_refused_naming_seastate_file_and_key(tmp_path):
    """OpenFAST v4 files: the waves are in SeaState; the CLI ends with exit status 2."""
    fst = lay_out("iea15-volturnus-v4", tmp_path / "m")
    ss = fst.parent / "IEA-15-240-RWT-UMaineSemi_SeaState.dat"
    text = ss.read_bytes().decode()
    line = next(ln for ln in text.splitlines() if "WaveHs" in ln.split()[1:2])
    ss.write_bytes(text.replace(line, line.replace(line.split()[0], "-6", 1), 1).encode())
    with pytest.raises(SceneError) as ei:
        import_openfast(fst, tmp_path / "out")
    assert ei.value.file == str(ss) and "WaveHs" in ei.value.key and ei.value.found == "-6"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        assert main(["import", "openfast", str(fst), "--out", str(tmp_path / "o2")]) == 2


def test_cli_prints_budget_unmapped_and_run_it_with(tmp_path, capsys):
    fst = lay_out("oc3-hywind", tmp_path / "m")
    assert main(["import", "openfast", str(fst), "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert "mass budget" in out and "closes within 0.5 %" in out
    assert "yaw_bearing" not in out  # the 5-MW ElastoDyn files have YawBrMass 0
    assert "not mapped (file:line key: what -- what floatmoor does instead):" in out
    assert "SeaState.dat:30 WaveSeed" in out
    assert f"run it with: floatmoor run {tmp_path / 'out' / 'scene.yaml'}" in out


def test_cli_never_prints_run_it_with_for_a_scene_check_refuses(tmp_path, capsys):
    """OC4 without its fill groups (the ballast water, 9,612 t): the budget is 69 % off, check
    refuses the scene (its mass against the displacement): no 'run it with', exit status 2."""
    fst = lay_out("oc4-deepcwind", tmp_path / "m")
    hd = fst.parent / "NRELOffshrBsline5MW_OC4DeepCwindSemi_HydroDyn.dat"
    _edit(hd, "             2   NFillGroups", "             0   NFillGroups")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        assert main(["import", "openfast", str(fst), "--out", str(tmp_path / "out")]) == 2
    out = capsys.readouterr().out
    assert "run it with" not in out
    assert "floatmoor check refuses the written scene" in out and "mass" in out
    assert "does not close" in out


def test_yaw_bearing_mass_is_in_the_vessel(tmp_path):
    """The issue's first symptom: IEA-15's YawBrMass (28,249 kg at the 144.386 m tower top) was
    dropped; it is a point mass now, and BldFile1 (not BldFile(1)) is read."""
    fst = lay_out("iea15-volturnus-v3", tmp_path / "m")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        res = import_openfast(fst, tmp_path / "out")
    import yaml

    pm = {p["name"]: p for p in yaml.safe_load(res.files["vessel"].read_text())["point_masses"]}
    assert pm["yaw_bearing"]["mass"] == 28249.0
    assert pm["yaw_bearing"]["position"] == [0.0, 0.0, 144.386]
    assert pm["blades"]["mass"] == pytest.approx(3 * 68.5e3, rel=0.01)


def test_stale_mass_budget_is_refused(tmp_path):
    fst = lay_out("oc3-hywind", tmp_path / "m")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        res = import_openfast(fst, tmp_path / "out", check=False)
    v = res.files["vessel"]
    text = v.read_text()
    v.write_text(text.replace("mass: 7466330.0", "mass: 7000000.0", 1))
    with pytest.raises(SceneError) as ei:
        load_vessel(v)
    assert "mass_budget.total_mass" in str(ei.value) and "stale" in str(ei.value)


def test_wamit_root_beside_the_hydrodyn_file(tmp_path):
    """A flat copy of the files (WAMIT files beside HydroDyn, as in vessels/*/source): the
    import uses them and says so."""
    fst = lay_out("oc3-hywind", tmp_path / "m")
    flat = tmp_path / "flat"
    shutil.copytree(fst.parent, flat)
    for p in (fst.parent.parent / "5MW_Baseline" / "HydroData").iterdir():
        shutil.copy(p, flat / p.name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        res = import_openfast(flat / fst.name, tmp_path / "out", check=False)
    assert any("Spar.* beside the HydroDyn file used" in n for n in res.notes)
