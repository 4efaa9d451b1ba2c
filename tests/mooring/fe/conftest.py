"""Shared OC3-Hywind line for the FE line tests.

Line data: vessels/oc3_hywind/mooring.yaml (Jonkman 2010; MAP++/MoorDyn input files): 902.2 m,
D 0.09 m, 77.7066 kg/m, EA 384.243e6 N, water depth 320 m, anchor radius 853.87 m, fairlead
radius 5.2 m at z = -70 m.  Hydrodynamic coefficients of the MoorDyn file: Cd 1.6, Ca 1.0,
CdAx 0.1 (MoorDyn's axial drag acts on the perimeter pi D: Cdt on D = 0.1 pi), CaAx 0.
"""

import math

import pytest

from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Friction, Seabed
from floatmoor.mooring.line_types import LineType

OC3 = dict(length=902.2, diameter=0.09, mass=77.7066, ea=384.243e6, depth=320.0,
           anchor=(853.87, 0.0, -320.0), fairlead=(5.2, 0.0, -70.0))


def oc3_type(ea=OC3["ea"]):
    d = OC3["diameter"]
    return LineType(name="oc3", material="user", diameter=d, mass_per_length=OC3["mass"],
                    displaced_volume=math.pi * d * d / 4, ea=ea, ea_dynamic=ea, mbs=6.0e6,
                    cdn=1.6, cdt=0.1 * math.pi, can=1.0, cat=0.0)


def oc3_spec(n=50, ea=OC3["ea"], damping=-0.8, friction=None, seabed=None, **kw):
    return FELineSpec(name="oc3_line1", anchor=OC3["anchor"], fairlead=OC3["fairlead"],
                      segments=(FESegment(line_type=oc3_type(ea), length=OC3["length"],
                                          n_elements=n, internal_damping=damping),),
                      seabed=seabed or Seabed(depth=OC3["depth"]),
                      friction=friction or Friction(), **kw)


@pytest.fixture
def oc3_line():
    def make(**kw):
        return FELine(oc3_spec(**kw))
    return make
