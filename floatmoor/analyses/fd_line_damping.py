"""LF mooring-line damping of the frequency-domain analysis (``line_damping: fe``).

The catenary mooring of the FD is quasi-static: it gives stiffness and no damping, while in a
coupled FE storm the drag on the moving lines damps the slow (LF) motion, to a large part
because of the lines' own WF motion (Lie, Gao & Moan (2007); Yang, Chen & Huang (2016)).
With the option each active line becomes a FE line at the FD mean pose (as for the dynamic WF
tension, :mod:`~floatmoor.analyses.fd_line_dynamics`: the scene's FE options, line types and
current), driven at its fairlead by the FD's WF and LF fairlead motion (two uncorrelated
bands: ``h = X_t + X_r x arm`` of the RAOs with the wave spectrum, and ``J S_LF J^H`` of the LF
cross-spectrum with ``J = [I, -[arm]x]``); the line's drag is linearised with the node
velocities of both bands (:func:`~floatmoor.mooring.fe.frequency_damping.fairlead_impedance`).
Its fairlead impedance ``Z(mu)`` beyond its static stiffness (which the catenary carries),
``J^T (Z(mu) - Re Z(0)) J`` summed over the lines (surge, sway and yaw block), is evaluated on
``N_MU`` frequencies of the LF band and interpolated onto the LF grid
(``FDModel.lf_impedance``): its imaginary part is the line damping ``mu B(mu)``, its real
part the drag's dynamic stiffening (the line cannot follow the fairlead through the water as
it would statically; on the Floatel-like lines both vary by a factor 2-5 over the LF band,
confirmed by time-domain forced oscillations, benchmarks/fd_lf_line_damping.py).  The LF
motion depends on the impedance and the drag linearisation on the motion: the two are iterated
(:func:`iterate_line_damping`) until the impedance changes by less than ``LINE_DAMPING_TOL``.
The LF tension of each line takes the FE line's dynamic tension increment on the catenary's
quasi-static gradient (:func:`lf_tension_spectra`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core.errors import ConvergenceError
from ..core.frames import rotation_matrix_into
from ..mooring.fe.body import scene_line_inputs
from ..mooring.fe.current_statics import MAX_STEP
from ..mooring.fe.frequency_damping import fairlead_impedance
from ..mooring.fe.from_system import spec_from_linedef
from ..mooring.fe.line import FELine
from ..solvers.frequency_domain import HORIZONTAL_DOFS, solve_frequency_domain, wf_directions
from .fd_line_dynamics import N_LINE_FREQUENCIES, coarse_grid

__all__ = ["LineDampingResult", "MooringLineDamping",
           "damping_ratio", "iterate_line_damping", "lf_impedance_on",
           "lf_mode_frequency", "lf_tension_spectra"]

LINE_DAMPING_TOL = 0.01
"""Relative change of the impedance increment (Frobenius norm over its frequencies) at which the
iteration with the response stops."""
LINE_DAMPING_MAX_ITER = 20


def _skew(a):
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


def lf_mode_frequency(stiffness, lf_mass, dof: int) -> float:
    """Undamped LF natural frequency (rad/s) of the mode dominated by ``dof`` (0 surge, 1 sway,
    5 yaw): eigenvalues of ``M^-1 K_c`` over surge, sway and yaw, heave-roll-pitch condensed
    out of ``K``; the mode with the largest mass-weighted share of ``dof``."""
    hz, vt = [0, 1, 5], [2, 3, 4]
    K = np.asarray(stiffness, float)
    Kc = K[np.ix_(hz, hz)] - K[np.ix_(hz, vt)] @ np.linalg.solve(K[np.ix_(vt, vt)],
                                                                K[np.ix_(vt, hz)])
    M = np.asarray(lf_mass, float)[np.ix_(hz, hz)]
    lam, V = np.linalg.eig(np.linalg.solve(M, Kc))
    share = np.abs(V.real) ** 2 * np.diag(M)[:, None]
    k = int(np.argmax(share[hz.index(dof)] / share.sum(axis=0)))
    return float(np.sqrt(abs(lam[k].real)))


@dataclass(frozen=True, kw_only=True)
class LineDampingResult:
    """The mooring lines' LF impedance beyond the quasi-static catenary.

    mu : (k,) rad/s, the frequencies where the lines were evaluated (0 first);
    impedance : (k, 6, 6) complex body impedance increment ``sum J^T (Z(mu) - Re Z(mu_0)) J``
    (surge, sway, yaw block; zero elsewhere), ``mu_0`` = ``MU_STATIC``: the FE lines' static
    stiffness, which the catenary already carries;
    omega : rad/s, the undamped LF natural frequency of surge (:func:`lf_mode_frequency`);
    damping, stiffness : (6, 6) ``Im Z_x / omega`` and ``Re Z_x`` there (N s/m .. N m s/rad,
    N/m .. N m/rad); per line at ``omega``: ``fairlead_damping``, ``fairlead_stiffness``
    (n_lines, 3, 3), earth axes (the stiffness the whole ``Re Z``; NaN for failed lines), and
    ``fairlead_velocity_std`` (n_lines, 3) m/s (WF and LF); ``iterations`` with the FD response;
    tension : (k, n_lines, 6) complex, the fairlead tension per unit body motion beyond its
    static value, ``t(mu) J - Re t(mu_0) J`` (``t`` the FE line's tension transfer; zero for
    failed lines), N/m .. N/rad.
    """

    mu: np.ndarray
    impedance: np.ndarray
    tension: np.ndarray
    omega: float
    damping: np.ndarray
    stiffness: np.ndarray
    fairlead_damping: np.ndarray
    fairlead_stiffness: np.ndarray
    fairlead_velocity_std: np.ndarray
    iterations: int


MU_STATIC = 1e-5
"""rad/s: the frequency taken for the lines' static stiffness (Re Z there)."""
N_MU = 32
"""Frequencies of the line impedance over the LF band (geometric from 1 % of the cut-off to the
cut-off, plus 0 and the natural frequency); linear interpolation onto the LF grid."""


class MooringLineDamping:
    """The FE lines of a built scene at the FD mean pose ``mean``, solved statically once;
    :meth:`__call__` gives their LF impedance for an FD solution."""

    def __init__(self, built, mean):
        system = built.mooring
        lm = getattr(system, "line_models", None)
        spec_kw = lm.options.spec_kw(system.water_depth) if lm is not None else {}
        inputs = scene_line_inputs(built.scene, system)
        R = np.zeros((3, 3))
        rotation_matrix_into(mean[3], mean[4], mean[5], R)
        self.lines = []
        for ld, active in zip(system.lines, system.active):
            if not active:
                self.lines.append(None)
                continue
            spec = spec_from_linedef(ld, water_depth=system.water_depth, pose=mean,
                                     water_density=system.water_density,
                                     gravity=system.gravity, line_types=inputs["line_types"],
                                     **spec_kw, **(inputs["current"] or {}))
            line = FELine(spec)
            line.solve_static(max_step=MAX_STEP)     # trust radius: the grounded chain in current
            arm = R @ np.asarray(ld.fairlead, float)
            J = np.hstack([np.eye(3), -_skew(arm)])       # fairlead motion per body motion
            self.lines.append((line, J))
        self._drag = [None] * len(self.lines)

    def __call__(self, sol, model, omega: float, iterations: int = 0) -> LineDampingResult:
        w, mu = model.omega, model.mu
        directions = wf_directions(model, sol)
        grid = np.unique(np.concatenate([[0.0], np.geomspace(mu[-1] / 100.0, mu[-1], N_MU),
                                         [omega]]))
        k_om = int(np.searchsorted(grid, omega))
        ev = np.concatenate([[MU_STATIC], grid[1:]])
        n = len(self.lines)
        Z6 = np.zeros((grid.size, 6, 6), complex)
        T6 = np.zeros((grid.size, n, 6), complex)
        Bf = np.full((n, 3, 3), np.nan)
        Kf = np.full((n, 3, 3), np.nan)
        vf = np.full((n, 3), np.nan)
        for i, item in enumerate(self.lines):
            if item is None:
                continue
            line, J = item
            Sx_wf = None
            for rao, S in directions:                        # the directions' motions add
                h = rao @ J.T                                # (n_w, 3) per unit amplitude
                part = h[:, :, None] * h[:, None, :].conj() * S[:, None, None]
                Sx_wf = part if Sx_wf is None else Sx_wf + part
            Sx_lf = np.einsum("ai,nij,bj->nab", J, sol.lf_cross_spectrum, J)
            bands = [coarse_grid(w, Sx_wf, N_LINE_FREQUENCIES),
                     coarse_grid(mu, Sx_lf, N_LINE_FREQUENCIES)]
            imp = fairlead_impedance(line, bands, ev, drag0=self._drag[i])
            self._drag[i] = imp.drag                         # warm start of the next call
            Zx = imp.impedance - imp.stiffness[0][None]      # beyond the static stiffness
            Zx[0] = 0.0
            Z6 += np.einsum("ai,kab,bj->kij", J, Zx, J)
            tx = imp.tension_transfer - imp.tension_transfer[0].real[None]
            tx[0] = 0.0
            T6[:, i] = tx @ J
            Bf[i], Kf[i] = imp.damping[k_om], imp.stiffness[k_om]
            vf[i] = imp.fairlead_velocity_std
        keep = np.zeros((6, 6), bool)
        keep[np.ix_(HORIZONTAL_DOFS, HORIZONTAL_DOFS)] = True
        Z6 *= keep
        return LineDampingResult(mu=grid, impedance=Z6, tension=T6, omega=omega,
                                 damping=Z6[k_om].imag / omega, stiffness=Z6[k_om].real,
                                 fairlead_damping=Bf, fairlead_stiffness=Kf,
                                 fairlead_velocity_std=vf, iterations=iterations)


def _interp_complex(mu, grid, Z):
    Zf = Z.reshape(grid.size, -1)
    out = np.empty((np.asarray(mu).size, Zf.shape[1]), complex)
    for c in range(Zf.shape[1]):
        out[:, c] = np.interp(mu, grid, Zf[:, c].real) + 1j * np.interp(mu, grid, Zf[:, c].imag)
    return out.reshape((-1, *Z.shape[1:]))


def lf_tension_spectra(res: LineDampingResult, gradient, sol, mu) -> np.ndarray:
    """LF fairlead tension spectra (m, n_lines), N^2 s/rad, of the lines with their dynamics:
    the tension per unit body motion ``g + dt(mu)`` (``gradient`` (n_lines, 6) the quasi-static
    one of the catenary, ``dt`` the FE lines' dynamic increment of ``res``) applied to the LF
    cross-spectrum of the body, ``h S_LF h^H``."""
    h = np.asarray(gradient, float)[None] + _interp_complex(mu, res.mu, res.tension)
    return np.real(np.einsum("nli,nij,nlj->nl", h, sol.lf_cross_spectrum, h.conj()))


def lf_impedance_on(res: LineDampingResult, mu) -> np.ndarray:
    """The impedance increment of ``res`` linearly interpolated onto the LF grid ``mu``
    (real and imaginary parts; zero at ``mu = 0``), (m, 6, 6) complex."""
    return _interp_complex(mu, res.mu, res.impedance)


def iterate_line_damping(built, mean, model, sol):
    """Solve the FD with the mooring lines' LF impedance, iterated with the response.

    Starts from ``sol`` (the FD solution without it), evaluates the lines
    (:class:`MooringLineDamping`), puts their impedance increment on the LF grid
    (``model.lf_impedance``) and solves again until the increment changes by less than
    ``LINE_DAMPING_TOL`` (relative, Frobenius norm over the evaluation frequencies).  Returns
    the model as solved, the solution and the :class:`LineDampingResult`.
    """
    lines = MooringLineDamping(built, mean)
    omega = lf_mode_frequency(model.stiffness, sol.lf_mass, 0)
    prev = None
    for it in range(1, LINE_DAMPING_MAX_ITER + 1):
        res = lines(sol, model, omega, it)
        model = replace(model, lf_impedance=lf_impedance_on(res, model.mu))
        sol = solve_frequency_domain(model)
        if prev is not None and np.linalg.norm(res.impedance - prev) <= LINE_DAMPING_TOL * max(
                np.linalg.norm(res.impedance), 1e-300):
            return model, sol, res
        prev = res.impedance
    raise ConvergenceError(
        f"the mooring-line damping did not settle in {LINE_DAMPING_MAX_ITER} iterations "
        "with the LF response", where="frequency domain, line_damping: fe",
        remedy="check the lines' FE options; line_damping: none leaves it out")


def damping_ratio(B, stiffness, lf_mass, dof: int = 0) -> float:
    """``B[dof, dof]`` as a fraction of the critical damping ``2 M w_n`` of ``dof``."""
    w = lf_mode_frequency(stiffness, lf_mass, dof)
    return float(B[dof, dof] / (2.0 * np.asarray(lf_mass)[dof, dof] * w))
