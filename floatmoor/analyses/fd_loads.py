"""Small numerical helpers of the frequency-domain analysis: rotations about z, interpolation
on the frequency grid and the QTF interpolant (plain arrays in and out; the last two are the
force models' own, :mod:`floatmoor.forces.spectral`).
"""

from __future__ import annotations

from ..core.frames import yaw_rotation6 as rot6
from ..forces.spectral import interp0, qtf_function

__all__ = ["rot6", "interp0", "qtf_function"]
