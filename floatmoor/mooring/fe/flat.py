"""The passes of the line kernel (one line at a time: :func:`~.forces.line_forces`,
:func:`~.gen_alpha.gen_alpha_step`, :func:`~.advance.ga_advance`) vectorised across the
elements and nodes of the line: element geometry, node tangents, the element pass of the forces
and their tangent, the drag pass; per step the kinematics, node mass blocks, the copies of a
state and the energy audit's terms.

The line kernel keeps its arrays as (node, axis); a loop over the nodes of such an array is
scalar in numba's code (every index carries a negative-index wrap-around and every division a
branch to ZeroDivisionError, and LLVM cannot prove the arrays apart).  These passes take flat
views of the same arrays (:func:`flat`: the entry of node ``i``, axis ``k`` at ``3 i + k``),
unsigned indices and the lanes' compiler options (:data:`~.lanes.LANE_JIT`: ``noalias``
arguments, numpy's error model), and they write both sides of a branch and select, as the lane
kernels do (:mod:`.lanes`).  LLVM then packs four elements or nodes per AVX2 register,
interleaving the axes of the (node, axis) rows in registers.  Each element or node gets the
arithmetic of the general function it replaces (:func:`~.elements.element_forces`,
:func:`~.elements.element_geometry`, :func:`~.elements._tangents_from`,
:func:`~.fluid.fluid_forces`, :func:`~.gen_alpha.kinematics`, :func:`~.energy.line_energy`,
...) operation for operation, so the results are those of these functions to the bit
(tests/mooring/fe/test_flat_passes.py; ``benchmarks/check_flat_asm.py`` shows the packed
instructions).

The force passes cover the common lines (:func:`~.forces.flat_kind`): elements with the
polynomial law (no fibre law), no tension estimates of stiff elements, the dynamic tangent
(``cC`` > 0) or none; the drag pass for lines without clump drag or wave accelerations at the
nodes (a current profile is looked up node by node first, :func:`current_speeds`).
:func:`~.forces._line_forces` takes them when a line qualifies and the general functions
otherwise.

The element pass is split in two: the element quantities (tension, tangent block) of every
element (:func:`element_pass`, vectorised), then the node sums (:func:`node_sums`, the node's
own load, element ``i - 1``, element ``i``, in that order as in the element loop of
:func:`~.elements.element_forces`).  The upper off-diagonal blocks ``Of`` hold the elements'
positive blocks in between.
"""

from __future__ import annotations

import math

import numpy as np
from numba import config as numba_config
from numba import njit, types
from numba.core import cgutils
from numba.core.imputils import impl_ret_borrowed
from numba.extending import intrinsic
from numba.np.arrayobj import _call_contiguous_check, make_array, populate_array
from numba.np.numpy_support import is_contiguous

from .bundles import N_EW
from .elements import E0_STIFF, tangent_from
from .energy import PEN_FLOOR, PEN_WEIGHTS
from .fibre_law import EL_LAW
from .fluid import _current, _current_scale
from .lanes import LANE_JIT
from .layout import (
    EL_B,
    EL_C1,
    EL_C2,
    EL_C3,
    EL_L0,
    KERNEL_JIT,
    N_EL,
    N_NP,
    NP_KDN,
    NP_KDT,
    NP_KS,
    NP_MAC,
    NP_MAN,
    NP_MASS,
    NP_MAT,
    NP_W,
)

__all__ = ["flat", "c_contiguous", "element_geometry_flat", "element_pass", "element_pass_jac", "node_sums",
           "block_sums", "fluid_pass", "fluid_pass_jac", "kinematics_flat", "mass_blocks_flat",
           "copy_nodes", "energy_terms", "energy_sums", "current_speeds",
           "node_tangents"]


def _contiguous_bit(context, builder, aryty, ary):
    """LLVM i1: the array value ``ary`` of type ``aryty`` is C-contiguous (a constant for a
    C-layout type, else numba's own stride check)."""
    if aryty.layout == "C":
        return cgutils.true_bit
    return _call_contiguous_check(is_contiguous, context, builder, aryty, ary)


@intrinsic
def c_contiguous(typingctx, arr):
    """``arr.flags.c_contiguous`` for the FE kernels, which compile without reference counting
    (``layout.KERNEL_JIT``): numba's ``flags`` object needs it.  A constant for a C-layout
    array type, a stride check for the others."""
    if not isinstance(arr, types.Array):
        return None

    def codegen(context, builder, sig, args):
        return _contiguous_bit(context, builder, sig.args[0], args[0])

    return types.boolean(arr), codegen


@intrinsic
def _flat_view(typingctx, arr):
    """The 1-D view of a C-contiguous array (same data, ``size`` entries): what
    ``arr.reshape(arr.size)`` returns, built directly (numba's reshape calls a helper that
    checks the strides, about 30 ns, more than a small pass over a line takes).  For an array
    type of another layout the strides are checked at run time and a ValueError raised when
    the array is not C-contiguous (as ``reshape`` does)."""
    if not isinstance(arr, types.Array):
        return None
    ret = types.Array(arr.dtype, 1, "C", readonly=not arr.mutable)

    def codegen(context, builder, sig, args):
        aryty = sig.args[0]
        ary = make_array(aryty)(context, builder, value=args[0])
        if aryty.layout != "C":
            ok = _contiguous_bit(context, builder, aryty, args[0])
            with builder.if_then(builder.not_(ok), likely=False):
                context.call_conv.return_user_exc(
                    builder, ValueError, ("flat: the array is not C-contiguous",))
        out = make_array(sig.return_type)(context, builder)
        shape = cgutils.unpack_tuple(builder, ary.shape)
        size = shape[0]
        for s in shape[1:]:
            size = builder.mul(size, s)
        populate_array(out, data=ary.data, shape=cgutils.pack_array(builder, [size]),
                       strides=cgutils.pack_array(builder, [ary.itemsize]),
                       itemsize=ary.itemsize, meminfo=ary.meminfo, parent=ary.parent)
        return impl_ret_borrowed(context, builder, sig.return_type, out._getvalue())

    return ret(arr), codegen


if numba_config.DISABLE_JIT:
    def flat(a):
        """The 1-D view of the contiguous array ``a`` (plain Python: ``a.reshape(a.size)``)."""
        return a.reshape(a.size)

    def c_contiguous(a):  # noqa: F811 (plain Python: the intrinsic cannot run)
        """``a.flags.c_contiguous`` (plain Python)."""
        return a.flags.c_contiguous
else:
    @njit(inline="always")
    def flat(a):
        """The 1-D view of the C-contiguous array ``a`` (``a.reshape(a.size)`` without numba's
        reshape helper; a ValueError for an array that is not C-contiguous).  Inlined into the
        caller's IR: the FE kernels compile without reference counting
        (``layout.KERNEL_JIT``), under which numba refuses a called function that returns an
        array other than its argument."""
        return _flat_view(a)


@njit(inline="always")
def u(i):
    """Unsigned index (no negative-index wrap-around; see :func:`~.lanes.ix`)."""
    return np.uintp(i)


@njit(**LANE_JIT)
def element_geometry_flat(r, el):
    """:func:`~.elements.element_geometry` on the flat views ``r`` (3 n) and ``el`` (4 (n-1))."""
    m = el.shape[0] // 4
    for j in range(m):
        a = u(3 * j)
        b = u(3 * j + 3)
        e = u(4 * j)
        dx = r[b] - r[a]
        dy = r[b + 1] - r[a + 1]
        dz = r[b + 2] - r[a + 2]
        ll = math.sqrt(dx * dx + dy * dy + dz * dz)
        el[e] = dx / ll
        el[e + 1] = dy / ll
        el[e + 2] = dz / ll
        el[e + 3] = ll


# The element law is written out in both element passes: called as a function (even inlined
# by numba), it keeps LLVM from vectorising the loop, and so does a select of a loaded value
# (checked in the assembly: benchmarks/check_flat_asm.py).
@njit(**LANE_JIT)
def element_pass(v, P, E, el, tens):
    """Element tensions into ``tens`` (n-1) (:func:`~.elements.element_forces` without the
    tangent): the polynomial law of :func:`~.elements._tension` with its slack cubic and the
    internal damping faded in over the slack transition; ``v`` (3 n), ``P`` (N_NP n), ``E``
    (N_EL (n-1)), ``el`` (4 (n-1)) flat."""
    m = tens.shape[0]
    for j in range(m):
        e4 = u(4 * j)
        ke = u(N_EL * j)
        pa = u(N_NP * j)
        pb = u(N_NP * j + N_NP)
        a = u(3 * j)
        b = u(3 * j + 3)
        ll = el[e4 + 3]
        ex = el[e4]
        ey = el[e4 + 1]
        ez = el[e4 + 2]
        L0 = E[ke + EL_L0]
        eps = ll / L0 - 1.0
        c1 = E[ke + EL_C1]
        c2 = E[ke + EL_C2]
        c3 = E[ke + EL_C3]
        e0 = max(abs(P[pa + NP_W]) + abs(P[pb + NP_W]), 1e-6) / c1
        # elements._tension: 0 in compression, the law beyond e0, the cubic in between
        Tl = c1 * eps + c2 * eps * eps + c3 * eps * eps * eps
        Dl = c1 + 2.0 * c2 * eps + 3.0 * c3 * eps * eps
        T0 = c1 * e0 + c2 * e0 * e0 + c3 * e0 * e0 * e0
        D0 = c1 + 2.0 * c2 * e0 + 3.0 * c3 * e0 * e0
        Bc = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
        Ac = (T0 - Bc * e0 * e0 * e0) / (e0 * e0)
        Tc = Ac * eps * eps + Bc * eps * eps * eps
        Dc = 2.0 * Ac * eps + 3.0 * Bc * eps * eps
        comp = eps <= 0.0
        up = eps >= e0
        T = 0.0 if comp else (Tl if up else Tc)
        dTde = 0.0 if comp else (Dl if up else Dc)
        # internal damping (element_forces: with Bj != 0 and eps > 0); the damping kinematics
        # of every element (with Bj = 0 they enter no result, so the element kernel's zeros
        # need not be selected)
        Bj = E[ke + EL_B]
        dvx = v[b] - v[a]
        dvy = v[b + 1] - v[a + 1]
        dvz = v[b + 2] - v[a + 2]
        ldot = ex * dvx + ey * dvy + ez * dvz
        on = (Bj != 0.0) & (eps > 0.0)
        xs = eps / e0
        inr = xs < 1.0
        sm = xs * xs * (3.0 - 2.0 * xs) if inr else 1.0
        dsm = 6.0 * xs * (1.0 - xs) / e0 if inr else 0.0
        B = Bj * sm if on else 0.0
        T = T + B * ldot / L0 if on else T
        dTde = dTde + Bj * dsm * ldot / L0 if on else dTde
        tens[u(j)] = T


@njit(**LANE_JIT)
def element_pass_jac(v, P, E, el, cK, cC, tens, Of):
    """:func:`element_pass` and every element's block ``(ka + cb) e e^T + kg (I - e e^T)`` plus
    the position derivative of the damping force, row by row into ``Of`` (9 (n-1)) (positive:
    :func:`block_sums` forms the diagonal blocks and then negates them); the dynamic tangent
    (``cC`` > 0) of :func:`~.elements.element_forces`."""
    m = tens.shape[0]
    for j in range(m):
        e4 = u(4 * j)
        ke = u(N_EL * j)
        pa = u(N_NP * j)
        pb = u(N_NP * j + N_NP)
        a = u(3 * j)
        b = u(3 * j + 3)
        ll = el[e4 + 3]
        ex = el[e4]
        ey = el[e4 + 1]
        ez = el[e4 + 2]
        L0 = E[ke + EL_L0]
        eps = ll / L0 - 1.0
        c1 = E[ke + EL_C1]
        c2 = E[ke + EL_C2]
        c3 = E[ke + EL_C3]
        e0 = max(abs(P[pa + NP_W]) + abs(P[pb + NP_W]), 1e-6) / c1
        # elements._tension: 0 in compression, the law beyond e0, the cubic in between
        Tl = c1 * eps + c2 * eps * eps + c3 * eps * eps * eps
        Dl = c1 + 2.0 * c2 * eps + 3.0 * c3 * eps * eps
        T0 = c1 * e0 + c2 * e0 * e0 + c3 * e0 * e0 * e0
        D0 = c1 + 2.0 * c2 * e0 + 3.0 * c3 * e0 * e0
        Bc = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
        Ac = (T0 - Bc * e0 * e0 * e0) / (e0 * e0)
        Tc = Ac * eps * eps + Bc * eps * eps * eps
        Dc = 2.0 * Ac * eps + 3.0 * Bc * eps * eps
        comp = eps <= 0.0
        up = eps >= e0
        T = 0.0 if comp else (Tl if up else Tc)
        dTde = 0.0 if comp else (Dl if up else Dc)
        # internal damping (element_forces: with Bj != 0 and eps > 0); the damping kinematics
        # of every element (with Bj = 0 they enter no result, so the element kernel's zeros
        # need not be selected)
        Bj = E[ke + EL_B]
        dvx = v[b] - v[a]
        dvy = v[b + 1] - v[a + 1]
        dvz = v[b + 2] - v[a + 2]
        ldot = ex * dvx + ey * dvy + ez * dvz
        on = (Bj != 0.0) & (eps > 0.0)
        xs = eps / e0
        inr = xs < 1.0
        sm = xs * xs * (3.0 - 2.0 * xs) if inr else 1.0
        dsm = 6.0 * xs * (1.0 - xs) / e0 if inr else 0.0
        B = Bj * sm if on else 0.0
        T = T + B * ldot / L0 if on else T
        dTde = dTde + Bj * dsm * ldot / L0 if on else dTde
        tens[u(j)] = T
        ka = cK * dTde / L0
        kg = cK * max(T, 0.0) / ll
        nz = B != 0.0
        cbv = cC * B / L0
        kbv = cK * B / (L0 * ll)
        cb = cbv if nz else 0.0
        kb = kbv if nz else 0.0
        kac = ka + cb
        ee = ex * ex
        v00 = kac * ee + kg * (1.0 - ee)
        ee = ey * ey
        v11 = kac * ee + kg * (1.0 - ee)
        ee = ez * ez
        v22 = kac * ee + kg * (1.0 - ee)
        ee = ex * ey
        v01 = kac * ee + kg * (0.0 - ee)
        v10 = v01
        ee = ex * ez
        v02 = kac * ee + kg * (0.0 - ee)
        v20 = v02
        ee = ey * ez
        v12 = kac * ee + kg * (0.0 - ee)
        v21 = v12
        kz = kb != 0.0
        dpx = dvx - ldot * ex
        dpy = dvy - ldot * ey
        dpz = dvz - ldot * ez
        w00 = v00 + kb * ex * dpx
        w01 = v01 + kb * ex * dpy
        w02 = v02 + kb * ex * dpz
        w10 = v10 + kb * ey * dpx
        w11 = v11 + kb * ey * dpy
        w12 = v12 + kb * ey * dpz
        w20 = v20 + kb * ez * dpx
        w21 = v21 + kb * ez * dpy
        w22 = v22 + kb * ez * dpz
        o = u(9 * j)
        Of[o] = w00 if kz else v00
        Of[o + 1] = w01 if kz else v01
        Of[o + 2] = w02 if kz else v02
        Of[o + 3] = w10 if kz else v10
        Of[o + 4] = w11 if kz else v11
        Of[o + 5] = w12 if kz else v12
        Of[o + 6] = w20 if kz else v20
        Of[o + 7] = w21 if kz else v21
        Of[o + 8] = w22 if kz else v22


@njit(**LANE_JIT)
def node_sums(P, el, tens, f):
    """Every node's weight and element forces into ``f`` (3 n) from the element tensions
    ``tens`` and directions ``el``: the sums of :func:`~.elements.element_forces` (the node's
    own load, then element ``i - 1``, then element ``i``)."""
    n = f.shape[0] // 3
    m = n - 1
    f[0] = 0.0 + tens[0] * el[0]
    f[1] = 0.0 + tens[0] * el[1]
    f[2] = -P[NP_W] + tens[0] * el[2]
    for i in range(1, n - 1):
        a = u(4 * i - 4)
        b = u(4 * i)
        ta = tens[u(i - 1)]
        tb = tens[u(i)]
        c = u(3 * i)
        f[c] = (0.0 - ta * el[a]) + tb * el[b]
        f[c + 1] = (0.0 - ta * el[a + 1]) + tb * el[b + 1]
        f[c + 2] = (-P[u(N_NP * i) + NP_W] - ta * el[a + 2]) + tb * el[b + 2]
    a = u(4 * m - 4)
    ta = tens[u(m - 1)]
    c = u(3 * m)
    f[c] = 0.0 - ta * el[a]
    f[c + 1] = 0.0 - ta * el[a + 1]
    f[c + 2] = -P[u(N_NP * m) + NP_W] - ta * el[a + 2]


@njit(**LANE_JIT)
def block_sums(Of, Dg):
    """The diagonal blocks ``Dg`` (9 n) of the element tangent from the elements' positive
    blocks in ``Of`` (9 (n-1), :func:`element_pass_jac`): ``0 + K_(i-1) + K_i`` as the element
    loop of :func:`~.elements.element_forces` sums them; then ``Of`` negated (the upper
    off-diagonal blocks).  Entry ``k`` of the block of node ``i`` is at ``9 i + k``, so the
    interior nodes are one loop over ``9 (i - 1) + k``."""
    m9 = Of.shape[0]
    for o in range(9):
        Dg[u(o)] = 0.0 + Of[u(o)]
    for o in range(m9 - 9):
        Dg[u(o + 9)] = (0.0 + Of[u(o)]) + Of[u(o + 9)]
    for o in range(m9 - 9, m9):
        Dg[u(o + 9)] = 0.0 + Of[u(o)]
    for o in range(m9):
        Of[u(o)] = -Of[u(o)]


@njit(**LANE_JIT)
def fluid_pass(v, q, P, uc, ccos, csin, wk, f):
    """The drag of :func:`~.fluid.fluid_forces` added into ``f`` (3 n), for a line without
    clump drag and wave accelerations at the nodes (the fluid inertia is then zero and the
    kernel skips it); ``v, q`` (3 n), ``P`` (N_NP n), ``wk`` (6 n) flat, ``uc`` (n) the
    current speed at every node (:func:`current_speeds`)."""
    n = f.shape[0] // 3
    for i in range(n):
        c = u(3 * i)
        w = u(6 * i)
        p = u(N_NP * i)
        qx = q[c]
        qy = q[c + 1]
        qz = q[c + 2]
        ui = uc[u(i)]
        vrx = v[c] - ui * ccos - wk[w]
        vry = v[c + 1] - ui * csin - wk[w + 1]
        vrz = v[c + 2] - wk[w + 2]
        vq = vrx * qx + vry * qy + vrz * qz
        vnx = vrx - vq * qx
        vny = vry - vq * qy
        vnz = vrz - vq * qz
        vn = math.sqrt(vnx * vnx + vny * vny + vnz * vnz)
        kdn = P[p + NP_KDN]
        kdt = P[p + NP_KDT]
        f[c] = f[c] - (kdn * vn * vnx + kdt * abs(vq) * vq * qx)
        f[c + 1] = f[c + 1] - (kdn * vn * vny + kdt * abs(vq) * vq * qy)
        f[c + 2] = f[c + 2] - (kdn * vn * vnz + kdt * abs(vq) * vq * qz)


@njit(**LANE_JIT)
def fluid_pass_jac(v, q, P, uc, ccos, csin, wk, cC, f, Dg):
    """:func:`fluid_pass` and the drag blocks of :func:`~.fluid.fluid_forces` times ``cC``
    added into ``Dg`` (9 n), in one pass."""
    n = f.shape[0] // 3
    for i in range(n):
        c = u(3 * i)
        w = u(6 * i)
        p = u(N_NP * i)
        qx = q[c]
        qy = q[c + 1]
        qz = q[c + 2]
        ui = uc[u(i)]
        vrx = v[c] - ui * ccos - wk[w]
        vry = v[c + 1] - ui * csin - wk[w + 1]
        vrz = v[c + 2] - wk[w + 2]
        vq = vrx * qx + vry * qy + vrz * qz
        vnx = vrx - vq * qx
        vny = vry - vq * qy
        vnz = vrz - vq * qz
        vn = math.sqrt(vnx * vnx + vny * vny + vnz * vnz)
        kdn = P[p + NP_KDN]
        kdt = P[p + NP_KDT]
        f[c] = f[c] - (kdn * vn * vnx + kdt * abs(vq) * vq * qx)
        f[c + 1] = f[c + 1] - (kdn * vn * vny + kdt * abs(vq) * vq * qy)
        f[c + 2] = f[c + 2] - (kdn * vn * vnz + kdt * abs(vq) * vq * qz)
        kv = kdn * vn
        kt = 2.0 * kdt * abs(vq)
        qq = qx * qx
        v00 = kv * (1.0 - qq) + kt * qq
        qq = qy * qy
        v11 = kv * (1.0 - qq) + kt * qq
        qq = qz * qz
        v22 = kv * (1.0 - qq) + kt * qq
        qq = qx * qy
        v01 = kv * (0.0 - qq) + kt * qq
        v10 = v01
        qq = qx * qz
        v02 = kv * (0.0 - qq) + kt * qq
        v20 = v02
        qq = qy * qz
        v12 = kv * (0.0 - qq) + kt * qq
        v21 = v12
        pos = vn > 0.0
        kn = kdn * vnx
        w00 = v00 + kn * vnx / vn
        w01 = v01 + kn * vny / vn
        w02 = v02 + kn * vnz / vn
        kn = kdn * vny
        w10 = v10 + kn * vnx / vn
        w11 = v11 + kn * vny / vn
        w12 = v12 + kn * vnz / vn
        kn = kdn * vnz
        w20 = v20 + kn * vnx / vn
        w21 = v21 + kn * vny / vn
        w22 = v22 + kn * vnz / vn
        o = u(9 * i)
        Dg[o] += cC * (w00 if pos else v00)
        Dg[o + 1] += cC * (w01 if pos else v01)
        Dg[o + 2] += cC * (w02 if pos else v02)
        Dg[o + 3] += cC * (w10 if pos else v10)
        Dg[o + 4] += cC * (w11 if pos else v11)
        Dg[o + 5] += cC * (w12 if pos else v12)
        Dg[o + 6] += cC * (w20 if pos else v20)
        Dg[o + 7] += cC * (w21 if pos else v21)
        Dg[o + 8] += cC * (w22 if pos else v22)


@njit(**LANE_JIT)
def kinematics_flat(dt, beta, gamma, r, v, a, a1, r1, v1):
    """:func:`~.gen_alpha.kinematics` on flat views (3 n): positions and velocities of the
    free nodes (entries 3 to 3 n - 4) from the accelerations ``a1``, the same arithmetic."""
    m = r.shape[0] - 3
    for o in range(3, m):
        k = u(o)
        r1[k] = r[k] + dt * v[k] + dt * dt * ((0.5 - beta) * a[k] + beta * a1[k])
        v1[k] = v[k] + dt * ((1.0 - gamma) * a[k] + gamma * a1[k])


@njit(**LANE_JIT)
def mass_blocks_flat(P, q, Mb):
    """:func:`~.elements._mass_blocks` on flat views: the 3x3 mass block (structural plus
    added mass) of every node from its tangent, ``P`` (N_NP n), ``q`` (3 n), ``Mb`` (9 n)."""
    n = q.shape[0] // 3
    for i in range(n):
        p = u(N_NP * i)
        c = u(3 * i)
        o = u(9 * i)
        m = P[p + NP_MASS] + P[p + NP_MAC]
        man = P[p + NP_MAN]
        mat = P[p + NP_MAT]
        q0 = q[c]
        q1 = q[c + 1]
        q2 = q[c + 2]
        qq = q0 * q0
        Mb[o] = m * 1.0 + man * (1.0 - qq) + mat * qq
        qq = q0 * q1
        Mb[o + 1] = m * 0.0 + man * (0.0 - qq) + mat * qq
        qq = q0 * q2
        Mb[o + 2] = m * 0.0 + man * (0.0 - qq) + mat * qq
        qq = q1 * q0
        Mb[o + 3] = m * 0.0 + man * (0.0 - qq) + mat * qq
        qq = q1 * q1
        Mb[o + 4] = m * 1.0 + man * (1.0 - qq) + mat * qq
        qq = q1 * q2
        Mb[o + 5] = m * 0.0 + man * (0.0 - qq) + mat * qq
        qq = q2 * q0
        Mb[o + 6] = m * 0.0 + man * (0.0 - qq) + mat * qq
        qq = q2 * q1
        Mb[o + 7] = m * 0.0 + man * (0.0 - qq) + mat * qq
        qq = q2 * q2
        Mb[o + 8] = m * 1.0 + man * (1.0 - qq) + mat * qq


@njit(**LANE_JIT)
def copy_nodes(r, v, a, f, r2, v2, a2, f2):
    """``r2, v2, a2, f2 = r, v, a, f`` entry by entry on flat views (a state's nodes: the
    copies of an accepted sub-step and of an accept, vectorised)."""
    for o in range(r.shape[0]):
        k = u(o)
        r2[k] = r[k]
        v2[k] = v[k]
        a2[k] = a[k]
        f2[k] = f[k]


# rows of LineWork.ew (the energy pass's per-element and per-node terms, flat_energy)
EW_UE, EW_PWE, EW_EON, EW_KE, EW_EZ, EW_PV, EW_ES, EW_PS, EW_PEN, EW_CON = range(N_EW)


@njit(**LANE_JIT)
def energy_terms(r, v, f, P, E, el, q, zc, dc, ew):
    """The terms of :func:`~.energy.line_energy` (``geom`` False) of every element and node
    into the rows of ``ew`` (N_EW n, flat; :data:`EW_UE` ...), computed for all and summed in
    the kernel's order by :func:`energy_sums`: element elastic energy, its tension power and
    whether it counts (polynomial law, not stiff, taut); node kinetic energy, weight term,
    force power, seabed spring energy and power, penetration over its bound and contact."""
    n = r.shape[0] // 3
    m = n - 1
    for j in range(m):
        e4 = u(4 * j)
        ke = u(N_EL * j)
        pa = u(N_NP * j)
        pb = u(N_NP * j + N_NP)
        a = u(3 * j)
        b = u(3 * j + 3)
        L0 = E[ke + EL_L0]
        eps = el[e4 + 3] / L0 - 1.0
        c1 = E[ke + EL_C1]
        c2 = E[ke + EL_C2]
        c3 = E[ke + EL_C3]
        # elements._stiff and _slack_strain
        wa = (9.80665 * (P[pa + NP_MASS] + P[pb + NP_MASS]) + abs(P[pa + NP_W])
              + abs(P[pb + NP_W]))
        law = E[ke + EL_LAW] == 0.0
        stiff = (wa < E0_STIFF * c1) & law
        e0 = max(abs(P[pa + NP_W]) + abs(P[pb + NP_W]), 1e-6) / c1
        # elements._tension for eps > 0
        T0 = c1 * e0 + c2 * e0 * e0 + c3 * e0 * e0 * e0
        D0 = c1 + 2.0 * c2 * e0 + 3.0 * c3 * e0 * e0
        Bc = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
        Ac = (T0 - Bc * e0 * e0 * e0) / (e0 * e0)
        up = eps >= e0
        Tl = c1 * eps + c2 * eps * eps + c3 * eps * eps * eps
        Tc = Ac * eps * eps + Bc * eps * eps * eps
        T = Tl if up else Tc
        # elements._elastic_energy for eps > 0
        Ul = L0 * (Ac * e0 ** 3 / 3.0 + Bc * e0 ** 4 / 4.0
                   + c1 * (eps * eps - e0 * e0) / 2.0 + c2 * (eps ** 3 - e0 ** 3) / 3.0
                   + c3 * (eps ** 4 - e0 ** 4) / 4.0)
        Uc = L0 * (Ac * eps ** 3 / 3.0 + Bc * eps ** 4 / 4.0)
        lo = eps < e0
        ldot = (el[e4] * (v[b] - v[a]) + el[e4 + 1] * (v[b + 1] - v[a + 1])
                + el[e4 + 2] * (v[b + 2] - v[a + 2]))
        ew[u(EW_UE * n + j)] = Uc if lo else Ul
        ew[u(EW_PWE * n + j)] = T * ldot
        on = law & (stiff == False) & ((eps <= 0.0) == False)  # noqa: E712
        ew[u(EW_EON * n + j)] = 1.0 if on else 0.0
    for i in range(1, n - 1):
        c = u(3 * i)
        p = u(N_NP * i)
        vx = v[c]
        vy = v[c + 1]
        vz = v[c + 2]
        vv = vx * vx + vy * vy + vz * vz
        vq = vx * q[c] + vy * q[c + 1] + vz * q[c + 2]
        ew[u(EW_KE * n + i)] = 0.5 * ((P[p + NP_MASS] + P[p + NP_MAC]) * vv
                                      + P[p + NP_MAN] * (vv - vq * vq)
                                      + P[p + NP_MAT] * vq * vq)
        w = P[p + NP_W]
        ew[u(EW_EZ * n + i)] = w * r[c + 2]
        ew[u(EW_PV * n + i)] = f[c] * vx + f[c + 1] * vy + f[c + 2] * vz + w * vz
        pen = zc - r[c + 2]
        ks = P[p + NP_KS]
        dpen = max(0.5 * max(w, 1e-12) / ks, dc)
        x = pen / dpen
        inr = pen < dpen
        gp = pen * x * (2.0 - x) if inr else pen
        esc = ks * (2.0 * pen ** 3 / (3.0 * dpen) - pen ** 4 / (4.0 * dpen * dpen))
        esl = ks * (5.0 * dpen * dpen / 12.0 + 0.5 * (pen * pen - dpen * dpen))
        ew[u(EW_ES * n + i)] = esc if inr else esl
        ew[u(EW_PS * n + i)] = ks * gp * vz
        lim = max(PEN_WEIGHTS * max(w, 0.0) / ks, PEN_FLOOR)
        ew[u(EW_PEN * n + i)] = pen / lim
        con = (pen > 0.0) & (ks > 0.0)
        ew[u(EW_CON * n + i)] = 1.0 if con else 0.0


@njit(**KERNEL_JIT, error_model="numpy")
def energy_sums(r, v, P, E, el, ew):
    """:func:`~.energy.line_energy`'s sums from the terms of :func:`energy_terms`, in its order
    (elements, with the internal damping power of the fairlead's element, then the free
    nodes); the same return value ``(E_m, P, budget, wsum, pen, ipen)``."""
    n = r.shape[0]
    ue = 0.0
    pw = 0.0
    for j in range(n - 1):
        if ew[EW_EON, j] == 0.0:
            continue
        ue += ew[EW_UE, j]
        pw += ew[EW_PWE, j]
        if j == n - 2 and E[j, EL_B] != 0.0:
            L0 = E[j, EL_L0]
            eps = el[j, 3] / L0 - 1.0
            e0 = max(abs(P[j, NP_W]) + abs(P[j + 1, NP_W]), 1e-6) / E[j, EL_C1]
            ldot = (el[j, 0] * (v[j + 1, 0] - v[j, 0]) + el[j, 1] * (v[j + 1, 1] - v[j, 1])
                    + el[j, 2] * (v[j + 1, 2] - v[j, 2]))
            xs = eps / e0
            sm = xs * xs * (3.0 - 2.0 * xs) if xs < 1.0 else 1.0
            Td = E[j, EL_B] * sm * ldot / L0
            pw += Td * (el[j, 0] * v[j + 1, 0] + el[j, 1] * v[j + 1, 1] + el[j, 2] * v[j + 1, 2])
    ke = 0.0
    eg = 0.0
    wsum = 0.0
    pen_max = 0.0
    ipen = 0
    for i in range(1, n - 1):
        ke += ew[EW_KE, i]
        wsum += abs(P[i, NP_W])
        eg += ew[EW_EZ, i]
        pw += ew[EW_PV, i]
        if ew[EW_CON, i] != 0.0:
            eg += ew[EW_ES, i]
            pw -= ew[EW_PS, i]
            if ew[EW_PEN, i] > pen_max:
                pen_max = ew[EW_PEN, i]
                ipen = i
    return ke + ue + eg, pw, ke + ue, wsum, pen_max, ipen


@njit(**KERNEL_JIT)
def current_speeds(r, cur_z, cur_u, uc):
    """The current speed at every node's level into ``uc`` (n): the lookup of
    :func:`~.fluid.fluid_forces` (:func:`~.fluid._current`, the same numbers), node by node
    (the walk through the profile levels does not vectorise); zeros without a profile, as the
    lookup returns."""
    n = r.shape[0]
    if cur_z.shape[0] == 0:
        for i in range(n):
            uc[i] = 0.0
        return
    csc = _current_scale(cur_z)
    for i in range(n):
        uc[i] = _current(r[i, 2], cur_z, cur_u, csc)


@njit(**LANE_JIT)
def _tangents_interior(el, q):
    """The interior nodes' tangents of :func:`~.elements._tangents_from` for adjacent elements
    of positive length and a non-zero sum (the common case, vectorised; the others are
    redone by :func:`node_tangents`): ``(0 + e_(i-1) + e_i) / |...|``; ``el`` (4 (n-1)), ``q``
    (3 n) flat."""
    n = q.shape[0] // 3
    for i in range(1, n - 1):
        a = u(4 * i - 4)
        b = u(4 * i)
        qx = (0.0 + el[a]) + el[b]
        qy = (0.0 + el[a + 1]) + el[b + 1]
        qz = (0.0 + el[a + 2]) + el[b + 2]
        nq = math.sqrt(qx * qx + qy * qy + qz * qz)
        c = u(3 * i)
        q[c] = qx / nq
        q[c + 1] = qy / nq
        q[c + 2] = qz / nq


@njit(**KERNEL_JIT)
def node_tangents(el, q):
    """:func:`~.elements._tangents_from` (the node tangents from the element directions ``el``
    (n-1, 4)) into ``q`` (n, 3), the same numbers: the interior nodes vectorised
    (:func:`_tangents_interior`), then the end nodes, and any node next to an element of zero
    or undefined length or with a zero or undefined sum (its quotient is then NaN), as the
    general function does them."""
    n = q.shape[0]
    _tangents_interior(flat(el), flat(q))
    for i in range(n):
        if 0 < i < n - 1 and el[i - 1, 3] > 0.0 and el[i, 3] > 0.0 and q[i, 0] == q[i, 0]:
            continue
        tangent_from(el, q, i)
