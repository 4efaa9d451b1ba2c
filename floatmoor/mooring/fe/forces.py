"""Nodal forces of the lumped-mass line and their tangent: the element pass
(:mod:`.elements`), bending, the fluid loads (:mod:`.fluid`) and seabed contact and friction
(:mod:`.seabed`), in that order, into preallocated arrays; and the force scale of the line
that the iterations use as their tolerance.

Tangent: ``K = -df/dx`` and ``C = -df/dv``; element blocks are exact for the axial force, the
drag, seabed and friction blocks are nodal (the dependence of the node tangents and of the
seabed axes on the positions is left out: a quasi-Newton iteration that still converges
quadratically for the dominant axial stiffness).
"""

from __future__ import annotations

import math

from numba import njit

from .elements import _tangents_from, bending_forces, element_forces, element_geometry
from .fibre_law import EL_LAW
from .flat import (
    block_sums,
    c_contiguous,
    current_speeds,
    element_geometry_flat,
    element_pass,
    element_pass_jac,
    flat,
    fluid_pass,
    fluid_pass_jac,
    node_sums,
    node_tangents,
)
from .fluid import fluid_forces
from .layout import EL_C1, EL_L0, EPS_MACH, KERNEL_JIT, NP_KC, NP_MASS, NP_W, S_BEND, S_CURC, S_CURS
from .seabed import seabed_forces


@njit(**KERNEL_JIT)
def line_forces(r, v, fs, par, want_jac, cK, cC, f, w):
    """Nodal forces of the line and (optionally) the combined tangent ``cK K + cC C``.

    Parameters
    ----------
    r, v : (n, 3) node positions (m) and velocities (m/s), earth axes.
    fs : (n, N_FS) friction state of the last accepted step (read only;
        :func:`~.seabed.friction_decide` and :func:`~.seabed.friction_commit` update it).
    par : :class:`~.bundles.LineParams`: node parameters ``P``, element parameters ``E``,
        scalars ``S``, current profile ``cur_z, cur_u`` (levels increasing, speeds m/s;
        direction in ``S``), wave particle velocity (m/s) and acceleration (m/s^2) at the nodes
        ``wk`` (n, 6) (zeros without waves; the velocity enters the drag, the acceleration the
        fluid inertia), friction code ``fric``.
    want_jac : bool; cK, cC : weights of the tangent.
    f : (n, 3) output, total force on every node (N).
    w : :class:`~.bundles.LineWork`: ``q`` node tangents on return, ``tens`` (n-1,) element
        tensions (N); ``Dg`` (n, 3, 3), ``Of`` (n-1, 3, 3) outputs (overwritten): diagonal and
        upper off-diagonal blocks of ``cK K + cC C`` (element blocks: the lower block equals
        the upper one); ``BX`` (7, n, 3, 3): with bending (``S[S_BEND] > 0``) ``BX[0]``
        lower-minus-upper correction of the first off-diagonal, ``BX[1]`` / ``BX[2]`` the
        upper / lower second off-diagonal blocks (overwritten); ``BX[3:7]`` solver scratch.
    """
    # the flags as plain booleans: numba types a constant argument True / False as a literal
    # and compiles the large force kernel once per literal value (three times over in a coupled
    # FE storm's first run, 3-8 s each); callers pass bool(...) for the same reason
    _line_forces(r, v, fs, par, bool(want_jac), cK, cC, f, w, bool(False))  # noqa: UP018


@njit(**KERNEL_JIT)
def _line_forces(r, v, fs, par, want_jac, cK, cC, f, w, use_act):
    """:func:`line_forces`; with ``use_act``, ``w.act`` (n-1,) holds a tension estimate of
    every element (N, see :func:`~.gen_alpha.gen_alpha_step`): an element in compression with
    a positive estimate acts as a bar, ``T = c1 eps`` (negative) with its axial tangent,
    instead of ``T = 0``, and the geometric stiffness of every element is ``max(act, 0) / l``.
    """
    S = par.S
    P = par.P
    E = par.E
    kind = flat_kind(P, E, par.wk, par.cur_z)
    # the flat views need C-contiguous arrays (the bundles' arrays are: numba types them so and
    # these tests are then constants)
    contig = (c_contiguous(r) and c_contiguous(v) and c_contiguous(f) and c_contiguous(P)
              and c_contiguous(E) and c_contiguous(par.wk) and c_contiguous(w.el)
              and c_contiguous(w.q) and c_contiguous(w.Of) and c_contiguous(w.Dg)
              and c_contiguous(w.tens))
    if contig and (kind & 1) and not use_act and not (want_jac and cC == 0.0):
        # the element passes vectorised across the elements (flat.py, the same bits); not for
        # the tension estimates of stiff elements nor the static tangent
        el = flat(w.el)
        element_geometry_flat(flat(r), el)
        node_tangents(w.el, w.q)
        vf = flat(v)
        Pf = flat(P)
        Ef = flat(E)
        if want_jac:
            Of = flat(w.Of)
            element_pass_jac(vf, Pf, Ef, el, cK, cC, w.tens, Of)
            block_sums(Of, flat(w.Dg))
        else:
            element_pass(vf, Pf, Ef, el, w.tens)
        node_sums(Pf, el, w.tens, flat(f))
    else:
        # element directions and lengths once, the node tangents from them
        element_geometry(r, w.el)
        _tangents_from(w.el, w.q)
        element_forces(v, fs, P, E, S, w.el, want_jac, cK, cC, use_act, w.act, w.tens, f,
                       w.Dg, w.Of)
    # bending (pinned ends): discrete elastica energy c_i (1 - e_a . e_b) at interior nodes
    if S[S_BEND] > 0.0:
        bending_forces(r, par.P, f, want_jac, cK, w.Dg, w.Of, w.BX)
    if contig and c_contiguous(w.uc) and (kind & 2):
        current_speeds(r, par.cur_z, par.cur_u, w.uc)
        qf = flat(w.q)
        vf = flat(v)
        Pf = flat(P)
        wkf = flat(par.wk)
        if want_jac:
            fluid_pass_jac(vf, qf, Pf, w.uc, S[S_CURC], S[S_CURS], wkf, cC, flat(f),
                           flat(w.Dg))
        else:
            fluid_pass(vf, qf, Pf, w.uc, S[S_CURC], S[S_CURS], wkf, flat(f))
    else:
        fluid_forces(r, v, w.q, P, S, par.cur_z, par.cur_u, par.wk, want_jac, cC, f, w.Dg)
    seabed_forces(r, v, w.q, fs, par.P, S, par.fric, want_jac, cK, cC, f, w.Dg)


@njit(**KERNEL_JIT)
def flat_kind(P, E, wk, cur_z):
    """Which passes of :mod:`.flat` a line's force evaluation can take: bit 1 the element
    passes (no element with a fibre law), bit 2 the fluid passes (no clump drag, no wave
    accelerations at the nodes)."""
    fib = False
    for j in range(E.shape[0]):
        fib = fib | (E[j, EL_LAW] != 0.0)
    other = False
    for i in range(P.shape[0]):
        other = other | (P[i, NP_KC] > 0.0) | (wk[i, 3] != 0.0) | (wk[i, 4] != 0.0) \
            | (wk[i, 5] != 0.0)
    return (0 if fib else 1) | (0 if other else 2)


@njit(**KERNEL_JIT)
def force_tolerances(r, P, E):
    """Force scale of the line for the iteration's convergence tests:
    ``(ftol, fcap, weight, rfloor)`` (N).

    ``ftol``: the largest node weight (in air if the net weight vanishes) times 1e-5, but not
    below the round-off of the axial forces: an element tension ``c1 (l / L0 - 1)`` carries the
    relative error of ``l / L0`` (~ 1 ulp, plus the coordinates' round-off ``|r| eps / L0``),
    which is several N for ``c1 = 3.84e14`` N; summed over the ``3 (n - 2)`` residual
    components.  ``fcap``: the weight-based bound of the residual when the position correction
    is below the position tolerance (1e3 ``ftol``, at least the round-off bound).  ``weight``:
    the weight in air of the free nodes (the scale of the force-terms stop of
    :func:`~.gen_alpha.gen_alpha_step`); ``rfloor``: the round-off of the axial forces summed
    over the ``3 (n - 2)`` residual components (below it no residual can be told from zero)."""
    n = r.shape[0]
    ftol = 0.0
    rmax = 0.0
    weight = 0.0
    for i in range(n):
        ftol = max(ftol, 1e-5 * abs(P[i, NP_W]), 1e-5 * 9.80665 * P[i, NP_MASS])
        for k in range(3):
            rmax = max(rmax, abs(r[i, k]))
        if 0 < i < n - 1:
            weight += 9.80665 * P[i, NP_MASS]
    fround = 0.0
    for j in range(n - 1):
        fround = max(fround, E[j, EL_C1] * EPS_MACH * (2.0 + 2.0 * rmax / E[j, EL_L0]))
    fcap = max(1e3 * ftol, math.sqrt(3.0 * n) * fround)
    ftol = max(ftol, math.sqrt(3.0 * n) * fround)
    return ftol, fcap, weight, 3.0 * (n - 2) * fround
