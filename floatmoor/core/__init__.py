"""Shared foundations: errors, DOF names, constants, frames and configuration reading."""

from .constants import GRAVITY, RHO_AIR, RHO_WATER
from .dofs import DOF_NAMES
from .errors import ConvergenceError, FloatmoorError, FloatmoorWarning, NumericalError, SceneError

__all__ = ["GRAVITY", "RHO_AIR", "RHO_WATER", "DOF_NAMES", "ConvergenceError", "FloatmoorError",
           "FloatmoorWarning", "NumericalError", "SceneError"]
