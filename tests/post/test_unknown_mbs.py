"""A line type without MBS (MoorDyn/MAP++ imports: ``mbs: unknown``): statics, motions and
tensions run; every design check that needs the MBS refuses it with a SceneError naming the line
type, the file it came from and what to set.

Before this rule the importer wrote a placeholder MBS of 1e30 N and the DNV-OS-E301 check of an
imported mooring passed with a utilisation of ~1e-24 (design tension / (0.95 x 1e30 N)): each
refusal below is a check that used to pass silently.  The imported mooring is the OC3-Hywind
MoorDyn file of the OpenFAST regression tests (Jonkman (2010)), kept in vessels/oc3_hywind/source.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from floatmoor.cli import main
from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.io import moordyn
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.post import dnv_os_e301 as dnv

ROOT = Path(__file__).resolve().parents[2]
OC3_MD = ROOT / "vessels/oc3_hywind/source/NRELOffshrBsline5MW_OC3Hywind_MoorDyn.dat"


@pytest.fixture(scope="module")
def imported():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return moordyn.read_model(OC3_MD)


def _names_source_and_remedy(text, type_name):
    assert type_name in text                      # the line type
    assert OC3_MD.name in text                    # the file it came from
    assert f"line_types.{type_name}.mbs" in text  # what to set


def test_import_writes_unknown_and_statics_still_run(imported):
    assert "mbs: unknown" in imported.yaml_text and "1.0e+30" not in imported.yaml_text
    ms = imported.system
    assert np.isnan(ms.mbs).all()
    t = ms.tensions()
    # statics are independent of the MBS: the fairlead tensions are those of the hand-written
    # OC3 mooring (test_import_moordyn: equal to 1e-4)
    assert np.isfinite(t["fairlead_tension"].values).all()
    assert np.isnan(t["utilisation"].values).all()          # never a silent ~0
    assert "unknown" in t["mbs"].attrs


def test_dnv_check_refuses_an_unknown_mbs(imported):
    ms = imported.system
    tf = ms.tensions()["fairlead_tension"].values
    with pytest.raises(SceneError, match="known minimum breaking strength"):
        dnv.check_lines(ms.names, ms.mbs, uls_mean=tf, uls_max=1.5 * tf)
    with pytest.raises(SceneError, match="unknown"):
        dnv.line_check(tf, 1.5 * tf, ms.mbs)                 # the campaign screening's path
    with pytest.raises(SceneError) as e:
        ms.require_mbs("the DNV-OS-E301 design report")
    type_name = ms.lines[0].segments[0].line_type
    _names_source_and_remedy(str(e.value), type_name)


def test_old_placeholder_1e30_is_read_as_unknown(imported, tmp_path):
    """A mooring file written by an earlier import (mbs: 1.0e+30) is refused the same way."""
    text = imported.yaml_text.replace("mbs: unknown", "mbs: 1.0e+30")
    p = tmp_path / "mooring.yaml"
    p.write_text(text)
    ms = parse_mooring(Node.load(p), water_depth=imported.water_depth)
    assert np.isnan(ms.mbs).all()
    with pytest.raises(SceneError, match="known minimum breaking strength"):
        dnv.check_lines(ms.names, np.full(3, 1.0e30), uls_mean=np.ones(3), uls_max=np.ones(3))
    # a real MBS set by the user is taken as given
    ms2 = parse_mooring(Node.load(_with_mbs(p, imported, 5.0e6)), water_depth=imported.water_depth)
    assert ms2.mbs == pytest.approx([5.0e6] * 3) and ms2.unknown_mbs() == ""


def _with_mbs(path, imported, mbs):
    q = path.with_name("mooring_mbs.yaml")
    q.write_text(imported.yaml_text.replace("mbs: unknown", f"mbs: {mbs!r}"))
    return q


def test_a_missing_mbs_is_still_an_error(tmp_path):
    """Only an explicit ``mbs: unknown`` is accepted: a user type without ``mbs`` stays a
    SceneError naming the key."""
    p = tmp_path / "m.yaml"
    p.write_text("""
line_types:
  a: {diameter: 0.1, mass_per_length: 50.0, ea: 5.0e8, density: 7850.0}
lines:
  - {name: l1, anchor: {x: -800.0, y: 0.0, z: -200.0}, fairlead: [0.0, 0.0, 0.0],
     segments: [{type: a, length: 900.0}]}
""")
    with pytest.raises(SceneError, match="mbs"):
        parse_mooring(Node.load(p), water_depth=200.0)


def test_weakest_segment_unknown_makes_the_line_unknown(tmp_path):
    """A line of a known and an unknown segment has an unknown MBS (the unknown one may be the
    weaker): min() of the two must not return the known one."""
    p = tmp_path / "m.yaml"
    p.write_text("""
line_types:
  a: {diameter: 0.1, mass_per_length: 50.0, ea: 5.0e8, mbs: 3.0e6, density: 7850.0}
  b: {diameter: 0.1, mass_per_length: 50.0, ea: 5.0e8, mbs: unknown, density: 7850.0,
      source: imported.dat line 7}
lines:
  - {name: l1, anchor: {x: -800.0, y: 0.0, z: -200.0}, fairlead: [0.0, 0.0, 0.0],
     segments: [{type: a, length: 400.0}, {type: b, length: 500.0}]}
""")
    ms = parse_mooring(Node.load(p), water_depth=200.0)
    assert math.isnan(ms.mbs[0])
    assert "imported.dat line 7" in ms.unknown_mbs() and "line_types.b.mbs" in ms.unknown_mbs()


def test_fatigue_refuses_an_unknown_mbs_where_the_curve_needs_it(imported):
    """A T-N curve on the tension range over the RBS (= MBS on the corroded area) needs the
    MBS; DNV's S-N curve of chain in MPa does not (nominal area of the diameter only)."""
    from dataclasses import replace

    from floatmoor.post.fatigue.locations import location_curves
    ms = imported.system
    name = ms.lines[0].segments[0].line_type
    segs = np.zeros((1, ms.n_lines), int)
    ms.line_types[name] = replace(ms.line_types[name], tn_curve="api_chain_studless")
    with pytest.raises(SceneError) as e:
        location_curves(ms, ["fairlead"], segs, design_life=20.0, corrosion={})
    assert "fatigue" in str(e.value) and "api_chain_studless" in str(e.value)
    _names_source_and_remedy(str(e.value), name)
    ms.line_types[name] = replace(ms.line_types[name], tn_curve="chain_studless")
    curves, ref, _ = location_curves(ms, ["fairlead"], segs, design_life=20.0, corrosion={})
    d = ms.line_types[name].diameter
    np.testing.assert_allclose(ref, 2 * np.pi * (d * 1e3) ** 2 / 4)   # mm^2, no MBS


def _scene_with(imported, tmp_path):
    moor = tmp_path / "mooring.yaml"
    moor.write_text(imported.yaml_text)
    text = (ROOT / "scenes" / "oc3_hywind.yaml").read_text()
    text = text.replace("../vessels/oc3_hywind/vessel.yaml",
                        (ROOT / "vessels/oc3_hywind/vessel.yaml").as_posix())
    text = text.replace("../vessels/oc3_hywind/mooring.yaml", moor.as_posix())
    scene = tmp_path / "scene.yaml"
    scene.write_text(text)
    return scene


def test_campaign_refuses_before_any_case_runs(imported, tmp_path):
    from floatmoor.campaign.spec import load_campaign
    scene = _scene_with(imported, tmp_path)
    c = tmp_path / "c.yaml"
    c.write_text(f"name: t\nbase_scene: {scene.as_posix()}\n"
                 "sea_states: {list: [{name: a, hs: 6.0, tp: 10.0}]}\n"
                 "headings: {waves_deg: [0]}\nconditions: {intact: true}\nseeds: '1-3'\n"
                 "analysis: {duration: 600.0, dt: 0.2, transient: 100.0}\n")
    with pytest.raises(SceneError) as e:
        load_campaign(c)
    assert "campaign" in str(e.value)
    _names_source_and_remedy(str(e.value), imported.system.lines[0].segments[0].line_type)


def test_run_works_and_report_refuses(imported, tmp_path, capsys):
    """A short run of the scene with the imported mooring: tensions computed, the MBS stored as
    nan with the reason; ``floatmoor report`` then exits 2 naming the type, file and remedy."""
    import floatmoor
    from floatmoor.analyses.runner import seed_file
    from floatmoor.io.scene import load_scene
    scene = load_scene(_scene_with(imported, tmp_path))
    out = tmp_path / "res"
    out.mkdir()
    for s in (1, 2, 3):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = floatmoor.simulate(scene, seed=s, duration=60.0, transient=20.0, ramp=10.0,
                                    dt=0.2)
        ds.to_netcdf(seed_file(out, scene.name, s))
    assert np.isfinite(ds["line_tension"].values).all() and ds["line_tension"].values.max() > 0
    assert np.isnan(ds["mbs"].values).all() and "unknown" in ds["mbs"].attrs
    code = main(["report", str(out), "--out", str(tmp_path / "r")])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    _names_source_and_remedy(err, imported.system.lines[0].segments[0].line_type)
    assert not (tmp_path / "r" / "report.html").exists()
    # results of an earlier import (placeholder 1e30 stored as the MBS): refused too
    for f in out.glob("*.nc"):
        with xr.open_dataset(f) as d:
            d = d.load()
        d["mbs"] = d["mbs"].fillna(1.0e30)
        d["mbs"].attrs.pop("unknown", None)
        d.to_netcdf(f)
    code = main(["report", str(out), "--out", str(tmp_path / "r")])
    err = capsys.readouterr().err
    assert code == 2 and "known minimum breaking strength" in err




def _cli_run(imported, tmp_path, capsys, command, prefix):
    """``floatmoor COMMAND scene`` on the imported mooring: its exit status and its output
    line starting with ``prefix`` (None when there is none)."""
    scene = _scene_with(imported, tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        code = main([command, str(scene)])
    out = capsys.readouterr().out
    return code, next((ln for ln in out.splitlines() if ln.startswith(prefix)), None)


def test_cli_statics_says_why_the_utilisation_is_nan(imported, tmp_path, capsys):
    """`floatmoor statics` runs on the imported mooring and, below the table whose utilisation
    column is nan, says which line type has no MBS, from which file, what to set."""
    code, line = _cli_run(imported, tmp_path, capsys, "statics", "utilisation nan:")
    assert code == 0
    assert line is not None
    _names_source_and_remedy(line, imported.system.lines[0].segments[0].line_type)


def test_cli_check_warns_that_design_checks_need_the_mbs(imported, tmp_path, capsys):
    """`floatmoor check` passes the scene (it is a valid scene) and says that the design
    checks will be refused until the MBS is set."""
    code, line = _cli_run(imported, tmp_path, capsys, "check", "design checks")
    assert code == 0
    assert line is not None
    _names_source_and_remedy(line, imported.system.lines[0].segments[0].line_type)
