"""floatmoor.mooring: line types, quasi-static catenary and mooring system statics."""

from .catenary import CatenaryResult, LineSolution, catenary, line_profile, solve_line

__all__ = ["catenary", "CatenaryResult", "solve_line", "LineSolution", "line_profile"]
