"""Static current drag on the lines as an increment on the catenary force
(:mod:`floatmoor.mooring.fe.current_statics`, the frequency domain's ``line_current_drag``).

Expected values come from: the still-water limit (the increment is exactly zero), MoorPy 1.3
(``System(current=...)``: ``Line.staticSolve`` adds the current drag of its last profile,
summed over its segments with the local tangent, to the weight as a uniform load and solves a
catenary in the plane of the tilted load; repeated here until the fairlead force settles), and
the generalised force of the coupled time domain's FE lines
(:meth:`floatmoor.mooring.fe.body.FEMooring.solve_static`).
"""

import math

import numpy as np
import pytest

from floatmoor.mooring.fe.body import FEMooring
from floatmoor.mooring.fe.current_statics import LineCurrentStatics
from floatmoor.mooring.fe.from_system import spec_from_linedef
from floatmoor.mooring.line_types import LineType
from floatmoor.mooring.system import LineDef, MooringSystem, Segment

RHO, G = 1025.0, 9.80665
# a suspended chain-like line (anchor 150 m above the seabed: no seabed contact, where MoorPy's
# current model applies): d 0.1 m (drag and volume diameter), 100 kg/m, EA 1e9 N, 300 m
D, MASS, EA, LENGTH, DEPTH = 0.1, 100.0, 1.0e9, 300.0, 300.0
CDN, CDT = 1.2, 0.4
ANCHOR = (0.0, 0.0, -150.0)
FAIRLEAD = (250.0, 0.0, -10.0)       # body axes; the body at the zero pose
W = (MASS - RHO * math.pi / 4 * D * D) * G


def _system(lines=None):
    lt = LineType(name="t", material="user", diameter=D, mass_per_length=MASS,
                  displaced_volume=math.pi / 4 * D * D, ea=EA, ea_dynamic=EA, mbs=1e7,
                  cdn=CDN, cdt=CDT)
    seg = Segment(length=LENGTH, ea=EA, w=W, mbs=1e7, line_type="t", mass_per_length=MASS,
                  diameter=D)
    lines = lines or [LineDef(name="l1", anchor=ANCHOR, fairlead=FAIRLEAD, segments=(seg,),
                              anchor_on_seabed=False)]
    return MooringSystem(lines, water_depth=DEPTH, water_density=RHO, gravity=G,
                         line_types={"t": lt})


def _current(speed, heading):
    return {"current_z": (-DEPTH, 0.0), "current_speed": (speed, speed),
            "current_heading": heading}


def _statics(system, speed, heading, n=200):
    return LineCurrentStatics(system, current=_current(speed, heading),
                              line_types=system.line_types, spec_kw={"n_elements": n})


def test_still_water_limit_is_exactly_zero():
    """Zero current speed: the line in 'current' is the still line, the increment is 0."""
    inc = _statics(_system(), 0.0, 0.3, n=60)(np.zeros(6))
    assert np.array_equal(inc.force, np.zeros(6))
    assert np.array_equal(inc.tension, [0.0])


def _moorpy(speed, heading, still=False):
    mp = pytest.importorskip("moorpy")
    cur = [0.0, 0.0, 0.0] if still else [speed * math.cos(heading), speed * math.sin(heading),
                                         0.0]
    ms = mp.System(depth=DEPTH, rho=RHO, g=G, current=cur)
    # MoorPy's axial drag acts on the perimeter pi d: CdAx = cdt / pi for the same force
    ms.setLineType(name="t", lineType=dict(name="t", m=MASS, d_vol=D, w=W, EA=EA, Cd=CDN,
                                           CdAx=CDT / math.pi, material="user", d_nom=D))
    ms.addPoint(1, np.array(ANCHOR))
    ms.addPoint(1, np.array(FAIRLEAD))
    ms.addLine(LENGTH, "t", nSegs=200, pointA=1, pointB=2)
    ms.initialize()
    ln = ms.lineList[0]
    prev = None
    for _ in range(60):       # the drag of the last profile is used in the next solve
        ln.staticSolve()
        if prev is not None and np.max(np.abs(ln.fB - prev)) < 1e-3:
            break
        prev = ln.fB.copy()
    return np.array(ln.fB)    # force of the line on its end B (the fairlead), N


def test_increment_against_moorpy_current_across_the_line():
    """1.5 m/s across the line's plane (drag 138 N/m, 15 % of the weight): the drag is nearly
    uniform along the line, MoorPy's uniform-load catenary is then close to exact.  Measured:
    increments (-2.36, 22.56, -0.85) kN here and (-2.49, 22.55, -0.87) kN by MoorPy."""
    system = _system()
    inc = _statics(system, 1.5, math.pi / 2)(np.zeros(6))
    f_total = system.force(np.zeros(6))[:3] + inc.force[:3]
    mp_cur, mp_still = _moorpy(1.5, math.pi / 2), _moorpy(0.0, 0.0, still=True)
    # the catenary in still water is MoorPy's to 1e-5
    np.testing.assert_allclose(system.force(np.zeros(6))[:3], mp_still, rtol=0,
                               atol=1e-5 * np.linalg.norm(mp_still))
    d_mp = mp_cur - mp_still
    assert np.linalg.norm(inc.force[:3] - d_mp) < 0.01 * np.linalg.norm(d_mp)
    assert np.linalg.norm(f_total - mp_cur) < 5e-4 * np.linalg.norm(mp_cur)
    assert inc.force[1] > 20e3   # the current (+y) pulls the fairlead downstream


@pytest.mark.parametrize("heading", [0.0, math.pi])
def test_total_against_moorpy_current_in_the_plane(heading):
    """1.5 m/s in the line's plane: the normal drag varies along the line (steep near the
    anchor, flat near the fairlead), which MoorPy spreads uniformly; the increments then differ
    by about 2 kN of 7 kN (FE, 200 elements: (1.42, -7.22) kN for current towards +x; MoorPy
    (-0.55, -6.28)), the total fairlead force by 0.6 %."""
    system = _system()
    inc = _statics(system, 1.5, heading)(np.zeros(6))
    f_total = system.force(np.zeros(6))[:3] + inc.force[:3]
    mp_cur = _moorpy(1.5, heading)
    assert np.linalg.norm(f_total - mp_cur) < 0.01 * np.linalg.norm(mp_cur)
    # the vertical increment has the sign of MoorPy's (drag adds to the line's load)
    mp_still = _moorpy(0.0, 0.0, still=True)
    assert np.sign(inc.force[2]) == np.sign(mp_cur[2] - mp_still[2])


def test_generalised_force_as_the_coupled_fe_lines():
    """Two lines, body displaced and rotated: the increment equals the difference of the
    generalised forces of the time domain's FE lines in current and in still water
    (FEMooring.solve_static: the same moment convention as MooringSystem.force)."""
    seg = Segment(length=LENGTH, ea=EA, w=W, mbs=1e7, line_type="t", mass_per_length=MASS,
                  diameter=D)
    lines = [LineDef(name="a", anchor=ANCHOR, fairlead=FAIRLEAD, segments=(seg,),
                     anchor_on_seabed=False),
             LineDef(name="b", anchor=(-240.0, 30.0, -150.0), fairlead=(-5.0, 3.0, -10.0),
                     segments=(seg,), anchor_on_seabed=False)]
    system = _system(lines)
    pose = np.array([1.0, -0.5, 0.2, 0.01, -0.02, 0.05])
    cur = _current(1.2, 0.7)
    # max_step 0: the same Newton iteration as FEMooring (no trust radius), hence the same
    # answer to round-off
    inc = LineCurrentStatics(system, current=cur, line_types=system.line_types,
                             spec_kw={"n_elements": 40}, max_step=0.0)(pose)
    # the default trust radius takes other steps to the same equilibrium: equal to the Newton
    # tolerance (nodal residual < 1e-6 node weight; here 2e-6 of the pitch moment)
    inc_tr = LineCurrentStatics(system, current=cur, line_types=system.line_types,
                                spec_kw={"n_elements": 40})(pose)
    np.testing.assert_allclose(inc_tr.force, inc.force, rtol=0, atol=1e-5 * np.abs(inc.force).max())
    specs = [spec_from_linedef(ld, water_depth=DEPTH, line_types=system.line_types,
                               n_elements=40, water_density=RHO, gravity=G) for ld in lines]
    specs_c = [spec_from_linedef(ld, water_depth=DEPTH, line_types=system.line_types,
                                 n_elements=40, water_density=RHO, gravity=G, **cur)
               for ld in lines]
    fb = [ld.fairlead for ld in lines]
    q = FEMooring(specs_c, fb).solve_static(pose) - FEMooring(specs, fb).solve_static(pose)
    np.testing.assert_allclose(inc.force, q, rtol=0, atol=1e-6 * np.abs(q).max())
    assert np.abs(inc.force[3:]).max() > 1e3   # the moments are not trivially zero



def test_trust_radius_on_a_grounded_chain_in_current():
    """The Floatel-like chains (50 elements) in the 100-year current, first solve from the
    still-water shape: the frictionless grounded chain slides tens of metres sideways, held by
    its tension alone (softest modes 15-24 N/m against the damping floor of the node weight over
    the element length, ~1e3 N/m), so the damped Newton of the statics crawls (hundreds of
    iterations).  The trust radius on the nodal move (``max_step``, the default of
    LineCurrentStatics) reaches the same equilibrium (each within the Newton tolerance of 1e-6
    node weight: compared with a 1000x tighter solve) in a fraction of the iterations;
    ``max_step`` 0 is the default iteration of FELine.solve_static, bit for bit."""
    import copy
    from pathlib import Path

    from floatmoor.io.build import build
    from floatmoor.mooring.fe import kernels as K
    built = build(Path(__file__).resolve().parents[3] / "scenes" / "floatel_100yr_fe.yaml")
    pose = np.array([10.47, 0.0, -0.75, 0.0, -0.0042, 0.0])   # about the FD mean
    lines = {}
    for m in (None, 0.0, 5.0):
        kw = {} if m is None else {"max_step": m}
        drag = LineCurrentStatics.from_scene(built.scene, copy.deepcopy(built.mooring),
                                             pose=pose, **kw)
        lines[m] = drag
    assert lines[None].max_step == 5.0      # the default of LineCurrentStatics
    pos, _ = lines[0.0].fairleads(pose)
    for k in (0, 5):                                   # line 1 (upstream) and line 6
        still = lines[0.0].still[k].solve_static(fairlead=pos[k], friction=False)
        sol = {m: lines[m].in_current[k].solve_static(fairlead=pos[k],
                                                      reference=still.positions, max_step=m)
               for m in (0.0, 5.0)}
        # FELine.solve_static without max_step: the default iteration, bit for bit
        plain = lines[None].in_current[k].solve_static(fairlead=pos[k], reference=still.positions)
        assert np.array_equal(plain.positions, sol[0.0].positions)
        assert plain.iterations == sol[0.0].iterations
        ln = copy.deepcopy(lines[5.0].in_current[k])
        ln.r[:] = sol[5.0].positions
        w_node = float(np.max(np.abs(ln.P[:, K.NP_W])))
        tight = ln.solve_static(fairlead=pos[k], reference=still.positions,
                                tol=1e-9 * w_node, max_step=5.0)
        assert sol[0.0].iterations > 60                   # the crawl (measured 76-286)
        assert sol[5.0].iterations < sol[0.0].iterations / 2
        assert abs(sol[5.0].positions[:, 1] - still.positions[:, 1]).max() > 10.0  # it slid
        for s_ in sol.values():
            # 1e-6 node weight per node over ~50 nodes: a few N at the fairlead
            np.testing.assert_allclose(s_.fairlead_force, tight.fairlead_force, rtol=0,
                                       atol=50 * 1e-6 * w_node)
