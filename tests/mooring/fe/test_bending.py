"""Optional bending stiffness: tangent against finite differences, the block-band solver against a
dense solve, a simply supported beam under uniform load (5 q L^4 / (384 EI)) and its first natural
frequency ((pi / L)^2 sqrt(EI / m))."""

import math

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Seabed
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.bundles import new_work
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed
from floatmoor.mooring.line_types import LineType

L, Q, EI, EA = 10.0, 10.0, 1.0e5, 1.0e6


def _beam(n=20, drag=False):
    m = Q / 9.80665
    lt = LineType(name="beam", material="user", diameter=0.05, mass_per_length=m,
                  displaced_volume=0.0, ea=EA, ea_dynamic=EA, mbs=1e6,
                  cdn=1.0 if drag else 0.0, cdt=0.0, can=0.0, cat=0.0)
    spec = FELineSpec(name="beam", anchor=(0.0, 0.0, -100.0), fairlead=(L, 0.0, -100.0),
                      segments=(FESegment(line_type=lt, length=L, n_elements=n,
                                          bending_stiffness=EI),),
                      seabed=Seabed(depth=1000.0))
    return FELine(spec)


def test_band_solver_matches_dense_solve():
    rng = np.random.default_rng(5)
    n = 10
    Dg = rng.normal(size=(n, 3, 3)) + 10 * np.eye(3)
    Of = rng.normal(size=(n - 1, 3, 3))
    BX = np.zeros((7, n, 3, 3))
    BX[0:3] = rng.normal(size=(3, n, 3, 3))
    b = rng.normal(size=(n, 3))
    i0, i1 = 1, n - 1
    A = np.zeros((3 * n, 3 * n))
    for i in range(i0, i1):
        A[3 * i:3 * i + 3, 3 * i:3 * i + 3] = Dg[i]
        if i + 1 < i1:
            A[3 * i:3 * i + 3, 3 * i + 3:3 * i + 6] = Of[i]
            A[3 * i + 3:3 * i + 6, 3 * i:3 * i + 3] = Of[i] + BX[0, i]
        if i + 2 < i1:
            A[3 * i:3 * i + 3, 3 * i + 6:3 * i + 9] = BX[1, i]
            A[3 * i + 6:3 * i + 9, 3 * i:3 * i + 3] = BX[2, i]
    sl = slice(3 * i0, 3 * i1)
    ref = np.linalg.solve(A[sl, sl], b[i0:i1].ravel())
    x = np.zeros((n, 3))
    assert K.block_band_solve(Dg, Of, BX, b, i0, i1, np.zeros((n, 3)), np.zeros((3, 3)), x) == -1
    assert np.allclose(x[i0:i1].ravel(), ref, rtol=1e-10, atol=1e-12)


def test_bending_tangent_matches_finite_differences():
    line = _beam(n=8)
    rng = np.random.default_rng(2)
    r = line.r.copy()
    r[1:-1] += rng.normal(scale=0.05, size=(line.n_nodes - 2, 3))
    r[1:-1, 0] += 0.001     # keep every element taut (no slack transition in the check)
    n = line.n_nodes
    v = np.zeros_like(r)

    def forces(rr):
        f = np.zeros((n, 3))
        K.line_forces(rr, v, line.fs, line.params(fric=0), False, 0.0, 0.0, f, new_work(n))
        return f
    w = new_work(n)
    K.line_forces(r, v, line.fs, line.params(fric=0), True, 1.0, 1e-300, np.zeros((n, 3)), w)
    Dg, Of, BX = w.Dg, w.Of, w.BX
    Kd = np.zeros((3 * n, 3 * n))
    for i in range(n):
        Kd[3 * i:3 * i + 3, 3 * i:3 * i + 3] = Dg[i]
        if i + 1 < n:
            Kd[3 * i:3 * i + 3, 3 * i + 3:3 * i + 6] = Of[i]
            Kd[3 * i + 3:3 * i + 6, 3 * i:3 * i + 3] = Of[i] + BX[0, i]
        if i + 2 < n:
            Kd[3 * i:3 * i + 3, 3 * i + 6:3 * i + 9] = BX[1, i]
            Kd[3 * i + 6:3 * i + 9, 3 * i:3 * i + 3] = BX[2, i]
    h = 1e-7
    for i in (2, 4):
        for a in range(3):
            rp = r.copy()
            rm = r.copy()
            rp[i, a] += h
            rm[i, a] -= h
            col = -(forces(rp) - forces(rm)).ravel() / (2 * h)
            rows = slice(3 * (i - 2), 3 * (i + 3))
            scale = np.abs(Kd[:, 3 * i + a]).max()
            assert np.allclose(col[rows], Kd[rows, 3 * i + a], atol=1e-5 * scale), (i, a)


def test_simply_supported_beam_midspan_deflection():
    """Pinned ends at the unstretched distance, uniform load q = 10 N/m, EI = 1e5 N m^2:
    midspan deflection 5 q L^4 / (384 EI) = 13.02 mm (Euler-Bernoulli; the membrane force of
    the tiny stretch changes it by about 0.05 %).  Measured: +0.78 / +0.17 / +0.009 % with
    10 / 20 / 40 elements."""
    line = _beam(n=20)
    s = line.solve_static()
    mid = -(s.positions[10, 2] + 100.0)
    assert mid == pytest.approx(5 * Q * L ** 4 / (384 * EI), rel=5e-3)
    # the ends carry half the load each
    assert -s.fairlead_force[2] == pytest.approx(0.5 * Q * L, rel=1e-6)


def test_simply_supported_beam_first_natural_period():
    """Released from the static shape with the weight removed: the midspan node oscillates at
    the first natural period 2 pi / ((pi / L)^2 sqrt(EI / m)) = 0.2033 s (measured +0.22 %
    with 20 elements, dt = 1 ms, rho_inf = 1)."""
    line = _beam(n=20)
    line.solve_static()
    line.P[:, K.NP_W] = 0.0
    line.start(rho_inf=1.0, tol=1e-10)
    dt = 0.001
    ds = run_prescribed(line, HarmonicMotion(amplitude=(0, 0, 0), period=1.0), 1.0, dt,
                        track_nodes=(10,))
    z = ds.node_position.values[:, 0, 2] + 100.0
    t = ds.time.values
    up = np.nonzero((z[:-1] < 0) & (z[1:] >= 0))[0]
    tc = t[up] - z[up] * dt / (z[up + 1] - z[up])
    T1 = np.mean(np.diff(tc))
    m = Q / 9.80665
    assert T1 == pytest.approx(2 * math.pi / ((math.pi / L) ** 2 * math.sqrt(EI / m)), rel=1e-2)
