"""The configuration reader: every mistake becomes a SceneError naming file, key, expected, found."""

import math

import numpy as np
import pytest

from floatmoor import SceneError
from floatmoor.core.config import Node, looks_like_radians


def write(tmp_path, text, name="scene.yaml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_missing_file_names_the_path(tmp_path):
    with pytest.raises(SceneError) as exc:
        Node.load(tmp_path / "nope.yaml")
    assert "nope.yaml" in str(exc.value)
    assert "existing file" in exc.value.expected


def test_yaml_syntax_error_names_line(tmp_path):
    p = write(tmp_path, "a: 1\nb: [1, 2\n")
    with pytest.raises(SceneError) as exc:
        Node.load(p)
    assert exc.value.file == str(p)
    assert "line" in exc.value.key


def test_duplicate_keys_are_refused(tmp_path):
    p = write(tmp_path, "a: 1\na: 2\n")
    with pytest.raises(SceneError, match="duplicate key"):
        Node.load(p)


def test_float_bounds_and_types(tmp_path):
    n = Node.load(write(tmp_path, "w: {hs: -1.0, tp: '12', gamma: true, depth: 150}\n")).child("w")
    with pytest.raises(SceneError) as exc:
        n.float("hs", gt=0.0, unit="m")
    e = exc.value
    assert e.key == "w.hs" and e.found == -1.0 and "> 0" in e.expected
    assert str(e).startswith(str(n.file))
    with pytest.raises(SceneError, match="remove the quotes"):
        n.float("tp", gt=0)
    with pytest.raises(SceneError, match="a boolean|True"):
        n.float("gamma", ge=1.0)
    assert n.float("depth", gt=0) == 150.0
    with pytest.raises(SceneError) as exc:
        n.float("missing_key")
    assert "missing" in str(exc.value)


def test_unknown_keys_and_angle_hint(tmp_path):
    n = Node.load(write(tmp_path, "heading: 0.5\nhs: 2\n"))
    with pytest.raises(SceneError) as exc:
        n.reject_unknown({"hs", "heading_deg"})
    assert "heading_deg" in str(exc.value)
    with pytest.raises(SceneError, match="degrees"):
        n.angle_deg("heading_deg")


def test_angle_in_radians_is_refused_and_degrees_converted(tmp_path):
    n = Node.load(write(tmp_path, "a_deg: 3.1416\nb_deg: 90\nc_deg: 1.5708\nd_deg: 45.0\n"))
    with pytest.raises(SceneError, match="radians"):
        n.angle_deg("a_deg")
    with pytest.raises(SceneError, match="radians"):
        n.angle_deg("c_deg")
    assert n.angle_deg("b_deg") == pytest.approx(math.pi / 2)
    assert n.angle_deg("d_deg") == pytest.approx(math.pi / 4)
    assert looks_like_radians(6.2832) and not looks_like_radians(180.0) and not looks_like_radians(3.0)


def test_choice_lists_available_names(tmp_path):
    n = Node.load(write(tmp_path, "spectrum: jonswapp\n"))
    with pytest.raises(SceneError) as exc:
        n.choice("spectrum", {"jonswap": 1, "torsethaugen": 2}, what="wave spectrum")
    assert "jonswap, torsethaugen" in str(exc.value)
    assert exc.value.found == "jonswapp"


def test_arrays_paths_and_lists(tmp_path):
    (tmp_path / "sub").mkdir()
    write(tmp_path / "sub", "x: 1\n", "other.yaml")
    n = Node.load(write(tmp_path, "t: [[0, 1], [2, 3]]\nbad: [[0, 1], [2]]\np: sub/other.yaml\n"
                                  "q: nothere.yaml\nitems: [{a: 1}, 3]\ninc: sub/other.yaml\n"))
    np.testing.assert_array_equal(n.array("t", shape=(None, 2)), [[0, 1], [2, 3]])
    with pytest.raises(SceneError):
        n.array("bad", shape=(None, 2))
    assert n.path_value("p").name == "other.yaml"
    with pytest.raises(SceneError, match="does not exist"):
        n.path_value("q")
    with pytest.raises(SceneError) as exc:
        n.item_nodes("items")
    assert exc.value.key == "items[1]"
    assert n.child_or_file("inc").float("x") == 1.0


def test_scene_error_pickles():
    import pickle
    e = SceneError("f.yaml", "a.b", "a number > 0", -1.0, "hint")
    e2 = pickle.loads(pickle.dumps(e))
    assert str(e2) == str(e) and e2.key == "a.b"
    m = SceneError(None, "x", "a mapping")
    assert "missing" in str(pickle.loads(pickle.dumps(m)))


def test_exponent_without_sign_is_a_number(tmp_path):
    # YAML 1.1 (PyYAML) would read 1.73e8 and 2e5 as strings; floatmoor reads them as numbers.
    n = Node.load(write(tmp_path, "ea: 1.73e8\nb: 2e5\nc: -3E-2\nname: e5\nd: 1.5\ne: 7\n"))
    assert n.float("ea") == 1.73e8 and n.float("b") == 2e5 and n.float("c") == -0.03
    assert n.str("name") == "e5" and n.float("d") == 1.5 and n.int("e") == 7
