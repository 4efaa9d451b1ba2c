"""Kernels checked directly: block-tridiagonal solver against a dense solve, tangent against
finite differences of the nodal forces."""

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.bundles import new_work

from .conftest import oc3_spec


def test_block_tridiagonal_solver_matches_dense_solve():
    rng = np.random.default_rng(1)
    n = 9
    Dg = rng.normal(size=(n, 3, 3)) + 8 * np.eye(3)
    Of = rng.normal(size=(n - 1, 3, 3))   # not symmetric: lower block = upper block
    b = rng.normal(size=(n, 3))
    A = np.zeros((3 * n, 3 * n))
    i0, i1 = 1, n - 1
    for i in range(i0, i1):
        A[3 * i:3 * i + 3, 3 * i:3 * i + 3] = Dg[i]
        if i + 1 < i1:
            A[3 * i:3 * i + 3, 3 * i + 3:3 * i + 6] = Of[i]
            A[3 * i + 3:3 * i + 6, 3 * i:3 * i + 3] = Of[i]
    sl = slice(3 * i0, 3 * i1)
    ref = np.linalg.solve(A[sl, sl], b[i0:i1].ravel())
    x = np.zeros((n, 3))
    bad = K.block_tridiag_solve(Dg, Of, b, i0, i1, np.zeros((n, 3, 3)), np.zeros((n, 3)),
                                np.zeros((3, 3)), x)
    assert bad == -1
    assert np.allclose(x[i0:i1].ravel(), ref, rtol=1e-12, atol=1e-12)


def _forces(line, r, v, fric=0):
    n = line.n_nodes
    f = np.zeros((n, 3))
    K.line_forces(r, v, line.fs, line.params(fric=fric), False, 0.0, 0.0, f, new_work(n))
    return f


def _jac(line, r, v, cK, cC, fric=0):
    n = line.n_nodes
    w = new_work(n)
    K.line_forces(r, v, line.fs, line.params(fric=fric), True, cK, cC, np.zeros((n, 3)), w)
    return w.Dg, w.Of


def test_stiffness_and_damping_blocks_match_finite_differences():
    """Axial (with internal damping), seabed and drag tangents: K = -df/dx and C = -df/dv by
    central differences at a perturbed moving state.  The drag's dependence on the positions
    (through the node tangent) is left out of K by design, so K is checked with drag off; cC is
    a tiny positive number so the statics-only tangent regularisation is not used."""
    line = FELine(oc3_spec(n=12))
    line.solve_static()
    rng = np.random.default_rng(3)
    r = line.r + rng.normal(scale=0.02, size=line.r.shape)
    r[0], r[-1] = line.r[0], line.r[-1]
    v = rng.normal(scale=0.3, size=r.shape)
    P_drag = line.P.copy()
    for which in ("K", "C"):
        if which == "K":
            line.P[:, K.NP_KDN] = 0.0
            line.P[:, K.NP_KDT] = 0.0
            Dg, Of = _jac(line, r, v, 1.0, 1e-300)
        else:
            line.P[:] = P_drag
            Dg, Of = _jac(line, r, v, 0.0, 1.0)
        for i in (3, 7, 11):
            for a in range(3):
                h = 1e-6
                x0 = v if which == "C" else r
                xp = x0.copy()
                xm = x0.copy()
                xp[i, a] += h
                xm[i, a] -= h
                if which == "C":
                    fp, fm = _forces(line, r, xp), _forces(line, r, xm)
                else:
                    fp, fm = _forces(line, xp, v), _forces(line, xm, v)
                col = -(fp - fm) / (2 * h)
                scale = np.abs(Dg[i]).max()
                assert np.allclose(col[i], Dg[i][:, a], atol=2e-5 * scale), (which, i, a)
                assert np.allclose(col[i + 1], Of[i][:, a], atol=2e-5 * scale), (which, i, a)
                assert np.allclose(col[i - 1], Of[i - 1][:, a], atol=2e-5 * scale), (which, i, a)


_NOJIT_CODE = """
from tests.mooring.fe.conftest import oc3_spec
from floatmoor.mooring.fe import FELine, Friction
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed
line = FELine(oc3_spec(n=8, friction=Friction(model="displacement_velocity_ramp",
                                              mu_axial=0.7, mu_lateral=1.0)))
line.solve_static(friction=False)
line.start()
ds = run_prescribed(line, HarmonicMotion(amplitude=(1.0, 2.0, 0.5), period=8.0, ramp=4.0),
                    2.0, 0.2)
print(repr(float(ds.fairlead_tension.values[-1])))
"""


def test_kernels_run_without_jit():
    """The kernels also run as plain Python (NUMBA_DISABLE_JIT=1) and give the same numbers."""
    import os
    import subprocess
    import sys
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(__file__))))
    vals = []
    for flag in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=flag)
        out = subprocess.run([sys.executable, "-c", _NOJIT_CODE], env=env, cwd=root,
                             capture_output=True, text=True, check=True)
        vals.append(float(out.stdout.strip().splitlines()[-1]))
    assert vals[0] == pytest.approx(vals[1], rel=1e-9)
