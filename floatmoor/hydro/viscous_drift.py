"""Viscous correction of the mean wave drift coefficients: the EXWAVE formula (eq. 6.6).

Stansberg et al. (2015, EXWAVE JIP), as quoted in Wang (2016), section 6.2, eq. 6.6,
corrects the potential-flow mean drift coefficients of a column-stabilised unit for high waves
and a current ``U`` along the waves::

    f_d(w) = F_d(w, U, Hs) / A^2 = f_d,pot(w) (1 + C_p U) + B(w) (G U + Hs)

    B(w) = B0 k p sum(d_i),   k = w^2 / g,   p = exp(-1.25 (k D0)^2)

with

* ``f_d,pot`` the potential-flow mean drift coefficient (N/m^2 per squared amplitude),
* ``C_p = 0.25 s/m`` the potential-flow wave-current interaction coefficient,
* ``G = 10 s`` the empirical viscous wave-current interaction parameter,
* ``Hs`` the significant wave height (m), ``U`` the current component along the waves (m/s),
* ``d_i`` the diameters (widths) of the surface-piercing columns (m), ``D0`` the diameter of the
  main columns (m); ``p`` removes the viscous part in short waves (large ``k D0``),
* ``k`` the deep-water wave number (rad/m), as in eq. 6.6.

Units of B.  ``k p sum(d_i)`` is dimensionless; Wang (2016) gives B in kN/m^3 ("[kN/m^3]" next to
p), i.e. ``B = B0 k p sum(d_i)`` with ``B0 = 1 kN/m^3 = 1000 N/m^3``; then ``B (G U + Hs)`` is in
N/m^2 like f_d,pot.  ``B0`` is a parameter (:attr:`CorrectionFormula.b0`) so that a user with the
original paper's constant can set it; 1000 N/m^3 is this module's reading of Wang (2016), not a
verified published value.

How the formula is applied to a 6-DOF database (our choices, documented in the report):

* the factor ``(1 + C_p U)`` multiplies the potential coefficients of all six DOFs;
* the viscous term is a force along the direction of wave travel: ``B (G U + Hs) cos(beta)`` is
  added to surge and ``B (G U + Hs) sin(beta)`` to sway, beta the wave direction relative to
  the body (the database's ``wave_direction``); no viscous moment is added;
* ``U = U_c cos(psi_c - yaw - beta)`` is the current component along each wave direction
  (``psi_c`` the current heading, earth; ``yaw`` the body heading); a current against the waves
  gives U < 0 and reduces both terms (the formula is used as written, without clipping).

The corrected coefficients replace ``mean_drift_force`` for both the time domain (Newman's
approximation uses them on and off the diagonal) and the frequency domain (mean drift
``2 int S(w) f_d(w) dw`` and the slow-drift spectrum).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.constants import GRAVITY
from ..core.errors import SceneError

__all__ = ["CorrectionFormula", "viscous_drift_b", "corrected_coefficients",
           "corrected_mean_drift", "extra_linear_damping"]


@dataclass(frozen=True, kw_only=True)
class CorrectionFormula:
    """Parameters of eq. 6.6 (SI units).

    column_diameters : diameters / widths d_i (m) of the surface-piercing columns (sum(d_i)).
    main_column_diameter : D0 (m) in p = exp(-1.25 (k D0)^2).
    cp : C_p (s/m), default 0.25.
    g_time : G (s), default 10.
    b0 : B0 (N/m^3), default 1000 (Wang's (2016) kN/m^3, see the module docstring).
    gravity : g (m/s^2) in k = w^2/g.
    """

    column_diameters: tuple
    main_column_diameter: float
    cp: float = 0.25
    g_time: float = 10.0
    b0: float = 1000.0
    gravity: float = GRAVITY

    def __post_init__(self):
        d = np.asarray(self.column_diameters, float).reshape(-1)
        if d.size == 0 or np.any(~np.isfinite(d)) or np.any(d <= 0.0):
            raise SceneError(None, "viscous_drift.column_diameters",
                             "a list of column diameters > 0 (m)", self.column_diameters)
        object.__setattr__(self, "column_diameters", tuple(float(x) for x in d))
        for name, lo in (("main_column_diameter", 0.0), ("b0", -1.0), ("gravity", 0.0)):
            v = getattr(self, name)
            if not (math.isfinite(v) and v > lo):
                raise SceneError(None, f"viscous_drift.{name}", f"a number > {lo}", v)
        for name in ("cp", "g_time"):
            if not math.isfinite(getattr(self, name)):
                raise SceneError(None, f"viscous_drift.{name}", "a finite number",
                                 getattr(self, name))

    @property
    def d_sum(self) -> float:
        """sum(d_i) (m)."""
        return float(sum(self.column_diameters))


def viscous_drift_b(omega, formula: CorrectionFormula) -> np.ndarray:
    """B(w) = B0 k p sum(d_i) (N/m^3) of eq. 6.6 at the angular frequencies ``omega`` (rad/s)."""
    w = np.asarray(omega, float)
    k = w * w / formula.gravity
    p = np.exp(-1.25 * (k * formula.main_column_diameter) ** 2)
    return formula.b0 * k * p * formula.d_sum


def corrected_coefficients(omega, wave_direction, f_pot, *, current_along, hs: float,
                           formula: CorrectionFormula) -> np.ndarray:
    """Eq. 6.6 applied to an array of potential mean drift coefficients.

    Parameters
    ----------
    omega : (n_w,) rad/s.
    wave_direction : (n_b,) rad, wave direction of travel relative to the body.
    f_pot : (n_w, n_b, 6) potential-flow mean drift coefficients (N/m^2, N m/m^2).
    current_along : float or (n_b,) current component along each wave direction U (m/s).
    hs : significant wave height Hs (m), >= 0.
    formula : :class:`CorrectionFormula`.

    Returns
    -------
    (n_w, n_b, 6) corrected coefficients, same units (see the module docstring for the split
    over the DOFs).
    """
    w = np.asarray(omega, float)
    beta = np.asarray(wave_direction, float)
    f = np.asarray(f_pot, float)
    if f.shape != (w.size, beta.size, 6):
        raise ValueError(f"f_pot shape {f.shape}, expected ({w.size}, {beta.size}, 6)")
    if not (math.isfinite(hs) and hs >= 0.0):
        raise SceneError(None, "environment.waves.hs", "a number >= 0 (m)", hs)
    U = np.broadcast_to(np.asarray(current_along, float), beta.shape)
    out = f * (1.0 + formula.cp * U)[None, :, None]
    visc = viscous_drift_b(w, formula)[:, None] * (formula.g_time * U + hs)[None, :]
    out[:, :, 0] += visc * np.cos(beta)[None, :]
    out[:, :, 1] += visc * np.sin(beta)[None, :]
    return out


def corrected_mean_drift(db, *, current_speed: float, current_heading: float, hs: float,
                         formula: CorrectionFormula, yaw: float = 0.0):
    """A copy of the hydrodynamic database with ``mean_drift_force`` corrected by eq. 6.6.

    Parameters
    ----------
    db : xarray.Dataset with ``mean_drift_force`` (omega, wave_direction, influenced_dof).
    current_speed : current speed U_c (m/s) (surface value of the profile, or the value at the
        depth the user chooses).
    current_heading : current direction of travel psi_c (rad, earth frame).
    hs : significant wave height (m).
    formula : :class:`CorrectionFormula`.
    yaw : body heading (rad); the current relative to the body is psi_c - yaw.

    Returns
    -------
    xarray.Dataset, a shallow copy whose ``mean_drift_force`` is corrected, with the potential
    values kept as ``mean_drift_force_potential`` and the parameters in the variable's attrs.
    The input database is not modified.
    """
    if "mean_drift_force" not in db:
        raise SceneError(None, "database", "a database with mean_drift_force for the "
                         "correction formula")
    da = db["mean_drift_force"].transpose("omega", "wave_direction", "influenced_dof")
    w = np.asarray(db["omega"].values, float)
    beta = np.asarray(db["wave_direction"].values, float)
    U = float(current_speed) * np.cos(float(current_heading) - float(yaw) - beta)
    f = corrected_coefficients(w, beta, np.nan_to_num(da.values), current_along=U, hs=hs,
                               formula=formula)
    f = np.where(np.isnan(da.values), np.nan, f)
    out = db.copy()
    out["mean_drift_force_potential"] = db["mean_drift_force"]
    new = da.copy(data=f)
    new.attrs = dict(da.attrs)
    new.attrs.update({
        "correction": "Stansberg et al. (2015) eq. 6.6: f_pot (1 + Cp U) + B (G U + Hs), "
                      "B = B0 k p sum(d_i)",
        "correction_hs_m": float(hs), "correction_current_speed_m_s": float(current_speed),
        "correction_current_heading_rad": float(current_heading),
        "correction_cp_s_per_m": formula.cp, "correction_G_s": formula.g_time,
        "correction_B0_N_per_m3": formula.b0, "correction_d_sum_m": formula.d_sum,
        "correction_D0_m": formula.main_column_diameter})
    out["mean_drift_force"] = new.transpose(*db["mean_drift_force"].dims)
    return out


def extra_linear_damping(linear_damping, *, increase: float, dofs=(0, 1)) -> np.ndarray:
    """The linear damping matrix with its diagonal in ``dofs`` raised by ``increase`` (fraction).

    Wang (2016) section 6.6 (table 6.10) raises the surge/sway linear damping of the
    correction-formula case by 50 %, 100 %, 200 %, 300 % (``increase`` 0.5 ... 3.0) to put back
    the viscous damping that eq. 6.6 leaves out.  Returns a new (6, 6) array (N s/m, N m s/rad).
    """
    B = np.array(linear_damping, float, copy=True)
    if B.shape != (6, 6):
        raise ValueError(f"linear damping of shape {B.shape}, expected (6, 6)")
    if not (math.isfinite(increase) and increase >= 0.0):
        raise SceneError(None, "viscous_drift.extra_damping", "a fraction >= 0", increase)
    for d in dofs:
        B[d, d] *= 1.0 + increase
    return B
