"""floatmoor.mooring.fe: finite-element (lumped-mass) dynamic mooring lines.

Line model, seabed contact and friction, statics from the catenary start, generalised-alpha
and explicit time integration, prescribed fairlead motion and the dynamic amplification factor.
See :mod:`floatmoor.mooring.fe.line` for the stepping interface a floater solver calls.
"""

from .analytic import transverse_friction_static
from .body import FEMooring
from .config import (
    FRICTION_MODELS,
    SEABED_MODELS,
    FELineSpec,
    FESegment,
    Friction,
    PointBody,
    Seabed,
)
from .decoupled import harmonic_poses, run_decoupled
from .frequency import frequency_response
from .from_system import spec_from_linedef, specs_from_system
from .line import FELine, StaticSolution, gen_alpha_coefficients
from .options import MOORING_MODELS, FEOptions, LineModels, parse_fe_options, parse_line_models
from .prescribed import (
    HarmonicMotion,
    TimeSeriesMotion,
    daf,
    decoupled_analysis,
    fairlead_track_from_body,
    quasi_static_tension,
    run_prescribed,
)

__all__ = ["FELineSpec", "FESegment", "Friction", "PointBody", "Seabed", "FRICTION_MODELS",
           "SEABED_MODELS", "FELine", "StaticSolution", "gen_alpha_coefficients",
           "HarmonicMotion", "TimeSeriesMotion", "fairlead_track_from_body", "run_prescribed",
           "quasi_static_tension", "daf", "transverse_friction_static", "spec_from_linedef",
           "specs_from_system", "FEMooring", "decoupled_analysis", "FEOptions",
           "parse_fe_options", "MOORING_MODELS", "LineModels", "parse_line_models",
           "run_decoupled", "harmonic_poses", "frequency_response"]
