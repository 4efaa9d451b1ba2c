"""The coupled run's FE lines as SIMD lanes (the default for one thread,
``floatmoor/mooring/fe/lanes_body.py``) against the same lines advanced one by one
(``fe_coupling.LANES`` False).

Reference: the line-by-line path itself.  Each lane does its line's arithmetic operation for
operation (tests/mooring/fe/test_lanes.py), so every output must be equal bit for bit: an
intact storm with waves, a storm with a line released (ALS), and a storm whose FE step fails
(the same NumericalError, naming the same line, time and node).  The flagship's digests
(tests/test_bit_identity.py) run the lanes too.
"""

from __future__ import annotations

import numpy as np
import pytest

from floatmoor.core.errors import NumericalError
from floatmoor.mooring.fe.lanes_body import LaneLines
from floatmoor.solvers import fe_coupling as FC
from tests.solvers.test_fe_threads import SEA, _assert_same, _run
from tests.solvers.test_time_domain_fe import _scene


def _both(monkeypatch, p, **kw):
    out = []
    for lanes in (True, False):
        monkeypatch.setattr(FC, "LANES", lanes)
        out.append(_run(p, 1, **kw))
    return out


def test_lanes_are_the_default_and_bit_identical(tmp_path, monkeypatch):
    p = _scene(tmp_path, n_elements=8, environment=SEA)
    seen = []
    orig = FC._mode

    def spy(lines, threads):
        m = orig(lines, threads)
        seen.append(m)
        return m
    monkeypatch.setattr(FC, "_mode", spy)
    (r1, c1), (r2, c2) = _both(monkeypatch, p)
    assert isinstance(seen[0], LaneLines) and not isinstance(seen[1], LaneLines)
    # the lines fill the lanes by start tension (lane_order), not in line order: the
    # comparison below covers the permutation
    order = [int(k) for k in seen[0].line_of[:12]]
    assert sorted(order) == list(range(12)) and order != list(range(12))
    assert all(seen[0].slot[k] == p for p, k in enumerate(order))
    _assert_same(r1, r2)
    np.testing.assert_array_equal(c1, c2)
    assert c1[:, 0].min() > 0 and np.ptp(r1.motion[:, 0]) > 0.01   # the lines worked


def test_lanes_with_a_released_line(tmp_path, monkeypatch):
    p = _scene(tmp_path, n_elements=8, environment=SEA,
               forces={"line_failure": {"line6": 16.0}})
    (r1, c1), (r2, c2) = _both(monkeypatch, p)
    j = r1.line_names.index("line6")
    assert r1.line_tension[-1, j] == 0.0 and r1.line_tension[0, j] > 1e5
    _assert_same(r1, r2)
    np.testing.assert_array_equal(c1, c2)


def test_a_failing_lane_raises_the_line_error(tmp_path, monkeypatch):
    """Lines 5-8 (a block of lanes of their own: ``lane_order`` groups the lines by iteration
    limit first) allowed no Newton iteration: the first step fails
    at its smallest sub-step, and the error names line5 with the time and node of the
    line-by-line run."""
    p = _scene(tmp_path, n_elements=8)

    def no_newton(a):
        orig = a.fe.mooring.start

        def start(**kw):
            orig(**kw)
            for i in (4, 5, 6, 7):
                a.fe.mooring.lines[i].maxit = 0
        a.fe.mooring.start = start

    seen = []
    orig_mode = FC._mode
    monkeypatch.setattr(FC, "_mode", lambda lines, threads: seen.append(
        orig_mode(lines, threads)) or seen[-1])
    msgs = []
    for lanes in (True, False):
        monkeypatch.setattr(FC, "LANES", lanes)
        with pytest.raises(NumericalError) as e:
            _run(p, 1, duration=10.0, patch=no_newton)
        msgs.append(str(e.value))
    assert isinstance(seen[0], LaneLines) and not isinstance(seen[1], LaneLines)
    assert "line 'line5'" in msgs[0] and "at t = " in msgs[0]
    assert msgs[0] == msgs[1]
