"""Retardation functions of the Cummins equation and their consistency with the database.

Theory (Wang (2016) section 2.2.3, eq. 2.55-2.59; Ogilvie 1964).  With A(w) = A_inf + a(w):

    K(t)  = (2/pi) int_0^inf B(w) cos(w t) dw                                   (eq. 2.58)
    B(w)  = int_0^inf K(t) cos(w t) dt
    A(w)  = A_inf - (1/w) int_0^inf K(t) sin(w t) dt                  (Ogilvie's relation)

Wang (2016) writes eq. 2.59 with the opposite sign of h; floatmoor uses the usual Cummins sign: the
radiation force is -A_inf x'' - int_0^t K(t - tau) x'(tau) dtau.

Numerics
--------
* Integrals over w and t use the exact integral of the piecewise-linear interpolant of the
  sampled function times cos / sin (a linear Filon rule), so they stay accurate when w t
  changes by more than a radian between samples (long times, long frequency steps).
* Low-frequency end: when the grid does not start at w = 0, B is taken linear from B(0) = 0 to
  the first sample (radiation damping vanishes at zero frequency for a body at the free
  surface).  Give a sample at w = 0 to override.
* High-frequency tail: for a K(t) smooth at t = 0+, integration by parts gives the asymptotic
  series B(w) = -K'(0) w^-2 + K^(3)(0) w^-4 - ...  Beyond the last frequency w_N the damping is
  continued by B(w) = c2 w^-2 + c4 w^-4, with c2, c4 fitted by least squares to the samples in
  the upper 15 % of the frequency range and rescaled to pass through B(w_N).  If that fit
  changes sign beyond w_N (or opposes B(w_N)), the power law B(w_N) (w_N / w)^n is used, n
  fitted log-log on the same samples and clipped to [2, 8].  The tail is integrated with the
  same linear rule on a geometric grid (480 points) out to 100 w_N and truncated there; the
  neglected remainder is about c2 / (100 w_N) at t = 0 and smaller at t > 0.
  ``tail="none"`` truncates at w_N with no extension (for comparison).
* Cut-off time: :func:`cutoff_time` returns the time after which |K| stays below a fraction
  (default 1 %) of its peak; the time-domain model convolves up to that time.
"""

from __future__ import annotations

import warnings

import numpy as np
import xarray as xr

from ..core.dofs import DOF_NAMES
from ..core.errors import FloatmoorWarning

__all__ = ["retardation_function", "cutoff_time", "reconstruct_from_retardation",
           "fit_infinite_frequency_added_mass", "consistency_report", "format_consistency",
           "filon_cos", "filon_sin", "tail_exponent"]

TAIL_FIT_FRACTION = 0.15
TAIL_N_RANGE = (2.0, 8.0)
TAIL_EXTENT = 100.0
DEFAULT_BAND = (0.2, 2.0)


def _filon(x, f, y, kind):
    """int_{x0}^{xN} f(x) trig(y x) dx for piecewise-linear f; f shape (..., n_x); y (n_y,).

    Returns (..., n_y)."""
    x = np.asarray(x, float)
    f = np.asarray(f, float)
    y = np.atleast_1d(np.asarray(y, float))
    h = np.diff(x)
    s = np.diff(f, axis=-1) / h  # slopes (..., n_x-1)
    out = np.empty(f.shape[:-1] + (y.size,))
    small = np.abs(y) * np.max(h) < 1e-6
    # y ~ 0: trapezoid (exact for linear f) for cos; for sin, int f x y dx (first order)
    if np.any(small):
        if kind == "cos":
            val = np.sum(0.5 * (f[..., 1:] + f[..., :-1]) * h, axis=-1)
            out[..., small] = val[..., None]
        else:
            # int f(x) sin(y x) dx ~ y int f x dx (exact for linear f: Simpson on f*x quadratic)
            fx0 = f[..., :-1] * x[:-1]
            fx1 = f[..., 1:] * x[1:]
            xm = 0.5 * (x[1:] + x[:-1])
            fm = 0.5 * (f[..., 1:] + f[..., :-1])
            val = np.sum(h * (fx0 + 4 * fm * xm + fx1) / 6.0, axis=-1)
            out[..., small] = val[..., None] * y[small]
    big = ~small
    if np.any(big):
        yb = y[big]
        xm = 0.5 * (x[1:] + x[:-1])[:, None]  # (n-1, 1)
        hh = (0.5 * h)[:, None]
        # sinc-like factor sin(y h/2) / (y h/2)
        arg = hh * yb[None, :]
        sincf = np.sinc(arg / np.pi)
        if kind == "cos":
            # [f sin(yx)/y + s cos(yx)/y^2] boundaries
            end = (f[..., -1, None] * np.sin(yb * x[-1]) - f[..., 0, None] * np.sin(yb * x[0])) / yb
            # sum s (cos(y x1) - cos(y x0)) / y^2 = sum s * (-2 sin(y xm) sin(y h/2)) / y^2
            #  = - sum s h sin(y xm) sinc / y
            trig = np.sin(xm * yb[None, :]) * sincf * h[:, None]  # (n-1, n_y)
            corr = -np.tensordot(s, trig, axes=([-1], [0])) / yb
        else:
            end = (-f[..., -1, None] * np.cos(yb * x[-1]) + f[..., 0, None] * np.cos(yb * x[0])) / yb
            trig = np.cos(xm * yb[None, :]) * sincf * h[:, None]
            corr = np.tensordot(s, trig, axes=([-1], [0])) / yb
        out[..., big] = end + corr
    return out


def filon_cos(x, f, y):
    """int f(x) cos(y x) dx over the samples x, f linear between samples; returns (..., n_y)."""
    return _filon(x, f, y, "cos")


def filon_sin(x, f, y):
    """int f(x) sin(y x) dx over the samples x, f linear between samples; returns (..., n_y)."""
    return _filon(x, f, y, "sin")


def tail_exponent(omega, damping, fraction: float = TAIL_FIT_FRACTION):
    """Log-log slope n of B ~ c w^-n fitted over the top ``fraction`` of the frequency range.

    Returns an array of shape damping.shape[:-1]; NaN where B changes sign or is ~0 there.
    """
    omega = np.asarray(omega, float)
    B = np.asarray(damping, float)
    sel = omega >= omega[-1] - fraction * (omega[-1] - omega[0])
    if sel.sum() < 3:
        sel = np.zeros_like(omega, bool)
        sel[-3:] = True
    lw = np.log(omega[sel])
    Bs = B[..., sel]
    same_sign = np.all(Bs > 0, axis=-1) | np.all(Bs < 0, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        lb = np.log(np.abs(Bs))
    lwc = lw - lw.mean()
    with np.errstate(invalid="ignore"):
            slope = np.sum((lb - lb.mean(axis=-1, keepdims=True)) * lwc, axis=-1) / np.sum(lwc ** 2)
    n = -slope
    return np.where(same_sign & np.isfinite(n), n, np.nan)


def _tail_coefficients(omega, B, fraction: float = TAIL_FIT_FRACTION):
    """Least-squares c2, c4 of B ~ c2 w^-2 + c4 w^-4 over the top ``fraction`` of the range,
    rescaled so that the asymptote passes through the last sample.  Returns (c2, c4, ok) with
    ok False where the fit is unusable (sign change beyond w_N, or a sign opposite to B(w_N))."""
    sel = omega >= omega[-1] - fraction * (omega[-1] - omega[0])
    if sel.sum() < 3:
        sel = np.zeros_like(omega, bool)
        sel[-3:] = True
    w = omega[sel]
    G = np.stack([w ** -2, w ** -4], axis=1)  # (m, 2)
    coef, *_ = np.linalg.lstsq(G, B[..., sel].reshape(-1, w.size).T, rcond=None)
    c2 = coef[0].reshape(B.shape[:-1])
    c4 = coef[1].reshape(B.shape[:-1])
    wN = omega[-1]
    BN = B[..., -1]
    at_N = c2 / wN ** 2 + c4 / wN ** 4
    with np.errstate(divide="ignore", invalid="ignore"):
        fac = np.where(at_N != 0, BN / at_N, 0.0)
    # c2 w^-2 + c4 w^-4 keeps its sign for w > wN when c2 and (c2 wN^2 + c4) share a sign
    ok = (fac > 0) & ((c2 == 0) | (np.sign(c2) == np.sign(at_N))) & np.isfinite(fac)
    return c2 * fac, c4 * fac, ok


def _extended(omega, damping, tail: str):
    omega = np.asarray(omega, float)
    B = np.asarray(damping, float)
    if omega[0] > 0:  # B(0) = 0
        omega = np.concatenate([[0.0], omega])
        B = np.concatenate([np.zeros(B.shape[:-1] + (1,)), B], axis=-1)
    if tail == "none":
        return omega, B
    if tail != "asymptote":
        raise ValueError(f"tail must be 'asymptote' or 'none', not {tail!r}")
    wN = omega[-1]
    wt = wN * np.geomspace(1.0, TAIL_EXTENT, 481)[1:]
    c2, c4, ok = _tail_coefficients(omega[1:], B[..., 1:])
    Bt = c2[..., None] * wt ** -2 + c4[..., None] * wt ** -4
    n = tail_exponent(omega[1:], B[..., 1:])
    n = np.clip(np.where(np.isfinite(n), n, TAIL_N_RANGE[0]), *TAIL_N_RANGE)
    Bp = B[..., -1, None] * (wN / wt) ** n[..., None]
    Bt = np.where(ok[..., None], Bt, Bp)
    return np.concatenate([omega, wt]), np.concatenate([B, Bt], axis=-1)


def retardation_function(omega, damping, t, *, tail: str = "asymptote") -> np.ndarray:
    """Retardation function K(t) = (2/pi) int_0^inf B(w) cos(w t) dw.

    Parameters
    ----------
    omega : (n_w,) rad/s, increasing, > 0 (the finite frequencies of the database).
    damping : (..., n_w) radiation damping B(w) (N s/m, N s or N m s/rad), e.g. one DOF pair
        or the (6, 6, n_w) stack ``ds.radiation_damping.transpose(..., "omega")``.
    t : (n_t,) s, times >= 0.
    tail : "asymptote" (default; see the module docstring) or "none" (truncate at w_N).

    Returns
    -------
    K : (..., n_t) in N/m, N, N m/rad per second (i.e. damping units / s).
    """
    w, B = _extended(omega, damping, tail)
    return (2.0 / np.pi) * filon_cos(w, B, np.asarray(t, float))


def cutoff_time(t, K, rel_tol: float = 0.01) -> np.ndarray:
    """Time after which |K(t)| stays below ``rel_tol`` times its peak (s); shape K.shape[:-1].

    Returns t[-1] where K has not decayed inside the given times (the caller should extend t).
    """
    t = np.asarray(t, float)
    K = np.asarray(K, float)
    peak = np.max(np.abs(K), axis=-1, keepdims=True)
    above = np.abs(K) > rel_tol * np.where(peak > 0, peak, np.inf)
    idx = np.where(np.any(above, axis=-1),
                   K.shape[-1] - 1 - np.argmax(above[..., ::-1], axis=-1), 0)
    idx = np.minimum(idx + 1, t.size - 1)
    return t[idx]


def reconstruct_from_retardation(t, K, omega, a_inf=None):
    """A(w) and B(w) rebuilt from K(t) (Ogilvie): B = int K cos, A = A_inf - (1/w) int K sin.

    Parameters
    ----------
    t : (n_t,) s; K : (..., n_t); omega : (n_w,) rad/s > 0; a_inf : (...) or None (then the
    returned A is A(w) - A_inf).

    Returns
    -------
    A, B : (..., n_w).
    """
    omega = np.asarray(omega, float)
    B = filon_cos(t, K, omega)
    A = -filon_sin(t, K, omega) / omega
    if a_inf is not None:
        A = A + np.asarray(a_inf, float)[..., None]
    return A, B


def fit_infinite_frequency_added_mass(omega, added_mass, t, K, band=None):
    """Least-squares A_inf from Ogilvie's relation: A(w) + (1/w) int K sin(w t) dt = A_inf.

    The least-squares constant over the frequencies in ``band`` (rad/s; all when None) is the
    mean of the left-hand side.  Shapes: added_mass (..., n_w), K (..., n_t); returns (...).
    """
    omega = np.asarray(omega, float)
    A = np.asarray(added_mass, float)
    a_minus, _ = reconstruct_from_retardation(t, K, omega)
    lhs = A - a_minus
    sel = np.ones(omega.size, bool) if band is None else (omega >= band[0]) & (omega <= band[1])
    return lhs[..., sel].mean(axis=-1)


def _default_times(omega):
    """Time grid: step resolving the highest frequency, length resolving the lowest."""
    omega = np.asarray(omega, float)
    dt = min(0.05, np.pi / (20.0 * omega[-1]))  # 40 samples per period of w_N
    dw = np.min(np.diff(omega)) if omega.size > 1 else omega[0]
    t_end = min(max(60.0, 0.5 * np.pi / dw), 600.0)
    return np.arange(0.0, t_end + 0.5 * dt, dt)


def consistency_report(ds: xr.Dataset, *, band=DEFAULT_BAND, t=None, rel_tol_cutoff=0.01,
                       spike_factor: float = 3.0, undecayed_fraction: float = 0.05) -> xr.Dataset:
    """Retardation functions of a database and how well they reproduce its A(w) and B(w).

    For every DOF pair (influenced i, radiating j): K_ij(t), the cut-off time, A_inf (from the
    database when present, else fitted by least squares), and the largest errors of the
    reconstructed A(w), B(w) against the database over the wave-energy ``band`` (rad/s):

        err_X_ij = max_band |X_rec - X_db| / sqrt(max_band|X_ii| max_band|X_jj|)

    (the diagonal norm keeps small coupling terms from blowing up the figure).  Pairs whose
    scale is zero get NaN, and so do DOFs whose diagonal damping is numerical noise (below
    1e-9 of the largest diagonal damping of the same kind, e.g. yaw of an axisymmetric spar).  Warnings (FloatmoorWarning, also stored in the ``warnings``
    attribute) for irregular-frequency spikes (a diagonal B sample more than ``spike_factor``
    times the median of its neighbours and above 5 % of the peak) and for diagonal damping that
    has not decayed at the highest frequency (B(w_N) > ``undecayed_fraction`` of its peak).

    Returns
    -------
    xarray.Dataset with ``retardation_function(influenced_dof, radiating_dof, time)``,
    ``cutoff_time``, ``infinite_frequency_added_mass``, ``a_inf_fitted`` (bool),
    ``max_rel_error_added_mass``, ``max_rel_error_damping``, ``tail_exponent`` and attrs
    ``band``, ``warnings`` (and ``limitations``, copied from the database's attribute of that
    name when present: known limits written by the database's author, printed by
    :func:`format_consistency`).
    """
    where = ds.attrs.get("source", "<database>")
    omega = ds["omega"].values
    A = ds["added_mass"].transpose("influenced_dof", "radiating_dof", "omega").values
    B = ds["radiation_damping"].transpose("influenced_dof", "radiating_dof", "omega").values
    if t is None:
        t = _default_times(omega)
    t = np.asarray(t, float)
    K = retardation_function(omega, B, t)
    sel = (omega >= band[0]) & (omega <= band[1])
    if not np.any(sel):
        raise ValueError(f"{where}: no database frequency inside the band {band} rad/s")
    if "infinite_frequency_added_mass" in ds:
        a_inf = ds["infinite_frequency_added_mass"].values
        fitted = False
    else:
        a_inf = fit_infinite_frequency_added_mass(omega, A, t, K, band=band)
        fitted = True
    A_rec, B_rec = reconstruct_from_retardation(t, K, omega[sel], a_inf)

    # DOFs whose diagonal damping is numerical noise (e.g. yaw of an axisymmetric spar):
    # below 1e-9 of the largest diagonal damping of the same kind (translation / rotation)
    bdiag = np.max(np.abs(np.diagonal(B, axis1=0, axis2=1)), axis=0)
    kind_max = np.array([bdiag[:3].max()] * 3 + [bdiag[3:].max()] * 3)
    live = bdiag > 1e-9 * kind_max

    def rel(X, Xr):
        d = np.max(np.abs(np.diagonal(X[:, :, sel])), axis=0)
        d = np.where(live, d, 0.0)
        scale = np.sqrt(np.outer(d, d))
        err = np.max(np.abs(Xr - X[:, :, sel]), axis=-1)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(scale > 0, err / scale, np.nan)

    errA = rel(A, A_rec)
    errB = rel(B, B_rec)
    tc = cutoff_time(t, K, rel_tol_cutoff)
    nexp = tail_exponent(omega, B)
    msgs = []
    for k, dof in enumerate(DOF_NAMES):
        b = B[k, k]
        peak = np.max(np.abs(b))
        if peak <= 0 or not live[k]:
            continue
        if b[-1] > undecayed_fraction * peak:
            msgs.append(f"{where}: radiation_damping[{dof},{dof}] has not decayed at the highest "
                        f"frequency {omega[-1]:.3g} rad/s (B = {b[-1]:.3g}, "
                        f"{100 * b[-1] / peak:.0f} % of its peak); the retardation function "
                        "depends on the tail model")
        if b.size >= 5:
            for m in range(2, b.size - 2):
                neigh = np.median(np.abs(np.r_[b[m - 2:m], b[m + 1:m + 3]]))
                if abs(b[m]) > 0.05 * peak and abs(b[m]) > spike_factor * max(neigh, 1e-300):
                    msgs.append(f"{where}: radiation_damping[{dof},{dof}] has a spike at "
                                f"omega = {omega[m]:.3g} rad/s ({b[m]:.3g} vs neighbours "
                                f"{neigh:.3g}): an irregular frequency (remove it) or a sharp "
                                "resonance that needs a finer frequency grid")
                    break
    for m in msgs:
        warnings.warn(m, FloatmoorWarning, stacklevel=2)
    dims = ("influenced_dof", "radiating_dof")
    rep = xr.Dataset(
        {
            "retardation_function": (dims + ("time",), K,
                                     {"units": "damping units / s (N/m/s, N/s, N m/rad/s)",
                                      "long_name": "retardation function K_ij(t)"}),
            "cutoff_time": (dims, tc, {"units": "s", "long_name":
                                       f"time after which |K| < {rel_tol_cutoff:g} of its peak"}),
            "infinite_frequency_added_mass": (dims, np.asarray(a_inf, float),
                                              {"units": "kg, kg m, kg m^2",
                                               "long_name": "A_inf used"}),
            "a_inf_fitted": ((), fitted, {"long_name": "A_inf fitted by least squares (Ogilvie)",
                                          "units": "1"}),
            "max_rel_error_added_mass": (dims, errA, {"units": "1", "long_name":
                                         "max |A_rec - A| / sqrt(max|A_ii| max|A_jj|) in band"}),
            "max_rel_error_damping": (dims, errB, {"units": "1", "long_name":
                                      "max |B_rec - B| / sqrt(max|B_ii| max|B_jj|) in band"}),
            "tail_exponent": (dims, nexp, {"units": "1", "long_name":
                              "n of the fitted B ~ w^-n at the highest frequencies"}),
        },
        coords={"influenced_dof": list(DOF_NAMES), "radiating_dof": list(DOF_NAMES),
                "time": ("time", t, {"units": "s", "long_name": "time lag"})},
    )
    rep.attrs.update({"band": np.asarray(band, float), "source": where,
                      "warnings": "\n".join(msgs)})
    if ds.attrs.get("limitations"):  # known limits recorded by the database's author
        rep.attrs["limitations"] = str(ds.attrs["limitations"])
    return rep


def format_consistency(report: xr.Dataset, *, min_scale_only: bool = True) -> str:
    """A printable table of a :func:`consistency_report` (one row per DOF pair)."""
    lo, hi = report.attrs["band"]
    lines = [f"Retardation-function consistency: {report.attrs.get('source', '')}",
             f"band {lo:.3g}..{hi:.3g} rad/s; errors relative to sqrt(max|X_ii| max|X_jj|); "
             f"A_inf {'fitted (Ogilvie, least squares)' if bool(report.a_inf_fitted) else 'from database'}",
             f"{'pair':<14}{'err A %':>9}{'err B %':>9}{'t_cut s':>9}{'tail n':>8}{'A_inf':>13}"]
    for i, di in enumerate(DOF_NAMES):
        for j, dj in enumerate(DOF_NAMES):
            if j < i:
                continue
            ea = float(report.max_rel_error_added_mass.values[i, j])
            eb = float(report.max_rel_error_damping.values[i, j])
            if min_scale_only and i != j and not (np.isfinite(ea) or np.isfinite(eb)):
                continue
            ainf = float(report.infinite_frequency_added_mass.values[i, j])
            kpk = np.max(np.abs(report.retardation_function.values[i, j]))
            kdi = np.sqrt(np.max(np.abs(report.retardation_function.values[i, i])) *
                          np.max(np.abs(report.retardation_function.values[j, j])))
            if i != j and min_scale_only and kpk < 1e-6 * max(kdi, 1e-300) and abs(ainf) < 1e-6 * \
                    np.sqrt(abs(report.infinite_frequency_added_mass.values[i, i] *
                                report.infinite_frequency_added_mass.values[j, j])):
                continue  # negligible coupling
            n = float(report.tail_exponent.values[i, j])
            lines.append(f"{di + '-' + dj:<14}{100 * ea:>9.3f}{100 * eb:>9.3f}"
                         f"{float(report.cutoff_time.values[i, j]):>9.1f}"
                         f"{n:>8.2f}{ainf:>13.4g}")
    if report.attrs.get("limitations"):
        lines.append("database limitations (recorded with the database):")
        lines.extend("  " + m for m in report.attrs["limitations"].split("\n"))
    if report.attrs.get("warnings"):
        lines.append("warnings:")
        lines.extend("  " + m for m in report.attrs["warnings"].split("\n"))
    return "\n".join(lines)
