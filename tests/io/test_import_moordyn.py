"""MoorDyn v1/v2 import (floatmoor.io.moordyn).

Expected values: the hand-written OC3 mooring (vessels/oc3_hywind/mooring.yaml, from Jonkman
2010 and the OpenFAST files) and, for OC4 (Robertson et al. 2014), the collector's independent
catenary cross-check quoted in the reference README (H = 907.5 kN, V = 631.1 kN, K11 = 70,836
N/m, K33 = 19,140 N/m, K55 = 8.724e7 N m/rad, K66 = 1.170e8 N m/rad).  The source files are the
OpenFAST regression-test files kept in vessels/*/source/.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.core.config import Node
from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.io import moordyn
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.mooring.system import LineDef, MooringSystem, Segment

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parent / "data"
OC3_MD = ROOT / "vessels/oc3_hywind/source/NRELOffshrBsline5MW_OC3Hywind_MoorDyn.dat"
OC4_MD = ROOT / "vessels/oc4_semi/source/NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat"


def _read(path, **kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = moordyn.read_model(path, **kw)
    msgs = [str(x.message) for x in w if issubclass(x.category, FloatmoorWarning)]
    return r, msgs


def _hand_written_oc3():
    return parse_mooring(Node.load(ROOT / "vessels/oc3_hywind/mooring.yaml"), water_depth=320.0)


def test_oc3_moordyn_statics_equal_hand_written():
    r, msgs = _read(OC3_MD)
    ref = _hand_written_oc3()
    assert r.format == "MoorDyn v2" and r.water_depth == 320.0
    t = r.system.tensions()["fairlead_tension"].values
    t_ref = ref.tensions()["fairlead_tension"].values
    # line 1 has the same geometry in both: equal to 1e-6 (the hand-written file adds the MAP++
    # friction CB = 0.001, which moves the fairlead tension by 5e-7 relative)
    assert t[0] == pytest.approx(t_ref[0], rel=1e-6)
    # lines 2 and 3: the MoorDyn file rounds their points to 0.01 m (fairlead radius
    # hypot(2.6, 4.5) = 5.1971 m instead of 5.2 m): 1e-4 relative, 5e-4 for the yaw stiffness
    np.testing.assert_allclose(t, t_ref, rtol=1e-4)
    K, K_ref = r.system.stiffness(), ref.stiffness()
    big = np.abs(K_ref) > 1e-3 * np.abs(K_ref).max(axis=1, keepdims=True)
    np.testing.assert_allclose(K[big], K_ref[big], rtol=5e-4)  # K66: 2 x 0.0029 m / 5.2 m arm
    # what was not mapped is said once, with the file's line numbers
    assert len(msgs) == 1 and "dtM = 0.001 (line 24)" in msgs[0] and "FairTen1" in msgs[0]
    assert "MBS" in msgs[0]


def test_oc3_line1_alone_equal_to_1e6():
    """With the hand-written system at the MoorDyn file's own points and without the MAP++
    friction, fairlead tensions and the 6x6 stiffness agree to 1e-6 relative."""
    r, _ = _read(OC3_MD)
    ref = _hand_written_oc3()
    lines = [LineDef(name=a.name, anchor=b.anchor, fairlead=b.fairlead, segments=a.segments,
                     cb=0.0) for a, b in zip(ref.lines, r.system.lines)]
    ref2 = MooringSystem(lines, water_depth=320.0)
    np.testing.assert_allclose(r.system.tensions()["fairlead_tension"].values,
                               ref2.tensions()["fairlead_tension"].values, rtol=1e-6)
    K, K_ref = r.system.stiffness(), ref2.stiffness()
    big = np.abs(K_ref) > 1e-6 * np.abs(K_ref).max()
    np.testing.assert_allclose(K[big], K_ref[big], rtol=1e-6)


def test_oc3_conversions_and_fe_options():
    r, _ = _read(OC3_MD)
    lt = r.system.line_types["main"]
    assert lt.diameter == 0.09 and lt.mass_per_length == 77.7066 and lt.ea == 384.243e6
    assert lt.displaced_volume == pytest.approx(math.pi * 0.09 ** 2 / 4, rel=1e-12)
    assert lt.cdn == 1.6 and lt.can == 1.0 and lt.cat == 0.0
    assert lt.cdt == pytest.approx(math.pi * 0.1)  # MoorDyn's CdAx acts on pi d
    fe = r.fe_options
    assert fe.n_elements == 20 and fe.internal_damping == -0.8
    sb = fe.seabed_for(320.0)
    assert sb.stiffness == pytest.approx(3.0e6 * 0.09) and sb.damping == pytest.approx(3.0e5 * 0.09)
    assert "CdAx acts on pi d" in r.yaml_text or "acts on pi d" in r.yaml_text


def test_oc4_moordyn_statics_match_independent_catenary():
    r, _ = _read(OC4_MD)
    ds = r.system.tensions()
    np.testing.assert_allclose(ds["horizontal_fairlead"].values, 907.5e3, rtol=1e-4)
    np.testing.assert_allclose(ds["vertical_fairlead"].values, 631.1e3, rtol=2e-4)
    K = r.system.stiffness()
    assert K[0, 0] == pytest.approx(70836.0, rel=1e-4)
    assert K[2, 2] == pytest.approx(19140.0, rel=1e-3)
    assert K[4, 4] == pytest.approx(8.724e7, rel=1e-3)
    assert K[5, 5] == pytest.approx(1.170e8, rel=1e-3)
    hand = ROOT / "vessels/oc4_semi/mooring.yaml"
    if hand.exists():  # a hand-written OC4 mooring, when the repository has one
        ref = parse_mooring(Node.load(hand), water_depth=200.0)
        # MoorDyn has no seabed friction (a hand-written file may carry MAP++'s CB = 1.0)
        ref = MooringSystem([LineDef(name=a.name, anchor=a.anchor, fairlead=a.fairlead,
                                     segments=a.segments, cb=0.0) for a in ref.lines],
                            water_depth=200.0)
        np.testing.assert_allclose(np.sort(ds["fairlead_tension"].values),
                                   np.sort(ref.tensions()["fairlead_tension"].values), rtol=1e-4)


def test_v1_file_reads_as_the_v2_file():
    """The same OC4 mooring written in the v1 format gives the same system as the v2 file."""
    r1, _ = _read(DATA / "oc4_moordyn_v1.dat")
    r2, _ = _read(OC4_MD)
    assert r1.format == "MoorDyn v1"
    np.testing.assert_array_equal(r1.system.tensions()["fairlead_tension"].values,
                                  r2.system.tensions()["fairlead_tension"].values)
    np.testing.assert_array_equal(r1.system.stiffness(), r2.system.stiffness())
    a, b = r1.system.line_types["main"], r2.system.line_types["main"]
    assert (a.cdn, a.can, a.cdt, a.cat) == (b.cdn, b.can, b.cdt, b.cat)


def test_clump_weight_free_point_and_options():
    r, msgs = _read(DATA / "moordyn_v2_clump.dat")
    ms = r.system
    assert ms.names == ("line1-2", "line3") and r.gravity == 9.81
    seg = ms.lines[0].segments
    assert [s.line_type for s in seg] == ["chain", "wire"]
    # point 2: (M - rho V) g = (5000 - 1025 * 0.2) * 9.81 N, positive down (clump weight)
    assert seg[0].point_load == pytest.approx((5000 - 1025 * 0.2) * 9.81, rel=1e-12)
    assert ms.lines[0].fairlead == (40.0, 0.0, -14.0)
    assert ms.cb[0] == 0.5  # mu_kA -> axial friction of the quasi-static lines
    # the same system built directly
    def w(m, d):
        return (m - 1025 * math.pi * d * d / 4) * 9.81
    direct = MooringSystem([LineDef(name="a", anchor=(800.0, 0, -200.0), fairlead=(40.0, 0, -14.0),
                                    cb=0.5, segments=(
        Segment(length=450.0, ea=7.536e8, w=w(113.35, 0.0766),
                point_load=(5000 - 1025 * 0.2) * 9.81),
        Segment(length=400.0, ea=6.0e8, w=w(40.0, 0.08))))], water_depth=200.0)
    np.testing.assert_allclose(ms.tensions()["fairlead_tension"].values[0],
                               direct.tensions()["fairlead_tension"].values[0], rtol=1e-12)
    assert "point 2 (line 12): drag area CdA = 1" in msgs[0]


@pytest.mark.parametrize("name, line, expected, found", [
    ("moordyn_extra_column.dat", 20, "7 columns in the MoorDyn v1 LINES table", "8 columns"),
    ("moordyn_truncated.dat", 22, "7 columns in the MoorDyn v1 LINES table", "4 columns"),
    ("moordyn_truncated_header.dat", 17, "a table: a row of column names", "truncated table"),
    ("moordyn_unknown_type.dat", 21, "a line type name in column 2, one of: main", "chain"),
    ("moordyn_v1_v2_columns.dat", 9, "MoorDyn v1 column names", "v2 column names"),
    ("moordyn_v1_with_rods.dat", 25, "the sections of a MoorDyn v1 file", "RODS"),
])
def test_malformed_files_name_file_line_expected_found(name, line, expected, found):
    with pytest.raises(SceneError) as ei:
        moordyn.read(DATA / name)
    e = ei.value
    assert Path(e.file).name == name and e.key == f"line {line}"
    assert expected in e.expected and found in str(e.found)


def test_missing_file():
    with pytest.raises(SceneError) as ei:
        moordyn.read(DATA / "no_such_file.dat")
    assert ei.value.found == "no such file"


def test_library_readers_misread_v1(tmp_path):
    """Why the reader is hand-written: MoorPy's and openfast_io's MoorDyn readers take every
    table in the v2 column order, so the v1 file fails or is misread."""
    moorpy = pytest.importorskip("moorpy")
    try:
        s = moorpy.System(file=str(DATA / "oc4_moordyn_v1.dat"), depth=200.0)
        ok = (len(s.lineList) == 3 and abs(s.lineList[0].L - 835.35) < 1e-9
              and all(p.r[2] in (-200.0, -14.0) for p in s.pointList))
    except (ValueError, IndexError, KeyError, TypeError):
        ok = False
    assert not ok
    ofio = pytest.importorskip("openfast_io.FAST_reader")
    r = ofio.InputReader_OpenFAST()
    r.fst_vt["MoorDyn"] = {}
    r.fst_vt.setdefault("outlist", {}).setdefault("MoorDyn", {})
    try:
        r.read_MoorDyn(str(DATA / "oc4_moordyn_v1.dat"))
        md = r.fst_vt["MoorDyn"]
        # v1 columns Can Cat Cdn Cdt land in v2's EI Cd Ca CdAx: Cd would be 0.25, not 2.0
        ok = md.get("Cd") == [2.0] and md.get("UnstrLen") == [835.35] * 3
    except (ValueError, IndexError, KeyError, TypeError):
        ok = False
    assert not ok


def test_rods_bodies_are_listed_never_dropped_silently():
    r, msgs = _read(DATA / "moordyn_v2_rods_bodies.dat")
    assert r.system.n_lines == 3  # the lines are still the OC4 lines
    text = msgs[0]
    for what in ("section 'ROD TYPES' (line 8, 1 entries)", "section 'BODIES' (line 12",
                 "section 'RODS' (line 16", "point 7 (line 29) on 'Body1', no line"):
        assert what in text


def test_line_on_a_body_point_is_an_error(tmp_path):
    text = (DATA / "moordyn_v2_rods_bodies.dat").read_text().replace(
        "3         main       3         6", "3         main       3         7")
    bad = tmp_path / "body_line.dat"
    bad.write_text(text)
    with pytest.raises(SceneError) as ei:
        moordyn.read(bad)
    assert ei.value.key == "line 29" and "attached to 'Body1'" in ei.value.found


def test_finite_element_model_of_the_import_runs(tmp_path):
    """The FE options the file implies build FE lines that a short time-domain run accepts."""
    r, _ = _read(OC3_MD, model="finite-element")
    assert r.system.line_models.finite_element_lines == ["line1", "line2", "line3"]
    (tmp_path / "mooring.yaml").write_text(r.yaml_text)
    (tmp_path / "scene.yaml").write_text(yaml.safe_dump({
        "site": {"water_depth": 320.0}, "vessel": str(ROOT / "vessels/oc3_hywind/vessel.yaml"),
        "mooring": "mooring.yaml", "analysis": {"duration": 2.0, "dt": 0.1}}))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        ds = floatmoor.simulate(floatmoor.load_scene(tmp_path / "scene.yaml"))
    t0 = r.system.tensions()["fairlead_tension"].values
    np.testing.assert_allclose(ds["line_tension"].values[-1], t0, rtol=0.02)
