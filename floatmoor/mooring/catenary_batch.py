"""Vectorised single-segment catenary: many lines in one call, for design charts and sweeps.

``catenary_batch(xf, zf, length, ea, w, cb)`` broadcasts its inputs against each other (numpy
rules) and solves every element with the same numba kernel as the scalar
:func:`floatmoor.mooring.catenary` (``catenary_kernel``), in one compiled loop over the
flattened inputs: no Python work per line.  Each element is the scalar call's answer to the
last bit (same kernel, same inputs, same cold or warm start).

:func:`floatmoor.mooring.catenary` dispatches here when any of its inputs is an array.

Failures
--------
* Invalid inputs (``length`` or ``ea`` not > 0, ``xf`` < 0, a value not finite, a fairlead
  below an anchor on the seabed, shapes that do not broadcast) raise ``ValueError`` naming the
  argument, the number of bad elements and the index and value of the first one: they are
  mistakes in the inputs, not results.
* A solve that fails numerically (no convergence, a buoyant part on the seabed, a line lying
  entirely on the seabed) does not stop the batch: its results are NaN, ``iterations`` is -1 and
  ``status`` holds the kernel's code (0 converged; see ``STATUS_MESSAGES``).  ``ok`` is the
  mask of converged elements and ``check()`` raises the ``ConvergenceError`` of the first failed
  element (its index, inputs and the number of failures).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numba import njit

from ..core.errors import ConvergenceError
from .catenary import (
    OUT_HA,
    OUT_HF,
    OUT_ITER,
    OUT_K11,
    OUT_K12,
    OUT_K21,
    OUT_K22,
    OUT_LB,
    OUT_SIZE,
    OUT_VA,
    OUT_VF,
    STATUS_MESSAGES,
    CatenaryResult,
    catenary_kernel,
)

__all__ = ["catenary_batch", "CatenaryBatch", "catenary_batch_kernel"]

_FLOAT_ARGS = ("xf", "zf", "length", "ea", "w", "cb", "hf0", "vf0")


@njit(cache=True)
def catenary_batch_kernel(xf, zf, length, ea, w, cb, seabed, hf0, vf0, work, out, status):
    """Solve ``xf.size`` single-segment catenaries with :func:`catenary_kernel`.

    All inputs are 1-D arrays of one length (float64; ``seabed`` bool); ``work`` scratch of
    length >= 24; ``out`` (n, OUT_SIZE) float64 receives each element's kernel output (NaN for a
    failed element); ``status`` (n,) int64 the kernel's status.  Returns the number of failed
    elements.
    """
    n_failed = 0
    for i in range(xf.size):
        row = out[i]
        st = catenary_kernel(xf[i], zf[i], length[i], ea[i], w[i], cb[i], seabed[i], hf0[i],
                             vf0[i], work, row)
        status[i] = st
        if st != 0:
            n_failed += 1
            for j in range(OUT_SIZE):
                row[j] = np.nan
    return n_failed


@dataclass(frozen=True, kw_only=True)
class CatenaryBatch:
    """Solutions of many single catenaries (arrays of the broadcast shape of the inputs; SI).

    Attributes
    ----------
    HF, VF : ndarray
        Horizontal and vertical tension components at the fairlead end, N.
    HA, VA : ndarray
        Tension components at the anchor end, N.
    grounded_length : ndarray
        Unstretched length resting on the seabed, m.
    stiffness : ndarray, shape ``shape + (2, 2)``
        ``[[dHF/dxf, dHF/dzf], [dVF/dxf, dVF/dzf]]`` of each element, N/m.
    iterations : int ndarray
        Newton iterations used (-1 where the solve failed).
    status : int ndarray
        0 converged; otherwise the kernel's status code (``STATUS_MESSAGES``); the float results
        of that element are NaN.
    inputs : dict
        The broadcast inputs (arrays of ``shape``).
    """

    HF: np.ndarray
    VF: np.ndarray
    HA: np.ndarray
    VA: np.ndarray
    grounded_length: np.ndarray
    stiffness: np.ndarray
    iterations: np.ndarray
    status: np.ndarray
    inputs: dict = field(repr=False)

    @property
    def shape(self) -> tuple:
        """Broadcast shape of the inputs."""
        return self.HF.shape

    @property
    def ok(self) -> np.ndarray:
        """Mask of the converged elements."""
        return self.status == 0

    @property
    def fairlead_tension(self) -> np.ndarray:
        """Tension at the fairlead, N."""
        return np.hypot(self.HF, self.VF)

    @property
    def anchor_tension(self) -> np.ndarray:
        """Tension at the anchor, N."""
        return np.hypot(self.HA, self.VA)

    def check(self) -> CatenaryBatch:
        """Return ``self`` if every element converged, else raise the ``ConvergenceError`` of the
        first failed element (its index, inputs, status and the number of failures)."""
        bad = np.flatnonzero(self.status != 0)
        if bad.size:
            self._raise_for(tuple(int(k) for k in np.unravel_index(bad[0], self.shape)), bad.size)
        return self

    def result(self, index) -> CatenaryResult:
        """The :class:`CatenaryResult` of one element (e.g. for its ``profile()``); ``index``
        selects one element (an int for 1-D results, else a tuple).  Raises the element's
        ``ConvergenceError`` if it failed."""
        idx = index
        if np.ndim(self.status[idx]) != 0:
            raise IndexError(f"catenary: result({index!r}) must select one element of the "
                             f"results of shape {self.shape}")
        if self.status[idx] != 0:
            self._raise_for(idx, int(np.count_nonzero(self.status)))
        i = self.inputs
        return CatenaryResult(HF=self.HF[idx], VF=self.VF[idx], HA=self.HA[idx],
                              VA=self.VA[idx], grounded_length=self.grounded_length[idx],
                              stiffness=self.stiffness[idx].copy(),
                              iterations=int(self.iterations[idx]),
                              inputs=dict(xf=float(i["xf"][idx]), zf=float(i["zf"][idx]),
                                          length=float(i["length"][idx]),
                                          ea=float(i["ea"][idx]), w=float(i["w"][idx]),
                                          cb=float(i["cb"][idx]),
                                          seabed=bool(i["seabed"][idx])))

    def _raise_for(self, idx, n_failed):
        st = int(self.status[idx])
        i = self.inputs
        where = (f"element {idx!r} ({n_failed} of {self.status.size} failed): "
                 f"catenary(xf={float(i['xf'][idx])!r}, zf={float(i['zf'][idx])!r}, "
                 f"length={float(i['length'][idx])!r}, ea={float(i['ea'][idx])!r}, "
                 f"w={float(i['w'][idx])!r}, cb={float(i['cb'][idx])!r}, "
                 f"seabed={bool(i['seabed'][idx])!r})")
        raise ConvergenceError(f"catenary: {STATUS_MESSAGES.get(st, st)}", where=where,
                               remedy="check the line length against the anchor-fairlead "
                                      "distance, EA and submerged weight of that element; give "
                                      "a warm start (hf0, vf0)")


def _first_bad(name, arr, bad, rule):
    k = np.flatnonzero(bad)
    idx = tuple(int(j) for j in np.unravel_index(k[0], bad.shape))
    raise ValueError(f"catenary: {name} must be {rule}: {k.size} of {bad.size} elements are not, "
                     f"the first at index {idx}: {name}={arr[idx].item()!r}")


def catenary_batch(xf, zf, length, ea, w, cb=0.0, *, seabed=True, hf0=0.0,
                   vf0=0.0) -> CatenaryBatch:
    """Solve many single elastic catenaries at once (inputs broadcast against each other).

    Parameters are those of :func:`floatmoor.mooring.catenary`, each a scalar or an array
    (``seabed`` a bool or bool array); the shapes must broadcast (numpy rules).

    Returns
    -------
    CatenaryBatch
        Arrays of the broadcast shape; failed elements are NaN with their ``status`` (see the
        module docstring); ``check()`` raises for the first failure.

    Raises
    ------
    ValueError
        Shapes that do not broadcast, or invalid values (named with the first bad index).
    """
    given = dict(xf=xf, zf=zf, length=length, ea=ea, w=w, cb=cb, hf0=hf0, vf0=vf0)
    arrs = {}
    for name, v in given.items():
        a = np.asarray(v)
        if a.dtype.kind not in "biuf":
            raise ValueError(f"catenary: {name} must be a real number or an array of real "
                             f"numbers, found dtype {a.dtype} (shape {a.shape})")
        arrs[name] = a.astype(np.float64, copy=False)
    sb = np.asarray(seabed)
    if sb.dtype.kind != "b":
        raise ValueError(f"catenary: seabed must be a bool or an array of bools, found dtype "
                         f"{sb.dtype} (shape {sb.shape})")
    arrs["seabed"] = sb
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrs.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {a.shape}" for k, a in arrs.items())
        raise ValueError(f"catenary: the input shapes do not broadcast together: {shapes}") \
            from None
    b = {k: np.broadcast_to(a, shape) for k, a in arrs.items()}
    # the scalar call's checks, element by element
    for name in _FLOAT_ARGS[:6]:
        finite = np.isfinite(b[name])
        if not finite.all():
            _first_bad(name, b[name], ~finite, "finite")
    for name in ("length", "ea"):
        if not (b[name] > 0).all():
            _first_bad(name, b[name], ~(b[name] > 0), "> 0")
    if not (b["xf"] >= 0).all():
        _first_bad("xf", b["xf"], ~(b["xf"] >= 0), ">= 0")
    below = b["seabed"] & (b["zf"] < 0)
    if below.any():
        _first_bad("zf", b["zf"], below, ">= 0 where seabed is true (the fairlead end must not "
                   "be below an anchor on the seabed)")
    flat = {k: np.ascontiguousarray(a).reshape(-1) for k, a in b.items()}
    n = flat["xf"].size
    out = np.empty((n, OUT_SIZE))
    status = np.zeros(n, dtype=np.int64)
    catenary_batch_kernel(flat["xf"], flat["zf"], flat["length"], flat["ea"], flat["w"],
                          flat["cb"], flat["seabed"], flat["hf0"], flat["vf0"], np.empty(24),
                          out, status)
    ok = status == 0
    iterations = np.where(ok, np.nan_to_num(out[:, OUT_ITER], nan=-1.0), -1.0).astype(np.int64)
    stiffness = out[:, [OUT_K11, OUT_K12, OUT_K21, OUT_K22]].reshape(shape + (2, 2))
    return CatenaryBatch(HF=out[:, OUT_HF].reshape(shape), VF=out[:, OUT_VF].reshape(shape),
                         HA=out[:, OUT_HA].reshape(shape), VA=out[:, OUT_VA].reshape(shape),
                         grounded_length=out[:, OUT_LB].reshape(shape), stiffness=stiffness,
                         iterations=iterations.reshape(shape), status=status.reshape(shape),
                         inputs={k: a.reshape(shape) for k, a in flat.items()})
