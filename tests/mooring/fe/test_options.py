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
