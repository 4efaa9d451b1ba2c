"""Linear springs that replace the grounded and touchdown part of a line in the frequency domain
(Ong & Pellegrino (2003)).

The part of the line from the anchor up to a *cut point* a little above the touchdown point is
taken as quasi-static: its end position relative to the anchor, ``x = f(H, V)``,
``z = g(V, H)``, follows from the elastic catenary with seabed contact for the forces ``(H, V)``
that the rest of the line applies at the cut (the touchdown point moves with ``V``: lift-off and
touchdown are part of these equations).  Ong & Pellegrino expand ``f`` and ``g`` to cubic order
about the static forces,

    z1 = sum g_ij V1^i H1^j,   x1 = sum f_ij V1^i H1^j      (i + j = 1 .. 3),

and replace them by the linear law ``[z1, x1] = E [V1, H1]`` whose coefficients minimise the
mean square error over the expected excursion; the spring matrix is ``E^-1``.  Over a harmonic
excitation they integrate over time; for the random excitation of the frequency domain the mean
is over the Gaussian distribution of ``(H1, V1)`` (covariance from the line's response,
iterated), which gives ``E = E[y f^T] E[f f^T]^-1`` (Gauss-Hermite, exact for these polynomial
moments).  In the small-excursion limit the springs are the catenary stiffness of the lower
part.

The cubic expansion is obtained by a least-squares fit of a full cubic in ``(H1, V1)`` to the
catenary on a small stencil (the quartic remainder is below 1e-9 of the terms kept).

Also here: the equivalent axial spring of the grounded part ("spring" seabed model: the
touchdown node held vertically, horizontally on the stretch stiffness of the grounded line).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.polynomial.hermite_e import hermegauss

from ..catenary import _eval_line

__all__ = ["LowerPart", "cubic_expansion", "grounded_axial_stiffness", "least_squares_springs"]

# cubic monomials V^i H^j, i + j = 0..3
_POWERS = [(i, j) for n in range(4) for i in range(n + 1) for j in range(n + 1) if i + j == n]


@dataclass(frozen=True, kw_only=True)
class LowerPart:
    """The line from the anchor (on the seabed) to the cut point: unstretched segment lengths
    (m), EA (N), submerged weight per length (N/m), from the anchor; and the static forces at the
    cut, ``H0`` (horizontal, towards the anchor) and ``V0`` (down), N."""

    lengths: np.ndarray
    ea: np.ndarray
    w: np.ndarray
    H0: float
    V0: float

    def position(self, H, V) -> np.ndarray:
        """(x, z) of the cut point relative to the anchor for cut forces (H, V), m."""
        L = np.ascontiguousarray(self.lengths, float)
        work = np.empty(24)
        res = np.zeros(10)
        st = _eval_line(float(H), float(V), L, np.ascontiguousarray(self.ea, float),
                        np.ascontiguousarray(self.w, float), np.zeros(L.size), 0, L.size, 0.0,
                        True, work, res)
        if st != 0:
            raise ValueError(f"catenary of the lower part failed (status {st}) at H={H}, V={V}")
        return res[0:2].copy()


def _monomials(V, H):
    return np.stack([V ** i * H ** j for i, j in _POWERS], axis=-1)


def cubic_expansion(part: LowerPart, rel_step: float = 2e-3) -> np.ndarray:
    """Coefficients (10, 2) of the cubic expansion of ``(x1, z1)`` in ``(V1, H1)`` about the
    static forces (monomials ``V1^i H1^j`` in the order of ``_POWERS``), by a least-squares fit
    on a 7 x 7 stencil of half-width ``rel_step`` times the static tension."""
    T0 = math.hypot(part.H0, part.V0)
    h = rel_step * T0
    dv = min(h, 0.5 * part.V0)  # keep the cut point suspended
    g = np.linspace(-1.0, 1.0, 7)
    VV, HH = np.meshgrid(g * dv, g * h, indexing="ij")
    x0 = part.position(part.H0, part.V0)
    Y = np.array([part.position(part.H0 + H1, part.V0 + V1) - x0
                  for V1, H1 in zip(VV.ravel(), HH.ravel())])
    # scaled monomials for conditioning
    A = _monomials(VV.ravel() / dv, HH.ravel() / h)
    c, *_ = np.linalg.lstsq(A, Y, rcond=None)
    scale = np.array([dv ** -i * h ** -j for i, j in _POWERS])
    c = c * scale[:, None]
    c[0] = 0.0
    return c


@functools.lru_cache(maxsize=4)
def _gauss_hermite_2d(n: int):
    """Tensor Gauss-Hermite rule for a standard normal 2-vector: nodes (n*n, 2), weights."""
    xg, wg = hermegauss(n)
    wg = wg / math.sqrt(2.0 * math.pi)
    a, b = np.meshgrid(xg, xg, indexing="ij")
    G = np.stack([a.ravel(), b.ravel()], axis=1)
    G.flags.writeable = False
    W = np.outer(wg, wg).ravel()
    W.flags.writeable = False
    return G, W


def least_squares_springs(part: LowerPart, cov_f, coeffs=None, n_gh: int = 4) -> np.ndarray:
    """Spring matrix ``K`` (2, 2) in the (horizontal outward, up) axes of the cut point: the
    restoring force of the lower part is ``-K d`` for a cut-point displacement ``d`` (m), N/m.

    ``cov_f`` (2, 2): covariance of the cut forces ``(H1, V1)`` (N^2); zero gives the tangent
    (catenary) stiffness.  Ong & Pellegrino (2003): least-squares linearisation of the cubic
    expansion, ``K = E^-1``."""
    c = cubic_expansion(part) if coeffs is None else coeffs
    cov = np.asarray(cov_f, float)
    cov = 0.5 * (cov + cov.T)
    # Gaussian (H1, V1) by a tensor Gauss-Hermite rule in the eigen axes
    lam, Q = np.linalg.eigh(cov)
    lam = np.maximum(lam, 0.0)
    G, W = _gauss_hermite_2d(n_gh)
    F = G * np.sqrt(lam)[None, :] @ Q.T              # (H1, V1)
    H1, V1 = F[:, 0], F[:, 1]
    Y = _monomials(V1, H1) @ c                       # (n, 2): x1, z1
    fv = np.stack([H1, V1], axis=1)
    Eyf = (Y * W[:, None]).T @ fv                    # E[y f^T]
    Eff = (fv * W[:, None]).T @ fv
    # linear part of the expansion: the tangent compliance J = d(x, z)/d(H, V)
    J = np.array([[c[_POWERS.index((0, 1)), 0], c[_POWERS.index((1, 0)), 0]],
                  [c[_POWERS.index((0, 1)), 1], c[_POWERS.index((1, 0)), 1]]])
    if np.all(lam <= 1e-30 * max(part.H0, part.V0) ** 2):
        E = J
    else:
        # a direction without variance keeps its tangent compliance
        E = J.copy()
        good = lam > 1e-12 * lam.max()
        Qg = Q[:, good]
        Ered = (Eyf @ Qg) @ np.linalg.inv(Qg.T @ Eff @ Qg)      # y = Ered (Qg^T f)
        E = Ered @ Qg.T + J @ Q[:, ~good] @ Q[:, ~good].T
    # force on the cut point pulling towards the anchor and down: x = f(H, V) with H, V the
    # forces the rest of the line applies; restoring force -K d with K = E^-1 in (x, z)
    return np.linalg.inv(E)


def grounded_axial_stiffness(lengths, ea) -> float:
    """Axial stiffness (N/m) of the grounded line (segments in series, no friction)."""
    return 1.0 / float(np.sum(np.asarray(lengths, float) / np.asarray(ea, float)))
