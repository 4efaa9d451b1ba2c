"""Predictor-corrector catenary solves for the time loop (scene option
``solver: {catenary: predictor}``; the default ``exact`` path is
:func:`floatmoor.mooring.system.system_force_kernel`).

Between two calls of the time loop a fairlead moves by a small ``(dx, dz)`` (a few cm per RK4
stage).  The previous solution (H, V) at (x, z) with its stiffness K = J^-1 (J = d(x, z)/d(H, V),
:mod:`floatmoor.mooring.catenary`) gives the first Newton step from it without evaluating the
line: the residual of the old solution at the new fairlead is exactly ``-(dx, dz)``, so

    predictor   (H, V)_p = (H, V) + K (dx, dz)

is that step, with an error O(|d|^2).  One evaluation of the line at (H, V)_p gives its residual
r and Jacobian J_p, and one Newton correction ``-(J_p)^-1 r`` leaves an error of the order of
the square of that correction (quadratic convergence).  The correction is accepted when both
its components are below ``tol`` x the fairlead tension (default :data:`STEP_TOL` = 1e-6: the
remaining error is then ~1e-12 relative, far below the time-step error); otherwise, and
whenever the evaluation fails (a touchdown or slack transition the predictor jumped over), the
line is solved by the exact Newton iteration (:func:`floatmoor.mooring.catenary.line_kernel`)
warm-started from the corrected point.  So a line solve costs one evaluation instead of the
exact path's three or four (its convergence test needs one more iteration after converging).

Outputs of an accepted step: HF, VF after the correction; the stiffness K from J_p (used only as
the next predictor); HA, VA and the grounded length from the evaluation at the predictor,
corrected to first order where that is exact (HA = H for a line without seabed friction,
VA = V - weights for a line without touchdown); with friction on the seabed HA keeps the error
of the predictor's point (below ``(1 + cb) tol`` x the tension).

The line states ``warm`` (n, 8) hold H, V, x, z, K11, K12, K21, K22 of the last solution (H <= 0:
no solution yet, a cold start); the exact path reads and writes only the first two columns.
"""

from __future__ import annotations

import math

from numba import njit

from ..core.frames import rotation_matrix_into
from .catenary import (
    OUT_HA,
    OUT_HF,
    OUT_ITER,
    OUT_K11,
    OUT_K12,
    OUT_K21,
    OUT_K22,
    OUT_LB,
    OUT_SIZE,
    OUT_VA,
    OUT_VF,
    _eval_line,
    line_kernel,
)
from .line_geometry import add_line_force, fairlead_geometry

__all__ = ["STEP_TOL", "WARM_SIZE", "line_step_kernel", "system_force_step_kernel"]

STEP_TOL = 1e-4
"""Largest accepted Newton correction after the predictor, relative to the fairlead tension
(the error left is of the order of its square; the flagship storm's corrections stay below
2e-5, so it never falls back to the exact solve)."""

WARM_SIZE = 8
"""Columns of the line states: H, V, x, z, K11, K12, K21, K22."""


@njit(cache=True, inline='always')
def _keep(xf, zf, out, warm, i):
    """Line state ``warm[i]`` from a solution ``out`` at (xf, zf)."""
    warm[i, 0] = out[OUT_HF]
    warm[i, 1] = out[OUT_VF]
    warm[i, 2] = xf
    warm[i, 3] = zf
    warm[i, 4] = out[OUT_K11]
    warm[i, 5] = out[OUT_K12]
    warm[i, 6] = out[OUT_K21]
    warm[i, 7] = out[OUT_K22]


@njit(cache=True, inline='always')
def line_step_kernel(xf, zf, L, EA, w, P, i0, i1, cb, seabed, warm, i, tol, work, out):
    """Solve line ``i`` (segments ``i0 .. i1-1``) at fairlead (xf, zf) from its state
    ``warm[i]`` (module docstring); arguments as :func:`floatmoor.mooring.catenary.line_kernel`.
    ``out[OUT_ITER]`` is 0 for an accepted predictor-corrector step, else the exact solve's
    iterations.  Returns 0 or the exact solve's negative status."""
    H0 = warm[i, 0]
    hf0 = H0
    vf0 = warm[i, 1]
    if H0 > 0.0:
        dx = xf - warm[i, 2]
        dz = zf - warm[i, 3]
        H = H0 + warm[i, 4] * dx + warm[i, 5] * dz
        V = warm[i, 1] + warm[i, 6] * dx + warm[i, 7] * dz
        if H > 0.0 and math.isfinite(H) and math.isfinite(V):
            ev = work[10:20]
            st = _eval_line(H, V, L, EA, w, P, i0, i1, cb, seabed, work, ev)
            if st == 0:
                a = ev[2]
                b = ev[3]
                c = ev[4]
                d = ev[5]
                det = a * d - b * c
                if det != 0.0 and math.isfinite(det):
                    rx = ev[0] - xf
                    rz = ev[1] - zf
                    dH = -(d * rx - b * rz) / det
                    dV = -(-c * rx + a * rz) / det
                    lim = tol * math.sqrt(H * H + V * V)
                    hf0 = H + dH
                    vf0 = V + dV
                    if abs(dH) <= lim and abs(dV) <= lim and H + dH > 0.0:
                        out[OUT_HF] = H + dH
                        out[OUT_VF] = V + dV
                        out[OUT_HA] = ev[6] + dH if ev[6] == H else ev[6]
                        out[OUT_VA] = ev[7] + dV if ev[9] < 0.0 else ev[7]
                        out[OUT_LB] = ev[8]
                        out[OUT_K11] = d / det
                        out[OUT_K12] = -b / det
                        out[OUT_K21] = -c / det
                        out[OUT_K22] = a / det
                        out[OUT_ITER] = 0.0
                        _keep(xf, zf, out, warm, i)
                        return 0
    if not hf0 > 0.0:
        hf0 = 0.0
        vf0 = 0.0
    st = line_kernel(xf, zf, L, EA, w, P, i0, i1, cb, seabed, hf0, vf0, work, out)
    if st != 0 and hf0 > 0.0:
        st = line_kernel(xf, zf, L, EA, w, P, i0, i1, cb, seabed, 0.0, 0.0, work, out)
    if st == 0:
        _keep(xf, zf, out, warm, i)
    return st


@njit(cache=True)
def system_force_step_kernel(pose, anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start,
                             cb, seabed, active, warm, tol, predict_only, work, rot, line_out,
                             force):
    """:func:`floatmoor.mooring.system.system_force_kernel` (force only) with the line solves
    of :func:`line_step_kernel`: ``warm`` (n, :data:`WARM_SIZE`) the line states, ``tol`` the
    accepted correction.  ``predict_only``: the fairlead forces of the predictor alone, no
    evaluation (for a pose within millimetres of the last solution: the second RK4 stage at
    t + dt/2, whose pose differs from the first one's by dt^2/4 x the change of acceleration;
    the line states and ``line_out`` columns other than HF, VF stay those of the last solve).
    Returns -1, or the index of the first line that failed (its status code in
    ``line_out[i, OUT_ITER]``)."""
    rotation_matrix_into(pose[3], pose[4], pose[5], rot)
    for k in range(6):
        force[k] = 0.0
    cw = work[24:48]
    out = work[48:48 + OUT_SIZE]
    for i in range(anchors.shape[0]):
        if not active[i]:
            for k in range(OUT_SIZE):
                line_out[i, k] = 0.0
            continue
        r0, r1, r2, h, dz, ux, uy = fairlead_geometry(pose, rot, fairleads, anchors, i)
        if predict_only and warm[i, 0] > 0.0:
            ddx = h - warm[i, 2]
            ddz = dz - warm[i, 3]
            HF = warm[i, 0] + warm[i, 4] * ddx + warm[i, 5] * ddz
            VF = warm[i, 1] + warm[i, 6] * ddx + warm[i, 7] * ddz
            line_out[i, OUT_HF] = HF
            line_out[i, OUT_VF] = VF
        else:
            st = line_step_kernel(h, dz, seg_L, seg_EA, seg_w, seg_P, line_start[i],
                                  line_start[i + 1], cb[i], seabed[i], warm, i, tol, cw, out)
            if st != 0:
                line_out[i, OUT_ITER] = st
                return i
            for k in range(OUT_SIZE):
                line_out[i, k] = out[k]
            HF = out[OUT_HF]
            VF = out[OUT_VF]
        add_line_force(force, HF, VF, ux, uy, r0, r1, r2)
    return -1
