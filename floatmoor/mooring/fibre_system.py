"""Fibre-rope segments in the quasi-static mooring system: the working curve in statics and the
dynamic stiffness about the mean tension.

Statics (the mean offset): the elastic catenary of :mod:`floatmoor.mooring.catenary` has a
constant ``EA`` per segment. A fibre segment gets the **equivalent EA = secant of the working
curve at the segment's mean tension**, ``EA_eq = T_m / f_w^-1(T_m / MBS)``, iterated with the
catenary solution to a fixed point (:func:`iterate_secant`). ``T_m`` is the mean of the tension
over the segment's length (exact for the suspended catenary, ``T = sqrt(H^2 + V^2)`` with ``V``
linear along the segment; grounded parts count with ``H``, friction neglected). For a segment
of uniform tension (a taut, weightless segment) this is exact; with weight it is exact to first
order in the variation of the tangent stiffness along the segment (verified against the direct
integration of the extensible catenary with the nonlinear law in the tests).

Dynamics (the frequency domain and the quasi-static time domain): the line is linearised about
the mean position (:func:`linearised_segments`): every fibre segment gets a constant stiffness
``K`` (``K = EA_dyn(T_m)``, the rope's dynamic stiffness at its mean tension, or for the lower
bound the working curve's tangent) and an unstretched length and weight such that

* its stretched length at the mean tension is that of the working curve (the mean position and
  mean tensions are unchanged), and
* a small change of its stretched length ``dl`` changes its tension by ``K dl / L`` (``K`` is
  the stiffness per unit strain on the rope's own length ``L``)::

      L' = L (1 + eps_w(T_m) - T_m / K),   EA' = K L' / L,   w' = w L / L'.

This is the SIMA/Syrope rule of elongating the line so that the dynamic curve meets the working
curve at the mean tension (SINTEF Ocean (2023); Falkenberg et al. (2017)) and MoorPy's
``activateDynamicStiffness`` (Hall (2024)). The frequency domain uses it about the mean
(static-equilibrium) tension.

Quasi-static time domain: the same linearisation about a **slowly varying tension** ``T_s(t)``
of every fibre segment (:func:`fibre_track`, :func:`fibre_track_update`): ``T_s`` starts at the
mean tension of the static equilibrium and follows the segment's length-mean tension ``T``
through an exponential low-pass filter of time constant ``tau`` (mooring key
``fibre_time_constant``, :data:`DEFAULT_TIME_CONSTANT` = 300 s, the value and meaning of the
finite-element lines' mean-strain filter), advanced once per time step with the exact
exponential ``T_s += (1 - exp(-dt / tau)) (T - T_s)`` from the tension at the step's start
(the accepted pose), after which ``L', EA', w'`` are recomputed from ``T_s``.  A stretch much
slower than ``tau`` therefore moves along the working curve (at a fixed offset the tension
converges to the working-curve statics: ``L'(1 + T_s / EA') = L (1 + eps_w(T_s))``), while
wave-frequency stretches (periods << ``tau``) see ``K = EA_dyn(T_s)``.  Stretches with periods
near ``tau`` see a stiffness between the two (the same two-component behaviour as the FE
lines' law).  ``tau = inf`` keeps the linearisation about the static mean for the whole run
(the rule before; the frequency domain's).  The first RK4 stage of a step uses the
linearisation before that step's update (a lag of under one step, ``dt / tau`` ~ 3e-4 at
dt = 0.1 s).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np
from numba import njit
from numba.extending import overload

from ..core.errors import ConvergenceError
from .catenary import OUT_HF, OUT_VF
from .fibre import dynamic_ea_nb, table_inverse_nb, table_slope_nb

__all__ = ["FibreSegments", "segment_mean_tensions", "iterate_secant", "linearised_segments",
           "RULES", "DEFAULT_TIME_CONSTANT", "FibreTrack", "NoFibre", "fibre_track",
           "no_fibre_track", "fibre_track_update", "fibre_step"]

RULES = ("dynamic", "tangent")
"""Linearisation rules: the fibre model's dynamic stiffness, or the working-curve tangent."""

SECANT_TOL = 1e-12
SECANT_MAX_ITER = 100
SECANT_ACCEPT = 1e-8
"""Largest relative EA change accepted when the iteration cap is reached."""


@dataclass(frozen=True, kw_only=True)
class FibreSegments:
    """The fibre segments of a system: their indices in the segment arrays, models, MBS and
    working-curve tables."""

    index: np.ndarray
    models: tuple
    mbs: np.ndarray
    tables: tuple

    @classmethod
    def of(cls, segments) -> FibreSegments | None:
        """From the flat list of segments; None when no segment has a fibre model."""
        idx = [j for j, s in enumerate(segments) if getattr(s, "fibre", None) is not None]
        if not idx:
            return None
        for j in idx:
            if not math.isfinite(segments[j].mbs):
                raise ValueError(f"segment {j} ({segments[j].line_type!r}) has a fibre model but "
                                 "no MBS (the curves are in fractions of MBS)")
        models = tuple(segments[j].fibre for j in idx)
        return cls(index=np.array(idx, np.int64), models=models,
                   mbs=np.array([segments[j].mbs for j in idx], float),
                   tables=tuple(m.working_arrays() for m in models))

    def bed_in(self, seg_L, seg_w) -> None:
        """Lengthen the fibre segments by their permanent strain after the largest mean
        tension of their model (:meth:`FibreModel.length_factor`), in place; the weight per
        length shrinks so that the segment's weight is unchanged."""
        for k, j in enumerate(self.index):
            f = self.models[k].length_factor(self.mbs[k])
            seg_L[j] *= f
            seg_w[j] /= f


@njit(cache=True)
def _mean_tension(H, Vt, Vb):
    """Mean of ``sqrt(H^2 + max(V, 0)^2)`` for ``V`` linear from ``Vb`` to ``Vt``."""
    if Vt < Vb:
        Vt, Vb = Vb, Vt
    h = H if H > 1e-9 else 1e-9
    if Vt - Vb <= 1e-12 * (abs(Vt) + h):
        v = Vt if Vt > 0.0 else 0.0
        return math.sqrt(h * h + v * v)
    hi = Vt if Vt > 0.0 else 0.0
    lo = Vb if Vb > 0.0 else 0.0
    f_hi = 0.5 * (hi * math.sqrt(h * h + hi * hi) + h * h * math.asinh(hi / h))
    f_lo = 0.5 * (lo * math.sqrt(h * h + lo * lo) + h * h * math.asinh(lo / h))
    neg = (lo - Vb) if Vb < 0.0 else 0.0  # part with V <= 0 (on the seabed): tension h
    if Vt < 0.0:
        neg = Vt - Vb
    return (f_hi - f_lo + h * neg) / (Vt - Vb)


@njit(cache=True)
def segment_mean_tensions(line_out, seg_L, seg_w, seg_P, line_start, active, out):
    """Length-mean tension of every segment (N) from the lines' fairlead tensions ``HF, VF``
    in ``line_out`` (written into ``out``; 0 for inactive lines)."""
    n = line_start.shape[0] - 1
    for i in range(n):
        a = line_start[i]
        b = line_start[i + 1]
        if not active[i]:
            for j in range(a, b):
                out[j] = 0.0
            continue
        H = line_out[i, OUT_HF]
        vt = line_out[i, OUT_VF]
        for j in range(b - 1, a - 1, -1):
            vb = vt - seg_w[j] * seg_L[j]
            out[j] = _mean_tension(H, vt, vb)
            if j > a:
                vt = vb - seg_P[j - 1]


def _mean_tensions(system) -> np.ndarray:
    out = np.zeros(system.seg_L.shape[0])
    segment_mean_tensions(system._line_out, system.seg_L, system.seg_w, system.seg_P,
                          system.line_start, system.active, out)
    return out


def iterate_secant(system, evaluate) -> int:
    """Set the fibre segments' ``seg_EA`` to the working-curve secant at their mean tension,
    re-evaluating the system (``evaluate()``, one catenary solve per line) until the EAs change by
    less than ``SECANT_TOL`` (relative). Returns the number of extra evaluations."""
    fs = system.fibre_segments
    for it in range(SECANT_MAX_ITER):
        tm = _mean_tensions(system)
        change = 0.0
        for k, j in enumerate(fs.index):
            xs, ys = fs.tables[k]
            t = tm[j]
            if t > 0.0:
                ea = t / table_inverse_nb(t / fs.mbs[k], xs, ys)
            else:
                ea = fs.mbs[k] * (ys[1] - ys[0]) / (xs[1] - xs[0])
            change = max(change, abs(ea - system.seg_EA[j]) / ea)
            system.seg_EA[j] = ea
        if change <= SECANT_TOL:
            return it
        evaluate()
    if change > SECANT_ACCEPT:
        raise ConvergenceError(
            f"fibre rope: the secant EA of the working curve changed by {change:.2g} after "
            f"{SECANT_MAX_ITER} iterations", where="mooring statics (fibre segments)",
            remedy="check the working curve (strictly increasing, no near-flat part) and the "
                   "line lengths")
    return SECANT_MAX_ITER


def linearised_segments(system, rule: str = "dynamic"):
    """``(L', EA', w')`` arrays of all segments, the fibre ones linearised about the mean
    tensions of the system's last evaluation (module docstring); other segments unchanged."""
    if rule not in RULES:
        raise ValueError(f"rule must be one of {RULES}, found {rule!r}")
    fs = system.fibre_segments
    L = system.seg_L.copy()
    EA = system.seg_EA.copy()
    w = system.seg_w.copy()
    tm = _mean_tensions(system)
    for k, j in enumerate(fs.index):
        xs, ys = fs.tables[k]
        mbs = fs.mbs[k]
        t = max(tm[j], 0.0)
        eps = table_inverse_nb(t / mbs, xs, ys)
        if rule == "tangent":
            K = mbs * table_slope_nb(eps, xs, ys)
        else:
            K = float(fs.models[k].dynamic_ea(t, mbs))
        f = 1.0 + eps - t / K
        if f <= 0.0:
            raise ValueError(f"fibre segment {j}: mean tension {t:.4g} N too large for the "
                             f"stiffness {K:.4g} N (negative linearised length)")
        L[j] = system.seg_L[j] * f
        EA[j] = K * f
        w[j] = system.seg_w[j] / f
    return L, EA, w


def linearised_lines(system, rule: str = "dynamic"):
    """The system's :class:`LineDef` list with the fibre segments replaced by their constant-EA
    linearisation (:func:`linearised_segments`; ``fibre`` removed)."""
    L, EA, w = linearised_segments(system, rule)
    lines = []
    j = 0
    for line in system.lines:
        segs = []
        for s in line.segments:
            if s.fibre is not None:
                f = float(L[j]) / s.length
                s = replace(s, length=float(L[j]), ea=float(EA[j]), w=float(w[j]), fibre=None,
                            mass_per_length=s.mass_per_length / f)
            segs.append(s)
            j += 1
        lines.append(replace(line, segments=tuple(segs)))
    return lines


# --------------------------------------------------------------------------------------------
# The quasi-static time domain: the linearisation about a slowly varying tension
# --------------------------------------------------------------------------------------------
DEFAULT_TIME_CONSTANT = 300.0
"""s, time constant of the slowly varying tension of the quasi-static time domain (the same
name and value as the finite-element lines' mean-strain filter, ``finite_element:
fibre_time_constant``): over 10 times the wave periods; ``inf`` keeps the linearisation about
the static mean for the whole run."""


class FibreTrack(NamedTuple):
    """The fibre segments of the time loop (numba bundle, :func:`fibre_track`): ``on`` (False:
    nothing to do, the fixed-mean rule); ``gain`` ``1 - exp(-dt / tau)``; per fibre segment k
    (k,): ``index`` its segment, ``line_of`` its line, ``L0``, ``w0`` its (bedded-in) length and
    weight per length, ``mbs``, ``alpha``, ``beta`` (:class:`~floatmoor.mooring.fibre.
    FibreModel`), ``tangent`` (True: the working-curve tangent, the ``lower`` bound),
    ``n_tab`` and ``xs``, ``ys`` (k, m) the working curve (strain, tension / MBS; padded);
    state ``ts`` (k,) the slowly varying tensions, N; work ``t_seg`` (N,) segment tensions."""

    on: bool
    gain: float
    index: np.ndarray
    line_of: np.ndarray
    L0: np.ndarray
    w0: np.ndarray
    mbs: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    tangent: np.ndarray
    n_tab: np.ndarray
    xs: np.ndarray
    ys: np.ndarray
    ts: np.ndarray
    t_seg: np.ndarray


class NoFibre(NamedTuple):
    """The fibre bundle of a run whose linearisation does not move (no fibre segment, the
    fixed-mean rule, or coupled FE lines; ``on`` False).  A type of its own: the time loop
    compiled for it leaves the fibre update out (:func:`fibre_step` chooses on the bundle's
    type), so such a run does not compile it."""

    on: bool


def no_fibre_track() -> NoFibre:
    """The fibre bundle of a run without a moving linearisation (:class:`NoFibre`)."""
    return NoFibre(False)


def fibre_track(system, tau: float, dt: float, tm=None) -> FibreTrack:
    """The :class:`FibreTrack` of ``system`` (the nonlinear fibre system) for time constant
    ``tau`` (s; ``inf``: off) and time step ``dt`` (s); ``ts`` starts at the segment mean
    tensions ``tm`` (N,) at the linearisation point (default: those of the system's last
    evaluation)."""
    fs = system.fibre_segments
    if fs is None or not tau < math.inf:
        return no_fibre_track()
    if not tau > 0.0:
        raise ValueError(f"fibre_time_constant must be > 0 s, found {tau}")
    k = fs.index.shape[0]
    m = max(t[0].shape[0] for t in fs.tables)
    xs = np.zeros((k, m))
    ys = np.zeros((k, m))
    n_tab = np.zeros(k, np.int64)
    for q, (x, y) in enumerate(fs.tables):
        n_tab[q] = x.shape[0]
        xs[q, :x.shape[0]] = x
        ys[q, :y.shape[0]] = y
    line_of = np.searchsorted(system.line_start, fs.index, side="right").astype(np.int64) - 1
    tm = _mean_tensions(system) if tm is None else np.asarray(tm, float)
    return FibreTrack(True, float(-math.expm1(-dt / tau)), fs.index.astype(np.int64).copy(),
                      line_of, system.seg_L[fs.index].copy(), system.seg_w[fs.index].copy(),
                      fs.mbs.copy(), np.array([mo.alpha for mo in fs.models], float),
                      np.array([mo.beta for mo in fs.models], float),
                      np.array([mo.bound == "lower" for mo in fs.models], np.bool_), n_tab, xs,
                      ys, tm[fs.index].copy(), np.zeros(system.seg_L.shape[0]))


@njit(cache=True, inline='always')
def fibre_track_update(fib, cat, active, line_out):
    """One step of the slowly varying tensions and the linearisation about them (no
    allocation): the segments' length-mean tensions ``T`` from the lines' fairlead tensions in
    ``line_out`` (at the accepted state), ``T_s += gain (T - T_s)`` (the exact exponential
    filter of the step), then ``L' = L0 (1 + eps_w(T_s) - T_s / K)``, ``EA' = K L' / L0``,
    ``w' = w0 L0 / L'`` with ``K = EA_dyn(T_s)`` written into the catenary arrays ``cat``
    (:class:`~floatmoor.mooring.system.CatenaryArrays`). Segments of failed lines are left."""
    segment_mean_tensions(line_out, cat.seg_L, cat.seg_w, cat.seg_P, cat.line_start, active,
                          fib.t_seg)
    for k in range(fib.index.shape[0]):
        if not active[fib.line_of[k]]:
            continue
        j = fib.index[k]
        ts = fib.ts[k] + fib.gain * (fib.t_seg[j] - fib.ts[k])
        fib.ts[k] = ts
        t = ts if ts > 0.0 else 0.0
        mbs = fib.mbs[k]
        nt = fib.n_tab[k]
        xs = fib.xs[k, :nt]
        ys = fib.ys[k, :nt]
        eps = table_inverse_nb(t / mbs, xs, ys)
        if fib.tangent[k]:
            K = mbs * table_slope_nb(eps, xs, ys)
        else:
            K = dynamic_ea_nb(t, mbs, fib.alpha[k], fib.beta[k])
        f = 1.0 + eps - t / K
        if f > 0.0:
            cat.seg_L[j] = fib.L0[k] * f
            cat.seg_EA[j] = K * f
            cat.seg_w[j] = fib.w0[k] / f


def fibre_step(fib, cat, active, line_out):
    """:func:`fibre_track_update` for a :class:`FibreTrack` bundle that is ``on``; nothing for
    a :class:`NoFibre` one.  Compiled, the choice is made on the bundle's type
    (:func:`_fibre_step_typed`): a time loop compiled for a run without fibre tracking neither
    contains nor compiles the fibre code."""
    if fib.on:
        fibre_track_update(fib, cat, active, line_out)


@overload(fibre_step)
def _fibre_step_typed(fib, cat, active, line_out):
    if getattr(fib, "instance_class", None) is NoFibre:
        def nothing(fib, cat, active, line_out):
            return None
        return nothing

    def update(fib, cat, active, line_out):
        if fib.on:
            fibre_track_update(fib, cat, active, line_out)
    return update
