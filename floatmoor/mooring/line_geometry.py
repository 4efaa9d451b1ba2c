"""Shared pieces of the kernels that sum the forces of quasi-static lines on the body
(:func:`floatmoor.mooring.system.system_force_kernel` and the predictor-corrector
:func:`floatmoor.mooring.catenary_step.system_force_step_kernel`): the fairlead position
relative to its anchor in the line's vertical plane, and the line force and moment on the body.
Inlined into both kernels (the same operations in the same order as before they were shared).
"""

from __future__ import annotations

import math

from numba import njit

__all__ = ["add_line_force", "fairlead_geometry"]


@njit(cache=True, inline='always')
def fairlead_geometry(pose, rot, fairleads, anchors, i):
    """Line ``i`` at ``pose`` (rotation ``rot`` of the pose): the fairlead arm in earth axes
    ``(r0, r1, r2)``, the horizontal span ``h`` and height ``dz`` from the anchor, and the
    horizontal unit vector ``(ux, uy)`` from the anchor towards the fairlead ((1, 0) over the
    anchor)."""
    r0 = rot[0, 0] * fairleads[i, 0] + rot[0, 1] * fairleads[i, 1] + rot[0, 2] * fairleads[i, 2]
    r1 = rot[1, 0] * fairleads[i, 0] + rot[1, 1] * fairleads[i, 1] + rot[1, 2] * fairleads[i, 2]
    r2 = rot[2, 0] * fairleads[i, 0] + rot[2, 1] * fairleads[i, 1] + rot[2, 2] * fairleads[i, 2]
    dx = pose[0] + r0 - anchors[i, 0]
    dy = pose[1] + r1 - anchors[i, 1]
    dz = pose[2] + r2 - anchors[i, 2]
    h = math.sqrt(dx * dx + dy * dy)
    if h > 1e-12:
        ux = dx / h
        uy = dy / h
    else:
        ux = 1.0
        uy = 0.0
    return r0, r1, r2, h, dz, ux, uy


@njit(cache=True, inline='always')
def add_line_force(force, HF, VF, ux, uy, r0, r1, r2):
    """Add to ``force`` (6,) the force of a line with fairlead tension components ``HF``
    (horizontal, towards the anchor along ``-(ux, uy)``) and ``VF`` (down) and its moment about
    the body origin (arm ``r``)."""
    f0 = -HF * ux
    f1 = -HF * uy
    f2 = -VF
    force[0] += f0
    force[1] += f1
    force[2] += f2
    force[3] += r1 * f2 - r2 * f1
    force[4] += r2 * f0 - r0 * f2
    force[5] += r0 * f1 - r1 * f0
