"""Block-tridiagonal (and block bandwidth 2) algebra of the line's iteration matrix: 3x3
inverses, block Gaussian elimination, and the sweeps that reuse a factorisation.

The matrix of a line without bending is block-tridiagonal: diagonal blocks ``Dg[i]`` (n, 3, 3),
upper blocks ``Of[i]`` (row i, column i+1) and lower blocks ``Of[i-1]`` (row i, column i-1):
element-assembled matrices have the same coupling block on both sides of the diagonal,
symmetric or not.  With bending the band is two blocks wide (``BX``, :func:`block_band_solve`).
"""

from __future__ import annotations

import math

from numba import njit

from .layout import KERNEL_JIT


@njit(**KERNEL_JIT)
def _inv3(A, out):
    a, b, c = A[0, 0], A[0, 1], A[0, 2]
    d, e, g = A[1, 0], A[1, 1], A[1, 2]
    h, k, m = A[2, 0], A[2, 1], A[2, 2]
    c00 = e * m - g * k
    c01 = -(d * m - g * h)
    c02 = d * k - e * h
    det = a * c00 + b * c01 + c * c02
    if det == 0.0 or not math.isfinite(det):
        return False
    inv = 1.0 / det
    out[0, 0] = c00 * inv
    out[1, 0] = c01 * inv
    out[2, 0] = c02 * inv
    out[0, 1] = -(b * m - c * k) * inv
    out[1, 1] = (a * m - c * h) * inv
    out[2, 1] = -(a * k - b * h) * inv
    out[0, 2] = (b * g - c * e) * inv
    out[1, 2] = -(a * g - c * d) * inv
    out[2, 2] = (a * e - b * d) * inv
    return True


@njit(**KERNEL_JIT)
def _inv3_vals(a, b, c, d, e, g, h, k, m):
    """:func:`_inv3` of the block ``[[a, b, c], [d, e, g], [h, k, m]]`` given by its entries
    (the same arithmetic): ``ok`` and the nine entries of the inverse by rows."""
    c00 = e * m - g * k
    c01 = -(d * m - g * h)
    c02 = d * k - e * h
    det = a * c00 + b * c01 + c * c02
    if det == 0.0 or not math.isfinite(det):
        return (False, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    inv = 1.0 / det
    return (True, c00 * inv, -(b * m - c * k) * inv, (b * g - c * e) * inv,
            c01 * inv, (a * m - c * h) * inv, -(a * g - c * d) * inv,
            c02 * inv, -(a * k - b * h) * inv, (a * e - b * d) * inv)


@njit(**KERNEL_JIT)
def solve_blocks(Dg, Of, BX, bend, rhs, i0, i1, W, Y, T1, x):
    """Solve the iteration system: block-tridiagonal, or block bandwidth 2 with bending."""
    if bend:
        return block_band_solve(Dg, Of, BX, rhs, i0, i1, Y, T1, x)
    return block_tridiag_solve(Dg, Of, rhs, i0, i1, W, Y, T1, x)


@njit(**KERNEL_JIT)
def block_band_solve(Dg, Of, BX, rhs, i0, i1, Y, T1, x):
    """Block Gaussian elimination (no pivoting between blocks, exact 3x3 inverses) for block
    bandwidth 2: diagonal ``Dg``, first upper ``Of[i]`` (i, i+1), first lower ``Of[i] +
    BX[0, i]`` (i+1, i), second upper ``BX[1, i]`` (i, i+2), second lower ``BX[2, i]``
    (i+2, i).  Scratch ``BX[3:7]``; ``Y`` (n, 3), ``T1`` (3, 3).  Returns -1 or the first
    singular pivot node."""
    Wi = BX[3]
    D = BX[4]
    U1 = BX[5]
    L1 = BX[6]
    n = Dg.shape[0]
    for i in range(i0, i1):
        for a in range(3):
            Y[i, a] = rhs[i, a]
            for b in range(3):
                D[i, a, b] = Dg[i, a, b]
                if i < n - 1:
                    U1[i, a, b] = Of[i, a, b]
                    L1[i, a, b] = Of[i, a, b] + BX[0, i, a, b]
    for k in range(i0, i1):
        if not _inv3(D[k], Wi[k]):
            return k
        for i in (k + 1, k + 2):
            if i >= i1:
                continue
            # M = A_ik W_k
            for a in range(3):
                for b in range(3):
                    s = 0.0
                    for m in range(3):
                        aik = L1[k, a, m] if i == k + 1 else BX[2, k, a, m]
                        s += aik * Wi[k, m, b]
                    T1[a, b] = s
            for a in range(3):
                Y[i, a] -= T1[a, 0] * Y[k, 0] + T1[a, 1] * Y[k, 1] + T1[a, 2] * Y[k, 2]
            for j in (k + 1, k + 2):
                if j >= i1:
                    continue
                for a in range(3):
                    for b in range(3):
                        s = 0.0
                        for m in range(3):
                            akj = U1[k, m, b] if j == k + 1 else BX[1, k, m, b]
                            s += T1[a, m] * akj
                        if i == j:
                            D[i, a, b] -= s
                        elif j == i + 1:
                            U1[i, a, b] -= s
                        else:  # j == i - 1: lower block (i, i-1) stored at L1[i-1]
                            L1[j, a, b] -= s
    for k in range(i1 - 1, i0 - 1, -1):
        for a in range(3):
            s = Y[k, a]
            if k + 1 < i1:
                s -= (U1[k, a, 0] * x[k + 1, 0] + U1[k, a, 1] * x[k + 1, 1]
                      + U1[k, a, 2] * x[k + 1, 2])
            if k + 2 < i1:
                s -= (BX[1, k, a, 0] * x[k + 2, 0] + BX[1, k, a, 1] * x[k + 2, 1]
                      + BX[1, k, a, 2] * x[k + 2, 2])
            T1[0, a] = s
        for a in range(3):
            x[k, a] = Wi[k, a, 0] * T1[0, 0] + Wi[k, a, 1] * T1[0, 1] + Wi[k, a, 2] * T1[0, 2]
    return -1


@njit(**KERNEL_JIT)
def block_tridiag_solve(Dg, Of, rhs, i0, i1, W, Y, T1, x):
    """Solve the block-tridiagonal system on nodes ``i0 .. i1-1`` (3x3 blocks).

    Diagonal blocks ``Dg[i]``, upper blocks ``Of[i]`` (row i, column i+1) and lower blocks
    ``Of[i-1]`` (row i, column i-1): element-assembled matrices have the same coupling block on
    both sides of the diagonal, symmetric or not.  ``W`` (n,3,3), ``Y`` (n,3), ``T1`` (3,3)
    scratch; solution into ``x`` (n,3).  On return ``W[i]`` holds the inverse pivots and ``Y``
    the forward-swept right-hand side (:func:`block_tridiag_resolve` reuses them).
    Returns the first node whose pivot block is singular, or -1.

    Block Gaussian elimination: pivot ``G_i = Dg[i] - Of[i-1] W[i-1] Of[i-1]``, ``W[i] =
    G_i^-1`` (:func:`_inv3_vals`), ``y_i = rhs[i] - Of[i-1] W[i-1] y_i-1``, then the backward
    sweep ``x_i = W[i] (y_i - Of[i] x_i+1)``.  Written out on scalars (the previous pivot's
    inverse and right-hand side carried in locals): every sum keeps the order of the
    loop form, ``p0 + p1 + p2`` (the loop's leading ``0.0 +`` left out: it changes at most
    the sign of a zero, which no later product, sum or quotient by a non-zero pivot carries
    into a non-zero number).
    """
    w00 = w01 = w02 = w10 = w11 = w12 = w20 = w21 = w22 = 0.0
    y0 = y1 = y2 = 0.0
    for i in range(i0, i1):
        g00 = Dg[i, 0, 0]
        g01 = Dg[i, 0, 1]
        g02 = Dg[i, 0, 2]
        g10 = Dg[i, 1, 0]
        g11 = Dg[i, 1, 1]
        g12 = Dg[i, 1, 2]
        g20 = Dg[i, 2, 0]
        g21 = Dg[i, 2, 1]
        g22 = Dg[i, 2, 2]
        r0 = rhs[i, 0]
        r1 = rhs[i, 1]
        r2 = rhs[i, 2]
        if i > i0:
            p = i - 1
            # W[p] y[p]
            z0 = w00 * y0 + w01 * y1 + w02 * y2
            z1 = w10 * y0 + w11 * y1 + w12 * y2
            z2 = w20 * y0 + w21 * y1 + w22 * y2
            o00 = Of[p, 0, 0]
            o01 = Of[p, 0, 1]
            o02 = Of[p, 0, 2]
            o10 = Of[p, 1, 0]
            o11 = Of[p, 1, 1]
            o12 = Of[p, 1, 2]
            o20 = Of[p, 2, 0]
            o21 = Of[p, 2, 1]
            o22 = Of[p, 2, 2]
            # H = W[p] Of[p]
            h00 = w00 * o00 + w01 * o10 + w02 * o20
            h01 = w00 * o01 + w01 * o11 + w02 * o21
            h02 = w00 * o02 + w01 * o12 + w02 * o22
            h10 = w10 * o00 + w11 * o10 + w12 * o20
            h11 = w10 * o01 + w11 * o11 + w12 * o21
            h12 = w10 * o02 + w11 * o12 + w12 * o22
            h20 = w20 * o00 + w21 * o10 + w22 * o20
            h21 = w20 * o01 + w21 * o11 + w22 * o21
            h22 = w20 * o02 + w21 * o12 + w22 * o22
            # G -= Of[p] H ;  y -= Of[p] (W[p] y[p])
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
        Y[i, 0] = r0
        Y[i, 1] = r1
        Y[i, 2] = r2
        y0 = r0
        y1 = r1
        y2 = r2
        ok, w00, w01, w02, w10, w11, w12, w20, w21, w22 = _inv3_vals(
            g00, g01, g02, g10, g11, g12, g20, g21, g22)
        if not ok:
            return i
        W[i, 0, 0] = w00
        W[i, 0, 1] = w01
        W[i, 0, 2] = w02
        W[i, 1, 0] = w10
        W[i, 1, 1] = w11
        W[i, 1, 2] = w12
        W[i, 2, 0] = w20
        W[i, 2, 1] = w21
        W[i, 2, 2] = w22
    # backward sweep: x_i = W[i] (y_i - Of[i] x_i+1), W[n-1] (and y) of the last node still in
    # the locals
    x0 = x1 = x2 = 0.0
    for i in range(i1 - 1, i0 - 1, -1):
        s0 = Y[i, 0]
        s1 = Y[i, 1]
        s2 = Y[i, 2]
        if i < i1 - 1:
            s0 = s0 - Of[i, 0, 0] * x0 - Of[i, 0, 1] * x1 - Of[i, 0, 2] * x2
            s1 = s1 - Of[i, 1, 0] * x0 - Of[i, 1, 1] * x1 - Of[i, 1, 2] * x2
            s2 = s2 - Of[i, 2, 0] * x0 - Of[i, 2, 1] * x1 - Of[i, 2, 2] * x2
        x0 = W[i, 0, 0] * s0 + W[i, 0, 1] * s1 + W[i, 0, 2] * s2
        x1 = W[i, 1, 0] * s0 + W[i, 1, 1] * s1 + W[i, 1, 2] * s2
        x2 = W[i, 2, 0] * s0 + W[i, 2, 1] * s1 + W[i, 2, 2] * s2
        x[i, 0] = x0
        x[i, 1] = x1
        x[i, 2] = x2
    return -1


@njit(**KERNEL_JIT)
def block_tridiag_resolve(Of, rhs, i0, i1, W, Y, x):
    """Solve the system factorised by the last :func:`block_tridiag_solve` (its inverse pivots
    ``W`` and off-diagonal blocks ``Of``, unchanged since) for a new right-hand side ``rhs``:
    the forward and backward sweeps alone, without the pivots.  ``Y`` (n, 3) scratch; solution
    into ``x`` (n, 3)."""
    for i in range(i0, i1):
        for a in range(3):
            Y[i, a] = rhs[i, a]
        if i > i0:
            p = i - 1
            for a in range(3):
                x[p, a] = W[p, a, 0] * Y[p, 0] + W[p, a, 1] * Y[p, 1] + W[p, a, 2] * Y[p, 2]
            for a in range(3):
                Y[i, a] -= Of[p, a, 0] * x[p, 0] + Of[p, a, 1] * x[p, 1] + Of[p, a, 2] * x[p, 2]
    for i in range(i1 - 1, i0 - 1, -1):
        s0 = Y[i, 0]
        s1 = Y[i, 1]
        s2 = Y[i, 2]
        if i < i1 - 1:
            s0 -= Of[i, 0, 0] * x[i + 1, 0] + Of[i, 0, 1] * x[i + 1, 1] + Of[i, 0, 2] * x[i + 1, 2]
            s1 -= Of[i, 1, 0] * x[i + 1, 0] + Of[i, 1, 1] * x[i + 1, 1] + Of[i, 1, 2] * x[i + 1, 2]
            s2 -= Of[i, 2, 0] * x[i + 1, 0] + Of[i, 2, 1] * x[i + 1, 1] + Of[i, 2, 2] * x[i + 1, 2]
        for a in range(3):
            x[i, a] = W[i, a, 0] * s0 + W[i, a, 1] * s1 + W[i, a, 2] * s2
