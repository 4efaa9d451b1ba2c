"""Static equilibrium of one line: damped Newton (Levenberg-Marquardt) on the free nodes, with
an optional trust radius on the nodal moves (:func:`static_newton`)."""

from __future__ import annotations

import math

from numba import njit

from .blocks import solve_blocks
from .forces import line_forces
from .layout import EL_L0, NP_W, S_BEND


@njit(cache=True)
def static_newton(r, v0, fs, par, f, w, max_step=0.0):
    """Damped Newton (Levenberg-Marquardt) for the static equilibrium of the free nodes
    (1 .. n-2); the end nodes stay where they are.  ``v0`` zero velocities (n, 3); ``fs``
    friction state, ``par`` (:class:`~.bundles.LineParams`: static axial law in ``E``,
    friction code ``fric``, tolerance ``tol`` (N) and ``maxit``), nodal forces into ``f``,
    scratch ``w`` (:class:`~.bundles.LineWork`, element tensions ``w.tens``).

    A step ``(K + lam I) dx = f`` is accepted when it lowers the 2-norm of the nodal residual;
    ``lam`` (N/m) starts at 0 (pure Newton), grows by 10 from the weight of a node over its
    element length when a step fails and falls by 10 after a success.

    ``max_step`` > 0 (m; default 0: off, the iteration above exactly) adds a trust radius on
    the largest nodal move: a step longer than the radius is scaled down to it along its
    direction; a failed step quarters the radius (down to ``1e-3 max_step``, below which the
    damping ``lam`` takes over as above) and an accepted scaled step doubles it.  For lines
    with very soft modes (a grounded chain pushed sideways by current: 15-24 N/m against the
    damping floor of ~1e3 N/m) the damped steps hardly move along those modes, while a
    shortened Newton step does (:class:`~.current_statics.LineCurrentStatics`).

    ``info[0]`` iterations, ``info[1]`` final max residual (N), ``info[2]`` node with the
    largest residual.  Returns 0 when converged (max nodal residual < ``tol`` N), -1 when not,
    -2 singular tangent (``info[2]`` = node).
    """
    P = par.P
    E = par.E
    S = par.S
    tol = par.tol
    maxit = par.maxit
    Dg = w.Dg
    Of = w.Of
    BX = w.BX
    W = w.W
    Y = w.Y
    T1 = w.T1
    dx = w.dx
    rtry = w.rtry
    info = w.info
    n = r.shape[0]
    lam_min = 0.0
    for i in range(n):
        lam_min = max(lam_min, abs(P[i, NP_W]))
    lam_min /= max(E[0, EL_L0], 1e-12)
    jac = bool(True)  # noqa: UP018 (a plain boolean, not a literal: see line_forces)
    line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
    res2 = _res2(f, n)
    lam = 0.0
    it = 0
    radius = max_step
    trust = False
    while it < maxit:
        info[0] = it
        info[1] = _max_res(f, n)
        if info[1] < tol:
            break
        it += 1
        if lam > 0.0:
            for i in range(1, n - 1):
                for a in range(3):
                    Dg[i, a, a] += lam
        bad = solve_blocks(Dg, Of, BX, S[S_BEND] > 0.0, f, 1, n - 1, W, Y, T1, dx)
        if bad >= 0:
            if lam == 0.0:
                lam = lam_min
                line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
                continue
            info[2] = bad
            return -2
        trust = max_step > 0.0 and radius > 1e-6 * max_step
        scaled = _limit_step(dx, n, radius) if trust else False
        for i in range(n):
            for a in range(3):
                rtry[i, a] = r[i, a] + (dx[i, a] if 0 < i < n - 1 else 0.0)
        line_forces(rtry, v0, fs, par, jac, 1.0, 0.0, f, w)
        r2 = _res2(f, n)
        if r2 < res2 or _max_res(f, n) < tol:
            for i in range(n):
                for a in range(3):
                    r[i, a] = rtry[i, a]
            res2 = r2
            lam = lam / 10.0 if lam > 100.0 * lam_min else 0.0
            if scaled:
                radius *= 2.0
        elif trust:
            radius = 0.25 * min(radius, _max_move(dx, n))
            line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
        else:
            lam = lam_min if lam == 0.0 else 10.0 * lam
            if lam > 1e30:
                break
            line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
    line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
    info[0] = it
    info[1] = _max_res(f, n)
    worst = 1
    for i in range(1, n - 1):
        if (abs(f[i, 0]) + abs(f[i, 1]) + abs(f[i, 2])
                > abs(f[worst, 0]) + abs(f[worst, 1]) + abs(f[worst, 2])):
            worst = i
    info[2] = worst
    return 0 if info[1] < tol else -1


@njit(cache=True)
def _max_move(dx, n):
    m = 0.0
    for i in range(1, n - 1):
        m = max(m, dx[i, 0] * dx[i, 0] + dx[i, 1] * dx[i, 1] + dx[i, 2] * dx[i, 2])
    return math.sqrt(m)


@njit(cache=True)
def _limit_step(dx, n, radius):
    """Scale the free nodes' moves ``dx`` so that the largest is at most ``radius`` (m);
    True when scaled."""
    m = _max_move(dx, n)
    if not m > radius:
        return False
    c = radius / m
    for i in range(1, n - 1):
        for a in range(3):
            dx[i, a] *= c
    return True


@njit(cache=True)
def _res2(f, n):
    m = 0.0
    for i in range(1, n - 1):
        for a in range(3):
            m += f[i, a] * f[i, a]
    return m if math.isfinite(m) else math.inf


@njit(cache=True)
def _max_res(f, n):
    m = 0.0
    for i in range(1, n - 1):
        for a in range(3):
            if not math.isfinite(f[i, a]):
                return math.inf
            if abs(f[i, a]) > m:
                m = abs(f[i, a])
    return m
