"""Numba kernels of the frequency-domain line model: the block-tridiagonal complex solve of the
linearised lumped-mass line for every frequency, the spectral moments, and the quadrature of the
normal-plane drag linearisation (no allocation inside the loops)."""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def _inv3(A, out):
    """Inverse of a complex 3x3 matrix (cofactors); returns False when singular."""
    a, b, c = A[0, 0], A[0, 1], A[0, 2]
    d, e, f = A[1, 0], A[1, 1], A[1, 2]
    g, h, k = A[2, 0], A[2, 1], A[2, 2]
    c00 = e * k - f * h
    c01 = f * g - d * k
    c02 = d * h - e * g
    det = a * c00 + b * c01 + c * c02
    if det == 0:
        return False
    out[0, 0] = c00 / det
    out[1, 0] = c01 / det
    out[2, 0] = c02 / det
    out[0, 1] = (c * h - b * k) / det
    out[1, 1] = (a * k - c * g) / det
    out[2, 1] = (b * g - a * h) / det
    out[0, 2] = (b * f - c * e) / det
    out[1, 2] = (c * d - a * f) / det
    out[2, 2] = (a * e - b * d) / det
    return True


@njit(cache=True)
def line_transfer(omega, M, C, K, Ko, Co, X, D, G, T1, T2, Up):
    """Node displacements per unit fairlead displacement.

    The unknowns are the interior nodes ``1 .. n-2`` (index ``i - 1``); node 0 (anchor) is fixed
    and node ``n-1`` (fairlead) moves with a unit displacement along each earth axis.

    ``M, C, K`` (n, 3, 3): nodal mass, damping and stiffness blocks (real; fixed DOFs have a
    unit stiffness and zero rows and columns elsewhere); ``Ko, Co`` (n-1, 3, 3): the
    element blocks (stiffness, damping) coupling node ``j`` and ``j+1``: the off-diagonal block
    of the dynamic matrix is ``-(Ko[j] + i w Co[j])``.  ``X`` (n_w, n, 3, 3) complex out:
    ``X[k, i, :, d]`` the displacement of node ``i`` for a unit fairlead displacement along
    ``d`` (rows 0 and n-1: zero and identity).  ``D, G`` (n, 3, 3), ``T1, T2, Up`` (3, 3):
    complex scratch.  Returns -1, or the index of the frequency where a block was singular.
    """
    nw = omega.shape[0]
    n = M.shape[0]
    for kw in range(nw):
        w = omega[kw]
        w2 = w * w
        # forward elimination: D_i = A_ii - U_{i-1}^T G_{i-1}, G_i = D_i^-1 U_i
        for i in range(1, n - 1):
            for a in range(3):
                for b in range(3):
                    D[i, a, b] = -w2 * M[i, a, b] + K[i, a, b] + 1j * w * C[i, a, b]
            for a in range(3):
                for b in range(3):
                    # U_i = -(Ko + i w Co)[i]: coupling of node i to node i+1
                    T2[a, b] = -(Ko[i, a, b] + 1j * w * Co[i, a, b])
            if i > 1:
                for a in range(3):
                    for b in range(3):
                        s = 0j
                        for c in range(3):
                            # U_{i-1}^T G_{i-1} (Up still holds U_{i-1})
                            s += Up[c, a] * G[i - 1, c, b]
                        D[i, a, b] -= s
            for a in range(3):
                for b in range(3):
                    Up[a, b] = T2[a, b]
            if not _inv3(D[i], T1):
                return kw
            if i < n - 2:
                for a in range(3):
                    for b in range(3):
                        s = 0j
                        for c in range(3):
                            s += T1[a, c] * Up[c, b]
                        G[i, a, b] = s
            else:
                # last interior node: the fairlead enters the right-hand side
                # D x = -(A_{i, n-1}) I = (Ko + i w Co)[n-2]
                for a in range(3):
                    for b in range(3):
                        s = 0j
                        for c in range(3):
                            s += -T1[a, c] * Up[c, b]
                        X[kw, i, a, b] = s
        # back substitution: x_i = -G_i x_{i+1}
        for i in range(n - 3, 0, -1):
            for a in range(3):
                for b in range(3):
                    s = 0j
                    for c in range(3):
                        s += G[i, a, c] * X[kw, i + 1, c, b]
                    X[kw, i, a, b] = -s
        for a in range(3):
            for b in range(3):
                X[kw, 0, a, b] = 0.0
                X[kw, n - 1, a, b] = 1.0 if a == b else 0.0
    return -1


@njit(cache=True)
def spectral_moments(X, Sx, e, gain, wt, w2, base, tr, S_T, var_T, cov_v):
    """Element tensions and node velocity covariances from the transfer functions.

    ``X`` (n_w, n, 3, 3) node transfer (see :func:`line_transfer`); ``Sx`` (n_w, 3, 3) fairlead
    cross-spectrum; ``e`` (n-1, 3) element directions; ``gain`` (n_w, n-1) complex tension per
    unit elongation (``dT/dl + i w B / L0``); ``wt`` trapezoidal weights; ``w2 = omega^2``;
    elements below ``base`` are left at zero.  Out: ``tr`` (n_w, n-1, 3) tension transfer,
    ``S_T`` (n_w, n-1) tension spectra, ``var_T`` (n-1,) variances, ``cov_v`` (n, 3, 3) node
    velocity covariances (real part of the integral of ``w^2 X Sx X^H``)."""
    nw = X.shape[0]
    n = X.shape[1]
    for j in range(n - 1):
        var_T[j] = 0.0
    for i in range(n):
        for a in range(3):
            for b in range(3):
                cov_v[i, a, b] = 0.0
    Y = np.zeros((3, 3), dtype=np.complex128)
    for kw in range(nw):
        for j in range(n - 1):
            if j < base:
                for d in range(3):
                    tr[kw, j, d] = 0.0
                S_T[kw, j] = 0.0
                continue
            for d in range(3):
                s = 0j
                for a in range(3):
                    s += e[j, a] * (X[kw, j + 1, a, d] - X[kw, j, a, d])
                tr[kw, j, d] = gain[kw, j] * s
            acc = 0.0
            for d in range(3):
                s = 0j
                for f in range(3):
                    s += tr[kw, j, f] * Sx[kw, f, d]
                acc += (s * tr[kw, j, d].conjugate()).real
            S_T[kw, j] = acc
            var_T[j] += wt[kw] * acc
        c = wt[kw] * w2[kw]
        for i in range(n):
            for a in range(3):
                for d in range(3):
                    s = 0j
                    for f in range(3):
                        s += X[kw, i, a, f] * Sx[kw, f, d]
                    Y[a, d] = s
            for a in range(3):
                for b in range(3):
                    s = 0j
                    for d in range(3):
                        s += Y[a, d] * X[kw, i, b, d].conjugate()
                    cov_v[i, a, b] += c * s.real


@njit(cache=True)
def drag_2d(k, mean, cov, xl, wl, xh, wh, span, out):
    """Linearised normal-plane drag damping ``k E[|u| I + u u^T / |u|]`` (n, 2, 2) into ``out``
    for Gaussian 2-vectors ``u`` with means ``mean`` (n, 2) and covariances ``cov`` (n, 2, 2).

    In the principal axes of the covariance (closed-form 2x2 eigen-decomposition): along the
    major axis the Gauss-Legendre rule ``xl, wl`` on ``[-span, c]`` and ``[c, span]`` (``c``
    the kink at ``u = 0``, standard normal weight applied), along the minor axis the
    Gauss-Hermite rule ``xh, wh`` (probabilists', normalised)."""
    n = mean.shape[0]
    c_norm = 1.0 / np.sqrt(2.0 * np.pi)
    for i in range(n):
        a = cov[i, 0, 0]
        c = cov[i, 1, 1]
        b = 0.5 * (cov[i, 0, 1] + cov[i, 1, 0])
        hd = 0.5 * (a - c)
        rad = np.sqrt(hd * hd + b * b)
        mid = 0.5 * (a + c)
        s1 = np.sqrt(max(mid + rad, 0.0))     # major
        s2 = np.sqrt(max(mid - rad, 0.0))     # minor
        if rad > 0.0:
            th = 0.5 * np.arctan2(2.0 * b, a - c)
            v1x, v1y = np.cos(th), np.sin(th)
        else:
            v1x, v1y = 0.0, 1.0
        v0x, v0y = -v1y, v1x
        m1 = v1x * mean[i, 0] + v1y * mean[i, 1]
        m0 = v0x * mean[i, 0] + v0y * mean[i, 1]
        kink = -m1 / s1 if s1 > 0.0 else 0.0
        kink = min(max(kink, -span), span)
        e_r = 0.0
        a11 = 0.0
        a22 = 0.0
        a12 = 0.0
        for half in range(2):
            lo = -span if half == 0 else kink
            hi = kink if half == 0 else span
            h = 0.5 * (hi - lo)
            cen = 0.5 * (hi + lo)
            for q in range(xl.shape[0]):
                x = cen + h * xl[q]
                w1 = h * wl[q] * np.exp(-0.5 * x * x) * c_norm
                u1 = m1 + s1 * x
                for p in range(xh.shape[0]):
                    u2 = m0 + s2 * xh[p]
                    w = w1 * wh[p]
                    r = np.sqrt(u1 * u1 + u2 * u2)
                    e_r += w * r
                    if r > 0.0:
                        a11 += w * u1 * u1 / r
                        a22 += w * u2 * u2 / r
                        a12 += w * u1 * u2 / r
        # principal axes: minor (index 0) and major (index 1); C = V Cp V^T, V = [v0 v1]
        p00 = e_r + a22
        p11 = e_r + a11
        out[i, 0, 0] = k[i] * (v0x * v0x * p00 + 2.0 * v0x * v1x * a12 + v1x * v1x * p11)
        out[i, 1, 1] = k[i] * (v0y * v0y * p00 + 2.0 * v0y * v1y * a12 + v1y * v1y * p11)
        out[i, 0, 1] = k[i] * (v0x * v0y * p00 + (v0x * v1y + v1x * v0y) * a12
                               + v1x * v1y * p11)
        out[i, 1, 0] = out[i, 0, 1]
