"""The block-tridiagonal algebra of :mod:`.blocks` for a block of :data:`~.lanes.LW` lines as
SIMD lanes: the recursion over the nodes stays sequential, each step of it runs on all lanes
at once (for one line the 3x3 recursion is latency-bound; the lanes fill the pipeline).  The
same arithmetic as :func:`~.blocks.block_tridiag_solve` and
:func:`~.blocks.block_tridiag_resolve` lane by lane; with bending the band solver runs lane by
lane (:func:`band_solve`)."""

from __future__ import annotations

import math

from numba import njit

from .blocks import block_band_solve
from .lanes import LANE_JIT, LW, ix, lanes_in
from .layout import KERNEL_JIT


@njit(inline="always")
def _pivot(b, i, l, g00, g01, g02, g10, g11, g12, g20, g21, g22, r0, r1, r2, W, Y, keep, mask,
           bad):
    """Store the forward-swept right-hand side and the inverse pivot of node ``i``
    (:func:`~.blocks._inv3_vals`' arithmetic); ``keep``: lanes with ``mask[l]`` 0 keep their
    ``W`` (a kept factorisation, modified Newton).  Records the first singular pivot of each
    lane in ``bad``."""
    Y[b, ix(i, 0, 3, l)] = r0
    Y[b, ix(i, 1, 3, l)] = r1
    Y[b, ix(i, 2, 3, l)] = r2
    c00 = g11 * g22 - g12 * g21
    c01 = -(g10 * g22 - g12 * g20)
    c02 = g10 * g21 - g11 * g20
    det = g00 * c00 + g01 * c01 + g02 * c02
    sing = det == 0.0 or not math.isfinite(det)
    bl = bad[b, l]
    bad[b, l] = i if (sing and bl < 0) else bl
    inv = 1.0 / det
    w00 = c00 * inv
    w01 = -(g01 * g22 - g02 * g21) * inv
    w02 = (g01 * g12 - g02 * g11) * inv
    w10 = c01 * inv
    w11 = (g00 * g22 - g02 * g20) * inv
    w12 = -(g00 * g12 - g02 * g10) * inv
    w20 = c02 * inv
    w21 = -(g00 * g21 - g01 * g20) * inv
    w22 = (g00 * g11 - g01 * g10) * inv
    if keep:
        m = mask[b, l] != 0
        w00 = w00 if m else W[b, ix(i, 0, 9, l)]
        w01 = w01 if m else W[b, ix(i, 1, 9, l)]
        w02 = w02 if m else W[b, ix(i, 2, 9, l)]
        w10 = w10 if m else W[b, ix(i, 3, 9, l)]
        w11 = w11 if m else W[b, ix(i, 4, 9, l)]
        w12 = w12 if m else W[b, ix(i, 5, 9, l)]
        w20 = w20 if m else W[b, ix(i, 6, 9, l)]
        w21 = w21 if m else W[b, ix(i, 7, 9, l)]
        w22 = w22 if m else W[b, ix(i, 8, 9, l)]
    W[b, ix(i, 0, 9, l)] = w00
    W[b, ix(i, 1, 9, l)] = w01
    W[b, ix(i, 2, 9, l)] = w02
    W[b, ix(i, 3, 9, l)] = w10
    W[b, ix(i, 4, 9, l)] = w11
    W[b, ix(i, 5, 9, l)] = w12
    W[b, ix(i, 6, 9, l)] = w20
    W[b, ix(i, 7, 9, l)] = w21
    W[b, ix(i, 8, 9, l)] = w22


@njit(**LANE_JIT)
def tridiag_solve(b, n, Dg, Of, rhs, W, Y, x, keep, mask, bad, OfK):
    """:func:`~.blocks.block_tridiag_solve` of the free nodes ``1 .. n-2`` of the lanes of
    block ``b`` with ``mask[b, l]`` 1 (the solution ``x`` of the others is kept; ``bad[b, l]``:
    the first node of a singular pivot of lane ``l``, or -1; ``keep``: the lanes with
    ``mask[b, l]`` 0 also keep their inverse pivots ``W``, and the others' off-diagonal blocks
    are copied into ``OfK`` for :func:`tridiag_resolve`: a kept factorisation, modified
    Newton).  The forward sweep reads the
    previous node's inverse pivot and right-hand side from ``W`` and ``Y`` (the line kernel
    keeps them in registers: the same numbers); the backward sweep the next node's solution
    from ``x``."""
    lw = lanes_in(mask, 1)
    for l in range(lw):
        bad[b, l] = -1
    for l in range(lw):
        _pivot(b, 1, l, Dg[b, ix(1, 0, 9, l)], Dg[b, ix(1, 1, 9, l)], Dg[b, ix(1, 2, 9, l)],
               Dg[b, ix(1, 3, 9, l)], Dg[b, ix(1, 4, 9, l)], Dg[b, ix(1, 5, 9, l)],
               Dg[b, ix(1, 6, 9, l)], Dg[b, ix(1, 7, 9, l)], Dg[b, ix(1, 8, 9, l)],
               rhs[b, ix(1, 0, 3, l)], rhs[b, ix(1, 1, 3, l)], rhs[b, ix(1, 2, 3, l)],
               W, Y, keep, mask, bad)
    for i in range(2, n - 1):
        p = i - 1
        for l in range(lw):
            g00 = Dg[b, ix(i, 0, 9, l)]
            g01 = Dg[b, ix(i, 1, 9, l)]
            g02 = Dg[b, ix(i, 2, 9, l)]
            g10 = Dg[b, ix(i, 3, 9, l)]
            g11 = Dg[b, ix(i, 4, 9, l)]
            g12 = Dg[b, ix(i, 5, 9, l)]
            g20 = Dg[b, ix(i, 6, 9, l)]
            g21 = Dg[b, ix(i, 7, 9, l)]
            g22 = Dg[b, ix(i, 8, 9, l)]
            r0 = rhs[b, ix(i, 0, 3, l)]
            r1 = rhs[b, ix(i, 1, 3, l)]
            r2 = rhs[b, ix(i, 2, 3, l)]
            w00 = W[b, ix(p, 0, 9, l)]
            w01 = W[b, ix(p, 1, 9, l)]
            w02 = W[b, ix(p, 2, 9, l)]
            w10 = W[b, ix(p, 3, 9, l)]
            w11 = W[b, ix(p, 4, 9, l)]
            w12 = W[b, ix(p, 5, 9, l)]
            w20 = W[b, ix(p, 6, 9, l)]
            w21 = W[b, ix(p, 7, 9, l)]
            w22 = W[b, ix(p, 8, 9, l)]
            y0 = Y[b, ix(p, 0, 3, l)]
            y1 = Y[b, ix(p, 1, 3, l)]
            y2 = Y[b, ix(p, 2, 3, l)]
            z0 = w00 * y0 + w01 * y1 + w02 * y2
            z1 = w10 * y0 + w11 * y1 + w12 * y2
            z2 = w20 * y0 + w21 * y1 + w22 * y2
            o00 = Of[b, ix(p, 0, 9, l)]
            o01 = Of[b, ix(p, 1, 9, l)]
            o02 = Of[b, ix(p, 2, 9, l)]
            o10 = Of[b, ix(p, 3, 9, l)]
            o11 = Of[b, ix(p, 4, 9, l)]
            o12 = Of[b, ix(p, 5, 9, l)]
            o20 = Of[b, ix(p, 6, 9, l)]
            o21 = Of[b, ix(p, 7, 9, l)]
            o22 = Of[b, ix(p, 8, 9, l)]
            h00 = w00 * o00 + w01 * o10 + w02 * o20
            h01 = w00 * o01 + w01 * o11 + w02 * o21
            h02 = w00 * o02 + w01 * o12 + w02 * o22
            h10 = w10 * o00 + w11 * o10 + w12 * o20
            h11 = w10 * o01 + w11 * o11 + w12 * o21
            h12 = w10 * o02 + w11 * o12 + w12 * o22
            h20 = w20 * o00 + w21 * o10 + w22 * o20
            h21 = w20 * o01 + w21 * o11 + w22 * o21
            h22 = w20 * o02 + w21 * o12 + w22 * o22
            g00 -= o00 * h00 + o01 * h10 + o02 * h20
            g01 -= o00 * h01 + o01 * h11 + o02 * h21
            g02 -= o00 * h02 + o01 * h12 + o02 * h22
            r0 -= o00 * z0 + o01 * z1 + o02 * z2
            g10 -= o10 * h00 + o11 * h10 + o12 * h20
            g11 -= o10 * h01 + o11 * h11 + o12 * h21
            g12 -= o10 * h02 + o11 * h12 + o12 * h22
            r1 -= o10 * z0 + o11 * z1 + o12 * z2
            g20 -= o20 * h00 + o21 * h10 + o22 * h20
            g21 -= o20 * h01 + o21 * h11 + o22 * h21
            g22 -= o20 * h02 + o21 * h12 + o22 * h22
            r2 -= o20 * z0 + o21 * z1 + o22 * z2
            _pivot(b, i, l, g00, g01, g02, g10, g11, g12, g20, g21, g22, r0, r1, r2, W, Y,
                   keep, mask, bad)
    last = n - 2
    for l in range(lw):
        m = mask[b, l] != 0
        s0 = Y[b, ix(last, 0, 3, l)]
        s1 = Y[b, ix(last, 1, 3, l)]
        s2 = Y[b, ix(last, 2, 3, l)]
        x0 = (W[b, ix(last, 0, 9, l)] * s0 + W[b, ix(last, 1, 9, l)] * s1
              + W[b, ix(last, 2, 9, l)] * s2)
        x1 = (W[b, ix(last, 3, 9, l)] * s0 + W[b, ix(last, 4, 9, l)] * s1
              + W[b, ix(last, 5, 9, l)] * s2)
        x2 = (W[b, ix(last, 6, 9, l)] * s0 + W[b, ix(last, 7, 9, l)] * s1
              + W[b, ix(last, 8, 9, l)] * s2)
        x[b, ix(last, 0, 3, l)] = x0 if m else x[b, ix(last, 0, 3, l)]
        x[b, ix(last, 1, 3, l)] = x1 if m else x[b, ix(last, 1, 3, l)]
        x[b, ix(last, 2, 3, l)] = x2 if m else x[b, ix(last, 2, 3, l)]
    for k in range(n - 3):
        i = n - 3 - k
        for l in range(lw):
            m = mask[b, l] != 0
            x0 = x[b, ix(i + 1, 0, 3, l)]
            x1 = x[b, ix(i + 1, 1, 3, l)]
            x2 = x[b, ix(i + 1, 2, 3, l)]
            s0 = (Y[b, ix(i, 0, 3, l)] - Of[b, ix(i, 0, 9, l)] * x0 - Of[b, ix(i, 1, 9, l)] * x1
                  - Of[b, ix(i, 2, 9, l)] * x2)
            s1 = (Y[b, ix(i, 1, 3, l)] - Of[b, ix(i, 3, 9, l)] * x0 - Of[b, ix(i, 4, 9, l)] * x1
                  - Of[b, ix(i, 5, 9, l)] * x2)
            s2 = (Y[b, ix(i, 2, 3, l)] - Of[b, ix(i, 6, 9, l)] * x0 - Of[b, ix(i, 7, 9, l)] * x1
                  - Of[b, ix(i, 8, 9, l)] * x2)
            y0 = (W[b, ix(i, 0, 9, l)] * s0 + W[b, ix(i, 1, 9, l)] * s1
                  + W[b, ix(i, 2, 9, l)] * s2)
            y1 = (W[b, ix(i, 3, 9, l)] * s0 + W[b, ix(i, 4, 9, l)] * s1
                  + W[b, ix(i, 5, 9, l)] * s2)
            y2 = (W[b, ix(i, 6, 9, l)] * s0 + W[b, ix(i, 7, 9, l)] * s1
                  + W[b, ix(i, 8, 9, l)] * s2)
            x[b, ix(i, 0, 3, l)] = y0 if m else x[b, ix(i, 0, 3, l)]
            x[b, ix(i, 1, 3, l)] = y1 if m else x[b, ix(i, 1, 3, l)]
            x[b, ix(i, 2, 3, l)] = y2 if m else x[b, ix(i, 2, 3, l)]
    if keep:
        for j in range(n - 1):
            for k in range(9):
                for l in range(lw):
                    m = mask[b, l] != 0
                    OfK[b, ix(j, k, 9, l)] = Of[b, ix(j, k, 9, l)] if m else OfK[b, ix(j, k, 9, l)]


@njit(**LANE_JIT)
def tridiag_resolve(b, n, Of, rhs, W, Y, x):
    """:func:`~.blocks.block_tridiag_resolve` of the free nodes of block ``b`` (the sweeps
    with the inverse pivots ``W`` and off-diagonal blocks ``Of`` of a kept factorisation:
    ``OfK`` of :func:`tridiag_solve`)."""
    lw = lanes_in(rhs, 3 * n)
    for l in range(lw):
        Y[b, ix(1, 0, 3, l)] = rhs[b, ix(1, 0, 3, l)]
        Y[b, ix(1, 1, 3, l)] = rhs[b, ix(1, 1, 3, l)]
        Y[b, ix(1, 2, 3, l)] = rhs[b, ix(1, 2, 3, l)]
    for i in range(2, n - 1):
        p = i - 1
        for l in range(lw):
            y0 = Y[b, ix(p, 0, 3, l)]
            y1 = Y[b, ix(p, 1, 3, l)]
            y2 = Y[b, ix(p, 2, 3, l)]
            xp0 = W[b, ix(p, 0, 9, l)] * y0 + W[b, ix(p, 1, 9, l)] * y1 + W[b, ix(p, 2, 9, l)] * y2
            xp1 = W[b, ix(p, 3, 9, l)] * y0 + W[b, ix(p, 4, 9, l)] * y1 + W[b, ix(p, 5, 9, l)] * y2
            xp2 = W[b, ix(p, 6, 9, l)] * y0 + W[b, ix(p, 7, 9, l)] * y1 + W[b, ix(p, 8, 9, l)] * y2
            x[b, ix(p, 0, 3, l)] = xp0
            x[b, ix(p, 1, 3, l)] = xp1
            x[b, ix(p, 2, 3, l)] = xp2
            Y[b, ix(i, 0, 3, l)] = rhs[b, ix(i, 0, 3, l)] - (
                Of[b, ix(p, 0, 9, l)] * xp0 + Of[b, ix(p, 1, 9, l)] * xp1
                + Of[b, ix(p, 2, 9, l)] * xp2)
            Y[b, ix(i, 1, 3, l)] = rhs[b, ix(i, 1, 3, l)] - (
                Of[b, ix(p, 3, 9, l)] * xp0 + Of[b, ix(p, 4, 9, l)] * xp1
                + Of[b, ix(p, 5, 9, l)] * xp2)
            Y[b, ix(i, 2, 3, l)] = rhs[b, ix(i, 2, 3, l)] - (
                Of[b, ix(p, 6, 9, l)] * xp0 + Of[b, ix(p, 7, 9, l)] * xp1
                + Of[b, ix(p, 8, 9, l)] * xp2)
    last = n - 2
    for l in range(lw):
        s0 = Y[b, ix(last, 0, 3, l)]
        s1 = Y[b, ix(last, 1, 3, l)]
        s2 = Y[b, ix(last, 2, 3, l)]
        for a in range(3):
            x[b, ix(last, a, 3, l)] = (W[b, ix(last, 3 * a, 9, l)] * s0
                                       + W[b, ix(last, 3 * a + 1, 9, l)] * s1
                                       + W[b, ix(last, 3 * a + 2, 9, l)] * s2)
    for k in range(n - 3):
        i = n - 3 - k
        for l in range(lw):
            x0 = x[b, ix(i + 1, 0, 3, l)]
            x1 = x[b, ix(i + 1, 1, 3, l)]
            x2 = x[b, ix(i + 1, 2, 3, l)]
            s0 = Y[b, ix(i, 0, 3, l)]
            s1 = Y[b, ix(i, 1, 3, l)]
            s2 = Y[b, ix(i, 2, 3, l)]
            s0 -= Of[b, ix(i, 0, 9, l)] * x0 + Of[b, ix(i, 1, 9, l)] * x1 + Of[b, ix(i, 2, 9, l)] * x2
            s1 -= Of[b, ix(i, 3, 9, l)] * x0 + Of[b, ix(i, 4, 9, l)] * x1 + Of[b, ix(i, 5, 9, l)] * x2
            s2 -= Of[b, ix(i, 6, 9, l)] * x0 + Of[b, ix(i, 7, 9, l)] * x1 + Of[b, ix(i, 8, 9, l)] * x2
            for a in range(3):
                x[b, ix(i, a, 3, l)] = (W[b, ix(i, 3 * a, 9, l)] * s0
                                        + W[b, ix(i, 3 * a + 1, 9, l)] * s1
                                        + W[b, ix(i, 3 * a + 2, 9, l)] * s2)


@njit(**KERNEL_JIT)
def band_solve(b, n, Dg, Of, BX, rhs, Y, T1, x, mask, bad):
    """:func:`~.blocks.block_band_solve` (bending) of the free nodes of the lanes of block
    ``b`` with ``mask[b, l]`` 1, lane by lane (``BX`` and ``T1``: one per lane row)."""
    for l in range(LW):
        if mask[b, l] == 0:
            continue
        p = b * LW + l
        bad[b, l] = block_band_solve(Dg[b].reshape((n, 3, 3, LW))[:, :, :, l],
                                     Of[b].reshape((n - 1, 3, 3, LW))[:, :, :, l], BX[p],
                                     rhs[b].reshape((n, 3, LW))[:, :, l], 1, n - 1,
                                     Y[b].reshape((n, 3, LW))[:, :, l], T1[p],
                                     x[b].reshape((n, 3, LW))[:, :, l])
