"""OpenFAST import (floatmoor.io.openfast) of the OC3-Hywind regression model (Jonkman 2010).

Expected values: the hand-written OC3 files (vessels/oc3_hywind/vessel.yaml, mooring.yaml and
scenes/oc3_hywind.yaml), made from the same OpenFAST files plus the tower and rotor masses of
the public OC3 definition.  The OpenFAST files in vessels/oc3_hywind/source/ do not include the
tower and blade files, so the import lists those masses as not mapped and its mass budget does
not close; the free-decay test adds them to the imported vessel exactly as the hand-written
vessel has them, and then the heave and pitch free-decay periods must be those of the
hand-written scene.  The complete public models (with their tower and blade files) are tested in
test_import_public_models.py.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.cli import main
from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.io.openfast import import_openfast

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parent / "data"
FST = ROOT / "vessels/oc3_hywind/source/5MW_OC3Spar_DLL_WTurb_WavesIrr.fst"


@pytest.fixture(scope="module")
def imported(tmp_path_factory):
    out = tmp_path_factory.mktemp("oc3")
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always", FloatmoorWarning)
        res = import_openfast(FST, out)
    return res, [str(x.message) for x in w if issubclass(x.category, FloatmoorWarning)]


def test_files_and_what_was_not_mapped(imported):
    res, msgs = imported
    assert set(res.files) == {"vessel", "database", "mooring", "scene"}
    text = "\n".join(msgs)
    # by file and line (ElastoDyn line 116 TwrFile, line 89 BldFile(1))
    assert ("NRELOffshrBsline5MW_OC3Hywind_ElastoDyn.dat:116 TwrFile: tower file "
            "NRELOffshrBsline5MW_OC3Hywind_ElastoDyn_Tower.dat not found") in text
    assert "ElastoDyn.dat:89 BldFile(1): blade file NRELOffshrBsline5MW_Blade.dat not found" in text
    assert "Morison members" in text and "MBS" in text
    # the mass budget does not close and names what is missing: the tower and the blades
    assert not res.budget.closes
    # (tower 249,718 kg + blades 52,610 kg) / (rho V = 1025 x 8029.21 m^3), plus the +0.0074 %
    # of the complete model (test_import_public_models.py)
    assert res.budget.fraction == pytest.approx((249718.0 + 52609.8) / (1025 * 8029.21)
                                                + 7.4e-5, rel=1e-3)
    warning = next(m for m in msgs if "mass budget does not close" in m)
    assert "the tower" in warning and "the blades" in warning
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)  # a 60 s analysis (the .fst TMax)
        scene = floatmoor.load_scene(res.files["scene"])
    assert scene.site.water_depth == 320.0 and scene.site.gravity == 9.80665


def test_vessel_matrices_equal_hand_written(imported):
    from floatmoor.hydro import load_vessel

    res, _ = imported
    v = load_vessel(res.files["vessel"])
    ref = load_vessel(ROOT / "vessels/oc3_hywind/vessel.yaml")
    np.testing.assert_array_equal(v.linear_damping, ref.linear_damping)
    np.testing.assert_array_equal(v.additional_stiffness, ref.additional_stiffness)
    np.testing.assert_allclose(v.hydrostatic_stiffness, ref.hydrostatic_stiffness, rtol=1e-12)
    np.testing.assert_allclose(v.database["added_mass"].values, ref.database["added_mass"].values,
                               rtol=1e-12)
    # the imported mass lacks exactly the tower (249,718 kg) and the blades (110,000 - 56,780)
    assert ref.mass - v.mass == pytest.approx(249718.0 + 110000.0 - 56780.0, rel=1e-12)


def _with_missing_masses(res, tmp_path):
    """The imported vessel plus the tower and blade masses of the hand-written vessel."""
    ref = yaml.safe_load((ROOT / "vessels/oc3_hywind/vessel.yaml").read_text())
    ves = yaml.safe_load(res.files["vessel"].read_text())
    tower = next(p for p in ref["point_masses"] if p["name"] == "tower")
    rotor = next(p for p in ref["point_masses"] if p["name"] == "rotor")
    hub = next(p for p in ves["point_masses"] if p["name"] == "hub")
    nac = next(p for p in ves["point_masses"] if p["name"] == "nacelle")
    nac_ref = next(p for p in ref["point_masses"] if p["name"] == "nacelle")
    assert hub["position"] == pytest.approx(rotor["position"], abs=1e-5)
    blades = {"name": "blades", "mass": rotor["mass"] - hub["mass"],
              "position": hub["position"],
              "inertia_cg": (np.array(rotor["inertia_cg"]) - np.array(hub["inertia_cg"])).tolist()}
    nac["inertia_cg"] = np.diag(nac_ref["inertia_cg"]).tolist()  # the hand-written yaw value
    ves["point_masses"] += [tower, blades]
    del ves["mass_budget"]  # the masses are edited: the import's budget no longer applies
    ves["database"] = str(res.files["database"])
    path = tmp_path / "vessel.yaml"
    path.write_text(yaml.safe_dump(ves))
    return path


def _periods(scene_path):
    ds = floatmoor.simulate(floatmoor.load_scene(scene_path), duration=130.0, dt=0.1,
                            start_pose=[0.0, 0.0, 2.0, 0.0, np.radians(2.0), 0.0])
    t = ds["time"].values
    out = []
    for k in (2, 4):
        x = ds["motion"].values[:, k]
        x = x - x[t > 60].mean()
        up = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
        tc = t[up] - x[up] * (t[up + 1] - t[up]) / (x[up + 1] - x[up])
        out.append(np.diff(tc).mean())
    return np.array(out)


def test_free_decay_periods_equal_hand_written_scene(imported, tmp_path):
    res, _ = imported
    ves = _with_missing_masses(res, tmp_path)
    calm = {"site": {"water_depth": 320.0, "water_density": 1025.0, "gravity": 9.80665},
            "analysis": {"duration": 130.0, "dt": 0.1}}
    a = tmp_path / "imported.yaml"
    a.write_text(yaml.safe_dump({**calm, "name": "imported", "vessel": str(ves),
                                 "mooring": str(res.files["mooring"])}))
    b = tmp_path / "hand.yaml"
    b.write_text(yaml.safe_dump({**calm, "name": "hand",
                                 "vessel": str(ROOT / "vessels/oc3_hywind/vessel.yaml"),
                                 "mooring": str(ROOT / "vessels/oc3_hywind/mooring.yaml")}))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        pa, pb = _periods(a), _periods(b)
    assert 25.0 < pb[0] < 35.0 and 25.0 < pb[1] < 35.0  # heave and pitch, about 30 s
    print("heave, pitch periods (s): imported", pa, "hand-written", pb)
    np.testing.assert_allclose(pa, pb, rtol=1e-6)


def test_cli_import_openfast_and_missing_file(tmp_path, capsys):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        assert main(["import", "openfast", str(tmp_path / "none.fst"), "--out",
                     str(tmp_path / "o")]) == 2
    assert "none.fst" in capsys.readouterr().err
    with pytest.raises(SceneError):
        import_openfast(tmp_path / "none.fst", tmp_path / "o")


def test_floatmoor_run_runs_the_imported_scene(imported, tmp_path, capsys):
    res, _ = imported
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        assert main(["run", str(res.files["scene"]), "--duration", "20", "--seeds", "1",
                     "--workers", "1", "--out", str(tmp_path / "results")]) == 0
    assert len(list((tmp_path / "results").glob("*.nc"))) == 1
    assert "line1r1 tension" in capsys.readouterr().out


def test_oc4_import_moordyn_mooring_and_what_is_missing(tmp_path):
    """OC4-DeepCwind (Robertson et al. 2014): MoorDyn mooring (CompMooring 3); the regression
    files lack marin_semi.3 and HydroDyn adds the ballast as filled members: both listed."""
    from floatmoor.io import moordyn

    fst = ROOT / "vessels/oc4_semi/source/5MW_OC4Semi_WSt_WavesWN.fst"
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always", FloatmoorWarning)
        res = import_openfast(fst, tmp_path)
        md = moordyn.read(ROOT / "vessels/oc4_semi/source/"
                          "NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat")
    text = next(str(x.message) for x in w if "not mapped to floatmoor" in str(x.message))
    assert "WAMIT marin_semi.3 not found" in text
    assert "\nenvironment:" not in res.files["scene"].read_text()
    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring

    ms = parse_mooring(Node.load(res.files["mooring"]), water_depth=200.0)
    np.testing.assert_array_equal(ms.tensions()["fairlead_tension"].values,
                                  md.tensions()["fairlead_tension"].values)
    ves = yaml.safe_load(res.files["vessel"].read_text())
    assert ves["mass"] == 3852180.0  # ElastoDyn PtfmMass (without the ballast)
    # the ballast water of HydroDyn's two fill groups is in the vessel as point masses
    fills = [p for p in ves["point_masses"] if p["name"].startswith("fill_group")]
    assert len(fills) == 2


def test_tower_and_blades_from_elastodyn_files(tmp_path):
    """With the tower and blade files present, their masses are lumped as ElastoDyn does.
    Expected: the ElastoDyn summary of the OpenFAST OC3 regression test (r-test,
    5MW_OC3Spar_DLL_WTurb_WavesIrr.ED.sum): Tower Mass 249,718.003 kg, blade Mass 17,536.614 kg,
    Rotor Inertia 38,677,040.613 kg m^2 (blades with PreCone -2.5 deg and the hub's HubIner).
    The test files hold the densities at ElastoDyn's nodes as that summary prints them."""
    import shutil

    from floatmoor.hydro import load_vessel

    case = tmp_path / "case"
    shutil.copytree(FST.parent, case)
    shutil.copy(DATA / "elastodyn_tower_oc3.dat",
                case / "NRELOffshrBsline5MW_OC3Hywind_ElastoDyn_Tower.dat")
    (tmp_path / "5MW_Baseline").mkdir()
    shutil.copy(DATA / "elastodyn_blade_5mw.dat",
                tmp_path / "5MW_Baseline" / "NRELOffshrBsline5MW_Blade.dat")
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always", FloatmoorWarning)
        res = import_openfast(case / FST.name, tmp_path / "out")
    text = "\n".join(str(x.message) for x in w)
    assert "tower mass" not in text and "blade mass" not in text
    pm = {p["name"]: p for p in yaml.safe_load(res.files["vessel"].read_text())["point_masses"]}
    assert pm["tower"]["mass"] == pytest.approx(249718.003, rel=1e-6)
    assert pm["blades"]["mass"] == pytest.approx(3 * 17536.614, rel=1e-6)
    tilt = np.radians(-5.0)
    a = np.array([np.cos(tilt), 0.0, np.sin(tilt)])
    rotor = a @ (np.array(pm["blades"]["inertia_cg"]) + np.array(pm["hub"]["inertia_cg"])) @ a
    # the hub carries GenIner (534.116 kg m^2 about the shaft), which the summary's rotor
    # inertia does not include
    assert rotor - 534.116 == pytest.approx(38677040.613, rel=1e-6)
    # the blades' centre of mass is on the shaft, upwind of the apex (coned upwind)
    c = np.array(pm["blades"]["position"]) - np.array(pm["hub"]["position"])
    assert np.linalg.norm(np.cross(c, a)) < 1e-9 and c @ a < 0
    v = load_vessel(res.files["vessel"])
    assert v.mass == pytest.approx(8065437.845, rel=1e-6)  # the summary's Mass Incl. Platform
