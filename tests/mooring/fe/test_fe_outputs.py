"""Issue-9 audit, line-model items without a test so far: profile snapshots (outputs), the
normal and tangential added mass of the node mass blocks, and a buoy at a node."""

import math
import time

import numpy as np
import pytest

from floatmoor.mooring import solve_line
from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, PointBody, Seabed
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import OC3, oc3_spec, oc3_type


def test_profile_snapshots_match_the_state_and_the_tension_channels():
    """Snapshots at t = 0 (the static profile), 7.5 s and 15 s: positions equal the static
    solution / the final state, the fairlead node follows the prescribed motion, and the largest
    element tension of each snapshot is the ``max_tension`` channel at that time."""
    line = FELine(oc3_spec(n=30))
    s = line.solve_static()
    line.start()
    m = HarmonicMotion(amplitude=(-3.0, 1.0, 0.0), period=15.0, ramp=15.0)
    ds = run_prescribed(line, m, 15.0, 0.1, snapshot_times=(0.0, 7.5, 15.0))
    P = ds.profile_position.values
    assert P.shape == (3, line.n_nodes, 3)
    assert np.allclose(ds.snapshot.values, [0.0, 7.5, 15.0])
    assert np.allclose(P[0], s.positions, atol=1e-12)
    assert np.allclose(P[2], line.r, atol=1e-12)
    for k, t in enumerate(ds.snapshot.values):
        d, _ = m(t)
        assert np.allclose(P[k, -1], np.asarray(OC3["fairlead"]) + d, atol=1e-9)
        assert P[k, 0] == pytest.approx(np.asarray(OC3["anchor"]))
        j = int(np.argmin(np.abs(ds.time.values - t)))
        assert ds.profile_tension.values[k].max() == pytest.approx(
            float(ds.max_tension.values[j]), rel=1e-12)



@pytest.mark.parametrize("integrator", ["generalized_alpha", "explicit"])
def test_stats_time_the_steps_alone_and_leave_the_answer(integrator):
    """``run_prescribed(..., stats=d)`` gives the CPU time of the steps alone (the benchmark
    against MoorDyn times that) and the step count, and changes no number of the run."""
    m = HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0)
    dt = 0.1 if integrator == "generalized_alpha" else 0.002
    runs = []
    for stats in (None, {}):
        line = FELine(oc3_spec(n=20))
        line.solve_static()
        line.start(integrator=integrator)
        c0 = time.process_time()
        ds = run_prescribed(line, m, 3.0, dt, stats=stats)
        total = time.process_time() - c0
        runs.append(ds.fairlead_tension.values)
    assert stats["steps"] == round(3.0 / dt)
    assert 0.0 < stats["cpu_steps"] <= total
    assert np.array_equal(runs[0], runs[1])

def test_node_mass_blocks_have_normal_and_tangential_added_mass():
    """Straight horizontal line along x (3 elements of 10 m): interior node blocks
    ``diag(m + m_at, m + m_an, m + m_an)`` with ``m_a = rho C_a (pi D^2 / 4) l`` per node
    (Morison, DNV-RP-C205 sec. 6.9) for C_an = 1.0, C_at = 0.3; rotated by 30 deg about z the
    block is ``R diag R^T``."""
    d, m_l, rho, l = 0.1, 50.0, 1025.0, 10.0
    lt = oc3_type()
    lt = type(lt)(**{**lt.__dict__, "diameter": d, "mass_per_length": m_l,
                     "displaced_volume": math.pi * d * d / 4, "can": 1.0, "cat": 0.3})
    for ang in (0.0, math.radians(30.0)):
        c, s_ = math.cos(ang), math.sin(ang)
        spec = FELineSpec(name="m", anchor=(0.0, 0.0, -20.0), fairlead=(30 * c, 30 * s_, -20.0),
                          segments=(FESegment(line_type=lt, length=30.0, n_elements=3),),
                          seabed=Seabed(depth=100.0))
        line = FELine(spec)
        r = np.array([[10 * i * c, 10 * i * s_, -20.0] for i in range(4)])
        Mb = np.zeros((4, 3, 3))
        K.node_mass(r, line.P, np.zeros((4, 3)), Mb)
        man = rho * 1.0 * math.pi * d * d / 4 * l
        mat = rho * 0.3 * math.pi * d * d / 4 * l
        R = np.array([[c, -s_, 0.0], [s_, c, 0.0], [0.0, 0.0, 1.0]])
        ref = R @ np.diag([m_l * l + mat, m_l * l + man, m_l * l + man]) @ R.T
        for i in (1, 2):
            assert np.allclose(Mb[i], ref, rtol=1e-12, atol=1e-9)


def test_buoy_at_a_joint_against_multisegment_catenary():
    """Two OC3 segments with a 10 m^3 buoy of 2 t at the joint (net uplift 81 kN), statics
    against the multi-segment catenary with a negative point load (floatmoor.mooring.solve_line),
    as the clump-weight test of test_model does for a weight."""
    lt = oc3_type()
    rho, g = 1025.0, 9.80665
    mass, vol = 2000.0, 10.0
    P = (mass - rho * vol) * g
    spec = FELineSpec(name="buoyed", anchor=OC3["anchor"], fairlead=OC3["fairlead"],
                      segments=(FESegment(line_type=lt, length=600.0, n_elements=40),
                                FESegment(line_type=lt, length=302.2, n_elements=20)),
                      point_bodies=(PointBody(node=40, mass=mass, volume=vol),),
                      seabed=Seabed(depth=OC3["depth"]))
    s = FELine(spec).solve_static()
    w = lt.submerged_weight()
    ref = solve_line(848.67, 250.0, [600.0, 302.2], [lt.ea] * 2, [w, w], [P, 0.0])
    assert P < 0.0
    assert s.fairlead_tension == pytest.approx(ref.fairlead_tension, rel=2e-3)
