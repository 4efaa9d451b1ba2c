"""Quasi-static elastic catenary: single segment and multi-segment lines with seabed contact.

Model and derivation
--------------------
A line hangs in a vertical plane between its anchor end (A, at the origin, on the seabed when
``seabed`` is true) and its fairlead end (F, at horizontal distance ``xf >= 0`` and height
``zf >= 0`` above A).  Every segment ``k`` (numbered from the anchor) has unstretched length
``L_k``, axial stiffness ``EA_k`` and submerged weight ``w_k`` per unstretched length (N/m);
point loads ``P_k`` (N, positive down: clump weight; negative: buoy) act at the joint at the upper
end of segment ``k``.  The unknowns are the tension components at the fairlead, ``H`` (horizontal,
positive pulling the fairlead towards the anchor) and ``V`` (vertical, positive pulling the
fairlead down).

Without friction on suspended parts, ``H`` is constant along the suspended line and the vertical
tension component at unstretched arc length ``s`` follows from the weight above it, ``V(s)``.
For a suspended piece with tension components ``Vt`` (top) and ``Vb = Vt - w Ls`` (bottom) and
unstretched length ``Ls``, integrating ``dx/ds = (1 + T/EA) H/T`` and ``dz/ds = (1 + T/EA) V/T``
with ``dV/ds = w`` gives (Wang (2016), eq. 2.28-2.30 with the current load F, D = 0)::

    dx = H/w [asinh(Vt/H) - asinh(Vb/H)] + H Ls / EA
    dz = 1/w [sqrt(H^2 + Vt^2) - sqrt(H^2 + Vb^2)] + Ls (Vt + Vb) / (2 EA)

A piece with ``|w| Ls`` negligible against its tension is straight (limit of the same formulas).

Seabed contact (Lu (2012), sec. 2.1, with the friction along the line axis as in the MAP++ and
FAST formulations): when the vertical force that a freely hanging line would need at the anchor is
negative, the line rests on the seabed from the anchor to the touchdown point, where the free
vertical force crosses zero.  The grounded part carries the tension ``H`` at the touchdown point,
falling towards the anchor by ``cb w`` per unit length (Coulomb friction, also ``cb P`` at a clump
weight on the seabed) and never below zero; its stretch is the integral of ``T/EA``.

Newton's method on ``(H, V)`` uses the analytic Jacobian ``J = d(x, z)/d(H, V)`` (derivatives
carried through every piece by hand, forward mode).  The fairlead stiffness is ``K = J^-1``:
``K = [[dH/dxf, dH/dzf], [dV/dxf, dV/dzf]]``.

A line that is slack horizontally (more line on the seabed than the horizontal distance to cover)
has ``H = 0``: it hangs vertically above the seabed and the rest lies in a heap; then
``dH/dxf = 0``.

Kernels are numba ``@njit(cache=True)``, take scalars and arrays and write into preallocated
outputs, so they can run in a time loop with warm starts from the previous solution.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from ..core.errors import ConvergenceError

__all__ = ["catenary", "CatenaryResult", "solve_line", "LineSolution", "line_profile",
           "catenary_kernel", "line_kernel", "OUT_SIZE", "STATUS_MESSAGES"]

# Layout of the kernel output vector.
OUT_HF, OUT_VF, OUT_HA, OUT_VA, OUT_LB, OUT_K11, OUT_K12, OUT_K21, OUT_K22, OUT_ITER = range(10)
OUT_SIZE = 10

MAX_ITER = 100
REL_TOL = 1e-9

STATUS_MESSAGES = {
    0: "converged",
    -1: "no convergence within the iteration cap",
    -2: "a buoyant segment would lie on the seabed (buoyant parts must stay suspended)",
    -3: "a buoy would lie on the seabed (buoys must stay suspended)",
    -5: "the whole line would rest on the seabed (no upward pull at the fairlead)",
    -4: "invalid input (length, EA must be > 0, xf >= 0 and all values finite)",
}


# --------------------------------------------------------------------------------------------
# Pieces with forward derivatives
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _susp_piece(H, Vt, Vb, Ls, w, EA, res):
    """Extent of a suspended piece and its partial derivatives.

    res[0:2] = dx, dz; res[2:6] = d(dx)/d(H, Vt, Vb, Ls); res[6:10] = d(dz)/d(H, Vt, Vb, Ls).
    ``Vb = Vt - w Ls`` must hold for the values; the partials treat the four as independent so
    the caller can chain them.
    """
    St = math.sqrt(H * H + Vt * Vt)
    Sb = math.sqrt(H * H + Vb * Vb)
    Tm = max(St, Sb)
    # elastic parts
    dx = H * Ls / EA
    dz = Ls * (Vt + Vb) / (2.0 * EA)
    dxH = Ls / EA
    dxVt = 0.0
    dxVb = 0.0
    dxL = H / EA
    dzH = 0.0
    dzVt = Ls / (2.0 * EA)
    dzVb = Ls / (2.0 * EA)
    dzL = (Vt + Vb) / (2.0 * EA)
    if abs(w) * Ls <= 1e-7 * Tm:
        # straight piece (weightless limit); mean vertical component
        Vm = 0.5 * (Vt + Vb)
        T = math.sqrt(H * H + Vm * Vm)
        T3 = T * T * T
        dx += Ls * H / T
        dz += Ls * Vm / T
        dxH += Ls * Vm * Vm / T3
        dxVt += -0.5 * Ls * H * Vm / T3
        dxVb += -0.5 * Ls * H * Vm / T3
        dxL += H / T
        dzH += -Ls * H * Vm / T3
        dzVt += 0.5 * Ls * H * H / T3
        dzVb += 0.5 * Ls * H * H / T3
        dzL += Vm / T
    else:
        at = math.asinh(Vt / H)
        ab = math.asinh(Vb / H)
        dx += H / w * (at - ab)
        dz += (St - Sb) / w
        dxH += (at - ab - Vt / St + Vb / Sb) / w
        dxVt += H / (w * St)
        dxVb += -H / (w * Sb)
        dzH += (H / St - H / Sb) / w
        dzVt += Vt / (w * St)
        dzVb += -Vb / (w * Sb)
    res[0] = dx
    res[1] = dz
    res[2] = dxH
    res[3] = dxVt
    res[4] = dxVb
    res[5] = dxL
    res[6] = dzH
    res[7] = dzVt
    res[8] = dzVb
    res[9] = dzL


@njit(cache=True)
def _eval_line(H, V, L, EA, w, P, i0, i1, cb, seabed, work, res):
    """Fairlead position (x, z) relative to the anchor for fairlead forces (H, V).

    Writes res[0:2] = x, z; res[2:6] = dx/dH, dx/dV, dz/dH, dz/dV; res[6] = HA; res[7] = VA;
    res[8] = grounded length; res[9] = index of the touchdown segment (-1 if none).
    ``work`` is scratch of length >= 10.  Returns 0, or a negative status code.
    """
    x = 0.0
    z = 0.0
    xH = 0.0
    xV = 0.0
    zH = 0.0
    zV = 0.0
    # free vertical force at the bottom of the line (anchor) if nothing touched the seabed
    Vfree_anchor = V
    for k in range(i1 - 1, i0 - 1, -1):
        Vfree_anchor -= w[k] * L[k]
        if k > i0:
            Vfree_anchor -= P[k - 1]
    tdp = -1          # segment holding the touchdown point
    lg_tdp = 0.0      # grounded length in that segment
    at_joint = False  # touchdown exactly at the joint below segment tdp
    n_clump = 0.0     # seabed normal force on that clump (= -V_free just below it)
    if seabed and Vfree_anchor < 0.0:
        # walk up from the anchor until the free vertical force turns positive
        vb = Vfree_anchor
        for k in range(i0, i1):
            if k > i0:
                if vb + P[k - 1] > 0.0:
                    # the clump at this joint rests on the seabed with normal force -vb
                    n_clump = -vb
                    tdp = k
                    at_joint = True
                    break
                vb += P[k - 1]
                if P[k - 1] < 0.0:
                    return -3
            vt = vb + w[k] * L[k]
            if vt > 0.0:
                if w[k] <= 0.0:
                    return -2
                tdp = k
                lg_tdp = -vb / w[k]
                break
            if w[k] <= 0.0:
                return -2
            vb = vt
        if tdp < 0:
            # the whole line would rest on the seabed (V <= 0 at the fairlead): not a solution
            return -5
    # suspended segments from the fairlead down to the touchdown segment
    Vt = V
    bottom = i0 if tdp < 0 else tdp
    for k in range(i1 - 1, bottom - 1, -1):
        if k == tdp and not at_joint:
            Ls = L[k] - lg_tdp
            Vb = 0.0
            # Ls = Vt / w  ->  dLs/dV = 1 / w ; Vb fixed at 0
            _susp_piece(H, Vt, Vb, Ls, w[k], EA[k], work)
            x += work[0]
            z += work[1]
            xH += work[2]
            xV += work[3] + work[5] / w[k]
            zH += work[6]
            zV += work[7] + work[9] / w[k]
        else:
            Vb = Vt - w[k] * L[k]
            _susp_piece(H, Vt, Vb, L[k], w[k], EA[k], work)
            x += work[0]
            z += work[1]
            xH += work[2]
            xV += work[3] + work[4]
            zH += work[6]
            zV += work[7] + work[8]
            Vt = Vb
        if k > i0:
            Vt -= P[k - 1]
    LB = 0.0
    if tdp < 0:
        HA = H
        VA = Vt  # free vertical force at the anchor (already includes every load)
    else:
        # grounded part: tension H at the touchdown point, Coulomb friction towards the anchor
        T = H
        TH = 1.0
        TV = 0.0
        start = tdp if not at_joint else tdp - 1
        if at_joint:
            # the clump under segment tdp rests on the seabed: friction cb x its normal force
            # n_clump = -V_free just below the joint, d(n_clump)/dV = -1, so dT/dV = +cb
            T = H - cb * n_clump
            TV = cb
            if T <= 0.0:
                T = 0.0
                TH = 0.0
                TV = 0.0
        for k in range(start, i0 - 1, -1):
            if k == tdp and not at_joint:
                lg = lg_tdp
                lgV = -1.0 / w[k]
            else:
                lg = L[k]
                lgV = 0.0
            c = cb * w[k]
            x += lg
            xV += lgV
            if c <= 0.0 or T - c * lg >= 0.0:
                x += (T * lg - 0.5 * c * lg * lg) / EA[k]
                xH += lg * TH / EA[k]
                xV += (lg * TV + (T - c * lg) * lgV) / EA[k]
                T = T - c * lg
                TV = TV - c * lgV
            else:
                x += T * T / (2.0 * c * EA[k])
                xH += T * TH / (c * EA[k])
                xV += T * TV / (c * EA[k])
                T = 0.0
                TH = 0.0
                TV = 0.0
            LB += lg
            if k > i0:
                T -= cb * P[k - 1]
                if T <= 0.0:
                    T = 0.0
                    TH = 0.0
                    TV = 0.0
        HA = T
        VA = 0.0
    res[0] = x
    res[1] = z
    res[2] = xH
    res[3] = xV
    res[4] = zH
    res[5] = zV
    res[6] = HA
    res[7] = VA
    res[8] = LB
    res[9] = tdp
    return 0


@njit(cache=True)
def _line_kernel_impl(xf, zf, L, EA, w, P, i0, i1, cb, seabed, hf0, vf0, work, out):
    """One Newton attempt of :func:`line_kernel`."""
    ev = work[10:20]
    Ltot = 0.0
    Wtot = 0.0
    Wabs = 0.0
    comp = 0.0
    for k in range(i0, i1):
        if not (L[k] > 0.0) or not (EA[k] > 0.0) or not math.isfinite(w[k]):
            return -4
        Ltot += L[k]
        Wtot += w[k] * L[k]
        Wabs += abs(w[k]) * L[k]
        comp += L[k] / EA[k]
        if k < i1 - 1:
            Wtot += P[k]
            Wabs += abs(P[k])
    if not (xf >= 0.0) or not math.isfinite(zf) or not math.isfinite(xf):
        return -4
    d = math.sqrt(xf * xf + zf * zf)
    # force scale, N: the weights (a weightless line: a small fraction of its axial stiffness)
    scale = Wabs if Wabs > 0.0 else max(1e-6 * Ltot / comp, 1e-300)
    Hmin = 1e-12 * scale
    # ---- initial guess
    if hf0 > 0.0:
        H = hf0
        V = vf0
    elif d >= Ltot:
        T0 = max((d - Ltot) / comp, 0.1 * scale)
        H = max(T0 * xf / max(d, 1e-300), 1e-3 * scale)
        V = T0 * zf / max(d, 1e-300) + 0.5 * Wtot
    else:
        wa = abs(Wtot) / Ltot if Wtot != 0.0 else 1e-6 * scale / Ltot
        if xf <= 1e-6 * Ltot:
            lam = 1e6
        else:
            lam = math.sqrt(3.0 * ((Ltot * Ltot - zf * zf) / (xf * xf) - 1.0)) \
                if Ltot * Ltot - zf * zf > xf * xf else 0.2
            lam = max(lam, 0.2)
        H = max(abs(0.5 * wa * xf / lam), 1e-6 * scale)
        V = 0.5 * wa * (zf / math.tanh(lam) + Ltot)
    H = max(H, Hmin)
    # ---- Newton with backtracking
    st = _eval_line(H, V, L, EA, w, P, i0, i1, cb, seabed, work, ev)
    if st < 0:
        return st
    rx = ev[0] - xf
    rz = ev[1] - zf
    ftol = 1e-14 * (Ltot + d)
    it = 0
    conv = False
    while it < MAX_ITER:
        it += 1
        a = ev[2]
        b = ev[3]
        c = ev[4]
        dd = ev[5]
        det = a * dd - b * c
        if det == 0.0 or not math.isfinite(det):
            return -1
        dH = -(dd * rx - b * rz) / det
        dV = -(-c * rx + a * rz) / det
        Tn = math.sqrt(H * H + V * V)
        small = abs(dH) <= REL_TOL * Tn and abs(dV) <= REL_TOL * Tn
        slack = False
        if H + dH < Hmin and H <= 1e-6 * scale:
            # horizontally slack: H goes to its floor, solve the vertical equation only
            slack = True
            dH = Hmin - H
            dV = -(rz + c * dH) / dd if dd != 0.0 else 0.0
        else:
            if H + dH < 0.1 * H:
                # scale the whole step so that H falls by at most a factor of 10
                f = 0.9 * H / (-dH)
                dH *= f
                dV *= f
            if H + dH < Hmin:
                dH = Hmin - H
        if slack:
            small = abs(dV) <= REL_TOL * Tn
        # near the round-off floor of the geometry (very stiff lines) the residual is noise:
        # a step below 1e-7 relative that does not reduce it ends the iteration
        tiny = abs(dH) <= 1e-7 * Tn and abs(dV) <= 1e-7 * Tn
        r0 = abs(rz) if slack else math.sqrt(rx * rx + rz * rz)
        alpha = 1.0
        ok = False
        last_st = 0
        for _ in range(40):
            Hn = max(H + alpha * dH, Hmin)
            Vn = V + alpha * dV
            st = _eval_line(Hn, Vn, L, EA, w, P, i0, i1, cb, seabed, work, ev)
            if st < 0:
                last_st = st
                alpha *= 0.5
                continue
            rxn = ev[0] - xf
            rzn = ev[1] - zf
            r1 = abs(rzn) if slack else math.sqrt(rxn * rxn + rzn * rzn)
            if r1 <= r0 or small or r1 <= ftol:
                ok = True
                break
            if tiny:
                small = True
                ok = True
                break
            ok = True  # accept the smallest step tried if nothing decreases the residual
            alpha *= 0.5
        if not ok:
            return last_st if last_st < 0 else -1
        H = Hn
        V = Vn
        rx = rxn
        rz = rzn
        if small or (not slack and math.sqrt(rx * rx + rz * rz) <= ftol):
            conv = True
            break
        if slack and (abs(rz) <= ftol or abs(dV) <= REL_TOL * max(abs(V), 1e-300)):
            conv = True
            break
    if not conv:
        return -1
    a = ev[2]
    b = ev[3]
    c = ev[4]
    dd = ev[5]
    slack = H <= Hmin * 1.0000001 and rx > 1e-12 * (Ltot + d)
    if slack:
        out[OUT_HF] = 0.0
        out[OUT_K11] = 0.0
        out[OUT_K12] = 0.0
        out[OUT_K21] = 0.0
        out[OUT_K22] = 1.0 / dd if dd != 0.0 else 0.0
        out[OUT_HA] = 0.0
    else:
        det = a * dd - b * c
        out[OUT_HF] = H
        out[OUT_K11] = dd / det
        out[OUT_K12] = -b / det
        out[OUT_K21] = -c / det
        out[OUT_K22] = a / det
        out[OUT_HA] = ev[6]
    out[OUT_VF] = V
    out[OUT_VA] = ev[7]
    out[OUT_LB] = ev[8]
    out[OUT_ITER] = it
    return 0


@njit(cache=True)
def line_kernel(xf, zf, L, EA, w, P, i0, i1, cb, seabed, hf0, vf0, work, out):
    """Solve one (multi-segment) line for its fairlead forces.  No allocation.

    Parameters
    ----------
    xf, zf : float
        Horizontal distance (>= 0) and height of the fairlead above the anchor, m.
    L, EA, w, P : float arrays
        Per segment (numbered from the anchor): unstretched length (m), axial stiffness (N),
        submerged weight per length (N/m), point load at the segment's upper joint (N, + down).
    i0, i1 : int
        The line's segments are ``i0 .. i1-1``.
    cb : float
        Seabed friction coefficient (axial Coulomb) on the grounded part.
    seabed : bool
        True when the anchor lies on the seabed (the line may touch down).
    hf0, vf0 : float
        Warm start (the previous HF, VF); ``hf0 <= 0`` for a cold start.
    work : float array, length >= 20
        Scratch.
    out : float array, length >= OUT_SIZE
        HF, VF, HA, VA, grounded length, K11, K12, K21, K22, iterations.

    Returns
    -------
    int
        0 when converged, negative status code otherwise (see ``STATUS_MESSAGES``).
    """
    st = _line_kernel_impl(xf, zf, L, EA, w, P, i0, i1, cb, seabed, hf0, vf0, work, out)
    if st == -1 and cb > 0.0:
        # friction makes the equations only piecewise smooth; start again from the
        # frictionless solution, which is close
        st0 = _line_kernel_impl(xf, zf, L, EA, w, P, i0, i1, 0.0, seabed, 0.0, 0.0, work, out)
        if st0 == 0 and out[OUT_HF] > 0.0:
            it0 = out[OUT_ITER]
            st = _line_kernel_impl(xf, zf, L, EA, w, P, i0, i1, cb, seabed, out[OUT_HF],
                                   out[OUT_VF], work, out)
            out[OUT_ITER] += it0 + MAX_ITER
    return st


@njit(cache=True)
def catenary_kernel(xf, zf, length, ea, w, cb, seabed, hf0, vf0, work, out):
    """Single-segment catenary with scalar inputs (see :func:`line_kernel`).

    ``work`` must have length >= 24: its first four entries hold the one-segment arrays.
    """
    seg = work[20:24]
    seg[0] = length
    seg[1] = ea
    seg[2] = w
    seg[3] = 0.0
    return line_kernel(xf, zf, seg[0:1], seg[1:2], seg[2:3], seg[3:4], 0, 1, cb, seabed,
                       hf0, vf0, work, out)


# --------------------------------------------------------------------------------------------
# Python API
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class CatenaryResult:
    """Solution of a single elastic catenary (SI units).

    Attributes
    ----------
    HF, VF : float
        Horizontal and vertical tension components at the fairlead end, N.  For a hanging line
        both are >= 0: the line pulls the fairlead towards the anchor and down.
    HA, VA : float
        Tension components at the anchor end, N (``VA`` = 0 when the line touches the seabed;
        ``VA`` > 0 when it pulls the anchor up).
    grounded_length : float
        Unstretched length resting on the seabed, m.
    stiffness : (2, 2) ndarray
        ``[[dHF/dxf, dHF/dzf], [dVF/dxf, dVF/dzf]]`` in N/m (analytic, inverse of the Jacobian).
    iterations : int
        Newton iterations used.
    inputs : dict
        The inputs, to compute the profile.
    """

    HF: float
    VF: float
    HA: float
    VA: float
    grounded_length: float
    stiffness: np.ndarray
    iterations: int
    inputs: dict = field(repr=False)

    @property
    def fairlead_tension(self) -> float:
        """Tension at the fairlead, N."""
        return math.hypot(self.HF, self.VF)

    @property
    def anchor_tension(self) -> float:
        """Tension at the anchor, N."""
        return math.hypot(self.HA, self.VA)

    def profile(self, n: int = 101):
        """Line shape and tension along the unstretched arc length from the anchor.

        Returns a dict with ``s`` (m), ``x``, ``z`` (m, relative to the anchor) and
        ``tension`` (N), each of length ``n``.
        """
        i = self.inputs
        return line_profile(self.HF, self.VF, np.array([i["length"]]), np.array([i["ea"]]),
                            np.array([i["w"]]), np.zeros(1), i["cb"], i["seabed"], n=n)


def _raise_status(status, what):
    if status == -4:
        raise ValueError(f"invalid catenary input: {what}")
    if status in (-2, -3):
        remedy = ("add weight or shorten the buoyant part so that it stays suspended; a lazy-wave "
                  "shape whose buoyant part touches the seabed is not modelled")
    else:
        remedy = ("check the line length against the anchor-fairlead distance, EA and submerged "
                  "weight; give a warm start (hf0, vf0)")
    raise ConvergenceError(f"catenary: {STATUS_MESSAGES.get(status, status)}", where=what,
                           remedy=remedy)


def _is_scalar(v) -> bool:
    return isinstance(v, (float, int)) or np.ndim(v) == 0


def catenary(xf, zf, length, ea, w, cb=0.0, *, seabed=True, hf0=0.0, vf0=0.0):
    """Solve a single elastic catenary line between anchor and fairlead.

    With arrays for any of the inputs, solves every element of their broadcast shape in one
    compiled loop and returns a ``CatenaryBatch`` of arrays (failed elements NaN with a status
    code): see :func:`floatmoor.mooring.catenary_batch.catenary_batch`.

    Parameters
    ----------
    xf : float
        Horizontal distance from the anchor end to the fairlead end, m (>= 0).
    zf : float
        Height of the fairlead end above the anchor end, m (>= 0 when ``seabed``).
    length : float
        Unstretched length, m (> 0).
    ea : float
        Axial stiffness, N (> 0).
    w : float
        Submerged weight per unit unstretched length, N/m (> 0 when part of the line may rest
        on the seabed; <= 0 allowed only for a line that stays suspended).
    cb : float, optional
        Coefficient of axial Coulomb friction on the seabed (anchor end on the seabed), -.
    seabed : bool, keyword
        The anchor end lies on a horizontal seabed (default).  False: the line never touches
        anything (a line between two points in the water column).
    hf0, vf0 : float, keyword
        Warm start: fairlead forces of a nearby solution, N.

    Returns
    -------
    CatenaryResult
        ``HF, VF, HA, VA, grounded_length, stiffness`` (2x2, N/m) and ``profile()``
        (a ``CatenaryBatch`` of arrays when an input is an array).

    Raises
    ------
    ConvergenceError
        No convergence to 1e-9 relative within 100 Newton iterations; the message names the
        inputs.
    """
    num = (float, int)
    if not ((isinstance(xf, num) and isinstance(zf, num) and isinstance(length, num)
             and isinstance(ea, num) and isinstance(w, num) and isinstance(cb, num)
             and isinstance(seabed, num) and isinstance(hf0, num) and isinstance(vf0, num))
            or all(_is_scalar(v) for v in (xf, zf, length, ea, w, cb, seabed, hf0, vf0))):
        from .catenary_batch import catenary_batch
        return catenary_batch(xf, zf, length, ea, w, cb, seabed=seabed, hf0=hf0, vf0=vf0)
    xf = float(xf)
    zf = float(zf)

    def what():  # the call, for error messages (formatted only when one is raised)
        return (f"catenary(xf={xf!r}, zf={zf!r}, length={length!r}, ea={ea!r}, w={w!r}, "
                f"cb={cb!r}, seabed={seabed!r})")
    if not (length > 0) or not (ea > 0) or not (xf >= 0) or not (
            math.isfinite(xf) and math.isfinite(zf) and math.isfinite(w) and math.isfinite(cb)):
        raise ValueError(f"invalid input: length and ea must be > 0, xf >= 0, all finite: "
                         f"{what()}")
    if seabed and zf < 0:
        raise ValueError(f"the fairlead end must not be below an anchor on the seabed: {what()}")
    work = np.empty(24)
    out = np.zeros(OUT_SIZE)
    status = catenary_kernel(xf, zf, float(length), float(ea), float(w), float(cb), bool(seabed),
                             float(hf0), float(vf0), work, out)
    if status != 0:
        _raise_status(status, what())
    return CatenaryResult(HF=out[OUT_HF], VF=out[OUT_VF], HA=out[OUT_HA], VA=out[OUT_VA],
                          grounded_length=out[OUT_LB],
                          stiffness=np.array([[out[OUT_K11], out[OUT_K12]],
                                              [out[OUT_K21], out[OUT_K22]]]),
                          iterations=int(out[OUT_ITER]),
                          inputs=dict(xf=xf, zf=zf, length=float(length), ea=float(ea),
                                      w=float(w), cb=float(cb), seabed=bool(seabed)))


@dataclass(frozen=True, kw_only=True)
class LineSolution:
    """Solution of a multi-segment line (see :func:`solve_line`); forces in N, lengths in m."""

    HF: float
    VF: float
    HA: float
    VA: float
    grounded_length: float
    stiffness: np.ndarray
    iterations: int
    segments: dict = field(repr=False)

    @property
    def fairlead_tension(self) -> float:
        return math.hypot(self.HF, self.VF)

    @property
    def anchor_tension(self) -> float:
        return math.hypot(self.HA, self.VA)

    def profile(self, n_per_segment: int = 51):
        """Shape and tension along the line from the anchor (dict of arrays ``s, x, z, tension,
        segment``); see :func:`line_profile`."""
        s = self.segments
        return line_profile(self.HF, self.VF, s["length"], s["ea"], s["w"], s["point_load"],
                            s["cb"], s["seabed"], n=n_per_segment)


def solve_line(xf, zf, lengths, ea, w, point_loads=None, cb=0.0, *, seabed=True, hf0=0.0,
               vf0=0.0, name="line") -> LineSolution:
    """Solve a multi-segment line (chain-polyester-chain, clump weights, buoys).

    Parameters
    ----------
    xf, zf : float
        Horizontal distance and height of the fairlead above the anchor, m.
    lengths, ea, w : sequence of float
        Per segment from the anchor to the fairlead: unstretched length (m), axial stiffness (N),
        submerged weight per length (N/m; negative = buoyant, allowed where the line stays
        suspended).
    point_loads : sequence of float, optional
        Point load at the upper joint of each segment, N, positive down (clump weight) or
        negative (buoy); the last entry (fairlead) is ignored.
    cb : float
        Seabed friction coefficient.
    seabed : bool, keyword
        The anchor lies on the seabed.
    hf0, vf0 : float, keyword
        Warm start, N.
    name : str
        Used in error messages.

    Returns
    -------
    LineSolution
    """
    L = np.ascontiguousarray(lengths, dtype=float).ravel()
    EA = np.ascontiguousarray(ea, dtype=float).ravel()
    W = np.ascontiguousarray(w, dtype=float).ravel()
    P = np.zeros(L.size) if point_loads is None else np.ascontiguousarray(point_loads, dtype=float).ravel()
    if not (L.size == EA.size == W.size == P.size) or L.size == 0:
        raise ValueError(f"{name}: lengths, ea, w and point_loads must have the same length >= 1")
    work = np.empty(24)
    out = np.zeros(OUT_SIZE)
    status = line_kernel(float(xf), float(zf), L, EA, W, P, 0, L.size, float(cb), bool(seabed),
                         float(hf0), float(vf0), work, out)
    if status != 0:
        _raise_status(status, f"{name} (xf={xf:.6g} m, zf={zf:.6g} m, lengths={L.tolist()}, "
                              f"EA={EA.tolist()}, w={W.tolist()}, point_loads={P.tolist()})")
    return LineSolution(HF=out[OUT_HF], VF=out[OUT_VF], HA=out[OUT_HA], VA=out[OUT_VA],
                        grounded_length=out[OUT_LB],
                        stiffness=np.array([[out[OUT_K11], out[OUT_K12]],
                                            [out[OUT_K21], out[OUT_K22]]]),
                        iterations=int(out[OUT_ITER]),
                        segments=dict(length=L, ea=EA, w=W, point_load=P, cb=float(cb),
                                      seabed=bool(seabed)))


def line_profile(HF, VF, lengths, ea, w, point_loads, cb, seabed, n=51):
    """Shape and effective tension along a solved line, from the anchor to the fairlead.

    Parameters
    ----------
    HF, VF : float
        Solved fairlead forces, N.
    lengths, ea, w, point_loads : arrays
        Segment data from the anchor (as in :func:`solve_line`).
    cb : float
        Seabed friction coefficient.
    seabed : bool
        Anchor on the seabed.
    n : int
        Points per segment.

    Returns
    -------
    dict
        ``s`` unstretched arc length from the anchor (m), ``x`` and ``z`` position relative to
        the anchor (m), ``tension`` (N), ``segment`` index, all arrays.
    """
    L = np.asarray(lengths, float)
    EA = np.asarray(ea, float)
    W = np.asarray(w, float)
    P = np.asarray(point_loads, float)
    nseg = L.size
    # free vertical force at the bottom of each segment (from the fairlead down)
    vbot = np.empty(nseg)
    v = VF
    for k in range(nseg - 1, -1, -1):
        v -= W[k] * L[k]
        vbot[k] = v
        if k > 0:
            v -= P[k - 1]
    # grounded length per segment
    lg = np.zeros(nseg)
    n_joint = None  # normal force of a clump at the touchdown joint
    if seabed and vbot[0] < 0.0:
        vb = vbot[0]
        for k in range(nseg):
            if k > 0:
                if vb + P[k - 1] > 0:
                    n_joint = -vb
                    break
                vb += P[k - 1]
            vt = vb + W[k] * L[k]
            if vt > 0:
                lg[k] = -vb / W[k]
                break
            lg[k] = L[k]
            vb = vt
    # tension at the touchdown-side end of each grounded piece (friction towards the anchor)
    t_top = np.zeros(nseg)
    grounded = np.nonzero(lg > 0)[0]
    if grounded.size:
        ktop = int(grounded[-1])
        T = HF
        if lg[ktop] >= L[ktop] and ktop < nseg - 1:
            T = max(T - cb * (P[ktop] if n_joint is None else n_joint), 0.0)
        for k in range(ktop, -1, -1):
            t_top[k] = T
            T = max(T - cb * W[k] * lg[k], 0.0)
            if k > 0:
                T = max(T - cb * P[k - 1], 0.0)

    def grounded_stretch(k, s):
        """Stretch of the grounded piece of segment k from its anchor-side end to s."""
        c = cb * W[k]
        if c <= 0:
            return t_top[k] * s / EA[k]
        u0 = max(lg[k] - t_top[k] / c, 0.0)
        ss = np.maximum(s - u0, 0.0)
        return ((t_top[k] - c * (lg[k] - u0)) * ss + 0.5 * c * ss * ss) / EA[k]

    s_all, x_all, z_all, t_all, seg_all = [], [], [], [], []
    x0 = 0.0
    z0 = 0.0
    s0 = 0.0
    for k in range(nseg):
        s = np.linspace(0.0, L[k], n)
        x = np.empty(n)
        z = np.empty(n)
        t = np.empty(n)
        g = s <= lg[k]
        if lg[k] > 0:
            c = cb * W[k]
            t[g] = np.maximum(t_top[k] - c * (lg[k] - s[g]), 0.0)
            x[g] = x0 + s[g] + grounded_stretch(k, s[g])
            z[g] = z0
            xg_end = x0 + lg[k] + float(grounded_stretch(k, np.array([lg[k]]))[0])
        else:
            xg_end = x0
        su = ~g if lg[k] > 0 else np.ones(n, bool)
        if np.any(su):
            vb = 0.0 if lg[k] > 0 else vbot[k]
            u = s[su] - lg[k]
            vv = vb + W[k] * u
            H = HF
            if H > 0:
                if abs(W[k]) * L[k] <= 1e-7 * max(math.hypot(H, vb), 1e-300):
                    tt = np.hypot(H, 0.5 * (vb + vv))
                    xs = u * H / tt
                    zs = u * 0.5 * (vb + vv) / tt
                else:
                    xs = H / W[k] * (np.arcsinh(vv / H) - math.asinh(vb / H))
                    zs = (np.hypot(H, vv) - math.hypot(H, vb)) / W[k]
                xs = xs + H * u / EA[k]
            else:
                xs = np.zeros_like(u)
                zs = np.abs(u)
            zs = zs + u * (vb + 0.5 * W[k] * u) / EA[k]
            x[su] = xg_end + xs
            z[su] = z0 + zs
            t[su] = np.hypot(H, vv)
        s_all.append(s0 + s)
        x_all.append(x)
        z_all.append(z)
        t_all.append(t)
        seg_all.append(np.full(n, k))
        x0 = x[-1]
        z0 = z[-1]
        s0 += L[k]
    return dict(s=np.concatenate(s_all), x=np.concatenate(x_all), z=np.concatenate(z_all),
                tension=np.concatenate(t_all), segment=np.concatenate(seg_all))
