"""Line model pieces: axial law, clump weights, current drag, mud-layer seabed, touchdown
outputs, configuration errors, the stepping interface for a coupled body solver."""

import math

import numpy as np
import pytest

from floatmoor.core.errors import SceneError
from floatmoor.mooring import catenary, solve_line
from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, PointBody, Seabed
from floatmoor.mooring.fe.prescribed import HarmonicMotion, fairlead_track_from_body, run_prescribed

from .conftest import OC3, oc3_spec, oc3_type


def test_nonlinear_axial_law_single_element():
    """One element between fixed ends: the end force is T(eps) = c1 eps + c2 eps^2 along the
    element plus half its weight (no free node, so statics is exact)."""
    lt = oc3_type()
    c = (1.0e8, 5.0e9, 0.0)
    spec = FELineSpec(name="rope", anchor=(0.0, 0.0, -100.0), fairlead=(0.0, 0.0, -49.0),
                      segments=(FESegment(line_type=lt, length=50.0, n_elements=1,
                                          tension_poly=c),), seabed=Seabed(depth=200.0))
    s = FELine(spec).solve_static()
    eps = 51.0 / 50.0 - 1.0
    T = c[0] * eps + c[1] * eps ** 2
    w_half = 0.5 * 50.0 * lt.submerged_weight()
    assert s.fairlead_force[2] == pytest.approx(-(T + w_half), rel=1e-12)


def test_clump_weight_at_a_joint_against_multisegment_catenary():
    """Two OC3 segments with a 20 t (submerged 150 kN) clump at the joint; reference: the
    multi-segment catenary with a point load (floatmoor.mooring.solve_line)."""
    lt = oc3_type()
    rho, g = 1025.0, 9.80665
    mass, vol = 20000.0, 20000.0 / 7850.0
    P = (mass - rho * vol) * g
    spec = FELineSpec(name="clumped", anchor=OC3["anchor"], fairlead=OC3["fairlead"],
                      segments=(FESegment(line_type=lt, length=600.0, n_elements=40),
                                FESegment(line_type=lt, length=302.2, n_elements=20)),
                      point_bodies=(PointBody(node=40, mass=mass, volume=vol),),
                      seabed=Seabed(depth=OC3["depth"]))
    s = FELine(spec).solve_static()
    w = lt.submerged_weight()
    ref = solve_line(848.67, 250.0, [600.0, 302.2], [lt.ea] * 2, [w, w], [P, 0.0])
    assert s.fairlead_tension == pytest.approx(ref.fairlead_tension, rel=2e-3)


def test_uniform_current_drag_on_the_line():
    """A 0.2 m/s current across the line (+y): the lateral reactions at anchor and fairlead
    carry the normal drag 0.5 rho Cd D L u^2 (the line stays nearly in its plane, so the
    current is normal to it; the grounded part is held by lateral friction-free seabed, so
    the whole line takes drag)."""
    u = 0.2
    spec = oc3_spec(n=40, current_z=(-320.0, 0.0), current_speed=(u, u),
                    current_heading=math.pi / 2)
    s = FELine(spec).solve_static()
    drag = 0.5 * 1025.0 * 1.6 * 0.09 * OC3["length"] * u * u
    Fy = s.fairlead_force[1] + s.anchor_force[1]
    assert Fy == pytest.approx(drag, rel=0.03)


def test_mud_layer_seabed_carries_the_weight_at_the_seabed():
    """ANSYS (2013) mud layer: the grounded nodes settle where the spring carries their net
    weight, i.e. at the seabed itself (penetration of the layer = its depth)."""
    spec = oc3_spec(n=50, seabed=Seabed(depth=320.0, model="mud_layer", mud_depth=0.2))
    line = FELine(spec)
    s = line.solve_static()
    assert s.positions[3, 2] == pytest.approx(-320.0, abs=1e-3)
    # critical damping of the mud springs: c = 2 sqrt(k M)
    from floatmoor.mooring.fe import kernels as K
    P = line.P[3]
    assert P[K.NP_CS] == pytest.approx(2 * math.sqrt(P[K.NP_KS] * (P[K.NP_MASS] + P[K.NP_MAN])))
    c = catenary(848.67, 250.0, OC3["length"], OC3["ea"], oc3_type().submerged_weight())
    assert s.fairlead_tension == pytest.approx(c.fairlead_tension, rel=2e-3)


def test_touchdown_outputs_against_catenary_grounded_length():
    line = FELine(oc3_spec(n=90))
    line.solve_static()
    line.start()
    ds = run_prescribed(line, HarmonicMotion(amplitude=(0, 0, 0), period=10.0), 0.2, 0.1)
    c = catenary(848.67, 250.0, OC3["length"], OC3["ea"], oc3_type().submerged_weight())
    le = OC3["length"] / 90
    assert ds.grounded_length.values[0] == pytest.approx(c.grounded_length, abs=1.5 * le)
    assert ds.anchor_tension.values[0] == pytest.approx(c.anchor_tension, rel=5e-3)
    assert ds.max_tension.values[0] <= ds.fairlead_tension.values[0] * 1.001


def test_configuration_errors():
    with pytest.raises(SceneError, match="n_elements"):
        FESegment(line_type=oc3_type(), length=10.0, n_elements=0)
    with pytest.raises(SceneError, match="seabed.model"):
        Seabed(depth=100.0, model="sand")
    with pytest.raises(SceneError, match="point_bodies.node"):
        oc3_spec(n=10, point_bodies=(PointBody(node=10, mass=1.0),))


def test_coupling_interface_advance_is_repeatable_and_step_matches_run():
    """A body solver may call advance() several times per step (iterations, RK stages): each
    call restarts from the accepted state.  Stepping by hand equals run_prescribed."""
    m = HarmonicMotion(amplitude=(-2.0, 1.0, 0.5), period=12.0, ramp=12.0)
    a = FELine(oc3_spec(n=20))
    a.solve_static()
    a.start()
    r0 = a.r[-1].copy()
    forces = []
    for k in range(1, 41):
        t = 0.1 * k
        d, v = m(t)
        a.advance(t, 0.1, r0 + 2 * d, v)        # a trial that is thrown away
        F1 = a.advance(t, 0.1, r0 + d, v)
        F2 = a.advance(t, 0.1, r0 + d, v)
        assert np.array_equal(F1, F2)
        a.accept()
        forces.append(F1)
    b = FELine(oc3_spec(n=20))
    b.solve_static()
    b.start()
    ds = run_prescribed(b, m, 4.0, 0.1)
    assert np.allclose(ds.fairlead_force.values[1:], np.array(forces), rtol=1e-12, atol=1e-6)


def test_fairlead_track_from_body_poses():
    """A previous floater run (poses) drives the fairlead: pure surge of the body moves the
    fairlead by the same amount; a yaw rotates the fairlead arm."""
    t = np.linspace(0.0, 10.0, 101)
    poses = np.zeros((101, 6))
    poses[:, 0] = 2.0 * np.sin(t)
    poses[:, 5] = 0.1 * t / 10.0
    tr = fairlead_track_from_body(t, poses, (5.2, 0.0, -70.0))
    d, _ = tr(5.0)
    assert d[0] == pytest.approx(2.0 * np.sin(5.0) + 5.2 * (np.cos(0.05) - 1.0), abs=1e-12)
    assert d[1] == pytest.approx(5.2 * np.sin(0.05), abs=1e-12)


def test_specs_from_the_oc3_mooring_file_match_the_quasi_static_system():
    """The OC3 mooring file (vessels/oc3_hywind/mooring.yaml) through the ``mooring:`` parser,
    converted to FE lines: static fairlead tensions within 0.2 % of the quasi-static system
    (which carries the MAP++ seabed friction 0.001; the FE statics use friction only where the
    grounded part is displaced, here nowhere)."""
    from pathlib import Path

    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.from_system import specs_from_system

    root = Path(__file__).resolve().parents[3]
    ms = parse_mooring(Node.load(root / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    ref = ms.tensions().fairlead_tension.values
    specs = specs_from_system(ms, element_length=18.0)
    assert [s.name for s in specs] == list(ms.names)
    for spec, T in zip(specs, ref):
        s = FELine(spec).solve_static()
        assert s.fairlead_tension == pytest.approx(T, rel=2e-3)


def test_fe_mooring_on_a_body_matches_the_quasi_static_system():
    """Three OC3 FE lines on the spar: at rest the generalised force equals the quasi-static
    MooringSystem force (force and moment about the displaced reference point) at zero and at
    an offset, rotated pose; one dynamic step of a body at rest keeps it."""
    from pathlib import Path

    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.body import FEMooring
    from floatmoor.mooring.fe.from_system import specs_from_system

    root = Path(__file__).resolve().parents[3]
    ms = parse_mooring(Node.load(root / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    fm = FEMooring(specs_from_system(ms, element_length=18.0), ms.fairleads)
    for pose in (np.zeros(6), np.array([8.0, -3.0, -0.5, 0.02, -0.03, 0.05])):
        Q = fm.solve_static(pose)
        Qref = ms.force(pose)
        scale = np.abs(Qref[:3]).max()
        assert np.allclose(Q[:3], Qref[:3], atol=3e-3 * scale)
        assert np.allclose(Q[3:], Qref[3:], atol=3e-3 * scale * 5.2 + 3e-3 * np.abs(Qref[3:]).max())
    fm.start()
    Q1 = fm.advance(0.1, 0.1, pose, np.zeros(6))
    fm.accept()
    assert np.allclose(Q1, Q, rtol=1e-3, atol=1e-3 * scale)


def test_decoupled_analysis_from_a_body_motion_history():
    """Wang (2016) chapter 8 workflow: body poses of a 'previous floater run' (here a ramped
    3 m / 15 s surge) drive the three OC3 lines.  Line 1 (anchor on +x) equals the single-line
    run of the same fairlead track; lines 2 and 3 (at 120 and 240 deg) see the surge at
    cos 120 deg and have smaller tension ranges; DAF > 1 for every line."""
    from pathlib import Path

    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe import decoupled_analysis
    from floatmoor.mooring.fe.from_system import spec_from_linedef

    root = Path(__file__).resolve().parents[3]
    ms = parse_mooring(Node.load(root / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    t = np.arange(0.0, 45.0 + 1e-9, 0.1)
    m = HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0)
    poses = np.zeros((t.size, 6))
    poses[:, 0] = [m(tt)[0][0] for tt in t]
    ds = decoupled_analysis(ms, t, poses, discard=30.0, element_length=18.0)
    assert ds.fe_tension.attrs["units"] == "N"
    assert np.all(ds.daf.values > 1.0)
    rng = np.ptp(ds.fe_tension.values[:, t > 30.0], axis=1)
    assert rng[1] < rng[0] and rng[2] < rng[0]
    assert rng[1] == pytest.approx(rng[2], rel=1e-3)     # symmetry of lines 2 and 3
    line = FELine(spec_from_linedef(ms.lines[0], water_depth=320.0, element_length=18.0))
    line.solve_static()
    line.start()
    single = run_prescribed(line, fairlead_track_from_body(t, poses, ms.lines[0].fairlead),
                            45.0, 0.1)
    assert np.allclose(single.fairlead_tension.values, ds.fe_tension.values[0], rtol=1e-9)


def test_harmonic_poses_and_run_decoupled_input_checks():
    """harmonic_poses uses the ramp of HarmonicMotion; run_decoupled refuses a non-uniform time
    base and a window left empty by the discarded start-up."""
    from pathlib import Path

    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.decoupled import harmonic_poses, run_decoupled

    t = np.arange(0.0, 40.0, 0.1)
    p = harmonic_poses(t, [(0, 3.0, 15.0), (4, 0.02, 20.0)], ramp=15.0)
    m0 = HarmonicMotion(amplitude=(3.0,), period=15.0, ramp=15.0)
    m4 = HarmonicMotion(amplitude=(0.02,), period=20.0, ramp=15.0)
    assert np.allclose(p[:, 0], [m0(tt)[0][0] for tt in t], atol=1e-12)
    assert np.allclose(p[:, 4], [m4(tt)[0][0] for tt in t], atol=1e-12)
    assert np.all(p[:, [1, 2, 3, 5]] == 0.0)
    root = Path(__file__).resolve().parents[3]
    ms = parse_mooring(Node.load(root / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    with pytest.raises(ValueError, match="uniformly"):
        run_decoupled(ms, np.array([0.0, 0.1, 0.3, 0.4]), np.zeros((4, 6)))
    with pytest.raises(ValueError, match="discarding"):
        run_decoupled(ms, t, p, discard=100.0)
