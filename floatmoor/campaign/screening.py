"""Frequency-domain screening and the DNV-OS-E301 utilisation of every case.

FD utilisation of a line in a case: the DNV-OS-E301 design equation (DNV 2008, Ch.2 Sec.2, as
:func:`floatmoor.post.dnv_os_e301.line_check`) with T_C-mean = the FD static tension and T_C =
the FD maximum tension (Wang (2016) eq. 2.49), ULS factors for the intact mooring and ALS factors
for a failed or breaking line.  A line that is failed in the case is not checked (NaN).

Screening rule (campaign ``screening:``): the governing FD utilisation of a line in a limit state
is its largest over the cases of that limit state; a case goes to the time domain when, for any
line, its FD utilisation is within ``within_percent`` % of that line's governing FD utilisation
(u >= (1 - X/100) u_gov), or it is among the ``top_per_line`` largest for that line.

TD utilisation of a case: per line, the Gumbel fit (maximum likelihood) of the seed maxima, its
90 % fractile as T_C and the mean over the seeds as T_C-mean (Wang (2016) section 5.4.4), in the
same design equation.
"""

from __future__ import annotations

import numpy as np

__all__ = ["select_cases", "td_case_check", "utilisation"]


def screening_analysis(design) -> str:
    """The analysis type of the screening's factors: the campaign's, and for ``auto`` (which
    the report resolves per line from the line model) the quasi-static one -- the larger
    factors, so that the screening keeps more cases -- or the dynamic one for a code without
    quasi-static factors (DNV-ST-0119)."""
    from ..post.design_codes import load_code
    an = getattr(design, "analysis", "auto")
    if an != "auto":
        return an
    code = load_code(getattr(design, "standard", "dnv-os-e301-2008"))
    return "quasi-static" if "quasi-static" in code.analyses else "dynamic"


def utilisation(t_mean, t_max, mbs, limit_state: str, design) -> np.ndarray:
    """Utilisation per line with the campaign's design code (NaN where a tension is NaN or
    <= 0)."""
    from ..post.dnv_os_e301 import line_check
    tm = np.asarray(t_mean, float)
    tc = np.asarray(t_max, float)
    ok = np.isfinite(tm) & np.isfinite(tc) & (tc > 0) & (tm >= 0)
    r = line_check(np.where(ok, tm, 0.0), np.where(ok, np.maximum(tc, tm), 1.0),
                   np.asarray(mbs, float), limit_state=limit_state,
                   consequence_class=design.consequence_class,
                   analysis=screening_analysis(design),
                   code=getattr(design, "standard", "dnv-os-e301-2008"))
    return np.where(ok, np.asarray(r["utilisation"], float), np.nan)


def select_cases(u_fd: np.ndarray, limit_states, screening) -> tuple[np.ndarray, np.ndarray]:
    """Cases kept for the time domain.

    Parameters
    ----------
    u_fd : (n_cases, n_lines) FD utilisation (NaN: not checked or FD failed).
    limit_states : (n_cases,) "ULS" / "ALS".
    screening : :class:`~floatmoor.campaign.spec.Screening`.

    Returns
    -------
    (keep, reason): boolean (n_cases,), and (n_cases, n_lines) int codes: 1 within X %, 2 top N,
    3 both, 0 neither.
    """
    u = np.asarray(u_fd, float)
    ls = np.asarray(limit_states)
    reason = np.zeros(u.shape, int)
    if screening.time_domain == "all":
        return np.ones(u.shape[0], bool), reason
    if screening.time_domain == "none":
        return np.zeros(u.shape[0], bool), reason
    frac = 1.0 - screening.within_percent / 100.0
    for state in np.unique(ls):
        rows = np.nonzero(ls == state)[0]
        for j in range(u.shape[1]):
            col = u[rows, j]
            good = np.isfinite(col)
            if not good.any():
                continue
            gov = col[good].max()
            within = good & (col >= frac * gov)
            reason[rows[within], j] |= 1
            order = rows[good][np.argsort(-col[good], kind="stable")]
            reason[order[:screening.top_per_line], j] |= 2
    return reason.any(axis=1), reason


def td_case_check(seed_max: np.ndarray, seed_mean: np.ndarray, mbs, limit_state: str, design,
                  skip_lines=()) -> dict:
    """DNV-OS-E301 check of one case from its seeds.

    ``seed_max`` and ``seed_mean`` are (n_seeds, n_lines) in N; lines in ``skip_lines`` (column
    indices: the failed or broken lines) and lines with a non-positive maximum are not checked.
    Returns per line ``t_c``, ``t_c_mean``, ``utilisation``, ``gumbel_loc``, ``gumbel_scale``
    (NaN where not checked)."""
    from ..post.extremes import gumbel_fit
    n_lines = seed_max.shape[1]
    out = {k: np.full(n_lines, np.nan) for k in ("t_c", "t_c_mean", "gumbel_loc",
                                                  "gumbel_scale")}
    import warnings
    for j in range(n_lines):
        x = seed_max[:, j]
        if j in skip_lines or not np.all(np.isfinite(x)) or np.any(x <= 0) or np.ptp(x) <= 0:
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fit = gumbel_fit(x, method="mle")
        out["t_c"][j] = fit.fractile(0.9)
        out["t_c_mean"][j] = float(np.mean(seed_mean[:, j]))
        out["gumbel_loc"][j] = fit.loc
        out["gumbel_scale"][j] = fit.scale
    out["utilisation"] = utilisation(out["t_c_mean"], out["t_c"], mbs, limit_state, design)
    return out
