"""Fibre (polyester) rope stiffness: quasi-static tension-strain curves and the mean-load
dependent dynamic stiffness.

The model (after the Syrope method as implemented in SIMA, SINTEF Ocean (2023), and
Falkenberg et al. (2017); MoorPy's ``EAd + EAd_Lm * T_mean``, Hall (2024)):

* **Quasi-static working curve** ``T/MBS = f_w(strain)``: the tension-strain curve of a rope
  already bedded in (the curve it follows under slow loading below the largest mean load it has
  seen). Given as a table (piecewise linear, linear extrapolation with the end slopes) starting
  at ``(0, 0)``; the strain is on the rope length *after* bedding in (the length a scene gives).
* **Original curve** ``T/MBS = f_o(strain)`` (optional): the first-loading curve of a new rope
  (strain on the new length). After a largest tension ``T_max`` the rope has the permanent
  strain ``eps_perm = f_o^-1(T_max) - f_w^-1(T_max)`` and unloads/reloads on the working curve
  shifted by ``eps_perm`` (SINTEF Ocean (2023): "shifting the WC along the strain axis until
  OWC and WC intercept at Tmax"); loading beyond ``T_max`` follows the original curve again.
* **Dynamic stiffness** about a mean tension ``T_mean`` (the Syrope / DNV-OS-E303 linear
  mean-load model)::

      EA_dyn / MBS = alpha + beta * L_m,    L_m = 100 * T_mean / MBS   (mean load in % MBS)

  ``alpha`` is dimensionless (EA over MBS), ``beta`` per % MBS. MoorPy's form
  ``EAd = EAd_MBL * MBS + EAd_Lm * T_mean`` is the same with ``alpha = EAd_MBL`` and
  ``beta = EAd_Lm / 100``.

Stiffness bounds (:meth:`FibreModel.lower`, :meth:`FibreModel.upper`): DNV-OS-E301 and
API RP 2SM ask for the mean offset with the static (post-installation) stiffness and the
dynamic tension with the storm (dynamic) stiffness, checking the offsets with the lower and the
tensions with the upper bound (DNV (2008) Ch.2 Sec.2; API RP 2SM; clause numbers unverified).
floatmoor's rule:

* ``lower``: the working curve for everything; the "dynamic" stiffness about a mean tension is
  the working curve's tangent there (slow, quasi-static response: largest offsets);
* ``upper``: the working curve for the mean, ``alpha + beta * L_m`` for the dynamic part
  (storm dynamic stiffness: largest dynamic tensions). This is also the nominal model.

Values of the shipped ``polyester_default`` preset (:data:`POLYESTER_DEFAULT`): ``alpha = 11.6``,
``beta = 0.40`` per % MBS from MoorPy's polyester line-property library (Hall (2024):
``EAd_MBL 11.6``, ``EAd_Lm 40``); the working and original curves are **illustrative**, shaped
so that the working-curve secant stiffness is about 13-14 MBS at 20-30 % MBS (MoorPy's quasi-
static ``EA_MBL 14``; DNV-OS-E303 / API RP 2SM quote 10-20 MBS for the static stiffness of
polyester) and the original curve has about 2 % more strain at 30 % MBS (bedding-in). Replace
them with the rope maker's test data for design.

All functions below are plain numpy/math; the ``*_nb`` helpers are ``@njit`` so kernels may
call them with the table arrays.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from numba import njit

__all__ = ["FibreModel", "POLYESTER_DEFAULT", "PRESETS", "table_value_nb", "table_inverse_nb",
           "table_slope_nb", "table_lookup_nb", "table_segment_nb", "dynamic_ea_nb", "BOUNDS",
           "unit_problems"]

BOUNDS = ("nominal", "lower", "upper")
"""Stiffness bounds a :class:`FibreModel` may carry."""


@njit(cache=True)
def _bracket(x, xs):
    """Indices ``(lo, lo + 1)`` of the interval of increasing ``xs`` holding ``x`` (bisection;
    ``xs[lo] <= x``), for ``xs[0] < x < xs[-1]``."""
    lo = 0
    hi = xs.shape[0] - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo, hi


@njit(cache=True)
def table_value_nb(x, xs, ys):
    """Piecewise-linear ``y(x)`` of a table with increasing ``xs``; linear extrapolation with
    the first/last slope outside it."""
    n = xs.shape[0]
    if x <= xs[0]:
        return ys[0] + (x - xs[0]) * (ys[1] - ys[0]) / (xs[1] - xs[0])
    if x >= xs[n - 1]:
        return ys[n - 1] + (x - xs[n - 1]) * (ys[n - 1] - ys[n - 2]) / (xs[n - 1] - xs[n - 2])
    lo, hi = _bracket(x, xs)
    return ys[lo] + (x - xs[lo]) * (ys[hi] - ys[lo]) / (xs[hi] - xs[lo])


@njit(cache=True)
def table_inverse_nb(y, xs, ys):
    """Inverse ``x(y)`` of a table with increasing ``xs`` and ``ys`` (same extrapolation)."""
    return table_value_nb(y, ys, xs)


@njit(cache=True)
def table_segment_nb(x, xs):
    """Index ``lo`` of the segment ``[xs[lo], xs[lo + 1]]`` of a table with increasing ``xs``
    that holds ``x``.  Convention (every fibre table lookup, quasi-static and FE): at an
    interior node the segment to its *right* (``xs[lo] <= x < xs[lo + 1]``: the slope there is
    the right derivative, the tangent for an increasing load); below the table the first and
    from its last node on the last segment (linear extrapolation)."""
    n = xs.shape[0]
    if x < xs[1]:
        return 0
    if x >= xs[n - 2]:
        return n - 2
    return _bracket(x, xs)[0]


@njit(cache=True)
def table_lookup_nb(x, xs, ys):
    """Piecewise-linear ``y(x)`` and its slope ``dy/dx`` on the segment of
    :func:`table_segment_nb` (right derivative at a node)."""
    lo = table_segment_nb(x, xs)
    x0 = xs[lo]
    y0 = ys[lo]
    d = (ys[lo + 1] - y0) / (xs[lo + 1] - x0)
    return y0 + d * (x - x0), d


@njit(cache=True)
def table_slope_nb(x, xs, ys):
    """Slope ``dy/dx`` of the piecewise-linear table at ``x`` (right derivative at a node,
    :func:`table_segment_nb`)."""
    return table_lookup_nb(x, xs, ys)[1]


@njit(cache=True)
def dynamic_ea_nb(mean_tension, mbs, alpha, beta):
    """``EA_dyn = MBS (alpha + beta * 100 T_mean / MBS)``, N (the mean tension floored at 0)."""
    tm = mean_tension if mean_tension > 0.0 else 0.0
    return mbs * alpha + beta * 100.0 * tm


def _check_curve(strain, tension, what):
    s = np.asarray(strain, float)
    t = np.asarray(tension, float)
    if s.ndim != 1 or s.shape != t.shape or s.size < 2:
        raise ValueError(f"{what}: strain and tension_mbs must be lists of the same length >= 2")
    if not (np.all(np.isfinite(s)) and np.all(np.isfinite(t))):
        raise ValueError(f"{what}: finite numbers expected")
    if s[0] != 0.0 or t[0] != 0.0:
        raise ValueError(f"{what}: the curve must start at (0, 0), found ({s[0]}, {t[0]})")
    if np.any(np.diff(s) <= 0.0) or np.any(np.diff(t) <= 0.0):
        raise ValueError(f"{what}: strain and tension must both increase strictly")
    return s, t


@dataclass(frozen=True, kw_only=True)
class FibreModel:
    """Load-dependent stiffness of a fibre rope (see the module docstring for the model).

    Attributes
    ----------
    working_strain, working_tension_mbs : tuple of float
        Quasi-static working curve: strain (-) and tension as a fraction of MBS, strictly
        increasing, starting at ``(0, 0)``.
    original_strain, original_tension_mbs : tuple of float or None
        First-loading (original) curve in the same form; both or neither.
    alpha : float
        Dynamic stiffness at zero mean load over MBS (-).
    beta : float
        Growth of the dynamic stiffness over MBS per % MBS of mean load.
    source : str
        Where the numbers come from.
    max_tension_mbs : float
        Largest mean tension the rope has seen, fraction of MBS (0: the length a scene gives is
        already the bedded-in length). With an original curve, the statics lengthen the segment
        by the permanent strain after that tension (:meth:`length_factor`), as SIMA does before
        its static analysis (SINTEF Ocean (2023)); the working curve then applies to the strain
        on the lengthened segment (the shift of the curve to first order in that strain).
    bound : str
        ``nominal`` (= ``upper``) or ``lower`` (dynamic stiffness = working-curve tangent).
    """

    working_strain: tuple
    working_tension_mbs: tuple
    original_strain: tuple | None = None
    original_tension_mbs: tuple | None = None
    alpha: float
    beta: float
    source: str = ""
    max_tension_mbs: float = 0.0
    bound: str = "nominal"

    def __post_init__(self):
        _check_curve(self.working_strain, self.working_tension_mbs, "working curve")
        if (self.original_strain is None) != (self.original_tension_mbs is None):
            raise ValueError("original curve: give both original_strain and original_tension_mbs")
        if self.original_strain is not None:
            _check_curve(self.original_strain, self.original_tension_mbs, "original curve")
        if not (math.isfinite(self.alpha) and self.alpha > 0.0):
            raise ValueError(f"alpha must be a positive number, found {self.alpha}")
        if not (math.isfinite(self.beta) and self.beta >= 0.0):
            raise ValueError(f"beta must be a number >= 0, found {self.beta}")
        if not (math.isfinite(self.max_tension_mbs) and 0.0 <= self.max_tension_mbs < 1.0):
            raise ValueError(f"max_tension_mbs must be in [0, 1), found {self.max_tension_mbs}")
        if self.max_tension_mbs > 0.0 and self.original_strain is None:
            raise ValueError("max_tension_mbs needs the original curve (the permanent strain "
                             "is the gap between the original and the working curve)")
        if self.bound not in BOUNDS:
            raise ValueError(f"bound must be one of {BOUNDS}, found {self.bound!r}")
        object.__setattr__(self, "working_strain", tuple(float(x) for x in self.working_strain))
        object.__setattr__(self, "working_tension_mbs",
                           tuple(float(x) for x in self.working_tension_mbs))
        if self.original_strain is not None:
            object.__setattr__(self, "original_strain",
                               tuple(float(x) for x in self.original_strain))
            object.__setattr__(self, "original_tension_mbs",
                               tuple(float(x) for x in self.original_tension_mbs))

    # -- tables as arrays (for kernels) ---------------------------------------------------
    def working_arrays(self):
        """``(strain, tension_mbs)`` of the working curve as float arrays."""
        return (np.array(self.working_strain, float), np.array(self.working_tension_mbs, float))

    def original_arrays(self):
        """``(strain, tension_mbs)`` of the original curve (the working curve if none given)."""
        if self.original_strain is None:
            return self.working_arrays()
        return (np.array(self.original_strain, float), np.array(self.original_tension_mbs, float))

    # -- quasi-static working curve -------------------------------------------------------
    def static_tension(self, strain, mbs):
        """Tension (N) on the working curve at ``strain`` (scalar or array)."""
        xs, ys = self.working_arrays()
        return mbs * np.vectorize(lambda e: table_value_nb(float(e), xs, ys))(strain)[()]

    def static_strain(self, tension, mbs):
        """Strain on the working curve at ``tension`` (N; scalar or array)."""
        xs, ys = self.working_arrays()
        return np.vectorize(lambda t: table_inverse_nb(float(t) / mbs, xs, ys))(tension)[()]

    def static_ea(self, tension, mbs):
        """Tangent stiffness ``dT/d(strain)`` (N) of the working curve at ``tension``."""
        xs, ys = self.working_arrays()
        return mbs * np.vectorize(
            lambda t: table_slope_nb(table_inverse_nb(float(t) / mbs, xs, ys), xs, ys))(tension)[()]

    def secant_ea(self, tension, mbs):
        """Secant stiffness ``T / strain`` (N) of the working curve at ``tension`` (> 0; the
        initial slope at 0): the equivalent constant EA giving the working-curve strain."""
        xs, ys = self.working_arrays()

        def one(t):
            if t <= 0.0:
                return mbs * (ys[1] - ys[0]) / (xs[1] - xs[0])
            return float(t) / table_inverse_nb(float(t) / mbs, xs, ys)
        return np.vectorize(one)(tension)[()]

    # -- dynamic stiffness ----------------------------------------------------------------
    def dynamic_ea(self, mean_tension, mbs):
        """Dynamic axial stiffness (N) about ``mean_tension`` (N): ``MBS (alpha + beta L_m)``
        with ``L_m`` the mean load in % MBS; for the ``lower`` bound the working-curve tangent
        at the mean tension."""
        if self.bound == "lower":
            return self.static_ea(mean_tension, mbs)
        return np.vectorize(lambda t: dynamic_ea_nb(float(t), mbs, self.alpha, self.beta))(
            mean_tension)[()]

    # -- load history ---------------------------------------------------------------------
    def permanent_strain(self, t_max, mbs):
        """Permanent strain after a largest tension ``t_max`` (N): ``f_o^-1 - f_w^-1`` at
        ``t_max`` (0 without an original curve)."""
        if self.original_strain is None or t_max <= 0.0:
            return 0.0
        xo, yo = self.original_arrays()
        xw, yw = self.working_arrays()
        return max(table_inverse_nb(t_max / mbs, xo, yo) - table_inverse_nb(t_max / mbs, xw, yw),
                   0.0)

    def length_factor(self, mbs) -> float:
        """``1 + permanent strain`` after ``max_tension_mbs``: the factor the statics apply to
        the segment's (new-rope) length."""
        return 1.0 + self.permanent_strain(self.max_tension_mbs * mbs, mbs)

    def quasi_static_path(self, strain, mbs):
        """Tensions (N) along a slow strain history (strain on the *new* rope length).

        Loading beyond the largest strain seen follows the original curve; below it the rope
        follows the working curve shifted by the permanent strain of the largest tension seen
        (zero tension when slack). Without an original curve this is the working curve.
        """
        xo, yo = self.original_arrays()
        xw, yw = self.working_arrays()
        strain = np.asarray(strain, float)
        out = np.empty_like(strain)
        e_max = 0.0
        for i, e in enumerate(strain):
            if e >= e_max:
                e_max = e
                out[i] = mbs * max(table_value_nb(e, xo, yo), 0.0)
            else:
                t_max = mbs * table_value_nb(e_max, xo, yo)
                e_perm = self.permanent_strain(t_max, mbs)
                out[i] = mbs * max(table_value_nb(e - e_perm, xw, yw), 0.0) if e > e_perm else 0.0
        return out

    # -- bounds ---------------------------------------------------------------------------
    def lower(self) -> FibreModel:
        """Lower stiffness bound: the working curve also for the dynamic stiffness."""
        return replace(self, bound="lower")

    def upper(self) -> FibreModel:
        """Upper stiffness bound: the storm dynamic stiffness ``alpha + beta L_m``."""
        return replace(self, bound="upper")


# -- plausibility of the parameters (units) -----------------------------------------------------
MAX_STRAIN = 0.5
"""Largest strain (-) a tension-strain curve may reach: fibre ropes break at 10-30 % strain
(nylon the most); a curve beyond 50 % is a strain given in percent."""

MAX_TENSION_MBS = 1.5
"""Largest tension of a curve as a fraction of MBS (the rope breaks at 1); above it, a tension
in kN, N or % MBS."""

STIFFNESS_MBS = (0.5, 200.0)
"""Range of a fibre rope's axial stiffness over its MBS (EA/MBS, -) accepted for the working
curve's secant and for the dynamic stiffness ``alpha + beta L_m`` up to L_m = 50 % MBS:
MoorPy's library (Hall (2024)) gives static 5 (nylon, 1-10), 14 (polyester), 56 (HMPE) and
dynamic 2.08, 11.6 and 59 at zero mean load.  A strain in percent makes the curve 100 times
softer, an ``alpha`` given as an EA in N or a ``beta`` per unit (not per %) of the mean load
far stiffer."""

MAX_BETA = 2.0
"""Largest ``beta`` (per % MBS of mean load): MoorPy's library gives 0.39-0.54 (its EAd_Lm of
39-54 is per unit of mean load, i.e. 100 times beta)."""


def unit_problems(model: FibreModel) -> list[tuple[str, str, object, str]]:
    """Parameters of ``model`` that are out of a fibre rope's physical range, as
    ``(key, expected, found, hint)`` (keys of the ``fibre:`` entry of a line type); empty
    when plausible.  The usual cause is a unit: strain in percent, tension in kN or % MBS,
    ``alpha`` as an EA in N, ``beta`` per unit of the mean load."""
    out = []
    lo, hi = STIFFNESS_MBS
    for name, xs, ys in (("working_curve", model.working_strain, model.working_tension_mbs),
                         ("original_curve", model.original_strain,
                          model.original_tension_mbs)):
        if xs is None:
            continue
        if max(xs) > MAX_STRAIN:
            out.append((f"{name}.strain", f"strains (-) up to at most {MAX_STRAIN:g} (fibre "
                        "ropes break at 10-30 % strain)", max(xs), "a strain given in percent? "
                        "give it as a fraction: 2 % is 0.02"))
            continue
        if max(ys) > MAX_TENSION_MBS:
            out.append((f"{name}.tension_mbs", f"tensions as a fraction of MBS, at most "
                        f"{MAX_TENSION_MBS:g} (the rope breaks at 1)", max(ys),
                        "a tension in kN, N or % of MBS? give T/MBS: 30 % MBS is 0.3"))
            continue
        secant = ys[-1] / xs[-1]
        if not lo <= secant <= hi:
            out.append((f"{name}.strain", f"a curve whose secant stiffness T/(MBS strain) is "
                        f"{lo:g}-{hi:g} MBS (fibre ropes: about 5-60)", f"{secant:.4g} MBS at "
                        f"strain {xs[-1]:g}", "a strain in percent, or a tension not over MBS?"))
    if not model.alpha <= hi:
        out.append(("dynamic.alpha", f"the dynamic stiffness at zero mean load over MBS "
                    f"(EA_dyn/MBS, -), at most {hi:g} (MoorPy: 2.08 nylon, 11.6 polyester, 59 "
                    "HMPE)", model.alpha, "an EA in N? give EA_dyn / MBS"))
    elif not model.beta <= MAX_BETA:
        out.append(("dynamic.beta", f"the growth of EA_dyn/MBS per % MBS of mean load, at "
                    f"most {MAX_BETA:g} (MoorPy: 0.39-0.54)", model.beta,
                    f"per unit of mean load? MoorPy's EAd_Lm {model.beta:g} is beta "
                    f"{model.beta / 100:g} per %"))
    elif not lo <= model.alpha + model.beta * 50.0 <= hi:
        out.append(("dynamic.alpha", f"a dynamic stiffness alpha + beta L_m of {lo:g}-{hi:g} "
                    "MBS up to a mean load of 50 % MBS", model.alpha,
                    f"alpha + 50 beta = {model.alpha + 50 * model.beta:.4g}"))
    return out


POLYESTER_DEFAULT = FibreModel(
    working_strain=(0.0, 0.005, 0.010, 0.015, 0.020, 0.025, 0.030, 0.040, 0.050, 0.060),
    working_tension_mbs=(0.0, 0.05, 0.12, 0.20, 0.28, 0.36, 0.44, 0.60, 0.76, 0.92),
    original_strain=(0.0, 0.010, 0.020, 0.030, 0.040, 0.050, 0.060, 0.070, 0.080),
    original_tension_mbs=(0.0, 0.05, 0.12, 0.20, 0.29, 0.39, 0.50, 0.62, 0.75),
    alpha=11.6, beta=0.40,
    source="alpha, beta: MoorPy polyester line properties, Hall (2024) (EAd_MBL 11.6, EAd_Lm 40); "
           "working and original curves illustrative (secant about 14 MBS at 20-30 % MBS)")
"""The shipped polyester preset (``fibre: polyester_default`` in a line-type entry)."""

PRESETS = {"polyester_default": POLYESTER_DEFAULT}
"""Named fibre models a line-type entry may use."""
