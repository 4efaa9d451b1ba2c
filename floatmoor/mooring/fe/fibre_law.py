"""Load-dependent axial law of fibre-rope (polyester) elements of the FE line.

Model (two components, in the spirit of the Syrope method, Falkenberg et al. (2017), as
described by SINTEF Ocean (2023): the working curve for the mean, a dynamic stiffness linear in
the mean tension about it).  Where SIMA takes the static tension as the mean of a whole
analysis, here every fibre element carries a slowly varying *mean strain* ``eps_m``, the
exponential low-pass filter of its strain ``eps`` with time constant ``tau`` (s),

    d eps_m / dt = (eps - eps_m) / tau,

and its elastic tension is

    T = T_w(eps_m) + EA_d(T_w(eps_m)) (eps - eps_m),

with ``T_w`` the quasi-static working tension-strain curve of the rope and ``EA_d(T_m)`` its
dynamic stiffness at the mean tension ``T_m`` (:class:`floatmoor.mooring.fibre.FibreModel`).
Loads much slower than ``tau`` follow the working curve (``eps_m -> eps``); wave-frequency
and, for ``tau`` well above their periods, low-frequency cycles see the dynamic stiffness at
the mean tension.  Statics use the working curve itself, ``T = T_w(eps)`` (law
:data:`LAW_WORKING`); so do the dynamics for the ``lower`` stiffness bound of the fibre model
(the working curve for everything) and for the FE option ``fibre_law: working_curve``.

In the linear limit about a mean state the law is a standard linear solid (Zener): a small
harmonic strain ``eps' e^{i omega t}`` gives the tension ``[EA_d - (EA_d - k_w) / (1 + i omega
tau)] eps'`` with ``k_w`` the working-curve tangent: ``k_w`` for ``omega tau << 1``, ``EA_d``
for ``omega tau >> 1``, and a hysteresis loss (the imaginary part) peaking near
``omega tau = sqrt(EA_d / k_w)``.  The default ``tau`` is :data:`DEFAULT_TIME_CONSTANT`
(300 s): over 10 times the wave periods and above the slow-drift periods of a moored semi
(100-250 s, where ``omega tau`` > 7.5 and the stiffness is within 1 % of ``EA_d``).

Time discretisation: ``eps_m`` is held over a line (sub-)step (the Newton tangent is then
``dT/deps = EA_d``, exact for the step) and updated after every accepted (sub-)step of length
``h`` with the exact exponential of the step, ``eps_m += (1 - exp(-h / tau)) (eps - eps_m)``
(a lag of one step, ``h / tau`` ~ 3e-4 at h = 0.1 s).  The dynamics start with ``eps_m`` at
the static strain (:func:`fibre_start`), so the tension is continuous at the start.

Slack: ``T = 0`` for ``eps <= 0``.  Near slack the working curve is blended into zero by the
cubic of :func:`kernels._tension` over the slack strain ``e0`` (C1), and the two-component law
``T_lin = T_w(eps_m) + EA_d (eps - eps_m)`` by the smooth maximum ``(T_lin + h)^2 / (4 h)`` on
``|T_lin| < h = EA_d e0`` (C1), so Newton does not cycle on a kink.

Storage (no allocation in the time loop, trial/accept/reject consistent):

* element columns of ``E`` (:mod:`.kernels`): ``EL_LAW`` 0 the polynomial law (the code path of
  lines without fibre elements, unchanged), :data:`LAW_WORKING` or :data:`LAW_TWO_COMPONENT`;
  ``EL_FIB`` the offset of the element's fibre record in ``S``;
* fibre records in ``S`` beyond its ``N_S`` line scalars (a line without fibre elements has
  exactly ``N_S``, :func:`fibre_record`): ``tau``, the working curve (strains and tensions in
  N, piecewise linear, extrapolated with the end slopes), the two coefficients of
  ``EA_d = MBS alpha + 100 beta T_m`` (the Syrope form of the model) and its cap ``kd_max``;

Axial stiffness limit and internal damping (what :class:`~.line.FELine` does with them):

* ``axial_stiffness_limit`` caps the axial stiffness of every element in dynamics, fibre
  elements included (a user who limits the stiffness of the system's lines expects it of all
  of them): the two-component law uses ``min(EA_d(T_m), limit)`` (the record's ``kd_max``),
  the working-curve law in dynamics a curve whose slopes are capped at the limit
  (:func:`capped_record`, a second record the dynamic elements point to).  Statics always use
  the working curve itself.
* internal damping given as a fraction of critical (``internal_damping: -zeta``) is, for a
  fibre element, ``zeta`` of the critical damping of the stiffness the element has when the
  dynamics start: ``EA_d`` at its static tension (two-component law) or the working-curve
  tangent at its static strain (working-curve law), both with the limit; not the line type's
  nominal ``ea_dynamic``.  A damping in N s is taken as given.
* the mean strain of element ``j`` in column :data:`FS_EM` of row ``j`` of the node state
  ``fs`` (:class:`~.bundles.LineState`), with ``T_w`` and ``EA_d`` at it (columns
  :data:`FS_TM`, :data:`FS_KD`: constant over a step, so a force evaluation does not search
  the table): copied with the rest of the state into the trial, committed by accept, dropped
  by reject.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..fibre import table_lookup_nb

__all__ = ["LAW_POLY", "LAW_WORKING", "LAW_TWO_COMPONENT", "EL_LAW", "EL_FIB", "FS_EM",
           "DEFAULT_TIME_CONSTANT", "fibre_record", "fibre_tension", "fibre_commit",
           "fibre_start", "working_tension", "dynamic_stiffness", "capped_record",
           "max_dynamic_stiffness"]

LAW_POLY, LAW_WORKING, LAW_TWO_COMPONENT = 0.0, 1.0, 2.0
EL_LAW, EL_FIB = 5, 6          # element columns (kernels.N_EL = 7)
FS_EM, FS_TM, FS_KD = 8, 9, 10  # node-state columns: mean strain, T_w and EA_d at it (N_FS 11)
DEFAULT_TIME_CONSTANT = 300.0  # s


def fibre_record(fibre, mbs: float, tau: float, stiffness_limit: float = math.inf) -> np.ndarray:
    """The ``S`` record of a fibre segment:
    ``[tau, n_w, kd0, kd1, eps_w (n_w), T_w (n_w), kd_max]``.

    ``fibre`` a :class:`~floatmoor.mooring.fibre.FibreModel`, ``mbs`` (N), ``tau`` (s).  The
    working curve in N (``T_w = MBS f_w``); the dynamic stiffness ``EA_d = min(kd0 + kd1
    max(T_m, 0), kd_max)`` with ``kd0 = MBS alpha``, ``kd1 = 100 beta`` (:func:`floatmoor.
    mooring.fibre.dynamic_ea_nb`, the same arithmetic) and ``kd_max`` the FE option
    ``axial_stiffness_limit`` (N; inf: none)."""
    if not (tau > 0.0 and math.isfinite(tau)):
        raise ValueError(f"fibre time constant must be > 0 s, got {tau!r}")
    ew, fw = fibre.working_arrays()
    return np.concatenate([[tau, ew.size, mbs * fibre.alpha, fibre.beta * 100.0], ew, fw * mbs,
                           [stiffness_limit]])


def capped_record(rec: np.ndarray, limit: float) -> np.ndarray:
    """A copy of the record ``rec`` whose working curve has its slopes capped at ``limit`` (N):
    the working-curve law in dynamics under ``axial_stiffness_limit`` (the tensions
    re-integrated from zero strain, ``T_w'(eps) = int_0^eps min(T_w', limit)``)."""
    n = int(rec[1])
    ew, tw = rec[4:4 + n], rec[4 + n:4 + 2 * n]
    slopes = np.minimum(np.diff(tw) / np.diff(ew), limit)
    out = rec.copy()
    out[4 + n:4 + 2 * n] = np.concatenate([[tw[0]], tw[0] + np.cumsum(slopes * np.diff(ew))])
    out[4 + 2 * n] = min(rec[4 + 2 * n], limit)
    return out


def max_dynamic_stiffness(rec: np.ndarray, mbs: float, two_component: bool) -> float:
    """The largest axial stiffness (N) the fibre law of ``rec`` reaches in dynamics up to the
    MBS: ``EA_d(MBS)`` for the two-component law, the steepest working-curve slope for the
    working-curve law (without ``kd_max``)."""
    n = int(rec[1])
    if two_component:
        return float(rec[2] + rec[3] * mbs)
    return float(np.max(np.diff(rec[4 + n:4 + 2 * n]) / np.diff(rec[4:4 + n])))


@njit(cache=True)
def _pl(S, ox, oy, n, x):
    """Piecewise-linear ``y(x)`` of the table ``S[ox:ox+n], S[oy:oy+n]`` and its slope;
    linear extrapolation with the end slopes.  The lookup of the quasi-static fibre model
    (:func:`floatmoor.mooring.fibre.table_lookup_nb`): at a node the right derivative."""
    return table_lookup_nb(x, S[ox:ox + n], S[oy:oy + n])


@njit(cache=True)
def working_tension(S, o, eps):
    """Working-curve tension ``T_w(eps)`` (N) of the record at ``S[o]`` and ``dT_w/deps``."""
    n = int(S[o + 1])
    return _pl(S, o + 4, o + 4 + n, n, eps)


@njit(cache=True)
def dynamic_stiffness(S, o, tm):
    """Dynamic stiffness ``EA_d(T_m) = min(kd0 + kd1 max(T_m, 0), kd_max)`` (N) of the record
    at ``S[o]`` (``kd_max`` inf without an ``axial_stiffness_limit``: the sum itself)."""
    kd = S[o + 2] + S[o + 3] * (tm if tm > 0.0 else 0.0)
    kmax = S[o + 4 + 2 * int(S[o + 1])]
    return kd if kd <= kmax else kmax


@njit(cache=True)
def _working_slack(S, o, eps, e0):
    """``T_w(eps)`` with zero tension in compression and the C1 cubic blend on ``[0, e0]``."""
    if eps <= 0.0:
        return 0.0, 0.0
    if eps >= e0:
        return working_tension(S, o, eps)
    T0, D0 = working_tension(S, o, e0)
    B = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
    A = (T0 - B * e0 * e0 * e0) / (e0 * e0)
    return A * eps * eps + B * eps * eps * eps, 2.0 * A * eps + 3.0 * B * eps * eps


@njit(cache=True)
def fibre_tension(law, eps, fs, j, S, o, e0):
    """Elastic tension (N) and ``dT/deps`` of the fibre element ``j`` with strain ``eps``,
    slack strain ``e0`` and (two-component law) the mean strain, ``T_w`` and ``EA_d`` of
    ``fs[j]`` (see the module docstring)."""
    if law == LAW_WORKING:
        return _working_slack(S, o, eps, e0)
    if eps <= 0.0:
        return 0.0, 0.0
    kd = fs[j, FS_KD]
    tl = fs[j, FS_TM] + kd * (eps - fs[j, FS_EM])
    h = kd * e0
    if tl >= h:
        return tl, kd
    if tl <= -h:
        return 0.0, 0.0
    return (tl + h) * (tl + h) / (4.0 * h), kd * (tl + h) / (2.0 * h)


@njit(cache=True)
def _strain(r, E, j):
    dx = r[j + 1, 0] - r[j, 0]
    dy = r[j + 1, 1] - r[j, 1]
    dz = r[j + 1, 2] - r[j, 2]
    return math.sqrt(dx * dx + dy * dy + dz * dz) / E[j, 0] - 1.0


@njit(cache=True)
def _set_mean(fs, j, em, P, E, S):
    """Mean strain ``em`` of element ``j`` and ``T_w``, ``EA_d`` at it into ``fs[j]`` (the
    slack strain ``e0`` as in :func:`kernels._line_forces`)."""
    o = int(E[j, EL_FIB])
    e0 = max(abs(P[j, 1]) + abs(P[j + 1, 1]), 1e-6) / E[j, 1]
    tm, _ = _working_slack(S, o, em, e0)
    fs[j, FS_EM] = em
    fs[j, FS_TM] = tm
    fs[j, FS_KD] = dynamic_stiffness(S, o, tm)


@njit(cache=True)
def fibre_commit(r, fs, P, E, S, h):
    """After an accepted step of ``h`` s: ``eps_m += (1 - exp(-h / tau)) (eps - eps_m)`` for
    every two-component element (``fs[j, FS_EM]``, and ``T_w``, ``EA_d`` at it)."""
    for j in range(r.shape[0] - 1):
        if E[j, EL_LAW] != LAW_TWO_COMPONENT:
            continue
        g = 1.0 - math.exp(-h / S[int(E[j, EL_FIB])])
        em = fs[j, FS_EM]
        _set_mean(fs, j, em + g * (_strain(r, E, j) - em), P, E, S)


@njit(cache=True)
def fibre_start(r, fs, P, E, S):
    """Mean strain of every two-component element at its current strain (start of the
    dynamics from a static state)."""
    for j in range(r.shape[0] - 1):
        if E[j, EL_LAW] == LAW_TWO_COMPONENT:
            _set_mean(fs, j, _strain(r, E, j), P, E, S)
