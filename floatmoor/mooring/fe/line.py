"""FE (lumped-mass) mooring line: arrays from the configuration, statics from the catenary start,
and a stepping interface a floater time-domain solver can call.

Coupling interface (for the body solver): ::

    line = FELine(spec)
    line.solve_static()                 # equilibrium at the initial fairlead position
    line.start()                        # generalised-alpha, rho_inf = 0.7
    for each body step t -> t + dt:
        F = line.advance(t + dt, dt, r_fair(t + dt), v_fair(t + dt))   # trial, N (3,)
        ... (the body solver may call advance again with new fairlead kinematics: every call
             restarts from the last accepted state)
        line.accept()                   # commit the trial state

``F`` is the force of the line on the fairlead point in earth axes (pulls towards the anchor and
down).  ``advance`` sub-steps the line (``substeps``) with the fairlead moving linearly between
the accepted and the new position when the body step is larger than the line can take, and
splits a step by itself (up to 2^5 times) where Newton does not converge.  For several lines on
one body, :class:`floatmoor.mooring.fe.body.FEMooring` takes the body pose and velocity and
returns the 6-DOF generalised force.

The trial state is changed only through the line's methods: :meth:`FELine.advance` (or
:meth:`FELine.trial` after a kernel that advanced several lines' :attr:`FELine.bundle` at
once), :meth:`FELine.accept` and :meth:`FELine.reject`; :attr:`FELine.failure` and
:meth:`FELine.step_error` describe a failed step.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace

import numpy as np

from ...core.errors import ConvergenceError, FloatmoorWarning, NumericalError
from ..catenary import line_profile, solve_line
from . import kernels as K
from .bundles import LineBundle, LineParams, LineState, new_state, new_work
from .config import FRICTION_MODELS, FELineSpec
from .fibre_law import (
    DEFAULT_TIME_CONSTANT,
    EL_FIB,
    EL_LAW,
    FS_KD,
    LAW_TWO_COMPONENT,
    LAW_WORKING,
    capped_record,
    fibre_record,
    fibre_start,
    max_dynamic_stiffness,
    working_tension,
)

__all__ = ["FELine", "StaticSolution", "gen_alpha_coefficients", "FIBRE_LAWS", "NEWTON_MODES"]

FIBRE_LAWS = ("two_component", "working_curve", "constant")
"""Axial laws of the segments whose line type has a fibre model (:class:`FELine`)."""

_NO_COEF = np.zeros(4)   # generalised-alpha coefficients of a static parameter bundle (unused)
NEWTON_MODES = ("force", "exact", "modified", "fast")
"""Newton iteration of the dynamic step (:meth:`FELine.start`)."""
_NEWTON_CODES = {"force": K.NW_TRAPEZ | K.NW_FORCE, "exact": K.NW_TRAPEZ, "modified": K.NW_KEEP,
                 "fast": K.NW_PREDICT | K.NW_QSTOP}
"""``newton`` code of :class:`~.bundles.LineParams` of each mode (bits of :mod:`.kernels`)."""


def gen_alpha_coefficients(rho_inf: float) -> np.ndarray:
    """Generalised-alpha parameters ``(alpha_m, alpha_f, beta, gamma)`` for the spectral radius
    at infinite frequency ``rho_inf`` in [0, 1] (Chung & Hulbert 1993, eq. 25)."""
    if not (0.0 <= rho_inf <= 1.0):
        raise ValueError(f"rho_inf must be in [0, 1], got {rho_inf!r}")
    am = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0)
    af = rho_inf / (rho_inf + 1.0)
    gamma = 0.5 - am + af
    beta = 0.25 * (1.0 - am + af) ** 2
    return np.array([am, af, beta, gamma])


@dataclass(frozen=True, kw_only=True)
class StaticSolution:
    """Static equilibrium of a FE line (SI units).

    ``positions`` (n, 3) m; ``tensions`` (n-1,) N per element; ``fairlead_force`` and
    ``anchor_force`` (3,) N: force of the line on the end points; ``iterations``;
    ``residual`` largest nodal force imbalance, N.
    """

    positions: np.ndarray
    tensions: np.ndarray
    fairlead_force: np.ndarray
    anchor_force: np.ndarray
    iterations: int
    residual: float

    @property
    def fairlead_tension(self) -> float:
        return float(np.linalg.norm(self.fairlead_force))

    @property
    def anchor_tension(self) -> float:
        return float(np.linalg.norm(self.anchor_force))


def _bedded_in(lt, le, fib):
    """Line type and element length of a fibre segment after bedding in: lengthened by the
    permanent strain after its largest mean tension (``FibreModel.length_factor``, 1 without
    one), mass and displaced volume per length reduced so that the segment's totals are
    unchanged (as the catenary statics of :mod:`floatmoor.mooring.fibre_system` do)."""
    f = fib.length_factor(lt.mbs) if fib is not None and hasattr(fib, "length_factor") else 1.0
    if f == 1.0:
        return lt, le, 1.0
    return (replace(lt, mass_per_length=lt.mass_per_length / f,
                    displaced_volume=lt.displaced_volume / f), le * f, f)


class FELine:
    """A lumped-mass line built from a :class:`FELineSpec`.

    Parameters
    ----------
    spec : FELineSpec
    dynamic_ea : bool
        Use the segments' ``ea_dynamic`` in dynamics (statics always use ``ea``).
    axial_stiffness_limit : float, optional
        Upper limit of the axial stiffness in dynamics, N (Aqwa limits the inline stiffness of
        dynamic cables the same way).  Not needed for convergence: stiff elements (strain under
        their own weight below ``kernels.E0_STIFF`` = 1e-6, e.g. the OC3 chain from EA ~ 5e10
        N) are handled by the implicit step with a tension estimate (mixed displacement-tension
        Newton, see :func:`kernels.gen_alpha_step`), and the OC3 line runs at its full
        EA = 3.84e14 N at dt 0.2 s (rho_inf 0.7) and 0.1 s (rho_inf 0.5); see RESULTS.md,
        "Stiff lines at full EA".  A limit such as 3.84e11 N (strain 4e-6 at 1.4 MN) gives
        the same tensions with slightly fewer Newton iterations.  A ``FloatmoorWarning`` says
        when the limit is active.  Fibre elements included: the two-component law's dynamic
        stiffness and the working-curve slopes in dynamics are capped at it (statics never);
        see :mod:`.fibre_law` (also for their ``-zeta`` internal damping, from the element's
        stiffness at the start of the dynamics, not the line type's ``ea_dynamic``).
    fibre_law : str
        Axial law of the segments whose line type has a fibre model
        (``line_type.fibre``, :class:`floatmoor.mooring.fibre.FibreModel`; other segments and
        segments with a ``tension_poly`` are not affected): ``"two_component"`` (default) the
        working curve in statics and, in dynamics, the dynamic stiffness about a filtered mean
        strain (:mod:`.fibre_law`; the working curve also in dynamics for the ``lower`` bound
        or with ``dynamic_ea=False``); ``"working_curve"`` the working curve in statics and
        dynamics; ``"constant"`` the constant ``ea`` / ``ea_dynamic`` of the line type, as for
        any other segment.  With the fibre laws a segment whose model has seen a largest mean
        tension (``max_tension_mbs``) is lengthened by its permanent strain, its mass and
        displaced volume kept (:attr:`length_factors`), as in the catenary statics.
    fibre_time_constant : float
        Time constant of the mean-strain filter of the two-component law, s (default
        :data:`.fibre_law.DEFAULT_TIME_CONSTANT`).
    waves : floatmoor.metocean.realisation.WaveRealisation, optional
        Wave kinematics in dynamics (option): the particle velocity enters the drag (relative
        velocity), the particle acceleration the fluid inertia ``(rho V l) a + m_a a`` of every
        node (Morison).  Evaluated at the node positions of the accepted state at the end time
        of each step (Wheeler stretching with ``wheeler``); the seabed boundary of the
        realisation must match the line's.  Costs one kinematics evaluation per node, step and
        wave component.
    """

    def __init__(self, spec: FELineSpec, *, dynamic_ea: bool = True,
                 axial_stiffness_limit: float | None = None, waves=None, wheeler: bool = True,
                 fibre_law: str = "two_component",
                 fibre_time_constant: float = DEFAULT_TIME_CONSTANT):
        if fibre_law not in FIBRE_LAWS:
            raise ValueError(f"fibre_law must be one of {FIBRE_LAWS}, got {fibre_law!r}")
        self.spec = spec
        rho = spec.water_density
        g = spec.gravity
        ne = spec.n_elements
        nn = ne + 1
        self.n_nodes = nn
        E_st = np.zeros((ne, K.N_EL))
        E_dy = np.zeros((ne, K.N_EL))
        P = np.zeros((nn, K.N_NP))
        seg_of = np.zeros(ne, dtype=np.int64)
        fib_rec = []         # fibre records appended to S (fibre_law)
        self.length_factors = []
        """Unstretched length of each segment over its given length (bedded-in fibre)."""
        fib_at = K.N_S
        fib_max = 0.0        # largest dynamic stiffness of the fibre elements (N)
        j = 0
        dmax = 0.0
        for k, seg in enumerate(spec.segments):
            lt = seg.line_type
            dmax = max(dmax, lt.diameter)
            le = seg.length / seg.n_elements
            fib = (getattr(lt, "fibre", None) if fibre_law != "constant" and not seg.tension_poly
                   else None)
            lt, le, f_len = _bedded_in(lt, le, fib)
            self.length_factors.append(f_len)
            w = lt.submerged_weight(rho, g)
            if fib is not None:
                lim = math.inf if axial_stiffness_limit is None else float(axial_stiffness_limit)
                fib_rec.append(fibre_record(fib, lt.mbs, fibre_time_constant, lim))
                fib_off = fib_dy = fib_at
                fib_at += fib_rec[-1].size
                two = (fibre_law == "two_component" and dynamic_ea
                       and getattr(fib, "bound", "nominal") != "lower")
                k_max = max_dynamic_stiffness(fib_rec[-1], lt.mbs, two)
                fib_max = max(fib_max, k_max)
                if not two and k_max > lim:   # working curve in dynamics: slopes capped
                    fib_rec.append(capped_record(fib_rec[-1], lim))
                    fib_dy = fib_at
                    fib_at += fib_rec[-1].size
            for _ in range(seg.n_elements):
                seg_of[j] = k
                for E, ea in ((E_st, lt.ea), (E_dy, lt.ea_dynamic if dynamic_ea else lt.ea)):
                    E[j, K.EL_L0] = le
                    if seg.tension_poly:
                        c = list(seg.tension_poly) + [0.0] * (3 - len(seg.tension_poly))
                        E[j, K.EL_C1:K.EL_C3 + 1] = c
                    else:
                        E[j, K.EL_C1] = ea
                    E[j, K.EL_B] = seg.damping_coefficient(ea)
                if fib is not None:
                    E_st[j, EL_LAW] = LAW_WORKING
                    E_dy[j, EL_LAW] = LAW_TWO_COMPONENT if two else LAW_WORKING
                    E_st[j, EL_FIB] = fib_off
                    E_dy[j, EL_FIB] = fib_dy
                for i in (j, j + 1):
                    h = 0.5 * le
                    P[i, K.NP_MASS] += lt.mass_per_length * h
                    P[i, K.NP_W] += w * h
                    P[i, K.NP_KDN] += 0.5 * rho * lt.cdn * lt.diameter * h
                    P[i, K.NP_KDT] += 0.5 * rho * lt.cdt * lt.diameter * h
                    P[i, K.NP_MAN] += rho * lt.can * lt.displaced_volume * h
                    P[i, K.NP_MAT] += rho * lt.cat * lt.displaced_volume * h
                    P[i, K.NP_MD] += rho * lt.displaced_volume * h
                    if spec.seabed.model == "springs":
                        P[i, K.NP_KS] += spec.seabed.stiffness * h
                        P[i, K.NP_CS] += spec.seabed.damping * h
                    P[i, K.NP_MUA] = spec.friction.mu_axial
                    P[i, K.NP_MUL] = spec.friction.mu_lateral
                j += 1
        EI = np.array([spec.segments[k].bending_stiffness for k in seg_of])
        for i in range(1, nn - 1):
            P[i, K.NP_CB] = (0.5 * (EI[i - 1] + EI[i])
                             / (0.5 * (E_st[i - 1, K.EL_L0] + E_st[i, K.EL_L0])))
        for pb in spec.point_bodies:
            P[pb.node, K.NP_MASS] += pb.mass
            P[pb.node, K.NP_W] += (pb.mass - rho * pb.volume) * g
            P[pb.node, K.NP_KC] += 0.5 * rho * pb.cda
            P[pb.node, K.NP_MAC] += rho * pb.ca * pb.volume
            P[pb.node, K.NP_MD] += rho * pb.volume
        if spec.seabed.model == "mud_layer":
            for i in range(nn):
                ks = max(P[i, K.NP_W], 0.0) / spec.seabed.mud_depth
                P[i, K.NP_KS] = ks
                P[i, K.NP_CS] = 2.0 * math.sqrt(ks * (P[i, K.NP_MASS] + P[i, K.NP_MAN]
                                                      + P[i, K.NP_MAC]))
        S = np.zeros(K.N_S)
        S[K.S_ZC] = -spec.seabed.depth + (spec.seabed.mud_depth
                                          if spec.seabed.model == "mud_layer" else 0.0)
        fr = spec.friction
        S[K.S_VR] = (fr.ramp_velocity if fr.ramp_velocity is not None
                     else dmax / fr.zero_crossing_period)
        S[K.S_CD] = fr.ramp_displacement if fr.ramp_displacement is not None else 0.5 * dmax
        S[K.S_CURC] = math.cos(spec.current_heading)
        S[K.S_CURS] = math.sin(spec.current_heading)
        S[K.S_RHO] = rho
        S[K.S_BEND] = 1.0 if np.any(P[:, K.NP_CB] > 0.0) else 0.0
        cs_ = spec.seabed.contact_smoothing
        S[K.S_DC] = 0.5 * dmax if cs_ is None else cs_
        S[K.S_SBLIFT] = 1.0 if spec.seabed.lift_off_damping else 0.0
        if fib_rec:
            S = np.concatenate([S] + fib_rec)
        if axial_stiffness_limit is not None:
            f = np.minimum(1.0, axial_stiffness_limit / E_dy[:, K.EL_C1])
            plain = E_dy[:, EL_LAW] == 0.0
            if np.any(f[plain] < 1.0) or fib_max > axial_stiffness_limit:
                ea_max = max(E_dy[plain, K.EL_C1].max(initial=0.0), fib_max)
                warnings.warn(f"line {spec.name}: axial stiffness limited to "
                              f"{axial_stiffness_limit:.4g} N in dynamics (EA up to "
                              f"{ea_max:.4g} N" + (", fibre dynamic stiffness up to the MBS "
                                                   "included" if fib_max > 0.0 else "") + ")",
                              FloatmoorWarning, stacklevel=2)
            for c in (K.EL_C1, K.EL_C2, K.EL_C3):
                E_dy[:, c] *= f
            # The axial damping B (EL_B) keeps its value from the uncapped EA, also for a
            # ``-zeta`` damping, on purpose: the capped line then stays the same line as the
            # uncapped one (maximum tension within 0.06 % on the inextensible OC3 line), while
            # B scaled to the capped mode (zeta of 2 sqrt(EA_cap m) l) lets the capped axial
            # mode ring and moves the maximum by +0.7 % (tests/mooring/fe/test_fe_extreme.py).
        self.P = P
        self.E_static = E_st
        self.E_dynamic = E_dy
        self.S = S
        self.segment_of_element = seg_of
        self.fric_code = FRICTION_MODELS[fr.model]
        cz = np.asarray(spec.current_z, float)
        cu = np.asarray(spec.current_speed, float)
        order = np.argsort(cz)
        self.cur_z = np.ascontiguousarray(cz[order])
        self.cur_u = np.ascontiguousarray(cu[order])
        self.s_nodes = np.concatenate([[0.0], np.cumsum(E_st[:, K.EL_L0])])
        self.waves = waves
        self.wheeler = bool(wheeler)
        self.wk = np.zeros((nn, 6))
        self._wk0 = np.zeros((nn, 6))
        if waves is not None:
            self._kin_work = waves.kinematics_work()
            self._kin_v = np.zeros((nn, 3))
            self._kin_a = np.zeros((nn, 3))
            self._kin_p = np.zeros(nn)
            self._kin_eta = np.zeros(nn)
        # state and work arrays (allocated once)
        self.r = np.zeros((nn, 3))
        self.v = np.zeros((nn, 3))
        self.a = np.zeros((nn, 3))
        self.fn = np.zeros((nn, 3))
        self.fs = np.zeros((nn, K.N_FS))
        self._alloc_work()
        self.r[:] = self.initial_shape()
        self.fs[:, 4:6] = self.r[:, 0:2]
        self.time = 0.0
        self._started = False

    # ------------------------------------------------------------------------------------------
    def _alloc_work(self):
        nn = self.n_nodes
        # kernel bundles (arrays allocated once; the line's own r, v, a, fn, fs are the
        # accepted state)
        self._now = LineState(self.r, self.v, self.a, self.fn, self.fs)
        self._trial_state = new_state(nn, K.N_FS)
        self._step_state = new_state(nn, K.N_FS)
        self.work = new_work(nn)
        self._ends = np.zeros(6)
        self._rf0 = np.zeros(3)
        self._vf0 = np.zeros(3)
        self._par = None
        self._newton_mode = 0
        self.newton = "exact"
        """The Newton iteration of the dynamics (:meth:`start`): ``"force"``, ``"exact"``,
        ``"modified"`` or ``"fast"``."""
        self._bundle = None
        self._trial = False
        self._t1 = 0.0

    def initial_shape(self, fairlead=None) -> np.ndarray:
        """Node positions (n, 3) from the quasi-static elastic catenary (no friction, static EA)
        in the vertical plane through anchor and fairlead; a straight line if the catenary has
        no solution (line too short)."""
        sp = self.spec
        A = np.asarray(sp.anchor, float)
        F = np.asarray(sp.fairlead if fairlead is None else fairlead, float)
        dh = F[:2] - A[:2]
        xf = float(np.hypot(*dh))
        zf = float(F[2] - A[2])
        u = dh / xf if xf > 0 else np.array([1.0, 0.0])
        rho, g = sp.water_density, sp.gravity
        L = np.array([s.length for s in sp.segments]) * np.array(self.length_factors)
        EA = np.array([s.line_type.ea for s in sp.segments])
        w = np.array([s.line_type.submerged_weight(rho, g) for s in sp.segments])
        on_seabed = A[2] <= -sp.seabed.depth + 1e-6
        try:
            sol = solve_line(xf, zf, L, EA, w, None, 0.0, seabed=bool(on_seabed), name=sp.name)
            prof = line_profile(sol.HF, sol.VF, L, EA, w, np.zeros(L.size), 0.0, bool(on_seabed),
                                n=401)
            s, x, z = prof["s"], prof["x"], prof["z"]
            keep = np.concatenate([[True], np.diff(s) > 0])
            xs = np.interp(self.s_nodes, s[keep], x[keep])
            zs = np.interp(self.s_nodes, s[keep], z[keep])
        except (ConvergenceError, ValueError):
            t = self.s_nodes / self.s_nodes[-1]
            xs = t * xf
            zs = t * zf
        r = np.empty((self.n_nodes, 3))
        r[:, 0] = A[0] + xs * u[0]
        r[:, 1] = A[1] + xs * u[1]
        r[:, 2] = A[2] + zs
        r[-1] = F
        r[0] = A
        return r

    # ------------------------------------------------------------------------------------------
    def solve_static(self, fairlead=None, *, friction: bool = True, reference=None,
                     tol: float | None = None, maxit: int = 3000, restart: bool = False,
                     max_step: float = 0.0) -> StaticSolution:
        """Static equilibrium (damped Newton) for the fairlead at ``fairlead`` (m).

        Starts from the current positions (the catenary shape after construction, or the last
        solution: use it for continuation), or from the catenary when ``restart``.  With
        friction a sliding front moves along the grounded part by about one node per iteration,
        hence the generous ``maxit`` (an iteration costs ~10-20 us for 100 elements).  When
        Newton fails the axial stiffness is ramped up (continuation) and the fairlead move is
        split in halves.  Seabed
        friction in statics is the displacement ramp (Lu 2012, sec. 2.2.1) measured from
        ``reference`` node positions (default: the positions before this call) when the
        line's friction model is not ``none`` and ``friction`` is true.  ``max_step`` > 0 (m):
        trust radius on the largest nodal move of a Newton step
        (:func:`~floatmoor.mooring.fe.kernels.static_newton`; default off).

        Raises
        ------
        ConvergenceError
            Naming the line, the node with the largest imbalance and a remedy.
        """
        ref = self.r.copy() if reference is None else np.asarray(reference, float)
        self.fs[:] = 0.0
        self.fs[:, 4:6] = ref[:, 0:2]
        code = K.FR_STATIC if (friction and self.fric_code != 0) else K.FR_NONE
        wmax = max(float(np.max(np.abs(self.P[:, K.NP_W]))), 1.0)
        eamax = float(np.max(self.E_static[:, K.EL_C1]))
        if tol is None:
            # 1e-6 of a node weight, but not below the round-off of the axial force
            tol = max(1e-6 * wmax, 1e-13 * eamax)
        v0 = np.zeros_like(self.r)
        args = (code, tol, maxit, v0, wmax, eamax, max_step)
        if restart:
            self.r[:] = self.initial_shape(fairlead)
            st = self._solve_here(*args)
        elif fairlead is not None:
            st = self._move_and_solve(np.asarray(fairlead, float), 0, args)
        else:
            st = self._solve_here(*args)
        info = self.work.info
        if st != 0:
            raise ConvergenceError(
                f"FE statics: {'singular tangent' if st == -2 else 'no convergence'} "
                f"(largest residual {info[1]:.3g} N after {int(info[0])} iterations)",
                where=f"line {self.spec.name}, node {int(info[2])}",
                remedy="move the fairlead in smaller steps (continuation), check that the line is "
                       "long enough and not slack, or add elements")
        K.end_forces(self.r, v0, self.P, self._step_state.f, self.work.tens, self._ends)
        # end forces: the internal nodal force of the end node
        return StaticSolution(positions=self.r.copy(), tensions=self.work.tens.copy(),
                              fairlead_force=self._ends[3:6].copy(),
                              anchor_force=self._ends[0:3].copy(),
                              iterations=int(info[0]), residual=float(info[1]))

    def _move_and_solve(self, F, depth, args):
        """Move the fairlead to ``F`` (nodes shifted in proportion to the arc length) and solve;
        on failure go back and get there in two halves (down to 1/16 of the move)."""
        r_prev = self.r.copy()
        d = F - self.r[-1]
        t = self.s_nodes / self.s_nodes[-1]
        self.r += t[:, None] * d[None, :]
        self.r[-1] = F
        st = self._solve_here(*args)
        if st != 0 and depth < 4:
            self.r[:] = r_prev
            st = self._move_and_solve(0.5 * (r_prev[-1] + F), depth + 1, args)
            if st == 0:
                st = self._move_and_solve(F, depth + 1, args)
        return st

    def _solve_here(self, code, tol, maxit, v0, wmax, eamax, max_step=0.0):
        r_start = self.r.copy()
        st = self._newton(self.E_static, code, tol, maxit, v0, max_step)
        if st != 0:
            # continuation in the axial stiffness: very stiff lines (EA / weight ~ 1e6 and more:
            # the catenary start is off by the chord-arc difference, ~ l^2 kappa^2 / 24 in
            # strain) are solved first with EA = 1e3 x the line weight, then stiffened by 4x
            self.r[:] = r_start
            f = min(1.0, 1e3 * float(np.sum(np.abs(self.P[:, K.NP_W]))) / max(eamax, 1e-300))
            Ec = self.E_static.copy()
            while True:
                Ec[:, K.EL_C1:K.EL_C3 + 1] = self.E_static[:, K.EL_C1:K.EL_C3 + 1] * f
                st = self._newton(Ec, code, max(tol * f, 1e-6 * wmax) if f < 1 else tol, maxit,
                                  v0, max_step)
                if st != 0 or f >= 1.0:
                    break
                f = min(1.0, 4.0 * f)
        return st

    def _newton(self, E, code, tol, maxit, v0, max_step=0.0):
        # statics: no waves (zero kinematics)
        par = LineParams(self.P, E, self.S, self.cur_z, self.cur_u, self._wk0, int(code),
                         _NO_COEF, float(tol), int(maxit), self.s_nodes, 0)
        if max_step > 0.0:
            return K.static_newton(self.r, v0, self.fs, par, self._step_state.f, self.work,
                                   float(max_step))
        return K.static_newton(self.r, v0, self.fs, par, self._step_state.f, self.work)

    # ------------------------------------------------------------------------------------------
    def start(self, *, rho_inf: float = 0.7, tol: float = 1e-6, maxit: int = 30,
              integrator: str = "generalized_alpha", t0: float = 0.0, newton: str = "exact"):
        """Prepare dynamics from the current (static) state: velocities and accelerations zero,
        friction references at the current positions.

        ``newton``: ``"exact"`` (default) rebuilds the iteration matrix of the
        generalised-alpha Newton iteration at every iteration, starts from a predictor with
        the fairlead's trapezoidal prediction (lines with bending stiffness: its
        constant-velocity prediction), stops on the position correction ``tol`` (or a
        residual below 1e-5 node weights) and evaluates the accepted state once more; the
        trapezoidal predictor (since 2026-11-27) takes 2.28 iterations per line step in the
        flagship storm against 3.35 from the constant-velocity one, 0.83-0.88 of the CPU time,
        with each line's maximum the same to 0.0002 % (benchmarks/RESULTS.md); ``"force"`` rebuilds
        the matrix at every iteration, starts from a predictor with the fairlead's
        trapezoidal prediction and stops, after at least one correction, when the force
        imbalance of the free nodes, summed and over ``1 - alpha_f``, is below 1e-4 of the
        line's weight in air, accepting that iterate with its forces
        (:func:`~.gen_alpha.gen_alpha_step`); an iterate with a slack element is judged by
        the exact iteration's stops instead; a line with bending stiffness takes ``"exact"``
        (with the force stop its steps create energy; :attr:`newton` is the iteration in
        use).  About 36 % fewer force evaluations per step in
        the flagship storm (2.13 against 3.36 per line step) with each line's maximum and
        standard deviation within 0.001 % of the exact iteration's over three 3-hour storms;
        opt-in, because in the surge decay of tests/solvers/test_time_domain_fe.py a leeward
        line's fairlead tension is up to 11 kN off the converged one at 900 kN
        (benchmarks/RESULTS.md); ``"modified"`` keeps the matrix
        of a step's first iteration while the residual falls fast enough and also stops on the
        estimated error left (same tolerance; 10-30 % less CPU; results not bit-identical
        to the exact iteration's and, over a storm, single-line extremes can differ by a few
        per cent: :func:`~.kernels.gen_alpha_step`; lines with bending or very stiff elements
        keep the exact matrix); ``"fast"`` rebuilds the matrix like ``"exact"`` but starts
        from a predictor that takes the fairlead's acceleration into account and stops when
        the quadratic-convergence estimate of the next correction is below ``tol`` (about
        one iteration less per step: 3.36 -> 2.17 in the flagship storm; each accepted state
        within ``tol`` of the converged one, but not bit-identical to ``"exact"``, and a snap
        load's peak can move as with ``"modified"``: benchmarks/RESULTS.md).

        ``tol`` (m; ``"exact"``, ``"modified"``, ``"fast"``): Newton stops when the position
        correction is below it and the residual
        below 1e-2 node weights, or when the residual is below 1e-5 node weights; for very
        stiff lines the residual bound is raised to the round-off of the axial forces
        (``c1 * 2.2e-16 * (2 + 2 max|r| / L0)`` per element, ~100 N summed for the OC3 line
        at EA = 3.84e14 N), which double precision cannot go below.
        """
        if integrator not in ("generalized_alpha", "explicit"):
            raise ValueError("integrator must be 'generalized_alpha' or 'explicit'")
        self.integrator = integrator
        if newton not in NEWTON_MODES:
            raise ValueError(f"newton must be one of {', '.join(NEWTON_MODES)}")
        self._newton_mode = _NEWTON_CODES[newton]
        if self.S[K.S_BEND] > 0.0 and newton in ("force", "exact"):
            # with bending stiffness the force stop's steps and the trapezoidal predictor's
            # create energy (the energy audit stops the beam of test_newton_force.py and
            # test_lanes.test_bending): the exact iteration from the constant-velocity predictor
            newton = "exact"
            self._newton_mode = 0
        self.newton = newton
        self.coef = gen_alpha_coefficients(rho_inf)
        self._tol = float(tol)
        self._maxit = int(maxit)
        self.v[:] = 0.0
        self.a[:] = 0.0
        self.fs[:] = 0.0
        self.fs[:, 4:6] = self.r[:, 0:2]
        fibre_start(self.r, self.fs, self.P, self.E_dynamic, self.S)
        self._fibre_damping()
        self._set_params()
        self.time = float(t0)
        K.line_forces(self.r, self.v, self.fs, self._par, False, 0.0, 0.0, self.fn, self.work)
        self._trial = False
        self._t1 = self.time
        self._started = True
        self.newton_iterations = 0
        self.substeps_taken = 0
        self.work.audit[:] = 0.0
        self.work.energy[:] = 0.0

    def _fibre_damping(self):
        """Internal damping ``-zeta`` of the fibre elements from the stiffness they have at the
        start of the dynamics (the current, static, state): ``EA_d`` at the static tension
        (two-component law, after :func:`fibre_start`) or the working-curve tangent at the
        static strain (working-curve law), with the stiffness limit (:mod:`.fibre_law`)."""
        E = self.E_dynamic
        for j in np.nonzero(E[:, EL_LAW] != 0.0)[0]:
            seg = self.spec.segments[self.segment_of_element[j]]
            if float(seg.internal_damping) >= 0.0:
                continue
            o = int(E[j, EL_FIB])
            if E[j, EL_LAW] == LAW_TWO_COMPONENT:
                k = self.fs[j, FS_KD]
            else:
                eps = float(np.linalg.norm(self.r[j + 1] - self.r[j])) / E[j, K.EL_L0] - 1.0
                k = working_tension(self.S, o, max(eps, 0.0))[1]
            E[j, K.EL_B] = seg.damping_coefficient(k)

    def _set_params(self):
        self._par = LineParams(self.P, self.E_dynamic, self.S, self.cur_z, self.cur_u, self.wk,
                               int(self.fric_code), self.coef, self._tol, self._maxit,
                               self.s_nodes, self._newton_mode)
        self._bundle = LineBundle(self._par, self._now, self._trial_state, self._step_state,
                                  self.work)
        # the same as plain tuples, for the entry from Python (fast dispatch, see ga_advance)
        self._tuples = tuple(tuple(b) for b in self._bundle[1:4]) + (tuple(self._par),
                                                                     tuple(self.work))

    @property
    def tol(self) -> float:
        """Newton tolerance in dynamics (m, :meth:`start`)."""
        return self._tol

    @tol.setter
    def tol(self, value: float):
        self._tol = float(value)
        if self._par is not None:
            self._set_params()

    @property
    def maxit(self) -> int:
        """Newton iteration limit in dynamics (:meth:`start`).  Setting it (or :attr:`tol`)
        after :meth:`start` renews :attr:`bundle`; typed lists built before keep the old one."""
        return self._maxit

    @maxit.setter
    def maxit(self, value: int):
        self._maxit = int(value)
        if self._par is not None:
            self._set_params()

    def params(self, *, static: bool = False, fric: int | None = None, wk=None,
               tol: float | None = None, maxit: int | None = None) -> LineParams:
        """The line's :class:`~.bundles.LineParams` for a kernel called directly: the dynamic
        (default) or static axial law, the line's friction code or ``fric``, its wave
        kinematics array or ``wk`` (n, 6), the Newton ``tol`` / ``maxit`` and coefficients of
        :meth:`start` (zeros before it)."""
        started = self._par is not None
        return LineParams(self.P, self.E_static if static else self.E_dynamic, self.S,
                          self.cur_z, self.cur_u, self.wk if wk is None else wk,
                          int(self.fric_code if fric is None else fric),
                          self.coef if started else _NO_COEF,
                          float(tol if tol is not None else (self.tol if started else 1e-6)),
                          int(maxit if maxit is not None else (self.maxit if started else 30)),
                          self.s_nodes, self._newton_mode if started else 0)

    @property
    def bundle(self) -> LineBundle:
        """The line's kernel bundles in dynamics (:class:`~.bundles.LineBundle`: parameters,
        accepted / trial / sub-step states, work arrays; the arrays are the line's own), for
        kernels that advance several lines at once (:mod:`.multi`).  Set by :meth:`start`."""
        if self._bundle is None:
            raise RuntimeError("call start() first")
        return self._bundle

    def advance(self, t1: float, dt: float, rf1, vf1, *, substeps: int = 1) -> np.ndarray:
        """Advance from the last accepted state (time ``t1 - dt``) to ``t1`` with the fairlead at
        ``rf1`` (m) moving with ``vf1`` (m/s) at ``t1``; returns the trial force of the line on
        the fairlead (N, (3,)).  Call :meth:`accept` to commit.

        With ``substeps > 1`` the fairlead moves linearly from its accepted position.
        """
        if not self._started:
            raise RuntimeError("call start() before advance()")
        rf1 = np.asarray(rf1, dtype=np.float64)
        vf1 = np.asarray(vf1, dtype=np.float64)
        tr = self._trial_state
        w = self.work
        if self.integrator == "explicit":
            tr.r[:] = self.r
            tr.v[:] = self.v
            tr.a[:] = self.a
            tr.fs[:] = self.fs
            tr.f[:] = self.fn
        if self.waves is not None:
            self.waves.kinematics_into(t1, self.r, self._kin_work, self._kin_v, self._kin_a,
                                       self._kin_p, self._kin_eta, wheeler=self.wheeler,
                                       g=self.spec.gravity, rho=self.spec.water_density)
            self.wk[:, 0:3] = self._kin_v
            self.wk[:, 3:6] = self._kin_a
        if self.integrator == "generalized_alpha":
            w.stats[:] = 0.0
            st = K.ga_advance(t1, dt, substeps, self.MAX_SPLIT, rf1, vf1, *self._tuples)
            self.newton_iterations += int(w.stats[0])
            self.substeps_taken += int(w.stats[1])
            if st < 0:
                raise self.step_error(st)
        else:
            w.energy[0, 0] = 0.0
            rf0, vf0, rf, vf = self._rf0, self._vf0, w.rf, w.vf
            rf0[:] = self.r[-1]
            vf0[:] = self.v[-1]
            h = dt / substeps
            t0 = t1 - dt
            for k in range(1, substeps + 1):
                s = k / substeps
                for c in range(3):
                    rf[c] = rf0[c] + s * (rf1[c] - rf0[c])
                    vf[c] = vf0[c] + s * (vf1[c] - vf0[c])
                tk = t0 + k * h
                # the explicit step reports the forces at the start of its (short) step
                bad = K.explicit_step(tk, h, rf, vf, tr, self._par, w)
                if bad >= 0:
                    self._fail(tk, bad, "explicit step diverged (NaN)",
                               "reduce dt below the axial-wave limit or use generalized_alpha")
                K.friction_commit(tr.r, tr.v, w.q, self.fric_code, tr.fs, self.P, self.S,
                                  self.S[K.S_ZC])
                if self.S.shape[0] > K.N_S:
                    K.fibre_commit(tr.r, tr.fs, self.P, self.E_dynamic, self.S, h)
        self.trial(t1)
        K.end_forces(tr.r, tr.v, self.P, tr.f, w.tens, self._ends)
        return self._ends[3:6].copy()

    MAX_SPLIT = 5
    STIFF_EA = 1e12
    """Dynamic EA (N) above which a failing step suggests a lower ``rho_inf`` or
    ``axial_stiffness_limit`` (the OC3 line with EA = 3.84e14 N, surge 3 m at 15 s, fails at
    dt 0.1 s with rho_inf 0.7 after 49 s and runs with rho_inf 0.5; see RESULTS.md)."""

    # ---- trial / accept protocol -------------------------------------------------------------
    def trial(self, t1: float) -> None:
        """Declare the trial state (:attr:`bundle` ``.trial``) the state at ``t1``: called by
        :meth:`advance`, and by a caller whose kernel advanced the line itself
        (:func:`.multi.body_advance`)."""
        self._t1 = float(t1)
        self._trial = True

    @property
    def has_trial(self) -> bool:
        """True between an advance (:meth:`trial`) and :meth:`accept` / :meth:`reject`."""
        return self._trial

    @property
    def trial_time(self) -> float:
        """Time of the trial state (s); the accepted time when there is none."""
        return self._t1 if self._trial else self.time

    def accept(self, *, copied: bool = False):
        """Commit the state of the last advance.  ``copied``: the trial arrays were already
        copied into the accepted state by a multi-line kernel (:func:`.multi.body_accept`);
        only the time is advanced."""
        if not self._trial:
            raise RuntimeError("accept() without a preceding advance()")
        if not copied:
            tr = self._trial_state
            self.r[:] = tr.r
            self.v[:] = tr.v
            self.a[:] = tr.a
            self.fn[:] = tr.f
            self.fs[:] = tr.fs
            self.work.energy[1] = self.work.energy[0]
        self.time = self._t1
        self._trial = False

    def reject(self) -> None:
        """Drop the trial state: the next advance starts again from the accepted state."""
        self._trial = False

    def set_time(self, t: float) -> None:
        """The accepted state is at ``t`` (s): for a kernel that advanced and accepted the line
        itself (:func:`floatmoor.solvers.fe_coupling.run`); drops any trial."""
        self.time = float(t)
        self._t1 = self.time
        self._trial = False

    def step(self, t1, dt, rf1, vf1, *, substeps: int = 1) -> np.ndarray:
        """:meth:`advance` then :meth:`accept`; returns the fairlead force (N)."""
        F = self.advance(t1, dt, rf1, vf1, substeps=substeps)
        self.accept()
        return F

    @property
    def tensions(self) -> np.ndarray:
        """Element tensions (N) of the last force evaluation (a copy)."""
        return self.work.tens.copy()

    @property
    def failure(self) -> tuple[float, int]:
        """Time (s) and node of the last failed step (kernel ``info``)."""
        return float(self.work.info[0]), int(self.work.info[1])

    def step_error(self, code: int, *, remedy: str | None = None,
                   coupled: bool = False) -> NumericalError:
        """The NumericalError of a failed generalised-alpha advance with status ``code`` (-1
        no convergence, -2 singular iteration matrix, -3 NaN), at :attr:`failure`."""
        t, node = self.failure
        au = self.work.audit
        head = "FE line coupled to the body" if coupled else "FE line"
        name = repr(self.spec.name) if coupled else self.spec.name
        if code == -4:
            j = int(node)
            msg = (f"the time step created energy: {au[K.AU_WORST]:.3g} of the line's kinetic "
                   f"and elastic energy in one step of {self.MAX_SPLIT} halvings (bound "
                   f"{K.AUDIT_HARD:g}), largest tension at s = {self.arc_length(j):.1f} m from "
                   f"the anchor (element {j})")
            return NumericalError(f"{head}: {msg}", time=t, where=f"line {name}",
                                  remedy=remedy or (
                                      "add axial damping (finite_element: internal_damping: "
                                      "-0.5, half the critical damping of an element) or "
                                      "seabed friction, reduce finite_element.dt, or use "
                                      "fewer, longer elements"))
        if code == -5:
            i = int(node)
            lim = max(K.PEN_WEIGHTS * max(self.P[i, K.NP_W], 0.0) / self.P[i, K.NP_KS],
                      K.PEN_FLOOR)
            msg = (f"node {i} (s = {self.s_nodes[i]:.1f} m from the anchor) went "
                   f"{au[K.AU_PEN] * lim:.3g} m below the seabed, deeper than the contact law "
                   f"allows ({lim:.3g} m: where its spring carries {K.PEN_WEIGHTS:g} times the "
                   f"node's submerged weight, at least {K.PEN_FLOOR:g} m)")
            return NumericalError(f"{head}: {msg}", time=t, where=f"line {name}",
                                  remedy=remedy or "reduce dt or raise the seabed stiffness "
                                                   "(finite_element: seabed: stiffness)")
        msg = {-1: f"no Newton convergence in {self.maxit} iterations",
               -2: "singular iteration matrix", -3: "NaN in the line state"}.get(
            code, f"line step failed (code {code})")
        if remedy is None:
            remedy = (f"reduce dt (the step was already halved {self.MAX_SPLIT} times), "
                      "add elements, or check for a slack line hit by a snap load")
            if self.E_dynamic[:, K.EL_C1].max() > self.STIFF_EA:
                remedy += (f"; the dynamic EA reaches {self.E_dynamic[:, K.EL_C1].max():.3g}"
                           " N: lower rho_inf (e.g. 0.5: more damping of the touchdown "
                           "impacts of a practically inextensible line) or set "
                           "axial_stiffness_limit (e.g. 3.84e11 N)")
        return NumericalError(f"{head}: {msg}", time=t,
                              where=f"line {name}, node {node} of {self.n_nodes - 1}",
                              remedy=remedy)

    def arc_length(self, element: int) -> float:
        """Unstretched arc length (m) of the middle of ``element`` from the anchor."""
        return 0.5 * float(self.s_nodes[element] + self.s_nodes[element + 1])

    @property
    def audit(self) -> dict:
        """The self-check of the dynamics since :meth:`start` (kernels ``AU_*``): steps halved
        because they created energy, steps that still did at the smallest sub-step (count,
        energy J, the largest over the energy budget, its time s and arc length m), the deepest
        seabed penetration over its bound (its time and arc length), and the most negative
        element tension (N, an element pushing; 0 when none)."""
        au = self.work.audit
        return {"energy_halvings": int(au[K.AU_SPLITS]),
                "energy_unresolved_steps": int(au[K.AU_NBAD]),
                "energy_unresolved_j": float(au[K.AU_EBAD]),
                "energy_worst_ratio": float(au[K.AU_WORST]),
                "energy_worst_time": float(au[K.AU_TWORST]),
                "energy_worst_arc_length": self.arc_length(int(au[K.AU_EWORST])),
                "seabed_penetration_ratio": float(au[K.AU_PEN]),
                "seabed_penetration_time": float(au[K.AU_TPEN]),
                "seabed_penetration_arc_length": float(self.s_nodes[int(au[K.AU_NPEN])]),
                "min_element_tension": float(au[K.AU_TMIN]),
                "min_element_tension_time": float(au[K.AU_TTMIN]),
                "min_element_tension_arc_length": self.arc_length(int(au[K.AU_ETMIN]))}

    def _error(self, t, node, what, remedy):
        return NumericalError(f"FE line: {what}", time=t,
                              where=f"line {self.spec.name}, node {node} of {self.n_nodes - 1}",
                              remedy=remedy)

    def _fail(self, t, node, what, remedy):
        raise self._error(t, node, what, remedy)
