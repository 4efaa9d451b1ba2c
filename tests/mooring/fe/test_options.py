"""FE options from scene YAML: values, defaults and SceneErrors naming the key."""

import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.mooring.fe.options import parse_fe_options


def _node(d):
    return Node(d, "scene.yaml", "mooring.finite_element")


def test_options_are_read():
    o = parse_fe_options(_node({"element_length": 15.0, "internal_damping": -0.8,
                                "rho_inf": 0.6, "substeps": 2,
                                "seabed": {"model": "mud_layer", "mud_depth": 0.2},
                                "friction": {"model": "displacement_velocity_ramp",
                                             "mu_axial": 0.7, "mu_lateral": 1.0}}))
    assert o.element_length == 15.0 and o.substeps == 2 and o.rho_inf == 0.6
    sb = o.seabed_for(320.0)
    assert sb.model == "mud_layer" and sb.mud_depth == 0.2 and sb.depth == 320.0
    assert o.friction.model == "displacement_velocity_ramp" and o.friction.mu_lateral == 1.0
    assert parse_fe_options(None).element_length == 20.0


@pytest.mark.parametrize("d,key", [
    ({"element_lenght": 10.0}, "element_lenght"),
    ({"rho_inf": 1.5}, "rho_inf"),
    ({"friction": {"model": "coulomb"}}, "friction.model"),
    ({"seabed": {"model": "sand"}}, "seabed.model"),
    ({"substeps": 0}, "substeps"),
])
def test_bad_options_name_the_key(d, key):
    with pytest.raises(SceneError, match=rf"scene.yaml: mooring.finite_element.{key}"):
        parse_fe_options(_node(d))


def test_more_options_and_the_derived_keywords():
    o = parse_fe_options(_node({"n_elements": 40, "dt": 0.04, "integrator": "explicit"}))
    assert o.n_elements == 40 and o.integrator == "explicit"
    assert o.substeps_for(0.1) == 3                    # ceil(0.1 / 0.04)
    assert o.substeps_for(0.04) == 1
    assert parse_fe_options(_node({"substeps": 4})).substeps_for(0.1) == 4
    assert o.start_kw() == {"rho_inf": 0.7, "integrator": "explicit", "newton": "exact"}
    kw = o.spec_kw(320.0)
    assert kw["n_elements"] == 40 and kw["seabed"].depth == 320.0 and "friction" not in kw


@pytest.mark.parametrize("d,key", [
    ({"element_length": 10.0, "n_elements": 30}, "n_elements"),
    ({"dt": 0.05, "substeps": 2}, "dt"),
    ({"integrator": "rk4"}, "integrator"),
    ({"n_elements": 0}, "n_elements"),
])
def test_conflicting_or_bad_options(d, key):
    with pytest.raises(SceneError, match=rf"scene.yaml: mooring.finite_element.{key}"):
        parse_fe_options(_node(d))


def _mooring(extra_top=None, line2=None):
    seg = [{"type": "chain_studless_R3", "diameter": 0.09, "length": 902.2}]
    lines = [{"name": "l1", "anchor": [853.87, 0.0, -320.0], "fairlead": [5.2, 0.0, -70.0],
              "segments": seg},
             {"name": "l2", "anchor": [-853.87, 0.0, -320.0], "fairlead": [-5.2, 0.0, -70.0],
              "segments": seg, **(line2 or {})}]
    return Node({"lines": lines, **(extra_top or {})}, "scene.yaml", "mooring")


def test_line_models_from_the_mooring_section():
    """``mooring: {model: ...}`` for all lines, ``lines[i].model`` per line, default
    quasi-static; the parsed choice is kept on the MooringSystem for the builder."""
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.options import parse_line_models

    ms = parse_mooring(_mooring(), water_depth=320.0)
    assert ms.line_models.models == {"l1": "quasi-static", "l2": "quasi-static"}
    assert not ms.line_models.any_finite_element
    ms = parse_mooring(_mooring({"model": "finite-element",
                                 "finite_element": {"n_elements": 30}},
                                {"model": "quasi-static"}), water_depth=320.0)
    assert ms.line_models.finite_element_lines == ["l1"]
    assert ms.line_models.model_of("l2") == "quasi-static"
    assert ms.line_models.options.n_elements == 30
    lm = parse_line_models(_mooring(None, {"model": "finite-element"}))
    assert lm.finite_element_lines == ["l2"]


@pytest.mark.parametrize("top,line2,key", [
    ({"model": "lumped"}, None, r"mooring.model"),
    (None, {"model": "fe"}, r"mooring.lines\[1\].model"),
    ({"finite_element": {"rho_inf": -1}}, None, r"mooring.finite_element.rho_inf"),
])
def test_bad_line_model_names_file_and_key(top, line2, key):
    from floatmoor.io.mooring_section import parse_mooring

    with pytest.raises(SceneError, match=rf"scene.yaml: {key}") as e:
        parse_mooring(_mooring(top, line2), water_depth=320.0)
    if "model" in key and "finite" not in key:
        assert "finite-element" in str(e.value)


def test_element_count_of_the_whole_line_is_shared_by_length():
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.from_system import spec_from_linedef, split_elements

    assert split_elements([762.0, 1828.8, 76.2], 50) == [14, 34, 2]   # 50 x L_i / 2667
    assert sum(split_elements([1.0, 5.0, 300.0], 7)) == 7
    assert split_elements([1.0, 1.0, 1.0], 2) == [1, 1, 1]            # at least one each
    ms = parse_mooring(_mooring(), water_depth=320.0)
    assert spec_from_linedef(ms.lines[0], water_depth=320.0, n_elements=37).n_elements == 37


def test_element_counts_given_per_segment():
    """``n_elements: [n1, n2, ...]``: the elements of each segment, anchor to fairlead (the
    flagship's [12, 26, 12], vessels/floatel_like/mooring_fe.yaml): each segment gets its count
    and elements of its own length; the FELine's node arc lengths follow."""
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.from_system import spec_from_linedef
    from floatmoor.mooring.fe.line import FELine

    seg = [{"type": "chain_studless_R3", "diameter": 0.09, "length": 300.0},
           {"type": "chain_studless_R3", "diameter": 0.09, "length": 602.2}]
    node = _mooring({"model": "finite-element", "finite_element": {"n_elements": [3, 14]}},
                    {"segments": seg})
    node.data["lines"][0]["segments"] = seg
    ms = parse_mooring(node, water_depth=320.0)
    assert ms.line_models.options.n_elements == (3, 14)
    spec = spec_from_linedef(ms.lines[0], water_depth=320.0,
                             **ms.line_models.options.spec_kw(320.0))
    assert [s.n_elements for s in spec.segments] == [3, 14] and spec.n_elements == 17
    line = FELine(spec)
    ds = line.s_nodes[1:] - line.s_nodes[:-1]
    assert ds[:3] == pytest.approx([100.0] * 3, rel=1e-12)
    assert ds[3:] == pytest.approx([602.2 / 14] * 14, rel=1e-12)


@pytest.mark.parametrize("value", [[], [3, 0], [3, 2.5], [True, 3], "3, 14"])
def test_bad_element_counts_per_segment_name_the_key(value):
    with pytest.raises(SceneError, match=r"scene.yaml: mooring.finite_element.n_elements"):
        parse_fe_options(_node({"n_elements": value}))


def test_element_counts_per_segment_must_match_every_fe_line():
    """A list of counts whose length is not every FE line's segment count is refused when the
    mooring is read (file, key, the line), and by spec_from_linedef given in Python."""
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.from_system import spec_from_linedef

    with pytest.raises(SceneError, match=r"scene.yaml: mooring.finite_element.n_elements.*"
                                         r"line 'l1' has 1 segments") as e:
        parse_mooring(_mooring({"model": "finite-element",
                                "finite_element": {"n_elements": [3, 14]}}), water_depth=320.0)
    assert "[3, 14]" in str(e.value)
    # a quasi-static line of another segment count is not concerned
    ms = parse_mooring(_mooring({"finite_element": {"n_elements": [3, 14]}},
                                {"model": "quasi-static"}), water_depth=320.0)
    with pytest.raises(SceneError, match=r"finite_element.n_elements.*one element count per "
                                         r"segment \(1 for line 'l1'"):
        spec_from_linedef(ms.lines[0], water_depth=320.0, n_elements=(3, 14))


@pytest.mark.parametrize("fe,key,found", [
    ({"n_elements": 100000}, "n_elements", "100000"),
    ({"n_elements": [25000]}, "n_elements", r"\[25000\]"),
    ({"element_length": 0.01}, "element_length", "0.01"),
])
def test_too_many_elements_name_the_file_when_the_mooring_is_read(fe, key, found):
    """More than MAX_ELEMENTS (20,000) elements on a FE line: refused when the mooring file is
    read, naming the file, the key, the value and the line (the 902.2 m line at 0.01 m is
    90,220 elements), before any array is allocated; quasi-static lines are not concerned."""
    from floatmoor.io.mooring_section import parse_mooring

    with pytest.raises(SceneError, match=rf"scene.yaml: mooring.finite_element.{key}: expected "
                                         rf"at most 20,000 elements per line.*found {found}.*"
                                         r"line 'l1'"):
        parse_mooring(_mooring({"model": "finite-element", "finite_element": fe}),
                      water_depth=320.0)
    parse_mooring(_mooring({"finite_element": fe}), water_depth=320.0)
