"""Closed-form references for FE line verification.

:func:`transverse_friction_static` is the static analytic solution of Lu (2012,
sec. 2.1, eq. 1-19) for an inextensible catenary line whose fairlead is moved slowly sideways by
``Y`` with Coulomb friction ``mu N`` acting only transversely on the grounded part.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import fsolve

__all__ = ["transverse_friction_static", "LU2012_CASES"]

LU2012_CASES = {
    1: dict(length=711.3, ea=1.69e9, weight_air=3.587e3, weight_water=3.202e3, diameter=0.14,
            span=683.26, height=82.5, depth=95.0),
    2: dict(length=902.2, ea=3.84e8, weight_air=7.623e2, weight_water=6.981e2, diameter=0.09,
            span=848.67, height=250.0, depth=320.0),
    3: dict(segments=((762.0, 9.759e8, 2.673e3, 2.326e3, 0.1524),      # ground chain
                      (1828.8, 1.212e9, 7.198e2, 5.703e2, 0.1905),     # wire
                      (76.2, 9.759e8, 2.673e3, 2.326e3, 0.1524)),      # top chain
            pretension=3.72e6, height=1100.0, depth=1000.0),
}
"""Lu (2012) tables 1 and 2: the shallow (1), intermediate (2, the OC3 line) and deep
(3, chain-wire-chain from the anchor; length m, EA N, weight in air and in water N/m, diameter m)
lines.  ``span`` is the horizontal anchor-fairlead distance, ``height`` the fairlead height above
the seabed (m).  Table 2 prints a 1100 m fairlead height in 1000 m water depth as given."""


def transverse_friction_static(total_length, weight, span, height, offset, mu):
    """Lu (2012) static solution (eq. 10-14 for a straight anchor piece, 15-19 when the whole
    grounded part has moved).

    Parameters
    ----------
    total_length : float
        S0, unstretched line length, m.
    weight : float
        N, submerged weight per length, N/m.
    span : float
        R, horizontal distance anchor-fairlead along the line's plane at zero offset, m.
    height : float
        H, height of the fairlead above the seabed, m.
    offset : float
        Y, sideways fairlead offset, m.
    mu : float
        Transverse friction coefficient.

    Returns
    -------
    dict
        ``T`` horizontal tension (N), ``V`` vertical fairlead force (N), ``tension`` total
        fairlead tension (N), ``sway`` fairlead force component along the offset (N),
        ``S1, S2, D0, alpha1, alpha2`` and ``case`` (1 or 2).
    """
    S0, N, R, H, Y = map(float, (total_length, weight, span, height, offset))
    muN = mu * N

    def cat(T, Ls):
        D0 = T / N * math.asinh(N * Ls / T)
        return D0, T / N * (math.cosh(N * D0 / T) - 1.0)

    # zero offset start: inextensible catenary with a grounded part
    def f0(x):
        T, Ls = x
        D0, h = cat(T, Ls)
        return [S0 - Ls + D0 - R, h - H]
    T0, Ls0 = fsolve(f0, [N * 1000.0, S0 * 0.85], xtol=1e-13)

    if Y == 0.0:
        D0, _ = cat(T0, Ls0)
        return dict(T=T0, V=N * Ls0, tension=math.hypot(T0, N * Ls0), sway=0.0, S1=S0 - Ls0,
                    S2=0.0, D0=D0, alpha1=0.0, alpha2=0.0, case=1)

    def case1(x):
        T, S1, S2 = x
        a2 = muN * S2 / T
        D0, h = cat(T, S0 - S2 - S1)
        return [T / muN * math.sin(a2) + D0 * math.cos(a2) + S1 - R,
                T / muN * (1.0 - math.cos(a2)) + D0 * math.sin(a2) - Y,
                h - H]
    S2g = min(math.sqrt(max(Y, 1e-9) * 2.0 * T0 / muN) * 0.3, 0.5 * (S0 - Ls0))
    sol, info, ier, _ = fsolve(case1, [T0, S0 - Ls0 - S2g, S2g], full_output=True, xtol=1e-13)
    T, S1, S2 = sol
    if ier == 1 and S1 >= 0.0 and S2 > 0.0 and np.max(np.abs(case1(sol))) < 1e-6:
        a2 = muN * S2 / T
        D0, _ = cat(T, S0 - S2 - S1)
        V = N * (S0 - S1 - S2)
        return dict(T=T, V=V, tension=math.hypot(T, V), sway=T * math.sin(a2), S1=S1, S2=S2,
                    D0=D0, alpha1=0.0, alpha2=a2, case=1)

    def case2(x):
        T, S2, a1 = x
        a2 = muN * S2 / T + a1
        D0, h = cat(T, S0 - S2)
        return [T / muN * (math.sin(a2) - math.sin(a1)) + D0 * math.cos(a2) - R,
                T / muN * (math.cos(a1) - math.cos(a2)) + D0 * math.sin(a2) - Y,
                h - H]
    sol, info, ier, _ = fsolve(case2, [T0, S0 - Ls0, 0.01], full_output=True, xtol=1e-13)
    T, S2, a1 = sol
    if ier != 1 or np.max(np.abs(case2(sol))) > 1e-6:
        raise RuntimeError(f"Lu (2012) analytic solution did not converge for Y = {Y}")
    a2 = muN * S2 / T + a1
    D0, _ = cat(T, S0 - S2)
    V = N * (S0 - S2)
    return dict(T=T, V=V, tension=math.hypot(T, V), sway=T * math.sin(a2), S1=0.0, S2=S2, D0=D0,
                alpha1=a1, alpha2=a2, case=2)
