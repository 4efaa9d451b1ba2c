"""FE statics against the quasi-static elastic catenary (floatmoor.mooring.catenary, itself
verified against MoorPy and the MAP++ OC3 summary in tests/mooring)."""

import numpy as np
import pytest

from floatmoor.core.errors import ConvergenceError
from floatmoor.mooring import catenary
from floatmoor.mooring.fe import FELine

from .conftest import OC3, oc3_spec, oc3_type

XF = OC3["anchor"][0] - OC3["fairlead"][0]     # 848.67 m
ZF = OC3["fairlead"][2] - OC3["anchor"][2]     # 250 m


def _cat(ea=OC3["ea"]):
    return catenary(XF, ZF, OC3["length"], ea, oc3_type(ea).submerged_weight())


def test_oc3_fairlead_tension_within_0p2_percent_with_50_elements():
    s = FELine(oc3_spec(n=50)).solve_static()
    c = _cat()
    assert abs(s.fairlead_tension / c.fairlead_tension - 1) < 2e-3
    # components: the line pulls the fairlead towards the anchor (+x) and down
    assert s.fairlead_force[0] == pytest.approx(c.HF, rel=2e-3)
    assert -s.fairlead_force[2] == pytest.approx(c.VF, rel=2e-3)
    assert abs(s.fairlead_force[1]) < 1e-6 * c.HF
    assert s.anchor_tension == pytest.approx(c.anchor_tension, rel=5e-3)


def test_fairlead_tension_converges_with_element_count():
    c = _cat().fairlead_tension
    err = {n: abs(FELine(oc3_spec(n=n)).solve_static().fairlead_tension / c - 1)
           for n in (10, 40, 160)}
    assert err[160] < err[10]
    assert err[160] < 2e-4


def test_inextensible_limit_ea_3p84e14_static():
    """Lu (2012) sec. 4.1 uses EA = 3.84e14 N for the inextensible line.  Reference: the elastic
    catenary with the same EA."""
    ea = 3.84e14
    s = FELine(oc3_spec(n=50, ea=ea)).solve_static()
    assert np.all(np.isfinite(s.positions))
    assert s.fairlead_tension == pytest.approx(_cat(ea).fairlead_tension, rel=2e-3)


def test_statics_failure_names_line_and_node():
    line = FELine(oc3_spec(n=20))
    with pytest.raises(ConvergenceError, match="oc3_line1, node"):
        line.solve_static(maxit=1, tol=1e-30)
