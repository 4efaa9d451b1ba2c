"""Time-domain counterpart of :func:`~floatmoor.mooring.fe.frequency.frequency_response`: the
FE line driven (``run_prescribed``) by realisations of the same fairlead motion spectrum.

The realisations are periodic: components on the grid ``k 2 pi / duration`` with the
deterministic amplitudes ``sqrt(2 S dw)`` and random phases, so that over the record
(``duration`` after a ramp and a settling time) the motion variance is the spectrum's exactly and
the sampling error of a linear response vanishes; what is left is the effect of the
nonlinearities (drag, touchdown) and of the random phases on them.
"""

from __future__ import annotations

import math

import numpy as np

from .prescribed import TimeSeriesMotion, run_prescribed

__all__ = ["periodic_realisation", "periodic_realisation_from_transfer", "td_tension_std"]


def periodic_realisation(omega, auto_psd, duration: float, seed: int, *, ramp: float = 60.0,
                         dt: float = 0.05) -> TimeSeriesMotion:
    """Fairlead motion (earth axes) with the auto-spectra ``auto_psd`` (n_w, 3), m^2 s/rad,
    given on ``omega`` (rad/s, interpolated), independent phases per axis, ramped in over
    ``ramp`` s; periodic with period ``duration`` after the ramp."""
    dw = 2.0 * math.pi / duration
    k = np.arange(math.ceil(omega[0] / dw), math.floor(omega[-1] / dw) + 1)
    wr = k * dw
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, ramp + duration + 2 * dt, dt)
    xyz = np.zeros((t.size, 3))
    for a in range(3):
        S = np.interp(wr, omega, np.asarray(auto_psd)[:, a])
        amp = np.sqrt(2.0 * S * dw)
        ph = rng.uniform(0.0, 2.0 * math.pi, wr.size)
        for j in range(0, wr.size, 256):
            xyz[:, a] += (amp[j:j + 256, None] * np.cos(wr[j:j + 256, None] * t[None]
                                                         + ph[j:j + 256, None])).sum(0)
    g = 0.5 * (1.0 - np.cos(math.pi * np.clip(t / ramp, 0.0, 1.0)))
    return TimeSeriesMotion(t=t, xyz=xyz * g[:, None])


def td_tension_std(line, omega, auto_psd, *, duration: float = 600.0, seeds=(1, 2, 3, 4),
                   ramp: float = 60.0, settle: float = 60.0, dt: float = 0.2) -> dict:
    """Fairlead tension std (N) of the FE line under periodic realisations (one per seed) of
    the motion spectrum: the line starts from its current static state for every seed (state
    saved and restored); the record is the last ``duration`` s after ``ramp + settle``.

    Returns ``{"std": per-seed std (N), "mean_std": RMS over seeds, "motion_std": (n_seeds, 3)
    record motion std (m), "max": per-seed maximum tension (N)}``."""
    r0 = line.r.copy()
    out_std, out_max, m_std = [], [], []
    for seed in seeds:
        line.r[:] = r0
        line.start()
        mo = periodic_realisation(omega, auto_psd, duration, seed, ramp=ramp + settle)
        res = run_prescribed(line, mo, ramp + settle + duration, dt)
        t = res.time.values
        keep = t > t[-1] - duration + 1e-9
        ft = res.fairlead_tension.values[keep]
        out_std.append(float(ft.std()))
        out_max.append(float(ft.max()))
        x = mo.track(t[keep])[0]
        m_std.append(x.std(axis=0))
    line.r[:] = r0
    s = np.array(out_std)
    return {"std": s, "mean_std": float(np.sqrt(np.mean(s ** 2))), "motion_std": np.array(m_std),
            "max": np.array(out_max)}


def periodic_realisation_from_transfer(omega, h, wave_psd, duration: float, seed: int, *,
                                       ramp: float = 60.0, dt: float = 0.05) -> TimeSeriesMotion:
    """Fairlead motion ``x(t) = Re sum h(w_k) a_k exp(i (w_k t + phi_k))`` (exp(+i w t)) for the
    fairlead displacement per unit wave amplitude ``h`` (n_w, 3) complex and the wave spectrum
    ``wave_psd`` (n_w,) on ``omega``; periodic with ``duration`` after the ramp (deterministic
    amplitudes ``a_k = sqrt(2 S dw)``, random phases)."""
    dw = 2.0 * math.pi / duration
    k = np.arange(math.ceil(omega[0] / dw), math.floor(omega[-1] / dw) + 1)
    wr = k * dw
    rng = np.random.default_rng(seed)
    amp = np.sqrt(2.0 * np.interp(wr, omega, wave_psd) * dw)
    ph = rng.uniform(0.0, 2.0 * math.pi, wr.size)
    H = np.stack([np.interp(wr, omega, h[:, a].real) + 1j * np.interp(wr, omega, h[:, a].imag)
                  for a in range(3)], axis=1)
    t = np.arange(0.0, ramp + duration + 2 * dt, dt)
    xyz = np.zeros((t.size, 3))
    for j in range(0, wr.size, 256):
        e = np.exp(1j * (wr[j:j + 256, None] * t[None] + ph[j:j + 256, None]))   # (k, t)
        xyz += np.real(np.einsum("ka,kt->ta", H[j:j + 256] * amp[j:j + 256, None], e))
    g = 0.5 * (1.0 - np.cos(math.pi * np.clip(t / ramp, 0.0, 1.0)))
    return TimeSeriesMotion(t=t, xyz=xyz * g[:, None])
