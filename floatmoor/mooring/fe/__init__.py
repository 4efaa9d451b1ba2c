"""floatmoor.mooring.fe: finite-element (lumped-mass) dynamic mooring lines.

Line model, seabed contact and friction, statics from the catenary start, generalised-alpha
and explicit time integration, prescribed fairlead motion and the dynamic amplification factor.
"""

from .config import (FRICTION_MODELS, SEABED_MODELS, FELineSpec, FESegment, Friction, PointBody,
                     Seabed)
from .line import FELine, StaticSolution, gen_alpha_coefficients

__all__ = ["FELineSpec", "FESegment", "Friction", "PointBody", "Seabed", "FRICTION_MODELS",
           "SEABED_MODELS", "FELine", "StaticSolution", "gen_alpha_coefficients"]
