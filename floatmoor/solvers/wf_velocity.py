"""The linear first-order (wave-frequency) body velocity of a run, for the wind and current
relative velocity.

Wang (2016) writes the wind and current forces on the hull with the velocity of the flow relative
to the **low-frequency** body motion (eq. 2.24 and 2.26)::

    Q_wi = C_wi [(U + u(t)) - x'_LF]^2,        Q_cu = C_cu (V - x'_LF) |V - x'_LF|

The hull-level coefficients C are steady-flow drag coefficients; letting the wave-frequency
velocity x'_WF into them turns them into a viscous-drift model (section 6.1 does that on
purpose, with slender elements and the total velocity, eq. 6.7-6.8).  The time-domain state
holds only the total velocity, so the standard separation is used: the WF velocity is predicted
linearly before the loop,

    v_WF(t) = Re sum_k i w_k H(w_k) a_k exp(i (w_k t + phi_k)),
    H(w) = [K - w^2 (M + A(w)) + i w (B(w) + B_l + B_eq)]^-1 X(w)      (Wang (2016) eq. 2.40)

with the same excitation X and wave components as the first-order wave force, the same mass,
damping and radiation as the time-domain model, and K the hydrostatic plus the mooring tangent
stiffness at the static start; the loop uses ``v_LF = v - v_WF``.  The RAOs come from
:func:`floatmoor.solvers.frequency_domain.wave_frequency_rao` (the frequency-domain module's
function, not a copy).  A quadratic damping B_q is linearised stochastically on the WF velocity
alone, B_eq = sqrt(8/pi) B_q diag(sigma_WF) (every entry, iterated).
"""

from __future__ import annotations

import numpy as np

from ..core.frames import yaw_rotation6
from ..forces.series import complex_envelope
from ..forces.waves import body_axes_to_earth, transfer_at
from .frequency_domain import equivalent_quadratic_damping, wave_frequency_rao

__all__ = ["wf_velocity_rao", "wf_velocity_series", "RELATIVE_VELOCITY_MODES"]

RELATIVE_VELOCITY_MODES = ("low_frequency", "total")


def _interp_matrix(omega, w_db, tab):
    """tab (n_db, 6, 6) linearly interpolated at omega (clamped at the ends): (n, 6, 6)."""
    out = np.empty((omega.size, 6, 6))
    for i in range(6):
        for j in range(6):
            out[:, i, j] = np.interp(omega, w_db, tab[:, i, j])
    return out


def wf_velocity_rao(db, omega, direction, *, mass, stiffness, linear_damping,
                    quadratic_damping=None, amplitude=None, radiation: bool = True,
                    a_inf=None, yaw0: float = 0.0, file=None, max_iter: int = 50):
    """Velocity RAOs i w H(w) (m/s per m, rad/s per m) at wave components, earth axes.

    Parameters
    ----------
    db : hydrodynamic database (xarray, Capytaine names).
    omega, direction : (n,) component frequencies (rad/s) and directions of travel (rad, earth).
    mass : (6, 6) rigid-body mass (body axes).
    stiffness : (6, 6) linearised restoring in earth axes at heading ``yaw0`` (N/m, N m/rad).
    linear_damping : (6, 6) (body axes); quadratic_damping : (6, 6) or None, linearised on the
        WF velocity standard deviation from the components' ``amplitude`` (m).
    radiation : with the frequency-dependent A(w), B(w) of the database; False: A_inf (``a_inf``)
        and no radiation damping (a run without radiation memory).
    yaw0 : body heading (rad) of the wave loads (as :class:`floatmoor.forces.waves.FirstOrderWave`).

    Returns
    -------
    (n, 6) complex velocity RAOs in earth axes, exp(+i w t).
    """
    omega = np.asarray(omega, float)
    direction = np.asarray(direction, float)
    T = yaw_rotation6(yaw0)
    X = transfer_at(db, "excitation_force", omega, direction - yaw0, file=file)  # body axes
    K = T.T @ np.asarray(stiffness, float) @ T                                       # body axes
    if radiation:
        w_db = np.asarray(db["omega"].values, float)
        A = _interp_matrix(omega, w_db, np.asarray(
            db["added_mass"].transpose("omega", "influenced_dof", "radiating_dof").values, float))
        B = _interp_matrix(omega, w_db, np.asarray(
            db["radiation_damping"].transpose("omega", "influenced_dof", "radiating_dof").values,
            float))
    else:
        A = np.asarray(a_inf, float)
        B = np.zeros((6, 6))
    B_l = np.asarray(linear_damping, float)
    bq = None if quadratic_damping is None else np.asarray(quadratic_damping, float)
    B_eq = np.zeros((6, 6))
    quadratic = bq is not None and bool(np.any(bq != 0.0))
    for _ in range(max_iter if quadratic else 1):
        H = wave_frequency_rao(omega, mass, A, B + (B_l + B_eq)[None], K, X)
        V = 1j * omega[:, None] * H
        if not quadratic:
            break
        amp = np.asarray(amplitude, float)
        sigma = np.sqrt(0.5 * np.sum((amp[:, None] * np.abs(V)) ** 2, axis=0))
        B_new = equivalent_quadratic_damping(bq, sigma)  # every entry of B_q
        done = np.allclose(B_new, B_eq, rtol=1e-4, atol=0.0)
        B_eq = B_new
        if done:
            break
    return body_axes_to_earth(V, yaw0)


def wf_velocity_series(waves, db, *, n_samples: int, h: float, ramp=None, **rao_kwargs):
    """The linear WF velocity (n_samples, 6) (m/s, rad/s; earth axes) at t = j h.

    ``waves`` the run's :class:`~floatmoor.forces.waves.WaveComponents` (the realisation the
    first-order wave force uses); ``ramp`` (n_samples,) the factor applied to that force (the
    velocity is ramped alike); ``rao_kwargs`` go to :func:`wf_velocity_rao`.
    """
    r = waves.realisation
    V = wf_velocity_rao(db, r.omega, r.direction, amplitude=r.amplitude, **rao_kwargs)
    c = waves.coefficients()[:, None] * V
    v = complex_envelope(r.omega, c, n_samples, h, waves.grid).real
    if ramp is not None:
        v = v * np.asarray(ramp, float)[:, None]
    return np.ascontiguousarray(v)
