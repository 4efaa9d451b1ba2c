"""Dynamic WF line tensions of the frequency-domain analysis (``tension_model: dynamic``).

Each active line becomes a FE line (:func:`~floatmoor.mooring.fe.from_system.spec_from_linedef`
at the mean pose, with the scene's FE options, line types and current) whose WF tension follows
from its WF fairlead motion by :func:`~floatmoor.mooring.fe.frequency.frequency_response`: the
fairlead displacement per unit wave amplitude ``h = X_t + X_r x arm`` (the body RAO, small
rotations, ``arm`` the fairlead from the body origin in earth axes at the mean pose) gives the
fairlead cross-spectrum ``h h^H S(w)`` (m^2 s/rad).  The LF tension stays quasi-static (the LF
motion is slow against the line's natural periods); WF and LF are combined as before (Wang
(2016) eq. 2.49).  The dynamic amplification is the ratio of the dynamic to the quasi-static WF
tension std.

The line is placed at the FD mean pose.  By default that is the quasi-static equilibrium of the
catenary lines, which carry no current drag: with a strong current the lines' drag moves the
vessel further downwind in a coupled FE storm (Floatel-like 100-year case: about 0.9 MN, mean
surge 14.7 against 10.5 m), and the WF dynamic tension follows the pose: there the FD is +3.6
to +6.4 % on the slack lines and -0.2 to -1.0 % on the taut ones against 12 coupled storms, and
at the storms' mean pose +0.4 to +3.6 %, the rest following the storms' smaller WF heave
(notebooks/fd_line_dynamics.ipynb).  With ``frequency_domain: line_current_drag`` the mean pose
includes the lines' static current drag (13.6 m): +1.4 to +2.9 % on every line.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.frames import rotation_matrix_into
from ..mooring.fe.body import scene_line_inputs
from ..mooring.fe.frequency import frequency_response
from ..mooring.fe.from_system import spec_from_linedef
from ..mooring.fe.line import FELine
from ..solvers.frequency_domain import wf_directions
from .fd_maxima import tension_columns

__all__ = ["FD_LINE_SEABED", "dynamic_line_columns", "dynamic_wf_tensions"]

FD_LINE_SEABED = "least_squares"
N_LINE_FREQUENCIES = 120
"""Frequencies of the line model: the drag linearisation runs on this many bins over the
energetic range of the fairlead motion (the line's transfer function is smooth on that scale);
the tension spectrum is then formed on the FD grid with the interpolated transfer function."""


def coarse_grid(w, Sx, n: int):
    """Bin centres (n + 2,) over the range holding all but 1e-6 of the fairlead motion variance
    (trace) and the bin-averaged cross-spectrum (zero at the two end points), so that the
    trapezoidal rule on the coarse grid integrates the spectrum as the fine grid does.  Grids
    with at most ``n`` points are returned unchanged."""
    if w.size <= n:
        return w, Sx
    tr = np.real(np.einsum("wii->w", Sx))
    wt = np.zeros_like(w)
    d = np.diff(w)
    wt[:-1] += 0.5 * d
    wt[1:] += 0.5 * d
    c = np.cumsum(tr * wt)
    if c[-1] <= 0:
        return w[np.linspace(0, w.size - 1, n).astype(int)], Sx[np.linspace(0, w.size - 1,
                                                                              n).astype(int)]
    lo = w[max(np.searchsorted(c, 1e-6 * c[-1]) - 1, 0)]
    hi = w[min(np.searchsorted(c, (1 - 1e-6) * c[-1]) + 1, w.size - 1)]
    edges = np.linspace(lo, hi, n + 1)
    k = np.clip(np.searchsorted(edges, w, side="right") - 1, 0, n - 1)
    inside = (w >= lo) & (w <= hi)
    Sc = np.zeros((n, 3, 3), complex)
    np.add.at(Sc, k[inside], Sx[inside] * wt[inside, None, None])
    dw = edges[1] - edges[0]
    Sc /= dw
    wc = np.concatenate([[edges[0]], 0.5 * (edges[:-1] + edges[1:]), [edges[-1]]])
    Sc = np.concatenate([np.zeros((1, 3, 3)), Sc, np.zeros((1, 3, 3))])
    # the end points carry no energy: the trapezoidal weights of the centres are dw (first and
    # last: 3/4 dw); rescale those two bins so the variance is that of the fine grid
    Sc[1] *= 4.0 / 3.0
    Sc[-2] *= 4.0 / 3.0
    return wc, Sc


def dynamic_wf_tensions(built, mean, rao, omega, wave_spectrum, *,
                        seabed: str = FD_LINE_SEABED, directions=None) -> dict:
    """WF fairlead tension std (N), Tz (s) and spectrum (n_w, n_lines) of every line; NaN for
    failed lines.  ``directions``: the (RAO, spectrum) pairs of a sea of several directions
    (:func:`floatmoor.solvers.frequency_domain.wf_directions`) instead of ``rao`` and
    ``wave_spectrum``."""
    if directions is None:
        directions = [(rao, wave_spectrum)]
    system = built.mooring
    lm = getattr(system, "line_models", None)
    spec_kw = lm.options.spec_kw(system.water_depth) if lm is not None else {}
    inputs = scene_line_inputs(built.scene, system)
    w = np.asarray(omega, float)
    R = np.zeros((3, 3))
    rotation_matrix_into(mean[3], mean[4], mean[5], R)
    n = len(system.names)
    std = np.full(n, np.nan)
    tz = np.full(n, np.nan)
    psd = np.full((w.size, n), np.nan)
    iters = np.zeros(n, np.int64)
    for i, (ld, active) in enumerate(zip(system.lines, system.active)):
        if not active:
            continue
        spec = spec_from_linedef(ld, water_depth=system.water_depth, pose=mean,
                                 water_density=system.water_density, gravity=system.gravity,
                                 line_types=inputs["line_types"], **spec_kw,
                                 **(inputs["current"] or {}))
        line = FELine(spec)
        line.solve_static()
        arm = R @ np.asarray(ld.fairlead, float)
        Sx = None
        for rao_d, S_d in directions:  # the fairlead motion of every direction adds
            h = rao_d[:, :3] + np.cross(rao_d[:, 3:], arm)
            part = h[:, :, None] * h[:, None, :].conj() * np.asarray(S_d, float)[:, None, None]
            Sx = part if Sx is None else Sx + part
        wc, Sc = coarse_grid(w, Sx, N_LINE_FREQUENCIES)
        ds = frequency_response(line, wc, Sc, seabed=seabed, n_modes=0)
        # the linearised line's tension transfer, interpolated onto the FD grid
        tr = ds["fairlead_tension_rao"].values
        hT = np.stack([np.interp(w, wc, tr[:, a, 0]) + 1j * np.interp(w, wc, tr[:, a, 1])
                       for a in range(3)], axis=1)
        p = np.real(np.einsum("wa,wab,wb->w", hT, Sx, hT.conj()))
        m0 = np.trapezoid(p, w)
        m2 = np.trapezoid(w * w * p, w)
        std[i] = math.sqrt(max(m0, 0.0))
        tz[i] = 2.0 * math.pi * math.sqrt(m0 / m2) if m2 > 0 else np.nan
        psd[:, i] = p
        iters[i] = ds.attrs["iterations"]
    return {"std": std, "tz": tz, "psd": psd, "iterations": iters}


def dynamic_line_columns(built, mean, sol, model, lines: dict, duration: float) -> dict:
    """The tension columns of :func:`~floatmoor.analyses.frequency_domain._line_statistics`
    with the dynamic WF tension: returns the FDResult fields to update (the WF std, Tz and
    maxima, eq. 2.49 total, safety factor) and the quasi-static WF std, Tz and the dynamic
    amplification beside them."""
    dyn = dynamic_wf_tensions(built, mean, None, model.omega, None,
                              directions=wf_directions(model, sol))
    failed = np.asarray(lines["line_failed"], bool)
    qs_std = np.asarray(lines["tension_std_wf"], float)
    cols = tension_columns(lines["tension_static"], lines["tension_std_lf"],
                           lines["tension_tz_lf"], dyn["std"], dyn["tz"], lines["mbs"],
                           duration)

    def nan_failed(x):
        return np.where(failed, np.nan, x)

    with np.errstate(invalid="ignore", divide="ignore"):
        daf = dyn["std"] / qs_std
    return {"tension_std_wf": nan_failed(dyn["std"]), "tension_tz_wf": nan_failed(dyn["tz"]),
            "tension_max_wf": nan_failed(cols["max_wf"]),
            "tension_wf_base": nan_failed(cols["wf_base"]),
            "tension_max_total": nan_failed(cols["max_total"]),
            "tension_branch": cols["branch"],
            "safety_factor": nan_failed(cols["safety_factor"]),
            "tension_std_wf_quasi_static": qs_std,
            "tension_tz_wf_quasi_static": np.asarray(lines["tension_tz_wf"], float),
            "tension_wf_dynamic_spectrum": dyn["psd"],
            "dynamic_amplification": nan_failed(daf)}
