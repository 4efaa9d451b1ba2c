"""MAP++ import (floatmoor.io.map) and the ``floatmoor import`` command.

Expected values: the hand-written OC3 mooring (vessels/oc3_hywind/mooring.yaml: Jonkman 2010,
MAP++ CB = 0.001), the MAP++ summary of the OC3 regression test (H = 736,939 N, V = 535,728 N
per line, quoted in the reference README) and, for OC4 (Robertson et al. 2014), the MoorDyn
file of the same regression test with the MAP++ friction CB = 1.0 added.
"""

from __future__ import annotations

import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from floatmoor.cli import main
from floatmoor.core.config import Node
from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.io import map as mapio
from floatmoor.io import moordyn
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.mooring.system import MooringSystem

ROOT = Path(__file__).resolve().parents[2]
OC3_MAP = ROOT / "vessels/oc3_hywind/source/NRELOffshrBsline5MW_OC3Hywind_MAP.dat"
OC4_MAP = ROOT / "vessels/oc4_semi/source/NRELOffshrBsline5MW_OC4DeepCwindSemi_MAP.dat"
OC4_MD = ROOT / "vessels/oc4_semi/source/NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat"


def _quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        return f(*a, **kw)


def _by_anchor(ms):
    """Line order by anchor azimuth (MAP++ 'repeat' lists 0, 240, 120 deg)."""
    return np.argsort(np.round(np.degrees(np.arctan2(ms.anchors[:, 1], ms.anchors[:, 0])) % 360, 6))


def test_oc3_map_statics_equal_hand_written():
    r = _quiet(mapio.read_model, OC3_MAP, water_depth=320.0)
    ref = parse_mooring(Node.load(ROOT / "vessels/oc3_hywind/mooring.yaml"), water_depth=320.0)
    ms = r.system
    i, j = _by_anchor(ms), _by_anchor(ref)
    np.testing.assert_allclose(ms.anchors[i], ref.anchors[j], atol=1e-9)
    np.testing.assert_allclose(ms.fairleads[i], ref.fairleads[j], atol=1e-12)
    t, tr = ms.tensions(), ref.tensions()
    np.testing.assert_allclose(t["fairlead_tension"].values[i], tr["fairlead_tension"].values[j],
                               rtol=1e-6)
    np.testing.assert_allclose(t["anchor_tension"].values[i], tr["anchor_tension"].values[j],
                               rtol=1e-6)
    K, Kr = ms.stiffness(), ref.stiffness()
    big = np.abs(Kr) > 1e-6 * np.abs(Kr).max()
    np.testing.assert_allclose(K[big], Kr[big], rtol=1e-6)
    # the MAP++ summary of the regression test: H = 736,939 N, V = 535,728 N per line
    np.testing.assert_allclose(t["horizontal_fairlead"].values, 736939.0, rtol=2e-6)
    np.testing.assert_allclose(t["vertical_fairlead"].values, 535728.0, rtol=2e-6)
    assert ms.cb.tolist() == [0.001] * 3


def test_oc4_map_equals_moordyn_with_map_friction():
    r = _quiet(mapio.read_model, OC4_MAP, water_depth=200.0)
    md = _quiet(moordyn.read, OC4_MD)
    md = MooringSystem([replace(l, cb=1.0) for l in md.lines], water_depth=200.0)
    i, j = _by_anchor(r.system), _by_anchor(md)
    t, tm = r.system.tensions()["fairlead_tension"].values, md.tensions()["fairlead_tension"].values
    assert t[0] == pytest.approx(tm[0], rel=1e-12)  # line 1: the same points in both files
    # the MoorDyn file rounds the rotated points to 1e-3 m: 1e-5 for the other lines
    np.testing.assert_allclose(t[i], tm[j], rtol=1e-5)
    K, Kr = r.system.stiffness(), md.stiffness()
    big = np.abs(Kr) > 1e-6 * np.abs(Kr).max()
    np.testing.assert_allclose(K[big], Kr[big], rtol=1e-4)  # K15, K24: a difference of large terms


def test_map_depth_needed_and_malformed(tmp_path):
    with pytest.raises(SceneError) as ei:
        _quiet(mapio.read, OC3_MAP)
    assert "water depth" in ei.value.expected
    bad = tmp_path / "bad.dat"
    text = OC3_MAP.read_bytes().decode().replace("2    Vessel    5.2    0    -70.0",
                                                 "2    Vessel    5.2    0    -70.0   0")
    bad.write_text(text)
    with pytest.raises(SceneError) as ei:
        _quiet(mapio.read, bad, water_depth=320.0)
    assert ei.value.key == "line 9" and "10 columns in the MAP++ NODE PROPERTIES" in ei.value.expected
    assert "11 columns" in ei.value.found
    bad.write_text(OC3_MAP.read_bytes().decode().replace("1       Material   902.2",
                                                         "1       Chain      902.2"))
    with pytest.raises(SceneError) as ei:
        _quiet(mapio.read, bad, water_depth=320.0)
    assert ei.value.key == "line 13" and ei.value.found == "Chain"


def test_cli_import_map_and_moordyn_write_loadable_mooring(tmp_path, capsys):
    out = tmp_path / "m.yaml"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        assert main(["import", "map", str(OC3_MAP), "--out", str(out),
                     "--water-depth", "320"]) == 0
    ms = parse_mooring(Node.load(out), water_depth=320.0)
    assert ms.n_lines == 3 and "water_depth: 320" in capsys.readouterr().out
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        assert main(["import", "moordyn", str(ROOT / "tests/io/data/moordyn_extra_column.dat"),
                     "--out", str(out)]) == 2
    assert "line 20" in capsys.readouterr().err
