"""Frequency-domain dynamic tension of a FE line under random fairlead motion.

The lumped-mass line of :class:`~floatmoor.mooring.fe.line.FELine` is linearised about its
static shape (ANSYS (2013), Aqwa Theory Manual, section "Dynamic Composite Catenary Mooring
Line", eq. 9-75 and table 9.1):

- mass: structural plus added mass, ``m I + m_an (I - q q^T) + m_at q q^T`` at every node
  (``q`` the static node tangent), point bodies included;
- stiffness: per element the axial and geometric stiffness ``dT/dl e e^T + T/l (I - e e^T)``
  from the static tension and direction (dynamic EA, or the slope of the tension polynomial;
  fibre segments (:mod:`.fibre_law`): the tension of the working curve and the dynamic
  stiffness at that mean tension, or the working-curve tangent for the ``working_curve`` law,
  the ``lower`` bound and ``dynamic_ea=False``);
- damping: the axial internal damping ``B / L0 e e^T`` of every element, the stochastically
  linearised normal and tangential drag on the velocity relative to the current
  (:mod:`~floatmoor.mooring.fe.drag_linearisation`), iterated to convergence with the node
  velocity covariances over the whole spectrum, and the seabed dampers of the ``fe`` model;
- seabed friction is left out (table 9.1), as is bending stiffness (a warning says so).

Seabed models (``seabed=``): ``"fe"`` every node free, vertical springs (and dampers) of the
line's own seabed model on the nodes in static contact; ``"pinned"`` the touchdown node fixed;
``"spring"`` the touchdown node held vertically and, horizontally, on the stretch stiffness of
the grounded line along the line and ``H / x`` across it; ``"least_squares"`` (Ong & Pellegrino
(2003)) the line below a cut point (``cut_fraction`` of the suspended nodes above the touchdown
point) replaced by the least-squares linearised catenary springs of
:mod:`~floatmoor.mooring.fe.touchdown_springs`, updated in the same iteration as the drag from
the covariance of the cut forces.  The fairlead tension is the tension of the top element.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg as sla
import xarray as xr

from ...core.errors import FloatmoorWarning, NumericalError
from ...core.quadrature import trapezoid_weights
from . import kernels as KN
from .drag_linearisation import drag_damping_1d, drag_damping_2d
from .fibre_law import EL_FIB, EL_LAW, LAW_TWO_COMPONENT, dynamic_stiffness, working_tension
from .frequency_kernels import line_transfer, spectral_moments
from .touchdown_springs import (
    LowerPart,
    cubic_expansion,
    grounded_axial_stiffness,
    least_squares_springs,
)

__all__ = ["SEABED_FD_MODELS", "LineStatics", "frequency_response", "line_statics"]

SEABED_FD_MODELS = ("least_squares", "pinned", "spring", "fe")


@dataclass(frozen=True, kw_only=True)
class LineStatics:
    """What the frequency-domain model reads from a FE line in static equilibrium (SI units):
    node positions ``r`` (n, 3) and arc lengths ``s`` (n,); per element the unstretched length
    ``L0``, static tension ``T``, dynamic axial slope ``dT/deps`` ``kax_eps``, internal damping
    ``B``; per node mass ``m`` (structural + isotropic point-body added mass), normal and
    tangential added mass ``man, mat``, drag factors ``kdn, kdt`` (N s^2/m^2, normal and
    tangential) and ``kc`` (isotropic, point bodies), seabed springs ``ks`` (N/m) and dampers
    ``cs`` (N s/m) of the line's seabed model, the current velocity ``u_c`` (n, 3); the seabed
    level ``z_seabed``, the largest diameter, the segments (lengths, EA, submerged weight) and the
    bending stiffness flag; ``ks_tangent`` (n,) N/m, the slope of the FE line's contact force at
    each node's static penetration (the kernel's smoothed contact law), used by the ``fe``
    seabed model of :func:`~floatmoor.mooring.fe.frequency_damping.fairlead_impedance`."""

    name: str
    r: np.ndarray
    s: np.ndarray
    L0: np.ndarray
    T: np.ndarray
    kax_eps: np.ndarray
    B: np.ndarray
    m: np.ndarray
    man: np.ndarray
    mat: np.ndarray
    kdn: np.ndarray
    kdt: np.ndarray
    kc: np.ndarray
    ks: np.ndarray
    cs: np.ndarray
    u_c: np.ndarray
    z_seabed: float
    diameter: float
    seg_lengths: np.ndarray
    seg_ea: np.ndarray
    seg_w: np.ndarray
    has_bending: bool
    ks_tangent: np.ndarray | None = None


def line_statics(line, *, dynamic_ea: bool = True) -> LineStatics:
    """The static state of ``line`` (an :class:`FELine` after ``solve_static``) as plain arrays.

    The only place that reads an FE line: its node positions ``line.r``, arc lengths
    ``line.s_nodes``, its specification ``line.spec`` (lumping as in :class:`FELine`) and, for
    fibre elements, their law and record (``E_static``, ``E_dynamic``, ``S``)."""
    sp = line.spec
    r = np.array(line.r, float)
    s = np.array(line.s_nodes, float)
    rho, g = sp.water_density, sp.gravity
    ne = sp.n_elements
    nn = ne + 1
    L0 = np.zeros(ne)
    T = np.zeros(ne)
    kax = np.zeros(ne)
    B = np.zeros(ne)
    m, man, mat, kdn, kdt, kc, ks, cs = (np.zeros(nn) for _ in range(8))
    wnode = np.zeros(nn)
    j = 0
    dmax = 0.0
    for k, seg in enumerate(sp.segments):
        lt = seg.line_type
        dmax = max(dmax, lt.diameter)
        le = seg.length / seg.n_elements
        f = line.length_factors[k] if hasattr(line, "length_factors") else 1.0
        if f != 1.0:
            # a bedded-in fibre segment, lumped as in FELine (same totals, longer)
            lt = replace(lt, mass_per_length=lt.mass_per_length / f,
                         displaced_volume=lt.displaced_volume / f)
            le = line.E_static[j, 0]
        w = lt.submerged_weight(rho, g)
        for _ in range(seg.n_elements):
            L0[j] = le
            eps = np.linalg.norm(r[j + 1] - r[j]) / le - 1.0
            ea_d = lt.ea_dynamic if dynamic_ea else lt.ea
            if line.E_static[j, EL_LAW] != 0.0:
                # fibre element: working curve, dynamic stiffness at the static (mean) tension
                # (the dynamic record: with axial_stiffness_limit, capped as in the time domain)
                o = int(line.E_static[j, EL_FIB])
                o_dy = int(line.E_dynamic[j, EL_FIB])
                T[j], _ = working_tension(line.S, o, max(eps, 0.0))
                kax[j] = (dynamic_stiffness(line.S, o_dy, T[j])
                          if dynamic_ea and line.E_dynamic[j, EL_LAW] == LAW_TWO_COMPONENT
                          else working_tension(line.S, o_dy, max(eps, 0.0))[1])
            elif seg.tension_poly:
                c = list(seg.tension_poly) + [0.0] * (3 - len(seg.tension_poly))
                T[j] = c[0] * eps + c[1] * eps ** 2 + c[2] * eps ** 3
                kax[j] = c[0] + 2 * c[1] * eps + 3 * c[2] * eps ** 2
            else:
                T[j] = lt.ea * eps
                kax[j] = ea_d
            # -zeta of a fibre element: of its dynamic stiffness at the static state, as FELine
            B[j] = seg.damping_coefficient(kax[j] if line.E_static[j, EL_LAW] != 0.0 else ea_d)
            for i in (j, j + 1):
                h = 0.5 * le
                m[i] += lt.mass_per_length * h
                wnode[i] += w * h
                kdn[i] += 0.5 * rho * lt.cdn * lt.diameter * h
                kdt[i] += 0.5 * rho * lt.cdt * lt.diameter * h
                man[i] += rho * lt.can * lt.displaced_volume * h
                mat[i] += rho * lt.cat * lt.displaced_volume * h
                if sp.seabed.model == "springs":
                    ks[i] += sp.seabed.stiffness * h
                    cs[i] += sp.seabed.damping * h
            j += 1
    for pb in sp.point_bodies:
        m[pb.node] += pb.mass + rho * pb.ca * pb.volume
        wnode[pb.node] += (pb.mass - rho * pb.volume) * g
        kc[pb.node] += 0.5 * rho * pb.cda
    if sp.seabed.model == "mud_layer":
        ks = np.maximum(wnode, 0.0) / sp.seabed.mud_depth
        cs = 2.0 * np.sqrt(ks * (m + man))
    z_seabed = -sp.seabed.depth + (sp.seabed.mud_depth if sp.seabed.model == "mud_layer"
                                   else 0.0)
    ks_t = np.zeros(nn)
    P, S = getattr(line, "P", None), getattr(line, "S", None)
    if P is not None and S is not None:
        # the kernel's contact law (kernels._line_forces): force ks g(pen), g(p) = p above
        # dpen = max(w / (2 ks), S_DC), 2 p^2 / dpen - p^3 / dpen^2 below; its slope here
        pen = S[KN.S_ZC] - r[:, 2]
        kn = P[:, KN.NP_KS]
        on = (pen > 0.0) & (kn > 0.0)
        dpen = np.maximum(0.5 * np.maximum(P[:, KN.NP_W], 1e-12) / np.where(on, kn, 1.0),
                          S[KN.S_DC])
        x = np.clip(pen / dpen, 0.0, 1.0)
        ks_t = np.where(on, kn * np.where(pen < dpen, x * (4.0 - 3.0 * x), 1.0), 0.0)
    u_c = np.zeros((nn, 3))
    if len(sp.current_z):
        cz = np.asarray(sp.current_z, float)
        cu = np.asarray(sp.current_speed, float)
        o = np.argsort(cz)
        sp_ = np.interp(r[:, 2], cz[o], cu[o])
        u_c[:, 0] = sp_ * math.cos(sp.current_heading)
        u_c[:, 1] = sp_ * math.sin(sp.current_heading)
    return LineStatics(
        name=sp.name, r=r, s=s, L0=L0, T=np.maximum(T, 0.0), kax_eps=kax, B=B, m=m, man=man,
        mat=mat, kdn=kdn, kdt=kdt, kc=kc, ks=ks, cs=cs, u_c=u_c, z_seabed=z_seabed,
        diameter=dmax, seg_lengths=np.array([sg.length for sg in sp.segments]),
        seg_ea=np.array([sg.line_type.ea for sg in sp.segments]),
        seg_w=np.array([sg.line_type.submerged_weight(rho, g) for sg in sp.segments]),
        has_bending=any(sg.bending_stiffness > 0 for sg in sp.segments), ks_tangent=ks_t)


# ---------------------------------------------------------------------------------------------
def _tangents(r):
    e = np.diff(r, axis=0)
    le = np.linalg.norm(e, axis=1)
    e = e / le[:, None]
    q = np.zeros_like(r)
    q[:-1] += e
    q[1:] += e
    q /= np.linalg.norm(q, axis=1)[:, None]
    return e, le, q


def _normal_basis(q):
    """Two unit vectors (n, 2, 3) normal to each tangent ``q`` (n, 3)."""
    ref = np.where(np.abs(q[:, 2:3]) < 0.9, np.array([[0.0, 0.0, 1.0]]),
                   np.array([[1.0, 0.0, 0.0]]))
    n1 = np.cross(q, ref)
    n1 /= np.linalg.norm(n1, axis=1)[:, None]
    n2 = np.cross(q, n1)
    return np.stack([n1, n2], axis=1)


@dataclass
class _Model:
    """Assembled real matrices of the linearised line (see :func:`line_transfer`)."""

    M: np.ndarray
    K: np.ndarray
    C0: np.ndarray     # damping without drag (internal damping on the diagonal, seabed)
    Ko: np.ndarray
    Co: np.ndarray
    fixed: np.ndarray  # (n, 3) bool
    base: int          # first node kept (elements below it dropped)
    spring_node: int   # node carrying the touchdown springs (-1: none)
    e_h: np.ndarray    # horizontal unit vector from the anchor towards the fairlead
    e_l: np.ndarray    # horizontal unit vector across the line


def _assemble(st: LineStatics, seabed: str, cut_fraction: float, contact_tangent: bool = False):
    """The line's matrices.  ``contact_tangent``: the ``fe`` seabed springs are the slopes of the
    FE line's contact law at the static penetration (``st.ks_tangent``) instead of the full
    spring stiffness on every node within half a diameter of the seabed."""
    r = st.r
    n = r.shape[0]
    e, le, q = _tangents(r)
    M = np.zeros((n, 3, 3))
    I3 = np.eye(3)
    qq = q[:, :, None] * q[:, None, :]
    M[:] = st.m[:, None, None] * I3 + st.man[:, None, None] * (I3 - qq) \
        + st.mat[:, None, None] * qq
    ee = e[:, :, None] * e[:, None, :]
    kax = st.kax_eps / st.L0
    Ke = kax[:, None, None] * ee + (st.T / le)[:, None, None] * (I3 - ee)
    Ce = (st.B / st.L0)[:, None, None] * ee
    dh = r[-1, :2] - r[0, :2]
    e_h = np.array([*(dh / max(np.linalg.norm(dh), 1e-300)), 0.0])
    e_l = np.array([-e_h[1], e_h[0], 0.0])
    contact = r[:, 2] <= st.z_seabed + 0.5 * st.diameter
    i_td = 0
    while i_td + 1 < n - 1 and contact[i_td + 1]:
        i_td += 1
    info = {"touchdown_node": i_td}
    base, spring_node = 0, -1
    Ks = np.zeros((3, 3))
    fixed = np.zeros((n, 3), bool)
    fixed[0] = True
    fixed[-1] = True
    C0 = np.zeros((n, 3, 3))
    Kn = np.zeros((n, 3, 3))
    if seabed == "fe":
        zz = np.zeros((3, 3))
        zz[2, 2] = 1.0
        if contact_tangent and st.ks_tangent is not None:
            Kn += st.ks_tangent[:, None, None] * zz
            C0 += np.where(st.ks_tangent > 0.0, st.cs, 0.0)[:, None, None] * zz
        else:
            Kn += np.where(contact, st.ks, 0.0)[:, None, None] * zz
            C0 += np.where(contact, st.cs, 0.0)[:, None, None] * zz
    elif i_td > 0:
        if seabed == "pinned":
            base = i_td
            fixed[:i_td + 1] = True
        elif seabed == "spring":
            base = spring_node = i_td
            fixed[:i_td] = True
            fixed[i_td, 2] = True
            s_td = st.s[i_td]
            lengths = _truncate(st.seg_lengths, s_td)
            k_ax = grounded_axial_stiffness(lengths, st.seg_ea[:lengths.size])
            x_td = float(np.linalg.norm(r[i_td, :2] - r[0, :2]))
            H = st.T[i_td] * math.hypot(e[i_td, 0], e[i_td, 1])
            Ks = k_ax * np.outer(e_h, e_h) + H / x_td * np.outer(e_l, e_l)
            info["spring_stiffness_axial"] = k_ax
        else:  # least_squares
            n_up = n - 1 - i_td
            c = min(i_td + max(1, math.ceil(cut_fraction * n_up)), n - 3)
            base = spring_node = c
            fixed[:c] = True
            lengths = _truncate(st.seg_lengths, st.s[c])
            nseg = lengths.size
            H0 = st.T[c] * math.hypot(e[c, 0], e[c, 1])
            V0 = st.T[c] * e[c, 2]
            part = LowerPart(lengths=lengths, ea=st.seg_ea[:nseg], w=st.seg_w[:nseg], H0=H0,
                             V0=V0)
            info.update(cut_node=c, lower_part=part, coeffs=cubic_expansion(part),
                        lateral=H0 / float(np.linalg.norm(r[c, :2] - r[0, :2])))
    for j in range(n - 1):
        if j < base:
            continue
        for i in (j, j + 1):
            Kn[i] += Ke[j]
            C0[i] += Ce[j]
    Ko = Ke.copy()
    Co = Ce.copy()
    Ko[:base] = 0.0
    Co[:base] = 0.0
    if spring_node >= 0:
        Kn[spring_node] += Ks
    model = _Model(M=M, K=Kn, C0=C0, Ko=Ko, Co=Co, fixed=fixed, base=base,
                   spring_node=spring_node, e_h=e_h, e_l=e_l)
    return model, info, e, q


def _cut_margin(st: LineStatics, X, Sx, w, e, j: int) -> float:
    """Static vertical force at node ``j`` over the std of its dynamic part: the linearised
    force of the element above the node, ``(dT/dl e e^T + T/l (I - e e^T)) (x_{j+1} - x_j)``,
    from the node transfer ``X``."""
    le = float(np.linalg.norm(st.r[j + 1] - st.r[j]))
    ez = e[j, 2]
    kz = st.kax_eps[j] / st.L0[j] * ez * e[j] + st.T[j] / le * (np.array([0.0, 0.0, 1.0])
                                                                  - ez * e[j])
    g = np.einsum("a,wad->wd", kz, X[:, j + 1] - X[:, j])
    var = float(np.trapezoid(np.real(np.einsum("wd,wde,we->w", g, Sx, g.conj())), w))
    return st.T[j] * ez / math.sqrt(var) if var > 0 else float("inf")


def _truncate(lengths, s):
    """Segment lengths of the line from the anchor up to arc length ``s``."""
    out = []
    acc = 0.0
    for L in lengths:
        if acc + L >= s - 1e-9:
            out.append(s - acc)
            break
        out.append(L)
        acc += L
    return np.array(out)


def _ls_block(Kls, lateral, e_h, e_l):
    z = np.array([0.0, 0.0, 1.0])
    ax = (e_h, z)
    B = lateral * np.outer(e_l, e_l)
    for a in range(2):
        for b in range(2):
            B += Kls[a, b] * np.outer(ax[a], ax[b])
    return B


def _mask(model: _Model, K, C):
    """Apply the fixed DOFs: zero rows and columns, unit stiffness."""
    M = model.M.copy()
    K = K.copy()
    C = C.copy()
    Ko = model.Ko.copy()
    Co = model.Co.copy()
    fi, fd = np.nonzero(model.fixed)
    for A in (M, K, C):
        A[fi, fd, :] = 0.0
        A[fi, :, fd] = 0.0
    K[fi, fd, fd] = 1.0
    # rows of held DOFs (node j) and columns (node j+1); the fairlead (prescribed, last node)
    # keeps its coupling: it is the right-hand side
    cols = model.fixed[1:].copy()
    cols[-1] = False
    keep = ~model.fixed[:-1, :, None] & ~cols[:, None, :]
    Ko *= keep
    Co *= keep
    return M, K, C, Ko, Co


def _transfer(omega, M, C, K, Ko, Co, scratch):
    X, D, G, T1, T2, Up = scratch
    bad = line_transfer(omega, M, C, K, Ko, Co, X, D, G, T1, T2, Up)
    if bad >= 0:
        raise NumericalError("frequency-domain line: singular dynamic matrix",
                             time=float("nan"), where=f"omega = {omega[bad]:.4g} rad/s",
                             remedy="check the line's static state (slack elements) and the "
                                    "seabed model")
    return X


def frequency_response(line, omega, motion_psd, *, seabed: str = "least_squares",
                       drag: bool = True, tol: float = 1e-3, max_iterations: int = 50,
                       relaxation: float = 0.7, cut_fraction: float = 0.05, n_modes: int = 6,
                       dynamic_ea: bool = True) -> xr.Dataset:
    """Linearised dynamic tension of a FE line under random fairlead motion.

    Parameters
    ----------
    line : FELine in static equilibrium (after ``solve_static``).
    omega : (n_w,) rad/s, increasing (spectral moments by the trapezoidal rule on this grid).
    motion_psd : fairlead displacement spectrum in earth axes, m^2 s/rad: auto-spectra
        (n_w, 3) (uncorrelated axes) or a cross-spectral matrix (n_w, 3, 3).
    seabed : ``"least_squares"`` (Ong & Pellegrino (2003)), ``"pinned"``, ``"spring"`` or
        ``"fe"`` (see the module docstring).
    drag : False leaves the drag out (linear limit).
    tol : convergence of the drag (and touchdown spring) iteration on the relative change of
        the fairlead tension std.
    relaxation : weight of the new linearised damping in each iteration.
    cut_fraction : least-squares model: the cut point is this fraction of the suspended nodes
        above the touchdown node (at least one node).  Ong & Pellegrino (2003) take the part
        below the cut as quasi-static ("dynamic effects near the seabed are negligible"): the
        cut belongs just above the touchdown, but high enough that it stays off the seabed over
        the excursion of the fit (attribute ``cut_force_margin``: static vertical force at the
        cut over its std; the 4-point Gauss-Hermite fit reaches 2.33 std).  A higher cut drops
        the drag and inertia of the line below it and lowers the tension.  The default 0.05
        was chosen on the OC3 line (50 elements, surge Tp 10 s); on cases that did not choose
        it (OC3 Tp 7 and 14 s, sigma 0.5-1.5 m; Floatel-like chain-polyester-chain lines
        under their 100-year WF motion) it stays within 3.4 % of the time domain, where 0.1
        and 0.2 reach -8 % and -29 % (benchmarks/fd_line_cut_study.py, RESULTS.md).

    Returns
    -------
    xarray.Dataset: ``fairlead_tension_psd(omega)`` N^2 s/rad, ``fairlead_tension_std`` N,
    ``tension_std(element)`` N, ``fairlead_tension_rao(omega, axis, complex)`` N/m (top element
    tension per unit fairlead displacement), ``node_velocity_std(node)`` m/s,
    ``iteration_tension_std(iteration)`` N, ``natural_frequency(mode)`` rad/s; attributes
    ``converged``, ``iterations``, ``seabed``, ``touchdown_node``, ``cut_node``,
    ``cut_force_margin`` (least-squares model, see ``cut_fraction``; NaN otherwise).
    """
    t0 = time.perf_counter()
    if seabed not in SEABED_FD_MODELS:
        raise ValueError(f"seabed must be one of {SEABED_FD_MODELS}, got {seabed!r}")
    w = np.ascontiguousarray(omega, float)
    S = np.asarray(motion_psd, float if np.isrealobj(motion_psd) else complex)
    if S.shape == (w.size, 3):
        Sx = np.zeros((w.size, 3, 3), complex)
        Sx[:, [0, 1, 2], [0, 1, 2]] = S
    elif S.shape == (w.size, 3, 3):
        Sx = S.astype(complex)
    else:
        raise ValueError(f"motion_psd must have shape ({w.size}, 3) or ({w.size}, 3, 3), "
                         f"got {S.shape}")
    st = line_statics(line, dynamic_ea=dynamic_ea)
    if st.has_bending:
        warnings.warn(f"line {st.name}: bending stiffness is left out of the frequency-domain "
                      "line model", FloatmoorWarning, stacklevel=2)
    model, info, e, q = _assemble(st, seabed, cut_fraction)
    n = st.r.shape[0]
    nb = _normal_basis(q)
    scratch = (np.zeros((w.size, n, 3, 3), complex), np.zeros((n, 3, 3), complex),
               np.zeros((n, 3, 3), complex), np.zeros((3, 3), complex),
               np.zeros((3, 3), complex), np.zeros((3, 3), complex))
    w2 = w * w
    wt = trapezoid_weights(w)
    kax = st.kax_eps / st.L0
    tr = np.zeros((w.size, n - 1, 3), complex)
    S_T = np.zeros((w.size, n - 1))
    var_T = np.zeros(n - 1)
    # initial guess of the node velocity covariance: the fairlead's, scaled by (s / L)^2
    Sv_f = np.real(np.trapezoid(w2[:, None, None] * Sx, w, axis=0))
    frac = ((st.s - st.s[model.base]) / (st.s[-1] - st.s[model.base])).clip(0.0, 1.0)
    cov_v = frac[:, None, None] ** 2 * Sv_f[None]
    ls = seabed == "least_squares" and "cut_node" in info
    Kls = least_squares_springs(info["lower_part"], np.zeros((2, 2)), info["coeffs"]) \
        if ls else None
    Kls_tangent = Kls
    Cd = _drag_damping(st, nb, q, cov_v) if drag else np.zeros((n, 3, 3))
    history = []
    converged = False
    sig_prev = None
    for it in range(max_iterations):
        K = model.K.copy()
        if ls:
            K[model.spring_node] += _ls_block(Kls, info["lateral"], model.e_h, model.e_l)
        Mm, Km, Cm, Ko, Co = _mask(model, K, model.C0 + Cd)
        X = _transfer(w, Mm, Cm, Km, Ko, Co, scratch)
        # tension of every element per unit fairlead displacement, node velocity covariances
        gain = kax[None, :] + 1j * w[:, None] * (st.B / st.L0)[None, :]
        spectral_moments(X, Sx, e, gain, wt, w2, model.base, tr, S_T, var_T, cov_v)
        sig_T = np.sqrt(np.maximum(var_T, 0.0))
        sig = sig_T[-1]
        history.append(sig)
        if sig_prev is not None and abs(sig - sig_prev) <= tol * max(sig, 1e-300):
            converged = True
            break
        sig_prev = sig
        if not drag and not ls:
            converged = True
            break
        if drag:
            Cd_new = _drag_damping(st, nb, q, cov_v)
            Cd = Cd_new if it == 0 else relaxation * Cd_new + (1.0 - relaxation) * Cd
        if ls:
            c = model.spring_node
            P = np.stack([model.e_h, [0.0, 0.0, 1.0]])       # (2, 3)
            Xc = np.einsum("pa,wad->wpd", P, X[:, c])
            cov_d = np.real(np.trapezoid(np.einsum("wpd,wde,wqe->wpq", Xc, Sx, Xc.conj()), w,
                                         axis=0))
            cov_f = Kls @ cov_d @ Kls.T
            Kls_new = least_squares_springs(info["lower_part"], cov_f, info["coeffs"])
            Kls = relaxation * Kls_new + (1.0 - relaxation) * Kls
    # natural frequencies of the final linear system (undamped, fairlead held)
    K = model.K.copy()
    if ls:
        K[model.spring_node] += _ls_block(Kls, info["lateral"], model.e_h, model.e_l)
    Mm, Km, _, Ko, _ = _mask(model, K, model.C0)
    nat = natural_frequencies(Mm, Km, Ko, model.fixed, n_modes)
    v_std = np.sqrt(np.maximum(np.trace(cov_v, axis1=1, axis2=2), 0.0)) \
        if len(history) > 1 else np.full(n, np.nan)
    S_top = S_T[:, -1]
    rao = tr[:, -1]
    ds = xr.Dataset(
        {
            "fairlead_tension_psd": ("omega", S_top, {
                "units": "N^2 s/rad", "long_name": "spectrum of the fairlead (top element) "
                                                   "tension"}),
            "fairlead_tension_std": ((), float(sig_T[-1]), {
                "units": "N", "long_name": "standard deviation of the fairlead tension"}),
            "tension_std": ("element", sig_T, {
                "units": "N", "long_name": "standard deviation of the element tension"}),
            "fairlead_tension_rao": (("omega", "axis", "complex"),
                                     np.stack([rao.real, rao.imag], axis=-1), {
                "units": "N/m", "long_name": "fairlead tension per unit fairlead displacement "
                                             "along the earth axis"}),
            "node_velocity_std": ("node", v_std, {
                "units": "m/s", "long_name": "standard deviation of the node speed (trace of "
                                             "the velocity covariance)"}),
            "iteration_tension_std": ("iteration", np.array(history), {
                "units": "N", "long_name": "fairlead tension std per linearisation "
                                           "iteration"}),
            "natural_frequency": ("mode", nat, {
                "units": "rad/s", "long_name": "undamped natural frequencies of the "
                                               "linearised line, fairlead held"}),
        },
        coords={"omega": ("omega", w, {"units": "rad/s", "long_name": "angular frequency"}),
                "element": np.arange(n - 1), "node": np.arange(n), "axis": ["x", "y", "z"],
                "complex": ["re", "im"], "iteration": np.arange(len(history)),
                "mode": np.arange(nat.size)},
        attrs={"line": st.name, "seabed": seabed, "converged": int(converged),
               "iterations": len(history), "touchdown_node": info["touchdown_node"],
               "cut_node": info.get("cut_node", -1),
               "cut_force_margin": _cut_margin(st, X, Sx, w, e, model.spring_node) if ls
               else float("nan"),
               "drag": int(drag),
               "run_time_s": time.perf_counter() - t0})
    if ls:
        ds["touchdown_stiffness"] = (("row", "col"), Kls, {
            "units": "N/m", "long_name": "least-squares touchdown springs (horizontal, "
                                         "vertical) at the cut node"})
        ds["touchdown_stiffness_tangent"] = (("row", "col"), Kls_tangent, {
            "units": "N/m", "long_name": "catenary tangent stiffness of the lower part"})
    if not converged:
        warnings.warn(f"line {st.name}: the drag linearisation did not converge in "
                      f"{max_iterations} iterations (last change "
                      f"{abs(history[-1] - history[-2]) / history[-1]:.2g})", FloatmoorWarning,
                      stacklevel=2)
    return ds


def _drag_damping(st: LineStatics, nb, q, cov_v):
    """Linearised drag damping blocks (n, 3, 3) from the node velocity covariances."""
    # relative velocity u = u_c - v: mean u_c, covariance cov_v
    mean_n = np.einsum("npa,na->np", nb, st.u_c)
    cov_n = np.einsum("npa,nab,nqb->npq", nb, cov_v, nb)
    Cn = drag_damping_2d(st.kdn, mean_n, cov_n)                       # (n, 2, 2)
    C = np.einsum("npa,npq,nqb->nab", nb, Cn, nb)
    mt = np.einsum("na,na->n", q, st.u_c)
    vt = np.einsum("na,nab,nb->n", q, cov_v, q)
    ct = drag_damping_1d(st.kdt, mt, np.sqrt(np.maximum(vt, 0.0)))
    C += ct[:, None, None] * q[:, :, None] * q[:, None, :]
    if np.any(st.kc > 0):
        # point bodies: isotropic drag, linearised per principal axis of the covariance
        for i in np.nonzero(st.kc > 0)[0]:
            lam, V = np.linalg.eigh(cov_v[i])
            mp = V.T @ st.u_c[i]
            c = drag_damping_1d(st.kc[i], mp, np.sqrt(np.maximum(lam, 0.0)))
            C[i] += V @ np.diag(c) @ V.T
    return C


def natural_frequencies(M, K, Ko, fixed, n_modes: int = 6) -> np.ndarray:
    """Lowest undamped natural frequencies (rad/s) of the block-tridiagonal system (nodal blocks
    ``M, K`` (n, 3, 3), element coupling ``-Ko`` (n-1, 3, 3)) with the ``fixed`` DOFs held.

    Mass-normalised (``M^-1/2 K M^-1/2`` with the 3x3 nodal blocks) and solved as a banded
    symmetric eigenproblem (bandwidth 5); held DOFs get an eigenvalue far above the rest."""
    n = M.shape[0]
    ndof = 3 * n
    nm = min(n_modes, int((~fixed).sum()))
    if nm <= 0:
        return np.zeros(0)
    Mh = M.copy()
    fi, fd = np.nonzero(fixed)
    Mh[fi, fd, fd] = 1.0
    lam_m, V = np.linalg.eigh(0.5 * (Mh + np.swapaxes(Mh, 1, 2)))
    R = V @ (lam_m[:, :, None] ** -0.5 * np.swapaxes(V, 1, 2))     # M^-1/2 per node
    Kd = K.copy()
    big = 1e6 * max(float(np.max(np.abs(K))), 1.0) / max(float(np.min(lam_m)), 1e-300)
    Kd[fi, fd, :] = 0.0
    Kd[fi, :, fd] = 0.0
    Kd[fi, fd, fd] = big
    Kc = -Ko.copy()
    for i, d in zip(fi, fd):
        if i < n - 1:
            Kc[i, d, :] = 0.0
        if i > 0:
            Kc[i - 1, :, d] = 0.0
    Ad = R @ (0.5 * (Kd + np.swapaxes(Kd, 1, 2))) @ R
    Ac = R[:-1] @ Kc @ R[1:]
    # lower band storage (the fairlead DOFs are held: their couplings are zeroed above): band[k, j] = A[j + k, j], k = 0..5
    band = np.zeros((6, ndof))
    for a in range(3):
        for b in range(a + 1):
            band[a - b, np.arange(n) * 3 + b] = Ad[:, a, b]
    for a in range(3):      # row in node i+1
        for b in range(3):  # column in node i
            band[3 + a - b, np.arange(n - 1) * 3 + b] = Ac[:, b, a]
    lam = sla.eig_banded(band, lower=True, eigvals_only=True, select="i",
                         select_range=(0, nm - 1))
    return np.sqrt(np.maximum(lam, 0.0))
