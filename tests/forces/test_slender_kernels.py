"""Slender-element drag strips against closed forms (Wang (2016) section 2.1, eq. 2.1-2.15).

The kernel is driven through the same kinematics table the time domain uses; the regular waves
here are tabulated by direct sums.
"""

import math

import numpy as np
import pytest

from floatmoor.core.constants import GRAVITY
from floatmoor.forces.slender import (
    build_kinematics_table,
    covered_current_dofs,
    current_table_without,
    slender_force,
    slender_geometry,
)
from floatmoor.forces.slender_config import SlenderElementSpec
from floatmoor.metocean.kinematics import wavenumber

RHO = 1025.0


def _column(z_top, z_bottom, c2y, n_strips=1, x=0.0, y=0.0):
    return SlenderElementSpec(name="c", p1=(x, y, z_top), p2=(x, y, z_bottom),
                              c2=(0.0, c2y, 0.0), n_strips=n_strips)


def _table(a, w, depth, stations, *, T_samples=200, n_periods=2, lev0=-60.0, dlev=0.25,
           wheeler=False):
    T = 2 * math.pi / w
    k = float(wavenumber([w], None if math.isinf(depth) else depth)[0])
    H = T / T_samples
    tab = build_kinematics_table([w], [a], [0.0], [k], 0.0, stations, duration=n_periods * T,
                                 H=H, depth=depth, lev0=lev0, dlev=dlev, wheeler=wheeler)
    return tab, k, T, H


def chakrabarti_mean(r):
    """Eq. 2.14 / 2.15: mean of |u + U|(u + U) over a cycle / u0^2, r = U / u0."""
    if abs(r) >= 1.0:
        return math.copysign(0.5 + r * r, r)
    psi = math.acos(-r)
    return (r * r * (2 * psi - math.pi) + 4 * r * math.sin(psi)
            + (psi - math.pi / 2 + 0.5 * math.sin(2 * psi))) / math.pi


def test_chakrabarti_formula_itself():
    # independent check of the transcription of eq. 2.15 by brute-force averaging
    th = (np.arange(20000) + 0.5) / 20000 * 2 * np.pi
    for r in (0.0, 0.3, 0.7, 1.5, -0.4):
        v = np.cos(th) + r
        assert chakrabarti_mean(r) == pytest.approx(np.mean(np.abs(v) * v), abs=1e-6)


@pytest.mark.parametrize("ratio", [0.0, 0.3, 0.7, 1.5])
def test_submerged_strip_with_current_chakrabarti(ratio):
    """Fixed, fully submerged vertical strip, regular wave + current along the waves: the
    mean force per unit length over whole periods / (c2 u0^2) equals eq. 2.14/2.15 within 1 %.
    Linear kinematics at a fixed point (wheeler=False: the closed form assumes u0 cos wt)."""
    a, w, depth = 1.0, 0.6, 100.0
    c2 = 5000.0  # 0.5 rho C_D D, N s^2/m^3
    zc, L = -20.0, 0.2
    geom = slender_geometry([_column(zc + L / 2, zc - L / 2, c2)])
    tab, k, T, H = _table(a, w, depth, geom.stations)
    u0 = a * w * math.cosh(k * (zc + depth)) / math.sinh(k * depth)
    U = ratio * u0
    fs = []
    n = 400
    for i in range(n):  # two whole periods at the table nodes
        t = i * (2 * T / n)
        f = slender_force(geom, tab, t, np.zeros(6), np.zeros(3), np.zeros(3),
                          current_z=np.array([-100.0, 0.0]), current_speed=np.array([U, U]))
        fs.append(f[0] / L)
    mean = np.mean(fs) / (c2 * u0 ** 2)
    expected = chakrabarti_mean(ratio)
    if ratio == 0.0:
        assert abs(mean) < 0.01 * 0.5   # closed form 0; 1 % of the |U| >= u0 scale 0.5
    else:
        assert mean == pytest.approx(expected, rel=0.01)


def _direct_column_mean(a, w, k, depth, c2, z_bottom, wheeler, n_t=240, n_z=4000):
    """Direct quadrature of eq. 2.8, F(t) = int_{z_bottom}^{eta(t)} c2 |u| u dz, with linear
    kinematics written out here (independent of the package), averaged over a period."""
    F = []
    for i in range(n_t):
        th = 2 * math.pi * (i + 0.5) / n_t
        eta = a * math.cos(th)
        z = np.linspace(z_bottom, eta, n_z)
        if wheeler:
            zs = (z - eta) * depth / (depth + eta)
        else:
            zs = np.minimum(z, 0.0)
        u = a * w * np.cosh(k * (zs + depth)) / math.sinh(k * depth) * math.cos(th)
        F.append(np.trapezoid(c2 * np.abs(u) * u, z))
    return float(np.mean(F))


def _column_mean(a, w, depth, c2, z_bottom, wheeler, n_strips=60):
    geom = slender_geometry([_column(12.0, z_bottom, c2, n_strips=n_strips)])
    tab, k, T, H = _table(a, w, depth, geom.stations, T_samples=240, n_periods=1,
                          lev0=z_bottom - 3 * a - 2.0, dlev=0.25, wheeler=wheeler)
    fs = [slender_force(geom, tab, i * H, np.zeros(6), np.zeros(3), np.zeros(3))[0]
          for i in range(240)]
    return float(np.mean(fs)), k


@pytest.mark.parametrize("wheeler", [False, True])
def test_surface_piercing_column_mean_force(wheeler):
    """Fixed column through the surface, regular wave, no current: the mean force of the
    wetted-length integration against direct quadrature of eq. 2.8 within 3 %."""
    a, w, depth, c2 = 2.0, 0.55, 150.0, 7687.5
    z_bottom = -15.0
    mean, k = _column_mean(a, w, depth, c2, z_bottom, wheeler)
    ref = _direct_column_mean(a, w, k, depth, c2, z_bottom, wheeler)
    assert ref > 0.0
    assert mean == pytest.approx(ref, rel=0.03)


def test_surface_piercing_column_cubic_growth():
    """Velocity constant across the splash zone (Wang (2016) section 2.1.2): the mean force is
    exactly (4 / 3 pi) c2 u0^2 a (u0 = a w / tanh kd the MWL velocity amplitude; the mean of
    |cos|^3 is 4 / 3 pi), i.e. c2 g k H^3 / (6 pi tanh kd): cubic in the wave height (eq. 2.9,
    leading term; the seed prints 1/sinh 2kd in eq. 2.9, which would vanish in deep water --
    the derivation here gives 1/tanh kd).  The trough part of the splash zone sees the
    velocity decaying below the MWL, an O(kH) correction (the C_1 kH term of eq. 2.9): measured
    -0.33 %, -0.66 %, -1.3 % at a = 0.25, 0.5, 1 m (-2.6 % at 2 m)."""
    w, depth, c2 = 0.55, 150.0, 7687.5
    means = {}
    for a in (0.25, 0.5, 1.0):
        m, k = _column_mean(a, w, depth, c2, -15.0, wheeler=False)
        means[a] = m
        closed = c2 * GRAVITY * k * (2 * a) ** 3 / (6 * math.pi * math.tanh(k * depth))
        assert m == pytest.approx(closed, rel=0.015)
    assert means[0.5] / means[0.25] == pytest.approx(8.0, rel=0.03)
    assert means[1.0] / means[0.5] == pytest.approx(8.0, rel=0.03)


def test_moving_strip_relative_velocity_eq_2_3():
    """Eq. 2.3: f = c2 |u - x'| (u - x') with the body velocity, at any time in a wave."""
    a, w, depth, c2 = 1.0, 0.6, 100.0, 5000.0
    zc, L = -10.0, 0.2
    geom = slender_geometry([_column(zc + L / 2, zc - L / 2, c2)])
    tab, k, T, H = _table(a, w, depth, geom.stations)
    for i, xdot in ((0, 0.3), (37, -0.5), (101, 0.9), (250, 0.0)):
        t = i * H
        u = a * w * math.cosh(k * (zc + depth)) / math.sinh(k * depth) * math.cos(w * t)
        f = slender_force(geom, tab, t, np.zeros(6), np.array([xdot, 0.0, 0.0]), np.zeros(3))
        rel = u - xdot
        assert f[0] / L == pytest.approx(c2 * abs(rel) * rel, rel=1e-6, abs=1e-6)
        assert abs(f[1]) < 1e-9 and abs(f[2]) < 1e-9  # c2x = 0 (vertical flow not taken)
        # moment about the reference point: (0, 0, zc) x (Fx, 0, 0) = (0, zc Fx, 0)
        assert f[4] == pytest.approx(zc * f[0], rel=1e-9, abs=1e-9)


def test_rotating_body_strip_velocity():
    """Yaw rate r: a strip at arm (x0, 0, z) moves at (0, r x0, 0) and sees -r x0 sideways.
    The column's local z axis is body -y: drag c2z along y."""
    tab = build_kinematics_table([0.5], [0.0], [0.0], [0.03], 0.0, [[20.0, 0.0]], duration=10.0,
                                 H=1.0, depth=100.0, lev0=-20.0)
    el = SlenderElementSpec(name="c", p1=(20.0, 0.0, -5.0), p2=(20.0, 0.0, -6.0),
                            c2=(0.0, 0.0, 3000.0), n_strips=1)
    geom = slender_geometry([el])
    r = 0.05
    f = slender_force(geom, tab, 0.0, np.zeros(6), np.zeros(3), np.array([0.0, 0.0, r]))
    v = r * 20.0
    assert f[1] == pytest.approx(-3000.0 * v * v * 1.0, rel=1e-9)
    assert f[5] == pytest.approx(20.0 * f[1], rel=1e-9)  # yaw moment x Fy


def test_free_decay_damped_by_body_velocity():
    """A spring-mass body with one submerged strip in still water: the body-velocity term is a
    quadratic damping; the amplitude drop per cycle matches the energy balance
    dA = (8 / 3) (c2 L / m) A^2 (small damping) within 5 %."""
    c2, L = 5000.0, 10.0
    m, kk = 1.0e6, 4.0e5
    geom = slender_geometry([_column(-5.0, -5.0 - L, c2, n_strips=4)])
    tab = build_kinematics_table([0.5], [0.0], [0.0], [0.03], 0.0, geom.stations,
                                 duration=200.0, H=1.0, depth=100.0, lev0=-30.0)
    wn = math.sqrt(kk / m)
    Tn = 2 * math.pi / wn
    dt = Tn / 400

    def acc(x, v, drag):
        f = slender_force(geom, tab, 0.0, np.array([x, 0, 0, 0, 0, 0.0]),
                          np.array([v, 0.0, 0.0]), np.zeros(3))[0] if drag else 0.0
        return (f - kk * x) / m

    for drag in (False, True):
        x, v = 1.0, 0.0
        peaks = []
        prev_v = v
        for _n in range(int(2.2 * Tn / dt)):
            k1x, k1v = v, acc(x, v, drag)
            k2x, k2v = v + 0.5 * dt * k1v, acc(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v, drag)
            k3x, k3v = v + 0.5 * dt * k2v, acc(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v, drag)
            k4x, k4v = v + dt * k3v, acc(x + dt * k3x, v + dt * k3v, drag)
            x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
            v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
            if prev_v > 0.0 >= v:   # a positive maximum of x
                peaks.append(x)
            prev_v = v
        if not drag:
            assert peaks[0] == pytest.approx(1.0, rel=5e-4)  # peak sampled at the steps
        else:
            A0 = 1.0
            drop = A0 - peaks[0]
            # energy balance over one cycle at mean amplitude
            Am = A0 - 0.5 * drop
            expected = 8.0 / 3.0 * c2 * L / m * Am ** 2
            assert drop > 0.0
            assert drop == pytest.approx(expected, rel=0.05)


def test_double_counting_dofs_and_table():
    # a column with drag along both horizontal local axes (local y = body x, local z = body
    # -y) and a pontoon along y (drag only across it: local y = body x, local z = up)
    col = SlenderElementSpec(name="c", p1=(0.0, 0.0, 5.0), p2=(0.0, 0.0, -10.0),
                             c2=(0.0, 7000.0, 8000.0), n_strips=4)
    geom = slender_geometry([col,
                             SlenderElementSpec(name="p", p1=(0.0, 40.0, -8.0),
                                                p2=(0.0, -40.0, -8.0), c2=(0.0, 1700.0, 11000.0),
                                                n_strips=8)])
    dofs = covered_current_dofs(geom)
    assert 0 in dofs and 1 in dofs   # horizontal current forces
    assert 2 not in dofs             # no vertical force from a horizontal current
    only_pontoon = covered_current_dofs(slender_geometry([SlenderElementSpec(
        name="p", p1=(0.0, 40.0, -8.0), p2=(0.0, -40.0, -8.0), c2=(0.0, 1700.0, 11000.0),
        n_strips=8)]))
    assert 1 not in only_pontoon and 0 in only_pontoon  # no drag along the pontoon axis
    tab = np.ones((12, 6))
    with pytest.warns(Warning, match="surge"):
        out = current_table_without(tab, dofs)
    assert np.all(out[:, list(dofs)] == 0.0)
    assert np.all(out[:, 2] == 1.0)


def test_dry_element_gives_no_force():
    geom = slender_geometry([_column(20.0, 10.0, 7000.0)])
    tab, k, T, H = _table(1.0, 0.6, 100.0, geom.stations)
    f = slender_force(geom, tab, 3.0, np.zeros(6), np.zeros(3), np.zeros(3),
                      current_z=np.array([0.0]), current_speed=np.array([1.0]))
    assert np.all(f == 0.0)


def test_inertia_option_closed_form():
    """Optional inertia: a fixed submerged strip with cm = rho C_M A (kg/m) feels
    cm a_x, a_x = -a w^2 cosh k(z+d)/sinh kd sin(w t) (linear theory, Faltinsen table 2.1);
    without the acceleration table (the default) the inertia term is absent."""
    a, w, depth = 1.0, 0.6, 100.0
    zc, L = -10.0, 0.2
    cm = RHO * 2.0 * math.pi * 4.0 ** 2 / 4.0   # C_M = 2, D = 4 m
    el = SlenderElementSpec(name="c", p1=(0.0, 0.0, zc + L / 2), p2=(0.0, 0.0, zc - L / 2),
                            c2=(0.0, 0.0, 0.0), n_strips=1, cm=(0.0, cm, cm))
    geom = slender_geometry([el])
    k = float(wavenumber([w], depth)[0])
    T = 2 * math.pi / w
    H = T / 200
    tab = build_kinematics_table([w], [a], [0.0], [k], 0.0, geom.stations, duration=2 * T,
                                 H=H, depth=depth, lev0=-60.0, dlev=0.25, wheeler=False,
                                 acceleration=True)
    for i in (0, 23, 77, 150):
        t = i * H
        ax = -a * w * w * math.cosh(k * (zc + depth)) / math.sinh(k * depth) * math.sin(w * t)
        f = slender_force(geom, tab, t, np.zeros(6), np.zeros(3), np.zeros(3))
        assert f[0] / L == pytest.approx(cm * ax, rel=1e-5, abs=1e-3)
    tab0 = build_kinematics_table([w], [a], [0.0], [k], 0.0, geom.stations, duration=2 * T,
                                  H=H, depth=depth, lev0=-60.0, dlev=0.25, wheeler=False)
    assert np.all(slender_force(geom, tab0, 23 * H, np.zeros(6), np.zeros(3),
                                np.zeros(3)) == 0.0)
