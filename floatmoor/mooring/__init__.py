"""floatmoor.mooring: line types, quasi-static catenary and mooring system statics."""

from .catenary import CatenaryResult, LineSolution, catenary, line_profile, solve_line
from .catenary_batch import CatenaryBatch, catenary_batch

__all__ = ["catenary", "CatenaryResult", "catenary_batch", "CatenaryBatch", "solve_line",
           "LineSolution", "line_profile"]
from .line_types import LineType, LineTypeLibrary, default_library  # noqa: E402
from .system import LineDef, MooringSystem, Segment  # noqa: E402

__all__ += ["LineType", "LineTypeLibrary", "default_library", "LineDef", "MooringSystem", "Segment"]
