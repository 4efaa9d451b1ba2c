"""Benchmarks of the quasi-static mooring.

1. A single catenary solve after compilation: the numba kernel called with preallocated arrays
   (cold start and warm start), and the Python wrapper ``floatmoor.mooring.catenary``.
2. Equilibrium (surge, sway, yaw free, 5,000 kN towards +x) plus the 6x6 stiffness of the
   12-line Floatel-like chain-polyester-chain system, floatmoor against MoorPy on the same system
   (MoorPy models each 3-segment line with two free connection points, its standard way, and
   computes the coupled stiffness analytically with getCoupledStiffnessA).

Run:  .venv/bin/python benchmarks/bench_mooring.py
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

from floatmoor.core.config import Node  # noqa: E402
from floatmoor.io.mooring_section import parse_mooring  # noqa: E402
from floatmoor.mooring import catenary  # noqa: E402
from floatmoor.mooring.catenary import OUT_SIZE, catenary_kernel  # noqa: E402
from floatmoor.solvers.statics import solve_equilibrium as equilibrium  # noqa: E402

EXT = np.array([5.0e6, 0.0, 0.0, 0.0, 0.0, 0.0])


def best_of(fun, n, repeat=5):
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(n):
            fun()
        best = min(best, (time.perf_counter() - t0) / n)
    return best


def bench_catenary():
    work = np.empty(24)
    out = np.zeros(OUT_SIZE)
    args = (848.67, 250.0, 902.2, 384.243e6, 698.09, 0.001, True)
    catenary_kernel(*args, 0.0, 0.0, work, out)  # compile / load cache
    cold = best_of(lambda: catenary_kernel(*args, 0.0, 0.0, work, out), 20000)
    hf, vf = out[0], out[1]
    args2 = (848.70, 250.0) + args[2:]
    warm = best_of(lambda: catenary_kernel(*args2, hf, vf, work, out), 20000)
    wrapper = best_of(lambda: catenary(*args[:6]), 5000)
    print("single catenary (OC3 line, seabed contact + friction), after compilation:")
    print(f"  numba kernel, cold start : {cold * 1e6:8.2f} us")
    print(f"  numba kernel, warm start : {warm * 1e6:8.2f} us")
    print(f"  Python wrapper catenary(): {wrapper * 1e6:8.2f} us")
    return cold, warm, wrapper


def floatmoor_run(ms):
    ms.warm[:] = 0.0  # cold start every time
    res = equilibrium(ms, external_force=EXT, dofs=("surge", "sway", "yaw"))
    K = ms.stiffness(res.pose)
    return res, K


def moorpy_system(ms):
    import moorpy as mp
    depth = ms.water_depth
    sysm = mp.System(depth=depth, rho=ms.water_density, g=ms.gravity)
    # line types with the same EA and submerged weight: d_vol from the displaced volume
    types = {}
    for line in ms.lines:
        for s in line.segments:
            if s.line_type not in types:
                mass = s.mass_per_length
                vol = (mass - s.w / ms.gravity) / ms.water_density
                sysm.setLineType(dnommm=s.diameter * 1000, name=s.line_type, mass=mass,
                                 d_vol=math.sqrt(4 * vol / math.pi), EA=s.ea)
                types[s.line_type] = True
    body = sysm.addBody(0, np.zeros(6), m=0, v=0, f6Ext=EXT, DOFs=[0, 1, 5])
    for line in ms.lines:
        a = np.array(line.anchor)
        f = np.array(line.fairlead)
        pts = [sysm.addPoint(1, a)]
        total = sum(s.length for s in line.segments)
        acc = 0.0
        for s in line.segments[:-1]:
            acc += s.length
            frac = acc / total
            r = a + frac * (f - a)
            r[2] = max(r[2] - 5.0, -depth + 0.5) if frac < 0.5 else r[2]
            pts.append(sysm.addPoint(0, r))
        pf = sysm.addPoint(1, f)
        body.attachPoint(len(sysm.pointList), f)
        pts.append(pf)
        for k, s in enumerate(line.segments):
            sysm.addLine(s.length, s.line_type, nSegs=20,
                         pointA=sysm.pointList.index(pts[k]) + 1,
                         pointB=sysm.pointList.index(pts[k + 1]) + 1)
    sysm.initialize()
    return sysm


def moorpy_run(ms):
    """Returns (system, stiffness, seconds spent in solveEquilibrium + stiffness only)."""
    sysm = moorpy_system(ms)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t0 = time.perf_counter()
        sysm.solveEquilibrium(tol=1e-3, maxIter=1000)
        body = sysm.bodyList[0]
        body.type = -1  # coupled: stiffness of the body with the free connection points condensed
        K = sysm.getCoupledStiffnessA(lines_only=True)
        dt = time.perf_counter() - t0
    return sysm, K, dt


def bench_system():
    ms = parse_mooring(Node.load(ROOT / "vessels/floatel_like/mooring.yaml"), water_depth=150.0)
    res, K = floatmoor_run(ms)  # compile
    t_fm = best_of(lambda: floatmoor_run(ms), 20)
    print("\n12-line Floatel-like system, equilibrium (surge, sway, yaw) + 6x6 stiffness:")
    print(f"  floatmoor: {t_fm * 1e3:9.3f} ms   ({res.iterations} Newton iterations), "
          f"surge {res.pose[0]:.4f} m, K11 {K[0, 0]:.6g} N/m")
    try:
        import moorpy  # noqa: F401
    except ImportError:
        print("  MoorPy not installed: comparison skipped")
        return t_fm, None
    runs = [moorpy_run(ms) for _ in range(3)]
    t_mp = min(r[2] for r in runs)
    sysm, Kmp = runs[0][0], runs[0][1]
    b = sysm.bodyList[0]
    print(f"  MoorPy   : {t_mp * 1e3:9.3f} ms   (solveEquilibrium + getCoupledStiffnessA; "
          f"building the System not counted), surge {b.r6[0]:.4f} m")
    print(f"  speed-up : {t_mp / t_fm:9.1f} x")
    Kfm6 = ms.stiffness(np.array([b.r6[0], b.r6[1], 0, 0, 0, b.r6[5]]))
    np.set_printoptions(precision=4, linewidth=150)
    print(f"  equilibrium: floatmoor surge {res.pose[0]:.4f} m, sway {res.pose[1]:.2e} m, "
          f"yaw {res.pose[5]:.2e} rad; MoorPy surge {b.r6[0]:.4f} m")
    d = np.diag(Kfm6)
    dm = np.diag(Kmp)
    print("  diag(K) floatmoor:", d)
    print("  diag(K) MoorPy   :", dm)
    p0 = np.array([b.r6[0], b.r6[1], 0, 0, 0, b.r6[5]])
    h = np.array([0.01, 0, 0, 0, 0, 0])
    k11_fd = -(ms.force(p0 + h)[0] - ms.force(p0 - h)[0]) / 0.02
    print(f"  K11 by central differences of floatmoor forces: {k11_fd:.6g} N/m "
          f"(MoorPy's DOFs are surge, sway, yaw: its K is 3x3)")
    return t_fm, t_mp


def _timed(f):
    t0 = time.perf_counter()
    f()
    return time.perf_counter() - t0


if __name__ == "__main__":
    import numba
    print(f"python {platform.python_version()}, numba {numba.__version__}, {platform.machine()}")
    bench_catenary()
    bench_system()
