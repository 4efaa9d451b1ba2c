"""Seabed damping acting both ways (``Seabed(lift_off_damping=True)``, scene key
``finite_element: seabed: lift_off_damping``), opt-in.

Expected numbers, independent of the option's implementation:

* the contact law itself: on a node in full contact (penetration beyond the smoothing depth)
  the vertical seabed force changes by ``-c v_z`` with ``c`` the node's seabed damping
  coefficient when the node lifts (``v_z > 0``; the default gives no damping force then) and
  not at all when it moves into the seabed;
* the converged line does not depend on the option (a damping force on lifting nodes vanishes
  with the element length): 160 elements at dt 0.00625 s, OC3 line, surge 3 m at 15 s, with and
  without it within 1e-4 of the tension range (measured 2026-11-24: 0.000 % max / range / rms);
* a coarse line at the coupling step against that converged run (the benchmark's view of
  accuracy): 40 elements at dt 0.1 s within max 0.1 %, range 0.25 %, rms 0.15 % (measured
  0.070 / 0.184 / 0.108 %; the default contact 0.083 / 0.237 / 0.122 %; the irregular case of
  benchmarks/bench_fe_moordyn.py gains more, benchmarks/RESULTS.md).
"""

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.mooring.fe import FELine, Seabed
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.options import parse_fe_options
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import OC3, oc3_spec

BA = 0.8 * 2.0 * np.sqrt(384.243e6 * 77.7066) * 902.2 / 160     # N s, as the benchmark


def _line(n, lift, damping=-0.8):
    line = FELine(oc3_spec(n=n, damping=damping,
                           seabed=Seabed(depth=OC3["depth"], lift_off_damping=lift)))
    line.solve_static()
    line.start()
    return line


@pytest.mark.parametrize("vz", [0.05, -0.05])
def test_seabed_force_of_a_lifting_node(vz):
    f = {}
    for lift in (False, True):
        line = _line(20, lift)
        zc = line.S[K.S_ZC]
        pen = zc - line.r[:, 2]
        i = int(np.argmax(pen))           # the deepest grounded node
        assert 0 < i < line.n_nodes - 1
        dpen = max(0.5 * line.P[i, K.NP_W] / line.P[i, K.NP_KS], line.S[K.S_DC])
        r = line.r.copy()
        r[i, 2] = zc - 2.0 * dpen         # full contact: smooth step 1
        v = np.zeros_like(r)
        v[i, 2] = vz
        out = np.zeros_like(r)
        K.line_forces(r, v, line.fs, line.params(), False, 0.0, 0.0, out, line.work)
        f[lift] = out[i, 2]
        cs = line.P[i, K.NP_CS]
    assert cs > 0.0
    if vz > 0.0:
        assert f[True] - f[False] == pytest.approx(-cs * vz, rel=1e-9)
    else:
        assert f[True] == f[False]


def _tension(n, nsub, lift):
    line = _line(n, lift, damping=BA)
    m = HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0)
    ds = run_prescribed(line, m, 60.0, 0.1, substeps=nsub)
    sel = ds.time.values >= 45.0 - 1e-9
    return ds.fairlead_tension.values[sel]


def _errors(a, b):
    return (abs(a.max() / b.max() - 1), abs(np.ptp(a) / np.ptp(b) - 1),
            np.sqrt(np.mean((a - b) ** 2)) / np.ptp(b))


def test_converged_line_is_the_same_and_a_coarse_line_is_close():
    ref = _tension(160, 16, True)
    ref0 = _tension(160, 16, False)
    assert np.max(np.abs(ref - ref0)) < 1e-4 * np.ptp(ref0)
    e = _errors(_tension(40, 1, True), ref)
    assert e[0] < 1e-3 and e[1] < 2.5e-3 and e[2] < 1.5e-3


def test_scene_key():
    node = Node({"seabed": {"lift_off_damping": True}}, "scene.yaml", "mooring.finite_element")
    assert parse_fe_options(node).seabed_for(320.0).lift_off_damping is True
    assert parse_fe_options(None).seabed_for(320.0).lift_off_damping is False
    bad = Node({"seabed": {"lift_off_damping": "yes"}}, "scene.yaml", "mooring.finite_element")
    with pytest.raises(SceneError, match="lift_off_damping"):
        parse_fe_options(bad)
