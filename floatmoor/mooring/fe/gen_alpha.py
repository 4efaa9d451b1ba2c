"""The generalised-alpha integrator of the lumped-mass line (Chung & Hulbert 1993): Newton
iterations on the nodal accelerations of one step.

The integrator sees the line as state (positions, velocities, accelerations of the nodes),
residual and iteration matrix: the line model supplies the nodal forces with their tangent
(:func:`~.forces._line_forces`), the mass blocks (:mod:`.elements`), the force scale of its
convergence tests (:func:`~.forces.force_tolerances`) and, for very stiff elements, the tension
estimates of a mixed displacement-tension iteration (:mod:`.elements`); the matrix is solved by
:mod:`.blocks`.  The scheme's coefficients ``(alpha_m, alpha_f, beta, gamma)`` are data
(``LineParams.coef``, :func:`~.line.gen_alpha_coefficients`).  The advance of a line over a
body step (sub-steps, halving, energy audit) is :func:`~.advance.ga_advance`.
"""

from __future__ import annotations

import math

from numba import njit

from .blocks import block_tridiag_resolve, solve_blocks
from .elements import (
    bar_push,
    release_bars,
    start_tension_estimates,
    update_tension_estimates,
)
from .flat import element_geometry_flat, flat, kinematics_flat, mass_blocks_flat, node_tangents
from .forces import _line_forces, force_tolerances
from .layout import FR_DISPVEL, KERNEL_JIT, S_BEND, S_ZC
from .seabed import friction_decide

# Modified Newton (``LineParams.newton`` 1, see gen_alpha_step): the kept iteration matrix is
# rebuilt when an iteration with it lowers the residual norm by less than this factor.
NEWTON_THETA = 0.25
# bits of the ``newton`` code of LineParams (gen_alpha_step): the kept iteration matrix of the
# modified iteration, the predictor with the fairlead's extrapolated acceleration, and the stop
# on the quadratic-convergence estimate of the next correction
NW_KEEP = 1
NW_PREDICT = 2
NW_QSTOP = 4
# ... and the stop in force terms (the opt-in iteration ``newton: force``): an iterate is
# accepted, with the forces already evaluated, when its force imbalance summed over the free
# nodes, over (1 - alpha_f), is below TENSION_TOL times the weight in air of the line's free
# nodes (or the round-off of the axial forces, whichever is larger); see gen_alpha_step
NW_FORCE = 8
# ... and the predictor of the exact and force-stop iterations: the fairlead's deviation from its
# trapezoidal prediction r + dt (v0 + v1) / 2 (its velocity at both ends is given): exact for a
# fairlead moving with constant acceleration, whatever the nodes' accelerations (see predict)
NW_TRAPEZ = 16
TENSION_TOL = 1e-4


@njit(**KERNEL_JIT)
def predict(dt, beta, mode, rf1, vf1, r, v, a, r1, v1, a1):
    """Predictor of a step of ``dt`` from the state ``r, v, a`` (n, 3): constant accelerations
    of the free nodes, plus the fairlead's deviation from its own constant-velocity prediction
    spread along the line in proportion to the node number (keeps the element lengths nearly
    unchanged: essential for very stiff lines).  With :data:`NW_TRAPEZ` in ``mode`` (the
    exact and force-stop iterations, but not for lines with bending stiffness) the deviation
    from its trapezoidal prediction ``r + dt (v0 + v1) / 2``
    (its velocity ``vf1`` at the end is given): what the nodes' constant accelerations do not
    already carry of a fairlead moving with constant acceleration is then its change of
    acceleration alone, and a rigid translation with constant acceleration is predicted
    exactly; with :data:`NW_PREDICT` (``newton: fast``) the deviation from its
    constant-acceleration prediction with the acceleration of the neighbouring node.  The end
    nodes of ``r1, v1`` take the anchor (at rest) and the fairlead ``rf1, vf1``; ``a1`` of the
    end nodes is zero."""
    n = r.shape[0]
    for i in range(n):
        for k in range(3):
            a1[i, k] = a[i, k] if 0 < i < n - 1 else 0.0
    for k in range(3):
        dev = rf1[k] - (r[n - 1, k] + dt * v[n - 1, k])
        if mode & NW_PREDICT:
            dev -= 0.5 * dt * dt * a[n - 2, k]
        elif mode & NW_TRAPEZ:
            dev -= 0.5 * dt * (vf1[k] - v[n - 1, k])
        for i in range(1, n - 1):
            a1[i, k] += dev * (i / (n - 1.0)) / (beta * dt * dt)
    for k in range(3):
        r1[0, k] = r[0, k]
        v1[0, k] = 0.0
        r1[n - 1, k] = rf1[k]
        v1[n - 1, k] = vf1[k]


@njit(**KERNEL_JIT)
def kinematics(dt, beta, gamma, r, v, a, a1, r1, v1):
    """Positions and velocities of the free nodes at the end of the step from their
    accelerations ``a1`` (Newmark's formulas of the scheme)."""
    # (on the flat views, vectorised: flat.kinematics_flat, the same arithmetic)
    kinematics_flat(dt, beta, gamma, flat(r), flat(v), flat(a), flat(a1), flat(r1), flat(v1))


@njit(**KERNEL_JIT)
def residual(am, af, a, a1, fn, f1, Mb, fresh, Dg, R):
    """Residual ``R = (1-af) f(r1, v1) + af fn - M ((1-am) a1 + am a)`` of the free nodes into
    ``R`` (n, 3) and its squared 2-norm (returned); with ``fresh`` the inertia block
    ``(1-am) M`` is added to the diagonal blocks ``Dg`` of the tangent (the iteration matrix
    ``(1-am) M + cK K + cC C``)."""
    n = a.shape[0]
    res = 0.0
    for i in range(1, n - 1):
        # (1 - am) a1 + am a, once per node
        b0 = (1.0 - am) * a1[i, 0] + am * a[i, 0]
        b1 = (1.0 - am) * a1[i, 1] + am * a[i, 1]
        b2 = (1.0 - am) * a1[i, 2] + am * a[i, 2]
        for k in range(3):
            s = 0.0 + Mb[i, k, 0] * b0 + Mb[i, k, 1] * b1 + Mb[i, k, 2] * b2
            if fresh:
                Dg[i, k, 0] += (1.0 - am) * Mb[i, k, 0]
                Dg[i, k, 1] += (1.0 - am) * Mb[i, k, 1]
                Dg[i, k, 2] += (1.0 - am) * Mb[i, k, 2]
            rk = (1.0 - af) * f1[i, k] + af * fn[i, k] - s
            R[i, k] = rk
            res += rk * rk
    return res


@njit(**KERNEL_JIT)
def imbalance(R):
    """The force imbalance of an iterate: the residual ``R`` (n, 3) of the free nodes summed in
    absolute value (N)."""
    s = 0.0
    for i in range(1, R.shape[0] - 1):
        s += abs(R[i, 0]) + abs(R[i, 1]) + abs(R[i, 2])
    return s


@njit(**KERNEL_JIT)
def correct(da, a1):
    """Apply the Newton correction ``da`` to the accelerations ``a1`` of the free nodes.
    Returns ``(dmax, imax)``: the largest correction component and its node, or ``(-1, i)``
    for a NaN correction at node ``i`` (``a1`` then partly corrected)."""
    n = a1.shape[0]
    dmax = 0.0
    imax = 1
    for i in range(1, n - 1):
        for k in range(3):
            if not math.isfinite(da[i, k]):
                return -1.0, i
            a1[i, k] += da[i, k]
            if abs(da[i, k]) > dmax:
                dmax = abs(da[i, k])
                imax = i
    return dmax, imax


@njit(**KERNEL_JIT)
def _first_nan(f1):
    """The first node of ``f1`` (n, 3) with a NaN or infinite entry, or -1."""
    for i in range(f1.shape[0]):
        for k in range(3):
            if not math.isfinite(f1[i, k]):
                return i
    return -1


@njit(**KERNEL_JIT)
def gen_alpha_step(t1, dt, rf1, vf1, s0, s1, par, w):
    """One generalised-alpha step (Chung & Hulbert 1993) of the free nodes with Newton
    iterations on the accelerations.

    State at ``t1 - dt``: ``s0`` (:class:`~.bundles.LineState`: ``r, v, a`` (n, 3), the nodal
    force ``f``, the friction state ``fs``, whose sliding branch this step decides); fairlead
    (node n-1) position ``rf1`` and velocity ``vf1`` at ``t1``.  ``par``
    (:class:`~.bundles.LineParams`, ``coef = (alpha_m, alpha_f, beta, gamma)``, ``tol`` m,
    ``maxit``); ``w`` (:class:`~.bundles.LineWork`) scratch, element tensions ``w.tens`` and
    ``w.info``.  Trial state at ``t1`` into ``s1.r, s1.v, s1.a, s1.f`` (the caller accepts it;
    ``s1.fs`` is not used).  Residual ``M ((1-am) a1 + am a) - (1-af) f(r1, v1) - af fn``;
    mass blocks from ``r``.

    Stiff elements (:func:`~.elements._stiff`, e.g. the OC3 chain at EA = 3.84e14 N, EA / L0 = 2e13 N/m)
    are handled as in a mixed displacement-tension Newton: every stiff element carries a
    tension estimate (start: its tension at ``t1 - dt``; then the linearised tension
    ``T + dT/dl dl`` of each correction) which gives its geometric stiffness and decides
    whether it is held taut.  A held element in compression is a visco-elastic bar (``c1 eps +
    B ldot / L0``) instead of slack; it is released when its estimate is negative by more than
    the estimate's own second-order error.  Converged: residual below the round-off-aware force
    tolerance and no held element pushing.  Without this, the predictor and every large
    correction leave nanometre compressions (slack, zero tangent) in a taut stiff line and
    Newton never converges.  The residual-increase backtracking is used only for lines without
    stiff elements (for a stiff line the residual rises while Newton converges).  Lines without
    stiff elements take exactly the previous iterations.

    Modified Newton (``par.newton`` 1): the factorised iteration matrix of the first iteration
    of the step (``w.W``, ``w.Of``) is kept for the following iterations (lines without bending
    and stiff elements): such an iteration evaluates the forces without the tangent and solves
    by the forward and backward sweeps alone (:func:`~.blocks.block_tridiag_resolve`); when it lowers
    the residual norm by less than the factor :data:`NEWTON_THETA` it is repeated with a new
    matrix.  The iteration also stops when the error left after a correction, estimated from
    the contraction of the last two corrections ``rho = |d_k| / |d_k-1|`` as
    ``rho / (1 - rho) |d_k|`` (Hairer & Wanner 1996, sec. IV.8), is below ``tol`` (besides the
    tests of the exact iteration).  Each accepted state is within about ``tol`` of the
    converged one by that estimate, but over a run the differences from the exact iteration
    can grow past it: the re-tensioning of a nearly slack line amplifies a tension difference
    of ~1 N about 1e5 times, so in the 12-line flagship storm one lightly loaded line's
    maximum (a snap after its main peak) moves by 4-9 %, while a perturbation made once, e.g.
    of the start positions by tol, moves none by more than 0.0003 % (benchmarks/RESULTS.md);
    hence opt-in.

    Fast exact Newton (``par.newton`` :data:`NW_PREDICT` | :data:`NW_QSTOP`, opt-in): the exact
    iteration from a predictor whose fairlead deviation is taken from the fairlead's
    constant-acceleration prediction (its acceleration that of node ``n - 2``) instead of its
    constant-velocity one, stopped also when the quadratic-convergence estimate of the next
    correction, ``(|d_k| / |d_k-1|)^2 |d_k|``, is below ``tol``.  About one iteration less per
    step; each accepted state is within ``tol`` of the converged one (test_newton_exact), but
    like the modified iteration it leaves a tolerance-level error at every step, which a
    snap load can amplify (benchmarks/RESULTS.md).

    Stop in force terms (``par.newton`` :data:`NW_TRAPEZ` | :data:`NW_FORCE`, the opt-in
    ``newton: force``): after the force evaluation of an iterate, the iteration stops when the
    force imbalance of the free nodes summed in absolute value, over ``1 - alpha_f``, is below
    ``TENSION_TOL`` (1e-4) times the weight in air of the free nodes (at least the round-off of
    the axial forces summed over the residual components), and no held element pushes by more;
    the iterate is accepted with its forces (no further evaluation), from the predictor with
    the fairlead's trapezoidal prediction (:func:`predict`; in the flagship storm the first
    iterate's largest nodal imbalance is ~0.7 kN against ~9 kN from the constant-velocity one,
    and most steps stop at the second force evaluation).  By the force balance of the free nodes this is the order of
    the step's error in the fairlead and anchor forces (quasi-static transmission of the
    imbalance along the line): 226 N on a 2.3 MN Floatel-like line, 70 N on the OC3 line; its
    effect on a storm's per-line statistics is measured in benchmarks/RESULTS.md.  The stop
    holds only for an iterate whose elements are all taut (:func:`all_taut`): a slack element
    has no stiffness, so there the force balance does not bound the positions, and Newton can
    stagnate at the slack / taut switches where no force tolerance is met (the OC3 line's
    8 m / 6 s snap at 0.5 s steps found no convergence in 30 iterations at a 1/64 s sub-step
    without this guard); an iterate with a slack element is judged by the exact iteration's
    stops below (a position stop then evaluates the accepted state once more).  Nor does it
    accept the predictor itself: at least one correction is made, as before the exact
    iteration's residual stop (accepting a balanced predictor, a taut fibre rope created energy
    until the energy audit stopped it: tests/mooring/fe/test_newton_force.py; lines with
    bending stiffness do not take this iteration, :meth:`~.line.FELine.start`).  Not the
    default: in the surge decay of the Floatel-like semi (tests/solvers/test_time_domain_fe.py)
    a leeward line's fairlead tension differs from the converged iteration's by up to 11 kN at
    900 kN (2.6 kN with a tolerance 100 times tighter), far above the bound above: the stop's
    ~0.1 mm state error is amplified by a touchdown node bouncing on the seabed, a rattle in
    which a 1e-5 change of the input moves the exact iteration by 6.7 kN
    (benchmarks/RESULTS.md).  Without
    :data:`NW_FORCE` the iteration stops on the position correction (``tol``, m) as described
    above (``newton: exact``) and evaluates the accepted state once more.

    Returns the number of Newton iterations (> 0), or -1 (no convergence: ``info[1]`` = node
    with the largest correction), -2 (singular iteration matrix at node ``info[1]``), -3 (NaN).
    """
    r, v, a, fn, fs = s0
    r1 = s1.r
    v1 = s1.v
    a1 = s1.a
    f1 = s1.f
    P = par.P
    E = par.E
    S = par.S
    coef = par.coef
    tol = par.tol
    maxit = par.maxit
    tens = w.tens
    Of = w.Of
    da = w.dx
    info = w.info
    # element activity (> 0: taut by the tension estimate of the iteration)
    act = w.act
    am = coef[0]
    af = coef[1]
    beta = coef[2]
    gamma = coef[3]
    bend = S[S_BEND] > 0.0
    ftol, fcap, weight, rfloor = force_tolerances(r, P, E)
    nstiff = start_tension_estimates(r, v, P, E, act)
    # node mass blocks from the element geometry of the start state (elements._node_mass_el on
    # the flat views: the same numbers)
    element_geometry_flat(flat(r), flat(w.el))
    node_tangents(w.el, w.q)
    mass_blocks_flat(flat(P), flat(w.q), flat(w.Mb))
    mode = par.newton
    predict(dt, beta, mode, rf1, vf1, r, v, a, r1, v1, a1)
    cK = (1.0 - af) * beta * dt * dt
    cC = (1.0 - af) * gamma * dt
    if par.fric == FR_DISPVEL:
        kinematics(dt, beta, gamma, r, v, a, a1, r1, v1)
        friction_decide(r1, v1, par.fric, fs, S[S_ZC])
    it = 0
    conv = False
    res_prev = math.inf
    alpha = 1.0
    # converged on the residual of the current iterate: its forces are those of the state
    by_res = False
    # modified Newton: keep the iteration matrix while it is the one of this step size; only
    # without bending (band solver) and stiff elements (whose tension estimate reads the
    # element blocks of the current iterate)
    modified = (mode & NW_KEEP) > 0
    # stop in force terms: the largest imbalance accepted, times (1 - af)
    by_force = (mode & NW_FORCE) > 0
    ttol = max(TENSION_TOL * weight, rfloor)
    reuse = modified and nstiff == 0 and not bend
    fresh = True
    dprev = 0.0
    while it < maxit:
        it += 1
        kinematics(dt, beta, gamma, r, v, a, a1, r1, v1)
        # (with no stiff element no element is managed by the estimate: use_act False skips
        # the per-element test, same bits)
        _line_forces(r1, v1, fs, par, bool(fresh), cK, cC, f1, w, nstiff > 0)
        # largest push of an element held as a bar in compression
        fbar = bar_push(act, tens) if nstiff > 0 else 0.0
        res = residual(am, af, a, a1, fn, f1, w.Mb, fresh, w.Dg, w.R)
        if not math.isfinite(res):
            info[1] = 1
            return -3
        if not fresh and it > 1 and res > NEWTON_THETA * NEWTON_THETA * res_prev:
            # the kept matrix lowered the residual too little: this iterate again with a new one
            fresh = True
            it -= 1
            continue
        if res > res_prev and alpha > 1.0 / 1024.0 and nstiff == 0:
            # the last correction raised the residual (a node jumping across the seabed
            # contact, a slack element): go back half of it
            alpha *= 0.5
            _back(alpha, da, a1)
            continue
        alpha = 1.0
        res_prev = res
        # the force stop holds for an iterate whose elements are all taut; with a slack one
        # the iterate is judged by the exact iteration's stops
        fstop = by_force and all_taut(tens)
        if fstop:
            if it > 1 and imbalance(w.R) <= (1.0 - af) * ttol and fbar <= ttol:
                # the iterate's forces balance to the tolerance (after at least one
                # correction, as the residual stop of the exact iteration): it is the state
                conv = True
                by_res = True
                break
        elif it > 1 and math.sqrt(res) <= ftol and fbar <= ftol:
            # residual below ftol (N): converged even if a contact or slack kink keeps the
            # position corrections from settling
            conv = True
            by_res = True
            break
        if fresh:
            bad = solve_blocks(w.Dg, Of, w.BX, bend, w.R, 1, r.shape[0] - 1, w.W, w.Y, w.T1, da)
            if bad >= 0:
                info[1] = bad
                return -2
            fresh = not reuse
        else:
            block_tridiag_resolve(Of, w.R, 1, r.shape[0] - 1, w.W, w.Y, da)
        if nstiff > 0:
            # tension estimate of the next iterate (elements.update_tension_estimates)
            update_tension_estimates(r1, da, beta * dt * dt, cK, P, E, Of, tens, act)
        dmax, imax = correct(da, a1)
        info[1] = imax
        if dmax < 0.0:
            return -3
        # a displacement correction beta dt^2 da below tol (m) ends the iteration if the
        # residual is also below 1e-2 node weights (for very stiff lines a tiny correction can
        # still leave a large axial force imbalance)
        if fstop:
            dprev = dmax
            continue
        if dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap and fbar <= fcap:
            conv = True
            break
        if (mode & NW_QSTOP) and not modified and 0.0 < dmax < dprev:
            # quadratic convergence, |d_k+1| ~ C |d_k|^2 with C from the last two corrections:
            # the next correction (the error left) is about rho^2 |d_k|
            rho = dmax / dprev
            if (rho * rho * dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap
                    and fbar <= fcap):
                conv = True
                break
        if modified and 0.0 < dmax < dprev:
            # error left after this correction, estimated from the contraction of the last two
            rho = dmax / dprev
            if (rho / (1.0 - rho) * dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap
                    and fbar <= fcap):
                conv = True
                break
        dprev = dmax
    if not conv:
        return -1
    kinematics(dt, beta, gamma, r, v, a, a1, r1, v1)
    # forces of the accepted state with the law of the converged iteration (a held element
    # keeps its damping; a bar push is below the tolerance): consistent with the residual.
    # Converged on the residual, the state is the last iterate's (the same a1, so the same
    # r1 and v1 to the bit) and f1, w.tens, w.q are already its forces: not evaluated again.
    if not by_res:
        _line_forces(r1, v1, fs, par, bool(False), cK, cC, f1, w, nstiff > 0)  # noqa: UP018
    release_bars(act, tens)
    bad = _first_nan(f1)
    if bad >= 0:
        info[1] = bad
        return -3
    return it


@njit(**KERNEL_JIT)
def all_taut(tens):
    """True when every element tension of the iterate is positive (no slack element, no
    held bar in compression): the condition of the force stop."""
    for j in range(tens.shape[0]):
        if not tens[j] > 0.0:
            return False
    return True


@njit(**KERNEL_JIT)
def _back(alpha, da, a1):
    """Take back the part ``alpha`` of the last correction ``da`` (residual-increase
    backtracking)."""
    for i in range(1, a1.shape[0] - 1):
        for k in range(3):
            a1[i, k] -= alpha * da[i, k]
