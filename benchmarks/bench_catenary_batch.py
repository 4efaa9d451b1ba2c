"""Benchmark of the vectorised catenary: 10,000 lines in one call against MoorPy's catenary()
called in a loop.

The lines (a third each, cold starts, no warm start for either program):

* slack chain with seabed contact: water depth 100-400 m, studless chain 76-157 mm, length
  2.5-4 depths, 10-60 % of the length on the seabed (inextensible estimate), axial friction
  coefficient 1.0 on half of them, 0 on the others;
* taut polyester: chord at 30-50 deg from the horizontal, stretched 0.2-2 %, EA 1e8-1e9 N,
  submerged weight 30-300 N/m, anchor on the seabed (the line pulls it up);
* hanging: chain suspended between two points of the water column (no seabed), ends at
  -30..+30 % of the length apart in height, chord 50-95 % of the length.

floatmoor: ``catenary(xf, zf, length, ea, w, cb, seabed=...)`` with arrays (one compiled loop);
its iteration stops at 1e-9 relative on the forces (its fixed setting).  MoorPy 1.3.0:
``moorpy.Catenary.catenary`` at its documented defaults (``Tol=1e-6`` m, an absolute error of the
fairlead position; ``MaxIter=100``; ``nNodes=20``, the profile points it always computes; its own
initial guess, ``HF0 = VF0 = 0``), ``CB = cb`` with the seabed, ``CB = -1e9`` (no seabed
contact) without; its end forces are the ones it returns (forces on the ends, positive towards
the other end and up: ``HF = -fBH``, ``VF = -fBV``; its ``info['VF']`` is that of the reversed
line when the fairlead is below the anchor).  Accuracy: both against MoorPy at ``Tol=1e-10`` (the converged reference) on
every line (MoorPy returns a few taut lines as a shape running below the seabed: left out of the
accuracy figures and counted).  Times: CPU time (time.process_time), best of the repeats.

Run:  .venv/bin/python benchmarks/bench_catenary_batch.py [N]
"""

from __future__ import annotations

import math
import platform
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from floatmoor.mooring import catenary  # noqa: E402

G = 9.80665
RHO = 1025.0


def chain(d):
    """Studless chain of nominal diameter d (m): submerged weight (N/m), EA (N) (the usual
    19.9 d^2 t/m mass and 0.854e11 d^2 N stiffness of R3 studless chain, steel/seawater 7850/1025)."""
    mass = 19.9e3 * d * d
    return mass * G * (1 - RHO / 7850.0), 0.854e11 * d * d


def spread(n, seed=2026):
    """The 10,000-line spread of the module docstring: arrays xf, zf, L, EA, w, cb, seabed, kind."""
    rng = np.random.default_rng(seed)
    k = np.arange(n) % 3
    xf, zf, L, EA, w, cb = (np.empty(n) for _ in range(6))
    seabed = np.ones(n, bool)
    # slack chain touching down
    m = k == 0
    nm = int(m.sum())
    h = rng.uniform(100, 400, nm)
    ww, ea = chain(rng.uniform(0.076, 0.157, nm))
    LL = rng.uniform(2.5, 4.0, nm) * h
    Ls = (1 - rng.uniform(0.1, 0.6, nm)) * LL
    Ls = np.maximum(Ls, 1.05 * h)
    a = (Ls * Ls - h * h) / (2 * h)
    xf[m] = (LL - Ls) + a * np.arccosh(1 + h / a)
    zf[m], L[m], EA[m], w[m] = h, LL, ea, ww
    cb[m] = np.where(rng.uniform(size=nm) < 0.5, 1.0, 0.0)
    # taut polyester
    m = k == 1
    nm = int(m.sum())
    h = rng.uniform(100, 400, nm)
    ang = np.radians(rng.uniform(30, 50, nm))
    chord = h / np.sin(ang)
    xf[m], zf[m] = chord * np.cos(ang), h
    L[m] = chord / (1 + rng.uniform(0.002, 0.02, nm))
    EA[m] = 10 ** rng.uniform(8, 9, nm)
    w[m] = rng.uniform(30, 300, nm)
    cb[m] = 0.0
    # hanging between two points
    m = k == 2
    nm = int(m.sum())
    LL = rng.uniform(100, 1000, nm)
    dz = rng.uniform(-0.3, 0.3, nm) * LL
    c = rng.uniform(0.5, 0.95, nm) * LL
    xf[m] = np.sqrt(np.maximum(c * c - dz * dz, 1.0))
    zf[m], L[m] = dz, LL
    w[m], EA[m] = chain(rng.uniform(0.076, 0.157, nm))
    cb[m] = 0.0
    seabed[m] = False
    return xf, zf, L, EA, w, cb, seabed, k


def run_moorpy(xf, zf, L, EA, w, cb, seabed, **kw):
    """MoorPy's catenary in a loop; returns (HF, VF, HA, VA, below_seabed, CPU seconds)."""
    from moorpy.Catenary import catenary as mp_catenary
    n = xf.size
    res = np.empty((n, 4))
    below = np.zeros(n, bool)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t0 = time.process_time()
        for i in range(n):
            fAH, fAV, fBH, fBV, _ = mp_catenary(xf[i], zf[i], L[i], EA[i], w[i],
                                                CB=cb[i] if seabed[i] else -1e9, **kw)
            res[i] = -fBH, -fBV, abs(fAH), fAV
        dt = time.process_time() - t0
    below = seabed & (res[:, 3] < -1e-6 * np.hypot(res[:, 2], res[:, 3]))
    return res, below, dt


def main(n=10000, repeat=5):
    import numba
    print(f"python {platform.python_version()}, numba {numba.__version__}, {platform.machine()}")
    xf, zf, L, EA, w, cb, seabed, kind = spread(n)
    catenary(xf[:3], zf[:3], L[:3], EA[:3], w[:3], cb[:3], seabed=seabed[:3])  # compile / cache
    t_fm = math.inf
    for _ in range(repeat):
        t0 = time.process_time()
        b = catenary(xf, zf, L, EA, w, cb, seabed=seabed)
        t_fm = min(t_fm, time.process_time() - t0)
    nfail = int((~b.ok).sum())
    t0 = time.process_time()
    for i in range(min(n, 2000)):
        catenary(float(xf[i]), float(zf[i]), float(L[i]), float(EA[i]), float(w[i]),
                 float(cb[i]), seabed=bool(seabed[i]))
    t_scalar = (time.process_time() - t0) / min(n, 2000)
    print(f"{n} lines (slack chain on the seabed, taut polyester, hanging), cold starts")
    print(f"  floatmoor catenary(arrays)  : {t_fm * 1e3:9.2f} ms CPU, {t_fm / n * 1e6:8.3f} us "
          f"per line (best of {repeat}); {nfail} failed; "
          f"iterations mean {b.iterations.mean():.1f}, max {b.iterations.max()}")
    print(f"  floatmoor catenary(scalars) : {t_scalar * 1e6:8.2f} us per line (Python loop, "
          f"for comparison)")
    try:
        import moorpy  # noqa: F401
    except ImportError:
        print("  MoorPy not installed: comparison skipped")
        return
    mp_def, below, t_mp = run_moorpy(xf, zf, L, EA, w, cb, seabed)
    print(f"  MoorPy catenary() loop      : {t_mp * 1e3:9.1f} ms CPU, {t_mp / n * 1e6:8.1f} us "
          f"per line (defaults Tol=1e-6 m, MaxIter=100, nNodes=20)")
    print(f"  ratio per solve             : {t_mp / t_fm:9.0f} x")
    ref, below_ref, t_ref = run_moorpy(xf, zf, L, EA, w, cb, seabed, Tol=1e-10, MaxIter=200)
    print(f"  (MoorPy at Tol=1e-10, the reference: {t_ref / n * 1e6:.1f} us per line; ratio "
          f"{t_ref / t_fm:.0f} x)")
    fm = np.column_stack([b.HF, b.VF, b.HA, b.VA])
    use = ~(below | below_ref) & b.ok
    T = np.hypot(ref[:, 0], ref[:, 1])
    print(f"  accuracy against the reference, max over lines of max |dHF, dVF, dHA, dVA| / "
          f"fairlead tension ({int(use.sum())} lines; {int((~use).sum())} MoorPy shapes below "
          f"the seabed left out):")
    for name, val in (("floatmoor", fm), ("MoorPy default", mp_def)):
        e = np.abs(val - ref).max(axis=1)[use] / T[use]
        per = ", ".join(f"{lab} {e[kind[use] == j].max():.1e}"
                        for j, lab in enumerate(("slack", "taut", "hanging")))
        print(f"    {name:15s}: max {e.max():.1e}, median {np.median(e):.1e} ({per})")
    d = np.abs(fm - mp_def).max(axis=1)[use] / T[use]
    print(f"  floatmoor against MoorPy default: max {d.max():.1e} of the fairlead tension")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10000)
