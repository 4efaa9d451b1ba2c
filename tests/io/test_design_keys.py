"""Design keys of mooring files (anchors, design life, corrosion) and the scene's limits:
read, and every mistake a SceneError naming the file and key; the end-of-life capacity they
give, worked out by hand."""

import math
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.io.limits_section import parse_limits
from floatmoor.io.mooring_design import parse_mooring_design
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.io.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
FLOATEL = ROOT / "vessels" / "floatel_like" / "mooring.yaml"


def _mooring(tmp_path, extra_top="", line_extra="", seg_extra="", defaults_extra=""):
    text = FLOATEL.read_text()
    if defaults_extra:
        text = text.replace("defaults:\n", f"defaults:\n  {defaults_extra}\n")
    if seg_extra:
        text = text.replace("    - {type: floatel_chain_84, length: 1200.0}",
                            "    - {type: floatel_chain_84, length: 1200.0, " + seg_extra + "}")
    if line_extra:
        text = text.replace("  - name: line7   # azimuth 219 deg\n",
                            f"  - name: line7   # azimuth 219 deg\n    {line_extra}\n")
    text += extra_top
    f = tmp_path / "mooring.yaml"
    f.write_text(text)
    return Node.load(f)


def test_design_keys_are_read(tmp_path):
    node = _mooring(tmp_path, extra_top="design: {design_life: 5.0, corrosion: {splash: 0.8, "
                    "catenary: 0.2, bottom: 0.5}, splash_zone_depth: 12.0}\n",
                    line_extra="anchor_type: suction\n    anchor_capacity: 1.2e+7\n    "
                    "anchor_uplift_deg: 12.0", defaults_extra="anchor_type: drag",
                    seg_extra="corrosion_zone: bottom")
    parse_mooring(node, water_depth=150.0)              # the mooring itself accepts the keys
    d = parse_mooring_design(node)
    assert d.design_life == 5.0 and d.life == 5.0
    assert d.corrosion == {"splash": 0.8, "catenary": 0.2, "bottom": 0.5}
    assert d.splash_zone_depth == 12.0
    assert d.anchor("line7").type == "suction" and d.anchor("line7").capacity == 1.2e7
    assert d.anchor("line7").uplift_deg == pytest.approx(12.0)
    assert d.anchor("line1").type == "drag" and d.anchor("line1").capacity is None
    assert d.segment_zones[("line1", 0)] == "bottom"


def test_no_design_keys_give_the_defaults(tmp_path):
    d = parse_mooring_design(_mooring(tmp_path))
    assert d.design_life is None and d.life == 20.0 and d.corrosion is None
    assert d.anchor("line3").type is None


@pytest.mark.parametrize("kw, key", [
    (dict(extra_top="design: {design_lyfe: 20}\n"), "design.design_lyfe"),
    (dict(extra_top="design: {design_life: 0}\n"), "design.design_life"),
    (dict(extra_top="design: {corrosion: {splash: 40.0}}\n"), "design.corrosion.splash"),
    (dict(extra_top="design: {corrosion: {bottm: 0.4}}\n"), "design.corrosion.bottm"),
    (dict(line_extra="anchor_type: bucket"), "lines[6].anchor_type"),
    (dict(line_extra="anchor_capacity: -5.0"), "lines[6].anchor_capacity"),
    (dict(line_extra="anchor_uplift_deg: 120.0"), "lines[6].anchor_uplift_deg"),
    (dict(line_extra="anchor_typ: drag"), "lines[6].anchor_typ"),
    (dict(seg_extra="corrosion_zone: splsh"), "defaults.segments[0].corrosion_zone"),
])
def test_design_key_mistakes_name_the_key(tmp_path, kw, key):
    node = _mooring(tmp_path, **kw)
    with pytest.raises(SceneError) as err:
        parse_mooring(node, water_depth=150.0)
    assert err.value.key == key
    assert str(err.value.file).endswith("mooring.yaml")


def test_end_of_life_capacity_by_hand(tmp_path):
    """Floatel-like line: chain 84 mm (bottom, catenary), polyester, chain 84 mm (fairlead).
    Default: 20 years, DNV-OS-E301 (2008) chain rates (code file: splash 0.4, catenary 0.3,
    bottom 0.4 mm/year); the top chain is in the splash zone (no depth given): 84 - 0.4 x 20 =
    76 mm; the bottom chain touches the seabed: 76 mm; MBS 8500 x (76/84)^2 = 6958.05 kN.
    With design_life 10, splash_zone_depth 5 m (the fairlead at -8.7 m is below it: catenary
    0.3 for the top chain) and an explicit zone for the bottom chain (catenary): 84 - 3 = 81 mm
    for both, MBS 8500 x (81/84)^2 = 7903.7 kN; polyester keeps 8500 kN."""
    from floatmoor.post.capacity import segment_capacities
    node = _mooring(tmp_path)
    m = parse_mooring(node, water_depth=150.0)
    cap = segment_capacities(m, parse_mooring_design(node))
    c = cap.sel(line="line7")
    assert list(c["zones"].values) == ["bottom+catenary", "catenary", "splash+catenary"]
    np.testing.assert_allclose(c["diameter_eol"].values * 1e3, [76.0, 185.0, 76.0])
    np.testing.assert_allclose(c["mbs_eol"].values / 1e3,
                               [8500 * (76 / 84) ** 2, 8500, 8500 * (76 / 84) ** 2])
    assert float(cap["mbs_eol_line"].sel(line="line7")) == pytest.approx(6958.04989e3, rel=1e-8)
    assert cap.attrs["design_life_source"].startswith("default 20 years")
    node = _mooring(tmp_path, extra_top="design: {design_life: 10.0, splash_zone_depth: 5.0}\n",
                    seg_extra="corrosion_zone: catenary")
    cap = segment_capacities(m, parse_mooring_design(node))
    c = cap.sel(line="line7")
    assert list(c["zones"].values) == ["catenary", "catenary", "catenary"]
    np.testing.assert_allclose(c["diameter_eol"].values * 1e3, [81.0, 185.0, 81.0])
    assert float(cap["mbs_eol_line"].sel(line="line7")) == pytest.approx(
        8500e3 * (81 / 84) ** 2, rel=1e-12)


def test_limits_are_read_and_interpolated():
    node = Node({"offset": [{"name": "riser", "max": 20.0},
                            {"name": "gangway", "directions_deg": [90, 0, 180, 270],
                             "max": [10.0, 8.0, 8.0, 10.0], "limit_states": ["ULS"]}],
                 "points": [{"name": "tip", "position": [40, 0, 25], "max_vertical": 3.0}]},
                None, "limits")
    lim = parse_limits(node)
    riser, gangway = lim.offset
    assert riser.limit_at(1.0) == 20.0 and riser.limit_states == ("ULS", "ALS")
    # sorted by direction; 45 deg halfway between 8 (0 deg) and 10 (90 deg); periodic at 315
    assert gangway.limit_at(math.radians(45.0)) == pytest.approx(9.0)
    assert gangway.limit_at(math.radians(315.0)) == pytest.approx(9.0)
    assert gangway.limit_at(math.radians(-45.0)) == pytest.approx(9.0)
    assert gangway.limit_states == ("ULS",)
    assert lim.points[0].max_horizontal is None and lim.points[0].max_vertical == 3.0


@pytest.mark.parametrize("data, key", [
    ({"offset": [{"name": "a", "max": -1.0}]}, "limits.offset[0].max"),
    ({"offset": [{"name": "a", "max": 1.0}, {"name": "a", "max": 2.0}]}, "limits.offset[1].name"),
    ({"offset": [{"name": "a", "directions_deg": [0, 360], "max": [1, 2]}]},
     "limits.offset[0].directions_deg"),
    ({"offset": [{"name": "a", "directions_deg": [0, 90], "max": [1]}]}, "limits.offset[0].max"),
    ({"offset": [{"name": "a", "max": 1.0, "limit_states": ["SLS"]}]},
     "limits.offset[0].limit_states"),
    ({"points": [{"name": "p", "position": [1, 2]}]}, "limits.points[0].position"),
    ({"points": [{"name": "p", "position": [1, 2, 3], "max_heave": 2}]},
     "limits.points[0].max_heave"),
    ({"offsets": []}, "limits.offsets"),
])
def test_limit_mistakes_name_the_key(data, key):
    with pytest.raises(SceneError) as err:
        parse_limits(Node(data, None, "limits"))
    assert err.value.key == key


def test_scene_with_limits_describes_them(tmp_path):
    text = (ROOT / "scenes" / "oc3_hywind.yaml").read_text().replace(
        "../vessels", str(ROOT / "vessels"))
    f = tmp_path / "s.yaml"
    f.write_text(text + "limits: {offset: [{name: riser, max: 15.0}]}\n")
    s = load_scene(f)
    assert s.limits.offset[0].name == "riser"
    assert "offset limit riser: radial 15 m (ULS, ALS)" in s.describe()
    # the limits change no analysis: the input fingerprint of the run is the same
    from floatmoor.analyses.fingerprint import scene_fingerprint
    f2 = tmp_path / "s2.yaml"
    f2.write_text(text)
    assert scene_fingerprint(s) == scene_fingerprint(load_scene(f2))
