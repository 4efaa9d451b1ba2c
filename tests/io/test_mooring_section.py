"""Mooring section parser: the two reference files, and every mistake as a SceneError."""

import math
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.io.mooring_section import parse_mooring

ROOT = Path(__file__).resolve().parents[2]
OC3 = ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"
FLOATEL = ROOT / "vessels" / "floatel_like" / "mooring.yaml"


def write(tmp_path, text, name="mooring.yaml"):
    p = tmp_path / name
    p.write_text(text)
    return p


BASE = """
line_types:
  my_chain: {material: chain, diameter: 0.1, mass_per_length: 200.0, density: 7850.0,
             ea: 8.0e+8, mbs: 9.0e+6}
lines:
  - name: L1
    anchor: {radius: 800.0, azimuth_deg: 0.0}
    fairlead: [10.0, 0.0, -15.0]
    segments:
      - {type: my_chain, length: %s}
"""


def load(tmp_path, text, depth=200.0, **kw):
    return parse_mooring(Node.load(write(tmp_path, text)), water_depth=depth, **kw)


def test_oc3_file_reproduces_map_and_published_stiffness():
    """vessels/oc3_hywind/mooring.yaml: MAP++ .sum H = 736,939 N, V = 535,728 N per line;
    Jonkman (2010) K11 41,180 N/m, K33 11,940 N/m, K15 -2.821e6 N/rad, K44 = K55 3.111e8,
    K66 1.156e7 N m/rad (within 1 %)."""
    ms = parse_mooring(Node.load(OC3), water_depth=320.0)
    t = ms.tensions()
    np.testing.assert_allclose(t["horizontal_fairlead"], 736939.29, rtol=1e-5)
    np.testing.assert_allclose(t["vertical_fairlead"], 535727.99, rtol=1e-5)
    K = ms.stiffness()
    for (i, j), ref in {(0, 0): 41180, (2, 2): 11940, (0, 4): -2.821e6, (3, 3): 3.111e8,
                        (4, 4): 3.111e8, (5, 5): 1.156e7}.items():
        assert K[i, j] == pytest.approx(ref, rel=0.01), (i, j)


def test_floatel_file_level_and_symmetry():
    """vessels/floatel_like/mooring.yaml.  The anchor radius was calibrated to 9,500 kN at
    30 m (Wang (2016) sec. 5.4.2), so the level is a regression check; the slope at 30 m is compared
    with Wang's (2016) 307 kN/m (sec. 5.4.3, within 15 %), the pretension with its ~1,000 kN."""
    ms = parse_mooring(Node.load(FLOATEL), water_depth=150.0)
    assert ms.n_lines == 12
    f30 = ms.force([30.0, 0, 0, 0, 0, 0])
    assert -f30[0] == pytest.approx(9.5e6, rel=0.01)
    slope = -(ms.force([31.0, 0, 0, 0, 0, 0])[0] - ms.force([29.0, 0, 0, 0, 0, 0])[0]) / 2
    assert slope == pytest.approx(3.07e5, rel=0.15)
    t0 = ms.tensions()
    assert float(t0["fairlead_tension"].mean()) == pytest.approx(1.0e6, rel=0.1)
    # symmetric about the heading (surge, heading 0): line k and line 13-k carry the same tension
    t = ms.tensions([20.0, 0, 0, 0, 0, 0])["fairlead_tension"].values
    np.testing.assert_allclose(t, t[::-1], rtol=1e-9)
    # loaded lines are those anchored towards -x (4-9), most loaded 6 and 7 (Wang (2016) fig. 5.9)
    assert set(np.argsort(t)[-2:]) == {5, 6}
    # diagonal heading 45 deg: mirror about the diagonal maps line k of group 1 onto 4 - k etc.
    d = 20.0 / math.sqrt(2)
    t45 = ms.tensions([d, d, 0, 0, 0, 0])["fairlead_tension"]
    assert float(t45.sel(line="line1")) == pytest.approx(float(t45.sel(line="line3")), rel=1e-9)
    assert float(t45.sel(line="line6")) == pytest.approx(float(t45.sel(line="line10")), rel=1e-9)
    # (line failure at equilibrium: tests/solvers/test_statics.py)


def test_failed_lines_key(tmp_path):
    text = OC3.read_text() + "failed_lines: [line2]\n"
    p = write(tmp_path, text)
    ms = parse_mooring(Node.load(p), water_depth=320.0)
    assert ms.failed == ("line2",)
    assert ms.force(np.zeros(6))[1] < -1e5  # line 2 (towards +y side) gone
    bad = write(tmp_path, OC3.read_text() + "failed_lines: [line9]\n", "bad.yaml")
    with pytest.raises(SceneError, match=r"failed_lines\[0\].*line1, line2, line3"):
        parse_mooring(Node.load(bad), water_depth=320.0)


@pytest.mark.parametrize("length", ["0.0", "-5.0"])
def test_zero_or_negative_length(tmp_path, length):
    with pytest.raises(SceneError) as exc:
        load(tmp_path, BASE % length)
    assert "lines[0].segments[0].length" in str(exc.value) and "> 0" in str(exc.value)


def test_zero_ea(tmp_path):
    text = (BASE % "850.0").replace("ea: 8.0e+8", "ea: 0.0")
    with pytest.raises(SceneError, match=r"line_types.my_chain.ea.*> 0"):
        load(tmp_path, text)


def test_unknown_line_type_lists_the_available_ones(tmp_path):
    text = (BASE % "850.0").replace("{type: my_chain", "{type: my_chian")
    with pytest.raises(SceneError) as exc:
        load(tmp_path, text)
    msg = str(exc.value)
    assert "segments[0].type" in msg and "my_chian" in msg
    assert "my_chain" in msg and "chain_studless_R4" in msg and "polyester" in msg


def test_anchor_above_its_fairlead(tmp_path):
    text = (BASE % "850.0").replace("{radius: 800.0, azimuth_deg: 0.0}",
                                    "{radius: 800.0, azimuth_deg: 0.0, z: -5.0}")
    with pytest.raises(SceneError, match=r"lines\[0\].anchor.*below its fairlead.*'L1'"):
        load(tmp_path, text)


def test_anchor_below_seabed(tmp_path):
    text = (BASE % "850.0").replace("{radius: 800.0, azimuth_deg: 0.0}",
                                    "{radius: 800.0, azimuth_deg: 0.0, z: -250.0}")
    with pytest.raises(SceneError, match=r"lines\[0\].anchor.z"):
        load(tmp_path, text)


def test_line_too_short_is_refused_with_tension_against_mbs(tmp_path):
    """800 m anchor radius, 200 m depth: a 780 m line must stretch beyond its MBS at rest; the
    SceneError gives the tension against the MBS, the length and the anchor-fairlead distance
    (a design tool must not go on to a heave of -184 m with exit status 0)."""
    with pytest.raises(SceneError, match=r"lines\[0\]\.segments: expected a line whose tension "
                       r"at zero offset is below its MBS 9000.0 kN.*'L1': unstretched length "
                       r"780 m, anchor-fairlead distance"):
        load(tmp_path, BASE % "780.0")


def test_buoyant_segment_on_the_seabed_is_refused(tmp_path):
    text = BASE % "100.0" + """      - {type: float_rope, length: 50.0}
      - {type: my_chain, length: 800.0}
"""
    text = text.replace("line_types:\n", "line_types:\n  float_rope: {diameter: 0.3, "
                        "mass_per_length: 20.0, density: 500.0, ea: 1.0e+8, mbs: 5.0e+6}\n")
    with pytest.raises(SceneError, match=r"segments.*'L1'.*buoyant"):
        load(tmp_path, text)


def test_extra_library_file_and_formula_family(tmp_path):
    write(tmp_path, "line_types:\n  big_chain: {family: chain_studlink, grade: R5, diameter: 0.12}\n",
          "lib.yaml")
    text = ("line_type_library: lib.yaml\n" + BASE % "850.0").replace(
        "{type: my_chain, length: 850.0}", "{type: big_chain, length: 850.0}")
    ms = load(tmp_path, text)
    # studlink 120 mm R5: mass 0.0219 d^2, MBS 0.0320 d^2 (44 - 0.08 d) kN
    assert ms.lines[0].segments[0].mass_per_length == pytest.approx(0.0219 * 120 ** 2)
    assert ms.mbs[0] == pytest.approx(0.0320 * 120 ** 2 * (44 - 9.6) * 1e3)


def test_family_without_diameter(tmp_path):
    text = (BASE % "850.0").replace("{type: my_chain, length: 850.0}",
                                    "{type: chain_studless_R4, length: 850.0}")
    with pytest.raises(SceneError, match=r"segments\[0\].diameter"):
        load(tmp_path, text)


def test_unknown_keys_and_duplicate_names(tmp_path):
    with pytest.raises(SceneError, match="lenght"):
        load(tmp_path, (BASE % "850.0").replace("length: 850.0", "lenght: 850.0"))
    text = BASE % "850.0" + """  - name: L1
    anchor: {radius: 800.0, azimuth_deg: 90.0}
    fairlead: [0.0, 10.0, -15.0]
    segments: [{type: my_chain, length: 850.0}]
"""
    with pytest.raises(SceneError, match=r"lines\[1\].name.*unique"):
        load(tmp_path, text)


def test_inline_section_names_the_scene_key():
    node = Node({"mooring": {"lines": [{"name": "a", "anchor": [0, 0, -100],
                                        "fairlead": [0, 0, -10],
                                        "segments": [{"type": "nope", "length": 5}]}]}},
                "scene.yaml").child("mooring")
    with pytest.raises(SceneError) as exc:
        parse_mooring(node, water_depth=100.0)
    assert exc.value.file == "scene.yaml"
    assert exc.value.key == "mooring.lines[0].segments[0].type"
