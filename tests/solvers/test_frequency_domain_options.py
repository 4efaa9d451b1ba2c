"""The frequency_domain: scene section parser (floatmoor.io.fd_section) and FDOptions checks."""

from __future__ import annotations

import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.io.fd_section import parse_fd_options, parse_frequency_domain
from floatmoor.solvers.frequency_domain import FDOptions


def _node(data):
    return Node({"frequency_domain": data}, "scene.yaml").child("frequency_domain")


def test_defaults_and_values():
    assert parse_fd_options(_node({})) == FDOptions()
    o = parse_fd_options(_node({"duration": 3600.0, "drift": "newman", "wave_drift_damping": True,
                                "lf_cutoff_period": 25.0}))
    assert (o.duration, o.drift, o.wave_drift_damping, o.lf_cutoff_period) == \
        (3600.0, "newman", True, 25.0)
    assert parse_frequency_domain(Node({}, "s.yaml"), "frequency_domain", {}) is None


@pytest.mark.parametrize("data, key", [
    ({"duration": -5.0}, "frequency_domain.duration"),
    ({"tension_model": "fully_dynamic"}, "frequency_domain.tension_model"),
    ({"drift": "pinkster"}, "frequency_domain.drift"),
    ({"wave_drift_damping": "yes"}, "frequency_domain.wave_drift_damping"),
    ({"n_lf": 10}, "frequency_domain.n_lf"),
    ({"durration": 3.0}, "frequency_domain"),
])
def test_mistakes_name_file_and_key(data, key):
    with pytest.raises(SceneError) as info:
        parse_fd_options(_node(data))
    assert info.value.file == "scene.yaml"
    assert key in str(info.value)


def test_fdoptions_refuses_bad_values_in_python():
    with pytest.raises(SceneError, match="d_omega"):
        FDOptions(d_omega=0.0)
    with pytest.raises(SceneError, match="heading_iterations"):
        FDOptions(heading_iterations=0)
