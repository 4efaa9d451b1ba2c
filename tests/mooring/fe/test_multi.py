"""FEMooring fast path (all lines of a body in one numba call, floatmoor.mooring.fe.multi)
against the line-by-line path through FELine.advance: the same kernels, so the same numbers up
to round-off."""

from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import NumericalError
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.mooring.fe.body import FEMooring
from floatmoor.mooring.fe.from_system import specs_from_system

ROOT = Path(__file__).resolve().parents[3]


def _system():
    return parse_mooring(Node.load(ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"),
                         water_depth=320.0)


def _motion(t):
    w = 2 * np.pi / 12.0
    pose = np.array([2 * np.sin(w * t), 1.5 * np.sin(w * t + 1), 0.3 * np.sin(w * t),
                     0.01 * np.sin(w * t), -0.02 * np.sin(w * t + 0.5), 0.02 * np.sin(w * t)])
    vel = np.array([2 * w * np.cos(w * t), 1.5 * w * np.cos(w * t + 1), 0.3 * w * np.cos(w * t),
                    0.01 * w * np.cos(w * t), -0.02 * w * np.cos(w * t + 0.5),
                    0.02 * w * np.cos(w * t)])
    return pose, vel


def test_fast_path_equals_line_by_line():
    ms = _system()
    runs = {}
    for fast in (False, True):
        fm = FEMooring(specs_from_system(ms, element_length=25.0), ms.fairleads, fast=fast)
        fm.solve_static(np.zeros(6))
        fm.start()
        assert (fm._packed is not None) == fast
        Qs = []
        for k in range(1, 61):
            pose, vel = _motion(k * 0.1)
            # a first trial with another pose, then the real one: advance is repeatable
            fm.advance(k * 0.1, 0.1, pose * 1.1, vel)
            Qs.append(fm.advance(k * 0.1, 0.1, pose, vel, substeps=2 if k % 7 == 0 else 1))
            fm.accept()
        runs[fast] = (np.array(Qs), fm.line_forces, [ln.r.copy() for ln in fm.lines],
                      fm.newton_iterations, [ln.time for ln in fm.lines])
    a, b = runs[False], runs[True]
    scale = np.abs(a[0]).max()
    assert np.allclose(a[0], b[0], rtol=0, atol=1e-9 * scale)
    assert np.allclose(a[1], b[1], rtol=1e-12, atol=1e-9 * scale)
    for ra, rb in zip(a[2], b[2]):
        # round-off of the fairlead kinematics (loops vs numpy) carried through Newton
        # (tolerance 1e-6 m): measured 1.5e-9 m
        assert np.allclose(ra, rb, rtol=0, atol=1e-7)
    assert np.array_equal(a[3], b[3]) and a[3].min() > 0
    assert a[4] == b[4] == [pytest.approx(6.0)] * 3


def test_fast_path_failure_names_time_line_node():
    """A line that cannot converge (maxit 1, no step splits) fails with a NumericalError
    naming the line, the node and a time inside the step."""
    ms = _system()
    fm = FEMooring(specs_from_system(ms, element_length=25.0), ms.fairleads)
    fm.solve_static(np.zeros(6))
    fm.start(maxit=1)
    fm.lines[0].MAX_SPLIT = 0
    with pytest.raises(NumericalError, match=r"line line1, node \d+") as e:
        for k in range(1, 20):
            pose, vel = _motion(k * 0.1)
            fm.advance(k * 0.1, 0.1, 20 * pose, 20 * vel)
            fm.accept()
    assert e.value.time is not None and 0.0 <= e.value.time <= 1.9


def test_fe_mooring_from_the_scene_choice():
    """FEMooring.from_system takes the lines the scene marks finite-element, with the scene's
    options; its static force equals the sum of those lines' quasi-static forces (0.3 %)."""
    import yaml

    d = yaml.safe_load((ROOT / "vessels" / "oc3_hywind" / "mooring.yaml").read_text())
    d["finite_element"] = {"n_elements": 36}
    d["model"] = "finite-element"
    d["lines"][2]["model"] = "quasi-static"
    ms = parse_mooring(Node(d, ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    fm, names = FEMooring.from_system(ms)
    assert names == ["line1", "line2"]
    assert [ln.n_nodes - 1 for ln in fm.lines] == [36, 36]
    pose = np.array([4.0, -2.0, 0.0, 0.0, 0.0, 0.03])
    Q = fm.solve_static(pose)
    Qqs = ms.without_lines(["line3"]).force(pose)
    assert np.allclose(Q[:3], Qqs[:3], atol=3e-3 * np.abs(Qqs[:3]).max())
    assert FEMooring.from_system(_system()) == (None, [])     # default: quasi-static
