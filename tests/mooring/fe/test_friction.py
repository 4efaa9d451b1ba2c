"""Seabed friction: Lu (2012) static analytic solution for transverse friction, and the
dynamic friction models."""

import numpy as np
import pytest

from floatmoor.core.errors import SceneError
from floatmoor.mooring.fe import FELine, Friction
from floatmoor.mooring.fe.analytic import transverse_friction_static
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import OC3, oc3_spec, oc3_type

MU = 1.0   # Lu (2012) does not print its coefficient; 1.0 is the usual lateral value for chain


def _case2_line(friction):
    """Lu (2012) table 1, case 2 (the OC3 line): anchor at the origin on the seabed, fairlead
    848.67 m away and 250 m above it.  EA = 3.84e11 N, the value Lu (2012) used in OrcaFlex for
    the inextensible line (sec. 4.1)."""
    spec = oc3_spec(n=100, ea=3.84e11, friction=friction)
    spec = type(spec)(**{**spec.__dict__, "anchor": (0.0, 0.0, -320.0),
                         "fairlead": (848.67, 0.0, -70.0)})
    return FELine(spec)


def test_lu2012_static_transverse_friction_analytic_solution():
    """Fairlead moved sideways 0 to 24 m: total fairlead tension within 1 % and sway component
    within 20 % of Lu (2012) eq. 10-19 (inextensible line, transverse Coulomb friction mu N).
    Measured: tension -0.001 %, sway -0.06 % at 24 m."""
    w = oc3_type().submerged_weight()
    line = _case2_line(Friction(model="displacement_velocity_ramp", mu_axial=0.0,
                                mu_lateral=MU))
    ref = line.solve_static(friction=False).positions
    free = _case2_line(Friction())
    free.solve_static()
    for Y in np.arange(2.0, 24.1, 2.0):
        s = line.solve_static(fairlead=(848.67, Y, -70.0), reference=ref)
        a = transverse_friction_static(OC3["length"], w, 848.67, 250.0, Y, MU)
        assert s.fairlead_tension == pytest.approx(a["tension"], rel=1e-2)
        # the line pulls the fairlead back towards y = 0
        assert -s.fairlead_force[1] == pytest.approx(a["sway"], rel=0.2)
        # friction holds the grounded part: more sway force than without friction
        s0 = free.solve_static(fairlead=(848.67, Y, -70.0))
        assert -s.fairlead_force[1] > -s0.fairlead_force[1]


def test_unknown_friction_model_is_a_scene_error():
    with pytest.raises(SceneError, match="velocity_ramp"):
        Friction(model="coulomb")


@pytest.mark.parametrize("model", ["velocity_ramp", "displacement_velocity_ramp"])
def test_lateral_friction_dissipates_energy_and_holds_the_grounded_part(model):
    """Sway 3 m at 15 s (Lu 2012, excitation 2) with lateral friction: the first grounded node
    next to the touchdown point slides much less (Lu 2012, conclusion 4) and the line dissipates
    more energy per cycle than without friction; the fairlead tension changes little (Lu 2012,
    conclusions 2 and 3)."""
    res = {}
    for name, fr in (("none", Friction()),
                     (model, Friction(model=model, mu_axial=0.7, mu_lateral=1.0))):
        line = FELine(oc3_spec(n=45, friction=fr))
        s = line.solve_static(friction=False)
        i_td = int(np.nonzero(s.positions[:, 2] < -320.0)[0].max())
        line.start()
        m = HarmonicMotion(amplitude=(0.0, 3.0, 0.0), period=15.0, ramp=15.0)
        ds = run_prescribed(line, m, 60.0, 0.1, track_nodes=(i_td - 1,))
        sel = ds.time.values > 45.0
        t = ds.time.values[sel]
        F = ds.fairlead_force.values[sel]
        v = np.array([m(tt)[1] for tt in t])
        p = -np.sum(F * v, axis=1)
        work = float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(t)))
        y = ds.node_position.values[sel, 0, 1]
        res[name] = (work, np.ptp(y), ds.fairlead_tension.values[sel])
        assert np.all(np.isfinite(ds.fairlead_tension.values))
    assert res[model][0] > res["none"][0] > 0.0
    assert res[model][1] < 0.5 * res["none"][1]
    assert res[model][2].max() == pytest.approx(res["none"][2].max(), rel=0.01)


def test_lu2012_case1_shallow_line_static_transverse_friction():
    """Lu (2012) case 1 (95 m water, more than 500 m on the seabed), fairlead moved sideways
    8, 16, 24 m: total tension within 1 %, sway component within 20 % of eq. 10-19.  EA raised
    to 100 x the table value for the inextensible analytic solution.  Measured: tension
    -0.03 / +0.07 / +0.01 %, sway -0.2 / -0.1 / -0.0 %."""
    import math

    from floatmoor.mooring.fe import FELineSpec, FESegment, Seabed
    from floatmoor.mooring.fe.analytic import LU2012_CASES
    from floatmoor.mooring.line_types import LineType

    c = LU2012_CASES[1]
    g, rho = 9.80665, 1025.0
    mass = c["weight_air"] / g
    vol = (c["weight_air"] - c["weight_water"]) / (rho * g)
    lt = LineType(name="case1", material="chain", diameter=c["diameter"], mass_per_length=mass,
                  displaced_volume=vol, ea=c["ea"] * 1e2, ea_dynamic=c["ea"] * 1e2, mbs=1e7)
    zf = -c["depth"] + c["height"]
    spec = FELineSpec(name="lu2012_case1", anchor=(0.0, 0.0, -c["depth"]),
                      fairlead=(c["span"], 0.0, zf),
                      segments=(FESegment(line_type=lt, length=c["length"], n_elements=100),),
                      seabed=Seabed(depth=c["depth"]),
                      friction=Friction(model="displacement_velocity_ramp", mu_lateral=MU))
    line = FELine(spec)
    ref = line.solve_static(friction=False).positions
    for Y in (8.0, 16.0, 24.0):
        s = line.solve_static(fairlead=(c["span"], Y, zf), reference=ref)
        a = transverse_friction_static(c["length"], lt.submerged_weight(), c["span"], c["height"],
                                       Y, MU)
        assert s.fairlead_tension == pytest.approx(a["tension"], rel=1e-2)
        assert -s.fairlead_force[1] == pytest.approx(a["sway"], rel=0.2)
    assert math.isfinite(a["T"])
